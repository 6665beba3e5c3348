!> Run one deck from file to print file: the engine's top-level procedure (ADORE main).
!>
!> Flow: read the deck (text, then records: adore_deck_parser) → model → quasi-static start
!> (step 0) → for a ball bearing, the time integration of the deck's Rec 1 step count (or
!> the run's) with its time histories (adore_driver_ball_dynamics) → print and plot-data
!> file.  The print file is written under `<out>.part` and renamed to `<out>` when the run
!> ends: on an error before or at step 0 the partial file is deleted, so no half-written
!> output ever poses as a good one; a time integration that stops early keeps its print,
!> whose last line says "*** RUN INCOMPLETE ...", and returns the error.  No state outlives
!> the call.
module adore_driver_run
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_os, only: rename_file, delete_file
   use adore_deck_text, only: deck_text_t, read_deck_text
   use adore_deck_deck_type, only: deck_t
   use adore_deck_parser, only: parse_deck
   use adore_deck_traction_table, only: read_traction_table
   use adore_model_bearing, only: bearing_t, BALL_BEARING, ROLLER_BEARING
   use adore_model_from_deck, only: build_bearing
   use adore_output_banner, only: write_listing, write_banner
   use adore_output_echo_data, only: echo_data_t
   use adore_output_print_echo, only: write_echo
   use adore_start_ball_step0, only: ball_step0_t, solve_ball_step0, BALL_START_METHOD
   use adore_quasistatic_ball_start, only: start_method_from_name, start_method_title
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_output_echo_fill, only: fill_echo
   use adore_output_step_report, only: write_ball_step0, write_roller_step0
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_dynamics_integrator, only: integrator_t
   use adore_dynamics_ball_system, only: ball_system_t, start_ball_dynamics
   use adore_driver_ball_dynamics, only: run_ball_dynamics, run_progress, INCOMPLETE_MARK
   use adore_driver_run_history, only: run_history_t, new_ball_history, write_history_csv, history_file_name, &
                                       history_shape
   implicit none
   private

   public :: run_deck, run_plan, run_progress, STEPS_FROM_DECK

   !> `steps` value meaning "as many steps as the deck asks for" (Rec 1 n_steps).
   integer, parameter :: STEPS_FROM_DECK = -1

