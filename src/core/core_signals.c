/* Interrupts (issue 20; the manual's ESC key, Section 2.2): SIGINT (Ctrl-C)
 * and SIGTERM only raise a flag here. The cycle loops poll it and end the
 * running CYCLE or RUN at the end of the current step; the interpreter then
 * goes back to the prompt, or (batch run, SIGTERM) skips the rest of the
 * input and exits with 128 + the signal number. A second SIGINT within two
 * seconds of the first quits at once, removing the temporary file of a SAVE
 * under way; so does SIGINT or SIGTERM while the program only waits at the
 * UDEC> prompt (nothing is running that could stop by itself).
 *
 * Signals are a property of the process, so this state is file-static; the
 * handler touches only sig_atomic_t flags and calls async-signal-safe
 * functions (clock_gettime, write, unlink, _exit). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static volatile sig_atomic_t pending_signal = 0;  /* 0 or the signal number */
static volatile sig_atomic_t busy = 0;            /* a command is executing */
static volatile sig_atomic_t interactive = 0;
static volatile sig_atomic_t temp_set = 0;
static char temp_path[4096];
static volatile sig_atomic_t sigint_seen = 0;
static struct timespec last_sigint;

static void say(const char *text)
{
    ssize_t ignored = write(STDOUT_FILENO, text, strlen(text));
    (void)ignored;
}

static void quit_now(int sig)
{
    if (temp_set)
        unlink(temp_path);
    say("\n*** udec quits (interrupted).\n");
    _exit(128 + sig);
}

static void on_signal(int sig)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    if (sig == SIGINT && sigint_seen) {
        double since = (double)(now.tv_sec - last_sigint.tv_sec)
                     + 1e-9 * (double)(now.tv_nsec - last_sigint.tv_nsec);
        if (since <= 2.0)
            quit_now(sig);
    }
    if (sig == SIGINT) {
        last_sigint = now;
        sigint_seen = 1;
    }
    if (!busy && interactive) {
        if (sig != SIGINT)
            quit_now(sig);
        pending_signal = sig;
        say("\n(Ctrl-C: nothing is running; press it again within 2 s to quit udec)\n");
        return;
    }
    if (pending_signal != SIGTERM)
        pending_signal = sig;
    if (sig == SIGINT)
        say("\n(Ctrl-C: stopping at the end of the current step; press it again "
            "within 2 s to quit udec)\n");
}

void udec_interrupt_install(int is_interactive)
{
    struct sigaction action;
    interactive = is_interactive;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    /* a read at the prompt goes on after the handler returns */
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);
}

int udec_interrupt_pending(void) { return pending_signal; }

void udec_interrupt_clear(void) { pending_signal = 0; }

void udec_interrupt_busy(int on) { busy = on; }

/* The temporary file a SAVE is writing (empty: none). */
void udec_interrupt_temporary(const char *path)
{
    temp_set = 0;
    if (path[0] == '\0')
        return;
    strncpy(temp_path, path, sizeof temp_path - 1);
    temp_path[sizeof temp_path - 1] = '\0';
    temp_set = 1;
}
