!> The cylindrical roller bearing's equations of motion as the integrator's derivative in
!> the report's dimensionless time tau (issue #26), on the loads of
!> adore_forces_roller_bearing.
!>
!> Packed state (roller_state_size): per roller ROLLER_SIZE unknowns in its orbit-following
!> frame (report eq 54) - x, r, phi, xdot, rdot, phidot, tilt gamma, skew zeta, the
!> transverse angular velocity omega_t, omega_r (absolute, orbit-frame components) and the
!> spin W_abs about the roller axis (absolute); then the cage angle about x and its rate;
!> then the inner race centre (x, y, z) and velocity; then the cage centre's y, z and their
!> rates (held at zero unless the cage is free); then the cage's axial position x_c, its
!> axis's transverse components (1, a_y, a_z) (its tilt), x_c' and its transverse angular
!> velocity (w_y, w_z) (held at zero unless the cage is free).  The outer race is fixed.
!>
!> Roller (polar coordinates in the orbiting frame, m the roller mass):
!>     m (rddot - r phidot**2) = F_r,   m (r phiddot + 2 rdot phidot) = F_t,   m xddot = F_x.
!> Rotation (symmetric body, small tilt and skew; I_a axial, I_t transverse moment of
!> inertia; H = I_a W_abs a + I_t omega_perp, a = e_x + gamma e_r - zeta e_t; dH/dt taken in
!> the frame turning at phidot about e_x):
!>     gammadot = omega_t - phidot zeta,   zetadot = omega_r + phidot gamma,
!>     I_t omega_t' = M_t + (I_a W_abs - I_t phidot) omega_r,
!>     I_t omega_r' = M_r - (I_a W_abs - I_t phidot) omega_t,
!>     I_a W_abs' = M_x.
!> A roller orbiting with a steady tilt gamma thus needs M_t = (I_a W_abs - I_t phidot)
!> phidot gamma: the gyroscopic moment of the tilted spinning roller.  The spin relative to
!> the orbit frame (the slip's W) is W_abs - phidot.
!> The rollers' degrees of freedom are the condition's (dof_constraints_t%elements, report
!> 4.4.6): a constrained axial translation keeps x and xdot, a constrained rotation about
!> e_t keeps the tilt (and omega_t), about e_r the skew (and omega_r).
!> Cage: turning about its axis (I_c thetaddot = pocket torques + guide-land torque) and,
!> when free (cage_free, run option cage=free), translating in the plane normal to the
!> bearing axis: m_c C'' = pocket forces + guide-land forces (adore_contact_cage_land: the
!> short-bearing film when the deck has a lubricant, metallic line contact with friction
!> when the clearance closes) + gravity, also axially (m_c x_c'' = F_x + m_c g_x), and tilting
!> as a symmetric body spinning at W_c about its axis (I_a, I_t its axial and transverse
!> moments of inertia; small tilt; the moments M about its centre, inertial):
!>     a_y' = w_z,   a_z' = -w_y,
!>     I_t w_y' = M_y - I_a W_c w_z,   I_t w_z' = M_z + I_a W_c w_y
!> (free of moments it nutates at I_a W_c / I_t, its transverse kinetic energy conserved;
!> tested).  The moments: the pocket reactions' (their axial lever arms included,
!> adore_forces_roller_bearing's cage_moment) and the lands' (their friction's axial part at
!> the land radius; the film is taken untilted, adore_contact_cage_land).  Centred
!> (the default), the cage stays on the bearing axis and the lands give their torque at zero
!> eccentricity (Petroff's Couette torque).  Inner race: its translation under the
!> applied load, gravity and the roller reactions, each direction as the condition's
!> constraints allow; its rotation prescribed.  No module state.
module adore_dynamics_roller_system
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   use adore_core_strings, only: itoa
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_INNER, BODY_CAGE
   use adore_model_condition, only: dof_constraints_t, default_constraints
   use adore_model_scales, only: scale_factors
   use adore_contact_line_slices, only: line_stiffness, contact_modulus
   use adore_contact_cage_land, only: cage_land_pair_t, cage_land_geometry_t, cage_land_contact
   use adore_state_bearing_state, only: body_state_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_quasistatic_roller_equilibrium, only: roller_qs_bearing_t
   use adore_forces_ball_bearing, only: guide_land_pairs
   use adore_contact_roller_flange, only: roller_flanges
   use adore_forces_roller_bearing, only: roller_force_model_t, roller_pose_t, race_pose_t, roller_loads_t, &
                                          roller_loads
   use adore_dynamics_integrator, only: derivative_t, integrator_t, integrator_settings_t, DERIV_OK, DERIV_FAIL, &
                                        INT_METHOD_ARK436, ADORE_FORCED_ERR_CAP
   use adore_dynamics_ball_system, only: ball_int_method
   use adore_dynamics_cage_whirl, only: whirl_frame_acceleration
   implicit none
   private

   public :: roller_system_t, roller_state_size, roller_pose, start_roller_dynamics, roller_error_scale, &
             roller_unknown_name

   integer, parameter, public :: ROLLER_SIZE = 11
   integer, parameter, public :: R_X = 1, R_R = 2, R_PHI = 3, R_XDOT = 4, R_RDOT = 5, R_PHIDOT = 6, R_TILT = 7, &
                                 R_SKEW = 8, R_WT = 9, R_WR = 10, R_SPIN = 11
   !> offsets after the rollers: cage angle and rate, inner race position and velocity, cage
   !> centre y, z and velocity y, z
   integer, parameter, public :: CAGE_OFFSET = 0, RACE_OFFSET = 2, CAGE_POS_OFFSET = 8, CAGE_TILT_OFFSET = 12, &
                                 TAIL_SIZE = 18

   !> The roller bearing's equations of motion.
   type, extends(derivative_t) :: roller_system_t
      type(roller_force_model_t) :: model          !< the loads' data
      type(cage_land_pair_t), allocatable :: lands(:)   !< guide lands (Rec 7.0/7.2.n)
      integer :: n = 0                             !< rollers
      real(wp) :: time_scale = 1.0_wp              !< T (s) per unit tau
      real(wp) :: inertia(2) = 0.0_wp              !< roller I_a, I_t (kg m**2)
      real(wp) :: cage_inertia = 0.0_wp            !< about x (kg m**2)
      real(wp) :: cage_mass = 0.0_wp               !< (kg)
      real(wp) :: cage_inertia_t = 0.0_wp          !< about a transverse axis (kg m**2)
      logical :: cage_free = .false.               !< cage centre integrated in y, z (module header)
      !> the free cage's centre in ADORE's whirl coordinates (adore_dynamics_cage_whirl; run option
      !> cage_whirl=adore) instead of Newton's inertial equations
      logical :: adore_whirl = .false.
      !> (m) within it of the axis the whirl terms fade to Newton's (whirl_frame_acceleration's
      !> r_blend): a tenth of the smallest guide-land clearance
      real(wp) :: whirl_blend = 0.0_wp
      real(wp) :: race_mass = 0.0_wp               !< inner race (kg)
      real(wp) :: force(3) = 0.0_wp                !< applied to the inner race (N)
      real(wp), allocatable :: pocket_azimuth(:)   !< each pocket's azimuth at cage angle 0 (rad)
      type(dof_constraints_t) :: constraints = dof_constraints_t()
      type(roller_loads_t), allocatable :: loads(:)   !< of the last evaluation
      real(wp) :: land_torque = 0.0_wp             !< guide-land torque on the cage of the last evaluation (N m)
      real(wp) :: land_power = 0.0_wp              !< guide-land loss (W)
      type(cage_land_geometry_t), allocatable :: land(:)   !< each guide land of the last evaluation
      !> threads of each evaluation's rollers (run option threads, adore_core_threads; the same
      !> rates bit for bit on any number)
      integer :: threads = 1
      real(wp) :: cage_force(3) = 0.0_wp           !< pocket + land force on the cage, last evaluation (N)
      real(wp) :: cage_moment(3) = 0.0_wp          !< pocket + land moment on the cage about its centre (N m)
      integer :: calls = 0
   contains
      procedure :: eval => roller_system_eval
   end type roller_system_t

