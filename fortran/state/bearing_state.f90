!> The state of a bearing at one instant: every body in 6 DOF and the temperatures.
!>
!> Frame: the inertial frame of the report (x along the bearing axis; the azimuth phi of a
!> rolling element is measured from the z axis towards -y, eq 54, so a body at radius r
!> sits at (x, -r sin phi, r cos phi) and e_t = e_x x e_r points along increasing phi).
!> Each body carries its mass-centre position and velocity in inertial components (m,
!> m/s), its attitude as a unit quaternion (body -> inertial, adore_core_rotation; no
!> singularity over any number of revolutions) and its angular velocity in BODY components
!> (rad/s: Euler's equations in principal axes; for a ball, whose inertia is isotropic,
!> the components of any frame serve).  Temperatures (K) are the seven bulk temperatures
!> of Rec 2.7 in the bearing model's order (adore_model_bearing TEMP_*), so the mounted
!> geometry can follow them during a run (adore_geometry_mounted).
!> The state is plain data: the physics reads it, the integrator packs it into a vector.
module adore_state_bearing_state
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: quat_identity
   implicit none
   private

   public :: body_state_t, bearing_state_t
   public :: new_bearing_state, state_size, pack_state, unpack_state, body_azimuth, body_radius

   !> Number of reals of one body in the packed vector: position 3, velocity 3,
   !> quaternion 4, angular velocity 3.
   integer, parameter, public :: BODY_SIZE = 13
   !> Number of bulk temperatures (Rec 2.7 order).
   integer, parameter, public :: N_TEMPERATURES = 7
   !> Race indices of bearing_state_t%races.
   integer, parameter, public :: RACE_OUTER = 1, RACE_INNER = 2

   !> One rigid body.
   type :: body_state_t
      real(wp) :: position(3) = 0.0_wp       !< mass centre, inertial (m)
      real(wp) :: velocity(3) = 0.0_wp       !< mass-centre velocity, inertial (m/s)
      real(wp) :: attitude(4) = quat_identity  !< unit quaternion body -> inertial
      real(wp) :: omega(3) = 0.0_wp          !< angular velocity, body components (rad/s)
   end type body_state_t

   !> Every body of the bearing and its temperatures.
   type :: bearing_state_t
      real(wp) :: time = 0.0_wp                          !< (s)
      type(body_state_t), allocatable :: elements(:)     !< rolling elements 1..n
      type(body_state_t) :: cage
      type(body_state_t) :: races(2)                     !< RACE_OUTER, RACE_INNER
      real(wp) :: temperature(N_TEMPERATURES) = 293.0_wp !< bulk temperatures (K), Rec 2.7 order
   end type bearing_state_t

contains

   !> A state of n_elements rolling elements, every body at rest at the origin.
   pure function new_bearing_state(n_elements) result(s)
      integer, intent(in) :: n_elements
      type(bearing_state_t) :: s
      allocate (s%elements(max(n_elements, 0)))
   end function new_bearing_state

   !> Length of the packed state vector of n_elements rolling elements (bodies, then the
   !> temperatures).
   pure integer function state_size(n_elements)
      integer, intent(in) :: n_elements
      state_size = BODY_SIZE*(n_elements + 3) + N_TEMPERATURES
   end function state_size

   !> The state as one vector y (order: elements, cage, outer race, inner race, then the
   !> temperatures; each body position, velocity, attitude, omega).
   pure subroutine pack_state(s, y)
      type(bearing_state_t), intent(in) :: s
      real(wp), intent(out) :: y(:)
      integer :: k, n

      n = size(s%elements)
      do k = 1, n
         y(BODY_SIZE*(k - 1) + 1:BODY_SIZE*k) = body_vector(s%elements(k))
      end do
      y(BODY_SIZE*n + 1:BODY_SIZE*(n + 1)) = body_vector(s%cage)
      y(BODY_SIZE*(n + 1) + 1:BODY_SIZE*(n + 2)) = body_vector(s%races(RACE_OUTER))
      y(BODY_SIZE*(n + 2) + 1:BODY_SIZE*(n + 3)) = body_vector(s%races(RACE_INNER))
      y(BODY_SIZE*(n + 3) + 1:BODY_SIZE*(n + 3) + N_TEMPERATURES) = s%temperature
   end subroutine pack_state

   !> The state of vector y (pack_state's order) at time t (s); s%elements must have the
   !> number of elements y was packed with.
   pure subroutine unpack_state(y, t, s)
      real(wp), intent(in) :: y(:), t
      type(bearing_state_t), intent(inout) :: s
      integer :: k, n

      n = size(s%elements)
      s%time = t
      do k = 1, n
         s%elements(k) = vector_body(y(BODY_SIZE*(k - 1) + 1:BODY_SIZE*k))
      end do
      s%cage = vector_body(y(BODY_SIZE*n + 1:BODY_SIZE*(n + 1)))
      s%races(RACE_OUTER) = vector_body(y(BODY_SIZE*(n + 1) + 1:BODY_SIZE*(n + 2)))
      s%races(RACE_INNER) = vector_body(y(BODY_SIZE*(n + 2) + 1:BODY_SIZE*(n + 3)))
      s%temperature = y(BODY_SIZE*(n + 3) + 1:BODY_SIZE*(n + 3) + N_TEMPERATURES)
   end subroutine unpack_state

   !> Azimuth phi (rad) of a body's mass centre about the bearing axis (eq 54 convention).
   pure real(wp) function body_azimuth(body)
      type(body_state_t), intent(in) :: body
      body_azimuth = atan2(-body%position(2), body%position(3))
   end function body_azimuth

   !> Distance (m) of a body's mass centre from the bearing axis.
   pure real(wp) function body_radius(body)
      type(body_state_t), intent(in) :: body
      body_radius = hypot(body%position(2), body%position(3))
   end function body_radius

   pure function body_vector(b) result(v)
      type(body_state_t), intent(in) :: b
      real(wp) :: v(BODY_SIZE)
      v = [b%position, b%velocity, b%attitude, b%omega]
   end function body_vector

   pure function vector_body(v) result(b)
      real(wp), intent(in) :: v(BODY_SIZE)
      type(body_state_t) :: b
      b = body_state_t(v(1:3), v(4:6), v(7:10), v(11:13))
   end function vector_body

end module adore_state_bearing_state
