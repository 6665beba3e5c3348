"""The input echo of ADORE 5.0 (banner box to first step header) as data.

This is the echo part of the print layout (docs/print-layout.md, section 3), shared by
the Python echo writer (:mod:`.echo_writer`) and - through the generated
``fortran/output/layout.f90`` - the engine's echo writer
(``fortran/output/print_echo.f90``).  It fixes

* the fields of the echo record (``echo_data_t`` in ``fortran/output/echo_data.f90``):
  :data:`TEXT_FIELDS`, :data:`INT_FIELDS` and :data:`REAL_FIELDS` with their sizes, in the
  order of the flat vectors that cross the f2py boundary;
* the labels, label widths and literal heading lines of every echo block, in print order.

A field reference in a layout row is ``name`` (scalar) or ``name[k]`` (1-based element of
an array field).  Matrix fields are stored as Fortran arrays ``(values per printed row,
printed rows)``, flattened in Fortran (column-major) order: printed row ``k`` of
``material`` is ``material[6*(k-1)+1 .. 6*k]``.
"""

from __future__ import annotations

#: Largest number of guide lands / quasi-static constraint flags an echo holds.
MAX_GUIDE = 8
MAX_QS = 6
TEXT_LEN = 80
ELEMENT_BALL = 1
ELEMENT_ROLLER = 2

#: Text fields (character(len=TEXT_LEN)).
TEXT_FIELDS = ("bearing_type", "run_id", "title", "lubricant", "weibull_slope", "life_mod_code", "coolant_type",
               "node_base_temp", "vary_geometry")
#: Integer fields and their sizes.
INT_FIELDS = (
    ("element_kind", 1), ("program_mode", 1), ("n_elements", 1), ("pocket_shape", 1), ("n_lands", 1),
    ("n_cage_segs", 1), ("n_guide", 1), ("guide_land", MAX_GUIDE), ("guide_type", MAX_GUIDE), ("n_qs", 1),
    ("qs_constraints", MAX_QS), ("trans_constraints", 6), ("rot_constraints", 6), ("print_htc", 1),
    ("n_steps", 1), ("data_control", 3), ("auto_plots", 3), ("int_method", 1),
)
#: Real fields and their Fortran shapes.
REAL_FIELDS = (
    ("element_dia", ()), ("pitch_dia", ()), ("contact_angle", ()), ("cur_fac", (2,)), ("dia_play", ()),
    ("end_play", ()), ("fit", (2,)), ("width", (2,)), ("shaft_od", ()), ("shaft_id", ()), ("bearing_od", ()),
    ("housing_od", ()), ("roller_len", ()), ("cen_land", ()), ("outer_len", (2,)), ("inner_len", (2,)),
    ("crown_rad", ()), ("cor_rad", (2,)), ("race_crown", (2,)),
    ("cage_od", ()), ("cage_id", ()), ("cage_cone", ()), ("cage_width", ()), ("seg_cut", ()), ("poc_cls", (2,)),
    ("race_cls", (2,)), ("guide", (4, MAX_GUIDE)),
    ("material", (6, 9)), ("inertia", (7, 4)), ("principal", (3, 4)), ("lubrication", (9, 4)),
    ("fatigue", (5, 2)), ("asperity", (8, 2)),
    ("room_temp", ()), ("housing_temp", ()), ("shaft_temp", ()), ("re_temp", ()), ("cage_temp", ()),
    ("race_speed", (2,)), ("race_temp", (2,)), ("misalign_y", (2,)), ("misalign_z", (2,)),
    ("load_fraction", ()), ("heat_trans_coeff", ()),
    ("applied_load", (3,)), ("rel_disp", (3,)), ("applied_moment", (3,)), ("gravity", (3,)),
    ("cage_position", (3,)), ("cage_angle", (3,)), ("whirl_ratio", ()), ("epicyclic_ratio", ()),
    ("scale_length", ()), ("scale_load", ()), ("scale_time", ()), ("step_min", ()), ("step_max", ()),
    ("step_initial", ()), ("error_limit", ()),
)


def size_of(shape: tuple) -> int:
    n = 1
    for d in shape:
        n *= d
    return n


