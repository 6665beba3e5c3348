!> Complete elliptic integrals of the first and second kind.
module adore_core_elliptic
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   implicit none
   private

   public :: elliptic_ke

contains

   !> Complete elliptic integrals K(m) and E(m) for parameter m = e**2 in [0, 1).
   !>
   !> Arithmetic–geometric mean (Abramowitz & Stegun 17.6): K = pi/(2 AGM(1, sqrt(1-m))),
   !> E = K (1 - sum 2**(n-1) c_n**2); converges quadratically to machine precision.
   pure subroutine elliptic_ke(m, k, e)
      real(wp), intent(in) :: m    !< parameter m = e**2 (eccentricity squared), 0 <= m < 1
      real(wp), intent(out) :: k   !< K(m), first kind
      real(wp), intent(out) :: e   !< E(m), second kind

      real(wp) :: a, b, c, a_next, s, pow
      integer :: n

      a = 1.0_wp
      b = sqrt(1.0_wp - m)
      c = sqrt(m)
      s = 0.5_wp*c*c
      pow = 0.5_wp
      do n = 1, 40
         if (abs(c) <= epsilon(1.0_wp)*a) exit
         a_next = 0.5_wp*(a + b)
         c = 0.5_wp*(a - b)
         b = sqrt(a*b)
         a = a_next
         pow = 2.0_wp*pow
         s = s + pow*c*c
      end do
      k = pi/(2.0_wp*a)
      e = k*(1.0_wp - s)
   end subroutine elliptic_ke

end module adore_core_elliptic
