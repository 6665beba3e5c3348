!> Body loads of a ball bearing at any state: every ball/race contact's normal and traction
!> forces and moments on both bodies, the heat of each contact, gravity and the applied
!> load of the inner race, from (bearing model, mounted geometry, state).
!>
!> The one force assembly for the quasi-static start's checks and the equations of motion
!> ([Dynamics]).  Per ball and race (adore_contact_ball_race): the Hertz load Q acts on the
!> ball along -n through the contact point P (no moment about the ball centre) and on the
!> race along +n at P.  The traction of the run's model (adore_forces_race_contact:
!> the deck's traction curve, an ADRX7 table or the EHD film traction of model 3; report
!> 2.1) acts along the rolling direction e_t, distributed over the major axis: on the race
!> dF e_t at Q(psi) = B + D/2 (cos psi n + sin psi e_m), on the ball the opposite, so the
!> ball feels the moment -D/2 (F_cos n + F_sin e_m) x e_t about its centre (F_cos, F_sin:
!> the sums of dF cos psi and dF sin psi; the second is the spin moment about the normal).
!> With the two-dimensional traction (two_d; report eq 5) the traction also has a part
!> dF_m along e_m(psi) across the rolling direction (contact_traction_t%cross_force): on the
!> race along e_m(psi) at Q(psi), on the ball the opposite with the moment -D/2 F_m (n x e_m).
!> Gravity (Rec 11) acts on every body; the applied force and moment of Rec 9.1.1 on the
!> inner race.  Inertial forces are not loads here: the equations of motion carry them.
!> Cage contacts (the `cage` flag, default on): every ball against its cylindrical pocket
!> (adore_contact_cage_pocket; pocket k at cage-frame azimuth 2 pi (k-1)/n, as the balls of
!> the start) and the cage against each guide land of Rec 7.0/7.2 (adore_contact_cage_land),
!> with the lubricant's viscosity at the cage temperature when the deck has a lubricant and
!> the friction coefficients of Rec 10.5.1B/10.5.2B (bearing_t%cage_friction, 0.05 in both
!> decks; docs/dynamics.md); an abnormal cage contact
!> (report 4.4.12) sets `abnormal` for the integrator to reject the step.
!> Moments are about each body's mass centre, inertial components.  Units SI.
module adore_forces_ball_bearing
   use adore_core_threads, only: team_join
   use adore_core_strings, only: itoa
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_core_constants, only: pi
   use adore_core_rotation, only: cross, quat_matrix
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, TEMP_CAGE
   use adore_cage_step0, only: land_contact, land_contact_t, GUIDE_OUTER
   use adore_contact_cage_pocket, only: cage_pocket_pair_t, cage_pocket_geometry_t, cage_pocket_pair, &
                                        cage_pocket_contact
   use adore_contact_cage_land, only: cage_land_pair_t, cage_land_geometry_t, cage_land_contact
   use adore_contact_line_slices, only: contact_modulus
   use adore_tribology_film, only: dynamic_viscosity
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, body_state_t, RACE_OUTER, RACE_INNER
   use adore_contact_ball_race, only: ball_race_pair_t, ball_race_geometry_t, ball_race_contact, planar_contact
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_traction, SIDE_OUTER, SIDE_INNER, &
                                   contact_kinematics
   use adore_forces_race_contact, only: PRINT_GAUSS, EHD_GAUSS, ehd_traction_model, lubricant_film, &
                                           fluid_fraction, fluid_contact, mixed_traction, ehd_traction, &
                                           rolling_resistance
   implicit none
   private

   public :: body_load_t, ball_bearing_loads_t, ball_race_pairs, ball_bearing_loads, ball_pocket_pair, &
             guide_land_pairs, add_gyroscopic_restraint, total_power_loss

   !> Force (N) and moment about the mass centre (N m) on one body, inertial components.
   type :: body_load_t
      real(wp) :: force(3) = 0.0_wp
      real(wp) :: moment(3) = 0.0_wp
   end type body_load_t

   !> Loads on every body and what each race contact does; (1, k) outer, (2, k) inner
   !> contact of ball k.
   type :: ball_bearing_loads_t
      type(body_load_t), allocatable :: elements(:)
      type(body_load_t) :: cage
      type(body_load_t) :: races(2)                         !< RACE_OUTER, RACE_INNER
      !> (2, n): what ball k's contacts put on race j (force N; moment N m about the race
      !> centre, without the gyroscopic restraint's), the terms of races(j)'s sum: the
      !> integrator's border rows of its Jacobian (adore_dynamics_ball_system%border_shares)
      type(body_load_t), allocatable :: race_shares(:, :)
      type(ball_race_geometry_t), allocatable :: contacts(:, :)
      type(contact_traction_t), allocatable :: traction(:, :)  !< zero where unloaded or traction off
      real(wp), allocatable :: heat(:, :)                   !< contact power loss (W)
      !> work rate of the race contacts' normal damping, sum of beta k d(delta)/dt**2 (W, >= 0)
      real(wp) :: damping_power = 0.0_wp
      type(cage_pocket_geometry_t), allocatable :: pockets(:)  !< ball k in pocket k (cage flag on)
      type(cage_land_geometry_t), allocatable :: lands(:)      !< per guide land (cage flag on)
      logical :: abnormal = .false.                         !< an abnormal cage contact (4.4.12)
   end type ball_bearing_loads_t

   !> What one ball/race contact puts on its race (force N, moments about the race centre
   !> N m, in the order the serial sum adds them): kept per contact so that the races' loads
   !> are summed after the balls, in ball order, whatever thread computed each ball.
   type :: race_share_t
      logical :: loaded = .false.           !< the contact carries load
      logical :: rolled = .false.           !< moment_rolling set (EHD rolling resistance)
      logical :: tractive = .false.         !< the traction's force and moments set
      real(wp) :: damping_power = 0.0_wp    !< the contact damping's work rate (W)
      real(wp) :: force_normal(3) = 0.0_wp, moment_normal(3) = 0.0_wp, moment_rolling(3) = 0.0_wp
      real(wp) :: force_traction(3) = 0.0_wp, arm_traction(3) = 0.0_wp, moment_traction(3) = 0.0_wp
   end type race_share_t

   !> A ball's error (its race contacts' traction model), the first in ball order returned.
   type :: ball_error_t
      type(error_type), allocatable :: error
   end type ball_error_t

