!> Engine unit tests of the thermal transients (fortran/thermal/transient.f90; issue #27
!> item 5): a single lumped node against its closed-form exponential and against a
!> numerical integration of its equation, the long-time limit of the transient equal to the
!> steady field, the energy balance (stored + leaving = generated) at every update against
!> a fine Runge-Kutta integration of the lumps, and Appendix C's capacities by hand.
program test_thermal_transient
   use adore_test_support, only: check, finish, get_decks_dir, near
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t, TEMP_HOUSING
   use adore_model_from_deck, only: read_bearing
   use adore_thermal_network, only: thermal_heat_t, thermal_options_t, thermal_field_t, default_thermal_options, &
                                    new_thermal_heat
   use adore_thermal_march, only: solve_thermal_field
   use adore_thermal_transient, only: thermal_transient_t, new_thermal_transient, lump_capacities, &
                                      lump_conductances, lump_relaxation, lump_net_inflow, thermal_transient_step, &
                                      lump_temperatures, LUMP_HOUSING, LUMP_SHAFT, LUMP_COOLANT, LUMP_ELEMENT1
   implicit none

   character(len=:), allocatable :: decks
   type(bearing_t) :: ball
   type(error_type), allocatable :: error

   call get_decks_dir(decks)
   call read_bearing(decks//"/appendix_c_ball.inp", ball, error)
   call check(.not. allocated(error), "Appendix C deck reads")
   if (allocated(error)) call finish("thermal transient")

   call test_single_node()
   call test_capacities()
   call test_long_time_limit()
   call test_energy_balance()

   call finish("thermal transient")

contains

   !> One lump (C = 1400 J/K, G = 62.3 W/K: about Appendix C's housing) heated by q from
   !> T0 with its sink at T_inf: C dT/dt = q - G (T - T_inf), closed form T(t) = T_inf + q/G
   !> + (T0 - T_inf - q/G) exp(-G t / C).  Ten updates of dt = 5 s with q = 143 W, then ten
   !> with q = 40 W (the closed form restarted from the state at 50 s): lump_relaxation
   !> toward the steady T_inf + q/G agrees to 1e-12 K at every update, whatever dt / tau.
   !> The net heat in over each update (lump_net_inflow) against a Simpson integration of
   !> G (T_s - T(t)) along the closed form, and the stored heat C dT.
   subroutine test_single_node()
      real(wp), parameter :: c = 1400.0_wp, g = 62.3_wp, t_inf = 323.0_wp, t0 = 300.0_wp, dt = 5.0_wp
      real(wp) :: t, t_exact, ts, q, t_start, t_before, e_num, s, x
      integer :: k, i
      integer, parameter :: m = 2000
      t = t0
      t_start = t0
      do k = 1, 20
         q = 143.0_wp
         if (k > 10) q = 40.0_wp
         if (k == 11) t_start = t
         ts = t_inf + q/g
         t_before = t
         t = lump_relaxation(t, ts, c, g, dt)
         t_exact = t_inf + q/g + (t_start - t_inf - q/g)*exp(-g*(k - merge(10, 0, k > 10))*dt/c)
         call check(abs(t - t_exact) < 1.0e-12_wp*t_exact, "single lump: the closed-form exponential")
         ! net heat in over the update by Simpson's rule on the closed form
         e_num = 0.0_wp
         do i = 0, m
            s = g*(ts - (ts + (t_before - ts)*exp(-g*i*dt/m/c)))
            e_num = e_num + s*merge(1.0_wp, merge(4.0_wp, 2.0_wp, mod(i, 2) == 1), i == 0 .or. i == m)
         end do
         e_num = e_num*dt/m/3.0_wp
         call check(near(lump_net_inflow(t_before, ts, c, g, dt), e_num, 1.0e-10_wp), &
                    "single lump: net heat in = the integral of G (T_s - T)")
         call check(near(lump_net_inflow(t_before, ts, c, g, dt), c*(t - t_before), 1.0e-10_wp), &
                    "single lump: net heat in = C dT")
      end do
      ! tiny steps: the exponential's small-argument branch keeps the net heat to round-off
      x = 1.0e-6_wp*g/c
      call check(near(lump_net_inflow(300.0_wp, 310.0_wp, c, g, 1.0e-6_wp), g*10.0_wp*1.0e-6_wp*(1.0_wp - x/2.0_wp + &
                      x*x/6.0_wp), 1.0e-14_wp), "single lump: a short step takes G (T_s - T0) dt (1 - x/2 + x^2/6)")
      call check(lump_relaxation(300.0_wp, 310.0_wp, 0.0_wp, g, dt) == 310.0_wp, &
                 "single lump: no capacity is the steady field")
   end subroutine test_single_node

   !> Appendix C's capacities by hand from its dimensions and Rec 8 (7750 kg/m**3, 470
   !> J/(kg K) for every body in its echo).
   subroutine test_capacities()
      real(wp), allocatable :: c(:), g(:)
      real(wp) :: rc
      integer :: k
      c = lump_capacities(ball)
      rc = 7750.0_wp*470.0_wp
      call check(size(c) == LUMP_ELEMENT1 - 1 + ball%n_elements, "capacities: one per body and ball")
      call check(near(c(LUMP_ELEMENT1), rc*pi*ball%d**3/6.0_wp, 1.0e-14_wp), "capacity: a ball rho c pi D^3/6")
      call check(near(c(LUMP_HOUSING), rc*0.25_wp*pi*(ball%housing_od**2 - ball%bearing_od**2)*ball%width_outer, &
                      1.0e-14_wp), "capacity: the housing ring")
      call check(near(c(LUMP_SHAFT), rc*0.25_wp*pi*(ball%shaft_od**2 - ball%shaft_id**2)*ball%width_inner, &
                      1.0e-14_wp), "capacity: the hollow shaft")
      call check(all(c > 0.0_wp), "capacities: every lump holds heat")
      ! a ball's conductance: eqs 15-16 from its mid point to both contacts, 2 k (pi D^2/6)/D,
      ! plus h pi D^2 (eqs 18-23)
      g = lump_conductances(ball, default_thermal_options(ball), [(8.1e3_wp, k = 1, ball%n_elements)])
      call check(near(g(LUMP_ELEMENT1), 2.0_wp*43.0_wp*pi*ball%d/6.0_wp + 8.1e3_wp*pi*ball%d**2, 1.0e-14_wp), &
                 "conductance: a ball's two contact paths and its convection")
      call check(near(g(LUMP_COOLANT), 945.429_wp*1836.10_wp*1.0e-5_wp, 1.0e-5_wp), "conductance: the coolant's rho c_p Q")
      ! the coolant: MIL-L-7808 (945.4 kg/m**3, 1836.1 J/(kg K)) in a free space below the
      ! annulus between the raceways
      call check(c(LUMP_COOLANT) < 945.5_wp*1836.2_wp*0.25_wp*pi*(ball%outer_raceway_dia**2 - &
                 ball%inner_raceway_dia**2)*0.5_wp*(ball%width_outer + ball%width_inner), &
                 "capacity: the coolant within the free space")
   end subroutine test_capacities

   !> A march field of Appendix C (sample heat), the option's lumps from the initial
   !> temperatures: 400 updates of 10 s with the same heat bring every temperature of the
   !> field (bulk, surfaces, contact nodes, exit) to the steady one within 1e-9 K; a single
   !> update of 1e6 s likewise.  The first 3 ms update moves each lump by (T_s - T0)(1 -
   !> exp(-dt G/C)) (the housing's time constant C/G is ~20 s: it barely moves).
   subroutine test_long_time_limit()
      type(thermal_heat_t) :: h
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: steady, f
      type(thermal_transient_t) :: tr
      real(wp), allocatable :: c(:), g(:)
      real(wp) :: worst, t0
      integer :: k
      call sample_field(h, opt, steady)
      if (allocated(error)) return
      tr = new_thermal_transient(ball)
      c = lump_capacities(ball)
      g = lump_conductances(ball, opt, steady%htc)
      f = steady
      call thermal_transient_step(tr, ball, opt, 3.0e-3_wp, f, error)
      call check(.not. allocated(error), "transient step runs")
      if (allocated(error)) return
      t0 = ball%temperature(TEMP_HOUSING)
      call check(near(f%temperature(TEMP_HOUSING) - t0, (steady%temperature(TEMP_HOUSING) - t0)* &
                      (1.0_wp - exp(-3.0e-3_wp*g(LUMP_HOUSING)/c(LUMP_HOUSING))), 1.0e-9_wp), &
                 "transient: the housing's first step")
      call check(f%housing(2) == opt%reference_temperature .and. f%housing(3) > f%housing(1) .and. &
                 f%housing(1) > f%housing(2), "transient: the housing's outer surface stays at the reference")
      call check(near(f%shaft(2) - f%shaft(3), steady%shaft(2) - steady%shaft(3), 1.0e-9_wp), &
                 "transient: the shaft's profile is the steady one shifted")
      call check(c(LUMP_HOUSING)/g(LUMP_HOUSING) > 1.0_wp .and. c(LUMP_ELEMENT1)/g(LUMP_ELEMENT1) > 0.1_wp, &
                 "transient: bodies' time constants of seconds")
      call check(abs(f%exit_temperature - steady%exit_temperature) > 1.0e-3_wp, "transient: the coolant lags")
      do k = 1, 400
         f = steady
         call thermal_transient_step(tr, ball, opt, 10.0_wp, f, error)
         if (allocated(error)) return
      end do
      worst = field_difference(f, steady)
      call check(worst <= 1.0e-9_wp, "transient: its long-time limit is the steady field (1e-9 K)")
      tr = new_thermal_transient(ball)
      f = steady
      call thermal_transient_step(tr, ball, opt, 1.0e6_wp, f, error)
      call check(field_difference(f, steady) <= 1.0e-9_wp, "transient: one long update gives the steady field")
   end subroutine test_long_time_limit

   !> Updates of 3 ms, then 0.5 s, with the heat changing between them (x1, x1.6, x0.4,
   !> x1): at each the module's generated = stored + leaving to round-off, and its new
   !> temperatures, stored and leaving heat against a fine Runge-Kutta integration (RK4,
   !> 2000 steps per update) of C dT/dt = G (T_s - T) for every lump with the heat leaving
   !> the bearing at the rate Q - sum G (T_s - T).
   subroutine test_energy_balance()
      type(thermal_heat_t) :: h, hk
      type(thermal_options_t) :: opt
      type(thermal_field_t) :: steady, f
      type(thermal_transient_t) :: tr
      real(wp), allocatable :: c(:), g(:), ts(:), y(:), k1(:), k2(:), k3(:), k4(:), y0(:)
      real(wp) :: dt, hh, out, stored, leaving, q
      real(wp), parameter :: scale(8) = [1.0_wp, 1.6_wp, 0.4_wp, 1.0_wp, 1.0_wp, 1.6_wp, 0.4_wp, 1.0_wp]
      integer :: k, i, m
      integer, parameter :: nsub = 2000
      call sample_field(h, opt, steady)
      if (allocated(error)) return
      tr = new_thermal_transient(ball)
      c = lump_capacities(ball)
      y = tr%temperature
      m = size(y)
      do k = 1, 8
         dt = 3.0e-3_wp
         if (k > 4) dt = 0.5_wp
         hk = h
         hk%outer = scale(k)*h%outer
         hk%inner = scale(k)*h%inner
         call solve_thermal_field(ball, hk, opt, f, error)
         if (allocated(error)) return
         g = lump_conductances(ball, opt, f%htc)
         ts = lump_temperatures(f)
         q = f%q_generated
         call thermal_transient_step(tr, ball, opt, dt, f, error)
         if (allocated(error)) return
         call check(abs(tr%generated - tr%stored - tr%leaving) <= 1.0e-9_wp*tr%generated, &
                    "transient: generated = stored + leaving at the update (round-off)")
         ! the independent integration
         y0 = y
         hh = dt/nsub
         out = 0.0_wp
         do i = 1, nsub
            k1 = g*(ts - y)/c
            k2 = g*(ts - (y + 0.5_wp*hh*k1))/c
            k3 = g*(ts - (y + 0.5_wp*hh*k2))/c
            k4 = g*(ts - (y + hh*k3))/c
            ! the heat leaving the bearing at the rate q - sum G (T_s - T), by the same stages
            out = out + hh*q - hh/6.0_wp*sum(c*(k1 + 2.0_wp*k2 + 2.0_wp*k3 + k4))
            y = y + hh/6.0_wp*(k1 + 2.0_wp*k2 + 2.0_wp*k3 + k4)
         end do
         stored = sum(c*(y - y0))
         leaving = out
         call check(maxval(abs(y - tr%temperature)) < 1.0e-9_wp, "transient: temperatures = Runge-Kutta's")
         call check(near(tr%stored, stored, 1.0e-8_wp) .and. near(tr%leaving, leaving, 1.0e-8_wp), &
                    "transient: stored and leaving heat = Runge-Kutta's")
         call check(near(stored + leaving, q*dt, 1.0e-9_wp), "transient (Runge-Kutta): stored + leaving = generated")
      end do
      call check(tr%balance <= 1.0e-9_wp .and. tr%updates == 8, &
                 "transient: the worst balance kept")
      write (*, "(a, es9.2)") "thermal transient: worst relative energy balance ", tr%balance
   end subroutine test_energy_balance

   !> The largest difference (K) between two fields' temperatures (bulk, surfaces, nodes, exit).
   real(wp) function field_difference(a, b) result(d)
      type(thermal_field_t), intent(in) :: a, b
      d = maxval(abs(a%temperature - b%temperature))
      d = max(d, maxval(abs(a%housing - b%housing)), maxval(abs(a%shaft - b%shaft)), &
              abs(a%exit_temperature - b%exit_temperature), maxval(abs(a%cage_surface - b%cage_surface)))
      d = max(d, maxval(abs(a%contact_outer - b%contact_outer)), maxval(abs(a%contact_inner - b%contact_inner)), &
              maxval(abs(a%mid - b%mid)), maxval(abs(a%element_bulk - b%element_bulk)), &
              maxval(abs(a%race_bulk - b%race_bulk)))
   end function field_difference

   !> Appendix C's march field for a sample heat (outer 14 W, inner 16 W per ball with a
   !> pattern around the orbit, 1 W a pocket, 2 W the lands) at 76 m/s.
   subroutine sample_field(h, opt, f)
      type(thermal_heat_t), intent(out) :: h
      type(thermal_options_t), intent(out) :: opt
      type(thermal_field_t), intent(out) :: f
      integer :: k, n
      n = ball%n_elements
      h = new_thermal_heat(n)
      h%outer = [(14.0_wp + 2.0_wp*cos(2.0_wp*pi*(k - 1)/n), k = 1, n)]
      h%inner = [(16.0_wp + 8.0_wp*cos(2.0_wp*pi*(k - 1)/n), k = 1, n)]
      h%pocket = 1.0_wp
      h%land = 2.0_wp
      opt = default_thermal_options(ball)
      opt%element_velocity = 76.0_wp
      call solve_thermal_field(ball, h, opt, f, error)
      call check(.not. allocated(error), "march field solves")
   end subroutine sample_field

end program test_thermal_transient
