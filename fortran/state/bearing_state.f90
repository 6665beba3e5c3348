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
!> Packed with orbit = .true., the rolling elements' position and velocity are their
!> orbit-following (cylindrical) coordinates of the report's eq 54, (x, r, phi) and their
!> rates (x', r', phi'), so that a ball orbiting at its pitch radius is a slowly varying
!> vector (issue #30: the contact modes then follow no rotating equilibrium); the rates
!> of such a vector come from pack_rates.
module adore_state_bearing_state
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: quat_identity
   use adore_core_strings, only: itoa
   implicit none
   private

   public :: body_state_t, bearing_state_t
   public :: new_bearing_state, state_size, pack_state, unpack_state, pack_rates, set_packed_temperatures, &
             body_azimuth, body_radius, packed_name

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
   !> temperatures; each body position, velocity, attitude, omega; with orbit = .true.
   !> the elements' (x, r, phi, x', r', phi') in place of position and velocity, phi in
   !> (-pi, pi]).
   pure subroutine pack_state(s, y, orbit)
      type(bearing_state_t), intent(in) :: s
      real(wp), intent(out) :: y(:)
      logical, intent(in), optional :: orbit
      integer :: k, n

      n = size(s%elements)
      do k = 1, n
         y(BODY_SIZE*(k - 1) + 1:BODY_SIZE*k) = body_vector(s%elements(k))
         if (orbit_frame(orbit)) y(BODY_SIZE*(k - 1) + 1:BODY_SIZE*(k - 1) + 6) = &
            cylindrical(s%elements(k)%position, s%elements(k)%velocity)
      end do
      y(BODY_SIZE*n + 1:BODY_SIZE*(n + 1)) = body_vector(s%cage)
      y(BODY_SIZE*(n + 1) + 1:BODY_SIZE*(n + 2)) = body_vector(s%races(RACE_OUTER))
      y(BODY_SIZE*(n + 2) + 1:BODY_SIZE*(n + 3)) = body_vector(s%races(RACE_INNER))
      y(BODY_SIZE*(n + 3) + 1:BODY_SIZE*(n + 3) + N_TEMPERATURES) = s%temperature
   end subroutine pack_state

   !> The state of vector y (pack_state's order, orbit as it was packed with) at time t (s);
   !> s%elements must have the number of elements y was packed with.
   pure subroutine unpack_state(y, t, s, orbit)
      real(wp), intent(in) :: y(:), t
      type(bearing_state_t), intent(inout) :: s
      logical, intent(in), optional :: orbit
      integer :: k, n

      n = size(s%elements)
      s%time = t
      do k = 1, n
         s%elements(k) = vector_body(y(BODY_SIZE*(k - 1) + 1:BODY_SIZE*k))
         if (orbit_frame(orbit)) call from_cylindrical(y(BODY_SIZE*(k - 1) + 1:BODY_SIZE*(k - 1) + 6), &
                                                       s%elements(k)%position, s%elements(k)%velocity)
      end do
      s%cage = vector_body(y(BODY_SIZE*n + 1:BODY_SIZE*(n + 1)))
      s%races(RACE_OUTER) = vector_body(y(BODY_SIZE*(n + 1) + 1:BODY_SIZE*(n + 2)))
      s%races(RACE_INNER) = vector_body(y(BODY_SIZE*(n + 2) + 1:BODY_SIZE*(n + 3)))
      s%temperature = y(BODY_SIZE*(n + 3) + 1:BODY_SIZE*(n + 3) + N_TEMPERATURES)
   end subroutine unpack_state

   !> The rates dydt of a packed state (pack_state's order and orbit) at state s whose
   !> rates in state form are `rates` (each body's position holding its velocity, velocity
   !> its acceleration, ...: adore_dynamics_ball_motion).  In the orbit frame an element's
   !> rates are (x', r', phi', x'', r'', phi'') with, for its acceleration a (e_r, e_phi of
   !> eq 54), r'' = a.e_r + r phi'**2 and phi'' = (a.e_phi - 2 r' phi') / r.
   pure subroutine pack_rates(s, rates, dydt, orbit)
      type(bearing_state_t), intent(in) :: s, rates
      real(wp), intent(out) :: dydt(:)
      logical, intent(in), optional :: orbit
      real(wp) :: q(6), e_r(3), e_p(3)
      integer :: k

      call pack_state(rates, dydt)
      if (.not. orbit_frame(orbit)) return
      do k = 1, size(s%elements)
         q = cylindrical(s%elements(k)%position, s%elements(k)%velocity)
         e_r = [0.0_wp, -sin(q(3)), cos(q(3))]
         e_p = [0.0_wp, -cos(q(3)), -sin(q(3))]
         associate (a => rates%elements(k)%velocity)
            dydt(BODY_SIZE*(k - 1) + 1:BODY_SIZE*(k - 1) + 6) = &
               [q(4), q(5), q(6), a(1), dot_product(a, e_r) + q(2)*q(6)**2, &
                (dot_product(a, e_p) - 2.0_wp*q(5)*q(6))/q(2)]
         end associate
      end do
   end subroutine pack_rates

   !> The temperatures of a packed state y of n_elements rolling elements set to temperature.
   pure subroutine set_packed_temperatures(y, n_elements, temperature)
      real(wp), intent(inout) :: y(:)
      integer, intent(in) :: n_elements
      real(wp), intent(in) :: temperature(N_TEMPERATURES)
      y(BODY_SIZE*(n_elements + 3) + 1:BODY_SIZE*(n_elements + 3) + N_TEMPERATURES) = temperature
   end subroutine set_packed_temperatures

   !> Whether the orbit-following frame is asked for (absent: no).
   pure logical function orbit_frame(orbit)
      logical, intent(in), optional :: orbit
      orbit_frame = .false.
      if (present(orbit)) orbit_frame = orbit
   end function orbit_frame

   !> (x, r, phi, x', r', phi') of a mass centre at position p with velocity v (eq 54).
   pure function cylindrical(p, v) result(q)
      real(wp), intent(in) :: p(3), v(3)
      real(wp) :: q(6), r, phi
      r = hypot(p(2), p(3))
      phi = atan2(-p(2), p(3))
      q = [p(1), r, phi, v(1), -v(2)*sin(phi) + v(3)*cos(phi), (-v(2)*cos(phi) - v(3)*sin(phi))/r]
   end function cylindrical

   !> Position and velocity of a mass centre at cylindrical coordinates q (cylindrical's order).
   pure subroutine from_cylindrical(q, p, v)
      real(wp), intent(in) :: q(6)
      real(wp), intent(out) :: p(3), v(3)
      real(wp) :: c, s
      c = cos(q(3))
      s = sin(q(3))
      p = [q(1), -q(2)*s, q(2)*c]
      v = [q(4), -q(5)*s - q(2)*q(6)*c, q(5)*c - q(2)*q(6)*s]
   end subroutine from_cylindrical

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

   !> The name of unknown i of a vector packed by pack_state with n_elements rolling elements
   !> (orbit as it was packed with), for messages: e.g. "ball 2's angular velocity (body x)"
   !> with noun = "ball"; its unit is the packed vector's.  A subroutine: a deferred-length
   !> function result would be static storage (fortran/core/strings.f90).
   pure subroutine packed_name(i, n_elements, noun, name, orbit)
      integer, intent(in) :: i, n_elements
      character(len=*), intent(in) :: noun
      character(len=:), allocatable, intent(out) :: name
      logical, intent(in), optional :: orbit
      character(len=*), parameter :: axis(3) = ["x", "y", "z"]
      character(len=*), parameter :: orbit_names(6) = [character(len=15) :: "axial position", "radius", &
                                                       "orbital angle", "axial velocity", "radial velocity", "orbital speed"]
      character(len=:), allocatable :: body
      integer :: k, c

      if (i < 1 .or. i > state_size(n_elements)) then
         name = "unknown "//itoa(i)
         return
      end if
      k = (i - 1)/BODY_SIZE + 1
      c = mod(i - 1, BODY_SIZE) + 1
      if (k > n_elements + 3) then
         name = "bulk temperature "//itoa(i - BODY_SIZE*(n_elements + 3))//" (Rec 2.7)"
         return
      end if
      if (k <= n_elements) then
         body = noun//" "//itoa(k)
      else if (k == n_elements + 1) then
         body = "the cage"
      else if (k == n_elements + 2) then
         body = "the outer race"
      else
         body = "the inner race"
      end if
      if (c <= 6 .and. k <= n_elements .and. orbit_frame(orbit)) then
         name = body//"'s "//trim(orbit_names(c))
      else if (c <= 3) then
         name = body//"'s position "//axis(c)
      else if (c <= 6) then
         name = body//"'s velocity "//axis(c - 3)
      else if (c <= 10) then
         name = body//"'s attitude (quaternion "//itoa(c - 7)//")"
      else
         name = body//"'s angular velocity (body "//axis(c - 10)//")"
      end if
   end subroutine packed_name

end module adore_state_bearing_state
