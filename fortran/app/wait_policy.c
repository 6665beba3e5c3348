/* The OpenMP wait policy of the standalone `adore` program (docs/performance.md, "Threads"):
 * OMP_WAIT_POLICY=PASSIVE with GOMP_SPINCOUNT=3000 unless the environment sets either.
 * Between the derivative calls' parallel loops libgomp's default lets its threads spin
 * (300 000 rounds) instead of sleeping; on a machine whose cores are busy with other work a
 * spinning thread holds a core the run's other thread needs, and a 2-thread run took 7-35
 * times the wall time of a 1-thread run (docs/dynamics.md).  Threads that sleep at once pay
 * a futex wake-up, on a virtual machine a halted virtual CPU's return (~30 us), at each of a
 * run's ~24 000 loops.  A short spin (3 000 rounds, a few microseconds: the serial work
 * between two loops of a derivative call) keeps the worker awake across that gap and then
 * lets it sleep: Appendix C on 2 threads 1.42-1.47 s against 1.86-1.95 s passive on the idle
 * machine, the same as passive with one or two other busy processes (session 20).
 * libgomp reads its environment in its own initialiser, before main, and a setenv before it
 * would be undone by the C library's initialiser (it resets environ to the process's
 * original array).  So this function, in the executable's .preinit_array (run by the
 * dynamic loader before any shared library's initialiser), starts the program again with the
 * variables added to its environment: the same process (pid, signals, open files), one exec
 * more (about a millisecond).  If that exec fails (no /proc), the program runs on as it is.
 * pyadore/__init__.py sets the same default for the Python extension. */
#define _POSIX_C_SOURCE 200809L
#include <stddef.h>
#include <string.h>
#include <unistd.h>

static void adore_wait_policy(int argc, char **argv, char **envp)
{
    static char policy[] = "OMP_WAIT_POLICY=PASSIVE";
    static char spin[] = "GOMP_SPINCOUNT=3000";
    size_t n = 0;
    (void)argc;
    if (envp == NULL || argv == NULL)
        return;
    for (char **e = envp; *e != NULL; ++e, ++n)
        if (strncmp(*e, "OMP_WAIT_POLICY=", 16) == 0 || strncmp(*e, "GOMP_SPINCOUNT=", 15) == 0)
            return;
    {
        char *env[n + 3];
        for (size_t i = 0; i < n; ++i)
            env[i] = envp[i];
        env[n] = policy;
        env[n + 1] = spin;
        env[n + 2] = NULL;
        execve("/proc/self/exe", argv, env);
    }
}

__attribute__((section(".preinit_array"), used)) static void (*const adore_preinit)(int, char **, char **) =
    adore_wait_policy;
