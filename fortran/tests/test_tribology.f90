!> Engine unit tests of the step-0 tribology building blocks (fortran/tribology/):
!> closed forms and defining conditions only; the comparison with the report's print is
!> in tests/test_tribology.py.
program test_tribology
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, ADORE_INPUT_ERROR
   use adore_core_quadrature, only: gauss_legendre, gauss_legendre_newton, TABLED_ORDERS
   use adore_tribology_film, only: lubricant_t, central_film_thickness, thermal_reduction_factor, &
                                   lubricant_from_code, kinematic_viscosity, dynamic_viscosity, &
                                   temperature_viscosity_coefficient, LUBRICANT_MIL_L_7808
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_traction, &
                                   contact_slip, pure_rolling_points, SIDE_OUTER, SIDE_INNER, print_slip_node
   use adore_tribology_flash, only: flash_rise_dimensionless, contact_temperature_rise
   use adore_tribology_traction_law, only: curve_law
   use adore_tribology_slip, only: contact_power
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_contact_power, &
                                           ehd_contact_traction_fast, film_shear_stress, film_constants, &
                                           thermal_film_shear
   use adore_tribology_ehd_strip_table, only: strip_log_shear, strip_log_shear_nodes, STRIP_ERROR, STRIP_A_MAX, &
                                              STRIP_L_MIN, STRIP_L_MAX
   use adore_quasistatic_ball_kinematics, only: ball_kinematics_t, min_dissipation_kinematics, ehd_films_t
   implicit none

   !> the Appendix C deck's fitted traction curve kappa = (A + B u) exp(-C u) + D: [A, B, C, D]
   !> (tests/test_ball_step0_tribology.py COEF)
   real(wp), parameter :: LAW(4) = [-1.6e-2_wp, 3.82896e-2_wp, 1.71782_wp, 1.6e-2_wp]

   call test_gauss()
   call test_film()
   call test_lubricant()
   call test_slip()
   call test_flash()
   call test_thermal_film_shear()
   call test_print_slip_series()
   call test_fast_paths()
   call test_strip_table()
   call test_strip_nodes()
   call test_min_dissipation_search()

   call finish("tribology")

