"""Derived deck fields: inputs an engineer thinks in that the deck stores as another field.

``diametral_clearance`` (m) of a ball bearing: the deck (Rec 5A) stores the free
(unmounted) contact angle alpha0, which the radial play fixes with the groove curvatures
(Harris & Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., section 2.3;
docs/examples.md)::

    P_d = 2 A (1 - cos alpha0),   A = (f_o + f_i - 1) D

D the ball diameter, f_o and f_i the outer and inner curvature factors.  Setting the
clearance writes ``alpha0 = acos(1 - P_d / (2 A))``, rounded to the digits the deck's 11
columns hold (at least 5 significant digits: the clearance holds to about 1e-4 of itself);
reading it gives P_d of the deck's alpha0.  :meth:`pyadore.deck.Deck.set`,
:meth:`~pyadore.deck.Deck.lookup`, ``pyadore.run(..., overrides=)`` and sweeps
(``--vary diametral_clearance=0:50e-6:6``) take the name like a deck field.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = ["DERIVED_FIELDS", "DerivedField", "free_contact_angle_deg", "diametral_clearance_m"]


def _ball_geometry(deck) -> tuple[float, float, float]:
    from .problems import DeckError

    rec = deck.record("5A")
    if rec is None:
        raise DeckError(f"diametral_clearance: a ball bearing's field (Rec 5A); this deck ({deck.path}) has no "
                        "Rec 5A (a roller bearing's clearance is its own field of Rec 5B)")
    return (rec.fields["ball_diameter"].value, rec.fields["outer_curvature_factor"].value,
            rec.fields["inner_curvature_factor"].value)


def free_contact_angle_deg(ball_diameter: float, outer_curvature: float, inner_curvature: float,
                           clearance: float) -> float:
    """Free contact angle (deg) of a ball bearing with diametral clearance ``clearance``
    (m): acos(1 - P_d / (2 (f_o + f_i - 1) D)).  ValueError outside 0 <= P_d < 2 A (the
    contact angle reaches 90 deg at P_d = 2 A)."""
    a = (outer_curvature + inner_curvature - 1.0) * ball_diameter
    if not math.isfinite(clearance) or clearance < 0.0 or clearance >= 2.0 * a:
        raise ValueError(f"diametral clearance {clearance!r} m: must be >= 0 and below 2 (f_o + f_i - 1) D = "
                         f"{2.0 * a:.6g} m (a 90 deg contact angle)")
    return math.degrees(math.acos(1.0 - clearance / (2.0 * a)))


def diametral_clearance_m(ball_diameter: float, outer_curvature: float, inner_curvature: float,
                          angle_deg: float) -> float:
    """Diametral clearance (m) of a free contact angle ``angle_deg``: 2 A (1 - cos alpha0)."""
    a = (outer_curvature + inner_curvature - 1.0) * ball_diameter
    return 2.0 * a * (1.0 - math.cos(math.radians(angle_deg)))


def _writable(fv, value: float) -> float:
    """``value`` rounded to the most significant digits field ``fv`` can hold."""
    from .problems import DeckError
    from .values import FieldValue
    from .writer import format_value

    for digits in (9, 8, 7, 6, 5, 4, 3):
        cand = float(f"{value:.{digits}g}")
        try:
            format_value(FieldValue(fv.name, fv.spec, cand))
        except DeckError:
            continue
        return cand
    return value


def _get_clearance(deck) -> float:
    d, fo, fi = _ball_geometry(deck)
    return diametral_clearance_m(d, fo, fi, deck.get("5A", "free_contact_angle"))


def _set_clearance(deck, value) -> None:
    from .problems import DeckError

    d, fo, fi = _ball_geometry(deck)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise DeckError(f"diametral_clearance: expected a number (m), got {value!r}")
    try:
        angle = free_contact_angle_deg(d, fo, fi, float(value))
    except ValueError as exc:
        raise DeckError(str(exc)) from None
    fv = deck.record("5A").fields["free_contact_angle"]
    fv.value = _writable(fv, angle)
    fv.blank = False


@dataclass(frozen=True)
class DerivedField:
    """A derived field: its name, unit, meaning, the deck field it sets (record, field) and
    its getter and setter on a Deck."""

    name: str
    unit: str
    meaning: str
    record: str
    sets: str
    get: object
    set: object
    kind: str = "real"


DERIVED_FIELDS = {
    "diametral_clearance": DerivedField(
        "diametral_clearance", "m", "diametral clearance (ball bearings; sets the free contact angle, Rec 5A)",
        "5A", "free_contact_angle", _get_clearance, _set_clearance),
}
