"""Reading decks: :func:`read_deck` (raises on bad input) and :func:`check_deck` (never raises).

Records are identified by their position in the sequence the schema prescribes
(:func:`pyadore.deck.schema.expected_records`); a ``Rec <id>`` label, when present, is
checked against the expected id, which lets the reader tell a missing record from a
surplus one and resynchronise.  Unlabelled decks are read purely by position.
"""

from __future__ import annotations

import re
from pathlib import Path

from .model import Deck, DeckError, FieldValue, Problem, Record
from .schema import ExpectedRecord, RecordSpec, expected_records, record_spec, static_order
from .tokenizer import cut_fields, parse_value, split_label
from .validate import validate_deck

__all__ = ["read_deck", "check_deck", "parse_text", "decode_bytes"]

_CONTROL_RE = re.compile(r"[\x00-\x08\x0b\x0e-\x1f\x7f]")


def decode_bytes(data: bytes, path: str) -> tuple[str | None, list[Problem]]:
    """Decode file content as UTF-8 text; a NUL byte, other control characters or invalid
    UTF-8 make it a non-text file (one ``non_text`` problem, text None)."""
    def bad(msg: str) -> tuple[None, list[Problem]]:
        return None, [Problem(path, 0, 0, None, None, None, msg, "non_text")]
    if b"\x00" in data:
        return bad("not a text file (contains NUL bytes): expected a text deck")
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        return bad(f"not a text file (invalid UTF-8 at byte {exc.start}): expected a text deck")
    m = _CONTROL_RE.search(text)
    if m:
        line = text.count("\n", 0, m.start()) + 1
        return bad(f"not a text file (control character {m.group()!r} on line {line}): expected a text deck")
    return text, []


def _split_lines(text: str) -> list[str]:
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return [ln[:-1] if ln.endswith("\r") else ln for ln in lines]


def _order_key(rid: str) -> tuple[int, int]:
    spec = record_spec(rid)
    k = int(rid.rsplit(".", 1)[1]) if spec is not None and spec.repeat else 0
    return static_order(rid), k


