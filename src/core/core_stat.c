/* What a path names (core_files: output targets and CALLed files), and the
 * temporaries an unfinished SAVE left beside a file. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* 0 no such file, 1 regular file, 2 folder, 3 character device, 4 block
 * device, 5 FIFO, 6 socket, 7 other, -1 cannot be examined (permission). */
int udec_file_kind(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return (errno == ENOENT || errno == ENOTDIR) ? 0 : -1;
    if (S_ISREG(st.st_mode)) return 1;
    if (S_ISDIR(st.st_mode)) return 2;
    if (S_ISCHR(st.st_mode)) return 3;
    if (S_ISBLK(st.st_mode)) return 4;
    if (S_ISFIFO(st.st_mode)) return 5;
    if (S_ISSOCK(st.st_mode)) return 6;
    return 7;
}

/* Does entry name `e` match `key`: starts with it (prefix) or equals it
 * but for letter case? */
static int starts_with(const char *e, const char *key)
{
    return strncmp(e, key, strlen(key)) == 0;
}

static int same_but_case(const char *e, const char *key)
{
    return strcasecmp(e, key) == 0;
}

/* Entries of folder `dir` that `match` `key`: their number; the first
 * one's name is copied into `first` (size `nfirst`). */
static int count_matching(const char *dir, const char *key, int (*match)(const char *, const char *),
                          char *first, int nfirst)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int count = 0;
    if (nfirst > 0) first[0] = '\0';
    if (d == NULL) return 0;
    while ((e = readdir(d)) != NULL) {
        if (!match(e->d_name, key)) continue;
        if (count == 0 && nfirst > 0) {
            strncpy(first, e->d_name, (size_t)nfirst - 1);
            first[nfirst - 1] = '\0';
        }
        count++;
    }
    closedir(d);
    return count;
}

/* Entries of folder `dir` whose name starts with `key` (how 0: the
 * temporaries a SAVE left) or equals it but for letter case (how 1: CALL
 * TUNNEL.DAT of a deck written under DOS, on a case-sensitive file system),
 * as count_matching. */
int udec_count_entries(const char *dir, const char *key, int how, char *first, int nfirst)
{
    return count_matching(dir, key, how == 0 ? starts_with : same_but_case, first, nfirst);
}

/* 1 when standard output is a terminal (the progress line of CYCLE and RUN). */
#include <unistd.h>
int udec_stdout_isatty(void)
{
    return isatty(STDOUT_FILENO) ? 1 : 0;
}
