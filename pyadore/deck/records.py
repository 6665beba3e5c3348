"""The record table of an ADORE 5.0 deck: every record, its presence rule and its fields.

Sources for names and meanings (cited per field in ``evidence``):

* ``echo``: the program's input echo in the print output of Appendices C and D;
* ``listing``: the legible deck listing lines of Appendices C and D;
* ``table``: Tables 5 and 6 (sections 5.1 and 5.4);
* ``section x``: the text of the report; ``A``: the data module of Appendix A;
* ``inference``: reasoned but not proved (the reasoning is in ``meaning``);
* ``unknown``: the field exists (its value is in the listing) but its meaning is not
  recoverable; such fields are named ``rec<id>_flag_<k>`` / ``rec<id>_value_<k>``.
"""

from __future__ import annotations

from .spec import FieldSpec, RecordSpec

__all__ = ["RECORDS"]

F = FieldSpec


def _unknown_ints(rid: str, first: int, last: int, note: str) -> tuple[FieldSpec, ...]:
    tag = rid.replace(".", "_").lower()
    return tuple(F(f"rec{tag}_flag_{k}", "int", meaning=f"unknown; {note}", evidence="unknown", default=0)
                 for k in range(first, last + 1))


def _pos(name, unit, meaning, adore="", evidence="echo", **kw) -> FieldSpec:
    """A strictly positive real (dimension, property)."""
    return F(name, "real", unit, meaning, adore, evidence, lo=0.0, lo_open=True, **kw)


def _real(name, unit, meaning, adore="", evidence="echo", default=0.0, **kw) -> FieldSpec:
    return F(name, "real", unit, meaning, adore, evidence, default=default, **kw)


def _material(rid: str, part: str, flag: str) -> RecordSpec:
    return RecordSpec(
        rid, f"Material properties: {part}", (
            _pos("density", "kg/m^3", "density", "", "listing"),
            _pos("elastic_modulus", "Pa", "elastic (Young's) modulus", "", "listing"),
            F("poisson_ratio", "real", "-", "Poisson's ratio", "", "listing", lo=0.0, hi=0.5,
              lo_open=True, hi_open=True),
            F("thermal_expansion", "real", "1/K", "coefficient of thermal expansion", "", "listing", lo=0.0),
            _pos("heat_capacity", "J/(kg K)", "specific heat capacity", "", "listing"),
            _pos("thermal_conductivity", "W/(m K)", "thermal conductivity", "", "listing"),
            _pos("elastic_strain_limit", "-", "elastic strain limit", "", "listing"),
            F("hardness", "real", "RC", "hardness, Rockwell C", "", "listing", lo=0.0),
            F("wear_coefficient", "real", "-", "wear coefficient", "", "listing", lo=0.0),
        ),
        when=f"{flag} != 0", section="echo: MATERIAL PROPERTIES",
        notes=(f"Present when `{flag}` (Rec 3.2) is non-zero; otherwise the {part} takes the default "
               "steel of the echo (density 7750 kg/m^3, E 2.0E11 Pa, nu 0.25, expansion 1.17E-5 1/K "
               "(cage 1.8E-5), conductivity 43 W/(m K), heat capacity 470 J/(kg K), strain limit 2.0E-3, "
               "hardness RC 61 (cage 20), wear coefficient 5.0E-6 (cage 5.0E-4)).  Field order from "
               "the roller deck's Rec 8.1 listing line; only 8.1 is attested, 8.2-8.6 are inferred "
               "from the six material columns of the echo."),
    )


_TEMP = dict(lo=0.0, lo_open=True)

