!> The linearly implicit methods of the integrator (issue #30 item 2): the Rosenbrock-W
!> ROS34PW2 and the additive (IMEX) ARK4(3)6L[2]SA attempts, which take the system's stiff
!> per-element blocks and their border (e.g. the inner race, issue #28) implicitly through
!> the arrowhead Jacobian (adore_dynamics_block_jacobian, forward differences, one derivative
!> call per column for all blocks and one per border unknown).  A submodule of
!> adore_dynamics_integrator: it works on integrator_t's workspace and statistics; the
!> explicit pairs, the step control and the statistics stay in the parent
!> (docs/integrator.md, "The stiff-aware method").
submodule(adore_dynamics_integrator) adore_dynamics_integrator_implicit
   implicit none

contains

   !> The linearly implicit methods' Jacobian (adore_dynamics_block_jacobian): nb blocks of m
   !> unknowns starting at first(:), whose rates depend on their own block, the border and the
   !> unknowns outside both only; columns cols(:) (1..m) of each block are differenced (one
   !> derivative call per column for all blocks); border(:), when given, the border unknowns
   !> (one call per border unknown; the border rows of the blocks from the derivative's
   !> border_shares in the blocks' calls).  Ignored by the explicit methods.
   module procedure set_jacobian_blocks
      logical :: ok
      if (.not. (self%rosenbrock .or. self%imex)) return
      call self%jac%setup(self%n, first, m, cols, ok, border)
      if (.not. ok) call engine_error(error, "integrator: Jacobian blocks outside the state, overlapping, "// &
                                      "columns outside the block (m = "//itoa(m)//"), or border unknowns "// &
                                      "outside the state, repeated or inside a block")
      self%jac_age = -1
   end procedure set_jacobian_blocks

   !> The block Jacobian at (t, y), k(:, 1) = f(t, y): forward differences, column c of every
   !> block perturbed at once by sqrt(eps) max(|y_i|, scale_i).  A column whose perturbed
   !> evaluation is refused or not finite is left zero (any W keeps a W-method's order).
   !> With a border: the blocks' border shares at (t, y) (deriv%border_shares, differenced in
   !> the blocks' calls into C_b; zero when the derivative has none) from the derivative's last
   !> evaluation when that was at the step's start (shares_at_start: first_stage or the accepted
   !> attempt's last call), else from one more call at (t, y); and one call per border unknown
   !> (B_b and D: that unknown perturbed alone).
   module procedure block_jacobian
      real(wp) :: d(size(self%jac%first)), dr
      real(wp), allocatable :: share0(:, :), share(:, :)
      integer :: c, b, i, i0, m, flag, nr
      logical :: shares_ok

      m = self%jac%m
      shares_ok = .false.
      if (self%jac%bordered()) then
         nr = size(self%jac%border)
         allocate (share0(nr, size(self%jac%first)), share(nr, size(self%jac%first)))
         ! the shares at (t, y) itself: the system's last evaluation when that was the step's
         ! first stage (first_stage or the accepted attempt's last call), else one call more
         flag = DERIV_OK
         if (.not. (self%shares_at_start .and. self%fsal_valid .and. t == self%t_fsal)) then
            call jacobian_call(t, y, flag)
         else if (any(y /= self%y_fsal)) then
            call jacobian_call(t, y, flag)
         end if
         if (allocated(error)) return
         if (flag == DERIV_OK) call deriv%border_shares(share0, shares_ok)
         if (shares_ok) shares_ok = all(ieee_is_finite(share0))
         self%jac%cj = 0.0_wp
      end if
      do c = 1, size(self%jac%cols)
         self%y_stage = y
         do b = 1, size(self%jac%first)
            i = self%jac%first(b) + self%jac%cols(c) - 1
            d(b) = sqrt(epsilon(1.0_wp))*max(abs(y(i)), self%scale(i))
            self%y_stage(i) = y(i) + d(b)
            d(b) = self%y_stage(i) - y(i)
         end do
         call jacobian_call(t, self%y_stage, flag)
         if (allocated(error)) return
         do b = 1, size(self%jac%first)
            i0 = self%jac%first(b) - 1
            if (flag == DERIV_OK .and. all(ieee_is_finite(self%k(i0 + 1:i0 + m, 2)))) then
               self%jac%j(:, self%jac%cols(c), b) = (self%k(i0 + 1:i0 + m, 2) - self%k(i0 + 1:i0 + m, 1))/d(b)
            else
               self%jac%j(:, self%jac%cols(c), b) = 0.0_wp
            end if
         end do
         if (shares_ok .and. flag == DERIV_OK) then
            call deriv%border_shares(share, shares_ok)
            if (shares_ok) shares_ok = all(ieee_is_finite(share))
            if (shares_ok) then
               do b = 1, size(self%jac%first)
                  self%jac%cj(:, self%jac%cols(c), b) = (share(:, b) - share0(:, b))/d(b)
               end do
            else
               self%jac%cj = 0.0_wp      ! all or nothing: C_b of some columns only is not kept
            end if
         end if
      end do
      if (self%jac%bordered()) then
         do c = 1, nr
            i = self%jac%border(c)
            self%y_stage = y
            self%y_stage(i) = y(i) + sqrt(epsilon(1.0_wp))*max(abs(y(i)), self%scale(i))
            dr = self%y_stage(i) - y(i)
            call jacobian_call(t, self%y_stage, flag)
            if (allocated(error)) return
            if (flag == DERIV_OK .and. all(ieee_is_finite(self%k(:, 2)))) then
               do b = 1, size(self%jac%first)
                  i0 = self%jac%first(b) - 1
                  self%jac%bj(:, c, b) = (self%k(i0 + 1:i0 + m, 2) - self%k(i0 + 1:i0 + m, 1))/dr
               end do
               self%jac%dj(:, c) = (self%k(self%jac%border, 2) - self%k(self%jac%border, 1))/dr
            else
               self%jac%bj(:, c, :) = 0.0_wp
               self%jac%dj(:, c) = 0.0_wp
            end if
         end do
      end if
      self%jac%hg = -1.0_wp
      self%jac_age = 0
      self%stats%jacobians = self%stats%jacobians + 1

   contains

      !> f(t, ys) into k(:, 2) for the Jacobian, counted; error when the derivative failed.
      subroutine jacobian_call(tc, ys, flag)
         real(wp), intent(in) :: tc
         real(wp), intent(in) :: ys(:)
         integer, intent(out) :: flag
         call deriv%eval(tc, ys, self%k(:, 2), flag)
         self%stats%derivative_calls = self%stats%derivative_calls + 1
         self%evaluated_new = .false.
         self%shares_at_start = .false.
         self%stats%jacobian_calls = self%stats%jacobian_calls + 1
         if (flag == DERIV_FAIL) &
            call self%stop_error(error, "the derivative failed (Jacobian)", t, self%h_next, deriv=deriv)
      end subroutine jacobian_call
   end procedure block_jacobian

   !> One Rosenbrock-W attempt of size h from (t, y), k(:, 1) = f(t, y) given (HNW II, IV.7
   !> eq 7.25 with the block Jacobian): stages u, y_new, the weighted error err (infinite when
   !> not finite or W is singular); when the step will be accepted (err <= 1 or accept), f at
   !> (t + h, y_new) into k(:, last), the first stage of the next step; flag from the derivative.
   module procedure attempt_rosenbrock
      real(wp) :: hg
      integer :: i, j
      logical :: ok

      err = ieee_value(err, ieee_positive_inf)
      flag = DERIV_OK
      associate (ros => self%ros, k => self%k, u => self%u, ys => self%y_stage)
         hg = h*ros%gamma
         if (self%jac%active() .and. self%jac%hg /= hg) then
            call self%jac%factor(hg, ok)
            if (.not. ok) return
         end if
         do i = 1, ros%stages
            if (i == 1) then
               u(:, 1) = hg*k(:, 1)
            else
               ys = y
               do j = 1, i - 1
                  if (ros%a(i, j) /= 0.0_wp) ys = ys + ros%a(i, j)*u(:, j)
               end do
               call eval_stage(self, deriv, t + ros%c(i)*h, ys, k(:, 2), flag, ok)
               if (.not. ok) return
               if (self%quadrature) call deriv%quadrature_values(self%g(:, i))
               u(:, i) = hg*k(:, 2)
               do j = 1, i - 1
                  if (ros%cc(i, j) /= 0.0_wp) u(:, i) = u(:, i) + (ros%gamma*ros%cc(i, j))*u(:, j)
               end do
            end if
            if (self%jac%active()) call self%jac%solve(u(:, i))
         end do
         self%y_new = y
         self%y_err = 0.0_wp
         do i = 1, ros%stages
            self%y_new = self%y_new + ros%m(i)*u(:, i)
            self%y_err = self%y_err + ros%e(i)*u(:, i)
         end do
      end associate
      call end_of_attempt(self, deriv, t, y, h, flag, err, accept)
   end procedure attempt_rosenbrock

   !> One attempt of the additive (IMEX) method of size h from (t, y), k(:, 1) = f(t, y) given:
   !> f split as J y + (f - J y) with J the block Jacobian (taken implicitly, the rest
   !> explicitly; Kennedy & Carpenter 2003).  Written for the increments z_i = Y_i - y:
   !>     (I - h gamma J) z_i = h sum_j<i ae_ij F_j + h sum_j<i (ai_ij - ae_ij) J z_j,
   !> (both tables' rows sum to c_i, the implicit one's with gamma), F_j = f(t + c_j h, y + z_j),
   !> y_new = y + h sum b_j F_j, error h sum e_j F_j; when the step will be accepted (err <= 1
   !> or accept) f at (t + h, y_new) into k(:, last).
   module procedure attempt_imex
      integer :: i, j
      logical :: ok, implicit

      err = ieee_value(err, ieee_positive_inf)
      flag = DERIV_OK
      implicit = self%jac%active()
      associate (ark => self%ark, k => self%k, jz => self%u, z => self%y_err, ys => self%y_stage)
         if (implicit .and. self%jac%hg /= h*ark%gamma) then
            call self%jac%factor(h*ark%gamma, ok)
            if (.not. ok) return
         end if
         jz(:, 1) = 0.0_wp
         do i = 2, ark%stages
            z = 0.0_wp
            do j = 1, i - 1
               if (ark%ae(i, j) /= 0.0_wp) z = z + (h*ark%ae(i, j))*k(:, j)
               if (implicit .and. j > 1) z = z + (h*(ark%ai(i, j) - ark%ae(i, j)))*jz(:, j)
            end do
            if (implicit) then
               call self%jac%solve(z)
               call self%jac%multiply(z, jz(:, i))
            else
               jz(:, i) = 0.0_wp
            end if
            ys = y + z
            call eval_stage(self, deriv, t + ark%c(i)*h, ys, k(:, i), flag, ok)
            if (.not. ok) return
            if (self%quadrature) call deriv%quadrature_values(self%g(:, i))
         end do
         self%y_new = y
         self%y_err = 0.0_wp
         do j = 1, ark%stages
            if (ark%b(j) /= 0.0_wp) self%y_new = self%y_new + (h*ark%b(j))*k(:, j)
            if (ark%e(j) /= 0.0_wp) self%y_err = self%y_err + (h*ark%e(j))*k(:, j)
         end do
      end associate
      call end_of_attempt(self, deriv, t, y, h, flag, err, accept)
   end procedure attempt_imex

   !> The end of a linearly implicit attempt (y_new and y_err set): the weighted error err
   !> (infinite when y_new is not finite) and, when the step will be accepted (err <= 1 or
   !> accept with err within settings%forced_err_cap), f at (t + h, y_new) into k(:, last), the
   !> first stage of the next step (an attempt beyond the cap is retried: no call at its end).
   subroutine end_of_attempt(self, deriv, t, y, h, flag, err, accept)
      class(integrator_t), intent(inout) :: self
      class(derivative_t), intent(inout) :: deriv
      real(wp), intent(in) :: t, h
      real(wp), intent(in) :: y(:)
      integer, intent(inout) :: flag
      real(wp), intent(inout) :: err
      logical, intent(in) :: accept
      if (.not. all(ieee_is_finite(self%y_new))) return
      err = self%weighted_error(y)
      if (.not. (err <= 1.0_wp .or. (accept .and. err <= self%settings%forced_err_cap)) .or. &
          .not. ieee_is_finite(err)) return
      call deriv%eval(t + h, self%y_new, self%k(:, self%last), flag)
      self%stats%derivative_calls = self%stats%derivative_calls + 1
      self%evaluated_new = flag == DERIV_OK
      self%shares_at_start = .false.
      self%t_new = t + h
      if (flag /= DERIV_OK) return
      if (.not. all(ieee_is_finite(self%k(:, self%last)))) err = ieee_value(err, ieee_positive_inf)
      if (self%quadrature) call deriv%quadrature_values(self%g(:, self%last))
   end subroutine end_of_attempt

   !> One stage of a linearly implicit attempt: f(t, ys) into f_out, counted in the run's
   !> statistics; ok when the derivative accepts the state and ys and f_out are finite.
   subroutine eval_stage(self, deriv, t, ys, f_out, flag, ok)
      class(integrator_t), intent(inout) :: self
      class(derivative_t), intent(inout) :: deriv
      real(wp), intent(in) :: t
      real(wp), intent(in) :: ys(:)
      real(wp), intent(out) :: f_out(:)
      integer, intent(out) :: flag
      logical, intent(out) :: ok
      call deriv%eval(t, ys, f_out, flag)
      self%stats%derivative_calls = self%stats%derivative_calls + 1
      self%evaluated_new = .false.
      self%shares_at_start = .false.
      ok = flag == DERIV_OK
      if (ok) ok = all(ieee_is_finite(f_out)) .and. all(ieee_is_finite(ys))
   end subroutine eval_stage

   !> At the first block Jacobian of an IMEX run (settings%switch_stiffness): the largest
   !> relaxation rate -J_cc of settings%switch_columns over the blocks times h_min
   !> (stats%switch_measure, dimensionless); above switch_stiffness the run goes on with
   !> ROS34PW2 from this first step - the same Jacobian, its controller exponents (error order
   !> 3) and DOPRI5's safety factor 0.9 (issue #28; the automatic method choice of LSODA,
   !> Petzold 1983, here from the Jacobian before the first step).
   module procedure stiffness_switch
      type(integrator_settings_t) :: defaults
      integer :: b, c
      real(wp) :: rate
      if (.not. allocated(self%settings%switch_columns)) return
      rate = 0.0_wp
      do b = 1, size(self%jac%j, 3)
         do c = 1, size(self%settings%switch_columns)
            associate (i => self%settings%switch_columns(c))
               if (i >= 1 .and. i <= size(self%jac%j, 1)) rate = max(rate, -self%jac%j(i, i, b))
            end associate
         end do
      end do
      self%stats%switch_measure = rate*self%settings%h_min
      if (.not. self%stats%switch_measure > self%settings%switch_stiffness) return
      self%imex = .false.
      self%rosenbrock = .true.
      self%last = self%ros%stages + 1
      self%beta = 0.2_wp/self%ros%error_order
      self%alpha = 1.0_wp/self%ros%error_order - 0.75_wp*self%beta
      self%settings%safety = defaults%safety
      self%stats%switched = .true.
   end procedure stiffness_switch

end submodule adore_dynamics_integrator_implicit
