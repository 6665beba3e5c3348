!> GENERATED FILE - do not edit.  Source: pyadore/printout/layout.py and echo_layout.py;
!> regenerate with `python -m pyadore.printout.fortran_layout > fortran/output/layout.f90`.
!> tests/test_print_writer.py fails when this file differs from a fresh generation.
!>
!> The ADORE 5.0 print layout (docs/print-layout.md) as parameter data for the engine's
!> print writer (fortran/output/print_tables.f90, print_echo.f90, echo_data.f90).
module adore_output_layout
   implicit none
   private

   public :: LINE_WIDTH, VALUE_WIDTH, INT_NOT_COMPUTED, NOT_COMPUTED_TOKEN, STEP_HEADING, &
      STEP_UNITS, STEP_RULE, SECTION_TITLE_1, SECTION_TITLE_1A, SECTION_TITLE_2, SECTION_TITLE_3, &
      SECTION_TITLE_4, TABLE_RE_CONTACT, TABLE_RE_MOTION, TABLE_RE_TRACTION, TABLE_RE_THERMAL, &
      TABLE_SLICES, TABLE_RE_CAGE, TABLE_RE_CAGE_ROLLER, TABLE_RACE_CAGE, TABLE_BODIES, &
      TABLE_LOADS, TABLE_ACCELERATIONS, TABLE_SUMMARY, N_TABLES, LABEL_INT, LABEL_STEP, LABEL_TEXT, &
      LABEL_RE_END, TABLE_NAME, TABLE_NCOL, TABLE_NCODE, TABLE_LABEL_KIND, TABLE_LABEL_WIDTH, &
      TABLE_HEAD_FIRST, TABLE_HEAD_COUNT, N_HEADING_LINES, HEADING_LINE, BODY_ROW, LOAD_ROW, &
      ACC_ROW, N_PERFORMANCE, RIGHT_LABEL, LOADS_RIGHT_COL, ACC_RIGHT_COL, LOADS_RIGHT_LINE, &
      LOADS_RIGHT_CELL, ACC_RIGHT_LINE, ACC_RIGHT_CELL, TERMINATION_STEP_TEXT, &
      TERMINATION_TIME_TEXT, STATISTICS_TITLE, STATISTICS_LABEL, ECHO_TEXT_LEN, ECHO_MAX_GUIDE, &
      ECHO_MAX_QS, ELEMENT_BALL, ELEMENT_ROLLER, ET_BEARING_TYPE, ET_RUN_ID, ET_TITLE, &
      ET_LUBRICANT, ET_WEIBULL_SLOPE, ET_LIFE_MOD_CODE, ET_COOLANT_TYPE, ET_NODE_BASE_TEMP, &
      ET_VARY_GEOMETRY, N_ECHO_TEXT, EI_ELEMENT_KIND, EI_PROGRAM_MODE, EI_N_ELEMENTS, &
      EI_POCKET_SHAPE, EI_N_LANDS, EI_N_CAGE_SEGS, EI_N_GUIDE, EI_GUIDE_LAND, EI_GUIDE_TYPE, &
      EI_N_QS, EI_QS_CONSTRAINTS, EI_TRANS_CONSTRAINTS, EI_ROT_CONSTRAINTS, EI_PRINT_HTC, &
      EI_N_STEPS, EI_DATA_CONTROL, EI_AUTO_PLOTS, EI_INT_METHOD, N_ECHO_INT, ER_ELEMENT_DIA, &
      ER_PITCH_DIA, ER_CONTACT_ANGLE, ER_CUR_FAC, ER_DIA_PLAY, ER_END_PLAY, ER_FIT, ER_WIDTH, &
      ER_SHAFT_OD, ER_SHAFT_ID, ER_BEARING_OD, ER_HOUSING_OD, ER_ROLLER_LEN, ER_CEN_LAND, &
      ER_OUTER_LEN, ER_INNER_LEN, ER_CROWN_RAD, ER_COR_RAD, ER_RACE_CROWN, ER_CAGE_OD, ER_CAGE_ID, &
      ER_CAGE_CONE, ER_CAGE_WIDTH, ER_SEG_CUT, ER_POC_CLS, ER_RACE_CLS, ER_GUIDE, ER_MATERIAL, &
      ER_INERTIA, ER_PRINCIPAL, ER_LUBRICATION, ER_FATIGUE, ER_ASPERITY, ER_ROOM_TEMP, &
      ER_HOUSING_TEMP, ER_SHAFT_TEMP, ER_RE_TEMP, ER_CAGE_TEMP, ER_RACE_SPEED, ER_RACE_TEMP, &
      ER_MISALIGN_Y, ER_MISALIGN_Z, ER_LOAD_FRACTION, ER_HEAT_TRANS_COEFF, ER_APPLIED_LOAD, &
      ER_REL_DISP, ER_APPLIED_MOMENT, ER_GRAVITY, ER_CAGE_POSITION, ER_CAGE_ANGLE, ER_WHIRL_RATIO, &
      ER_EPICYCLIC_RATIO, ER_SCALE_LENGTH, ER_SCALE_LOAD, ER_SCALE_TIME, ER_STEP_MIN, ER_STEP_MAX, &
      ER_STEP_INITIAL, ER_ERROR_LIMIT, N_ECHO_REAL, ECHO_COPYRIGHT, ECHO_BOX_RULE, &
      ECHO_BOX_TYPE_TEXT, ECHO_BOX_MODE_TEXT, ECHO_BOX_RUN_TEXT, ECHO_BLOCK_TITLE, ECHO_ITEM_WIDTH, &
      ECHO_GEOM_BALL_LABEL, ECHO_GEOM_ROLLER_LABEL, ECHO_CAGE_LABEL, ECHO_GUIDE_HEAD, &
      ECHO_MAT_HEAD, ECHO_MAT_LABEL, ECHO_MAT_COUNT, ECHO_BODY_LABEL, ECHO_INERTIA_HEAD, &
      ECHO_PRINCIPAL_HEAD, ECHO_LUB_HEAD, ECHO_LUB_LABEL, ECHO_LUBRICANT_LABEL, ECHO_FAT_HEAD, &
      ECHO_RACE_LABEL, ECHO_FAT_TEXT_LABEL, ECHO_ASP_HEAD, ECHO_OPER_RACE_HEAD, &
      ECHO_OPER_LEFT_LABEL, ECHO_OPER_RIGHT_LABEL, ECHO_LOAD_FRACTION_LABEL, ECHO_HTC_LABEL, &
      ECHO_FLAGS_LABEL, ECHO_OPER_TEXT_LABEL, ECHO_VECTOR_HEAD, ECHO_VECTOR_LABEL, ECHO_SCALE_HEAD, &
      ECHO_SCALE_LABEL, ECHO_STEP_LABEL, ECHO_CONTROL_LABEL, ECHO_SCALE_RIGHT_LABEL, &
      ECHO_ERROR_LIMIT_LABEL

   !> General rules: line width, table value width (1X,ES10.3), the integer 'not computed' value.
   integer, parameter :: LINE_WIDTH = 132
   integer, parameter :: VALUE_WIDTH = 11
   integer, parameter :: INT_NOT_COMPUTED = -2147483647
   character(len=*), parameter :: NOT_COMPUTED_TOKEN = "NaN"

   !> Step header block (I6,2(1X,ES10.3),2(5X,ES10.3),2X,A) between these lines; section titles.
   character(len=*), parameter :: STEP_HEADING = &
      "  step        tau       Time Outer Race Rot Inner Race Rot  " // &
      "(ADORE 5.0)"
   character(len=*), parameter :: STEP_UNITS = &
      "    no                   (s)          (rev)          (rev)"
   character(len=*), parameter :: STEP_RULE = &
      "====== ========== ========== ============== =============="
   character(len=*), parameter :: SECTION_TITLE_1 = "1. Rolling Element Parameters"
   character(len=*), parameter :: SECTION_TITLE_1A = "1a. Load Distribution Along Roller no."
   character(len=*), parameter :: SECTION_TITLE_2 = "2. Race and Cage Parameters"
   character(len=*), parameter :: SECTION_TITLE_3 = "3. Applied Parameters"
   character(len=*), parameter :: SECTION_TITLE_4 = "4. Time Step Summary"

   !> Step tables: id, name, value columns, I3 code columns, row-label kind and width,
   !> and the range of their heading lines in HEADING_LINE.
   integer, parameter :: TABLE_RE_CONTACT = 1
   integer, parameter :: TABLE_RE_MOTION = 2
   integer, parameter :: TABLE_RE_TRACTION = 3
   integer, parameter :: TABLE_RE_THERMAL = 4
   integer, parameter :: TABLE_SLICES = 5
   integer, parameter :: TABLE_RE_CAGE = 6
   integer, parameter :: TABLE_RE_CAGE_ROLLER = 7
   integer, parameter :: TABLE_RACE_CAGE = 8
   integer, parameter :: TABLE_BODIES = 9
   integer, parameter :: TABLE_LOADS = 10
   integer, parameter :: TABLE_ACCELERATIONS = 11
   integer, parameter :: TABLE_SUMMARY = 12
   integer, parameter :: N_TABLES = 12
   integer, parameter :: LABEL_INT = 1
   integer, parameter :: LABEL_STEP = 2
   integer, parameter :: LABEL_TEXT = 3
   integer, parameter :: LABEL_RE_END = 4
   character(len=13), parameter :: TABLE_NAME(12) = [character(len=13) :: &
      "re_contact", &
      "re_motion", &
      "re_traction", &
      "re_thermal", &
      "slices", &
      "re_cage", &
      "re_cage", &
      "race_cage", &
      "bodies", &
      "loads", &
      "accelerations", &
      "summary"]
   integer, parameter :: TABLE_NCOL(12) = [11, 11, 11, 11, 10, 8, 8, 7, 11, 6, 7, 10]
   integer, parameter :: TABLE_NCODE(12) = [0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0]
   integer, parameter :: TABLE_LABEL_KIND(12) = [1, 1, 1, 1, 1, 1, 4, 1, 3, 3, 3, 2]
   integer, parameter :: TABLE_LABEL_WIDTH(12) = [5, 5, 5, 5, 5, 5, 5, 5, 5, 10, 10, 6]
   integer, parameter :: TABLE_HEAD_FIRST(12) = [1, 4, 7, 10, 13, 16, 20, 24, 27, 30, 35, 39]
   integer, parameter :: TABLE_HEAD_COUNT(12) = [3, 3, 3, 3, 3, 4, 4, 3, 3, 5, 4, 4]
   integer, parameter :: N_HEADING_LINES = 42
   character(len=126), parameter :: HEADING_LINE(42) = [character(len=126) :: &
      "   RE  Orbital       Contact Angle          Contact Load    " // &
      "     Contact Stress       Major Half Width      Minor Half W" // &
      "idth", &
      "   no   Position      (deg)                   (N)           " // &
      "       (Pa)                   (m)                   (m)", &
      "           (deg) Outer Race Inner Race Outer Race Inner Race" // &
      " Outer Race Inner Race Outer Race Inner Race Outer Race Inne" // &
      "r Race", &
      "   RE  Orbital           Angular Velocity            RE Ang " // &
      "Position          Spin/Roll            Contact Loss      Tim" // &
      "e Ave", &
      "   no   Velocity  Amplitude      Theta        Phi      Theta" // &
      "        Phi                              (W)             Wea" // &
      "r Rate", &
      "           (rpm)      (rpm)      (deg)      (deg)      (deg)" // &
      "      (deg) Outer Race Inner Race Outer Race Inner Race   (m" // &
      "**3/s)", &
      "   RE     Slip Velocity           Trac Coeff           Iso L" // &
      "ub Film        Thermal Red Fac       Drag     Chrn Mom   Net" // &
      " Loss", &
      "   no      (m/s)                                         (m)" // &
      "                                         (N)      (N.m)     " // &
      "   (W)", &
      "      Outer Race Inner Race Outer Race Inner Race Outer Race" // &
      " Inner Race Outer Race Inner Race                      (Drag" // &
      "+Chur)", &
      "   RE Rel Axial    Contact Deflection       Race Flexing    " // &
      "   Contact Temp Rise        Contact Temp     Bulk Temp  Conv" // &
      "ec HTC", &
      "   no        Pos        (m)                   (m)           " // &
      "        (K)                   (K)                   (K)", &
      "             (m) Outer Race Inner Race Outer Race Inner Race" // &
      " Outer Race Inner Race Outer Race Inner Race            (W/m" // &
      "**2/K)", &
      "Slice                   Outer Race Contact                  " // &
      "                   Inner Race Contact", &
      "   no  Axial Pos    Geo Int Half Width   Nor Load  Trac Load" // &
      "  Axial Pos    Geo Int Half Width   Nor Load  Trac Load", &
      "             (m)        (m)        (m)      (N/m)      (N/m)" // &
      "        (m)        (m)        (m)      (N/m)      (N/m)", &
      "   RE  C                                   RE/Cage Interacti" // &
      "on", &
      "   no       Geo Int    Contact    Con Ang    Con Ang    Cont" // &
      "act    Contact    Contact   Time Ave", &
      "                         Force      THETA        PHI      Po" // &
      "s X      Pos Z       Loss  Wear Rate", &
      "                (m)        (N)      (deg)      (deg)        " // &
      "(m)        (m)        (W)   (m**3/s)", &
      "   RE End  C                                   RE/Cage Inter" // &
      "action", &
      "   no  no       Geo Int    Contact    Con Ang    Con Ang    " // &
      "Contact    Contact    Contact   Time Ave", &
      "                            Force      THETA        PHI     " // &
      " Pos X      Pos Z       Loss  Wear Rate", &
      "                   (m)        (N)      (deg)      (deg)     " // &
      "   (m)        (m)        (W)   (m**3/s)", &
      "   LD  C            Race/Cage Interaction            Effecti" // &
      "ve   Contact    Time Ave", &
      "   no       Geo Int      Force  Con Angle  Att Angle   Dia P" // &
      "lay       Loss  Wear Rate", &
      "                (m)        (N)      (deg)      (deg)        " // &
      "(m)        (W)   (m**3/s)", &
      "            Mass Center Position        Orbital           An" // &
      "gular Velocity              Ang Position        Hoop     Tim" // &
      "e Ave", &
      "           Axial     Radial    Orbital   Velocity  Amplitude" // &
      "      Theta        Phi      Theta        Phi     Stress  Wea" // &
      "r Rate", &
      "             (m)        (m)      (deg)      (rpm)      (rpm)" // &
      "      (deg)      (deg)      (deg)      (deg)       (Pa)   (m" // &
      "**3/s)", &
      "", &
      "               Forces in Inertial Frame       Moments in Bod" // &
      "y-Fixed Frame", &
      "               Comp-x     Comp-y     Comp-z     Comp-x     C" // &
      "omp-y     Comp-z", &
      "                  (N)        (N)        (N)      (N.m)      " // &
      "(N.m)      (N.m)", &
      "", &
      "               MC Acc in Inertial Frame       Ang Acc in Bod" // &
      "y-Fixed Frame    Bulk Temp", &
      "                       (m/s**2)                         (rpm" // &
      "/s)                 (K)", &
      "               Comp-x     Comp-y     Comp-z     Comp-x     C" // &
      "omp-y     Comp-z", &
      "", &
      "                                                            " // &
      " Time Average Parameters", &
      "  Step       Time Outer Race Inner Race    Fatigue      Powe" // &
      "r RE Orbital Cage Omega Cage Whirl       Cage Average RE", &
      "    no              Rotation   Rotation       Life       Los" // &
      "s  Vel Ratio      Ratio      Ratio  Wear Rate  Excursion", &
      "              (s)      (rev)      (rev)    (hours)        (W" // &
      ")                                    (m**3/s)        (m)"]

   !> Row labels of the text-labelled tables.
   character(len=5), parameter :: BODY_ROW(3) = [character(len=5) :: &
      "Cage", &
      "ORace", &
      "IRace"]
   character(len=10), parameter :: LOAD_ROW(5) = [character(len=10) :: &
      "Cage", &
      "Int ORace", &
      "Int IRace", &
      "Ext ORace", &
      "Ext IRace"]
   character(len=10), parameter :: ACC_ROW(3) = [character(len=10) :: &
      "Cage", &
      "ORace", &
      "IRace"]

   !> Section 3: the right-hand cells (T<col>,A30,1X,ES10.3).  RIGHT_LABEL is indexed like the
   !> performance vector; *_RIGHT_LINE is the 1-based line of the block (headings, then rows)
   !> that carries performance value *_RIGHT_CELL.
   integer, parameter :: N_PERFORMANCE = 14
   character(len=30), parameter :: RIGHT_LABEL(14) = [character(len=30) :: &
      "Basic Fatigue Life     (hours)", &
      "Modified Fatigue Life  (hours)", &
      "Outer Race Fit         (m)", &
      "Inner Race Fit         (m)", &
      "Internal Clearance     (m)", &
      "Total Power Loss       (W)", &
      "Churning Loss Fraction", &
      "Exit Fluid Temperature (K)", &
      "Hsng/Bulk Temp  (K)", &
      "Hsng/Outer Temp (K)", &
      "Hsng/Inner Temp (K)", &
      "Shft/Bulk Temp  (K)", &
      "Shft/Outer Temp (K)", &
      "Shft/Inner Temp (K)"]
   integer, parameter :: LOADS_RIGHT_COL = 79
   integer, parameter :: ACC_RIGHT_COL = 90
   integer, parameter :: LOADS_RIGHT_LINE(8) = [1, 2, 3, 4, 5, 7, 8, 9]
   integer, parameter :: LOADS_RIGHT_CELL(8) = [1, 2, 3, 4, 5, 6, 7, 8]
   integer, parameter :: ACC_RIGHT_LINE(6) = [1, 2, 3, 4, 6, 7]
   integer, parameter :: ACC_RIGHT_CELL(6) = [9, 10, 11, 12, 13, 14]

   !> End of run: (5X,A,I8,5X,A,1X,ES10.4); statistics (5X,A22,' =',1X,ES12.5) / (5X,A22,' =',I13).
   character(len=*), parameter :: TERMINATION_STEP_TEXT = "Normal termination: Last Step Number ="
   character(len=*), parameter :: TERMINATION_TIME_TEXT = "Final Time ="
   character(len=*), parameter :: STATISTICS_TITLE = "Statistics of this Run"
   character(len=22), parameter :: STATISTICS_LABEL(5) = [character(len=22) :: &
      "Minimum Step Size", &
      "Maximum Step Size", &
      "Last Step Size", &
      "Max Truncation", &
      "Total Derivative Calls"]

   !> Echo record (echo_data_t): sizes, and the 1-based offsets of every field in the flat
   !> text / integer / real vectors of the f2py wrapper (order of echo_layout.py).
   integer, parameter :: ECHO_TEXT_LEN = 80
   integer, parameter :: ECHO_MAX_GUIDE = 8
   integer, parameter :: ECHO_MAX_QS = 6
   integer, parameter :: ELEMENT_BALL = 1
   integer, parameter :: ELEMENT_ROLLER = 2
   integer, parameter :: ET_BEARING_TYPE = 1
   integer, parameter :: ET_RUN_ID = 2
   integer, parameter :: ET_TITLE = 3
   integer, parameter :: ET_LUBRICANT = 4
   integer, parameter :: ET_WEIBULL_SLOPE = 5
   integer, parameter :: ET_LIFE_MOD_CODE = 6
   integer, parameter :: ET_COOLANT_TYPE = 7
   integer, parameter :: ET_NODE_BASE_TEMP = 8
   integer, parameter :: ET_VARY_GEOMETRY = 9
   integer, parameter :: N_ECHO_TEXT = 9
   integer, parameter :: EI_ELEMENT_KIND = 1
   integer, parameter :: EI_PROGRAM_MODE = 2
   integer, parameter :: EI_N_ELEMENTS = 3
   integer, parameter :: EI_POCKET_SHAPE = 4
   integer, parameter :: EI_N_LANDS = 5
   integer, parameter :: EI_N_CAGE_SEGS = 6
   integer, parameter :: EI_N_GUIDE = 7
   integer, parameter :: EI_GUIDE_LAND = 8
   integer, parameter :: EI_GUIDE_TYPE = 16
   integer, parameter :: EI_N_QS = 24
   integer, parameter :: EI_QS_CONSTRAINTS = 25
   integer, parameter :: EI_TRANS_CONSTRAINTS = 31
   integer, parameter :: EI_ROT_CONSTRAINTS = 37
   integer, parameter :: EI_PRINT_HTC = 43
   integer, parameter :: EI_N_STEPS = 44
   integer, parameter :: EI_DATA_CONTROL = 45
   integer, parameter :: EI_AUTO_PLOTS = 48
   integer, parameter :: EI_INT_METHOD = 51
   integer, parameter :: N_ECHO_INT = 51
   integer, parameter :: ER_ELEMENT_DIA = 1
   integer, parameter :: ER_PITCH_DIA = 2
   integer, parameter :: ER_CONTACT_ANGLE = 3
   integer, parameter :: ER_CUR_FAC = 4
   integer, parameter :: ER_DIA_PLAY = 6
   integer, parameter :: ER_END_PLAY = 7
   integer, parameter :: ER_FIT = 8
   integer, parameter :: ER_WIDTH = 10
   integer, parameter :: ER_SHAFT_OD = 12
   integer, parameter :: ER_SHAFT_ID = 13
   integer, parameter :: ER_BEARING_OD = 14
   integer, parameter :: ER_HOUSING_OD = 15
   integer, parameter :: ER_ROLLER_LEN = 16
   integer, parameter :: ER_CEN_LAND = 17
   integer, parameter :: ER_OUTER_LEN = 18
   integer, parameter :: ER_INNER_LEN = 20
   integer, parameter :: ER_CROWN_RAD = 22
   integer, parameter :: ER_COR_RAD = 23
   integer, parameter :: ER_RACE_CROWN = 25
   integer, parameter :: ER_CAGE_OD = 27
   integer, parameter :: ER_CAGE_ID = 28
   integer, parameter :: ER_CAGE_CONE = 29
   integer, parameter :: ER_CAGE_WIDTH = 30
   integer, parameter :: ER_SEG_CUT = 31
   integer, parameter :: ER_POC_CLS = 32
   integer, parameter :: ER_RACE_CLS = 34
   integer, parameter :: ER_GUIDE = 36
   integer, parameter :: ER_MATERIAL = 68
   integer, parameter :: ER_INERTIA = 122
   integer, parameter :: ER_PRINCIPAL = 150
   integer, parameter :: ER_LUBRICATION = 162
   integer, parameter :: ER_FATIGUE = 198
   integer, parameter :: ER_ASPERITY = 208
   integer, parameter :: ER_ROOM_TEMP = 224
   integer, parameter :: ER_HOUSING_TEMP = 225
   integer, parameter :: ER_SHAFT_TEMP = 226
   integer, parameter :: ER_RE_TEMP = 227
   integer, parameter :: ER_CAGE_TEMP = 228
   integer, parameter :: ER_RACE_SPEED = 229
   integer, parameter :: ER_RACE_TEMP = 231
   integer, parameter :: ER_MISALIGN_Y = 233
   integer, parameter :: ER_MISALIGN_Z = 235
   integer, parameter :: ER_LOAD_FRACTION = 237
   integer, parameter :: ER_HEAT_TRANS_COEFF = 238
   integer, parameter :: ER_APPLIED_LOAD = 239
   integer, parameter :: ER_REL_DISP = 242
   integer, parameter :: ER_APPLIED_MOMENT = 245
   integer, parameter :: ER_GRAVITY = 248
   integer, parameter :: ER_CAGE_POSITION = 251
   integer, parameter :: ER_CAGE_ANGLE = 254
   integer, parameter :: ER_WHIRL_RATIO = 257
   integer, parameter :: ER_EPICYCLIC_RATIO = 258
   integer, parameter :: ER_SCALE_LENGTH = 259
   integer, parameter :: ER_SCALE_LOAD = 260
   integer, parameter :: ER_SCALE_TIME = 261
   integer, parameter :: ER_STEP_MIN = 262
   integer, parameter :: ER_STEP_MAX = 263
   integer, parameter :: ER_STEP_INITIAL = 264
   integer, parameter :: ER_ERROR_LIMIT = 265
   integer, parameter :: N_ECHO_REAL = 265

   !> Echo: banner box, block titles, item grids (labels row by row; blank = empty cell).
   character(len=*), parameter :: ECHO_COPYRIGHT = "Copyright Pradeep K Gupta Inc"
   character(len=*), parameter :: ECHO_BOX_RULE = &
      "************************************************************" // &
      "************************************************************"
   character(len=*), parameter :: ECHO_BOX_TYPE_TEXT = "*  Bearing Type = "
   character(len=*), parameter :: ECHO_BOX_MODE_TEXT = "Program Mode = "
   character(len=*), parameter :: ECHO_BOX_RUN_TEXT = "Run Id = "
   character(len=33), parameter :: ECHO_BLOCK_TITLE(7) = [character(len=33) :: &
      "BEARING GEOMETRY", &
      "MATERIAL PROPERTIES", &
      "INERTIAL PARAMETERS", &
      "LUBRICATION PARAMETERS", &
      "FATIGUE PARAMETERS", &
      "INITIAL OPERATING CONDITIONS", &
      "SCALE FACTORS AND OUTPUT CONTROLS"]
   integer, parameter :: ECHO_ITEM_WIDTH = 20
   character(len=20), parameter :: ECHO_GEOM_BALL_LABEL(16) = [character(len=20) :: &
      "NO OF BALLS", &
      "OUTER CUR FAC", &
      "OUTER FIT (m)", &
      "SHAFT OD (m)", &
      "BALL DIA (m)", &
      "INNER CUR FAC", &
      "INNER FIT (m)", &
      "SHAFT ID (m)", &
      "PITCH DIA (m)", &
      "DIA PLAY (m)", &
      "WIDTH I (m)", &
      "BEARING OD (m)", &
      "CON ANGLE (deg)", &
      "END PLAY (m)", &
      "WIDTH II (m)", &
      "HOUSING OD (m)"]
   character(len=20), parameter :: ECHO_GEOM_ROLLER_LABEL(24) = [character(len=20) :: &
      "NO OF ROLLERS", &
      "PITCH DIA (m)", &
      "OUTER FIT (m)", &
      "SHAFT OD (m)", &
      "ROLLER DIA (m)", &
      "CROWN RAD (m)", &
      "INNER FIT (m)", &
      "SHAFT ID (m)", &
      "ROLLER LEN (m)", &
      "COR RAD I (m)", &
      "DIA PLAY (m)", &
      "BEARING OD (m)", &
      "CEN LAND (m)", &
      "COR RAD II (m)", &
      "OUTER CRN (m)", &
      "HOUSING OD (m)", &
      "OUTER LEN1 (m)", &
      "INNER LEN1 (m)", &
      "INNER CRN (m)", &
      "WIDTH I (m)", &
      "OUTER LEN2 (m)", &
      "INNER LEN2 (m)", &
      "", &
      "WIDTH II (m)"]
   character(len=20), parameter :: ECHO_CAGE_LABEL(12) = [character(len=20) :: &
      "CAGE OD (m)", &
      "CAGE WIDTH (m)", &
      "POC CLS I (m)", &
      "OUTER CLS (m)", &
      "CAGE ID (m)", &
      "SEG CUT (deg)", &
      "POC CLS II (m)", &
      "INNER CLS (m)", &
      "CAGE CONE (deg)", &
      "POCKET SHAPE", &
      "NO OF C/R LANDS", &
      "NO OF CAGE SEGS"]
   character(len=70), parameter :: ECHO_GUIDE_HEAD(3) = [character(len=70) :: &
      "    GUIDE    GUIDE   GUIDE LAND   GUIDE LAND   GUIDE LAND   " // &
      "GUIDE LAND", &
      "     LAND     TYPE          DIA          CLS        WIDTH   " // &
      "  POSITION", &
      "                            (m)          (m)          (m)   " // &
      "       (m)"]

   !> Echo: matrices (1X,A<w>,n(1X,ES12.5)) with their heading lines; the label arrays have
   !> the print width as their length.
   character(len=*), parameter :: ECHO_MAT_HEAD = &
      "                              ROLLING ELEM   OUTER RACE   IN" // &
      "NER RACE         CAGE        SHAFT      HOUSING"
   character(len=28), parameter :: ECHO_MAT_LABEL(9) = [character(len=28) :: &
      "DENSITY (kg/m**3)", &
      "ELASTIC MODULUS (Pa)", &
      "POISSON-S RATIO", &
      "COEFF OF THERMAL EXP", &
      "THERMAL CONDUCTIVITY (W/m/K)", &
      "HEAT CAPACITY (J/kg/K)", &
      "ELASTIC STRAIN LIMIT", &
      "HARDNESS (RC)", &
      "WEAR COEFFICIENT"]
   integer, parameter :: ECHO_MAT_COUNT(9) = [6, 6, 6, 6, 6, 4, 4, 4, 4]
   character(len=12), parameter :: ECHO_BODY_LABEL(4) = [character(len=12) :: &
      "RE", &
      "CAGE", &
      "OUTER RACE", &
      "INNER RACE"]
   character(len=104), parameter :: ECHO_INERTIA_HEAD(3) = [character(len=104) :: &
      "                      MASS    MOMENT OF      INERTIA        " // &
      "       MASS TO GEO       CENTER", &
      "                      (kg)    (kg*m**2)                     " // &
      "               (m)", &
      "                                 X-COMP       Y-COMP       Z" // &
      "-COMP       X-COMP       Y-COMP       Z-COMP"]
   character(len=52), parameter :: ECHO_PRINCIPAL_HEAD(3) = [character(len=52) :: &
      "              PRINCIPAL TO    GEO FRAME", &
      "                     (deg)", &
      "                    X-COMP       Y-COMP       Z-COMP"]
   character(len=130), parameter :: ECHO_LUB_HEAD(3) = [character(len=130) :: &
      "              HYPOTHETICAL   TRAC COEFF      MAXIMUM   TRAC " // &
      "COEFF  SLIP AT MAX  COEFFICIENT  COEFFICIENT  COEFFICIENT  C" // &
      "OEFFICIENT", &
      "                    MODELS AT ZERO SLIP   TRAC COEFF  AT INF" // &
      " SLIP     TRACTION            A            B            C   " // &
      "         D", &
      "                                                            " // &
      "             (m/s)                     (s/m)        (s/m)"]
   character(len=12), parameter :: ECHO_LUB_LABEL(4) = [character(len=12) :: &
      "RE/RACE1", &
      "RE/RACE2", &
      "RE/CAGE", &
      "RACE/CAGE"]
   character(len=11), parameter :: ECHO_LUBRICANT_LABEL(1) = [character(len=11) :: &
      "LUBRICANT:"]
   character(len=78), parameter :: ECHO_FAT_HEAD(3) = [character(len=78) :: &
      "              LINE CONTACT      CONTACT   POINT CONT      CO" // &
      "NTACT      WEIBULL", &
      "              FATIGUE CONS     LOAD EXP FATIGUE CONS     LOA" // &
      "D EXP   DISPERSION", &
      "              N/m**(50/27)               (N/m**1.80)        " // &
      "          EXPONENT"]
   character(len=12), parameter :: ECHO_RACE_LABEL(2) = [character(len=12) :: &
      "OUTER RACE", &
      "INNER RACE"]
   character(len=25), parameter :: ECHO_FAT_TEXT_LABEL(2) = [character(len=25) :: &
      "BEARING WEIBULL SLOPE:", &
      "LIFE MODIFICATION CODE:"]
   character(len=117), parameter :: ECHO_ASP_HEAD(3) = [character(len=117) :: &
      "                 COMPOSITE    COMPOSITE     TRACTION  LIMIT " // &
      "SHEAR     RESIDUAL    MATERIALS      CONTAM-   PROCESSING", &
      "                RMS HEIGHT    RMS SLOPE        COEFF       S" // &
      "TRESS       STRESS       FACTOR      INATION       FACTOR", &
      "                       (m)        (rad)                     " // &
      " (Pa)         (Pa)                    FACTOR"]

   !> Echo: initial operating conditions.
   character(len=*), parameter :: ECHO_OPER_RACE_HEAD = &
      "                                                            " // &
      "             OUTER RACE   INNER RACE"
   character(len=31), parameter :: ECHO_OPER_LEFT_LABEL(5) = [character(len=31) :: &
      "ROOM TEMPERATURE (K)", &
      "HOUSING TEMPERATURE (K)", &
      "SHAFT TEMPERATURE (K)", &
      "ROLLING ELEMENT TEMPERATURE (K)", &
      "CAGE TEMPERATURE (K)"]
   character(len=24), parameter :: ECHO_OPER_RIGHT_LABEL(4) = [character(len=24) :: &
      "ANGULAR VELOCITY (rpm)", &
      "TEMPERATURE (K)", &
      "MISALIGNMENT-Y (rad)", &
      "MISALIGNMENT-Z (rad)"]
   character(len=31), parameter :: ECHO_LOAD_FRACTION_LABEL(1) = [character(len=31) :: &
      "CONSTRAINING LOAD FRACTION"]
   character(len=31), parameter :: ECHO_HTC_LABEL(1) = [character(len=31) :: &
      "HEAT TRANS COEFF (W/m**2/K)"]
   character(len=30), parameter :: ECHO_FLAGS_LABEL(3) = [character(len=30) :: &
      "QUASI-STATIC CONSTRAINTS", &
      "TRANSLATIONAL CONSTRAINTS", &
      "ROTATIONAL CONSTRAINTS"]
   character(len=32), parameter :: ECHO_OPER_TEXT_LABEL(3) = [character(len=32) :: &
      "BEARING COOLANT TYPE:", &
      "NODE AT BASE TEMPERATURE:", &
      "VARY GEOMETRY WITH TEMPERATURE:"]
   character(len=*), parameter :: ECHO_VECTOR_HEAD = &
      "                                            X-COMP       Y-C" // &
      "OMP       Z-COMP"
   character(len=36), parameter :: ECHO_VECTOR_LABEL(8) = [character(len=36) :: &
      "APPLIED LOAD VECTOR (N)", &
      "RELATIVE DISPLACEMENT VECTOR (m)", &
      "APPLIED MOMENT VECTOR (N.m)", &
      "GRAVITY VECTOR (m/s**2)", &
      "CAGE GEOM CEN POSITION (m)", &
      "CAGE ANGULAR POSITION (deg)", &
      "CAGE WHIRL TO ANG VEL RATIO", &
      "CAGE ANG VEL TO EPICYCLIC VEL RATIO"]

   !> Echo: scale factors and output controls.
   character(len=*), parameter :: ECHO_SCALE_HEAD = &
      "     SCALE FACTORS               STEP SIZE INFO"
   character(len=11), parameter :: ECHO_SCALE_LABEL(3) = [character(len=11) :: &
      "LENGTH (m)", &
      "LOAD (N)", &
      "TIME (S)"]
   character(len=11), parameter :: ECHO_STEP_LABEL(3) = [character(len=11) :: &
      "MINIMUM", &
      "MAXIMUM", &
      "INITIAL"]
   character(len=15), parameter :: ECHO_CONTROL_LABEL(2) = [character(len=15) :: &
      "DATA CONTROL", &
      "AUTO PLOTS"]
   character(len=14), parameter :: ECHO_SCALE_RIGHT_LABEL(2) = [character(len=14) :: &
      "NO OF STEPS", &
      "INT METHOD"]
   character(len=35), parameter :: ECHO_ERROR_LIMIT_LABEL(1) = [character(len=35) :: &
      "ERROR LIMIT"]

end module adore_output_layout
