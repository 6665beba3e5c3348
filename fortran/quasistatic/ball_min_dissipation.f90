!> Newton minimisation of a smooth function of one or two variables from function values
!> only: the fast search of the minimum-dissipation ball start (report 4.4.7,
!> adore_quasistatic_ball_kinematics' min_dissipation_kinematics).
!>
!> The contact dissipation is a smooth function of the pitch and spin speed (its
!> quadrature's zones follow the pure-rolling points), so Newton's method on its
!> stationarity conditions converges quadratically.  Gradient and Hessian are central
!> differences with step h in the caller's scaled variables: the gradient's error is
!> O(h**2 f''') + O(eps f / h), which places the minimum to ~1e-10 of the variables' scale
!> with h = 1e-4 - finer than a golden section on function values can (sqrt(eps), ~1e-8).
!> Every Newton step is limited to max_step and halved until the function does not
!> increase, and clipped to the box [lo, hi]; the search reports failure (ok = .false.)
!> when the Hessian is not positive definite, the minimum found lies on the box or the
!> iteration does not converge, so that the caller can fall back to its reference search.
module adore_quasistatic_ball_min_dissipation
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: objective_1d, objective_2d, newton_minimum_1d, newton_minimum_2d, brent_minimum

   abstract interface
      !> f(x) of one scaled variable; failed = .true. stops the search (an error is set).
      subroutine objective_1d(x, f, failed)
         import :: wp
         real(wp), intent(in) :: x
         real(wp), intent(out) :: f
         logical, intent(out) :: failed
      end subroutine objective_1d

      !> f(y) of two scaled variables; failed = .true. stops the search (an error is set).
      subroutine objective_2d(y, f, failed)
         import :: wp
         real(wp), intent(in) :: y(2)
         real(wp), intent(out) :: f
         logical, intent(out) :: failed
      end subroutine objective_2d
   end interface

   integer, parameter :: MAX_NEWTON = 40   !< Newton steps before giving up
   integer, parameter :: MAX_HALVING = 30  !< step halvings per Newton step

contains

   !> Local minimum of fun(x) on [lo, hi] by Brent's method (golden section with parabolic
   !> interpolation; R. P. Brent, Algorithms for minimization without derivatives, 1973,
   !> ch. 5): x within ~tol of the minimum, f = fun(x).  failed = .true. when fun failed.
   subroutine brent_minimum(fun, lo, hi, tol, x, f, failed)
      procedure(objective_1d) :: fun
      real(wp), intent(in) :: lo, hi, tol
      real(wp), intent(out) :: x, f
      logical, intent(out) :: failed
      real(wp), parameter :: c = 0.5_wp*(3.0_wp - sqrt(5.0_wp))
      real(wp) :: a, b, d, e, m, p, q, r, t2, u, v, w, fu, fv, fw, tol1
      integer :: it

      a = lo
      b = hi
      v = a + c*(b - a)
      w = v
      x = v
      e = 0.0_wp
      d = 0.0_wp
      call fun(x, f, failed)
      if (failed) return
      fv = f
      fw = f
      do it = 1, 200
         m = 0.5_wp*(a + b)
         tol1 = tol + 1.0e-3_wp*tol
         t2 = 2.0_wp*tol1
         if (abs(x - m) <= t2 - 0.5_wp*(b - a)) exit
         p = 0.0_wp
         q = 0.0_wp
         r = 0.0_wp
         if (abs(e) > tol1) then                 ! trial parabola through x, v, w
            r = (x - w)*(f - fv)
            q = (x - v)*(f - fw)
            p = (x - v)*q - (x - w)*r
            q = 2.0_wp*(q - r)
            if (q > 0.0_wp) then
               p = -p
            else
               q = -q
            end if
            r = e
            e = d
         end if
         if (abs(p) < abs(0.5_wp*q*r) .and. p > q*(a - x) .and. p < q*(b - x)) then
            d = p/q                              ! parabolic step
            u = x + d
            if (u - a < t2 .or. b - u < t2) d = sign(tol1, m - x)
         else
            e = merge(b - x, a - x, x < m)       ! golden-section step
            d = c*e
         end if
         u = x + merge(d, sign(tol1, d), abs(d) >= tol1)
         call fun(u, fu, failed)
         if (failed) return
         if (fu <= f) then
            if (u < x) then
               b = x
            else
               a = x
            end if
            v = w
            fv = fw
            w = x
            fw = f
            x = u
            f = fu
         else
            if (u < x) then
               a = u
            else
               b = u
            end if
            if (fu <= fw .or. w == x) then
               v = w
               fv = fw
               w = u
               fw = fu
            else if (fu <= fv .or. v == x .or. v == w) then
               v = u
               fv = fu
            end if
         end if
      end do
   end subroutine brent_minimum

   !> Minimum of fun(x) by Newton with central differences (module header), from x0 inside
   !> [lo, hi]: x and f = fun(x) at the minimum, when |Newton step| < tol (scaled units);
   !> h difference step, max_step largest step.  ok = .false. when the search failed (no
   !> positive curvature, left the box, no convergence); failed = .true. when fun failed.
   subroutine newton_minimum_1d(fun, x0, lo, hi, h, tol, max_step, x, f, ok, failed)
      procedure(objective_1d) :: fun
      real(wp), intent(in) :: x0, lo, hi, h, tol, max_step
      real(wp), intent(out) :: x, f
      logical, intent(out) :: ok, failed
      real(wp) :: fp, fm, g, c, dx, xt, ft
      integer :: it, m

      ok = .false.
      x = x0
      call fun(x, f, failed)
      if (failed) return
      do it = 1, MAX_NEWTON
         call fun(x + h, fp, failed)
         if (failed) return
         call fun(x - h, fm, failed)
         if (failed) return
         g = (fp - fm)/(2.0_wp*h)
         c = (fp - 2.0_wp*f + fm)/(h*h)
         if (.not. (c > 0.0_wp)) return
         dx = -g/c
         if (abs(dx) > max_step) dx = sign(max_step, dx)
         dx = min(max(x + dx, lo), hi) - x               ! stay in the box
         do m = 1, MAX_HALVING
            xt = x + dx
            call fun(xt, ft, failed)
            if (failed) return
            if (ft <= f .or. abs(dx) <= tol) exit
            dx = 0.5_wp*dx
         end do
         x = xt
         f = ft
         if (abs(dx) <= tol) then
            ok = x > lo .and. x < hi                     ! a minimum on the box is no stationary point
            return
         end if
      end do
   end subroutine newton_minimum_1d

   !> Minimum of fun(y) of two scaled variables by Newton with central differences (module
   !> header), from y0 inside the box [lo, hi]: y and f = fun(y) at the minimum, when both
   !> components of the Newton step are below tol; max_step largest step per component.
   !> The difference step of each variable starts at h and is then set from the curvature
   !> so that it changes f by ~1e-7 relative (a narrow valley needs a small step: a step
   !> wider than the valley's quadratic bottom would displace the minimum).  ok, failed as
   !> newton_minimum_1d; n_eval: calls of fun.
   subroutine newton_minimum_2d(fun, y0, lo, hi, h, tol, max_step, y, f, ok, failed, n_eval)
      procedure(objective_2d) :: fun
      real(wp), intent(in) :: y0(2), lo(2), hi(2), h, tol, max_step
      real(wp), intent(out) :: y(2), f
      logical, intent(out) :: ok, failed
      integer, intent(out) :: n_eval
      real(wp), parameter :: DF = 1.0e-7_wp    !< relative change of f over a difference step
      real(wp) :: fp(2), fm(2), fpp, fpm, fmp, fmm, g(2), hs(2, 2), det, dy(2), yt(2), ft, s, hd(2), hn(2)
      integer :: it, m, i, pass

      ok = .false.
      n_eval = 0
      y = y0
      hd = h
      call eval(y, f)
      if (failed) return
      do it = 1, MAX_NEWTON
         do pass = 1, 3
            do i = 1, 2
               call eval(y + hd(i)*unit(i), fp(i))
               if (failed) return
               call eval(y - hd(i)*unit(i), fm(i))
               if (failed) return
            end do
            hs(1, 1) = (fp(1) - 2.0_wp*f + fm(1))/hd(1)**2
            hs(2, 2) = (fp(2) - 2.0_wp*f + fm(2))/hd(2)**2
            if (.not. (hs(1, 1) > 0.0_wp .and. hs(2, 2) > 0.0_wp)) return
            hn = min(max(sqrt(DF*abs(f)/[hs(1, 1), hs(2, 2)]), 1.0e-10_wp), 1.0e-2_wp)
            if (all(hd <= 4.0_wp*hn .and. hd >= 0.25_wp*hn)) exit
            hd = hn
         end do
         call eval(y + [hd(1), hd(2)], fpp)
         if (failed) return
         call eval(y + [hd(1), -hd(2)], fpm)
         if (failed) return
         call eval(y + [-hd(1), hd(2)], fmp)
         if (failed) return
         call eval(y - [hd(1), hd(2)], fmm)
         if (failed) return
         g = (fp - fm)/(2.0_wp*hd)
         hs(1, 2) = (fpp - fpm - fmp + fmm)/(4.0_wp*hd(1)*hd(2))
         hs(2, 1) = hs(1, 2)
         det = hs(1, 1)*hs(2, 2) - hs(1, 2)**2
         if (.not. (hs(1, 1) > 0.0_wp .and. det > 0.0_wp)) return
         dy = -[hs(2, 2)*g(1) - hs(1, 2)*g(2), hs(1, 1)*g(2) - hs(2, 1)*g(1)]/det
         s = maxval(abs(dy))/max_step
         if (s > 1.0_wp) dy = dy/s
         dy = min(max(y + dy, lo), hi) - y               ! stay in the box
         do m = 1, MAX_HALVING
            yt = y + dy
            call eval(yt, ft)
            if (failed) return
            if (ft <= f .or. maxval(abs(dy)) <= tol) exit
            dy = 0.5_wp*dy
         end do
         y = yt
         f = ft
         if (maxval(abs(dy)) <= tol .and. m == 1) then
            ok = all(y > lo .and. y < hi)                ! a minimum on the box is no stationary point
            return
         end if
      end do

   contains

      !> fun(z) counted
      subroutine eval(z, v)
         real(wp), intent(in) :: z(2)
         real(wp), intent(out) :: v
         n_eval = n_eval + 1
         call fun(z, v, failed)
      end subroutine eval

      !> unit vector i of the plane
      pure function unit(i) result(e)
         integer, intent(in) :: i
         real(wp) :: e(2)
         e = 0.0_wp
         e(i) = 1.0_wp
      end function unit

   end subroutine newton_minimum_2d

end module adore_quasistatic_ball_min_dissipation
