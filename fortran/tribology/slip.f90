!> Slip along the major axis of a ball/race contact and the traction and power loss it
!> produces with the four-parameter traction curve (report section 2.1, eqs 1, 3, 4).
!>
!> Frame: the one that orbits with the ball (orbital speed w_m about the bearing axis x);
!> components (axial x, radial r) in the ball's meridian plane, as in
!> adore_quasistatic_ball_kinematics.  The ball turns at omega = (w_x, w_r) (the print's
!> "Angular Velocity" with phi = 0), the race at w = Omega - w_m about x.  A point of the
!> major axis lies at angle psi from the contact centre on a circle of radius rho about
!> the ball centre, on the normal n(psi) = side (sin(alpha + psi), cos(alpha + psi))
!> (side = +1 outer race, -1 inner race).  Eq (3), rolling (circumferential) component:
!>     u(psi) = rho (w_x n_r - w_r n_x) - w (r_b + rho n_r)
!>            = A cos(theta) + B sin(theta) + C,  theta = alpha + psi,
!>     A = side rho (w_x - w),  B = -side rho w_r,  C = -w r_b,
!> so the pure-rolling points (u = 0) are found in closed form; the major axis (s = rho psi
!> in [-a, a]) is split there and each zone integrated by Gauss-Legendre (report 2.1).
!> Load per unit length along the major axis (Hertz): dQ/ds = 3 Q / (4 a) (1 - (s/a)**2).
!> Traction per strip: kappa(|u|) sign(u) dQ (eq 1, one-dimensional model); power: the
!> integral of kappa(|u|) |u| dQ (eq 4).
module adore_tribology_slip
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_quadrature, only: gauss_legendre
   use adore_tribology_traction_law, only: traction_law_t, law_kappa
   use adore_contact_ball_race_kinematics, only: ball_race_contact_t, SIDE_OUTER, SIDE_INNER
   implicit none
   private

   public :: ball_race_contact_t, contact_traction_t, SIDE_OUTER, SIDE_INNER
   public :: contact_slip, pure_rolling_points, contact_traction, contact_kinematics, interior_extremum, &
             major_axis_nodes, print_slip_node, contact_power, rolling_zones, axis_nodes, cross_slip, &
             take_kinematics


   !> Integrated contact quantities.
   type :: contact_traction_t
      real(wp) :: force = 0.0_wp        !< traction on the race along the slip direction (N)
      !> the traction's distribution over the major axis, sum of dF cos(psi) and dF sin(psi)
      !> with psi = s / rho (N): the moment of the traction about the ball centre
      !> (adore_forces_ball_bearing)
      real(wp) :: force_cos = 0.0_wp, force_sin = 0.0_wp
      !> two-dimensional traction only (a transverse slip given): the traction across the
      !> rolling direction, along e_m(psi) = d n(psi) / d psi, on the race: sums of dF_m,
      !> dF_m cos(psi), dF_m sin(psi) (N; adore_forces_ball_bearing); 0 in one dimension
      real(wp) :: cross_force(3) = 0.0_wp
      real(wp) :: coefficient = 0.0_wp  !< force / load (-)
      real(wp) :: power = 0.0_wp        !< heat generated, integral of kappa |u| dQ (W)
      real(wp) :: sliding = 0.0_wp      !< integral of |u| dQ (N m/s): the Archard wear's load x slip
      real(wp) :: max_slip = 0.0_wp     !< largest |u| on the major axis (m/s)
      real(wp) :: centre_slip = 0.0_wp  !< u at the contact centre (m/s)
      real(wp) :: rolling_speed = 0.0_wp  !< mean entraining speed (u_ball + u_race)/2 at the centre (m/s)
      real(wp) :: spin = 0.0_wp         !< spin of the ball relative to the race about the normal (rad/s)
      real(wp) :: spin_roll = 0.0_wp    !< spin / (rolling_speed / R_x) (-)
      real(wp) :: rx = 0.0_wp           !< effective radius in the rolling direction (m)
      integer :: n_rolling = 0          !< number of pure-rolling points inside (-a, a)
      real(wp) :: rolling_points(2) = 0.0_wp  !< their positions s (m), ascending
   end type contact_traction_t

