"""The input echo (banner to first step header) as named values.

Echo lines are read by tokens, not columns, so the several-per-line arrangement of the
report can be kept: within a block (``BEARING GEOMETRY`` ... ``SCALE FACTORS AND OUTPUT
CONTROLS``), consecutive words form a label and the numbers after it are its values
(run-together numbers such as ``0.00000E+00-6.00000E-04`` are split).  A line holding
``LABEL: text`` gives a text value.  Lines without numbers are headings and are skipped.
A line starting with a number (a table row without a label) is named ``row<k>``.

Names are ``<block>.<label>`` in snake_case (``bearing_geometry.ball_dia_m``); a label
with several values gives ``<name>[1]``, ``<name>[2]`` ...; a label repeated within a
block gets ``#2``, ``#3`` ...  The banner box gives ``banner.bearing_type``,
``banner.program_mode`` and ``banner.run_id``.
"""

from __future__ import annotations

import re

from .echo_layout import BLOCK_TITLES
from .model import NUMBER_TOKEN, UNKNOWN_VALUE, parse_echo_token

ECHO_BLOCKS = BLOCK_TITLES
_WHOLE_NUMBERS = re.compile(rf"^(?:{NUMBER_TOKEN.pattern})+$")
_BANNER = re.compile(r"Bearing Type\s*=\s*(\S+)\s+Program\s+Mode\s*=\s*(\S+)\s+Run Id\s*=\s*(.*?)\s*\*?\s*$")


def slug(text: str) -> str:
    """snake_case name of a label: ``BALL DIA (m)`` -> ``ball_dia_m``."""
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")


def _tokens(line: str) -> list[tuple[str, object]]:
    out = []
    for word in line.split():
        if _WHOLE_NUMBERS.match(word):
            for t in NUMBER_TOKEN.findall(word):
                out.append(("num", parse_echo_token(t)))
        else:
            out.append(("word", word))
    return out


def _store(echo: dict, block: str, label: str, values: list, fail, lineno: int) -> None:
    base = f"{block}.{slug(label)}"
    name, k = base, 1
    while name in echo or f"{name}[1]" in echo:
        k += 1
        name = f"{base}#{k}"
    if len(values) == 1:
        echo[name] = values[0]
    else:
        for j, v in enumerate(values, 1):
            echo[f"{name}[{j}]"] = v


def parse_echo(lines: list[str], start: int, end: int, fail) -> dict:
    """Named echo values from ``lines[start:end]`` (banner line to first step header).

    Values are int, float, str, or UNKNOWN_VALUE / OVERFLOW_VALUE; units as the label says.
    """
    echo: dict = {}
    block = None
    rows = 0
    for i in range(start, end):
        text = lines[i].strip()
        m = _BANNER.search(text)
        if m:
            echo["banner.bearing_type"] = UNKNOWN_VALUE if m.group(1) == "?" else m.group(1)
            mode = parse_echo_token(m.group(2))
            echo["banner.program_mode"] = mode if mode is not None else m.group(2)
            echo["banner.run_id"] = m.group(3).strip()
            continue
        if text in ECHO_BLOCKS:
            block, rows = slug(text), 0
            continue
        if block is None or not text or set(text) <= {"-", "=", "*"}:
            continue
        if ":" in text:
            label, _, rest = text.partition(":")
            toks = _tokens(rest)
            if toks and all(kind == "num" for kind, _ in toks):
                _store(echo, block, label, [v for _, v in toks], fail, i)
            elif rest.strip():
                echo[f"{block}.{slug(label)}"] = rest.strip()
            continue
        toks = _tokens(text)
        if not any(kind == "num" for kind, _ in toks):
            continue
        label, values = [], []
        if toks[0][0] == "num":
            rows += 1
            label = [f"row{rows}"]
        for kind, val in toks:
            if kind == "word":
                if values:
                    _store(echo, block, " ".join(label), values, fail, i)
                    label, values = [], []
                label.append(val)
            else:
                values.append(val)
        if values:
            _store(echo, block, " ".join(label), values, fail, i)
    return echo
