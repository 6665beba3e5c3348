!> Unit tests of the EHD film's limiting shear stress (run option limiting_shear;
!> adore_tribology_ehd_traction's limited_shear, docs/tribology.md "Limiting shear stress"):
!> tau = tau_L tanh(tau_N / tau_L), tau_L = Lambda p.  Closed checks: the law itself (never
!> above Lambda p nor above the film's own stress, slope 1 at small stress, off at Lambda =
!> 0), every strip's traction at most Lambda times its load (with the Maxwell film too), and
!> the saturated film (tau_N >> tau_L everywhere) whose strip traction is Lambda times the
!> strip's load and whose contact force is Lambda times the contact load; the fast quadrature against the
!> reference with the cap on, at Appendix C's ball-1 outer contact and at 3 and 12.8 times
!> its load (up to 3.7 GPa).  No files.
program test_limiting_shear
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, SIDE_OUTER
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_contact_traction_fast, &
                                           ehd_strip_traction, film_shear_stress, limited_shear
   use adore_test_support, only: check, finish
   implicit none

   type(ball_race_contact_t) :: c
   type(ehd_rheology_t) :: rheo
   real(wp), parameter :: H = 4.55e-7_wp, B = 3.15e-4_wp

   ! Appendix C ball 1, outer race contact at its step-0 state (as test_tribology)
   c = ball_race_contact_t(SIDE_OUTER, atan2(0.14701482232434315_wp, 0.9891342891725783_wp), 0.009525_wp, &
                           0.07004480819399529_wp, -7894.364961447181_wp*[cos(-0.13801441540302414_wp), &
                           sin(-0.13801441540302414_wp)], -943.0_wp, 0.0023737604859883953_wp, 2479.297919485147_wp)
   rheo = ehd_rheology_t(eta_w=0.0815882_wp, alpha=5.2214e-9_wp, beta=0.0425519_wp, conductivity=0.1425185_wp)
   call test_law()
   call test_strip_bound()
   call test_saturated_film()
   call test_fast_against_reference()
   call finish("limiting shear")

