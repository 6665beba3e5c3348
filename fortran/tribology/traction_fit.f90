!> Four-parameter traction curve of ADORE 5.0 ("LUBRICATION PARAMETERS" of the echo):
!>     kappa(u) = (A + B u) exp(-C u) + D,   u = slip velocity (m/s),
!> fitted to the deck's four numbers: kappa at zero slip k0, maximum kappa kmax,
!> kappa at infinite slip kinf, slip at maximum umax (Rec 10.1).
!>
!> Conditions and solution (derived here; reproduces A, B, C of the Appendix C and D
!> echo): kappa(inf) = kinf with C > 0 gives D = kinf; kappa(0) = k0 gives A = k0 - kinf;
!> kappa'(umax) = 0 gives B (1 - x) = C A with x = C umax; kappa(umax) = kmax then gives
!> (B/C) exp(-x) = kmax - kinf, i.e.
!>     A exp(-x) / (1 - x) = kmax - kinf.
!> With q = (kmax - kinf) / |A|:
!>   A < 0 (k0 < kinf): y = x - 1 > 0 solves y exp(y) = 1/(e q)      (Lambert W0),
!>   A > 0 (k0 > kinf): y = 1 - x in (0,1) solves y exp(-y) = 1/(e q), needs q > 1,
!>   A = 0: x = 1.
!> Then C = x / umax, B = C A / (1 - x) (A = 0: B = e C (kmax - kinf)).
!> A solution exists exactly when umax > 0 and kmax > max(k0, kinf).
module adore_tribology_traction_fit
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: fit_traction_curve, traction_coefficient, traction_slope

contains

   !> Traction coefficient (A + B u) exp(-C u) + D; B and C in s/m, slip u in m/s.
   elemental function traction_coefficient(a, b, c, d, u) result(kappa)
      real(wp), intent(in) :: a, b, c, d, u
      real(wp) :: kappa

      kappa = (a + b*u)*exp(-c*u) + d
   end function traction_coefficient

   !> d kappa / du (s/m) of the traction curve: (B - C (A + B u)) exp(-C u).
   elemental function traction_slope(a, b, c, u) result(slope)
      real(wp), intent(in) :: a, b, c, u
      real(wp) :: slope

      slope = (b - c*(a + b*u))*exp(-c*u)
   end function traction_slope

   !> Fit coef = [A, B, C, D] to (k0, kmax, kinf, umax) as derived in the module header.
   !> Input error when umax <= 0 or kmax <= max(k0, kinf) (no such curve exists).
   subroutine fit_traction_curve(k0, kmax, kinf, umax, coef, error)
      real(wp), intent(in) :: k0, kmax, kinf, umax
      real(wp), intent(out) :: coef(4)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: a, b, c, x, q, y
      character(len=200) :: buf

      coef = 0.0_wp
      if (.not. (umax > 0.0_wp)) then
         write (buf, "(a,es12.5,a)") "traction curve: slip at maximum traction must be positive, got ", &
            umax, " m/s"
         call input_error(error, trim(buf))
         return
      end if
      if (.not. (kmax > max(k0, kinf))) then
         write (buf, "(a,es12.5,a,es12.5,a,es12.5,a)") "traction curve: maximum coefficient ", kmax, &
            " must exceed both the zero-slip (", k0, ") and infinite-slip (", kinf, ") coefficients"
         call input_error(error, trim(buf))
         return
      end if

      a = k0 - kinf
      if (a == 0.0_wp) then
         x = 1.0_wp
         c = x/umax
         b = exp(1.0_wp)*c*(kmax - kinf)
      else
         q = (kmax - kinf)/abs(a)
         if (a < 0.0_wp) then
            y = solve_yexpy(1.0_wp/(exp(1.0_wp)*q), 1.0_wp)     ! y e^y = 1/(e q), y > 0
            x = 1.0_wp + y
         else
            y = solve_yexpy(1.0_wp/(exp(1.0_wp)*q), -1.0_wp)    ! y e^-y = 1/(e q), 0 < y < 1
            x = 1.0_wp - y
         end if
         c = x/umax
         b = c*a/(1.0_wp - x)
      end if
      coef = [a, b, c, kinf]
   end subroutine fit_traction_curve

   !> Root y > 0 of y exp(s y) = t for s = +1 (any t > 0) or s = -1 (0 < t < 1/e, root
   !> in (0, 1)): bisection on log(y) + s y - log(t), monotone on the bracket.
   pure function solve_yexpy(t, s) result(y)
      real(wp), intent(in) :: t, s
      real(wp) :: y
      real(wp) :: lo, hi, f
      integer :: it

      lo = 0.0_wp
      if (s > 0.0_wp) then
         hi = max(1.0_wp, log(t) + 1.0_wp)       ! y exp(y) >= t at y = hi
         do while (hi*exp(hi) < t)
            hi = 2.0_wp*hi
         end do
      else
         hi = 1.0_wp
      end if
      y = 0.5_wp*(lo + hi)
      do it = 1, 200
         y = 0.5_wp*(lo + hi)
         f = log(y) + s*y - log(t)
         if (f > 0.0_wp) then
            hi = y
         else
            lo = y
         end if
         if (hi - lo <= 4.0_wp*epsilon(1.0_wp)*max(hi, tiny(1.0_wp))) exit
      end do
      y = 0.5_wp*(lo + hi)
   end function solve_yexpy

end module adore_tribology_traction_fit
