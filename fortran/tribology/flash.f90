!> Contact temperature rise by the moving heat source (flash temperature) model of the
!> report, sections 2.7-2.8, equal-surface-temperature case (eqs 34-36, 40-43, 49-53).
!>
!> On a strip of the contact along the rolling direction y (half width b), a heat flux
!> q(y) (W/m**2, eq 29: q = kappa u_s p) raises both surfaces, at equal temperature, by
!>     dT(y) = 1 / (sqrt(pi rho1 c1 k1 U1) + sqrt(pi rho2 c2 k2 U2))
!>             * integral_{-b}^{y} q(xi) / sqrt(y - xi) dxi                           (35)
!> With xi' = xi / b the integral is sqrt(b) times the dimensionless one, which is
!> evaluated with q linear between grid points (eqs 39-43):
!>     I_j^i = 2 [sqrt(xi_i - xi_{j-1}) - sqrt(xi_i - xi_j)]                          (40)
!>     J_j^i = 2/3 [(2 xi_i + xi_{j-1}) sqrt(xi_i - xi_{j-1}) - (2 xi_i + xi_j) sqrt(xi_i - xi_j)]  (41)
!>     S(q)_ij = (q_{j-1} - m_j xi_{j-1}) I_j^i + m_j J_j^i,  m_j = (q_j - q_{j-1}) / (xi_j - xi_{j-1})
!>       (eq 42 as printed has '+' where '=' is meant; this is the integral it defines)
!>     dT~_i = sum_{j=2}^{i} S(q)_ij                                                   (53)
!> The contact average is eq (36): (1 / (pi a b)) times the integral of dT over the ellipse.
!> On the uniform grids of the runs, I_j^i and J_j^i depend on i - j alone (J = xi_i I - K
!> with K the integral of sqrt(xi_i - xi)), so the trapezoid sum of dT~ over a strip is
!> sum_k c_k q_k with weights c computed once in O(n) (flash_trapezoid_weights): the
!> contact average then costs O(n) per strip instead of eq 53's O(n**2).
module adore_tribology_flash
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: flash_i, flash_j, flash_rise_dimensionless, strip_temperature_rise
   public :: contact_temperature_rise, flash_trapezoid_weights

   !> Uniform points per strip of the flash temperature in the runs (eqs 39-43); the
   !> contact average changes by < 0.3 % from 51 to 3201 points (docs/tribology.md)
   integer, parameter, public :: FLASH_POINTS = 201

