!> Step 0 of a ball bearing run: mounting, the consistent quasi-static start and the basic
!> fatigue life (ADORE's start-up: ADRA4 equilibrium, initial ball velocities, ADRF1).
!>
!> Everything printed at step 0 that needs no time integration: the ball speeds by
!> minimum contact dissipation (report 4.4.7; with the EHD traction of model 3 when the
!> deck selects it, seeded by the deck curve's minimum) and the race-contact tribology of those
!> speeds (slip, traction coefficient, spin/roll, contact power loss, report 2.1), and,
!> for a lubricated deck, the isothermal central film and its thermal reduction factor
!> (report 2.6; adore_tribology_film), the EHD traction and flash temperature rise (traction
!> model 3), the balls' Archard wear rates (adore_tribology_wear), the basic and Tallian
!> modified lives.  Quantities of later issues (cage contact forces) are not computed here
!> and stay NaN, so the print shows them as not computed.
module adore_start_ball_step0
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER
   use adore_geometry_fits, only: mounting_t
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t, ball_qs_load_t
   use adore_quasistatic_models, only: ball_qs_model
   use adore_quasistatic_ball_kinematics, only: CONTROL_OUTER, CONTROL_INNER, MIN_DISSIPATION, ball_contacts, &
                                                ehd_films_t
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_traction
   use adore_forces_race_contact, only: PRINT_GAUSS, ehd_traction_model, wall_temperature, wall_rheology, &
                                           lubricant_film, fluid_fraction, fluid_contact, mixed_traction, &
                                           ehd_traction, ehd_flash, law_flash, printed_slip
   use adore_quasistatic_ball_start, only: ball_start_t, solve_ball_start, is_loaded
   use adore_cage_step0, only: cage_step0_t, solve_cage_step0, POCKET_BALL
   use adore_life_lundberg_palmgren, only: life_params_t, bearing_life, life_hours
   use adore_life_ball_life, only: ball_basic_life
   use adore_life_tallian, only: ball_race_modified_life
   use adore_tribology_wear, only: archard_wear_rate
   implicit none
   private

   public :: ball_step0_t, solve_ball_step0

   !> Default ball start hypothesis of step 0 (report 4.4.7: minimum dissipation); race
   !> control (CONTROL_OUTER, CONTROL_INNER) is the report's alternative, chosen per run
   !> (solve_ball_step0's start_method; docs/tribology.md for the comparison).
   integer, parameter, public :: BALL_START_METHOD = MIN_DISSIPATION

   !> The step-0 state of a ball bearing.
   type :: ball_step0_t
      type(mounting_t) :: mounting
      !> the mounted geometry at the initial temperatures (the dynamics starts from it)
      type(mounted_geometry_t) :: geometry
      type(ball_start_t) :: start
      !> start hypothesis used: MIN_DISSIPATION, CONTROL_OUTER or CONTROL_INNER
      integer :: start_method = BALL_START_METHOD
      real(wp) :: basic_life_hours = 0.0_wp        !< bearing basic (Lundberg-Palmgren) life (h)
      real(wp) :: basic_life_outer = 0.0_wp        !< outer race (h)
      real(wp) :: basic_life_inner = 0.0_wp        !< inner race (h)
      real(wp) :: modified_life_hours = 0.0_wp     !< bearing modified (Tallian) life (h)
      real(wp) :: inner_weight(3) = 0.0_wp, outer_weight(3) = 0.0_wp   !< race weights (N)
      !> cage state and geometric interactions; axial positions from the outer groove
      !> curvature centre plane (the print's axial frame, see adore_cage_step0)
      type(cage_step0_t) :: cage
      !> the free cage's dynamic start: cage, unless its Rec 9.5.1 centre puts a ball into its
      !> pocket or the cage into a land; then with the centre's offset scaled down until every
      !> gap is open (solve_cage_step0's open_start, cage_start%start_scale)
      type(cage_step0_t) :: cage_start
      ! race-contact tribology, (1, k) outer and (2, k) inner contact of ball k
      real(wp), allocatable :: slip(:, :)          !< printed slip velocity, max |u| at the nodes (m/s)
      real(wp), allocatable :: trac_coeff(:, :)    !< local traction coefficient at the node of the printed slip (-)
      real(wp), allocatable :: spin_roll(:, :)     !< spin to roll ratio (-)
      real(wp), allocatable :: loss(:, :)          !< contact power loss (W), eq (4)
      real(wp), allocatable :: film(:, :)          !< isothermal central film (m); NaN unlubricated
      real(wp), allocatable :: thermal_factor(:, :)  !< inlet thermal reduction factor (-); NaN unlubricated
      real(wp), allocatable :: temp_rise(:, :)     !< average flash temperature rise (K), eqs 35-36; EHD only
      real(wp), allocatable :: contact_temp(:, :)  !< surface (wall) temperature of the contact (K)
      real(wp), allocatable :: sliding(:, :)       !< integral of |u| dQ (N m/s), Archard's load x slip
      !> net traction of the ball on the race along e_t = e_x x e_r, the orbit direction (N)
      real(wp), allocatable :: traction(:, :)
      !> loads of the balls on the outer (:, 1) and inner (:, 2) race: [force x, y, z (N),
      !> moment x, y, z about the origin (N m)], the normal contact loads of the equilibrium
      !> plus the net traction of each contact along e_t at its contact point (section 3)
      real(wp) :: race_loads(6, 2) = 0.0_wp
      !> wear rate of each ball (m**3/s): Archard with the ball's k and hardness over both
      !> race contacts (adore_tribology_wear)
      real(wp), allocatable :: wear(:)
      !> wear rate of the outer (1) and inner (2) race (m**3/s): Archard with the race's k and
      !> hardness over all its contacts (adore_tribology_wear; section 2's ORace/IRace rows)
      real(wp) :: race_wear(2) = 0.0_wp
      real(wp) :: power_loss = 0.0_wp              !< bearing power loss: sum of contact losses (W)
   end type ball_step0_t

contains

   !> Solve step 0 for the ball bearing b (report sections 3.1, 3.2, 4.4.7).
   !>
   !> Race misalignments are prescribed zero (the deck's quasi-static constraint flags are not
   !> identified; both appendix echoes show prescribed misalignment) unless moment_equilibrium
   !> asks for them to be solved (docs/examples.md), ball speeds from the
   !> start hypothesis (default: minimum contact dissipation).
   subroutine solve_ball_step0(b, s, error, start_method, moment_equilibrium, centrifugal_tol)
      type(bearing_t), intent(in) :: b
      type(ball_step0_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error
      !> start hypothesis (report 4.4.7): MIN_DISSIPATION (default), CONTROL_OUTER or
      !> CONTROL_INNER (race control, the report's kAngVel alternative)
      integer, intent(in), optional :: start_method
      !> .true.: the inner race's misalignments about y and z are solved for moment
      !> equilibrium (ADORE kFS4 = kFS5 = 0) instead of prescribed (zero)
      logical, intent(in), optional :: moment_equilibrium
      !> the start's consistency test on the centrifugal forces (adore_quasistatic_ball_start
      !> MECH_TOL by default; tests use a tighter one)
      real(wp), intent(in), optional :: centrifugal_tol

      type(ball_qs_bearing_t) :: qb
      type(mounted_geometry_t) :: geometry
      type(ball_qs_load_t) :: ld
      type(life_params_t) :: lp
      real(wp), allocatable :: lives_o(:), lives_i(:), p_max(:), mu(:), speeds(:)
      real(wp) :: n_o, n_i, m_o, m_i, psi, wi_rpm, wo_rpm, race_centre(3, 2), hours(3)
      real(wp), allocatable :: centres(:, :)

      if (b%n_elements < 1 .or. b%d <= 0.0_wp .or. b%dm <= b%d) then
         call input_error(error, "ball bearing: need at least one ball and 0 < ball diameter < pitch diameter")
         return
      end if
      if (present(start_method)) s%start_method = start_method
      if (all(s%start_method /= [MIN_DISSIPATION, CONTROL_OUTER, CONTROL_INNER])) then
         call input_error(error, "ball start: unknown start hypothesis code")
         return
      end if
      geometry = mount_geometry(b, b%temperature)
      s%geometry = geometry
      s%mounting = geometry%mounting

      qb = ball_qs_model(b, geometry)
      ld%force = b%force
      ld%moment = b%moment
      ld%gravity = b%gravity
      ld%solve_moment = .false.
      if (present(moment_equilibrium)) ld%solve_moment = moment_equilibrium
      ld%misalignment = 0.0_wp
      s%inner_weight = b%mass(BODY_INNER)*b%gravity
      s%outer_weight = b%mass(BODY_OUTER)*b%gravity

      call solve_ball_start(qb, ld, b%speed_outer, b%speed_inner, s%start_method, s%start, error, &
                            b%race_traction, centrifugal_tol=centrifugal_tol)
      if (allocated(error)) return
      ! With both races at rest nothing entrains a film: the start with the deck's curve is
      ! the static solution (no EHD iteration; its films would shrink towards 0 without end).
      if (ehd_traction_model(b) .and. s%start_method == MIN_DISSIPATION .and. &
          (b%speed_outer /= 0.0_wp .or. b%speed_inner /= 0.0_wp)) then
         call ehd_start(error)
         if (allocated(error)) return
      end if
      call contact_tribology(error)
      if (allocated(error)) return
      call traction_race_loads()

      ! basic life, eqs 73-74 and 102 (inner race rotating, outer stationary), and the
      ! Tallian modified life, eqs 77-109: film parameter Lambda = (iso film x thermal
      ! reduction factor) / composite roughness, mu_EHD = the printed traction coefficient,
      ! the races' hoop stress of the mounting (docs/life-model.md, M1-M3); an unloaded or
      ! unlubricated contact counts as no film (M5)
      allocate (lives_o(b%n_elements), lives_i(b%n_elements), p_max(b%n_elements), &
                mu(b%n_elements), speeds(b%n_elements))
      speeds = s%start%kinematics%orbital_speed          ! contiguous (no array temporary)
      wi_rpm = b%speed_inner*30.0_wp/pi
      wo_rpm = b%speed_outer*30.0_wp/pi
      associate (e => s%start%equilibrium)
         call ball_basic_life(b, lp, e%q_o, e%alpha_o, e%q_i, e%alpha_i, speeds, &
                              lives_o, lives_i, n_o, n_i, hours)
         p_max = e%c_o%max_pressure
         mu = no_nan(s%trac_coeff(1, :))
         call ball_race_modified_life(lp, lives_o, n_o, p_max, film_parameter(1), mu, &
                                      s%mounting%outer_hoop_stress, .false., psi, m_o)
         p_max = e%c_i%max_pressure
         mu = no_nan(s%trac_coeff(2, :))
         call ball_race_modified_life(lp, lives_i, n_i, p_max, film_parameter(2), mu, &
                                      s%mounting%inner_hoop_stress, .true., psi, m_i)
      end associate
      s%basic_life_hours = hours(1)
      s%basic_life_outer = hours(2)
      s%basic_life_inner = hours(3)
      s%modified_life_hours = life_hours(bearing_life(m_o, m_i, lp%weibull_e_point), wi_rpm - wo_rpm)

      ! cage (section 4.4.4): ball centres and race centres in the print's axial frame
      associate (e => s%start%equilibrium)
         allocate (centres(3, b%n_elements))
         centres(1, :) = e%x - qb%x_o
         centres(2, :) = -e%r*sin(e%azimuth)
         centres(3, :) = e%r*cos(e%azimuth)
         race_centre(:, 1) = 0.0_wp
         race_centre(:, 2) = [e%u(1), e%u(2), e%u(3)]
         call solve_cage_step0(b%cage_initial, centres, e%azimuth, &
                               sum(s%start%kinematics%orbital_speed)/b%n_elements, b%d, POCKET_BALL, &
                               b%pocket_clearance(1), b%cage_od, b%cage_id, b%lands, race_centre, &
                               [-s%mounting%outer_raceway_shrink, s%mounting%inner_raceway_growth], s%cage, error)
         if (allocated(error)) return
         call solve_cage_step0(b%cage_initial, centres, e%azimuth, &
                               sum(s%start%kinematics%orbital_speed)/b%n_elements, b%d, POCKET_BALL, &
                               b%pocket_clearance(1), b%cage_od, b%cage_id, b%lands, race_centre, &
                               [-s%mounting%outer_raceway_shrink, s%mounting%inner_raceway_growth], s%cage_start, &
                               error, open_start=.true.)
      end associate

   contains

      !> Film parameter Lambda of race j's contacts (0 where the film is not computed).
      function film_parameter(j) result(lam)
         integer, intent(in) :: j
         real(wp) :: lam(b%n_elements)
         lam = no_nan(s%film(j, :)*s%thermal_factor(j, :))/lp%sigma_rms
      end function film_parameter

      !> The not-computed entries (NaN) of v as 0.
      pure function no_nan(v) result(w)
         real(wp), intent(in) :: v(:)
         real(wp) :: w(size(v))
         w = merge(v, 0.0_wp, v == v)
      end function no_nan

      !> The start with the EHD traction (model 3) in the minimum-dissipation search (report
      !> 4.4.7 with the run's own traction model): the films of the current state are held
      !> fixed while the start is re-solved from it, then recomputed, until the films change
      !> by less than 1e-5 relative (the film follows the entraining speed to the power 0.67;
      !> the speeds then move by ~1e-6 relative, far below the printed 4 digits).
      subroutine ehd_start(error)
         type(error_type), allocatable, intent(out) :: error
         type(ehd_films_t), allocatable :: films(:), next(:)
         type(ball_start_t) :: previous
         real(wp) :: change
         integer :: iter
         logical, allocatable :: loaded(:)

         call current_films(films, error)
         if (allocated(error)) return
         do iter = 1, 10
            previous = s%start
            call solve_ball_start(qb, ld, b%speed_outer, b%speed_inner, s%start_method, s%start, error, &
                                  b%race_traction, films, previous, centrifugal_tol)
            if (allocated(error)) return
            call current_films(next, error)
            if (allocated(error)) return
            ! only the loaded balls' films set speeds (unloaded ones follow the cage)
            loaded = is_loaded(s%start%equilibrium%q_i)
            ! relative to the film, or to 1 nm where there is next to none (a shaft at rest:
            ! no entraining speed, no film; 1 nm is far below any surface roughness); the film
            ! weighted by its fluid fraction, which is continuous through the mixed films (a
            ! contact near boundary_lambda does not flip between the film and none)
            change = maxval(film_change(next, films, 1), mask=loaded)
            change = max(change, maxval(film_change(next, films, 2), mask=loaded))
            films = next
            if (change <= 1.0e-5_wp) return
         end do
         call engine_error(error, "ball start: EHD films and ball speeds did not become consistent")
      end subroutine ehd_start

      !> Relative change of race j's films (fluid fraction x film, m) from old to new: to the
      !> new value, or to 1 nm where there is next to none.
      pure function film_change(new, old, j) result(change)
         type(ehd_films_t), intent(in) :: new(:), old(:)
         integer, intent(in) :: j
         real(wp) :: change(size(new))
         real(wp), parameter :: FILM_FLOOR = 1.0e-9_wp    ! m
         change = abs(new%fluid(j)*new%h(j) - old%fluid(j)*old%h(j))/max(new%fluid(j)*new%h(j), FILM_FLOOR)
      end function film_change

      !> The EHD films of every ball's race contacts at the current start (unloaded
      !> contacts: h = 0, skipped by the search).
      subroutine current_films(films, error)
         type(ehd_films_t), allocatable, intent(out) :: films(:)
         type(error_type), allocatable, intent(out) :: error
         type(ball_race_contact_t) :: c(2)
         type(contact_traction_t) :: t
         real(wp) :: h, phi, b_minor(2), k_ell(2), p_h(2)
         integer :: k, j

         allocate (films(b%n_elements))
         do k = 1, b%n_elements
            call ball_race_contacts(k, c, b_minor, k_ell, p_h)
            do j = 1, 2
               films(k)%rheo(j) = wall_rheology(b, b%temperature, merge(BODY_OUTER, BODY_INNER, j == 1))
               films(k)%b(j) = b_minor(j)
               if (.not. (c(j)%load > 0.0_wp .and. c(j)%a > 0.0_wp)) cycle
               call contact_traction(c(j), b%race_traction, 1.0_wp, PRINT_GAUSS, t, error)
               if (allocated(error)) return
               call lubricant_film(b, b%temperature, t, k_ell(j), c(j)%load, p_h(j), merge(BODY_OUTER, BODY_INNER, j == 1), &
                                   h, phi, error)
               if (allocated(error)) return
               ! no film: 0, and the search takes the deck's curve for that contact; a mixed
               ! film blends the two by its fluid fraction
               films(k)%fluid(j) = fluid_fraction(b, h, phi)
               films(k)%h(j) = merge(h*phi, 0.0_wp, films(k)%fluid(j) > 0.0_wp)
            end do
         end do
      end subroutine current_films

      !> Ball k's two race contacts at the start's speeds (outer first, ball_contacts), with
      !> their semi-minor axes (m), ellipticities a/b and largest Hertz pressures (Pa).
      subroutine ball_race_contacts(k, c, b_minor, k_ell, p_h)
         integer, intent(in) :: k
         type(ball_race_contact_t), intent(out) :: c(2)
         real(wp), intent(out) :: b_minor(2), k_ell(2), p_h(2)
         associate (e => s%start%equilibrium, kin => s%start%kinematics)
            c = ball_contacts(b%d, e%r(k), e%n_o(:, k), e%n_i(:, k), b%speed_outer, b%speed_inner, &
                              [e%c_o(k)%semi_major, e%c_i(k)%semi_major], [e%q_o(k), e%q_i(k)], &
                              kin(k)%pitch, kin(k)%spin_speed, kin(k)%orbital_speed)
            b_minor = [e%c_o(k)%semi_minor, e%c_i(k)%semi_minor]
            k_ell = [e%c_o(k)%semi_major, e%c_i(k)%semi_major]/max(b_minor, tiny(1.0_wp))
            p_h = [e%c_o(k)%max_pressure, e%c_i(k)%max_pressure]
         end associate
      end subroutine ball_race_contacts







      !> Slip, traction, spin/roll and power loss of every loaded race contact at the
      !> start's speeds (report 2.1, eqs 3-4; PRINT_GAUSS points per slip zone); NaN for an
      !> unloaded contact.  Bearing power loss = sum of the contact losses (no cage loss at
      !> step 0: the report prints zero cage contact forces).
      subroutine contact_tribology(error)
         type(error_type), allocatable, intent(out) :: error
         type(ball_race_contact_t) :: c(2)
         type(contact_traction_t) :: t, t_curve
         real(wp) :: nan, h, b_minor(2), k_ell(2), p_h(2), f, rise, slip, coefficient
         integer :: k, j, race
         logical :: ehd

         nan = ieee_value(1.0_wp, ieee_quiet_nan)
         allocate (s%slip(2, b%n_elements), s%trac_coeff(2, b%n_elements), s%spin_roll(2, b%n_elements), &
                   s%loss(2, b%n_elements), s%film(2, b%n_elements), s%thermal_factor(2, b%n_elements), &
                   s%temp_rise(2, b%n_elements), s%contact_temp(2, b%n_elements), &
                   s%sliding(2, b%n_elements), s%wear(b%n_elements), s%traction(2, b%n_elements))
         s%slip = nan
         s%trac_coeff = nan
         s%spin_roll = nan
         s%loss = nan
         s%film = nan
         s%thermal_factor = nan
         s%temp_rise = nan
         s%contact_temp = nan
         s%sliding = 0.0_wp                          ! an unloaded contact does not wear
         s%traction = 0.0_wp
         s%power_loss = 0.0_wp
         ehd = ehd_traction_model(b)
         do k = 1, b%n_elements
            call ball_race_contacts(k, c, b_minor, k_ell, p_h)
            do j = 1, 2
               if (.not. (c(j)%load > 0.0_wp .and. c(j)%a > 0.0_wp)) cycle
               race = merge(BODY_OUTER, BODY_INNER, j == 1)
               h = 0.0_wp
               call contact_traction(c(j), b%race_traction, 1.0_wp, PRINT_GAUSS, t, error)
               if (allocated(error)) return
               if (b%lubricant_code /= 0) then
                  call lubricant_film(b, b%temperature, t, k_ell(j), c(j)%load, p_h(j), race, s%film(j, k), &
                                      s%thermal_factor(j, k), error)
                  if (allocated(error)) return
               end if
               f = 0.0_wp
               if (ehd) f = fluid_fraction(b, s%film(j, k), s%thermal_factor(j, k))
               if (f > 0.0_wp) then
                  h = s%film(j, k)*s%thermal_factor(j, k)
                  t_curve = t
                  ! the print's losses and tractions by the reference quadrature
                  ! the film's share of the load (f Q at f p_H; the whole load for a full film)
                  call ehd_traction(b, b%temperature, fluid_contact(c(j), f), b_minor(j), race, h, t, error, &
                                    reference=.true.)
                  if (allocated(error)) return
                  call ehd_flash(b, b%temperature, fluid_contact(c(j), f), b_minor(j), race, h, abs(t%rolling_speed), &
                                 s%temp_rise(j, k), error)
                  if (f < 1.0_wp .and. .not. allocated(error)) then
                     ! mixed film: the blend of the two tractions, and of their flash rises
                     ! (eq 35 is linear in the heat; docs/tribology.md, "Mixed films")
                     t = mixed_traction(f, t, t_curve)
                     call law_flash(b, c(j), b_minor(j), p_h(j), race, abs(t%rolling_speed), rise, error)
                     s%temp_rise(j, k) = f*s%temp_rise(j, k) + (1.0_wp - f)*rise
                  end if
               else
                  call law_flash(b, c(j), b_minor(j), p_h(j), race, abs(t%rolling_speed), s%temp_rise(j, k), error)
               end if
               if (allocated(error)) return
               s%contact_temp(j, k) = wall_temperature(b%temperature, race)
               ! the printed node of the traction used: model 3's with a film, else the curve's,
               ! a mixed film's blend of the two
               call printed_slip(b, b%temperature, fluid_contact(c(j), f), b_minor(j), race, h, h > 0.0_wp, &
                                 s%slip(j, k), s%trac_coeff(j, k))
               if (f > 0.0_wp .and. f < 1.0_wp) then
                  ! the film's node coefficient is over its share f of the strip's load
                  call printed_slip(b, b%temperature, c(j), b_minor(j), race, h, .false., slip, coefficient)
                  s%trac_coeff(j, k) = f*f*s%trac_coeff(j, k) + (1.0_wp - f)*coefficient
               end if
               s%spin_roll(j, k) = t%spin_roll
               s%loss(j, k) = t%power
               s%sliding(j, k) = t%sliding
               s%traction(j, k) = t%force
               s%power_loss = s%power_loss + t%power
            end do
         end do
         s%wear = archard_wear_rate(b%material(BODY_ELEMENT)%wear, b%material(BODY_ELEMENT)%hardness, &
                                    s%sliding(1, :) + s%sliding(2, :))
         s%race_wear(1) = archard_wear_rate(b%material(BODY_OUTER)%wear, b%material(BODY_OUTER)%hardness, &
                                            sum(s%sliding(1, :)))
         s%race_wear(2) = archard_wear_rate(b%material(BODY_INNER)%wear, b%material(BODY_INNER)%hardness, &
                                            sum(s%sliding(2, :)))
      end subroutine contact_tribology

      !> Race loads of section 3: the equilibrium's normal loads plus the net traction F_t
      !> of each contact on its race along e_t = (0, -cos phi, -sin phi), applied at the
      !> contact point P = ball centre + D/2 n (axial x_c, radius r_c): force F_t e_t, moment
      !> P x F_t e_t = F_t (r_c e_x - x_c e_r), e_r = (0, -sin phi, cos phi).  The roller
      !> run's tractions reproduce the report's race Fy and Mx this way (docs/tribology.md).
      subroutine traction_race_loads()
         real(wp) :: e_t(3), e_r(3), e_x(3), x_c, r_c, f
         integer :: k, j

         associate (e => s%start%equilibrium)
            s%race_loads(:, 1) = [e%outer_force, e%outer_moment]
            s%race_loads(:, 2) = [e%inner_force, e%inner_moment]
            e_x = [1.0_wp, 0.0_wp, 0.0_wp]
            do k = 1, b%n_elements
               e_t = [0.0_wp, -cos(e%azimuth(k)), -sin(e%azimuth(k))]
               e_r = [0.0_wp, -sin(e%azimuth(k)), cos(e%azimuth(k))]
               do j = 1, 2
                  f = s%traction(j, k)
                  if (j == 1) then
                     x_c = e%x(k) + 0.5_wp*b%d*e%n_o(1, k)
                     r_c = e%r(k) + 0.5_wp*b%d*e%n_o(2, k)
                  else
                     x_c = e%x(k) + 0.5_wp*b%d*e%n_i(1, k)
                     r_c = e%r(k) + 0.5_wp*b%d*e%n_i(2, k)
                  end if
                  s%race_loads(1:3, j) = s%race_loads(1:3, j) + f*e_t
                  s%race_loads(4:6, j) = s%race_loads(4:6, j) + f*(r_c*e_x - x_c*e_r)
               end do
            end do
         end associate
      end subroutine traction_race_loads




   end subroutine solve_ball_step0

end module adore_start_ball_step0
