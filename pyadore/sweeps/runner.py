"""``pyadore.sweep``: run one deck over a grid of field values, resumable, failures isolated.

The client (this module) writes every file of the sweep folder (layout in
:mod:`.store`); the cases run on a local process pool or a Dask cluster
(:mod:`.execute`).  A rerun of the same sweep into the same folder keeps every finished
case and runs only the missing and failed ones.
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
from pathlib import Path

from ..deck import Deck, DeckError, format_deck, parse_text
from . import store
from .execute import run_dask, run_local
from .grid import Case, SweepError, Varied, case_deck_text, make_cases, parse_vary
from .results import RESULT_COLUMNS, key_results, mean_results

__all__ = ["sweep", "run_sweep", "read_summary", "read_summary_file", "summary_csv", "dispatch_order", "CostModel"]

#: While cases finish, manifest.json is rewritten after a case when the last rewrite is
#: MANIFEST_COST_FACTOR times its own duration and at least MANIFEST_MIN_INTERVAL (s) ago, and at
#: least every MANIFEST_INTERVAL (s): four times a second at most, at most 1/MANIFEST_COST_FACTOR
#: of the time for a large sweep (the file grows with the cases).  Each rewrite is followed by
#: the events.log lines of the cases it added, so the events log is never ahead of the
#: manifest, even in a sweep killed at any moment; both are written at the end.  Each case's own
#: result.json is what a resume reads.  (A rewrite after every case - a 30 kB file created and
#: renamed over the old one, about 0.4 ms of the client's CPU and the file system's write-back -
#: competed with two workers for the cores: docs/sweeps.md, "Scaling, nineteenth session".)
MANIFEST_INTERVAL = 1.0
MANIFEST_MIN_INTERVAL = 0.25
MANIFEST_COST_FACTOR = 20.0


def _vary_specs(vary) -> list[str]:
    """The varied fields as FIELD=V1,V2,... texts: from one such text, a list of them, or a
    dict {field: values} whose values are an iterable or one comma-separated text."""
    if isinstance(vary, str):
        return [vary]
    if isinstance(vary, dict):
        specs = []
        for name, values in vary.items():
            if isinstance(values, str):
                values = [v for v in values.split(",")]
            elif isinstance(values, (int, float)):
                values = [values]
            try:
                text = ",".join(str(v).strip() for v in values)
            except TypeError:
                raise SweepError(f"values of {name!r}: expected a list of numbers or a text 'V1,V2,...', "
                                 f"got {values!r}") from None
            specs.append(f"{name}={text}")
        return specs
    try:
        return [str(v) for v in vary]
    except TypeError:
        raise SweepError(f"vary: expected a dict {{field: values}}, a text 'FIELD=V1,V2,...' or a list of "
                         f"them, got {vary!r}") from None


def _sha256_hex(data: bytes) -> str:
    """The SHA-256 digest of ``data`` in hex (sweep.json's ``deck_sha256``), by CPython's own
    implementation where it has one: ``hashlib`` loads OpenSSL's library (``_hashlib``) on its
    import, 3-6 ms of the ``pyadore sweep`` client's path to its first job (docs/sweeps.md,
    "Scaling, nineteenth session"); the digest is the same."""
    try:
        from _sha256 import sha256  # CPython <= 3.11
    except ImportError:
        try:
            from _sha2 import sha256  # CPython >= 3.12
        except ImportError:
            from hashlib import sha256
    return sha256(data).hexdigest()


def _now() -> str:
    from datetime import datetime, timezone

    return datetime.now(timezone.utc).isoformat(timespec="milliseconds").replace("+00:00", "Z")


def _jsonable(value):
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


class _Sweep:
    """The state of one sweep folder while the sweep runs."""

    def __init__(self, deck_path: Path, base_text: str, varied: list[Varied], cases: list[Case],
                 out_dir: Path, steps: int | None, zip_values: bool, options: dict, base_deck=None):
        self.deck_path = deck_path
        self.base_text = base_text
        self.base_deck = base_deck  # parsed once; case_deck_text restores its values after each case
        self.varied = varied
        self.cases = cases
        self.root = out_dir
        self.steps = steps
        self.options = options
        self.definition = {
            "deck": str(deck_path),
            "deck_sha256": _sha256_hex(base_text.encode("utf-8")),
            "vary": [{"name": v.name, "records": list(v.records), "field": v.field, "unit": v.unit,
                      "values": list(v.values)} for v in varied],
            "zip": zip_values, "steps": steps, "options": options,
        }
        self.entries: dict[str, dict] = {}
        self._manifest_written = 0.0
        self._manifest_cost = 0.0      # how long the last manifest rewrite took (s)
        self._events: list[str] = []   # events.log lines of cases the manifest does not list yet
        #: case id -> (its entry when encoded, or None while pending; its manifest line; its status)
        self._manifest_lines: dict[str, tuple] = {}
        self._unflushed: Path | None = None  # sweep.json, written and not flushed yet
        #: the folder's cases/ made by this sweep: no case folder held a file before it
        #: (nothing to resume, no earlier print to remove)
        self._fresh = False

    # -- folder -------------------------------------------------------------------------------
    def case_dir(self, case_id: str) -> Path:
        """The folder of case ``case_id``."""
        return self.root / store.CASES / case_id

    def open_folder(self) -> None:
        """Create the folder, or check that it holds this same sweep; clear stale temporaries."""
        self.root.mkdir(parents=True, exist_ok=True)
        try:
            (self.root / store.CASES).mkdir()
            self._fresh = True
        except FileExistsError:
            if not (self.root / store.CASES).is_dir():
                raise
        store.remove_stale_temporaries(self.root)
        path = self.root / store.SWEEP_FILE
        if path.exists():
            old = store.read_json(path)
            if old is None:
                raise SweepError(f"{path}: unreadable; this folder does not hold a sweep pyadore can resume")
            if "options" not in old:  # a sweep folder of before the option table: its one option
                old["options"] = {} if old.get("ball_start") is None else {"ball_start": old["ball_start"]}
            keys = ("deck_sha256", "vary", "zip", "steps", "options")
            diffs = [k for k in keys if old.get(k) != self.definition[k]]
            if diffs:
                what = ", ".join({"deck_sha256": "the deck's content", "vary": "the varied fields or values",
                                  "zip": "--zip", "steps": "--steps", "options": "the run options"}[k]
                                 for k in diffs)
                raise SweepError(f"{self.root} holds another sweep (of {old.get('deck')}; it differs in {what}): "
                                 f"rerun the same command to resume it, or give another -o DIR")
        else:
            # flushed to the disk before the first case is recorded (record), not here: the path
            # to the first job is the sweep's serial start (docs/sweeps.md, "Scaling, eighteenth
            # session"); a case file is never durable before the folder's definition
            store.write_atomic(path, json.dumps(self.definition, indent=1), durable=False)
            self._unflushed = path

    def flush_definition(self) -> None:
        """Flush sweep.json to the disk if :meth:`open_folder` wrote it (without fsync): before
        the first case's files are recorded, or at the end."""
        if self._unflushed is not None:
            store.flush_file(self._unflushed)
            self._unflushed = None

    def load_finished(self) -> None:
        """Take every case already finished (``ok`` with its print) from the folder.  A case
        finished by a sweep killed before its events.log line was written (the log follows
        the manifest rewrites, which a fast sweep batches) gets its line now, once.  Nothing to
        take from a folder whose cases/ this sweep made (64 failed look-ups of the 32-case grid's
        files on the client's path to its first job otherwise)."""
        if self._fresh:
            return
        logged = set()
        events = self.root / store.EVENTS
        if events.exists():
            for line in events.read_text(encoding="utf-8", errors="replace").splitlines():
                parts = line.split()
                if len(parts) >= 2:
                    logged.add(parts[1])
        self._load_finished()
        for case in self.cases:
            e = self.entries.get(case.case_id)
            if e is not None and case.case_id not in logged:
                dur = e.get("duration_s")
                dur = "-" if dur is None else f"{dur:.3f}s"
                self._events.append(f"{e.get('finished_at') or _now()} {case.case_id} {e['status']} {dur} "
                                    f"{e.get('worker') or ''}".rstrip())

    def _load_finished(self) -> None:
        for case in self.cases:
            cdir = self.case_dir(case.case_id)
            saved = store.read_json(cdir / store.CASE_RESULT)
            prt = cdir / store.CASE_PRINT
            if saved and saved.get("status") == "ok" and saved.get("params") == case.params and prt.exists():
                self.entries[case.case_id] = saved
                continue
            if saved is None and prt.exists() and not (cdir / store.CASE_RESULTS).exists():
                # killed between writing the (complete, flushed, renamed) print and its result.json, or
                # a power cut lost result.json (written without fsync): a case without time steps has
                # every result in its print, as its worker took them; one with time steps (its netCDF
                # file) has averages from its run's arrays: it runs again
                try:
                    from ..printout import read_print

                    results = key_results(read_print(prt, frames=False, echo=False))
                    results.update(mean_results(None))
                except Exception:
                    continue
                entry = self._entry(case, "ok", "", None, [], "", results)
                entry["recovered"] = True
                self.flush_definition()
                store.write_atomic(cdir / store.CASE_RESULT, json.dumps(entry, indent=1))
                self.entries[case.case_id] = entry

    # -- records ------------------------------------------------------------------------------
    def _entry(self, case: Case, status: str, error: str, duration, notes, worker, results) -> dict:
        return {"case": case.case_id, "params": case.params, "status": status,
                "duration_s": _jsonable(duration), "error": error, "notes": list(notes), "worker": worker,
                "finished_at": _now(), "results": {k: _jsonable(v) for k, v in results.items()}}

    def record(self, case: Case, status: str, error: str = "", duration=None, notes=(), worker: str = "",
               results=None, print_text: str | None = None, incomplete_text: str | None = None,
               incomplete_history: str | None = None, history_text: str | None = None,
               results_nc: str | None = None) -> None:
        """Write a finished case: its time histories and netCDF results (when ok and the run
        has time steps), its print (when ok; an incomplete print of a failed case as
        incomplete.prt), then result.json; its event and the manifest follow
        (MANIFEST_INTERVAL)."""
        import base64

        self.flush_definition()
        cdir = self.case_dir(case.case_id)
        prt = cdir / store.CASE_PRINT
        kept = {store.CASE_HISTORY: history_text if status == "ok" else None,
                store.CASE_RESULTS: base64.b64decode(results_nc) if status == "ok" and results_nc else None}
        fresh = self._fresh  # no earlier file in the case's folder to remove (five look-ups less)
        if not fresh and prt.exists():
            prt.unlink()  # no print from an earlier run may pose as this case's result
        for name, content in kept.items():
            path = cdir / name
            if content is not None:
                store.write_atomic(path, content)
            elif not fresh and path.exists():
                path.unlink()  # of an earlier run of this case
        if status == "ok":
            store.write_atomic(prt, print_text)
        for name, text in ((store.CASE_INCOMPLETE, incomplete_text), (store.CASE_INCOMPLETE_HISTORY,
                                                                      incomplete_history)):
            path = cdir / name
            if text is not None:
                store.write_atomic(path, text)
            elif not fresh and path.exists():
                path.unlink()  # of an earlier failed run of this case
        entry = self._entry(case, status, error, duration, notes, worker, results or {})
        # not flushed to the disk: the print it vouches for is (fsync above), and a result.json a
        # power cut left empty reads as absent, so a resume recovers the case from its print
        # (_load_finished) or runs it again; about 0.5 ms of the client's CPU a case (docs/sweeps.md)
        store.write_atomic(cdir / store.CASE_RESULT, json.dumps(entry, indent=1), durable=False)
        self.entries[case.case_id] = entry
        dur = "-" if duration is None or not math.isfinite(duration) else f"{duration:.3f}s"
        self._events.append(f"{entry['finished_at']} {case.case_id} {status} {dur} {worker}".rstrip())
        since = time.monotonic() - self._manifest_written
        if since >= min(MANIFEST_INTERVAL, max(MANIFEST_MIN_INTERVAL, MANIFEST_COST_FACTOR * self._manifest_cost)):
            self.write_manifest(durable=False)

    def write_manifest(self, durable: bool = True, summary: bool = False) -> None:
        """Write manifest.json - every case with its parameters, status, duration and error -
        then the events.log lines of the cases finished since the last one.  ``durable``: flushed
        to the disk first (fsync); the rewrites while the cases run, and the pending one at the start,
        are progress (a resume reads each case's result.json, never the manifest) and skip the
        fsync, as events.log's appends do: about 0.6 ms of the client's CPU a case, which
        competes with the workers (docs/sweeps.md, "Scaling").  Whole or absent all the same:
        written atomically.  ``summary`` (the sweep's end, :meth:`write_end`): summary.csv is
        written with it, both flushed at the same time (:func:`store.write_atomic_many`), the
        manifest renamed first."""
        self._manifest_written = time.monotonic()
        lines = []
        counts: dict[str, int] = {}
        for case in self.cases:
            e = self.entries.get(case.case_id)
            cached = self._manifest_lines.get(case.case_id)
            if cached is None or cached[0] is not e:  # each case's line encoded once per entry
                row = e if e is not None else {
                    "case": case.case_id, "params": case.params, "status": "pending", "duration_s": None,
                    "error": "", "notes": [], "worker": "", "finished_at": None, "results": {}}
                cached = self._manifest_lines[case.case_id] = (e, json.dumps(row), row["status"])
            lines.append(cached[1])
            counts[cached[2]] = counts.get(cached[2], 0) + 1
        text = _manifest_text(self.definition, _now(), counts, lines)
        if summary:
            store.write_atomic_many([(self.root / store.MANIFEST, text),
                                     (self.root / store.SUMMARY, summary_csv(*self.summary_rows()))])
        else:
            store.write_atomic(self.root / store.MANIFEST, text, durable=durable)
        if self._events:
            store.append_event(self.root, "\n".join(self._events))
            self._events = []
        self._manifest_cost = time.monotonic() - self._manifest_written

    def summary_rows(self) -> tuple[list[str], list[dict]]:
        """The summary's columns (case, the varied parameters, status, the key results) and
        rows (one dict a case; a result the case does not have is NaN)."""
        rows = []
        for case in self.cases:
            e = self.entries.get(case.case_id, {})
            row = {"case": case.case_id, **case.params, "status": e.get("status", "pending")}
            res = e.get("results") or {}
            for col in RESULT_COLUMNS:
                v = res.get(col)
                row[col] = float("nan") if v is None else v
            rows.append(row)
        return ["case", *[v.name for v in self.varied], "status", *RESULT_COLUMNS], rows

    def summary(self):
        """The summary frame (pandas): :meth:`summary_rows` as summary.csv holds them."""
        import pandas as pd

        columns, rows = self.summary_rows()
        return pd.DataFrame(rows, columns=columns)

    def write_summary(self) -> None:
        """Write summary.csv (:func:`summary_csv`: pandas' text, without pandas)."""
        store.write_atomic(self.root / store.SUMMARY, summary_csv(*self.summary_rows()))

    def write_end(self) -> None:
        """The sweep's end: manifest.json, then summary.csv, flushed to the disk together
        (:meth:`write_manifest`), then the events of the cases the manifest added; sweep.json
        flushed first if no case flushed it."""
        self.flush_definition()
        self.write_manifest(summary=True)

    def status_counts(self) -> dict[str, int]:
        """How many cases have each status, the most frequent first (as pandas' value_counts)."""
        counts: dict[str, int] = {}
        for case in self.cases:
            status = self.entries.get(case.case_id, {}).get("status", "pending")
            counts[status] = counts.get(status, 0) + 1
        return dict(sorted(counts.items(), key=lambda kv: -kv[1]))

    # -- preparing the cases --------------------------------------------------------------------
    def prepare(self, case: Case) -> str | None:
        """Write the case deck; its text, or None when a varied value cannot be written in its
        field (the case is recorded ``invalid``).  The deck is validated where the case runs
        (:func:`~pyadore.sweeps.execute.run_case`), in parallel: this serial part of the sweep
        stays a few milliseconds a case (docs/sweeps.md, "Scaling")."""
        cdir = self.case_dir(case.case_id)
        cdir.mkdir(parents=True, exist_ok=True)
        deck_file = cdir / store.CASE_DECK
        try:
            text = case_deck_text(self.base_text, str(self.deck_path), self.varied, case, base=self.base_deck)
        except DeckError as exc:
            self.record(case, "invalid", error=str(exc))
            return None
        # rewritten from the sweep's definition whenever the case runs: no fsync needed
        store.write_atomic(deck_file, text, durable=False)
        return text


