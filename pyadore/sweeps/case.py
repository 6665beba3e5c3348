"""One case of a sweep, run where its worker is: :func:`run_case` (the local worker process,
:mod:`.worker`, or a Dask worker, :mod:`.execute`).  It runs the case deck in a private
temporary folder and returns the print text and key results; it never raises and writes
nothing the client reads: the client writes every file of the sweep folder itself."""

from __future__ import annotations

import os
import time
from pathlib import Path

__all__ = ["run_case"]


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
    incomplete_text, incomplete_history, timing}``: ``timing`` when the case started and
    its parts ended (``start``, ``checked``, ``engine``, ``results``, ``end``; time.time())
    and its CPU time ``cpu_s``, for the bench's budget (bench/sweep_bench.py; not recorded);
    ``history_text`` the plot-data file of a run with time steps, ``results_nc`` its netCDF
    results file (base64; docs/results.md), ``results`` the key results of the last printed
    step and the time averages over the last shaft revolution
    (:func:`pyadore.sweeps.results.mean_results`).
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
    cpu = time.process_time()
    stamps = {"start": time.time()}  # when each part of the case ended (s since the epoch): the budget's
    out = {"case": case_id, "status": "ok", "error": "", "notes": [], "print_text": None, "results": {},
           "timing": stamps,
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
            stamps["checked"] = time.time()
            if problems:
                out.update(status="invalid", error="\n".join(p.format() for p in problems)
                           + f"\n{deck}: {len(problems)} problem(s)")
                out["duration_s"] = time.perf_counter() - start
                return out
            try:
                # the sweep has its own progress bar; one thread a case unless the sweep's options
                # say otherwise (its workers share the cores: docs/performance.md, "Threads")
                result = run(deck, steps=steps, out=prt, progress=False, **{"threads": 1, **(options or {})})
                stamps["engine"] = time.time()
                out["notes"] = list(result.notes)
                # plain tables of the steps: the worker needs no pandas for a run without time steps
                out["results"] = key_results(read_print(prt, frames=False, echo=False))
                # the averages from the run's arrays: no xarray in the worker; the guide race
                # (a second parse of the deck) only for a run that has results to average
                if result.arrays is not None:
                    out["results"].update(mean_results(result.arrays, guide=_guide(deck_text)))
                else:
                    out["results"].update(mean_results(None))
                stamps["results"] = time.time()
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
    stamps["end"] = time.time()
    stamps["cpu_s"] = time.process_time() - cpu  # the case's CPU time in the worker
    return out
