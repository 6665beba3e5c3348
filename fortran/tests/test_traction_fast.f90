!> Unit tests of the fast race traction and the Hertz ellipse shortcut (moved from
!> test_forces): the fast one- and two-dimensional traction against the reference
!> quadrature at every Appendix C race contact, at the step-0 state and at states slipping
!> across the rolling direction; hertz_geometry's Newton ellipticity against a quad-precision
!> root; the fast traction's series sin(phi) against libm's sin and quadruple precision.  Run by `meson test` with the decks/ directory as argument.
program test_traction_fast
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, ball_bearing_loads
   use adore_start_ball_step0, only: ball_step0_t
   use adore_contact_hertz, only: hertz_geometry_t, hertz_geometry, hertz_contact_t, hertz_contact
   use adore_tribology_ehd_traction, only: series_sin, series_cos_sin
   use adore_test_support, only: check, finish
   use adore_test_ball_fixture, only: step0_state, appendix_c_race_control
   implicit none

   integer, parameter :: QP = selected_real_kind(30)   ! quadruple precision of the Hertz reference root

   type(bearing_t) :: b
   type(mounted_geometry_t) :: g
   type(error_type), allocatable :: error
   type(ball_step0_t) :: s0

   call appendix_c_race_control("fast traction", b, g, s0)
   call test_fast_two_dimensional_traction(b, g, step0_state(b, s0))
   call test_hertz_bisection_shortcut()
   call test_series_sin()
   call test_series_cos_sin()
   call finish("fast traction")

