"""The ``pyadore`` command (``python -m pyadore``; the console script's entry point).

Its stop signals are caught first (pyadore/_signals.py), before the command line's modules
(click, the engine extension, numpy) are imported, so that a signal at any moment of the
command ends it with one line and never a traceback.  What remains before this runs is the
interpreter's own start (and, in a development install, meson-python's rebuild check on
the first import of pyadore): a SIGINT there is Python's KeyboardInterrupt.
"""

from __future__ import annotations


def main() -> None:
    """Run the ``pyadore`` command line."""
    from ._signals import exit_by_signal, hold_signals, install_command_handlers, raised_signal, set_phase, \
        signal_label

    set_phase("while starting: nothing done")
    install_command_handlers()
    import sys

    try:
        if sys.argv[1:2] == ["sweep"]:
            from .sweeps.execute import start_early

            # a local sweep's workers boot while the command's modules load (docs/sweeps.md, "Scaling")
            start_early(sys.argv[1:])
        from .cli import main as command
    except BaseException:
        # a stop signal while the command's modules load (a C extension may turn it into an
        # ImportError): nothing was done yet
        signum = raised_signal()
        if signum is None:
            raise
        hold_signals()
        try:
            import sys

            print(f"pyadore: stopped by {signal_label(signum)} while starting: nothing done", file=sys.stderr)
        except (OSError, ValueError):
            pass
        exit_by_signal(signum)
    set_phase("")
    if sys.argv[1:2] not in (["sweep"], ["run"]):
        command()
        return
    try:
        command()
    except SystemExit as exc:  # the command's end: every file written and closed (a sweep's workers ended)
        _exit_now(exc.code)


def _exit_now(code) -> None:
    """End the ``pyadore sweep`` or ``pyadore run`` command with exit status ``code`` (as
    SystemExit takes it) once its output is flushed, without the interpreter's clean-up:
    freeing the modules (a sweep's client: about 0.06 s of CPU; a run, which has numpy and the
    engine extension loaded: 35-65 ms of CPU and 55-130 ms of wall at load 3-4; docs/sweeps.md,
    "Scaling, eighteenth session") is time the user waits for and nothing else.  Every file is
    written and closed by then: a sweep's each atomically, its workers and their fork server ended; a run's print
    read back by the API once the engine closed it (the engine writes nothing to the standard
    streams: its messages come back as notes), its plot-data and netCDF files written and
    closed.  pyadore registers no atexit handler.  A stop signal or an unexpected exception
    does not come here: it ends the command as before."""
    import os
    import sys

    if code is None:
        status = 0
    elif isinstance(code, int):
        status = code
    else:  # a message (sys.exit("...")): printed as the interpreter prints it
        print(code, file=sys.stderr)
        status = 1
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, AttributeError):
            pass
    os._exit(status & 0xFF)  # as the interpreter: sys.exit(-1) is 255


if __name__ == "__main__":
    main()