contains

   !> The name of unknown i of the packed state of n rollers (the module header's order), for
   !> messages: e.g. "roller 3's spin", "the cage's angle".  A subroutine: a deferred-length
   !> function result would be static storage (fortran/core/strings.f90).
   pure subroutine roller_unknown_name(n, i, name)
      integer, intent(in) :: n, i
      character(len=:), allocatable, intent(out) :: name
      character(len=*), parameter :: roller(ROLLER_SIZE) = [character(len=26) :: "axial position", "radius", &
         "orbital angle", "axial velocity", "radial velocity", "orbital speed", "tilt", "skew", &
         "angular velocity (orbit t)", "angular velocity (orbit r)", "spin"]
      character(len=*), parameter :: tail(TAIL_SIZE) = [character(len=40) :: "the cage's angle", &
         "the cage's speed", "the inner race's position x", "the inner race's position y", &
         "the inner race's position z", "the inner race's velocity x", "the inner race's velocity y", &
         "the inner race's velocity z", "the cage's centre y", "the cage's centre z", &
         "the cage's centre velocity y", "the cage's centre velocity z", "the cage's axial position", &
         "the cage's axis tilt y", "the cage's axis tilt z", "the cage's axial velocity", &
         "the cage's angular velocity y", "the cage's angular velocity z"]
      if (i >= 1 .and. i <= ROLLER_SIZE*n) then
         name = "roller "//itoa((i - 1)/ROLLER_SIZE + 1)//"'s "//trim(roller(mod(i - 1, ROLLER_SIZE) + 1))
      else if (i > ROLLER_SIZE*n .and. i <= roller_state_size(n)) then
         name = trim(tail(i - ROLLER_SIZE*n))
      else
         name = "unknown "//itoa(i)
      end if
   end subroutine roller_unknown_name

   pure integer function roller_state_size(n)
      integer, intent(in) :: n
      roller_state_size = ROLLER_SIZE*n + TAIL_SIZE
   end function roller_state_size

   !> Roller k's pose from packed state y (the orbit-frame rates of tilt and skew from the
   !> transverse angular velocity, module header).
   pure function roller_pose(y, k) result(p)
      real(wp), intent(in) :: y(:)
      integer, intent(in) :: k
      type(roller_pose_t) :: p
      associate (v => y(ROLLER_SIZE*(k - 1) + 1:ROLLER_SIZE*k))
         p = roller_pose_t(v(R_X), v(R_R), v(R_PHI), v(R_XDOT), v(R_RDOT), v(R_PHIDOT), v(R_TILT), v(R_SKEW), &
                           v(R_WT) - v(R_PHIDOT)*v(R_SKEW), v(R_WR) + v(R_PHIDOT)*v(R_TILT), &
                           v(R_SPIN) - v(R_PHIDOT))
      end associate
   end function roller_pose

   !> dy/dtau at tau = t (module header); the loads of every roller are kept (self%loads).
   subroutine roller_system_eval(self, t, y, dydt, flag)
      class(roller_system_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      type(race_pose_t) :: a
      type(body_state_t) :: cage, outer
      type(cage_land_geometry_t) :: lc
      real(wp) :: race_force(3), cage_torque, cage_force(3), m, ia, it, cage_moment(3)
      integer :: k, c0, r0, g0, t0

      self%calls = self%calls + 1
      if (allocated(self%failure_reason)) deallocate (self%failure_reason)
      if (.not. allocated(self%loads)) allocate (self%loads(self%n))
      c0 = ROLLER_SIZE*self%n + CAGE_OFFSET
      r0 = ROLLER_SIZE*self%n + RACE_OFFSET
      g0 = ROLLER_SIZE*self%n + CAGE_POS_OFFSET
      t0 = ROLLER_SIZE*self%n + CAGE_TILT_OFFSET
      a%position = y(r0 + 1:r0 + 3)
      a%velocity = y(r0 + 4:r0 + 6)
      a%cage_speed = y(c0 + 2)
      a%cage_position = [0.0_wp, y(g0 + 1), y(g0 + 2)]
      a%cage_velocity = [0.0_wp, y(g0 + 3), y(g0 + 4)]
      a%cage_position(1) = y(t0 + 1)
      a%cage_velocity(1) = y(t0 + 4)
      a%cage_tilt = y(t0 + 2:t0 + 3)
      a%cage_omega_t = [0.0_wp, y(t0 + 5), y(t0 + 6)]
      m = self%model%mass
      ia = self%inertia(1)
      it = self%inertia(2)
      race_force = 0.0_wp
      cage_torque = 0.0_wp
      cage_force = 0.0_wp
      cage_moment = 0.0_wp
      ! every roller's loads and rates into its own slots, on self%threads threads (run option
      ! threads, adore_core_threads); the sums over the rollers after, in roller order: the
      ! same numbers bit for bit on any number of threads
      if (self%threads > 1) then
         !$omp parallel do num_threads(self%threads) schedule(static, 1) default(shared) private(k)
         do k = 1, self%n
            call roller_rates(k)
         end do
         !$omp end parallel do
      else
         do k = 1, self%n
            call roller_rates(k)
         end do
      end if
      do k = 1, self%n
         race_force = race_force + self%loads(k)%race_force(:, 2)
         cage_torque = cage_torque + self%loads(k)%cage_torque
         cage_force = cage_force + self%loads(k)%cage_force
         cage_moment = cage_moment + self%loads(k)%cage_moment
      end do
      ! guide lands: the cage on its land film (at zero eccentricity when centred: the Couette
      ! torque) or metal; the outer race fixed, the inner race's land at its centre
      self%land_torque = 0.0_wp
      self%land_power = 0.0_wp
      if (allocated(self%lands)) then
         if (.not. allocated(self%land)) allocate (self%land(size(self%lands)))
         cage%position = a%cage_position
         cage%velocity = a%cage_velocity
         ! small tilt: the attitude taken as the identity, the angular velocity inertial
         cage%omega = [y(c0 + 2), y(t0 + 5), y(t0 + 6)]
         do k = 1, size(self%lands)
            if (self%lands(k)%race_is_journal) then
               outer%position = a%position
               outer%velocity = a%velocity
               outer%omega = [self%model%speed(2), 0.0_wp, 0.0_wp]
            else
               outer = body_state_t()
               outer%omega = [self%model%speed(1), 0.0_wp, 0.0_wp]
            end if
            call cage_land_contact(self%lands(k), cage, outer, lc)
            self%land(k) = lc
            self%land_torque = self%land_torque + lc%moment_cage(1)
            self%land_power = self%land_power + lc%power + lc%film_loss
            if (self%cage_free) cage_force = cage_force + lc%force_cage
            if (self%cage_free) cage_moment = cage_moment + lc%moment_cage
            if (self%lands(k)%race_is_journal) race_force = race_force + lc%force_race
         end do
      end if
      self%cage_force = cage_force
      self%cage_moment = cage_moment
      dydt(c0 + 1) = y(c0 + 2)
      dydt(c0 + 2) = 0.0_wp
      if (self%constraints%cage%rotation(1)) dydt(c0 + 2) = (cage_torque + self%land_torque)/self%cage_inertia
      dydt(g0 + 1:g0 + 4) = 0.0_wp
      if (self%cage_free) then
         dydt(g0 + 1:g0 + 2) = y(g0 + 3:g0 + 4)
         dydt(g0 + 3:g0 + 4) = cage_force(2:3)/self%cage_mass + self%model%gravity(2:3)
         if (self%adore_whirl) dydt(g0 + 3:g0 + 4) = dydt(g0 + 3:g0 + 4) + &
                                                     whirl_frame_acceleration(y(g0 + 1:g0 + 2), y(g0 + 3:g0 + 4), &
                                                                              self%whirl_blend)
      end if
      dydt(t0 + 1:t0 + 6) = 0.0_wp
      if (self%cage_free) call cage_axial_tilt_rates(self, y(c0 + 2), y(t0 + 1:t0 + 6), cage_force(1), &
                                                     cage_moment, dydt(t0 + 1:t0 + 6))
      dydt(r0 + 1:r0 + 3) = a%velocity
      dydt(r0 + 4:r0 + 6) = merge((self%force + race_force)/self%race_mass + self%model%gravity, 0.0_wp, &
                                  self%constraints%inner%translation)
      dydt = self%time_scale*dydt
      flag = DERIV_OK
      if (.not. all(ieee_is_finite(dydt))) then
         self%failure_reason = "roller equations of motion: non-finite rates (a roller or race outside the "// &
                               "contact model's range)"
         flag = DERIV_FAIL
      end if

   contains

      !> Roller k's loads (self%loads(k)) and rates (its part of dydt) at the state y; run by
      !> one thread per roller.
      subroutine roller_rates(k)
         integer, intent(in) :: k
         type(roller_pose_t) :: p
         type(race_pose_t) :: ak
         real(wp) :: h
         integer :: i0

         i0 = ROLLER_SIZE*(k - 1)
         p = roller_pose(y, k)
         ! constrained roller degrees of freedom (report 4.4.6): axial position, tilt and skew
         ! held with their rates
         if (.not. self%constraints%elements%translation(1)) p%xdot = 0.0_wp
         if (.not. self%constraints%elements%rotation(3)) p%tiltdot = 0.0_wp
         if (.not. self%constraints%elements%rotation(2)) p%skewdot = 0.0_wp
         ak = a
         ak%pocket_azimuth = self%pocket_azimuth(k) + y(c0 + 1)
         call roller_loads(self%model, p, ak, self%loads(k))
         associate (f => self%loads(k)%force, mo => self%loads(k)%moment, d => dydt(i0 + 1:i0 + ROLLER_SIZE))
            h = ia*y(i0 + R_SPIN) - it*p%phidot
            d(R_X) = p%xdot
            d(R_R) = p%rdot
            d(R_PHI) = p%phidot
            d(R_XDOT) = f(1)/m
            d(R_RDOT) = f(2)/m + p%r*p%phidot**2
            d(R_PHIDOT) = (f(3)/m - 2.0_wp*p%rdot*p%phidot)/p%r
            d(R_TILT) = p%tiltdot
            d(R_SKEW) = p%skewdot
            d(R_WT) = (mo(3) + h*y(i0 + R_WR))/it
            d(R_WR) = (mo(2) - h*y(i0 + R_WT))/it
            d(R_SPIN) = mo(1)/ia
            if (.not. self%constraints%elements%translation(1)) d(R_X:R_XDOT:R_XDOT - R_X) = 0.0_wp
            if (.not. self%constraints%elements%rotation(3)) d([R_TILT, R_WT]) = 0.0_wp
            if (.not. self%constraints%elements%rotation(2)) d([R_SKEW, R_WR]) = 0.0_wp
         end associate
      end subroutine roller_rates

   end subroutine roller_system_eval

   !> The free cage's axial motion and tilt (module header): the rates of (x_c, a_y, a_z, x_c',
   !> w_y, w_z) = v (m, rad, m/s, rad/s) at spin w_c (rad/s) under the axial force f_x (N)
   !> and the moments m (N m, about the cage centre, inertial), per second.
   pure subroutine cage_axial_tilt_rates(self, w_c, v, f_x, m, d)
      class(roller_system_t), intent(in) :: self
      real(wp), intent(in) :: w_c, v(6), f_x, m(3)
      real(wp), intent(out) :: d(6)
      real(wp) :: h
      h = self%cage_inertia*w_c
      d(1) = v(4)
      d(2) = v(6)
      d(3) = -v(5)
      d(4) = f_x/self%cage_mass + self%model%gravity(1)
      d(5) = (m(2) - h*v(6))/self%cage_inertia_t
      d(6) = (m(3) + h*v(5))/self%cage_inertia_t
   end subroutine cage_axial_tilt_rates

   !> The integrator's error scale of each unknown (report 4.4.5: ADORE's dimensionless
   !> variables): positions l (m), velocities l/tt, orbital angle and its rate as the arc
   !> length at the pitch radius, tilt and skew as the displacement at the roller's ends,
   !> angular velocities 1/tt, the cage angle 1.
   pure function roller_error_scale(n, l, tt, pitch_radius, half_length) result(scale)
      integer, intent(in) :: n
      real(wp), intent(in) :: l, tt, pitch_radius, half_length
      real(wp) :: scale(roller_state_size(n))
      integer :: k
      do k = 0, n - 1
         scale(ROLLER_SIZE*k + 1:ROLLER_SIZE*(k + 1)) = [l, l, l/pitch_radius, l/tt, l/tt, l/(tt*pitch_radius), &
                                                         l/half_length, l/half_length, 1.0_wp/tt, 1.0_wp/tt, &
                                                         1.0_wp/tt]
      end do
      scale(ROLLER_SIZE*n + 1:) = [1.0_wp, 1.0_wp/tt, l, l, l, l/tt, l/tt, l/tt, l, l, l/tt, l/tt, &
                                   l, l/pitch_radius, l/pitch_radius, l/tt, 1.0_wp/tt, 1.0_wp/tt]
   end function roller_error_scale

   !> The dynamics of roller bearing b (mounted geometry g, slice model qs) from its step-0
   !> start: azimuth, radius, tilt, orbital speed and spin (relative to the orbit frame) of
   !> each roller, inner race y, z (u), the cage's angle (rad) and speed (rad/s); the pockets
   !> centred on the rollers' start azimuths at cage angle 0.  cage_free: the cage centre
   !> integrated in y, z from cage_start = (y, z, vy, vz) (m, m/s; report 4.4.4's start whirl).  The integrator has the deck's
   !> Rec 2.1 steps and error limit (tau), the deck's Rec 1 INT METHOD as ball_int_method reads
   !> it (5: the IMEX ARK4(3)6L with each roller's block of the Jacobian implicit; int_method:
   !> another adore_dynamics_integrator method) and the packed state y at tau = 0.  An
   !> explicit method is not advised: the loaded rollers' spin is stiff (traction time
   !> constant ~0.6 us, 0.009 tau) and Dormand-Prince 5(4) at the deck's error limit holds it
   !> off its traction balance (docs/dynamics.md, Roller dynamics).
   subroutine start_roller_dynamics(b, g, qs, azimuth, r, tilt, orbital_speed, spin, u, cage_angle, cage_speed, &
                                    sys, it, y, error, int_method, damping, cage_free, cage_start, axial, race_axial)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(roller_qs_bearing_t), intent(in) :: qs
      real(wp), intent(in) :: azimuth(:), r(:), tilt(:), orbital_speed(:), spin(:), u(2), cage_angle, cage_speed
      type(roller_system_t), intent(out) :: sys
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: int_method
      real(wp), intent(in), optional :: damping
      logical, intent(in), optional :: cage_free
      real(wp), intent(in), optional :: cage_start(4)
      !> the flanged start's roller axial positions and inner race axial position (m; default 0)
      real(wp), intent(in), optional :: axial(:), race_axial
      real(wp) :: scales(3)
      type(integrator_settings_t) :: settings
      integer :: k, n

      n = b%n_elements
      call scale_factors(b%d, b%mass(BODY_ELEMENT), b%force, scales, error)
      if (allocated(error)) return
      if (.not. (b%moments(1, BODY_CAGE) > 0.0_wp .and. b%mass(BODY_INNER) > 0.0_wp)) then
         call input_error(error, "roller dynamics: the cage needs a moment of inertia and the inner race a mass")
         return
      end if
      sys%n = n
      sys%time_scale = scales(3)
      sys%inertia = [b%moments(1, BODY_ELEMENT), b%moments(2, BODY_ELEMENT)]
      sys%cage_inertia = b%moments(1, BODY_CAGE)
      sys%cage_mass = b%mass(BODY_CAGE)
      sys%cage_inertia_t = b%moments(2, BODY_CAGE)
      if (present(cage_free)) sys%cage_free = cage_free
      if (sys%cage_free .and. .not. (sys%cage_mass > 0.0_wp .and. sys%cage_inertia_t > 0.0_wp)) then
         call input_error(error, "roller dynamics: a free cage needs a mass and a transverse moment of inertia")
         return
      end if
      sys%race_mass = b%mass(BODY_INNER)
      sys%force = b%force
      sys%constraints = default_constraints(.true.)
      sys%pocket_azimuth = azimuth
      associate (md => sys%model)
         md%qs = qs
         md%law = b%race_traction
         md%damping = 2.5e-6_wp
         if (present(damping)) md%damping = damping
         md%speed = [b%speed_outer, b%speed_inner]
         md%gravity = b%gravity
         md%mass = b%mass(BODY_ELEMENT)
         md%pocket_clearance = b%pocket_clearance(1)
         md%pocket_length = b%roller%roller_length - sum(b%roller%corner_radius)
         md%pocket_k = line_stiffness(contact_modulus(b%material(BODY_ELEMENT)%modulus, &
                                                      b%material(BODY_ELEMENT)%poisson, &
                                                      b%material(BODY_CAGE)%modulus, b%material(BODY_CAGE)%poisson), &
                                      0.5_wp*b%d)
         md%pocket_friction = b%cage_friction(1)
         md%pocket_type = b%roller%pocket_type
         md%pocket_radius = 0.5_wp*b%dm
      end associate
      if (any(b%roller%flange)) then
         call check_flanges(b, error)
         if (allocated(error)) return
         associate (r => b%roller)
            sys%model%flanges = roller_flanges(b%d, r%roller_length, r%corner_radius, r%end_radius, r%flange, &
                                               r%flange_height, r%flange_angle, r%flange_clearance, [qs%r_o, qs%r_i], &
                                               [qs%e_o, qs%e_i])
         end associate
      end if
      sys%lands = guide_land_pairs(b, g, b%temperature)
      if (size(sys%lands) > 0) sys%whirl_blend = 0.1_wp*minval(sys%lands%clearance)
      allocate (y(roller_state_size(n)))
      y = 0.0_wp
      do k = 1, n
         associate (v => y(ROLLER_SIZE*(k - 1) + 1:ROLLER_SIZE*k))
            v(R_R) = r(k)
            v(R_PHI) = azimuth(k)
            v(R_PHIDOT) = orbital_speed(k)
            v(R_TILT) = tilt(k)
            if (present(axial)) v(R_X) = axial(k)
            ! a roller orbiting with a steady tilt turns about e_r at -phidot gamma
            v(R_WR) = -orbital_speed(k)*tilt(k)
            v(R_SPIN) = spin(k) + orbital_speed(k)
         end associate
      end do
      y(ROLLER_SIZE*n + CAGE_OFFSET + 1:ROLLER_SIZE*n + CAGE_OFFSET + 2) = [cage_angle, cage_speed]
      y(ROLLER_SIZE*n + RACE_OFFSET + 2:ROLLER_SIZE*n + RACE_OFFSET + 3) = u
      if (present(race_axial)) y(ROLLER_SIZE*n + RACE_OFFSET + 1) = race_axial
      if (sys%cage_free .and. present(cage_start)) &
         y(ROLLER_SIZE*n + CAGE_POS_OFFSET + 1:ROLLER_SIZE*n + CAGE_POS_OFFSET + 4) = cage_start
      associate (c => b%controls)
         settings = integrator_settings_t(int_method=ball_int_method(c%int_method), h_initial=c%step_initial, h_min=c%step_min, &
                                          h_max=c%step_max, error_limit=c%error_limit, rel_weight=0.0_wp, &
                                          accept_at_h_min=.true., forced_err_cap=ADORE_FORCED_ERR_CAP)
      end associate
      if (present(int_method)) settings%int_method = int_method
      if (settings%int_method == INT_METHOD_ARK436) then
         ! as the ball's IMEX tuning (adore_dynamics_ball_system): a new block Jacobian every 20
         ! steps, safety 0.8
         settings%jacobian_every = 20
         settings%safety = 0.8_wp
      end if
      ! a free cage: a new block Jacobian every step (a kept one lags the pocket contacts
      ! opening and closing; measured with ROS34PW2, the free cage's method under the deck's
      ! INT METHOD 5: docs/rollers.md, "The free roller cage's pocket episode")
      if (sys%cage_free) settings%jacobian_every = 1
      call it%init(size(y), settings, error, scale=roller_error_scale(n, scales(1), scales(3), 0.5_wp*b%dm, &
                                                                       0.5_wp*b%roller%roller_length))
      if (allocated(error)) return
      ! each roller's block of the Jacobian (the linearly implicit methods only): a roller
      ! touches the races and the cage, never another roller
      call it%set_jacobian_blocks([(ROLLER_SIZE*(k - 1) + 1, k=1, n)], ROLLER_SIZE, [(k, k=1, ROLLER_SIZE)], error)
   end subroutine start_roller_dynamics

   !> What the flange contact model (adore_contact_roller_flange) cannot honour is an input
   !> error: a flat roller end (conformal flat-on-flat contact), a contact point of the
   !> centred aligned roller off the flange face (its height D/2 - R_e sin theta outside
   !> [0, flange height]) or off the end's spherical cap (R_e sin theta > D/2 - r_c), a
   !> roller end sphere that is not within the roller (R_e < L/2 is a ball end, refused).
   subroutine check_flanges(b, error)
      type(bearing_t), intent(in) :: b
      type(error_type), allocatable, intent(out) :: error
      character(len=160) :: msg
      real(wp) :: hc, off
      integer :: j
      associate (r => b%roller)
         if (.not. (r%end_radius > 0.0_wp)) then
            call input_error(error, "Rec 5B.2: a flange needs a spherical roller end (roller_end_radius > 0); "// &
                             "a flat end on a flange is a conformal contact the flange model does not have")
            return
         end if
         if (r%end_radius < 0.5_wp*r%roller_length) then
            call input_error(error, "Rec 5B.2: roller_end_radius below half the roller length is not modelled")
            return
         end if
         do j = 1, 2
            if (.not. any(r%flange(:, j))) cycle
            off = r%end_radius*sin(r%flange_angle(j))
            hc = 0.5_wp*b%d - off
            if (hc < 0.0_wp .or. hc > r%flange_height(j) .or. off > 0.5_wp*b%d - maxval(r%corner_radius)) then
               write (msg, "(a,es10.3,a,es10.3,a,es10.3,a)") " flange: the end sphere meets the face at height ", hc, &
                  " m (D/2 - R_e sin theta), off the flange (height ", r%flange_height(j), &
                  " m) or the end's cap (R_e sin theta = ", off, " m)"
               call input_error(error, "Rec 5B.2: the "//trim(merge("outer", "inner", j == 1))//trim(msg))
               return
            end if
         end do
      end associate
   end subroutine check_flanges

end module adore_dynamics_roller_system
