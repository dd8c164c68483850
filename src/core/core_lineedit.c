/* Line editing at the UDEC> prompt (issue 24): when standard input is a
 * terminal and udec was built with libedit (Debian's libedit-dev, BSD
 * licence), lines are read through its readline interface: cursor keys,
 * history of the session (up and down arrows) and tab completion of the
 * command names and keywords the command registry holds. Without libedit, or
 * when input is a pipe or file, udec_lineedit_active() is 0 and the
 * interpreter reads plain lines as before. */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifdef UDEC_HAVE_LIBEDIT
#include <stdio.h>
#include <editline/readline.h>
#endif

static char **words = NULL;     /* completion words, upper case */
static int nwords = 0;
static int capwords = 0;

/* Add one completion word (a command or keyword name); duplicates ignored. */
void udec_lineedit_add_word(const char *word, int length)
{
    char *copy;
    int i;
    if (length <= 0) return;
    for (i = 0; i < nwords; i++)
        if ((int)strlen(words[i]) == length && strncmp(words[i], word, (size_t)length) == 0) return;
    if (nwords == capwords) {
        int cap = capwords ? 2 * capwords : 256;
        char **grown = realloc(words, (size_t)cap * sizeof *words);
        if (!grown) return;
        words = grown;
        capwords = cap;
    }
    copy = malloc((size_t)length + 1);
    if (!copy) return;
    for (i = 0; i < length; i++) copy[i] = (char)toupper((unsigned char)word[i]);
    copy[length] = '\0';
    words[nwords++] = copy;
}

#ifdef UDEC_HAVE_LIBEDIT
/* readline's generator: the next word that starts with `text` (any case),
 * written in the case of what was typed (lower case when its first letter
 * is). */
static char *complete_word(const char *text, int state)
{
    static int next;
    size_t n = strlen(text);
    if (state == 0) next = 0;
    while (next < nwords) {
        const char *w = words[next++];
        size_t k;
        int match = strlen(w) >= n;
        for (k = 0; match && k < n; k++)
            if (toupper((unsigned char)text[k]) != w[k]) match = 0;
        if (match) {
            char *out = strdup(w);
            if (out && n > 0 && islower((unsigned char)text[0]))
                for (k = 0; out[k]; k++) out[k] = (char)tolower((unsigned char)out[k]);
            return out;
        }
    }
    return NULL;
}

static char **complete(const char *text, int start, int end)
{
    (void)start;
    (void)end;
    rl_attempted_completion_over = 1;   /* no file-name completion */
    return rl_completion_matches(text, complete_word);
}
#endif

/* 1 when lines are read through libedit: built with it and stdin is a tty. */
int udec_lineedit_active(void)
{
#ifdef UDEC_HAVE_LIBEDIT
    static int initialised = 0;
    if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) return 0;
    if (!initialised) {
        rl_readline_name = "udec";
        rl_attempted_completion_function = complete;
        initialised = 1;
    }
    return 1;
#else
    return 0;
#endif
}

/* Read one line with `prompt` (length plen) into buf (capacity cap): returns
 * the line's length (cut at cap), or -1 at end of input (Ctrl-D). A non-blank
 * line joins the session's history. */
int udec_lineedit_read(const char *prompt, int plen, char *buf, int cap)
{
#ifdef UDEC_HAVE_LIBEDIT
    char p[256];
    char *line;
    int n;
    if (plen < 0) plen = 0;
    if (plen > (int)sizeof p - 1) plen = (int)sizeof p - 1;
    memcpy(p, prompt, (size_t)plen);
    p[plen] = '\0';
    line = readline(p);
    if (!line) return -1;
    n = (int)strlen(line);
    if (n > cap) n = cap;
    memcpy(buf, line, (size_t)n);
    if (strspn(line, " \t") < strlen(line)) add_history(line);
    free(line);
    return n;
#else
    (void)prompt;
    (void)plen;
    (void)buf;
    (void)cap;
    return -1;
#endif
}
