!> ADORE 5.0's temperature field (ADRH1) as the report's section 2.10 lists it, step by
!> step from the reference node inward (steps 3-8), and the dispatch between it and the
!> conduction/convection network of adore_thermal_network (docs/thermal.md, "The march").
!>
!> Step 3, the heat partition (eqs 6-7, 49): of each contact's heat q the element takes
!> gamma q and the race (1 - gamma) q; with the equal surface temperatures of 2.8 the
!> partition is the moving-source one of eq 49, gamma = sqrt(rho c k)_e / (sqrt(rho c k)_e
!> + sqrt(rho c k)_r) for the equal surface speeds of rolling (0.5 for like materials).
!> Step 4: the outer race's share of all outer contacts is the heat transferred to the
!> housing: housing outer surface at the reference temperature (or a film of coefficient
!> reference_htc to it), housing inner surface by eq 11, each outer raceway sector j by
!> eq 11 over 2 pi / n with its share.  Step 5: element j's outer contact temperature T1 =
!> that raceway's.  Step 6: eqs 15-16 with the element's shares gamma q: mid point T0 = T1 -
!> gamma q_o / (k A / D), inner contact T2 = T0 + gamma q_i / (k A / D).  Step 7: the inner
!> race's share of each inner contact conducts through its sector to the inner race bore
!> (one surface: the sectors' mean) and through the shaft to its bore (eq 11; a solid shaft
!> is one temperature).  Step 8: the coolant takes the rest (the elements' shares, the cage,
!> drag and churning): exit = inlet + rest / (rho c_p Q); without flow the "exit" is the
!> fluid near the elements (report 5.5), the temperature at which the elements convect
!> their heat with h of eqs 18-27 (ADRH3, iterated with the film temperature).
!> Heat balance: generated = coolant + housing (reference) + shaft (bore), exactly.
!> Units SI (K, W, m).
module adore_thermal_march
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_model_bearing, only: bearing_t, ROLLER_BEARING, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_SHAFT, &
                                  BODY_HOUSING
   use adore_thermal_conduction, only: cylinder_conductance, element_conductance, element_bulk
   use adore_thermal_network, only: thermal_heat_t, thermal_options_t, thermal_field_t, solve_thermal_network, &
                                    coolant_capacity_rate, complete_field, element_coefficient, thermal_input, &
                                    FIELD_NETWORK
   implicit none
   private

   public :: solve_thermal_field, solve_thermal_march, element_heat_fraction