contains

   !> The law: 0 < tau <= min(tau_N, Lambda p) over 24 decades of tau_N / tau_L, 1 - tau /
   !> tau_N ~ (tau_N / tau_L)**2 / 3 at small stress, tau_L at large; Lambda = 0: tau_N bit for
   !> bit; p = 0 with a cap: 0.
   subroutine test_law()
      real(wp) :: p, tau_n, tau, worst_small
      integer :: k
      logical :: bounded

      bounded = .true.
      worst_small = 0.0_wp
      p = 2.0e9_wp
      do k = -120, 120
         tau_n = 0.08_wp*p*10.0_wp**(0.1_wp*k)
         tau = limited_shear(tau_n, 0.08_wp, p)
         ! tau <= tau_N up to the rounding of tau_L x (tau_N / tau_L): one ulp of each
         bounded = bounded .and. tau > 0.0_wp .and. tau <= tau_n*(1.0_wp + 2.0_wp*epsilon(1.0_wp)) &
                   .and. tau <= 0.08_wp*p
         ! (tau_N / tau_L from 1e-4 to 1e-2: (tau_N - tau) / tau_N >= 3e-9, far above rounding)
         if (k >= -40 .and. k <= -20) worst_small = max(worst_small, abs((tau_n - tau)/tau_n - (tau_n/(0.08_wp*p))**2/3.0_wp) &
                                         /((tau_n/(0.08_wp*p))**2/3.0_wp))
      end do
      write (*, "(a,es10.2)") "limited shear: 1 - tau / tau_N against (tau_N / tau_L)**2 / 3, tau_N / tau_L 1e-4 .. 1e-2:", &
         worst_small
      call check(bounded, "limited shear: 0 < tau <= min(tau_N, Lambda p)")
      call check(worst_small < 1.0e-3_wp, "limited shear: slope 1 at small stress (tanh's series)")
      call check(limited_shear(1.0e30_wp, 0.08_wp, p) == 0.08_wp*p, "limited shear: tau_L at large stress")
      call check(limited_shear(1.234e7_wp, 0.0_wp, p) == 1.234e7_wp, "limited shear: Lambda = 0 is no cap, bit for bit")
      call check(limited_shear(1.234e7_wp, 0.08_wp, 0.0_wp) == 0.0_wp, "limited shear: no pressure, no shear strength")
   end subroutine test_law

   !> Every strip's traction f with the cap is at most Lambda times its load q (each strip
   !> point's stress <= Lambda p, the same weights) and below the uncapped film's, at 11
   !> strips along the major axis, slips 1e-3 .. 30 m/s, Lambda 0.02 .. 0.1, thermal and
   !> isothermal; and at the uncapped film's own peak stress (0.53 p at 2 GPa: docs) the cap
   !> of 0.05 takes a part of the traction.
   subroutine test_strip_bound()
      type(ehd_rheology_t) :: r
      real(wp) :: f, q, f0, q0, s, u, worst, lam(3)
      integer :: i, k, l, iso
      logical :: ok

      lam = [0.02_wp, 0.05_wp, 0.1_wp]
      ok = .true.
      worst = 0.0_wp
      do iso = 0, 1
         do l = 1, 3
            r = rheo
            if (iso == 1) r%beta = 0.0_wp
            do k = -3, 3
               u = 10.0_wp**(0.5_wp*k)*3.0_wp
               do i = -5, 5
                  s = 0.19_wp*i*c%a
                  r%limiting_shear = 0.0_wp
                  call ehd_strip_traction(c, r, H, B, 24, s, u, f0, q0)
                  r%limiting_shear = lam(l)
                  call ehd_strip_traction(c, r, H, B, 24, s, u, f, q)
                  ok = ok .and. f <= lam(l)*q .and. f <= f0 .and. f > 0.0_wp .and. q == q0
                  worst = max(worst, f/(lam(l)*q))
               end do
            end do
         end do
      end do
      write (*, "(a,f10.6)") "limiting shear: largest strip traction / (Lambda x strip load):", worst
      call check(ok, "limiting shear: every strip's traction <= Lambda x its load and <= the uncapped film's")
      ! with the film's elasticity (G = 1 GPa, 0.3 GPa): the Maxwell ratio of the uncapped film
      ! times the capped strip integral (docs): still at most Lambda q and the capped viscous film's
      ok = .true.
      worst = 0.0_wp
      do l = 1, 2
         do k = -3, 3
            u = 10.0_wp**(0.5_wp*k)*3.0_wp
            do i = -5, 5
               s = 0.19_wp*i*c%a
               r = rheo
               r%limiting_shear = 0.08_wp
               call ehd_strip_traction(c, r, H, B, 24, s, u, f0, q0)
               r%shear_modulus = merge(1.0e9_wp, 3.0e8_wp, l == 1)
               call ehd_strip_traction(c, r, H, B, 24, s, u, f, q)
               ok = ok .and. f <= 0.08_wp*q .and. f <= f0 .and. f > 0.0_wp
               worst = max(worst, f/(0.08_wp*q))
            end do
         end do
      end do
      write (*, "(a,f10.6)") "limiting shear with the elastic film: largest strip traction / (Lambda q):", worst
      call check(ok, "limiting shear: with the Maxwell film every strip's traction <= Lambda x its load")
   end subroutine test_strip_bound

   !> tau_N >> tau_L everywhere (an isothermal film of 1e6 Pa s at 5 m/s: tau_N >= 1.1e13 Pa,
   !> tau_L <= 0.08 p0 ~ 1.2e8 Pa): each strip's traction is Lambda times its load, and the
   !> contact's force Lambda times the contact load (the strips' loads integrate to Q up to
   !> the major axis' quadrature), reference and fast.
   subroutine test_saturated_film()
      type(ehd_rheology_t) :: r
      type(ball_race_contact_t) :: cs
      type(contact_traction_t) :: t, tf
      type(error_type), allocatable :: error
      real(wp) :: f, q, worst
      integer :: i

      r = ehd_rheology_t(eta_w=1.0e6_wp, alpha=0.0_wp, beta=0.0_wp, conductivity=0.14_wp, limiting_shear=0.08_wp)
      worst = 0.0_wp
      do i = -5, 5
         call ehd_strip_traction(c, r, H, B, 24, 0.19_wp*i*c%a, 5.0_wp, f, q)
         worst = max(worst, abs(f/(0.08_wp*q) - 1.0_wp))
      end do
      write (*, "(a,es10.2)") "limiting shear, saturated film: strip traction / (Lambda q) - 1, worst:", worst
      call check(worst < 1.0e-13_wp, "limiting shear: a saturated strip's traction is Lambda x its load")
      ! a contact sliding one way everywhere: the race at rest, the ball spinning about its
      ! rolling axis only (no pure-rolling point inside the contact)
      cs = c
      cs%omega = [cs%omega(1), 0.0_wp]
      cs%race_speed = 0.0_wp
      call ehd_contact_traction(cs, r, H, B, 64, 24, t, error)
      call check(.not. allocated(error), "limiting shear: saturated contact (reference) computed")
      call ehd_contact_traction_fast(cs, r, H, B, tf, error)
      call check(.not. allocated(error), "limiting shear: saturated contact (fast) computed")
      write (*, "(a,i0,2es10.2)") "limiting shear, saturated contact: rolling points, |force| / (Lambda Q) - 1 "// &
         "(reference, fast):", t%n_rolling, abs(t%force)/(0.08_wp*cs%load) - 1.0_wp, &
         abs(tf%force)/(0.08_wp*cs%load) - 1.0_wp
      call check(t%n_rolling == 0 .and. abs(abs(t%force)/(0.08_wp*cs%load) - 1.0_wp) < 1.0e-4_wp .and. &
                 abs(abs(tf%force)/(0.08_wp*cs%load) - 1.0_wp) < 1.0e-6_wp, &
                 "limiting shear: a saturated contact's force is Lambda x its load")
   end subroutine test_saturated_film

   !> With the cap on (Lambda 0.05, 0.08, 0.1) the fast traction at its default orders (the
   !> time steps') agrees with the reference at 128 x 128 points as tests/test_ehd_fast.py
   !> bounds it without (force and its moments to 1e-4 of the gross traction, power to 1e-4),
   !> at Appendix C's ball-1 outer contact (p0 1.58 GPa) and at 3 and 12.8 times its load (2.28
   !> and 3.70 GPa, the ellipse scaled by the load's cube root); the cap lowers the power.
   subroutine test_fast_against_reference()
      type(contact_traction_t) :: t, tf, t0
      type(error_type), allocatable :: error
      type(ehd_rheology_t) :: r
      type(ball_race_contact_t) :: cc
      real(wp) :: lam(3), bb, ef, ep, worst_f, worst_p, p0
      integer :: l, m
      logical :: lower

      lam = [0.05_wp, 0.08_wp, 0.1_wp]
      worst_f = 0.0_wp
      worst_p = 0.0_wp
      lower = .true.
      do m = 1, 3
         cc = c
         bb = B
         if (m == 2) then
            cc%load = 3.0_wp*c%load
            cc%a = c%a*3.0_wp**(1.0_wp/3.0_wp)
            bb = B*3.0_wp**(1.0_wp/3.0_wp)
         else if (m == 3) then
            ! p0 3.70 GPa: the deep-groove deck's ball 3 inner contact at 10 kN (docs)
            cc%load = 12.8_wp*c%load
            cc%a = c%a*12.8_wp**(1.0_wp/3.0_wp)
            bb = B*12.8_wp**(1.0_wp/3.0_wp)
         end if
         p0 = 1.5_wp*cc%load/(pi*cc%a*bb)
         r = rheo
         call ehd_contact_traction(cc, r, H, bb, 128, 128, t0, error)
         do l = 1, 3
            r%limiting_shear = lam(l)
            call ehd_contact_traction(cc, r, H, bb, 128, 128, t, error)
            call ehd_contact_traction_fast(cc, r, H, bb, tf, error)
            call check(.not. allocated(error), "limiting shear: fast and reference computed")
            ef = max(abs(tf%force - t%force), abs(tf%force_cos - t%force_cos), abs(tf%force_sin - t%force_sin)) &
                 /(t%power/t%max_slip)
            ep = abs(tf%power/t%power - 1.0_wp)
            worst_f = max(worst_f, ef)
            worst_p = max(worst_p, ep)
            lower = lower .and. t%power < t0%power
            write (*, "(a,f5.2,a,f5.2,a,2es12.4,a,2es10.2)") "limiting shear: p0", p0*1.0e-9_wp, " GPa, Lambda", &
               lam(l), ": power and force", t%power, t%force, "; fast against reference (force, power)", ef, ep
         end do
         write (*, "(a,2es12.4)") "  the uncapped film's power and force:", t0%power, t0%force
      end do
      call check(worst_f < 1.0e-4_wp .and. worst_p < 1.0e-4_wp, &
                 "limiting shear: fast traction within 1e-4 of the reference with the cap on")
      call check(lower, "limiting shear: the cap lowers the contact's power")
   end subroutine test_fast_against_reference

end program test_limiting_shear
