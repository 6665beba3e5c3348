!> The thermal model wired into a cylindrical roller bearing run (issues #26, #27; report
!> 2.10, 5.5; docs/thermal.md, "Roller runs"): the rollers' heat rates and their update on the
!> kinds' common adore_bearings_thermal_run (schedule, averaging by space-fixed location,
!> field solve, heat-balance check).
!>
!> Heat rates (W) at an accepted state of the roller equations of motion: each roller's
!> outer and inner race contact loss (eq 4 over its slices, adore_forces_roller_bearing's
!> loads%power), the traction loss of its ends on the outer and inner race's flanges added to
!> that race's contact (the roller end and the flange share it as a race contact does: the
!> march's partition, eq 49), its pocket loss, the guide lands' loss (into the cage, as the
!> ball's), and its drag and churning (adore_thermal_drag with the roller's length; the deck
!> gives no lubricant fraction, so 0).  Eq 18's velocity of a roller: its spin surface
!> speed |W| D / 2, W its spin relative to the orbit frame (the print's Amplitude).
!> No module state.
module adore_bearings_roller_thermal
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t
   use adore_thermal_network, only: thermal_heat_t, new_thermal_heat
   use adore_thermal_convection, only: fluid_properties_t, air_properties, lubricant_properties
   use adore_thermal_drag, only: element_fluid_loss_t, element_fluid_loss
   use adore_dynamics_roller_system, only: roller_system_t, roller_pose, ROLLER_SIZE, R_PHI
   use adore_forces_roller_bearing, only: roller_pose_t
   use adore_bearings_thermal_run, only: thermal_run_t, thermal_update, heat_by_location
   implicit none
   private

   public :: roller_heat_rates, roller_thermal_update, roller_azimuths

contains

   !> Each roller's azimuth (rad) in the packed state y of sys.
   pure function roller_azimuths(sys, y) result(phi)
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:)
      real(wp) :: phi(sys%n)
      integer :: k
      phi = [(y(ROLLER_SIZE*(k - 1) + R_PHI), k = 1, sys%n)]
   end function roller_azimuths

   !> The heat rates (W) of roller bearing b at the packed state y whose loads are sys's last
   !> evaluation's (module header), by location when th%by_location; each roller's drag and
   !> churning (th%fluid) as a side result: centre speed r phidot, spin |W|, the fluid (the
   !> lubricant for coolant type 1, air otherwise) at the coolant's temperature (the last
   !> exit temperature, the inlet's before the first field).
   subroutine roller_heat_rates(th, b, sys, y, heat)
      class(thermal_run_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:)
      type(thermal_heat_t), intent(out) :: heat
      type(fluid_properties_t) :: props
      type(roller_pose_t) :: p
      real(wp) :: t_fluid
      logical :: ok
      integer :: k, n
      n = sys%n
      heat = new_thermal_heat(n)
      do k = 1, n
         associate (ld => sys%loads(k))
            heat%outer(k) = ld%power(1) + ld%flange_race_power(1)
            heat%inner(k) = ld%power(2) + ld%flange_race_power(2)
            heat%pocket(k) = ld%pocket_power
         end associate
      end do
      heat%land = sys%land_power
      t_fluid = b%coolant%inlet_temperature
      if (th%have_field) t_fluid = th%field%exit_temperature
      do k = 1, n
         th%fluid(k) = element_fluid_loss_t()
         if (.not. (th%lubricant_fraction > 0.0_wp)) cycle
         if (b%coolant%coolant_type == 1) then
            props = lubricant_properties(b%lubricant, t_fluid)
         else
            call air_properties(max(t_fluid, 1.0_wp), props, ok)
         end if
         p = roller_pose(y, k)
         th%fluid(k) = element_fluid_loss(b%d, b%roller%roller_length, p%r*p%phidot, abs(p%spin), props, &
                                          th%lubricant_fraction)
         heat%drag(k) = th%fluid(k)%loss
      end do
      if (th%by_location) heat = heat_by_location(heat, roller_azimuths(sys, y))
   end subroutine roller_heat_rates

   !> The end of an interval (thermal_update) at the packed state y of sys: each roller at
   !> its azimuth, eq 18's velocity its spin surface speed |W| D / 2; time (s).
   subroutine roller_thermal_update(th, b, sys, y, time, error)
      class(thermal_run_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:)
      real(wp), intent(in) :: time
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: v(sys%n)
      integer :: k
      do k = 1, sys%n
         associate (p => roller_pose(y, k))
            v(k) = 0.5_wp*b%d*abs(p%spin)
         end associate
      end do
      call thermal_update(th, b, roller_azimuths(sys, y), v, time, error)
   end subroutine roller_thermal_update

end module adore_bearings_roller_thermal