class _Reader:
    def __init__(self, text: str, path: str):
        self.path = path
        self.lines = _split_lines(text)
        self.problems: list[Problem] = []
        self.records: list[Record] = []
        self.values: dict[str, object] = {}
        self.counts: dict[str, int] = {}
        self.idx = 0

    def problem(self, lineno: int, col: int, rid, fname, value, msg: str, kind: str) -> None:
        src = self.lines[lineno - 1] if 0 < lineno <= len(self.lines) else None
        self.problems.append(Problem(self.path, lineno, col, rid, fname, value, msg, kind, src))

    # -- main loop ------------------------------------------------------------------------
    def run(self) -> Deck:
        if not any(ln.strip() for ln in self.lines):
            self.problems.append(Problem(self.path, 0, 0, None, None, None,
                                         "empty file: expected an ADORE deck starting with Rec 1", "empty"))
            return Deck([], self.path)
        gen = expected_records(lambda: self.values)
        while True:
            try:
                exp = next(gen)
            except StopIteration:
                break
            except LookupError as exc:
                last = self.records[-1].rid if self.records else "start"
                self.problem(self.idx, 1, last, None, None,
                             f"reading stopped: the records after this point depend on field {exc.args[0]}, "
                             "which is missing or unreadable", "type")
                return Deck(self.records, self.path)
            if not self._take(exp):
                return Deck(self.records, self.path)
        self._surplus()
        return Deck(self.records, self.path)

    def _take(self, exp: ExpectedRecord) -> bool:
        """Consume lines until ``exp`` is read or declared missing; False at end of file."""
        while True:
            if self.idx >= len(self.lines):
                n = len(self.lines)
                self.problems.append(Problem(
                    self.path, n + 1, 1, exp.rid, None, None,
                    f"truncated file: it ends after line {n}, expected Rec {exp.rid} ({exp.spec.title})",
                    "truncated"))
                return False
            line = self.lines[self.idx]
            label, offset, lerr = split_label(line)
            if label is None or label.upper() == exp.rid.upper():
                self._parse(exp, line, offset, lerr, label is not None)
                self.idx += 1
                return True
            lineno = self.idx + 1
            if record_spec(label) is None:
                self.problem(lineno, 5, label, None, None,
                             f"unknown record id 'Rec {label}': expected Rec {exp.rid} here", "unknown_record")
                self.idx += 1
                continue
            if _order_key(label) > _order_key(exp.rid):
                self._missing(exp, lineno, label)
                return True
            self._unexpected(label, lineno, exp)
            self.idx += 1

    def _missing(self, exp: ExpectedRecord, lineno: int, found: str) -> None:
        why, kind = "", "missing_record"
        if exp.spec.repeat:
            why = f" ({exp.spec.repeat} = {self.values.get(exp.spec.repeat)} requires one record per land)"
            kind = "cross_field"
        elif exp.spec.when:
            cond = exp.spec.condition
            why = f" (required because {cond}: {cond.field} = {self.values.get(cond.field)})"
            kind = "cross_field"
        self.problem(lineno, 1, exp.rid, None, None,
                     f"missing record: expected Rec {exp.rid} ({exp.spec.title}) before Rec {found}{why}", kind)

    def _unexpected(self, label: str, lineno: int, exp: ExpectedRecord) -> None:
        spec = record_spec(label)
        kind, why = "surplus_record", f"expected Rec {exp.rid} here (record out of order or duplicated)"
        if spec.repeat:
            n = self.values.get(spec.repeat)
            k = int(label.rsplit(".", 1)[1])
            if isinstance(n, int) and k > n:
                kind, why = "cross_field", f"expected no Rec {label}: {spec.repeat} = {n}"
        elif spec.when:
            cond = spec.condition
            if cond.holds(self.values) is False:
                kind = "cross_field"
                why = f"expected no Rec {label}: it requires {cond}, but {cond.field} = {self.values.get(cond.field)}"
        self.problem(lineno, 1, label, None, None, f"unexpected record: {why}", kind)

    def _surplus(self) -> None:
        last = self.records[-1].rid if self.records else "?"
        for i in range(self.idx, len(self.lines)):
            line = self.lines[i]
            if not line.strip():
                continue
            label, _, _ = split_label(line)
            if label is not None and record_spec(label) is None:
                self.problem(i + 1, 5, label, None, None,
                             f"unknown record id 'Rec {label}': expected end of deck after Rec {last}",
                             "unknown_record")
            else:
                self.problem(i + 1, 1, label, None, None,
                             f"surplus record: expected end of deck after Rec {last}", "surplus_record")

    # -- one record -----------------------------------------------------------------------
    def _parse(self, exp: ExpectedRecord, line: str, offset: int, lerr: str | None, labelled: bool) -> None:
        lineno = self.idx + 1
        spec: RecordSpec = exp.spec
        if lerr:
            self.problem(lineno, 1, exp.rid, None, None, lerr, "format")
        if "\t" in line:
            self.problem(lineno, line.index("\t") + 1, exp.rid, None, None,
                         "tab character: expected blanks (fields are fixed columns)", "format")
        # Numbers live in fixed ASCII columns (ADORE reads bytes): a non-ASCII character in a
        # record without text fields is one problem, and its fields are left unread (their
        # columns cannot be told apart); fortran/deck/parser.f90 applies the same rule.
        foreign = None
        if not any(fs.kind == "text" for fs in spec.fields):
            foreign = next((i for i, ch in enumerate(line[offset:], offset) if ord(ch) > 127), None)
        if foreign is not None:
            ch = line[foreign]
            self.problem(lineno, foreign + 1, exp.rid, None, None,
                         f"non-ASCII character '{ch}' (U+{ord(ch):04X}): expected ASCII digits, signs, points, "
                         "exponent letters and blanks (fields are fixed columns of ASCII characters)", "format")
        fields: dict[str, FieldValue] = {}
        local: dict[str, object] = {}
        pos = offset
        names: list[tuple[str, object]] = []
        for fs in spec.fields:
            if fs.count is None:
                names = [(fs.name, fs)]
            else:
                n = local.get(fs.count)
                if foreign is not None:
                    break
                if not isinstance(n, int) or n < 0:
                    self.problem(lineno, pos + 1, exp.rid, fs.name, None,
                                 f"cannot read: its count {fs.count} is unreadable", "type")
                    break
                names = [(f"{fs.name}[{i}]", fs) for i in range(1, n + 1)]
            tokens, _ = cut_fields(line, pos, names)
            for (name, s), tok in zip(names, tokens):
                if foreign is not None:
                    fields[name] = FieldValue(name, s, None, False, lineno, tok.col, tok.text)
                    local[name] = None
                    pos += s.width
                    continue
                value, blank, err = parse_value(s, tok.text)
                if err:
                    kind = "missing_value" if blank else "type"
                    lead = len(tok.text) - len(tok.text.lstrip()) if tok.text.strip() else 0
                    self.problem(lineno, tok.col + lead, exp.rid, name, tok.text.strip() or None, err, kind)
                fields[name] = FieldValue(name, s, value, blank, lineno, tok.col, tok.text)
                local[name] = value
                pos += s.width
        _, extra = cut_fields(line, pos, [])
        text_fields = [f for f in fields.values() if f.spec.kind == "text"]
        if foreign is not None:
            pass
        elif extra is not None and text_fields:
            tf = text_fields[-1]
            full = (tf.raw + line[pos:]).rstrip()
            self.problem(lineno, extra.col, exp.rid, tf.name, full.strip(),
                         f"expected at most {tf.spec.width} characters (run id is {len(full.strip())} long)", "range")
        elif extra is not None:
            self.problem(lineno, extra.col, exp.rid, None, extra.text,
                         f"text after the last field (column {pos}): expected at most {len(fields)} fields", "format")
        occ = self.counts.get(spec.rid, 0)
        self.counts[spec.rid] = occ + 1
        rec = Record(exp.rid, spec, fields, occurrence=occ, line=lineno, labelled=labelled, source=line)
        rec.mark_read()
        self.records.append(rec)
        for n, f in fields.items():
            self.values.setdefault(n, f.value)