contains

   !> The ball/race pairs (outer, inner) of ball bearing b in its mounted geometry g.
   pure function ball_race_pairs(b, g) result(p)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_race_pair_t) :: p(2)
      p(RACE_OUTER) = ball_race_pair_t(SIDE_OUTER, g%element_diameter, b%dm, b%ball%f_o, g%groove_radius(1), &
                                       g%groove_centre(:, 1), b%material(BODY_ELEMENT)%modulus, &
                                       b%material(BODY_ELEMENT)%poisson, b%material(BODY_OUTER)%modulus, &
                                       b%material(BODY_OUTER)%poisson)
      p(RACE_INNER) = ball_race_pair_t(SIDE_INNER, g%element_diameter, b%dm, b%ball%f_i, g%groove_radius(2), &
                                       g%groove_centre(:, 2), b%material(BODY_ELEMENT)%modulus, &
                                       b%material(BODY_ELEMENT)%poisson, b%material(BODY_INNER)%modulus, &
                                       b%material(BODY_INNER)%poisson)
   end function ball_race_pairs

   !> Lubricant dynamic viscosity (Pa s) at the cage temperature temperature(TEMP_CAGE) (K),
   !> 0 when the deck has no lubricant (dry cage contacts).
   pure real(wp) function cage_viscosity(b, temperature)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      cage_viscosity = 0.0_wp
      if (b%lubricant_code /= 0) cage_viscosity = dynamic_viscosity(b%lubricant, temperature(TEMP_CAGE), 0.0_wp)
   end function cage_viscosity

   !> The ball/pocket pair of ball bearing b (mounted geometry g) at bulk temperatures
   !> temperature (K): ball diameter, Rec 7.1 pocket clearance, pocket radius (OD + ID)/4,
   !> ball and cage materials, lubricant at the cage temperature, friction of Rec 10.5.1B.
   pure function ball_pocket_pair(b, g, temperature) result(p)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      real(wp), intent(in) :: temperature(:)
      type(cage_pocket_pair_t) :: p
      p = cage_pocket_pair(g%element_diameter, b%pocket_clearance(1), 0.25_wp*(b%cage_od + b%cage_id), &
                           b%material(BODY_ELEMENT)%modulus, b%material(BODY_ELEMENT)%poisson, &
                           b%material(BODY_CAGE)%modulus, b%material(BODY_CAGE)%poisson, &
                           cage_viscosity(b, temperature), b%cage_friction(1))
   end function ball_pocket_pair

   !> The guide-land pairs of bearing b (Rec 7.0/7.2.n) in mounted geometry g: radial
   !> clearance = half the effective play of adore_cage_step0 with the guiding race's
   !> raceway growth (mounting plus thermal), lubricant at the cage temperature, friction of
   !> Rec 10.5.2B, the lubricant layer b%land_oil_layer (run option land_oil).
   pure function guide_land_pairs(b, g, temperature) result(p)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      real(wp), intent(in) :: temperature(:)
      type(cage_land_pair_t), allocatable :: p(:)
      real(wp) :: growth(2), zero(3)
      type(land_contact_t) :: lc
      integer :: k, race_body

      growth = [-g%mounting%outer_raceway_shrink + g%thermal_growth(1), &
                g%mounting%inner_raceway_growth + g%thermal_growth(2)]
      zero = 0.0_wp
      allocate (p(b%n_lands))
      do k = 1, b%n_lands
         associate (land => b%lands(k))
            race_body = merge(BODY_OUTER, BODY_INNER, land%guide == GUIDE_OUTER)
            p(k)%race_is_journal = land%guide /= GUIDE_OUTER
            p(k)%radius = 0.5_wp*land%diameter
            p(k)%width = land%width
            lc = land_contact(land, zero, zero, growth(land%guide))
            p(k)%clearance = 0.5_wp*lc%effective_play
            p(k)%e_star = contact_modulus(b%material(BODY_CAGE)%modulus, b%material(BODY_CAGE)%poisson, &
                                          b%material(race_body)%modulus, b%material(race_body)%poisson)
            p(k)%viscosity = cage_viscosity(b, temperature)
            p(k)%friction = b%cage_friction(2)
            p(k)%oil_layer = b%land_oil_layer
         end associate
      end do
   end function guide_land_pairs

   !> Total power loss (W) of the loads of one evaluation: the race contacts' heat plus the
   !> friction power of the pocket and guide-land contacts and the guide-land films' viscous
   !> loss when the cage contacts are on (the report's total counts its cage contacts' loss:
   !> Appendix D step 0, docs/dynamics.md).
   pure real(wp) function total_power_loss(loads)
      type(ball_bearing_loads_t), intent(in) :: loads
      total_power_loss = sum(loads%heat)
      if (allocated(loads%pockets)) total_power_loss = total_power_loss + sum(loads%pockets%power)
      if (allocated(loads%lands)) total_power_loss = total_power_loss + sum(loads%lands%power) + &
                                                     sum(loads%lands%film_loss)
   end function total_power_loss

   !> The balls' gyroscopic moments resisted by friction without sliding (Jones 1960; Harris &
   !> Kotzalas, Rolling Bearing Analysis, 5th ed., vol. 2, ch. 2, "ball gyroscopic moment"):
   !> a ball whose angular velocity w (inertial) orbits with it at the orbital rate w_m about
   !> the bearing axis x needs the moment M_g = J w_m (e_x x w) (J its moment of inertia, N m).
   !> The classical assumption is that the race contacts supply it by static friction, with
   !> no slip and so no heat; this adds M_g to every ball touching a race and its reaction -M_g
   !> to the races it touches, shared in proportion to the normal loads.  M_g is normal to w
   !> and to the race speeds (along x): it does no work on either body (energy neutral), and
   !> the contacts' moments still sum to zero (action = reaction).  Without it the 2-D
   !> traction resists M_g only by sliding across the rolling direction (docs/dynamics.md,
   !> "Ball gyroscopic moment").  j_ball: the ball's moment of inertia (kg m**2).
   subroutine add_gyroscopic_restraint(s, j_ball, loads)
      type(bearing_state_t), intent(in) :: s
      real(wp), intent(in) :: j_ball
      type(ball_bearing_loads_t), intent(inout) :: loads
      real(wp) :: m_g(3)
      integer :: k
      logical :: found

      do k = 1, size(s%elements)
         call gyroscopic_moment(s%elements(k), quat_matrix(s%elements(k)%attitude), j_ball, loads%contacts(:, k), &
                                m_g, found)
         if (.not. found) cycle
         loads%elements(k)%moment = loads%elements(k)%moment + m_g
         call add_gyroscopic_reaction(loads, k, m_g)
      end do
   end subroutine add_gyroscopic_restraint

   !> The gyroscopic moment m_g (N m) of ball e (attitude matrix ball_rot, moment of inertia
   !> j_ball, kg m**2) resisted by its race contacts c (add_gyroscopic_restraint); found false
   !> (m_g not set) when the ball touches no race or sits on the bearing axis.
   pure subroutine gyroscopic_moment(e, ball_rot, j_ball, c, m_g, found)
      type(body_state_t), intent(in) :: e
      real(wp), intent(in) :: ball_rot(3, 3), j_ball
      type(ball_race_geometry_t), intent(in) :: c(2)
      real(wp), intent(out) :: m_g(3)
      logical, intent(out) :: found
      real(wp) :: w(3), r2, w_m

      found = .false.
      if (.not. (c(1)%load + c(2)%load > 0.0_wp)) return
      r2 = e%position(2)**2 + e%position(3)**2
      if (.not. (r2 > 0.0_wp)) return
      w_m = (e%position(2)*e%velocity(3) - e%position(3)*e%velocity(2))/r2
      w = matmul(ball_rot, e%omega)
      m_g = j_ball*w_m*[0.0_wp, -w(3), w(2)]
      found = .true.
   end subroutine gyroscopic_moment

   !> The races' reaction -m_g to ball k's gyroscopic moment m_g (N m), shared in proportion
   !> to its contacts' normal loads (add_gyroscopic_restraint).
   pure subroutine add_gyroscopic_reaction(loads, k, m_g)
      type(ball_bearing_loads_t), intent(inout) :: loads
      integer, intent(in) :: k
      real(wp), intent(in) :: m_g(3)
      real(wp) :: q_sum
      integer :: j
      q_sum = loads%contacts(1, k)%load + loads%contacts(2, k)%load
      do j = 1, 2
         if (loads%contacts(j, k)%load > 0.0_wp) &
            loads%races(j)%moment = loads%races(j)%moment - m_g*loads%contacts(j, k)%load/q_sum
      end do
   end subroutine add_gyroscopic_reaction

   !> Loads on every body of ball bearing b (mounted geometry g) at state s (module
   !> header).  traction (default .true.): include the race contacts' traction and heat;
   !> cage (default .true.): include the pocket and guide-land contacts.
   !> stiffness(2, n), when given, replaces each contact's Hertz K(alpha) (N/m**1.5; a
   !> verification option: with K frozen the normal loads derive from an energy).
   !> two_d (default .false.): the traction of the slip vector along AND across the rolling
   !> direction (report eq 5's two-dimensional slip) instead of the one-dimensional model
   !> along the rolling direction (eq 1): at every node of the major axis the traction of
   !> the run's model at the slip vector's length acts along it (the contact_traction and
   !> ehd_traction procedures with the contact's transverse_coeff; docs/dynamics.md).
   !> reference (default .false.): the EHD traction by its reference quadrature
   !> (EHD_GAUSS x EHD_STRIP points, ehd_contact_traction) instead of the fast one - for
   !> tests; the law's traction has one quadrature.
   !> damping (s, default 0): normal contact damping of the ball/race contacts, a viscous
   !> force beta k delta_dot along the normal with k = dQ/d(delta) = 1.5 Q / delta the
   !> contact's tangent stiffness and delta_dot the approach rate of ball and race; the normal
   !> force Q + beta k delta_dot never pulls (>= 0).  Stiffness-proportional damping with
   !> beta = 2.5e-6 s is the lower end of Kraemer's rolling-bearing damping d = (0.25 ...
   !> 2.5)e-5 k (E. Kraemer, Dynamics of Rotors and Foundations, Springer 1993, ch. 6);
   !> docs/dynamics.md, "Contact damping".
   !> land_film (default .true.): the guide lands' short-bearing film (adore_contact_cage_land);
   !> .false. keeps only their metallic contact (docs/cage.md, "Cage dynamics").
   !> rolling (default .false.): the race contacts' EHD rolling resistance (rolling_couple).
   !> lubricant_temperature (K, the TEMP_* order; default: s%temperature): the bulk
   !> temperatures the race contacts' lubricant (film, EHD traction, rolling resistance) is
   !> evaluated at - the thermal model holds them at the initial ones, as ADORE 5.0 does
   !> (report 5.3, 7 rec. 1; docs/thermal.md, "Traction and the temperatures").
   !> threads (default 1): the balls' contacts and the cage's guide-land contacts on that many
   !> OpenMP threads (run option threads, adore_core_threads); every sum over the balls and
   !> the lands is taken afterwards in ball and land order, so the loads are the same bit for
   !> bit on any number of threads.
   !> Input errors of the traction model (e.g. no EHD film) come back in error (the first
   !> ball's in ball order).
   subroutine ball_bearing_loads(b, g, s, loads, error, traction, cage, stiffness, two_d, reference, damping, &
                                 land_film, rolling, lubricant_temperature, threads, gyro_inertia)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(out) :: loads
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: traction, cage
      real(wp), intent(in), optional :: stiffness(:, :)
      logical, intent(in), optional :: two_d, reference
      real(wp), intent(in), optional :: damping
      logical, intent(in), optional :: land_film
      logical, intent(in), optional :: rolling
      real(wp), intent(in), optional :: lubricant_temperature(:)
      integer, intent(in), optional :: threads
      real(wp), intent(in), optional :: gyro_inertia
      type(ball_race_pair_t) :: pairs(2)
      type(cage_pocket_pair_t) :: pp
      type(race_share_t) :: share(2, size(s%elements))
      type(ball_error_t) :: failed(size(s%elements))
      real(wp) :: gyro(3, size(s%elements))
      logical :: gyrating(size(s%elements))
      real(wp) :: rho, beta
      real(wp) :: t_lub(size(s%temperature)), race_rot(3, 3, 2)
      type(cage_land_pair_t), allocatable :: lp(:)
      integer :: n, k, j, n_threads, n_lands, arrived
      logical :: with_traction, with_2d, with_reference, with_rolling, with_cage, with_gyro

      with_traction = .true.
      if (present(traction)) with_traction = traction
      with_2d = .false.
      if (present(two_d)) with_2d = two_d
      with_reference = .false.
      if (present(reference)) with_reference = reference
      beta = 0.0_wp
      if (present(damping)) beta = damping
      with_rolling = .false.
      if (present(rolling)) with_rolling = rolling
      with_cage = .true.
      if (present(cage)) with_cage = cage
      with_gyro = present(gyro_inertia)
      n_threads = 1
      if (present(threads)) n_threads = max(threads, 1)
      t_lub = s%temperature
      if (present(lubricant_temperature)) t_lub = lubricant_temperature
      n = size(s%elements)
      pairs = ball_race_pairs(b, g)
      rho = 0.5_wp*g%element_diameter
      allocate (loads%elements(n), loads%contacts(2, n), loads%traction(2, n))
      allocate (loads%heat(2, n), source=0.0_wp)
      do k = 1, n
         loads%elements(k)%force = b%mass(BODY_ELEMENT)*b%gravity
      end do
      loads%cage%force = b%mass(BODY_CAGE)*b%gravity
      loads%races(RACE_OUTER)%force = b%mass(BODY_OUTER)*b%gravity
      loads%races(RACE_INNER)%force = b%mass(BODY_INNER)*b%gravity + b%force
      loads%races(RACE_INNER)%moment = b%moment

      ! the attitude matrices once per race (every contact of a race uses its own)
      do j = 1, 2
         race_rot(:, :, j) = quat_matrix(s%races(j)%attitude)
      end do
      n_lands = 0
      if (with_cage) then
         pp = ball_pocket_pair(b, g, s%temperature)
         allocate (loads%pockets(n))
         lp = guide_land_pairs(b, g, s%temperature)
         if (present(land_film)) then
            if (.not. land_film) lp%viscosity = 0.0_wp       ! metallic contact only
         end if
         n_lands = size(lp)
         allocate (loads%lands(n_lands))
      end if
      ! every ball's race and pocket contacts, each ball's into its own slots (its loads, its
      ! contacts, its share of the races' loads, its error), and the cage's guide-land contacts
      ! (after the balls, each into its own slot; they depend on the cage and the races only):
      ! on n_threads threads (run option threads, adore_core_threads) or without OpenMP on one,
      ! the same numbers bit for bit
      ! (dynamic: the first thread starts on the items while the others wake; team_join: it
      ! usually reaches the closing barrier last, so it does not sleep there)
      if (n_threads > 1) then
         arrived = 0
         !$omp parallel num_threads(n_threads) default(shared) private(k)
         !$omp do schedule(dynamic, 1)
         do k = 1, n + n_lands
            call loop_item(k)
         end do
         !$omp end do nowait
         call team_join(arrived)
         !$omp end parallel
      else
         do k = 1, n + n_lands
            call loop_item(k)
         end do
      end if
      ! the first failed ball in ball order (as a serial loop would stop there)
      do k = 1, n
         if (allocated(failed(k)%error)) then
            call move_alloc(failed(k)%error, error)
            return
         end if
      end do
      ! the sums over the balls, in ball order (the races' loads and the damping's work), and
      ! each ball's terms of them
      allocate (loads%race_shares(2, n))
      do k = 1, n
         do j = 1, 2
            associate (r => share(j, k), rs => loads%race_shares(j, k))
               if (.not. r%loaded) cycle
               loads%damping_power = loads%damping_power + r%damping_power
               loads%races(j)%force = loads%races(j)%force + r%force_normal
               loads%races(j)%moment = loads%races(j)%moment + r%moment_normal
               rs%force = r%force_normal
               rs%moment = r%moment_normal
               if (r%rolled) then
                  loads%races(j)%moment = loads%races(j)%moment + r%moment_rolling
                  rs%moment = rs%moment + r%moment_rolling
               end if
               if (r%tractive) then
                  loads%races(j)%force = loads%races(j)%force + r%force_traction
                  loads%races(j)%moment = loads%races(j)%moment + r%arm_traction + r%moment_traction
                  rs%force = rs%force + r%force_traction
                  rs%moment = rs%moment + r%arm_traction + r%moment_traction
               end if
            end associate
         end do
      end do
      if (with_cage) call add_cage_contacts()
      if (.not. with_gyro) return
      ! the races' reactions to the balls' gyroscopic moments, in ball order
      do k = 1, n
         if (gyrating(k)) call add_gyroscopic_reaction(loads, k, gyro(:, k))
      end do

   contains

      !> Ball k's race contacts and (with_cage) its pocket contact: its loads, contacts,
      !> traction and heat into its slots of loads, what its contacts put on the races into
      !> share(:, k), an error into failed(k) (module header).  Run by one thread per ball.
      subroutine ball_contacts(k)
         integer, intent(in) :: k
         type(ball_race_contact_t) :: cj
         type(contact_traction_t) :: t
         real(wp) :: f_n(3), f_t(3), m_t(3), sums(6), q_n, rate, ball_rot(3, 3), arm(3)
         integer :: j

         gyrating(k) = .false.
         ball_rot = quat_matrix(s%elements(k)%attitude)
         do j = 1, 2
            if (present(stiffness)) then
               call ball_race_contact(pairs(j), s%elements(k), s%races(j), loads%contacts(j, k), stiffness(j, k), &
                                      race_rot(:, :, j), ball_rot)
            else
               call ball_race_contact(pairs(j), s%elements(k), s%races(j), loads%contacts(j, k), &
                                      race_rot=race_rot(:, :, j), ball_rot=ball_rot)
            end if
            associate (c => loads%contacts(j, k), ball => s%elements(k)%position, race => s%races(j)%position, &
                       r => share(j, k))
               if (.not. (c%load > 0.0_wp)) cycle
               call normal_force(c, j, k, q_n, rate)
               f_n = q_n*c%normal
               r%loaded = .true.
               r%damping_power = (q_n - c%load)*rate
               loads%elements(k)%force = loads%elements(k)%force - f_n
               r%force_normal = f_n
               r%moment_normal = cross(c%point - race, f_n)
               cj = planar_contact(pairs(j), c)
               if (with_rolling) then
                  call rolling_couple(j, k, cj, loads%contacts(j, k), ball_rot, r, failed(k)%error)
                  if (allocated(failed(k)%error)) return
               end if
               if (.not. with_traction) cycle
               call race_traction(j, cj, c%transverse_coeff, c%ellipse%semi_minor, c%ellipse%max_pressure, t, &
                                  failed(k)%error)
               if (allocated(failed(k)%error)) then   ! name the contact (the integrator adds time and step)
                  failed(k)%error%message = "ball "//itoa(k)//", "//trim(merge("outer", "inner", j == RACE_OUTER))// &
                                            " race contact: "//failed(k)%error%message
                  return
               end if
               ! the traction along the rolling direction and (two-dimensional only) across it
               sums = [t%force, t%force_cos, t%force_sin, t%cross_force]
               loads%traction(j, k) = t
               loads%heat(j, k) = loads%heat(j, k) + t%power
               ! on the race: along e_t at the nodes, and along e_m(psi) = -sin(psi) n + cos(psi) e_m;
               ! about the ball centre: D/2 [(F_cos n + F_sin e_m) x e_t + F_m (n x e_m)]
               f_t = sums(1)*c%rolling + sums(5)*c%transverse - sums(6)*c%normal
               m_t = rho*(cross(sums(2)*c%normal + sums(3)*c%transverse, c%rolling) + &
                          sums(4)*cross(c%normal, c%transverse))
               r%tractive = .true.
               r%force_traction = f_t
               arm = ball - race      ! a named vector: the associated sections' difference is a heap temporary
               r%arm_traction = cross(arm, f_t)
               r%moment_traction = m_t
               loads%elements(k)%force = loads%elements(k)%force - f_t
               loads%elements(k)%moment = loads%elements(k)%moment - m_t
            end associate
         end do
         if (with_cage) then
            ! the ball in its pocket (pocket k at cage-frame azimuth 2 pi (k-1)/n)
            call cage_pocket_contact(pp, 2.0_wp*pi*(k - 1)/n, s%elements(k), s%cage, loads%pockets(k))
            loads%elements(k)%force = loads%elements(k)%force + loads%pockets(k)%force_ball
            loads%elements(k)%moment = loads%elements(k)%moment + loads%pockets(k)%moment_ball
         end if
         ! the ball's gyroscopic moment (add_gyroscopic_restraint), the races' reaction later
         if (with_gyro) then
            call gyroscopic_moment(s%elements(k), ball_rot, gyro_inertia, loads%contacts(:, k), gyro(:, k), gyrating(k))
            if (gyrating(k)) loads%elements(k)%moment = loads%elements(k)%moment + gyro(:, k)
         end if
      end subroutine ball_contacts

      !> Normal force q_n (N) of race contact c (race j, ball k): the Hertz load plus the
      !> contact damping beta (1.5 Q / delta) d(delta)/dt, never negative; rate: the approach
      !> rate d(delta)/dt (m/s; 0 without damping, where it is not needed).
      subroutine normal_force(c, j, k, q_n, rate)
         type(ball_race_geometry_t), intent(in) :: c
         integer, intent(in) :: j, k
         real(wp), intent(out) :: q_n, rate
         real(wp) :: v_rel(3)
         q_n = c%load
         rate = 0.0_wp
         if (beta <= 0.0_wp .or. .not. (c%delta > 0.0_wp)) return
         associate (race => s%races(j), ball => s%elements(k))
            v_rel = ball%velocity - race%velocity - &
                    cross(matmul(race_rot(:, :, j), race%omega), ball%position - race%position)
         end associate
         rate = dot_product(v_rel, c%normal)
         q_n = max(c%load + beta*1.5_wp*c%load/c%delta*rate, 0.0_wp)
      end subroutine normal_force

      !> The EHD rolling resistance of race contact c (race j, ball k; planar form cj; ball_rot
      !> the ball's attitude matrix) as a couple about the contact's major axis e_m: M = F_R R_x
      !> opposing the relative rolling rate w = (omega_ball - omega_race).e_m (smoothly through 0:
      !> w / sqrt(w**2 + w0**2), w0 = 1e-3 u / R_x), -M on the ball and +M on the race (into
      !> the contact's share r); its heat M w enters the contact's heat (rolling_resistance;
      !> docs/tribology.md, "Rolling resistance").
      subroutine rolling_couple(j, k, cj, c, ball_rot, r, error)
         integer, intent(in) :: j, k
         type(ball_race_contact_t), intent(in) :: cj
         type(ball_race_geometry_t), intent(in) :: c
         real(wp), intent(in) :: ball_rot(3, 3)
         type(race_share_t), intent(inout) :: r
         type(error_type), allocatable, intent(out) :: error
         type(contact_traction_t) :: tk
         real(wp) :: f_r, w, w0, m_r
         call contact_kinematics(cj, tk)
         call rolling_resistance(b, t_lub, tk, c%ellipse%semi_major/c%ellipse%semi_minor, c%load, &
                                 c%ellipse%max_pressure, merge(BODY_OUTER, BODY_INNER, j == RACE_OUTER), f_r, error)
         if (allocated(error)) return
         if (.not. (f_r > 0.0_wp .and. tk%rx > 0.0_wp)) return
         associate (ball => s%elements(k), race => s%races(j))
            w = dot_product(matmul(ball_rot, ball%omega) - matmul(race_rot(:, :, j), race%omega), c%transverse)
         end associate
         w0 = 1.0e-3_wp*abs(tk%rolling_speed)/tk%rx
         m_r = f_r*tk%rx*w/sqrt(w*w + w0*w0)
         loads%elements(k)%moment = loads%elements(k)%moment - m_r*c%transverse
         r%rolled = .true.
         r%moment_rolling = m_r*c%transverse
         loads%heat(j, k) = loads%heat(j, k) + m_r*w
      end subroutine rolling_couple

      !> The cage's sums over the pockets (ball order) and the guide-land contacts (module
      !> header); the pockets' contacts themselves are each ball's (ball_contacts).
      !> Item k of the loop over the contacts: ball k's (k <= n), else guide land k - n's.
      subroutine loop_item(k)
         integer, intent(in) :: k
         if (k <= n) then
            call ball_contacts(k)
         else
            call guide_land(k - n)
         end if
      end subroutine loop_item

      !> Guide land k's contact of cage and race (adore_contact_cage_land) into loads%lands(k).
      !> Run by one thread per land, after the balls.
      subroutine guide_land(k)
         integer, intent(in) :: k
         integer :: j
         j = b%lands(k)%guide        ! GUIDE_OUTER/INNER = RACE_OUTER/INNER
         call cage_land_contact(lp(k), s%cage, s%races(j), loads%lands(k))
      end subroutine guide_land

      !> The pockets' and the guide lands' loads on the cage and the races, in ball and land order.
      subroutine add_cage_contacts()
         integer :: k, j

         do k = 1, n
            associate (c => loads%pockets(k))
               loads%cage%force = loads%cage%force + c%force_cage
               loads%cage%moment = loads%cage%moment + c%moment_cage
               loads%abnormal = loads%abnormal .or. c%abnormal
            end associate
         end do
         do k = 1, n_lands
            j = b%lands(k)%guide        ! GUIDE_OUTER/INNER = RACE_OUTER/INNER
            associate (c => loads%lands(k))
               loads%cage%force = loads%cage%force + c%force_cage
               loads%cage%moment = loads%cage%moment + c%moment_cage
               loads%races(j)%force = loads%races(j)%force + c%force_race
               loads%races(j)%moment = loads%races(j)%moment + c%moment_race
               loads%abnormal = loads%abnormal .or. c%abnormal
            end associate
         end do
      end subroutine add_cage_contacts

      !> Traction of race contact j of ball k (planar form cj, transverse slip coefficients
      !> tc, m/s; semi-minor axis b_minor, m; Hertz pressure p_h, Pa) by the run's model: the
      !> law, or the EHD film traction with the film of the current state (report 2.6) at
      !> the lubricant temperatures t_lub; one- or two-dimensional (with_2d: tc used), by the fast
      !> or (with_reference) the reference EHD quadrature.  The film needs only the
      !> contact's centre kinematics (entraining speed, R_x, centre slip).
      subroutine race_traction(j, cj, tc, b_minor, p_h, t, error)
         integer, intent(in) :: j
         type(ball_race_contact_t), intent(in) :: cj
         real(wp), intent(in) :: tc(3), b_minor, p_h
         type(contact_traction_t), intent(out) :: t
         type(error_type), allocatable, intent(out) :: error
         type(contact_traction_t) :: tk, t_curve
         real(wp) :: h, phi, f
         integer :: race

         race = merge(BODY_OUTER, BODY_INNER, j == RACE_OUTER)
         h = 0.0_wp
         phi = 0.0_wp
         if (ehd_traction_model(b)) then
            call contact_kinematics(cj, tk)
            call lubricant_film(b, t_lub, tk, cj%a/b_minor, cj%load, p_h, race, h, phi, error)
            if (allocated(error)) return
         end if
         f = fluid_fraction(b, h, phi)
         if (f < 1.0_wp) then
            ! the deck's traction curve: traction model 1, or model 3's contacts without an EHD
            ! film (no entraining speed, Gupta's thermal reduction at 0, a film parameter below
            ! boundary_lambda) or in mixed lubrication (f > 0, blended below; docs/tribology.md)
            if (with_2d) then
               ! the slip vector turns across the contact: the EHD traction's nodes per zone
               call contact_traction(cj, b%race_traction, 1.0_wp, EHD_GAUSS, t_curve, error, transverse=tc)
            else
               call contact_traction(cj, b%race_traction, 1.0_wp, PRINT_GAUSS, t_curve, error)
            end if
            if (allocated(error) .or. f == 0.0_wp) then
               t = t_curve
               return
            end if
         end if
         ! the film's traction of the load it carries (f Q at f p_H: the whole contact for a
         ! full film), then in mixed lubrication (boundary_lambda < film parameter <
         ! full_film_lambda) blended with the curve's (docs/tribology.md, "Mixed films")
         if (with_2d) then
            call ehd_traction(b, t_lub, fluid_contact(cj, f), b_minor, race, h*phi, t, error, with_reference, tc, &
                              kinematics=tk)
         else
            call ehd_traction(b, t_lub, fluid_contact(cj, f), b_minor, race, h*phi, t, error, with_reference, &
                              kinematics=tk)
         end if
         if (allocated(error)) return
         if (f < 1.0_wp) t = mixed_traction(f, t, t_curve)
      end subroutine race_traction

   end subroutine ball_bearing_loads

end module adore_forces_ball_bearing
