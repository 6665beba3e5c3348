!> Unit tests of the fatigue life model (fortran/life): independent truths of
!> eqs 73-109 and the Appendix C ball-bearing case of AFRL-PR-WP-TR-2002-2042.
!>
!> Report numbers below are quoted from the PDF-to-text file
!> /work/shared/seed/000_f0ab926e9a2b5d30.txt ("line NNNN" = its line number).
program test_life
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_life_lundberg_palmgren, only: life_params_t, pass_cycles, point_contact_capacity, &
      contact_life, race_life, bearing_life, life_hours, line_equivalent_load, ball_race_lp_life, &
      life_params_to_array, life_params_from_array, line_contact_lp_life
   use adore_life_roller, only: roller_lives_t, roller_race_lp_life, roller_bearing_lp_life
   use adore_contact_line_slices, only: line_contact_t
   use adore_life_tallian, only: contact_hazard_products, race_psi, tallian_life, &
      ball_race_modified_life, gauss_upper_tail
   implicit none

   integer, parameter :: nb = 18
   real(wp), parameter :: deg = pi/180.0_wp
   ! Appendix C bearing (BEARING GEOMETRY echo, line ~3080; Table 5)
   real(wp), parameter :: d_ball = 1.905e-2_wp, d_pitch = 0.140_wp, f_outer = 0.52_wp, f_inner = 0.54_wp
   real(wp), parameter :: inner_rpm = 2.0e4_wp      ! inner race speed, input deck line 3047 / IRace line 3290

   call test_truths()
   call test_roller_truths()
   call test_appendix_c_step0()
   call test_appendix_c_step2500()

   call finish("life")

