!> The bearing model (ADORE's data modules, report Appendix A): geometry, materials,
!> inertia, traction curves and operating conditions, in SI units, with every derived
!> value of the input echo.  Built once per run from the deck by adore_model_from_deck
!> (checked by adore_model_checks); read-only after.
module adore_model_bearing
   use adore_core_kinds, only: wp
   use adore_tribology_traction_law, only: traction_law_t
   use adore_tribology_film, only: lubricant_t
   use adore_cage_step0, only: guide_land_t, cage_input_t
   implicit none
   private

   public :: material_t, bearing_t, run_controls_t, ball_data_t, roller_data_t, coolant_data_t
   public :: BALL_BEARING, ROLLER_BEARING
   public :: BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, BODY_SHAFT, BODY_HOUSING
   public :: TEMP_ROOM, TEMP_HOUSING, TEMP_SHAFT, TEMP_ELEMENT, TEMP_CAGE, TEMP_OUTER, TEMP_INNER

   integer, parameter :: BALL_BEARING = 1     !< Rec 3.2 bearing type
   integer, parameter :: ROLLER_BEARING = 2
   !> Body indices of the material table (echo column order).
   integer, parameter :: BODY_ELEMENT = 1, BODY_OUTER = 2, BODY_INNER = 3, BODY_CAGE = 4, &
                         BODY_SHAFT = 5, BODY_HOUSING = 6
   !> Indices of bearing_t%temperature, the initial temperatures (K): room (Rec 9.0),
   !> housing, shaft, rolling elements, cage, outer race and inner race (Rec 2.7 bulk
   !> temperatures), in the order of the echo's initial operating conditions.
   integer, parameter :: TEMP_ROOM = 1, TEMP_HOUSING = 2, TEMP_SHAFT = 3, TEMP_ELEMENT = 4, &
                         TEMP_CAGE = 5, TEMP_OUTER = 6, TEMP_INNER = 7

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

   !> The deck's time integration controls (Rec 1, Rec 2.1; steps in dimensionless time tau).
   type :: run_controls_t
      integer :: n_steps = 0                   !< Rec 1 n_steps (NUMBER OF STEPS)
      integer :: int_method = 5                !< Rec 1 int_method (INT METHOD)
      integer :: print_interval = 0            !< Rec 1 data_control_2: steps between printed steps
      real(wp) :: step_initial = 0.0_wp, step_min = 0.0_wp, step_max = 0.0_wp   !< Rec 2.1 (tau)
      real(wp) :: error_limit = 0.0_wp         !< Rec 2.1 ERROR LIMIT
   end type run_controls_t

   !> The coolant and the thermal model's times (Rec 2.4, 2.5; docs/thermal.md for how each
   !> field was identified).
   type :: coolant_data_t
      integer :: coolant_type = 0              !< Rec 2.4 field 1: 1 = lubricant, 0 = no coolant (air)
      real(wp) :: inlet_temperature = 0.0_wp   !< Rec 2.5 field 1 (K)
      real(wp) :: flow_rate = 0.0_wp           !< Rec 2.5 field 2 (m**3/s)
      real(wp) :: thermal_time(2) = 0.0_wp     !< Rec 2.5 fields 4, 5 (s): one and ten revolutions (Appendix C)
   end type coolant_data_t

   !> What only a ball bearing has (Rec 5A).
   type :: ball_data_t
      real(wp) :: alpha0 = 0.0_wp              !< free contact angle (rad)
      real(wp) :: f_o = 0.0_wp, f_i = 0.0_wp   !< groove curvature factors
      real(wp) :: end_play = 0.0_wp            !< unmounted end play (m)
   end type ball_data_t

   !> What only a cylindrical roller bearing has (Rec 5B).
   type :: roller_data_t
      real(wp) :: roller_length = 0.0_wp       !< (m)
      real(wp) :: roller_land = 0.0_wp         !< central flat land length (m)
      real(wp) :: crown_radius = 1.0e10_wp     !< roller crown radius (m)
      real(wp) :: corner_radius(2) = 0.0_wp    !< roller corner radii, -x and +x end (m)
      real(wp) :: race_crown(2) = 1.0e10_wp    !< outer, inner race crown radii (m)
      real(wp) :: race_length(2) = 0.0_wp      !< outer, inner race length 1 (Rec 5B.1, m; 0 = none)
      !> pyadore's Rec 5B.2 (docs/rollers.md, "Flanges"): kPocType (0 rectangular, -1
      !> cylindrical, report 4.4.11); flange present (end 1 = -x, end 2 = +x; race 1 outer, 2
      !> inner); spherical end radius (m; 0 flat); flange height (m), lay-back angle (rad) and
      !> axial play between the race's flange faces (m), per race
      integer :: pocket_type = 0
      logical :: flange(2, 2) = .false.
      real(wp) :: end_radius = 0.0_wp
      real(wp) :: flange_height(2) = 0.0_wp
      real(wp) :: flange_angle(2) = 0.0_wp
      real(wp) :: flange_clearance(2) = 0.0_wp
   end type roller_data_t

   !> Everything the physics needs from the deck: the data common to every bearing kind, the
   !> kinds' own data (ball, roller) and the deck's run controls, each in its own record.
   type :: bearing_t
      character(len=:), allocatable :: run_id
      integer :: bearing_type = BALL_BEARING
      integer :: mode = 1
      integer :: n_elements = 0
      !> the deck's time integration (Rec 1, Rec 2.1): run controls, not bearing data
      type(run_controls_t) :: controls
      ! envelope, Rec 4 (m)
      real(wp) :: shaft_od = 0.0_wp, bearing_od = 0.0_wp, shaft_id = 0.0_wp, housing_od = 0.0_wp
      real(wp) :: width_outer = 0.0_wp, width_inner = 0.0_wp
      ! rolling elements, Rec 5A (ball) / 5B (roller)
      real(wp) :: d = 0.0_wp                   !< ball or roller diameter (m)
      real(wp) :: dm = 0.0_wp                  !< pitch diameter (m)
      type(ball_data_t) :: ball                !< ball bearings' own data (Rec 5A)
      type(roller_data_t) :: roller            !< cylindrical roller bearings' own data (Rec 5B)
      real(wp) :: dia_play = 0.0_wp            !< unmounted diametral play (m)
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
      ! inertia by body (BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE: the one body-index
      ! convention of the model): kg and kg m**2 (x, y, z)
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
      !> boundary-lubrication film (m): traction model 3's contacts whose thermally reduced film
      !> is thinner take the deck's curve (run option boundary_lambda times the
      !> composite RMS roughness; docs/tribology.md, "Thin films"); 0: off (the 1 nm floor only)
      real(wp) :: boundary_film = 0.0_wp
      !> full-film thickness (m): above it a model-3 contact is a full EHD film; between
      !> boundary_film and it (mixed lubrication) the traction blends the EHD film's and the
      !> deck's curve by the fluid fraction (run option full_film_lambda times the composite
      !> RMS roughness; docs/tribology.md, "Mixed films"); at or below boundary_film: no blend
      real(wp) :: full_film = 0.0_wp
      !> elastic shear modulus G (Pa) of the EHD film (run option film_shear_modulus): > 0 makes
      !> traction model 3's film a Maxwell film (docs/tribology.md, "The film's elasticity"); 0: off
      real(wp) :: film_shear_modulus = 0.0_wp
      !> limiting shear stress coefficient Lambda (-) of the EHD film (run option limiting_shear):
      !> > 0 caps traction model 3's local shear stress at Lambda p (docs/tribology.md, "Limiting
      !> shear stress"); 0: off
      real(wp) :: limiting_shear = 0.0_wp
      type(lubricant_t) :: lubricant
      !> the coolant and the thermal times (Rec 2.4, 2.5)
      type(coolant_data_t) :: coolant
      !> cage friction coefficients, RE/cage pocket (Rec 10.5.1B coefficient A) and race/cage
      !> guide land (Rec 10.5.2B coefficient A): the constant Coulomb friction of the cage
      !> contacts (0.05 in both decks, report Table 5 "Cage Friction Coefficient"; the default
      !> for a model not read from a deck).  Coefficients B, C, D of those records (0 in both
      !> decks) are not used.
      real(wp) :: cage_friction(2) = 0.05_wp
      !> lubricant layer on the guide lands (m; run option land_oil): the land film exists where
      !> the local gap is below it (adore_contact_cage_land, starved land; docs/cage.md,
      !> "The guide-land film where the report has none"); huge: flooded
      real(wp) :: land_oil_layer = 1.0e-4_wp
      !> Rec 3.3's eleven flags as the deck gives them.  Their positions are not identified
      !> (docs/cage.md, "The cage's degrees of freedom"); the run option cage=deck reads
      !> them through adore_model_condition's deck_constraints (all zero: nothing constrained).
      integer :: dof_flags(11) = 0
      ! operating conditions, Rec 2.7, 9.0, 9.1.x, 11
      !> initial temperatures (K), indexed by TEMP_ROOM ... TEMP_INNER: room, housing, shaft,
      !> element, cage, outer race, inner race
      real(wp) :: temperature(7) = 293.0_wp
      real(wp) :: fit_outer = 0.0_wp, fit_inner = 0.0_wp   !< mounted diametral interference (m)
      real(wp) :: speed_outer = 0.0_wp, speed_inner = 0.0_wp  !< race speeds (rad/s)
      real(wp) :: force(3) = 0.0_wp            !< applied to the inner race (N)
      real(wp) :: moment(3) = 0.0_wp           !< applied to the inner race (N m)
      real(wp) :: gravity(3) = 0.0_wp          !< (m/s**2)
   end type bearing_t

end module adore_model_bearing
