!> The ball bearing as a system for the integrator: the equations of motion
!> (adore_dynamics_ball_motion) behind the integrator's derivative interface, on the state
!> vector of adore_state_bearing_state, in the report's dimensionless time tau.
!>
!> ADORE integrates in dimensionless time (the echo's TIME scale T = sqrt(m L / F),
!> adore_model_scales; Rec 2.1's step sizes are in tau): dy/dtau = T dy/dt.  The model
!> data travel inside the type (no module state); the state and rate scratch live there too,
!> so an evaluation allocates nothing after the first.  The initial state of a run is the
!> step-0 start (initial_ball_state): balls at their equilibrium positions, orbiting and
!> spinning with the start's speeds; the races at their speeds, the inner race at its
!> equilibrium offset and misalignment; the cage on the report's initial whirl (4.4.4).
module adore_dynamics_ball_system
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error
   use adore_core_rotation, only: quat_from_rotation_vector
   use adore_model_bearing, only: bearing_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, new_bearing_state, state_size, pack_state, unpack_state, &
                                        RACE_OUTER, RACE_INNER
   use adore_forces_ball_bearing, only: ball_bearing_loads_t
   use adore_dynamics_ball_motion, only: ball_bearing_rates
   use adore_dynamics_integrator, only: derivative_t, DERIV_OK, DERIV_FAIL, DERIV_REJECT_STEP
   use adore_driver_ball_step0, only: ball_step0_t
   implicit none
   private

   public :: ball_system_t, new_ball_system, initial_ball_state

   !> The ball bearing's equations of motion dy/dtau (integrator's derivative_t).
   type, extends(derivative_t) :: ball_system_t
      type(bearing_t) :: bearing
      type(mounted_geometry_t) :: geometry
      real(wp) :: time_scale = 1.0_wp        !< T (s) of one unit of tau
      logical :: traction = .true.           !< race contact traction on (off: normal loads only)
      logical :: cage = .true.               !< pocket and guide-land contacts on
      type(bearing_state_t) :: state, rates  !< scratch of eval
      type(ball_bearing_loads_t) :: loads    !< the loads of the last evaluation
      integer :: calls = 0                   !< evaluations so far
      type(error_type), allocatable :: failure   !< why the last evaluation returned DERIV_FAIL
   contains
      procedure :: eval => ball_system_eval
   end type ball_system_t

contains

   !> The system of bearing b in mounted geometry g, time scale time_scale (s per unit
   !> tau), with (default) or without race traction and cage contacts.
   function new_ball_system(b, g, time_scale, traction, cage) result(sys)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      real(wp), intent(in) :: time_scale
      logical, intent(in), optional :: traction, cage
      type(ball_system_t) :: sys
      sys%bearing = b
      sys%geometry = g
      sys%time_scale = time_scale
      if (present(traction)) sys%traction = traction
      if (present(cage)) sys%cage = cage
      sys%state = new_bearing_state(b%n_elements)
   end function new_ball_system

   !> dy/dtau at tau = t for the packed state y (adore_state_bearing_state's order).
   subroutine ball_system_eval(self, t, y, dydt, flag)
      class(ball_system_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag

      self%calls = self%calls + 1
      call unpack_state(y, t*self%time_scale, self%state)
      call ball_bearing_rates(self%bearing, self%geometry, self%state, self%rates, self%loads, self%failure, &
                              self%traction, self%cage)
      if (allocated(self%failure)) then
         flag = DERIV_FAIL
         dydt = 0.0_wp
         return
      end if
      call pack_state(self%rates, dydt)
      dydt = self%time_scale*dydt
      flag = DERIV_OK
      ! an abnormal cage contact (report 4.4.12): the integrator retries with a smaller step
      if (self%loads%abnormal) flag = DERIV_REJECT_STEP
      if (.not. all(ieee_is_finite(dydt))) then
         call engine_error(self%failure, "equations of motion: non-finite rates (a body or contact state is "// &
                           "outside the model's range)")
         flag = DERIV_FAIL
      end if
   end subroutine ball_system_eval

   !> The state of ball bearing b (mounted geometry g) at the start of the dynamics: its
   !> step-0 solution s0 (module header).  Positions in the bearing frame (origin at the
   !> outer race centre).
   function initial_ball_state(b, g, s0) result(st)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_step0_t), intent(in) :: s0
      type(bearing_state_t) :: st
      real(wp) :: phi, e_r(3), e_t(3), r
      integer :: k

      st = new_bearing_state(b%n_elements)
      st%temperature = b%temperature
      associate (e => s0%start%equilibrium, kin => s0%start%kinematics, c => s0%cage%state)
         do k = 1, b%n_elements
            phi = e%azimuth(k)
            r = e%r(k)
            e_r = [0.0_wp, -sin(phi), cos(phi)]
            e_t = [0.0_wp, -cos(phi), -sin(phi)]
            st%elements(k)%position = [e%x(k), 0.0_wp, 0.0_wp] + r*e_r
            st%elements(k)%velocity = kin(k)%orbital_speed*r*e_t
            ! attitude identity: body components = inertial components at the start
            st%elements(k)%omega = [kin(k)%orbital_speed + kin(k)%spin_speed*cos(kin(k)%pitch), 0.0_wp, 0.0_wp] &
                                   + kin(k)%spin_speed*sin(kin(k)%pitch)*e_r
         end do
         st%races(RACE_OUTER)%omega = [b%speed_outer, 0.0_wp, 0.0_wp]
         st%races(RACE_INNER)%omega = [b%speed_inner, 0.0_wp, 0.0_wp]
         st%races(RACE_INNER)%position = e%u(1:3)
         st%races(RACE_INNER)%attitude = quat_from_rotation_vector([0.0_wp, e%u(4), e%u(5)])
         ! cage: the step-0 whirl; its axial position is in the print's frame (outer groove
         ! curvature centre plane), the state's origin is the outer race centre
         st%cage%position = c%centre + [g%groove_centre(1, 1), 0.0_wp, 0.0_wp]
         st%cage%velocity = c%velocity
         st%cage%attitude = quat_from_rotation_vector(c%angle)
         st%cage%omega = [c%angular_speed, 0.0_wp, 0.0_wp]
      end associate
   end function initial_ball_state

end module adore_dynamics_ball_system