def _speed_field(varied: list[Varied]) -> Varied | None:
    """The varied inner race speed (Rec 9.1.2), the cheap estimate of a case's cost; None."""
    return next((v for v in varied if v.field == "inner_race_speed"), None)


def _cheap_cost(case: Case, speed: Varied | None) -> float:
    """The cheap estimate of a case's cost: its shaft speed (rpm; 0 when not varied)."""
    if speed is None:
        return 0.0
    try:
        return abs(float(case.params[speed.name]))
    except (KeyError, TypeError, ValueError):
        return 0.0


def dispatch_order(cases: list[Case], varied: list[Varied]) -> list[Case]:
    """The order in which the cases go to the workers: the longest first, by a cheap estimate of
    their cost, so that the workers end together instead of one idling while the other runs a
    long last case (the grid's order puts the fastest speeds, the longest cases, last).  The
    estimate is the varied inner race speed (Rec 9.1.2): Appendix C's step 0 takes 55-80 ms of
    CPU at 10 000-15 000 rpm and 90-137 ms at 25 000 rpm (docs/sweeps.md, "Scaling"); cases of
    one speed, or a sweep that does not vary it, keep the grid's order here, and the workers
    order them by the costs of the cases finished meanwhile (:class:`CostModel`).  Only the
    order of the work changes: every file, the manifest and the summary list the cases in the
    grid's order."""
    speed = _speed_field(varied)
    if speed is None:
        return list(cases)
    return sorted(cases, key=lambda c: _cheap_cost(c, speed), reverse=True)  # stable: the grid's order


