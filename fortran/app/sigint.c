/* The stop signals of the standalone `adore` program: SIGINT (Ctrl-C), SIGTERM and SIGHUP,
 * the one piece of process state outside the engine (docs/dynamics.md, "The run").
 *
 * The first of them only records its number, which the time loop's progress callback
 * (fortran/app/main.f90) reads after each step, so the run stops there with its files
 * consistent; the program then ends by that signal itself (adore_signal_exit: the default
 * action), so its parent sees a death by the signal (a shell: exit status 128 + its
 * number).  A signal the process was started with ignored (nohup: SIGHUP; a background
 * job: SIGINT) stays ignored.  The SIGINT handler reverts to the default once it ran
 * (SA_RESETHAND): a second Ctrl-C ends the process at once, leaving the print being
 * written as <out>.part, never a file posing as complete.  A repeated SIGTERM or SIGHUP
 * (a closing terminal may send SIGHUP twice) only repeats the request. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t received = 0;

static void on_stop_signal(int sig)
{
    if (received == 0)
        received = sig;
}

static void install(int sig, int flags)
{
    struct sigaction old, sa;
    if (sigaction(sig, NULL, &old) == 0 && old.sa_handler == SIG_IGN)
        return;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = flags;
    sigaction(sig, &sa, NULL);
}

/* Install the handlers (called once, first thing in the program). */
void adore_signals_install(void)
{
    install(SIGINT, SA_RESETHAND);
    install(SIGHUP, 0);
    install(SIGTERM, 0);
}

/* The number of the first stop signal received, 0 while none came. */
int adore_signal_received(void)
{
    return received;
}

/* Which stop signal came first: 0 none, 1 SIGINT, 2 SIGTERM, 3 SIGHUP (the program's
 * names for them, whatever their numbers). */
int adore_signal_kind(void)
{
    switch (received) {
    case 0:
        return 0;
    case SIGINT:
        return 1;
    case SIGTERM:
        return 2;
    case SIGHUP:
        return 3;
    default:
        return 0;
    }
}

/* End the process by signal `sig` (its default action, normally termination); should the
 * signal not end it (its default ignored, a blocked mask), exit with status 128 + sig. */
void adore_signal_exit(int sig)
{
    struct sigaction sa;
    sigset_t set;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, NULL);
    sigemptyset(&set);
    sigaddset(&set, sig);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
    raise(sig);
    _exit(128 + sig);
}
