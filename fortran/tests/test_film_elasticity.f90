!> Unit tests of the EHD film's elasticity (run option film_shear_modulus;
!> adore_tribology_ehd_elastic, docs/tribology.md "The film's elasticity"): the Maxwell
!> strip against closed forms and an independent ODE solution.  The viscous limit
!> (De -> 0) is today's film, bit for bit where Lambda is negligible and converging as De
!> where it is not; the elastic limit (De -> infinity) is tau = G (u / U) (x + b') / h,
!> i.e. the strip traction 2 b'**2 G |u| / (U h); with a uniform viscosity the strip
!> traction is the closed form eta u / h (2 b' - lambda (1 - exp(-2 b' / lambda))) at every
!> De (the slope at zero slip); with the Hertz pressure's exp(alpha p) the ratio against a
!> fine RK4 solution of (U / G) dtau/dx = u / h - tau / eta(x), and its convergence in the
!> intervals; the fast quadrature against the reference with the option on.  No files.
program test_film_elasticity
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_kinematics, SIDE_OUTER
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_contact_traction_fast, &
                                           ehd_strip_traction
   use adore_tribology_ehd_elastic, only: elastic_strip_ratio, ELASTIC_INTERVALS
   use adore_test_support, only: check, finish
   implicit none

   type(ball_race_contact_t) :: c
   type(ehd_rheology_t) :: rheo
   real(wp), parameter :: H = 4.55e-7_wp, B = 3.15e-4_wp
   real(wp) :: u_e

   ! Appendix C ball 1, outer race contact at its step-0 state (as test_tribology)
   c = ball_race_contact_t(SIDE_OUTER, atan2(0.14701482232434315_wp, 0.9891342891725783_wp), 0.009525_wp, &
                           0.07004480819399529_wp, -7894.364961447181_wp*[cos(-0.13801441540302414_wp), &
                           sin(-0.13801441540302414_wp)], -943.0_wp, 0.0023737604859883953_wp, 2479.297919485147_wp)
   rheo = ehd_rheology_t(eta_w=0.0815882_wp, alpha=5.2214e-9_wp, beta=0.0425519_wp, conductivity=0.1425185_wp)
   u_e = entraining_speed(c)
   call test_viscous_limit()
   call test_elastic_limit()
   call test_uniform_viscosity()
   call test_against_ode()
   call test_fast_against_reference()
   call finish("film elasticity")

