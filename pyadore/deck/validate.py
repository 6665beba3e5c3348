"""Value checks of a parsed deck: ranges from the schema, cross-field consistency, structure.

All problems are collected and returned at once; nothing raises.  Fields whose value is
None (unreadable; already reported by the reader) are skipped.
"""

from __future__ import annotations

import math

from .model import Deck, FieldValue, Problem, Record
from .schema import expected_records

__all__ = ["validate_deck", "CROSS_CHECKS"]


def _problem(deck: Deck, rec: Record | None, fv: FieldValue | None, msg: str, kind: str) -> Problem:
    if rec is None:
        return Problem(str(deck.path), 0, 0, None, None, None, msg, kind)
    if fv is None:
        return Problem(str(deck.path), rec.line, 1 if rec.line else 0, rec.rid, None, None, msg, kind,
                       rec.source if rec.line else None)
    lead = len(fv.raw) - len(fv.raw.lstrip()) if fv.raw.strip() else 0  # caret on the first character
    return Problem(str(deck.path), fv.line, fv.col + lead if fv.line else 0, rec.rid, fv.name, fv.value, msg,
                   kind, rec.source if fv.line else None)


def _ranges(deck: Deck) -> list[Problem]:
    out = []
    for rec in deck.records:
        for fv in rec.fields.values():
            v = fv.value
            if v is None:
                continue
            spec = fv.spec
            if spec.kind == "text":
                if len(v) > 36:
                    out.append(_problem(deck, rec, fv, "expected at most 36 characters", "range"))
                continue
            if not spec.in_range(v):
                out.append(_problem(deck, rec, fv, f"expected {spec.range_text()} ({spec.meaning.split(';')[0]})",
                                    "range"))
    return out


def _find(deck: Deck, name: str) -> tuple[Record | None, FieldValue | None]:
    for rec in deck.records:
        fv = rec.fields.get(name)
        if fv is not None:
            return rec, fv
    return None, None


def _num(deck: Deck, name: str):
    _, fv = _find(deck, name)
    return None if fv is None else fv.value


def _fmt(x) -> str:
    return f"{x:.6G}" if isinstance(x, float) else str(x)


def _less(a: str, b: str, what: str):
    """Check field a < field b; report on field a."""
    def check(deck: Deck) -> list[Problem]:
        va, vb = _num(deck, a), _num(deck, b)
        if va is None or vb is None or va < vb:
            return []
        rec, fv = _find(deck, a)
        return [_problem(deck, rec, fv, f"expected < {b} = {_fmt(vb)} ({what})", "cross_field")]
    check.__doc__ = f"{a} < {b}: {what}"
    return check


def _element_diameter(deck: Deck) -> str:
    return "ball_diameter" if deck.lookup("ball_diameter") is not None else "roller_diameter"


def _pitch_between_bore_and_od(deck: Deck) -> list[Problem]:
    """shaft_outer_diameter (bore) < pitch_diameter < bearing_outer_diameter."""
    dp, bore, od = _num(deck, "pitch_diameter"), _num(deck, "shaft_outer_diameter"), _num(deck, "bearing_outer_diameter")
    if dp is None or bore is None or od is None or bore < dp < od:
        return []
    rec, fv = _find(deck, "pitch_diameter")
    return [_problem(deck, rec, fv, f"expected between the bore (shaft_outer_diameter = {_fmt(bore)}) and "
                     f"bearing_outer_diameter = {_fmt(od)}", "cross_field")]


def _elements_fit_radially(deck: Deck) -> list[Problem]:
    """element diameter < (bearing_outer_diameter - shaft_outer_diameter) / 2."""
    name = _element_diameter(deck)
    d, bore, od = _num(deck, name), _num(deck, "shaft_outer_diameter"), _num(deck, "bearing_outer_diameter")
    if d is None or bore is None or od is None or d < (od - bore) / 2:
        return []
    rec, fv = _find(deck, name)
    return [_problem(deck, rec, fv, f"expected < (bearing_outer_diameter - shaft_outer_diameter)/2 = "
                     f"{_fmt((od - bore) / 2)} (the element must fit between bore and OD)", "cross_field")]


def _elements_fit_around(deck: Deck) -> list[Problem]:
    """n elements of diameter D fit around the pitch circle: pitch_diameter * sin(pi/n) > D."""
    name = _element_diameter(deck)
    d, dp, n = _num(deck, name), _num(deck, "pitch_diameter"), _num(deck, "n_rolling_elements")
    if d is None or dp is None or not isinstance(n, int) or n < 2 or dp <= 0:
        return []
    chord = dp * math.sin(math.pi / n)
    if chord > d:
        return []
    n_max = max(int(math.pi / math.asin(min(d / dp, 1.0))), 1) if d < dp else 1
    rec, fv = _find(deck, "n_rolling_elements")
    return [_problem(deck, rec, fv, f"expected at most {n_max}: {n} elements of {name} = {_fmt(d)} m do not fit "
                     f"around pitch_diameter = {_fmt(dp)} m (spacing {_fmt(chord)} m)", "cross_field")]


def _cage_around_pitch(deck: Deck) -> list[Problem]:
    """cage_inner_diameter < pitch_diameter < cage_outer_diameter (the cage carries the elements)."""
    ci, co, dp = _num(deck, "cage_inner_diameter"), _num(deck, "cage_outer_diameter"), _num(deck, "pitch_diameter")
    if ci is None or co is None or dp is None or not ci < co or ci < dp < co:
        return []
    rec, fv = _find(deck, "pitch_diameter")
    return [_problem(deck, rec, fv, f"expected between cage_inner_diameter = {_fmt(ci)} and "
                     f"cage_outer_diameter = {_fmt(co)}", "cross_field")]