# ------------------------------------------------------------------------------ banner box
COPYRIGHT = "Copyright Pradeep K Gupta Inc"
BOX_RULE = "*" * 120
#: ``('*  Bearing Type = ',A12,'Program Mode = ',I1,5X,'Run Id = ',A,T120,'*')``
BOX_TYPE_TEXT = "*  Bearing Type = "
BOX_MODE_TEXT = "Program Mode = "
BOX_RUN_TEXT = "Run Id = "

BLOCK_TITLES = (
    "BEARING GEOMETRY", "MATERIAL PROPERTIES", "INERTIAL PARAMETERS", "LUBRICATION PARAMETERS",
    "FATIGUE PARAMETERS", "INITIAL OPERATING CONDITIONS", "SCALE FACTORS AND OUTPUT CONTROLS",
)

# ------------------------------------------------------------------- item grids (A20 cells)
#: Item cell ``(1X,A<w>,ES12.5)`` / ``(1X,A<w>,I12)``; a field starting ``i:`` is an integer.
ITEM_WIDTH = 20
GEOM_BALL = (
    (("NO OF BALLS", "i:n_elements"), ("OUTER CUR FAC", "cur_fac[1]"), ("OUTER FIT (m)", "fit[1]"),
     ("SHAFT OD (m)", "shaft_od")),
    (("BALL DIA (m)", "element_dia"), ("INNER CUR FAC", "cur_fac[2]"), ("INNER FIT (m)", "fit[2]"),
     ("SHAFT ID (m)", "shaft_id")),
    (("PITCH DIA (m)", "pitch_dia"), ("DIA PLAY (m)", "dia_play"), ("WIDTH I (m)", "width[1]"),
     ("BEARING OD (m)", "bearing_od")),
    (("CON ANGLE (deg)", "contact_angle"), ("END PLAY (m)", "end_play"), ("WIDTH II (m)", "width[2]"),
     ("HOUSING OD (m)", "housing_od")),
)
#: ``None``: an empty cell (33 blanks).
GEOM_ROLLER = (
    (("NO OF ROLLERS", "i:n_elements"), ("PITCH DIA (m)", "pitch_dia"), ("OUTER FIT (m)", "fit[1]"),
     ("SHAFT OD (m)", "shaft_od")),
    (("ROLLER DIA (m)", "element_dia"), ("CROWN RAD (m)", "crown_rad"), ("INNER FIT (m)", "fit[2]"),
     ("SHAFT ID (m)", "shaft_id")),
    (("ROLLER LEN (m)", "roller_len"), ("COR RAD I (m)", "cor_rad[1]"), ("DIA PLAY (m)", "dia_play"),
     ("BEARING OD (m)", "bearing_od")),
    (("CEN LAND (m)", "cen_land"), ("COR RAD II (m)", "cor_rad[2]"), ("OUTER CRN (m)", "race_crown[1]"),
     ("HOUSING OD (m)", "housing_od")),
    (("OUTER LEN1 (m)", "outer_len[1]"), ("INNER LEN1 (m)", "inner_len[1]"), ("INNER CRN (m)", "race_crown[2]"),
     ("WIDTH I (m)", "width[1]")),
    (("OUTER LEN2 (m)", "outer_len[2]"), ("INNER LEN2 (m)", "inner_len[2]"), None, ("WIDTH II (m)", "width[2]")),
)
CAGE_ITEMS = (
    (("CAGE OD (m)", "cage_od"), ("CAGE WIDTH (m)", "cage_width"), ("POC CLS I (m)", "poc_cls[1]"),
     ("OUTER CLS (m)", "race_cls[1]")),
    (("CAGE ID (m)", "cage_id"), ("SEG CUT (deg)", "seg_cut"), ("POC CLS II (m)", "poc_cls[2]"),
     ("INNER CLS (m)", "race_cls[2]")),
    (("CAGE CONE (deg)", "cage_cone"), ("POCKET SHAPE", "i:pocket_shape"), ("NO OF C/R LANDS", "i:n_lands"),
     ("NO OF CAGE SEGS", "i:n_cage_segs")),
)
#: Guide-land table: these heading lines, then rows ``(2I9,4(1X,ES12.5))``.
GUIDE_HEAD = (
    "    GUIDE    GUIDE   GUIDE LAND   GUIDE LAND   GUIDE LAND   GUIDE LAND",
    "     LAND     TYPE          DIA          CLS        WIDTH     POSITION",
    "                            (m)          (m)          (m)          (m)",
)


