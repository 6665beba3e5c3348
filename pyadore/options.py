"""The run options: one table, in the engine (``fortran/model/run_options.f90``).

Every option a run takes beyond the deck is a row of the engine's option table: its name
(the keyword of :func:`pyadore.run` and ``--name`` of ``pyadore run`` / ``adore``), kind,
default, limits or choices and help.  This module reads the table once from the engine and
derives from it

- :func:`options_text`: keyword values checked and turned into the engine's
  ``name=value`` lines (what crosses the f2py boundary);
- :func:`click_options`: the click options of ``pyadore run`` and ``pyadore sweep``.

So a new option is a row in the engine's table, the code that uses it and its test;
neither this module nor the command line changes.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from .errors import AdoreInputError

__all__ = ["RunOption", "run_options", "options_text", "click_options", "INT", "TEXT", "FLAG", "FLAG_OFF",
           "CHOICE", "REAL"]

#: Option kinds (the engine's OPTION_*): an integer, a text (a file), a flag that sets a
#: logical true, a flag whose ``flag`` spelling sets it false, one of ``choices``, a real.
INT, TEXT, FLAG, FLAG_OFF, CHOICE, REAL = 1, 2, 3, 4, 5, 6


@dataclass(frozen=True)
class RunOption:
    """One row of the engine's run option table."""

    name: str
    kind: int
    default: str
    minimum: int
    flag: str
    metavar: str
    choices: tuple[str, ...]
    help: str

    @property
    def default_value(self):
        """The default as a Python value (None where the engine's default is blank)."""
        if self.kind == INT:
            return int(self.default)
        if self.kind == REAL:
            return float(self.default)
        if self.kind in (FLAG, FLAG_OFF):
            return self.default == "true"
        return self.default or None


@lru_cache(maxsize=1)
def run_options() -> tuple[RunOption, ...]:
    """The engine's run option table, in its order: read from the engine once per build of
    its extension and then from a copy in the user's cache folder (:func:`_table_cache`), so
    that the command line's options cost no import of numpy and the engine (about 0.15 s of
    CPU of a ``pyadore sweep`` client's start, the serial path to its first case: docs/sweeps.md,
    "Scaling"; ``pyadore run`` imports the engine anyway)."""
    cache = _table_cache()
    rows = _read_cached(cache)
    if rows is None:
        from ._core import run_option_table

        rows = run_option_table()
        _write_cached(cache, rows)
    return tuple(RunOption(*row) for row in rows)


def _table_cache() -> tuple[Path, str] | None:
    """Where the copy of the option table lives and the key it must carry: the engine
    extension's file (found, not loaded), its size and modification time, so a rebuilt engine
    is read again (an editable install rebuilds it when ``pyadore`` is imported, before this).
    ``$XDG_CACHE_HOME/pyadore`` or ``~/.cache/pyadore``; None when the extension's file is not
    known (then the engine is read every time)."""
    try:
        from importlib.util import find_spec

        origin = find_spec("pyadore._engine").origin
        st = os.stat(origin)
        key = f"{origin}|{st.st_size}|{st.st_mtime_ns}"
        import zlib

        root = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "pyadore"
        return root / f"run-options-{zlib.crc32(origin.encode()):08x}.json", key
    except Exception:  # noqa: BLE001 - no cache: the table is read from the engine
        return None


def _read_cached(cache) -> list[tuple] | None:
    """The cached table when its key is ``cache``'s, else None."""
    if cache is None:
        return None
    import json

    try:
        data = json.loads(cache[0].read_text(encoding="utf-8"))
        if data["key"] != cache[1]:
            return None
        return [(r[0], r[1], r[2], r[3], r[4], r[5], tuple(r[6]), r[7]) for r in data["rows"]]
    except Exception:  # noqa: BLE001 - absent, unreadable, of another format: read the engine
        return None


def _write_cached(cache, rows: list[tuple]) -> None:
    """Keep the table for the next process (atomically; a failure only costs the next one the
    engine's import)."""
    if cache is None:
        return
    import json
    import tempfile

    path, key = cache
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            json.dump({"key": key, "rows": [list(r[:6]) + [list(r[6]), r[7]] for r in rows]}, fh)
        os.replace(tmp, path)
    except OSError:
        try:
            os.unlink(tmp)
        except (OSError, UnboundLocalError):
            pass


