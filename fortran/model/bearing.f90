!> The bearing model built from a deck (ADORE's data modules, report Appendix A): geometry,
!> materials, inertia, traction curves and operating conditions, in SI units, with every
!> derived value of the input echo.  Built once per run by build_bearing; read-only after.
module adore_model_bearing
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_deck_deck_type, only: deck_t, deck_has, deck_count, deck_collect_real, deck_collect_int, &
                                   deck_collect_text
   use adore_deck_parser, only: read_deck
   use adore_deck_problems, only: deck_field_problem
   use adore_deck_tokenizer, only: show_real, itoa
   use adore_model_clearance, only: ball_diametral_play, ball_end_play, ball_groove_diameters, &
                                    roller_race_diameters
   use adore_model_inertia, only: sphere_inertia, hollow_cylinder_inertia, ball_cage_inertia, &
                                  roller_cage_inertia, roller_moments
   use adore_contact_line_slices, only: roller_profile_t, roller_mass
   use adore_model_traction_fit, only: fit_traction_curve
   use adore_model_scales, only: load_scale
   use adore_tribology_traction_law, only: traction_law_t, curve_law
   use adore_tribology_film, only: lubricant_t, lubricant_from_code
   use adore_cage_step0, only: guide_land_t, cage_input_t
   implicit none
   private

   public :: material_t, bearing_t, build_bearing, read_bearing
   public :: BALL_BEARING, ROLLER_BEARING
   public :: BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, BODY_SHAFT, BODY_HOUSING

   integer, parameter :: BALL_BEARING = 1     !< Rec 3.2 bearing type
   integer, parameter :: ROLLER_BEARING = 2
   !> Body indices of the material table (echo column order).
   integer, parameter :: BODY_ELEMENT = 1, BODY_OUTER = 2, BODY_INNER = 3, BODY_CAGE = 4, &
                         BODY_SHAFT = 5, BODY_HOUSING = 6

   real(wp), parameter :: rpm = pi/30.0_wp

   !> Material properties of one body (echo MATERIAL PROPERTIES).
   type :: material_t
      real(wp) :: density = 7750.0_wp          !< kg/m**3
      real(wp) :: modulus = 2.0e11_wp          !< Pa
      real(wp) :: poisson = 0.25_wp
      real(wp) :: expansion = 1.17e-5_wp       !< 1/K
      real(wp) :: conductivity = 43.0_wp       !< W/(m K)
      real(wp) :: heat_capacity = 470.0_wp     !< J/(kg K)
      real(wp) :: strain_limit = 2.0e-3_wp
      real(wp) :: hardness = 61.0_wp           !< Rockwell C
      real(wp) :: wear = 5.0e-6_wp             !< wear coefficient
   end type material_t

   !> Everything the physics needs from the deck.
   type :: bearing_t
      character(len=:), allocatable :: run_id
      integer :: bearing_type = BALL_BEARING
      integer :: mode = 1
      integer :: n_elements = 0
      integer :: n_steps = 0
      ! envelope, Rec 4 (m)
      real(wp) :: shaft_od = 0.0_wp, bearing_od = 0.0_wp, shaft_id = 0.0_wp, housing_od = 0.0_wp
      real(wp) :: width_outer = 0.0_wp, width_inner = 0.0_wp
      ! rolling elements, Rec 5A (ball) / 5B (roller)
      real(wp) :: d = 0.0_wp                   !< ball or roller diameter (m)
      real(wp) :: dm = 0.0_wp                  !< pitch diameter (m)
      real(wp) :: alpha0 = 0.0_wp              !< free contact angle (rad), ball
      real(wp) :: f_o = 0.0_wp, f_i = 0.0_wp   !< groove curvature factors, ball
      real(wp) :: roller_length = 0.0_wp       !< (m), roller
      real(wp) :: roller_land = 0.0_wp         !< central flat land length (m), roller
      real(wp) :: crown_radius = 1.0e10_wp     !< roller crown radius (m), roller
      real(wp) :: corner_radius(2) = 0.0_wp    !< roller corner radii, -x and +x end (m)
      real(wp) :: race_crown(2) = 1.0e10_wp    !< outer, inner race crown radii (m)
      real(wp) :: race_length(2) = 0.0_wp      !< outer, inner race length 1 (Rec 5B.1, m; 0 = none)
      real(wp) :: dia_play = 0.0_wp            !< unmounted diametral play (m)
      real(wp) :: end_play = 0.0_wp            !< unmounted end play (m), ball
      real(wp) :: outer_raceway_dia = 0.0_wp   !< outer groove bottom / raceway diameter (m)
      real(wp) :: inner_raceway_dia = 0.0_wp   !< inner groove bottom / raceway diameter (m)
      ! cage, Rec 7.1
      real(wp) :: cage_od = 0.0_wp, cage_id = 0.0_wp, cage_width = 0.0_wp
      real(wp) :: pocket_clearance(2) = 0.0_wp
      integer :: n_lands = 0                   !< cage guide lands (Rec 7.0)
      type(guide_land_t), allocatable :: lands(:)   !< Rec 7.0 guide types, Rec 7.2.n (n_lands)
      type(cage_input_t) :: cage_initial       !< Rec 9.5.1 (angles in rad)
      ! materials (echo order: element, outer, inner, cage, shaft, housing)
      type(material_t) :: material(6)
      ! inertia (element, cage, outer race, inner race): kg and kg m**2 (x, y, z)
      real(wp) :: mass(4) = 0.0_wp
      real(wp) :: moments(3, 4) = 0.0_wp
      ! traction curves (RE/race): kappa(u) = (A + B u) exp(-C u) + D, Rec 10.1x
      real(wp) :: traction(4) = 0.0_wp
      !> its deck inputs: kappa at zero slip, maximum kappa, kappa at infinite slip, slip at the maximum (m/s)
      real(wp) :: traction_input(4) = 0.0_wp
      !> RE/race traction model (Rec 10.0 traction_model): 3 = EHD (report Table 5), else the curve
      integer :: traction_model = 0
      !> the RE/race traction law the run uses: the curve above, or a traction-slip table
      !> (ADRX7, report 4.4.9) given besides the deck, which then replaces curve and model
      type(traction_law_t) :: race_traction
      !> lubricant of the library (Rec 10.0 lubricant_code; 0: none, lubricant unset)
      integer :: lubricant_code = 0
      type(lubricant_t) :: lubricant
      ! operating conditions, Rec 2.7, 9.0, 9.1.x, 11
      !> initial temperatures (K): room, housing, shaft, element, cage, outer race, inner race
      real(wp) :: temperature(7) = 293.0_wp
      real(wp) :: fit_outer = 0.0_wp, fit_inner = 0.0_wp   !< mounted diametral interference (m)
      real(wp) :: speed_outer = 0.0_wp, speed_inner = 0.0_wp  !< race speeds (rad/s)
      real(wp) :: force(3) = 0.0_wp            !< applied to the inner race (N)
      real(wp) :: moment(3) = 0.0_wp           !< applied to the inner race (N m)
      real(wp) :: gravity(3) = 0.0_wp          !< (m/s**2)
   end type bearing_t

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
      call deck_collect_int(deck, "1", "n_steps", b%n_steps, error)
      call deck_collect_int(deck, "3.2", "bearing_type", b%bearing_type, error)
      call deck_collect_int(deck, "3.2", "n_rolling_elements", b%n_elements, error)
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

      ! operating conditions (Rec 2.7, 9.0, 9.1, 11)
      call deck_collect_real(deck, "9.0", "room_temperature", b%temperature(1), error)
      call deck_collect_real(deck, "2.7", "housing_temperature", b%temperature(2), error)
      call deck_collect_real(deck, "2.7", "shaft_temperature", b%temperature(3), error)
      call deck_collect_real(deck, "2.7", "rolling_element_temperature", b%temperature(4), error)
      call deck_collect_real(deck, "2.7", "cage_temperature", b%temperature(5), error)
      call deck_collect_real(deck, "2.7", "outer_race_temperature", b%temperature(6), error)
      call deck_collect_real(deck, "2.7", "inner_race_temperature", b%temperature(7), error)
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
         call deck_collect_real(deck, "5A", "ball_diameter", b%d, error)
         call deck_collect_real(deck, "5A", "pitch_diameter", b%dm, error)
         call deck_collect_real(deck, "5A", "free_contact_angle", deg, error)
         call deck_collect_real(deck, "5A", "outer_curvature_factor", b%f_o, error)
         call deck_collect_real(deck, "5A", "inner_curvature_factor", b%f_i, error)
         call deck_collect_real(deck, "10.1C", "traction_at_zero_slip", k(1), error)
         call deck_collect_real(deck, "10.1C", "max_traction", k(2), error)
         call deck_collect_real(deck, "10.1C", "traction_at_infinite_slip", k(3), error)
         call deck_collect_real(deck, "10.1C", "slip_at_max_traction", k(4), error)
         if (allocated(error)) return
         b%alpha0 = deg*pi/180.0_wp
         b%dia_play = ball_diametral_play(b%d, b%f_o, b%f_i, b%alpha0)
         b%end_play = ball_end_play(b%d, b%f_o, b%f_i, b%alpha0)
         call ball_groove_diameters(b%dm, b%d, b%f_o, b%f_i, b%alpha0, b%outer_raceway_dia, b%inner_raceway_dia)
         call sphere_inertia(b%d, b%material(BODY_ELEMENT)%density, b%mass(1), b%moments(:, 1))
         pocket = b%d + b%pocket_clearance(1)
         call ball_cage_inertia(b%cage_od, b%cage_id, b%cage_width, b%n_elements, pocket, &
                                b%material(BODY_CAGE)%density, b%mass(2), b%moments(:, 2))
      else
         call deck_collect_real(deck, "5B", "roller_diameter", b%d, error)
         call deck_collect_real(deck, "5B", "roller_length", b%roller_length, error)
         call deck_collect_real(deck, "5B", "pitch_diameter", b%dm, error)
         call deck_collect_real(deck, "5B", "diametral_play", b%dia_play, error)
         call deck_collect_real(deck, "5B", "central_land_length", b%roller_land, error)
         call deck_collect_real(deck, "5B", "crown_radius", b%crown_radius, error)
         call deck_collect_real(deck, "5B", "corner_radius_1", b%corner_radius(1), error)
         call deck_collect_real(deck, "5B", "corner_radius_2", b%corner_radius(2), error)
         call deck_collect_real(deck, "5B", "outer_race_crown_radius", b%race_crown(1), error)
         call deck_collect_real(deck, "5B", "inner_race_crown_radius", b%race_crown(2), error)
         call deck_collect_real(deck, "5B.1", "outer_race_len1", b%race_length(1), error)
         call deck_collect_real(deck, "5B.1", "inner_race_len1", b%race_length(2), error)
         call deck_collect_real(deck, "10.1B", "traction_at_zero_slip", k(1), error)
         call deck_collect_real(deck, "10.1B", "max_traction", k(2), error)
         call deck_collect_real(deck, "10.1B", "traction_at_infinite_slip", k(3), error)
         call deck_collect_real(deck, "10.1B", "slip_at_max_traction", k(4), error)
         if (allocated(error)) return
         call roller_race_diameters(b%dm, b%d, b%dia_play, b%outer_raceway_dia, b%inner_raceway_dia)
         ! the crowned roller (land and crown arcs; adore_contact_line_slices): the same mass
         ! for the centrifugal force, the echo and the time scale
         b%mass(1) = roller_mass(roller_profile_t(b%roller_length, b%roller_land, b%crown_radius, &
                                                  b%corner_radius), b%d, b%material(BODY_ELEMENT)%density)
         b%moments(:, 1) = roller_moments(b%mass(1), b%d, b%roller_length)
         call roller_cage_inertia(b%cage_od, b%cage_id, b%cage_width, b%n_elements, &
                                  b%d + b%pocket_clearance(1), b%roller_length + b%pocket_clearance(2), &
                                  b%material(BODY_CAGE)%density, b%mass(2), b%moments(:, 2))
      end if
      b%traction_input = k
      call check_values(deck, b, error)
      if (allocated(error)) return
      call hollow_cylinder_inertia(b%bearing_od, b%outer_raceway_dia, b%width_outer, &
                                   b%material(BODY_OUTER)%density, b%mass(3), b%moments(:, 3))
      call hollow_cylinder_inertia(b%inner_raceway_dia, b%shaft_od, b%width_inner, &
                                   b%material(BODY_INNER)%density, b%mass(4), b%moments(:, 4))
      call fit_traction_curve(k(1), k(2), k(3), k(4), b%traction, error)
      if (allocated(error)) return
      b%race_traction = curve_law(b%traction)
      call deck_collect_int(deck, "10.0", "traction_model", b%traction_model, error, if_present=.true.)
      call deck_collect_int(deck, "10.0", "lubricant_code", b%lubricant_code, error, if_present=.true.)
      if (allocated(error)) return
      if (b%lubricant_code /= 0) then
         call lubricant_from_code(b%lubricant_code, b%lubricant, error)
         if (allocated(error)) then
            error%message = "Rec 10.0 field lubricant_code: "//error%message
            return
         end if
      end if

   end subroutine build_bearing

   !> The relations between deck values the physics needs (envelope and ring geometry for
   !> the mounting, inertia and contacts; the traction curve's peak; the step sizes): input
   !> error listing every violated relation at once, each at its deck field with a caret.
   !> These are pyadore/deck/validate.py's CROSS_CHECKS, in the same words (the deck
   !> reader does not port them; pyadore validate reports them with the record checks),
   !> plus a positive wall for both races, which the mounting's thick-ring formulas divide
   !> by (inner raceway diameter > bore, outer raceway diameter < bearing OD), and a
   !> non-zero applied force (the echo's load scale; ADORE's rule without one is unknown).
   subroutine check_values(deck, b, error)
      type(deck_t), intent(in) :: deck
      type(bearing_t), intent(in) :: b
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: msg, rec5, dname, text, rec10
      integer :: n, n_max
      real(wp) :: chord, step(3)

      rec5 = merge("5A", "5B", b%bearing_type == BALL_BEARING)
      dname = merge("ball_diameter  ", "roller_diameter", b%bearing_type == BALL_BEARING)
      dname = trim(dname)
      msg = ""
      n = 0
      call less("4", "shaft_inner_diameter", b%shaft_id, "shaft_outer_diameter", b%shaft_od, &
                "a hollow shaft's bore is inside its OD")
      call less("4", "shaft_outer_diameter", b%shaft_od, "bearing_outer_diameter", b%bearing_od, &
                "bore inside the bearing OD")
      call less("4", "bearing_outer_diameter", b%bearing_od, "housing_outer_diameter", b%housing_od, &
                "bearing inside the housing")
      if (.not. (b%shaft_od < b%dm .and. b%dm < b%bearing_od)) &
         call add(rec5, "pitch_diameter", "expected between the bore (shaft_outer_diameter = "// &
                  show_real(b%shaft_od)//") and bearing_outer_diameter = "//show_real(b%bearing_od))
      if (.not. b%d < 0.5_wp*(b%bearing_od - b%shaft_od)) &
         call add(rec5, dname, "expected < (bearing_outer_diameter - shaft_outer_diameter)/2 = "// &
                  show_real(0.5_wp*(b%bearing_od - b%shaft_od))//" (the element must fit between bore and OD)")
      if (b%n_elements >= 2 .and. b%dm > 0.0_wp) then
         chord = b%dm*sin(pi/b%n_elements)
         if (.not. chord > b%d) then
            n_max = 1
            if (b%d < b%dm) n_max = max(int(pi/asin(min(b%d/b%dm, 1.0_wp))), 1)
            call add("3.2", "n_rolling_elements", "expected at most "//itoa(n_max)//": "// &
                     itoa(b%n_elements)//" elements of "//dname//" = "//show_real(b%d)// &
                     " m do not fit around pitch_diameter = "//show_real(b%dm)//" m (spacing "// &
                     show_real(chord)//" m)")
         end if
      end if
      call less("7.1", "cage_inner_diameter", b%cage_id, "cage_outer_diameter", b%cage_od, &
                "cage ID inside cage OD")
      if (b%cage_id < b%cage_od .and. .not. (b%cage_id < b%dm .and. b%dm < b%cage_od)) &
         call add(rec5, "pitch_diameter", "expected between cage_inner_diameter = "//show_real(b%cage_id)// &
                  " and cage_outer_diameter = "//show_real(b%cage_od))
      ! the races' walls, once the envelope itself is ordered (as validate.py's _race_walls)
      if (b%shaft_od < b%dm .and. b%dm < b%bearing_od .and. b%d < 0.5_wp*(b%bearing_od - b%shaft_od)) then
         if (.not. b%inner_raceway_dia > b%shaft_od) &
            call add(rec5, "pitch_diameter", "the inner race has no wall: its raceway diameter "// &
                     show_real(b%inner_raceway_dia)//" m is not above the bore (shaft_outer_diameter = "// &
                     show_real(b%shaft_od)//")")
         if (.not. b%outer_raceway_dia < b%bearing_od) &
            call add(rec5, "pitch_diameter", "the outer race has no wall: its raceway diameter "// &
                     show_real(b%outer_raceway_dia)//" m is not below bearing_outer_diameter = "// &
                     show_real(b%bearing_od))
      end if
      call deck_collect_real(deck, "2.1", "step_initial", step(1), error)
      call deck_collect_real(deck, "2.1", "step_min", step(2), error)
      call deck_collect_real(deck, "2.1", "step_max", step(3), error)
      if (allocated(error)) return
      if (.not. (step(2) <= step(1) .and. step(1) <= step(3))) &
         call add("2.1", "step_initial", "expected between step_min = "//show_real(step(2))// &
                  " and step_max = "//show_real(step(3)))
      rec10 = merge("10.1C", "10.1B", b%bearing_type == BALL_BEARING)
      associate (k => b%traction_input)
         if (k(1) > k(2) .or. k(3) > k(2)) &
            call add(rec10, "max_traction", "expected >= "//show_real(max(k(1), k(3)))// &
                     " (the maximum of the traction-slip curve)")
      end associate
      if (.not. load_scale(b%force) > 0.0_wp) &
         call add("9.1.1", "applied_force_x", "expected a non-zero applied force (applied_force_x, "// &
                  "applied_force_y and applied_force_z are all 0): the echo's LOAD scale factor, the largest "// &
                  "applied load, is undefined for an unloaded bearing (ADORE's rule for one is not known)")
      if (n > 0) call input_error(error, deck%path//": "//itoa(n)// &
                                  " problem(s) in the deck's values"//msg)

   contains

      !> Field a of record rid must be below field b (both of record rid).
      subroutine less(rid, a, va, bname, vb, what)
         character(len=*), intent(in) :: rid, a, bname, what
         real(wp), intent(in) :: va, vb
         if (va < vb) return
         call add(rid, a, "expected < "//bname//" = "//show_real(vb)//" ("//what//")")
      end subroutine less

      subroutine add(rid, field, message)
         character(len=*), intent(in) :: rid, field, message
         call deck_field_problem(deck, rid, field, message, text)
         msg = msg//new_line("a")//text
         n = n + 1
      end subroutine add

   end subroutine check_values

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

end module adore_model_bearing
