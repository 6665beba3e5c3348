"""The engine's cross-field deck checks (fortran/model/checks.f90; pyadore.deck.validate): without
numpy while the engine extension is not imported (:mod:`.lite`)."""

from __future__ import annotations

from .base import _engine, _text, check


def _names(what: int) -> tuple[str, ...]:
    return tuple(line for line in _text(_engine(lite=True).adore_deck_cross_check_names(what)).split("\n") if line)


def cross_field_fields() -> tuple[str, ...]:
    """Names of the deck fields the engine's cross-field checks read, in the order of
    :func:`cross_field_problems`' values (fortran/model/checks.f90 CHECK_FIELDS)."""
    return _names(1)


def cross_field_rules() -> tuple[str, ...]:
    """What each of the engine's cross-field checks requires, in the order they are applied
    (fortran/model/checks.f90 CHECK_RULES; listed in docs/deck-format.md)."""
    return _names(2)


def cross_field_problems(values: dict[str, object]) -> list[tuple[str, str, bool]]:
    """The engine's cross-field checks (the ones ``adore`` applies before a run) on deck values.

    ``values`` maps each name of :func:`cross_field_fields` to its value in the deck (the first
    field of that name, schema SI units), None or absent when missing or unreadable.
    Returns ``(field name, message, warning)`` per violated relation, in rule order;
    ``warning`` is True for a legal but implausible value (the run goes on), False for an
    error (the run refuses the deck).
    """
    names = cross_field_fields()
    nums = [values.get(n) for n in names]
    have = [int(isinstance(v, (int, float)) and not isinstance(v, bool)) for v in nums]
    vals = [float(v) if h else 0.0 for v, h in zip(nums, have)]
    n, fields, warning, messages, status, message = _engine(lite=True).adore_deck_cross_checks(vals, have, len(names) + 8)
    check(int(status), message)
    texts = _text(messages).split("\n") if n else []
    return [(names[fields[i] - 1], texts[i], bool(warning[i])) for i in range(int(n))]
