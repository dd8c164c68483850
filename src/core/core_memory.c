/* Memory policy of the process (issue 23). glibc serves large blocks with
 * mmap and returns them to the system when freed, but after the first such
 * block is freed it raises its threshold to that block's size, so the next
 * large arrays come from the heap and stay resident after they are freed:
 * the temporaries of zoning a 1M-zone block (GENERATE) then add to the peak
 * of the first CYCLE (measured: 265 B a zone at 1M zones against 246 B with
 * a fixed threshold). A fixed threshold keeps large arrays returned. Hot
 * loops allocate nothing, so the mmap of a large array is paid once per
 * command at most. */
#include <stdlib.h>  /* defines __GLIBC__ on glibc */
#ifdef __GLIBC__
#include <malloc.h>
#endif

void udec_memory_policy(void)
{
#ifdef __GLIBC__
    static int done = 0;
    if (done) return;
    done = 1;
    mallopt(M_MMAP_THRESHOLD, 256 * 1024);
#endif
}
