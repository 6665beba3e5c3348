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
   use adore_core_strings, only: itoa
   use adore_core_threads, only: team_t, team_threads, team_note, wall_seconds
   use adore_core_rotation, only: quat_from_rotation_vector, quat_matrix
   use adore_model_bearing, only: BODY_CAGE, BODY_ELEMENT, BODY_INNER, bearing_t
   use adore_model_condition, only: dof_constraints_t, default_constraints
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, new_bearing_state, state_size, pack_state, unpack_state, &
                                        pack_rates, &
                                        RACE_OUTER, RACE_INNER, BODY_SIZE
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, guide_land_pairs
   use adore_dynamics_ball_motion, only: ball_bearing_rates
   use adore_dynamics_integrator, only: derivative_t, integrator_t, integrator_settings_t, DERIV_OK, DERIV_FAIL, &
                                        DERIV_REJECT_STEP, INT_METHOD_DP54, INT_METHOD_ARK436, ADORE_FORCED_ERR_CAP
   use adore_quasistatic_ball_start, only: ball_start_t, start_contact_load
   use adore_cage_step0, only: cage_step0_t
   use adore_model_scales, only: scale_factors
   implicit none
   private

   public :: ball_system_t, new_ball_system, initial_ball_state, state_error_scale, start_ball_dynamics
   public :: ball_int_method, BALL_JACOBIAN_COLUMNS, BALL_SWITCH_STIFFNESS, BALL_SPIN_COLUMNS

   !> The columns of each ball's block of the Jacobian of the linearly implicit methods (of its
   !> 13 state values): position and velocity, where the race contacts' normal stiffness and
   !> damping act, and angular velocity, where the traction's slip damping acts
   !> (docs/integrator.md, "The stiff-aware method")
   integer, parameter :: BALL_JACOBIAN_COLUMNS(9) = [1, 2, 3, 4, 5, 6, 11, 12, 13]

   !> A ball's angular velocity in its block of 13 (the traction's slip damping acts there)
   integer, parameter :: BALL_SPIN_COLUMNS(3) = [11, 12, 13]

   !> The deck's IMEX method gives way to ROS34PW2 (start_ball_dynamics' method_switch) when a
   !> ball's spin relaxation rate -d(omega')/d(omega) (the first block Jacobian's diagonal)
   !> times the Rec 2.1 minimum step exceeds this: the traction then damps the spin within a
   !> minimum step.  Measured at step 0 (2026-11-27, issue #28): Appendix C 0.037, the grid's
   !> light loads below 0.003, a 1 kN deep-groove at 3 000 rpm 0.03; the heavily loaded fast
   !> runs whose every step the IMEX method forced at the minimum 17-364, and these run
   !> unforced on ROS34PW2 (docs/integrator.md, "Step control")
   real(wp), parameter :: BALL_SWITCH_STIFFNESS = 1.0_wp

   !> The ball bearing's equations of motion dy/dtau (integrator's derivative_t).
   type, extends(derivative_t) :: ball_system_t
      type(bearing_t) :: bearing
      type(mounted_geometry_t) :: geometry
      real(wp) :: time_scale = 1.0_wp        !< T (s) of one unit of tau
      logical :: traction = .true.           !< race contact traction on (off: normal loads only)
      !> pocket and guide-land contacts on (default): the pockets keep the balls' spacing
      !> (without them the balls bunch and the ball set's rotating unbalance distorts the
      !> load distribution); the guide lands' metallic contact is on, their short-bearing film
      !> only with land_film (docs/cage.md, "Cage dynamics")
      logical :: cage = .true.
      !> the guide lands' hydrodynamic (Ocvirk) film.  Off by default: with it the Appendix C
      !> cage ends in the film's half-frequency whirl (oil whip, ~700 N of film force on the
      !> inner race), which the report's figures 21-22 and step-2500 print do not show
      !> (docs/cage.md, "Cage dynamics")
      logical :: land_film = .false.
      !> normal damping of the ball/race contacts, beta (s) of ball_bearing_loads' damping:
      !> Kraemer's stiffness-proportional rolling-bearing damping at its lower end (docs/
      !> dynamics.md, "Contact damping"); 0 for a conservative model (energy tests)
      real(wp) :: contact_damping = 2.5e-6_wp
      !> the cage's degrees of freedom (report 4.4.6): .true. (default) constrains its
      !> translation and tilt - it stays centred on the bearing axis and turns about its own
      !> axis, driven by its pockets; .false. frees all six (docs/cage.md, "Cage dynamics":
      !> the free cage of Appendix C either whips on its land films or rides its lands)
      logical :: cage_spin_only = .true.
      !> a free cage's mass centre in ADORE's whirl coordinates (adore_dynamics_cage_whirl;
      !> run option cage_whirl=adore, the default) instead of Newton's inertial equations
      logical :: adore_whirl = .false.
      !> (m) within it of the bearing axis ADORE's whirl terms fade to Newton's
      !> (whirl_frame_acceleration's r_blend; the whirl angle is undefined on the axis): a
      !> tenth of the smallest guide land's radial clearance, else of the pockets' (set by
      !> start_ball_dynamics; docs/cage.md, "The cage's whirl frame")
      real(wp) :: whirl_blend = 0.0_wp
      !> the bodies' degrees of freedom (adore_model_condition; the bearing kind sets them
      !> from its operating condition); not allocated: those of cage_spin_only
      type(dof_constraints_t), allocatable :: constraints
      !> two-dimensional race traction (ball_bearing_loads' two_d; report eqs 2-3: the slip
      !> vector along and across the rolling direction): on by default, it damps the balls'
      !> motion across the rolling direction that the 1-D traction leaves free
      !> (docs/dynamics.md, "Ball gyroscopic moment")
      logical :: traction_2d = .true.
      !> the balls' gyroscopic moments resisted by the races without slip (Jones; Harris &
      !> Kotzalas; add_gyroscopic_restraint): the classical assumption, and what ADORE 5.0's
      !> Appendix C print shows (docs/dynamics.md, "Ball gyroscopic moment")
      logical :: gyro_restraint = .true.
      !> the balls in the orbit-following coordinates of the report's eq 54 in the packed
      !> state (adore_state_bearing_state's orbit): (x, r, phi) and their rates instead of
      !> inertial position and velocity (issue #30); the physics is the same
      logical :: orbit_frame = .false.
      !> the race contacts' EHD rolling resistance (Houpert, Harris & Kotzalas; ball_bearing_loads'
      !> rolling): off by default, as in ADORE 5.0 (docs/tribology.md, "Rolling resistance")
      logical :: rolling_resistance = .false.
      !> (2, n): when allocated, every contact's Hertz stiffness frozen at these values
      !> (N/m**1.5) instead of K(alpha): a verification option, the normal loads then derive
      !> from an energy (fortran/tests/test_dynamics.f90)
      real(wp), allocatable :: frozen_stiffness(:, :)
      !> (7, K) when allocated: the bulk temperatures the race contacts' lubricant is
      !> evaluated at instead of the state's (ball_bearing_loads' lubricant_temperature; the
      !> thermal model holds them at the initial ones, docs/thermal.md)
      real(wp), allocatable :: lubricant_temperature(:)
      !> threads of each evaluation's ball contacts (run option threads, adore_core_threads;
      !> ball_bearing_loads: the same rates bit for bit on any number)
      integer :: threads = 1
      !> the choice between those threads and one, call by call, measured (adore_core_threads)
      type(team_t) :: team
      type(bearing_state_t) :: state, rates  !< scratch of eval
      type(ball_bearing_loads_t) :: loads    !< the loads of the last evaluation
      integer :: calls = 0                   !< evaluations so far
      type(error_type), allocatable :: failure   !< why the last evaluation returned DERIV_FAIL
      !> the border of the integrator's arrowhead Jacobian (packed indices; set by
      !> start_ball_dynamics: the inner race's translation and a free cage's unknowns), whose
      !> rows border_shares gives per ball (docs/integrator.md, "The stiff-aware method")
      integer, allocatable :: jacobian_border(:)
   contains
      procedure :: eval => ball_system_eval
      procedure :: border_shares => ball_border_shares
   end type ball_system_t