contains

   !> The fast race traction (the default) against its reference (the EHD strip
   !> quadrature of EHD_GAUSS x EHD_STRIP points at every node, reference = .true.), two-
   !> and one-dimensional, at every race contact of Appendix C: at the step-0 state (race
   !> control: the outer contacts' two pure-rolling points merge at the centre, where the
   !> fast rule grades at the slip's dip) and at three states whose balls slip across the
   !> rolling direction (each ball's spin tilted out of its orbital plane, from 3 to 3000
   !> rad/s over the balls, alternating in sign; the balls also moving axially and
   !> radially; all together with a spin about each ball's outer normal).  Each of the six
   !> sums (along the rolling direction: force, its cos and sin moments; across it: the
   !> same) and the power, relative to the larger of the reference value and the contact's
   !> gross traction power / max slip (a tenth of it for the sin moments, whose arm is
   !> small), within the 1e-4 that the fast one-dimensional traction keeps from its
   !> reference at the step-0 contacts (tests/test_ehd_fast.py).
   subroutine test_fast_two_dimensional_traction(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: lf, lr, l0
      real(wp) :: worst(4, 2), e, wk, sf(7), sr(7), gross, cross_max(4)
      integer :: s, k, j, n, i, d
      character(len=*), parameter :: label(4) = [character(len=24) :: "step 0", "tilted spin", &
                                                 "tilted spin, moving", "tilted, moving, spun"]

      n = size(base%elements)
      call ball_bearing_loads(b, g, base, l0, error, cage=.false.)
      if (allocated(error)) return
      worst = 0.0_wp
      cross_max = 0.0_wp
      do s = 1, 4
         st = base
         do k = 1, n
            wk = merge(1.0_wp, -1.0_wp, mod(k, 2) == 0)*3.0_wp*1000.0_wp**(real(k - 1, wp)/real(n - 1, wp))
            if (s >= 2) st%elements(k)%omega = st%elements(k)%omega + wk*l0%contacts(1, k)%rolling
            if (s >= 3) st%elements(k)%velocity = st%elements(k)%velocity + 1.0e-3_wp*wk*[1.0_wp, 0.0_wp, 0.0_wp] + &
                                                  1.0e-4_wp*wk*l0%contacts(1, k)%normal
            if (s >= 4) st%elements(k)%omega = st%elements(k)%omega + 300.0_wp*l0%contacts(1, k)%normal
         end do
         do d = 1, 2             ! 2-D, 1-D
            call ball_bearing_loads(b, g, st, lf, error, cage=.false., two_d=d == 1)
            call check(.not. allocated(error), "fast traction: "//trim(label(s)))
            if (allocated(error)) return
            call ball_bearing_loads(b, g, st, lr, error, cage=.false., two_d=d == 1, reference=.true.)
            call check(.not. allocated(error), "reference traction: "//trim(label(s)))
            if (allocated(error)) return
            do k = 1, n
               do j = 1, 2
                  if (.not. (lr%contacts(j, k)%load > 0.0_wp)) cycle
                  associate (tf => lf%traction(j, k), tr => lr%traction(j, k))
                     sf = [tf%force, tf%force_cos, tf%force_sin, tf%cross_force, tf%power]
                     sr = [tr%force, tr%force_cos, tr%force_sin, tr%cross_force, tr%power]
                     gross = tr%power/tr%max_slip
                     if (d == 1) cross_max(s) = max(cross_max(s), abs(tr%cross_force(1))/gross)
                  end associate
                  do i = 1, 6
                     e = abs(sf(i) - sr(i))/max(abs(sr(i)), merge(0.1_wp, 1.0_wp, i == 3 .or. i == 6)*gross)
                     worst(s, d) = max(worst(s, d), e)
                  end do
                  worst(s, d) = max(worst(s, d), abs(sf(7)/sr(7) - 1.0_wp))
               end do
            end do
         end do
      end do
      write (*, "(a,4es10.2)") "fast 2-D traction vs reference, worst per state (step 0, tilted, moving, spun): ", &
         worst(:, 1)
      write (*, "(a,4es10.2)") "fast 1-D traction vs reference, worst per state (step 0, tilted, moving, spun): ", &
         worst(:, 2)
      write (*, "(a,4es10.2)") "  largest cross traction / gross traction per state: ", cross_max
      call check(all(cross_max(2:) > 0.1_wp), "fast 2-D traction: the perturbed states slip across the rolling direction")
      call check(all(worst(:, 1) <= 1.0e-4_wp), "fast 2-D traction: six sums and power within 1e-4 of the reference")
      call check(all(worst(:, 2) <= 1.0e-4_wp), "fast 1-D traction: force, moments, power within 1e-4 of the reference")
   end subroutine test_fast_two_dimensional_traction

   !> hertz_geometry's Newton ellipticity against an independent root in quadruple precision
   !> (AGM and bisection in real(QP), F(kappa) = F(rho) for the double F(rho)): ball/race
   !> curvatures of Appendix C's ball (D = 19.05 mm, dm = 125 mm) at contact angles
   !> 0 .. 60 deg and groove factors 0.501 .. 0.6 (ellipticities 2 .. 40, the dynamics'
   !> range): kappa within 5e-14 relative, and a*, b*, delta*, stiffness within 5e-14 of the
   !> exhaustive bisection's, the loaded semi-major axis a* (1.5 Q c / S)**(1/3) within 5e-14
   !> of its cube root in quadruple precision.  Curvature ratios R_y/R_x from 1 + 1e-9 to 1e5 (ellipticities
   !> 1 .. 844): kappa within 8 times F's conditioning, eps max(1, 1/(kappa**2 - 1)) /
   !> |dF/dlog(kappa)| (F's rounding over its slope; measured: Newton <= 3.3 times, the
   !> exhaustive bisection <= 11 times).
   subroutine test_hertz_bisection_shortcut()
      real(wp) :: rho(4), gam, d, ff, alpha, ratio, worst(3)
      logical :: same
      integer :: i, j, n

      same = .true.
      n = 0
      worst = 0.0_wp
      d = 0.01905_wp
      do i = 0, 60
         alpha = real(i, wp)*acos(-1.0_wp)/180.0_wp
         gam = d*cos(alpha)/0.125_wp
         do j = 0, 20
            ff = 0.501_wp + 0.099_wp*real(j, wp)/20.0_wp
            rho = [2.0_wp/d, 2.0_wp/d, 2.0_wp*gam/(d*(1.0_wp - gam)), -1.0_wp/(ff*d)]
            call compare(rho, same, n, worst, .true.)
            rho(3) = -2.0_wp*gam/(d*(1.0_wp + gam))
            call compare(rho, same, n, worst, .true.)
         end do
      end do
      do i = 0, 1400
         ratio = 1.0_wp + 10.0_wp**(-9.0_wp + real(i, wp)/100.0_wp)
         rho = [1.0_wp, 1.0_wp, ratio - 1.0_wp, 0.0_wp]
         call compare(rho, same, n, worst, .false.)
      end do
      write (*, "(a,i0,a,3es10.2)") "Hertz ellipse, Newton vs quad-precision root: ", n, " contacts; ball range: "// &
         "kappa error, ellipse vs exhaustive bisection; ratio sweep: error / conditioning ", worst
      call check(same .and. worst(1) <= 5.0e-14_wp .and. worst(2) <= 5.0e-14_wp .and. worst(3) <= 8.0_wp, &
                 "Hertz ellipse: Newton's ellipticity within its bounds of the quad-precision root")
   end subroutine test_hertz_bisection_shortcut

   !> The fast traction's sin(phi) at its nodes (series_sin, Taylor to phi**21 / 21!) over
   !> the whole range of phi, [-pi/2, pi/2] (200 001 points): within 2.3e-16 of libm's sin
   !> (its ulp at 1 is 2.2e-16) and within 2 ulp of sin in quadruple precision.
   subroutine test_series_sin()
      real(wp) :: x, worst_libm, worst_ulp
      integer :: i
      worst_libm = 0.0_wp
      worst_ulp = 0.0_wp
      do i = -100000, 100000
         x = 0.5_wp*acos(-1.0_wp)*real(i, wp)/100000.0_wp
         worst_libm = max(worst_libm, abs(series_sin(x) - sin(x)))
         if (x /= 0.0_wp) worst_ulp = max(worst_ulp, real(abs(real(series_sin(x), QP) - sin(real(x, QP))), wp) &
                                                      /spacing(abs(sin(x))))
      end do
      write (*, "(a,es10.2,a,f5.2)") "series sin(phi) on [-pi/2, pi/2]: worst against libm's sin", worst_libm, &
         ", against quad precision (ulp)", worst_ulp
      call check(worst_libm <= 2.3e-16_wp .and. worst_ulp <= 2.0_wp, "series sin = sin to round-off on [-pi/2, pi/2]")
   end subroutine test_series_sin

   !> cos and sin of s / rho at a pure-rolling point (series_cos_sin: the short series for
   !> |x| <= 0.4, the long one for |x| < 1; 200 001 points each): within 2 ulp of cos and sin
   !> in quadruple precision (libm's cos and sin are within 1 ulp) and within 3.4e-16 of libm.
   subroutine test_series_cos_sin()
      real(wp) :: x, cs(2), worst_libm, worst_ulp, top
      integer :: i, k
      logical :: short
      worst_libm = 0.0_wp
      worst_ulp = 0.0_wp
      do k = 1, 2
         short = k == 1
         top = merge(0.4_wp, 0.999_wp, short)
         do i = -100000, 100000
            x = top*real(i, wp)/100000.0_wp
            cs = series_cos_sin(x, short)
            worst_libm = max(worst_libm, abs(cs(1) - cos(x)), abs(cs(2) - sin(x)))
            worst_ulp = max(worst_ulp, real(abs(real(cs(1), QP) - cos(real(x, QP))), wp)/spacing(cos(x)))
            if (x /= 0.0_wp) worst_ulp = max(worst_ulp, real(abs(real(cs(2), QP) - sin(real(x, QP))), wp) &
                                                         /spacing(abs(sin(x))))
         end do
      end do
      write (*, "(a,es10.2,a,f5.2)") "series cos, sin of s / rho: worst against libm", worst_libm, &
         ", against quad precision (ulp)", worst_ulp
      call check(worst_libm <= 3.4e-16_wp .and. worst_ulp <= 2.0_wp, &
                 "series cos, sin = cos, sin to round-off on |x| <= 0.4 (short) and |x| < 1")
      ! a graded sub-zone's e**vmax, vmax = asinh(z) = log(y), y = z + sqrt(1 + z**2), is y itself
      ! (issue #30: no exp) where the fast traction grades (vmax > 1, z <= 40): within 5 ulp
      worst_ulp = 0.0_wp
      do i = 0, 100000
         x = sinh(1.0_wp) + (40.0_wp - sinh(1.0_wp))*real(i, wp)/100000.0_wp
         top = x + sqrt(1.0_wp + x*x)
         worst_ulp = max(worst_ulp, abs(exp(log(top)) - top)/spacing(top))
      end do
      write (*, "(a,f5.2)") "graded sub-zone: e**vmax as the logarithm's argument, exp(log(y)) - y (ulp)", worst_ulp
      call check(worst_ulp <= 5.0_wp, "graded sub-zone: e**vmax = y to round-off")
   end subroutine test_series_cos_sin

   !> Count one more comparison in n; same stays true while both ellipses of curvatures rho
   !> (1/m, steel on steel) exist.  ball: worst(1) the largest relative error of kappa
   !> against the quad-precision root, worst(2) of a*, b*, delta*, stiffness against the
   !> exhaustive bisection's; else worst(3) kappa's error over F's conditioning.
   subroutine compare(rho, same, n, worst, ball)
      real(wp), intent(in) :: rho(4)
      logical, intent(inout) :: same
      integer, intent(inout) :: n
      real(wp), intent(inout) :: worst(3)
      logical, intent(in) :: ball
      type(hertz_geometry_t) :: fast, full
      type(hertz_contact_t) :: ell
      logical :: ok1, ok2
      real(QP) :: kq, slope, err, sq
      real(wp) :: q
      integer :: i
      call hertz_geometry(rho, 2.0e11_wp, 0.3_wp, 2.0e11_wp, 0.3_wp, fast, ok1)
      call hertz_geometry(rho, 2.0e11_wp, 0.3_wp, 2.0e11_wp, 0.3_wp, full, ok2, exhaustive=.true.)
      n = n + 1
      same = same .and. ok1 .and. ok2
      if (.not. (ok1 .and. ok2)) return
      kq = root_qp(real(fast%curvature_diff, QP))
      err = abs(real(fast%kappa, QP)/kq - 1.0_QP)
      if (ball) then
         worst(1) = max(worst(1), real(err, wp))
         worst(2) = max(worst(2), abs(fast%a_star/full%a_star - 1.0_wp), abs(fast%b_star/full%b_star - 1.0_wp), &
                        abs(fast%delta_star/full%delta_star - 1.0_wp), abs(fast%stiffness/full%stiffness - 1.0_wp))
         ! the loaded ellipse's cube root (libm cbrt) against quadruple precision, 1 mN .. 100 kN
         do i = -3, 5
            q = 10.0_wp**i
            ell = hertz_contact(fast, q)
            sq = (1.5_QP*real(q, QP)*real(fast%compliance, QP)/real(fast%curvature_sum, QP))**(1.0_QP/3.0_QP)
            worst(2) = max(worst(2), real(abs(real(ell%semi_major, QP)/(real(fast%a_star, QP)*sq) - 1.0_QP), wp))
         end do
      else
         slope = abs(f_qp(kq*exp(1.0e-12_QP)) - f_qp(kq*exp(-1.0e-12_QP)))/2.0e-12_QP
         worst(3) = max(worst(3), real(err*slope/(epsilon(1.0_wp)*max(1.0_QP, 1.0_QP/(kq**2 - 1.0_QP))), wp))
      end if
   end subroutine compare

   !> F(kappa) of the Hertz ellipse in quadruple precision (AGM for K, E; adore_contact_hertz).
   function f_qp(kappa) result(f)
      real(QP), intent(in) :: kappa
      real(QP) :: f, a, b, c, a_next, s, pw, m, k, e
      integer :: i
      m = 1.0_QP - 1.0_QP/kappa**2
      a = 1.0_QP
      b = sqrt(1.0_QP - m)
      c = sqrt(m)
      s = 0.5_QP*c*c
      pw = 0.5_QP
      do i = 1, 60
         if (abs(c) <= epsilon(1.0_QP)*a) exit
         a_next = 0.5_QP*(a + b)
         c = 0.5_QP*(a - b)
         b = sqrt(a*b)
         a = a_next
         pw = 2.0_QP*pw
         s = s + pw*c*c
      end do
      k = acos(-1.0_QP)/(2.0_QP*a)
      e = k*(1.0_QP - s)
      f = ((kappa**2 + 1.0_QP)*e - 2.0_QP*k)/((kappa**2 - 1.0_QP)*e)
   end function f_qp

   !> The root kappa of F(kappa) = f in quadruple precision: bisection on log(kappa) in [0, log(1e6)].
   function root_qp(f) result(kappa)
      real(QP), intent(in) :: f
      real(QP) :: kappa, lo, hi, mid
      integer :: i
      lo = 0.0_QP
      hi = log(1.0e6_QP)
      do i = 1, 300
         mid = 0.5_QP*(lo + hi)
         if (f_qp(exp(mid)) > f) then
            hi = mid
         else
            lo = mid
         end if
         if (hi - lo < 1.0e-30_QP) exit
      end do
      kappa = exp(0.5_QP*(lo + hi))
   end function root_qp

end program test_traction_fast