def parse_text(text: str, path: str = "<memory>") -> tuple[Deck, list[Problem]]:
    """Parse deck text; returns the (possibly partial) deck and the reading problems
    (format, type, missing/surplus/unknown records, truncation).  Never raises for bad text."""
    reader = _Reader(text, path)
    deck = reader.run()
    return deck, reader.problems


def _load(path) -> tuple[str | None, list[Problem]]:
    p = str(path)
    try:
        data = Path(path).read_bytes()
    except OSError as exc:
        return None, [Problem(p, 0, 0, None, None, None,
                              f"cannot read the file ({exc.strerror or exc}): expected a readable deck file", "io")]
    return decode_bytes(data, p)


def read_deck(path) -> Deck:
    """Read the deck at ``path`` (str or Path) into a :class:`Deck`.

    Raises :class:`DeckError` (an ``AdoreInputError``) listing every reading problem if the
    file is missing, not text, truncated, or has malformed / missing / surplus records.
    Range and cross-field checks are not applied here: call :meth:`Deck.validate`.
    """
    text, problems = _load(path)
    if text is None:
        raise DeckError(f"{path}: cannot read deck", problems)
    deck, problems = parse_text(text, str(path))
    if problems:
        raise DeckError(f"{path}: {len(problems)} problem(s) reading the deck", problems)
    return deck


def check_deck(path) -> tuple[Deck | None, list[Problem]]:
    """Read and validate the deck at ``path``; never raises for bad input.

    Returns ``(deck, problems)``: ``problems`` lists reading problems and validation
    problems (ranges, cross-field) together, in file order where possible; ``deck`` is None
    when the file could not be read completely (it is returned, with its validation
    problems, when only values are out of range).
    """
    try:
        text, problems = _load(path)
        if text is None:
            return None, problems
        deck, read_problems = parse_text(text, str(path))
        problems = read_problems + validate_deck(deck, structure=not read_problems)
        problems.sort(key=lambda p: (p.line == 0, p.line, p.col))
        return (None if read_problems else deck), problems
    except Exception as exc:  # never a traceback for bad input
        return None, [Problem(str(path), 0, 0, None, None, None,
                              f"internal error while checking the deck ({type(exc).__name__}: {exc})", "io")]

