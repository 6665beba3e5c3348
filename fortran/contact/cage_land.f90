!> Cage/race guide-land contact in three dimensions: the cage guided on a land of one race
!> (Rec 7.0 guide type, Rec 7.2.n land), at any pose and velocity of cage and race, as a
!> short hydrodynamic journal bearing while the film is open and a metallic line contact
!> when the clearance closes; loads on both bodies.
!>
!> Geometry: the journal is the inner surface of the pair (the race land of an inner-race
!> guided cage, the cage OD of an outer-race guided one), the bearing the outer surface.
!> The land acts at the cage's centre plane (the meaning of the Rec 7.2.n position field is
!> not resolved: both Appendix C lands print 1.81204E-02, half the cage width); A is the
!> point of the race axis a at the axial station of the cage centre C.  The eccentricity is
!> e = C_inner - C_outer (C, A) in the plane normal to a, e = |e|, the radial clearance
!> c = (effective diametral play)/2 of adore_cage_step0 (the land clearance minus or plus
!> twice the race land's radial growth), eps = e/c, and the geometric interaction
!> c - e (> 0 clearance) equals adore_cage_step0's Geo Int for an untilted cage.  Relative
!> cage/race tilt is not modelled in the film.
!> Hydrodynamic force (short bearing, Ocvirk; Hamrock, Fundamentals of Fluid Film
!> Lubrication, NASA RP-1255 1991, "short-width journal bearings", half-Sommerfeld
!> film): with theta from the eccentricity direction e_e towards e_t = a x e_e,
!> h = c (1 - eps cos theta) and the short-bearing pressure
!>     p = -(6 eta / h**3) S (L**2/4 - z**2),   S = c [eps (wbar - psidot) sin theta - epsdot cos theta],
!> wbar = (w_inner + w_outer)/2 the mean surface angular speed about a, psidot the whirl
!> rate of e about a, epsdot = d(eps)/dt (the squeeze term), p kept where positive (S < 0):
!>     F_inner = eta R L**3 / c**2 int_{S<0} (S/c) / (1 - eps cos theta)**3 (cos theta, sin theta) dtheta
!> (Gauss-Legendre over the positive half).  For epsdot = psidot = 0 this is Hamrock's
!> closed form F_e = -eta w R L**3 eps**2 / (c**2 (1 - eps**2)**2),
!> F_t = pi eta w R L**3 eps / (4 c**2 (1 - eps**2)**1.5), w = w_inner + w_outer.
!> Viscous torque: the Couette shear of the full film on the journal,
!> T = -2 pi eta R**3 L (w_inner - w_outer) / (c sqrt(1 - eps**2)) along a, and the
!> pressure-driven shear split evenly so that the couples of journal and bearing differ by
!> e x F (Hamrock: the torques on journal and bearing differ by W e sin(phi)): action =
!> reaction holds in force and moment.  The film is taken at eps <= 1 - h_crit/c (Gupta 1979,
!> Part III: hydrodynamic or metallic switched at a critical film thickness h_crit).
!> Starved land (the lubricant layer h_oil): the gap is filled only where the local
!> clearance h(theta) is below the thickness of the oil layer the surfaces carry (the
!> fractional film content h_oil/h of starved films, Chevalier, Lubrecht, Cann, Colin &
!> Dalmaz 1998, J. Tribol. 120, 126; the film of a starved journal bearing begins where the
!> gap equals the supplied layer, Artiles & Heshmat 1985, J. Tribol. 107, 1): the wetted arc
!> |theta| < theta_w, cos theta_w = (1 - h_oil/c)/eps.  Pressure and shear act on that arc
!> only (the short-bearing pressure is local in theta, so the arc's pressure is Ocvirk's),
!> the Couette torque becomes eta R**3 L dw/c J, J = int_{-theta_w}^{theta_w}
!> dtheta/(1 - eps cos theta) = 4/sqrt(1 - eps**2) atan(sqrt((1 + eps)/(1 - eps)) tan(theta_w/2)).
!> Gap c - e >= h_oil: no film, no force, no loss; h_oil >= c (1 + eps): the flooded film.
!> The film's loss (film_loss) is what its loads take from the two bodies (viscous heat).
!> Metallic contact when e > c: delta = e - c, Palmgren's line contact over the land width
!> (adore_contact_line_slices palmgren_load, scaled in E*), along -e_e on the journal at
!> P = C_inner + R e_e, and Coulomb friction (Rec 10.5.2B A, 0.05 in both decks; the report's
!> roller land loss is 0.05 x force x sliding speed, docs/tribology.md) against the sliding
!> of the journal surface over the bearing's at P, regularised below slip_reg.
!> Abnormal (report 4.4.12): delta beyond ABNORMAL_FRACTION of c.  Units SI.
module adore_contact_cage_land
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_rotation, only: quat_matrix, cross
   use adore_core_quadrature, only: gauss_legendre
   use adore_contact_line_slices, only: contact_modulus, palmgren_load
   use adore_state_bearing_state, only: body_state_t
   implicit none
   private

   public :: cage_land_pair_t, cage_land_geometry_t
   public :: cage_land_contact, land_energy, short_bearing_force, wetted_half_angle, couette_integral

   real(wp), parameter, public :: LAND_ABNORMAL_FRACTION = 0.25_wp
   integer, parameter :: N_PANELS = 8, N_GAUSS = 24

   !> One guide land: what does not change with the state (m, Pa, Pa s).
   type :: cage_land_pair_t
      logical :: race_is_journal = .true.    !< inner-race guided (GUIDE_INNER): the race land is inside
      real(wp) :: radius = 0.0_wp            !< land radius R (Rec 7.2.n diameter / 2)
      real(wp) :: width = 0.0_wp             !< land width L
      real(wp) :: clearance = 0.0_wp         !< radial clearance c (effective play / 2)
      real(wp) :: e_star = 0.0_wp            !< contact modulus of cage and race (Pa)
      real(wp) :: friction = 0.05_wp         !< race/cage friction coefficient (Rec 10.5.2B A)
      real(wp) :: viscosity = 0.0_wp         !< lubricant dynamic viscosity (0: dry)
      real(wp) :: critical_film = 1.0e-6_wp  !< h_crit (m)
      real(wp) :: slip_reg = 1.0e-3_wp       !< friction regularisation speed (m/s)
      real(wp) :: oil_layer = huge(1.0_wp)   !< h_oil: lubricant layer on the land (m); huge: flooded
   end type cage_land_pair_t

   !> The land contact at one state.  Vectors inertial.
   type :: cage_land_geometry_t
      real(wp) :: eccentricity = 0.0_wp      !< e (m)
      real(wp) :: gap = 0.0_wp               !< c - e (m); < 0 interference
      real(wp) :: direction(3) = 0.0_wp      !< e_e: outer -> inner centre
      real(wp) :: hydro_force(3) = 0.0_wp    !< film force on the journal (N)
      real(wp) :: metallic_load = 0.0_wp     !< (N)
      real(wp) :: friction_force(3) = 0.0_wp !< metallic friction on the journal (N)
      real(wp) :: power = 0.0_wp             !< friction power loss of the metallic contact (W)
      real(wp) :: film_loss = 0.0_wp         !< viscous loss of the film (W): minus its loads' power on both bodies
      real(wp) :: force_cage(3) = 0.0_wp, moment_cage(3) = 0.0_wp   !< about the cage mass centre
      real(wp) :: force_race(3) = 0.0_wp, moment_race(3) = 0.0_wp   !< about the race mass centre
      logical :: abnormal = .false.
   end type cage_land_geometry_t

contains

   !> Half-angle theta_w (rad) of the wetted arc of pair p at eccentricity ratio eps (module
   !> header): pi flooded (h_oil >= c (1 + eps)), 0 dry (gap c - e >= h_oil), else
   !> acos((1 - h_oil/c)/eps).
   pure real(wp) function wetted_half_angle(p, eps) result(tw)
      type(cage_land_pair_t), intent(in) :: p
      real(wp), intent(in) :: eps
      real(wp) :: kappa
      tw = pi
      if (p%oil_layer >= p%clearance*(1.0_wp + eps)) return
      tw = 0.0_wp
      if (.not. eps > 0.0_wp) return
      kappa = (1.0_wp - p%oil_layer/p%clearance)/eps
      if (kappa >= 1.0_wp) return
      tw = acos(max(kappa, -1.0_wp))
   end function wetted_half_angle

   !> J = int_{-tw}^{tw} dtheta / (1 - eps cos theta) (module header; 0 <= eps < 1,
   !> 0 <= tw <= pi): the Couette torque's factor, 2 pi / sqrt(1 - eps**2) flooded.
   pure real(wp) function couette_integral(eps, tw) result(j)
      real(wp), intent(in) :: eps, tw
      real(wp) :: r
      r = sqrt(1.0_wp - eps**2)
      if (tw >= pi) then
         j = 2.0_wp*pi/r
      else
         j = 4.0_wp/r*atan(sqrt((1.0_wp + eps)/(1.0_wp - eps))*tan(0.5_wp*tw))
      end if
   end function couette_integral

   !> Short-bearing film force (N) on the journal in (e_e, e_t) components, for the pair p
   !> at eccentricity ratio eps, mean surface speed wbar minus whirl psidot (rad/s) and
   !> epsdot (1/s) (module header): the positive pressure over its half (beta + pi,
   !> beta + 2 pi) intersected with the wetted arc |theta| < theta_w of the oil layer.
   pure function short_bearing_force(p, eps, wbar_minus_whirl, epsdot) result(f)
      type(cage_land_pair_t), intent(in) :: p
      real(wp), intent(in) :: eps, wbar_minus_whirl, epsdot
      real(wp) :: f(2), a, bb, r0, beta, x(N_GAUSS), w(N_GAUSS), lo, hi, tw
      integer :: k

      f = 0.0_wp
      a = eps*wbar_minus_whirl
      bb = epsdot
      r0 = hypot(a, bb)
      if (.not. r0 > 0.0_wp .or. p%viscosity <= 0.0_wp) return
      beta = atan2(bb, a)
      tw = wetted_half_angle(p, eps)
      if (.not. tw > 0.0_wp) return
      call gauss_legendre(N_GAUSS, x, w)
      if (tw >= pi) then
         f = arc(beta + pi, pi)
      else
         ! the positive half, shifted into [0, 3 pi), against the wetted arcs about 0 and 2 pi
         lo = modulo(beta + pi, 2.0_wp*pi)
         hi = lo + pi
         do k = 0, 1
            if (min(hi, tw + 2.0_wp*pi*k) > max(lo, -tw + 2.0_wp*pi*k)) &
               f = f + arc(max(lo, -tw + 2.0_wp*pi*k), min(hi, tw + 2.0_wp*pi*k) - max(lo, -tw + 2.0_wp*pi*k))
         end do
      end if
      f = f*p%viscosity*p%radius*p%width**3/p%clearance**2

   contains

      !> int over (t0, t0 + len) of (S/c) / (1 - eps cos theta)**3 (cos theta, sin theta)
      !> dtheta (S/c < 0 there), N_PANELS Gauss-Legendre panels.  The nodes' cos and sin by
      !> angle addition, theta = m_k + hw x_i (panel centre m_k, half width hw): N_GAUSS +
      !> N_PANELS sincos an arc instead of two calls a node; S/c = r0 sin(theta - beta) =
      !> a sin(theta) - bb cos(theta) (r0 cos(beta) = a, r0 sin(beta) = bb).  Equal to the
      !> direct form to round-off (test_cage_contacts: within 8.4e-15 of the flooded force).
      pure function arc(t0, len) result(g)
         real(wp), intent(in) :: t0, len
         real(wp) :: g(2), hw, cm, sm, ct, st, d, q, co(N_GAUSS), so(N_GAUSS)
         integer :: i, kk
         g = 0.0_wp
         hw = 0.5_wp*len/N_PANELS
         do i = 1, N_GAUSS
            co(i) = cos(hw*x(i))
            so(i) = sin(hw*x(i))
         end do
         do kk = 1, N_PANELS
            cm = cos(t0 + (2*kk - 1)*hw)
            sm = sin(t0 + (2*kk - 1)*hw)
            do i = 1, N_GAUSS
               ct = cm*co(i) - sm*so(i)
               st = sm*co(i) + cm*so(i)
               d = 1.0_wp - eps*ct
               q = hw*w(i)*(a*st - bb*ct)/(d*d*d)
               g(1) = g(1) + q*ct
               g(2) = g(2) + q*st
            end do
         end do
      end function arc

   end function short_bearing_force

   !> The land contact of cage with race for the pair p (module header).
   pure subroutine cage_land_contact(p, cage, race, c)
      type(cage_land_pair_t), intent(in) :: p
      type(body_state_t), intent(in) :: cage, race
      type(cage_land_geometry_t), intent(out) :: c
      real(wp) :: ax(3), pa(3), ev(3), e_e(3), e_t(3), w_c(3), w_r(3), v_a(3), de(3), w_in, w_out, psidot, eps
      real(wp) :: epsdot, eps_max, f(2), couette(3), c_in(3), c_out(3), pt(3), u(3), q, f_in(3), tq_in(3), tq_out(3)
      real(wp) :: v_in(3), v_out(3), race_rot(3, 3), cage_rot(3, 3), tw

      ! the attitude matrices named (a function result inside matmul is a heap temporary)
      race_rot = quat_matrix(race%attitude)
      cage_rot = quat_matrix(cage%attitude)
      ax = matmul(race_rot, [1.0_wp, 0.0_wp, 0.0_wp])
      pa = race%position + dot_product(cage%position - race%position, ax)*ax
      w_c = matmul(cage_rot, cage%omega)
      w_r = matmul(race_rot, race%omega)
      v_a = race%velocity + cross(w_r, pa - race%position)
      if (p%race_is_journal) then
         c_in = pa
         c_out = cage%position
         v_in = v_a
         v_out = cage%velocity
         w_in = dot_product(w_r, ax)
         w_out = dot_product(w_c, ax)
      else
         c_in = cage%position
         c_out = pa
         v_in = cage%velocity
         v_out = v_a
         w_in = dot_product(w_c, ax)
         w_out = dot_product(w_r, ax)
      end if
      ev = c_in - c_out
      ev = ev - dot_product(ev, ax)*ax
      de = v_in - v_out
      de = de - dot_product(de, ax)*ax
      c%eccentricity = norm2(ev)
      c%gap = p%clearance - c%eccentricity
      if (c%eccentricity > 0.0_wp) then
         e_e = ev/c%eccentricity
      else if (norm2(de) > 0.0_wp) then
         e_e = de/norm2(de)
      else
         e_e = cross(ax, cross([0.0_wp, 0.0_wp, 1.0_wp], ax))
         if (norm2(e_e) == 0.0_wp) e_e = cross(ax, cross([0.0_wp, 1.0_wp, 0.0_wp], ax))
         e_e = e_e/norm2(e_e)
      end if
      e_t = cross(ax, e_e)
      c%direction = e_e

      f_in = 0.0_wp
      tq_in = 0.0_wp
      tq_out = 0.0_wp
      if (p%viscosity > 0.0_wp .and. p%clearance > 0.0_wp) then
         eps = c%eccentricity/p%clearance
         eps_max = max(1.0_wp - p%critical_film/p%clearance, 0.0_wp)
         psidot = 0.0_wp
         if (c%eccentricity > 0.0_wp) psidot = dot_product(ax, cross(ev, de))/c%eccentricity**2
         epsdot = dot_product(de, e_e)/p%clearance
         eps = min(eps, eps_max)
         tw = wetted_half_angle(p, eps)
         if (tw > 0.0_wp) then
            f = short_bearing_force(p, eps, 0.5_wp*(w_in + w_out) - psidot, epsdot)
            c%hydro_force = f(1)*e_e + f(2)*e_t
            if (tw >= pi) then
               couette = -2.0_wp*pi*p%viscosity*p%radius**3*p%width*(w_in - w_out)/(p%clearance*sqrt(1.0_wp - eps**2))*ax
            else
               couette = -p%viscosity*p%radius**3*p%width*(w_in - w_out)/p%clearance*couette_integral(eps, tw)*ax
            end if
            f_in = c%hydro_force
            tq_in = couette - 0.5_wp*cross(ev, c%hydro_force)
            tq_out = -couette - 0.5_wp*cross(ev, c%hydro_force)
            ! the film's viscous loss: minus the power of its loads on journal and bearing
            if (p%race_is_journal) then
               c%film_loss = -(dot_product(f_in, v_in - v_out) + dot_product(tq_in, w_r) + dot_product(tq_out, w_c))
            else
               c%film_loss = -(dot_product(f_in, v_in - v_out) + dot_product(tq_in, w_c) + dot_product(tq_out, w_r))
            end if
         end if
      end if
      ! on the journal through its centre: F_in; on the bearing: -F_in through its centre
      call add_loads(c, f_in, c_in, c_out, tq_in, tq_out)

      if (c%gap < 0.0_wp) then
         q = palmgren_load(p%e_star, -c%gap, p%width)
         c%metallic_load = q
         c%abnormal = -c%gap > LAND_ABNORMAL_FRACTION*p%clearance
         pt = c_in + p%radius*e_e
         if (p%race_is_journal) then
            u = (v_a + cross(w_r, pt - pa)) - (cage%velocity + cross(w_c, pt - cage%position))
         else
            u = (cage%velocity + cross(w_c, pt - cage%position)) - (v_a + cross(w_r, pt - pa))
         end if
         u = u - dot_product(u, e_e)*e_e
         c%friction_force = -p%friction*q*u/sqrt(dot_product(u, u) + p%slip_reg**2)
         c%power = -dot_product(c%friction_force, u)
         call add_loads(c, -q*e_e + c%friction_force, pt, pt, [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp])
      end if

   contains

      !> Add force f on the journal at point x_in and -f on the bearing at x_out, with the
      !> couples t_in and t_out, to the cage and race loads (moments about mass centres).
      pure subroutine add_loads(c, f, x_in, x_out, t_in, t_out)
         type(cage_land_geometry_t), intent(inout) :: c
         real(wp), intent(in) :: f(3), x_in(3), x_out(3), t_in(3), t_out(3)
         if (p%race_is_journal) then
            c%force_race = c%force_race + f
            c%moment_race = c%moment_race + cross(x_in - race%position, f) + t_in
            c%force_cage = c%force_cage - f
            c%moment_cage = c%moment_cage + cross(x_out - cage%position, -f) + t_out
         else
            c%force_cage = c%force_cage + f
            c%moment_cage = c%moment_cage + cross(x_in - cage%position, f) + t_in
            c%force_race = c%force_race - f
            c%moment_race = c%moment_race + cross(x_out - race%position, -f) + t_out
         end if
      end subroutine add_loads

   end subroutine cage_land_contact

   !> Elastic energy (J) of the metallic land contact: int Q d(delta) = 9/19 Q delta.
   pure real(wp) function land_energy(c)
      type(cage_land_geometry_t), intent(in) :: c
      land_energy = 0.0_wp
      if (c%gap < 0.0_wp) land_energy = 9.0_wp/19.0_wp*c%metallic_load*(-c%gap)
   end function land_energy

end module adore_contact_cage_land
