!> The bearing's steady temperature field (ADORE's ADRH1, report sections 2.3-2.6 and 2.10):
!> a conduction/convection network without thermal inertia, solved as one small linear
!> system (adore_core_linalg) for the heat of the bearing's interactions averaged over an
!> interval (report 2.10 steps 1-9).
!>
!> Nodes (n rolling elements; each race divided into n angular sectors, report 2.3's
!> "angular sector of the cylinder", one per element):
!>   housing inner surface = outer race outside surface  -> housing (hollow cylinder, eq 11)
!>   -> the reference node: the housing's outer surface at the reference temperature (2.10;
!>   echo "NODE AT BASE TEMPERATURE: Housing/Outer"), directly, or through a convective film
!>   of coefficient reference_htc on the housing's outer surface (the Appendix C echo prints
!>   a "HEAT TRANS COEFF" instead of the node; its value is illegible);
!>   outer raceway sector j (= element j's outer contact temperature, the race and the
!>   element being at one temperature at the contact, 2.10 step 5) -> outer race sector
!>   (eq 11 with theta = 2 pi/n);
!>   element j's mid point T0 (eqs 13-16), its bulk temperature by eq 17, convecting to the
!>   coolant from its surface with h of eqs 18-23 (adore_thermal_convection, ADRH3);
!>   inner raceway sector j -> inner race sector -> inner race bore = shaft outer surface
!>   -> shaft (hollow; a solid shaft is one temperature) -> its bore: adiabatic, or a
!>   conductance bore_conductance to the reference temperature;
!>   the coolant: one well-mixed node at the exit temperature (the fluid near the elements;
!>   report 5.5: with no flow the "exit" temperature is the ambient air near the elements),
!>   fed at the inlet temperature with heat capacity rate W = rho c_p Q (Rec 2.5), so the
!>   heat to the coolant is W (T_exit - T_inlet) (2.10 step 8).
!>   The cage (2.5): all pocket and land heat enters at its guided surface and conducts
!>   radially through the cage ring to its other surface, at the coolant temperature.
!>   Drag and churning heat goes to the coolant.
!> Each contact's heat enters at the shared contact node; how much flows into the element
!> and how much into the race is the network's answer (the report's partition gamma of
!> eqs 6-9 for bulk temperatures, with equal temperatures at the contact).  The contact
!> temperature the print shows adds the flash rise of section 2.7 (tribology/flash.f90).
!> Convection depends on temperature through the fluid's properties (film temperature =
!> mean of element bulk and coolant); the system is solved again until the temperatures
!> change by less than 1e-9 K (ADRH3 "interactively called by ADRH1", report 4.2).
!> Heat balance: generated = W (T_exit - T_inlet) + reference + bore, to round-off.
!> Units SI (K, W, m).
module adore_thermal_network
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_linalg, only: solve_dense
   use adore_model_bearing, only: bearing_t, ROLLER_BEARING, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, &
                                  BODY_SHAFT, BODY_HOUSING, TEMP_ROOM, TEMP_HOUSING, TEMP_SHAFT, TEMP_ELEMENT, &
                                  TEMP_CAGE, TEMP_OUTER, TEMP_INNER
   use adore_cage_step0, only: GUIDE_OUTER
   use adore_thermal_convection, only: fluid_properties_t, air_properties, lubricant_properties, &
                                       heat_transfer_coefficient, SHAPE_SPHERE, SHAPE_CYLINDER, FLUID_AIR, FLUID_LIQUID
   use adore_thermal_conduction, only: cylinder_conductance, cylinder_bulk_weight, cylinder_bulk_mirrored, &
                                       element_conductance, element_bulk
   implicit none
   private

   public :: thermal_heat_t, thermal_options_t, thermal_field_t, solve_thermal_network, coolant_capacity_rate
   public :: default_thermal_options, new_thermal_heat, complete_field, element_coefficient, thermal_input

   !> The field models of thermal_options_t%field_model: the report's march of 2.10
   !> (adore_thermal_march, ADORE 5.0's) and this module's network
   integer, parameter, public :: FIELD_MARCH = 1, FIELD_NETWORK = 2

   !> Heat of the interactions averaged over the interval (W), per rolling element.
   type :: thermal_heat_t
      real(wp), allocatable :: outer(:)    !< element/outer race contact
      real(wp), allocatable :: inner(:)    !< element/inner race contact
      real(wp), allocatable :: pocket(:)   !< element/cage pocket (into the cage)
      real(wp), allocatable :: drag(:)     !< drag and churning of the element (into the coolant)
      real(wp) :: land = 0.0_wp            !< cage/race guide lands, all lands (into the cage)
   end type thermal_heat_t

   !> What the deck does not say about the boundaries (docs/thermal.md).
   type :: thermal_options_t
      !> FIELD_MARCH (the report's 2.10 steps 3-8, docs/thermal.md "The march") or
      !> FIELD_NETWORK (this module: a conduction/convection network)
      integer :: field_model = FIELD_MARCH
      !> reference temperature (K) of the housing's outer surface, or of the ambient the
      !> housing convects to (reference_htc > 0); the wiring passes Rec 2.7's housing temperature
      real(wp) :: reference_temperature = 0.0_wp
      real(wp) :: reference_htc = 0.0_wp          !< W/(m**2 K) on the housing OD; 0: node held at the reference
      real(wp) :: bore_conductance = 0.0_wp       !< shaft bore to the reference (W/K); 0: adiabatic bore
      !> conductance of the outer and inner race's wetted surfaces to the coolant (W/K, whole race)
      real(wp) :: race_fluid_conductance(2) = 0.0_wp
      !> velocity of each element's surface relative to the coolant (m/s), eq 18's V
      real(wp), allocatable :: element_velocity(:)
      !> the shaft's bulk temperature as ADORE 5.0 prints it (cylinder_bulk_mirrored) instead of
      !> eq 12 as written (docs/thermal.md); also what its step-2500 fits follow
      logical :: shaft_bulk_as_printed = .false.
      real(wp) :: tolerance = 1.0e-9_wp           !< K, on the temperature change between passes
      integer :: max_passes = 60
   end type thermal_options_t

   !> The temperature field and the heat flows.
   type :: thermal_field_t
      real(wp) :: temperature(7) = 0.0_wp     !< bulk temperatures in the TEMP_* order (room kept)
      real(wp) :: housing(3) = 0.0_wp         !< housing bulk, outer surface, inner surface (K)
      real(wp) :: shaft(3) = 0.0_wp           !< shaft bulk, outer surface, inner surface (K)
      real(wp) :: exit_temperature = 0.0_wp   !< coolant exit (K)
      real(wp) :: cage_surface(2) = 0.0_wp    !< cage guided surface, base surface (K)
      real(wp), allocatable :: contact_outer(:), contact_inner(:)  !< contact node temperatures (K)
      real(wp), allocatable :: mid(:), element_bulk(:)             !< element mid point, bulk (K)
      real(wp), allocatable :: htc(:)         !< element convective coefficient (W/(m**2 K))
      real(wp), allocatable :: race_bulk(:, :)  !< bulk of each race sector (sector, 1 outer / 2 inner) (K)
      real(wp) :: q_generated = 0.0_wp        !< all heat generated (W)
      real(wp) :: q_coolant = 0.0_wp          !< carried away by the coolant, W (T_exit - T_inlet)
      real(wp) :: q_reference = 0.0_wp        !< through the housing to the reference
      real(wp) :: q_bore = 0.0_wp             !< through the shaft bore
      real(wp) :: q_convection = 0.0_wp       !< from the elements to the coolant
      logical :: htc_in_range = .true.        !< every correlation within its range
      integer :: passes = 0
   end type thermal_field_t

contains

   !> The options a run starts from: the reference at Rec 2.7's housing temperature on the
   !> housing's outer surface, adiabatic shaft bore, no race convection, elements at rest
   !> relative to the coolant (the caller sets their velocities).
   pure function default_thermal_options(b) result(opt)
      type(bearing_t), intent(in) :: b
      type(thermal_options_t) :: opt
      opt%reference_temperature = b%temperature(TEMP_HOUSING)
      allocate (opt%element_velocity(b%n_elements), source=0.0_wp)
   end function default_thermal_options

   !> A heat record of n elements, all zero (W).
   pure function new_thermal_heat(n) result(h)
      integer, intent(in) :: n
      type(thermal_heat_t) :: h
      allocate (h%outer(n), h%inner(n), h%pocket(n), h%drag(n), source=0.0_wp)
   end function new_thermal_heat

   !> Heat capacity rate W = rho c_p Q (W/K) of bearing b's coolant (Rec 2.4, 2.5): the
   !> lubricant's at coolant type 1, air (eq 27, Table 2) at the inlet temperature otherwise.
   pure function coolant_capacity_rate(b) result(w)
      type(bearing_t), intent(in) :: b
      real(wp) :: w
      type(fluid_properties_t) :: p
      logical :: ok
      if (b%coolant%coolant_type == 1) then
         p = lubricant_properties(b%lubricant, b%coolant%inlet_temperature)
      else
         call air_properties(max(b%coolant%inlet_temperature, 1.0_wp), p, ok)
      end if
      w = p%density*p%heat_capacity*b%coolant%flow_rate
   end function coolant_capacity_rate

   !> Steady temperature field of bearing b for the averaged heat `heat` under the boundary
   !> options `opt` (module header; ADRH1).  Input error for missing or inconsistent data,
   !> engine error when the system is singular.
   subroutine solve_thermal_network(b, heat, opt, field, error)
      type(bearing_t), intent(in) :: b
      type(thermal_heat_t), intent(in) :: heat
      type(thermal_options_t), intent(in) :: opt
      type(thermal_field_t), intent(out) :: field
      type(error_type), allocatable, intent(out) :: error

      integer :: n, m, j, pass, shape, ih, iib, isb, if_
      real(wp) :: g_h, g_o, g_e, g_i, g_s, g_ref, g_bore, g_of, g_if, w_cap, area, t_in, l_el, q_cage
      real(wp) :: t_film, change
      real(wp), allocatable :: a(:, :), rhs(:), x(:), x_old(:), c(:), vel(:)
      logical :: ok, in_range, liquid

      n = b%n_elements
      call thermal_input(b, heat, opt, "thermal network", vel, error)
      if (allocated(error)) return
      liquid = b%coolant%coolant_type == 1
      shape = SHAPE_SPHERE
      l_el = 0.0_wp
      if (b%bearing_type == ROLLER_BEARING) then
         shape = SHAPE_CYLINDER
         l_el = b%roller%roller_length
      end if

      ! conductances (W/K)
      g_h = cylinder_conductance(0.5_wp*b%housing_od, 0.5_wp*b%bearing_od, b%width_outer, &
                                 b%material(BODY_HOUSING)%conductivity, 2.0_wp*pi)
      g_ref = g_h
      if (opt%reference_htc > 0.0_wp) then
         area = pi*b%housing_od*b%width_outer
         g_ref = 1.0_wp/(1.0_wp/g_h + 1.0_wp/(opt%reference_htc*area))
      end if
      g_o = cylinder_conductance(0.5_wp*b%bearing_od, 0.5_wp*b%outer_raceway_dia, b%width_outer, &
                                 b%material(BODY_OUTER)%conductivity, 2.0_wp*pi/n)
      g_i = cylinder_conductance(0.5_wp*b%inner_raceway_dia, 0.5_wp*b%shaft_od, b%width_inner, &
                                 b%material(BODY_INNER)%conductivity, 2.0_wp*pi/n)
      g_e = element_conductance(b%material(BODY_ELEMENT)%conductivity, b%d, l_el)
      g_s = 0.0_wp
      g_bore = 0.0_wp
      if (b%shaft_id > 0.0_wp) then
         g_s = cylinder_conductance(0.5_wp*b%shaft_od, 0.5_wp*b%shaft_id, b%width_inner, &
                                    b%material(BODY_SHAFT)%conductivity, 2.0_wp*pi)
         g_bore = opt%bore_conductance
      end if
      g_of = opt%race_fluid_conductance(1)/n
      g_if = opt%race_fluid_conductance(2)/n
      w_cap = coolant_capacity_rate(b)
      t_in = b%coolant%inlet_temperature
      area = pi*b%d*b%d                               ! ball surface
      if (shape == SHAPE_CYLINDER) area = pi*b%d*l_el + 0.5_wp*pi*b%d*b%d
      q_cage = sum(heat%pocket) + heat%land

      ! unknowns: housing inner surface, outer raceway sectors, element mid points, inner
      ! raceway sectors, inner race bore, shaft bore, coolant
      ih = 1
      iib = 2 + 3*n
      isb = 3 + 3*n
      if_ = 4 + 3*n
      m = if_
      allocate (a(m, m), rhs(m), x(m), c(n), field%htc(n))
      x = t_in
      x(ih:iib) = opt%reference_temperature
      field%htc_in_range = .true.
      do pass = 1, opt%max_passes
         x_old = x
         ! convective coefficients at the film temperature (ADRH3)
         do j = 1, n
            t_film = 0.5_wp*(element_bulk(x(1 + n + j), x(1 + j), x(1 + 2*n + j)) + x(if_))
            call element_coefficient(b, vel(j), t_film, field%htc(j), in_range)
            field%htc_in_range = field%htc_in_range .and. in_range
         end do
         c = field%htc*area
         a = 0.0_wp
         rhs = 0.0_wp
         ! housing inner surface
         a(ih, ih) = g_ref + n*g_o
         a(ih, 2:1 + n) = -g_o
         rhs(ih) = g_ref*opt%reference_temperature
         do j = 1, n
            associate (io => 1 + j, im => 1 + n + j, ii => 1 + 2*n + j)
               ! contact nodes: heat in, conduction into the race sector and the element,
               ! convection of the race's wetted face
               call contact_row(io, ih, g_o, g_of, heat%outer(j))
               call contact_row(ii, iib, g_i, g_if, heat%inner(j))
               ! element mid point: conduction from both contacts, convection from its bulk (eq 17)
               a(im, im) = 2.0_wp*g_e + 0.5_wp*c(j)
               a(im, io) = -g_e + 0.25_wp*c(j)
               a(im, ii) = -g_e + 0.25_wp*c(j)
               a(im, if_) = -c(j)
               ! coolant: convection from the element and the race sectors
               a(if_, if_) = a(if_, if_) + c(j) + g_of + g_if
               a(if_, im) = a(if_, im) - 0.5_wp*c(j)
               a(if_, io) = a(if_, io) - 0.25_wp*c(j) - g_of
               a(if_, ii) = a(if_, ii) - 0.25_wp*c(j) - g_if
            end associate
         end do
         ! inner race bore / shaft outer surface
         a(iib, iib) = n*g_i + g_s
         a(iib, 2 + 2*n:1 + 3*n) = -g_i
         a(iib, isb) = -g_s
         ! shaft bore (a solid shaft, or a shaft without conductance: one temperature)
         if (g_s > 0.0_wp) then
            a(isb, isb) = g_s + g_bore
            a(isb, iib) = -g_s
            rhs(isb) = g_bore*opt%reference_temperature
         else
            a(isb, isb) = 1.0_wp
            a(isb, iib) = -1.0_wp
         end if
         ! coolant: inflow at the inlet temperature, cage and drag heat
         a(if_, if_) = a(if_, if_) + w_cap
         rhs(if_) = w_cap*t_in + q_cage + sum(heat%drag)
         if (a(if_, if_) <= 0.0_wp) then
            call input_error(error, "thermal network: the coolant node has no flow and no convection")
            return
         end if
         call solve_dense(m, a, rhs, x, ok)
         if (.not. ok) then
            call engine_error(error, "thermal network: singular conduction/convection system")
            return
         end if
         change = maxval(abs(x - x_old))
         field%passes = pass
         if (change <= opt%tolerance) exit
      end do

      ! results
      field%contact_outer = x(2:1 + n)
      field%mid = x(2 + n:1 + 2*n)
      field%contact_inner = x(2 + 2*n:1 + 3*n)
      field%exit_temperature = x(if_)
      field%q_reference = g_ref*(x(ih) - opt%reference_temperature)
      field%q_bore = g_bore*(x(isb) - opt%reference_temperature)
      field%q_coolant = w_cap*(x(if_) - t_in)
      field%q_generated = sum(heat%outer) + sum(heat%inner) + q_cage + sum(heat%drag)
      ! housing: inner surface x(ih), outer surface after its conduction
      field%housing(3) = x(ih)
      field%housing(2) = x(ih) - field%q_reference/g_h
      ! shaft: outer surface = inner race bore, inner surface = bore
      field%shaft(2) = x(iib)
      field%shaft(3) = x(isb)
      call complete_field(b, opt, q_cage, field)
      field%q_convection = sum(c*(field%element_bulk - x(if_)))
   contains

      !> The equation (row `row` of a, rhs) of a contact node of element j: conductance
      !> g_race to node `race`, g_e to the element's mid point, g_fluid to the coolant, heat q in.
      subroutine contact_row(row, race, g_race, g_fluid, q)
         integer, intent(in) :: row, race
         real(wp), intent(in) :: g_race, g_fluid, q
         a(row, row) = g_race + g_e + g_fluid
         a(row, race) = -g_race
         a(row, 1 + n + j) = -g_e
         a(row, if_) = -g_fluid
         rhs(row) = q
      end subroutine contact_row

   end subroutine solve_thermal_network

   !> Checks of a field solve's input (`who` names the model in the message): elements,
   !> one heat value per element, a lubricant for coolant type 1, one velocity per element;
   !> vel (m/s) the elements' velocities (0 when opt gives none).  Input error otherwise.
   subroutine thermal_input(b, heat, opt, who, vel, error)
      type(bearing_t), intent(in) :: b
      type(thermal_heat_t), intent(in) :: heat
      type(thermal_options_t), intent(in) :: opt
      character(len=*), intent(in) :: who
      real(wp), allocatable, intent(out) :: vel(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      n = b%n_elements
      if (n < 1) then
         call input_error(error, who//": no rolling elements")
         return
      end if
      if (.not. (size(heat%outer) == n .and. size(heat%inner) == n .and. size(heat%pocket) == n .and. &
                 size(heat%drag) == n)) then
         call input_error(error, who//": heat arrays must have one value per rolling element")
         return
      end if
      if (b%coolant%coolant_type == 1 .and. b%lubricant%density <= 0.0_wp) then
         call input_error(error, who//": coolant type 1 (lubricant) needs a lubricant (Rec 10.0)")
         return
      end if
      allocate (vel(n), source=0.0_wp)
      if (allocated(opt%element_velocity)) then
         if (size(opt%element_velocity) /= n) then
            call input_error(error, who//": one element velocity per rolling element")
            return
         end if
         vel = opt%element_velocity
      end if
   end subroutine thermal_input

   !> The bulk temperatures of a field whose node temperatures are set (contact, mid-point,
   !> exit, housing surfaces housing(2:3), shaft surfaces shaft(2:3)): elements by eq 17,
   !> housing and shaft by eq 12 (the shaft as printed with opt%shaft_bulk_as_printed),
   !> each race sector by eq 12 between its raceway and its other surface, the cage by 2.5
   !> (heat q_cage, W, in at its guided surface, its other surface at the coolant
   !> temperature); field%temperature in the TEMP_* order (room kept).  K.
   subroutine complete_field(b, opt, q_cage, field)
      type(bearing_t), intent(in) :: b
      type(thermal_options_t), intent(in) :: opt
      real(wp), intent(in) :: q_cage
      type(thermal_field_t), intent(inout) :: field
      real(wp) :: r_in, r_out, w_cage, g_cage, t_f
      integer :: n
      n = size(field%mid)
      t_f = field%exit_temperature
      field%element_bulk = element_bulk(field%mid, field%contact_outer, field%contact_inner)
      field%housing(1) = field%housing(3) + cylinder_bulk_weight(0.5_wp*b%housing_od, 0.5_wp*b%bearing_od)* &
                         (field%housing(2) - field%housing(3))
      field%shaft(1) = field%shaft(2)
      if (b%shaft_id > 0.0_wp .and. b%shaft_od > b%shaft_id) then
         if (opt%shaft_bulk_as_printed) then
            field%shaft(1) = cylinder_bulk_mirrored(0.5_wp*b%shaft_od, 0.5_wp*b%shaft_id, field%shaft(2), &
                                                    field%shaft(3))
         else
            field%shaft(1) = field%shaft(3) + cylinder_bulk_weight(0.5_wp*b%shaft_od, 0.5_wp*b%shaft_id)* &
                             (field%shaft(2) - field%shaft(3))
         end if
      end if
      if (allocated(field%race_bulk)) deallocate (field%race_bulk)
      allocate (field%race_bulk(n, 2))
      field%race_bulk(:, 1) = field%contact_outer + cylinder_bulk_weight(0.5_wp*b%bearing_od, &
                              0.5_wp*b%outer_raceway_dia)*(field%housing(3) - field%contact_outer)
      field%race_bulk(:, 2) = field%shaft(2) + cylinder_bulk_weight(0.5_wp*b%inner_raceway_dia, 0.5_wp*b%shaft_od)* &
                              (field%contact_inner - field%shaft(2))
      r_in = 0.5_wp*b%cage_id
      r_out = 0.5_wp*b%cage_od
      field%cage_surface = t_f
      field%temperature(TEMP_CAGE) = t_f
      if (r_out > r_in .and. r_in > 0.0_wp) then
         g_cage = cylinder_conductance(r_out, r_in, b%cage_width, b%material(BODY_CAGE)%conductivity, 2.0_wp*pi)
         field%cage_surface(1) = t_f + q_cage/g_cage
         w_cage = cylinder_bulk_weight(r_out, r_in)
         if (cage_guided_outside(b)) then   ! guided at the OD: base (coolant) at the bore
            field%temperature(TEMP_CAGE) = t_f + w_cage*(field%cage_surface(1) - t_f)
         else                               ! guided at the bore: base at the OD
            field%temperature(TEMP_CAGE) = field%cage_surface(1) + w_cage*(t_f - field%cage_surface(1))
         end if
      end if
      field%temperature(TEMP_ROOM) = b%temperature(TEMP_ROOM)
      field%temperature(TEMP_HOUSING) = field%housing(1)
      field%temperature(TEMP_SHAFT) = field%shaft(1)
      field%temperature(TEMP_ELEMENT) = sum(field%element_bulk)/n
      field%temperature(TEMP_OUTER) = sum(field%race_bulk(:, 1))/n
      field%temperature(TEMP_INNER) = sum(field%race_bulk(:, 2))/n
   end subroutine complete_field

   !> Convective coefficient h (W/(m**2 K)) of one rolling element of bearing b moving at
   !> velocity (m/s) through the coolant at film temperature t_film (K): eqs 18-27 with the
   !> lubricant's properties (Rec 2.4 type 1) or air's (Table 2); in_range .false. when a
   !> correlation or the air table was left (ADRH3).
   subroutine element_coefficient(b, velocity, t_film, h, in_range)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: velocity, t_film
      real(wp), intent(out) :: h
      logical, intent(out) :: in_range
      type(fluid_properties_t) :: props
      logical :: ok
      integer :: shape
      shape = SHAPE_SPHERE
      if (b%bearing_type == ROLLER_BEARING) shape = SHAPE_CYLINDER
      if (b%coolant%coolant_type == 1) then
         props = lubricant_properties(b%lubricant, t_film)
         call heat_transfer_coefficient(shape, FLUID_LIQUID, props, velocity, b%d, h, in_range)
      else
         call air_properties(t_film, props, ok)
         call heat_transfer_coefficient(shape, FLUID_AIR, props, velocity, b%d, h, in_range)
         in_range = in_range .and. ok
      end if
   end subroutine element_coefficient

   !> Whether bearing b's cage is guided on the outer race (at its OD): its first land's type.
   pure logical function cage_guided_outside(b)
      type(bearing_t), intent(in) :: b
      cage_guided_outside = .false.
      if (allocated(b%lands)) then
         if (size(b%lands) > 0) cage_guided_outside = b%lands(1)%guide == GUIDE_OUTER
      end if
   end function cage_guided_outside

end module adore_thermal_network