RECORDS: tuple[RecordSpec, ...] = (
    RecordSpec("1", "Program mode and output control", (
        F("mode", "int", "-", "program mode MODE (1 in both decks; echo 'Program Mode')", "MODE",
          "echo; section 4.4.6", lo=-2, hi=2),
        *_unknown_ints("1", 2, 5, "0 in both decks, not echoed"),
        F("data_control_1", "int", "-", "first value echoed as DATA CONTROL (1 in both decks)", "",
          "echo", default=0),
        F("data_control_2", "int", "-", "second value echoed as DATA CONTROL (500 in both decks)", "",
          "echo", default=0),
        F("rec1_flag_8", "int", "-", "unknown; 1 in the ball deck, 2 in the roller deck (equal to the "
          "bearing type in both), not echoed", "", "unknown", default=0),
        *_unknown_ints("1", 9, 10, "0 in both decks, not echoed"),
        F("rec1_flag_11", "int", "-", "unknown; 1 in both decks, not echoed", "", "unknown", default=0),
        F("n_steps", "int", "-", "number of time steps (echo NO OF STEPS; 'Last Step Number = 2500')",
          "", "echo", lo=0),
        F("rec1_flag_13", "int", "-", "unknown; 0 in both decks, not echoed", "", "unknown", default=0),
        F("int_method", "int", "-", "integration method (echo INT METHOD; 5 in both decks): 5 = "
          "the deck's production method (ball dynamics: ARK4(3)6L[2]SA with the balls' contact blocks "
          "implicit; ROS34PW2 from the first step where a ball's spin relaxes within the minimum step, "
          "docs/integrator.md \"Step control\"), 3 = Bogacki-Shampine 3(2); assumed (docs/integrator.md, "
          "\"INT METHOD\")", "", "echo", choices=(3, 5)),
    ), section="4.4.5, 4.4.6; echo: SCALE FACTORS AND OUTPUT CONTROLS",
        notes="The last three fields stand apart from the first eleven in the text copy of both listings."),
    RecordSpec("2.1", "Step size information", (
        _pos("step_initial", "-", "initial step size, dimensionless time (echo INITIAL)"),
        _pos("step_min", "-", "minimum step size (echo MINIMUM)"),
        _pos("step_max", "-", "maximum step size (echo MAXIMUM)"),
        _real("rec2_1_value_4", "-", "unknown; 1.0E+03 in both decks, not echoed", evidence="unknown"),
        F("error_limit", "real", "-", "integration error limit (echo ERROR LIMIT)", "", "echo", lo=0.0,
          lo_open=True, hi=1.0, hi_open=True),
        F("constraining_load_fraction", "real", "-", "constraining load fraction of the quasi-static "
          "start (echo CONSTRAINING LOAD FRACTION)", "", "echo", default=0.0, lo=0.0, hi=1.0),
    ), section="echo: STEP SIZE INFO"),
    RecordSpec("2.4", "Thermal option flags", (
        F("coolant_type", "int", "-", "bearing coolant type (echo: 1 = Lubricant, 0 = No Coolant)", "",
          "echo", default=0, lo=0),
        *_unknown_ints("2.4", 2, 4, "the echo also prints NODE AT BASE TEMPERATURE (Housing/Outer in "
                       "both decks) and VARY GEOMETRY WITH TEMPERATURE (Yes in both) but the four flags "
                       "(ball 1 0 2 blank, roller 0 0 0 1) cannot be matched to them"),
    ), section="4.3; echo: BEARING COOLANT TYPE"),
    RecordSpec("2.5", "Coolant and thermal update times", (
        F("coolant_inlet_temperature", "real", "K", "coolant inlet temperature (Table 5: 323 K)", "",
          "table", default=0.0, lo=0.0),
        F("coolant_flow_rate", "real", "m^3/s", "coolant flow rate (Table 5: 1.0E-5)", "", "table",
          default=0.0, lo=0.0),
        _real("rec2_5_value_3", "-", "unknown; 0 in both decks", evidence="unknown"),
        F("thermal_time_1", "real", "s", "thermal time: one shaft revolution in both decks "
          "(3.0E-3 s at 20 000 rpm, 8.57E-4 s at 70 000 rpm); heat averaging interval or update "
          "time (sections 5.3, 5.5) - which one is not provable", "", "inference", default=0.0, lo=0.0),
        F("thermal_time_2", "real", "s", "thermal time: ten revolutions (ball) / one (roller); see "
          "thermal_time_1", "", "inference", default=0.0, lo=0.0),
    ), section="5.3, 5.5"),
    RecordSpec("2.7", "Initial temperatures", (
        F("housing_temperature", "real", "K", "housing temperature", "", "echo", **_TEMP),
        F("shaft_temperature", "real", "K", "shaft temperature", "", "echo", **_TEMP),
        F("rolling_element_temperature", "real", "K", "rolling element temperature", "", "echo", **_TEMP),
        F("cage_temperature", "real", "K", "cage temperature", "", "echo", **_TEMP),
        F("outer_race_temperature", "real", "K", "outer race temperature", "", "echo", **_TEMP),
        F("inner_race_temperature", "real", "K", "inner race temperature", "", "echo", **_TEMP),
    ), section="echo: INITIAL OPERATING CONDITIONS",
        notes="Six values in the listing, all equal in both decks, so the order (taken from the echo) "
              "is an inference; the echo's seventh temperature (ROOM) is on Rec 9.0."),
    RecordSpec("3.1", "Run identification", (
        F("run_id", "text", "-", "run identification text, at most 36 characters", "runId", "A",
          default=""),
    ), section="Appendix A (character*36 :: runId)"),
    RecordSpec("3.2", "Program options: bearing type, rolling elements, materials", (
        F("rec3_2_flag_1", "int", "-", "unknown; 1 in the roller deck (ball line lost)", "", "unknown",
          default=0),
        F("bearing_type", "int", "-", "bearing type: 1 = ball, 2 = cylindrical roller (ADORE also "
          "defines 3-5, whose geometry records are not in this schema)", "kBrg", "A; echo",
          choices=(1, 2)),
        F("n_rolling_elements", "int", "-", "number of rolling elements (echo NO OF BALLS / ROLLERS); at "
          "least 3: fewer cannot hold the inner race radially in every direction", "nRe", "echo", lo=3, hi=999),
        *(F(f"material_flag_{part}", "int", "-", f"inferred: 1 = {part.replace('_', ' ')} material "
            f"given on Rec {rid}, 0 = default steel. Fields 4-9 of the roller line are 1 0 0 0 0 0 and "
            "only that deck has Rec 8.1 (ceramic rollers); six flags match the six echo columns",
            "", "inference", default=0, choices=(0, 1))
          for part, rid in (("rolling_element", "8.1"), ("outer_race", "8.2"), ("inner_race", "8.3"),
                            ("cage", "8.4"), ("shaft", "8.5"), ("housing", "8.6"))),
        F("rec3_2_flag_10", "int", "-", "unknown; 1 in the roller deck (ball line lost)", "", "unknown",
          default=0),
        F("roller_extension", "int", "-", "pyadore extension, not ADORE's: 1 = Rec 5B.2 (roller ends, "
          "flanges, pocket type) follows a roller deck's Rec 5B.1; 0 or blank = none (both appendix "
          "decks)", "", "pyadore", default=0, choices=(0, 1)),
    ), section="echo: Bearing Type, NO OF BALLS/ROLLERS",
        notes="Field count (10) from the roller listing line `1 2 8 1 0 0 0 0 0 1`; field 11 is "
              "pyadore's (the report gives no record layout for flanges or the pocket code: "
              "docs/rollers.md, \"Flanges\")."),
    RecordSpec("3.3", "Program options (flags)", tuple(
        F(f"rec3_3_flag_{k}", "int", "-", "DOF constraint flag (report 4.4.6), read as one pattern with "
          "the other ten: all eleven 0 = nothing constrained; 1 1 1 1 0 0 0 0 0 0 1 (Appendix D, the "
          "report's own 4.4.6 example) = every rolling element's axial motion, tilt and skew held, the "
          "cage free; any other pattern is refused at the run (an input error naming the field): what "
          "this field alone holds is not identified", "", "inference", default=0)
        for k in range(1, 12)),
        section="4.4.6; Appendix D step 4000",
        notes="Field count (11) from the roller listing line.  Evidence for the pattern reading: report "
              "4.4.6 names the example of an aligned cylindrical roller bearing under pure radial load "
              "whose rollers' and cage's axial and transverse-rotation DOFs may be suppressed - "
              "Appendix D is that bearing, and its Rec 3.3 has four ones in fields 1-4 (four DOF groups "
              "in that sentence) and one in field 11.  Appendix D's step 4000 (after 5.45 ms of "
              "dynamics) prints every roller's Rel Axial Pos and Ang Position Theta/Phi exactly "
              "0.000E+00 (held), while its cage is at axial -5.457E-08 m and has a transverse angular "
              "acceleration (-6.448, 1.225 rpm/s) under zero applied moment, i.e. it turns about a "
              "transverse axis (free); so Appendix D holds the rollers only.  The ball deck's listing "
              "line is lost (its zeros are the transcription's).  The echo's TRANSLATIONAL / ROTATIONAL "
              "CONSTRAINTS rows (1 1 1 1 1 1 each in Appendix D) do not follow Rec 3.3's order and are "
              "not read (docs/cage.md, \"The cage's degrees of freedom\")."),
    RecordSpec("3.4", "Program options (flags, incl. kRotFrames)", _unknown_ints(
        "3.4", 1, 12, "ball deck 0 0 0 0 0 2 1 19 0 0 0 0, roller 1 1 1 1 0 0 0 0 0 0 0 0; one of the "
        "twelve is kRotFrames (section 4.4.10), which one is not recoverable"),
        section="4.4.10", notes="Field count (12) from the ball listing line."),
    RecordSpec("4", "Bearing envelope", (
        _pos("shaft_outer_diameter", "m", "shaft OD = bearing bore (echo SHAFT OD)", "brgBore", "listing; echo"),
        _pos("bearing_outer_diameter", "m", "bearing outer diameter (echo BEARING OD)", "brgOD", "listing; echo"),
        F("shaft_inner_diameter", "real", "m", "shaft inner diameter, 0 = solid (echo SHAFT ID)", "",
          "listing; echo", default=0.0, lo=0.0),
        _pos("housing_outer_diameter", "m", "housing outer diameter (echo HOUSING OD)", "hsngOD", "listing; echo"),
        _pos("outer_race_width", "m", "outer race width (echo WIDTH I)", "raceWidth(1)", "listing; echo"),
        _pos("inner_race_width", "m", "inner race width (echo WIDTH II)", "raceWidth(2)", "listing; echo"),
    ), section="echo: BEARING GEOMETRY"),
    RecordSpec("5A", "Ball and race geometry", (
        _pos("ball_diameter", "m", "ball diameter (echo BALL DIA)", "bReDia", "listing; echo"),
        _pos("pitch_diameter", "m", "pitch diameter (echo PITCH DIA)", "pitchDia", "listing; echo"),
        F("free_contact_angle", "real", "deg", "unmounted contact angle (echo CON ANGLE)", "freeConAng",
          "listing; echo", lo=0.0, hi=90.0, hi_open=True),
        _real("rec5a_value_4", "-", "unknown; 0 in the listing. The echo's DIA PLAY and END PLAY are "
              "computed from the contact angle", evidence="unknown"),
        F("outer_curvature_factor", "real", "-", "outer race curvature factor (echo OUTER CUR FAC)",
          "raceCurFac(1)", "listing; echo", lo=0.5, lo_open=True),
        F("inner_curvature_factor", "real", "-", "inner race curvature factor (echo INNER CUR FAC)",
          "raceCurFac(2)", "listing; echo", lo=0.5, lo_open=True),
    ), when="bearing_type == 1", section="echo: BEARING GEOMETRY; Table 5"),
    RecordSpec("5B", "Cylindrical roller and race geometry", (
        _pos("roller_diameter", "m", "roller diameter (echo ROLLER DIA)", "bReDia"),
        _pos("roller_length", "m", "roller length (echo ROLLER LEN)"),
        F("central_land_length", "real", "m", "central (flat) land length of the roller (echo CEN LAND)",
          "", "echo", lo=0.0),
        _pos("pitch_diameter", "m", "pitch diameter (echo PITCH DIA)", "pitchDia"),
        _pos("crown_radius", "m", "roller crown radius (echo CROWN RAD)"),
        F("corner_radius_1", "real", "m", "roller corner radius, negative axis end (echo COR RAD I)",
          "bReCorRad(1)", "echo", lo=0.0),
        F("corner_radius_2", "real", "m", "roller corner radius, positive axis end (echo COR RAD II)",
          "bReCorRad(2)", "echo", lo=0.0),
        _real("diametral_play", "m", "unmounted diametral clearance (echo DIA PLAY; Table 6)", "freeIntCls",
              default=None),
        _pos("outer_race_crown_radius", "m", "outer race crown radius (echo OUTER CRN; 1.0E+10 = flat)",
             "raceCrn(1)"),
        _pos("inner_race_crown_radius", "m", "inner race crown radius (echo INNER CRN)", "raceCrn(2)"),
    ), when="bearing_type == 2", section="echo: BEARING GEOMETRY; Table 6",
        notes="The listing line is lost in both copies; the field order is that of the echo, which "
              "for the ball deck's Rec 5A equals the record order (inference)."),
    RecordSpec("5B.1", "Race lengths (roller bearings)", (
        F("outer_race_len1", "real", "m", "echo OUTER LEN1 (race length for roller interaction, "
          "probably raceLandLmt)", "", "listing; echo", default=0.0, lo=0.0),
        F("outer_race_len2", "real", "m", "echo OUTER LEN2", "", "listing; echo", default=0.0, lo=0.0),
        F("inner_race_len1", "real", "m", "echo INNER LEN1", "", "listing; echo", default=0.0, lo=0.0),
        F("inner_race_len2", "real", "m", "echo INNER LEN2", "", "listing; echo", default=0.0, lo=0.0),
    ), when="bearing_type == 2", section="echo: BEARING GEOMETRY"),
    RecordSpec("5B.2", "Roller ends, flanges and pocket type (pyadore extension)", (
        F("pocket_type", "int", "-", "roller pocket code as kPocType of report 4.4.11: 0 = rectangular, "
          "-1 = cylindrical (roller guided cage); which Rec 7.0 field carries kPocType is not identified",
          "kPocType", "section 4.4.11", default=0, choices=(-1, 0)),
        F("outer_flange_1", "int", "-", "outer race flange at the negative-axis roller end: 1 = present",
          "kFlngInd(1,1)", "A", default=0, choices=(0, 1)),
        F("outer_flange_2", "int", "-", "outer race flange at the positive-axis roller end",
          "kFlngInd(2,1)", "A", default=0, choices=(0, 1)),
        F("inner_flange_1", "int", "-", "inner race flange at the negative-axis roller end",
          "kFlngInd(1,2)", "A", default=0, choices=(0, 1)),
        F("inner_flange_2", "int", "-", "inner race flange at the positive-axis roller end",
          "kFlngInd(2,2)", "A", default=0, choices=(0, 1)),
        F("roller_end_radius", "real", "m", "spherical roller end radius (centre on the roller axis, "
          "apex at the end face); 0 = flat end, refused with a flange", "bReEndRad", "A", default=0.0,
          lo=0.0),
        F("outer_flange_height", "real", "m", "outer flange height below the outer raceway", "flngHt",
          "A", default=0.0, lo=0.0),
        F("inner_flange_height", "real", "m", "inner flange height above the inner raceway", "flngHt",
          "A", default=0.0, lo=0.0),
        F("outer_flange_angle", "real", "deg", "outer flange lay-back angle (face inclined away from "
          "the roller with height)", "flngAng", "A", default=0.0, lo=0.0, hi=10.0),
        F("inner_flange_angle", "real", "deg", "inner flange lay-back angle", "flngAng", "A",
          default=0.0, lo=0.0, hi=10.0),
        F("outer_flange_clearance", "real", "m", "axial play of the centred, aligned roller between "
          "the outer race's flange faces (each face c/2 beyond the roller end)", "flngCls", "A",
          default=0.0, lo=0.0),
        F("inner_flange_clearance", "real", "m", "axial play between the inner race's flange faces",
          "flngCls", "A", default=0.0, lo=0.0),
    ), when="roller_extension != 0", section="4.4.11; A (guide flange data)",
        notes="pyadore's record (not in ADORE decks): the report's Appendix A names the data "
              "(kFlngInd, flngHt, flngAng, flngCls, bReEndRad) but not its input record.  Flange "
              "contact model: docs/rollers.md, \"Flanges\"."),
    RecordSpec("7.0", "Cage options and guide lands", (
        *_unknown_ints("7.0", 1, 8, "0 in both decks; one of fields 1-8 is the pocket code kPocType "
                       "(section 4.4.11; echo POCKET SHAPE 0), which one is not recoverable"),
        F("n_guide_lands", "int", "-", "number of cage/race guide lands (echo NO OF C/R LANDS); one "
          "Rec 7.2.n per land", "nGL", "echo; section 4.4.8", lo=1, hi=10),
        F("guide_type", "int", "-", "guidance type of each land: 1 = outer race, 2 = inner race "
          "(echo GUIDE TYPE; Tables 5/6)", "iCageGuide", "echo; A", choices=(1, 2),
          count="n_guide_lands"),
    ), section="4.4.8, 4.4.11; echo: CAGE"),
    RecordSpec("7.1", "Cage geometry", (
        _pos("cage_outer_diameter", "m", "cage outer diameter (echo CAGE OD)", "cageDia(1)", "echo; table"),
        _pos("cage_inner_diameter", "m", "cage inner diameter (echo CAGE ID)", "cageDia(2)", "echo; table"),
        _pos("cage_width", "m", "cage width (echo CAGE WIDTH)", "cageWidth", "echo; table"),
        F("cage_outer_clearance", "real", "m", "outer diametral clearance (echo OUTER CLS)", "cageCls(1)",
          "echo", lo=0.0),
        F("cage_inner_clearance", "real", "m", "inner diametral clearance (echo INNER CLS)", "cageCls(2)",
          "echo", lo=0.0),
        F("pocket_clearance_1", "real", "m", "pocket clearance I (echo POC CLS I); > 0: an element without "
          "clearance touches both pocket walls at the start (report 4.4.12)", "bPocCls(1)", "echo", lo=0.0,
          lo_open=True),
        F("pocket_clearance_2", "real", "m", "pocket clearance II (echo POC CLS II)", "bPocCls(2)", "echo",
          default=0.0, lo=0.0),
        F("segment_cut_angle", "real", "deg", "angular cut of a segmented cage (echo SEG CUT)",
          "cageAngCut", "echo", default=0.0, lo=0.0, hi=360.0),
        F("cage_cone_angle", "real", "deg", "cage semi-cone angle (echo CAGE CONE)", "cageConeAng",
          "echo", default=0.0, lo=-90.0, hi=90.0, lo_open=True, hi_open=True),
    ), section="echo: CAGE; Tables 5/6"),
    RecordSpec("7.2.n", "Cage guide land (one per land)", (
        _pos("guide_land_diameter", "m", "diameter at the guide land (echo GUIDE LAND DIA)", "cageGsDia"),
        _pos("guide_land_width", "m", "guide land width (echo GUIDE LAND WIDTH)", "cageGsWidth"),
        _real("guide_land_position", "m", "axial position of the land (echo GUIDE LAND POSITION)",
              "cageGsPos", default=None),
        F("guide_land_clearance", "real", "m", "guide land diametral clearance (echo GUIDE LAND CLS); > 0: "
          "a cage without land clearance starts in contact with its land", "cageGsCls", "echo", lo=0.0,
          lo_open=True),
    ), repeat="n_guide_lands", section="4.4.8; echo: GUIDE LAND"),
    _material("8.1", "rolling element", "material_flag_rolling_element"),
    _material("8.2", "outer race", "material_flag_outer_race"),
    _material("8.3", "inner race", "material_flag_inner_race"),
    _material("8.4", "cage", "material_flag_cage"),
    _material("8.5", "shaft", "material_flag_shaft"),
    _material("8.6", "housing", "material_flag_housing"),
    RecordSpec("9.0", "Room temperature and race fits", (
        F("room_temperature", "real", "K", "room temperature (echo ROOM TEMPERATURE; Tables 5/6)", "",
          "echo; table", **_TEMP),
        _real("outer_race_fit", "m", "outer race fit (echo OUTER FIT)", evidence="echo; table"),
        _real("inner_race_fit", "m", "inner race fit (echo INNER FIT)", evidence="echo; table"),
    ), section="echo; Tables 5/6"),
    RecordSpec("9.1.1", "Applied loads and moments", (
        _real("applied_force_x", "N", "applied force x (echo APPLIED LOAD VECTOR; thrust)"),
        _real("applied_force_y", "N", "applied force y"),
        _real("applied_force_z", "N", "applied force z (radial in both decks)"),
        _real("applied_moment_x", "N m", "applied moment x (echo APPLIED MOMENT VECTOR)"),
        _real("applied_moment_y", "N m", "applied moment y"),
        _real("applied_moment_z", "N m", "applied moment z"),
    ), section="echo: APPLIED LOAD / MOMENT VECTOR"),
    RecordSpec("9.1.2", "Race motion", (
        *(_real(f"rec9_1_2_value_{k}", "-", "unknown; 0 in both decks (the echo prints zero relative "
                "displacements, misalignments and outer race speed)", evidence="unknown")
          for k in range(1, 7)),
        F("inner_race_speed", "real", "rpm", "inner race (shaft) speed (echo ANGULAR VELOCITY, INNER "
          "RACE; Tables 5/6)", "", "echo; table"),
    ), section="echo: ANGULAR VELOCITY"),
    RecordSpec("9.5.1", "Cage initial conditions", (
        F("cage_whirl_radius", "real", "m", "meaning not identified, not used; formerly read as the start "
          "whirl's radius (section 4.4.4), but ball 6.636E-04 and roller 2.5E-04 m against the centres "
          "printed at the start, 5.900E-04 and 5.0E-05 m, the roller's beyond its land radial clearance "
          "5.0E-05 m: the start whirl turns about the axis at the centre's own radius (docs/cage.md)",
          "", "inference",
          default=0.0, lo=0.0),
        _real("cage_whirl_ratio", "-", "cage whirl to angular velocity ratio (echo)", default=1.0),
        _real("cage_epicyclic_ratio", "-", "cage angular velocity to epicyclic velocity ratio (echo)",
              default=1.0),
        _real("cage_center_x", "m", "cage geometric centre x (echo CAGE GEOM CEN POSITION)"),
        _real("cage_center_y", "m", "cage geometric centre y"),
        _real("cage_center_z", "m", "cage geometric centre z"),
        _real("cage_angle_x", "deg", "cage angular position x (echo CAGE ANGULAR POSITION)"),
        _real("cage_angle_y", "deg", "cage angular position y"),
        _real("cage_angle_z", "deg", "cage angular position z"),
    ), section="4.4.4; echo"),
    RecordSpec("10.0", "Traction and lubricant model codes", (
        F("traction_model", "int", "-", "inferred: selects the traction record, 2 -> Rec 10.1B, "
          "3 -> Rec 10.1C (ball deck 3 with 10.1C; the roller deck has 10.1B)", "", "inference",
          choices=(2, 3)),
        F("lubricant_code", "int", "-", "inferred: non-zero when a lubricant is used and Rec 10.3 "
          "follows (ball deck 1, MIL-L-7808 in the echo); the engine's library has 1 = MIL-L-7808 "
          "(docs/tribology.md)", "", "inference", default=0, choices=(0, 1)),
        *_unknown_ints("10.0", 3, 5, "0 in the ball deck"),
    ), section="echo: LUBRICATION PARAMETERS"),
    *(RecordSpec(f"10.1{letter}", f"Traction-slip curve (traction model {code})", (
        F("traction_at_zero_slip", "real", "-", "traction coefficient at zero slip", "", "listing; echo",
          default=0.0, lo=0.0),
        _pos("max_traction", "-", "maximum traction coefficient", evidence="listing; echo"),
        F("traction_at_infinite_slip", "real", "-", "traction coefficient at infinite slip", "",
          "listing; echo", default=0.0, lo=0.0),
        _pos("slip_at_max_traction", "m/s", "slip velocity at maximum traction", evidence="listing; echo"),
    ), when=f"traction_model == {code}", section="4.4.9; echo: LUBRICATION PARAMETERS",
        notes="The echo prints the fitted kappa(u) = (A + B u) exp(-C u) + D with A = kappa0 - kappa_inf, "
              "D = kappa_inf and the maximum at the given slip.")
      for letter, code in (("B", 2), ("C", 3))),
    RecordSpec("10.3", "Lubricant data", (
        _real("rec10_3_value_1", "-", "unknown; 1.25E-07 in the ball deck, echoed in the first column of "
              "the RE/RACE rows of the lubrication table", evidence="unknown"),
        _real("rec10_3_value_2", "-", "unknown; 10.0 in the ball deck, not echoed", evidence="unknown"),
    ), when="lubricant_code != 0", section="echo: LUBRICATION PARAMETERS"),
    *(RecordSpec(rid, f"{who} friction", (
        _real(f"{tag}_coeff_a", "-", f"{who} traction coefficient A (constant friction 0.05 in both decks; "
              "Tables 5/6 cage friction coefficient; the friction of the dynamics' cage contacts)",
              evidence="listing; echo; table", lo=0.0),
        _real(f"{tag}_coeff_b", "s/m", "coefficient B (echo)", evidence="listing; echo"),
        _real(f"{tag}_coeff_c", "s/m", "coefficient C (echo)", evidence="listing; echo"),
        _real(f"{tag}_coeff_d", "-", "coefficient D (echo)", evidence="listing; echo"),
        _real(f"rec{rid.replace('.', '_').lower()}_value_5", "-", "unknown; 1.25E-07 in both decks, "
              f"echoed in the first column of the {who.upper()} row", evidence="unknown"),
    ), section="echo: LUBRICATION PARAMETERS")
      for rid, who, tag in (("10.5.1B", "RE/cage", "re_cage"), ("10.5.2B", "race/cage", "race_cage"))),
    RecordSpec("11", "Gravity", (
        _real("gravity_x", "m/s^2", "gravity vector x (echo GRAVITY VECTOR)"),
        _real("gravity_y", "m/s^2", "gravity vector y"),
        _real("gravity_z", "m/s^2", "gravity vector z"),
    ), section="echo: GRAVITY VECTOR"),
)
