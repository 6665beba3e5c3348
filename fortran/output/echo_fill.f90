!> The input echo record of the print (report Appendix C/D echo) filled from the deck and
!> the bearing model: no formatting here (adore_output_print_echo writes it), no physics.
!>
!> A deck value whose meaning is not identified is left as IEEE NaN / INT_NOT_COMPUTED and
!> prints "NaN": the print never shows a made-up number.
module adore_output_echo_fill
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_deck_deck_type, only: deck_t, deck_collect_real, deck_collect_int, deck_count, deck_has
   use adore_model_bearing, only: bearing_t, BALL_BEARING, BODY_ELEMENT, BODY_CAGE, BODY_OUTER, BODY_INNER, &
                                   TEMP_CAGE, TEMP_ELEMENT, TEMP_HOUSING, TEMP_INNER, TEMP_OUTER, TEMP_ROOM, TEMP_SHAFT
   use adore_model_scales, only: scale_factors
   use adore_tribology_film, only: LUBRICANT_MIL_L_7808
   use adore_life_lundberg_palmgren, only: life_params_t
   use adore_output_echo_data, only: echo_data_t, echo_data_init
   use adore_output_layout, only: ELEMENT_BALL, ELEMENT_ROLLER, INT_NOT_COMPUTED, ECHO_MAX_GUIDE
   implicit none
   private

   !> The echo's inertia rows: rolling element, cage, outer race, inner race.
   integer, parameter :: ECHO_BODIES(4) = [BODY_ELEMENT, BODY_CAGE, BODY_OUTER, BODY_INNER]

   public :: fill_echo

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
         e%contact_angle = b%ball%alpha0*180.0_wp/pi
         e%cur_fac = [b%ball%f_o, b%ball%f_i]
         e%end_play = b%ball%end_play
      else
         e%bearing_type = "ROLLER"
         e%element_kind = ELEMENT_ROLLER
         e%roller_len = b%roller%roller_length
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
         associate (body => ECHO_BODIES(k))
            e%inertia(:, k) = [b%mass(body), b%moments(:, body), 0.0_wp, 0.0_wp, 0.0_wp]
         end associate
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
      e%room_temp = b%temperature(TEMP_ROOM)
      e%housing_temp = b%temperature(TEMP_HOUSING)
      e%shaft_temp = b%temperature(TEMP_SHAFT)
      e%re_temp = b%temperature(TEMP_ELEMENT)
      e%cage_temp = b%temperature(TEMP_CAGE)
      e%race_temp = b%temperature([TEMP_OUTER, TEMP_INNER])
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
      call scale_factors(b%d, b%mass(BODY_ELEMENT), b%force, scales, error, b%moment, 0.5_wp*b%dm)
      if (allocated(error)) return
      e%scale_length = scales(1)
      e%scale_load = scales(2)
      e%scale_time = scales(3)
      call deck_collect_real(deck, "2.1", "step_min", e%step_min, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "step_max", e%step_max, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "step_initial", e%step_initial, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "error_limit", e%error_limit, error, if_present=.true.)
      e%n_steps = b%controls%n_steps
      call deck_collect_int(deck, "1", "data_control_1", e%data_control(1), error)
      call deck_collect_int(deck, "1", "data_control_2", e%data_control(2), error)
      e%data_control(3) = INT_NOT_COMPUTED
      e%auto_plots = INT_NOT_COMPUTED
      call deck_collect_int(deck, "1", "int_method", e%int_method, error)

   end subroutine fill_echo

end module adore_output_echo_fill