contains

   !> n-point Gauss-Legendre integrates x**(2n-1) and x**(2n-2) exactly.
   subroutine test_gauss()
      real(wp) :: x(7), w(7)
      call gauss_legendre(7, x, w)
      call check(abs(sum(w) - 2.0_wp) < 1.0e-14_wp, "gauss: weights sum to 2")
      call check(abs(sum(w*x**12) - 2.0_wp/13.0_wp) < 1.0e-14_wp, "gauss: x**12 exact")
      call check(abs(sum(w*x**13)) < 1.0e-14_wp, "gauss: x**13 exact")
   end subroutine test_gauss

   !> The fast paths of issue #16 against their references: tabled Gauss rules bit for bit
   !> the Newton ones; the power-only integrals bit for bit the full routines' power; the
   !> flash contact average by trapezoid weights equal to eq 53's O(n**2) sum; the fast EHD
   !> traction converging to the reference quadrature's limit as its orders grow.
   subroutine test_fast_paths()
      type(error_type), allocatable :: error
      type(ball_race_contact_t) :: c
      type(contact_traction_t) :: t, tf
      type(ehd_rheology_t) :: rheo
      real(wp), allocatable :: x(:), w(:), xn(:), wn(:)
      real(wp) :: p, avg_ref, avg_fast, peak, xk(3), wk(3), g(3)
      integer :: k, n

      do k = 1, size(TABLED_ORDERS)
         n = TABLED_ORDERS(k)
         allocate (x(n), w(n), xn(n), wn(n))
         call gauss_legendre(n, x, w)
         call gauss_legendre_newton(n, xn, wn)
         call check(all(x == xn) .and. all(w == wn), "gauss: tabled rule bit-identical to Newton's")
         deallocate (x, w, xn, wn)
      end do
      ! Appendix C ball 1, outer race contact at its step-0 state (EHD film of model 3)
      c = ball_race_contact_t(SIDE_OUTER, atan2(0.14701482232434315_wp, 0.9891342891725783_wp), 0.009525_wp, &
                              0.07004480819399529_wp, -7894.364961447181_wp*[cos(-0.13801441540302414_wp), &
                              sin(-0.13801441540302414_wp)], -943.0_wp, 0.0023737604859883953_wp, 2479.297919485147_wp)
      rheo = ehd_rheology_t(eta_w=0.0815882_wp, alpha=5.2214e-9_wp, beta=0.0425519_wp, conductivity=0.1425185_wp)
      call ehd_contact_traction(c, rheo, 4.55e-7_wp, 3.15e-4_wp, 4, 8, t, error)
      call ehd_contact_power(c, rheo, 4.55e-7_wp, 3.15e-4_wp, 4, 8, p, error)
      call check(.not. allocated(error) .and. p == t%power, "EHD power-only: bit-identical to the full routine's")
      call contact_traction(c, curve_law([0.0_wp, 0.02_wp, 0.016_wp, 1.0_wp]), 1.0_wp, 4, t, error)
      call contact_power(c, curve_law([0.0_wp, 0.02_wp, 0.016_wp, 1.0_wp]), 1.0_wp, 4, p, error)
      call check(.not. allocated(error) .and. p == t%power, "law power-only: bit-identical to the full routine's")
      ! fast EHD traction at high orders against the reference quadrature at high orders
      call ehd_contact_traction(c, rheo, 4.55e-7_wp, 3.15e-4_wp, 128, 128, t, error)
      call ehd_contact_traction_fast(c, rheo, 4.55e-7_wp, 3.15e-4_wp, tf, error, 32, 24)
      call check(abs(tf%power/t%power - 1.0_wp) < 1.0e-7_wp .and. abs(tf%force - t%force) < 1.0e-6_wp*abs(t%force) &
                 .and. abs(tf%force_sin - t%force_sin) < 1.0e-5_wp*abs(t%force), &
                 "EHD fast: same limit as the reference quadrature")
      ! flash contact average: trapezoid weights against eq 53 summed
      xk = [-0.8e-3_wp, 0.1e-3_wp, 0.7e-3_wp]
      wk = [0.3e-3_wp, 0.9e-3_wp, 0.4e-3_wp]
      g = [0.3_wp, 0.01_wp, 0.2_wp]
      call contact_temperature_rise(1.0e-3_wp, 2.0e-4_wp, 2.0e9_wp, xk, wk, g, 12.0_wp, 9.0_wp, [7800.0_wp, 460.0_wp, &
                                    40.0_wp], [7800.0_wp, 460.0_wp, 40.0_wp], 201, avg_ref, peak, error)
      call contact_temperature_rise(1.0e-3_wp, 2.0e-4_wp, 2.0e9_wp, xk, wk, g, 12.0_wp, 9.0_wp, [7800.0_wp, 460.0_wp, &
                                    40.0_wp], [7800.0_wp, 460.0_wp, 40.0_wp], 201, avg_fast, error=error)
      call check(abs(avg_fast/avg_ref - 1.0_wp) < 1.0e-12_wp, "flash: trapezoid weights = eq 53's sum")
   end subroutine test_fast_paths

   !> The strip integral's table (adore_tribology_ehd_strip_table, generated by
   !> tools/ehd_strip_table.py in numpy) against the integral computed here: G(A, L) =
   !> ln W - 2 L, W = integral_0^{pi/2} H(L + A cos psi) cos psi dpsi, H(x) = 2 theta
   !> tanh(theta), theta = asinh(e**x), by 16 panels x 24 Gauss points, on a lattice of
   !> (A, L) off the table's grid (steps 0.37 and 0.53 from the domain's corner, and the far
   !> edges): within the table's error bound STRIP_ERROR.  Then the isothermal limit G(A,
   !> L -> -inf) = ln(integral of exp(2 A sqrt(1 - y**2)) over y in [-1, 1]) and, at A = 0,
   !> the exact G(0, L) = ln H(L) - 2 L.
   subroutine test_strip_table()
      integer, parameter :: NPAN = 16, NG = 24
      real(wp) :: xg(NG), wg(NG), cpsi(NPAN*NG), wpsi(NPAN*NG), a, l, worst, lo, iso, th
      integer :: i, j, k

      call gauss_legendre(NG, xg, wg)
      do k = 1, NPAN
         lo = 0.5_wp*pi*real(k - 1, wp)/NPAN
         cpsi((k - 1)*NG + 1:k*NG) = cos(lo + 0.25_wp*pi/NPAN*(1.0_wp + xg))
         wpsi((k - 1)*NG + 1:k*NG) = 0.25_wp*pi/NPAN*wg*cpsi((k - 1)*NG + 1:k*NG)
      end do
      worst = 0.0_wp
      do i = 0, 33
         a = min(0.37_wp*i, STRIP_A_MAX)
         do j = 0, 53
            l = min(STRIP_L_MIN + 0.53_wp*j, STRIP_L_MAX)
            worst = max(worst, abs(strip_log_shear(a, l) - g_direct(a, l, cpsi, wpsi)))
         end do
      end do
      call check(worst <= STRIP_ERROR, "EHD strip table: within its error bound of the direct integral")
      ! isothermal limit (Z -> 0): exp(G) -> integral of E**2 across the strip, = 2 x the
      ! integral over psi of exp(2 A cos psi) cos psi
      a = 3.7_wp
      iso = log(2.0_wp*sum(wpsi*exp(2.0_wp*a*cpsi)))
      call check(abs(strip_log_shear(a, STRIP_L_MIN) - iso) <= STRIP_ERROR, &
                 "EHD strip table: the isothermal limit at its lowest L")
      th = asinh(exp(0.3_wp))
      call check(abs(strip_log_shear(0.0_wp, 0.3_wp) - (log(2.0_wp*th*tanh(th)) - 0.6_wp)) <= STRIP_ERROR, &
                 "EHD strip table: A = 0 is H(L) itself")
   end subroutine test_strip_table

   !> strip_log_shear_nodes (the C kernel of fortran/tribology/ehd_strip_kernel.c) against
   !> strip_log_shear node by node, bit for bit: 2 000 000 pseudo-random points of the
   !> domain (A in [0, STRIP_A_MAX], L in [STRIP_L_MIN - 3, STRIP_L_MAX]: below STRIP_L_MIN
   !> clamped), the domain's corners and grid lines; the nodes beyond the domain (A >
   !> STRIP_A_MAX or L > STRIP_L_MAX) keep their value and a NaN argument gives NaN.
   subroutine test_strip_nodes()
      integer, parameter :: N = 1000
      real(wp) :: a(N), l(N), g(N), r(2, N), expect
      integer :: pass, j, bad, left
      integer, allocatable :: seed(:)

      call random_seed(size=j)
      allocate (seed(j))
      seed = 20261127
      call random_seed(put=seed)
      bad = 0
      do pass = 1, 2000
         call random_number(r)
         a = STRIP_A_MAX*r(1, :)
         l = STRIP_L_MIN - 3.0_wp + (STRIP_L_MAX - STRIP_L_MIN + 3.0_wp)*r(2, :)
         if (pass == 1) then
            ! the corners, the grid lines (cell edges: x0 = 1 exactly) and the upper edges
            a(1:4) = [0.0_wp, STRIP_A_MAX, 0.0_wp, STRIP_A_MAX]
            l(1:4) = [STRIP_L_MIN, STRIP_L_MIN, STRIP_L_MAX, STRIP_L_MAX]
            a(5:104) = [(0.08_wp*j, j = 0, 99)]
            l(5:104) = [(STRIP_L_MIN + 0.08_wp*j, j = 0, 99)]
         end if
         g = -7.0_wp
         call strip_log_shear_nodes(N, a, l, g, left)
         if (left /= 0) bad = bad + 1
         do j = 1, N
            expect = strip_log_shear(a(j), max(l(j), STRIP_L_MIN))
            if (.not. (g(j) == expect)) bad = bad + 1
         end do
      end do
      call check(bad == 0, "EHD strip table at nodes (C kernel): strip_log_shear's bits at 2e6 points")
      a(1:4) = [STRIP_A_MAX*1.0001_wp, 1.0_wp, 1.0_wp, 1.0_wp]
      l(1:4) = [0.0_wp, STRIP_L_MAX + 0.01_wp, 0.0_wp, 0.0_wp]
      a(3) = ieee_value(1.0_wp, ieee_quiet_nan)
      g(1:4) = -7.0_wp
      call strip_log_shear_nodes(4, a(1:4), l(1:4), g(1:4), left)
      call check(left == 2 .and. g(1) == -7.0_wp .and. g(2) == -7.0_wp .and. ieee_is_nan(g(3)) .and. &
                 g(4) == strip_log_shear(1.0_wp, 0.0_wp), &
                 "EHD strip table at nodes: beyond the domain untouched and counted, NaN for NaN")
   end subroutine test_strip_nodes

   !> G(A, L) of the strip table by the rule cpsi = cos(psi), wpsi = weights x cos(psi)
   !> on [0, pi/2] (test_strip_table).
   function g_direct(a, l, cpsi, wpsi) result(g)
      real(wp), intent(in) :: a, l, cpsi(:), wpsi(:)
      real(wp) :: g, theta(size(cpsi))
      theta = asinh(exp(l + a*cpsi))
      g = log(sum(wpsi*2.0_wp*theta*tanh(theta))) - 2.0_wp*l
   end function g_direct

   !> The minimum-dissipation search (Newton, default) finds the reference search's minimum
   !> (grid and golden sections) of the same power: Appendix C ball 1's geometry with the
   !> a traction curve and with EHD films, with and without a pitch hint.
   subroutine test_min_dissipation_search()
      type(error_type), allocatable :: error
      type(ball_kinematics_t) :: kf, kr
      type(ehd_films_t) :: films
      real(wp), parameter :: d = 0.01905_wp, r = 0.07004480819399529_wp, w_i = 20000.0_wp*pi/30.0_wp
      real(wp), parameter :: n_o(2) = [0.14701482232434315_wp, 0.9891342891725783_wp]
      real(wp), parameter :: n_i(2) = [-0.4611144976769735_wp, -0.8873406448665092_wp]
      real(wp), parameter :: a(2) = [0.0023737604859883953_wp, 0.0012601685765409561_wp]
      real(wp), parameter :: q(2) = [2479.297919485147_wp, 790.4621194043308_wp]
      integer :: m

      films%rheo = ehd_rheology_t(eta_w=0.0815882_wp, alpha=5.2214e-9_wp, beta=0.0425519_wp, &
                                  conductivity=0.1425185_wp)
      films%h = [4.549771167475113e-07_wp, 4.5936049558531147e-07_wp]
      films%b = [0.0003151476071606269_wp, 0.0002141590871031877_wp]
      do m = 1, 3
         select case (m)
         case (1)
            call min_dissipation_kinematics(d, r, n_o, n_i, 0.0_wp, w_i, a, q, curve_law(LAW), kf, error)
            call min_dissipation_kinematics(d, r, n_o, n_i, 0.0_wp, w_i, a, q, curve_law(LAW), kr, error, &
                                            reference=.true.)
         case (2)
            call min_dissipation_kinematics(d, r, n_o, n_i, 0.0_wp, w_i, a, q, curve_law(LAW), kf, error, &
                                            hint=-0.13_wp, ehd=films)
            call min_dissipation_kinematics(d, r, n_o, n_i, 0.0_wp, w_i, a, q, curve_law(LAW), kr, error, &
                                            hint=-0.13_wp, ehd=films, reference=.true.)
         case (3)
            call min_dissipation_kinematics(d, r, n_o, n_i, 0.0_wp, w_i, a, q, curve_law(LAW), kf, error, ehd=films)
            call min_dissipation_kinematics(d, r, n_o, n_i, 0.0_wp, w_i, a, q, curve_law(LAW), kr, error, &
                                            ehd=films, reference=.true.)
         end select
         call check(.not. allocated(error) .and. kf%ok .and. kr%ok, "min dissipation: both searches solve")
         ! the golden section places a shallow minimum to ~sqrt(eps): 1e-6 deg, 1e-8 relative
         call check(abs(kf%pitch - kr%pitch) < 1.0e-6_wp*pi/180.0_wp, "min dissipation: Newton's pitch = reference's")
         call check(abs(kf%spin_speed/kr%spin_speed - 1.0_wp) < 1.0e-8_wp, "min dissipation: Newton's speed = reference's")
         call check(kf%power <= kr%power*(1.0_wp + 1.0e-13_wp), "min dissipation: Newton's power <= reference's")
      end do
   end subroutine test_min_dissipation_search

   !> Scaling laws of the Hamrock-Dowson formula and the limits of the thermal factor.
   subroutine test_film()
      type(error_type), allocatable :: error
      real(wp) :: h1, h2
      call central_film_thickness(0.01_wp, 5.0_wp, 20.0_wp, 1000.0_wp, 2.2e11_wp, 0.01_wp, 1.0e-8_wp, h1, error)
      call check(.not. allocated(error), "film: accepted")
      call central_film_thickness(0.01_wp, 5.0_wp, 40.0_wp, 1000.0_wp, 2.2e11_wp, 0.01_wp, 1.0e-8_wp, h2, error)
      call check(abs(h2/h1 - 2.0_wp**0.67_wp) < 1.0e-12_wp, "film: h ~ u**0.67")
      call central_film_thickness(0.01_wp, 5.0_wp, 20.0_wp, 2000.0_wp, 2.2e11_wp, 0.01_wp, 1.0e-8_wp, h2, error)
      call check(abs(h2/h1 - 2.0_wp**(-0.067_wp)) < 1.0e-12_wp, "film: h ~ Q**-0.067")
      call central_film_thickness(0.01_wp, 5.0_wp, 20.0_wp, 1000.0_wp, 2.2e11_wp, 0.01_wp, 2.0e-8_wp, h2, error)
      call check(abs(h2/h1 - 2.0_wp**0.53_wp) < 1.0e-12_wp, "film: h ~ alpha**0.53")
      call central_film_thickness(0.01_wp, 5.0_wp, -1.0_wp, 1000.0_wp, 2.2e11_wp, 0.01_wp, 1.0e-8_wp, h2, error)
      call check(allocated(error), "film: negative speed rejected")
      call check(abs(thermal_reduction_factor(1.0e9_wp, 2.2e11_wp, 0.0_wp, 0.0_wp) - 1.0_wp) < 1.0e-15_wp, &
                 "thermal factor: 1 at zero thermal loading")
      call check(thermal_reduction_factor(1.0e9_wp, 2.2e11_wp, 5.0_wp, 0.1_wp) < &
                 thermal_reduction_factor(1.0e9_wp, 2.2e11_wp, 5.0_wp, 0.0_wp), "thermal factor: falls with slip")
      call test_film_powers()
   end subroutine test_film

   !> The film and the thermal factor (their powers as exp of logarithms, issue #30) against
   !> the formulas written with `**` (libm pow), over the decks' range and beyond: R_x 2 ..
   !> 30 mm, k 1.5 .. 60, u 0.1 .. 200 m/s, Q 1 .. 3e4 N, eta0 1e-3 .. 0.1 Pa s, alpha 5e-9
   !> .. 3e-8 1/Pa; p_h 0.3 .. 4 GPa, L 0 .. 100, S 0 .. 3: equal to round-off.
   subroutine test_film_powers()
      type(error_type), allocatable :: error
      real(wp) :: rx, k, u, q, eta0, al, h, hp, su, sg, sw, worst_h, worst_phi, ph, l, sr, phi, phip
      integer :: i1, i2, i3, i4, i5, n
      real(wp), parameter :: EP = 2.2e11_wp
      worst_h = 0.0_wp
      n = 0
      do i1 = 0, 3
         rx = 2.0e-3_wp*15.0_wp**(i1/3.0_wp)
         do i2 = 0, 3
            k = 1.5_wp*40.0_wp**(i2/3.0_wp)
            do i3 = 0, 4
               u = 0.1_wp*2000.0_wp**(i3/4.0_wp)
               do i4 = 0, 4
                  q = 3.0e4_wp**(i4/4.0_wp)
                  do i5 = 0, 3
                     eta0 = 1.0e-3_wp*100.0_wp**(i5/3.0_wp)
                     al = 5.0e-9_wp*6.0_wp**(mod(i1 + i5, 4)/3.0_wp)
                     call central_film_thickness(rx, k, u, q, EP, eta0, al, h, error)
                     su = eta0*u/(EP*rx)
                     sg = al*EP
                     sw = q/(EP*rx*rx)
                     hp = rx*2.69_wp*su**0.67_wp*sg**0.53_wp*sw**(-0.067_wp)*(1.0_wp - 0.61_wp*exp(-0.73_wp*k))
                     worst_h = max(worst_h, abs(h/hp - 1.0_wp))
                     n = n + 1
                  end do
               end do
            end do
         end do
      end do
      worst_phi = 0.0_wp
      do i1 = 0, 6
         ph = 0.3e9_wp*(4.0_wp/0.3_wp)**(i1/6.0_wp)
         do i2 = 0, 20
            l = merge(0.0_wp, 1.0e-3_wp*1.0e5_wp**((i2 - 1)/19.0_wp), i2 == 0)
            do i3 = 0, 10
               sr = merge(0.0_wp, 1.0e-3_wp*3000.0_wp**((i3 - 1)/9.0_wp), i3 == 0)
               phi = thermal_reduction_factor(ph, EP, l, sr)
               phip = max((1.0_wp - 13.2_wp*(ph/EP)*l**0.42_wp)/(1.0_wp + 0.213_wp*(1.0_wp + 2.23_wp*sr**0.83_wp)* &
                                                                   l**0.64_wp), 0.0_wp)
               ! the factor's scale is 1 (its value at L = 0): differences relative to max(phi, 1e-3)
               worst_phi = max(worst_phi, abs(phi - phip)/max(phip, 1.0e-3_wp))
            end do
         end do
      end do
      write (*, "(a,i0,a,es9.2,a,es9.2)") "film powers by exp(log): film (", n, " points) worst relative ", worst_h, &
         ", thermal factor ", worst_phi
      call check(worst_h < 1.0e-13_wp .and. worst_phi < 1.0e-13_wp, "film: exp(log) powers = pow to round-off")
   end subroutine test_film_powers

   !> MIL-L-7808 is the report's echoed library entry; beta matches a central difference;
   !> an unknown code is an input error.
   subroutine test_lubricant()
      type(error_type), allocatable :: error
      type(lubricant_t) :: lub
      real(wp) :: t, fd, eps
      call lubricant_from_code(LUBRICANT_MIL_L_7808, lub, error)
      call check(.not. allocated(error), "lubricant: MIL-L-7808 accepted")
      call check(abs(dynamic_viscosity(lub, 323.0_wp, 0.0_wp)/8.61565e-3_wp - 1.0_wp) < 1.0e-14_wp, &
                 "lubricant: echoed viscosity at 323 K")
      call check(abs(dynamic_viscosity(lub, 323.0_wp, 1.0e8_wp)/(8.61565e-3_wp*exp(1.07562_wp)) - 1.0_wp) &
                 < 1.0e-13_wp, "lubricant: Barus pressure law")
      call check(kinematic_viscosity(lub, 313.15_wp) > 11.5e-6_wp, "lubricant: 40 C above the grade-3 minimum")
      t = 323.0_wp
      eps = 1.0e-3_wp
      fd = -(log(kinematic_viscosity(lub, t + eps)) - log(kinematic_viscosity(lub, t - eps)))/(2.0_wp*eps)
      call check(abs(temperature_viscosity_coefficient(lub, t)/fd - 1.0_wp) < 1.0e-7_wp, "lubricant: beta = -dln(eta)/dT")
      call lubricant_from_code(99, lub, error)
      call check(allocated(error), "lubricant: unknown code rejected")
      if (allocated(error)) call check(error%stat == ADORE_INPUT_ERROR, "lubricant: unknown code is an input error")
   end subroutine test_lubricant

   !> Pure rolling points are roots; the zone-split Gauss integral equals a fine midpoint
   !> sum; power equals the integral of traction times slip.
   subroutine test_slip()
      type(ball_race_contact_t) :: c
      type(contact_traction_t) :: t
      type(error_type), allocatable :: error
      real(wp) :: coef(4), s, ds, u, f, p, dq, kap, pts(2)
      integer :: n, j, m

      c%side = SIDE_INNER
      c%alpha = 0.48_wp
      c%rho = 0.009525_wp
      c%r_b = 0.07_wp
      c%omega = [-7800.0_wp, 1140.0_wp]
      c%race_speed = 1151.0_wp
      c%a = 1.25e-3_wp
      c%load = 770.0_wp
      coef = [-0.016_wp, 0.0382896_wp, 1.71782_wp, 0.016_wp]
      call pure_rolling_points(c, n, pts)
      do j = 1, n
         call check(abs(contact_slip(c, pts(j))) < 1.0e-9_wp, "slip: rolling point is a root")
      end do
      call contact_traction(c, curve_law(coef), 1.0_wp, 24, t, error)
      call check(.not. allocated(error), "slip: accepted")
      m = 200000
      ds = 2.0_wp*c%a/m
      f = 0.0_wp
      p = 0.0_wp
      do j = 1, m
         s = -c%a + (j - 0.5_wp)*ds
         u = contact_slip(c, s)
         kap = (coef(1) + coef(2)*abs(u))*exp(-coef(3)*abs(u)) + coef(4)
         dq = 0.75_wp*c%load/c%a*(1.0_wp - (s/c%a)**2)*ds
         f = f + sign(kap, u)*dq
         p = p + kap*abs(u)*dq
      end do
      call check(abs(t%force - f) <= 1.0e-6_wp*abs(p/1.0_wp), "slip: traction = fine midpoint sum")
      call check(abs(t%power/p - 1.0_wp) < 1.0e-7_wp, "slip: power = fine midpoint sum")
      call check(n >= 1, "slip: the test contact has a pure-rolling point")
      c%a = 2.0_wp*c%rho
      call contact_traction(c, curve_law(coef), 1.0_wp, 24, t, error)
      call check(allocated(error), "slip: a > rho rejected")
   end subroutine test_slip

   !> Uniform flux: dT~(xi) = 2 q sqrt(xi + 1) exactly (the linear quadrature is exact);
   !> elliptical flux on a circle: contact average positive and below the maximum.
   subroutine test_flash()
      real(wp) :: xi(41), q(41), dt(41), xk(16), wk(16), g(16), avg, mx
      type(error_type), allocatable :: error
      integer :: i
      xi = [(-1.0_wp + 2.0_wp*(i - 1)/40.0_wp, i=1, 41)]
      q = 3.0_wp
      call flash_rise_dimensionless(xi, q, dt)
      call check(maxval(abs(dt - 6.0_wp*sqrt(xi + 1.0_wp))) < 1.0e-12_wp, "flash: uniform flux closed form")
      q = xi
      call flash_rise_dimensionless(xi, q, dt)
      ! integral of xi / sqrt(y - xi) from -1 to y = (2/3) (2 y - 1) sqrt(y + 1)
      call check(maxval(abs(dt - (2.0_wp/3.0_wp)*(2.0_wp*xi - 1.0_wp)*sqrt(xi + 1.0_wp))) < 1.0e-12_wp, &
                 "flash: linear flux closed form")
      call gauss_legendre(16, xk, wk)
      xk = 1.0e-3_wp*xk
      wk = 1.0e-3_wp*wk
      g = 0.01_wp
      call contact_temperature_rise(1.0e-3_wp, 1.0e-3_wp, 1.0e9_wp, xk, wk, g, 10.0_wp, 10.0_wp, &
                                    [7750.0_wp, 470.0_wp, 43.0_wp], [7750.0_wp, 470.0_wp, 43.0_wp], 201, &
                                    avg, mx, error)
      call check(.not. allocated(error), "flash: contact accepted")
      call check(avg > 0.0_wp .and. avg < mx, "flash: 0 < average < maximum")
   end subroutine test_flash

   !> The print node's slip (print_slip_node: cos, sin of alpha + s / rho by angle addition
   !> and the series of s / rho, issue #30) against contact_slip at that node: 20 000
   !> pseudo-random contacts (either race, alpha -40 .. 40 deg, a / rho 0.05 .. 0.6, spins and
   !> race speeds of either sign, with and without the angle's sine and cosine carried):
   !> within 4 eps (|A| + |B| + |C|) of u = A cos(theta) + B sin(theta) + C.
   subroutine test_print_slip_series()
      type(ball_race_contact_t) :: c
      real(wp) :: r(7), s, u, scale, worst
      integer :: i
      integer, allocatable :: seed(:)
      call random_seed(size=i)
      allocate (seed(i))
      seed = 4242
      call random_seed(put=seed)
      worst = 0.0_wp
      do i = 1, 20000
         call random_number(r)
         c%side = merge(SIDE_OUTER, SIDE_INNER, r(1) < 0.5_wp)
         c%alpha = (r(2) - 0.5_wp)*1.4_wp
         c%rho = 0.006_wp
         c%a = c%rho*(0.05_wp + 0.55_wp*r(3))
         c%r_b = 0.05_wp
         c%omega = [2000.0_wp*(r(4) - 0.5_wp), 3000.0_wp*(r(5) - 0.5_wp)]
         c%race_speed = 400.0_wp*(r(6) - 0.5_wp)
         c%load = 100.0_wp
         c%trig_of = huge(1.0_wp)
         if (r(7) < 0.5_wp) then
            c%sin_cos = [sin(c%alpha), cos(c%alpha)]
            c%trig_of = c%alpha
         end if
         call print_slip_node(c, 4, s, u)
         scale = c%rho*(abs(c%omega(1) - c%race_speed) + abs(c%omega(2))) + abs(c%race_speed*c%r_b)
         worst = max(worst, abs(u - contact_slip(c, s))/(epsilon(1.0_wp)*scale))
      end do
      write (*, "(a,f6.2)") "print node slip by the series, against contact_slip (eps x scale):", worst
      call check(worst <= 4.0_wp, "print node slip: angle addition and series = contact_slip to round-off")
   end subroutine test_print_slip_series

   !> The EHD flash's film shear (adore_tribology_ehd_flash, issue #30) in the strip traction's
   !> form amp E shear_shape(zeta |u| E), E = exp(alpha p / 2) (thermal_film_shear), against
   !> film_shear_stress at eta_w exp(alpha p): 3 wall rheologies (eta_w 0.01 .. 0.2 Pa s,
   !> alpha 5e-9 .. 2e-8 1/Pa), films 0.05 .. 2 um, pressures 0 .. 3 GPa, slips 1e-9 .. 200 m/s
   !> of either sign (Appendix C's flash: ~0.08 Pa s, 5.2e-9 1/Pa, <= 2.4 GPa): within 1e-14
   !> relative (a few ulp of the exp, square roots and divisions).
   subroutine test_thermal_film_shear()
      type(ehd_rheology_t) :: rheo
      real(wp), parameter :: ETA(3) = [0.01_wp, 0.0816_wp, 0.2_wp], ALF(3) = [5.0e-9_wp, 5.2214e-9_wp, 2.0e-8_wp]
      real(wp) :: amp, zeta, worst, p, u, h, ref, got
      integer :: ir, ih, ip, iu
      worst = 0.0_wp
      do ir = 1, 3
         rheo = ehd_rheology_t(eta_w=ETA(ir), alpha=ALF(ir), beta=4.25519e-2_wp, conductivity=0.1425185_wp)
         do ih = 0, 4
            h = 5.0e-8_wp*40.0_wp**(ih/4.0_wp)
            call film_constants(rheo, h, amp, zeta)
            do ip = 0, 30
               p = 1.0e8_wp*ip
               do iu = -110, 110
                  if (iu == 0) cycle
                  u = sign(1.0e-9_wp*10.0_wp**(abs(iu)/10.0_wp), real(iu, wp))
                  if (abs(u) > 200.0_wp) cycle
                  ref = film_shear_stress(rheo%eta_w*exp(rheo%alpha*p), rheo%beta, rheo%conductivity, u, h)
                  got = thermal_film_shear(amp, zeta, exp(0.5_wp*rheo%alpha*p), u)
                  worst = max(worst, abs(got - ref)/ref)
               end do
            end do
         end do
      end do
      write (*, "(a,es10.2)") "flash film shear, strip form against film_shear_stress: worst relative", worst
      call check(worst <= 1.0e-14_wp, "flash film shear: amp E shear_shape(zeta |u| E) = film_shear_stress to round-off")
   end subroutine test_thermal_film_shear

end program test_tribology