contains

   logical function close_to(a, b, rtol)
      real(wp), intent(in) :: a, b, rtol
      close_to = abs(a - b) <= rtol*abs(b)
   end function close_to

   !> Mirror balls 1..10 onto 11..18 (ball k = ball 20-k at step 0, Appendix C symmetry).
   function mirror(h) result(full)
      real(wp), intent(in) :: h(10)
      real(wp) :: full(nb)
      integer :: k
      full(1:10) = h
      do k = 11, nb
         full(k) = h(20 - k)
      end do
   end function mirror

   ! ------------------------------------------------------------------ truths
   subroutine test_truths()
      type(life_params_t) :: p, lp
      real(wp) :: qc, qc8, l, n10, psi, s, s_lp, a(2), b(2), phi(3), phil(3), lives(3)
      real(wp) :: n_hi, n_lo, q(4), dx(4)

      ! eq 73: a contact at its capacity lives 10**6 revolutions
      qc = point_contact_capacity(p, 0.52_wp, 0.4_wp, d_ball, d_pitch, 0.45_wp, .true.)
      call check(close_to(contact_life(qc, qc, p%load_exp_point), 1.0_wp, 1.0e-14_wp), &
                 "N_LP = 1 at Q = Q_c (eq 73)")
      ! eq 74: Q_c ~ n**(-1/3): eight times the cycles halves the capacity
      qc8 = point_contact_capacity(p, 0.52_wp, 0.4_wp, d_ball, d_pitch, 8.0_wp*0.45_wp, .true.)
      call check(close_to(qc8, 0.5_wp*qc, 1.0e-14_wp), "Q_c(8n) = Q_c(n)/2 (eq 74)")
      ! eq 74: outer race (+gamma) has the larger capacity than inner (-gamma) at equal f
      call check(qc > point_contact_capacity(p, 0.52_wp, 0.4_wp, d_ball, d_pitch, 0.45_wp, .false.), &
                 "Q_c outer > Q_c inner at equal conformity (eq 74, 1 +- gamma)")
      ! monotonic in load, cube law
      call check(close_to(contact_life(2.0_wp*qc, qc, 3.0_wp), 0.125_wp, 1.0e-14_wp), "N_LP(2 Q_c) = 1/8")
      call check(contact_life(0.0_wp, qc, 3.0_wp) >= huge(1.0_wp), "unloaded contact never fails")

      ! race and bearing combination of equal lives
      l = 7.0_wp
      call check(close_to(race_life([l, l], .true., 10.0_wp/9.0_wp, .false.), l/2.0_wp, 1.0e-14_wp), &
                 "rotating race: two equal contacts give half the life")
      call check(close_to(race_life([l, l], .false., 10.0_wp/9.0_wp, .false.), l*2.0_wp**(-0.9_wp), 1.0e-14_wp), &
                 "stationary race, report rule: two equal contacts give L 2**(-1/e)")
      ! Lundberg-Palmgren stationary rule: with equal loads the stationary and the
      ! rotating race have the same life (both are the race capacity formula)
      call check(close_to(race_life([l, l, l], .false., 10.0_wp/9.0_wp, .true.), l/3.0_wp, 1.0e-14_wp), &
                 "stationary race, Lundberg-Palmgren rule: equal contacts give L/m like a rotating race")
      call check(close_to(bearing_life(l, l, 10.0_wp/9.0_wp), l*2.0_wp**(-0.9_wp), 1.0e-14_wp), &
                 "eq 102: two equal race lives give L 2**(-1/e)")
      call check(close_to(bearing_life(huge(1.0_wp), l, 10.0_wp/9.0_wp), l, 1.0e-14_wp), &
                 "eq 102: a race that never fails does not shorten the bearing life")
      call check(race_life([huge(1.0_wp), huge(1.0_wp)], .false., 1.0_wp, .false.) >= huge(1.0_wp), &
                 "race with no loaded contact never fails")

      ! unit conversion: 10**6 revolutions at 20 000 rpm = 50 minutes
      call check(close_to(life_hours(1.0_wp, 2.0e4_wp), 50.0_wp/60.0_wp, 1.0e-14_wp), "life_hours")
      ! pure rolling (outer fixed, cage at (1-gamma)/2): passes sum to 1 per revolution
      call check(close_to(pass_cycles(0.43_wp, 0.0_wp, 1.0_wp, 0.0_wp) + pass_cycles(0.43_wp, 1.0_wp, 1.0_wp, 0.0_wp), &
                          1.0_wp, 1.0e-14_wp), "pass_cycles: outer + inner passes = 1")
      ! eq 75: uniform intensity q over 2a gives Q_e = 2a q
      q = 3.0e5_wp
      dx = 1.0e-3_wp
      call check(close_to(line_equivalent_load(q, dx, 4.0_wp, 9.0_wp/8.0_wp), 1.2e3_wp, 1.0e-13_wp), &
                 "eq 75 uniform load")

      ! eq 77 limit: Psi = 1, tau_0 = 0  ->  N_10 = 12 A M**(-1/beta) N_LP
      n10 = tallian_life(p, 5.0_wp, 1.0_wp)
      call check(close_to(n10, 12.0_wp*0.23_wp*1.197_wp**(-1.0_wp/1.6_wp)*5.0_wp, 1.0e-13_wp), &
                 "eq 77: Psi = 1, tau0 = 0 gives 12 A M**(-1/beta) N_LP")
      ! eq 77: a fatigue limit lengthens life
      lp = p
      lp%tau0 = 1.0e8_wp
      call check(tallian_life(lp, 5.0_wp, 0.1_wp) > tallian_life(p, 5.0_wp, 0.1_wp), "tau0 > 0 lengthens life")
      ! Lundberg-Palmgren limit of the factors: no asperity/furrow terms, I = 1, s_stat = 0
      lp = p
      lp%phi1_asperity = 0.0_wp
      lp%phi1_furrow = 0.0_wp
      lp%processing_i = 1.0_wp
      call contact_hazard_products(lp, 1.5e9_wp, 3.0_wp, 0.01_wp, 0.0_wp, s, s_lp)
      call check(close_to(s, s_lp, 1.0e-14_wp), "LP limit: Phi_T = Phi_TLP (eqs 105, 109)")
      call check(close_to(s_lp, 1.60e-5_wp, 1.0e-2_wp), "Phi_3bLP = 0.39**(beta zeta) = 1.60e-5 (text after eq 100)")
      ! Psi is a weighted mean of the contact ratios: equal ratios give that ratio
      lives = [2.0_wp, 3.0_wp, 5.0_wp]
      phi = 0.3_wp*s_lp
      phil = s_lp
      psi = race_psi(p, lives, phi, phil, .true.)
      call check(close_to(psi, 0.3_wp, 1.0e-14_wp), "Psi of equal ratios, rotating race (eqs 104/107)")
      psi = race_psi(p, lives, phi, phil, .false.)
      call check(close_to(psi, 0.3_wp, 1.0e-14_wp), "Psi of equal ratios, stationary race (eqs 106/108)")
      ! monotonicity of the factors: tensile hoop stress and thin films shorten life
      call contact_hazard_products(p, 1.5e9_wp, 3.0_wp, 0.01_wp, 0.0_wp, a(1), b(1))
      call contact_hazard_products(p, 1.5e9_wp, 3.0_wp, 0.01_wp, 1.0e8_wp, a(2), b(2))
      call check(a(2) > a(1), "tensile hoop stress raises the hazard (eqs 91-95)")
      call contact_hazard_products(p, 1.5e9_wp, 0.8_wp, 0.01_wp, 0.0_wp, a(2), b(2))
      call check(a(2) > a(1), "a thinner film raises the hazard (eqs 83, 98, 99)")
      n_hi = tallian_life(p, 5.0_wp, a(1)/b(1))
      n_lo = tallian_life(p, 5.0_wp, a(2)/b(2))
      call check(n_lo < n_hi, "modified life falls with the hazard ratio")
      call check(close_to(gauss_upper_tail(0.0_wp), 0.5_wp, 1.0e-15_wp), "1 - G(0) = 1/2")
      ! flat constants round trip (f2py wrapper)
      call check(all(life_params_to_array(life_params_from_array(life_params_to_array(lp))) &
                     == life_params_to_array(lp)), "constants array round trip")
      call check(close_to(p%e_prime, 2.0e11_wp/(2.0_wp*0.9375_wp), 1.0e-14_wp), "default E' steel/steel")
   end subroutine test_truths

   ! ------------------------------------------------------------ roller truths

   !> A straight roller with uniform load per unit length q over its contact length,
   !> on n slices of the given widths (in_contact, x at slice centres).
   function uniform_contact(q, widths) result(c)
      real(wp), intent(in) :: q, widths(:)
      type(line_contact_t) :: c
      integer :: j
      c%in_contact = q > 0.0_wp
      c%weight = widths
      c%q = [(q, j = 1, size(widths))]
      c%x = [(sum(widths(1:j)) - 0.5_wp*widths(j) - 0.5_wp*sum(widths), j = 1, size(widths))]
      c%load = q*sum(widths)
      c%half_length = 0.5_wp*sum(widths)
   end function uniform_contact

   !> Line-contact life (eqs 73, 75, 76) and the roller race/bearing sums against
   !> hand evaluations; Lundberg-Palmgren lamina consistency; Harris's line-contact
   !> race capacity.
   subroutine test_roller_truths()
      real(wp), parameter :: d = 8.0e-3_wp, dm = 4.3e-2_wp, g = d/dm, e = 9.0_wp/8.0_wp
      real(wp), parameter :: widths(7) = [0.3e-3_wp, 0.9e-3_wp, 1.1e-3_wp, 0.7e-3_wp, 1.4e-3_wp, 0.8e-3_wp, 0.8e-3_wp]
      type(life_params_t) :: p, lp
      type(line_contact_t) :: c(4), ci(4), cu(3)
      type(roller_lives_t) :: rl
      real(wp) :: q0, l, n, qc, n_hand, qx(12), dx(12), n_all, n_a, n_b, lives(4), nr, ho, hi, qcr, harris
      real(wp) :: om(4), passes
      integer :: j, k

      ! uniformly loaded straight roller: eq 75 is the plain load, eq 73/76 by hand
      q0 = 1.25e5_wp
      l = sum(widths)
      passes = 0.4_wp
      call check(close_to(line_equivalent_load([(q0, j = 1, 7)], widths, 4.0_wp, e), q0*l, 1.0e-13_wp), &
                 "eq 75: uniform q on unequal slices gives Q_e = q l")
      n = line_contact_lp_life(p, [(q0, j = 1, 7)], widths, 0.0_wp, d, dm, passes, .true.)
      qc = 1.6655e8_wp*(1.0_wp + g)**(29.0_wp/27.0_wp)*g**(2.0_wp/9.0_wp)*d**(29.0_wp/27.0_wp) &
           *(p%line_length_factor*l)**(7.0_wp/9.0_wp)*(2.0_wp*passes)**(-0.25_wp)
      n_hand = (q0*l/qc)**(-4)
      call check(close_to(n, n_hand, 1.0e-12_wp), "uniform roller, outer race: N = (Q/Q_c)**-4, eq 76 by hand")
      n = line_contact_lp_life(p, [(q0, j = 1, 7)], widths, 0.0_wp, d, dm, passes, .false.)
      call check(close_to(n, n_hand*((1.0_wp - g)/(1.0_wp + g))**(4.0_wp*29.0_wp/27.0_wp), 1.0e-12_wp), &
                 "uniform roller, inner race: (1 - gamma)**(29/27) in eq 76")
      call check(line_contact_lp_life(p, [(0.0_wp, j = 1, 7)], widths, 0.0_wp, d, dm, passes, .true.) &
                 >= huge(1.0_wp), "unloaded line contact never fails")

      ! Lundberg-Palmgren lamina consistency (p e = 4.5, l**(7/9)): the contact cut in two
      ! parts, each part a contact of its own, gives N**-e = N_a**-e + N_b**-e
      qx = [(1.0e5_wp*(1.0_wp + 0.3_wp*sin(real(j, wp))), j = 1, 12)]
      dx = [(1.0e-4_wp*(1.0_wp + 0.5_wp*cos(real(j, wp))), j = 1, 12)]
      n_all = line_contact_lp_life(p, qx, dx, 0.0_wp, d, dm, passes, .true.)
      n_a = line_contact_lp_life(p, qx(1:5), dx(1:5), 0.0_wp, d, dm, passes, .true.)
      n_b = line_contact_lp_life(p, qx(6:12), dx(6:12), 0.0_wp, d, dm, passes, .true.)
      call check(close_to(n_all, (n_a**(-e) + n_b**(-e))**(-1.0_wp/e), 1.0e-12_wp), &
                 "eqs 75-76: a line contact is the Weibull sum of its laminae")

      ! race sums by hand: three loaded rollers and one out of contact
      do k = 1, 3
         c(k) = uniform_contact(q0*(1.0_wp + 0.2_wp*k), widths)
      end do
      c(4) = uniform_contact(0.0_wp, widths)
      do k = 1, 4
         lives(k) = huge(1.0_wp)
         if (k < 4) lives(k) = line_contact_lp_life(p, c(k)%q, c(k)%weight, 0.0_wp, d, dm, passes, .true.)
      end do
      call roller_race_lp_life(p, c, [(passes, k = 1, 4)], d, dm, .true., .true., lives, nr)
      call check(close_to(nr, 1.0_wp/sum(1.0_wp/lives(1:3)), 1.0e-13_wp), "roller race, rotating: 1/N = sum 1/N_k")
      call roller_race_lp_life(p, c, [(passes, k = 1, 4)], d, dm, .true., .false., lives, nr)
      call check(close_to(nr, sum(lives(1:3)**(-e))**(-1.0_wp/e), 1.0e-13_wp), &
                 "roller race, stationary (report rule): N**-e = sum N_k**-e, e = 9/8")
      lp = p
      lp%stationary_rule = 1.0_wp
      call roller_race_lp_life(lp, c, [(passes, k = 1, 4)], d, dm, .true., .false., lives, nr)
      call check(close_to(nr, (4.0_wp**(e - 1.0_wp)*sum(lives(1:3)**(-e)))**(-1.0_wp/e), 1.0e-13_wp), &
                 "roller race, stationary (Lundberg-Palmgren): N**-e = m**(e-1) sum N_k**-e, m = 4")

      ! bearing: outer fixed, inner at 7e4 rpm (speeds in rad/s), orbit by pure rolling;
      ! eq 102 and hours by hand
      om = 0.5_wp*(1.0_wp - g)*7.0e4_wp*pi/30.0_wp
      do k = 1, 4
         ci(k) = uniform_contact(0.8_wp*q0*(1.0_wp + 0.1_wp*k), widths)
      end do
      call roller_bearing_lp_life(p, c, ci, om, 0.0_wp, 7.0e4_wp*pi/30.0_wp, d, dm, rl)
      ho = sum([(line_contact_lp_life(p, c(k)%q, c(k)%weight, 0.0_wp, d, dm, 0.5_wp*(1.0_wp - g), .true.), &
                 k = 1, 3)]**(-e))**(-1.0_wp/e)
      hi = 1.0_wp/sum([(1.0_wp/line_contact_lp_life(p, ci(k)%q, ci(k)%weight, 0.0_wp, d, dm, &
                                                    0.5_wp*(1.0_wp + g), .false.), k = 1, 4)])
      call check(close_to(rl%outer_mrev, ho, 1.0e-12_wp), "roller bearing: outer race stationary sum")
      call check(close_to(rl%inner_mrev, hi, 1.0e-12_wp), "roller bearing: inner race rotating sum")
      call check(close_to(rl%bearing_mrev, (ho**(-e) + hi**(-e))**(-1.0_wp/e), 1.0e-12_wp), &
                 "roller bearing: eq 102 with e = 9/8")
      call check(close_to(rl%bearing_hours, rl%bearing_mrev*1.0e6_wp/(60.0_wp*7.0e4_wp), 1.0e-12_wp), &
                 "roller bearing: hours at the relative race speed")

      ! Harris (Rolling Bearing Analysis, Lundberg-Palmgren line contact): Z equal uniformly
      ! loaded rollers in pure rolling with B = 552 N/mm**(50/27), n = 2 x passes, the
      ! Lundberg-Palmgren stationary sum and l = contact length give the race capacity
      !   outer: 552 (1+g)**(29/27) (1-g)**(-1/4) g**(2/9) D**(29/27) l**(7/9) Z**(-1/4)  (N, mm)
      lp = p
      lp%b_line = 552.0_wp*1.0e3_wp**(50.0_wp/27.0_wp)
      lp%cycle_factor = 2.0_wp
      lp%line_length_factor = 1.0_wp
      lp%stationary_rule = 1.0_wp
      do k = 1, 3
         cu(k) = uniform_contact(q0, widths)
      end do
      call roller_race_lp_life(lp, cu, [(0.5_wp*(1.0_wp - g), k = 1, 3)], d, dm, .true., .false., lives(1:3), nr)
      qcr = q0*l*nr**0.25_wp
      harris = 552.0_wp*(1.0_wp + g)**(29.0_wp/27.0_wp)*(1.0_wp - g)**(-0.25_wp)*g**(2.0_wp/9.0_wp) &
               *(d*1.0e3_wp)**(29.0_wp/27.0_wp)*(l*1.0e3_wp)**(7.0_wp/9.0_wp)*3.0_wp**(-0.25_wp)
      call check(close_to(qcr, harris, 1.0e-12_wp), "outer race capacity = Harris/Lundberg-Palmgren line contact")
      call roller_race_lp_life(lp, cu, [(0.5_wp*(1.0_wp + g), k = 1, 3)], d, dm, .false., .true., lives(1:3), nr)
      qcr = q0*l*nr**0.25_wp
      harris = 552.0_wp*(1.0_wp - g)**(29.0_wp/27.0_wp)*(1.0_wp + g)**(-0.25_wp)*g**(2.0_wp/9.0_wp) &
               *(d*1.0e3_wp)**(29.0_wp/27.0_wp)*(l*1.0e3_wp)**(7.0_wp/9.0_wp)*3.0_wp**(-0.25_wp)
      call check(close_to(qcr, harris, 1.0e-12_wp), "inner race capacity = Harris/Lundberg-Palmgren line contact")
   end subroutine test_roller_truths

   ! ------------------------------------------------------------- step 0
   subroutine test_appendix_c_step0()
      type(life_params_t) :: p
      real(wp) :: ao(nb), ai(nb), qo(nb), qi(nb), po(nb), pi_(nb), wo(nb)
      real(wp) :: lam_o(nb), lam_i(nb), mu_o(nb), mu_i(nb), rest_ax, rest_rad
      real(wp) :: lives_o(nb), lives_i(nb), n_o, n_i, n_b, psi_o, psi_in, m_o, m_i, m_b
      real(wp) :: q1, a1, q5
      integer :: k

      ! Section 1 at step 0, lines 3166-3182 (balls 1..10; 11..18 mirror, line 3183 garbled).
      ! Contact angle outer / inner (deg).  Ball 1 inner lost (line 3166): reconstructed below.
      ao = mirror([8.472_wp, 8.334_wp, 7.936_wp, 7.327_wp, 6.591_wp, 5.816_wp, 5.101_wp, 4.505_wp, 4.139_wp, 4.014_wp])
      ai = mirror([0.0_wp, 27.53_wp, 27.78_wp, 28.16_wp, 28.62_wp, 29.11_wp, 29.56_wp, 29.93_wp, 30.16_wp, 30.24_wp])
      ! Contact load outer / inner (N).  Ball 5 inner angle from row 15 (line 3179); ball 9
      ! outer load from row 11 (line 3175); balls 8/9 from the merged line 3173.
      ! Ball 5 outer load lost in rows 5 and 15: reconstructed below.
      qo = mirror([2474.0_wp, 2457.0_wp, 2411.0_wp, 2348.0_wp, 0.0_wp, 2218.0_wp, 2170.0_wp, 2153.0_wp, 2133.0_wp, 2127.0_wp])
      qi = mirror([0.0_wp, 770.4_wp, 714.2_wp, 634.5_wp, 546.0_wp, 462.1_wp, 391.2_wp, 338.9_wp, 306.4_wp, 295.5_wp])
      ! Ball 5 outer load from the printed contact deflections (lines 3234-3236) and the
      ! Hertz law Q ~ delta**1.5, geometric mean of the estimates from balls 4 and 6.
      q5 = sqrt(2348.0_wp*(1.510_wp/1.540_wp)**1.5_wp*2218.0_wp*(1.510_wp/1.483_wp)**1.5_wp)
      qo(5) = q5
      qo(15) = q5
      ! Ball 1 inner load and angle from inner race equilibrium: Int IRace force
      ! (line 3306) axial 4.495e3 N, radial 1.995e3 N, balls at 20 deg spacing (col 2).
      rest_ax = 0.0_wp
      rest_rad = 0.0_wp
      do k = 2, nb
         rest_ax = rest_ax + qi(k)*sin(ai(k)*deg)
         rest_rad = rest_rad + qi(k)*cos(ai(k)*deg)*cos(20.0_wp*(k - 1)*deg)
      end do
      q1 = hypot(4495.0_wp - rest_ax, 1995.0_wp - rest_rad)
      a1 = atan2(4495.0_wp - rest_ax, 1995.0_wp - rest_rad)/deg
      qi(1) = q1
      ai(1) = a1
      ! cross-check of the reconstruction against the inner deflections (lines 3231-3232)
      call check(close_to(q1, 770.4_wp*(8.916_wp/8.762_wp)**1.5_wp, 3.0e-3_wp), &
                 "ball 1 inner load: equilibrium and Hertz deflection agree")
      ! Orbital velocity (rpm), lines 3188-3197 (ball k = ball 20-k)
      wo = mirror([8.999e3_wp, 9.006e3_wp, 9.028e3_wp, 9.061e3_wp, 9.100e3_wp, 9.147e3_wp, 9.194e3_wp, &
                   9.272e3_wp, 9.297e3_wp, 9.306e3_wp])

      call ball_race_lp_life(p, qo, ao*deg, pass_cycles(wo, 0.0_wp, inner_rpm, 0.0_wp), f_outer, d_ball, d_pitch, &
                             .true., .false., lives_o, n_o)
      call ball_race_lp_life(p, qi, ai*deg, pass_cycles(wo, inner_rpm, inner_rpm, 0.0_wp), f_inner, d_ball, d_pitch, &
                             .false., .true., lives_i, n_i)
      n_b = bearing_life(n_o, n_i, p%weibull_e_point)
      write (*, "(a,3f10.1)") "step 0 basic life (h) outer, inner, bearing:", &
         life_hours(n_o, inner_rpm), life_hours(n_i, inner_rpm), life_hours(n_b, inner_rpm)
      ! Report: "Basic Fatigue Life (hours) 5.334E+02", line 3298
      call check(close_to(life_hours(n_b, inner_rpm), 533.4_wp, 0.03_wp), &
                 "step 0 basic life within 3 % of 533.4 h (line 3298)")

      ! Max Hertz pressure (Pa), lines 3166-3182.  Lost: outer balls 1 and 5, inner ball 1;
      ! scaled from the neighbour by Hertz p ~ Q**(1/3).
      po = mirror([0.0_wp, 1.577e9_wp, 1.568e9_wp, 1.554e9_wp, 0.0_wp, 1.524e9_wp, 1.513e9_wp, 1.509e9_wp, &
                   1.504e9_wp, 1.503e9_wp])
      pi_ = mirror([0.0_wp, 1.386e9_wp, 1.352e9_wp, 1.299e9_wp, 1.235e9_wp, 1.168e9_wp, 1.105e9_wp, 1.053e9_wp, &
                    1.018e9_wp, 1.006e9_wp])
      po(1) = 1.577e9_wp*(qo(1)/2457.0_wp)**(1.0_wp/3.0_wp)
      po(5) = 1.554e9_wp*(q5/2348.0_wp)**(1.0_wp/3.0_wp)
      po(15) = po(5)
      pi_(1) = 1.386e9_wp*(qi(1)/770.4_wp)**(1.0_wp/3.0_wp)
      ! Film: Iso Lub Film (m) times Thermal Red Fac, lines 3211-3218, over the composite
      ! RMS height 1.0e-7 m (FATIGUE PARAMETERS echo, line 3126).
      lam_o = mirror([1.293e-6_wp, 1.294e-6_wp, 1.298e-6_wp, 1.304e-6_wp, 1.311e-6_wp, 1.318e-6_wp, 1.325e-6_wp, &
                      1.333e-6_wp, 1.336e-6_wp, 1.337e-6_wp] &
                     *[0.3559_wp, 0.3559_wp, 0.3559_wp, 0.3557_wp, 0.3543_wp, 0.3535_wp, 0.3524_wp, 0.3502_wp, &
                       0.3497_wp, 0.3495_wp])/p%sigma_rms
      lam_i = mirror([1.188e-6_wp, 1.190e-6_wp, 1.194e-6_wp, 1.202e-6_wp, 1.212e-6_wp, 1.223e-6_wp, 1.234e-6_wp, &
                      1.241e-6_wp, 1.248e-6_wp, 1.250e-6_wp] &
                     *[0.3908_wp, 0.3919_wp, 0.3951_wp, 0.4000_wp, 0.4057_wp, 0.4121_wp, 0.4182_wp, 0.4244_wp, &
                       0.4277_wp, 0.4289_wp])/p%sigma_rms
      ! Trac Coeff (EHD traction coefficient), lines 3211-3218
      mu_o = mirror([7.673e-3_wp, 7.608e-3_wp, 7.433e-3_wp, 7.191e-3_wp, 6.412e-3_wp, 6.096e-3_wp, 5.834e-3_wp, &
                     5.672e-3_wp, 5.611e-3_wp, 5.591e-3_wp])
      mu_i = mirror([1.267e-2_wp, 1.253e-2_wp, 1.214e-2_wp, 1.156e-2_wp, 1.087e-2_wp, 1.016e-2_wp, 9.503e-3_wp, &
                     9.171e-3_wp, 8.796e-3_wp, 8.665e-3_wp])
      ! Hoop stress (Pa), section 2 Stress column: ORace -6.402e6 (line 3289), IRace 1.184e8 (line 3290)
      call ball_race_modified_life(p, lives_o, n_o, po, lam_o, mu_o, -6.402e6_wp, .false., psi_o, m_o)
      call ball_race_modified_life(p, lives_i, n_i, pi_, lam_i, mu_i, 1.184e8_wp, .true., psi_in, m_i)
      m_b = bearing_life(m_o, m_i, p%weibull_e_point)
      write (*, "(a,3f10.1,a,2f8.4)") "step 0 modified life (h) outer, inner, bearing:", &
         life_hours(m_o, inner_rpm), life_hours(m_i, inner_rpm), life_hours(m_b, inner_rpm), &
         "   Psi outer, inner:", psi_o, psi_in
      ! Report: "Modified Fatigue Life (hours) 4.460E+03", line 3299.  Not checked here:
      ! the equations as printed give about 5564 h (+25 %, docs/life-model.md); the
      ! comparison is the strict xfail in tests/test_life.py.  Here only sanity:
      call check(m_b > n_b .and. m_b < huge(1.0_wp), "step 0 modified life is finite and exceeds the basic life")
   end subroutine test_appendix_c_step0

   ! ---------------------------------------------------------- step 2500
   subroutine test_appendix_c_step2500()
      type(life_params_t) :: p
      real(wp) :: ao(nb), ai(nb), qo(nb), qi(nb), wo(nb), lives_o(nb), lives_i(nb), n_o, n_i, n_b
      real(wp) :: w_known(11)

      ! Section 1 at step 2500, lines 3337-3354 (all 18 rows legible)
      ao = [7.675_wp, 7.241_wp, 6.708_wp, 6.127_wp, 5.592_wp, 5.120_wp, 4.830_wp, 4.596_wp, 4.854_wp, &
            4.743_wp, 5.091_wp, 5.555_wp, 6.114_wp, 6.703_wp, 7.264_wp, 7.639_wp, 7.914_wp, 8.352_wp]
      ai = [27.82_wp, 28.09_wp, 28.43_wp, 28.81_wp, 29.16_wp, 29.47_wp, 29.67_wp, 29.82_wp, 29.69_wp, &
            29.73_wp, 29.50_wp, 29.20_wp, 28.83_wp, 28.45_wp, 28.09_wp, 27.85_wp, 27.68_wp, 27.44_wp]
      qo = [2416.0_wp, 2359.0_wp, 2293.0_wp, 2229.0_wp, 2172.0_wp, 2137.0_wp, 2113.0_wp, 2084.0_wp, 2108.0_wp, &
            2104.0_wp, 2139.0_wp, 2185.0_wp, 2245.0_wp, 2311.0_wp, 2360.0_wp, 2415.0_wp, 2454.0_wp, 2506.0_wp]
      qi = [691.4_wp, 631.6_wp, 562.6_wp, 493.7_wp, 434.4_wp, 387.6_wp, 359.4_wp, 335.8_wp, 360.1_wp, &
            350.8_wp, 385.5_wp, 433.6_wp, 495.7_wp, 566.1_wp, 633.6_wp, 687.1_wp, 727.6_wp, 790.0_wp]
      ! Orbital velocity (rpm) legible for balls 1-11 (lines 3362-3372); lost for 12-18
      ! (lines 3373-3374): the mean of the legible ones is used there.
      w_known = [9.094e3_wp, 9.096e3_wp, 9.094e3_wp, 9.096e3_wp, 9.092e3_wp, 9.115e3_wp, 9.121e3_wp, &
                 9.104e3_wp, 9.107e3_wp, 9.118e3_wp, 9.127e3_wp]
      wo(1:11) = w_known
      wo(12:) = sum(w_known)/11.0_wp
      ! inner race 28.71 rev in 8.612e-2 s (line 3421) = 2.0e4 rpm
      call ball_race_lp_life(p, qo, ao*deg, pass_cycles(wo, 0.0_wp, inner_rpm, 0.0_wp), f_outer, d_ball, d_pitch, &
                             .true., .false., lives_o, n_o)
      call ball_race_lp_life(p, qi, ai*deg, pass_cycles(wo, inner_rpm, inner_rpm, 0.0_wp), f_inner, d_ball, d_pitch, &
                             .false., .true., lives_i, n_i)
      n_b = bearing_life(n_o, n_i, p%weibull_e_point)
      write (*, "(a,3f10.1)") "step 2500 basic life (h) outer, inner, bearing:", &
         life_hours(n_o, inner_rpm), life_hours(n_i, inner_rpm), life_hours(n_b, inner_rpm)
      ! Report: "Basic Fatigue Life (hours) 5.515E+02", line 3465
      call check(close_to(life_hours(n_b, inner_rpm), 551.5_wp, 0.03_wp), &
                 "step 2500 basic life within 3 % of 551.5 h (line 3465)")
   end subroutine test_appendix_c_step2500

end program test_life
