"""The fixed-column ADORE 5.0 print layout, as data shared by the reader and the writer.

Every step table is described once here (:data:`TABLES`): its section, its heading lines
(literal text), the width and kind of its row label and its value columns (snake_case
name with the unit as suffix).  ``docs/print-layout.md`` gives the same layout as Fortran
format strings; the two must agree.

Widths (characters):

* a table value is ``1X,ES10.3`` (11 characters: one blank, then e.g. ``-1.234E+00``);
* an integer label is ``I5`` (element, slice, land), ``I6`` (step number) and an
  integer code column ``I3``;
* a text label is ``A5`` (section 2 bodies) or ``A10`` (section 3 rows);
* no line is longer than :data:`LINE_WIDTH`.

A field holding :data:`UNKNOWN_TOKEN` right-aligned means "unknown, not compared" (only
golden files use it; a Fortran numeric write never produces ``?``).  A field made only
of ``*`` is a Fortran overflow.  A field holding :data:`NOT_COMPUTED_TOKEN` (``NaN``, what
a Fortran write prints for IEEE NaN) is a value the engine does not compute; integer
fields print it for :data:`INT_NOT_COMPUTED`.

``pyadore/printout/fortran_layout.py`` turns this module into Fortran parameter data
(``fortran/output/layout.f90``) for the engine's print writer.
"""

from __future__ import annotations

from dataclasses import dataclass, field

LINE_WIDTH = 132
VALUE_WIDTH = 11  # 1X,ES10.3
UNKNOWN_TOKEN = "?"
NOT_COMPUTED_TOKEN = "NaN"
#: Integer fields (codes, echo integers) that the engine does not compute carry this
#: value (-huge(0) of a default Fortran integer) and print ``NaN`` right-aligned.
INT_NOT_COMPUTED = -(2**31 - 1)

BANNER_LINE = "ADVANCED DYNAMICS OF ROLLING ELEMENTS"
STEP_HEADING = "  step        tau       Time Outer Race Rot Inner Race Rot  (ADORE 5.0)"
STEP_UNITS = "    no                   (s)          (rev)          (rev)"
STEP_RULE = "====== ========== ========== ============== =============="

SECTION_TITLES = {
    "1": "1. Rolling Element Parameters",
    "1a": "1a. Load Distribution Along Roller no.",
    "2": "2. Race and Cage Parameters",
    "3": "3. Applied Parameters",
    "4": "4. Time Step Summary",
}
TERMINATION_PREFIX = "Normal termination:"
#: First words of the last line of a print whose time integration stopped early (engine:
#: fortran/driver/ball_dynamics.f90, INCOMPLETE_MARK).
INCOMPLETE_PREFIX = "*** RUN INCOMPLETE"
#: First words of the listing line of a print that integrates time steps (engine:
#: fortran/output/banner.f90); such a print is complete only with its termination line.
TIME_INTEGRATION_PREFIX = "TIME INTEGRATION:"
#: ``(5X,A,I8,5X,A,1X,ES10.4)`` with these two texts.
TERMINATION_STEP_TEXT = "Normal termination: Last Step Number ="
TERMINATION_TIME_TEXT = "Final Time ="
STATISTICS_TITLE = "Statistics of this Run"


def _cells(lead: str, texts: list[str], width: int = VALUE_WIDTH) -> str:
    """Right-align each text in a cell of ``width`` after the lead text."""
    return (lead + "".join(t.rjust(width) for t in texts)).rstrip()


def _spans(lead_width: int, spans: list[tuple[str, int]]) -> str:
    """Centre each group title over ``n`` value cells (``spans`` = [(title, n), ...])."""
    out = " " * lead_width
    for title, n in spans:
        w = n * VALUE_WIDTH
        out += (" " + title.center(w - 1)) if title else " " * w
    return out.rstrip()


OI = ["Outer Race", "Inner Race"]


@dataclass(frozen=True)
class TableSpec:
    """One fixed-column step table.

    ``label`` is the row-label kind: ``"int"`` (I5 element/slice/land number),
    ``"step"`` (I6), ``"text"`` (A``label_width``) or ``"re_end"`` (I5 element + I3 end).
    ``codes`` integer columns (I3 each) follow the label; then ``columns`` values
    (1X,ES10.3 each).  ``headings`` are literal lines printed before the rows.
    """

    name: str
    section: str
    headings: tuple[str, ...]
    columns: tuple[str, ...]
    label: str = "int"
    label_width: int = 5
    codes: tuple[str, ...] = ()
    right_cells: dict = field(default_factory=dict)  # section 3: line offset -> cell name

    @property
    def key(self) -> str:
        """Normalised first heading line: identifies the table when reading."""
        return " ".join(self.headings[0].split())

    @property
    def lead_width(self) -> int:
        """Characters before the first value column."""
        extra = 3 if self.label == "re_end" else 0
        return self.label_width + extra + 3 * len(self.codes)


