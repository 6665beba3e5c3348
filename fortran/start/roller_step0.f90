!> Step 0 of a cylindrical roller bearing run: mounting, kinematics and the quasi-static
!> start with line contacts by slices (ADORE's start-up: ADRA4 with ADRC1 LineContact).
!> Pure compute, no printing.
!>
!> * Mounting (section 3 of the print): adore_geometry_fits, as for the ball bearing.
!> * Contact geometry: raceway radii R_o = d_o/2 - n s_o, R_i = d_i/2 + n g_i with the
!>   raceway displacements of the mounting (g_i inner growth, s_o outer shrink).
!>   n = growth_count = 1 is the consistent model (the operating clearance of the print is
!>   then R_o - R_i - D, doubled).  The report's step-0 contacts need n = 2: its unloaded
!>   rollers (90..270 deg) have outer/inner interactions 2.413e-6 / -1.534e-7 m and its
!>   inner race moves 7.758e-6 m, which makes the effective diametral clearance
!>   -4.52e-6 m = (printed clearance 1.774e-5) - 2 x (inner raceway growth 1.113e-5):
!>   ADORE 5.0 apparently applies the raceway growth to raceways already built from the
!>   mounted clearance.  The driver's default is n = 2 (reproduce the report).
!> * Kinematics: orbital speed epicyclic at the pitch diameter,
!>   w_m = (w_i (1 - D/d_m) + w_o (1 + D/d_m))/2, roller spin from pure rolling on the
!>   outer raceway, w_R = (w_o - w_m) R_o/(D/2) (outer race control).  Both reproduce
!>   the report (2.849e4 and 1.817e5 rpm; pure rolling at the pitch diameter would give
!>   1.816e5).
!> * Slices: the report's grid (3 zones x 4 Gauss points), slice reference length the
!>   length scale D/2 (adore_contact_line_slices).
!> * Flanges: a deck without Rec 5B.2 flanges (both appendix decks) has none: the rollers
!>   carry no axial load at step 0 (zero thrust, no misalignment, symmetric profile) and the
!>   report prints no flange loads at step 0.  With Rec 5B.2 flanges (a spherical roller end,
!>   R_e >= L/2) the start is adore_quasistatic_roller_flange_equilibrium: each roller's axial
!>   position and tilt with its flange contacts, the inner race's axial position, so that the
!>   flanges carry the axial load (docs/rollers.md, "Flanges at step 0").  Roller skew is
!>   prescribed 0; roller tilt is solved.
!> * Race and roller weights are left out of the start (see solve_roller_step0).
!> * Tribology (roller_tribology): slice slips, tractions and contact losses of both races
!>   (adore_tribology_roller_traction, docs/tribology.md); spin SPIN_ROLLING (the report)
!>   or SPIN_EQUILIBRIUM (moment balance); total power NaN while a cage contact touches.
!>   Also the flash temperature rise of each contact (eqs 35-36 over the printed contact
!>   ellipse) and the race loads of section 3 (normal slice loads plus slice tractions).
!> * Roller mass: the crowned roller (roller_mass), which is the echo's RE mass.
!> * Basic fatigue life (ADRF1): adore_life_roller from the slice contacts, eqs 73, 75, 76,
!>   102, with the default life_params_t (the deck has no fatigue records).  The modified
!>   (Tallian) life is not computed for line contacts and stays NaN.
module adore_start_roller_step0
   use adore_core_kinds, only: wp
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_error, only: error_type, input_error
   use adore_model_bearing, only: bearing_t, ROLLER_BEARING, BODY_ELEMENT, BODY_OUTER, BODY_INNER
   use adore_geometry_fits, only: mounting_t
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_quasistatic_models, only: roller_qs_model
   use adore_quasistatic_roller_equilibrium, only: roller_qs_bearing_t, roller_qs_load_t, &
                                                   roller_qs_solution_t, solve_roller_equilibrium
   use adore_quasistatic_roller_flange_equilibrium, only: solve_flanged_equilibrium
   use adore_contact_roller_flange, only: roller_flange_set_t, roller_flanges, flange_contact_t, flange_contact
   use adore_life_lundberg_palmgren, only: life_params_t
   use adore_life_roller, only: roller_lives_t, roller_bearing_lp_life
   use adore_cage_step0, only: cage_step0_t, solve_cage_step0, POCKET_RECTANGULAR
   use adore_tribology_wear, only: archard_wear_rate
   use adore_tribology_traction_law, only: law_slip_scale, law_kappa
   use adore_forces_race_contact, only: line_flash, wall_temperature
   use adore_tribology_roller_traction, only: roller_spin_t, line_traction_t, line_traction, &
                                              roller_equilibrium_spin, RACE_OUTER, RACE_INNER
   implicit none
   private

   public :: roller_step0_t, solve_roller_step0, roller_wear

   integer, parameter, public :: SPIN_ROLLING = 1      !< land rolls on both races (ADORE's start, default)
   integer, parameter, public :: SPIN_EQUILIBRIUM = 2  !< spin from the roller's traction moment balance

   !> The step-0 state of a roller bearing.
   type :: roller_step0_t
      type(mounting_t) :: mounting
      type(roller_qs_bearing_t) :: model       !< the contact model actually solved
      type(roller_qs_solution_t) :: equilibrium
      !> the roller end / flange contacts solved at step 0 (none allocated: no flanges)
      type(roller_flange_set_t) :: flanges
      real(wp) :: orbital_speed = 0.0_wp       !< w_m (rad/s)
      real(wp) :: spin_speed = 0.0_wp          !< roller spin about its axis, w_R (rad/s, <0: -x)
      real(wp) :: contact_clearance = 0.0_wp   !< 2 (R_o - R_i - D) of the contact geometry (m)
      type(roller_lives_t) :: life             !< basic (Lundberg-Palmgren) lives, outer/inner/bearing
      real(wp) :: basic_life_hours = 0.0_wp    !< bearing basic life (h), = life%bearing_hours
      real(wp) :: modified_life_hours = 0.0_wp !< NaN: Tallian life of line contacts not computed
      type(cage_step0_t) :: cage               !< cage state and geometric interactions
      integer :: spin_method = SPIN_ROLLING
      real(wp), allocatable :: roller_spin(:)  !< spin of each roller about +x (rad/s)
      real(wp), allocatable :: moment_residual(:)  !< traction moment on each roller about its axis (N m)
      type(line_traction_t), allocatable :: tr_o(:), tr_i(:)   !< slice tractions, outer / inner race
      real(wp), allocatable :: tangential_force(:) !< net traction force on each roller along e_t (N)
      real(wp) :: contact_power = 0.0_wp       !< sum of the roller/race contact losses (W), eq 4
      !> wear rate of each roller (m**3/s): Archard with the roller's k and hardness over
      !> both race contacts (adore_tribology_wear)
      real(wp), allocatable :: wear(:)
      !> wear rate of the outer (1) and inner (2) race (m**3/s): Archard with the race's k and
      !> hardness over all its contacts (section 2's ORace/IRace rows)
      real(wp) :: race_wear(2) = 0.0_wp
      !> average flash temperature rise (K) of each roller's outer (1) and inner (2) race
      !> contact, eqs 35-36 over the contact ellipse the print reports (flash_rise)
      real(wp), allocatable :: temp_rise(:, :)
      !> surface (wall) temperature of each contact (K): mean of the roller and race
      !> temperatures of Rec 2.7; the rise is not fed back at step 0
      real(wp), allocatable :: contact_temp(:, :)
      !> loads of the rollers on the outer (:, 1) and inner (:, 2) race: [force x, y, z (N),
      !> moment x, y, z about the race centre (N m)], the normal slice loads of the
      !> equilibrium plus the slice tractions along the orbit direction (section 3 of the print)
      real(wp) :: race_loads(6, 2) = 0.0_wp
      !> the flange contacts' traction loss (W): kappa(|u|) Q |u| of each loaded flange contact at
      !> the start's kinematics (flange_power; 0 without flanges)
      real(wp) :: flange_power = 0.0_wp
      !> total power loss (W): contact_power + flange_power + cage contact losses; NaN while a cage contact
      !> (pocket or land) touches, since the cage contact forces are not modelled
      real(wp) :: power_loss = 0.0_wp
   end type roller_step0_t

contains

   !> Solve step 0 for the roller bearing b (sections 3.1, 4.4.1, Appendix B).
   !> growth_count: 2 reproduces the report (default), 1 the consistent clearance.
   !> spin_method: SPIN_ROLLING (default, the report) or SPIN_EQUILIBRIUM (traction moment
   !> balance per roller, adore_tribology_roller_traction).
   !> misalignment: the inner race's prescribed misalignment about y and z (rad; default 0):
   !> the report runs roller bearings with prescribed misalignment, not moment equilibrium
   !> (section 4.4.1; its moment equilibrium is for ball bearings only).
   subroutine solve_roller_step0(b, s, error, growth_count, spin_method, misalignment)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: growth_count, spin_method
      real(wp), intent(in), optional :: misalignment(2)

      type(roller_qs_load_t) :: ld
      type(life_params_t) :: lp
      real(wp), allocatable :: w(:), centres(:, :)
      real(wp) :: race_centre(3, 2)
      type(mounted_geometry_t) :: geometry
      integer :: ng
      if (present(spin_method)) s%spin_method = spin_method
      if (s%spin_method /= SPIN_ROLLING .and. s%spin_method /= SPIN_EQUILIBRIUM) then
         call input_error(error, "roller step 0: unknown spin method")
         return
      end if

      if (b%bearing_type /= ROLLER_BEARING .or. b%n_elements < 1 .or. b%d <= 0.0_wp .or. &
          b%dm <= b%d .or. b%roller%roller_length <= 0.0_wp .or. b%roller%crown_radius <= 0.0_wp) then
         call input_error(error, "roller bearing: need rollers with 0 < diameter < pitch diameter, "// &
                          "a length and a crown radius > 0")
         return
      end if
      ng = 2
      if (present(growth_count)) ng = growth_count
      geometry = mount_geometry(b, b%temperature, ng)
      s%mounting = geometry%mounting
      s%model = roller_qs_model(b, geometry, 3)
      s%contact_clearance = 2.0_wp*(s%model%r_o - s%model%r_i - b%d)

      s%orbital_speed = 0.5_wp*(b%speed_inner*(1.0_wp - b%d/b%dm) + b%speed_outer*(1.0_wp + b%d/b%dm))
      s%spin_speed = (b%speed_outer - s%orbital_speed)*s%model%r_o/(0.5_wp*b%d)

      ld%force = b%force
      ! no race weight: the report's step-0 roller force on the inner race is -1.000e3 N,
      ! with the weight (0.23 N) it would print -9.998e2
      ld%gravity = 0.0_wp
      ld%misalignment = 0.0_wp
      if (present(misalignment)) ld%misalignment = misalignment
      ld%skew = 0.0_wp
      allocate (w(b%n_elements))
      w = s%orbital_speed
      associate (r => b%roller)
         ! flanges at step 0 (docs/rollers.md, "Flanges at step 0"); a flange set the contact
         ! model cannot honour (flat or short end) is left to the dynamics' input error
         if (any(r%flange) .and. r%end_radius > 0.0_wp .and. r%end_radius >= 0.5_wp*r%roller_length) then
            s%flanges = roller_flanges(b%d, r%roller_length, r%corner_radius, r%end_radius, r%flange, &
                                       r%flange_height, r%flange_angle, r%flange_clearance, [s%model%r_o, s%model%r_i], &
                                       [s%model%e_o, s%model%e_i])
            call solve_flanged_equilibrium(s%model, s%flanges, ld, w, s%equilibrium, error)
         else
            call solve_roller_equilibrium(s%model, ld, w, s%equilibrium, error)
         end if
      end associate
      if (allocated(error)) return

      ! basic life from the slice contacts (eqs 73, 75, 76, 102); default constants
      call roller_bearing_lp_life(lp, s%equilibrium%c_o, s%equilibrium%c_i, s%equilibrium%orbital_speed, &
                                  b%speed_outer, b%speed_inner, &
                                  b%d, b%dm, s%life)
      s%basic_life_hours = s%life%bearing_hours
      s%modified_life_hours = ieee_value(1.0_wp, ieee_quiet_nan)
      ! cage (section 4.4.4): rectangular pockets (kPocType 0, the echo's POCKET SHAPE 0;
      ! the kPocType field of Rec 7.0 is not identified, so cylindrical pockets are not
      ! selectable); rollers axially centred; land growth from the mounting, applied once
      associate (e => s%equilibrium)
         allocate (centres(3, b%n_elements))
         centres(1, :) = 0.0_wp
         centres(2, :) = -e%r*sin(e%azimuth)
         centres(3, :) = e%r*cos(e%azimuth)
         race_centre(:, 1) = 0.0_wp
         race_centre(:, 2) = [0.0_wp, e%u(1), e%u(2)]
         call solve_cage_step0(b%cage_initial, centres, e%azimuth, sum(e%orbital_speed)/b%n_elements, b%d, &
                               POCKET_RECTANGULAR, b%pocket_clearance(1), b%cage_od, b%cage_id, b%lands, &
                               race_centre, [-s%mounting%outer_raceway_shrink, s%mounting%inner_raceway_growth], &
                               s%cage, error)
      end associate
      if (allocated(error)) return
      call roller_tribology(b, s, error)

   end subroutine solve_roller_step0

   !> Step-0 tribology of the rollers (report 2.1, eqs 1, 3, 4 by slices): spin per roller
   !> (s%spin_method), slice tractions and contact losses of both races, the net
   !> tangential force each roller puts on the cage, and the power balance.  The spin does not
   !> change the centrifugal forces (orbital speed unchanged), so no iteration with the
   !> equilibrium is needed.
   subroutine roller_tribology(b, s, error)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(inout) :: s
      type(error_type), allocatable, intent(out) :: error
      type(roller_spin_t) :: k
      real(wp) :: u_step
      integer :: j, n

      n = b%n_elements
      allocate (s%roller_spin(n), s%moment_residual(n), s%tr_o(n), s%tr_i(n), s%tangential_force(n))
      ! slip step of the spin search: the slip of maximum traction (>= 1 mm/s)
      u_step = law_slip_scale(b%race_traction)
      associate (e => s%equilibrium)
         do j = 1, n
            k = roller_spin_t(b%d, s%spin_speed, s%spin_speed, &
                              [b%speed_outer - e%orbital_speed(j), b%speed_inner - e%orbital_speed(j)])
            if (s%spin_method == SPIN_EQUILIBRIUM) then
               call roller_equilibrium_spin(s%model%profile, k, e%c_o(j), e%c_i(j), b%race_traction, 0.0_wp, &
                                            u_step, k%spin, s%moment_residual(j), error)
               if (allocated(error)) return
            end if
            s%roller_spin(j) = k%spin
            call line_traction(s%model%profile, k, RACE_OUTER, e%c_o(j), b%race_traction, s%tr_o(j))
            call line_traction(s%model%profile, k, RACE_INNER, e%c_i(j), b%race_traction, s%tr_i(j))
            s%moment_residual(j) = s%tr_o(j)%moment + s%tr_i(j)%moment
            s%tangential_force(j) = -(s%tr_o(j)%force + s%tr_i(j)%force)
         end do
      end associate
      s%contact_power = sum(s%tr_o%power) + sum(s%tr_i%power)
      call roller_wear(b, s)
      allocate (s%temp_rise(2, n), s%contact_temp(2, n))
      associate (e => s%equilibrium)
         do j = 1, n
            call line_flash(b, e%c_o(j), s%tr_o(j), BODY_OUTER, s%model%r_o, b%speed_outer - e%orbital_speed(j), &
                            s%roller_spin(j), s%temp_rise(1, j), error)
            if (allocated(error)) return
            call line_flash(b, e%c_i(j), s%tr_i(j), BODY_INNER, s%model%r_i, b%speed_inner - e%orbital_speed(j), &
                            s%roller_spin(j), s%temp_rise(2, j), error)
            if (allocated(error)) return
         end do
         ! race loads: normal loads of the equilibrium plus the net slice tractions, each acting
         ! along the orbit direction e_t = (0, -cos phi, -sin phi) at the raceway radius
         ! (azimuth phi from +z towards -y); its moment about the race axis is R F_t
         s%race_loads(:, 1) = [e%outer_force, e%outer_moment]
         s%race_loads(:, 2) = [e%inner_force, e%inner_moment]
         s%race_loads(2, 1) = s%race_loads(2, 1) - sum(s%tr_o%force*cos(e%azimuth))
         s%race_loads(3, 1) = s%race_loads(3, 1) - sum(s%tr_o%force*sin(e%azimuth))
         s%race_loads(4, 1) = s%race_loads(4, 1) + s%model%r_o*sum(s%tr_o%force)
         s%race_loads(2, 2) = s%race_loads(2, 2) - sum(s%tr_i%force*cos(e%azimuth))
         s%race_loads(3, 2) = s%race_loads(3, 2) - sum(s%tr_i%force*sin(e%azimuth))
         s%race_loads(4, 2) = s%race_loads(4, 2) + s%model%r_i*sum(s%tr_i%force)
      end associate
      s%contact_temp(1, :) = wall_temperature(b%temperature, BODY_OUTER)
      s%contact_temp(2, :) = wall_temperature(b%temperature, BODY_INNER)
      if (allocated(s%flanges%flange)) s%flange_power = flange_power(b, s)
      s%power_loss = s%contact_power + s%flange_power
      if (any(s%cage%pocket%in_contact) .or. any(s%cage%land%in_contact)) &
         s%power_loss = ieee_value(1.0_wp, ieee_quiet_nan)

   end subroutine roller_tribology

   !> The Archard wear rates (m**3/s) of s's contacts (their sliding, s%tr_o / s%tr_i): each
   !> roller's over both races with the roller's coefficient and hardness, each race's over
   !> all its contacts with the race's (adore_tribology_wear).
   pure subroutine roller_wear(b, s)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(inout) :: s
      s%wear = archard_wear_rate(b%material(BODY_ELEMENT)%wear, b%material(BODY_ELEMENT)%hardness, &
                                 s%tr_o%sliding + s%tr_i%sliding)
      s%race_wear(1) = archard_wear_rate(b%material(BODY_OUTER)%wear, b%material(BODY_OUTER)%hardness, &
                                         sum(s%tr_o%sliding))
      s%race_wear(2) = archard_wear_rate(b%material(BODY_INNER)%wear, b%material(BODY_INNER)%hardness, &
                                         sum(s%tr_i%sliding))
   end subroutine roller_wear

   !> The flange contacts' traction loss (W) at the start (docs/rollers.md, "Flanges at step
   !> 0"): each loaded contact of the flanged equilibrium with the start's kinematics - roller
   !> centre orbiting at w_m, its absolute spin w_m + W about its axis, the races turning -
   !> the sliding u of the roller end over the flange (adore_contact_roller_flange) and the
   !> run's law, kappa(|u|) Q |u| (as the dynamics' flange_loads, without damping: no approach rate).
   real(wp) function flange_power(b, s) result(p)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(in) :: s
      type(flange_contact_t) :: c
      real(wp) :: centre(3), axis(3), omega(3), o(3), e_r(3), e_t(3), um, w_o
      integer :: k, i
      p = 0.0_wp
      associate (e => s%equilibrium, f => s%flanges)
         do k = 1, size(e%x)
            e_r = [0.0_wp, -sin(e%azimuth(k)), cos(e%azimuth(k))]
            e_t = [0.0_wp, -cos(e%azimuth(k)), -sin(e%azimuth(k))]
            centre = [e%x(k), e%r(k), 0.0_wp]
            axis = [1.0_wp, e%tilt(k), 0.0_wp]
            axis = axis/norm2(axis)
            omega = [e%orbital_speed(k) + s%roller_spin(k), s%roller_spin(k)*e%tilt(k), 0.0_wp]
            do i = 1, size(f%flange)
               if (.not. (e%flange_load(i, k) > 0.0_wp)) cycle
               o = 0.0_wp
               w_o = b%speed_outer
               if (f%flange(i)%race == 2) then
                  o = [e%u_axial, dot_product([0.0_wp, e%u], e_r), dot_product([0.0_wp, e%u], e_t)]
                  w_o = b%speed_inner
               end if
               call flange_contact(f, f%flange(i), centre, axis, [0.0_wp, 0.0_wp, e%r(k)*e%orbital_speed(k)], omega, &
                                   o, [0.0_wp, 0.0_wp, 0.0_wp], w_o, c)
               um = norm2(c%slip)
               if (um > 0.0_wp) p = p + law_kappa(b%race_traction, um)*c%load*um
            end do
         end do
      end associate
   end function flange_power

end module adore_start_roller_step0
