"""``read_print``: parse an ADORE 5.0 print file (golden or engine output) into a PrintRun.

The reader follows docs/print-layout.md: it skips everything before the banner (the
engine's "Listing of input data records"), reads the input echo as named values
(:mod:`.echo`), then every step: the step header, the tables of sections 1, 1a, 2, 3 and 4
by their fixed columns, and finally the termination line and the run statistics.
Every departure from the layout raises PrintFormatError naming file, line and what was
expected.
"""

from __future__ import annotations

import re
from pathlib import Path

from . import layout as L
from .echo import parse_echo
from .model import NUMBER_TOKEN, PlainTable, PrintFormatError, PrintRun, Step, parse_field, parse_number

_BANNER_INFO = re.compile(r"Bearing Type\s*=\s*(\S+)\s+Program\s+Mode\s*=\s*(\S+)\s+Run Id\s*=\s*(.*?)\s*\*?\s*$")
_TERMINATION = re.compile(r"Last Step Number\s*=\s*(\S+)\s+Final Time\s*=\s*(\S+)")
_SLICES_TITLE = re.compile(r"^1a\.\s+Load Distribution Along Roller no\.\s*(\d+)\s*$")
_SECTION_TITLE = re.compile(r"^(1|1a|2|3|4)\.\s")
#: the flanged start's block after step 0 (docs/rollers.md, "Flanges at step 0"; not in the report)
_FLANGE_TITLE = "ROLLER END / FLANGE CONTACTS AT STEP 0"
_FLANGE_RACE = re.compile(r"Inner race axial position\s+(\S+)\s+flanges' axial force on it\s+(\S+)")
_LOAD_ROWS = L.LOAD_ROWS
_ACC_ROWS = L.ACC_ROWS


def _norm(text: str) -> str:
    return " ".join(text.split())


