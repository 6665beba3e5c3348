/* Ctrl-C of the standalone `adore` program: the one piece of process state outside the
 * engine (docs/dynamics.md, "The run").  The first SIGINT only sets a flag, which the time
 * loop's progress callback (fortran/app/main.f90) reads after each step, so the run stops
 * there with its print kept and marked "*** RUN INCOMPLETE"; the handler then reverts to
 * the default (SA_RESETHAND), so a second Ctrl-C ends the process at once (its print then
 * stays an unfinished <out>.part, never a file posing as complete). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <string.h>

static volatile sig_atomic_t interrupted = 0;

static void on_sigint(int sig)
{
    (void)sig;
    interrupted = 1;
}

/* Install the handler (called once by the program before the run). */
void adore_sigint_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &sa, NULL);
}

/* 1 once a SIGINT arrived, else 0. */
int adore_sigint_received(void)
{
    return interrupted;
}
