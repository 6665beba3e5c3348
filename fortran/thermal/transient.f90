!> Thermal transients with lumped heat capacities (issue #27 item 5; report section 7,
!> recommendation 4: "the issue of thermal transients is another area where additional
!> modeling work may be recommended").  Not ADORE 5.0, whose field has "no thermal inertia"
!> (report 2.10 step 9): off by default (run option thermal_transient).
!>
!> Each body is one lump of heat capacity C = m c (J/K; mass from the bearing's dimensions
!> and Rec 8's density, c Rec 8's heat capacity; the coolant in the bearing's free space with
!> the lubricant's or air's properties) and a conductance G (W/K) by which its heat leaves
!> in the steady field model (the report's conduction and convection laws, eqs 11, 15-16,
!> 18-23, 2.5, 2.10 step 8).  Over an update interval dt the heat is the interval's average
!> (report 2.10 steps 1-2) and the lump's temperature relaxes toward its steady value T_s
!> (the field of adore_thermal_march or adore_thermal_network for that heat):
!>     C dT/dt = G (T_s - T),  T(dt) = T_s + (T(0) - T_s) exp(-dt G / C),
!> the exact solution for heat held constant over the interval (no step-size limit, no
!> truncation error; implicit Euler would lag it by O(dt G/C)).  A body's internal profile
!> (surfaces, contact nodes, mid point) is the steady one shifted with its bulk; the
!> housing's, anchored at the reference, has its rise above the reference scaled instead.  The lumps
!> are not coupled to each other: the report's march is not a conductance network (the
!> shaft bore has no sink temperature, the element's mid point is set from its outer
!> contact), so capacities cannot be attached to its nodes; a lag toward the steady field
!> keeps that field (either model's) as the long-time limit exactly.  docs/thermal.md,
!> "Thermal transients".
!> Energy over an interval: generated Q dt = stored sum C (T(dt) - T(0)) + leaving, the
!> heat leaving = the steady field's outflow (= Q) less each lump's net inflow G (T_s - T),
!> integrated in closed form.  Units SI (K, W, J, s, m).
module adore_thermal_transient
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error
   use adore_model_bearing, only: bearing_t, ROLLER_BEARING, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, &
                                  BODY_SHAFT, BODY_HOUSING, TEMP_HOUSING, TEMP_SHAFT, TEMP_ELEMENT, TEMP_CAGE, &
                                  TEMP_OUTER, TEMP_INNER
   use adore_thermal_conduction, only: cylinder_conductance, element_conductance, element_surface_area
   use adore_thermal_convection, only: fluid_properties_t, air_properties, lubricant_properties
   use adore_thermal_network, only: thermal_field_t, thermal_options_t, coolant_capacity_rate
   implicit none
   private

   public :: thermal_transient_t, new_thermal_transient, lump_capacities, lump_conductances, lump_relaxation, &
             lump_net_inflow, lump_temperatures, thermal_transient_step

   !> The lumps (bodies) in the order of thermal_transient_t's arrays; element k is lump
   !> LUMP_ELEMENT1 - 1 + k.
   integer, parameter, public :: LUMP_HOUSING = 1, LUMP_OUTER = 2, LUMP_INNER = 3, LUMP_SHAFT = 4, &
                                 LUMP_CAGE = 5, LUMP_COOLANT = 6, LUMP_ELEMENT1 = 7

   !> The lumps' state between updates.
   type :: thermal_transient_t
      real(wp), allocatable :: capacity(:)     !< J/K, per lump
      real(wp), allocatable :: temperature(:)  !< K, per lump: the bulk temperatures now
      integer :: updates = 0
      real(wp) :: generated = 0.0_wp           !< J, over the last interval
      real(wp) :: stored = 0.0_wp              !< J, sum C dT over the last interval
      real(wp) :: leaving = 0.0_wp             !< J, leaving the bearing over the last interval
      real(wp) :: balance = 0.0_wp             !< worst |generated - stored - leaving| / generated so far
   end type thermal_transient_t

contains

   !> The lumps of bearing b at its initial temperatures (Rec 2.7; the coolant at the inlet
   !> temperature of Rec 2.5, the room's when there is none), their capacities (J/K) from
   !> lump_capacities.
   function new_thermal_transient(b) result(tr)
      type(bearing_t), intent(in) :: b
      type(thermal_transient_t) :: tr
      real(wp) :: t_cool
      tr%capacity = lump_capacities(b)
      allocate (tr%temperature(LUMP_ELEMENT1 - 1 + b%n_elements))
      tr%temperature(LUMP_HOUSING) = b%temperature(TEMP_HOUSING)
      tr%temperature(LUMP_OUTER) = b%temperature(TEMP_OUTER)
      tr%temperature(LUMP_INNER) = b%temperature(TEMP_INNER)
      tr%temperature(LUMP_SHAFT) = b%temperature(TEMP_SHAFT)
      tr%temperature(LUMP_CAGE) = b%temperature(TEMP_CAGE)
      t_cool = b%coolant%inlet_temperature
      if (.not. (t_cool > 0.0_wp)) t_cool = b%temperature(1)
      tr%temperature(LUMP_COOLANT) = t_cool
      tr%temperature(LUMP_ELEMENT1:) = b%temperature(TEMP_ELEMENT)
   end function new_thermal_transient

   !> Heat capacities m c (J/K) of bearing b's lumps, Rec 8's density and heat capacity of
   !> each body: housing ring D_h / D over the outer race width; outer race ring D / outer
   !> raceway diameter and inner race ring inner raceway diameter / shaft OD (each over its
   !> width; the groove's volume not removed); shaft ring shaft OD / bore over the inner race
   !> width (the conduction model's length); cage ring OD / bore over its width less its
   !> pockets (one element's volume each); ball pi D^3/6, roller pi D^2 L/4; coolant: the
   !> free space between the raceway diameters over the mean width less elements and cage,
   !> rho c_p of the lubricant (Rec 2.4 type 1) or air (eq 27, Table 2) at the inlet
   !> temperature (the room's without one).
   function lump_capacities(b) result(c)
      type(bearing_t), intent(in) :: b
      real(wp), allocatable :: c(:)
      real(wp) :: v_el, v_cage, v_free, w_mean, t_cool
      type(fluid_properties_t) :: p
      logical :: ok
      allocate (c(LUMP_ELEMENT1 - 1 + b%n_elements), source=0.0_wp)
      v_el = pi*b%d**3/6.0_wp
      if (b%bearing_type == ROLLER_BEARING) v_el = 0.25_wp*pi*b%d**2*b%roller%roller_length
      c(LUMP_HOUSING) = body_heat(b, BODY_HOUSING, ring_volume(b%housing_od, b%bearing_od, b%width_outer))
      c(LUMP_OUTER) = body_heat(b, BODY_OUTER, ring_volume(b%bearing_od, b%outer_raceway_dia, b%width_outer))
      c(LUMP_INNER) = body_heat(b, BODY_INNER, ring_volume(b%inner_raceway_dia, b%shaft_od, b%width_inner))
      c(LUMP_SHAFT) = body_heat(b, BODY_SHAFT, ring_volume(b%shaft_od, max(b%shaft_id, 0.0_wp), b%width_inner))
      v_cage = max(ring_volume(b%cage_od, b%cage_id, b%cage_width) - b%n_elements*v_el, 0.0_wp)
      c(LUMP_CAGE) = body_heat(b, BODY_CAGE, v_cage)
      c(LUMP_ELEMENT1:) = body_heat(b, BODY_ELEMENT, v_el)
      w_mean = 0.5_wp*(b%width_outer + b%width_inner)
      v_free = max(ring_volume(b%outer_raceway_dia, b%inner_raceway_dia, w_mean) - b%n_elements*v_el - v_cage, &
                   0.0_wp)
      t_cool = b%coolant%inlet_temperature
      if (.not. (t_cool > 0.0_wp)) t_cool = b%temperature(1)
      if (b%coolant%coolant_type == 1) then
         p = lubricant_properties(b%lubricant, t_cool)
      else
         call air_properties(max(t_cool, 1.0_wp), p, ok)
      end if
      c(LUMP_COOLANT) = p%density*p%heat_capacity*v_free
   end function lump_capacities

   !> Conductances G (W/K) by which each lump's heat leaves in the steady field of bearing b
   !> with boundaries opt and the field's element coefficients h (W/(m**2 K)): housing eq 11
   !> in series with the film opt%reference_htc on its OD (if any); outer race eq 11 (whole
   !> ring, to the housing); inner race eq 11 (to the shaft); shaft eq 11 (hollow; a solid
   !> shaft the inner race's); cage eq 11 (2.5); element eqs 15-16 from its mid point to both
   !> contacts plus h times its surface (eqs 18-23); coolant its flow's rho c_p Q (2.10 step
   !> 8), without flow the elements' convection sum h A.
   function lump_conductances(b, opt, htc) result(g)
      type(bearing_t), intent(in) :: b
      type(thermal_options_t), intent(in) :: opt
      real(wp), intent(in) :: htc(:)
      real(wp), allocatable :: g(:)
      real(wp) :: area, l_el, film
      allocate (g(LUMP_ELEMENT1 - 1 + b%n_elements), source=0.0_wp)
      l_el = 0.0_wp
      if (b%bearing_type == ROLLER_BEARING) l_el = b%roller%roller_length
      area = element_surface_area(b%d, l_el)
      g(LUMP_HOUSING) = cylinder_conductance(0.5_wp*b%housing_od, 0.5_wp*b%bearing_od, b%width_outer, &
                                             b%material(BODY_HOUSING)%conductivity, 2.0_wp*pi)
      if (opt%reference_htc > 0.0_wp) then
         film = opt%reference_htc*pi*b%housing_od*b%width_outer
         g(LUMP_HOUSING) = 1.0_wp/(1.0_wp/g(LUMP_HOUSING) + 1.0_wp/film)
      end if
      g(LUMP_OUTER) = cylinder_conductance(0.5_wp*b%bearing_od, 0.5_wp*b%outer_raceway_dia, b%width_outer, &
                                           b%material(BODY_OUTER)%conductivity, 2.0_wp*pi)
      g(LUMP_INNER) = cylinder_conductance(0.5_wp*b%inner_raceway_dia, 0.5_wp*b%shaft_od, b%width_inner, &
                                           b%material(BODY_INNER)%conductivity, 2.0_wp*pi)
      g(LUMP_SHAFT) = g(LUMP_INNER)
      if (b%shaft_id > 0.0_wp .and. b%shaft_od > b%shaft_id) &
         g(LUMP_SHAFT) = cylinder_conductance(0.5_wp*b%shaft_od, 0.5_wp*b%shaft_id, b%width_inner, &
                                              b%material(BODY_SHAFT)%conductivity, 2.0_wp*pi)
      if (b%cage_od > b%cage_id .and. b%cage_id > 0.0_wp) &
         g(LUMP_CAGE) = cylinder_conductance(0.5_wp*b%cage_od, 0.5_wp*b%cage_id, b%cage_width, &
                                             b%material(BODY_CAGE)%conductivity, 2.0_wp*pi)
      g(LUMP_ELEMENT1:) = 2.0_wp*element_conductance(b%material(BODY_ELEMENT)%conductivity, b%d, l_el) + htc*area
      g(LUMP_COOLANT) = coolant_capacity_rate(b)
      if (.not. (g(LUMP_COOLANT) > 0.0_wp)) g(LUMP_COOLANT) = sum(htc)*area
   end function lump_conductances

   !> A lump's temperature (K) after dt (s) from t0 (K) toward its steady temperature ts (K)
   !> with capacity c (J/K) and conductance g (W/K): ts + (t0 - ts) exp(-dt g / c), the
   !> exact solution of c dT/dt = g (ts - T); ts when c is 0 (no inertia), t0 when g is 0.
   elemental real(wp) function lump_relaxation(t0, ts, c, g, dt) result(t)
      real(wp), intent(in) :: t0, ts, c, g, dt
      if (.not. (c > 0.0_wp)) then
         t = ts
      else
         t = ts + (t0 - ts)*exp(-dt*g/c)
      end if
   end function lump_relaxation

   !> The heat (J) a lump takes in net over dt (s): the integral of g (ts - T(t)) along
   !> lump_relaxation's solution, c (ts - t0) (1 - exp(-dt g / c)); 0 without capacity (the
   !> lump is at ts throughout).
   elemental real(wp) function lump_net_inflow(t0, ts, c, g, dt) result(e)
      real(wp), intent(in) :: t0, ts, c, g, dt
      if (.not. (c > 0.0_wp)) then
         e = 0.0_wp
      else
         e = c*(ts - t0)*(-expm1_(-dt*g/c))
      end if
   end function lump_net_inflow

   !> 1 - exp(x) computed as -(exp(x) - 1) without cancellation for small x.
   elemental real(wp) function expm1_(x) result(y)
      real(wp), intent(in) :: x
      if (abs(x) < 1.0e-5_wp) then
         y = x*(1.0_wp + x*(0.5_wp + x/6.0_wp))
      else
         y = exp(x) - 1.0_wp
      end if
   end function expm1_

   !> One update of the lumps of bearing b (module header): the steady field `field` (K;
   !> solved for the interval's averaged heat, which the field's q_generated, W, carries)
   !> becomes the transient one after dt (s): every lump relaxed from its temperature toward
   !> the field's, the field's bulk temperatures replaced and its surface and node
   !> temperatures shifted with their body's bulk (the housing's rise above the reference
   !> scaled); the energy of the interval (generated,
   !> stored, leaving, J) and the worst relative balance kept.  Engine error for dt <= 0 or
   !> lumps of another bearing.
   subroutine thermal_transient_step(tr, b, opt, dt, field, error)
      type(thermal_transient_t), intent(inout) :: tr
      type(bearing_t), intent(in) :: b
      type(thermal_options_t), intent(in) :: opt
      real(wp), intent(in) :: dt
      type(thermal_field_t), intent(inout) :: field
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: g(:), ts(:), tn(:), d(:)
      integer :: n, m
      n = b%n_elements
      m = LUMP_ELEMENT1 - 1 + n
      if (.not. (dt > 0.0_wp)) then
         call engine_error(error, "thermal transient: the update interval must be positive")
         return
      end if
      if (size(tr%temperature) /= m .or. size(field%element_bulk) /= n) then
         call engine_error(error, "thermal transient: the lumps are not this bearing's")
         return
      end if
      g = lump_conductances(b, opt, field%htc)
      ts = lump_temperatures(field)
      tn = lump_relaxation(tr%temperature, ts, tr%capacity, g, dt)
      ! energy: stored from the capacities, leaving = the steady outflow less the net inflows
      tr%generated = field%q_generated*dt
      tr%stored = sum(tr%capacity*(tn - tr%temperature))
      tr%leaving = field%q_generated*dt - sum(lump_net_inflow(tr%temperature, ts, tr%capacity, g, dt))
      tr%balance = max(tr%balance, abs(tr%generated - tr%stored - tr%leaving)/ &
                       max(abs(tr%generated), tiny(1.0_wp)))
      tr%temperature = tn
      tr%updates = tr%updates + 1
      ! the field: bulk temperatures the lumps', each body's profile shifted with its bulk
      d = tn - ts
      field%temperature(TEMP_HOUSING) = tn(LUMP_HOUSING)
      ! the housing's rise above the reference scaled (its outer surface is the reference
      ! node without a film: it stays there), the other bodies' profiles shifted
      if (abs(ts(LUMP_HOUSING) - opt%reference_temperature) > 0.0_wp) then
         field%housing = opt%reference_temperature + (field%housing - opt%reference_temperature)* &
                         ((tn(LUMP_HOUSING) - opt%reference_temperature)/(ts(LUMP_HOUSING) - opt%reference_temperature))
      else
         field%housing = field%housing + d(LUMP_HOUSING)
      end if
      field%temperature(TEMP_OUTER) = tn(LUMP_OUTER)
      field%temperature(TEMP_INNER) = tn(LUMP_INNER)
      if (allocated(field%race_bulk)) then
         field%race_bulk(:, 1) = field%race_bulk(:, 1) + d(LUMP_OUTER)
         field%race_bulk(:, 2) = field%race_bulk(:, 2) + d(LUMP_INNER)
      end if
      field%temperature(TEMP_SHAFT) = tn(LUMP_SHAFT)
      field%shaft = field%shaft + d(LUMP_SHAFT)
      field%temperature(TEMP_CAGE) = tn(LUMP_CAGE)
      field%cage_surface = field%cage_surface + d(LUMP_CAGE)
      field%exit_temperature = tn(LUMP_COOLANT)
      field%element_bulk = tn(LUMP_ELEMENT1:)
      field%mid = field%mid + d(LUMP_ELEMENT1:)
      field%contact_outer = field%contact_outer + d(LUMP_ELEMENT1:)
      field%contact_inner = field%contact_inner + d(LUMP_ELEMENT1:)
      field%temperature(TEMP_ELEMENT) = sum(field%element_bulk)/n
   end subroutine thermal_transient_step

   !> The lumps' temperatures (K) in a field, in the lumps' order: the bulk temperatures of
   !> housing, races, shaft and cage, the exit temperature, each element's bulk.
   pure function lump_temperatures(field) result(t)
      type(thermal_field_t), intent(in) :: field
      real(wp), allocatable :: t(:)
      allocate (t(LUMP_ELEMENT1 - 1 + size(field%element_bulk)))
      t(LUMP_HOUSING) = field%temperature(TEMP_HOUSING)
      t(LUMP_OUTER) = field%temperature(TEMP_OUTER)
      t(LUMP_INNER) = field%temperature(TEMP_INNER)
      t(LUMP_SHAFT) = field%temperature(TEMP_SHAFT)
      t(LUMP_CAGE) = field%temperature(TEMP_CAGE)
      t(LUMP_COOLANT) = field%exit_temperature
      t(LUMP_ELEMENT1:) = field%element_bulk
   end function lump_temperatures

   !> Volume (m**3) of a ring of outer diameter d1, inner d2 (m) and width w (m); 0 if d1 <= d2.
   pure real(wp) function ring_volume(d1, d2, w) result(v)
      real(wp), intent(in) :: d1, d2, w
      v = 0.0_wp
      if (d1 > d2) v = 0.25_wp*pi*(d1*d1 - d2*d2)*w
   end function ring_volume

   !> Heat capacity (J/K) of volume v (m**3) of body `body` of bearing b (Rec 8: rho c v).
   pure real(wp) function body_heat(b, body, v) result(c)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: body
      real(wp), intent(in) :: v
      c = b%material(body)%density*b%material(body)%heat_capacity*v
   end function body_heat

end module adore_thermal_transient
