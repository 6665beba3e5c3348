"""Python layer of the test-only f2py extension ``pyadore._probes``: the engine's building
blocks that only the tests call (Hertz and line contacts, quasi-static solutions, derived
echo quantities, fatigue life, the Fortran deck reader and print writer, the tribology
pieces), one thin wrapper each, status codes checked as in :mod:`pyadore._core`.

The production extension ``pyadore._engine`` (layer :mod:`pyadore._core`) holds only what
the package and bench/ call; this layer lives with the tests because nothing in the package
uses it, and ``pyadore._probes`` is built only with the meson option ``probes`` (``make
setup`` turns it on).  Tests import it as ``import probes`` (tests/ is on sys.path under
pytest) and call production functions through ``pyadore._core``.
"""

from .contact import hertz_point, LINE_CONTACT_RESULT, line_contact  # noqa: F401
from .quasistatic import BALL_QS_COLUMNS, ball_quasi_static, ball_race_jacobian, race_control, mount_races, ROLLER_STEP0_COLUMNS, ROLLER_STEP0_SLICES, ROLLER_STEP0_SUMMARY, roller_step0_from_deck  # noqa: F401
from .roller_tribology import ROLLER_TRIBOLOGY_COLUMNS, ROLLER_TRIBOLOGY_SLICES, ROLLER_TRIBOLOGY_SUMMARY, SPIN_ROLLING, SPIN_EQUILIBRIUM, roller_step0_tribology  # noqa: F401
from .model import ball_clearance, roller_races, body_inertia, traction_fit, scale_factors  # noqa: F401
from .life import LIFE_CONSTANT_NAMES, life_default_constants, ball_bearing_life  # noqa: F401
from .deck import deck_field_table  # noqa: F401
from .printer import fortran_print_step, fortran_print_end, fortran_print_echo  # noqa: F401
from .tribology import film_thickness, thermal_reduction_factor, CONTACT_TRACTION_KEYS, contact_traction, ehd_contact_traction, ehd_temperature_rise, film_shear_stress, contact_slip, flash_rise, contact_temperature_rise, wear_rate  # noqa: F401