class _Reader:
    def __init__(self, path: Path, lines: list[str], frames: bool = True, echo: bool = True) -> None:
        self.path = path
        self.lines = lines
        self.frames = frames
        self.echo = echo

    def frame(self, rows: list, index: list, name: str, columns: list):
        """A table: a pandas DataFrame (index ``name``; tuples make a MultiIndex of element
        and end), or a PlainTable when the reader builds no frames."""
        if not self.frames:
            return PlainTable(rows, index, columns, name)
        import pandas as pd

        if index and isinstance(index[0], tuple):
            idx = pd.MultiIndex.from_tuples(index, names=["element", "end"])
        else:
            idx = pd.Index(index, name=name)
        return pd.DataFrame(rows, index=idx, columns=columns)

    def fail(self, lineno: int, expected: str, found: str | None = None) -> PrintFormatError:
        found = self.lines[lineno].strip() if found is None and lineno < len(self.lines) else (found or "end of file")
        return PrintFormatError(f"{self.path}: line {lineno + 1}: expected {expected}; found {found[:80]!r}")

    # -- fields ---------------------------------------------------------------------------
    def values(self, i: int, text: str, n: int, what: str, start_col: int) -> tuple[list, list]:
        """Parse ``n`` fields of 11 characters; fall back to tokens for run-together numbers."""
        vals, marks = [], []
        ok = len(text.rstrip()) <= n * L.VALUE_WIDTH
        if ok:
            for k in range(n):
                parsed = parse_field(text[k * L.VALUE_WIDTH:(k + 1) * L.VALUE_WIDTH])
                if parsed is None:
                    ok = False
                    break
                vals.append(parsed[0])
                marks.append(parsed[1])
        if ok:
            return vals, marks
        tokens = NUMBER_TOKEN.findall(text)
        rest = NUMBER_TOKEN.sub(" ", text).strip()
        if len(tokens) != n or rest:
            raise self.fail(i, f"{n} values (1X,ES10.3 each, from column {start_col + 1}) in {what}")
        vals, marks = [], []
        for t in tokens:
            v, m = parse_field(t)
            vals.append(v)
            marks.append(m)
        return vals, marks

    def codes(self, i: int, text: str, n: int, what: str) -> tuple[list, list]:
        vals, marks = [], []
        for k in range(n):
            t = text[3 * k:3 * k + 3].strip()
            parsed = parse_field(t) if t else None
            if parsed is None:
                raise self.fail(i, f"an integer code (I3) in {what}")
            vals.append(parsed[0])
            marks.append(parsed[1])
        return vals, marks

    # -- tables ---------------------------------------------------------------------------
    def table(self, i: int, spec: L.TableSpec, name: str) -> tuple:
        """Parse the table whose first heading line is line ``i``; return (next line, values, markers)."""
        i += len(spec.headings)
        index, rows, marks = [], [], []
        what = f"table {name}"
        while i < len(self.lines) and self.lines[i].strip():
            line = self.lines[i]
            if spec.label == "re_end":
                a, b = line[:5].strip(), line[5:8].strip()
                if not (a.isdigit() and b.isdigit()):
                    break
                label = (int(a), int(b))
            elif spec.label == "text":
                label = line[:spec.label_width].strip()
                if not label or parse_number(label) is not None:
                    break
            else:
                lab = line[:spec.label_width].strip()
                if not lab.isdigit():
                    break
                label = int(lab)
            lead = spec.label_width + (3 if spec.label == "re_end" else 0)
            cvals, cmarks = self.codes(i, line[lead:lead + 3 * len(spec.codes)], len(spec.codes), what)
            vals, vmarks = self.values(i, line[spec.lead_width:], len(spec.columns), what, spec.lead_width)
            index.append(label)
            rows.append(cvals + vals)
            marks.append(cmarks + vmarks)
            i += 1
        if not rows:
            raise self.fail(i, f"rows of {what}")
        cols = list(spec.codes) + list(spec.columns)
        idx_name = None
        if spec.label != "re_end":
            idx_name = {"int": "element", "text": "body", "step": "step"}[spec.label]
            if name.startswith("slices"):
                idx_name = "slice"
            elif name == "race_cage":
                idx_name = "land"
        return i, self.frame(rows, index, idx_name, cols), self.frame(marks, index, idx_name, cols)

    def section3(self, i: int, step: Step) -> int:
        """Section 3: the force/moment rows, acceleration rows and the labelled cells on the right."""
        loads, accs, perf = {}, {}, {}
        block = "loads"
        labels = {_norm(v): k for k, v in L.RIGHT_LABELS.items()}
        while i < len(self.lines) and not _SECTION_TITLE.match(self.lines[i].strip()):
            line = self.lines[i]
            if "MC Acc in Inertial Frame" in line:
                block = "acc"
            start = L.RIGHT3 if block == "loads" else L.RIGHT3_ACC
            label = line[:10].strip()
            rows, n = (_LOAD_ROWS, 6) if block == "loads" else (_ACC_ROWS, 7)
            if label in rows:
                vals = self.values(i, line[10:10 + n * L.VALUE_WIDTH], n, f"section 3 row {label!r}", 10)
                (loads if block == "loads" else accs)[label] = vals
            right = _norm(line[start:])
            if right:
                for lab, name in labels.items():
                    if right.startswith(lab):
                        parsed = parse_field(right[len(lab):])
                        if parsed is None:
                            raise self.fail(i, f"a value after {lab!r} (1X,ES10.3)")
                        perf[name] = parsed
                        break
                else:
                    if line[:start].strip() == "" or label in rows:
                        raise self.fail(i, "a section 3 labelled value (" + ", ".join(L.RIGHT_LABELS.values())[:60] + "...)")
            i += 1
        for name, got, spec, rows in (("loads", loads, L.LOADS, _LOAD_ROWS), ("accelerations", accs, L.ACCELERATIONS, _ACC_ROWS)):
            if not got:
                raise self.fail(i, f"the {name} rows of section 3 ({', '.join(rows)})")
            step.tables[name] = self.frame([v[0] for v in got.values()], list(got), "body", list(spec.columns))
            step.markers[name] = self.frame([v[1] for v in got.values()], list(got), "body", list(spec.columns))
        cols = [c for c in L.PERFORMANCE_COLUMNS if c in perf]
        step.tables["performance"] = self.frame([[perf[c][0] for c in cols]], ["bearing"], "body", cols)
        step.markers["performance"] = self.frame([[perf[c][1] for c in cols]], ["bearing"], "body", cols)
        return i

    # -- whole file -----------------------------------------------------------------------
    def step_header(self, i: int) -> tuple[int, int, dict, dict, str]:
        if i + 2 >= len(self.lines):
            raise self.fail(i, "the step header value line")
        line = self.lines[i + 2]
        num = line[:6].strip()
        if not num.lstrip("-").isdigit():
            raise self.fail(i + 2, "a step number (I6) in the step header")
        parts = [line[6:17], line[17:28], line[32:43], line[47:58]]
        header, marks = {}, {}
        for col, text in zip(L.HEADER_COLUMNS, parts):
            parsed = parse_field(text)
            if parsed is None:
                raise self.fail(i + 2, "step header values (I6,2(1X,ES10.3),2(5X,ES10.3),2X,A)")
            header[col], marks[col] = parsed
        return i + 4, int(num), header, marks, line[60:].strip()

    def run(self) -> PrintRun:
        run = PrintRun(path=str(self.path))
        start = next((k for k, s in enumerate(self.lines) if s.strip() == L.BANNER_LINE), None)
        if start is None:
            raise PrintFormatError(f"{self.path}: not an ADORE print file: no banner line {L.BANNER_LINE!r}")
        first_step = next((k for k in range(start, len(self.lines)) if self._is_step(k)), len(self.lines))
        for k in range(start, first_step):
            m = _BANNER_INFO.search(self.lines[k])
            if m:
                run.bearing_type, mode, run.run_id = m.group(1), m.group(2), m.group(3).strip()
                run.program_mode = int(mode) if mode.isdigit() else None
                break
        if self.echo:
            run.echo = parse_echo(self.lines, start, first_step, self.fail)
        i, step, section = first_step, None, None
        spec_by_key = {s.key: s for s in L.ALL_TABLES if s.key}
        while i < len(self.lines):
            line = self.lines[i]
            text = line.strip()
            if self._is_step(i):
                i, num, header, marks, run_id = self.step_header(i)
                step = run.steps.setdefault(num, Step(number=num))
                step.header, step.run_id = header, run_id
                step.markers["header"] = marks
                continue
            if not text:
                i += 1
                continue
            if text.startswith(L.INCOMPLETE_PREFIX):
                run.incomplete = text.strip("* ").strip()
                i += 1
                continue
            if text.startswith(L.TERMINATION_PREFIX):
                m = _TERMINATION.search(text)
                last = parse_number(m.group(1)) if m else None
                final = parse_field(m.group(2)) if m else None
                if last is None or final is None:
                    raise self.fail(i, "'Normal termination: Last Step Number = n  Final Time = t'")
                run.termination = {"last_step_number": int(last), "final_time": final[0]}
                run.termination_markers = {"last_step_number": "", "final_time": final[1]}
                i += 1
                continue
            if text == L.STATISTICS_TITLE:
                i = self.statistics(i + 1, run)
                continue
            if step is None:
                raise self.fail(i, "a step header before any table")
            m = _SLICES_TITLE.match(text)
            if m:
                section = f"1a:{m.group(1)}"
                i += 1
                continue
            sec = _SECTION_TITLE.match(text)
            if sec:
                section = sec.group(1)
                i += 1
                if section == "3":
                    i = self.section3(i, step)
                continue
            if text.startswith(_FLANGE_TITLE):
                i = self.flanges(i + 1, step)
                continue
            spec = spec_by_key.get(_norm(line))
            if spec is None:
                raise self.fail(i, f"a table heading, step header or section title in section {section or '?'}")
            name = spec.name if not spec.name == "slices" else "slices_" + (section or "1a:?").split(":")[-1]
            i, values, markers = self.table(i, spec, name)
            if spec.name == "summary":
                for n in values.index:
                    target = run.steps.setdefault(int(n), Step(number=int(n)))
                    target.tables["summary"] = values.loc[[n]]
                    target.markers["summary"] = markers.loc[[n]]
            else:
                step.tables[name] = values
                step.markers[name] = markers
        if not run.incomplete and not run.termination and any(
                s.startswith(L.TIME_INTEGRATION_PREFIX) for s in self.lines[:start]):
            run.incomplete = ("its listing announces time steps but it has no termination line "
                              "(the run did not end)")
        return run

    def _is_step(self, k: int) -> bool:
        s = self.lines[k]
        return s.lstrip().startswith("step") and "(ADORE 5.0)" in s

    def flanges(self, i: int, step: Step) -> int:
        """The flanged start's block after step 0 (docs/rollers.md, "Flanges at step 0"):
        ``step.tables["flanges"]``, per roller its axial position (m), tilt (rad) and each
        flange's load (N, columns ``outer_minus_x_N`` ... ``inner_plus_x_N``), and
        ``step.tables["flanges_race"]``, the inner race's axial position (m) and the flanges'
        axial force on it (N)."""
        head = self.lines[i].split() if i < len(self.lines) else []
        if head[:5] != ["RE", "No", "Axial", "Pos", "Tilt"] or len(head) % 2 == 0:
            raise self.fail(i, "the flange table's heading 'RE No Axial Pos Tilt <race> <end> ...'")
        columns = ["axial_pos_m", "tilt_rad"] + [
            f"{head[k].lower()}_{'minus' if head[k + 1] == '-x' else 'plus'}_x_N" for k in range(5, len(head), 2)]
        rows, index = [], []
        i += 1
        while i < len(self.lines) and self.lines[i].split() and self.lines[i].split()[0].isdigit():
            tokens = self.lines[i].split()
            vals = [parse_number(t) for t in tokens[1:]]
            if len(vals) != len(columns) or any(v is None for v in vals):
                raise self.fail(i, f"a flange row: RE no and {len(columns)} numbers")
            rows.append(vals)
            index.append(int(tokens[0]))
            i += 1
        m = _FLANGE_RACE.search(self.lines[i]) if i < len(self.lines) else None
        race = [parse_number(m.group(1)), parse_number(m.group(2))] if m else [None]
        if None in race:
            raise self.fail(i, "'Inner race axial position <m>   flanges' axial force on it <N>'")
        step.tables["flanges"] = self.frame(rows, index, "re_no", columns)
        step.tables["flanges_race"] = self.frame([race], [0], "row", ["inner_race_axial_pos_m",
                                                                      "flange_axial_force_on_inner_race_N"])
        return i + 1

    def statistics(self, i: int, run: PrintRun) -> int:
        labels = {_norm(k): v for k, v in L.STATISTICS_LABELS.items()}
        while i < len(self.lines):
            text = self.lines[i].strip()
            if not text:
                i += 1
                continue
            if "=" not in text:
                break
            lab, _, val = text.partition("=")
            name = labels.get(_norm(lab))
            parsed = parse_field(val)
            if name is None or parsed is None:
                raise self.fail(i, "'<statistic> = <value>' (" + ", ".join(L.STATISTICS_LABELS) + ")")
            run.statistics[name] = parsed[0]
            run.statistics_markers[name] = parsed[1]
            i += 1
        return i


def read_print(path, frames: bool = True, echo: bool = True) -> PrintRun:
    """Read the print file at ``path`` (golden or engine output) into a :class:`PrintRun`.

    frames: the tables as pandas DataFrames (default), or with ``frames=False`` as
    :class:`~pyadore.printout.model.PlainTable` rows (no pandas imported: a sweep worker
    reads its case's key results so, and starts without pandas).  echo: parse the input
    echo (``echo=False``: ``PrintRun.echo`` stays empty, for a reader of the steps only).

    Raises PrintFormatError (an AdoreInputError) when the file is missing, unreadable,
    not text, or departs from docs/print-layout.md; the message names file and line.
    """
    p = Path(path)
    try:
        raw = p.read_bytes()
    except OSError as exc:
        raise PrintFormatError(f"{p}: cannot read the print file: {exc.strerror or exc}") from None
    try:
        text = raw.decode("ascii")
    except UnicodeDecodeError as exc:
        raise PrintFormatError(f"{p}: not a text print file (byte {exc.start} is not ASCII)") from None
    return _Reader(p, text.splitlines(), frames, echo).run()