contains

   !> The system of bearing b in mounted geometry g, time scale time_scale (s per unit
   !> tau), with (default) or without race traction, with or without (default) the cage
   !> contacts.
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
      integer :: threads
      real(wp) :: start

      self%calls = self%calls + 1
      if (allocated(self%failure_reason)) deallocate (self%failure_reason)   ! only the last eval's reason
      call unpack_state(y, t*self%time_scale, self%state, self%orbit_frame)
      ! the run's threads or one, whichever the last measured windows found faster
      threads = team_threads(self%team, self%threads)
      start = 0.0_wp
      if (self%threads > 1) start = wall_seconds()
      if (allocated(self%frozen_stiffness)) then
         call ball_bearing_rates(self%bearing, self%geometry, self%state, self%rates, self%loads, self%failure, &
                                 self%traction, self%cage, self%frozen_stiffness, self%traction_2d, self%gyro_restraint, &
                                 self%contact_damping, self%land_film, self%cage_spin_only, &
                                 rolling=self%rolling_resistance, lubricant_temperature=self%lubricant_temperature, &
                                 adore_whirl=self%adore_whirl, threads=threads, &
                                 whirl_blend=self%whirl_blend)
      else if (allocated(self%constraints)) then
         call ball_bearing_rates(self%bearing, self%geometry, self%state, self%rates, self%loads, self%failure, &
                                 self%traction, self%cage, two_d=self%traction_2d, &
                                 gyro_restraint=self%gyro_restraint, damping=self%contact_damping, &
                                 land_film=self%land_film, constraints=self%constraints, &
                                 rolling=self%rolling_resistance, lubricant_temperature=self%lubricant_temperature, &
                                 adore_whirl=self%adore_whirl, threads=threads, &
                                 whirl_blend=self%whirl_blend)
      else
         call ball_bearing_rates(self%bearing, self%geometry, self%state, self%rates, self%loads, self%failure, &
                                 self%traction, self%cage, two_d=self%traction_2d, &
                                 gyro_restraint=self%gyro_restraint, damping=self%contact_damping, &
                                 land_film=self%land_film, cage_spin_only=self%cage_spin_only, &
                                 rolling=self%rolling_resistance, lubricant_temperature=self%lubricant_temperature, &
                                 adore_whirl=self%adore_whirl, threads=threads, &
                                 whirl_blend=self%whirl_blend)
      end if
      if (self%threads > 1) call team_note(self%team, self%threads, wall_seconds() - start)
      if (allocated(self%failure)) then
         ! a state outside the contact models' range (e.g. a stage of a too long step that
         ! drove a ball deep into a race): the integrator retries smaller (report 4.4.12);
         ! at the start of a step or at the minimum step the run stops with this reason
         flag = DERIV_REJECT_STEP
         self%failure_reason = self%failure%message
         dydt = 0.0_wp
         return
      end if
      call pack_rates(self%state, self%rates, dydt, self%orbit_frame)
      dydt = self%time_scale*dydt
      flag = DERIV_OK
      ! an abnormal cage contact (report 4.4.12): the integrator retries with a smaller step
      if (self%loads%abnormal) then
         flag = DERIV_REJECT_STEP
         call abnormal_cage_contact(self%loads, self%failure_reason)
      end if
      if (.not. all(ieee_is_finite(dydt))) then
         call engine_error(self%failure, "equations of motion: non-finite rates of "// &
                           trim(body_name(size(self%state%elements), findloc(ieee_is_finite(dydt), .false., 1)))// &
                           " (a body or contact state is outside the model's range)")
         self%failure_reason = self%failure%message
         flag = DERIV_FAIL
      end if
   end subroutine ball_system_eval

   !> Each ball's share of the last evaluation's rates of the Jacobian's border unknowns
   !> (jacobian_border; per unit of tau), shares(i, k) for border unknown i and ball k: the
   !> border's rates are linear in the loads on its bodies, which are sums over the balls of
   !> what each ball's contacts put on them (action and reaction) plus loads of the border
   !> bodies alone.  The inner race's velocity rows: T F_k / m_race, F_k the force of ball k's
   !> contacts on the race (ball_bearing_loads' race_shares); a free cage's velocity rows
   !> T F_k / m_cage and angular-velocity rows T (R**T M_k)_i / I_i (Euler's equations are
   !> linear in the moment), F_k, M_k its pocket contact's force and moment on the cage.
   !> Positions and attitudes (their rates are velocities) and the race's prescribed rotation:
   !> 0.  ok = .false. when the last evaluation has no loads.
   subroutine ball_border_shares(self, shares, ok)
      class(ball_system_t), intent(in) :: self
      real(wp), intent(out) :: shares(:, :)
      logical, intent(out) :: ok
      integer :: i, k, n, body, comp
      real(wp) :: rot(3, 3)
      type(dof_constraints_t) :: dof
      shares = 0.0_wp
      n = size(self%state%elements)
      ok = allocated(self%jacobian_border) .and. allocated(self%loads%race_shares) .and. &
           .not. allocated(self%failure_reason)
      if (ok) ok = size(shares, 1) == size(self%jacobian_border) .and. size(shares, 2) == n .and. &
                   size(self%loads%race_shares, 2) == n
      if (.not. ok) return
      rot = quat_matrix(self%state%cage%attitude)
      if (allocated(self%constraints)) then
         dof = self%constraints
      else
         dof = default_constraints(self%cage_spin_only)
      end if
      associate (b => self%bearing, tt => self%time_scale)
         do i = 1, size(self%jacobian_border)
            body = (self%jacobian_border(i) - 1)/BODY_SIZE + 1
            comp = self%jacobian_border(i) - BODY_SIZE*(body - 1)
            if (body == n + 3 .and. comp >= 4 .and. comp <= 6) then
               if (.not. dof%inner%translation(comp - 3)) cycle
               do k = 1, n
                  shares(i, k) = tt*self%loads%race_shares(RACE_INNER, k)%force(comp - 3)/b%mass(BODY_INNER)
               end do
            else if (body == n + 1 .and. allocated(self%loads%pockets)) then
               if (comp >= 4 .and. comp <= 6) then
                  if (.not. dof%cage%translation(comp - 3)) cycle
                  do k = 1, n
                     shares(i, k) = tt*self%loads%pockets(k)%force_cage(comp - 3)/b%mass(BODY_CAGE)
                  end do
               else if (comp >= 11) then
                  if (.not. dof%cage%rotation(comp - 10)) cycle
                  do k = 1, n
                     shares(i, k) = tt*dot_product(self%loads%pockets(k)%moment_cage, rot(:, comp - 10))/ &
                                    b%moments(comp - 10, BODY_CAGE)
                  end do
               end if
            end if
         end do
      end associate
   end subroutine ball_border_shares

   !> The body of unknown i of a packed state of n balls (adore_state_bearing_state's order):
   !> "ball k", "the cage", "the outer race", "the inner race" or "the temperatures".
   pure function body_name(n, i) result(name)
      integer, intent(in) :: n, i
      character(len=32) :: name
      select case ((i - 1)/BODY_SIZE + 1)
      case (:0)
         name = "the state"
      case default
         write (name, "(a,i0)") "ball ", (i - 1)/BODY_SIZE + 1
         if ((i - 1)/BODY_SIZE + 1 == n + 1) name = "the cage"
         if ((i - 1)/BODY_SIZE + 1 == n + 2) name = "the outer race"
         if ((i - 1)/BODY_SIZE + 1 == n + 3) name = "the inner race"
         if ((i - 1)/BODY_SIZE + 1 > n + 3) name = "the temperatures"
      end select
   end function body_name

   !> The state of ball bearing b (mounted geometry g) at the start of the dynamics: its
   !> step-0 start (equilibrium and ball speeds) and cage state (module header).  Positions
   !> in the bearing frame (origin at the outer race centre).
   function initial_ball_state(b, g, start, cage) result(st)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_start_t), intent(in) :: start
      type(cage_step0_t), intent(in) :: cage
      type(bearing_state_t) :: st
      real(wp) :: phi, e_r(3), e_t(3), r
      integer :: k

      st = new_bearing_state(b%n_elements)
      st%temperature = b%temperature
      associate (e => start%equilibrium, kin => start%kinematics, c => cage%state)
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

   !> Which cage contact of loads is abnormal (report 4.4.12): "ball k's pocket" or "guide
   !> land k" (a subroutine: no deferred-length function result, adore_core_strings).
   subroutine abnormal_cage_contact(loads, text)
      type(ball_bearing_loads_t), intent(in) :: loads
      character(len=:), allocatable, intent(out) :: text
      integer :: k
      text = "an abnormal cage contact"
      if (allocated(loads%pockets)) then
         do k = 1, size(loads%pockets)
            if (loads%pockets(k)%abnormal) then
               text = text//": ball "//itoa(k)//"'s pocket"
               return
            end if
         end do
      end if
      if (allocated(loads%lands)) then
         do k = 1, size(loads%lands)
            if (loads%lands(k)%abnormal) then
               text = text//": guide land "//itoa(k)
               return
            end if
         end do
      end if
   end subroutine abnormal_cage_contact

   !> The integration method of the ball dynamics for the deck's Rec 1 int_method (INT METHOD):
   !> 5, the value of both of the report's decks, is the additive (IMEX) Runge-Kutta method
   !> ARK4(3)6L[2]SA with the balls' blocks of the Jacobian taken implicitly (docs/integrator.md,
   !> "INT METHOD"); other codes as the integrator reads them.
   pure integer function ball_int_method(deck_code) result(method)
      integer, intent(in) :: deck_code
      method = deck_code
      if (deck_code == INT_METHOD_DP54) method = INT_METHOD_ARK436
   end function ball_int_method

   !> The integrator's error scale of each unknown of a packed state of n elements: the
   !> report's dimensionless variables (4.4.5: ADORE integrates in units of the echo's
   !> scales) - positions in L (m), velocities in L/T, quaternions in 1, angular velocities
   !> in 1/T, temperatures in K.  orbit_radius (m), when present: the elements are packed in
   !> the orbit frame, their azimuth scaled L / orbit_radius and its rate L / (T orbit_radius)
   !> (the same arc length as a position).
   pure function state_error_scale(n, l, tt, orbit_radius) result(scale)
      integer, intent(in) :: n
      real(wp), intent(in) :: l, tt
      real(wp), intent(in), optional :: orbit_radius
      real(wp) :: scale(state_size(n))
      integer :: i
      do i = 0, n + 2
         scale(BODY_SIZE*i + 1:BODY_SIZE*(i + 1)) = [l, l, l, l/tt, l/tt, l/tt, 1.0_wp, 1.0_wp, 1.0_wp, 1.0_wp, &
                                                     1.0_wp/tt, 1.0_wp/tt, 1.0_wp/tt]
         if (present(orbit_radius) .and. i < n) then
            scale(BODY_SIZE*i + 3) = l/orbit_radius
            scale(BODY_SIZE*i + 6) = l/(tt*orbit_radius)
         end if
      end do
      scale(BODY_SIZE*(n + 3) + 1:) = 1.0_wp
   end function state_error_scale

   !> The dynamics of ball bearing b (mounted geometry g) from its step-0 start and cage
   !> state: the system (time scale from the echo's scales, adore_model_scales; input error
   !> for a bearing without applied load, whose scales are undefined), the integrator with the
   !> deck's Rec 1 int_method and Rec 2.1 steps and error limit (in tau; the minimum step is
   !> accepted when the error test still fails there, as ADORE's Appendix C statistics
   !> show: docs/dynamics.md), the packed initial state y at tau = 0.  traction: race
   !> traction on (default); two_d: the two-dimensional race traction (default .true.).
   subroutine start_ball_dynamics(b, g, start, cage, sys, it, y, error, traction, two_d, orbit_frame, int_method, &
                                  cage_free, adore_whirl, method_switch, balance_tolerance)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_start_t), intent(in) :: start
      type(cage_step0_t), intent(in) :: cage
      type(ball_system_t), intent(out) :: sys
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: traction, two_d
      !> the balls in the orbit-following frame (ball_system_t%orbit_frame; default .false.)
      logical, intent(in), optional :: orbit_frame
      !> the integration method (adore_dynamics_integrator's INT_METHOD_*) instead of the
      !> deck's (ball_int_method of Rec 1 int_method)
      integer, intent(in), optional :: int_method
      !> the cage free in all six DOFs with its guide lands' film (report 4.4.6; run option
      !> cage=free): cage_spin_only = .false., land_film = .true.; absent or .false.: the defaults
      logical, intent(in), optional :: cage_free
      !> a free cage in ADORE's whirl coordinates (ball_system_t%adore_whirl; default .false.)
      logical, intent(in), optional :: adore_whirl
      !> the deck's IMEX method gives way to ROS34PW2 from the first step when the balls' spin
      !> relaxes faster than the Rec 2.1 minimum step can follow (BALL_SWITCH_STIFFNESS; the
      !> deck's method, not one a run option names); default .false.
      logical, intent(in), optional :: method_switch
      !> the integrator's power-balance control (integrator_settings_t%balance_tolerance, run
      !> option balance_tolerance); default 0: off
      real(wp), intent(in), optional :: balance_tolerance
      real(wp) :: scales(3), l, tt
      integer :: k
      type(bearing_state_t) :: st
      type(integrator_settings_t) :: settings

      ! the load scale: the applied load or, when larger, the start's largest contact load
      ! (adore_model_scales; docs/operating-points.md)
      call scale_factors(b%d, b%mass(BODY_ELEMENT), b%force, scales, error, b%moment, 0.5_wp*b%dm, &
                         start_contact_load(start))
      if (allocated(error)) return
      l = scales(1)
      tt = scales(3)
      sys = new_ball_system(b, g, tt, traction)
      if (present(two_d)) sys%traction_2d = two_d
      if (present(orbit_frame)) sys%orbit_frame = orbit_frame
      if (present(adore_whirl)) sys%adore_whirl = adore_whirl
      sys%whirl_blend = whirl_blend_radius(b, g)
      if (present(cage_free)) then
         if (cage_free) then
            sys%cage_spin_only = .false.
            sys%land_film = .true.
         end if
      end if
      allocate (y(state_size(b%n_elements)))
      st = initial_ball_state(b, g, start, cage)
      if (sys%cage_spin_only) then
         ! the constrained cage (report 4.4.6): centred on the bearing axis, untilted, turning
         ! at its start speed (the 4.4.4 whirl needs its free translation)
         st%cage%position(2:3) = 0.0_wp
         st%cage%velocity = 0.0_wp
         st%cage%attitude = quat_from_rotation_vector([0.0_wp, 0.0_wp, 0.0_wp])
      end if
      call pack_state(st, y, sys%orbit_frame)
      associate (c => b%controls)
         settings = integrator_settings_t(int_method=ball_int_method(c%int_method), h_initial=c%step_initial, &
                                          h_min=c%step_min, h_max=c%step_max, error_limit=c%error_limit, &
                                          rel_weight=0.0_wp, accept_at_h_min=.true., &
                                          forced_err_cap=ADORE_FORCED_ERR_CAP)
      end associate
      if (present(int_method)) settings%int_method = int_method
      if (present(balance_tolerance)) settings%balance_tolerance = balance_tolerance
      if (settings%int_method == INT_METHOD_ARK436) then
         ! the IMEX method's tuning (docs/integrator.md, "The stiff-aware method"): a new arrowhead
         ! Jacobian every 10 steps (and after a rejected step; with the inner race in the border
         ! a stale J lets the radial deck's balls oscillate on their contacts: 27 mW of contact
         ! damping at 20, 0.2 mW at 10, 27 mW before the border); safety factor 0.8 (0.9 rejected 29 % of the attempts)
         settings%jacobian_every = 10
         settings%safety = 0.8_wp
         if (present(method_switch)) then
            if (method_switch) then
               settings%switch_stiffness = BALL_SWITCH_STIFFNESS
               settings%switch_columns = BALL_SPIN_COLUMNS
            end if
         end if
      end if
      if (sys%orbit_frame) then
         call it%init(size(y), settings, error, scale=state_error_scale(b%n_elements, l, tt, 0.5_wp*b%dm))
      else
         call it%init(size(y), settings, error, scale=state_error_scale(b%n_elements, l, tt))
      end if
      if (allocated(error)) return
      ! the linearly implicit methods' arrowhead Jacobian: each ball's block (the balls touch
      ! the races and the cage, never another ball), bordered by the inner race's translation
      ! (every ball touches it; issue #28: the balls' contact mode against the race is then
      ! implicit too).  A free cage stays explicit: bordered too (13 more columns), the deep-
      ! groove radial deck's 3 revolutions took 38 272 calls with 96 mW of contact damping and
      ! closure -28 % against 24 597, 0.22 mW and -0.45 % without; Appendix C 23 398 calls
      ! against 19 496 (docs/integrator.md, "The arrowhead")
      sys%jacobian_border = [(BODY_SIZE*(b%n_elements + 2) + k, k=1, 6)]
      call it%set_jacobian_blocks([(BODY_SIZE*(k - 1) + 1, k=1, b%n_elements)], BODY_SIZE, BALL_JACOBIAN_COLUMNS, &
                                  error, border=sys%jacobian_border)
   end subroutine start_ball_dynamics

   !> The radius (m) about the bearing axis within which a free cage's whirl coordinates fade
   !> to Newton's (ball_system_t%whirl_blend): a tenth of the smallest radial clearance of its
   !> guide lands at the deck's temperatures (adore_forces_ball_bearing's land pairs), for a
   !> cage without lands a tenth of the pockets' radial clearance (Rec 7.1, diametral).
   function whirl_blend_radius(b, g) result(r)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      real(wp) :: r
      r = 0.0_wp
      if (b%n_lands > 0) then
         associate (pairs => guide_land_pairs(b, g, b%temperature))
            if (size(pairs) > 0) r = 0.1_wp*minval(pairs%clearance)
         end associate
      end if
      if (.not. r > 0.0_wp) r = 0.1_wp*0.5_wp*maxval(b%pocket_clearance)
   end function whirl_blend_radius

end module adore_dynamics_ball_system
