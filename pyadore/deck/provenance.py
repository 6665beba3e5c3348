"""Where every value of the two reconstructed appendix decks comes from.

Each entry is ``(record id, field or None, source, note)``; a ``None`` field covers every
field of the record not listed separately.  ``source`` is one of :data:`SOURCES`:

* ``listing``: a legible line of the deck listing (Appendix C / D of the report);
* ``echo``: the program's input echo in the print output (more digits than the listing);
* ``table``: Table 5 (ball) or Table 6 (roller);
* ``inference``: the line is lost and the value is not printed; the note gives the reasoning
  (the documented default is used where nothing better is known).

The documentation generator turns this into the provenance tables of docs/deck-format.md;
a test checks that it covers every record of ``decks/*.inp`` and names only real fields.
"""

from __future__ import annotations

__all__ = ["SOURCES", "PROVENANCE", "DECK_FILES"]

SOURCES = ("listing", "echo", "table", "inference")

#: Deck name -> file under decks/.
DECK_FILES = {"appendix_c_ball": "decks/appendix_c_ball.inp", "appendix_d_roller": "decks/appendix_d_roller.inp"}

_FRIC = "`5.0000E-02 0 0 0 1.2500E-07`; echo COEFFICIENT A 5.0E-02 and first column 1.25E-07"