contains

   real(wp) function entraining_speed(cc)
      type(ball_race_contact_t), intent(in) :: cc
      type(contact_traction_t) :: t
      call contact_kinematics(cc, t)
      entraining_speed = abs(t%rolling_speed)
   end function entraining_speed

   !> De -> 0: G = 1e30 Pa leaves the traction bit for bit the viscous film's (G = 0, the
   !> option off), reference and fast; G = 1e13 .. 1e11 Pa (Lambda at the centre strip
   !> ~1e-4 .. 1e-2) moves the force by an amount that falls with De.
   subroutine test_viscous_limit()
      type(contact_traction_t) :: t0, t1, f0, f1
      type(error_type), allocatable :: error
      type(ehd_rheology_t) :: r
      real(wp) :: d(3)
      integer :: k

      call ehd_contact_traction(c, rheo, H, B, 16, 24, t0, error)
      call ehd_contact_traction_fast(c, rheo, H, B, f0, error)
      r = rheo
      r%shear_modulus = 1.0e30_wp
      call ehd_contact_traction(c, r, H, B, 16, 24, t1, error)
      call ehd_contact_traction_fast(c, r, H, B, f1, error)
      call check(t1%force == t0%force .and. t1%power == t0%power .and. t1%force_sin == t0%force_sin, &
                 "elastic film: G = 1e30 Pa is the viscous film bit for bit (reference)")
      call check(f1%force == f0%force .and. f1%power == f0%power .and. f1%force_cos == f0%force_cos, &
                 "elastic film: G = 1e30 Pa is the viscous film bit for bit (fast)")
      do k = 1, 3
         r%shear_modulus = 10.0_wp**(14 - k)
         call ehd_contact_traction_fast(c, r, H, B, f1, error)
         d(k) = abs(f1%power/f0%power - 1.0_wp)
      end do
      write (*, "(a,3es10.2)") "elastic film, power change at G = 1e13, 1e12, 1e11 Pa:", d
      call check(d(1) < d(2) .and. d(2) < d(3) .and. d(1) < 1.0e-4_wp, "elastic film: tends to the viscous film as De -> 0")
   end subroutine test_viscous_limit

   !> De -> infinity (G = 1e-3 Pa): the strip traction is the elastic film's 2 b'**2 G |u| /
   !> (U h) at the centre strip and at s = 0.6 a (b' = 0.8 b), thermal and isothermal.
   subroutine test_elastic_limit()
      type(ehd_rheology_t) :: r
      real(wp) :: f, q, bp, s, u, want, bound
      integer :: k, iso
      logical :: ok

      ! the ratio's denominator, the viscous strip integral on the intervals, is that of
      ! Lambda (sin psi_hi - sin psi_lo) = Lambda cos(psi_mid) h (1 - h**2 / 24 + ...): h**2 / 24 low
      bound = 1.01_wp*(pi/ELASTIC_INTERVALS)**2/24.0_wp
      ok = .true.
      do iso = 0, 1
         r = rheo
         if (iso == 1) r%beta = 0.0_wp
         r%shear_modulus = 1.0e-3_wp
         do k = 0, 1
            s = 0.6_wp*k*c%a
            bp = B*sqrt(1.0_wp - (s/c%a)**2)
            u = 0.37_wp
            call ehd_strip_traction(c, r, H, B, 24, s, u, f, q)
            want = 2.0_wp*bp*bp*r%shear_modulus*u/(u_e*H)
            write (*, "(a,2i2,es10.2)") "elastic film, elastic limit (isothermal, strip): error ", iso, k, f/want - 1.0_wp
            ok = ok .and. abs(f/want - 1.0_wp) < bound
         end do
      end do
      call check(ok, "elastic film: De -> infinity is tau = G (u / U) (x + b') / h across the strip")
   end subroutine test_elastic_limit

   !> A uniform viscosity (alpha = 0, isothermal): the Maxwell strip is linear in u at every
   !> De, f = eta u / h (2 b' - lambda (1 - exp(-2 b' / lambda))), lambda = U eta / G (the
   !> slope at zero slip of Johnson & Tevaarwerk's linear film); lambda / 2b' from 1e-3 to 1e3.
   subroutine test_uniform_viscosity()
      type(ehd_rheology_t) :: r
      real(wp) :: f, q, lam, de, want, worst
      integer :: k

      r = ehd_rheology_t(eta_w=0.35_wp, alpha=0.0_wp, beta=0.0_wp, conductivity=0.14_wp)
      worst = 0.0_wp
      do k = -3, 3
         de = 10.0_wp**k
         lam = de*2.0_wp*B
         r%shear_modulus = u_e*r%eta_w/lam
         call ehd_strip_traction(c, r, H, B, 24, 0.0_wp, 2.0e-3_wp, f, q)
         want = r%eta_w*2.0e-3_wp/H*2.0_wp*B*lag(1.0_wp/de)
         worst = max(worst, abs(f/want - 1.0_wp))
      end do
      write (*, "(a,es10.2)") "elastic film, uniform viscosity against the closed form:", worst
      call check(worst < 1.0e-12_wp, "elastic film: uniform viscosity is the linear Maxwell film's closed form")
   end subroutine test_uniform_viscosity

   !> 1 - (1 - exp(-x)) / x, by its series below x = 0.1 (no cancellation)
   real(wp) function lag(x)
      real(wp), intent(in) :: x
      real(wp) :: tk
      integer :: k
      if (x >= 0.1_wp) then
         lag = 1.0_wp - (1.0_wp - exp(-x))/x
         return
      end if
      ! sum over k >= 1 of -(-x)**k / (k + 1)!
      lag = 0.0_wp
      tk = 1.0_wp
      do k = 1, 14
         tk = -tk*x/real(k + 1, wp)
         lag = lag - tk
      end do
   end function lag

   !> The ratio with the Hertz pressure (isothermal, Lambda(x) = lam0 exp(2 A sqrt(1 - x**2)))
   !> against the RK4 solution of dT/dx = 1 - T / Lambda(x), T(-1) = 0, on 1e6 steps (its
   !> integral over the integral of Lambda): within 2.5e-3 at ELASTIC_INTERVALS (second order), and the
   !> error falls with the intervals (x 8: at least x 10 smaller).
   subroutine test_against_ode()
      real(wp), parameter :: CASES(2, 5) = reshape([2.0_wp, 1.0e-1_wp, 3.0_wp, 1.0e-2_wp, 6.0_wp, 1.0e-3_wp, &
                                                    10.0_wp, 1.0e-5_wp, 11.5_wp, 1.0e-6_wp], [2, 5])
      real(wp) :: worst, worst_fine, r_ode, e1, e8
      integer :: k

      worst = 0.0_wp
      worst_fine = 0.0_wp
      do k = 1, size(CASES, 2)
         r_ode = ode_ratio(CASES(1, k), CASES(2, k))
         e1 = abs(elastic_strip_ratio(CASES(1, k), 0.0_wp, .false., CASES(2, k))/r_ode - 1.0_wp)
         e8 = abs(elastic_strip_ratio(CASES(1, k), 0.0_wp, .false., CASES(2, k), 8*ELASTIC_INTERVALS)/r_ode - 1.0_wp)
         write (*, "(a,f5.1,es9.1,a,f8.5,a,2es10.2)") "elastic film, A, lam0 ", CASES(:, k), ": ratio ", r_ode, &
            ", error at 1x, 8x intervals", e1, e8
         worst = max(worst, e1)
         worst_fine = max(worst_fine, e8)
      end do
      call check(worst < 2.5e-3_wp, "elastic film: the strip's ratio within 2.5e-3 of the ODE's (Hertz pressure)")
      call check(worst_fine < 0.1_wp*worst, "elastic film: the ratio converges with the intervals")
   end subroutine test_against_ode

   !> The ODE's ratio by RK4 on n steps in x (module header of adore_tribology_ehd_elastic).
   real(wp) function ode_ratio(a, lam0) result(r)
      real(wp), intent(in) :: a, lam0
      integer, parameter :: N = 1000000
      real(wp) :: dx, x, t, k1, k2, k3, k4, it, il, f0, f1
      integer :: i
      real(wp) :: lam, xx
      lam(xx) = lam0*exp(2.0_wp*a*sqrt(max(0.0_wp, 1.0_wp - xx*xx)))     ! Lambda(x) of the strip
      dx = 2.0_wp/N
      t = 0.0_wp
      it = 0.0_wp
      il = 0.0_wp
      do i = 0, N - 1
         x = -1.0_wp + i*dx
         k1 = 1.0_wp - t/lam(x)
         k2 = 1.0_wp - (t + 0.5_wp*dx*k1)/lam(x + 0.5_wp*dx)
         k3 = 1.0_wp - (t + 0.5_wp*dx*k2)/lam(x + 0.5_wp*dx)
         k4 = 1.0_wp - (t + dx*k3)/lam(x + dx)
         f0 = t
         t = t + dx*(k1 + 2.0_wp*k2 + 2.0_wp*k3 + k4)/6.0_wp
         f1 = t
         ! Simpson on the step with the RK4 midpoint estimate
         it = it + dx*(f0 + 4.0_wp*(f0 + 0.5_wp*dx*(k2 + k3)*0.5_wp) + f1)/6.0_wp
         il = il + dx*(lam(x) + 4.0_wp*lam(x + 0.5_wp*dx) + lam(x + dx))/6.0_wp
      end do
      r = it/il
   end function ode_ratio

   !> With the option on (G = 1 GPa; De ~ 1 at this contact's centre) the fast traction at high
   !> orders agrees with the reference quadrature at high orders, as without it.
   subroutine test_fast_against_reference()
      type(contact_traction_t) :: t, tf, t0
      type(error_type), allocatable :: error
      type(ehd_rheology_t) :: r

      r = rheo
      r%shear_modulus = 1.0e9_wp
      call ehd_contact_traction(c, r, H, B, 128, 128, t, error)
      call ehd_contact_traction_fast(c, r, H, B, tf, error, 32, 24)
      call ehd_contact_traction(c, rheo, H, B, 128, 128, t0, error)
      write (*, "(a,2es12.4,a,es10.2)") "elastic film (G = 1 GPa), power and force at Appendix C's ball-1 outer contact: ", &
         t%power, t%force, ";  fast/reference - 1:", tf%power/t%power - 1.0_wp
      write (*, "(a,2es12.4)") "  the viscous film's:", t0%power, t0%force
      write (*, "(a,f7.2,a,es10.3,a,f8.2,a)") "  entraining speed", u_e, " m/s; De at the centre (small slip)", &
         u_e*rheo%eta_w*exp(rheo%alpha*1.5_wp*c%load/(pi*c%a*B))/(r%shear_modulus*2.0_wp*B), "; p_H", &
         1.5e-9_wp*c%load/(pi*c%a*B), " GPa"
      call check(abs(tf%power/t%power - 1.0_wp) < 1.0e-6_wp .and. abs(tf%force - t%force) < 1.0e-5_wp*abs(t%force), &
                 "elastic film: fast traction has the reference quadrature's limit")
      call check(t%power < t0%power, "elastic film: less traction power than the viscous film")
   end subroutine test_fast_against_reference

end program test_film_elasticity
