!> A block-diagonal approximation of the Jacobian df/dy for the integrator's linearly implicit
!> methods (Rosenbrock-W, IMEX), bordered by a few coupling unknowns (an "arrowhead"), and its
!> W = I - h gamma J factorised block by block with the border by its Schur complement.
!>
!> The system names its blocks: nb equally sized groups of m consecutive unknowns (first(b)
!> .. first(b) + m - 1, e.g. the 13 values of each rolling element) whose rates depend on
!> their own block, on the border unknowns and on unknowns outside both, never directly on
!> another block's (each ball touches the races and the cage, not another ball).  Within a
!> block only the listed columns cols(:) are approximated (e.g. a ball's position and
!> velocity, the contact's stiffness and damping); the others are zero.  With that structure a
!> column c of every block can be differenced at once (one derivative call for all blocks:
!> a "colouring", Curtis, Powell & Reid, IMA J. Appl. Math. 13 (1974) 117-119), so the blocks
!> cost size(cols) derivative calls whatever the number of blocks.
!>
!> The border (optional): nr unknowns border(:) outside every block (e.g. the inner race's
!> translation, which every ball touches).  J then has, besides the blocks A_b, the columns
!> B_b = df_b/dy_r (m x nr, every row of the block), the rows C_b = df_r/dy_b (nr x m, the
!> columns cols(:)) and the corner D = df_r/dy_r (nr x nr): an arrowhead matrix
!>     J = [ A_1          B_1 ]
!>         [      ...     ... ]
!>         [          A_nb B_nb]
!>         [ C_1 ... C_nb  D  ].
!> W x = v is solved by the Schur complement of the border (Golub & Van Loan, Matrix
!> Computations, 4th ed., 3.2.11 and 4.5.5 "block tridiagonal/arrowhead" elimination):
!>     E_b = (I - hg A_b)**-1 (hg B_b),   S = I - hg D - hg sum_b C_b E_b   (nr x nr),
!>     w_b = (I - hg A_b)**-1 v_b,   S x_r = v_r + hg sum_b C_b w_b,   x_b = w_b + E_b x_r.
!> Everything outside the blocks and the border is zero in J (treated explicitly).
module adore_dynamics_block_jacobian
   use adore_core_kinds, only: wp
   use adore_core_threads, only: team_join, team_t, team_threads, team_note, wall_seconds
   implicit none
   private

   public :: block_jacobian_t

   !> The blocks, the border, their Jacobian parts and the factors of I - hg J.
   type :: block_jacobian_t
      integer :: m = 0                        !< unknowns per block
      integer, allocatable :: first(:)        !< first unknown of each block
      integer, allocatable :: cols(:)         !< columns (1..m) approximated in every block
      real(wp), allocatable :: j(:, :, :)     !< (m, m, nb) A_b = df_block/dy_block (per unit of t)
      real(wp), allocatable :: lu(:, :, :)    !< (m, m, nb) LU factors of I - hg A_b (unit lower L), transposed
      integer, allocatable :: piv(:, :)       !< (m, nb) row interchanges of the factorisation
      real(wp) :: hg = -1.0_wp                !< h gamma of the factors (unit of t); < 0: none
      integer, allocatable :: border(:)       !< (nr) the border unknowns; not allocated: no border
      real(wp), allocatable :: bj(:, :, :)    !< (m, nr, nb) B_b = df_block/dy_border
      real(wp), allocatable :: cj(:, :, :)    !< (nr, m, nb) C_b = df_border/dy_block (columns cols only)
      real(wp), allocatable :: dj(:, :)       !< (nr, nr) D = df_border/dy_border
      real(wp), allocatable :: e(:, :, :)     !< (m, nr, nb) E_b = (I - hg A_b)**-1 hg B_b
      real(wp), allocatable :: slu(:, :)      !< (nr, nr) LU factors of the Schur complement S, transposed
      integer, allocatable :: spiv(:)         !< (nr) its row interchanges
      !> threads of factor's per-block work (OpenMP; the run option threads, adore_core_threads):
      !> every block's factors, E_b and C_b E_b into its own slots, S summed after them in block
      !> order, so the factors are the same bit for bit on any number of threads
      integer :: threads = 1
      !> the choice between those threads and one for each factorisation, measured (team_t)
      type(team_t) :: team
   contains
      procedure :: setup
      procedure :: factor
      procedure :: solve
      procedure :: multiply
      procedure :: active
      procedure :: bordered
   end type block_jacobian_t

contains

   !> Blocks of m unknowns starting at first(:) of a state of n unknowns, columns cols(:) (1..m)
   !> approximated; border(:) (optional) the border unknowns; J = 0.  ok = .false. for blocks
   !> outside 1..n or overlapping, columns outside 1..m, or border unknowns outside 1..n,
   !> repeated or inside a block.
   subroutine setup(self, n, first, m, cols, ok, border)
      class(block_jacobian_t), intent(inout) :: self
      integer, intent(in) :: n, first(:), m, cols(:)
      logical, intent(out) :: ok
      integer, intent(in), optional :: border(:)
      integer :: b, nb, i, nr
      nb = size(first)
      ok = m >= 1 .and. nb >= 1 .and. size(cols) >= 1
      if (ok) ok = all(first >= 1) .and. all(first + m - 1 <= n) .and. all(cols >= 1) .and. all(cols <= m)
      do b = 2, nb
         if (ok) ok = all(abs(first(b) - first(1:b - 1)) >= m)
      end do
      if (present(border)) then
         nr = size(border)
         if (ok) ok = nr >= 1
         if (ok) ok = all(border >= 1) .and. all(border <= n)
         do i = 1, nr
            if (.not. ok) exit
            ok = count(border == border(i)) == 1 .and. .not. any(border(i) >= first .and. border(i) <= first + m - 1)
         end do
      end if
      if (.not. ok) return
      self%m = m
      self%first = first
      self%cols = cols
      allocate (self%j(m, m, nb), self%lu(m, m, nb), self%piv(m, nb))
      self%j = 0.0_wp
      self%hg = -1.0_wp
      if (present(border)) then
         self%border = border
         allocate (self%bj(m, nr, nb), self%cj(nr, m, nb), self%dj(nr, nr), self%e(m, nr, nb), self%slu(nr, nr), &
                   self%spiv(nr))
         self%bj = 0.0_wp
         self%cj = 0.0_wp
         self%dj = 0.0_wp
      end if
   end subroutine setup

   !> Whether blocks are set.
   pure logical function active(self)
      class(block_jacobian_t), intent(in) :: self
      active = allocated(self%first)
   end function active

   !> Whether a border is set.
   pure logical function bordered(self)
      class(block_jacobian_t), intent(in) :: self
      bordered = allocated(self%border)
   end function bordered

   !> LU factors (partial pivoting) of I - hg A_b of every block (hg = h gamma, unit of t) and,
   !> with a border, E_b and the factors of the Schur complement S (module header);
   !> ok = .false. when a block or S is singular.  The blocks on self%threads threads or on
   !> one, whichever self%team measured faster.
   subroutine factor(self, hg, ok)
      class(block_jacobian_t), intent(inout) :: self
      real(wp), intent(in) :: hg
      logical, intent(out) :: ok
      integer :: b, i, nr, nb, arrived, threads
      real(wp) :: start
      logical :: ok_b(size(self%first))
      real(wp), allocatable :: s(:, :), ce(:, :, :)
      nb = size(self%first)
      nr = 0
      if (self%bordered()) nr = size(self%border)
      allocate (ce(nr, nr, nb))
      ! the run's threads or one, whichever the last measured windows found faster (team_t)
      threads = team_threads(self%team, self%threads)
      start = 0.0_wp
      if (self%threads > 1) start = wall_seconds()
      if (threads > 1) then
         ! (as adore_forces_ball_bearing's loop: dynamic, the first thread joins last)
         arrived = 0
         !$omp parallel num_threads(threads) default(shared) private(b)
         !$omp do schedule(dynamic, 1)
         do b = 1, nb
            call factor_block(b)
         end do
         !$omp end do nowait
         call team_join(arrived)
         !$omp end parallel
      else
         do b = 1, nb
            call factor_block(b)
         end do
      end if
      if (self%threads > 1) call team_note(self%team, self%threads, wall_seconds() - start)
      ok = all(ok_b)
      if (.not. ok) then
         self%hg = -1.0_wp
         return
      end if
      if (self%bordered()) then
         s = -hg*self%dj
         do i = 1, nr
            s(i, i) = s(i, i) + 1.0_wp
         end do
         do b = 1, nb
            s = s - hg*ce(:, :, b)
         end do
         call lu_factor(s, self%spiv, ok)
         if (.not. ok) then
            self%hg = -1.0_wp
            return
         end if
         self%slu = transpose(s)
      end if
      self%hg = hg

   contains

      !> Block b: the LU factors of I - hg A_b (transposed, into lu(:, :, b)) and with a
      !> border E_b and C_b E_b (into ce(:, :, b)); ok_b(b).  One thread per block.
      subroutine factor_block(b)
         integer, intent(in) :: b
         real(wp) :: a(self%m, self%m)
         integer :: i, k, l, m
         m = self%m
         a = -hg*self%j(:, :, b)
         do i = 1, m
            a(i, i) = a(i, i) + 1.0_wp
         end do
         call lu_factor(a, self%piv(:, b), ok_b(b))
         if (.not. ok_b(b)) return
         self%lu(:, :, b) = transpose(a)      ! rows of the factors contiguous for solve
         if (nr == 0) return
         do k = 1, nr
            self%e(:, k, b) = hg*self%bj(:, k, b)
            call lu_solve(m, self%lu(:, :, b), self%piv(:, b), self%e(:, k, b))
         end do
         ! C_b E_b in matmul's order (each element summed from 0 over the block's unknowns)
         do k = 1, nr
            ce(:, k, b) = 0.0_wp
            do l = 1, m
               ce(:, k, b) = ce(:, k, b) + self%cj(:, l, b)*self%e(l, k, b)
            end do
         end do
      end subroutine factor_block
   end subroutine factor

   !> v := (I - hg J)**-1 v on the blocks' and the border's unknowns (the factors of the last
   !> factor call; module header); the other unknowns unchanged (their W is the identity).
   subroutine solve(self, v)
      class(block_jacobian_t), intent(in) :: self
      real(wp), intent(inout), contiguous :: v(:)
      integer :: b, i0, m, k, l, nr
      real(wp) :: r(border_size(self)), p(border_size(self))
      m = self%m
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         call lu_solve(m, self%lu(:, :, b), self%piv(:, b), v(i0 + 1:i0 + m))
      end do
      if (.not. self%bordered()) return
      nr = size(self%border)
      r = v(self%border)
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         ! r + hg matmul(C_b, w_b), the product in matmul's order
         p = 0.0_wp
         do l = 1, m
            p = p + self%cj(:, l, b)*v(i0 + l)
         end do
         r = r + self%hg*p
      end do
      call lu_solve(nr, self%slu, self%spiv, r)
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         ! w_b + matmul(E_b, x_r), the product in matmul's order
         associate (x => v(i0 + 1:i0 + m))
            block
               real(wp) :: q(m)
               q = 0.0_wp
               do k = 1, nr
                  q = q + self%e(:, k, b)*r(k)
               end do
               x = x + q
            end block
         end associate
      end do
      v(self%border) = r
   end subroutine solve

   !> w := J v on the blocks' and the border's unknowns, 0 elsewhere (units of v per unit of t).
   subroutine multiply(self, v, w)
      class(block_jacobian_t), intent(in) :: self
      real(wp), intent(in), contiguous :: v(:)
      real(wp), intent(out), contiguous :: w(:)
      integer :: b, i0, m, k, nr
      real(wp) :: vr(border_size(self)), wr(border_size(self)), p(border_size(self)), q(self%m)
      m = self%m
      w = 0.0_wp
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         ! matmul's sum in its order (from 0, column by column), written out so that it vectorises
         do k = 1, m
            w(i0 + 1:i0 + m) = w(i0 + 1:i0 + m) + self%j(:, k, b)*v(i0 + k)
         end do
      end do
      if (.not. self%bordered()) return
      nr = size(self%border)
      vr = v(self%border)
      ! the products below in matmul's order (each element summed from 0, column by column)
      wr = 0.0_wp
      do k = 1, nr
         wr = wr + self%dj(:, k)*vr(k)
      end do
      do b = 1, size(self%first)
         i0 = self%first(b) - 1
         q = 0.0_wp
         do k = 1, nr
            q = q + self%bj(:, k, b)*vr(k)
         end do
         w(i0 + 1:i0 + m) = w(i0 + 1:i0 + m) + q
         p = 0.0_wp
         do k = 1, m
            p = p + self%cj(:, k, b)*v(i0 + k)
         end do
         wr = wr + p
      end do
      w(self%border) = wr
   end subroutine multiply

   !> The number of border unknowns (0 without a border).
   pure integer function border_size(self) result(nr)
      class(block_jacobian_t), intent(in) :: self
      nr = 0
      if (allocated(self%border)) nr = size(self%border)
   end function border_size

   !> In-place LU factorisation with partial pivoting of the square a (unit lower L below the
   !> diagonal, U on and above), row interchanges in piv; ok = .false. when a is singular.
   subroutine lu_factor(a, piv, ok)
      real(wp), intent(inout) :: a(:, :)
      integer, intent(out) :: piv(:)
      logical, intent(out) :: ok
      integer :: i, k, p, m
      real(wp) :: row(size(a, 1))
      m = size(a, 1)
      ok = .true.
      do k = 1, m
         p = k - 1 + maxloc(abs(a(k:m, k)), 1)
         piv(k) = p
         if (a(p, k) == 0.0_wp) then
            ok = .false.
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
   end subroutine lu_factor

   !> x := A**-1 x for the factors at (m x m, lu_factor's result, transposed) and interchanges
   !> piv.  Explicit shapes (contiguous): the sums are dot_product's, from 0 in index order.
   pure subroutine lu_solve(m, at, piv, x)
      integer, intent(in) :: m
      real(wp), intent(in) :: at(m, m)
      integer, intent(in) :: piv(m)
      real(wp), intent(inout) :: x(m)
      integer :: k, j
      real(wp) :: s
      do k = 1, m
         if (piv(k) /= k) then
            s = x(k)
            x(k) = x(piv(k))
            x(piv(k)) = s
         end if
      end do
      do k = 2, m
         s = 0.0_wp
         do j = 1, k - 1
            s = s + at(j, k)*x(j)
         end do
         x(k) = x(k) - s
      end do
      do k = m, 1, -1
         s = 0.0_wp
         do j = k + 1, m
            s = s + at(j, k)*x(j)
         end do
         x(k) = (x(k) - s)/at(k, k)
      end do
   end subroutine lu_solve

end module adore_dynamics_block_jacobian
