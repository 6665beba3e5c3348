!> A block-diagonal approximation of the Jacobian df/dy for the integrator's linearly implicit
!> (Rosenbrock-W) methods, and its W = I - h gamma J factorised block by block.
!>
!> The system names its blocks: nb equally sized groups of m consecutive unknowns (first(b)
!> .. first(b) + m - 1, e.g. the 13 values of each rolling element) whose rates depend on
!> their own block and on unknowns outside every block, never directly on another block's
!> (each ball touches the races and the cage, not another ball).  Within a block only the
!> listed columns cols(:) are approximated (e.g. a ball's position and velocity, the
!> contact's stiffness and damping); the others are zero, and so is everything outside the
!> blocks: those unknowns are treated explicitly by the method.  With that structure a
!> column c of every block can be differenced at once (one derivative call for all blocks:
!> a "colouring", Curtis, Powell & Reid, IMA J. Appl. Math. 13 (1974) 117-119), so a
!> Jacobian costs size(cols) derivative calls whatever the number of blocks.
module adore_dynamics_block_jacobian
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: block_jacobian_t

   !> The blocks, their Jacobian blocks and the LU factors of I - hg J.
   type :: block_jacobian_t
      integer :: m = 0                        !< unknowns per block
      integer, allocatable :: first(:)        !< first unknown of each block
      integer, allocatable :: cols(:)         !< columns (1..m) approximated in every block
      real(wp), allocatable :: j(:, :, :)     !< (m, m, nb) df_block/dy_block (per unit of t)
      real(wp), allocatable :: lu(:, :, :)    !< (m, m, nb) LU factors of I - hg J (unit lower L), transposed
      integer, allocatable :: piv(:, :)       !< (m, nb) row interchanges of the factorisation
      real(wp) :: hg = -1.0_wp                !< h gamma of the factors (unit of t); < 0: none
   contains
      procedure :: setup
      procedure :: factor
      procedure :: solve
      procedure :: multiply
      procedure :: active
   end type block_jacobian_t

contains

   !> Blocks of m unknowns starting at first(:), columns cols(:) (1..m) approximated; J = 0.
   !> ok = .false. for blocks outside 1..n or overlapping, or columns outside 1..m.
   subroutine setup(self, n, first, m, cols, ok)
      class(block_jacobian_t), intent(inout) :: self
      integer, intent(in) :: n, first(:), m, cols(:)
      logical, intent(out) :: ok
      integer :: b, nb
      nb = size(first)
      ok = m >= 1 .and. nb >= 1 .and. size(cols) >= 1
      if (ok) ok = all(first >= 1) .and. all(first + m - 1 <= n) .and. all(cols >= 1) .and. all(cols <= m)
      do b = 2, nb
         if (ok) ok = all(abs(first(b) - first(1:b - 1)) >= m)
      end do
      if (.not. ok) return
      self%m = m
      self%first = first
      self%cols = cols
      allocate (self%j(m, m, nb), self%lu(m, m, nb), self%piv(m, nb))
      self%j = 0.0_wp
      self%hg = -1.0_wp
   end subroutine setup

   !> Whether blocks are set.
   pure logical function active(self)
      class(block_jacobian_t), intent(in) :: self
      active = allocated(self%first)
   end function active

   !> LU factors (partial pivoting) of I - hg J of every block (hg = h gamma, unit of t);
   !> ok = .false. when a block is singular.
   subroutine factor(self, hg, ok)
      class(block_jacobian_t), intent(inout) :: self
      real(wp), intent(in) :: hg
      logical, intent(out) :: ok
      integer :: b, i, k, p, m
      real(wp) :: row(self%m), a(self%m, self%m)
      m = self%m
      ok = .true.
      do b = 1, size(self%first)
         associate (piv => self%piv(:, b))
            a = -hg*self%j(:, :, b)
            do i = 1, m
               a(i, i) = a(i, i) + 1.0_wp
            end do
            do k = 1, m
               p = k - 1 + maxloc(abs(a(k:m, k)), 1)
               piv(k) = p
               if (a(p, k) == 0.0_wp) then
                  ok = .false.
                  self%hg = -1.0_wp
                  return
               end if
               if (p /= k) then
                  row = a(k, :)
                  a(k, :) = a(p, :)
                  a(p, :) = row
               end if
               a(k + 1:m, k) = a(k + 1:m, k)/a(k, k)
               ! the update column by column (contiguous): each element sees the same operations
               do i = k + 1, m
                  a(k + 1:m, i) = a(k + 1:m, i) - a(k + 1:m, k)*a(k, i)
               end do
            end do
         end associate
         self%lu(:, :, b) = transpose(a)      ! rows of the factors contiguous for solve
      end do
      self%hg = hg
   end subroutine factor

   !> v := (I - hg J)**-1 v on the blocks' unknowns (the factors of the last factor call);
   !> the unknowns outside the blocks unchanged (their W is the identity).
   subroutine solve(self, v)
      class(block_jacobian_t), intent(in) :: self
      real(wp), intent(inout) :: v(:)
      integer :: b, k, i0, m
      real(wp) :: x(self%m), s
      m = self%m
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         x = v(i0 + 1:i0 + m)
         associate (at => self%lu(:, :, b), piv => self%piv(:, b))
            do k = 1, m
               if (piv(k) /= k) then
                  s = x(k)
                  x(k) = x(piv(k))
                  x(piv(k)) = s
               end if
            end do
            do k = 2, m
               x(k) = x(k) - dot_product(at(1:k - 1, k), x(1:k - 1))
            end do
            do k = m, 1, -1
               x(k) = (x(k) - dot_product(at(k + 1:m, k), x(k + 1:m)))/at(k, k)
            end do
         end associate
         v(i0 + 1:i0 + m) = x
      end do
   end subroutine solve

   !> w := J v on the blocks' unknowns, 0 elsewhere (units of v per unit of t).
   subroutine multiply(self, v, w)
      class(block_jacobian_t), intent(in) :: self
      real(wp), intent(in) :: v(:)
      real(wp), intent(out) :: w(:)
      integer :: b, i0, m, k
      m = self%m
      w = 0.0_wp
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         ! matmul's sum in its order (from 0, column by column), written out so that it vectorises
         do k = 1, m
            w(i0 + 1:i0 + m) = w(i0 + 1:i0 + m) + self%j(:, k, b)*v(i0 + k)
         end do
      end do
   end subroutine multiply

end module adore_dynamics_block_jacobian
