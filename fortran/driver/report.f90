!> Assembly of the print output from the model and the solution (no formatting here, no
!> physics): the input echo record from the deck and the bearing model, and the step-0
!> tables of a ball bearing from its quasi-static start.
!>
!> A value pyadore does not compute yet (cage contact forces and their wear, the roller's modified
!> life, deck fields whose meaning is not identified) is left as
!> IEEE NaN / INT_NOT_COMPUTED and prints "NaN": the print never shows a made-up number.
module adore_driver_report
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi, rad_to_deg, rad_s_to_rpm
   use adore_core_error, only: error_type
   use adore_deck_reader, only: deck_t, deck_collect_real, deck_collect_int, deck_count, deck_has
   use adore_model_bearing, only: bearing_t, BALL_BEARING, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, &
                                  BODY_SHAFT, BODY_HOUSING
   use adore_model_scales, only: scale_factors
   use adore_tribology_film, only: LUBRICANT_MIL_L_7808
   use adore_life_lundberg_palmgren, only: life_params_t
   use adore_output_echo_data, only: echo_data_t, echo_data_init
   use adore_output_layout, only: ELEMENT_BALL, ELEMENT_ROLLER, INT_NOT_COMPUTED, ECHO_MAX_GUIDE, N_PERFORMANCE
   use adore_output_print_tables, only: write_step
   use adore_driver_ball_step0, only: ball_step0_t
   use adore_driver_roller_step0, only: roller_step0_t
   use adore_cage_step0, only: cage_step0_t
   implicit none
   private

   public :: fill_echo, write_ball_step0, write_roller_step0, cage_tables


