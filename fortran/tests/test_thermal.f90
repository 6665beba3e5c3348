!> Engine unit tests of the thermal model (fortran/thermal/): independent checks only -
!> closed forms, conservation, textbook limits, the report's tables at their own points -
!> and the report's printed step-2500 fits from its printed temperatures (ADRC2) and its
!> printed step-2500 temperature field from its printed contact losses (the march, ADRH1).
program test_thermal
   use adore_test_support, only: check, finish, get_decks_dir, near
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_core_quadrature, only: gauss_legendre
   use adore_model_bearing, only: bearing_t, TEMP_HOUSING, TEMP_SHAFT, TEMP_ELEMENT, TEMP_CAGE, &
                                  TEMP_OUTER, TEMP_INNER, BODY_OUTER, BODY_ELEMENT
   use adore_model_from_deck, only: read_bearing
   use adore_thermal_convection, only: fluid_properties_t, air_properties, nusselt_sphere_air, &
      nusselt_sphere_liquid, nusselt_cylinder_air, nusselt_cylinder_liquid, nusselt_cylinder_liquid_table, &
      heat_transfer_coefficient, reynolds_number, prandtl_number, SHAPE_SPHERE, SHAPE_CYLINDER, &
      FLUID_LIQUID, AIR_TABLE_T, AIR_TABLE_CP, AIR_TABLE_MU, AIR_TABLE_K, CYL_TABLE_RE, CYL_TABLE_C, CYL_TABLE_N
   use adore_thermal_conduction, only: cylinder_temperature, cylinder_bulk, cylinder_conductance, &
      cylinder_bulk_weight, cylinder_bulk_mirrored, element_core_area, element_conductance, element_bulk
   use adore_thermal_network, only: thermal_heat_t, thermal_options_t, thermal_field_t, solve_thermal_network, &
      coolant_capacity_rate, default_thermal_options, new_thermal_heat
   use adore_thermal_march, only: solve_thermal_march, solve_thermal_field, element_heat_fraction
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_start_ball_step0, only: ball_step0_t
   use adore_state_bearing_state, only: bearing_state_t
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, ball_bearing_loads
   use adore_test_ball_fixture, only: step0_state, appendix_c_race_control
   use adore_thermal_distortion, only: distortion_t, thermal_distortion
   use adore_thermal_drag, only: sphere_drag_coefficient, cylinder_drag_coefficient, element_drag, churning_moment, &
                                 element_fluid_loss_t, element_fluid_loss
   implicit none

   character(len=:), allocatable :: decks
   type(bearing_t) :: ball
   type(error_type), allocatable :: error

   call get_decks_dir(decks)
   call read_bearing(decks//"/appendix_c_ball.inp", ball, error)
   call check(.not. allocated(error), "Appendix C deck reads")
   if (allocated(error)) call finish("thermal")

   call test_deck_coolant()
   call test_air_table()
   call test_cylinder_table()
   call test_sphere_correlations()
   call test_hollow_cylinder()
   call test_rolling_element()
   call test_network_balance()
   call test_network_closed_form()
   call test_march_closed_form()
   call test_march_report_step2500()
   call test_march_report_roller()
   call test_free_growth()
   call test_report_fits()
   call test_report_bulk_conventions()
   call test_drag()
   call test_traction_at_initial_temperatures()

   call finish("thermal")

contains

   !> Rec 2.4 / 2.5 of Appendix C (listing `1 0 2`, `323 1e-5 0 3e-3 3e-2`).
   subroutine test_deck_coolant()
      call check(ball%coolant%coolant_type == 1, "Rec 2.4 coolant type 1 (lubricant)")
      call check(ball%coolant%inlet_temperature == 323.0_wp, "Rec 2.5 inlet 323 K")
      call check(ball%coolant%flow_rate == 1.0e-5_wp, "Rec 2.5 flow 1e-5 m^3/s")
      call check(all(ball%coolant%thermal_time == [3.0e-3_wp, 3.0e-2_wp]), "Rec 2.5 thermal times")
      ! heat capacity rate = rho c_p Q of MIL-L-7808
      call check(near(coolant_capacity_rate(ball), 945.429_wp*1836.10_wp*1.0e-5_wp, 1.0e-12_wp), &
                 "coolant capacity rate rho c_p Q")
   end subroutine test_deck_coolant

   !> Table 2 at its own points, eq 27 against the ideal gas, Sutherland's viscosity, Pr.
   subroutine test_air_table()
      type(fluid_properties_t) :: p
      logical :: ok
      integer :: i
      real(wp) :: mu_s, t
      do i = 1, 16
         t = AIR_TABLE_T(i)
         call air_properties(t, p, ok)
         call check(ok, "Table 2 point in range")
         call check(near(p%heat_capacity, AIR_TABLE_CP(i), 1.0e-14_wp) .and. near(p%viscosity, AIR_TABLE_MU(i), &
                    1.0e-14_wp) .and. near(p%conductivity, AIR_TABLE_K(i), 1.0e-14_wp), "Table 2 values at its points")
         ! eq 27 = ideal gas at 101325 Pa, R = 287.05 J/(kg K)
         call check(near(p%density, 101325.0_wp/(287.05_wp*t), 1.0e-3_wp), "eq 27 = ideal gas density")
         ! Sutherland's law (White, Viscous Fluid Flow): mu0 1.716e-5, T0 273.15, S 110.4 K
         mu_s = 1.716e-5_wp*(t/273.15_wp)**1.5_wp*(273.15_wp + 110.4_wp)/(t + 110.4_wp)
         call check(near(p%viscosity, mu_s, 0.04_wp), "Table 2 viscosity within 4 % of Sutherland")
         call check(prandtl_number(p) > 0.68_wp .and. prandtl_number(p) < 0.78_wp, "air Prandtl number 0.68-0.78")
      end do
      ! midway between two points: the mean (linear interpolation)
      call air_properties(0.5_wp*(AIR_TABLE_T(5) + AIR_TABLE_T(6)), p, ok)
      call check(near(p%viscosity, 0.5_wp*(AIR_TABLE_MU(5) + AIR_TABLE_MU(6)), 1.0e-12_wp), "Table 2 interpolation")
      call air_properties(80.0_wp, p, ok)
      call check(.not. ok .and. p%viscosity == AIR_TABLE_MU(1), "below Table 2: flagged, end value")
      call air_properties(1000.0_wp, p, ok)
      call check(.not. ok .and. p%conductivity == AIR_TABLE_K(16), "above Table 2: flagged, end value")
   end subroutine test_air_table

   !> Table 1 (eq 24) at each row's limits; the rows meet within 1 % (Hilpert's table is
   !> continuous); eq 26 = 1.1 Pr**0.31 eq 24; range limits.
   subroutine test_cylinder_table()
      real(wp) :: nu, nu_lo, nu_hi, re
      logical :: ok
      integer :: i
      do i = 1, 5
         re = CYL_TABLE_RE(i)
         call nusselt_cylinder_air(re, nu, ok)
         call check(ok .and. near(nu, CYL_TABLE_C(i)*re**CYL_TABLE_N(i), 1.0e-14_wp), "Table 1 at a row's lower limit")
         re = CYL_TABLE_RE(i + 1)*(1.0_wp - 1.0e-12_wp)
         call nusselt_cylinder_air(re, nu, ok)
         call check(ok .and. near(nu, CYL_TABLE_C(i)*re**CYL_TABLE_N(i), 1.0e-14_wp), "Table 1 at a row's upper limit")
      end do
      do i = 1, 4
         nu_lo = CYL_TABLE_C(i)*CYL_TABLE_RE(i + 1)**CYL_TABLE_N(i)
         nu_hi = CYL_TABLE_C(i + 1)*CYL_TABLE_RE(i + 1)**CYL_TABLE_N(i + 1)
         call check(near(nu_lo, nu_hi, 0.01_wp), "Table 1 rows meet within 1 %")
      end do
      call nusselt_cylinder_air(4.0e5_wp, nu, ok)
      call check(ok .and. near(nu, 0.0239_wp*4.0e5_wp**0.805_wp, 1.0e-14_wp), "Table 1 at 4e5")
      call nusselt_cylinder_air(5.0e5_wp, nu_hi, ok)
      call check(.not. ok .and. nu_hi == nu, "Table 1 above 4e5: flagged, clamped")
      call nusselt_cylinder_air(0.1_wp, nu, ok)
      call check(.not. ok .and. near(nu, 0.891_wp*0.4_wp**0.33_wp, 1.0e-14_wp), "Table 1 below 0.4: flagged, clamped")
      call nusselt_cylinder_liquid_table(100.0_wp, 50.0_wp, nu, ok)
      call check(near(nu, 1.1_wp*0.615_wp*100.0_wp**0.466_wp*50.0_wp**0.31_wp, 1.0e-14_wp), "eq 26")
      call check(near(nusselt_cylinder_liquid(400.0_wp, 50.0_wp), (0.35_wp + 0.56_wp*20.0_wp)*50.0_wp**0.31_wp, &
                       1.0e-14_wp), "eq 25")
   end subroutine test_cylinder_table

   !> Eqs 21-23 at their range limits; h = Nu k / D (eq 19) with Re of eq 18.
   subroutine test_sphere_correlations()
      real(wp) :: nu, h
      logical :: ok
      type(fluid_properties_t) :: p
      call nusselt_sphere_air(25.0_wp, 0.7_wp, nu, ok)
      call check(ok .and. near(nu, 0.37_wp*25.0_wp**0.6_wp, 1.0e-14_wp), "eq 21 at Re = 25")
      call nusselt_sphere_air(1.0e5_wp, 0.7_wp, nu, ok)
      call check(ok .and. near(nu, 0.37_wp*1.0e5_wp**0.6_wp, 1.0e-14_wp), "eq 21 at Re = 1e5")
      call nusselt_sphere_air(2.0e5_wp, 0.7_wp, h, ok)
      call check(.not. ok .and. h == nu, "eq 21 above 1e5: flagged, clamped")
      call nusselt_sphere_air(1.0_wp, 0.7_wp, nu, ok)
      call check(ok .and. near(nu, 0.7_wp*(2.2_wp + 0.48_wp), 1.0e-14_wp), "eq 22 at Re = 1")
      call nusselt_sphere_air(24.999_wp, 0.7_wp, nu, ok)
      call check(ok .and. near(nu, 24.999_wp*0.7_wp*(2.2_wp/24.999_wp + 0.48_wp/sqrt(24.999_wp)), 1.0e-14_wp), &
                 "eq 22 below Re = 25")
      call nusselt_sphere_air(0.5_wp, 0.7_wp, h, ok)
      call check(.not. ok .and. near(h, 0.7_wp*2.68_wp, 1.0e-14_wp), "eq 22 below Re = 1: flagged, clamped")
      ! eq 23 at Re = 0, Pr = 1 gives 0.97 (the report's text says "approaches 2", the
      ! conduction limit of a sphere; its own equation does not: docs/thermal.md)
      call check(near(nusselt_sphere_liquid(0.0_wp, 1.0_wp), 0.97_wp, 1.0e-14_wp), "eq 23 at Re = 0")
      call check(near(nusselt_sphere_liquid(100.0_wp, 2.0_wp), 2.0_wp**0.3_wp*(0.97_wp + 6.8_wp), 1.0e-14_wp), "eq 23")
      p = fluid_properties_t(900.0_wp, 0.01_wp, 0.14_wp, 2000.0_wp)
      call check(near(reynolds_number(p, 2.0_wp, 0.01_wp), 1800.0_wp, 1.0e-14_wp), "eq 18")
      call check(near(prandtl_number(p), 2000.0_wp*0.01_wp/0.14_wp, 1.0e-14_wp), "eq 20")
      call heat_transfer_coefficient(SHAPE_SPHERE, FLUID_LIQUID, p, 2.0_wp, 0.01_wp, h, ok)
      call check(near(h, nusselt_sphere_liquid(1800.0_wp, prandtl_number(p))*0.14_wp/0.01_wp, 1.0e-14_wp), &
                 "eq 19: h = Nu k / D (sphere, liquid)")
      call heat_transfer_coefficient(SHAPE_CYLINDER, FLUID_LIQUID, p, 2.0_wp, 0.01_wp, h, ok)
      call check(near(h, nusselt_cylinder_liquid(1800.0_wp, prandtl_number(p))*0.14_wp/0.01_wp, 1.0e-14_wp), &
                 "cylinders in liquid use eq 25")
   end subroutine test_sphere_correlations

   !> Eqs 11-12 against the closed form: eq 11 solves div(k grad T) = 0 with q = -k A dT/dr
   !> (eq 10, checked by a central difference), eq 12 = the radius average of eq 11 (Gauss).
   subroutine test_hollow_cylinder()
      real(wp), parameter :: r1 = 0.05_wp, r2 = 0.01_wp, l = 0.03_wp, k = 43.0_wp, t2 = 320.0_wp, q = 150.0_wp
      real(wp) :: x(16), w(16), avg, r, dr, dtdr, t1, g, th
      integer :: i
      th = 2.0_wp*pi
      call check(cylinder_temperature(r2, r2, t2, q, l, k, th) == t2, "eq 11 at r2")
      do i = 1, 3
         r = r2 + 0.25_wp*i*(r1 - r2)
         dr = 1.0e-6_wp*r
         dtdr = (cylinder_temperature(r + dr, r2, t2, q, l, k, th) - cylinder_temperature(r - dr, r2, t2, q, l, k, th)) &
                /(2.0_wp*dr)
         call check(near(-k*th*r*l*dtdr, q, 1.0e-7_wp), "eq 11: q = -k A dT/dr at every radius (eq 10)")
      end do
      call gauss_legendre(16, x, w)
      avg = 0.0_wp
      do i = 1, 16
         r = 0.5_wp*(r1 + r2) + 0.5_wp*(r1 - r2)*x(i)
         avg = avg + 0.5_wp*w(i)*cylinder_temperature(r, r2, t2, q, l, k, th)
      end do
      call check(near(cylinder_bulk(r1, r2, t2, q, l, k, th) - t2, avg - t2, 1.0e-12_wp), &
                 "eq 12 = radius average of eq 11")
      t1 = cylinder_temperature(r1, r2, t2, q, l, k, th)
      g = cylinder_conductance(r1, r2, l, k, th)
      call check(near(g*(t2 - t1), q, 1.0e-13_wp), "conductance: q = G (T2 - T1)")
      call check(near(g, 2.0_wp*pi*l*k/log(r1/r2), 1.0e-14_wp), "G = 2 pi L k / ln(r1/r2)")
      call check(near(cylinder_bulk_weight(r1, r2)*(t1 - t2) + t2, cylinder_bulk(r1, r2, t2, q, l, k, th), 1.0e-13_wp), &
                 "eq 12 in surface temperatures")
      call check(abs(cylinder_bulk_weight(1.0_wp + 1.0e-4_wp, 1.0_wp) - 0.5_wp) < 1.0e-4_wp, "thin ring: bulk = mean")
      call check(near(cylinder_conductance(r1, r2, l, k, th/18.0_wp)*18.0_wp, g, 1.0e-14_wp), &
                 "18 sectors conduct as the ring")
   end subroutine test_hollow_cylinder

   !> Eqs 13-17: the core has the element's volume; eq 17 is the mean of the piecewise
   !> linear profile T1 -> T0 -> T2 over the core's length.
   subroutine test_rolling_element()
      real(wp), parameter :: d = 0.01905_wp
      call check(near(element_core_area(d, 0.0_wp)*d, pi*d**3/6.0_wp, 1.0e-14_wp), "eq 13: core volume = ball volume")
      call check(near(element_core_area(0.008_wp, 0.008_wp)*0.008_wp, 0.25_wp*pi*0.008_wp**2*0.008_wp, 1.0e-14_wp), &
                 "eq 14: core volume = roller volume")
      call check(near(element_conductance(43.0_wp, d, 0.0_wp), 43.0_wp*pi*d/6.0_wp, 1.0e-14_wp), "eqs 15-16: k A / D")
      ! mean of the two linear halves: ((T1 + T0)/2 + (T0 + T2)/2)/2
      call check(near(element_bulk(330.0_wp, 340.0_wp, 350.0_wp), 0.5_wp*(0.5_wp*(340.0_wp + 330.0_wp) + &
                       0.5_wp*(330.0_wp + 350.0_wp)), 1.0e-15_wp), "eq 17 = mean of the linear profile")
   end subroutine test_rolling_element

   !> A heat set on the Appendix C bearing.
   function sample_heat(n) result(h)
      integer, intent(in) :: n
      type(thermal_heat_t) :: h
      integer :: j
      h = new_thermal_heat(n)
      do j = 1, n
         h%outer(j) = 13.0_wp + 4.0_wp*cos(2.0_wp*pi*(j - 1)/n)
         h%inner(j) = 15.0_wp + 12.0_wp*cos(2.0_wp*pi*(j - 1)/n)
         h%pocket(j) = 0.05_wp*j
         h%drag(j) = 0.3_wp
      end do
      h%land = 2.0_wp
   end function sample_heat

   !> Heat generated = heat to the coolant + through the reference + through the bore, to
   !> 1e-6 relative, with every path open; no heat: everything at the reference = inlet.
   subroutine test_network_balance()
      type(thermal_heat_t) :: h
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: f
      real(wp) :: out
      integer :: i
      h = sample_heat(ball%n_elements)
      opt = default_thermal_options(ball)
      call check(opt%reference_temperature == 323.0_wp .and. size(opt%element_velocity) == 18, &
                 "default options: reference at Rec 2.7's housing temperature")
      opt%bore_conductance = 2.0_wp
      opt%race_fluid_conductance = [5.0_wp, 3.0_wp]
      opt%element_velocity = [(75.0_wp, i = 1, ball%n_elements)]
      call solve_thermal_network(ball, h, opt, f, error)
      call check(.not. allocated(error), "network solves")
      if (allocated(error)) return
      out = f%q_coolant + f%q_reference + f%q_bore
      call check(abs(f%q_generated - out) <= 1.0e-6_wp*f%q_generated, "heat generated = coolant + reference + bore")
      call check(f%q_coolant > 0.0_wp .and. f%q_reference > 0.0_wp .and. f%q_bore > 0.0_wp, "heat leaves by every path")
      call check(f%passes > 1 .and. f%passes < opt%max_passes, "convection iteration converges")
      call check(all(f%temperature(TEMP_HOUSING:TEMP_INNER) > 323.0_wp), "every body above the reference")
      call check(f%exit_temperature > 323.0_wp, "coolant warms")
      call check(f%htc_in_range, "eq 23 holds for all Re")
      ! housing: eq 12 between its surfaces, heat through it = G_h dT
      call check(f%housing(3) > f%housing(1) .and. f%housing(1) > f%housing(2), "housing: inner > bulk > outer")
      call check(abs(f%housing(2) - 323.0_wp) < 1.0e-9_wp, "housing outer surface held at the reference")
      call check(f%shaft(2) > f%shaft(1) .and. f%shaft(1) > f%shaft(3), "shaft drained at the bore: outer > bulk > bore")
      opt%shaft_bulk_as_printed = .true.
      call solve_thermal_network(ball, h, opt, f, error)
      call check(.not. allocated(error), "network solves (shaft bulk as printed)")
      if (allocated(error)) return
      call check(abs(f%shaft(1) - cylinder_bulk_mirrored(0.5_wp*ball%shaft_od, 0.5_wp*ball%shaft_id, f%shaft(2), &
                 f%shaft(3))) < 1.0e-12_wp, "shaft bulk as printed: weight from the outer surface")
      opt%shaft_bulk_as_printed = .false.
      ! doubling the heat doubles every rise above the reference when the fluid properties are fixed
      ! is not exact (viscosity follows temperature); the no-heat field is exact:
      h%outer = 0.0_wp; h%inner = 0.0_wp; h%pocket = 0.0_wp; h%drag = 0.0_wp; h%land = 0.0_wp
      call solve_thermal_network(ball, h, opt, f, error)
      call check(.not. allocated(error), "network solves without heat")
      if (allocated(error)) return
      call check(all(abs(f%temperature(TEMP_HOUSING:TEMP_INNER) - 323.0_wp) < 1.0e-9_wp) .and. &
                 abs(f%exit_temperature - 323.0_wp) < 1.0e-9_wp, "no heat: everything at the reference")
   end subroutine test_network_balance

   !> Closed form with one path: no coolant flow, adiabatic bore -> all heat leaves through
   !> the housing: T(housing inner) = T_ref + Q / G_h, and with an outer film h the housing
   !> outer surface is T_ref + Q / (h A).
   subroutine test_network_closed_form()
      type(bearing_t) :: b
      type(thermal_heat_t) :: h
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: f
      real(wp) :: g_h, q
      integer :: i
      b = ball
      b%coolant%flow_rate = 0.0_wp
      h = sample_heat(b%n_elements)
      opt%reference_temperature = 300.0_wp
      opt%element_velocity = [(40.0_wp, i = 1, b%n_elements)]
      call solve_thermal_network(b, h, opt, f, error)
      call check(.not. allocated(error), "network solves without flow")
      if (allocated(error)) return
      q = f%q_generated
      call check(abs(f%q_reference - q) <= 1.0e-9_wp*q .and. abs(f%q_coolant) <= 1.0e-9_wp*q, &
                 "no flow, adiabatic bore: all heat through the housing")
      g_h = 2.0_wp*pi*b%width_outer*b%material(6)%conductivity/log(b%housing_od/b%bearing_od)
      call check(near(f%housing(3) - 300.0_wp, q/g_h, 1.0e-9_wp), "housing inner surface = T_ref + Q / G_h")
      call check(abs(f%shaft(2) - f%shaft(3)) < 1.0e-9_wp, "adiabatic bore: no gradient in the shaft")
      opt%reference_htc = 500.0_wp
      call solve_thermal_network(b, h, opt, f, error)
      call check(.not. allocated(error), "network solves with a housing film")
      if (allocated(error)) return
      call check(near(f%housing(2) - 300.0_wp, q/(500.0_wp*pi*b%housing_od*b%width_outer), 1.0e-9_wp), &
                 "housing outer surface = T_ref + Q / (h A)")
   end subroutine test_network_closed_form

   !> The report's march (2.10 steps 3-8) against its closed forms: partition 1/2 for like
   !> materials (eq 49), the races' shares through housing and shaft (eq 11), the element by
   !> eqs 15-16, the exit by the heat balance; generated = coolant + housing + shaft to
   !> round-off; no heat leaves everything at the reference; without flow the fluid is the
   !> temperature at which the elements convect their heat (eqs 18-27).
   subroutine test_march_closed_form()
      type(bearing_t) :: b
      type(thermal_heat_t) :: h
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: f
      real(wp) :: g_h, g_o, g_e, g_s, g_i, q_rest, w, e, r, area
      integer :: i, n
      b = ball
      n = b%n_elements
      h = sample_heat(n)
      opt = default_thermal_options(b)
      opt%element_velocity = [(75.0_wp, i = 1, n)]
      call check(element_heat_fraction(b, BODY_OUTER) == 0.5_wp, "eq 49: like materials share the heat equally")
      call solve_thermal_field(b, h, opt, f, error)
      call check(.not. allocated(error), "march solves (the default field model)")
      if (allocated(error)) return
      call check(abs(f%q_generated - (f%q_coolant + f%q_reference + f%q_bore)) <= 1.0e-12_wp*f%q_generated, &
                 "march: heat generated = coolant + housing + shaft")
      call check(near(f%q_reference, 0.5_wp*sum(h%outer), 1.0e-14_wp) .and. &
                 near(f%q_bore, 0.5_wp*sum(h%inner), 1.0e-14_wp), "march: the races' halves leave through housing and shaft")
      q_rest = 0.5_wp*(sum(h%outer) + sum(h%inner)) + sum(h%pocket) + h%land + sum(h%drag)
      w = 945.429_wp*1836.10_wp*1.0e-5_wp
      call check(near(f%exit_temperature - 323.0_wp, q_rest/w, 1.0e-12_wp), "march: exit = inlet + rest / (rho c_p Q)")
      g_h = 2.0_wp*pi*b%width_outer*43.0_wp/log(b%housing_od/b%bearing_od)
      g_o = (2.0_wp*pi/n)*b%width_outer*43.0_wp/log(b%bearing_od/b%outer_raceway_dia)
      g_i = (2.0_wp*pi/n)*b%width_inner*43.0_wp/log(b%inner_raceway_dia/b%shaft_od)
      g_s = 2.0_wp*pi*b%width_inner*43.0_wp/log(b%shaft_od/b%shaft_id)
      g_e = 43.0_wp*pi*b%d/6.0_wp
      call check(abs(f%housing(2) - 323.0_wp) < 1.0e-12_wp .and. near(f%housing(3) - f%housing(2), &
                 0.5_wp*sum(h%outer)/g_h, 1.0e-12_wp), "march: housing outer at the reference, inner by eq 11")
      call check(all(abs(f%contact_outer - f%housing(3) - 0.5_wp*h%outer/g_o) < 1.0e-9_wp), &
                 "march: each outer raceway sector by eq 11 over 2 pi / n")
      call check(all(abs(f%contact_outer - f%mid - 0.5_wp*h%outer/g_e) < 1.0e-9_wp) .and. &
                 all(abs(f%contact_inner - f%mid - 0.5_wp*h%inner/g_e) < 1.0e-9_wp), "march: the element by eqs 15-16")
      call check(abs(f%shaft(2) - sum(f%contact_inner - 0.5_wp*h%inner/g_i)/n) < 1.0e-9_wp, &
                 "march: inner race bore = the sectors' mean by eq 11")
      call check(near(f%shaft(2) - f%shaft(3), 0.5_wp*sum(h%inner)/g_s, 1.0e-12_wp), "march: shaft bore by eq 11")
      call check(all(abs(f%element_bulk - element_bulk(f%mid, f%contact_outer, f%contact_inner)) < 1.0e-12_wp), &
                 "march: element bulk by eq 17")
      ! no heat: everything at the reference (= inlet)
      call solve_thermal_march(b, new_thermal_heat(n), opt, f, error)
      call check(.not. allocated(error), "march solves without heat")
      if (allocated(error)) return
      call check(all(abs(f%temperature(TEMP_HOUSING:TEMP_INNER) - 323.0_wp) < 1.0e-9_wp) .and. &
                 abs(f%exit_temperature - 323.0_wp) < 1.0e-9_wp, "march, no heat: everything at the reference")
      ! unlike materials: eq 49 with sqrt(rho c k) of each body
      b%material(BODY_ELEMENT)%density = 3200.0_wp
      b%material(BODY_ELEMENT)%heat_capacity = 800.0_wp
      b%material(BODY_ELEMENT)%conductivity = 30.0_wp
      e = sqrt(3200.0_wp*800.0_wp*30.0_wp)
      r = sqrt(7750.0_wp*470.0_wp*43.0_wp)
      call check(near(element_heat_fraction(b, BODY_OUTER), e/(e + r), 1.0e-14_wp), "eq 49: unlike materials")
      ! no flow, air: the fluid near the elements takes their heat by convection
      b = ball
      b%coolant%coolant_type = 0
      b%coolant%flow_rate = 0.0_wp
      call solve_thermal_march(b, h, opt, f, error)
      call check(.not. allocated(error), "march solves without flow (air)")
      if (allocated(error)) return
      area = pi*b%d**2
      call check(abs(sum(f%htc*area*(f%element_bulk - f%exit_temperature)) - q_rest) <= 1.0e-6_wp*q_rest, &
                 "march without flow: the elements convect the coolant's share to the fluid near them")
      call check(abs(f%q_generated - (f%q_coolant + f%q_reference + f%q_bore)) <= 1.0e-12_wp*f%q_generated, &
                 "march without flow: heat balance")
   end subroutine test_march_closed_form

   !> The report's step-2500 field (Appendix C section 3 and section 1's last table) from
   !> its printed contact losses (section 1 "Contact Loss"; balls 12 and 18 are illegible:
   !> ball 12 takes ball 5's, the ball at its load, and ball 18 the rest of the printed total
   !> 567.7 W split as ball 17's) by the march with the housing film backed out of the
   !> printed housing surfaces (h = 2 k dT_housing / (D_h ln(D_h/D_o) dT_film) = 327
   !> W/(m**2 K), docs/thermal.md) and the printed shaft bulk convention.  The march's
   !> races carry their halves: the printed housing and shaft drops follow within the
   !> instantaneous-against-averaged heat (the print's losses are step 2500's, ADORE's field
   !> the last revolution's average).  Asserted within the issue's 1 % (3.5 K).
   subroutine test_march_report_step2500()
      type(thermal_heat_t) :: h
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: f
      real(wp), parameter :: ball_bulk(18) = [335.4_wp, 335.4_wp, 336.4_wp, 338.2_wp, 340.7_wp, 343.7_wp, 347.2_wp, &
                                              347.7_wp, 353.5_wp, 347.6_wp, 346.4_wp, 344.5_wp, 342.0_wp, 340.0_wp, &
                                              338.2_wp, 336.5_wp, 336.7_wp, 344.0_wp]
      real(wp) :: rest, got(9), want(9)
      integer :: k
      character(len=12), parameter :: names(9) = [character(len=12) :: "exit", "housing in", "housing bulk", &
                                                   "outer race", "inner race", "shaft outer", "shaft bore", &
                                                   "shaft bulk", "ball mean"]
      h = new_thermal_heat(18)
      h%outer = [16.32_wp, 14.57_wp, 13.07_wp, 12.55_wp, 13.16_wp, 14.13_wp, 14.80_wp, 15.05_wp, 14.50_wp, 14.31_wp, &
                 13.34_wp, 13.16_wp, 12.64_wp, 13.46_wp, 14.77_wp, 16.69_wp, 17.91_wp, 0.0_wp]
      h%inner = [27.35_wp, 22.71_wp, 18.22_wp, 14.32_wp, 11.45_wp, 8.797_wp, 7.595_wp, 7.474_wp, 8.171_wp, 7.608_wp, &
                 8.763_wp, 11.45_wp, 14.11_wp, 18.80_wp, 23.05_wp, 27.25_wp, 30.93_wp, 0.0_wp]
      rest = 567.7_wp - sum(h%outer) - sum(h%inner)
      h%outer(18) = rest*17.91_wp/(17.91_wp + 30.93_wp)
      h%inner(18) = rest - h%outer(18)
      opt = default_thermal_options(ball)
      opt%reference_htc = 327.0_wp
      opt%shaft_bulk_as_printed = .true.
      call solve_thermal_march(ball, h, opt, f, error)
      call check(.not. allocated(error), "march solves the report's step-2500 heat")
      if (allocated(error)) return
      got = [f%exit_temperature, f%housing(3), f%housing(1), f%temperature(TEMP_OUTER), f%temperature(TEMP_INNER), &
             f%shaft(2), f%shaft(3), f%shaft(1), f%temperature(TEMP_ELEMENT)]
      want = [341.9_wp, 348.0_wp, 346.8_wp, 349.0_wp, 351.4_wp, 349.6_wp, 317.4_wp, 329.3_wp, sum(ball_bulk)/18.0_wp]
      do k = 1, 9
         write (*, "(2a,f8.2,a,f8.2,a,f6.2,a)") "  report step 2500 by the march: ", names(k), got(k), " K (report ", &
            want(k), ", ", 100.0_wp*(got(k) - want(k))/want(k), " %)"
         call check(abs(got(k) - want(k)) <= 0.01_wp*want(k), "march from the report's losses: "//trim(names(k))// &
                    " within 1 % of the report's")
      end do
   end subroutine test_march_report_step2500

   !> Appendix D's step 4000 (roller, ambient air, no flow, reference 294 K) from its printed
   !> contact losses (all legible; they sum to its total power loss 0.9677 W) by the march:
   !> the report prints rollers, shaft and exit fluid below the reference, which no passive
   !> network with its sink at 294 K gives (maximum principle) and the march does (the
   !> rollers' mid points below their outer contacts).  Housing 294.0, shaft 293.9 K and the
   !> rollers' mean within the issue's 0.1 %; the exit fluid below the reference (its value
   !> depends on eq 18's velocity, not identified: docs/thermal.md).
   subroutine test_march_report_roller()
      type(bearing_t) :: r
      type(thermal_heat_t) :: h
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: f
      real(wp), parameter :: printed(8) = [294.0_wp, 294.0_wp, 294.0_wp, 293.9_wp, 293.6_wp, 293.6_wp, 293.9_wp, &
                                           294.0_wp]
      integer :: i
      call read_bearing(decks//"/appendix_d_roller.inp", r, error)
      call check(.not. allocated(error), "Appendix D deck reads")
      if (allocated(error)) return
      h = new_thermal_heat(8)
      h%outer = [1.331e-2_wp, 1.331e-2_wp, 8.355e-2_wp, 2.700e-1_wp, 1.996e-1_wp, 2.793e-2_wp, 1.331e-2_wp, 1.331e-2_wp]
      h%inner = [0.0_wp, 0.0_wp, 2.412e-2_wp, 1.913e-1_wp, 1.173e-1_wp, 6.026e-4_wp, 0.0_wp, 0.0_wp]
      opt = default_thermal_options(r)
      opt%element_velocity = [(1.817e5_wp*pi/30.0_wp*0.5_wp*r%d, i = 1, 8)]   ! spin surface speed
      call solve_thermal_march(r, h, opt, f, error)
      call check(.not. allocated(error), "march solves Appendix D's step-4000 heat")
      if (allocated(error)) return
      write (*, "(a,3f9.3,a,8f8.3)") "  Appendix D by the march: housing, shaft, exit ", f%housing(1), f%shaft(1), &
         f%exit_temperature, "; rollers ", f%element_bulk
      call check(abs(f%housing(1) - 294.0_wp) <= 1.0e-3_wp*294.0_wp, "Appendix D march: housing 294.0 K within 0.1 %")
      call check(abs(f%shaft(1) - 293.9_wp) <= 1.0e-3_wp*293.9_wp, "Appendix D march: shaft 293.9 K within 0.1 %")
      ! the mean roller (the bulk temperature the geometry update uses) within 0.1 %; each
      ! roller's printed value is its heat averaged over the last interval, the losses here
      ! step 4000's own, so single rollers differ more (worst 0.13 %, roller 6; measured, not
      ! asserted: docs/thermal.md)
      call check(abs(sum(f%element_bulk)/8.0_wp - sum(printed)/8.0_wp) <= 1.0e-3_wp*sum(printed)/8.0_wp, &
                 "Appendix D march: mean roller within 0.1 %")
      call check(f%exit_temperature < 294.0_wp .and. minval(f%element_bulk) < 294.0_wp, &
                 "Appendix D march: exit fluid and rollers below the reference, as printed")
   end subroutine test_march_report_roller

   !> A free ring grows by alpha dT r; a ball by alpha dT D; equal expansion of all bodies
   !> keeps the fits and scales the unmounted play.
   subroutine test_free_growth()
      type(bearing_t) :: b
      type(distortion_t) :: d0, d1
      real(wp) :: t(7), dt, alpha
      b = ball
      b%fit_inner = 0.0_wp; b%fit_outer = 0.0_wp; b%speed_inner = 0.0_wp; b%speed_outer = 0.0_wp
      dt = 40.0_wp
      alpha = b%material(BODY_OUTER)%expansion
      d0 = thermal_distortion(b, b%temperature)
      t = b%temperature
      t(TEMP_OUTER) = t(TEMP_OUTER) + dt
      t(TEMP_HOUSING) = t(TEMP_HOUSING) + dt
      d1 = thermal_distortion(b, t)
      call check(near(d1%mounted%thermal_growth(1), alpha*dt*0.5_wp*b%outer_raceway_dia, 1.0e-12_wp), &
                 "free outer ring: raceway grows by alpha dT r")
      call check(near(d1%clearance - d0%clearance, 2.0_wp*alpha*dt*0.5_wp*b%outer_raceway_dia, 1.0e-9_wp), &
                 "clearance grows by the outer raceway's diametral growth")
      t = b%temperature + dt
      d1 = thermal_distortion(b, t)
      call check(near(d1%element_diameter, b%d*(1.0_wp + b%material(BODY_ELEMENT)%expansion*dt), 1.0e-14_wp), &
                 "ball diameter grows by alpha dT D")
      call check(abs(d1%fit_inner) < 1.0e-20_wp .and. abs(d1%fit_outer) < 1.0e-20_wp, "uniform expansion keeps the fits")
      call check(near(d1%clearance - d0%clearance, alpha*dt*(b%outer_raceway_dia - b%inner_raceway_dia - 2.0_wp*b%d), &
                 1.0e-9_wp), "uniform expansion scales the play by (1 + alpha dT)")
   end subroutine test_free_growth

   !> The report's step 2500 (Appendix C): its printed bulk temperatures (housing 346.8,
   !> shaft 329.3, outer race 349.0, inner race 351.4 K) give its printed outer race fit
   !> 1.458e-5 m and effective inner race fit -2.484e-5 m (section 3).
   subroutine test_report_fits()
      type(distortion_t) :: d, d0
      real(wp) :: t(7)
      t = ball%temperature
      t(TEMP_HOUSING) = 346.8_wp
      t(TEMP_SHAFT) = 329.3_wp
      t(TEMP_OUTER) = 349.0_wp
      t(TEMP_INNER) = 351.4_wp
      t(TEMP_CAGE) = 342.0_wp
      t(TEMP_ELEMENT) = 341.9_wp   ! mean of the 18 printed ball bulk temperatures
      d = thermal_distortion(ball, t)
      call check(near(d%mounted%mounting%outer_fit, 1.458e-5_wp, 0.01_wp), "report: outer race fit 1.458e-5 within 1 %")
      call check(near(d%mounted%mounting%inner_fit, -2.484e-5_wp, 0.01_wp), "report: inner race fit -2.484e-5 within 1 %")
      write (*, "(a,3es12.4,a)") "  step-2500 temperatures -> fits, clearance: ", d%mounted%mounting%outer_fit, &
         d%mounted%mounting%inner_fit, d%clearance, "  (report 1.458e-5 -2.484e-5 1.537e-4)"
      ! the clearance's parts (measured, docs/thermal.md "Thermal distortion"): change from
      ! step 0, the free growth of outer and inner raceway and of the ball, the mounting's
      d0 = thermal_distortion(ball, ball%temperature)
      write (*, "(a,5es12.4)") "  clearance change, outer/inner raceway growth, 2 dD, mounting change: ", &
         d%clearance - d0%clearance, 2.0_wp*d%mounted%thermal_growth(1), 2.0_wp*d%mounted%thermal_growth(2), &
         2.0_wp*(d%element_diameter - ball%d), d%mounted%mounting%clearance - d0%mounted%mounting%clearance
      ! closed form: the clearance falls by 2 alpha D per kelvin of ball temperature alone
      t = ball%temperature
      t(TEMP_ELEMENT) = t(TEMP_ELEMENT) + 10.0_wp
      d = thermal_distortion(ball, t)
      call check(near(d0%clearance - d%clearance, 2.0_wp*ball%material(BODY_ELEMENT)%expansion*10.0_wp*ball%d, &
                 1.0e-9_wp), "clearance: -2 alpha D per kelvin of the ball (free growth of a sphere)")
      ! step 0: the initial temperatures change nothing (report clearance 1.525e-4)
      d = thermal_distortion(ball, ball%temperature)
      call check(near(d%clearance, 1.525e-4_wp, 0.001_wp), "initial temperatures: report's step-0 clearance 1.525e-4")
      call check(d%fit_outer == ball%fit_outer .and. d%fit_inner == ball%fit_inner, "initial temperatures: fits unchanged")
   end subroutine test_report_fits

   !> The report's printed step-2500 housing and shaft temperatures: the housing's bulk is
   !> eq 12 as written (surfaces 348.0 inside, 345.7 K outside -> 346.8 K); the shaft's is
   !> eq 12's weight taken from its outer surface (349.6 outside, 317.4 K at the bore ->
   !> 329.3 K; eq 12 as written gives 337.6 K).  Within print precision (0.05 K + the
   !> surfaces' rounding, 0.1 K).
   subroutine test_report_bulk_conventions()
      real(wp) :: tb
      tb = 348.0_wp + cylinder_bulk_weight(0.5_wp*ball%housing_od, 0.5_wp*ball%bearing_od)*(345.7_wp - 348.0_wp)
      call check(abs(tb - 346.8_wp) < 0.1_wp, "report housing bulk 346.8 K = eq 12 of its surfaces")
      tb = cylinder_bulk_mirrored(0.5_wp*ball%shaft_od, 0.5_wp*ball%shaft_id, 349.6_wp, 317.4_wp)
      call check(abs(tb - 329.3_wp) < 0.1_wp, "report shaft bulk 329.3 K = eq 12's weight from the outer surface")
      tb = 317.4_wp + cylinder_bulk_weight(0.5_wp*ball%shaft_od, 0.5_wp*ball%shaft_id)*(349.6_wp - 317.4_wp)
      call check(abs(tb - 337.6_wp) < 0.1_wp, "eq 12 as written gives 337.6 K for the report's shaft")
   end subroutine test_report_bulk_conventions

   !> Sphere drag: Stokes (C_D Re/24 -> 1, F = 3 pi mu D V) at low Re; Newton's regime
   !> C_D 0.44-0.47; the two branches meet at Re = 1000.
   subroutine test_drag()
      real(wp) :: cd, cd2, f, m
      logical :: ok
      call sphere_drag_coefficient(1.0e-4_wp, cd, ok)
      call check(ok .and. near(cd*1.0e-4_wp/24.0_wp, 1.0_wp, 0.002_wp), "Stokes: C_D = 24/Re at Re -> 0")
      ! F = 3 pi mu D V at Re = rho V D / mu = 1e-4: rho 900, mu 0.1, D 0.01 -> V = 1.11e-6
      call element_drag(0.01_wp, 0.0_wp, 1.0e-4_wp*0.1_wp/(900.0_wp*0.01_wp), 900.0_wp, 0.1_wp, 1.0_wp, f, ok)
      call check(near(f, 3.0_wp*pi*0.1_wp*0.01_wp*1.0e-4_wp*0.1_wp/(900.0_wp*0.01_wp), 0.002_wp), &
                 "Stokes drag 3 pi mu D V")
      call sphere_drag_coefficient(2.0e3_wp, cd, ok)
      call check(ok .and. cd >= 0.44_wp .and. cd <= 0.47_wp, "Newton's regime C_D 0.44-0.47 at Re 2e3")
      call sphere_drag_coefficient(1.0e5_wp, cd, ok)
      call check(ok .and. cd >= 0.44_wp .and. cd <= 0.47_wp, "Newton's regime C_D 0.44-0.47 at Re 1e5")
      call sphere_drag_coefficient(1000.0_wp, cd, ok)
      call sphere_drag_coefficient(1000.0_wp*(1.0_wp + 1.0e-9_wp), cd2, ok)
      call check(near(cd, cd2, 0.005_wp), "sphere drag branches meet at Re = 1000")
      call sphere_drag_coefficient(3.0e5_wp, cd, ok)
      call check(.not. ok, "drag crisis range flagged")
      call cylinder_drag_coefficient(1.0e4_wp, cd, ok)
      call check(ok .and. cd > 1.0_wp .and. cd < 1.1_wp, "cylinder in crossflow C_D ~ 1 at Re 1e4")
      ! effective density: X = 0.1 gives a tenth of the full-oil drag in Newton's regime
      call element_drag(0.01905_wp, 0.0_wp, 10.0_wp, 900.0_wp, 0.001_wp, 1.0_wp, f, ok)
      call element_drag(0.01905_wp, 0.0_wp, 10.0_wp, 900.0_wp, 0.001_wp, 0.1_wp, cd, ok)
      call check(near(cd, 0.1_wp*f, 1.0e-12_wp), "Newton's regime: drag proportional to the lubricant fraction")
      call churning_moment(0.01_wp, 0.0_wp, 1.0e-3_wp, 900.0_wp, 0.1_wp, 1.0_wp, m, ok)
      call check(ok .and. near(m, 8.0_wp*pi*0.1_wp*0.005_wp**3*1.0e-3_wp, 1.0e-14_wp), "creeping spin: 8 pi mu R^3 w")
      call churning_moment(0.01_wp, 0.0_wp, 1.0e4_wp, 900.0_wp, 0.01_wp, 1.0_wp, m, ok)
      call check(.not. ok, "churning beyond creeping flow flagged")
      block
         type(element_fluid_loss_t) :: r
         r = element_fluid_loss(0.01905_wp, 0.0_wp, 66.0_wp, 7970.0_wp, fluid_properties_t(945.0_wp, 5.0e-3_wp, &
                                0.14_wp, 1836.0_wp), 0.05_wp)
         call element_drag(0.01905_wp, 0.0_wp, 66.0_wp, 945.0_wp, 5.0e-3_wp, 0.05_wp, f, ok)
         call churning_moment(0.01905_wp, 0.0_wp, 7970.0_wp, 945.0_wp, 5.0e-3_wp, 0.05_wp, m, ok)
         call check(r%drag == f .and. r%moment == m .and. near(r%loss, f*66.0_wp + m*7970.0_wp, 1.0e-14_wp), &
                    "net loss = drag V + churning moment omega")
         r = element_fluid_loss(0.01905_wp, 0.0_wp, 66.0_wp, 7970.0_wp, fluid_properties_t(945.0_wp, 5.0e-3_wp, &
                                0.14_wp, 1836.0_wp), 0.0_wp)
         call check(r%loss == 0.0_wp, "no lubricant in the free space: no drag, no churning")
      end block
   end subroutine test_drag

   !> ADORE 5.0's traction does not follow the computed bulk temperatures (report 5.3, 7
   !> rec. 1): at Appendix C's step-0 state with the balls and races 30 K warmer, the force
   !> assembly with the lubricant at the initial temperatures gives the initial heat and
   !> forces bit for bit; at the state's own temperatures the EHD traction changes (thinner
   !> oil: less heat).
   subroutine test_traction_at_initial_temperatures()
      type(bearing_t) :: b
      type(mounted_geometry_t) :: g
      type(ball_step0_t) :: s0
      type(bearing_state_t) :: st, warm
      type(ball_bearing_loads_t) :: l0, l1, l2
      call appendix_c_race_control("thermal", b, g, s0)
      st = step0_state(b, s0)
      warm = st
      warm%temperature([TEMP_ELEMENT, TEMP_OUTER, TEMP_INNER]) = st%temperature([TEMP_ELEMENT, TEMP_OUTER, TEMP_INNER]) &
                                                                 + 30.0_wp
      call ball_bearing_loads(b, g, st, l0, error)
      call check(.not. allocated(error), "loads at the initial temperatures")
      if (allocated(error)) return
      call ball_bearing_loads(b, g, warm, l1, error, lubricant_temperature=b%temperature)
      call check(.not. allocated(error), "loads of the warm state, lubricant at the initial temperatures")
      if (allocated(error)) return
      call ball_bearing_loads(b, g, warm, l2, error)
      call check(.not. allocated(error), "loads of the warm state at its own temperatures")
      if (allocated(error)) return
      call check(all(l1%heat == l0%heat) .and. all(l1%races(2)%force == l0%races(2)%force), &
                 "lubricant at the initial temperatures: the warm state's heat and forces are the initial ones")
      write (*, "(a,2f9.2,a)") "  race contact heat at 323 K and at the state's +30 K: ", sum(l0%heat), sum(l2%heat), " W"
      call check(sum(l2%heat) < 0.95_wp*sum(l0%heat), "lubricant at the state's temperatures: 30 K warmer, less heat")
   end subroutine test_traction_at_initial_temperatures

end program test_thermal