contains

   !> Time steps a run of bearing b integrates after step 0 for the run option `steps`
   !> (STEPS_FROM_DECK: Rec 1 n_steps; 0: none; n > 0: n): ball bearings only - a roller
   !> bearing's print ends after step 0 (its dynamics is a later issue, [Roller dynamics]).
   pure integer function dynamic_steps(b, steps)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: steps
      dynamic_steps = 0
      if (b%bearing_type /= BALL_BEARING) return
      if (steps == STEPS_FROM_DECK) then
         dynamic_steps = max(b%n_steps, 0)
      else
         dynamic_steps = max(steps, 0)
      end if
   end function dynamic_steps

   !> What a run of the deck at `deck_path` with option `steps` (as run_deck) will do:
   !> n_steps time steps after step 0, and the shape of its time history (row capacity,
   !> columns; 0, 0 without time steps), so that a caller can hold the history
   !> (adore_driver_run_history).  Reads and checks the deck and its model, nothing more.
   subroutine run_plan(deck_path, steps, n_steps, rows, cols, error)
      character(len=*), intent(in) :: deck_path
      integer, intent(in) :: steps
      integer, intent(out) :: n_steps, rows, cols
      type(error_type), allocatable, intent(out) :: error
      type(deck_text_t) :: text
      type(deck_t) :: deck
      type(bearing_t) :: bearing
      integer :: stride

      n_steps = 0
      rows = 0
      cols = 0
      call check_steps(steps, error)
      if (allocated(error)) return
      call read_deck_text(deck_path, text, error)
      if (allocated(error)) return
      call parse_deck(text, deck, error)
      if (allocated(error)) return
      call build_bearing(deck, bearing, error)
      if (allocated(error)) return
      n_steps = dynamic_steps(bearing, steps)
      if (n_steps > 0) call history_shape(n_steps, bearing%print_interval, bearing%n_lands, rows, cols, stride)
   end subroutine run_plan

   !> Input error unless steps is STEPS_FROM_DECK, 0 or positive.
   subroutine check_steps(steps, error)
      integer, intent(in) :: steps
      type(error_type), allocatable, intent(out) :: error
      if (steps < STEPS_FROM_DECK) then
         call input_error(error, "steps must be -1 (from the deck), 0 (quasi-static start "// &
                          "only) or a positive number of time steps")
      end if
   end subroutine check_steps

   !> Run the deck at `deck_path` and write the print file `out_path` and, when the run
   !> integrates time steps, its plot-data file beside it (history_file_name:
   !> `<out stem>.hist.csv`, docs/plots.md; a stale one of a run without time steps is
   !> deleted).
   !>
   !> steps: STEPS_FROM_DECK (-1) for the deck's own count (Rec 1 n_steps), 0 for the
   !> quasi-static start only, n > 0 to integrate n time steps after step 0 (ball decks:
   !> adore_driver_ball_dynamics; roller decks: step 0 only, `note` says so).
   !> A time integration that stops early (failed integration, non-finite state, progress
   !> asking to stop) keeps its print and plot-data file, both ending with the
   !> "RUN INCOMPLETE" line, and returns an engine error naming the print.
   subroutine run_deck(deck_path, out_path, steps, error, traction_table, ball_start, moment_equilibrium, &
                       integrated, history, note, progress, history_element, traction_2d, substeps)
      character(len=*), intent(in) :: deck_path, out_path
      integer, intent(in) :: steps
      type(error_type), allocatable, intent(out) :: error
      !> traction-slip table file (ADRX7, report 4.4.9) replacing the deck's RE/race traction
      !> model; absent or blank: the deck's model
      character(len=*), intent(in), optional :: traction_table
      !> ball start hypothesis by name (report 4.4.7; adore_quasistatic_ball_start's
      !> START_NAMES: dissipation, outer-race-control, inner-race-control); absent or
      !> blank: the default, minimum dissipation.  Ball decks only.
      character(len=*), intent(in), optional :: ball_start
      !> .true.: moment equilibrium of the inner race in the quasi-static start (its
      !> misalignments about y and z solved, ADORE kFS4 = kFS5 = 0) instead of the prescribed
      !> zero misalignment; absent: .false.  Ball decks only (docs/examples.md).
      logical, intent(in), optional :: moment_equilibrium
      !> time steps the run integrated and printed after step 0 (0: the print ends after
      !> step 0; on an early stop, the last accepted step)
      integer, intent(out), optional :: integrated
      !> the time history the run recorded (no rows without time steps)
      type(run_history_t), intent(out), optional :: history
      !> what the run does not do that a user may expect (thermal model off, cage contacts
      !> off, a roller deck's steps not integrated); blank when there is nothing to say
      character(len=:), allocatable, intent(out), optional :: note
      !> called after every accepted time step (adore_driver_ball_dynamics' run_progress)
      procedure(run_progress), optional :: progress
      !> rolling element of the time history's per-element columns (default 1)
      integer, intent(in), optional :: history_element
      !> .false.: the dynamics uses the one-dimensional race traction (slip along the rolling
      !> direction only, report eq 1), a developer option listed in the print; absent or
      !> .true.: the two-dimensional traction (eqs 2-3; ball_system_t%traction_2d, the default)
      logical, intent(in), optional :: traction_2d
      !> integrator steps per nominal step (report 4.4.5: output is neither processed nor saved
      !> over the substeps); absent: 1.  Input error below 1.
      integer, intent(in), optional :: substeps

      type(deck_text_t) :: text
      type(deck_t) :: deck
      type(bearing_t) :: bearing
      type(echo_data_t) :: echo
      type(ball_step0_t) :: ball0
      type(roller_step0_t) :: roller0
      type(mounted_geometry_t) :: geometry
      type(ball_system_t) :: sys
      type(integrator_t) :: it
      type(run_history_t) :: hist
      type(error_type), allocatable :: run_error
      real(wp), allocatable :: y(:)
      character(len=:), allocatable :: part_path, table_path, start_title, hist_path, incomplete, run_note
      character(len=256) :: iomsg
      integer :: unit, stat, start_method, n_dynamic, element
      logical :: ok, table, start_given, moments

      if (present(integrated)) integrated = 0
      if (present(note)) note = ""
      call check_steps(steps, error)
      if (allocated(error)) return
      if (present(substeps)) then
         if (substeps < 1) then
            call input_error(error, "substeps must be at least 1 (integrator steps per printed time step, "// &
                             "report 4.4.5)")
            return
         end if
      end if
      if (len_trim(out_path) == 0) then
         call input_error(error, "print file: no output path given")
         return
      end if

      call read_deck_text(deck_path, text, error)
      if (allocated(error)) return
      ! Records and values (same checks as read_deck; the text is not read twice).  A
      ! malformed deck stops here, before any print file exists.
      call parse_deck(text, deck, error)
      if (allocated(error)) return
      ! The model and the step-0 solution are computed before the print file is opened:
      ! a deck the physics cannot use fails without leaving any output behind.
      call build_bearing(deck, bearing, error)
      if (allocated(error)) return
      start_method = BALL_START_METHOD
      start_given = .false.
      if (present(ball_start)) start_given = len_trim(ball_start) > 0
      if (start_given) then
         if (bearing%bearing_type /= BALL_BEARING) then
            call input_error(error, trim(deck_path)//": the ball start option applies to ball "// &
                             "bearings; this deck is a cylindrical roller bearing (Rec 3.2)")
            return
         end if
         call start_method_from_name(ball_start, start_method, error)
         if (allocated(error)) return
      end if
      moments = .false.
      if (present(moment_equilibrium)) moments = moment_equilibrium
      if (moments .and. bearing%bearing_type /= BALL_BEARING) then
         call input_error(error, trim(deck_path)//": the moment equilibrium option applies to ball "// &
                          "bearings; this deck is a cylindrical roller bearing (Rec 3.2)")
         return
      end if
      table = .false.
      if (present(traction_table)) table = len_trim(traction_table) > 0
      if (table) then
         call read_traction_table(trim(traction_table), bearing%race_traction, error)
         if (allocated(error)) return
      end if
      call fill_echo(deck, bearing, echo, error)
      if (allocated(error)) return
      select case (bearing%bearing_type)
      case (BALL_BEARING)
         call solve_ball_step0(bearing, ball0, error, start_method, moments)
      case (ROLLER_BEARING)
         call solve_roller_step0(bearing, roller0, error)
      end select
      if (allocated(error)) return
      ! The time integration of a ball deck: its integrator (Rec 1 int_method, Rec 2.1) and
      ! history are set up before the print file is opened (bad settings leave no output).
      n_dynamic = dynamic_steps(bearing, steps)
      run_note = ""
      if (n_dynamic > 0) then
         element = 1
         if (present(history_element)) element = history_element
         call new_ball_history(hist, bearing, n_dynamic, element, error)
         if (allocated(error)) return
         geometry = mount_geometry(bearing, bearing%temperature)
         call start_ball_dynamics(bearing, geometry, ball0%start, ball0%cage, sys, it, y, error, two_d=traction_2d)
         if (allocated(error)) return
         run_note = "thermal model off: bulk temperatures fixed at the initial ones (Rec 2.7)"
         if (.not. sys%cage) run_note = run_note//"; cage contacts off (no pocket or guide-land forces)"
         if (sys%cage .and. sys%cage_spin_only) run_note = run_note//"; cage centred, turning about its axis only "// &
                                                         "(translation and tilt constrained, report 4.4.6)"
         if (sys%cage .and. .not. sys%land_film) run_note = run_note//"; guide-land film off (metallic land contact only)"
         if (sys%gyro_restraint) run_note = run_note//"; ball gyroscopic moments carried by the races without slip"
         if (sys%contact_damping > 0.0_wp) run_note = run_note//"; ball/race contact damping (stiffness-proportional)"
      else if (bearing%bearing_type == ROLLER_BEARING .and. &
               (steps > 0 .or. (steps == STEPS_FROM_DECK .and. bearing%n_steps > 0))) then
         run_note = "time integration of roller bearings is not implemented yet ([Roller dynamics]); "// &
                    "the print file ends after step 0 (the quasi-static start)"
      end if

      part_path = trim(out_path)//".part"
      open (newunit=unit, file=part_path, status="replace", action="write", &
            form="formatted", iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call input_error(error, trim(out_path)//": cannot write print file: "//trim(iomsg))
         return
      end if

      ! the run options that replace deck models: a traction table, a non-default start
      table_path = ""
      if (table) table_path = trim(traction_table)
      start_title = ""
      if (start_method /= BALL_START_METHOD) start_title = trim(start_method_title(start_method))
      call write_listing(unit, text, bearing%race_traction, table_path, start_title, moments, n_dynamic, sys%cage, &
                         sys%land_film, sys%traction_2d, sys%cage_spin_only, substeps, sys%contact_damping, &
                         sys%gyro_restraint)
      call write_banner(unit)
      call write_echo(unit, echo)
      ! Step 0, the quasi-static start; then the time steps of a ball deck.
      incomplete = ""
      select case (bearing%bearing_type)
      case (BALL_BEARING)
         call write_ball_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], bearing, ball0)
         if (n_dynamic > 0) then
            call run_ball_dynamics(unit, bearing, geometry, ball0, sys, it, y, n_dynamic, hist, incomplete, &
                                   run_error, progress, substeps)
         end if
      case (ROLLER_BEARING)
         call write_roller_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], bearing, roller0)
      end select

      close (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call delete_file(part_path)
         call engine_error(error, trim(out_path)//": cannot close print file: "//trim(iomsg))
         return
      end if
      ! the plot-data file first: a print is moved into place only with its history
      call history_file_name(trim(out_path), hist_path)
      if (n_dynamic > 0) then
         call write_history_csv(hist, hist_path, incomplete, error)
         if (allocated(error)) then
            call delete_file(part_path)
            return
         end if
      end if
      call rename_file(part_path, trim(out_path), ok)
      if (.not. ok) then
         call delete_file(part_path)
         if (n_dynamic > 0) call delete_file(hist_path)
         call engine_error(error, trim(out_path)//": cannot move the finished print file into place")
         return
      end if
      if (n_dynamic == 0) call delete_file(hist_path)    ! a stale file of an earlier run
      if (present(note)) note = run_note
      if (present(history)) history = hist
      if (present(integrated)) then
         integrated = n_dynamic
         if (hist%rows > 0) integrated = nint(hist%values(hist%rows, 2))
      end if
      if (allocated(run_error)) then
         call engine_error(error, run_error%message//"; kept: the print file "//trim(out_path)//" (its last line "// &
                           "says '"//INCOMPLETE_MARK//"') and its plot-data file "//hist_path)
         error%stat = run_error%stat
      end if
   end subroutine run_deck

end module adore_driver_run
