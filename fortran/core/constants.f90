!> Mathematical and unit-conversion constants of the engine: one definition each.
module adore_core_constants
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: pi, two_pi, rad_to_deg, deg_to_rad, rpm_to_rad_s, rad_s_to_rpm

   real(wp), parameter :: pi = acos(-1.0_wp)          !< pi (-)
   real(wp), parameter :: two_pi = 2.0_wp*pi          !< one revolution (rad)
   real(wp), parameter :: rad_to_deg = 180.0_wp/pi    !< degrees per radian
   real(wp), parameter :: deg_to_rad = pi/180.0_wp    !< radians per degree
   real(wp), parameter :: rpm_to_rad_s = pi/30.0_wp   !< (rad/s) per (rev/min)
   real(wp), parameter :: rad_s_to_rpm = 30.0_wp/pi   !< (rev/min) per (rad/s)

end module adore_core_constants
