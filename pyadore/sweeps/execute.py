"""Where the cases of a sweep run: a local process pool or a Dask distributed cluster.

:func:`run_case` is the worker: it runs one case deck in a private temporary folder and
returns the print text and key results (it never raises and writes nothing the client
reads), so the client writes every file of the sweep folder itself, whichever backend ran
the case.  The local pool starts its worker processes once per sweep, each a fresh
interpreter (``python -m pyadore.sweeps.worker``, jobs and results as JSON lines on its
pipes) that loads the engine extension itself: nothing of the client's state is copied
by a fork (its threads, the Fortran run-time), and unlike multiprocessing's ``spawn`` the
worker never re-imports the client's ``__main__`` (a script without a main guard, stdin).
A worker that dies is known by the one case it was running.
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path
from typing import Callable, Iterable

__all__ = ["run_case", "run_local", "run_dask", "WorkerPool"]


def _guide(deck_text: str) -> str:
    """The race guiding the cage of a case deck: "outer" for Rec 7.0's first guide type 1,
    else "inner" (type 2, and decks without guide lands)."""
    from ..deck import parse_text

    try:
        deck, _problems = parse_text(deck_text, "case")
        return "outer" if deck.get("7.0", "guide_type[1]") == 1 else "inner"
    except Exception:  # an unreadable deck fails in the run itself, with its own message
        return "inner"


def _host() -> str:
    """This machine's host name (the socket module's gethostname without importing it: a
    few ms of every worker's start-up; os.uname where there is one)."""
    if hasattr(os, "uname"):
        return os.uname().nodename
    import socket

    return socket.gethostname()


def run_case(case_id: str, deck_text: str, steps: int | None, options: dict | None = None) -> dict:
    """Run one case deck (text) and return ``{case, status, error, notes, duration_s,
    print_text, history_text, results_nc, results, worker, tmp_deck, tmp_print,
    incomplete_text, incomplete_history}``: ``history_text`` the plot-data file of a run with
    time steps, ``results_nc`` its netCDF results file (base64; docs/results.md), ``results``
    the key results of the last printed step and the time averages over the last shaft
    revolution (:func:`pyadore.sweeps.results.mean_results`).
    ``status`` is ``ok``, ``invalid`` (the deck validator's problems, before any run; the
    message names the worker's ``tmp_deck``), ``input-error`` (the engine refused the deck),
    ``engine-failure`` or ``error`` (anything else, e.g. a print file that does not read).  A failed run that
    kept its print and plot-data file (a time integration that stopped early) returns their
    texts as ``incomplete_text`` and ``incomplete_history``: the worker's folder is removed,
    the client keeps them in the case folder (``tmp_deck`` and ``tmp_print``: the paths
    the message names in the worker's folder).  options: the run options of every case
    (:func:`pyadore.run`'s keywords, the engine's option table).  Never raises."""
    import tempfile

    start = time.perf_counter()
    out = {"case": case_id, "status": "ok", "error": "", "notes": [], "print_text": None, "results": {},
           "history_text": None, "results_nc": None,
           "worker": f"{_host()}:{os.getpid()}", "tmp_deck": "", "tmp_print": "",
           "incomplete_text": None, "incomplete_history": None}
    try:
        from ..api import run
        from ..deck import check_deck
        from ..errors import AdoreEngineError, AdoreInputError
        from ..printout import PrintFormatError, read_print
        from .results import key_results, mean_results

        with tempfile.TemporaryDirectory(prefix="pyadore-case-") as tmp:
            deck = Path(tmp) / "deck.inp"
            out["tmp_deck"] = str(deck)
            deck.write_text(deck_text, encoding="utf-8")
            prt = Path(tmp) / "case.prt"
            out["tmp_print"] = str(prt)
            _, problems = check_deck(deck)  # here, in parallel, not in the client's serial loop
            if problems:
                out.update(status="invalid", error="\n".join(p.format() for p in problems)
                           + f"\n{deck}: {len(problems)} problem(s)")
                out["duration_s"] = time.perf_counter() - start
                return out
            try:
                # the sweep has its own progress bar; one thread a case unless the sweep's options
                # say otherwise (its workers share the cores: docs/dynamics.md, "Threads")
                result = run(deck, steps=steps, out=prt, progress=False, **{"threads": 1, **(options or {})})
                out["notes"] = list(result.notes)
                # plain tables of the steps: the worker needs no pandas for a run without time steps
                out["results"] = key_results(read_print(prt, frames=False, echo=False))
                # the averages from the run's arrays: no xarray in the worker; the guide race
                # (a second parse of the deck) only for a run that has results to average
                if result.arrays is not None:
                    out["results"].update(mean_results(result.arrays, guide=_guide(deck_text)))
                else:
                    out["results"].update(mean_results(None))
                out["print_text"] = prt.read_text(encoding="utf-8", errors="replace")
                if result.history_path is not None:
                    out["history_text"] = result.history_path.read_text(encoding="utf-8", errors="replace")
                if result.results_path is not None:
                    import base64

                    out["results_nc"] = base64.b64encode(result.results_path.read_bytes()).decode("ascii")
            except PrintFormatError as exc:  # the engine's own print does not read: not the deck's fault
                out.update(status="error", error=f"the case's print file does not read: {exc}", results={},
                           print_text=None)
            except AdoreInputError as exc:
                out.update(status="input-error", error=str(exc))
            except AdoreEngineError as exc:
                out.update(status="engine-failure", error=str(exc))
                kept = getattr(exc, "print_path", None)
                if kept is not None and Path(kept).is_file():
                    from ..timehistory import history_path

                    out["incomplete_text"] = Path(kept).read_text(encoding="utf-8", errors="replace")
                    hist = history_path(kept)
                    if hist.is_file():
                        out["incomplete_history"] = hist.read_text(encoding="utf-8", errors="replace")
    except Exception as exc:  # a case's failure is a row of the manifest, never the sweep's end
        out.update(status="error", error=f"{type(exc).__name__}: {exc}", print_text=None, results={})
    out["duration_s"] = time.perf_counter() - start
    return out


