!> The time loop of a ball bearing run (report 4.4.5; issue #20 [Dynamics]): integrates the
!> equations of motion (adore_dynamics_ball_system) from the step-0 start for the run's
!> number of accepted steps, prints the dynamic steps with their time averages since the
!> start, records the time histories (adore_driver_run_history), and ends with the
!> termination line and "Statistics of this Run" - or, when the run stops early (a failed
!> integration, a non-finite state, a progress callback asking to stop), with the last
!> accepted step and a last line "*** RUN INCOMPLETE after step N (tau = ...): <reason> ***".
!>
!> The system's settings are the caller's (start_ball_dynamics: cage contacts and traction
!> as its defaults; the thermal model is off: the bulk temperatures stay at Rec 2.7's).
!> No module state.
module adore_driver_ball_dynamics
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error
   use adore_core_strings, only: itoa
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, body_azimuth
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, guide_land_pairs, total_power_loss
   use adore_tribology_wear, only: archard_wear_rate
   use adore_dynamics_integrator, only: integrator_t, DERIV_FAIL
   use adore_dynamics_ball_system, only: ball_system_t
   use adore_start_ball_step0, only: ball_step0_t
   use adore_driver_time_average, only: time_average_t
   use adore_driver_run_history, only: run_history_t, history_due, record_ball_history
   use adore_output_ball_dynamic_report, only: write_ball_step, dynamic_speed_ratios
   use adore_output_print_tables, only: write_termination, write_statistics
   implicit none
   private

   public :: run_ball_dynamics, run_progress, ball_averaged_values, INCOMPLETE_MARK

   !> First words of the last line of a print whose run stopped early.
   character(len=*), parameter :: INCOMPLETE_MARK = "*** RUN INCOMPLETE"

   !> Positions in the vector of ball_averaged_values: power loss (W), the three speed
   !> ratios, the outer and inner race wear (m**3/s), then each ball's wear (m**3/s).
   integer, parameter, public :: AVG_POWER = 1, AVG_RATIOS = 2, AVG_RACE_WEAR = 5, AVG_BALL_WEAR = 7

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

   !> The quantities the print shows as time averages, at one state s of ball bearing b
   !> with the force assembly's loads there, into v (size AVG_BALL_WEAR - 1 + n): the total
   !> power loss of the race contacts (W), dynamic_speed_ratios, and the Archard wear rates
   !> (adore_tribology_wear, as step 0 computes them) of the outer and inner race (over all
   !> their contacts) and of each ball (over both its contacts), from each contact's
   !> integral of |slip| dQ of the rolling-direction traction model (0 where unloaded).
   subroutine ball_averaged_values(b, s, loads, v)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(out) :: v(:)
      integer :: k
      v(AVG_POWER) = total_power_loss(loads)
      v(AVG_RATIOS:AVG_RATIOS + 2) = dynamic_speed_ratios(b, s)
      v(AVG_RACE_WEAR) = archard_wear_rate(b%material(BODY_OUTER)%wear, b%material(BODY_OUTER)%hardness, &
                                           sum(loads%traction(1, :)%sliding))
      v(AVG_RACE_WEAR + 1) = archard_wear_rate(b%material(BODY_INNER)%wear, b%material(BODY_INNER)%hardness, &
                                               sum(loads%traction(2, :)%sliding))
      do k = 1, b%n_elements
         v(AVG_BALL_WEAR - 1 + k) = archard_wear_rate(b%material(BODY_ELEMENT)%wear, &
                                                      b%material(BODY_ELEMENT)%hardness, &
                                                      loads%traction(1, k)%sliding + loads%traction(2, k)%sliding)
      end do
   end subroutine ball_averaged_values

   !> Integrate ball bearing b (mounted geometry g) from its step-0 solution s0 for n_steps
   !> accepted steps (n_steps >= 1) with the system sys, integrator it and packed state y of
   !> start_ball_dynamics (y at tau = 0 on entry), writing to `unit`: every
   !> b%print_interval-th step (Rec 1 data_control_2; 0: only the last) and always the last,
   !> each in the ADORE 5.0 layout with the time averages since the start
   !> (adore_output_ball_dynamic_report), then the termination line (last step, final tau)
   !> and the integrator's statistics (steps in tau).  history (allocated by
   !> new_ball_history) records the rows history_due asks for.  Each ball's orbital position
   !> is unwrapped from step to step (a step moves a ball far less than half a revolution).
   !> progress, when present, is called after every accepted step (run_progress).
   !>
   !> A run that stops early (the integrator's error, a failed evaluation, progress asking
   !> to stop) prints its last accepted step (when not printed yet) and the line
   !> INCOMPLETE_MARK//incomplete//" ***", and returns an engine error with the same reason;
   !> incomplete = " after step N (tau = T): <reason>" (blank when the run completed).
   !> Errors of the integrator's settings come from start_ball_dynamics, before any print.
   subroutine run_ball_dynamics(unit, b, g, s0, sys, it, y, n_steps, history, incomplete, error, progress, substeps)
      integer, intent(in) :: unit
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_step0_t), intent(in) :: s0
      type(ball_system_t), intent(inout) :: sys
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      integer, intent(in) :: n_steps
      type(run_history_t), intent(inout) :: history
      character(len=:), allocatable, intent(out) :: incomplete
      type(error_type), allocatable, intent(out) :: error
      procedure(run_progress), optional :: progress
      !> integrator steps per nominal (printed, recorded, counted) step, report 4.4.5
      !> (default 1); the time averages take every one of them
      integer, intent(in), optional :: substeps

      type(time_average_t) :: averages
      real(wp), allocatable :: dydt(:), azimuth(:), last(:), values(:), mean(:)
      real(wp) :: t, t_old, clearance, axial_origin
      character(len=:), allocatable :: reason
      integer :: i, j, k, flag, stop, printed_last, n_values, n_sub
      logical :: print_now

      incomplete = ""
      n_sub = 1
      if (present(substeps)) n_sub = max(substeps, 1)
      n_values = AVG_BALL_WEAR - 1 + b%n_elements
      allocate (dydt(size(y)), values(n_values), mean(n_values))
      axial_origin = s0%start%equilibrium%u(1) - s0%start%equilibrium%axial_displacement
      clearance = guide_clearance(b, g, sys%state%temperature)
      azimuth = s0%start%equilibrium%azimuth
      last = azimuth
      t = 0.0_wp
      printed_last = 0
      ! the initial state: its loads start the averages and the history's first row
      call sys%eval(t, y, dydt, flag)
      if (flag == DERIV_FAIL) then
         call stop_run(0, "the equations of motion failed at the start: "//sys%failure_reason, .false.)
         return
      end if
      call ball_averaged_values(b, sys%state, sys%loads, values)
      call averages%start(values)
      call averages%mean(mean)
      call record(0)
      do i = 1, n_steps
         do j = 1, n_sub                      ! substeps (4.4.5): nothing printed or recorded
            t_old = t
            call it%step(sys, t, y, error)
            if (allocated(error)) then
               reason = error%message
               deallocate (error)
               call stop_run(i - 1, reason, .true.)
               return
            end if
            ! sys%state, rates and loads belong to the accepted state: the integrator's pairs
            ! are first-same-as-last, their last stage is evaluated at (t, y) of the step
            do k = 1, b%n_elements
               associate (phi => body_azimuth(sys%state%elements(k)))
                  azimuth(k) = azimuth(k) + (modulo(phi - last(k) + pi, 2.0_wp*pi) - pi)
                  last(k) = phi
               end associate
            end do
            call ball_averaged_values(b, sys%state, sys%loads, values)
            call averages%add(t - t_old, values)
         end do
         print_now = i == n_steps
         if (b%print_interval > 0) print_now = print_now .or. mod(i, b%print_interval) == 0
         if (print_now .or. history_due(history, i, n_steps, print_now)) call averages%mean(mean)
         if (history_due(history, i, n_steps, print_now)) call record(i)
         if (print_now) call print_step(i)
         if (present(progress)) then
            call progress(i, n_steps, t, t*sys%time_scale, stop)
            if (stop /= 0) then
               call stop_run(i, "interrupted", .false.)
               return
            end if
         end if
      end do
      call write_termination(unit, n_steps, t)
      write (unit, "(a)") ""
      call write_statistics(unit, [it%stats%h_min_used, it%stats%h_max_used, it%stats%h_last, &
                                   it%stats%max_truncation], it%stats%derivative_calls)

   contains

      !> Print step i at the system's last evaluated state (the state at tau = t).
      subroutine print_step(i)
         integer, intent(in) :: i
         real(wp) :: time
         time = t*sys%time_scale
         call write_ball_step(unit, i, [t, time, b%speed_outer*time/(2.0_wp*pi), b%speed_inner*time/(2.0_wp*pi)], &
                              b, g, sys%state, sys%rates, sys%loads, azimuth, axial_origin, &
                              mean(AVG_BALL_WEAR:), mean(AVG_RACE_WEAR:AVG_RACE_WEAR + 1), &
                              mean(AVG_POWER:AVG_RATIOS + 2))
         printed_last = i
      end subroutine print_step

      !> A history row of step i at the system's last evaluated state.
      subroutine record(i)
         integer, intent(in) :: i
         call record_ball_history(history, i, t*sys%time_scale, sys%state, sys%loads, mean(AVG_BALL_WEAR:), &
                                  mean(AVG_RACE_WEAR:AVG_RACE_WEAR + 1), clearance)
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
                  if (nint(history%values(history%rows, 2)) /= i_last) call record(i_last)
               end if
            end if
         end if
         write (unit, "(a)") INCOMPLETE_MARK//incomplete//" ***"
         call engine_error(error, "run incomplete"//incomplete)
      end subroutine stop_run

   end subroutine run_ball_dynamics

   !> Diametral clearance (m) of the cage's guide: the smallest effective diametral play of
   !> its guide lands at bulk temperatures temperature (adore_forces_ball_bearing's land
   !> pairs); NaN without a guide land.
   function guide_clearance(b, g, temperature) result(c)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      real(wp), intent(in) :: temperature(:)
      real(wp) :: c
      if (b%n_lands < 1) then
         c = ieee_value(1.0_wp, ieee_quiet_nan)
         return
      end if
      associate (pairs => guide_land_pairs(b, g, temperature))
         c = 2.0_wp*minval(pairs%clearance)
      end associate
   end function guide_clearance

end module adore_driver_ball_dynamics
