!> Rotations of rigid bodies: unit quaternions (singularity-free attitudes over any number
!> of revolutions), rotation matrices, small-angle misalignments and the attitude rate.
!>
!> A quaternion q = [w, x, y, z] (scalar first) rotates body-frame vectors into the
!> inertial frame: v_inertial = R(q) v_body.  The attitude rate with the angular velocity
!> omega_b in body components is dq/dt = 1/2 q * [0, omega_b] (Hamilton product; e.g.
!> Shabana, Dynamics of Multibody Systems, ch. 2; Kuipers, Quaternions and Rotation
!> Sequences, ch. 10).
module adore_core_rotation
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: quat_identity, quat_matrix, quat_multiply, quat_rate, quat_from_rotation_vector, quat_normalized
   public :: cross

   !> The identity attitude.
   real(wp), parameter :: quat_identity(4) = [1.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]

contains

   !> Cross product a x b.
   pure function cross(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross

   !> Rotation matrix R (body -> inertial) of the quaternion q (normalised here, so a
   !> slowly drifting integrated q still gives an orthogonal R).
   pure function quat_matrix(q) result(r)
      real(wp), intent(in) :: q(4)
      real(wp) :: r(3, 3)
      real(wp) :: w, x, y, z, n
      ! quat_normalized's q / |q| in line (the same norm2 and divisions: the same bits), the
      ! elements one by one (issue #30: no array temporaries, no call)
      n = norm2(q)
      if (n > 0.0_wp) then
         w = q(1)/n
         x = q(2)/n
         y = q(3)/n
         z = q(4)/n
      else
         w = 1.0_wp
         x = 0.0_wp
         y = 0.0_wp
         z = 0.0_wp
      end if
      r(1, 1) = 1.0_wp - 2.0_wp*(y*y + z*z)
      r(2, 1) = 2.0_wp*(x*y + w*z)
      r(3, 1) = 2.0_wp*(x*z - w*y)
      r(1, 2) = 2.0_wp*(x*y - w*z)
      r(2, 2) = 1.0_wp - 2.0_wp*(x*x + z*z)
      r(3, 2) = 2.0_wp*(y*z + w*x)
      r(1, 3) = 2.0_wp*(x*z + w*y)
      r(2, 3) = 2.0_wp*(y*z - w*x)
      r(3, 3) = 1.0_wp - 2.0_wp*(x*x + y*y)
   end function quat_matrix

   !> q / |q| (the identity for a zero quaternion).
   pure function quat_normalized(q) result(u)
      real(wp), intent(in) :: q(4)
      real(wp) :: u(4), n
      n = norm2(q)
      if (n > 0.0_wp) then
         u = q/n
      else
         u = quat_identity
      end if
   end function quat_normalized

   !> Hamilton product p * q.
   pure function quat_multiply(p, q) result(r)
      real(wp), intent(in) :: p(4), q(4)
      real(wp) :: r(4)
      r(1) = p(1)*q(1) - dot_product(p(2:4), q(2:4))
      r(2:4) = p(1)*q(2:4) + q(1)*p(2:4) + cross(p(2:4), q(2:4))
   end function quat_multiply

   !> Attitude rate dq/dt (1/s) of q for the body-frame angular velocity omega_b (rad/s).
   pure function quat_rate(q, omega_b) result(dq)
      real(wp), intent(in) :: q(4), omega_b(3)
      real(wp) :: dq(4)
      dq = 0.5_wp*quat_multiply(q, [0.0_wp, omega_b])
   end function quat_rate

   !> Quaternion of the rotation by |theta| (rad) about theta/|theta| (exact, any angle);
   !> a race misalignment (0, theta_2, theta_3) of the equilibrium is the small-angle case.
   pure function quat_from_rotation_vector(theta) result(q)
      real(wp), intent(in) :: theta(3)
      real(wp) :: q(4), angle
      angle = norm2(theta)
      if (angle > 0.0_wp) then
         q = [cos(0.5_wp*angle), sin(0.5_wp*angle)*theta/angle]
      else
         q = quat_identity
      end if
   end function quat_from_rotation_vector

end module adore_core_rotation
