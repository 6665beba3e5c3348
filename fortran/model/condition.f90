!> The operating condition of a run: what may change while the bearing runs (issue #24 item 3)
!> - the bulk temperatures (which set the mounted geometry: fits, growth, clearance; ADRC2)
!> and the load applied to the inner race.  A bearing system owns one
!> (adore_bearings_system's set_condition re-mounts and restarts the integrator); the
!> thermal model and any periodic update change it through that one call.
module adore_model_condition
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t
   implicit none
   private

   public :: operating_condition_t, condition_of, same_condition

   !> Bulk temperatures (K, the TEMP_* order of adore_model_bearing) and the load applied to
   !> the inner race (N, N m; inertial components).
   type :: operating_condition_t
      real(wp) :: temperature(7) = 293.0_wp
      real(wp) :: force(3) = 0.0_wp
      real(wp) :: moment(3) = 0.0_wp
   end type operating_condition_t

contains

   !> The condition bearing b starts with (Rec 2.7 temperatures, Rec 9.0 / 11 loads).
   pure function condition_of(b) result(c)
      type(bearing_t), intent(in) :: b
      type(operating_condition_t) :: c
      c%temperature = b%temperature
      c%force = b%force
      c%moment = b%moment
   end function condition_of

   !> Whether two conditions are equal value by value (a bitwise comparison: an unchanged
   !> condition changes nothing, not even the integrator's step).
   pure logical function same_condition(a, b)
      type(operating_condition_t), intent(in) :: a, b
      same_condition = all(a%temperature == b%temperature) .and. all(a%force == b%force) .and. &
                       all(a%moment == b%moment)
   end function same_condition

end module adore_model_condition
