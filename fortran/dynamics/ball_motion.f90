!> Equations of motion of a ball bearing: the rates of every body's state from the loads
!> of the force assembly, Newton's law for the mass centres and Euler's equations with the
!> gyroscopic terms for the rotations (report section 1 and 4.4.3: ADORE's "generalized
!> dynamic model" of every element in six degrees of freedom).
!>
!> For each body (adore_state_bearing_state: inertial position and velocity, attitude
!> quaternion, body-frame angular velocity omega; principal inertia I of Appendix A's
!> inertial parameters, adore_model_bearing's mass and moments):
!>     dx/dt = v,   m dv/dt = F,   dq/dt = 1/2 q [0, omega],
!>     I domega/dt = M_b - omega x (I omega),   M_b = R(q)^T M
!> (Euler's equations in principal axes; Goldstein, Classical Mechanics, 5.6), F and M the
!> body's loads about its mass centre (adore_forces_ball_bearing: contacts, traction,
!> gravity, the applied load of the inner race).  A ball's inertia is isotropic, so its
!> gyroscopic term vanishes.
!> Constraints (report 4.4.6, until the deck's DOF constraints of Rec 3.3 are identified):
!> the operating condition's (adore_model_condition's dof_constraints_t; by default the
!> outer race is fixed in the housing and turns at its Rec 9.1.2 speed; the inner race
!> turns at its prescribed speed about its axis, no angular acceleration, its misalignment
!> held, and translates freely under the applied load; the cage moves in six degrees of
!> freedom under its pocket and guide-land contacts, adore_forces_ball_bearing).
!> Temperatures do not change here (the thermal model is [Thermal]).  Units SI, time in s.
module adore_dynamics_ball_motion
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_core_rotation, only: cross, quat_matrix, quat_rate
   use adore_model_bearing, only: BODY_CAGE, BODY_ELEMENT, BODY_INNER, BODY_OUTER, bearing_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_model_condition, only: dof_constraints_t, body_dof_t, default_constraints
   use adore_state_bearing_state, only: bearing_state_t, body_state_t, new_bearing_state, RACE_OUTER, RACE_INNER
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, body_load_t, ball_bearing_loads
   use adore_dynamics_cage_whirl, only: whirl_frame_acceleration
   implicit none
   private

   public :: ball_bearing_rates, body_rates

contains

   !> Rates ds/dt of the ball bearing state s (module header): in rates, each body's
   !> position holds its velocity (m/s), velocity its acceleration (m/s**2), attitude the
   !> quaternion rate (1/s) and omega the body-frame angular acceleration (rad/s**2); the
   !> temperatures' rates are 0.  loads: the force assembly at s (adore_forces_ball_bearing).
   !> traction, cage, stiffness and two_d as ball_bearing_loads; gyro_restraint (default
   !> .false.): the balls' gyroscopic moments resisted by the races without slip
   !> (add_gyroscopic_restraint); damping, land_film as ball_bearing_loads; cage_spin_only:
   !> the cage's translation and tilt constrained (report 4.4.6); constraints: the bodies'
   !> degrees of freedom (replaces cage_spin_only; absent: default_constraints);
   !> lubricant_temperature as ball_bearing_loads'; adore_whirl (default .false.): a free
   !> cage's mass centre in ADORE's whirl coordinates (adore_dynamics_cage_whirl) instead of
   !> Newton's, faded to Newton's within whirl_blend (m; default 0) of the bearing axis
   !> (whirl_frame_acceleration's r_blend); threads (default 1): the balls' contacts on that many threads (ball_bearing_loads',
   !> the same rates bit for bit).  Input errors of the traction model come back in error.
   subroutine ball_bearing_rates(b, g, s, rates, loads, error, traction, cage, stiffness, two_d, gyro_restraint, &
                                 damping, land_film, cage_spin_only, constraints, rolling, lubricant_temperature, &
                                 adore_whirl, threads, whirl_blend)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: s
      type(bearing_state_t), intent(out) :: rates
      type(ball_bearing_loads_t), intent(out) :: loads
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: traction, cage
      real(wp), intent(in), optional :: stiffness(:, :)
      logical, intent(in), optional :: two_d, gyro_restraint
      real(wp), intent(in), optional :: damping
      logical, intent(in), optional :: land_film
      !> .true.: the cage's translation and tilt are constrained (report 4.4.6's DOF
      !> constraints): it keeps its position and turns about its own axis only
      logical, intent(in), optional :: cage_spin_only
      type(dof_constraints_t), intent(in), optional :: constraints
      !> the race contacts' EHD rolling resistance (ball_bearing_loads' rolling)
      logical, intent(in), optional :: rolling
      real(wp), intent(in), optional :: lubricant_temperature(:)
      logical, intent(in), optional :: adore_whirl
      integer, intent(in), optional :: threads
      real(wp), intent(in), optional :: whirl_blend
      type(dof_constraints_t) :: dof
      integer :: k
      logical :: with_gyro

      if (present(constraints)) then
         dof = constraints
      else
         dof = default_constraints(.false.)
         if (present(cage_spin_only)) dof = default_constraints(cage_spin_only)
      end if

      with_gyro = .false.
      if (present(gyro_restraint)) with_gyro = gyro_restraint
      ! the gyroscopic restraint (add_gyroscopic_restraint) inside the force assembly: each
      ! ball's moment on its thread, the races' reactions after the balls in ball order
      if (with_gyro) then
         call ball_bearing_loads(b, g, s, loads, error, traction, cage, stiffness, two_d, damping=damping, &
                                 land_film=land_film, rolling=rolling, lubricant_temperature=lubricant_temperature, &
                                 threads=threads, gyro_inertia=b%moments(1, BODY_ELEMENT))
      else
         call ball_bearing_loads(b, g, s, loads, error, traction, cage, stiffness, two_d, damping=damping, &
                                 land_film=land_film, rolling=rolling, lubricant_temperature=lubricant_temperature, &
                                 threads=threads)
      end if
      if (allocated(error)) return
      rates = new_bearing_state(size(s%elements))
      rates%time = 1.0_wp
      rates%temperature = 0.0_wp
      do k = 1, size(s%elements)
         rates%elements(k) = body_rates(s%elements(k), loads%elements(k), b%mass(BODY_ELEMENT), b%moments(:, BODY_ELEMENT))
      end do
      rates%cage = body_rates(s%cage, loads%cage, b%mass(BODY_CAGE), b%moments(:, BODY_CAGE))
      if (present(adore_whirl)) then
         if (adore_whirl) rates%cage%velocity(2:3) = rates%cage%velocity(2:3) + &
                                                     whirl_frame_acceleration(s%cage%position(2:3), s%cage%velocity(2:3), &
                                                                              whirl_blend)
      end if
      call constrain(rates%cage, dof%cage)
      rates%races(RACE_OUTER) = body_rates(s%races(RACE_OUTER), loads%races(RACE_OUTER), b%mass(BODY_OUTER), &
                                           b%moments(:, BODY_OUTER))
      call constrain(rates%races(RACE_OUTER), dof%outer)
      rates%races(RACE_INNER) = body_rates(s%races(RACE_INNER), loads%races(RACE_INNER), b%mass(BODY_INNER), &
                                           b%moments(:, BODY_INNER))
      call constrain(rates%races(RACE_INNER), dof%inner)
   end subroutine ball_bearing_rates

   !> The rates r of a body with its constrained degrees of freedom dof held: no velocity
   !> and no acceleration along a constrained translation, no angular acceleration about a
   !> constrained axis (the attitude still turns at the body's angular velocity).
   pure subroutine constrain(r, dof)
      type(body_state_t), intent(inout) :: r
      type(body_dof_t), intent(in) :: dof
      where (.not. dof%translation)
         r%position = 0.0_wp
         r%velocity = 0.0_wp
      end where
      where (.not. dof%rotation) r%omega = 0.0_wp
   end subroutine constrain

   !> Rates of one free rigid body of mass m (kg) and principal moments inertia(3) (kg m**2)
   !> under the load ld (force and moment about the mass centre, inertial components).
   pure function body_rates(body, ld, m, inertia) result(r)
      type(body_state_t), intent(in) :: body
      type(body_load_t), intent(in) :: ld
      real(wp), intent(in) :: m, inertia(3)
      type(body_state_t) :: r
      real(wp) :: m_b(3), rot(3, 3)

      r%position = body%velocity
      r%velocity = ld%force/m
      r%attitude = quat_rate(body%attitude, body%omega)
      rot = quat_matrix(body%attitude)     ! named: a function result inside matmul is a heap temporary
      m_b = matmul(ld%moment, rot)         ! R**T M
      r%omega = (m_b - cross(body%omega, inertia*body%omega))/inertia
   end function body_rates

end module adore_dynamics_ball_motion