contains

   !> Slip velocity u(s) (m/s) at position s (m) on the major axis, eq (3) rolling
   !> component (ball surface speed minus race surface speed).
   elemental function contact_slip(c, s) result(u)
      type(ball_race_contact_t), intent(in) :: c
      real(wp), intent(in) :: s
      real(wp) :: u, th

      th = c%alpha + s/c%rho
      u = c%side*c%rho*(c%omega(1) - c%race_speed)*cos(th) - c%side*c%rho*c%omega(2)*sin(th) &
          - c%race_speed*c%r_b
   end function contact_slip

   !> Pure-rolling points s (m) of the contact: roots of u(s) strictly inside (-a, a),
   !> ascending (at most two: u is a shifted sinusoid in s / rho with period >> 2 a).
   !> polar, when given: u(s) + race_speed r_b = r cos(theta - delta) as [r (m/s), delta
   !> (rad)], delta 0 when r = 0 (interior_extremum takes it instead of recomputing it).
   pure subroutine pure_rolling_points(c, n, s, polar)
      type(ball_race_contact_t), intent(in) :: c
      integer, intent(out) :: n
      real(wp), intent(out) :: s(2)
      real(wp), intent(out), optional :: polar(2)
      real(wp) :: aa, bb, cc, r, delta, gam, cand, psi
      integer :: k, m

      n = 0
      s = 0.0_wp
      aa = c%side*c%rho*(c%omega(1) - c%race_speed)
      bb = -c%side*c%rho*c%omega(2)
      cc = -c%race_speed*c%r_b
      r = hypot(aa, bb)
      if (present(polar)) polar = [r, 0.0_wp]
      if (r <= 0.0_wp) return
      if (present(polar)) then
         delta = atan2(bb, aa)
         polar(2) = delta
      end if
      if (abs(cc) > r) return
      if (.not. present(polar)) delta = atan2(bb, aa)
      gam = acos(-cc/r)
      do k = 1, 2
         cand = delta + merge(gam, -gam, k == 1)
         do m = -2, 2                       ! bring psi = theta - alpha to its principal value
            psi = cand + 2.0_wp*pi*m - c%alpha
            if (abs(psi*c%rho) < c%a) then
               if (n == 1) then
                  if (abs(psi*c%rho - s(1)) <= 1.0e-14_wp*c%a) cycle
               end if
               n = n + 1
               s(n) = psi*c%rho
               exit
            end if
         end do
      end do
      if (n == 2) then
         if (s(2) < s(1)) s = [s(2), s(1)]
      end if
   end subroutine pure_rolling_points

   !> Centre kinematics (no traction): spin (rad/s), entraining speed (m/s), R_x (m),
   !> spin/roll ratio and centre slip, filled into t; sin_cos: sin and cos of the contact
   !> angle when the caller has computed them.
   pure subroutine contact_kinematics(c, t, sin_cos)
      type(ball_race_contact_t), intent(in) :: c
      type(contact_traction_t), intent(inout) :: t
      !> [sin(c%alpha), cos(c%alpha)] when the caller has them (the same libm values)
      real(wp), intent(in), optional :: sin_cos(2)
      real(wp) :: n(2), u_ball, u_race, r_race

      if (present(sin_cos)) then
         n = c%side*sin_cos
      else if (c%trig_of == c%alpha) then
         n = c%side*c%sin_cos           ! the contact geometry's (planar_contact), the same values
      else
         n = c%side*[sin(c%alpha), cos(c%alpha)]
      end if
      u_ball = c%rho*(c%omega(1)*n(2) - c%omega(2)*n(1))
      r_race = c%r_b + c%rho*n(2)
      u_race = c%race_speed*r_race
      t%centre_slip = u_ball - u_race
      t%rolling_speed = 0.5_wp*(u_ball + u_race)
      t%spin = dot_product(c%omega, n) - c%race_speed*n(1)
      ! 1/R_x = 1/rho - side/R (outer race concave, inner race convex in the rolling direction)
      t%rx = 1.0_wp/(1.0_wp/c%rho - real(c%side, wp)/r_race)
      t%spin_roll = 0.0_wp
      if (t%rolling_speed /= 0.0_wp) t%spin_roll = t%spin*t%rx/t%rolling_speed
   end subroutine contact_kinematics

   !> The centre kinematics that contact_kinematics fills (centre slip, entraining speed,
   !> spin, R_x, spin/roll), copied from k into t: for a caller that has them for the same
   !> contact already.
   pure subroutine take_kinematics(k, t)
      type(contact_traction_t), intent(in) :: k
      type(contact_traction_t), intent(inout) :: t
      t%centre_slip = k%centre_slip
      t%rolling_speed = k%rolling_speed
      t%spin = k%spin
      t%rx = k%rx
      t%spin_roll = k%spin_roll
   end subroutine take_kinematics

   !> Traction, power loss and kinematics of the contact (report eqs 1, 3, 4): traction
   !> law (the deck's curve or a traction-slip table, `adore_tribology_traction_law`), each zone between pure-rolling points
   !> integrated with an n_gauss-point Gauss-Legendre rule; kappa is multiplied by
   !> kappa_scale (1 for the bare curve).  Input error for a bad contact or n_gauss < 1.
   !> transverse (m/s), when given: the two-dimensional traction of report eq 5 - the slip
   !> across the rolling direction u_m(psi) = m1 + m2 cos psi + m3 sin psi (psi = s / rho;
   !> adore_contact_ball_race's transverse_coeff) joins u(s) at every node, the traction
   !> kappa(|u|) dQ acts along the slip vector (u, u_m)/|u| (force, force_cos, force_sin
   !> from its rolling part, t%cross_force from its transverse part), power and sliding
   !> take |u|, max_slip the largest |u| at the ends and nodes.
   subroutine contact_traction(c, law, kappa_scale, n_gauss, t, error, transverse)
      type(ball_race_contact_t), intent(in) :: c
      type(traction_law_t), intent(in) :: law
      real(wp), intent(in) :: kappa_scale
      integer, intent(in) :: n_gauss
      type(contact_traction_t), intent(out) :: t
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: transverse(3)
      real(wp) :: x(3*max(n_gauss, 1)), w(3*max(n_gauss, 1))
      real(wp) :: u, kap, dq, um, us, cs, sn
      integer :: j, n

      call check_law_contact(c, n_gauss, error)
      if (allocated(error)) return
      call contact_kinematics(c, t)
      call pure_rolling_points(c, t%n_rolling, t%rolling_points)
      call axis_nodes(c, n_gauss, x, w, n)
      if (present(transverse)) then
         t%max_slip = max(hypot(contact_slip(c, -c%a), cross_slip(transverse, -c%a/c%rho)), &
                          hypot(contact_slip(c, c%a), cross_slip(transverse, c%a/c%rho)))
         do j = 1, n
            u = contact_slip(c, x(j))
            cs = cos(x(j)/c%rho)
            sn = sin(x(j)/c%rho)
            um = transverse(1) + transverse(2)*cs + transverse(3)*sn
            us = hypot(u, um)
            kap = kappa_scale*law_kappa(law, us)
            dq = 0.75_wp*c%load/c%a*(1.0_wp - (x(j)/c%a)**2)*w(j)
            t%power = t%power + kap*us*dq
            t%sliding = t%sliding + us*dq
            t%max_slip = max(t%max_slip, us)
            if (us <= 0.0_wp) cycle
            t%force = t%force + kap*dq*u/us
            t%force_cos = t%force_cos + kap*dq*u/us*cs
            t%force_sin = t%force_sin + kap*dq*u/us*sn
            t%cross_force = t%cross_force + kap*dq*um/us*[1.0_wp, cs, sn]
         end do
         call interior_extremum(c, t%max_slip)      ! |u| >= |u_r| there
         if (c%load > 0.0_wp) t%coefficient = t%force/c%load
         return
      end if
      t%max_slip = max(abs(contact_slip(c, -c%a)), abs(contact_slip(c, c%a)))
      do j = 1, n
         u = contact_slip(c, x(j))
         kap = kappa_scale*law_kappa(law, u)
         dq = 0.75_wp*c%load/c%a*(1.0_wp - (x(j)/c%a)**2)*w(j)
         t%force = t%force + sign(kap, u)*dq
         t%force_cos = t%force_cos + sign(kap, u)*dq*cos(x(j)/c%rho)
         t%force_sin = t%force_sin + sign(kap, u)*dq*sin(x(j)/c%rho)
         t%power = t%power + kap*abs(u)*dq
         t%sliding = t%sliding + abs(u)*dq
         t%max_slip = max(t%max_slip, abs(u))
      end do
      ! a stationary point of u inside the contact (the sinusoid's extremum)
      call interior_extremum(c, t%max_slip)
      if (c%load > 0.0_wp) t%coefficient = t%force/c%load
   end subroutine contact_traction

   !> Slip (m/s) across the rolling direction at psi (rad) on the major axis from the
   !> coefficients m = [m1, m2, m3] of u_m(psi) = m1 + m2 cos psi + m3 sin psi.
   pure real(wp) function cross_slip(m, psi)
      real(wp), intent(in) :: m(3), psi
      cross_slip = m(1) + m(2)*cos(psi) + m(3)*sin(psi)
   end function cross_slip

   !> Power (W) of contact c with the traction law: contact_traction's t%power, the same
   !> nodes and sums bit for bit, without the other integrals (the minimum-dissipation
   !> search's objective).  Input error as contact_traction.
   subroutine contact_power(c, law, kappa_scale, n_gauss, power, error)
      type(ball_race_contact_t), intent(in) :: c
      type(traction_law_t), intent(in) :: law
      real(wp), intent(in) :: kappa_scale
      integer, intent(in) :: n_gauss
      real(wp), intent(out) :: power
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: x(3*n_gauss), w(3*n_gauss), u, kap, dq
      integer :: n, j

      power = 0.0_wp
      call check_law_contact(c, n_gauss, error)
      if (allocated(error)) return
      call axis_nodes(c, n_gauss, x, w, n)
      do j = 1, n
         u = contact_slip(c, x(j))
         kap = kappa_scale*law_kappa(law, u)
         dq = 0.75_wp*c%load/c%a*(1.0_wp - (x(j)/c%a)**2)*w(j)
         power = power + kap*abs(u)*dq
      end do
   end subroutine contact_power

   !> The nodes s(1:n) (m) and weights w(1:n) (m) of major_axis_nodes without allocation:
   !> n_gauss Gauss-Legendre points per slip zone, zones split at the pure-rolling points.
   pure subroutine axis_nodes(c, n_gauss, s, w, n)
      type(ball_race_contact_t), intent(in) :: c
      integer, intent(in) :: n_gauss
      real(wp), intent(out) :: s(3*n_gauss), w(3*n_gauss)
      integer, intent(out) :: n
      real(wp) :: edges(4), pts(2), x(n_gauss), wx(n_gauss), lo, hi
      integer :: nz, nr, z

      call rolling_zones(c, edges, nz, nr, pts)
      call gauss_legendre(n_gauss, x, wx)
      s = 0.0_wp
      w = 0.0_wp
      do z = 1, nz
         lo = edges(z)
         hi = edges(z + 1)
         s((z - 1)*n_gauss + 1:z*n_gauss) = 0.5_wp*(lo + hi) + 0.5_wp*(hi - lo)*x
         w((z - 1)*n_gauss + 1:z*n_gauss) = 0.5_wp*(hi - lo)*wx
      end do
      n = nz*n_gauss
   end subroutine axis_nodes

   !> Engine error unless contact c lies inside the traction model (0 < a < rho < r_b: the
   !> contact ellipse inside the groove, the groove wider than the ball); input error unless
   !> n_gauss >= 1.
   subroutine check_law_contact(c, n_gauss, error)
      type(ball_race_contact_t), intent(in) :: c
      integer, intent(in) :: n_gauss
      type(error_type), allocatable, intent(out) :: error
      character(len=600) :: buf
      if (.not. (c%rho > 0.0_wp .and. c%a > 0.0_wp .and. c%a < c%rho .and. c%load >= 0.0_wp &
                 .and. c%r_b > c%rho .and. abs(c%side) == 1)) then
         write (buf, "(a,es10.3,a,es10.3,a,es10.3,a,es10.3,a)") "contact traction: the contact is outside the "// &
            "model (need 0 < a < rho < r_b): semi-major axis a =", c%a, " m, contact surface radius about the "// &
            "ball centre rho =", c%rho, " m, ball-centre radius r_b =", c%r_b, " m, load", c%load, &
            " N; the contact ellipse is as large as the ball: a conformity this close (curvature factor near "// &
            "0.5), an interference fit or a speed this large loads the contact beyond the Hertz model"
         call engine_error(error, trim(buf))
         return
      end if
      if (n_gauss < 1) then
         call input_error(error, "contact traction: need at least one Gauss point per zone")
         return
      end if
   end subroutine check_law_contact

   !> The slip zones of contact c's major axis: edges(1:nz+1) from -a to a (m), split at
   !> its pure-rolling points (n_rolling of them, at points(1:n_rolling), m; report 2.1);
   !> polar: as pure_rolling_points'.
   pure subroutine rolling_zones(c, edges, nz, n_rolling, points, polar)
      type(ball_race_contact_t), intent(in) :: c
      real(wp), intent(out) :: edges(4), points(2)
      integer, intent(out) :: nz, n_rolling
      real(wp), intent(out), optional :: polar(2)

      edges = 0.0_wp
      call pure_rolling_points(c, n_rolling, points, polar)
      edges(1) = -c%a
      edges(2:n_rolling + 1) = points(1:n_rolling)
      edges(n_rolling + 2) = c%a
      nz = n_rolling + 1
   end subroutine rolling_zones

   !> Centre kinematics of contact c into t and the quadrature of the major axis: nodes
   !> s(:) (m) and weights w(:) (m, sum 2a), n_gauss Gauss-Legendre points per slip zone
   !> (zones split at the pure-rolling points, report 2.1).
   pure subroutine major_axis_nodes(c, n_gauss, t, s, w)
      type(ball_race_contact_t), intent(in) :: c
      integer, intent(in) :: n_gauss
      type(contact_traction_t), intent(inout) :: t
      real(wp), allocatable, intent(out) :: s(:), w(:)
      real(wp) :: sa(3*n_gauss), wa(3*n_gauss)
      integer :: n

      call contact_kinematics(c, t)
      call pure_rolling_points(c, t%n_rolling, t%rolling_points)
      call axis_nodes(c, n_gauss, sa, wa, n)
      s = sa(1:n)
      w = wa(1:n)
   end subroutine major_axis_nodes

   !> The print node of contact c: among the nodes of the n_gauss-point rule per slip zone
   !> (major_axis_nodes), the one of largest |u| (the last of equal ones), its position s
   !> (m) and slip u (m/s).  The report prints that |u| as the contact's "Slip Velocity"
   !> and the local traction coefficient there as "Trac Coeff" with n_gauss = 4
   !> (docs/tribology.md).
   pure subroutine print_slip_node(c, n_gauss, s, u)
      type(ball_race_contact_t), intent(in) :: c
      integer, intent(in) :: n_gauss
      integer :: q_
      real(wp), parameter :: COS_T(9) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 1.0_wp), q_ = 1, 9)]
      real(wp), parameter :: SIN_T(8) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 2.0_wp), q_ = 1, 8)]
      real(wp), intent(out) :: s, u
      real(wp) :: x(3*max(n_gauss, 1)), w(3*max(n_gauss, 1))
      real(wp) :: uj, sc(2), ps, ps2, cps, sps
      integer :: j, n

      ! major_axis_nodes' nodes without its kinematics and allocation (the same nodes)
      call axis_nodes(c, n_gauss, x, w, n)
      if (c%trig_of == c%alpha) then
         sc = c%sin_cos
      else
         sc = [sin(c%alpha), cos(c%alpha)]
      end if
      s = 0.0_wp
      u = 0.0_wp
      do j = 1, n
         ! contact_slip(c, x(j)) with cos, sin of alpha + psi by angle addition, psi = s / rho
         ! (|psi| < a / rho < 1) by its Taylor series to psi**18 / 18!, psi**17 / 17!
         ! (truncation below 8.3e-18): no sincos a node (issue #30; equal to round-off,
         ! test_tribology)
         ps = x(j)/c%rho
         ps2 = ps*ps
         cps = 1.0_wp + ps2*(COS_T(1) + ps2*(COS_T(2) + ps2*(COS_T(3) + ps2*(COS_T(4) + ps2*(COS_T(5) &
               + ps2*(COS_T(6) + ps2*(COS_T(7) + ps2*(COS_T(8) + ps2*COS_T(9)))))))))
         sps = ps + ps*ps2*(SIN_T(1) + ps2*(SIN_T(2) + ps2*(SIN_T(3) + ps2*(SIN_T(4) + ps2*(SIN_T(5) &
               + ps2*(SIN_T(6) + ps2*(SIN_T(7) + ps2*SIN_T(8))))))))
         uj = c%side*c%rho*(c%omega(1) - c%race_speed)*(sc(2)*cps - sc(1)*sps) &
              - c%side*c%rho*c%omega(2)*(sc(1)*cps + sc(2)*sps) - c%race_speed*c%r_b
         if (abs(uj) >= abs(u)) then
            s = x(j)
            u = uj
         end if
      end do
   end subroutine print_slip_node

   !> Raise umax to |u| at the extremum of u(s) when it lies inside (-a, a).  polar, when
   !> given: pure_rolling_points' [r, delta] of the same contact (not recomputed).
   pure subroutine interior_extremum(c, umax, polar)
      type(ball_race_contact_t), intent(in) :: c
      real(wp), intent(inout) :: umax
      real(wp), intent(in), optional :: polar(2)
      real(wp) :: aa, bb, delta, psi
      integer :: m

      if (present(polar)) then
         if (polar(1) <= 0.0_wp) return
         delta = polar(2)
      else
         aa = c%side*c%rho*(c%omega(1) - c%race_speed)
         bb = -c%side*c%rho*c%omega(2)
         if (hypot(aa, bb) <= 0.0_wp) return
         delta = atan2(bb, aa)              ! u' = 0 where theta = delta (+ k pi)
      end if
      do m = -3, 3
         psi = delta + pi*m - c%alpha
         if (abs(psi*c%rho) < c%a) umax = max(umax, abs(contact_slip(c, psi*c%rho)))
      end do
   end subroutine interior_extremum

end module adore_tribology_slip
