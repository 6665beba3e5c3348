"""The files of a sweep folder, each written atomically (a temporary file, then a rename).

Layout of ``DIR``::

    sweep.json            what the sweep is (base deck hash, varied fields and values, steps)
    manifest.json         every case: parameters, status, duration, error, when and where it ran
    summary.csv           one row per case: varied parameters, status, key results
    events.log            one line per finished case (appended; a rerun adds lines)
    cases/<case>/deck.inp the case deck (base deck with the varied fields changed)
    cases/<case>/case.prt the case's print file, present only when the run finished
    cases/<case>/case.hist.csv, case.nc
                          its time histories and full results (docs/results.md) when the run
                          has time steps, written before the print
    cases/<case>/result.json  status, message and key results; a case counts as done only
                          when this says ``ok`` and its print file is present
    cases/<case>/incomplete.prt, incomplete.hist.csv
                          a failed case's print and plot-data file when its run kept them
                          (a time integration that stopped early, marked incomplete): the
                          files its message names

A killed sweep leaves at most temporary files (``.<name>.tmp-*``), removed by the next run.
"""

from __future__ import annotations

import itertools
import json
import os
import tempfile
from pathlib import Path

__all__ = ["SWEEP_FILE", "MANIFEST", "SUMMARY", "EVENTS", "CASES", "CASE_DECK", "CASE_PRINT", "CASE_HISTORY",
           "CASE_RESULTS", "CASE_RESULT", "CASE_INCOMPLETE", "CASE_INCOMPLETE_HISTORY", "write_atomic", "write_atomic_many",
           "flush_file", "read_json", "remove_stale_temporaries", "append_event"]

SWEEP_FILE = "sweep.json"
MANIFEST = "manifest.json"
SUMMARY = "summary.csv"
EVENTS = "events.log"
CASES = "cases"
CASE_DECK = "deck.inp"
CASE_PRINT = "case.prt"
CASE_HISTORY = "case.hist.csv"
CASE_RESULTS = "case.nc"
CASE_RESULT = "result.json"
CASE_INCOMPLETE = "incomplete.prt"
CASE_INCOMPLETE_HISTORY = "incomplete.hist.csv"
_TMP_TAG = ".tmp-"


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


#: permissions of the files written (mkstemp makes them private; these are ordinary files)
_MODE = 0o666 & ~_umask()


def write_atomic(path: Path, text: str | bytes, durable: bool = True) -> None:
    """Write ``text`` (or bytes) to ``path`` so that ``path`` is either the old file or the
    whole new one; ``durable``: flushed to the disk (fsync) before it replaces the old file.
    The temporary file (``.<name>.tmp-<pid>-<n>`` beside it, created exclusively with the
    ordinary files' permissions) is written by one ``os.write`` loop, without a text stream,
    a random name or a chmod: the sweep's client writes three files a case while it shares the
    cores with the workers (docs/sweeps.md, "Scaling")."""
    path = Path(path)
    data = text if isinstance(text, bytes) else text.encode("utf-8")
    fd, tmp = _create_temporary(path)
    try:
        try:
            view = memoryview(data)
            while view:
                view = view[os.write(fd, view):]
            if durable:
                os.fsync(fd)
        finally:
            os.close(fd)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def write_atomic_many(files: list[tuple[Path, str | bytes]]) -> None:
    """Write several files as :func:`write_atomic` does, each flushed to the disk (fsync)
    before it replaces its old file, with their flushes at the same time (one thread each
    but the first; fsync releases the GIL, and the file system commits them together): the
    sweep's end writes manifest.json and summary.csv, and the command waits for their flushes
    (about one disk round trip instead of two; docs/sweeps.md, "Scaling").  Renamed in the
    order given, after every flush; an error in a write or a flush renames none and removes
    the temporary files."""
    import threading

    made: list[tuple[int, str, Path]] = []
    open_fds = True
    try:
        for path, text in files:
            path = Path(path)
            fd, tmp = _create_temporary(path)
            made.append((fd, tmp, path))
            view = memoryview(text if isinstance(text, bytes) else text.encode("utf-8"))
            while view:
                view = view[os.write(fd, view):]
        errors: list[BaseException] = []

        def flush(fd: int) -> None:
            try:
                os.fsync(fd)
            except BaseException as exc:  # noqa: BLE001 - raised again by the caller's thread
                errors.append(exc)

        threads = [threading.Thread(target=flush, args=(fd,)) for fd, _, _ in made[1:]]
        for t in threads:
            t.start()
        if made:
            flush(made[0][0])
        for t in threads:
            t.join()
        if errors:
            raise errors[0]
        open_fds = False
        for fd, _, _ in made:
            os.close(fd)
        for _, tmp, path in made:
            os.replace(tmp, path)
    except BaseException:
        for fd, tmp, _ in made:
            if open_fds:
                try:
                    os.close(fd)
                except OSError:
                    pass
            try:
                os.unlink(tmp)  # (gone already when it was renamed)
            except OSError:
                pass
        raise


_FLAGS = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_BINARY", 0)
_counter = itertools.count()


def _create_temporary(path: Path) -> tuple[int, str]:
    """A new temporary file beside ``path`` (its descriptor and name), with the permissions of
    an ordinary file (0o666 less the umask), never one that exists (O_EXCL; a name taken, e.g.
    by a process of the same pid in another container, is passed over)."""
    folder = os.fspath(path.parent)
    for _ in range(100):
        tmp = os.path.join(folder, f".{path.name}{_TMP_TAG}{os.getpid()}-{next(_counter)}")
        try:
            return os.open(tmp, _FLAGS, 0o666), tmp
        except FileExistsError:
            continue
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}{_TMP_TAG}", dir=folder)
    os.chmod(tmp, _MODE)
    return fd, tmp


def flush_file(path: Path) -> None:
    """Flush ``path``'s content to the disk (fsync), e.g. a file :func:`write_atomic` wrote
    with ``durable=False``.  A file that is gone is left so."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        return
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def read_json(path: Path):
    """The JSON content of ``path``, or None when it is absent or unreadable."""
    try:
        return json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def remove_stale_temporaries(root: Path) -> int:
    """Remove the temporary files a killed sweep left under ``root``; returns how many."""
    n = 0
    for tmp in Path(root).rglob(f".*{_TMP_TAG}*"):
        try:
            tmp.unlink()
            n += 1
        except OSError:
            pass
    return n


def append_event(root: Path, line: str) -> None:
    """Append a line (or several, joined by newlines) to ``events.log`` (one write call, so
    the lines are whole or absent unless the process dies within that call)."""
    with open(Path(root) / EVENTS, "a", encoding="utf-8") as fh:
        fh.write(line.rstrip("\n") + "\n")