def _option(name: str) -> RunOption:
    for opt in run_options():
        if opt.name == name:
            return opt
    names = ", ".join(o.name for o in run_options())
    raise AdoreInputError(f"unknown run option {name!r} (the options: {names})")


def _value_text(opt: RunOption, value) -> str:
    if opt.kind == INT:
        if isinstance(value, bool) or not isinstance(value, int):
            raise AdoreInputError(f"{opt.name} must be an integer >= {opt.minimum} ({opt.help}), got {value!r}")
        if value < opt.minimum:
            raise AdoreInputError(f"{opt.name} must be an integer >= {opt.minimum} ({opt.help}), got {value!r}")
        return str(value)
    if opt.kind == REAL:
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                or value < opt.minimum:
            raise AdoreInputError(f"{opt.name} must be a finite number >= {opt.minimum} ({opt.help}), got {value!r}")
        return repr(float(value))
    if opt.kind in (FLAG, FLAG_OFF):
        if not isinstance(value, bool):
            raise AdoreInputError(f"{opt.name} must be True or False, got {value!r}")
        return "true" if value else "false"
    if opt.kind == TEXT:
        text = os.fspath(value) if isinstance(value, (str, os.PathLike)) else None
        if text is None:
            raise AdoreInputError(f"{opt.name} must be a file name, got {value!r}")
        if not text.strip():
            raise AdoreInputError(f"{opt.name.replace('_', ' ')}: the file name is blank")
        if "\n" in text:
            raise AdoreInputError(f"{opt.name}: a file name with a line break is not supported")
        return text
    text = str(value)
    if "\n" in text:
        raise AdoreInputError(f"{opt.name}: a value with a line break is not supported")
    return text  # a choice: the engine checks it and names the choices


def options_text(**values) -> str:
    """The engine's ``name=value`` lines for the keyword options given (``None``: the
    option's default).  Raises :class:`~pyadore.errors.AdoreInputError` for an unknown
    name or a value of the wrong type; the engine checks ranges and choices."""
    lines = []
    for name, value in values.items():
        opt = _option(name)
        if value is None:
            continue
        lines.append(f"{opt.name}={_value_text(opt, value)}")
    return "\n".join(lines)


def click_options(skip: tuple[str, ...] = ()):
    """A decorator adding every run option (but those in ``skip``) to a click command as
    ``--name`` (flags as ``--name``, an off-flag as its own spelling, e.g. ``--traction-1d``);
    the command receives them as keywords named after the options, ``None`` or the flag's
    default when not given."""
    import click

    def decorate(command):
        for opt in reversed(run_options()):
            if opt.name in skip:
                continue
            dashed = "--" + opt.name.replace("_", "-")
            if opt.kind == INT:
                deco = click.option(dashed, opt.name, type=click.IntRange(min=opt.minimum), default=None,
                                    metavar=opt.metavar or None, help=f"{opt.help} [default: {opt.default}]")
            elif opt.kind == REAL:
                deco = click.option(dashed, opt.name, type=click.FloatRange(min=opt.minimum), default=None,
                                    metavar=opt.metavar or None, help=f"{opt.help} [default: {opt.default}]")
            elif opt.kind == TEXT:
                deco = click.option(dashed, opt.name, type=click.Path(dir_okay=False, path_type=Path), default=None,
                                    metavar=opt.metavar or None, help=opt.help)
            elif opt.kind == CHOICE:
                deco = click.option(dashed, opt.name, type=click.Choice(opt.choices), default=None,
                                    help=f"{opt.help} [default: {opt.default}]")
            elif opt.kind == FLAG:
                deco = click.option(dashed, opt.name, flag_value=True, default=None, help=opt.help)
            else:  # FLAG_OFF: its own spelling sets the option false
                deco = click.option("--" + opt.flag.replace("_", "-"), opt.name, flag_value=False, default=None,
                                    help=opt.help)
            command = deco(command)
        return command

    return decorate
