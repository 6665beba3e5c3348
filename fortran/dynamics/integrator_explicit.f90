!> The explicit Runge-Kutta pairs' attempt (Dormand-Prince 5(4), Bogacki-Shampine 3(2): FSAL,
!> the higher order propagated; rk_tableau.f90).  A submodule of adore_dynamics_integrator:
!> it works on integrator_t's workspace; step control and statistics stay in the parent.
submodule(adore_dynamics_integrator) adore_dynamics_integrator_explicit
   implicit none

contains

   !> One attempt of size h from (t, y), k(:, 1) given: stages 2..s, y_new, the weighted error
   !> err (infinite if a stage or y_new is not finite); flag from the derivative.
   module procedure attempt
      integer :: i, j

      err = huge(1.0_wp)
      flag = DERIV_OK
      associate (tab => self%tab, k => self%k, ys => self%y_stage)
         do i = 2, tab%stages
            ys = y
            do j = 1, i - 1
               if (tab%a(i, j) /= 0.0_wp) ys = ys + (h*tab%a(i, j))*k(:, j)
            end do
            call deriv%eval(t + tab%c(i)*h, ys, k(:, i), flag)
            self%stats%derivative_calls = self%stats%derivative_calls + 1
            self%evaluated_new = .false.
            self%shares_at_start = .false.
            if (flag /= DERIV_OK) return
            if (.not. (all(ieee_is_finite(k(:, i))) .and. all(ieee_is_finite(ys)))) then
               err = ieee_value(err, ieee_positive_inf)
               return
            end if
            if (self%quadrature) call deriv%quadrature_values(self%g(:, i))
         end do
         ! FSAL pairs: the last stage is taken at y_new = y + h sum_j b_j k_j
         self%y_new = ys
         self%y_err = 0.0_wp
         do j = 1, tab%stages
            if (tab%e(j) /= 0.0_wp) self%y_err = self%y_err + (h*tab%e(j))*k(:, j)
         end do
      end associate
      err = self%weighted_error(y)
   end procedure attempt

end submodule adore_dynamics_integrator_explicit