contains

   !> The input echo record of deck / bearing model b (SI units; angles in deg as printed).
   subroutine fill_echo(deck, b, e, error)
      type(deck_t), intent(in) :: deck
      type(bearing_t), intent(in) :: b
      type(echo_data_t), intent(out) :: e
      type(error_type), allocatable, intent(out) :: error

      real(wp) :: v(9), scales(3)
      integer :: k, body, code
      type(life_params_t) :: life

      e = echo_data_init()
      e%run_id = b%run_id
      e%title = b%run_id
      e%program_mode = b%mode
      e%n_elements = b%n_elements
      e%element_dia = b%d
      e%pitch_dia = b%dm
      e%dia_play = b%dia_play
      e%fit = [b%fit_outer, b%fit_inner]
      e%width = [b%width_outer, b%width_inner]
      e%shaft_od = b%shaft_od
      e%shaft_id = b%shaft_id
      e%bearing_od = b%bearing_od
      e%housing_od = b%housing_od
      if (b%bearing_type == BALL_BEARING) then
         e%bearing_type = "BALL"
         e%element_kind = ELEMENT_BALL
         e%contact_angle = b%alpha0*180.0_wp/pi
         e%cur_fac = [b%f_o, b%f_i]
         e%end_play = b%end_play
      else
         e%bearing_type = "ROLLER"
         e%element_kind = ELEMENT_ROLLER
         e%roller_len = b%roller_length
         call deck_collect_real(deck, "5B", "central_land_length", e%cen_land, error, if_present=.true.)
         call deck_collect_real(deck, "5B", "crown_radius", e%crown_rad, error, if_present=.true.)
         call deck_collect_real(deck, "5B", "corner_radius_1", e%cor_rad(1), error, if_present=.true.)
         call deck_collect_real(deck, "5B", "corner_radius_2", e%cor_rad(2), error, if_present=.true.)
         call deck_collect_real(deck, "5B", "outer_race_crown_radius", e%race_crown(1), error, if_present=.true.)
         call deck_collect_real(deck, "5B", "inner_race_crown_radius", e%race_crown(2), error, if_present=.true.)
         call deck_collect_real(deck, "5B.1", "outer_race_len1", e%outer_len(1), error, if_present=.true.)
         call deck_collect_real(deck, "5B.1", "outer_race_len2", e%outer_len(2), error, if_present=.true.)
         call deck_collect_real(deck, "5B.1", "inner_race_len1", e%inner_len(1), error, if_present=.true.)
         call deck_collect_real(deck, "5B.1", "inner_race_len2", e%inner_len(2), error, if_present=.true.)
      end if

      ! cage and guide lands (Rec 7.x)
      e%cage_od = b%cage_od
      e%cage_id = b%cage_id
      e%cage_width = b%cage_width
      e%poc_cls = b%pocket_clearance
      call deck_collect_real(deck, "7.1", "segment_cut_angle", e%seg_cut, error, if_present=.true.)
      call deck_collect_real(deck, "7.1", "cage_cone_angle", e%cage_cone, error, if_present=.true.)
      call deck_collect_real(deck, "7.1", "cage_outer_clearance", e%race_cls(1), error, if_present=.true.)
      call deck_collect_real(deck, "7.1", "cage_inner_clearance", e%race_cls(2), error, if_present=.true.)
      e%pocket_shape = INT_NOT_COMPUTED     ! kPocType: its Rec 7.0 position is not identified
      e%n_cage_segs = INT_NOT_COMPUTED
      call deck_collect_int(deck, "7.0", "n_guide_lands", e%n_lands, error)
      e%n_guide = min(deck_count(deck, "7.2"), ECHO_MAX_GUIDE)
      do k = 1, e%n_guide
         e%guide_land(k) = k
         call deck_collect_int(deck, "7.0", "guide_type["//achar(iachar("0") + k)//"]", e%guide_type(k), error)
         call deck_collect_real(deck, "7.2", "guide_land_diameter", e%guide(1, k), error, k, .true.)
         call deck_collect_real(deck, "7.2", "guide_land_clearance", e%guide(2, k), error, k, .true.)
         call deck_collect_real(deck, "7.2", "guide_land_width", e%guide(3, k), error, k, .true.)
         call deck_collect_real(deck, "7.2", "guide_land_position", e%guide(4, k), error, k, .true.)
      end do

      ! materials: rows = properties, columns = RE, outer, inner, cage, shaft, housing
      do body = 1, 6
         associate (m => b%material(body))
            v = [m%density, m%modulus, m%poisson, m%expansion, m%conductivity, m%heat_capacity, &
                 m%strain_limit, m%hardness, m%wear]
         end associate
         e%material(body, :) = v
      end do
      ! inertia rows: RE, cage, outer race, inner race: mass, 3 moments, 3 offsets (0: centred)
      do k = 1, 4
         e%inertia(:, k) = [b%mass(k), b%moments(:, k), 0.0_wp, 0.0_wp, 0.0_wp]
         e%principal(:, k) = 0.0_wp
      end do

      ! lubrication: RE/race traction curve coefficients (Rec 10.1x fit); cage friction (Rec 10.5.x)
      e%lubrication(2:5, 1) = b%traction_input
      e%lubrication(2:5, 2) = b%traction_input
      e%lubrication(6:9, 1) = b%traction
      e%lubrication(6:9, 2) = b%traction
      call deck_collect_real(deck, "10.5.1B", "re_cage_coeff_d", e%lubrication(9, 3), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.2B", "race_cage_coeff_d", e%lubrication(9, 4), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.1B", "re_cage_coeff_a", e%lubrication(6, 3), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.1B", "re_cage_coeff_b", e%lubrication(7, 3), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.1B", "re_cage_coeff_c", e%lubrication(8, 3), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.2B", "race_cage_coeff_a", e%lubrication(6, 4), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.2B", "race_cage_coeff_b", e%lubrication(7, 4), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.2B", "race_cage_coeff_c", e%lubrication(8, 4), error, if_present=.true.)
      ! "HYPOTHETICAL MODELS" column: the deck value echoed, its meaning not identified.  RE/RACE
      ! rows: Rec 10.3 field 1 (ball deck 1.25E-07; the roller deck has no Rec 10.3 and prints
      ! 0.0, the field's default); RE/CAGE and RACE/CAGE: field 5 of Rec 10.5.1B / 10.5.2B
      ! (1.25E-07 in both decks; the roller's 0.0 rows rule out these for RE/RACE)
      e%lubrication(1, 1:2) = 0.0_wp
      call deck_collect_real(deck, "10.3", "rec10_3_value_1", e%lubrication(1, 1), error, if_present=.true.)
      call deck_collect_real(deck, "10.3", "rec10_3_value_1", e%lubrication(1, 2), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.1B", "rec10_5_1b_value_5", e%lubrication(1, 3), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.2B", "rec10_5_2b_value_5", e%lubrication(1, 4), error, if_present=.true.)

      ! fatigue parameters: the constants the life model uses (the decks carry no fatigue
      ! records; these are the model's defaults, docs/life-model.md), same for both races
      do k = 1, 2
         if (b%bearing_type == BALL_BEARING) then
            e%fatigue(:, k) = [life%b_line, life%load_exp_line, life%a_point, life%load_exp_point, &
                               life%weibull_e_point]
         else
            e%fatigue(:, k) = [life%b_line, life%load_exp_line, life%a_point, life%load_exp_point, &
                               life%weibull_e_line]
         end if
         e%asperity(:, k) = [life%sigma_rms, life%theta_rms, life%mu_asperity, life%tau0, life%sigma_residual, &
                             life%matrix_m, life%contamination, life%processing_i]
      end do

      ! lubricant of the library (Rec 10.0 lubricant code); none printed for other codes
      if (deck_has(deck, "10.0")) then
         call deck_collect_int(deck, "10.0", "lubricant_code", code, error)
         if (code == LUBRICANT_MIL_L_7808) e%lubricant = "MIL-L-7808"
      end if

      ! initial operating conditions
      ! coolant type (Rec 2.4): 0 prints "No Coolant" (Appendix D echo), 1 "Lubricant"
      ! (Table 5 of the report for the Appendix C deck, whose echo line is lost)
      call deck_collect_int(deck, "2.4", "coolant_type", code, error)
      select case (code)
      case (0)
         e%coolant_type = "No Coolant"
      case (1)
         e%coolant_type = "Lubricant"
      end select
      e%room_temp = b%temperature(1)
      e%housing_temp = b%temperature(2)
      e%shaft_temp = b%temperature(3)
      e%re_temp = b%temperature(4)
      e%cage_temp = b%temperature(5)
      e%race_temp = b%temperature(6:7)
      e%race_speed = [b%speed_outer, b%speed_inner]*30.0_wp/pi
      e%misalign_y = 0.0_wp
      e%misalign_z = 0.0_wp
      e%n_qs = 0
      e%trans_constraints = INT_NOT_COMPUTED
      e%rot_constraints = INT_NOT_COMPUTED
      call deck_collect_real(deck, "2.1", "constraining_load_fraction", e%load_fraction, error, if_present=.true.)
      e%applied_load = b%force
      e%rel_disp = 0.0_wp
      e%applied_moment = b%moment
      e%gravity = b%gravity
      call deck_collect_real(deck, "9.5.1", "cage_center_x", e%cage_position(1), error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_center_y", e%cage_position(2), error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_center_z", e%cage_position(3), error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_angle_x", e%cage_angle(1), error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_angle_y", e%cage_angle(2), error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_angle_z", e%cage_angle(3), error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_whirl_ratio", e%whirl_ratio, error, if_present=.true.)
      call deck_collect_real(deck, "9.5.1", "cage_epicyclic_ratio", e%epicyclic_ratio, error, if_present=.true.)

      ! scale factors and output controls
      call scale_factors(b%d, b%mass(1), b%force, scales, error)
      if (allocated(error)) return
      e%scale_length = scales(1)
      e%scale_load = scales(2)
      e%scale_time = scales(3)
      call deck_collect_real(deck, "2.1", "step_min", e%step_min, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "step_max", e%step_max, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "step_initial", e%step_initial, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "error_limit", e%error_limit, error, if_present=.true.)
      e%n_steps = b%n_steps
      call deck_collect_int(deck, "1", "data_control_1", e%data_control(1), error)
      call deck_collect_int(deck, "1", "data_control_2", e%data_control(2), error)
      e%data_control(3) = INT_NOT_COMPUTED
      e%auto_plots = INT_NOT_COMPUTED
      call deck_collect_int(deck, "1", "int_method", e%int_method, error)

   end subroutine fill_echo

   !> Write step 0 of a ball bearing (sections 1-4) from its quasi-static start s.
   subroutine write_ball_step0(unit, b, s)
      integer, intent(in) :: unit
      type(bearing_t), intent(in) :: b
      type(ball_step0_t), intent(in) :: s

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp), allocatable :: contact(:, :), motion(:, :), traction(:, :), thermal(:, :), re_cage(:, :)
      real(wp) :: slices(1, 10, 0), race_cage(max(b%n_lands, 1), 7), bodies(3, 11)
      real(wp) :: loads(5, 6), acc(3, 7), perf(N_PERFORMANCE), summary(1, 10), nan
      integer, allocatable :: re_no(:), cage_code(:), cage_end(:)
      integer :: n, k
      integer :: land_no(max(b%n_lands, 1)), land_code(max(b%n_lands, 1))

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      n = b%n_elements
      allocate (contact(n, 11), motion(n, 11), traction(n, 11), thermal(n, 11), re_cage(n, 8))
      allocate (re_no(n), cage_code(n), cage_end(n))
      re_no = [(k, k=1, n)]
      motion = nan
      traction = nan
      thermal = nan
      re_cage = nan
      cage_code = INT_NOT_COMPUTED
      cage_end = 0
      associate (e => s%start%equilibrium, kin => s%start%kinematics)
         contact(:, 1) = e%azimuth*deg
         contact(:, 2) = e%alpha_o*deg
         contact(:, 3) = e%alpha_i*deg
         contact(:, 4) = e%q_o
         contact(:, 5) = e%q_i
         contact(:, 6) = e%c_o%max_pressure
         contact(:, 7) = e%c_i%max_pressure
         contact(:, 8) = e%c_o%semi_major
         contact(:, 9) = e%c_i%semi_major
         contact(:, 10) = e%c_o%semi_minor
         contact(:, 11) = e%c_i%semi_minor
         motion(:, 1) = kin%orbital_speed*rpm
         motion(:, 2) = abs(kin%spin_speed)*rpm
         motion(:, 5:6) = 0.0_wp                       ! angular positions at time 0
         ! spin axis in the print's convention: omega = -amplitude (cos theta, sin theta)
         motion(:, 3) = atan2(-kin%spin_speed*sin(kin%pitch), -kin%spin_speed*cos(kin%pitch))*deg
         motion(:, 4) = 0.0_wp                         ! no out-of-plane component at step 0
         motion(:, 7) = s%spin_roll(1, :)
         motion(:, 8) = s%spin_roll(2, :)
         motion(:, 9) = s%loss(1, :)
         motion(:, 10) = s%loss(2, :)
         motion(:, 11) = s%wear                        ! Archard, adore_tribology_wear
         traction(:, 1) = s%slip(1, :)
         traction(:, 2) = s%slip(2, :)
         traction(:, 3) = s%trac_coeff(1, :)
         traction(:, 4) = s%trac_coeff(2, :)
         traction(:, 5) = s%film(1, :)
         traction(:, 6) = s%film(2, :)
         traction(:, 7) = s%thermal_factor(1, :)
         traction(:, 8) = s%thermal_factor(2, :)
         thermal(:, 2) = e%delta_o
         thermal(:, 3) = e%delta_i
         thermal(:, 4:5) = 0.0_wp                      ! rigid races: no race flexing
         thermal(:, 6) = s%temp_rise(1, :)
         thermal(:, 7) = s%temp_rise(2, :)
         thermal(:, 8) = s%contact_temp(1, :)
         thermal(:, 9) = s%contact_temp(2, :)
         ! section 2 bodies: Cage, ORace, IRace
         call race_rows(bodies, e%u(2:3), b%speed_outer, b%speed_inner)
         bodies(3, [1, 8, 9]) = [e%axial_displacement, e%u(4)*deg, e%u(5)*deg]  ! docs/examples.md
         bodies(2, 10) = s%mounting%outer_hoop_stress  ! largest hoop stress (adore_mounting_fits)
         bodies(3, 10) = s%mounting%inner_hoop_stress
         bodies(2:3, 11) = s%race_wear                 ! Archard over each race's contacts
         ! section 3: forces of the balls on the races and the reactions holding them
         loads = nan
         ! normal contact loads plus contact tractions (solve_ball_step0)
         loads(2, :) = s%race_loads(:, 1)
         loads(3, :) = s%race_loads(:, 2)
         loads(4, 1:3) = -(s%race_loads(1:3, 1) + s%outer_weight)
         loads(4, 4:6) = -s%race_loads(4:6, 1)
         loads(5, 1:3) = -(s%race_loads(1:3, 2) + s%inner_weight)
         loads(5, 4:6) = -s%race_loads(4:6, 2)
      end associate
      land_no = [(k, k=1, size(land_no))]
      call cage_tables(s%cage, cage_code, re_cage, land_code, race_cage, bodies(1, :))
      acc = nan
      acc(2, 1:6) = 0.0_wp                             ! quasi-static: races at rest / in equilibrium
      acc(3, 1:6) = 0.0_wp
      acc(2, 7) = b%temperature(6)
      acc(3, 7) = b%temperature(7)
      call initial_thermal_state(b, s%cage, thermal, loads, acc, perf)
      perf(1) = s%basic_life_hours
      perf(2) = s%modified_life_hours
      perf(3) = s%mounting%outer_fit
      perf(4) = s%mounting%inner_fit
      perf(5) = s%mounting%clearance
      perf(6) = s%power_loss                           ! energy balance: sum of the contact losses
      summary = nan
      summary(1, 1:3) = 0.0_wp
      summary(1, 5) = s%power_loss
      summary(1, 4) = s%modified_life_hours            ! the report's summary shows the modified life
      summary(1, 6:8) = speed_ratios(b, sum(s%start%kinematics%orbital_speed)/n, s%cage)
      summary(1, 9) = bodies(1, 11)                    ! cage wear: 0 without a cage contact
      call write_step(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], b%run_id, re_no, contact, motion, traction, &
                      thermal, [integer ::], [integer ::], slices, 0, re_no, cage_end, cage_code, re_cage, &
                      land_no, land_code, race_cage, bodies, loads, acc, perf, [0], summary)
   end subroutine write_ball_step0

   !> Write step 0 of a cylindrical roller bearing (sections 1, 1a for roller 1, 2-4) from
   !> its quasi-static start s.  Section 1a: axial positions in each contact's frame (the
   !> inner contact's axis runs opposite to the outer one, as the report prints them) and
   !> loads per unit length in N/m for both races (the report's outer column appears to be
   !> scaled by the length scale D/2; pyadore prints N/m as the heading says - a known
   !> difference, see tests/test_run_golden.py).
   subroutine write_roller_step0(unit, b, s)
      integer, intent(in) :: unit
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(in) :: s

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp), allocatable :: contact(:, :), motion(:, :), traction(:, :), thermal(:, :), re_cage(:, :)
      real(wp), allocatable :: slices(:, :, :)
      real(wp) :: race_cage(max(b%n_lands, 1), 7), bodies(3, 11), loads(5, 6), acc(3, 7)
      real(wp) :: perf(N_PERFORMANCE), summary(1, 10), nan
      integer, allocatable :: re_no(:), slice_no(:), cage_el(:), cage_end(:), cage_code(:)
      integer :: land_no(max(b%n_lands, 1)), land_code(max(b%n_lands, 1))
      integer :: n, k, ns

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      n = b%n_elements
      allocate (contact(n, 11), motion(n, 11), traction(n, 11), thermal(n, 11))
      allocate (re_no(n), cage_el(2*n), cage_end(2*n), cage_code(2*n), re_cage(2*n, 8))
      re_no = [(k, k=1, n)]
      motion = nan
      traction = nan
      thermal = nan
      associate (e => s%equilibrium)
         ns = size(e%c_o(1)%x)
         allocate (slices(ns, 10, 1), slice_no(ns))
         slice_no = [(k, k=1, ns)]
         do k = 1, n
            contact(k, :) = [e%azimuth(k)*deg, 0.0_wp, 0.0_wp, e%c_o(k)%load, e%c_i(k)%load, &
                             e%c_o(k)%stress, e%c_i(k)%stress, e%c_o(k)%half_length, e%c_i(k)%half_length, &
                             e%c_o(k)%mean_half_width, e%c_i(k)%mean_half_width]
            thermal(k, 1) = 0.0_wp                    ! rollers stay axially centred at step 0
            thermal(k, 2) = e%c_o(k)%max_deflection
            thermal(k, 3) = e%c_i(k)%max_deflection
            thermal(k, 4:5) = 0.0_wp                  ! rigid races: no race flexing
            thermal(k, 6) = s%temp_rise(1, k)
            thermal(k, 7) = s%temp_rise(2, k)
            thermal(k, 8) = s%contact_temp(1, k)
            thermal(k, 9) = s%contact_temp(2, k)
         end do
         motion(:, 1) = e%orbital_speed*rpm
         motion(:, 2) = abs(s%spin_speed)*rpm
         motion(:, 3) = merge(180.0_wp, 0.0_wp, s%spin_speed < 0.0_wp)   ! spin axis along -x or +x
         motion(:, 4) = 0.0_wp                        ! no skew at the start
         motion(:, 5:6) = 0.0_wp                      ! angular positions at time 0
         motion(:, 7:8) = 0.0_wp                      ! cylindrical contact: no spin
         ! tribology (adore_tribology_roller_traction): printed slip = largest |u| over the
         ! slices, coefficient = kappa of it, contact loss = eq 4 summed over the slices
         motion(:, 9) = s%tr_o%power
         motion(:, 10) = s%tr_i%power
         motion(:, 11) = s%wear                       ! Archard, adore_tribology_wear
         traction(:, 1) = s%tr_o%max_slip
         traction(:, 2) = s%tr_i%max_slip
         traction(:, 3) = s%tr_o%max_slip_kappa
         traction(:, 4) = s%tr_i%max_slip_kappa
         slices = nan
         slices(:, 1, 1) = e%c_o(1)%x
         slices(:, 2, 1) = e%c_o(1)%delta
         slices(:, 3, 1) = e%c_o(1)%b
         slices(:, 4, 1) = e%c_o(1)%q
         slices(:, 6, 1) = -e%c_i(1)%x                ! in the inner contact frame (axis reversed)
         slices(:, 7, 1) = e%c_i(1)%delta
         slices(:, 8, 1) = e%c_i(1)%b
         slices(:, 9, 1) = e%c_i(1)%q
         ! traction on the race along the orbit direction, N/m (the report's outer column is
         ! scaled by D/2 as its normal load column)
         slices(:, 5, 1) = s%tr_o(1)%traction
         slices(:, 10, 1) = s%tr_i(1)%traction
         call race_rows(bodies, e%u, b%speed_outer, b%speed_inner)
         bodies(3, 1) = 0.0_wp          ! the roller model has no axial race motion (no thrust)
         bodies(2, 10) = s%mounting%outer_hoop_stress
         bodies(3, 10) = s%mounting%inner_hoop_stress
         bodies(2:3, 11) = s%race_wear
         loads = nan
         ! normal slice loads plus slice tractions (roller_tribology); the start leaves
         ! race weights out, so the external loads balance the internal ones
         loads(2, :) = s%race_loads(:, 1)
         loads(3, :) = s%race_loads(:, 2)
         loads(4, :) = -s%race_loads(:, 1)
         loads(5, :) = -s%race_loads(:, 2)
      end associate
      cage_el = [(1 + (k - 1)/2, k=1, 2*n)]
      cage_end = [(1 + mod(k - 1, 2), k=1, 2*n)]
      land_no = [(k, k=1, size(land_no))]
      call cage_tables(s%cage, cage_code, re_cage, land_code, race_cage, bodies(1, :))
      acc = nan
      acc(2:3, 1:6) = 0.0_wp
      acc(2, 7) = b%temperature(6)
      acc(3, 7) = b%temperature(7)
      call initial_thermal_state(b, s%cage, thermal, loads, acc, perf)
      perf(1) = s%basic_life_hours       ! eqs 73, 75, 76, 102 (adore_life_roller)
      perf(2) = s%modified_life_hours    ! NaN: no Tallian life for line contacts
      perf(3) = s%mounting%outer_fit
      perf(4) = s%mounting%inner_fit
      perf(5) = s%mounting%clearance
      perf(6) = s%power_loss             ! energy balance; NaN while a cage contact is not modelled
      summary = nan
      summary(1, 1:3) = 0.0_wp
      summary(1, 5) = s%power_loss
      summary(1, 4) = s%basic_life_hours   ! no modified life for line contacts: the basic one, as printed
      summary(1, 6:8) = speed_ratios(b, sum(s%equilibrium%orbital_speed)/n, s%cage)
      summary(1, 9) = bodies(1, 11)      ! cage wear: NaN while a cage contact is not modelled
      call write_step(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], b%run_id, re_no, contact, motion, traction, &
                      thermal, [1], slice_no, slices, 1, cage_el, cage_end, cage_code, re_cage, &
                      land_no, land_code, race_cage, bodies, loads, acc, perf, [0], summary)
   end subroutine write_roller_step0

   !> Section 2 cage rows from the step-0 cage c: RE/cage rows (one per ball, or end 1 and
   !> end 2 of each roller, in that order), race/cage rows (one per guide land; rows beyond
   !> the lands stay NaN) and the Cage row of the bodies table.
   !>
   !> Contact force, loss and wear rate are 0 and the code 0 where there is no contact
   !> (pocket and land: gap > 0, see adore_cage_step0); a contact needs the cage
   !> contact model (Rec 10.5.x, not done): NaN / not computed.  Land contact and attitude angles print 0 without contact
   !> (as the report's ball step 0), NaN with contact.  The cage's angular velocity is about
   !> +x (theta = phi = 0); its angular position theta, phi is 0 for an untilted cage (the
   !> mapping of Rec 9.5.1 angles y, z onto theta, phi is not identified: NaN otherwise).
   !> Hoop stress: not computed (NaN; the report prints 0 for the ball cage).
   subroutine cage_tables(c, code, re_cage, land_code, race_cage, cage_row)
      type(cage_step0_t), intent(in) :: c
      integer, intent(out) :: code(:), land_code(:)
      real(wp), intent(out) :: re_cage(:, :), race_cage(:, :), cage_row(:)

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp) :: nan
      integer :: k, j, row
      logical :: any_contact, contact

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      code = INT_NOT_COMPUTED
      re_cage = nan
      land_code = INT_NOT_COMPUTED
      race_cage = nan
      cage_row = nan
      any_contact = .false.
      if (allocated(c%pocket)) then
         do k = 1, size(c%pocket, 2)
            do j = 1, size(c%pocket, 1)
               row = (k - 1)*size(c%pocket, 1) + j
               if (row > size(re_cage, 1)) cycle
               associate (p => c%pocket(j, k))
                  re_cage(row, 1) = p%geo_int
                  re_cage(row, 3) = p%theta*deg
                  re_cage(row, 4) = p%phi*deg
                  re_cage(row, 5) = p%pos(1)
                  re_cage(row, 6) = p%pos(3)
                  contact = p%in_contact
               end associate
               if (.not. contact) then
                  code(row) = 0
                  re_cage(row, [2, 7, 8]) = 0.0_wp
               else
                  any_contact = .true.
               end if
            end do
         end do
      end if
      if (allocated(c%land)) then
         do k = 1, min(size(c%land), size(race_cage, 1))
            race_cage(k, 1) = c%land(k)%geo_int
            race_cage(k, 5) = c%land(k)%effective_play
            if (.not. c%land(k)%in_contact) then
               land_code(k) = 0
               race_cage(k, [2, 3, 4, 6, 7]) = 0.0_wp
            else
               any_contact = .true.
            end if
         end do
      end if
      associate (st => c%state)
         cage_row(1) = st%centre(1)
         cage_row(2) = hypot(st%centre(2), st%centre(3))
         cage_row(3) = st%orbital_angle*deg
         cage_row(4) = st%whirl_speed*rpm
         cage_row(5) = abs(st%angular_speed)*rpm
         if (st%angular_speed >= 0.0_wp) cage_row(6:7) = 0.0_wp   ! along +x
         if (c%geometry_known) cage_row(8:9) = 0.0_wp
         if (.not. any_contact) cage_row(11) = 0.0_wp
      end associate
   end subroutine cage_tables

   !> Section 2's ORace and IRace rows (bodies rows 2, 3) at step 0, from the inner race's
   !> displacement u_yz = (Y, Z) (m) and the race speeds (rad/s): the outer race fixed at
   !> the origin, the inner race centre at radius |u_yz| and azimuth (from +z towards -y, as
   !> the elements and the cage) of u_yz; no orbital motion of either centre in the
   !> quasi-static start; both races untilted (the runs prescribe zero misalignment), so
   !> they spin about +x (theta 0; 180 deg for a negative speed), phi 0, at angular position
   !> 0.  The report prints exactly these for the roller run's inner race (0, 7.758E-06, 0,
   !> 0, 7.000E+04, 0, 0, 0, 0) and phi 0 for the ball run's outer race.  The inner race's
   !> axial position (its origin is not identified for the ball), hoop stress and wear are
   !> left NaN for the caller.
   subroutine race_rows(bodies, u_yz, w_outer, w_inner)
      real(wp), intent(inout) :: bodies(:, :)
      real(wp), intent(in) :: u_yz(2), w_outer, w_inner
      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp) :: w(2)
      integer :: j

      bodies(2:3, :) = ieee_value(1.0_wp, ieee_quiet_nan)
      bodies(2, 1:3) = 0.0_wp
      bodies(3, 2) = hypot(u_yz(1), u_yz(2))
      bodies(3, 3) = 0.0_wp
      if (bodies(3, 2) > 0.0_wp) bodies(3, 3) = modulo(atan2(-u_yz(1), u_yz(2)), 2.0_wp*pi)*deg
      w = [w_outer, w_inner]
      do j = 1, 2
         bodies(j + 1, 4) = 0.0_wp
         bodies(j + 1, 5) = abs(w(j))*rpm
         bodies(j + 1, 6) = merge(180.0_wp, 0.0_wp, w(j) < 0.0_wp)
         bodies(j + 1, 7:9) = 0.0_wp
      end do
   end subroutine race_rows

   !> Step-0 values fixed by the deck alone, before any thermal solution or cage contact:
   !> the bodies' initial temperatures of Rec 2.7 (rolling elements' Bulk Temp, the cage's
   !> Bulk Temp, housing and shaft temperatures of section 3: ADORE's thermal nodes start
   !> at them; both report decks print them so at step 0), and, for a cage that touches
   !> nothing, zero cage forces and moments and an acceleration of gravity (Rec 11; no
   !> moment: no angular acceleration of the cage spinning about its axis of symmetry).
   !> perf is reset to NaN first; the rest of loads and acc is left as it is.
   subroutine initial_thermal_state(b, c, thermal, loads, acc, perf)
      type(bearing_t), intent(in) :: b
      type(cage_step0_t), intent(in) :: c
      real(wp), intent(inout) :: thermal(:, :), loads(:, :), acc(:, :)
      real(wp), intent(out) :: perf(:)
      perf = ieee_value(1.0_wp, ieee_quiet_nan)
      thermal(:, 10) = b%temperature(4)
      acc(1, 7) = b%temperature(5)
      perf(9:11) = b%temperature(2)                    ! Hsng/Bulk, Hsng/Outer, Hsng/Inner
      perf(12:14) = b%temperature(3)                   ! Shft/Bulk, Shft/Outer, Shft/Inner
      if (cage_free(c)) then
         loads(1, :) = 0.0_wp
         acc(1, 1:3) = b%gravity
         acc(1, 4:6) = 0.0_wp
      end if
   end subroutine initial_thermal_state

   !> True when the cage's geometry is modelled and it touches no rolling element and no land.
   pure logical function cage_free(c)
      type(cage_step0_t), intent(in) :: c
      cage_free = c%geometry_known
      if (allocated(c%pocket)) cage_free = cage_free .and. .not. any(c%pocket%in_contact)
      if (allocated(c%land)) cage_free = cage_free .and. .not. any(c%land%in_contact)
   end function cage_free

   !> Section 4 speed ratios at step 0 (time averages over one instant): mean rolling-element
   !> orbital speed, cage angular speed and cage whirl speed, each relative to the outer race
   !> over the inner race's speed relative to the outer race (both report decks turn the
   !> inner race only: 9139.7/20000 = 0.457 and 28490/70000 = 0.407 as printed); NaN when the
   !> races turn together.
   function speed_ratios(b, mean_orbital_speed, c) result(r)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: mean_orbital_speed   !< mean rolling-element orbital speed (rad/s)
      type(cage_step0_t), intent(in) :: c
      real(wp) :: r(3)
      real(wp) :: rel
      rel = b%speed_inner - b%speed_outer
      if (rel == 0.0_wp) then
         r = ieee_value(1.0_wp, ieee_quiet_nan)
         return
      end if
      r = ([mean_orbital_speed, c%state%angular_speed, c%state%whirl_speed] - b%speed_outer)/rel
   end function speed_ratios

end module adore_driver_report