class CostModel:
    """The order in which the workers take the cases, learnt while they run.  The cases go by
    the cheap estimate first (:func:`dispatch_order`: the faster shaft first); among cases of
    one cheap estimate (one speed, or all of them when the speed is not varied) the case of the
    highest learnt cost first, once ``LEARN_AFTER`` cases have finished: each case's CPU time in
    its worker, additive in the other varied fields' values - the mean cost, then for each
    field in turn the mean of what is left of the finished cases' costs at each of its values
    (one backfitting pass, so that a zipped field that repeats another adds nothing; a value no
    finished case had adds nothing).  So the last cases are the shortest and the workers end
    together: Appendix C's step 0 varies by up to 2x within a speed with the loads (56-140 ms
    of CPU at 25 000 rpm), which the speed does not tell, and the loads' effect is learnt from
    the faster speeds' cases before the slower speeds' run (docs/sweeps.md, "Scaling,
    nineteenth session").  Only the work's order changes.  :meth:`rank` is called by the
    workers' threads, :meth:`add` by the client's: the estimate is replaced whole."""

    #: the finished cases needed before their costs order the rest
    LEARN_AFTER = 4

    def __init__(self, order: list[Case], varied: list[Varied]) -> None:
        speed = _speed_field(varied)
        self.names = [v.name for v in varied if v is not speed]
        self.position = {c.case_id: k for k, c in enumerate(order)}
        self.cheap = {c.case_id: _cheap_cost(c, speed) for c in order}
        self.params = {c.case_id: c.params for c in order}
        self.costs: dict[str, float] = {}
        #: (mean, [{value: effect} for each field of self.names], {case id: its cost by them})
        self.estimate: tuple | None = None

    def add(self, case_id: str, cost) -> None:
        """Learn from a finished case its cost (s; a case without one, e.g. a worker that died,
        teaches nothing)."""
        if case_id not in self.params or isinstance(cost, bool) or not isinstance(cost, (int, float)) \
                or not math.isfinite(cost):
            return
        self.costs[case_id] = float(cost)
        if len(self.costs) >= self.LEARN_AFTER:
            self.estimate = self._fit()

    def _fit(self) -> tuple:
        mean = sum(self.costs.values()) / len(self.costs)
        left = {c: v - mean for c, v in self.costs.items()}
        effects = []
        for name in self.names:
            sums: dict = {}
            for c, v in left.items():
                key = self.params[c].get(name)
                total, n = sums.get(key, (0.0, 0))
                sums[key] = (total + v, n + 1)
            effect = {key: total / n for key, (total, n) in sums.items()}
            left = {c: v - effect[self.params[c].get(name)] for c, v in left.items()}
            effects.append(effect)
        return mean, effects, {}

    def cost(self, case_id: str) -> float | None:
        """The learnt cost (s) of case ``case_id`` among the cases of its cheap estimate; None
        before enough cases finished."""
        estimate = self.estimate
        if estimate is None:
            return None
        mean, effects, known = estimate
        cost = known.get(case_id)
        if cost is None:  # once per case and estimate: a free worker ranks every case not taken yet
            params = self.params[case_id]
            cost = known[case_id] = mean + sum(effect.get(params.get(name), 0.0)
                                               for name, effect in zip(self.names, effects))
        return cost

    def rank(self, job: tuple) -> tuple:
        """The key a worker free for a case takes the highest of (``job[0]``: its case id): its
        cheap estimate, then its learnt cost, then the earlier in :func:`dispatch_order` first."""
        case_id = job[0]
        cost = self.cost(case_id)
        return (self.cheap.get(case_id, 0.0), 0.0 if cost is None else cost, -self.position.get(case_id, 0))


