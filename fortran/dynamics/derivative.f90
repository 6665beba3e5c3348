!> The right-hand side of the integrator's y' = f(t, y) (adore_dynamics_integrator, which
!> re-exports it): an abstract type a model extends with its data and its eval, plus what
!> the linearly implicit methods and the quadrature ask of it, each with a default (no border
!> shares, no quadrature values).  No module state: the model travels in the extension.
module adore_dynamics_derivative
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: derivative_t

   !> The right-hand side of y' = f(t, y): extend it with the model data and give eval.
   type, abstract :: derivative_t
      !> why the last eval returned DERIV_FAIL (set by the extension; appended to the error)
      character(len=:), allocatable :: failure_reason
   contains
      procedure(eval_i), deferred :: eval
      procedure :: border_shares
      procedure :: n_quadrature
      procedure :: quadrature_values
      procedure :: balance_defect
   end type derivative_t

   abstract interface
      !> dydt = f(t, y) (units of y per unit of t); flag = DERIV_OK, DERIV_REJECT_STEP or DERIV_FAIL.
      subroutine eval_i(self, t, y, dydt, flag)
         import :: derivative_t, wp
         class(derivative_t), intent(inout) :: self
         real(wp), intent(in) :: t
         real(wp), intent(in) :: y(:)
         real(wp), intent(out) :: dydt(:)
         integer, intent(out) :: flag
      end subroutine eval_i
   end interface

contains

   !> The last evaluation's share of each Jacobian block in the rates of the border unknowns
   !> (adore_dynamics_block_jacobian; units of y per unit of t): a system whose border rates
   !> are sum_b p_b(y_b, y_border) + q(y_border) gives p_b in shares(:, b) (nr x nb, border
   !> and block order of set_jacobian_blocks), from which the integrator differences the
   !> border rows C_b of every block in the blocks' coloured calls.  This default has none:
   !> ok = .false., C_b is left zero (a valid but poorer W).
   subroutine border_shares(self, shares, ok)
      class(derivative_t), intent(in) :: self
      real(wp), intent(out) :: shares(:, :)
      logical, intent(out) :: ok
      shares = 0.0_wp
      ok = .false.
   end subroutine border_shares

   !> How many values the derivative wants integrated over each accepted step by the method's
   !> own quadrature (integrator_t%start_quadrature): this default, none.
   integer function n_quadrature(self)
      class(derivative_t), intent(in) :: self
      n_quadrature = 0
      if (.false.) n_quadrature = len(self%failure_reason)
   end function n_quadrature

   !> The values v (any units) to integrate over time at the derivative's last evaluation
   !> (integrator_t%start_quadrature; n_quadrature of them): this default has none.
   subroutine quadrature_values(self, v)
      class(derivative_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      v = 0.0_wp
      if (.false.) v = len(self%failure_reason)
   end subroutine quadrature_values

   !> The balance defect of a step of size h (unit of t) whose quadrature_values were g0 at its
   !> start and g1 at its end and integrate to q over it (integrator_settings_t%
   !> balance_tolerance): defect, what the step's change of a conserved or balanced quantity
   !> misses against the integral of its rates (e.g. energy change minus net power times h), and
   !> flow > 0, the step's gross flows of that quantity (same units, e.g. J), against which the
   !> integrator measures the defect.  This default: no balance (defect 0, flow 1).
   subroutine balance_defect(self, g0, g1, q, h, defect, flow)
      class(derivative_t), intent(in) :: self
      real(wp), intent(in) :: g0(:), g1(:), q(:), h
      real(wp), intent(out) :: defect, flow
      defect = 0.0_wp
      flow = 1.0_wp
      if (.false.) defect = len(self%failure_reason) + size(g0) + size(g1) + size(q) + h
   end subroutine balance_defect

end module adore_dynamics_derivative
