!> Roller end / race flange contact of a cylindrical roller bearing (issue #26 item 2;
!> docs/rollers.md, "Flanges"): the spherical roller end against a flange face, a Hertz
!> point contact.
!>
!> Geometry (report Appendix A's guide flange data kFlngInd, flngHt, flngAng, flngCls and
!> the roller end radius bReEndRad; the record layout is pyadore's Rec 5B.2).  The roller
!> end at axial side s (-1: the roller's -x end, +1: its +x end) is a sphere of radius R_e
!> centred on the roller axis at s (L/2 - R_e) from the roller centre, so that its apex is
!> the end face's centre; it is bounded by the corner at radius D/2 - r_c from the axis.
!> A flange of race j on side s is a surface of revolution about the race axis; in the
!> race's meridian plane (axial X, radius R from the race axis) its face is the line
!> through (X_f, R_rw) (R_rw the raceway radius) laid back by the angle theta: it leans
!> away from the roller with height.  Its unit normal towards the roller is
!> n = (-s cos theta, s_r sin theta) with s_r = +1 for the inner race (the flange rises from
!> R_i), -1 for the outer (it hangs from R_o).  X_f is placed so that the centred, aligned
!> roller, its axis D/2 from the raceway, has the axial play c/2 to the face (c the race's
!> flange clearance): X_f = s (L/2 - R_e + R_e/cos theta + c/2 - (D/2) tan theta).
!> With d the distance of the sphere centre from the face (its meridian line) on the
!> roller's side, the interference is delta = R_e - d.  The face is straight along its
!> generatrix; around the race it curves with the normal curvature sin theta/R_c at the
!> contact radius R_c (convex on the inner race, concave on the outer: s_r sin theta/R_c),
!> which is not small against the end's 1/R_e (their ratio (D/2 - h_c)/R_c, 14 % in the
!> example deck).  The load is Hertz's for the slightly elliptic contact through the
!> equivalent sphere of radius R_eff = sqrt(R_x R_y), R_x = R_e, 1/R_y = 1/R_e + s_r sin
!> theta/R_c (Johnson, Contact Mechanics, section 4.2: the error of the equivalent sphere is
!> well below 1 % for R_x/R_y < 1.2):
!>     Q = (4/3) E* sqrt(R_eff) delta**(3/2)   (Johnson eq 4.22),
!> its stiffness dQ/ddelta = 2 E* sqrt(R_eff) delta**(1/2); at theta = 0 the exact
!> sphere-on-plane law.  The contact point is the sphere's
!> point nearest the face, C_s - R_e n; it lies on the face when its radius from the race
!> axis is within the flange height and its distance from the roller axis within the end's
!> spherical cap (on_face).  The contact's height above the raceway is D/2 - R_e sin theta
!> for the aligned roller (Harris & Kotzalas, Advanced Concepts of Bearing Technology, 5th
!> ed., ch. 1 "roller end - flange contact": the end sphere against the laid-back flange).
!> All vectors in one right-handed orthonormal basis whose first axis is the bearing axis
!> (the roller's orbit frame (e_x, e_r, e_t) in adore_forces_roller_bearing).  Units SI.
module adore_contact_roller_flange
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: cross
   implicit none
   private

   public :: roller_flange_t, roller_flange_set_t, flange_contact_t
   public :: roller_flanges, flange_contact, sphere_plane_load

   !> One flange face.
   type :: roller_flange_t
      integer :: race = 1                  !< 1 outer, 2 inner
      integer :: side = 1                  !< -1: at the roller's -x end, +1: at its +x end
      real(wp) :: face_x = 0.0_wp          !< X_f: the face's axial position at the raceway, from the race centre (m)
      real(wp) :: raceway = 0.0_wp         !< R_rw: raceway radius (m)
      real(wp) :: height = 0.0_wp          !< flange height above (inner) / below (outer) the raceway (m)
      real(wp) :: angle = 0.0_wp           !< lay-back angle theta (rad)
   end type roller_flange_t

   !> The flanges of a bearing and the roller ends they touch.
   type :: roller_flange_set_t
      type(roller_flange_t), allocatable :: flange(:)
      real(wp) :: end_radius = 0.0_wp      !< R_e (m)
      real(wp) :: end_centre = 0.0_wp      !< L/2 - R_e: the end sphere's centre from the roller centre (m)
      real(wp) :: cap_radius = 0.0_wp      !< D/2 - r_c: the spherical end's radius from the roller axis (m)
      real(wp) :: e_star(2) = 0.0_wp       !< contact modulus roller/outer, roller/inner race (Pa)
   end type roller_flange_set_t

   !> One roller end / flange contact.
   type :: flange_contact_t
      real(wp) :: delta = 0.0_wp           !< interference (m; < 0 gap)
      real(wp) :: load = 0.0_wp            !< Hertz load (N)
      real(wp) :: stiffness = 0.0_wp       !< dQ/ddelta (N/m)
      real(wp) :: rate = 0.0_wp            !< ddelta/dt (m/s)
      real(wp) :: normal(3) = 0.0_wp       !< unit normal of the face towards the roller
      real(wp) :: point(3) = 0.0_wp        !< contact point (m)
      real(wp) :: slip(3) = 0.0_wp         !< sliding velocity of the roller surface over the flange, tangential (m/s)
      real(wp) :: height = 0.0_wp          !< contact point's height above (inner) / below (outer) the raceway (m)
      real(wp) :: radius = 0.0_wp          !< R_eff, the equivalent sphere's radius (m)
      logical :: on_face = .true.          !< the contact point lies on the face and on the end's cap
   end type flange_contact_t

contains

   !> The flange set of a roller of diameter d, length l, corner radii r_c (m), spherical end
   !> radius r_e (m), with flanges present(end, race) (end 1: -x, 2: +x; race 1 outer, 2
   !> inner), heights h, lay-back angles theta (rad) and plays c per race (m), raceway radii
   !> r_rw (outer, inner; m), contact moduli e_star (Pa) per race.  Geometry in the module header.
   pure function roller_flanges(d, l, r_c, r_e, present, h, theta, c, r_rw, e_star) result(s)
      real(wp), intent(in) :: d, l, r_c(2), r_e, h(2), theta(2), c(2), r_rw(2), e_star(2)
      logical, intent(in) :: present(2, 2)
      type(roller_flange_set_t) :: s
      integer :: j, k, n
      real(wp) :: side
      allocate (s%flange(count(present)))
      s%end_radius = r_e
      s%end_centre = 0.5_wp*l - r_e
      s%cap_radius = 0.5_wp*d - maxval(r_c)
      s%e_star = e_star
      n = 0
      do j = 1, 2
         do k = 1, 2
            if (.not. present(k, j)) cycle
            n = n + 1
            side = merge(-1.0_wp, 1.0_wp, k == 1)
            s%flange(n) = roller_flange_t(j, nint(side), side*(0.5_wp*l - r_e + r_e/cos(theta(j)) + 0.5_wp*c(j) - &
                                                                 0.5_wp*d*tan(theta(j))), r_rw(j), h(j), theta(j))
         end do
      end do
   end function roller_flanges

   !> Hertz load (N) of a sphere of radius r (m) pressed delta (m) into a plane, contact
   !> modulus e_star (Pa): (4/3) E* sqrt(r) delta**1.5 (Johnson eq 4.22); 0 without contact.
   pure real(wp) function sphere_plane_load(e_star, r, delta) result(q)
      real(wp), intent(in) :: e_star, r, delta
      q = 4.0_wp/3.0_wp*e_star*sqrt(r)*max(delta, 0.0_wp)**1.5_wp
   end function sphere_plane_load

   !> Flange f of set s against the roller (centre, unit axis, centre velocity v, absolute
   !> angular velocity omega) with the race (centre o, velocity v_o, angular speed w_o about
   !> the bearing axis): interference, Hertz load, normal, contact point, approach rate and
   !> the tangential sliding velocity of the roller surface over the flange (module header).
   pure subroutine flange_contact(s, f, centre, axis, v, omega, o, v_o, w_o, c)
      type(roller_flange_set_t), intent(in) :: s
      type(roller_flange_t), intent(in) :: f
      real(wp), intent(in) :: centre(3), axis(3), v(3), omega(3), o(3), v_o(3), w_o
      type(flange_contact_t), intent(out) :: c
      real(wp) :: sc(3), p(3), perp(3), rr, e_rad(3), n_m(2), d, s_r, u(3), rel(3), rc, off
      sc = centre + real(f%side, wp)*s%end_centre*axis
      p = sc - o
      perp = [0.0_wp, p(2), p(3)]
      rr = norm2(perp)
      if (rr > 0.0_wp) then
         e_rad = perp/rr
      else
         e_rad = [0.0_wp, 1.0_wp, 0.0_wp]
      end if
      s_r = merge(1.0_wp, -1.0_wp, f%race == 2)
      n_m = [-real(f%side, wp)*cos(f%angle), s_r*sin(f%angle)]
      d = (p(1) - f%face_x)*n_m(1) + (rr - f%raceway)*n_m(2)
      c%delta = s%end_radius - d
      c%normal = n_m(1)*[1.0_wp, 0.0_wp, 0.0_wp] + n_m(2)*e_rad
      c%point = sc - s%end_radius*c%normal
      rc = rr - s%end_radius*n_m(2)
      c%height = s_r*(rc - f%raceway)
      rel = c%point - centre
      off = norm2(rel - dot_product(rel, axis)*axis)
      c%on_face = c%height >= 0.0_wp .and. c%height <= f%height .and. off <= s%cap_radius
      ! surface velocities at the contact point: roller minus race
      u = (v + cross(omega, c%point - centre)) - (v_o + cross([w_o, 0.0_wp, 0.0_wp], c%point - o))
      c%rate = -dot_product(u, c%normal)
      c%slip = u - dot_product(u, c%normal)*c%normal
      ! the equivalent sphere's radius; a state with the end's centre on or across the
      ! raceway's axis (rc <= 0, a trial point of the start's solve) has none: the end's own
      c%radius = s%end_radius
      if (rc > 0.0_wp) then
         if (1.0_wp + s%end_radius*s_r*sin(f%angle)/rc > 0.0_wp) then
            c%radius = sqrt(s%end_radius/(1.0_wp + s%end_radius*s_r*sin(f%angle)/rc))
            c%radius = c%radius*sqrt(s%end_radius)
         end if
      end if
      if (c%delta > 0.0_wp) then
         c%load = sphere_plane_load(s%e_star(f%race), c%radius, c%delta)
         c%stiffness = 2.0_wp*s%e_star(f%race)*sqrt(c%radius*c%delta)
      end if
   end subroutine flange_contact

end module adore_contact_roller_flange
