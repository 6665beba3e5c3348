!> Hertz point contact: contact ellipse, load–deflection, maximum pressure.
!>
!> Classical Hertz theory as in Harris & Kotzalas (Rolling Bearing Analysis, ch. 6):
!> the ellipticity kappa = a/b solves
!>     F(rho) = ((kappa**2 + 1) E(m) - 2 K(m)) / ((kappa**2 - 1) E(m)),  m = 1 - 1/kappa**2,
!> with F(rho) the curvature difference, and the dimensionless semi-axes and
!> approach are
!>     a* = (2 kappa**2 E / pi)**(1/3),  b* = (2 E / (pi kappa))**(1/3),
!>     delta* = (2 K / pi) (pi / (2 kappa**2 E))**(1/3).
!> Then with C = 3 Q / (2 sum rho) * ((1-nu1**2)/E1 + (1-nu2**2)/E2):
!>     a = a* C**(1/3),  b = b* C**(1/3),  delta = delta* C**(2/3) sum rho / 2,
!>     p_max = 3 Q / (2 pi a b).
!> The elliptic integrals are exact (AGM), not the Hamrock–Brewe fits, so the
!> ellipse is accurate to round-off.  Units SI throughout.
module adore_contact_hertz
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_elliptic, only: elliptic_ke
   use, intrinsic :: iso_c_binding, only: c_double
   implicit none
   private

   interface
      !> C99's cube root (libm), within 1 ulp; x**(1.0_wp/3.0_wp) is libm's pow, about three
      !> times its instructions (issue #30)
      pure function cbrt(x) result(y) bind(c, name="cbrt")
         import :: c_double
         real(c_double), value, intent(in) :: x
         real(c_double) :: y
      end function cbrt
   end interface

   public :: hertz_geometry_t, hertz_contact_t
   public :: hertz_geometry, hertz_contact, hertz_load, curvature_difference

   !> Load-independent part of a point contact: curvature sum/difference, ellipse shape.
   type :: hertz_geometry_t
      real(wp) :: curvature_sum = 0.0_wp   !< sum rho (1/m)
      real(wp) :: curvature_diff = 0.0_wp  !< F(rho), 0 <= F < 1
      real(wp) :: kappa = 1.0_wp           !< ellipticity a/b >= 1
      real(wp) :: a_star = 1.0_wp          !< dimensionless major semi-axis
      real(wp) :: b_star = 1.0_wp          !< dimensionless minor semi-axis
      real(wp) :: delta_star = 1.0_wp      !< dimensionless approach
      real(wp) :: compliance = 0.0_wp      !< (1-nu1**2)/E1 + (1-nu2**2)/E2 (1/Pa)
      real(wp) :: stiffness = 0.0_wp       !< K_n in Q = K_n delta**1.5 (N/m**1.5)
   end type hertz_geometry_t

   !> A loaded point contact.
   type :: hertz_contact_t
      real(wp) :: load = 0.0_wp          !< normal load Q (N)
      real(wp) :: deflection = 0.0_wp    !< elastic approach delta (m)
      real(wp) :: semi_major = 0.0_wp    !< major half width a (m)
      real(wp) :: semi_minor = 0.0_wp    !< minor half width b (m)
      real(wp) :: max_pressure = 0.0_wp  !< maximum Hertz pressure (Pa)
   end type hertz_contact_t


contains

   !> Curvature difference F(rho) from the four principal curvatures (1/m).
   !>
   !> rho = [rho_I1, rho_II1, rho_I2, rho_II2]: body 1 (rolling element) in planes
   !> I and II, then body 2 (race); concave curvatures negative (Harris eq. 6.3).
   pure function curvature_difference(rho) result(f)
      real(wp), intent(in) :: rho(4)
      real(wp) :: f

      f = abs((rho(1) - rho(2)) + (rho(3) - rho(4)))/sum(rho)
   end function curvature_difference

   !> F(kappa) of the Hertz ellipse, the right-hand side of the ellipticity equation.
   pure function f_of_kappa(kappa) result(f)
      real(wp), intent(in) :: kappa
      real(wp) :: f, k, e, k2

      k2 = kappa*kappa
      call elliptic_ke(1.0_wp - 1.0_wp/k2, k, e)
      f = ((k2 + 1.0_wp)*e - 2.0_wp*k)/((k2 - 1.0_wp)*e)
   end function f_of_kappa

   !> Geometry of a point contact from curvatures (1/m) and elastic constants (Pa, -).
   !>
   !> Solves F(kappa) = F(rho) for x = log(kappa) by Newton's method (ellipticity_root,
   !> quadratic convergence to round-off, K and E of the root from its last iteration); a
   !> circular contact (F <= 1e-14) gives kappa = 1.  Where Newton does not converge, and
   !> with exhaustive = .true. (the reference of tests/test_traction_fast's bound), by
   !> bisection on log(kappa) in [0, log(1e6)] to 1e-14 (F is monotonic in kappa) with K and E
   !> of the midpoint.  The two agree within 2e-14 relative in kappa (measured over
   !> ellipticities 1 + 1e-9 .. 1e5; bisection's own resolution is 1e-14).
   !> ok is .false. when sum rho <= 0 (no convex contact) or F(rho) >= 1.
   pure subroutine hertz_geometry(rho, e1, nu1, e2, nu2, geo, ok, exhaustive)
      real(wp), intent(in) :: rho(4), e1, nu1, e2, nu2
      type(hertz_geometry_t), intent(out) :: geo
      logical, intent(out) :: ok
      logical, intent(in), optional :: exhaustive

      real(wp) :: f, lo, hi, mid, k, e, k2, y
      logical :: found
      integer :: iter

      ok = .false.
      geo%curvature_sum = sum(rho)
      if (.not. geo%curvature_sum > 0.0_wp) return
      f = curvature_difference(rho)
      geo%curvature_diff = f
      if (f >= 1.0_wp) return
      geo%compliance = (1.0_wp - nu1**2)/e1 + (1.0_wp - nu2**2)/e2

      found = .false.
      if (f <= 1.0e-14_wp) then
         geo%kappa = 1.0_wp
         call elliptic_ke(0.0_wp, k, e)
         found = .true.
      else if (.not. present(exhaustive)) then
         call ellipticity_root(f, geo%kappa, k, e, found)
      else if (.not. exhaustive) then
         call ellipticity_root(f, geo%kappa, k, e, found)
      end if
      if (.not. found) then
         lo = 0.0_wp              ! log(kappa) bracket
         hi = log(1.0e6_wp)
         do iter = 1, 200
            mid = 0.5_wp*(lo + hi)
            if (f_of_kappa(exp(mid)) > f) then
               hi = mid
            else
               lo = mid
            end if
            if (hi - lo < 1.0e-14_wp) exit
         end do
         geo%kappa = exp(0.5_wp*(lo + hi))
         call elliptic_ke(1.0_wp - 1.0_wp/geo%kappa**2, k, e)
      end if

      k2 = geo%kappa**2
      ! one cube root: b* = a* / kappa, delta* = (2 K / pi) / a*
      geo%a_star = cbrt(2.0_wp*k2*e/pi)
      geo%b_star = geo%a_star/geo%kappa
      geo%delta_star = (2.0_wp*k/pi)/geo%a_star
      ! delta = delta* (3 Q c / (2 S))**(2/3) S/2  =>  Q = K_n delta**1.5 (y**1.5 = y sqrt(y))
      y = 2.0_wp/(geo%delta_star*geo%curvature_sum)
      geo%stiffness = (2.0_wp*geo%curvature_sum/3.0_wp/geo%compliance)*(y*sqrt(y))
      ok = .true.
   end subroutine hertz_geometry

   !> The ellipticity kappa = exp(x) solving F(kappa) = f (0 < f < 1) by Newton's method on
   !> x = log(kappa) from a polynomial fit of x against log(R_y/R_x), R_y/R_x = (1 + f)/(1 - f),
   !> within 1.5e-10 for kappa 1.18 .. 94 (one evaluation of F instead of three; issue #30),
   !> elsewhere from the Hamrock-Brewe estimate kappa = 1.0339 (R_y/R_x)**0.636, and K(m),
   !> E(m) at m = 1 - 1/kappa**2.  Quadratic
   !> convergence: after a step |dx| <= 1e-9 the error of x is ~1e-18, and K, E at the new x
   !> are the last iteration's plus their first-order change (the second-order term,
   !> ~dx**2 K'' <= 1e-17, is below K's rounding).  found = .false. when Newton leaves
   !> (0, log(1e6)), takes a step |dx| >= 1, or does not converge in 20 iterations.
   pure subroutine ellipticity_root(f, kappa, k, e, found)
      real(wp), intent(in) :: f
      real(wp), intent(out) :: kappa, k, e
      logical, intent(out) :: found
      !> x(t) = log(kappa) against t = log(R_y/R_x) on [T_LO, T_HI] (kappa 1.18 .. 94): a
      !> least-squares polynomial of degree 18 in u = (2 t - T_LO - T_HI) / (T_HI - T_LO),
      !> within 1.5e-10 of the root (fitted to 4001 roots of F by scipy's K, E and brentq; 1.4e-10
      !> at 2000 other roots), so that Newton's first step is its last (|dx| <= 1e-9)
      real(wp), parameter :: T_LO = 0.25_wp, T_HI = 7.5_wp
      real(wp), parameter :: X_FIT(0:18) = [2.46869763727594638e+00_wp, 2.16705105000151255e+00_wp, &
         -1.17450783956337124e-01_wp, 3.45648784404197773e-02_wp, -3.73782428866869772e-04_wp, &
         -8.82140610420659513e-03_wp, 7.10596219323445140e-03_wp, -3.04687473187671828e-03_wp, &
         2.37211111223900860e-04_wp, 8.06263599313112797e-04_wp, -7.72722197966433494e-04_wp, &
         4.32843167031075090e-04_wp, -1.25795174067784706e-04_wp, -1.07588794578212526e-04_wp, &
         1.71208201739082286e-04_wp, -6.03130138605743061e-05_wp, -2.80596266021640021e-05_wp, &
         2.11241534850942831e-05_wp, -2.33228607233952720e-06_wp]
      real(wp) :: x, dx, g, slope, dk, de, t, u
      integer :: iter

      found = .false.
      kappa = 1.0_wp
      k = 0.0_wp
      e = 0.0_wp
      t = log((1.0_wp + f)/(1.0_wp - f))
      if (t >= T_LO .and. t <= T_HI) then
         ! the fit: Newton then stops after one evaluation (|dx| <= 1e-9 at the first)
         u = (2.0_wp*t - (T_LO + T_HI))/(T_HI - T_LO)
         x = X_FIT(18)
         do iter = 17, 0, -1
            x = X_FIT(iter) + u*x
         end do
      else
         x = log(1.0339_wp) + 0.636_wp*t
      end if
      do iter = 1, 20
         if (.not. (x > 0.0_wp .and. x < log(1.0e6_wp))) return
         call f_and_slope(x, g, slope, k, e, dk, de)
         dx = -(g - f)/slope
         if (.not. (abs(dx) < 1.0_wp)) return
         x = x + dx
         if (abs(dx) <= 1.0e-9_wp) then
            if (.not. (x > 0.0_wp .and. x < log(1.0e6_wp))) return
            kappa = exp(x)
            k = k + dk*dx
            e = e + de*dx
            found = .true.
            return
         end if
      end do
   end subroutine ellipticity_root

   !> F(kappa) and dF/dx at x = log(kappa) (kappa > 1), with K(m), E(m) and dK/dx, dE/dx:
   !> m = 1 - 1/kappa**2, dm/dx = 2 / kappa**2, dK/dm = (E - (1 - m) K) / (2 m (1 - m)),
   !> dE/dm = (E - K) / (2 m).
   pure subroutine f_and_slope(x, f, slope, k, e, dkx, dex)
      real(wp), intent(in) :: x
      real(wp), intent(out) :: f, slope, k, e, dkx, dex
      real(wp) :: k2, m, dk, de, mx, num, den

      k2 = exp(2.0_wp*x)
      m = 1.0_wp - 1.0_wp/k2
      call elliptic_ke(m, k, e)
      dk = (e - (1.0_wp - m)*k)/(2.0_wp*m*(1.0_wp - m))
      de = (e - k)/(2.0_wp*m)
      mx = 2.0_wp/k2
      num = (k2 + 1.0_wp)*e - 2.0_wp*k
      den = (k2 - 1.0_wp)*e
      f = num/den
      slope = ((2.0_wp*k2*e + (k2 + 1.0_wp)*de*mx - 2.0_wp*dk*mx)*den - num*(2.0_wp*k2*e + (k2 - 1.0_wp)*de*mx))/den**2
      dkx = dk*mx
      dex = de*mx
   end subroutine f_and_slope

   !> Loaded contact for normal load q (N) on a contact of geometry geo.
   pure function hertz_contact(geo, q) result(c)
      type(hertz_geometry_t), intent(in) :: geo
      real(wp), intent(in) :: q
      type(hertz_contact_t) :: c
      real(wp) :: scale

      c%load = max(q, 0.0_wp)
      if (c%load <= 0.0_wp) return
      scale = cbrt(1.5_wp*c%load*geo%compliance/geo%curvature_sum)
      c%semi_major = geo%a_star*scale
      c%semi_minor = geo%b_star*scale
      c%deflection = geo%delta_star*scale**2*0.5_wp*geo%curvature_sum
      c%max_pressure = 1.5_wp*c%load/(pi*c%semi_major*c%semi_minor)
   end function hertz_contact

   !> Normal load (N) for elastic approach delta (m): Q = K_n delta**1.5, 0 for delta <= 0.
   elemental function hertz_load(geo, delta) result(q)
      type(hertz_geometry_t), intent(in) :: geo
      real(wp), intent(in) :: delta
      real(wp) :: q

      q = 0.0_wp
      if (delta > 0.0_wp) q = geo%stiffness*(delta*sqrt(delta))
   end function hertz_load

end module adore_contact_hertz
