!> One ball/race contact in the ball's meridian plane at a given instant: the kinematic and
!> geometric data that the slip and traction of a ball/race contact need (adore_tribology_slip,
!> report section 2.1), filled by the contact geometry (adore_contact_ball_race) and the
!> quasi-static start.  SI units, angles in rad.  Kept in contact/ so that tribology/ depends
!> on contact/ and never the other way (no folder cycle).
module adore_contact_ball_race_kinematics
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: ball_race_contact_t

   integer, parameter, public :: SIDE_OUTER = 1   !< contact with the outer race
   integer, parameter, public :: SIDE_INNER = -1  !< contact with the inner race

   !> One ball/race contact at a given instant (SI units, angles in rad).
   type :: ball_race_contact_t
      integer :: side = SIDE_OUTER      !< SIDE_OUTER or SIDE_INNER
      real(wp) :: alpha = 0.0_wp        !< contact angle (rad)
      real(wp) :: rho = 0.0_wp          !< radius of the contact surface about the ball centre (m)
      real(wp) :: r_b = 0.0_wp          !< radius of the ball centre from the bearing axis (m)
      real(wp) :: omega(2) = 0.0_wp     !< ball angular velocity (axial, radial) in the orbit frame (rad/s)
      real(wp) :: race_speed = 0.0_wp   !< race angular speed relative to the orbit frame, Omega - w_m (rad/s)
      real(wp) :: a = 0.0_wp            !< semi-major axis of the contact ellipse (m)
      real(wp) :: load = 0.0_wp         !< normal load (N)
      !> [sin(alpha), cos(alpha)] (-), valid when trig_of == alpha: set by the contact geometry
      !> (adore_contact_ball_race's planar_contact, which computes them anyway), taken by the
      !> slip and traction routines instead of a sincos of their own (the same libm values;
      !> issue #30); a contact built or changed elsewhere keeps trig_of /= alpha
      real(wp) :: sin_cos(2) = 0.0_wp
      real(wp) :: trig_of = huge(1.0_wp) !< the alpha (rad) that sin_cos belongs to
   end type ball_race_contact_t

end module adore_contact_ball_race_kinematics
