!> The time loop of a ball bearing run (report 4.4.5; issue #20 [Dynamics], in progress):
!> integrates the equations of motion (adore_dynamics_ball_system) from the step-0 start
!> for a given number of accepted steps and prints the dynamic steps, the termination line
!> and "Statistics of this Run".
!>
!> Opt-in while [Dynamics] is in progress (run_deck: an explicit positive step count):
!> the system's defaults hold - no cage contacts, the thermal model off (bulk temperatures
!> stay at Rec 2.7's) - and the print's listing says so.  No module state.
module adore_driver_ball_dynamics
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error
   use adore_core_strings, only: itoa
   use adore_model_bearing, only: bearing_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: body_azimuth
   use adore_dynamics_integrator, only: integrator_t, DERIV_FAIL
   use adore_dynamics_ball_system, only: ball_system_t, start_ball_dynamics
   use adore_driver_ball_step0, only: ball_step0_t
   use adore_output_ball_dynamic_report, only: write_ball_step
   use adore_output_print_tables, only: write_termination, write_statistics
   implicit none
   private

   public :: run_ball_dynamics

contains

   !> Integrate ball bearing b (mounted geometry g) from its step-0 solution s0 for n_steps
   !> accepted steps (n_steps >= 1) and write to `unit`: every b%print_interval-th step (Rec 1
   !> data_control_2; 0: only the last) and always the last, each in the ADORE 5.0 layout
   !> (adore_output_ball_dynamic_report), then the termination line (last step, final tau)
   !> and the integrator's statistics (steps in tau).  Each ball's orbital position is
   !> unwrapped from step to step (a step moves a ball far less than half a revolution).
   !> Errors (integrator settings of Rec 1/2.1, a failed integration) come back in error;
   !> the caller discards the partial print.  two_d (default .true.): the two-dimensional
   !> race traction (start_ball_dynamics).
   subroutine run_ball_dynamics(unit, b, g, s0, n_steps, error, two_d)
      integer, intent(in) :: unit
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_step0_t), intent(in) :: s0
      integer, intent(in) :: n_steps
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: two_d

      type(ball_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:), azimuth(:), last(:)
      real(wp) :: t, time
      integer :: i, k, flag
      logical :: print_now

      call start_ball_dynamics(b, g, s0%start, s0%cage, sys, it, y, error, two_d=two_d)
      if (allocated(error)) return
      allocate (dydt(size(y)))
      azimuth = s0%start%equilibrium%azimuth
      last = azimuth
      t = 0.0_wp
      do i = 1, n_steps
         call it%step(sys, t, y, error)
         if (allocated(error)) return
         ! the state, rates and loads at the accepted state (one evaluation outside the
         ! integrator's count; it does not disturb its first-same-as-last reuse)
         call sys%eval(t, y, dydt, flag)
         if (flag == DERIV_FAIL) then
            call engine_error(error, "dynamics: step "//itoa(i)//": "//sys%failure_reason)
            return
         end if
         do k = 1, b%n_elements
            associate (phi => body_azimuth(sys%state%elements(k)))
               azimuth(k) = azimuth(k) + (modulo(phi - last(k) + pi, 2.0_wp*pi) - pi)
               last(k) = phi
            end associate
         end do
         print_now = i == n_steps
         if (b%print_interval > 0) print_now = print_now .or. mod(i, b%print_interval) == 0
         if (.not. print_now) cycle
         time = t*sys%time_scale
         call write_ball_step(unit, i, [t, time, b%speed_outer*time/(2.0_wp*pi), b%speed_inner*time/(2.0_wp*pi)], &
                              b, g, sys%state, sys%rates, sys%loads, azimuth, &
                              s0%start%equilibrium%u(1) - s0%start%equilibrium%axial_displacement)
      end do
      call write_termination(unit, n_steps, t)
      write (unit, "(a)") ""
      call write_statistics(unit, [it%stats%h_min_used, it%stats%h_max_used, it%stats%h_last, &
                                   it%stats%max_truncation], it%stats%derivative_calls)
   end subroutine run_ball_dynamics

end module adore_driver_ball_dynamics
