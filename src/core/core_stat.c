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

/* Entries of folder `dir` whose name starts with `prefix`: their number;
 * the first one's name is copied into `first` (size `nfirst`). */
int udec_count_prefixed(const char *dir, const char *prefix, char *first, int nfirst)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    size_t n = strlen(prefix);
    int count = 0;
    if (nfirst > 0) first[0] = '\0';
    if (d == NULL) return 0;
    while ((e = readdir(d)) != NULL) {
        if (strncmp(e->d_name, prefix, n) != 0) continue;
        if (count == 0 && nfirst > 0) {
            strncpy(first, e->d_name, (size_t)nfirst - 1);
            first[nfirst - 1] = '\0';
        }
        count++;
    }
    closedir(d);
    return count;
}

/* Entries of folder `dir` whose name equals `name` but for letter case
 * (CALL TUNNEL.DAT of a deck written under DOS, on a case-sensitive file
 * system): their number; the first one's name is copied into `first`. */
int udec_count_case_matches(const char *dir, const char *name, char *first, int nfirst)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int count = 0;
    if (nfirst > 0) first[0] = '\0';
    if (d == NULL) return 0;
    while ((e = readdir(d)) != NULL) {
        if (strcasecmp(e->d_name, name) != 0) continue;
        if (count == 0 && nfirst > 0) {
            strncpy(first, e->d_name, (size_t)nfirst - 1);
            first[nfirst - 1] = '\0';
        }
        count++;
    }
    closedir(d);
    return count;
}

/* 1 when standard output is a terminal (the progress line of CYCLE and RUN). */
#include <unistd.h>
int udec_stdout_isatty(void)
{
    return isatty(STDOUT_FILENO) ? 1 : 0;
}
