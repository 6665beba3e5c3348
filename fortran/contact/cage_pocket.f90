!> Ball/cage pocket contact in three dimensions: a ball in the cylindrical pocket of the
!> cage (POCKET_BALL of adore_cage_step0, the Appendix C ball deck) at any pose and
!> velocity of ball and cage; normal force (metallic Hertz contact and an isoviscous
!> hydrodynamic rolling force), friction, and the loads on both bodies.
!>
!> Geometry (adore_cage_step0's pocket frame, now at any cage attitude R_c): pocket k sits
!> at azimuth psi_k in the cage frame, origin at radius R_p = (cage OD + cage ID)/4; pocket
!> axis z_p = e_r(psi_k), x_p = e_x, y_p = z_p x x_p.  With b' = R_c^T (B - C) the ball
!> centre in the cage frame, q = (b'.x_p, b'.y_p, b'.z_p - R_p) and rho = |(q_1, q_2)|:
!>     gap = c/2 - rho   (c the diametral pocket clearance; > 0 clearance, = Geo Int)
!> normal n = R_c (q_1 x_p + q_2 y_p)/rho (pocket axis -> ball centre), contact point
!> P = B + D/2 n.  Metallic force (report 4.4.12: "equivalent to conventional Hertzian
!> contact"): Q = K delta**1.5, delta = -gap, K of a ball (curvatures 2/D, 2/D) in a
!> concave cylinder of radius (D + c)/2 (curvatures 0 along the axis, -2/(D + c) around
!> it), Hertz point contact (adore_contact_hertz) with the cage material.
!> Hydrodynamic force (Gupta 1979, Part III: ball/cage interaction hydrodynamic or metallic,
!> a critical film thickness between): the isoviscous-rigid point contact of Brewe, Hamrock
!> & Taylor (1979), Hamrock, Fundamentals of Fluid Film Lubrication (NASA RP-1255, 1991):
!> H_min (W/U)**2 = 128 alpha_r lambda_b**2 (0.131 atan(alpha_r/2) + 1.683)**2,
!> lambda_b = 1/(1 + 2/(3 alpha_r)), solved for the load
!>     W(h) = eta u_e R_x sqrt(Hhat R_x / h),
!> R_x = D/2 along the pocket axis (the entraining direction of a ball spinning about the
!> bearing axis), alpha_r = R_y/R_x = (D + c)/c, u_e the mean entraining speed (the pocket
!> wall is stationary at the contact: half the ball's slip speed over the wall), evaluated at
!> h = max(gap, h_crit).  Both walls of the pocket act along the line through the ball
!> centre: the net hydrodynamic force on the ball is (W(near gap) - W(far gap)) along -n,
!> zero for a centred ball.  Not modelled: the squeeze film (approach velocity) term.
!> Friction: the deck's RE/cage coefficient (Rec 10.5.1B A, 0.05 in both decks; the report's
!> roller pocket loss is mu F_n x sliding speed, docs/tribology.md) on the metallic load
!> only (a full film carries its load without Coulomb friction; its viscous drag is not
!> modelled), opposite to the slip u of the ball surface over the cage at P, regularised
!> below slip_reg: F = -mu Q u/sqrt(u**2 + slip_reg**2).
!> Abnormal contact (report 4.4.12): delta beyond abnormal_fraction of the radial clearance
!> c/2 - a step whose stage lands there is rejected by the integrator.  Units SI.
module adore_contact_cage_pocket
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: quat_matrix
   use adore_contact_hertz, only: hertz_geometry_t, hertz_geometry
   use adore_state_bearing_state, only: body_state_t
   implicit none
   private

   public :: cage_pocket_pair_t, cage_pocket_geometry_t
   public :: cage_pocket_pair, cage_pocket_contact, pocket_energy, ir_point_load

   !> Interference, as a fraction of the radial clearance, beyond which a contact is abnormal.
   real(wp), parameter, public :: ABNORMAL_FRACTION = 0.25_wp

   !> One ball in a cylindrical pocket: what does not change with the state (m, Pa, Pa s).
   type :: cage_pocket_pair_t
      real(wp) :: d = 0.0_wp                 !< ball diameter
      real(wp) :: clearance = 0.0_wp         !< diametral pocket clearance c (Rec 7.1)
      real(wp) :: pocket_radius = 0.0_wp     !< R_p: radius of the pocket frame origin in the cage
      real(wp) :: stiffness = 0.0_wp         !< Hertz K (N/m**1.5)
      real(wp) :: friction = 0.05_wp         !< RE/cage friction coefficient (Rec 10.5.1B A)
      real(wp) :: viscosity = 0.0_wp         !< lubricant dynamic viscosity at the cage (0: dry)
      real(wp) :: critical_film = 1.0e-6_wp  !< h_crit (m): the hydrodynamic force is taken at max(gap, h_crit)
      real(wp) :: slip_reg = 1.0e-3_wp       !< friction regularisation speed (m/s)
      real(wp) :: ir_constant = 0.0_wp       !< Hhat of the isoviscous-rigid solution (-)
   end type cage_pocket_pair_t

   !> The pocket contact of one ball at one state.  Vectors inertial.
   type :: cage_pocket_geometry_t
      real(wp) :: q(3) = 0.0_wp              !< ball centre in the pocket frame (m)
      real(wp) :: gap = 0.0_wp               !< c/2 - rho (m); < 0: interference
      real(wp) :: normal(3) = 0.0_wp         !< n: pocket axis -> ball centre
      real(wp) :: point(3) = 0.0_wp          !< contact point P (m)
      real(wp) :: metallic_load = 0.0_wp     !< Hertz Q (N)
      real(wp) :: hydro_load = 0.0_wp        !< net hydrodynamic force along -n on the ball (N)
      real(wp) :: slip(3) = 0.0_wp           !< tangential slip of the ball over the cage at P (m/s)
      real(wp) :: friction_force(3) = 0.0_wp !< on the ball (N)
      real(wp) :: power = 0.0_wp             !< friction power loss (W)
      real(wp) :: force_ball(3) = 0.0_wp, moment_ball(3) = 0.0_wp   !< about the ball centre
      real(wp) :: force_cage(3) = 0.0_wp, moment_cage(3) = 0.0_wp   !< about the cage mass centre
      logical :: abnormal = .false.          !< interference beyond the physical limit (4.4.12)
   end type cage_pocket_geometry_t

contains

   !> The pair of a ball of diameter d (m) in a pocket of diametral clearance c (m) at radius
   !> r_pocket (m) of the cage, elastic constants of ball and cage (Pa, -), lubricant viscosity
   !> eta (Pa s, 0: dry) and friction coefficient mu.  ok: the Hertz geometry exists.
   pure function cage_pocket_pair(d, c, r_pocket, e_ball, nu_ball, e_cage, nu_cage, eta, mu) result(p)
      real(wp), intent(in) :: d, c, r_pocket, e_ball, nu_ball, e_cage, nu_cage, eta, mu
      type(cage_pocket_pair_t) :: p
      type(hertz_geometry_t) :: geo
      logical :: ok
      real(wp) :: alpha_r, lambda_b

      p%d = d
      p%clearance = c
      p%pocket_radius = r_pocket
      p%viscosity = eta
      p%friction = mu
      call hertz_geometry([2.0_wp/d, 2.0_wp/d, 0.0_wp, -2.0_wp/(d + c)], e_ball, nu_ball, e_cage, nu_cage, geo, ok)
      if (ok) p%stiffness = geo%stiffness
      if (c > 0.0_wp) then
         alpha_r = (d + c)/c
         lambda_b = 1.0_wp/(1.0_wp + 2.0_wp/(3.0_wp*alpha_r))
         p%ir_constant = 128.0_wp*alpha_r*lambda_b**2*(0.131_wp*atan(0.5_wp*alpha_r) + 1.683_wp)**2
      end if
   end function cage_pocket_pair

   !> Isoviscous-rigid normal load (N) of the pocket at film h (m) and entraining speed u_e
   !> (m/s): eta u_e R_x sqrt(Hhat R_x / h) (module header; Hamrock 1991).
   pure real(wp) function ir_point_load(p, h, u_e)
      type(cage_pocket_pair_t), intent(in) :: p
      real(wp), intent(in) :: h, u_e
      real(wp) :: rx
      rx = 0.5_wp*p%d
      ir_point_load = p%viscosity*abs(u_e)*rx*sqrt(p%ir_constant*rx/h)
   end function ir_point_load

   !> The contact of ball with its pocket at cage-frame azimuth psi (rad) for the pair p
   !> (module header).
   pure subroutine cage_pocket_contact(p, psi, ball, cage, c)
      type(cage_pocket_pair_t), intent(in) :: p
      real(wp), intent(in) :: psi
      type(body_state_t), intent(in) :: ball, cage
      type(cage_pocket_geometry_t), intent(out) :: c
      real(wp) :: rot(3, 3), ball_rot(3, 3), b_rel(3), e_r(3), y_p(3), rho, n_b(3), w_b(3), w_c(3), u(3), u_far(3)
      real(wp) :: p_far(3), w_total, h_near, h_far, delta, un

      rot = quat_matrix(cage%attitude)
      ! R^T (B - c) written out (matmul of a transpose is a libgfortran call; issue #30)
      u = ball%position - cage%position
      b_rel = [rot(1, 1)*u(1) + rot(2, 1)*u(2) + rot(3, 1)*u(3), rot(1, 2)*u(1) + rot(2, 2)*u(2) + rot(3, 2)*u(3), &
               rot(1, 3)*u(1) + rot(2, 3)*u(2) + rot(3, 3)*u(3)]
      e_r = [0.0_wp, -sin(psi), cos(psi)]
      y_p = [0.0_wp, cos(psi), sin(psi)]
      c%q = [b_rel(1), dot_product(b_rel, y_p), dot_product(b_rel, e_r) - p%pocket_radius]
      rho = hypot(c%q(1), c%q(2))
      n_b = y_p
      if (rho > 0.0_wp) n_b = (c%q(1)*[1.0_wp, 0.0_wp, 0.0_wp] + c%q(2)*y_p)/rho
      c%gap = 0.5_wp*p%clearance - rho
      c%normal = matmul(rot, n_b)
      c%point = ball%position + 0.5_wp*p%d*c%normal

      ball_rot = quat_matrix(ball%attitude)     ! a named matrix: no heap temporary for matmul
      w_b = matmul(ball_rot, ball%omega)
      w_c = matmul(rot, cage%omega)
      u = ball%velocity + cross3(w_b, c%point - ball%position) - cage%velocity - cross3(w_c, c%point - cage%position)
      un = dot_product(u, c%normal)
      c%slip = u - un*c%normal

      delta = -c%gap
      if (delta > 0.0_wp) c%metallic_load = p%stiffness*delta**1.5_wp
      c%abnormal = delta > ABNORMAL_FRACTION*0.5_wp*p%clearance
      if (p%viscosity > 0.0_wp .and. p%ir_constant > 0.0_wp) then
         p_far = ball%position - 0.5_wp*p%d*c%normal
         u_far = ball%velocity + cross3(w_b, p_far - ball%position) - cage%velocity - cross3(w_c, p_far - cage%position)
         u_far = u_far - dot_product(u_far, c%normal)*c%normal
         h_near = max(c%gap, p%critical_film)
         h_far = max(0.5_wp*p%clearance + rho, p%critical_film)
         c%hydro_load = ir_point_load(p, h_near, 0.5_wp*norm2(c%slip)) - ir_point_load(p, h_far, 0.5_wp*norm2(u_far))
      end if
      w_total = c%metallic_load + c%hydro_load
      ! Coulomb friction of the metallic contact only: a full film carries its load without
      ! it (Gupta 1979: hydrodynamic or metallic); the film's viscous drag is not modelled
      c%friction_force = -p%friction*c%metallic_load*c%slip/sqrt(dot_product(c%slip, c%slip) + p%slip_reg**2)
      ! 0 - (...): a contact without friction loses +0 W, not the -0 that a negation of 0 prints
      c%power = 0.0_wp - dot_product(c%friction_force, c%slip)

      c%force_ball = -w_total*c%normal + c%friction_force
      c%moment_ball = cross3(c%point - ball%position, c%friction_force)
      c%force_cage = -c%force_ball
      c%moment_cage = cross3(c%point - cage%position, c%force_cage)
   end subroutine cage_pocket_contact

   !> a x b, as adore_core_rotation's cross (the same operations, so the same bits), here so
   !> that gcc inlines it into cage_pocket_contact (6 calls a pocket; issue #30)
   pure function cross3(a, b) result(c)
      real(wp), intent(in) :: a(3), b(3)
      real(wp) :: c(3)
      c = [a(2)*b(3) - a(3)*b(2), a(3)*b(1) - a(1)*b(3), a(1)*b(2) - a(2)*b(1)]
   end function cross3

   !> Elastic energy (J) of the metallic contact, 2/5 K delta**2.5; 0 with clearance.
   pure real(wp) function pocket_energy(p, c)
      type(cage_pocket_pair_t), intent(in) :: p
      type(cage_pocket_geometry_t), intent(in) :: c
      pocket_energy = 0.0_wp
      if (c%gap < 0.0_wp) pocket_energy = 0.4_wp*p%stiffness*(-c%gap)**2.5_wp
   end function pocket_energy

end module adore_contact_cage_pocket
