!> The time loop of a run (report 4.4.5): integrates the equations of motion of any bearing
!> kind (adore_bearings_system) from its step-0 start for the run's number of accepted
!> steps, prints the dynamic steps with their time averages since the start, records the
!> time histories (adore_output_run_history), calls the system's event hook at its event
!> times, and ends with the termination line and "Statistics of this Run" - or, when the run
!> stops early (a failed integration, a non-finite state, a progress callback asking to
!> stop), with the last accepted step and a last line
!> "*** RUN INCOMPLETE after step N (tau = ...): <reason> ***".
!>
!> The balance window (issue #28 item 2): the last half of the run (from the step
!> n_steps/2, or from half the end time of a run to a time); over it the system's
!> balance_values are time-averaged (adore_driver_time_average) and, at the end of a
!> completed run, the system's balance_text says what they add up to (`balance`).
!>
!> Nothing here knows the bearing kind: what is printed, recorded and averaged is the
!> system's.  No module state.
module adore_driver_time_loop
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error
   use adore_core_strings, only: itoa
   use adore_dynamics_integrator, only: integrator_t, DERIV_FAIL
   use adore_bearings_system, only: bearing_system_t
   use adore_driver_time_average, only: time_average_t
   use adore_output_run_history, only: run_history_t, history_due
   use adore_output_print_tables, only: write_termination, write_statistics
   implicit none
   private

   public :: run_time_loop, run_progress, INCOMPLETE_MARK, closure_hint

   !> First words of the last line of a print whose run stopped early.
   character(len=*), parameter :: INCOMPLETE_MARK = "*** RUN INCOMPLETE"

   abstract interface
      !> Called after every accepted step with the step number, the run's number of steps,
      !> tau and the time (s); stop /= 0 asks the run to stop there (it ends incomplete:
      !> "interrupted").  The f2py run passes a Python function; the standalone program its
      !> progress line and Ctrl-C flag.
      subroutine run_progress(step, n_steps, tau, time, stop)
         import :: wp
         integer, intent(in) :: step, n_steps
         real(wp), intent(in) :: tau, time
         integer, intent(out) :: stop
      end subroutine run_progress
   end interface

