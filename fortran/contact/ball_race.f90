!> Ball/race contact in three dimensions: geometry, Hertz normal load and surface
!> kinematics of a ball against a groove for any positions, attitudes and velocities of
!> both bodies (race misalignment included).
!>
!> Report section 3.1, eqs 59-64, generalised from the meridian plane to 3-D: the ball
!> centre B is taken into the race frame (b' = R^T (B - c), R the race attitude, c its
!> mass centre); at the ball's azimuth phi' in that frame the groove curvature centre is
!> g' = (x_g, r_g e_r(phi')); a = b' - g', the geometric interaction is
!>     delta = |a| - (f D - D/2)                                               (60)
!> and, when positive, the Hertz load Q = K delta**1.5 (61) acts on the ball along -n,
!> n = a/|a| (inertial R a/|a|), through the contact point P = B + D/2 n (64).  K follows
!> the contact angle alpha = atan(|a_x| / |a_r|) (62-63) through the rolling-plane
!> curvature (Harris & Kotzalas, Rolling Bearing Analysis, ch. 6).  Hertz's normal force
!> is the gradient of the contact energy 2/5 K delta**2.5 at fixed K.
!> Kinematics: the slip of the ball surface over the race surface at a point Q,
!> u = v_B + w_B x (Q - B) - v_c - w_R x (Q - c) (frame independent), along the race's
!> circumferential direction e_t (the rolling direction; report eq 3) on the major axis
!> Q(psi) = B + D/2 (cos psi n + sin psi e_m), psi = s / (D/2), e_m in the race meridian
!> plane.  That rolling component is C + P cos psi + Q sin psi for any state, which is
!> exactly the slip of the planar contact of adore_tribology_slip with suitable (omega,
!> race speed): planar_contact maps the 3-D state onto it, so the planar traction, film,
!> EHD and flash models apply at any state; the step-0 contact is its special case
!> (ball in the race meridian plane, no misalignment).  The slip across the rolling
!> direction is returned (tangent_slip) but not yet used by the one-dimensional traction
!> models (report eq 1).  Units SI.
module adore_contact_ball_race
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: quat_matrix
   use adore_contact_hertz, only: hertz_geometry_t, hertz_contact_t, hertz_geometry, hertz_contact
   use adore_state_bearing_state, only: body_state_t
   use adore_contact_ball_race_kinematics, only: ball_race_contact_t, SIDE_OUTER, SIDE_INNER
   implicit none
   private

   public :: ball_race_pair_t, ball_race_geometry_t
   public :: ball_race_curvatures, ball_race_contact, planar_contact, contact_energy

   !> One ball against one race: what does not change with the state (m, Pa).
   type :: ball_race_pair_t
      integer :: side = SIDE_OUTER          !< SIDE_OUTER or SIDE_INNER
      real(wp) :: d = 0.0_wp                !< ball diameter
      real(wp) :: dm = 0.0_wp               !< pitch diameter (rolling-plane curvature)
      real(wp) :: f = 0.52_wp               !< groove curvature factor (groove radius / D)
      real(wp) :: groove_radius = 0.0_wp    !< groove radius (m), f D of the mounted geometry
      real(wp) :: groove_centre(2) = 0.0_wp !< groove curvature centre (axial, radial) in the race frame
      real(wp) :: e_ball = 2.0e11_wp, nu_ball = 0.25_wp   !< ball elastic constants
      real(wp) :: e_race = 2.0e11_wp, nu_race = 0.25_wp   !< race elastic constants
   end type ball_race_pair_t

   !> The contact at one state.  Directions are inertial unit vectors.
   type :: ball_race_geometry_t
      real(wp) :: delta = 0.0_wp            !< geometric interaction (m); <= 0: no contact
      real(wp) :: load = 0.0_wp             !< Hertz normal load Q (N)
      real(wp) :: stiffness = 0.0_wp        !< K (N/m**1.5)
      real(wp) :: alpha = 0.0_wp            !< contact angle, signed as the planar contact's (rad)
      real(wp) :: normal(3) = 0.0_wp        !< n: ball centre -> contact point
      real(wp) :: rolling(3) = 0.0_wp       !< e_t: the race's circumferential direction
      real(wp) :: transverse(3) = 0.0_wp    !< e_m: along the major axis, d(normal)/d(psi)
      real(wp) :: point(3) = 0.0_wp         !< contact centre P (m)
      real(wp) :: ball_radius = 0.0_wp      !< distance of the ball centre from the race axis (m)
      real(wp) :: tangent_slip(3) = 0.0_wp  !< slip of ball over race at P, tangent plane (m/s)
      real(wp) :: slip_coeff(3) = 0.0_wp    !< rolling slip u(psi) = c1 + c2 cos psi + c3 sin psi (m/s)
      !> slip across the rolling direction, along e_m(psi) = d n(psi) / d psi on the major axis:
      !> u_m(psi) = m1 + m2 cos psi + m3 sin psi (m/s)
      real(wp) :: transverse_coeff(3) = 0.0_wp
      type(hertz_contact_t) :: ellipse      !< semi-axes, pressure, approach of the load
   end type ball_race_geometry_t