def _oi(base: str, unit: str) -> list[str]:
    return [f"{base}_outer_{unit}" if unit else f"{base}_outer", f"{base}_inner_{unit}" if unit else f"{base}_inner"]


RE_CONTACT = TableSpec(
    "re_contact", "1",
    (
        _spans(5, [("Orbital", 1), ("Contact Angle", 2), ("Contact Load", 2), ("Contact Stress", 2),
                   ("Major Half Width", 2), ("Minor Half Width", 2)]).replace("     ", "   RE", 1),
        _cells("   no", ["Position", "(deg)", "", "(N)", "", "(Pa)", "", "(m)", "", "(m)", ""]),
        _cells("     ", ["(deg)"] + OI * 5),
    ),
    tuple(["orbital_position_deg"] + _oi("contact_angle", "deg") + _oi("contact_load", "N")
          + _oi("contact_stress", "Pa") + _oi("major_half_width", "m") + _oi("minor_half_width", "m")),
)
RE_MOTION = TableSpec(
    "re_motion", "1",
    (
        _spans(5, [("Orbital", 1), ("Angular Velocity", 3), ("RE Ang Position", 2), ("Spin/Roll", 2),
                   ("Contact Loss", 2), ("Time Ave", 1)]).replace("     ", "   RE", 1),
        _cells("   no", ["Velocity", "Amplitude", "Theta", "Phi", "Theta", "Phi", "", "", "(W)", "", "Wear Rate"]),
        _cells("     ", ["(rpm)", "(rpm)", "(deg)", "(deg)", "(deg)", "(deg)"] + OI * 2 + ["(m**3/s)"]),
    ),
    tuple(["orbital_velocity_rpm", "ang_vel_amplitude_rpm", "ang_vel_theta_deg", "ang_vel_phi_deg",
           "ang_pos_theta_deg", "ang_pos_phi_deg"] + _oi("spin_roll", "") + _oi("contact_loss", "W")
          + ["wear_rate_m3_s"]),
)
RE_TRACTION = TableSpec(
    "re_traction", "1",
    (
        _spans(5, [("Slip Velocity", 2), ("Trac Coeff", 2), ("Iso Lub Film", 2), ("Thermal Red Fac", 2),
                   ("Drag", 1), ("Chrn Mom", 1), ("Net Loss", 1)]).replace("     ", "   RE", 1),
        _cells("   no", ["(m/s)", "", "", "", "(m)", "", "", "", "(N)", "(N.m)", "(W)"]),
        _cells("     ", OI * 4 + ["", "", "(Drag+Chur)"]),
    ),
    tuple(_oi("slip_velocity", "m_s") + _oi("trac_coeff", "") + _oi("film_thickness", "m")
          + _oi("thermal_red_fac", "") + ["drag_N", "churning_moment_Nm", "net_loss_W"]),
)
RE_THERMAL = TableSpec(
    "re_thermal", "1",
    (
        _spans(5, [("Rel Axial", 1), ("Contact Deflection", 2), ("Race Flexing", 2), ("Contact Temp Rise", 2),
                   ("Contact Temp", 2), ("Bulk Temp", 1), ("Convec HTC", 1)]).replace("     ", "   RE", 1),
        _cells("   no", ["Pos", "(m)", "", "(m)", "", "(K)", "", "(K)", "", "(K)", ""]),
        _cells("     ", ["(m)"] + OI * 4 + ["", "(W/m**2/K)"]),
    ),
    tuple(["rel_axial_pos_m"] + _oi("contact_deflection", "m") + _oi("race_flexing", "m")
          + _oi("contact_temp_rise", "K") + _oi("contact_temp", "K") + ["bulk_temp_K", "convec_htc_W_m2K"]),
)
SLICES = TableSpec(
    "slices", "1a",
    (
        _spans(5, [("Outer Race Contact", 5), ("Inner Race Contact", 5)]).replace("     ", "Slice", 1),
        _cells("   no", ["Axial Pos", "Geo Int", "Half Width", "Nor Load", "Trac Load"] * 2),
        _cells("     ", ["(m)", "(m)", "(m)", "(N/m)", "(N/m)"] * 2),
    ),
    tuple(f"{q}_{r}_{u}" for r in ("outer", "inner") for q, u in
          (("axial_pos", "m"), ("geo_int", "m"), ("half_width", "m"), ("normal_load", "N_m"), ("trac_load", "N_m"))),
)
_RE_CAGE_COLS = ("geo_int_m", "contact_force_N", "con_ang_theta_deg", "con_ang_phi_deg", "contact_pos_x_m",
                 "contact_pos_z_m", "contact_loss_W", "wear_rate_m3_s")
