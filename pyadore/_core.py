"""Thin layer over the f2py extension: status codes become exceptions.

Nothing else in pyadore imports ``pyadore._engine`` directly.  Every wrapper of the
extension returns ``(status, message)``; :func:`check` raises the matching
:class:`~pyadore.errors.AdoreError` subclass for a non-zero status.
"""

from __future__ import annotations

import os
import tempfile

from .errors import (
    STATUS_ENGINE,
    STATUS_INPUT,
    STATUS_OK,
    AdoreEngineError,
    AdoreError,
    AdoreInputError,
)

__all__ = ["check", "run_file", "engine_version", "hertz_point", "deck_field_table"]


def _engine():
    try:
        from . import _engine as engine
    except ImportError as exc:  # the package was installed without its extension
        raise AdoreEngineError(
            "the pyadore engine extension (pyadore._engine) is not built; "
            "run `make setup` (or `pip install -e .`) first"
        ) from exc
    return engine


def _text(value) -> str:
    if isinstance(value, bytes):
        value = value.decode("utf-8", errors="replace")
    return str(value).rstrip()


def check(status: int, message) -> None:
    """Raise the AdoreError subclass that ``status`` stands for (0: return)."""
    if status == STATUS_OK:
        return
    text = _text(message) or f"engine returned status {status}"
    if status == STATUS_INPUT:
        raise AdoreInputError(text)
    if status == STATUS_ENGINE:
        raise AdoreEngineError(text)
    raise AdoreError(f"{text} (unknown engine status {status})")


def run_file(deck_path: str | os.PathLike, out_path: str | os.PathLike, steps: int) -> None:
    """Run the engine on a deck file and write the print file (status checked)."""
    status, message = _engine().adore_run_file(os.fspath(deck_path), os.fspath(out_path), int(steps))
    check(int(status), message)


def engine_version() -> str:
    """Version string compiled into the engine."""
    return _text(_engine().adore_version())


def hertz_point(rho, e1: float, nu1: float, e2: float, nu2: float, load: float) -> dict:
    """Hertz point contact (engine module adore_contact_hertz) as a dict of SI values.

    rho: the four principal curvatures (1/m) [body 1 plane I, II, body 2 plane I, II],
    concave negative.  Keys: kappa, a_star, b_star, delta_star, semi_major (m),
    semi_minor (m), max_pressure (Pa), deflection (m), stiffness (N/m**1.5).
    """
    import numpy as np

    values, status, message = _engine().adore_hertz_point(
        np.asarray(rho, dtype=float), e1, nu1, e2, nu2, load)
    check(int(status), message)
    keys = ["kappa", "a_star", "b_star", "delta_star", "semi_major", "semi_minor",
            "max_pressure", "deflection", "stiffness"]
    return dict(zip(keys, (float(v) for v in values)))


def deck_field_table(deck_path: str | os.PathLike) -> list[tuple[str, int, str, object]]:
    """Read a deck with the engine's Fortran reader and return its field table.

    Same shape as :func:`pyadore.deck.field_table`: ``(record id, occurrence, field name,
    value)`` per field in deck order, occurrence 0-based among records of the same type,
    value int, float (exact: written with 17 significant digits) or str in the schema's
    SI unit.  Raises :class:`AdoreInputError` listing every problem for a bad deck.
    """
    with tempfile.TemporaryDirectory(prefix="pyadore-deck-") as tmp:
        table = os.path.join(tmp, "fields.txt")
        status, message = _engine().adore_deck_table(os.fspath(deck_path), table)
        check(int(status), message)
        with open(table, encoding="utf-8") as fh:
            lines = fh.read().split("\n")
    out: list[tuple[str, int, str, object]] = []
    convert = {"int": int, "real": float, "text": str}
    for line in lines:
        if not line:
            continue
        rid, occ, name, kind, value = line.split("\t", 4)
        out.append((rid, int(occ), name, convert[kind](value.strip() if kind != "text" else value)))
    return out