PROVENANCE: dict[str, tuple[tuple[str, str | None, str, str], ...]] = {
    "appendix_c_ball": (
        ("1", None, "listing", "first eleven values in the (LaTeX-matrix) first line; echo: Program Mode = 1, "
                               "DATA CONTROL 1 500, INT METHOD 5"),
        ("1", "n_steps", "listing", "`2500`, printed apart from the line (as are `0` and `5`); echo: "
                                    "'Last Step Number = 2500'"),
        ("2.1", None, "listing", "echo: MINIMUM 5.0E-03, MAXIMUM 3.0E-01, INITIAL 5.0E-02, ERROR LIMIT 1.0E-04, "
                                 "CONSTRAINING LOAD FRACTION 0"),
        ("2.4", None, "listing", "`1 0 2`; echo: coolant type Lubricant"),
        ("2.4", "rec2_4_flag_4", "inference", "the listing shows three values where the roller deck has four; "
                                              "the field is written blank (default 0)"),
        ("2.5", None, "listing", "`3.2300E+02 1.0000E-05 0.0000E+00 3.0000E-03 3.0000E-02`; Table 5: inlet "
                                 "temperature 323 K, flow rate 1.0E-05 m^3/s"),
        ("2.7", None, "echo", "listing shows three of six values, one OCR-damaged (`1.2300E+02`); the echo prints "
                              "every initial temperature as 3.23000E+02"),
        ("3.1", None, "echo", "listing line lost; echo 'Run Id = Ball Bearing Test Case kGeoMod=100' (also in "
                              "every step header)"),
        ("3.2", "bearing_type", "echo", "'Bearing Type = BALL' (kBrg 1 = ball, Appendix A)"),
        ("3.2", "n_rolling_elements", "echo", "NO OF BALLS 18; Table 5: 18 balls"),
        ("3.2", None, "inference", "listing line lost; material flags 0 because the echo shows the default steel "
                                   "for all six parts and the deck has no Rec 8.x; flags 1 and 10 not echoed: "
                                   "default 0"),
        ("3.3", None, "inference", "listing line lost and not matched in the echo: default 0 for all eleven flags"),
        ("3.4", None, "listing", "`0 0 0 0 0 2 1 19 0 0 0 0`, the one line printed after the Rec 3.2-3.4 labels"),
        ("4", None, "listing", "`1.0000E-01 1.800E-01 2.000E-02 2.0500E-01 3.0000E-02 3.0000E-02`; echo SHAFT OD, "
                               "BEARING OD 1.80000E-01, SHAFT ID, HOUSING OD, WIDTH I/II; Table 5 bore 0.100, OD 0.180"),
        ("5A", None, "listing", "echo BALL DIA, PITCH DIA, CON ANGLE, CUR FACs; DIA PLAY 2.14180E-04 and END PLAY "
                                "9.66105E-04 follow from these values; Table 5"),
        ("7.0", None, "listing", "`0 0 0 0 0 0 0 0 2 2 2`; echo NO OF C/R LANDS 2, GUIDE TYPE 2 2; Table 5 inner"),
        ("7.1", None, "listing", "echo CAGE WIDTH 3.62410E-02, OUTER/INNER CLS, POC CLS I/II, SEG CUT, CONE"),
        ("7.1", "cage_outer_diameter", "echo", "1.46292E-01 (listing 1.4629E-01); Table 5 0.146292"),
        ("7.1", "cage_inner_diameter", "echo", "1.30073E-01 (listing 1.3007E-01); Table 5 0.130073"),
        ("7.2.1", None, "listing", "`1.3007E-01 8.0000E-03 1.8120E-02 1.5000E-03`; Table 5 width, clearance"),
        ("7.2.1", "guide_land_diameter", "echo", "GUIDE LAND DIA 1.30073E-01"),
        ("7.2.1", "guide_land_position", "echo", "GUIDE LAND POSITION 1.81204E-02"),
        ("7.2.2", None, "listing", "same as Rec 7.2.1"),
        ("7.2.2", "guide_land_diameter", "echo", "GUIDE LAND DIA 1.30073E-01"),
        ("7.2.2", "guide_land_position", "echo", "GUIDE LAND POSITION 1.81204E-02"),
        ("9.0", "room_temperature", "listing", "3.2300E+02; echo ROOM TEMPERATURE; Table 5 323 K"),
        ("9.0", None, "echo", "OUTER FIT 1.00000E-05, INNER FIT 5.00000E-05 (listing OCR `1.0000E+05 5.0000E+05`); "
                              "Table 5"),
        ("9.1.1", None, "listing", "echo APPLIED LOAD VECTOR 4500, 0, 2000; Table 5 thrust 4500 N, radial 2000 N"),
        ("9.1.2", None, "listing", "last value: echo INNER RACE ANGULAR VELOCITY 2.0E+04 rpm; Table 5"),
        ("9.5.1", None, "listing", "run-together `0.0000E+00-6.0000E-04`; echo cage centre, whirl and epicyclic "
                                   "ratios"),
        ("10.0", None, "listing", "`3 1 0 0 0`"),
        ("10.1C", None, "listing", "echo fit A = -1.6E-02, B = 3.82896E-02, C = 1.71782, D = 1.6E-02 reproduces "
                                   "these four values"),
        ("10.3", None, "listing", "`1.2500E-07 1.0000E+01`"),
        ("10.5.1B", None, "listing", _FRIC),
        ("10.5.2B", None, "listing", _FRIC),
        ("11", None, "listing", "`0.0000E+00 0.0000E+00-9.8100E+00`; echo GRAVITY VECTOR"),
    ),
    "appendix_d_roller": (
        ("1", None, "listing", "`1 0 0 0 1 500 2 0 0 1` and `4000 0 5` printed apart; echo NO OF STEPS 4000, "
                               "DATA CONTROL 1 500, INT METHOD 5"),
        ("1", "rec1_flag_5", "inference", "the text copy shows three zeros between MODE and DATA CONTROL where the "
                                          "ball listing shows four; all four are 0, so the restored field is 0 "
                                          "whichever was lost"),
        ("2.1", None, "listing", "echo: MINIMUM 1.0E-04, MAXIMUM 5.0E-01, INITIAL 5.0E-02, CONSTRAINING LOAD "
                                 "FRACTION 5.0E-02"),
        ("2.4", None, "listing", "`0 0 0 1` (also OCR'd as `0 U U L`); echo No Coolant"),
        ("2.5", None, "listing", "`0.0000E+00 0.0000E+00 0.0000E+00 8.5700E-04 8.5700E-04`"),
        ("2.7", None, "listing", "six times 2.9400E+02; echo"),
        ("3.1", None, "listing", "`Cyl Roller Bearing Geo Mod`; echo Run Id"),
        ("3.2", None, "listing", "`1 2 8 1 0 0 0 0 0 1` (one number per line in the text copy); echo NO OF ROLLERS 8"),
        ("3.3", None, "listing", "`1 1 1 1 0 0 0 0 0 0 1` (one number per line)"),
        ("3.4", None, "listing", "first twelve of a garbled run of 91 numbers (`1 1 1 1` then zeros); the count "
                                 "12 is that of the ball deck's Rec 3.4"),
        ("4", None, "echo", "listing line lost; SHAFT OD 3.0E-02, BEARING OD 5.5E-02, SHAFT ID 1.0E-02, HOUSING "
                            "OD 6.5E-02, WIDTH I/II 1.2E-02; Table 6 bore 0.030, OD 0.055"),
        ("5B", None, "echo", "listing line lost; ROLLER DIA, ROLLER LEN, CEN LAND, PITCH DIA, CROWN RAD, COR RAD "
                             "I/II, DIA PLAY, OUTER/INNER CRN; Table 6. The field order is an inference (echo order)"),
        ("5B.1", None, "listing", "`1.0000E-02 0.0000E+00 1.0000E-02 0.0000E+00`; echo OUTER/INNER LEN1/LEN2"),
        ("7.0", None, "listing", "`0 0 0 0 0 0 0 0 2 1 1`; echo GUIDE TYPE 1 1; Table 6 outer"),
        ("7.1", None, "listing", "echo CAGE OD 4.5E-02, ID 4.0E-02, WIDTH 1.0E-02, OUTER CLS 1.0E-04, INNER CLS "
                                 "1.0E-03; Table 6"),
        ("7.2.1", None, "listing", "`4.5000E-02 1.0000E-03 5.0000E-03 1.0000E-04`; echo guide land table"),
        ("7.2.2", None, "listing", "same as Rec 7.2.1"),
        ("8.1", None, "listing", "ceramic roller material (section 5.4)"),
        ("9.0", None, "listing", "echo ROOM TEMPERATURE 294, OUTER FIT 0, INNER FIT 2.0E-05; Table 6"),
        ("9.1.1", None, "listing", "echo APPLIED LOAD VECTOR 0, 0, 1000; Table 6 radial load 1000 N"),
        ("9.1.2", None, "listing", "last value: echo INNER RACE ANGULAR VELOCITY 7.0E+04 rpm; Table 6"),
        ("9.5.1", None, "listing", "first nine values of the line (the text copy appends garbled zeros); echo cage "
                                   "centre z 5.0E-05"),
        ("10.0", "traction_model", "inference", "listing line lost; 2 because the deck carries Rec 10.1B "
                                                "(the ball deck's 3 goes with Rec 10.1C)"),
        ("10.0", "lubricant_code", "inference", "0: no Rec 10.3 follows, no lubricant or coolant (Table 6)"),
        ("10.0", None, "inference", "listing line lost; flags 3-5 take the default 0 (0 in the ball deck too)"),
        ("10.1B", None, "echo", "listing line lost; inverted from the echo fit A = -8.0E-02, B = 9.57239E-01, "
                                "C = 8.58912, D = kappa_inf: kappa0 = 0, kappa_inf = 0.08, slip at maximum "
                                "1/C - A/B = 0.2000 m/s, kappa_max = 0.1000"),
        ("10.5.1B", None, "listing", _FRIC),
        ("10.5.2B", None, "listing", _FRIC),
        ("11", None, "listing", "`0.0000E+00 0.0000E+00-9.8100E+00`"),
    ),
}