_RE_CAGE_HEAD = (
    ["Geo Int", "Contact", "Con Ang", "Con Ang", "Contact", "Contact", "Contact", "Time Ave"],
    ["", "Force", "THETA", "PHI", "Pos X", "Pos Z", "Loss", "Wear Rate"],
    ["(m)", "(N)", "(deg)", "(deg)", "(m)", "(m)", "(W)", "(m**3/s)"],
)
RE_CAGE = TableSpec(
    "re_cage", "2",
    (_spans(8, [("RE/Cage Interaction", 8)]).replace("        ", "   RE  C", 1),
     _cells("   no   ", _RE_CAGE_HEAD[0]),
     _cells("        ", _RE_CAGE_HEAD[1]),
     _cells("        ", _RE_CAGE_HEAD[2])),
    _RE_CAGE_COLS, codes=("code",),
)
RE_CAGE_ROLLER = TableSpec(
    "re_cage", "2",
    (_spans(11, [("RE/Cage Interaction", 8)]).replace("           ", "   RE End  C", 1),
     _cells("   no  no   ", _RE_CAGE_HEAD[0]),
     _cells("           ", _RE_CAGE_HEAD[1]),
     _cells("           ", _RE_CAGE_HEAD[2])),
    _RE_CAGE_COLS, label="re_end", codes=("code",),
)
RACE_CAGE = TableSpec(
    "race_cage", "2",
    (_spans(8, [("Race/Cage Interaction", 4), ("Effective", 1), ("Contact", 1), ("Time Ave", 1)]).replace(
        "        ", "   LD  C", 1),
     _cells("   no   ", ["Geo Int", "Force", "Con Angle", "Att Angle", "Dia Play", "Loss", "Wear Rate"]),
     _cells("        ", ["(m)", "(N)", "(deg)", "(deg)", "(m)", "(W)", "(m**3/s)"])),
    ("geo_int_m", "force_N", "con_angle_deg", "att_angle_deg", "effective_dia_play_m", "contact_loss_W",
     "wear_rate_m3_s"), codes=("code",),
)
BODIES = TableSpec(
    "bodies", "2",
    (_spans(5, [("Mass Center Position", 3), ("Orbital", 1), ("Angular Velocity", 3), ("Ang Position", 2),
                ("Hoop", 1), ("Time Ave", 1)]),
     _cells("     ", ["Axial", "Radial", "Orbital", "Velocity", "Amplitude", "Theta", "Phi", "Theta", "Phi",
                     "Stress", "Wear Rate"]),
     _cells("     ", ["(m)", "(m)", "(deg)", "(rpm)", "(rpm)", "(deg)", "(deg)", "(deg)", "(deg)", "(Pa)",
                     "(m**3/s)"])),
    ("mc_pos_axial_m", "mc_pos_radial_m", "mc_pos_orbital_deg", "orbital_velocity_rpm", "ang_vel_amplitude_rpm",
     "ang_vel_theta_deg", "ang_vel_phi_deg", "ang_pos_theta_deg", "ang_pos_phi_deg", "hoop_stress_Pa",
     "wear_rate_m3_s"),
    label="text", label_width=5,
)
RIGHT3 = 78  # section 3: right-hand labelled cells start here in the loads block
RIGHT3_ACC = 89  # ... and here in the accelerations block
LOADS = TableSpec(
    "loads", "3",
    ("",  # first line carries only the right-hand cell
     _spans(10, [("Forces in Inertial Frame", 3), ("Moments in Body-Fixed Frame", 3)]),
     _cells(" " * 10, ["Comp-x", "Comp-y", "Comp-z"] * 2),
     _cells(" " * 10, ["(N)"] * 3 + ["(N.m)"] * 3),
     ""),
    ("force_x_N", "force_y_N", "force_z_N", "moment_x_Nm", "moment_y_Nm", "moment_z_Nm"),
    label="text", label_width=10,
    right_cells={0: "basic_fatigue_life_hours", 1: "modified_fatigue_life_hours", 2: "outer_race_fit_m",
                 3: "inner_race_fit_m", 4: "internal_clearance_m", 6: "total_power_loss_W",
                 7: "churning_loss_fraction", 8: "exit_fluid_temp_K"},
)
ACCELERATIONS = TableSpec(
    "accelerations", "3",
    (_spans(10, [("MC Acc in Inertial Frame", 3), ("Ang Acc in Body-Fixed Frame", 3), ("Bulk Temp", 1)]),
     _spans(10, [("(m/s**2)", 3), ("(rpm/s)", 3), ("(K)", 1)]),
     _cells(" " * 10, ["Comp-x", "Comp-y", "Comp-z"] * 2),
     ""),
    ("acc_x_m_s2", "acc_y_m_s2", "acc_z_m_s2", "ang_acc_x_rpm_s", "ang_acc_y_rpm_s", "ang_acc_z_rpm_s",
     "bulk_temp_K"),
    label="text", label_width=10,
    right_cells={0: "hsng_bulk_temp_K", 1: "hsng_outer_temp_K", 2: "hsng_inner_temp_K", 3: "shft_bulk_temp_K",
                 5: "shft_outer_temp_K", 6: "shft_inner_temp_K"},
)
#: Labels (with units) of the section 3 right-hand cells, keyed by column name.
RIGHT_LABELS = {
    "basic_fatigue_life_hours": "Basic Fatigue Life     (hours)",
    "modified_fatigue_life_hours": "Modified Fatigue Life  (hours)",
    "outer_race_fit_m": "Outer Race Fit         (m)",
    "inner_race_fit_m": "Inner Race Fit         (m)",
    "internal_clearance_m": "Internal Clearance     (m)",
    "total_power_loss_W": "Total Power Loss       (W)",
    "churning_loss_fraction": "Churning Loss Fraction",
    "exit_fluid_temp_K": "Exit Fluid Temperature (K)",
    "hsng_bulk_temp_K": "Hsng/Bulk Temp  (K)",
    "hsng_outer_temp_K": "Hsng/Outer Temp (K)",
    "hsng_inner_temp_K": "Hsng/Inner Temp (K)",
    "shft_bulk_temp_K": "Shft/Bulk Temp  (K)",
    "shft_outer_temp_K": "Shft/Outer Temp (K)",
    "shft_inner_temp_K": "Shft/Inner Temp (K)",
}
SUMMARY = TableSpec(
    "summary", "4",
    (" " * 61 + "Time Average Parameters",
     _cells("  Step", ["Time", "Outer Race", "Inner Race", "Fatigue", "Power", "RE Orbital", "Cage Omega",
                       "Cage Whirl", "Cage", "Average RE"]),
     _cells("    no", ["", "Rotation", "Rotation", "Life", "Loss", "Vel Ratio", "Ratio", "Ratio", "Wear Rate",
                       "Excursion"]),
     _cells("      ", ["(s)", "(rev)", "(rev)", "(hours)", "(W)", "", "", "", "(m**3/s)", "(m)"])),
    ("time_s", "outer_race_rotation_rev", "inner_race_rotation_rev", "fatigue_life_hours", "power_loss_W",
     "re_orbital_vel_ratio", "cage_omega_ratio", "cage_whirl_ratio", "cage_wear_rate_m3_s",
     "average_re_excursion_m"),
    label="step", label_width=6,
)
#: Row labels of the text-labelled tables, in print order.
BODY_ROWS = ("Cage", "ORace", "IRace")
LOAD_ROWS = ("Cage", "Int ORace", "Int IRace", "Ext ORace", "Ext IRace")
ACC_ROWS = ("Cage", "ORace", "IRace")
HEADER_COLUMNS = ("tau", "time_s", "outer_race_rot_rev", "inner_race_rot_rev")
PERFORMANCE_COLUMNS = tuple(RIGHT_LABELS)
TERMINATION_COLUMNS = ("last_step_number", "final_time")
STATISTICS_LABELS = {
    "Minimum Step Size": "minimum_step_size",
    "Maximum Step Size": "maximum_step_size",
    "Last Step Size": "last_step_size",
    "Max Truncation": "max_truncation",
    "Total Derivative Calls": "total_derivative_calls",
}

#: Tables of each section in print order.  Section 2's RE/cage table depends on the
#: bearing type (``re_cage`` for balls, the ``re_end`` variant for rollers).
SECTION_TABLES = {
    "1": (RE_CONTACT, RE_MOTION, RE_TRACTION, RE_THERMAL),
    "1a": (SLICES,),
    "2": (RE_CAGE, RACE_CAGE, BODIES),
    "3": (LOADS, ACCELERATIONS),
    "4": (SUMMARY,),
}
ALL_TABLES = (RE_CONTACT, RE_MOTION, RE_TRACTION, RE_THERMAL, SLICES, RE_CAGE, RE_CAGE_ROLLER, RACE_CAGE,
              BODIES, LOADS, ACCELERATIONS, SUMMARY)
