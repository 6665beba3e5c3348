!> Run one deck from file to print file: the engine's top-level procedure (ADORE main).
!>
!> Flow: read the deck (text, then records: adore_deck_parser) → model → the bearing system
!> of its kind (adore_bearings_select, picked once) → quasi-static start (step 0) → when the
!> kind integrates time steps, the time loop (adore_driver_time_loop) with its time
!> histories → print and plot-data file.  The print file is written under `<out>.part` and
!> renamed to `<out>` when the run ends: on an error before or at step 0 the partial file
!> is deleted, so no half-written output ever poses as a good one; a time integration that
!> stops early keeps its print, whose last line says "*** RUN INCOMPLETE ...", and returns
!> the error.  What the run does beyond the deck is one record, run_options_t
!> (adore_model_run_options).  No state outlives the call.
module adore_driver_run
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_os, only: rename_file, delete_file
   use adore_core_strings, only: itoa
   use adore_core_threads, only: run_threads
   use adore_deck_text, only: deck_text_t, read_deck_text
   use adore_deck_deck_type, only: deck_t
   use adore_deck_parser, only: parse_deck
   use adore_deck_traction_table, only: read_traction_table
   use adore_tribology_traction_law, only: boundary_law
   use adore_forces_race_contact, only: TRACTION_EHD
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BALL_BEARING
   use adore_model_scales, only: scale_factors
   use adore_model_from_deck, only: build_bearing
   use adore_model_checks, only: check_warnings
   use adore_model_run_options, only: run_options_t, STEPS_FROM_DECK
   use adore_life_lundberg_palmgren, only: life_params_t
   use adore_output_banner, only: write_listing, write_banner
   use adore_output_echo_data, only: echo_data_t
   use adore_output_print_echo, only: write_echo
   use adore_output_echo_fill, only: fill_echo
   use adore_output_run_history, only: run_history_t, write_history_csv, history_file_name, write_element_file, &
                                       element_file_name
   use adore_quasistatic_ball_start, only: start_method_from_name, start_method_title, MIN_DISSIPATION
   use adore_dynamics_integrator, only: integrator_t, integrator_stats_t, ADORE_FORCED_ERR_CAP
   use adore_bearings_system, only: bearing_system_t
   use adore_bearings_select, only: new_bearing_system
   use adore_driver_time_loop, only: run_time_loop, run_progress, INCOMPLETE_MARK
   implicit none
   private

   public :: run_deck, run_progress, run_options_t, STEPS_FROM_DECK

