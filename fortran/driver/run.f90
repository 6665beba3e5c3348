!> Run one deck from file to print file: the engine's top-level procedure (ADORE main).
!>
!> Flow: read the deck (text, then records: adore_deck_parser) → (model, quasi-static start, dynamics: later issues) → print.
!> The print file is written under `<out>.part` and renamed to `<out>` only when the
!> run succeeded; on any error the partial file is deleted, so no half-written
!> output ever poses as a good one.  No state outlives the call.
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
   use adore_driver_ball_step0, only: ball_step0_t, solve_ball_step0, BALL_START_METHOD
   use adore_quasistatic_ball_start, only: start_method_from_name, start_method_title
   use adore_driver_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_output_echo_fill, only: fill_echo
   use adore_output_step_report, only: write_ball_step0, write_roller_step0
   use adore_geometry_mounted, only: mount_geometry
   use adore_driver_ball_dynamics, only: run_ball_dynamics
   implicit none
   private

   public :: run_deck, STEPS_FROM_DECK, TIME_STEPS_IMPLEMENTED

   !> `steps` value meaning "as many steps as the deck asks for".
   integer, parameter :: STEPS_FROM_DECK = -1

   !> Time steps a run with the deck's own count (STEPS_FROM_DECK) integrates: 0 while the
   !> dynamics issue (#20) is in progress - such a print ends after step 0, the quasi-static
   !> start.  Time integration is opt-in meanwhile: an explicit steps > 0 on a ball deck
   !> integrates that many steps (run_deck's `integrated`); roller decks end after step 0.
   integer, parameter :: TIME_STEPS_IMPLEMENTED = 0

contains

   !> Run the deck at `deck_path` and write the print file `out_path`.
   !>
   !> steps: STEPS_FROM_DECK (-1) for the deck's own count (while [Dynamics] is in
   !> progress: step 0 only, TIME_STEPS_IMPLEMENTED), 0 for the quasi-static start only,
   !> n > 0 to integrate n time steps after step 0 (ball decks, opt-in dynamics of issue #20:
   !> adore_driver_ball_dynamics; roller decks: step 0 only).
   subroutine run_deck(deck_path, out_path, steps, error, traction_table, ball_start, moment_equilibrium, &
                       integrated, traction_2d)
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
      !> time steps the run integrated and printed after step 0 (0: the print ends after step 0)
      integer, intent(out), optional :: integrated
      !> .false.: the dynamics uses the one-dimensional race traction (slip along the rolling
      !> direction only, report eq 1), a developer option listed in the print; absent or
      !> .true.: the two-dimensional traction (eqs 2-3; ball_system_t%traction_2d, the default)
      logical, intent(in), optional :: traction_2d

      type(deck_text_t) :: text
      type(deck_t) :: deck
      type(bearing_t) :: bearing
      type(echo_data_t) :: echo
      type(ball_step0_t) :: ball0
      type(roller_step0_t) :: roller0
      character(len=:), allocatable :: part_path, table_path, start_title
      character(len=256) :: iomsg
      integer :: unit, stat, start_method, n_dynamic
      logical :: ok, table, start_given, moments, two_d

      if (present(integrated)) integrated = 0
      if (steps < STEPS_FROM_DECK) then
         call input_error(error, "steps must be -1 (from the deck), 0 (quasi-static start "// &
                          "only) or a positive number of time steps")
         return
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
      two_d = .true.
      if (present(traction_2d)) two_d = traction_2d
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
      ! opt-in dynamics (issue #20 in progress): explicit time steps of a ball deck
      n_dynamic = 0
      if (steps > 0 .and. bearing%bearing_type == BALL_BEARING) n_dynamic = steps

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
      call write_listing(unit, text, bearing%race_traction, table_path, start_title, moments, n_dynamic, two_d)
      call write_banner(unit)
      call write_echo(unit, echo)
      ! Step 0, the quasi-static start; then the opt-in time steps of a ball deck.  Without
      ! them the print ends here.
      select case (bearing%bearing_type)
      case (BALL_BEARING)
         call write_ball_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], bearing, ball0)
         if (n_dynamic > 0) then
            call run_ball_dynamics(unit, bearing, mount_geometry(bearing, bearing%temperature), ball0, n_dynamic, &
                                   error, two_d)
            if (allocated(error)) then
               close (unit, iostat=stat)
               call delete_file(part_path)
               return
            end if
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
      call rename_file(part_path, trim(out_path), ok)
      if (.not. ok) then
         call delete_file(part_path)
         call engine_error(error, trim(out_path)//": cannot move the finished print file into place")
         return
      end if
      if (present(integrated)) integrated = n_dynamic
   end subroutine run_deck

end module adore_driver_run
