!> Small dense linear algebra for the equilibrium solvers (ADRG0's role in ADORE).
module adore_core_linalg
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: solve_dense

contains

   !> Solve a x = b for a small dense n x n system by Gaussian elimination with partial
   !> pivoting.  ok is .false. when a pivot vanishes (singular to working precision).
   pure subroutine solve_dense(n, a, b, x, ok)
      integer, intent(in) :: n
      real(wp), intent(in) :: a(n, n), b(n)
      real(wp), intent(out) :: x(n)
      logical, intent(out) :: ok

      real(wp) :: m(n, n), r(n), row(n), tmp, scale
      integer :: i, k, p

      m = a
      r = b
      x = 0.0_wp
      ok = .false.
      scale = maxval(abs(m))
      if (scale <= 0.0_wp) return
      do k = 1, n
         p = k - 1 + maxloc(abs(m(k:n, k)), dim=1)
         if (abs(m(p, k)) <= 1.0e3_wp*epsilon(1.0_wp)*scale) return
         if (p /= k) then
            row = m(k, :)
            m(k, :) = m(p, :)
            m(p, :) = row
            tmp = r(k)
            r(k) = r(p)
            r(p) = tmp
         end if
         do i = k + 1, n
            tmp = m(i, k)/m(k, k)
            m(i, k:n) = m(i, k:n) - tmp*m(k, k:n)
            r(i) = r(i) - tmp*r(k)
         end do
      end do
      do k = n, 1, -1
         x(k) = (r(k) - dot_product(m(k, k + 1:n), x(k + 1:n)))/m(k, k)
      end do
      ok = .true.
   end subroutine solve_dense

end module adore_core_linalg