def _race_walls(deck: Deck) -> list[Problem]:
    """inner raceway diameter > shaft_outer_diameter and outer raceway diameter <
    bearing_outer_diameter: both races have a wall (once bore < pitch < OD and the element
    fits radially)."""
    # the engine's raceway diameters (fortran/model/clearance.f90): ball dm -/+ (D + 2 (f - 1/2)
    # D (1 - cos alpha0)), roller dm -/+ (D + Pd/2); the mounting's thick-ring formulas divide
    # by each wall's thickness
    name = _element_diameter(deck)
    d, dp = _num(deck, name), _num(deck, "pitch_diameter")
    bore, od = _num(deck, "shaft_outer_diameter"), _num(deck, "bearing_outer_diameter")
    if None in (d, dp, bore, od) or not (bore < dp < od and d < (od - bore) / 2):
        return []
    if name == "ball_diameter":
        fo, fi, a0 = (_num(deck, n) for n in ("outer_curvature_factor", "inner_curvature_factor",
                                              "free_contact_angle"))
        if None in (fo, fi, a0):
            return []
        c = 1.0 - math.cos(math.radians(a0))
        d_outer = dp + d + 2.0 * (fo - 0.5) * d * c
        d_inner = dp - d - 2.0 * (fi - 0.5) * d * c
    else:
        pd = _num(deck, "diametral_play")
        if pd is None:
            return []
        d_outer = dp + d + 0.5 * pd
        d_inner = dp - d - 0.5 * pd
    rec, fv = _find(deck, "pitch_diameter")
    out = []
    if not d_inner > bore:
        out.append(_problem(deck, rec, fv, f"the inner race has no wall: its raceway diameter {_fmt(d_inner)} m "
                            f"is not above the bore (shaft_outer_diameter = {_fmt(bore)})", "cross_field"))
    if not d_outer < od:
        out.append(_problem(deck, rec, fv, f"the outer race has no wall: its raceway diameter {_fmt(d_outer)} m "
                            f"is not below bearing_outer_diameter = {_fmt(od)}", "cross_field"))
    return out


def _step_order(deck: Deck) -> list[Problem]:
    """step_min <= step_initial <= step_max."""
    lo, ini, hi = _num(deck, "step_min"), _num(deck, "step_initial"), _num(deck, "step_max")
    if lo is None or ini is None or hi is None or lo <= ini <= hi:
        return []
    rec, fv = _find(deck, "step_initial")
    return [_problem(deck, rec, fv, f"expected between step_min = {_fmt(lo)} and step_max = {_fmt(hi)}",
                     "cross_field")]


def _traction_peak(deck: Deck) -> list[Problem]:
    """max_traction >= traction_at_zero_slip and >= traction_at_infinite_slip."""
    mx = _num(deck, "max_traction")
    others = [(n, _num(deck, n)) for n in ("traction_at_zero_slip", "traction_at_infinite_slip")]
    if mx is None or all(v is None or v <= mx for _, v in others):
        return []
    rec, fv = _find(deck, "max_traction")
    worst = max((v for _, v in others if v is not None))
    return [_problem(deck, rec, fv, f"expected >= {_fmt(worst)} (the maximum of the traction-slip curve)",
                     "cross_field")]


#: Every cross-field check, in the order they are applied (documented in docs/deck-format.md).
CROSS_CHECKS = (
    _less("shaft_inner_diameter", "shaft_outer_diameter", "a hollow shaft's bore is inside its OD"),
    _less("shaft_outer_diameter", "bearing_outer_diameter", "bore inside the bearing OD"),
    _less("bearing_outer_diameter", "housing_outer_diameter", "bearing inside the housing"),
    _pitch_between_bore_and_od,
    _elements_fit_radially,
    _elements_fit_around,
    _less("cage_inner_diameter", "cage_outer_diameter", "cage ID inside cage OD"),
    _cage_around_pitch,
    _race_walls,
    _step_order,
    _traction_peak,
)


def _structure(deck: Deck) -> list[Problem]:
    """Records present exactly as the schema and the deck's own flags/counts require."""
    values = deck.values()
    try:
        expected = [e.rid for e in expected_records(lambda: values)]
    except LookupError as exc:
        return [_problem(deck, None, None, f"cannot determine the record sequence: field {exc.args[0]} "
                         "is missing or unreadable", "cross_field")]
    actual = [r.rid for r in deck.records]
    out = []
    for rid in expected:
        if rid not in actual:
            out.append(_problem(deck, deck.records[-1] if deck.records else None, None,
                                f"missing record: expected Rec {rid} (required by the deck's flags/counts)",
                                "cross_field"))
    for rec in deck.records:
        if rec.rid not in expected:
            out.append(_problem(deck, rec, None, f"unexpected record: Rec {rec.rid} is not required by "
                                "the deck's flags/counts", "cross_field"))
    return out


def validate_deck(deck: Deck, structure: bool = True) -> list[Problem]:
    """All range, cross-field (and, if ``structure``, record-presence) problems of ``deck``."""
    out = _ranges(deck)
    for check in CROSS_CHECKS:
        out.extend(check(deck))
    if structure and deck.records:
        out.extend(_structure(deck))
    return out
