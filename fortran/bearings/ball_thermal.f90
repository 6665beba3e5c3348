!> The thermal model wired into a ball bearing run (issue #27; report 2.10, 5.3, 5.5): the
!> ball's heat rates and its update; the schedule, the averaging (by space-fixed location by
!> default), the field solve and the heat-balance check are the kinds' common
!> adore_bearings_thermal_run (bearings/thermal_run.f90), re-exported here under the names
!> the ball kind uses.
!>
!> The run's event hook (adore_bearings_system's on_event, every `interval` seconds) calls
!> ball_thermal_update; the ball kind (adore_bearings_ball) then sets the new bulk
!> temperatures as its operating condition and, in THERMAL_GEOMETRY mode from the geometry
!> start time (Rec 2.5 field 5) on, mounts the geometry at them (ADRC2) with the load-holding
!> constraint.  The deck fields and the modes: docs/thermal.md, "The wiring".
!>
!> Heat rates (W) at an accepted state: each ball's outer and inner race contact loss
!> (the force assembly's loads%heat), its pocket's power, all guide lands' power, the
!> ball's drag and churning loss; integrated over time by the trapezoidal rule between
!> accepted instants (the first interval of a run starts with a rectangle from t = 0).
!> No module state: the record is part of the ball kind.
module adore_bearings_ball_thermal
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t
   use adore_state_bearing_state, only: bearing_state_t, body_azimuth
   use adore_forces_ball_bearing, only: ball_bearing_loads_t
   use adore_thermal_network, only: thermal_heat_t, new_thermal_heat
   use adore_thermal_convection, only: fluid_properties_t, lubricant_properties
   use adore_thermal_drag, only: element_fluid_loss_t, element_fluid_loss
   use adore_bearings_thermal_run, only: thermal_run_t, new_thermal_run, thermal_mode_of, thermal_update, &
                                         heat_total, location_weights, heat_by_location, THERMAL_OFF, &
                                         THERMAL_TEMPERATURES, THERMAL_GEOMETRY, &
                                         ball_thermal_accumulate => thermal_accumulate
   implicit none
   private

   public :: ball_thermal_t, new_ball_thermal, thermal_mode_of, ball_heat_rates, ball_thermal_accumulate
   public :: ball_thermal_update, heat_total, location_weights, heat_by_location
   public :: THERMAL_OFF, THERMAL_TEMPERATURES, THERMAL_GEOMETRY

   !> A ball run's thermal model (adore_bearings_thermal_run's record).
   type, extends(thermal_run_t) :: ball_thermal_t
   end type ball_thermal_t

contains

   !> The thermal model of bearing b in mode `mode` (new_thermal_run).
   function new_ball_thermal(b, mode) result(th)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: mode
      type(ball_thermal_t) :: th
      th%thermal_run_t = new_thermal_run(b, mode)
   end function new_ball_thermal

   !> The heat rates (W) of ball bearing b at state s with the force assembly's loads
   !> there (module header); each ball's drag and churning (th%fluid) as a side result:
   !> centre speed = orbital speed x pitch radius, spin = |omega|, the lubricant at the
   !> coolant's temperature (the last exit temperature, the inlet's before the first field).
   subroutine ball_heat_rates(th, b, s, loads, heat)
      type(ball_thermal_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      type(thermal_heat_t), intent(out) :: heat
      type(fluid_properties_t) :: props
      real(wp) :: t_fluid, v, r2
      integer :: k, n
      n = b%n_elements
      heat = new_thermal_heat(n)
      heat%outer = loads%heat(1, :)
      heat%inner = loads%heat(2, :)
      if (allocated(loads%pockets)) then
         if (size(loads%pockets) == n) heat%pocket = loads%pockets%power
      end if
      if (allocated(loads%lands)) heat%land = sum(loads%lands%power)
      t_fluid = b%coolant%inlet_temperature
      if (th%have_field) t_fluid = th%field%exit_temperature
      do k = 1, n
         th%fluid(k) = element_fluid_loss_t()
         if (.not. (th%lubricant_fraction > 0.0_wp .and. b%lubricant%density > 0.0_wp)) cycle
         props = lubricant_properties(b%lubricant, t_fluid)
         associate (e => s%elements(k))
            r2 = e%position(2)**2 + e%position(3)**2
            v = 0.0_wp
            if (r2 > 0.0_wp) v = (e%position(2)*e%velocity(3) - e%position(3)*e%velocity(2))/sqrt(r2)
            th%fluid(k) = element_fluid_loss(b%d, 0.0_wp, v, norm2(e%omega), props, th%lubricant_fraction)
         end associate
         heat%drag(k) = th%fluid(k)%loss
      end do
      if (th%by_location) heat = heat_by_location(heat, [(body_azimuth(s%elements(k)), k = 1, n)])
   end subroutine ball_heat_rates

   !> The end of an interval (report 2.10 steps 2-9; thermal_update): eq 18's velocity of
   !> ball k = its spin surface speed |omega| D / 2 at state s (docs/thermal.md), each ball at
   !> its azimuth there; time (s).
   subroutine ball_thermal_update(th, b, s, time, error)
      type(ball_thermal_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      real(wp), intent(in) :: time
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      call thermal_update(th, b, [(body_azimuth(s%elements(k)), k = 1, b%n_elements)], &
                          [(0.5_wp*b%d*norm2(s%elements(k)%omega), k = 1, b%n_elements)], time, error)
   end subroutine ball_thermal_update

end module adore_bearings_ball_thermal