contains

   !> Quadrature I_j^i of eq (40): integral of 1/sqrt(xi_i - xi) from xa to xb (xb <= xi_i).
   elemental function flash_i(xi_i, xa, xb) result(v)
      real(wp), intent(in) :: xi_i, xa, xb
      real(wp) :: v
      v = 2.0_wp*(sqrt(max(xi_i - xa, 0.0_wp)) - sqrt(max(xi_i - xb, 0.0_wp)))
   end function flash_i

   !> Quadrature J_j^i of eq (41): integral of xi/sqrt(xi_i - xi) from xa to xb (xb <= xi_i).
   elemental function flash_j(xi_i, xa, xb) result(v)
      real(wp), intent(in) :: xi_i, xa, xb
      real(wp) :: v
      v = 2.0_wp/3.0_wp*((2.0_wp*xi_i + xa)*sqrt(max(xi_i - xa, 0.0_wp)) &
                         - (2.0_wp*xi_i + xb)*sqrt(max(xi_i - xb, 0.0_wp)))
   end function flash_j

   !> Dimensionless temperature rise dT~_i = sum_{j=2}^{i} S(q)_ij (eq 53) on an ascending
   !> grid xi(1:n) for the flux values q(1:n), q linear between grid points (eq 39).
   pure subroutine flash_rise_dimensionless(xi, q, dt)
      real(wp), intent(in) :: xi(:), q(:)
      real(wp), intent(out) :: dt(size(xi))
      real(wp) :: slope
      integer :: i, j

      dt = 0.0_wp
      do i = 2, size(xi)
         do j = 2, i
            slope = (q(j) - q(j - 1))/(xi(j) - xi(j - 1))
            dt(i) = dt(i) + (q(j - 1) - slope*xi(j - 1))*flash_i(xi(i), xi(j - 1), xi(j)) &
                    + slope*flash_j(xi(i), xi(j - 1), xi(j))
         end do
      end do
   end subroutine flash_rise_dimensionless

   !> Weights c(1:n) of the uniform grid xi_i = -1 + (i - 1) d, d = 2 / (n - 1) (n >= 2):
   !> sum_i t_i dT~_i = sum_k c_k q_k for the dimensionless rise of eq 53 with q linear
   !> between grid points, t_i the trapezoid weights (1/2 at both ends, 1 inside).  With
   !> m = i - j: eq 53's term is q_{j-1} (A_m - B_m) + q_j B_m, A_m = I_j^i (eq 40) and
   !> B_m = ((m + 1) d A_m - K_m) / d, K_m = 2/3 (((m + 1) d)**1.5 - (m d)**1.5).
   pure subroutine flash_trapezoid_weights(n, c)
      integer, intent(in) :: n
      real(wp), intent(out) :: c(n)
      real(wp) :: d, a(0:n - 2), bm(0:n - 2), pa(0:n - 2), pb(0:n - 2), t_ab, t_b
      integer :: m, j

      c = 0.0_wp
      if (n < 2) return
      d = 2.0_wp/real(n - 1, wp)
      do m = 0, n - 2
         a(m) = 2.0_wp*(sqrt(real(m + 1, wp)*d) - sqrt(real(m, wp)*d))
         bm(m) = (real(m + 1, wp)*d*a(m) - 2.0_wp/3.0_wp*((real(m + 1, wp)*d)**1.5_wp - (real(m, wp)*d)**1.5_wp))/d
      end do
      ! prefix sums over m of A - B and B
      pa(0) = a(0) - bm(0)
      pb(0) = bm(0)
      do m = 1, n - 2
         pa(m) = pa(m - 1) + (a(m) - bm(m))
         pb(m) = pb(m - 1) + bm(m)
      end do
      do j = 2, n
         m = n - j
         t_ab = pa(m) - 0.5_wp*(a(m) - bm(m))       ! sum over i = j..n of t_i (A - B)_{i-j}
         t_b = pb(m) - 0.5_wp*bm(m)
         c(j - 1) = c(j - 1) + t_ab
         c(j) = c(j) + t_b
      end do
   end subroutine flash_trapezoid_weights

   !> Temperature rise dT (K) along one strip of half width b (m), eq (35): grid xi(1:n)
   !> in [-1, 1] (y = b xi, the heat source enters at -1), flux q (W/m**2); u1, u2 surface
   !> speeds (m/s) of the two bodies relative to the contact; th1, th2 = [density (kg/m**3),
   !> heat capacity (J/kg/K), conductivity (W/m/K)] of the two bodies.
   pure subroutine strip_temperature_rise(b, xi, q, u1, u2, th1, th2, dt)
      real(wp), intent(in) :: b, xi(:), q(:), u1, u2, th1(3), th2(3)
      real(wp), intent(out) :: dt(size(xi))
      real(wp) :: denom

      call flash_rise_dimensionless(xi, q, dt)
      denom = sqrt(pi*th1(1)*th1(2)*th1(3)*abs(u1)) + sqrt(pi*th2(1)*th2(2)*th2(3)*abs(u2))
      dt = sqrt(b)*dt/denom
   end subroutine strip_temperature_rise

   !> Average (eq 36) and largest temperature rise (K) of an elliptical contact: semi-axes
   !> a (major, across rolling) and b (minor, rolling direction) in m, max Hertz pressure
   !> p0 (Pa).  Strips at major-axis positions xk (m) with quadrature weights wk (m) carry
   !> the heat factor g = kappa |u_s| (m/s), so q = g p (eq 29) with the Hertz pressure
   !> p = p0 sqrt(1 - (x/a)**2 - (y/b)**2); ny >= 2 uniform points per strip.
   !> u1, u2, th1, th2 as in strip_temperature_rise.  Without dt_max the average alone, by
   !> the trapezoid weights of flash_trapezoid_weights (O(ny) per strip, the same sum).
   subroutine contact_temperature_rise(a, b, p0, xk, wk, g, u1, u2, th1, th2, ny, dt_avg, dt_max, error)
      real(wp), intent(in) :: a, b, p0, xk(:), wk(:), g(:), u1, u2, th1(3), th2(3)
      integer, intent(in) :: ny
      real(wp), intent(out) :: dt_avg
      real(wp), intent(out), optional :: dt_max
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: xi(:), q(:), dt(:), cw(:)
      real(wp) :: ek, bk, strip, denom
      integer :: k, i

      dt_avg = 0.0_wp
      if (present(dt_max)) dt_max = 0.0_wp
      if (.not. (a > 0.0_wp .and. b > 0.0_wp .and. p0 >= 0.0_wp .and. ny >= 2)) then
         call input_error(error, "contact temperature: need a, b > 0, p0 >= 0 and at least 2 points per strip")
         return
      end if
      if (size(wk) /= size(xk) .or. size(g) /= size(xk)) then
         call input_error(error, "contact temperature: strip positions, weights and heat factors differ in length")
         return
      end if
      if (.not. (minval(th1) > 0.0_wp .and. minval(th2) > 0.0_wp .and. abs(u1) + abs(u2) > 0.0_wp)) then
         call input_error(error, "contact temperature: need positive thermal properties and a moving surface")
         return
      end if
      allocate (xi(ny), q(ny), dt(ny), cw(ny))
      xi = [(-1.0_wp + 2.0_wp*real(i - 1, wp)/real(ny - 1, wp), i=1, ny)]
      if (.not. present(dt_max)) call flash_trapezoid_weights(ny, cw)
      denom = sqrt(pi*th1(1)*th1(2)*th1(3)*abs(u1)) + sqrt(pi*th2(1)*th2(2)*th2(3)*abs(u2))
      do k = 1, size(xk)
         ek = 1.0_wp - (xk(k)/a)**2
         if (ek <= 0.0_wp) cycle
         bk = b*sqrt(ek)
         q = g(k)*p0*sqrt(ek)*sqrt(max(1.0_wp - xi**2, 0.0_wp))
         if (present(dt_max)) then
            call strip_temperature_rise(bk, xi, q, u1, u2, th1, th2, dt)
            ! trapezoid over y = bk xi
            strip = bk*(sum(dt) - 0.5_wp*(dt(1) + dt(ny)))*(xi(2) - xi(1))
            dt_max = max(dt_max, maxval(dt))
         else
            strip = bk*sqrt(bk)*dot_product(cw, q)/denom*(xi(2) - xi(1))
         end if
         dt_avg = dt_avg + wk(k)*strip
      end do
      dt_avg = dt_avg/(pi*a*b)
   end subroutine contact_temperature_rise

end module adore_tribology_flash
