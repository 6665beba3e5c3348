"""Thin layer over the production f2py extension: status codes become exceptions.

Nothing else in pyadore imports ``pyadore._engine`` directly.  Every wrapper of the
extension returns ``(status, message)``; :func:`check` raises the matching
:class:`~pyadore.errors.AdoreError` subclass for a non-zero status.  The extension holds
only what the package and bench/ call (fortran/api/_engine.pyf); the engine's other building
blocks, which only the tests call, are the test-only extension ``pyadore._probes``
(fortran/api/probes/) with its own layer in tests/probes/.  One module per engine concept
(base, deck, model, quasistatic, tribology), everything re-exported here:
``from pyadore import _core; _core.lubricant(...)``.  A run and the deck's cross-field checks
call the extension's shared object through ctypes, without numpy, while the module is not
imported (:mod:`.lite`).
"""

from .base import check, run_option_table, run_file, RunOutput, engine_version  # noqa: F401
from .deck import cross_field_fields, cross_field_rules, cross_field_problems  # noqa: F401
from .model import traction_eval  # noqa: F401
from .quasistatic import BALL_STEP0_COLUMNS, BALL_STEP0_SUMMARY, ball_step0_from_deck  # noqa: F401
from .tribology import LUBRICANT_KEYS, lubricant, traction_table, EHD_METHOD_KEYS, ehd_contact_method, ehd_contact_microseconds  # noqa: F401

__all__ = [
    "check",
    "run_option_table",
    "run_file",
    "RunOutput",
    "engine_version",
    "cross_field_fields",
    "cross_field_rules",
    "cross_field_problems",
    "traction_eval",
    "BALL_STEP0_COLUMNS",
    "BALL_STEP0_SUMMARY",
    "ball_step0_from_deck",
    "LUBRICANT_KEYS",
    "lubricant",
    "traction_table",
    "EHD_METHOD_KEYS",
    "ehd_contact_method",
    "ehd_contact_microseconds",
]