def _csv_column(values: list) -> list[str]:
    """The cells of one summary column as pandas writes them: a column of integers as
    integers, a column of numbers with one float (or NaN) in it all as floats (repr, NaN
    empty), anything else as text."""
    numbers = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values)
    if numbers and any(isinstance(v, float) for v in values):
        return ["" if v != v else repr(float(v)) for v in values]
    return [str(v) for v in values]


def summary_csv(columns: list[str], rows: list[dict]) -> str:
    """summary.csv's text: what ``pandas.DataFrame(rows, columns=columns).to_csv(index=False)``
    writes, without importing pandas (0.3-0.6 s of the client's serial end of a
    ``pyadore sweep``; tests/test_sweep.py compares the two)."""
    import csv
    import io

    cells = [_csv_column([row.get(c, float("nan")) for row in rows]) for c in columns]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns)
    writer.writerows(zip(*cells))
    return buffer.getvalue()


def _manifest_text(definition: dict, updated_at: str, counts: dict, lines: list[str]) -> str:
    """manifest.json's text: the sweep's definition, when, the counts by status, then the
    cases one a line (``lines``: each case's entry as ``json.dumps`` encodes it).  Each line
    is encoded by json's C encoder (an indented dump takes the pure-Python one, five times
    slower), once per entry (:meth:`_Sweep.write_manifest` keeps them): the manifest is
    rewritten while the cases run, by the client that shares the cores with the workers
    (docs/sweeps.md, "Scaling")."""
    head = json.dumps({"sweep": definition, "updated_at": updated_at, "counts": counts}, indent=1)
    cases = ",\n  ".join(lines)
    return f'{head[:-2]},\n "cases": [\n  {cases}\n ]\n}}' if lines else f'{head[:-2]},\n "cases": []\n}}'


