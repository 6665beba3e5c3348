"""Thin layer over the f2py extension: status codes become exceptions.

Nothing else in pyadore imports ``pyadore._engine`` directly.  Every wrapper of the
extension returns ``(status, message)``; :func:`check` raises the matching
:class:`~pyadore.errors.AdoreError` subclass for a non-zero status.  One module per engine
concept (base, contact, quasistatic, roller_tribology, model, life, deck, printer, tribology), everything
re-exported here: ``from pyadore import _core; _core.hertz_point(...)``.
"""

from .base import check, run_option_table, run_file, RunOutput, engine_version  # noqa: F401
from .contact import hertz_point, LINE_CONTACT_RESULT, line_contact  # noqa: F401
from .quasistatic import BALL_QS_COLUMNS, ball_quasi_static, ball_race_jacobian, race_control, mount_races, BALL_STEP0_COLUMNS, BALL_STEP0_SUMMARY, ball_step0_from_deck, ROLLER_STEP0_COLUMNS, ROLLER_STEP0_SLICES, ROLLER_STEP0_SUMMARY, roller_step0_from_deck  # noqa: F401
from .roller_tribology import ROLLER_TRIBOLOGY_COLUMNS, ROLLER_TRIBOLOGY_SLICES, ROLLER_TRIBOLOGY_SUMMARY, SPIN_ROLLING, SPIN_EQUILIBRIUM, roller_step0_tribology  # noqa: F401
from .model import ball_clearance, roller_races, body_inertia, traction_fit, traction_eval, scale_factors  # noqa: F401
from .life import LIFE_CONSTANT_NAMES, life_default_constants, ball_bearing_life  # noqa: F401
from .deck import deck_field_table, cross_field_fields, cross_field_rules, cross_field_problems  # noqa: F401
from .printer import fortran_print_step, fortran_print_end, fortran_print_echo  # noqa: F401
from .tribology import film_thickness, thermal_reduction_factor, lubricant, LUBRICANT_KEYS, CONTACT_TRACTION_KEYS, contact_traction, ehd_contact_traction, ehd_contact_method, ehd_contact_microseconds, EHD_METHOD_KEYS, ehd_temperature_rise, film_shear_stress, contact_slip, flash_rise, contact_temperature_rise, wear_rate, traction_table  # noqa: F401

__all__ = [
    "check",
    "run_option_table",
    "run_file",
    "RunOutput",
    "engine_version",
    "hertz_point",
    "LINE_CONTACT_RESULT",
    "line_contact",
    "BALL_QS_COLUMNS",
    "ball_quasi_static",
    "ball_race_jacobian",
    "race_control",
    "mount_races",
    "BALL_STEP0_COLUMNS",
    "BALL_STEP0_SUMMARY",
    "ball_step0_from_deck",
    "ROLLER_STEP0_COLUMNS",
    "ROLLER_STEP0_SLICES",
    "ROLLER_STEP0_SUMMARY",
    "roller_step0_from_deck",
    "ROLLER_TRIBOLOGY_COLUMNS",
    "ROLLER_TRIBOLOGY_SLICES",
    "ROLLER_TRIBOLOGY_SUMMARY",
    "SPIN_ROLLING",
    "SPIN_EQUILIBRIUM",
    "roller_step0_tribology",
    "ball_clearance",
    "roller_races",
    "body_inertia",
    "traction_fit",
    "traction_eval",
    "scale_factors",
    "LIFE_CONSTANT_NAMES",
    "life_default_constants",
    "ball_bearing_life",
    "deck_field_table",
    "cross_field_fields",
    "cross_field_rules",
    "cross_field_problems",
    "fortran_print_step",
    "fortran_print_end",
    "fortran_print_echo",
    "film_thickness",
    "thermal_reduction_factor",
    "lubricant",
    "LUBRICANT_KEYS",
    "ehd_contact_traction",
    "ehd_contact_method",
    "ehd_contact_microseconds",
    "EHD_METHOD_KEYS",
    "ehd_temperature_rise",
    "film_shear_stress",
    "CONTACT_TRACTION_KEYS",
    "contact_traction",
    "contact_slip",
    "flash_rise",
    "contact_temperature_rise",
    "wear_rate",
    "traction_table",
]
