!> The printed tables of one dynamic step of a ball bearing (sections 1-4, ADORE 5.0
!> layout) assembled from the integrated state, its rates and the force assembly's loads at
!> that state and the run's time averages (no formatting here, no physics): write_ball_step.
!>
!> What a dynamic step prints and which columns stay NaN: docs/print-layout.md, "Dynamic
!> steps".  A value the dynamics does not compute yet (the thermal columns: drag, churning,
!> net loss, HTC, churning fraction, exit fluid temperature) is IEEE NaN /
!> INT_NOT_COMPUTED and prints "NaN": the print never shows a made-up number.
module adore_output_ball_dynamic_report
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi, rad_to_deg, rad_s_to_rpm
   use adore_core_rotation, only: quat_matrix
   use adore_model_bearing, only: BODY_CAGE, bearing_t, BODY_OUTER, BODY_INNER, &
                                   TEMP_CAGE, TEMP_ELEMENT, TEMP_HOUSING, TEMP_INNER, TEMP_OUTER, TEMP_SHAFT
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, body_state_t, body_azimuth, RACE_OUTER, RACE_INNER
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, total_power_loss, guide_land_pairs
   use adore_contact_cage_land, only: cage_land_pair_t, cage_land_geometry_t
   use adore_cage_hoop, only: cage_hoop_stress
   use adore_forces_race_contact, only: wall_temperature
   use adore_cage_step0, only: cage_step0_t
   use adore_output_layout, only: INT_NOT_COMPUTED, N_PERFORMANCE
   use adore_output_print_tables, only: write_step
   use adore_output_step_report, only: race_rows, speed_ratios, thermal_columns
   use adore_life_lundberg_palmgren, only: life_params_t
   use adore_life_ball_life, only: ball_basic_life
   use adore_life_lundberg_palmgren, only: bearing_life, life_hours
   use adore_life_tallian, only: ball_race_modified_life
   use adore_output_ball_contact_print, only: contact_print_t, ball_contact_print
   use adore_thermal_network, only: thermal_field_t
   use adore_thermal_drag, only: element_fluid_loss_t
   implicit none
   private

   public :: write_ball_step, orbital_speed, dynamic_speed_ratios, ball_axis_angles, dynamic_lives, &
             pocket_excursion, cage_wear_sliding