contains

   !> Integrate bearing system sys from its step-0 start for n_steps accepted steps
   !> (n_steps >= 1) with the integrator it and packed state y of sys%start_dynamics (y at
   !> tau = 0 on entry), writing to `unit`: every print_interval-th step (Rec 1
   !> data_control_2; 0: only the last) and always the last, each with the time averages
   !> since the start (sys%write_step), then the termination line (last step, final tau)
   !> and the integrator's statistics (steps in tau).  history (sys%new_history) records
   !> the rows history_due asks for (sys%record_row).  progress, when present, is called
   !> after every accepted step (run_progress).  substeps: integrator steps per nominal
   !> (printed, recorded, counted) step, report 4.4.5 (default 1); the time averages take
   !> every one of them.  At each of the system's event times a step ends exactly there and
   !> sys%on_event is called after it.  t_end (tau), when present: the run goes on until tau =
   !> t_end exactly (the last step landing on it, printed) instead of for n_steps steps;
   !> n_steps is then only the estimate the progress callback starts from.
   !>
   !> A run that stops early (the integrator's error, a failed evaluation, an event's error,
   !> progress asking to stop) prints its last accepted step (when not printed yet) and the
   !> line INCOMPLETE_MARK//incomplete//" ***", and returns an engine error with the same
   !> reason; incomplete = " after step N (tau = T): <reason>" (blank when the run completed).
   subroutine run_time_loop(unit, sys, it, y, n_steps, history, incomplete, error, progress, substeps, t_end, balance)
      integer, intent(in) :: unit
      class(bearing_system_t), intent(inout) :: sys
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      integer, intent(in) :: n_steps
      type(run_history_t), intent(inout) :: history
      character(len=:), allocatable, intent(out) :: incomplete
      type(error_type), allocatable, intent(out) :: error
      procedure(run_progress), optional :: progress
      integer, intent(in), optional :: substeps
      real(wp), intent(in), optional :: t_end
      !> what the system's balances add up to over the balance window (module header; blank
      !> for a kind without balances or a run that stopped early)
      character(len=:), allocatable, intent(out), optional :: balance

      type(time_average_t) :: averages, window
      real(wp), allocatable :: dydt(:), values(:), mean(:), bal(:), bal_first(:), bal_mean(:)
      real(wp) :: t, t_old, t_event, t_stop, t_window
      character(len=:), allocatable :: reason, hint
      integer :: i, j, flag, stop, printed_last, n_sub, print_interval, n_events, n_report
      integer :: n_window, forced_before, n_at_max, n_at_min
      logical :: print_now, events, to_time, last, in_window

      incomplete = ""
      if (present(balance)) balance = ""
      n_sub = 1
      if (present(substeps)) n_sub = max(substeps, 1)
      print_interval = sys%bearing%controls%print_interval
      allocate (dydt(size(y)), values(sys%n_values()), mean(sys%n_values()))
      allocate (bal(sys%n_balance()), bal_first(sys%n_balance()), bal_mean(sys%n_balance()))
      in_window = .false.
      t = 0.0_wp
      printed_last = 0
      events = sys%event_period > 0.0_wp
      n_events = 0
      t_event = huge(1.0_wp)
      if (events) t_event = max(sys%event_start, 0.0_wp)/sys%time_scale
      to_time = present(t_end)
      t_stop = huge(1.0_wp)
      if (to_time) t_stop = t_end
      ! the initial state: its loads start the averages and the history's first row
      call sys%eval(t, y, dydt, flag)
      if (flag == DERIV_FAIL) then
         call stop_run(0, "the equations of motion failed at the start: "//sys%failure_reason, .false.)
         return
      end if
      call sys%averaged_values(values)
      call averages%start(values)
      ! the integrator's power-balance control integrates the balance values from the start
      if (it%settings%balance_tolerance > 0.0_wp .and. size(bal) > 0) then
         call sys%balance_values(bal)
         call it%start_quadrature(bal)
      end if
      call averages%mean(mean)
      call record(0, .true.)
      if (.not. to_time .and. n_steps/2 == 0) call open_window()
      i = 0
      do
         i = i + 1
         if (.not. to_time .and. i > n_steps) exit
         do j = 1, n_sub                      ! substeps (4.4.5): nothing printed or recorded
            t_old = t
            if (events .or. to_time) then
               call it%step(sys, t, y, error, t_limit=min(t_event, t_stop))
            else
               call it%step(sys, t, y, error)
            end if
            if (allocated(error)) then
               reason = error%message
               deallocate (error)
               call stop_run(i - 1, reason, .true.)
               return
            end if
            ! the system's state, rates and loads belong to the accepted state: the
            ! integrator's pairs are first-same-as-last, their last stage is evaluated at
            ! (t, y) of the step
            call sys%accepted()
            call sys%averaged_values(values)
            call averages%add(t - t_old, values)
            if (in_window) then
               call sys%balance_values(bal)
               ! the window's means by the method's own quadrature of the balance values at
               ! its stages where that is consistent with its steps (a fast torque the steps
               ! do not resolve is then not sampled at their ends; issue #28), else the
               ! trapezoid of the steps' ends; the values at the step's end for the energy change
               if (it%quadrature .and. it%quadrature_consistent()) then
                  call window%add_integral(t - t_old, it%q_step, bal)
               else
                  call window%add(t - t_old, bal)
               end if
               n_window = n_window + 1
               if (t - t_old >= (1.0_wp - 1.0e-9_wp)*it%settings%h_max) n_at_max = n_at_max + 1
               if (t - t_old <= (1.0_wp + 1.0e-9_wp)*it%settings%h_min) n_at_min = n_at_min + 1
            else if (to_time .and. t >= 0.5_wp*t_stop) then
               call open_window()
            end if
            if (events .and. t >= t_event) then
               n_events = n_events + 1
               call sys%on_event(t*sys%time_scale, it, y, error)
               if (allocated(error)) then
                  reason = "event at "//itoa(n_events)//": "//error%message
                  deallocate (error)
                  call stop_run(i, reason, .true.)
                  return
               end if
               t_event = (max(sys%event_start, 0.0_wp) + n_events*sys%event_period)/sys%time_scale
            end if
            if (to_time .and. t >= t_stop) exit
         end do
         if (to_time) then
            last = t >= t_stop
            n_report = i
            if (.not. last) n_report = max(i + 1, nint(i*(t_stop/t)))
         else
            last = i == n_steps
            n_report = n_steps
         end if
         print_now = last
         if (print_interval > 0) print_now = print_now .or. mod(i, print_interval) == 0
         if (print_now .or. history_due(history, i, n_report, print_now)) call averages%mean(mean)
         if (history_due(history, i, n_report, print_now)) call record(i, print_now)
         if (print_now) call print_step(i)
         if (.not. to_time .and. .not. in_window .and. i >= n_steps/2) call open_window()
         if (present(progress)) then
            call progress(i, n_report, t, t*sys%time_scale, stop)
            if (stop /= 0) then
               call stop_run(i, "interrupted", .false.)
               return
            end if
         end if
         if (last) exit
      end do
      if (present(balance) .and. in_window .and. size(bal) > 0) then
         if (window%elapsed > 0.0_wp) then
            call window%mean(bal_mean)
            call closure_hint(n_window, it%stats%forced_at_h_min - forced_before, n_at_max, hint, &
                              it%settings%balance_tolerance, n_at_min)
            call sys%balance_text([t_window, t], bal_mean, bal_first, window%last, hint, balance)
         end if
      end if
      call write_termination(unit, i, t)
      write (unit, "(a)") ""
      call write_statistics(unit, [it%stats%h_min_used, it%stats%h_max_used, it%stats%h_last, &
                                   it%stats%max_truncation], it%stats%derivative_calls)

   contains

      !> Open the balance window at the system's last evaluated state (tau = t).
      subroutine open_window()
         in_window = .true.
         t_window = t
         n_window = 0
         n_at_max = 0
         n_at_min = 0
         forced_before = it%stats%forced_at_h_min
         call sys%balance_values(bal)
         bal_first = bal
         call window%start(bal)
         ! from the next step on, the integrator integrates the balance values at its stages
         if (size(bal) > 0) call it%start_quadrature(bal)
      end subroutine open_window

      !> Print step i at the system's last evaluated state (the state at tau = t).
      subroutine print_step(i)
         integer, intent(in) :: i
         call sys%write_step(unit, i, t, mean)
         printed_last = i
      end subroutine print_step

      !> A history row of step i at the system's last evaluated state; printed: step i is
      !> (or step 0, the print's own) a printed step (run_history_t%printed).
      subroutine record(i, printed)
         integer, intent(in) :: i
         logical, intent(in) :: printed
         history%printed = printed
         call sys%record_row(history, i, t, mean)
      end subroutine record

      !> End the run early after accepted step i_last (state y at tau = t): print that step if
      !> it is not printed yet (evaluated anew when evaluate, i.e. when the system's last
      !> evaluation was not at that state), its history row, the incomplete mark; the error.
      subroutine stop_run(i_last, reason, evaluate)
         integer, intent(in) :: i_last
         character(len=*), intent(in) :: reason
         logical, intent(in) :: evaluate
         character(len=24) :: tau_text
         logical :: ok

         write (tau_text, "(es10.4)") t
         incomplete = " after step "//itoa(i_last)//" (tau = "//trim(adjustl(tau_text))//"): "//reason
         if (i_last > printed_last) then
            ok = .true.
            if (evaluate) then
               call sys%eval(t, y, dydt, flag)
               ok = flag /= DERIV_FAIL
            end if
            call averages%mean(mean)          ! step i_last is in the averages already
            if (ok) then
               call print_step(i_last)
               if (history%rows > 0) then
                  if (nint(history%values(history%rows, 2)) /= i_last) call record(i_last, .true.)
               end if
            end if
         end if
         write (unit, "(a)") INCOMPLETE_MARK//incomplete//" ***"
         call engine_error(error, "run incomplete"//incomplete)
      end subroutine stop_run

   end subroutine run_time_loop

   !> What limited the balance window's time steps, for the run note when its balances do
   !> not close (issue #28): of the window's n_window accepted steps, n_forced were accepted
   !> at (or below) the Rec 2.1 minimum step with their error above the error limit (ADORE's
   !> rule) - then the minimum step, not the maximum, is what a deck changes; else, under the
   !> integrator's power-balance control (balance_tolerance > 0, run option balance_tolerance),
   !> every step above the minimum step met it (n_at_min at the minimum, where the control
   !> stops: then the minimum step) and the closure is its steps' defects added up - then the tolerance;
   !> else n_at_max were at the Rec 2.1 maximum step - then the maximum step; else every step
   !> met the error limit between the two - then the error limit.  Text without units.
   subroutine closure_hint(n_window, n_forced, n_at_max, hint, balance_tolerance, n_at_min)
      integer, intent(in) :: n_window, n_forced, n_at_max
      character(len=:), allocatable, intent(out) :: hint
      real(wp), intent(in), optional :: balance_tolerance
      integer, intent(in), optional :: n_at_min
      logical :: controlled
      character(len=16) :: tol_text
      controlled = .false.
      if (present(balance_tolerance)) controlled = balance_tolerance > 0.0_wp
      if (n_forced > 0) then
         hint = itoa(n_forced)//" of the window's "//itoa(n_window)//" time steps accepted at the minimum step "// &
                "with their error above the error limit: a smaller Rec 2.1 minimum step resolves them"
      else if (controlled .and. present(n_at_min)) then
         if (n_at_min > 0) then
            hint = itoa(n_at_min)//" of the window's "//itoa(n_window)//" time steps at the minimum step, where "// &
                   "the balance control stops: a smaller Rec 2.1 minimum step does"
         else
            write (tol_text, "(es9.2)") balance_tolerance
            hint = "the window's "//itoa(n_window)//" time steps met the balance tolerance "// &
                   trim(adjustl(tol_text))//" each: a smaller balance_tolerance does"
         end if
      else if (controlled) then
         write (tol_text, "(es9.2)") balance_tolerance
         hint = "the window's "//itoa(n_window)//" time steps met the balance tolerance "//trim(adjustl(tol_text))// &
                " each: a smaller balance_tolerance does"
      else if (n_at_max > 0) then
         hint = itoa(n_at_max)//" of the window's "//itoa(n_window)//" time steps at the maximum step: "// &
                "a smaller Rec 2.1 maximum step does"
      else
         hint = "the window's "//itoa(n_window)//" time steps met the error limit between the minimum and "// &
                "maximum steps: a smaller Rec 2.1 error limit does"
      end if
   end subroutine closure_hint

end module adore_driver_time_loop
