!> Time averages since the start of a run (issue #20 item 5): the print's "Time Ave Wear
!> Rate" columns and section 4's "Time Average Parameters".
!>
!>     mean(t_n) = (1/t_n) integral_0^t_n f dt
!>
!> by the trapezoidal rule over the accepted steps (time-weighted: a long step counts more
!> than a short one); at t = 0 the mean is the value itself.  A NaN value (a quantity the
!> engine does not compute) makes its mean NaN.  The record is plain data owned by the
!> caller (no module state); start, add and mean allocate nothing after start.
module adore_driver_time_average
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: time_average_t

   !> Running time integrals of a vector of quantities.
   type :: time_average_t
      real(wp) :: elapsed = 0.0_wp             !< time integrated over (the caller's unit)
      real(wp), allocatable :: last(:)         !< the values at the last accepted instant
      real(wp), allocatable :: integral(:)     !< integral of each value over `elapsed`
   contains
      procedure :: start => average_start
      procedure :: add => average_add
      procedure :: add_integral => average_add_integral
      procedure :: mean => average_mean
   end type time_average_t

contains

   !> Start the averages at the values `values` of the first instant (elapsed time 0).
   subroutine average_start(self, values)
      class(time_average_t), intent(inout) :: self
      real(wp), intent(in) :: values(:)
      self%elapsed = 0.0_wp
      self%last = values
      if (allocated(self%integral)) deallocate (self%integral)
      allocate (self%integral(size(values)), source=0.0_wp)
   end subroutine average_start

   !> Add the interval dt (> 0, the caller's time unit) ending at an instant with `values`
   !> (trapezoidal rule with the previous instant's values).
   subroutine average_add(self, dt, values)
      class(time_average_t), intent(inout) :: self
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: values(:)
      self%integral = self%integral + 0.5_wp*dt*(self%last + values)
      self%last = values
      self%elapsed = self%elapsed + dt
   end subroutine average_add

   !> Add the interval dt (> 0, the caller's time unit) with the integral of each value over
   !> it given (e.g. the integrator's own quadrature, integrator_t%q_step) and the values at its
   !> end instant.
   subroutine average_add_integral(self, dt, integral, values)
      class(time_average_t), intent(inout) :: self
      real(wp), intent(in) :: dt
      real(wp), intent(in) :: integral(:), values(:)
      self%integral = self%integral + integral
      self%last = values
      self%elapsed = self%elapsed + dt
   end subroutine average_add_integral

   !> The time averages since the start into `values` (same size as the started vector).
   subroutine average_mean(self, values)
      class(time_average_t), intent(in) :: self
      real(wp), intent(out) :: values(:)
      if (self%elapsed > 0.0_wp) then
         values = self%integral/self%elapsed
      else
         values = self%last
      end if
   end subroutine average_mean

end module adore_driver_time_average