def _mat(label: str, texts, w: int) -> str:
    """A heading line in the ``(1X,A<w>,n(1X,A12))`` grid of a matrix."""
    return (f" {label:<{w}}" + "".join(f" {t:>12}" for t in texts)).rstrip()


# ----------------------------------------------------------------------- matrices (1X,A<w>)
MAT_WIDTH = 28
MAT_HEAD = _mat("", ["ROLLING ELEM", "OUTER RACE", "INNER RACE", "CAGE", "SHAFT", "HOUSING"], MAT_WIDTH)
MAT_LABELS = ("DENSITY (kg/m**3)", "ELASTIC MODULUS (Pa)", "POISSON-S RATIO", "COEFF OF THERMAL EXP",
              "THERMAL CONDUCTIVITY (W/m/K)", "HEAT CAPACITY (J/kg/K)", "ELASTIC STRAIN LIMIT", "HARDNESS (RC)",
              "WEAR COEFFICIENT")
#: Values printed on each material row (shaft and housing only for the first five).
MAT_COUNTS = (6, 6, 6, 6, 6, 4, 4, 4, 4)

BODY_WIDTH = 12
BODY_LABELS = ("RE", "CAGE", "OUTER RACE", "INNER RACE")
INERTIA_HEAD = (
    _mat("", ["MASS", "MOMENT OF", "INERTIA", "", "MASS TO GEO", "CENTER", ""], BODY_WIDTH),
    _mat("", ["(kg)", "(kg*m**2)", "", "", "(m)", "", ""], BODY_WIDTH),
    _mat("", ["", "X-COMP", "Y-COMP", "Z-COMP", "X-COMP", "Y-COMP", "Z-COMP"], BODY_WIDTH),
)
PRINCIPAL_HEAD = (
    _mat("", ["PRINCIPAL TO", "GEO FRAME", ""], BODY_WIDTH),
    _mat("", ["(deg)", "", ""], BODY_WIDTH),
    _mat("", ["X-COMP", "Y-COMP", "Z-COMP"], BODY_WIDTH),
)
LUB_HEAD = (
    _mat("", ["HYPOTHETICAL", "TRAC COEFF", "MAXIMUM", "TRAC COEFF", "SLIP AT MAX", "COEFFICIENT", "COEFFICIENT",
              "COEFFICIENT", "COEFFICIENT"], BODY_WIDTH),
    _mat("", ["MODELS", "AT ZERO SLIP", "TRAC COEFF", "AT INF SLIP", "TRACTION", "A", "B", "C", "D"], BODY_WIDTH),
    _mat("", ["", "", "", "", "(m/s)", "", "(s/m)", "(s/m)", ""], BODY_WIDTH),
)
LUB_LABELS = ("RE/RACE1", "RE/RACE2", "RE/CAGE", "RACE/CAGE")
#: ``(1X,A11,A)``, printed (after a blank line) only when the lubricant name is not blank.
LUBRICANT_LABEL = "LUBRICANT:"
LUBRICANT_WIDTH = 11
FAT_HEAD = (
    _mat("", ["LINE CONTACT", "CONTACT", "POINT CONT", "CONTACT", "WEIBULL"], BODY_WIDTH),
    _mat("", ["FATIGUE CONS", "LOAD EXP", "FATIGUE CONS", "LOAD EXP", "DISPERSION"], BODY_WIDTH),
    _mat("", ["N/m**(50/27)", "", "(N/m**1.80)", "", "EXPONENT"], BODY_WIDTH),
)
RACE_LABELS = ("OUTER RACE", "INNER RACE")
#: Fatigue text items ``(1X,A25,A)``.
FAT_TEXT_WIDTH = 25
FAT_TEXT_LABELS = ("BEARING WEIBULL SLOPE:", "LIFE MODIFICATION CODE:")
ASP_HEAD = (
    _mat("", ["COMPOSITE", "COMPOSITE", "TRACTION", "LIMIT SHEAR", "RESIDUAL", "MATERIALS", "CONTAM-",
              "PROCESSING"], BODY_WIDTH),
    _mat("", ["RMS HEIGHT", "RMS SLOPE", "COEFF", "STRESS", "STRESS", "FACTOR", "INATION", "FACTOR"], BODY_WIDTH),
    _mat("", ["(m)", "(rad)", "", "(Pa)", "(Pa)", "", "FACTOR", ""], BODY_WIDTH),
)

