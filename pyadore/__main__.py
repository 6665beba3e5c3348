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
    try:
        import sys

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
    command()


if __name__ == "__main__":
    main()
