/* Mesa's software rasteriser performs floating-point operations that would
 * raise the traps enabled in Debug builds (-ffpe-trap=invalid,zero,overflow).
 * Calls into OSMesa are bracketed by these two functions: traps off, then the
 * caller's traps restored with any flags Mesa raised cleared. */
#define _GNU_SOURCE
#include <fenv.h>

int udec_fp_traps_off(void)
{
    int old = fegetexcept();
    fedisableexcept(FE_ALL_EXCEPT);
    return old;
}

void udec_fp_traps_restore(int old)
{
    feclearexcept(FE_ALL_EXCEPT);
    if (old > 0) feenableexcept(old);
}
