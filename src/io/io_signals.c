/* A file size limit (ulimit -f) is a "disk full" that arrives as SIGXFSZ,
 * whose default action (and the gfortran runtime's handler) ends the program.
 * Ignoring it makes the write fail with EFBIG instead, so SAVE reports the
 * error and keeps the older file like any other failed write. */
#include <signal.h>

void udec_ignore_file_size_signal(void)
{
#ifdef SIGXFSZ
    signal(SIGXFSZ, SIG_IGN);
#endif
}