contains

   !> The temperature field of bearing b for the averaged heat `heat` (W) by the model of
   !> opt%field_model: the report's march (default) or the network.
   subroutine solve_thermal_field(b, heat, opt, field, error)
      type(bearing_t), intent(in) :: b
      type(thermal_heat_t), intent(in) :: heat
      type(thermal_options_t), intent(in) :: opt
      type(thermal_field_t), intent(out) :: field
      type(error_type), allocatable, intent(out) :: error
      if (opt%field_model == FIELD_NETWORK) then
         call solve_thermal_network(b, heat, opt, field, error)
      else
         call solve_thermal_march(b, heat, opt, field, error)
      end if
   end subroutine solve_thermal_field

   !> Fraction gamma of a contact's heat that enters the rolling element at race `race`
   !> (BODY_OUTER or BODY_INNER) of bearing b: eq 49 with the moving-source parameters of
   !> both surfaces at equal surface speed, sqrt(rho c k) of each body (Rec 8).
   pure real(wp) function element_heat_fraction(b, race) result(gamma)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: race
      real(wp) :: e, r
      associate (me => b%material(BODY_ELEMENT), mr => b%material(race))
         e = sqrt(me%density*me%heat_capacity*me%conductivity)
         r = sqrt(mr%density*mr%heat_capacity*mr%conductivity)
      end associate
      gamma = 0.5_wp
      if (e + r > 0.0_wp) gamma = e/(e + r)
   end function element_heat_fraction

   !> The report's march (module header) for bearing b, heat `heat` (W), boundaries opt.
   !> Input error for missing data, no way for the coolant's heat (no flow and no
   !> convection).
   subroutine solve_thermal_march(b, heat, opt, field, error)
      type(bearing_t), intent(in) :: b
      type(thermal_heat_t), intent(in) :: heat
      type(thermal_options_t), intent(in) :: opt
      type(thermal_field_t), intent(out) :: field
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: gam(2), g_h, g_o, g_i, g_e, g_s, w_cap, q_h, q_s, q_cage, q_rest, l_el, area, ha, t_f, t_old
      real(wp), allocatable :: vel(:), q_ro(:), q_ri(:)
      logical :: in_range
      integer :: n, j, pass

      n = b%n_elements
      call thermal_input(b, heat, opt, "thermal march", vel, error)
      if (allocated(error)) return
      l_el = 0.0_wp
      area = pi*b%d*b%d
      if (b%bearing_type == ROLLER_BEARING) then
         l_el = b%roller%roller_length
         area = pi*b%d*l_el + 0.5_wp*pi*b%d*b%d
      end if

      ! step 3: the partition; the races' shares (W)
      gam = [element_heat_fraction(b, BODY_OUTER), element_heat_fraction(b, BODY_INNER)]
      q_ro = (1.0_wp - gam(1))*heat%outer
      q_ri = (1.0_wp - gam(2))*heat%inner
      q_h = sum(q_ro)
      q_s = sum(q_ri)
      q_cage = sum(heat%pocket) + heat%land
      q_rest = gam(1)*sum(heat%outer) + gam(2)*sum(heat%inner) + q_cage + sum(heat%drag)

      ! step 4: housing and outer race
      g_h = cylinder_conductance(0.5_wp*b%housing_od, 0.5_wp*b%bearing_od, b%width_outer, &
                                 b%material(BODY_HOUSING)%conductivity, 2.0_wp*pi)
      g_o = cylinder_conductance(0.5_wp*b%bearing_od, 0.5_wp*b%outer_raceway_dia, b%width_outer, &
                                 b%material(BODY_OUTER)%conductivity, 2.0_wp*pi/n)
      field%housing(2) = opt%reference_temperature
      if (opt%reference_htc > 0.0_wp) field%housing(2) = field%housing(2) + q_h/(opt%reference_htc*pi*b%housing_od* &
                                                                                 b%width_outer)
      field%housing(3) = field%housing(2) + q_h/g_h
      ! steps 5-6: the contact temperatures, the element's mid point and inner contact
      g_e = element_conductance(b%material(BODY_ELEMENT)%conductivity, b%d, l_el)
      field%contact_outer = field%housing(3) + q_ro/g_o
      field%mid = field%contact_outer - gam(1)*heat%outer/g_e
      field%contact_inner = field%mid + gam(2)*heat%inner/g_e
      ! step 7: inner race and shaft
      g_i = cylinder_conductance(0.5_wp*b%inner_raceway_dia, 0.5_wp*b%shaft_od, b%width_inner, &
                                 b%material(BODY_INNER)%conductivity, 2.0_wp*pi/n)
      field%shaft(2) = sum(field%contact_inner - q_ri/g_i)/n
      field%shaft(3) = field%shaft(2)
      if (b%shaft_id > 0.0_wp .and. b%shaft_od > b%shaft_id) then
         g_s = cylinder_conductance(0.5_wp*b%shaft_od, 0.5_wp*b%shaft_id, b%width_inner, &
                                    b%material(BODY_SHAFT)%conductivity, 2.0_wp*pi)
         field%shaft(3) = field%shaft(2) - q_s/g_s
      end if
      field%element_bulk = element_bulk(field%mid, field%contact_outer, field%contact_inner)

      ! step 8: the coolant; ADRH3's coefficients at the film temperature
      w_cap = coolant_capacity_rate(b)
      allocate (field%htc(n))
      t_f = b%coolant%inlet_temperature
      if (w_cap > 0.0_wp) t_f = b%coolant%inlet_temperature + q_rest/w_cap
      if (.not. (w_cap > 0.0_wp)) t_f = sum(field%element_bulk)/n
      field%htc_in_range = .true.
      do pass = 1, max(opt%max_passes, 1)
         t_old = t_f
         field%htc_in_range = .true.
         do j = 1, n
            call element_coefficient(b, vel(j), 0.5_wp*(field%element_bulk(j) + t_f), field%htc(j), in_range)
            field%htc_in_range = field%htc_in_range .and. in_range
         end do
         field%passes = pass
         if (w_cap > 0.0_wp) exit
         ha = sum(field%htc)*area
         if (.not. (ha > 0.0_wp)) then
            call input_error(error, "thermal march: the coolant has no flow and the elements no convection")
            return
         end if
         t_f = (sum(field%htc*area*field%element_bulk) - q_rest)/ha
         if (abs(t_f - t_old) <= opt%tolerance) exit
      end do
      field%exit_temperature = t_f
      field%q_generated = sum(heat%outer) + sum(heat%inner) + q_cage + sum(heat%drag)
      field%q_reference = q_h
      field%q_bore = q_s
      field%q_coolant = q_rest
      if (w_cap > 0.0_wp) field%q_coolant = w_cap*(t_f - b%coolant%inlet_temperature)
      field%q_convection = sum(field%htc*area*(field%element_bulk - t_f))
      call complete_field(b, opt, q_cage, field)
   end subroutine solve_thermal_march

end module adore_thermal_march
