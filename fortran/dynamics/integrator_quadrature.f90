!> The method's own quadrature of a derivative's values over each accepted step (issue #28:
!> the balance window's means, adore_driver_time_loop): the values at every stage, weighted
!> as the method weights its stages' derivatives.  A submodule of adore_dynamics_integrator
!> (docs/integrator.md, "Quadrature of the derivative's values").
submodule(adore_dynamics_integrator) adore_dynamics_integrator_quadrature
   implicit none

contains

   !> From the next step on, integrate the derivative's quadrature_values g(y) over every
   !> accepted step (q_step: the integral, units of g times the unit of t) with the method's own
   !> weights at its stages, as if q' = g(y) were unknowns of the state outside the error test
   !> and the Jacobian: h sum_i b_i g(Y_i) for the Runge-Kutta and IMEX pairs, the
   !> Rosenbrock-W recursion with J = 0 for ROS34PW2 (HNW II, IV.7 eq 7.25).  The integral of a
   !> rate is then consistent with the state's change to the method's order, where the values at
   !> the steps' ends sample whatever the steps do not resolve (issue #28: the drive power of a
   !> race contact's fast torque).  g0: the values at the state the next step starts from (the
   !> last evaluation's, the accepted state's).
   module procedure start_quadrature
      if (allocated(self%g)) deallocate (self%g)
      if (allocated(self%q_step)) deallocate (self%q_step)
      allocate (self%g(size(g0), size(self%k, 2)), source=0.0_wp)
      allocate (self%q_step(size(g0)), source=0.0_wp)
      self%g(:, 1) = g0
      self%quadrature = size(g0) > 0
   end procedure start_quadrature

   !> Whether the method's stage quadrature (start_quadrature) is consistent with the way its
   !> steps move the state, also where the steps pass over stiff modes: the IMEX method, whose
   !> step is y + h sum_i b_i f(Y_i) at stages its implicit part keeps bounded.  Not an explicit
   !> pair at its stability limit (its stages carry stiff components the step's weights cancel
   !> and a nonlinear g does not: the deep-groove ISO example 3 at 10 000 rpm, DP5's dissipation
   !> 22 % low), nor the Rosenbrock-W method, whose step is no weighted sum of f at its stages (it
   !> carries (I - h gamma J)**-1; test_quadrature_closes_the_energy: closure 0.6-1.2 on stiff
   !> oscillators where the steps' ends close within 1e-5).  For those the values at the steps'
   !> ends (their trapezoid) are the better mean (adore_driver_time_loop).
   module procedure quadrature_consistent
      quadrature_consistent = self%imex
   end procedure quadrature_consistent

   !> The quadrature of g over the accepted step of size h into q_step (start_quadrature).
   module procedure step_quadrature
      real(wp), allocatable :: uq(:, :)
      integer :: i, j
      self%q_step = 0.0_wp
      if (self%rosenbrock) then
         ! the W-method on q' = g with zero rows and columns of J for q: W = I
         allocate (uq(size(self%g, 1), self%ros%stages))
         do i = 1, self%ros%stages
            uq(:, i) = (h*self%ros%gamma)*self%g(:, i)
            do j = 1, i - 1
               if (self%ros%cc(i, j) /= 0.0_wp) uq(:, i) = uq(:, i) + (self%ros%gamma*self%ros%cc(i, j))*uq(:, j)
            end do
            self%q_step = self%q_step + self%ros%m(i)*uq(:, i)
         end do
      else if (self%imex) then
         do j = 1, self%ark%stages
            if (self%ark%b(j) /= 0.0_wp) self%q_step = self%q_step + (h*self%ark%b(j))*self%g(:, j)
         end do
      else
         do j = 1, self%tab%stages
            if (self%tab%b(j) /= 0.0_wp) self%q_step = self%q_step + (h*self%tab%b(j))*self%g(:, j)
         end do
      end if
   end procedure step_quadrature

   !> The power-balance control's error ratio of an attempt of size h (settings%
   !> balance_tolerance; issue #28): the derivative's balance_defect from the values at the
   !> step's ends and their integral over it - the stage quadrature where it is consistent with
   !> the method's steps (quadrature_consistent: the IMEX method), else the trapezoid of the
   !> ends, the integral the balance window takes (adore_driver_time_loop) - as r = |defect| /
   !> (tolerance * flow).  Only for an attempt the error test accepted: the implicit methods
   !> evaluate the step's end only then.  The stage quadrature's defect of a step of order p
   !> shrinks as h**(p+1) and the flow as h, as the embedded error estimate does; the
   !> trapezoid's defect as h**3, r as h**2, so there the ratio is r**(1/(2 alpha)), which
   !> shrinks as the controller's exponent alpha assumes (and is 1 where r is).  Leaves q_step at
   !> the attempt's integral.
   module procedure balance_error
      real(wp) :: defect, flow
      logical :: consistent
      consistent = self%quadrature_consistent()
      if (consistent) then
         call step_quadrature(self, h)
      else
         self%q_step = (0.5_wp*h)*(self%g(:, 1) + self%g(:, self%last))
      end if
      call deriv%balance_defect(self%g(:, 1), self%g(:, self%last), self%q_step, h, defect, flow)
      balance_error = abs(defect)/(self%settings%balance_tolerance*max(flow, tiny(1.0_wp)))
      if (.not. consistent) balance_error = balance_error**(0.5_wp/self%alpha)
   end procedure balance_error

end submodule adore_dynamics_integrator_quadrature