contains

   !> Run the deck at `deck_path` with the run options opts and write the print file
   !> `out_path` and, when the run integrates time steps, its plot-data file beside it
   !> (history_file_name: `<out stem>.hist.csv`, docs/plots.md; a stale one of a run without
   !> time steps is deleted).  A time integration that stops early (failed integration,
   !> non-finite state, progress asking to stop) keeps its print and plot-data file, both
   !> ending with the "RUN INCOMPLETE" line, and returns an engine error naming the print.
   subroutine run_deck(deck_path, out_path, opts, error, integrated, history, note, progress)
      character(len=*), intent(in) :: deck_path, out_path
      type(run_options_t), intent(in) :: opts
      type(error_type), allocatable, intent(out) :: error
      !> time steps the run integrated and printed after step 0 (0: the print ends after
      !> step 0; on an early stop, the last accepted step)
      integer, intent(out), optional :: integrated
      !> the time history the run recorded (no rows without time steps)
      type(run_history_t), intent(out), optional :: history
      !> what the run does not do that a user may expect (thermal model off, a roller
      !> deck's steps not integrated) and, after a completed time integration, its balances
      !> over the last half of the run (adore_driver_time_loop); blank when there is nothing
      !> to say
      character(len=:), allocatable, intent(out), optional :: note
      !> called after every accepted time step (adore_driver_time_loop's run_progress)
      procedure(run_progress), optional :: progress

      type(deck_text_t) :: text
      type(deck_t) :: deck
      type(bearing_t) :: bearing
      type(life_params_t) :: roughness
      type(echo_data_t) :: echo
      class(bearing_system_t), allocatable :: sys
      type(integrator_t) :: it
      type(run_history_t) :: hist
      type(error_type), allocatable :: run_error
      real(wp), allocatable :: y(:)
      character(len=:), allocatable :: forced_text
      character(len=:), allocatable :: part_path, table_path, start_title, hist_path, incomplete, run_note, listing, &
                                       element_path
      character(len=:), allocatable :: deck_warnings, balance
      character(len=256) :: iomsg
      real(wp) :: duration, t_end, scales(3)
      integer :: unit, stat, start_method, n_dynamic
      logical :: ok, table, to_time

      if (present(integrated)) integrated = 0
      if (present(note)) note = ""
      if (opts%steps < STEPS_FROM_DECK) then
         call input_error(error, "steps must be -1 (from the deck), 0 (quasi-static start "// &
                          "only) or a positive number of time steps")
         return
      end if
      if (opts%substeps < 1) then
         call input_error(error, "substeps must be at least 1 (integrator steps per printed time step, "// &
                          "report 4.4.5)")
         return
      end if
      if (len_trim(out_path) == 0) then
         call input_error(error, "print file: no output path given")
         return
      end if
      if (opts%duration > 0.0_wp .and. opts%revolutions > 0.0_wp) then
         call input_error(error, "run options duration and revolutions: give one of them (both set the end of "// &
                          "the time integration)")
         return
      end if
      if ((opts%duration > 0.0_wp .or. opts%revolutions > 0.0_wp) .and. opts%steps /= STEPS_FROM_DECK) then
         call input_error(error, "run options steps and duration/revolutions: give one of them (a run ends after "// &
                          "a step count or at a simulated time)")
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
      call check_warnings(deck, deck_warnings)
      ! thin films on the deck's curve (run option; sigma: the composite RMS roughness of the
      ! film parameter the print and the life model use, docs/tribology.md "Thin films")
      bearing%boundary_film = opts%boundary_lambda*roughness%sigma_rms
      ! mixed films between it and the full film blend the two tractions ("Mixed films")
      bearing%full_film = opts%full_film_lambda*roughness%sigma_rms
      ! the EHD film's elasticity (run option; docs/tribology.md, "The film's elasticity")
      bearing%film_shear_modulus = opts%film_shear_modulus
      ! the EHD film's limiting shear stress (run option; docs/tribology.md, "Limiting shear stress")
      if (.not. (opts%limiting_shear >= 0.0_wp .and. opts%limiting_shear < 1.0_wp)) then
         call input_error(error, "limiting_shear (--limiting-shear): must be >= 0 and < 1 (the limiting shear "// &
                          "stress over the local pressure, 0.05-0.1 for oils; 0: off)")
         return
      end if
      bearing%limiting_shear = opts%limiting_shear
      if (.not. (opts%balance_tolerance >= 0.0_wp .and. opts%balance_tolerance < 1.0_wp)) then
         call input_error(error, "balance_tolerance (--balance-tolerance): must be >= 0 and < 1 (the largest "// &
                          "energy defect of a time step over its energy flow, e.g. 1e-3; 0: off)")
         return
      end if
      ! the guide lands' lubricant layer (run option land_oil; docs/cage.md, "The guide-land
      ! film where the report has none")
      bearing%land_oil_layer = opts%land_oil
      table = len_trim(opts%traction_table) > 0
      if (table) then
         call read_traction_table(trim(opts%traction_table), bearing%race_traction, error)
         if (allocated(error)) return
      end if
      ! boundary friction (run option): Coulomb friction where an EHD deck's contacts take the
      ! deck's curve (boundary and mixed films; docs/tribology.md, "Boundary friction")
      if (opts%boundary_friction > 0.0_wp) then
         if (table .or. bearing%bearing_type /= BALL_BEARING .or. bearing%traction_model /= TRACTION_EHD .or. &
             bearing%lubricant_code == 0) then
            call input_error(error, trim(deck_path)//": boundary_friction needs a ball deck with the EHD "// &
                             "traction model (Rec 10.0 traction_model 3, a lubricant) and no traction table")
            return
         end if
         if (.not. opts%boundary_slip > 0.0_wp) then
            call input_error(error, "boundary_slip (--boundary-slip): must be > 0 m/s")
            return
         end if
         bearing%race_traction = boundary_law(opts%boundary_friction, opts%boundary_slip)
      end if
      call fill_echo(deck, bearing, echo, error)
      if (allocated(error)) return
      call new_bearing_system(bearing, opts, sys, error)
      if (allocated(error)) return
      call sys%solve_start(error)
      if (allocated(error)) then
         ! name the deck (a sweep runs many)
         if (index(error%message, trim(deck_path)) == 0) &
            error%message = trim(deck_path)//": "//error%message
         return
      end if
      ! the echo's scales as the time integration takes them: the load scale is the start's
      ! largest contact load where that exceeds the applied load (adore_model_scales)
      call scale_factors(bearing%d, bearing%mass(BODY_ELEMENT), bearing%force, scales, error, bearing%moment, &
                         0.5_wp*bearing%dm, sys%start_load())
      if (allocated(error)) return
      echo%scale_load = scales(2)
      echo%scale_time = scales(3)
      ! The time integration: its integrator (Rec 1 int_method, Rec 2.1) and history are set
      ! up before the print file is opened (bad settings leave no output).
      n_dynamic = sys%dynamic_steps()
      to_time = opts%duration > 0.0_wp .or. opts%revolutions > 0.0_wp
      if (n_dynamic > 0) then
         call sys%start_dynamics(it, y, error)
         if (allocated(error)) return
         if (to_time) then
            ! a run to a simulated time: its end in tau, and a first estimate of its steps
            ! (Rec 2.1's largest step) to size the history, which grows as needed
            call run_end_time(opts, bearing, sys%time_scale, duration, error)
            if (allocated(error)) return
            t_end = duration/sys%time_scale
            n_dynamic = max(1, ceiling(t_end/max(bearing%controls%step_max, tiny(1.0_wp))))
         end if
         call sys%new_history(hist, n_dynamic, error)
         if (allocated(error)) return
      end if
      call sys%run_note(n_dynamic, run_note)
      if (len(deck_warnings) > 0) run_note = "deck warnings: "//deck_warnings//"; "//run_note
      call sys%listing_lines(n_dynamic, listing)
      ! the run options that replace deck models: a traction table, a non-default start
      table_path = ""
      if (table) table_path = trim(opts%traction_table)
      start_title = ""
      if (len_trim(opts%ball_start) > 0) then
         call start_method_from_name(opts%ball_start, start_method, error)
         if (allocated(error)) return
         if (start_method /= MIN_DISSIPATION) start_title = trim(start_method_title(start_method))
      end if

      part_path = trim(out_path)//".part"
      open (newunit=unit, file=part_path, status="replace", action="write", &
            form="formatted", iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call input_error(error, trim(out_path)//": cannot write print file: "//trim(iomsg))
         return
      end if

      if (to_time .and. n_dynamic > 0) then
         call write_listing(unit, text, bearing%race_traction, table_path, start_title, opts%moment_equilibrium, &
                            n_dynamic, opts%substeps, listing, duration, duration*abs(bearing%speed_inner)/(2.0_wp*pi), &
                            run_threads(opts%threads))
      else
         call write_listing(unit, text, bearing%race_traction, table_path, start_title, opts%moment_equilibrium, &
                            n_dynamic, opts%substeps, listing, threads=run_threads(opts%threads))
      end if
      call write_banner(unit)
      call write_echo(unit, echo)
      ! Step 0, the quasi-static start; then the time steps.
      incomplete = ""
      balance = ""
      call sys%write_start(unit)
      if (n_dynamic > 0 .and. to_time) then
         call run_time_loop(unit, sys, it, y, n_dynamic, hist, incomplete, run_error, progress, opts%substeps, t_end, &
                            balance=balance)
      else if (n_dynamic > 0) then
         call run_time_loop(unit, sys, it, y, n_dynamic, hist, incomplete, run_error, progress, opts%substeps, &
                            balance=balance)
      end if
      if (n_dynamic > 0 .and. it%stats%forced_at_h_min > 0) then
         ! ADORE's rule accepts a step at the Rec 2.1 minimum with its error above the limit
         ! (up to ADORE_FORCED_ERR_CAP; adore_dynamics_integrator's accept_at_h_min): say how many (issue #28)
         call add_forced_steps_note(it%stats, sys, balance)
      end if
      if (n_dynamic > 0 .and. it%stats%below_h_min > 0) call add_below_minimum_note(it%stats, balance)
      if (n_dynamic > 0 .and. it%stats%switched) call add_switch_note(it%stats, balance)
      if (n_dynamic > 0 .and. it%stats%rejected_balance > 0) call add_balance_control_note(it, balance)
      if (len(balance) > 0) then
         if (len(run_note) > 0) then
            run_note = run_note//"; "//balance
         else
            run_note = balance
         end if
      end if

      close (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call delete_file(part_path)
         call engine_error(error, trim(out_path)//": cannot close print file: "//trim(iomsg))
         return
      end if
      ! the plot-data and element files first: a print is moved into place only with them
      call history_file_name(trim(out_path), hist_path)
      call element_file_name(trim(out_path), element_path)
      if (n_dynamic > 0) then
         call write_history_csv(hist, hist_path, incomplete, error)
         if (.not. allocated(error)) call write_element_file(hist, element_path, incomplete, error)
         if (allocated(error)) then
            call delete_file(part_path)
            call delete_file(hist_path)
            return
         end if
      end if
      call rename_file(part_path, trim(out_path), ok)
      if (.not. ok) then
         call delete_file(part_path)
         if (n_dynamic > 0) call delete_file(hist_path)
         if (n_dynamic > 0) call delete_file(element_path)
         call engine_error(error, trim(out_path)//": cannot move the finished print file into place")
         return
      end if
      if (n_dynamic == 0) call delete_file(hist_path)    ! a stale file of an earlier run
      if (n_dynamic == 0) call delete_file(element_path)
      if (present(note)) note = run_note
      if (present(history)) history = hist
      if (present(integrated)) then
         integrated = n_dynamic
         if (hist%rows > 0) integrated = nint(hist%values(hist%rows, 2))
      end if
      if (allocated(run_error)) then
         ! a run that steps at the minimum without error control before it stops: say so, and
         ! what led those steps' error (the stop is then a consequence, issue #28)
         forced_text = ""
         if (n_dynamic > 0 .and. it%stats%forced_at_h_min > 0) call add_forced_steps_note(it%stats, sys, forced_text)
         if (n_dynamic > 0 .and. it%stats%below_h_min > 0) call add_below_minimum_note(it%stats, forced_text)
         if (len(forced_text) > 0) forced_text = "; before it, "//forced_text
         call engine_error(error, run_error%message//forced_text//"; kept: the print file "//trim(out_path)// &
                           " (its last line says '"//INCOMPLETE_MARK//"') and its plot-data file "//hist_path)
         error%stat = run_error%stat
      end if
   end subroutine run_deck

   !> The simulated time (s) a run to a time integrates: opts%duration, or opts%revolutions
   !> of the shaft (inner race, Rec 9.1.2 speed); input error for revolutions of a shaft that
   !> does not turn.
   subroutine run_end_time(opts, b, time_scale, duration, error)
      type(run_options_t), intent(in) :: opts
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: time_scale
      real(wp), intent(out) :: duration
      type(error_type), allocatable, intent(out) :: error
      duration = opts%duration
      if (opts%revolutions > 0.0_wp) then
         if (.not. abs(b%speed_inner) > 0.0_wp) then
            call input_error(error, "run option revolutions: the shaft (inner race, Rec 9.1.2) does not turn; "// &
                             "give the simulated time with duration")
            return
         end if
         duration = opts%revolutions*2.0_wp*pi/abs(b%speed_inner)
      end if
      if (.not. duration/time_scale < 1.0e12_wp) call input_error(error, "run option duration: the simulated "// &
         "time is beyond 1e12 time units of the echo's TIME scale")
   end subroutine run_end_time

   !> Append to text ("; "-separated) the run note's clause on steps the integrator accepted
   !> at the Rec 2.1 minimum step with their error estimate above the error limit (forced of
   !> accepted; ADORE's rule, report 4.4.12's minimum step): such a run went on without
   !> error control, so its states and balances are not resolved - a smaller minimum step
   !> (or a less stiff traction) is what resolves it (docs/operating-points.md, "The last ten
   !> grid failures").  A subroutine: a deferred-length function result would be static
   !> storage (fortran/core/strings.f90).
   subroutine add_forced_steps_note(stats, sys, text)
      type(integrator_stats_t), intent(in) :: stats
      class(bearing_system_t), intent(in) :: sys
      character(len=:), allocatable, intent(inout) :: text
      character(len=16) :: ratio
      character(len=:), allocatable :: name
      integer, allocatable :: lead(:)
      integer :: j, i
      if (len(text) > 0) text = text//"; "
      text = text//itoa(stats%forced_at_h_min)//" of "//itoa(stats%accepted)//" time steps accepted at the "// &
             "minimum step (Rec 2.1) with their error above the error limit: not resolved"
      ! the diagnosis (issue #28): how far above, and which unknowns led the error test
      write (ratio, "(f16.2)") stats%forced_err_max
      text = text//"; their error up to "//trim(adjustl(ratio))//" times the limit ("// &
             itoa(stats%forced_within_2)//" of them within twice it), led by "
      if (allocated(stats%forced_lead)) then
         lead = stats%forced_lead
         do j = 1, 3
            if (maxval(lead) <= 0) exit
            i = maxloc(lead, 1)
            call sys%unknown_name(i, name)
            if (j > 1) text = text//", "
            text = text//name//" at "//itoa(lead(i))
            lead(i) = 0
         end do
         if (sum(lead) > 0) text = text//", other unknowns at "//itoa(sum(lead))
      end if
      text = text//" (a smaller Rec 2.1 minimum step lets the error control resolve them; "// &
             "docs/operating-points.md)"
   end subroutine add_forced_steps_note

   !> Append to text ("; "-separated) the run note's clause on steps shorter than the Rec 2.1
   !> minimum that report 4.4.12's reduced step took after the model refused attempts (or
   !> they were not finite) at the minimum, or their error there was above what ADORE is
   !> attested to accept (ADORE_FORCED_ERR_CAP times the limit; adore_dynamics_integrator,
   !> ADORE's rule; issue #28).
   subroutine add_below_minimum_note(stats, text)
      type(integrator_stats_t), intent(in) :: stats
      character(len=:), allocatable, intent(inout) :: text
      character(len=16) :: shortest, cap
      if (len(text) > 0) text = text//"; "
      write (shortest, "(es10.3)") stats%h_min_used
      text = text//itoa(stats%below_h_min)//" time steps shorter than the minimum step (Rec 2.1; the shortest "// &
             trim(adjustl(shortest))//" tau) after attempts the model refused at it (report 4.4.12's reduced step)"
      if (stats%below_h_min_error > 0) then
         write (cap, "(f16.2)") ADORE_FORCED_ERR_CAP
         text = text//" or whose error there was above "//trim(adjustl(cap))//" times the limit, the most "// &
                "ADORE's Appendix C run accepts at the minimum ("//itoa(stats%below_h_min_error)//" of them)"
      end if
   end subroutine add_below_minimum_note

   !> Append to text ("; "-separated) the run note's clause on the deck's IMEX method giving
   !> way to ROS34PW2 from the first step (integrator_settings_t%switch_stiffness; issue #28):
   !> the balls' fastest spin relaxation rate times the Rec 2.1 minimum step.
   subroutine add_switch_note(stats, text)
      type(integrator_stats_t), intent(in) :: stats
      character(len=:), allocatable, intent(inout) :: text
      character(len=16) :: measure
      if (len(text) > 0) text = text//"; "
      write (measure, "(es10.3)") stats%switch_measure
      text = text//"integrated by ROS34PW2 instead of the deck's IMEX method ARK4(3)6L[2]SA: a ball's spin "// &
             "relaxes within the minimum step (Rec 2.1; relaxation rate times minimum step "// &
             trim(adjustl(measure))//" at the first step, above 1; docs/integrator.md)"
   end subroutine add_switch_note

   !> Append to text ("; "-separated) the run note's clause on the attempts the integrator's
   !> power-balance control rejected (integrator_settings_t%balance_tolerance, run option
   !> balance_tolerance; issue #28): why the run took more, shorter steps than the error test
   !> alone asks.
   subroutine add_balance_control_note(it, text)
      type(integrator_t), intent(in) :: it
      character(len=:), allocatable, intent(inout) :: text
      character(len=16) :: tol
      if (len(text) > 0) text = text//"; "
      write (tol, "(es9.2)") it%settings%balance_tolerance
      text = text//"the power-balance control (balance_tolerance "//trim(adjustl(tol))//") rejected "// &
             itoa(it%stats%rejected_balance)//" of the run's attempts (docs/integrator.md)"
   end subroutine add_balance_control_note

end module adore_driver_run
