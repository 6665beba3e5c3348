!> Gauss-Legendre quadrature nodes and weights (used by the contact integrals, report
!> section 2.1: Gaussian quadrature in each zone between pure-rolling points).
module adore_core_quadrature
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   implicit none
   private

   public :: gauss_legendre

contains

   !> Nodes x(1:n) (ascending) and weights w(1:n) of the n-point Gauss-Legendre rule on
   !> [-1, 1]; Newton iteration on P_n from the Chebyshev guesses (n >= 1).
   pure subroutine gauss_legendre(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: z, z1, p1, p2, p3, pp
      integer :: i, j, it

      do i = 1, (n + 1)/2
         z = cos(pi*(real(i, wp) - 0.25_wp)/(real(n, wp) + 0.5_wp))
         do it = 1, 100
            p1 = 1.0_wp
            p2 = 0.0_wp
            do j = 1, n
               p3 = p2
               p2 = p1
               p1 = ((2.0_wp*j - 1.0_wp)*z*p2 - (j - 1.0_wp)*p3)/real(j, wp)
            end do
            pp = real(n, wp)*(z*p1 - p2)/(z*z - 1.0_wp)
            z1 = z
            z = z1 - p1/pp
            if (abs(z - z1) <= 4.0_wp*epsilon(1.0_wp)) exit
         end do
         x(i) = -z
         x(n + 1 - i) = z
         w(i) = 2.0_wp/((1.0_wp - z*z)*pp*pp)
         w(n + 1 - i) = w(i)
      end do
   end subroutine gauss_legendre

end module adore_core_quadrature
