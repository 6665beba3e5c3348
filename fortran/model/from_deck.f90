!> The bearing model built from a read deck (ADORE's data modules, report Appendix A):
!> every deck value the physics uses, in SI units, and the derived values of the input
!> echo (plays, raceway diameters, inertia, fitted traction curve, lubricant).  The
!> relations between the values are checked by adore_model_checks before anything
!> divides by them.
module adore_model_from_deck
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_deck_deck_type, only: deck_t, deck_has, deck_count, deck_collect_real, deck_collect_int, &
                                   deck_collect_text
   use adore_deck_parser, only: read_deck
   use adore_model_bearing, only: bearing_t, BALL_BEARING, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, &
                                   TEMP_CAGE, TEMP_ELEMENT, TEMP_HOUSING, TEMP_INNER, TEMP_OUTER, TEMP_ROOM, TEMP_SHAFT
   use adore_model_checks, only: check_values
   use adore_model_clearance, only: ball_diametral_play, ball_end_play, ball_groove_diameters, &
                                    roller_race_diameters
   use adore_model_inertia, only: sphere_inertia, hollow_cylinder_inertia, ball_cage_inertia, &
                                  roller_cage_inertia, roller_moments
   use adore_contact_line_slices, only: roller_profile_t, roller_mass
   use adore_tribology_traction_fit, only: fit_traction_curve
   use adore_tribology_traction_law, only: curve_law
   use adore_tribology_film, only: lubricant_from_code
   implicit none
   private

   public :: build_bearing, read_bearing

   real(wp), parameter :: rpm = pi/30.0_wp

contains

   !> Build the bearing model from a read deck.  Input errors (values the physics cannot
   !> use, such as a traction curve without a maximum) come back in error.
   subroutine build_bearing(deck, b, error)
      type(deck_t), intent(in) :: deck
      type(bearing_t), intent(out) :: b
      type(error_type), allocatable, intent(out) :: error

      real(wp) :: k(4), deg, pocket, angle(3)
      integer :: j
      character(len=8) :: digits
      character(len=*), parameter :: material_rid(6) = ["8.1", "8.2", "8.3", "8.4", "8.5", "8.6"]

      call deck_collect_text(deck, "3.1", "run_id", b%run_id, error)
      call deck_collect_int(deck, "1", "mode", b%mode, error)
      call deck_collect_int(deck, "1", "n_steps", b%controls%n_steps, error)
      call deck_collect_int(deck, "1", "int_method", b%controls%int_method, error)
      call deck_collect_int(deck, "1", "data_control_2", b%controls%print_interval, error)
      call deck_collect_real(deck, "2.1", "step_initial", b%controls%step_initial, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "step_min", b%controls%step_min, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "step_max", b%controls%step_max, error, if_present=.true.)
      call deck_collect_real(deck, "2.1", "error_limit", b%controls%error_limit, error, if_present=.true.)
      call deck_collect_int(deck, "3.2", "bearing_type", b%bearing_type, error)
      call deck_collect_int(deck, "3.2", "n_rolling_elements", b%n_elements, error)
      do j = 1, size(b%dof_flags)
         write (digits, "(i0)") j
         call deck_collect_int(deck, "3.3", "rec3_3_flag_"//trim(digits), b%dof_flags(j), error)
      end do
      call deck_collect_real(deck, "4", "shaft_outer_diameter", b%shaft_od, error)
      call deck_collect_real(deck, "4", "bearing_outer_diameter", b%bearing_od, error)
      call deck_collect_real(deck, "4", "shaft_inner_diameter", b%shaft_id, error)
      call deck_collect_real(deck, "4", "housing_outer_diameter", b%housing_od, error)
      call deck_collect_real(deck, "4", "outer_race_width", b%width_outer, error)
      call deck_collect_real(deck, "4", "inner_race_width", b%width_inner, error)
      call deck_collect_real(deck, "7.1", "cage_outer_diameter", b%cage_od, error)
      call deck_collect_real(deck, "7.1", "cage_inner_diameter", b%cage_id, error)
      call deck_collect_real(deck, "7.1", "cage_width", b%cage_width, error)
      call deck_collect_real(deck, "7.1", "pocket_clearance_1", b%pocket_clearance(1), error)
      call deck_collect_real(deck, "7.1", "pocket_clearance_2", b%pocket_clearance(2), error)
      call deck_collect_int(deck, "7.0", "n_guide_lands", b%n_lands, error)
      if (allocated(error)) return
      if (b%n_lands < 0 .or. deck_count(deck, "7.2") < b%n_lands) then
         call input_error(error, "Rec 7.0: n_guide_lands must be >= 0 with one Rec 7.2.n per land")
         return
      end if
      allocate (b%lands(b%n_lands))
      do j = 1, b%n_lands
         write (digits, "(i0)") j
         call deck_collect_int(deck, "7.0", "guide_type["//trim(digits)//"]", b%lands(j)%guide, error)
         call deck_collect_real(deck, "7.2", "guide_land_diameter", b%lands(j)%diameter, error, j)
         call deck_collect_real(deck, "7.2", "guide_land_width", b%lands(j)%width, error, j)
         call deck_collect_real(deck, "7.2", "guide_land_position", b%lands(j)%position, error, j)
         call deck_collect_real(deck, "7.2", "guide_land_clearance", b%lands(j)%clearance, error, j)
      end do
      if (deck_has(deck, "9.5.1")) then
         call deck_collect_real(deck, "9.5.1", "cage_whirl_radius", b%cage_initial%whirl_radius, error)
         call deck_collect_real(deck, "9.5.1", "cage_whirl_ratio", b%cage_initial%whirl_ratio, error)
         call deck_collect_real(deck, "9.5.1", "cage_epicyclic_ratio", b%cage_initial%epicyclic_ratio, error)
         call deck_collect_real(deck, "9.5.1", "cage_center_x", b%cage_initial%centre(1), error)
         call deck_collect_real(deck, "9.5.1", "cage_center_y", b%cage_initial%centre(2), error)
         call deck_collect_real(deck, "9.5.1", "cage_center_z", b%cage_initial%centre(3), error)
         call deck_collect_real(deck, "9.5.1", "cage_angle_x", angle(1), error)
         call deck_collect_real(deck, "9.5.1", "cage_angle_y", angle(2), error)
         call deck_collect_real(deck, "9.5.1", "cage_angle_z", angle(3), error)
         b%cage_initial%angle = angle*pi/180.0_wp
      end if
      if (allocated(error)) return

      ! coolant and thermal times (Rec 2.4, 2.5)
      call deck_collect_int(deck, "2.4", "coolant_type", b%coolant%coolant_type, error)
      call deck_collect_real(deck, "2.5", "coolant_inlet_temperature", b%coolant%inlet_temperature, error)
      call deck_collect_real(deck, "2.5", "coolant_flow_rate", b%coolant%flow_rate, error)
      call deck_collect_real(deck, "2.5", "thermal_time_1", b%coolant%thermal_time(1), error)
      call deck_collect_real(deck, "2.5", "thermal_time_2", b%coolant%thermal_time(2), error)
      ! operating conditions (Rec 2.7, 9.0, 9.1, 11)
      call deck_collect_real(deck, "9.0", "room_temperature", b%temperature(TEMP_ROOM), error)
      call deck_collect_real(deck, "2.7", "housing_temperature", b%temperature(TEMP_HOUSING), error)
      call deck_collect_real(deck, "2.7", "shaft_temperature", b%temperature(TEMP_SHAFT), error)
      call deck_collect_real(deck, "2.7", "rolling_element_temperature", b%temperature(TEMP_ELEMENT), error)
      call deck_collect_real(deck, "2.7", "cage_temperature", b%temperature(TEMP_CAGE), error)
      call deck_collect_real(deck, "2.7", "outer_race_temperature", b%temperature(TEMP_OUTER), error)
      call deck_collect_real(deck, "2.7", "inner_race_temperature", b%temperature(TEMP_INNER), error)
      call deck_collect_real(deck, "9.0", "outer_race_fit", b%fit_outer, error)
      call deck_collect_real(deck, "9.0", "inner_race_fit", b%fit_inner, error)
      call deck_collect_real(deck, "9.1.2", "inner_race_speed", b%speed_inner, error)
      call deck_collect_real(deck, "9.1.1", "applied_force_x", b%force(1), error)
      call deck_collect_real(deck, "9.1.1", "applied_force_y", b%force(2), error)
      call deck_collect_real(deck, "9.1.1", "applied_force_z", b%force(3), error)
      call deck_collect_real(deck, "9.1.1", "applied_moment_x", b%moment(1), error)
      call deck_collect_real(deck, "9.1.1", "applied_moment_y", b%moment(2), error)
      call deck_collect_real(deck, "9.1.1", "applied_moment_z", b%moment(3), error)
      call deck_collect_real(deck, "11", "gravity_x", b%gravity(1), error)
      call deck_collect_real(deck, "11", "gravity_y", b%gravity(2), error)
      call deck_collect_real(deck, "11", "gravity_z", b%gravity(3), error)
      if (allocated(error)) return
      b%speed_inner = b%speed_inner*rpm

      ! materials: default steel (cage: its own expansion, hardness and wear), Rec 8.n when present
      b%material(BODY_CAGE)%expansion = 1.8e-5_wp
      b%material(BODY_CAGE)%hardness = 20.0_wp
      b%material(BODY_CAGE)%wear = 5.0e-4_wp
      do j = 1, 6
         if (.not. deck_has(deck, material_rid(j))) cycle
         call deck_collect_real(deck, material_rid(j), "density", b%material(j)%density, error)
         call deck_collect_real(deck, material_rid(j), "elastic_modulus", b%material(j)%modulus, error)
         call deck_collect_real(deck, material_rid(j), "poisson_ratio", b%material(j)%poisson, error)
         call deck_collect_real(deck, material_rid(j), "thermal_expansion", b%material(j)%expansion, error)
         call deck_collect_real(deck, material_rid(j), "heat_capacity", b%material(j)%heat_capacity, error)
         call deck_collect_real(deck, material_rid(j), "thermal_conductivity", b%material(j)%conductivity, error)
         call deck_collect_real(deck, material_rid(j), "elastic_strain_limit", b%material(j)%strain_limit, error)
         call deck_collect_real(deck, material_rid(j), "hardness", b%material(j)%hardness, error)
         call deck_collect_real(deck, material_rid(j), "wear_coefficient", b%material(j)%wear, error)
      end do
      if (allocated(error)) return

      if (b%bearing_type == BALL_BEARING) then
         if (deck_has(deck, "5B.2")) then
            call input_error(error, "Rec 5B.2 (roller ends, flanges, pocket type) applies to cylindrical roller "// &
                             "bearings; this deck is a ball bearing (Rec 3.2): set Rec 3.2 field 11 to 0")
            return
         end if
         call deck_collect_real(deck, "5A", "ball_diameter", b%d, error)
         call deck_collect_real(deck, "5A", "pitch_diameter", b%dm, error)
         call deck_collect_real(deck, "5A", "free_contact_angle", deg, error)
         call deck_collect_real(deck, "5A", "outer_curvature_factor", b%ball%f_o, error)
         call deck_collect_real(deck, "5A", "inner_curvature_factor", b%ball%f_i, error)
         call deck_collect_real(deck, "10.1C", "traction_at_zero_slip", k(1), error)
         call deck_collect_real(deck, "10.1C", "max_traction", k(2), error)
         call deck_collect_real(deck, "10.1C", "traction_at_infinite_slip", k(3), error)
         call deck_collect_real(deck, "10.1C", "slip_at_max_traction", k(4), error)
         if (allocated(error)) return
         b%ball%alpha0 = deg*pi/180.0_wp
         b%dia_play = ball_diametral_play(b%d, b%ball%f_o, b%ball%f_i, b%ball%alpha0)
         b%ball%end_play = ball_end_play(b%d, b%ball%f_o, b%ball%f_i, b%ball%alpha0)
         call ball_groove_diameters(b%dm, b%d, b%ball%f_o, b%ball%f_i, b%ball%alpha0, b%outer_raceway_dia, b%inner_raceway_dia)
         call sphere_inertia(b%d, b%material(BODY_ELEMENT)%density, b%mass(BODY_ELEMENT), b%moments(:, BODY_ELEMENT))
         pocket = b%d + b%pocket_clearance(1)
         call ball_cage_inertia(b%cage_od, b%cage_id, b%cage_width, b%n_elements, pocket, &
                                b%material(BODY_CAGE)%density, b%mass(BODY_CAGE), b%moments(:, BODY_CAGE))
      else
         call deck_collect_real(deck, "5B", "roller_diameter", b%d, error)
         call deck_collect_real(deck, "5B", "roller_length", b%roller%roller_length, error)
         call deck_collect_real(deck, "5B", "pitch_diameter", b%dm, error)
         call deck_collect_real(deck, "5B", "diametral_play", b%dia_play, error)
         call deck_collect_real(deck, "5B", "central_land_length", b%roller%roller_land, error)
         call deck_collect_real(deck, "5B", "crown_radius", b%roller%crown_radius, error)
         call deck_collect_real(deck, "5B", "corner_radius_1", b%roller%corner_radius(1), error)
         call deck_collect_real(deck, "5B", "corner_radius_2", b%roller%corner_radius(2), error)
         call deck_collect_real(deck, "5B", "outer_race_crown_radius", b%roller%race_crown(1), error)
         call deck_collect_real(deck, "5B", "inner_race_crown_radius", b%roller%race_crown(2), error)
         call deck_collect_real(deck, "5B.1", "outer_race_len1", b%roller%race_length(1), error)
         call deck_collect_real(deck, "5B.1", "inner_race_len1", b%roller%race_length(2), error)
         if (deck_has(deck, "5B.2")) call read_roller_extension(deck, b, error)
         call deck_collect_real(deck, "10.1B", "traction_at_zero_slip", k(1), error)
         call deck_collect_real(deck, "10.1B", "max_traction", k(2), error)
         call deck_collect_real(deck, "10.1B", "traction_at_infinite_slip", k(3), error)
         call deck_collect_real(deck, "10.1B", "slip_at_max_traction", k(4), error)
         if (allocated(error)) return
         call roller_race_diameters(b%dm, b%d, b%dia_play, b%outer_raceway_dia, b%inner_raceway_dia)
         ! the crowned roller (land and crown arcs; adore_contact_line_slices): the same mass
         ! for the centrifugal force, the echo and the time scale
         b%mass(BODY_ELEMENT) = roller_mass(roller_profile_t(b%roller%roller_length, b%roller%roller_land, b%roller%crown_radius, &
                                                  b%roller%corner_radius), b%d, b%material(BODY_ELEMENT)%density)
         b%moments(:, BODY_ELEMENT) = roller_moments(b%mass(BODY_ELEMENT), b%d, b%roller%roller_length)
         call roller_cage_inertia(b%cage_od, b%cage_id, b%cage_width, b%n_elements, &
                                  b%d + b%pocket_clearance(1), b%roller%roller_length + b%pocket_clearance(2), &
                                  b%material(BODY_CAGE)%density, b%mass(BODY_CAGE), b%moments(:, BODY_CAGE))
      end if
      b%traction_input = k
      call check_values(deck, error)
      if (allocated(error)) return
      call hollow_cylinder_inertia(b%bearing_od, b%outer_raceway_dia, b%width_outer, &
                                   b%material(BODY_OUTER)%density, b%mass(BODY_OUTER), b%moments(:, BODY_OUTER))
      call hollow_cylinder_inertia(b%inner_raceway_dia, b%shaft_od, b%width_inner, &
                                   b%material(BODY_INNER)%density, b%mass(BODY_INNER), b%moments(:, BODY_INNER))
      call fit_traction_curve(k(1), k(2), k(3), k(4), b%traction, error)
      if (allocated(error)) return
      b%race_traction = curve_law(b%traction)
      call deck_collect_int(deck, "10.0", "traction_model", b%traction_model, error, if_present=.true.)
      call deck_collect_int(deck, "10.0", "lubricant_code", b%lubricant_code, error, if_present=.true.)
      if (allocated(error)) return
      call deck_collect_real(deck, "10.5.1B", "re_cage_coeff_a", b%cage_friction(1), error, if_present=.true.)
      call deck_collect_real(deck, "10.5.2B", "race_cage_coeff_a", b%cage_friction(2), error, if_present=.true.)
      if (allocated(error)) return
      if (b%lubricant_code /= 0) then
         call lubricant_from_code(b%lubricant_code, b%lubricant, error)
         if (allocated(error)) then
            error%message = "Rec 10.0 field lubricant_code: "//error%message
            return
         end if
      end if

   end subroutine build_bearing

   !> pyadore's Rec 5B.2 (roller ends, flanges, pocket type; docs/rollers.md, "Flanges"):
   !> angles from degrees to radians.
   subroutine read_roller_extension(deck, b, error)
      type(deck_t), intent(in) :: deck
      type(bearing_t), intent(inout) :: b
      type(error_type), allocatable, intent(inout) :: error
      character(len=*), parameter :: flag(2, 2) = reshape([character(len=14) :: "outer_flange_1", &
                                                           "outer_flange_2", "inner_flange_1", "inner_flange_2"], [2, 2])
      integer :: j, k, v
      call deck_collect_int(deck, "5B.2", "pocket_type", b%roller%pocket_type, error)
      do j = 1, 2
         do k = 1, 2
            v = 0
            call deck_collect_int(deck, "5B.2", flag(k, j), v, error)
            b%roller%flange(k, j) = v /= 0
         end do
      end do
      call deck_collect_real(deck, "5B.2", "roller_end_radius", b%roller%end_radius, error)
      call deck_collect_real(deck, "5B.2", "outer_flange_height", b%roller%flange_height(1), error)
      call deck_collect_real(deck, "5B.2", "inner_flange_height", b%roller%flange_height(2), error)
      call deck_collect_real(deck, "5B.2", "outer_flange_angle", b%roller%flange_angle(1), error)
      call deck_collect_real(deck, "5B.2", "inner_flange_angle", b%roller%flange_angle(2), error)
      call deck_collect_real(deck, "5B.2", "outer_flange_clearance", b%roller%flange_clearance(1), error)
      call deck_collect_real(deck, "5B.2", "inner_flange_clearance", b%roller%flange_clearance(2), error)
      b%roller%flange_angle = b%roller%flange_angle*pi/180.0_wp
   end subroutine read_roller_extension

   !> Read the deck at `path` (all checks of adore_deck_parser) and build its bearing model.
   subroutine read_bearing(path, b, error)
      character(len=*), intent(in) :: path
      type(bearing_t), intent(out) :: b
      type(error_type), allocatable, intent(out) :: error
      type(deck_t) :: deck

      call read_deck(path, deck, error)
      if (allocated(error)) return
      call build_bearing(deck, b, error)
   end subroutine read_bearing

end module adore_model_from_deck