def _died(case_id: str, why: str) -> dict:
    return {"case": case_id, "status": "error", "error": why, "notes": [], "print_text": None, "results": {},
            "history_text": None, "results_nc": None,
            "worker": "", "tmp_deck": "", "tmp_print": "", "incomplete_text": None, "incomplete_history": None,
            "duration_s": float("nan")}


def _start_process():
    import subprocess

    return subprocess.Popen([sys.executable, "-m", "pyadore.sweeps.worker"], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True, encoding="utf-8")


class _Worker:
    """One local worker process (:mod:`pyadore.sweeps.worker`), started on demand and
    restarted after a crash; :meth:`serve` feeds it one sweep's jobs in a thread."""

    def __init__(self) -> None:
        import threading

        self.proc = None
        self.interrupted = threading.Event()  # set by kill(): serve() ends without a report

    def start(self) -> None:
        """Start the process unless it runs (it boots while the client prepares cases)."""
        if self.proc is None or self.proc.poll() is not None:
            self.proc = _start_process()

    def serve(self, jobs, results) -> None:
        """Run jobs from the queue ``jobs`` until a None; each result, then a None, to ``results``.
        After :meth:`kill` (the sweep was interrupted) it ends quietly: the process it was
        waiting on is gone on purpose, not a crash to report, and none is started again."""
        while True:
            job = jobs.get()
            if job is None or self.interrupted.is_set():
                break
            self.start()
            proc = self.proc  # kill() may set self.proc to None from the client's thread
            try:
                proc.stdin.write(json.dumps(list(job)) + "\n")
                proc.stdin.flush()
                line = proc.stdout.readline()
            except (OSError, ValueError, AttributeError):
                line = ""
            if self.interrupted.is_set():
                break
            if not line:  # the process died on this job: report it, go on with a fresh one
                code = proc.poll()
                results.put(_died(job[0], f"the worker process died while running this case (exit status "
                                          f"{code}): a crash of the engine"))
                self.stop()
                continue
            results.put(json.loads(line))
        results.put(None)

    def stop(self) -> None:
        """Close the worker's stdin (it exits when idle) and end it if it does not."""
        if self.proc is None:
            return
        try:
            self.proc.stdin.close()
        except OSError:
            pass
        try:
            self.proc.wait(timeout=5)
        except Exception:
            self.proc.kill()
        self.proc = None

    def kill(self) -> None:
        """End the worker now (the sweep was interrupted)."""
        self.interrupted.set()
        proc, self.proc = self.proc, None
        if proc is None:
            return
        proc.kill()
        try:
            proc.wait(timeout=5)
        except Exception:
            pass