# -------------------------------------------------------------- initial operating conditions
OPER_WIDTH = 31
OPER_RIGHT_WIDTH = 24
OPER_RACE_HEAD = " " * 70 + "   OUTER RACE   INNER RACE"
#: Left cells ``(1X,A31,ES12.5)``; the first four lines carry a right cell ``(1X,A24,ES12.5)``
#: (outer race) and the inner-race value ``(1X,ES12.5)``.
OPER_LEFT = (("ROOM TEMPERATURE (K)", "room_temp"), ("HOUSING TEMPERATURE (K)", "housing_temp"),
             ("SHAFT TEMPERATURE (K)", "shaft_temp"), ("ROLLING ELEMENT TEMPERATURE (K)", "re_temp"),
             ("CAGE TEMPERATURE (K)", "cage_temp"))
OPER_RIGHT = (("ANGULAR VELOCITY (rpm)", "race_speed"), ("TEMPERATURE (K)", "race_temp"),
              ("MISALIGNMENT-Y (rad)", "misalign_y"), ("MISALIGNMENT-Z (rad)", "misalign_z"))
#: Integer lists ``(1X,A30,n(I3))``.
FLAGS_WIDTH = 30
QS_LABEL = "QUASI-STATIC CONSTRAINTS"
TRANS_LABEL = "TRANSLATIONAL CONSTRAINTS"
ROT_LABEL = "ROTATIONAL CONSTRAINTS"
LOAD_FRACTION_LABEL = "CONSTRAINING LOAD FRACTION"
#: Operating-condition text items ``(1X,A32,A)``.
OPER_TEXT_WIDTH = 32
COOLANT_LABEL = "BEARING COOLANT TYPE:"
NODE_LABEL = "NODE AT BASE TEMPERATURE:"  # printed when node_base_temp is not blank
VARY_LABEL = "VARY GEOMETRY WITH TEMPERATURE:"
HTC_LABEL = "HEAT TRANS COEFF (W/m**2/K)"  # printed when print_htc /= 0
VECTOR_WIDTH = 36
VECTOR_HEAD = _mat("", ["X-COMP", "Y-COMP", "Z-COMP"], VECTOR_WIDTH)
VECTORS = (("APPLIED LOAD VECTOR (N)", "applied_load"), ("RELATIVE DISPLACEMENT VECTOR (m)", "rel_disp"),
           ("APPLIED MOMENT VECTOR (N.m)", "applied_moment"), ("GRAVITY VECTOR (m/s**2)", "gravity"),
           ("CAGE GEOM CEN POSITION (m)", "cage_position"), ("CAGE ANGULAR POSITION (deg)", "cage_angle"),
           ("CAGE WHIRL TO ANG VEL RATIO", "whirl_ratio"),
           ("CAGE ANG VEL TO EPICYCLIC VEL RATIO", "epicyclic_ratio"))

# ---------------------------------------------------------------- scale factors and controls
SCALE_HEAD = "     SCALE FACTORS               STEP SIZE INFO"
SCALE_WIDTH = 11
SCALE_RIGHT_WIDTH = 14
SCALE_LABELS = (("LENGTH (m)", "scale_length"), ("LOAD (N)", "scale_load"), ("TIME (S)", "scale_time"))
STEP_LABELS = (("MINIMUM", "step_min"), ("MAXIMUM", "step_max"), ("INITIAL", "step_initial"))
NO_OF_STEPS_LABEL = "NO OF STEPS"
#: ``(1X,A15,3I6)``
CONTROL_WIDTH = 15
DATA_CONTROL_LABEL = "DATA CONTROL"
AUTO_PLOTS_LABEL = "AUTO PLOTS"
ERROR_LIMIT_LABEL = "ERROR LIMIT"
ERROR_LIMIT_WIDTH = 35
INT_METHOD_LABEL = "INT METHOD"