contains

   !> Principal curvatures (1/m) [ball I, ball II, race rolling plane, race across the
   !> groove] of a ball of diameter d on pitch diameter dm in a groove of curvature factor
   !> f at contact angle alpha (rad): gamma = d cos(alpha) / dm, rolling plane
   !> +-2 gamma / (d (1 -+ gamma)) (inner convex, outer concave), groove -1/(f d).
   pure function ball_race_curvatures(d, dm, f, alpha, outer) result(rho)
      real(wp), intent(in) :: d, dm, f, alpha
      logical, intent(in) :: outer
      real(wp) :: rho(4)
      rho = curvatures_of_cosine(d, dm, f, cos(alpha), outer)
   end function ball_race_curvatures

   !> ball_race_curvatures for cos(alpha) (-) given.
   pure function curvatures_of_cosine(d, dm, f, cos_alpha, outer) result(rho)
      real(wp), intent(in) :: d, dm, f, cos_alpha
      logical, intent(in) :: outer
      real(wp) :: rho(4), gamma
      gamma = d*cos_alpha/dm
      if (outer) then
         rho = [2.0_wp/d, 2.0_wp/d, -2.0_wp*gamma/(d*(1.0_wp + gamma)), -1.0_wp/(f*d)]
      else
         rho = [2.0_wp/d, 2.0_wp/d, 2.0_wp*gamma/(d*(1.0_wp - gamma)), -1.0_wp/(f*d)]
      end if
   end function curvatures_of_cosine

   !> The contact of `ball` with the race `race` (body states, adore_state_bearing_state)
   !> for the pair p: geometry, Hertz load and slip (module header).  stiffness, when
   !> given, replaces the contact-angle-dependent K (N/m**1.5; the energy test's frozen K).
   !> race_rot, ball_rot, when given: quat_matrix of the race's and the ball's attitude,
   !> computed once by the caller for all contacts of that body (the same numbers).
   pure subroutine ball_race_contact(p, ball, race, c, stiffness, race_rot, ball_rot)
      type(ball_race_pair_t), intent(in) :: p
      type(body_state_t), intent(in) :: ball, race
      type(ball_race_geometry_t), intent(out) :: c
      real(wp), intent(in), optional :: stiffness
      real(wp), intent(in), optional :: race_rot(3, 3), ball_rot(3, 3)
      real(wp) :: rot(3, 3), b_rel(3), e_r(3), e_t(3), a(3), la, n(3), alpha_s, e_m(3), nr, ln
      real(wp) :: w_b(3), w_r(3), dv(3), dw(3), v_ball(3), v_race(3), u(3), side
      type(hertz_geometry_t) :: g
      logical :: ok

      side = real(p%side, wp)
      if (present(race_rot)) then
         rot = race_rot
      else
         rot = quat_matrix(race%attitude)
      end if
      ! R^T (B - c) written out (matmul of a transpose is a libgfortran call, ~250 instructions)
      dv = ball%position - race%position
      b_rel = [rot(1, 1)*dv(1) + rot(2, 1)*dv(2) + rot(3, 1)*dv(3), rot(1, 2)*dv(1) + rot(2, 2)*dv(2) + rot(3, 2)*dv(3), &
               rot(1, 3)*dv(1) + rot(2, 3)*dv(2) + rot(3, 3)*dv(3)]
      ! the ball's azimuth phi' = atan2(-b_2, b_3): e_r = (0, -sin phi', cos phi') and
      ! e_t = (0, -cos phi', -sin phi') from b' itself (no trigonometric call)
      c%ball_radius = hypot(b_rel(2), b_rel(3))
      if (c%ball_radius > 0.0_wp) then
         e_r = [0.0_wp, b_rel(2)/c%ball_radius, b_rel(3)/c%ball_radius]
      else
         e_r = [0.0_wp, 0.0_wp, 1.0_wp]       ! atan2(0, 0) = 0
      end if
      e_t = [0.0_wp, -e_r(3), e_r(2)]
      a = b_rel - ([p%groove_centre(1), 0.0_wp, 0.0_wp] + p%groove_centre(2)*e_r)
      la = norm2(a)
      n = a/la
      c%delta = la - (p%groove_radius - 0.5_wp*p%d)
      ! planar angle: n = side (sin alpha, cos alpha) in (axial, radial); n is a unit
      ! vector in the plane of e_x and e_r, so cos, sin alpha are its components there
      nr = dot_product(n, e_r)
      alpha_s = atan2(side*n(1), side*nr)
      ln = hypot(n(1), nr)
      e_m = (nr/ln)*[1.0_wp, 0.0_wp, 0.0_wp] - (n(1)/ln)*e_r
      c%alpha = alpha_s
      c%normal = matmul(rot, n)
      c%rolling = matmul(rot, e_t)
      c%transverse = matmul(rot, e_m)
      c%point = ball%position + 0.5_wp*p%d*c%normal

      ! the Hertz contact angle atan(|n_x| / |n_r|) by its cosine |n_r| / |n|
      call hertz_geometry(curvatures_of_cosine(p%d, p%dm, p%f, abs(nr)/ln, p%side == SIDE_OUTER), &
                          p%e_ball, p%nu_ball, p%e_race, p%nu_race, g, ok)
      c%stiffness = 0.0_wp
      if (ok) c%stiffness = g%stiffness
      if (present(stiffness)) c%stiffness = stiffness
      if (c%delta > 0.0_wp .and. ok) then
         c%load = c%stiffness*(c%delta*sqrt(c%delta))   ! delta**1.5 without pow
         c%ellipse = hertz_contact(g, c%load)
      end if

      ! surface velocities (inertial): ball and race angular velocities from body components
      if (present(ball_rot)) then
         w_b = matmul(ball_rot, ball%omega)
      else
         w_b = matmul(quat_matrix(ball%attitude), ball%omega)
      end if
      w_r = matmul(rot, race%omega)
      v_ball = ball%velocity + cross3(w_b, c%point - ball%position)
      v_race = race%velocity + cross3(w_r, c%point - race%position)
      u = v_ball - v_race
      c%tangent_slip = u - dot_product(u, c%normal)*c%normal
      dv = ball%velocity - race%velocity - cross3(w_r, ball%position - race%position)
      dw = w_b - w_r
      c%slip_coeff = [dot_product(c%rolling, dv), 0.5_wp*p%d*dot_product(c%rolling, cross3(dw, c%normal)), &
                      0.5_wp*p%d*dot_product(c%rolling, cross3(dw, c%transverse))]
      ! e_m(psi) . (dv + dw x D/2 n(psi)) with n(psi) x e_m(psi) = n x e_m for every psi
      c%transverse_coeff = [0.5_wp*p%d*dot_product(dw, cross3(c%normal, c%transverse)), &
                            dot_product(c%transverse, dv), -dot_product(c%normal, dv)]
   end subroutine ball_race_contact

   !> a x b, as adore_core_rotation's cross (the same operations, so the same bits), here so
   !> that gcc inlines it into ball_race_contact (6 calls a contact; no link-time optimisation)
   pure function cross3(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross3

   !> The planar contact (adore_tribology_slip) whose rolling slip along the major axis
   !> equals that of the 3-D contact c of pair p: same side, angle, radii, semi-major axis
   !> and load; (omega, race speed) from c's slip coefficients (module header).
   pure function planar_contact(p, c) result(q)
      type(ball_race_pair_t), intent(in) :: p
      type(ball_race_geometry_t), intent(in) :: c
      type(ball_race_contact_t) :: q
      real(wp) :: rho, w, x, y, s, sn, cs

      rho = 0.5_wp*p%d
      s = real(p%side, wp)
      ! u = side rho [(w_x - w) cos(alpha + psi) - w_r sin(alpha + psi)] - w r_b
      w = -c%slip_coeff(1)/c%ball_radius
      sn = sin(c%alpha)
      cs = cos(c%alpha)
      x = s*(cs*c%slip_coeff(2) - sn*c%slip_coeff(3))/rho
      y = -s*(sn*c%slip_coeff(2) + cs*c%slip_coeff(3))/rho
      q = ball_race_contact_t(p%side, c%alpha, rho, c%ball_radius, [x + w, y], w, c%ellipse%semi_major, c%load)
      ! the contact angle's sine and cosine for the slip and traction (no sincos of their own)
      q%sin_cos = [sn, cs]
      q%trig_of = c%alpha
   end function planar_contact

   !> Elastic energy (J) of the contact, 2/5 K delta**1.5 delta; 0 without contact.
   pure real(wp) function contact_energy(c)
      type(ball_race_geometry_t), intent(in) :: c
      contact_energy = 0.0_wp
      if (c%delta > 0.0_wp) contact_energy = 0.4_wp*c%stiffness*c%delta**2.5_wp
   end function contact_energy

end module adore_contact_ball_race