class WorkerPool:
    """Local worker processes that stay warm across sweeps: ``with WorkerPool(2) as pool:``
    then ``pyadore.sweep(..., workers=pool)`` as often as needed.  Each process boots once
    (the interpreter, numpy, the engine: about 0.4 s of CPU, docs/sweeps.md "Scaling"), at
    its first sweep, instead of at every sweep; :meth:`close` (or the end of the ``with``)
    ends them, and they end by themselves when this process exits."""

    def __init__(self, workers: int) -> None:
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
        self.size = workers
        self._workers = [_Worker() for _ in range(workers)]

    def __enter__(self) -> "WorkerPool":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def __repr__(self) -> str:
        running = sum(w.proc is not None for w in self._workers)
        return f"WorkerPool({self.size}, {running} running)"

    def close(self) -> None:
        """End the worker processes (a later sweep on this pool starts them again)."""
        for w in self._workers:
            w.stop()


def run_local(jobs: Iterable[tuple], workers, on_result: Callable[[dict], None], count: int) -> None:
    """Run ``jobs`` (tuples of :func:`run_case` arguments, at most ``count``) on ``workers``
    local worker processes (a number: started for this sweep when the first job comes, so
    they boot while the client prepares the next ones, and ended after it; or a
    :class:`WorkerPool`, whose processes stay warm); ``on_result`` gets each
    :func:`run_case` result, in this thread, as it arrives.  A case whose process dies (a
    crash in the engine) is reported as an error and a fresh process takes the next case;
    the others are not affected."""
    import queue
    import threading

    own = not isinstance(workers, WorkerPool)
    pool = WorkerPool(max(1, min(workers, count))) if own else workers
    pending: queue.Queue = queue.Queue()
    results: queue.Queue = queue.Queue()
    used: list[_Worker] = []
    try:
        for job in jobs:
            if not used:
                used = pool._workers[:max(1, min(pool.size, count))]
                for w in used:
                    w.interrupted.clear()  # a pool's worker serves again after an interrupted sweep
                    w.start()
                    threading.Thread(target=w.serve, args=(pending, results), daemon=True).start()
            pending.put(job)
        for _ in used:
            pending.put(None)  # no more jobs: each worker's thread ends after its last one
        running = len(used)
        while running:
            try:
                res = results.get(timeout=0.5)
            except queue.Empty:
                continue
            if res is None:
                running -= 1
                continue
            on_result(res)
    except BaseException:
        while True:  # nothing more is started
            try:
                pending.get_nowait()
            except queue.Empty:
                break
        for w in used:
            pending.put(None)
            w.kill()
        raise
    finally:
        if own:
            pool.close()


def run_dask(jobs: Iterable[tuple], scheduler, on_result: Callable[[dict], None]) -> None:
    """Run ``jobs`` on a Dask distributed cluster: ``scheduler`` is its address
    (``tcp://host:8786``) or a ``distributed.Client``.  The workers need pyadore installed."""
    from .grid import SweepError

    try:
        from distributed import Client, as_completed
    except ImportError:
        raise SweepError("--scheduler needs dask.distributed: pip install 'pyadore[dask]'") from None
    own = not isinstance(scheduler, Client)
    if own:
        try:
            client = Client(scheduler, timeout="20s", set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise SweepError(f"--scheduler {scheduler}: cannot reach the Dask scheduler ({exc})") from None
    else:
        client = scheduler
    futures = {}
    try:
        token = os.urandom(4).hex()
        for job in jobs:  # submitted as the client prepares them
            futures[client.submit(run_case, *job, key=f"pyadore-sweep-{job[0]}-{token}", pure=False)] = job
        if not futures:
            return
        for fut in as_completed(list(futures), loop=client.loop):
            job = futures[fut]
            try:
                res = fut.result()
            except Exception as exc:  # e.g. KilledWorker: the case's worker died
                res = _died(job[0], f"the Dask worker failed on this case ({type(exc).__name__}: {exc})")
            on_result(res)
    except BaseException:
        if futures:
            client.cancel(list(futures))
        raise
    finally:
        if own:
            client.close()