def _progress(total: int, enabled: bool | None):
    """A tqdm bar on stderr: shown when enabled, or (None) on a terminal only; None when
    not shown, without importing tqdm (0.2 s of the client's serial start)."""
    if enabled is False or (enabled is None and not (hasattr(sys.stderr, "isatty") and sys.stderr.isatty())):
        return None
    try:
        from tqdm import tqdm
    except ImportError:  # the bar is a convenience
        return None
    return tqdm(total=total, unit="case", desc="sweep", disable=False, file=sys.stderr, dynamic_ncols=True)


def sweep(deck, vary, out_dir, zip: bool = False, steps: int | None = None, workers=None,
          scheduler=None, progress: bool | None = None, **options):
    """Run ``deck`` (a deck file or a :class:`pyadore.deck.Deck`) over the values of ``vary``
    and return the summary as a pandas DataFrame.

    vary: ``{"inner_race_speed": [10000, 20000], "applied_force_z": [1000, 2000]}`` or a list of
    ``"FIELD=V1,V2,..."`` strings; field names as in docs/deck-format.md (``REC/FIELD`` where
    several records of the deck have the field), values in the deck's units (rpm, N, m, K).
    Several fields make the full grid; ``zip=True`` pairs the i-th values.
    out_dir: the sweep folder (layout in :mod:`pyadore.sweeps.store`); rerunning the same
    sweep into it runs only the cases that are missing or failed.
    steps: as :func:`pyadore.run` (0 = the quasi-static start only).
    workers: local worker processes [default: the CPU count], or a
    :class:`~pyadore.sweeps.WorkerPool` whose processes stay warm across sweeps; scheduler: the address of a
    Dask distributed scheduler (or a ``distributed.Client``) to run the cases on instead.
    progress: ``None`` shows a progress bar on a terminal only.
    options: the run options of every case, as :func:`pyadore.run` takes them (the engine's
    option table, e.g. ``ball_start="outer-race-control"``, ``substeps=5``); checked before
    any case runs.
    Raises :class:`~pyadore.sweeps.SweepError` (an ``AdoreInputError``) when the sweep cannot
    start; a case that fails is a row with its status and message, never an exception.
    """
    return run_sweep(deck, vary, out_dir, zip=zip, steps=steps, workers=workers, scheduler=scheduler,
                     progress=progress, **options).summary()


