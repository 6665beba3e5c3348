!> The run options: what a run does beyond the deck, as one record (issue #24 item 2).
!>
!> One table (OPTION_TABLE) names every option once: its name (the Python keyword, the
!> `--name` of `adore` and `pyadore run` with '-' for '_'), its kind, default, limits or
!> choices, the value name of the command lines and its help line.  The f2py boundary
!> passes options as "name=value" lines (run_options_from_text), the standalone program
!> reads "--name value" (set_run_option), Python builds its click options and keyword
!> checks from the same table (adore_run_option_table, pyadore/options.py).  Adding an
!> option touches this file (table row, field, one case of set_run_option), the code that
!> uses it, and its test.  No module state: the table is a constant.
module adore_model_run_options
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   use adore_core_strings, only: itoa, replaced
   implicit none
   private

   public :: run_options_t, option_spec_t, OPTION_TABLE, N_OPTIONS, STEPS_FROM_DECK
   public :: set_run_option, run_options_from_text, option_index
   public :: OPTION_INT, OPTION_TEXT, OPTION_FLAG, OPTION_FLAG_OFF, OPTION_CHOICE, OPTION_REAL

   !> `steps` value meaning "as many steps as the deck asks for" (Rec 1 n_steps).
   integer, parameter :: STEPS_FROM_DECK = -1

   !> Option kinds: an integer >= its minimum; a text (a file name); a flag that sets a
   !> logical .true. (`--name`); a flag that sets its logical .false. (its `flag` spelling,
   !> e.g. --traction-1d for traction_2d); one of the listed choices; a finite real >= its
   !> minimum.
   integer, parameter :: OPTION_INT = 1, OPTION_TEXT = 2, OPTION_FLAG = 3, OPTION_FLAG_OFF = 4, OPTION_CHOICE = 5, &
                         OPTION_REAL = 6

   !> What a run does beyond the deck.  Defaults: the deck's own run.
   type :: run_options_t
      !> time steps after step 0: STEPS_FROM_DECK (Rec 1 n_steps), 0 (quasi-static start
      !> only) or n > 0
      integer :: steps = STEPS_FROM_DECK
      !> integrator steps per printed time step (report 4.4.5)
      integer :: substeps = 1
      !> rolling element of the time history's per-element columns
      integer :: history_element = 1
      !> every history_stride-th time step is a row of the time history and of the element
      !> record (printed steps and the last always are); 0: automatic (every step up to
      !> adore_output_run_history's HISTORY_ROWS steps)
      integer :: history_stride = 0
      !> traction-slip table file (ADRX7, report 4.4.9) replacing the deck's RE/race model;
      !> blank: the deck's model
      character(len=4096) :: traction_table = ""
      !> ball start hypothesis (report 4.4.7; adore_quasistatic_ball_start's START_NAMES);
      !> blank: minimum dissipation
      character(len=32) :: ball_start = ""
      !> moment equilibrium of the inner race in the quasi-static start (ADORE kFS4 = kFS5 = 0)
      logical :: moment_equilibrium = .false.
      !> two-dimensional race traction (report eqs 2-3); .false.: the 1-D developer option
      logical :: traction_2d = .true.
      !> the race contacts' EHD rolling resistance in the time integration (docs/tribology.md,
      !> "Rolling resistance"; not in ADORE 5.0)
      logical :: rolling_resistance = .false.
      !> film parameter Lambda_b: traction model 3's race contacts whose film parameter
      !> Lambda = h / sigma (thermally reduced central film over the composite RMS roughness)
      !> is below it take the deck's traction curve - boundary lubrication (docs/tribology.md,
      !> "Thin films"); default 1 (Tallian's boundary of boundary lubrication); 0: off (films
      !> down to 1 nm are sheared as EHD films)
      real(wp) :: boundary_lambda = 1.0_wp
      !> film parameter Lambda_f of a full EHD film: between boundary_lambda and it (mixed
      !> lubrication) a model-3 race contact's traction is f EHD + (1 - f) the deck's curve,
      !> f the fluid fraction rising smoothly from 0 to 1 (docs/tribology.md, "Mixed films");
      !> default 2 (Tallian's classical bound 3 changes Appendix C's print: a contact of its
      !> run passes through film parameters 2.9-3); at or below boundary_lambda (0 included):
      !> no blend, the step at boundary_lambda
      real(wp) :: full_film_lambda = 2.0_wp
      !> boundary friction coefficient mu_b: > 0 replaces the deck's traction curve of an EHD
      !> (model 3) ball deck by Coulomb friction mu_b (1 - exp(-|u| / boundary_slip)) where the
      !> curve acts - boundary-lubricated contacts (film parameter below boundary_lambda), the
      !> dry share of mixed films, contacts without a film (docs/tribology.md, "Boundary
      !> friction"; not in ADORE 5.0); 0 (default): the deck's curve
      real(wp) :: boundary_friction = 0.0_wp
      !> slip speed u_b (m/s) over which the boundary friction rises to its coefficient
      real(wp) :: boundary_slip = 1.0e-2_wp
      !> elastic shear modulus G (Pa) of traction model 3's EHD film: > 0 makes it a Maxwell
      !> film (Johnson & Tevaarwerk 1977; docs/tribology.md, "The film's elasticity"; not in
      !> ADORE 5.0); 0 (default): the viscous film
      real(wp) :: film_shear_modulus = 0.0_wp
      !> limiting shear stress coefficient Lambda (-, 0 <= Lambda < 1) of traction model 3's EHD
      !> film: > 0 caps its local shear stress smoothly at Lambda p (Bair & Winer 1979;
      !> docs/tribology.md, "Limiting shear stress"; not in ADORE 5.0); 0 (default): no cap
      real(wp) :: limiting_shear = 0.0_wp
      !> the integrator's power-balance control (integrator_settings_t%balance_tolerance; issue
      !> #28, docs/integrator.md, "Power-balance control"): a time step is also rejected when its
      !> energy change misses the integral of the net power by more than this fraction of the
      !> step's energy flow (0 <= x < 1; ball bearings); 0 (default): off
      real(wp) :: balance_tolerance = 3.0e-3_wp
      !> the coordinates of the balls in the integrated state: "orbit" (the report's eq 54:
      !> axial, radial, azimuth and their rates; issue #30) or "cartesian" (inertial position
      !> and velocity, the runs before issue #30)
      character(len=16) :: ball_frame = "orbit"
      !> the integration method: "deck" (Rec 1 INT METHOD: 5 is the IMEX method ARK4(3)6L[2]SA
      !> for ball decks, ROS34PW2 from the first step when a ball's spin relaxes within the
      !> minimum step; docs/integrator.md), "ark4", "ros34pw2", "dp5" (Dormand-Prince 5(4)) or
      !> "bs3" (Bogacki-Shampine 3(2))
      character(len=16) :: integrator = "deck"
      !> simulated time of the time integration (s): the run ends exactly there, its last
      !> step printed, instead of after a step count; 0: the step count
      real(wp) :: duration = 0.0_wp
      !> the same in shaft (inner race) revolutions; 0: none
      real(wp) :: revolutions = 0.0_wp
      !> the cage's degrees of freedom (report 4.4.6; docs/cage.md, "The cage's degrees of
      !> freedom"): "deck" (the default: the deck's own constraints, Rec 3.3 all zero or
      !> Appendix D's pattern constrain nothing of the cage, a free cage), "centred"
      !> (translation and tilt constrained, turning about its axis) or "free" (all six
      !> integrated, the guide lands' film on)
      character(len=16) :: cage = "deck"
      !> the equations of a free cage's mass centre in its whirl plane (docs/cage.md, "The
      !> cage's whirl frame"): "adore" (ADORE's, as report 4.4.4 and its prints show them: the
      !> whirl radius and angle integrated as r'' = F_r/m, r psi'' = F_t/m, so a cage free of
      !> interactions keeps its whirl circle) or "inertial" (Newton's: the centripetal and
      !> Coriolis accelerations of the whirl included)
      character(len=16) :: cage_whirl = "adore"
      !> the lubricant layer on the cage's guide lands (m): the land film exists where the local
      !> gap is below it (docs/cage.md, "The guide-land film where the report has none");
      !> default 10 um, pyadore's choice (the report prints no land force at gaps of 0.12 mm
      !> and more); 0: dry lands (metallic contact only); a value above the clearance: flooded
      real(wp) :: land_oil = 1.0e-4_wp
      !> the thermal model (docs/thermal.md, "The wiring"): "off" (the default: bulk
      !> temperatures fixed at Rec 2.7's; with the boundaries the report states, the model
      !> moves Appendix C's final step further from the report, docs/thermal.md), "deck" (on,
      !> geometry updated, when Rec 2.5 field 4, the heat averaging interval, is positive),
      !> "temperatures" (updated, geometry held: report 5.3's first set) or "geometry"
      !> (temperatures and geometry updated: its second set)
      character(len=16) :: thermal = "off"
      !> with the thermal model on, the race contacts' lubricant (film, EHD traction) at the
      !> computed bulk temperatures (report 7 rec. 1: not in ADORE 5.0, whose traction stays at
      !> the initial temperatures, report 5.3; docs/thermal.md, "Traction and the temperatures")
      logical :: thermal_traction = .false.
      !> the thermal model's temperature field (docs/thermal.md): "march" (the report's 2.10
      !> steps 3-8, ADORE 5.0's) or "network" (a conduction/convection network)
      character(len=16) :: thermal_field = "march"
      !> film coefficient (W/(m**2 K)) from the housing's outer surface to the reference
      !> temperature; 0 (default): the surface at the reference (report 2.10's text)
      real(wp) :: housing_htc = 0.0_wp
      !> with the thermal model on, thermal transients with lumped heat capacities (report 7
      !> rec. 4; not ADORE 5.0, whose field has no thermal inertia; docs/thermal.md, "Thermal
      !> transients"): each body's bulk temperature relaxes toward the steady field
      logical :: thermal_transient = .false.
      !> threads of the time integration's derivative (the rolling elements' contacts shared
      !> by an OpenMP team; the results the same bit for bit on any number; docs/performance.md,
      !> "Threads"); 0: automatic (adore_core_threads' run_threads: OMP_NUM_THREADS, else the
      !> processors, at most 4)
      integer :: threads = 0
   end type run_options_t

   !> One row of the option table.
   type :: option_spec_t
      character(len=24) :: name = ""       !< keyword (snake case)
      integer :: kind = OPTION_INT
      character(len=24) :: default = ""    !< default as text ("" for none)
      integer :: minimum = 0               !< OPTION_INT: smallest value
      character(len=24) :: flag = ""       !< OPTION_FLAG_OFF: the flag that sets .false.
      character(len=8) :: metavar = ""     !< value name on the command lines
      character(len=64) :: choices = ""    !< OPTION_CHOICE: the values, comma-separated
      character(len=160) :: help = ""      !< one line
   end type option_spec_t

   integer, parameter :: N_OPTIONS = 29

   !> The run options (keep the order of run_options_t).
   type(option_spec_t), parameter :: OPTION_TABLE(N_OPTIONS) = [ &
      option_spec_t("steps", OPTION_INT, "-1", -1, "", "N", "", &
                    "time steps after step 0: -1 as the deck says (Rec 1), 0 the quasi-static start only"), &
      option_spec_t("substeps", OPTION_INT, "1", 1, "", "N", "", &
                    "integrator steps in each printed time step (report 4.4.5)"), &
      option_spec_t("history_element", OPTION_INT, "1", 1, "", "N", "", &
                    "rolling element whose race contacts and pocket force the time history records"), &
      option_spec_t("history_stride", OPTION_INT, "0", 0, "", "N", "", &
                    "record every N-th time step in the time histories and the element results (printed "// &
                    "and last steps always); 0: every step up to 10000 steps"), &
      option_spec_t("traction_table", OPTION_TEXT, "", 0, "", "FILE", "", &
                    "traction-slip table (slip m/s, coefficient per line; ADRX7) replacing the deck's "// &
                    "RE/race traction model"), &
      option_spec_t("ball_start", OPTION_CHOICE, "dissipation", 0, "", "NAME", &
                    "dissipation,outer-race-control,inner-race-control", &
                    "initial ball angular velocity (report 4.4.7): minimum contact dissipation or race "// &
                    "control at one race (ball decks)"), &
      option_spec_t("moment_equilibrium", OPTION_FLAG, "false", 0, "", "", "", &
                    "solve the inner race's misalignment for moment equilibrium (ADORE kFS4 = kFS5 = 0) "// &
                    "instead of prescribing it zero (ball decks)"), &
      option_spec_t("traction_2d", OPTION_FLAG_OFF, "true", 0, "traction_1d", "", "", &
                    "developer option: one-dimensional race traction (slip along the rolling direction "// &
                    "only, report eq 1) instead of the two-dimensional default"), &
      option_spec_t("rolling_resistance", OPTION_FLAG, "false", 0, "", "", "", &
                    "the race contacts' EHD rolling resistance (Houpert) in the time steps, not in "// &
                    "ADORE 5.0 (ball decks)"), &
      option_spec_t("boundary_lambda", OPTION_REAL, "1", 0, "", "L", "", &
                    "film parameter h/sigma below which an EHD (model 3) race contact takes the deck's "// &
                    "traction curve (boundary lubrication); 0: off (1 nm films sheared)"), &
      option_spec_t("full_film_lambda", OPTION_REAL, "2", 0, "", "L", "", &
                    "film parameter h/sigma of a full EHD film (model 3): below it, down to boundary_lambda, "// &
                    "traction blends EHD and the deck's curve; <= boundary_lambda: no blend"), &
      option_spec_t("boundary_friction", OPTION_REAL, "0", 0, "", "MU", "", &
                    "Coulomb friction of model-3 race contacts below boundary_lambda and of the dry share "// &
                    "of mixed films, instead of the deck's curve (not ADORE 5.0); 0: the curve"), &
      option_spec_t("boundary_slip", OPTION_REAL, "0.01", 0, "", "M/S", "", &
                    "slip speed (m/s, > 0) over which boundary_friction rises to its coefficient: "// &
                    "mu (1 - exp(-|u| / boundary_slip))"), &
      option_spec_t("film_shear_modulus", OPTION_REAL, "0", 0, "", "PA", "", &
                    "elastic shear modulus G (Pa) of the EHD (model 3) film: a Maxwell film (Johnson & "// &
                    "Tevaarwerk), not in ADORE 5.0; 0: the viscous film"), &
      option_spec_t("limiting_shear", OPTION_REAL, "0", 0, "", "LAMBDA", "", &
                    "limiting shear stress Lambda p of the EHD (model 3) film, tau_L tanh(tau / tau_L) "// &
                    "(Bair & Winer), 0 <= Lambda < 1; not in ADORE 5.0; 0: no cap"), &
      option_spec_t("balance_tolerance", OPTION_REAL, "3e-3", 0, "", "FRACTION", "", &
                    "reject a time step whose energy change misses its integrated net power by more than this "// &
                    "fraction of its energy flow (0 <= x < 1; ball decks); 0: off"), &
      option_spec_t("duration", OPTION_REAL, "0", 0, "", "SECONDS", "", &
                    "simulated time to integrate (s): the run ends exactly there, its last step printed "// &
                    "(instead of a step count)"), &
      option_spec_t("revolutions", OPTION_REAL, "0", 0, "", "N", "", &
                    "shaft (inner race) revolutions to integrate: the run ends exactly there, its last step "// &
                    "printed (instead of a step count)"), &
      option_spec_t("ball_frame", OPTION_CHOICE, "orbit", 0, "", "NAME", "orbit,cartesian", &
                    "coordinates of the balls in the integrated state: orbit-following (report eq 54: axial, "// &
                    "radial, azimuth) or inertial cartesian"), &
      option_spec_t("integrator", OPTION_CHOICE, "deck", 0, "", "NAME", "deck,ark4,ros34pw2,dp5,bs3", &
                    "integration method: the deck's INT METHOD (5: ark4; ros34pw2 if a ball's spin is stiff), "// &
                    "IMEX ARK4(3)6L[2]SA, Rosenbrock-W ROS34PW2, DOPRI 5(4) or BS 3(2)"), &
      option_spec_t("cage", OPTION_CHOICE, "deck", 0, "", "NAME", "deck,centred,free", &
                    "cage DOFs (report 4.4.6): as the deck's Rec 3.3 says (all zeros: free), centred (translation "// &
                    "and tilt constrained) or free (all six, land films on)"), &
      option_spec_t("cage_whirl", OPTION_CHOICE, "adore", 0, "", "NAME", "adore,inertial", &
                    "a free cage's mass centre: ADORE's whirl coordinates (report 4.4.4: a cage free of "// &
                    "interactions keeps its whirl circle) or Newton's inertial equations"), &
      option_spec_t("land_oil", OPTION_REAL, "0.0001", 0, "", "M", "", &
                    "lubricant layer on the cage's guide lands (m): the land film acts where the gap is below "// &
                    "it (starved land; 0: dry, metallic contact only; 1: flooded)"), &
      option_spec_t("thermal", OPTION_CHOICE, "off", 0, "", "MODE", "off,deck,temperatures,geometry", &
                    "thermal model (report 2.10, 5.3): off, the deck's (geometry updated when Rec 2.5 gives an "// &
                    "averaging interval), temperatures only, or temperatures and geometry"), &
      option_spec_t("thermal_traction", OPTION_FLAG, "false", 0, "", "", "", &
                    "thermal model on: the race contacts' lubricant follows the computed bulk temperatures "// &
                    "(report 7 rec. 1; not ADORE 5.0: its traction stays at the initial ones)"), &
      option_spec_t("thermal_field", OPTION_CHOICE, "march", 0, "", "NAME", "march,network", &
                    "thermal model's temperature field: the report's march (2.10 steps 3-8, ADORE 5.0) or a "// &
                    "conduction/convection network"), &
      option_spec_t("housing_htc", OPTION_REAL, "0", 0, "", "W/M2K", "", &
                    "thermal model: film coefficient from the housing's outer surface to the reference "// &
                    "temperature (0: the surface at it, report 2.10)"), &
      option_spec_t("thermal_transient", OPTION_FLAG, "false", 0, "", "", "", &
                    "thermal model on: transients with lumped heat capacities, the bodies relaxing toward the "// &
                    "steady field (report 7 rec. 4; not ADORE 5.0)"), &
      option_spec_t("threads", OPTION_INT, "0", 0, "", "N", "", &
                    "threads of the time steps' derivative (OpenMP; same results on any number); 0: "// &
                    "OMP_NUM_THREADS, else the processors, at most 4") &
      ]

contains

   !> Position of option `name` in OPTION_TABLE (its name, or the flag of an OPTION_FLAG_OFF;
   !> '-' and '_' alike); 0 when there is none.
   pure integer function option_index(name) result(k)
      character(len=*), intent(in) :: name
      character(len=len(name)) :: key
      key = replaced(name, "-", "_")
      do k = 1, N_OPTIONS
         if (trim(key) == trim(OPTION_TABLE(k)%name)) return
         if (len_trim(OPTION_TABLE(k)%flag) > 0 .and. trim(key) == trim(OPTION_TABLE(k)%flag)) return
      end do
      k = 0
   end function option_index

   !> Set option `name` (OPTION_TABLE) of opts from its text `value` ("true"/"false" or
   !> "1"/"0" for flags; a flag's own off-spelling, e.g. traction_1d, takes "true" to mean
   !> off).  Input error naming the option for an unknown name or a bad value.
   subroutine set_run_option(opts, name, value, error)
      type(run_options_t), intent(inout) :: opts
      character(len=*), intent(in) :: name, value
      type(error_type), allocatable, intent(out) :: error
      type(option_spec_t) :: spec
      character(len=:), allocatable :: names, flag_name
      real(wp) :: x
      integer :: k, n, stat
      logical :: flag, ok

      k = option_index(name)
      if (k == 0) then
         call option_names(names)
         call input_error(error, "run option '"//trim(name)//"': unknown (the options: "//names//")")
         return
      end if
      spec = OPTION_TABLE(k)
      flag_name = replaced(trim(spec%name), "_", "-")
      n = 0
      x = 0.0_wp
      flag = .false.
      select case (spec%kind)
      case (OPTION_INT)
         read (value, *, iostat=stat) n
         if (stat /= 0 .or. len_trim(value) == 0 .or. verify(trim(adjustl(value)), "+-0123456789") /= 0) then
            call input_error(error, trim(spec%name)//" (--"//flag_name//"): expected an integer, got '"// &
                             trim(value)//"'")
            return
         end if
         if (n < spec%minimum) then
            call input_error(error, trim(spec%name)//" (--"//flag_name//"): "//itoa(n)//" is below its minimum "// &
                             itoa(spec%minimum)//" ("//trim(spec%help)//")")
            return
         end if
      case (OPTION_REAL)
         read (value, *, iostat=stat) x
         if (stat /= 0 .or. len_trim(value) == 0 .or. verify(trim(adjustl(value)), "+-.0123456789eEdD") /= 0) then
            call input_error(error, trim(spec%name)//" (--"//flag_name//"): expected a number, got '"// &
                             trim(value)//"'")
            return
         end if
         if (.not. (x >= real(spec%minimum, wp) .and. x <= huge(x))) then
            call input_error(error, trim(spec%name)//" (--"//flag_name//"): '"//trim(value)//"' is not a finite "// &
                             "number >= "//itoa(spec%minimum)//" ("//trim(spec%help)//")")
            return
         end if
      case (OPTION_FLAG, OPTION_FLAG_OFF)
         select case (trim(adjustl(value)))
         case ("true", "True", "1", "yes", "on")
            flag = .true.
         case ("false", "False", "0", "no", "off")
            flag = .false.
         case default
            call input_error(error, trim(name)//": expected true or false, got '"//trim(value)//"'")
            return
         end select
         ! the off-spelling of a flag (traction_1d = true sets traction_2d = .false.)
         if (trim(name) /= trim(spec%name) .and. trim(replaced(name, "-", "_")) /= trim(spec%name)) flag = .not. flag
      case (OPTION_CHOICE)
         ok = len_trim(value) == 0
         if (.not. ok) ok = index(","//trim(spec%choices)//",", ","//trim(adjustl(value))//",") > 0
         if (.not. ok) then
            call spaced_list(spec%choices, names)
            call input_error(error, replaced(trim(spec%name), "_", " ")//": expected one of "//names//", got '"//trim(value)//"'")
            return
         end if
      end select
      select case (spec%name)
      case ("steps")
         opts%steps = n
      case ("substeps")
         opts%substeps = n
      case ("history_element")
         opts%history_element = n
      case ("history_stride")
         opts%history_stride = n
      case ("threads")
         opts%threads = n
      case ("traction_table")
         if (len_trim(value) > len(opts%traction_table)) then
            call input_error(error, "run option traction_table: the file name is longer than "// &
                             itoa(len(opts%traction_table))//" characters")
            return
         end if
         opts%traction_table = value
      case ("ball_start")
         opts%ball_start = trim(adjustl(value))
      case ("moment_equilibrium")
         opts%moment_equilibrium = flag
      case ("traction_2d")
         opts%traction_2d = flag
      case ("rolling_resistance")
         opts%rolling_resistance = flag
      case ("thermal_traction")
         opts%thermal_traction = flag
      case ("thermal_field")
         opts%thermal_field = "march"
         if (len_trim(value) > 0) opts%thermal_field = trim(adjustl(value))
      case ("housing_htc")
         opts%housing_htc = x
      case ("land_oil")
         opts%land_oil = x
      case ("thermal_transient")
         opts%thermal_transient = flag
      case ("boundary_lambda")
         opts%boundary_lambda = x
      case ("full_film_lambda")
         opts%full_film_lambda = x
      case ("boundary_friction")
         opts%boundary_friction = x
      case ("boundary_slip")
         opts%boundary_slip = x
      case ("film_shear_modulus")
         opts%film_shear_modulus = x
      case ("limiting_shear")
         opts%limiting_shear = x
      case ("balance_tolerance")
         opts%balance_tolerance = x
      case ("duration")
         opts%duration = x
      case ("revolutions")
         opts%revolutions = x
      case ("ball_frame")
         opts%ball_frame = "orbit"
         if (len_trim(value) > 0) opts%ball_frame = trim(adjustl(value))
      case ("integrator")
         opts%integrator = "deck"
         if (len_trim(value) > 0) opts%integrator = trim(adjustl(value))
      case ("cage")
         opts%cage = "deck"
         if (len_trim(value) > 0) opts%cage = trim(adjustl(value))
      case ("cage_whirl")
         opts%cage_whirl = "adore"
         if (len_trim(value) > 0) opts%cage_whirl = trim(adjustl(value))
      case ("thermal")
         opts%thermal = "off"
         if (len_trim(value) > 0) opts%thermal = trim(adjustl(value))
      end select
   end subroutine set_run_option

   !> Options from text: one "name=value" per line (LF-separated; blank lines ignored), each
   !> through set_run_option; the defaults for the rest.  Every bad line is reported in one
   !> input error.
   subroutine run_options_from_text(text, opts, error)
      character(len=*), intent(in) :: text
      type(run_options_t), intent(out) :: opts
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: line_error
      character(len=:), allocatable :: messages
      integer :: start, finish, eq

      messages = ""
      start = 1
      do while (start <= len(text))
         finish = index(text(start:), new_line("a"))
         if (finish == 0) then
            finish = len(text)
         else
            finish = start + finish - 2
         end if
         if (len_trim(text(start:finish)) > 0) then
            eq = index(text(start:finish), "=")
            if (eq == 0) then
               messages = messages//"; run option '"//trim(text(start:finish))//"': expected name=value"
            else
               call set_run_option(opts, trim(adjustl(text(start:start + eq - 2))), text(start + eq:finish), line_error)
               if (allocated(line_error)) messages = messages//"; "//line_error%message
            end if
         end if
         start = finish + 2
      end do
      if (len(messages) > 0) call input_error(error, messages(3:))
   end subroutine run_options_from_text

   !> The option names, comma-separated (a subroutine: no deferred-length function results
   !> in the engine, adore_core_strings).
   subroutine option_names(names)
      character(len=:), allocatable, intent(out) :: names
      integer :: k
      names = trim(OPTION_TABLE(1)%name)
      do k = 2, N_OPTIONS
         names = names//", "//trim(OPTION_TABLE(k)%name)
      end do
   end subroutine option_names



   !> A comma-separated list with ', ' between its items.
   subroutine spaced_list(list, text)
      character(len=*), intent(in) :: list
      character(len=:), allocatable, intent(out) :: text
      integer :: i
      text = ""
      do i = 1, len_trim(list)
         if (list(i:i) == ",") then
            text = text//", "
         else
            text = text//list(i:i)
         end if
      end do
   end subroutine spaced_list

end module adore_model_run_options