contains

   !> Orbital angular velocity (rad/s) of a body's mass centre about the bearing axis:
   !> (r x v)_x / r**2 with r the radial part (0, y, z) of its position; 0 on the axis.
   pure real(wp) function orbital_speed(body)
      type(body_state_t), intent(in) :: body
      real(wp) :: r2
      r2 = body%position(2)**2 + body%position(3)**2
      orbital_speed = 0.0_wp
      if (r2 > 0.0_wp) orbital_speed = (body%position(2)*body%velocity(3) - body%position(3)*body%velocity(2))/r2
   end function orbital_speed

   !> Write dynamic step `step` of ball bearing b (mounted geometry g) at state s (SI), with
   !> rates (the state's time derivatives per second: velocities in `position`,
   !> accelerations in `velocity`, angular accelerations (rad/s**2, body frame) in `omega`)
   !> and loads at that state; azimuth(k) = ball k's orbital position (rad) unwrapped since
   !> the start (the caller tracks it); axial_origin (m) = the inner race's axial position
   !> the print's IRace Axial is measured from (step 0's u(1) - axial displacement).
   !> header = [tau, time (s), outer and inner race rotations (rev)].
   !> The time averages since the start (adore_driver_time_average) of the "Time Ave" columns:
   !> wear(n) of each ball and race_wear(2) of the outer and inner race (m**3/s), and section
   !> 4's summary_avg = [power loss (W), RE orbital velocity, cage omega and cage whirl
   !> ratios (dynamic_speed_ratios)]; the cage's Archard wear (m**3/s) of each pocket
   !> pocket_wear(n) and guide land land_wear(n_lands), and cage_avg = [fatigue life (h):
   !> t / integral of dt / L (Palmgren-Miner) of section 3's modified life L, the cage's
   !> wear (m**3/s: pockets and lands), average RE excursion (m, pocket_excursion)].
   !> With the thermal model on (docs/thermal.md, "The wiring"): fluid(n), each ball's drag,
   !> churning moment and loss (section 1's Drag, Chrn Mom, Net Loss; added to the total
   !> power loss, their share of it the Churning Loss Fraction), and field, the last solved
   !> temperature field (each ball's contact node, bulk temperature and HTC, the exit fluid,
   !> housing and shaft temperatures); lubricant_temperature as the force assembly's
   !> (ball_contact_print); threads (default 1): the printed tribology's balls on that many
   !> threads (ball_contact_print's, the same numbers).
   subroutine write_ball_step(unit, step, header, b, g, s, rates, loads, azimuth, axial_origin, wear, race_wear, &
                              summary_avg, pocket_wear, land_wear, cage_avg, fluid, field, lubricant_temperature, &
                              threads)
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: header(4)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: s, rates
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(in) :: azimuth(:), axial_origin
      real(wp), intent(in) :: wear(:), race_wear(2), summary_avg(4), pocket_wear(:), land_wear(:), cage_avg(3)
      type(element_fluid_loss_t), intent(in), optional :: fluid(:)
      type(thermal_field_t), intent(in), optional :: field
      real(wp), intent(in), optional :: lubricant_temperature(:)
      integer, intent(in), optional :: threads

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp), allocatable :: contact(:, :), motion(:, :), traction(:, :), thermal(:, :), re_cage(:, :)
      real(wp) :: slices(1, 10, 0), race_cage(max(b%n_lands, 1), 7), bodies(3, 11)
      real(wp) :: ld(5, 6), acc(3, 7), perf(N_PERFORMANCE), summary(1, 10), nan, w_orb(size(azimuth))
      integer, allocatable :: re_no(:), cage_code(:), cage_end(:)
      integer :: land_no(max(b%n_lands, 1)), land_code(max(b%n_lands, 1))
      type(contact_print_t) :: tribology
      integer :: n, k, j

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      n = b%n_elements
      allocate (contact(n, 11), motion(n, 11), traction(n, 11), thermal(n, 11), re_cage(n, 8))
      call ball_contact_print(b, g, s, loads, tribology, lubricant_temperature=lubricant_temperature, threads=threads)
      allocate (re_no(n), cage_code(n), cage_end(n))
      re_no = [(k, k=1, n)]
      motion = nan
      traction = nan                 ! drag, churning moment, net loss: not computed
      thermal = nan
      contact(:, 1) = azimuth*deg
      motion(:, 11) = wear                                     ! time averages since the start
      do k = 1, n
         w_orb(k) = orbital_speed(s%elements(k))
         motion(k, 1) = w_orb(k)*rpm
         motion(k, 2:4) = ball_spin_angles(s%elements(k), w_orb(k))
         motion(k, 5:6) = ball_axis_angles(s%elements(k))
         thermal(k, 10) = s%temperature(TEMP_ELEMENT)
         ! Rel Axial Pos: the ball centre from the outer groove curvature-centre plane
         ! (the print frame of the cage's Mass Center Axial; docs/print-layout.md)
         thermal(k, 1) = s%elements(k)%position(1) - g%groove_centre(1, 1)
         do j = 1, 2
            associate (c => loads%contacts(j, k))
               contact(k, 1 + j) = abs(c%alpha)*deg
               contact(k, 3 + j) = c%load
               contact(k, 5 + j) = c%ellipse%max_pressure
               contact(k, 7 + j) = c%ellipse%semi_major
               contact(k, 9 + j) = c%ellipse%semi_minor
               thermal(k, 1 + j) = max(c%delta, 0.0_wp)     ! a separated contact does not deflect
               if (.not. (c%load > 0.0_wp)) cycle             ! unloaded: no tribology (as step 0)
               motion(k, 6 + j) = loads%traction(j, k)%spin_roll
               motion(k, 8 + j) = loads%heat(j, k)
               thermal(k, 7 + j) = wall_temperature(s%temperature, merge(BODY_OUTER, BODY_INNER, j == 1))
               traction(k, j) = tribology%slip(j, k)
               traction(k, 2 + j) = tribology%coefficient(j, k)
               traction(k, 4 + j) = tribology%film(j, k)
               traction(k, 6 + j) = tribology%thermal_factor(j, k)
               thermal(k, 5 + j) = tribology%temp_rise(j, k)
            end associate
         end do
      end do
      thermal(:, 4:5) = 0.0_wp                                 ! rigid races: no race flexing

      ! section 2: the pocket and guide-land contacts of this state (cage_contact_tables);
      ! not computed (NaN) when the run has no cage contacts
      cage_end = 0
      land_no = [(k, k=1, size(land_no))]
      call cage_contact_tables(b, g, s, loads, cage_code, re_cage, land_code, race_cage)
      if (allocated(loads%pockets)) re_cage(:, 8) = pocket_wear     ! time averages since the start
      if (allocated(loads%lands)) race_cage(1:size(land_wear), 7) = land_wear
      bodies = nan
      associate (c => s%cage)
         bodies(1, 1) = c%position(1) - g%groove_centre(1, 1)   ! print frame: outer groove centre plane
         bodies(1, 2) = hypot(c%position(2), c%position(3))
         ! orbital angle of the centre as the races' (race_rows): 0 for a centre on the axis
         bodies(1, 3) = modulo(body_azimuth(c), 2.0_wp*pi)*deg
         bodies(1, 4) = orbital_speed(c)*rpm
         bodies(1, 5:7) = axis_angles(matmul(quat_matrix(c%attitude), c%omega))
         bodies(1, 8:9) = race_tilt(c)                          ! tilt of its axis, as the races'
         bodies(1, 10) = cage_hoop_stress(b%material(BODY_CAGE)%density, b%cage_id, b%cage_od, c%omega(1))
         bodies(1, 11) = cage_avg(2)
      end associate
      call race_rows(bodies, s%races(RACE_INNER)%position(2:3), s%races(RACE_OUTER)%omega(1), &
                     s%races(RACE_INNER)%omega(1))
      bodies(3, 1) = s%races(RACE_INNER)%position(1) - axial_origin
      bodies(3, 4) = orbital_speed(s%races(RACE_INNER))*rpm   ! the inner race is free in translation
      bodies(3, 8:9) = race_tilt(s%races(RACE_INNER))
      bodies(2:3, 11) = race_wear
      bodies(2, 10) = g%mounting%outer_hoop_stress
      bodies(3, 10) = g%mounting%inner_hoop_stress

      ! section 3: forces of the balls on the races (contact loads = the race's load minus
      ! its weight and, for the inner race, the applied load) and the reactions
      ld = nan
      ld(1, :) = [loads%cage%force - b%mass(BODY_CAGE)*b%gravity, loads%cage%moment]   ! cage contacts
      ld(2, :) = [loads%races(RACE_OUTER)%force - b%mass(BODY_OUTER)*b%gravity, loads%races(RACE_OUTER)%moment]
      ld(3, :) = [loads%races(RACE_INNER)%force - b%mass(BODY_INNER)*b%gravity - b%force, &
                  loads%races(RACE_INNER)%moment - b%moment]
      ! the outer race is held fixed: its support carries the contact loads and its weight
      ld(4, :) = [-(ld(2, 1:3) + b%mass(BODY_OUTER)*b%gravity), -ld(2, 4:6)]
      ! the inner race is free in translation (the applied load) with its rotation held
      ! (the shaft's moment balances the contacts')
      ld(5, :) = [b%force, -ld(3, 4:6)]
      acc = nan
      acc(1, :) = [rates%cage%velocity, rates%cage%omega*rpm, s%temperature(TEMP_CAGE)]
      acc(2, :) = [rates%races(RACE_OUTER)%velocity, rates%races(RACE_OUTER)%omega*rpm, s%temperature(TEMP_OUTER)]
      acc(3, :) = [rates%races(RACE_INNER)%velocity, rates%races(RACE_INNER)%omega*rpm, s%temperature(TEMP_INNER)]
      perf = nan                  ! churning, exit fluid: not computed
      ! basic life (eqs 73-74, 102) and the Tallian modified life of this instant
      perf(1:2) = dynamic_lives(b, g, loads, tribology, w_orb)
      perf(3) = g%mounting%outer_fit
      perf(4) = g%mounting%inner_fit
      perf(5) = g%mounting%clearance
      perf(6) = total_power_loss(loads)              ! race contacts and cage contacts
      perf(9:11) = s%temperature(TEMP_HOUSING)
      perf(12:14) = s%temperature(TEMP_SHAFT)
      call thermal_columns(traction, thermal, perf, fluid, field)   ! the thermal model's, where given

      summary(1, 1:3) = header(2:4)
      summary(1, 4) = cage_avg(1)                    ! time averages since the start
      summary(1, 5:8) = summary_avg
      summary(1, 9:10) = cage_avg(2:3)
      call write_step(unit, step, header, b%run_id, re_no, contact, motion, traction, &
                      thermal, [integer ::], [integer ::], slices, 0, re_no, cage_end, cage_code, re_cage, &
                      land_no, land_code, race_cage, bodies, ld, acc, perf, [step], summary)
   end subroutine write_ball_step

   !> [basic, modified] bearing life (hours) of ball bearing b at one state, from the force
   !> assembly's loads there, the printed tribology p of its race contacts and each ball's
   !> orbital speed w_orb (rad/s): the basic life (eqs 73-74, 102, adore_life_ball_life,
   !> shared with step 0) and the Tallian modified life (eqs 77-109) as step 0 computes it
   !> (adore_start_ball_step0): film parameter = iso film x thermal reduction factor /
   !> composite roughness, mu_EHD = the printed traction coefficient, 0 where a contact has
   !> none (unloaded).
   function dynamic_lives(b, g, loads, p, w_orb) result(hours2)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_bearing_loads_t), intent(in) :: loads
      type(contact_print_t), intent(in) :: p
      real(wp), intent(in) :: w_orb(:)
      real(wp) :: hours2(2)
      real(wp) :: lives(size(w_orb), 2), n_race(2), hours(3), q(2, size(w_orb)), a(2, size(w_orb)), m_race(2), psi
      real(wp) :: p_max(size(w_orb))
      type(life_params_t) :: lp
      integer :: j
      q = loads%contacts%load                     ! contiguous copies (no array temporaries)
      a = abs(loads%contacts%alpha)
      call ball_basic_life(b, life_params_t(), q(1, :), a(1, :), q(2, :), a(2, :), w_orb, lives(:, 1), lives(:, 2), &
                           n_race(1), n_race(2), hours)
      do j = 1, 2
         p_max = loads%contacts(j, :)%ellipse%max_pressure     ! contiguous (this runs at every step)
         call ball_race_modified_life(lp, lives(:, j), n_race(j), p_max, &
                                      no_nan(p%film(j, :)*p%thermal_factor(j, :))/lp%sigma_rms, &
                                      no_nan(p%coefficient(j, :)), &
                                      merge(g%mounting%outer_hoop_stress, g%mounting%inner_hoop_stress, j == 1), &
                                      j == 2, psi, m_race(j))
      end do
      hours2 = [hours(1), life_hours(bearing_life(m_race(1), m_race(2), lp%weibull_e_point), &
                                     (b%speed_inner - b%speed_outer)*rad_s_to_rpm)]
   end function dynamic_lives

   !> The entries of v with NaN replaced by 0.
   pure function no_nan(v) result(w)
      real(wp), intent(in) :: v(:)
      real(wp) :: w(size(v))
      w = merge(v, 0.0_wp, v == v)
   end function no_nan

   !> Section 1's "RE Ang Position" of a ball: where its body x axis (along the bearing
   !> axis at the start: the attitude starts at identity) points, in the frame (e_x, e_r,
   !> e_t) of its azimuth: [theta (deg) = angle from e_x, phi (deg) = azimuth of its tilt
   !> from e_r towards e_t in [0, 360); 0 0 at the start, as step 0 prints] (pyadore's
   !> reading, docs/print-layout.md).
   pure function ball_axis_angles(ball) result(a)
      type(body_state_t), intent(in) :: ball
      real(wp) :: a(2), r(3, 3), x(3), phi, e_r(3), e_t(3), xr, xt
      r = quat_matrix(ball%attitude)
      x = r(:, 1)
      phi = body_azimuth(ball)
      e_r = [0.0_wp, -sin(phi), cos(phi)]
      e_t = [0.0_wp, -cos(phi), -sin(phi)]
      xr = dot_product(x, e_r)
      xt = dot_product(x, e_t)
      a(1) = atan2(hypot(xr, xt), x(1))*rad_to_deg
      a(2) = 0.0_wp
      if (hypot(xr, xt) > 0.0_wp) a(2) = modulo(atan2(xt, xr), 2.0_wp*pi)*rad_to_deg
   end function ball_axis_angles

   !> Section 2's cage contact tables at state s (loads of that state): per pocket Geo Int =
   !> the pocket gap (m, the step-0 definition), Contact Force = the metallic (Hertz) load
   !> (N; the hydrodynamic film force is not in it), Con Ang THETA / PHI and Contact Pos X /
   !> Z as adore_cage_step0 defines them from the ball centre in the pocket frame, Contact
   !> Loss = the friction power (W), code 1 with metallic contact, 0 without; per guide land
   !> Geo Int = gap (m), Force = the land's force on the cage in the plane normal to the
   !> race axis (film and metal, N), Con Angle and Att Angle (land_angles, 0 without force),
   !> Effective Dia Play = twice the land's radial clearance (m), Contact Loss = metallic
   !> friction plus the film's viscous loss (W).  Wear rates are filled by the caller.
   !> Everything NaN / not computed when the loads have no cage contacts.
   subroutine cage_contact_tables(b, g, s, loads, code, re_cage, land_code, race_cage)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      integer, intent(out) :: code(:), land_code(:)
      real(wp), intent(out) :: re_cage(:, :), race_cage(:, :)
      type(cage_land_pair_t), allocatable :: lp(:)
      real(wp) :: nan, n_p(2), r, f_r(3)
      integer :: k

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      code = INT_NOT_COMPUTED
      re_cage = nan
      land_code = INT_NOT_COMPUTED
      race_cage = nan
      if (allocated(loads%pockets)) then
         do k = 1, min(size(loads%pockets), size(re_cage, 1))
            associate (p => loads%pockets(k))
               re_cage(k, 1) = p%gap
               re_cage(k, 2) = p%metallic_load
               r = hypot(p%q(1), p%q(2))
               n_p = [1.0_wp, 0.0_wp]
               if (r > 0.0_wp) n_p = p%q(1:2)/r
               re_cage(k, 3) = modulo(atan2(-n_p(1), n_p(2)), 2.0_wp*pi)*rad_to_deg
               re_cage(k, 4) = 0.0_wp
               re_cage(k, 5) = p%q(1) + 0.5_wp*g%element_diameter*n_p(1)
               re_cage(k, 6) = p%q(3)
               re_cage(k, 7) = p%power
               code(k) = merge(1, 0, p%metallic_load > 0.0_wp)
            end associate
         end do
      end if
      if (allocated(loads%lands)) then
         lp = guide_land_pairs(b, g, s%temperature)
         do k = 1, min(size(loads%lands), size(race_cage, 1))
            associate (c => loads%lands(k))
               race_cage(k, 1) = c%gap
               f_r = c%force_cage - dot_product(c%force_cage, lp_axis(s, b%lands(k)%guide))*lp_axis(s, b%lands(k)%guide)
               race_cage(k, 2) = norm2(f_r)
               race_cage(k, 5) = 2.0_wp*lp(k)%clearance
               race_cage(k, 6) = c%power + c%film_loss
               land_code(k) = merge(1, 0, c%metallic_load > 0.0_wp)
               race_cage(k, 3:4) = 0.0_wp                 ! no force: 0, as step 0 prints
               if (race_cage(k, 2) > 0.0_wp) race_cage(k, 3:4) = land_angles(c)
            end associate
         end do
      end if
   end subroutine cage_contact_tables

   !> The race axis (inertial unit vector) of the race that guides a land of guide type
   !> `guide` (GUIDE_OUTER / GUIDE_INNER = RACE_OUTER / RACE_INNER) at state s.
   pure function lp_axis(s, guide) result(ax)
      type(bearing_state_t), intent(in) :: s
      integer, intent(in) :: guide
      real(wp) :: ax(3)
      ax = matmul(quat_matrix(s%races(guide)%attitude), [1.0_wp, 0.0_wp, 0.0_wp])
   end function lp_axis

   !> A guide land's [contact angle, attitude angle] (deg) of a land force c: the
   !> azimuth of its eccentricity direction e_e (from +z towards -y in [0, 360), as the
   !> pockets' and the races' azimuths), and the attitude angle of journal-bearing theory:
   !> the angle in the radial plane from the load line (the force of the land on the cage,
   !> reversed) to e_e, in [0, 360) (pyadore's reading; docs/print-layout.md).
   pure function land_angles(c) result(a)
      type(cage_land_geometry_t), intent(in) :: c
      real(wp) :: a(2), load_azimuth
      a(1) = modulo(atan2(-c%direction(2), c%direction(3)), 2.0_wp*pi)*rad_to_deg
      load_azimuth = atan2(c%force_cage(2), -c%force_cage(3))
      a(2) = modulo(atan2(-c%direction(2), c%direction(3)) - load_azimuth, 2.0_wp*pi)*rad_to_deg
   end function land_angles

   !> Average RE excursion (m) at one state: the root mean square over the balls of each
   !> ball centre's distance from its pocket centre, |q| (adore_contact_cage_pocket's
   !> pocket frame); NaN without cage contacts (pyadore's reading, docs/print-layout.md).
   real(wp) function pocket_excursion(loads)
      type(ball_bearing_loads_t), intent(in) :: loads
      integer :: k
      pocket_excursion = ieee_value(1.0_wp, ieee_quiet_nan)
      if (.not. allocated(loads%pockets)) return
      if (size(loads%pockets) < 1) return
      pocket_excursion = 0.0_wp
      do k = 1, size(loads%pockets)
         pocket_excursion = pocket_excursion + dot_product(loads%pockets(k)%q, loads%pockets(k)%q)
      end do
      pocket_excursion = sqrt(pocket_excursion/size(loads%pockets))
   end function pocket_excursion

   !> Archard's load x sliding speed (N m/s) of the cage's metallic contacts at one state:
   !> pockets(k) = Q |u| of ball k's pocket, lands(j) = Q |u| of guide land j, each its
   !> friction power over the friction coefficient (b%cage_friction: pocket, land), with the
   !> friction's own slip regularisation; 0 where there is no contact or no cage contacts.
   subroutine cage_wear_sliding(b, loads, pockets, lands)
      type(bearing_t), intent(in) :: b
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(out) :: pockets(:), lands(:)
      integer :: k
      pockets = 0.0_wp
      lands = 0.0_wp
      if (allocated(loads%pockets) .and. b%cage_friction(1) > 0.0_wp) then
         do k = 1, min(size(pockets), size(loads%pockets))
            pockets(k) = loads%pockets(k)%power/b%cage_friction(1)
         end do
      end if
      if (allocated(loads%lands) .and. b%cage_friction(2) > 0.0_wp) then
         do k = 1, min(size(lands), size(loads%lands))
            lands(k) = loads%lands(k)%power/b%cage_friction(2)
         end do
      end if
   end subroutine cage_wear_sliding

   !> Section 4's speed ratios at state s of ball bearing b (step 0's speed_ratios): the mean
   !> ball orbital speed (orbital_speed), the cage's angular speed about its axis (body x)
   !> and its whirl speed, each relative to the outer race over the inner race's speed
   !> relative to the outer race.
   function dynamic_speed_ratios(b, s) result(r)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      real(wp) :: r(3), w
      type(cage_step0_t) :: cage_speeds
      integer :: k
      w = 0.0_wp
      do k = 1, size(s%elements)
         w = w + orbital_speed(s%elements(k))
      end do
      cage_speeds%state%angular_speed = s%cage%omega(1)   ! body x: the cage's axis
      cage_speeds%state%whirl_speed = orbital_speed(s%cage)
      r = speed_ratios(b, w/size(s%elements), cage_speeds)
   end function dynamic_speed_ratios

   !> Section 1's angular velocity of a ball relative to its orbiting frame
   !> (omega - omega_m e_x, omega_m = w_orb its orbital speed, rad/s), in the frame
   !> (e_x, e_r, e_t) of its azimuth: [amplitude (rpm), theta (deg), phi (deg)].  As step 0:
   !> omega_rel = -amplitude (cos phi cos theta e_x + cos phi sin theta e_r + sin phi e_t),
   !> theta = atan2(-w_r, -w_x); phi = atan2(-w_t, hypot(w_x, w_r)), the out-of-plane
   !> elevation, in [0, 360) as the report prints it (pyadore's reading: small negative
   !> values print 3.600E+02 in the report's step 2500).
   pure function ball_spin_angles(ball, w_orb) result(a)
      type(body_state_t), intent(in) :: ball
      real(wp), intent(in) :: w_orb
      real(wp) :: a(3), w(3), phi, e_r(3), e_t(3), wx, wr, wt
      w = matmul(quat_matrix(ball%attitude), ball%omega)
      w(1) = w(1) - w_orb
      phi = body_azimuth(ball)
      e_r = [0.0_wp, -sin(phi), cos(phi)]
      e_t = [0.0_wp, -cos(phi), -sin(phi)]
      wx = w(1)
      wr = dot_product(w, e_r)
      wt = dot_product(w, e_t)
      a(1) = norm2(w)*rad_s_to_rpm
      a(2) = atan2(-wr, -wx)*rad_to_deg
      a(3) = modulo(atan2(-wt, hypot(wx, wr))*rad_to_deg, 360.0_wp)
   end function ball_spin_angles

   !> Section 2's angular velocity of a body from its inertial angular velocity w (rad/s):
   !> [amplitude (rpm), theta (deg) = angle of w from +x (0 along +x, 180 along -x, as step 0
   !> prints the races and the cage), phi (deg) = azimuth of w's tilt about the axis, from +z
   !> towards -y in [0, 360); 0 without tilt] (pyadore's convention).
   pure function axis_angles(w) result(a)
      real(wp), intent(in) :: w(3)
      real(wp) :: a(3), tilt
      tilt = hypot(w(2), w(3))
      a(1) = norm2(w)*rad_s_to_rpm
      a(2) = atan2(tilt, w(1))*rad_to_deg
      a(3) = 0.0_wp
      if (tilt > 0.0_wp) a(3) = modulo(atan2(-w(2), w(3)), 2.0_wp*pi)*rad_to_deg
   end function axis_angles

   !> Misalignment of a race about y and z (deg) from its attitude: the body x axis
   !> (a_x, a_y, a_z) in inertial components gives atan2(-a_z, a_x) and atan2(a_y, a_x),
   !> exactly the step-0 angles of a rotation about one axis (quat_from_rotation_vector).
   pure function race_tilt(race) result(t)
      type(body_state_t), intent(in) :: race
      real(wp) :: t(2), r(3, 3), a(3)
      r = quat_matrix(race%attitude)
      a = r(:, 1)
      t = [atan2(-a(3), a(1)), atan2(a(2), a(1))]*rad_to_deg + 0.0_wp   ! + 0: no -0 printed
   end function race_tilt

end module adore_output_ball_dynamic_report