def run_sweep(deck, vary, out_dir, zip: bool = False, steps: int | None = None, workers=None,
              scheduler=None, progress: bool | None = None, **options) -> _Sweep:
    """:func:`sweep` without pandas (the ``pyadore sweep`` command): the sweep's state, whose
    :meth:`~_Sweep.status_counts` and ``entries`` tell how its cases ended; summary.csv is
    written all the same.  A local sweep starts its workers first, so that they boot while
    the deck is read and the cases are prepared (docs/sweeps.md, "Scaling")."""
    given = deck if isinstance(deck, Deck) else None
    deck_path = Path(str(deck.path)) if given is not None else Path(os.fspath(deck))
    if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int) or steps < 0):
        raise SweepError(f"steps must be None or an integer >= 0, got {steps!r}")
    from .execute import WorkerPool

    if workers is not None and not isinstance(workers, WorkerPool) and (
            isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise SweepError(f"workers must be an integer >= 1 or a WorkerPool, got {workers!r}")
    pool, own = None, False
    if scheduler is None:
        own = not isinstance(workers, WorkerPool)
        pool = WorkerPool(workers or os.cpu_count() or 1) if own else workers
        pool.once = pool.once or own  # this sweep's own: its workers end with its last job
        pool.start()  # boots while the client reads the deck and prepares the cases
    try:
        return _run_sweep(deck, given, deck_path, vary, out_dir, zip, steps, pool, scheduler, progress, options)
    finally:
        if own:
            pool.close()


def _run_sweep(deck, given, deck_path, vary, out_dir, zip, steps, pool, scheduler, progress, options) -> _Sweep:
    """:func:`run_sweep` once its arguments are checked and its local pool started."""
    if given is not None:  # a Deck: its text as the deck writer gives it (unchanged records verbatim)
        base_text = format_deck(given)
    elif deck_path.exists() and not deck_path.is_file():  # a FIFO would wait for a writer for ever
        raise SweepError(f"{deck_path}: the deck is not a regular file: give the deck file itself")
    else:
        try:
            base_text = deck_path.read_bytes().decode("utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise SweepError(f"{deck_path}: cannot read the deck ({exc})") from None
    base, problems = parse_text(base_text, str(deck_path))
    if problems:
        raise DeckError(f"{deck_path}: {len(problems)} problem(s) reading the deck", problems)
    varied = [parse_vary(text, base) for text in _vary_specs(vary)]
    cases = make_cases(varied, zip_values=zip)
    from ..options import options_text

    options = {k: v for k, v in options.items() if v is not None}
    options_text(**options)  # an unknown option or a value of the wrong type: before any case
    options = {k: (os.fspath(v) if isinstance(v, os.PathLike) else v) for k, v in options.items()}
    run = _Sweep(deck_path, base_text, varied, cases, Path(os.fspath(out_dir)), steps, zip, options,
                 base_deck=base)
    run.open_folder()
    run.load_finished()
    todo = dispatch_order([c for c in cases if c.case_id not in run.entries], varied)
    costs = CostModel(todo, varied)  # the order of the rest, learnt from the cases finished
    by_id = {c.case_id: c for c in cases}
    bar = _progress(len(todo), progress)

    def on_result(res: dict) -> None:
        case = by_id[res["case"]]
        costs.add(case.case_id, (res.get("timing") or {}).get("cpu_s"))
        error = res["error"]
        cdir = run.case_dir(case.case_id)
        incomplete = res.get("incomplete_text")
        history = res.get("incomplete_history")
        # the paths the message names in the worker's folder (gone) -> the case folder's (a
        # message only: timehistory imports numpy, 0.1 s of the client's CPU amid the workers)
        if error and res.get("tmp_print"):
            from ..timehistory import history_path

            tmp_print = res["tmp_print"]
            error = error.replace(str(history_path(tmp_print)), str(cdir / store.CASE_INCOMPLETE_HISTORY)
                                  if history is not None else "(not kept)")
            error = error.replace(tmp_print, str(cdir / store.CASE_INCOMPLETE) if incomplete is not None
                                  else "(not kept)")
        if error and res.get("tmp_deck"):
            error = error.replace(res["tmp_deck"], str(cdir / store.CASE_DECK))
        run.record(case, res["status"], error=error, duration=res["duration_s"], notes=res["notes"],
                   worker=res["worker"], results=res["results"], print_text=res["print_text"],
                   incomplete_text=incomplete, incomplete_history=history, history_text=res.get("history_text"),
                   results_nc=res.get("results_nc"))
        if bar is not None:
            bar.update(1)

    def jobs():
        pending = True  # the manifest listing every case pending: written once the first job is out
        for case in todo:
            text = run.prepare(case)
            if text is None:
                if bar is not None:
                    bar.update(1)
                continue
            yield (case.case_id, text, steps, options)
            if pending:
                # after the first job, not on the client's path to it (docs/sweeps.md, "Scaling,
                # nineteenth session"); flushed with the summary at the end
                pending = False
                if run._manifest_written == 0.0:
                    run.write_manifest(durable=False)

    try:
        if scheduler is not None:
            run_dask(jobs(), scheduler, on_result)
        else:
            run_local(jobs(), pool, on_result, count=len(todo), rank=costs.rank)
    finally:
        if bar is not None:
            bar.close()
        run.write_end()
    return run


def read_summary(out_dir):
    """The summary of the sweep folder ``out_dir`` (``summary.csv``) as a DataFrame."""
    import pandas as pd

    path = Path(os.fspath(out_dir)) / store.SUMMARY
    if not path.exists():
        raise SweepError(f"{out_dir}: no {store.SUMMARY}; is this a sweep folder (pyadore sweep ... -o DIR)?")
    return read_summary_file(path)


def read_summary_file(path):
    """A sweep summary CSV file as a DataFrame; SweepError when it is empty or not a CSV
    file of text."""
    import pandas as pd

    try:
        return pd.read_csv(path)
    except (pd.errors.EmptyDataError, pd.errors.ParserError, UnicodeDecodeError) as exc:
        raise SweepError(f"{path}: not a readable sweep summary ({type(exc).__name__}: {exc})") from None
