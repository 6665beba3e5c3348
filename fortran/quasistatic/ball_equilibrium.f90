!> Quasi-static equilibrium of a ball bearing at high speed (ADORE ADRA4/ADRG0,
!> report section 3.1, eqs 54-72).
!>
!> Geometry (eqs 59-64), in the meridian plane of ball k at azimuth phi_k (measured from
!> the inertial z axis towards -y, eq 54): the ball centre B = (x, r); the groove curvature
!> centre of race j is C_j; a_j = B - C_j; the geometric interaction is
!>     delta_j = |a_j| - (f_j - 1/2) D                                        (60)
!> (eq 60 with the groove radius f_j D and the ball radius D/2); the Hertz load
!>     Q_j = K_j delta_j**1.5                                                  (61)
!> acts on the ball along -a_j/|a_j| through the contact point B + D/2 a_j/|a_j| (64),
!> and the contact angle is alpha_j = atan(|a_jx| / |a_jr|) (62-63).
!> Ball equilibrium (65-66): the two contact forces and the centrifugal force
!> m r w_m**2 (radial, outward) balance; gyroscopic moments and contact tractions are
!> not part of eqs 65-66 and are left out, as in the report.
!> Race equilibrium (68-72): the outer race is fixed; the inner race moves by
!> u = (X, Y, Z, theta_2, theta_3) (translations, misalignment about y and z).  Its
!> groove centre at azimuth phi moves by S(phi) u (small rotations, linear in theta:
!> misalignments of the order 1e-4 rad make the neglected terms 1e-8 of the deflection).
!> The forces and moments of the balls on the inner race, plus the applied load and the
!> race weight, vanish.  The moment of a contact force is taken about the race centre
!> with the force applied at the groove centre (on the force's line of action, so the
!> moment equals that of eq 67).  kFS4/kFS5: a misalignment is either solved for
!> (moment equilibrium) or prescribed.
!>
!> Solution as in ADORE, in two Newton-Raphson levels with analytic Jacobians: for a
!> given race position every ball is put in equilibrium (2 x 2), then the race equations
!> are iterated with the Jacobian of the race forces including the balls' response
!> (implicit function theorem: dB/du = J_b**-1 K_i S).  The Hertz stiffness K_j depends
!> weakly on the contact angle (through the rolling-direction curvature); it is frozen
!> during one Newton solve and updated between solves until it no longer changes.
!> Units SI: m, N, rad, rad/s, kg.
module adore_quasistatic_ball_equilibrium
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error
   use adore_core_linalg, only: solve_dense
   use adore_contact_hertz, only: hertz_geometry_t, hertz_contact_t, hertz_geometry, hertz_contact
   use adore_contact_ball_race, only: ball_race_curvatures
   implicit none
   private

   public :: ball_qs_bearing_t, ball_qs_load_t, ball_qs_solution_t
   public :: solve_ball_equilibrium, race_residual, ball_residual, contact_stiffness
   public :: inner_groove_centre, mounted_axial_origin

   !> Levenberg-Marquardt damping of a singular race Jacobian, relative to its largest
   !> entry (the race stiffness; the Jacobian of the race residual is -stiffness).
   real(wp), parameter :: LM_DAMPING = 1.0e-6_wp

   !> Bearing data needed by the quasi-static solution.
   type :: ball_qs_bearing_t
      integer :: n_balls = 0
      real(wp) :: d = 0.0_wp                !< ball diameter D (m)
      real(wp) :: dm = 0.0_wp               !< pitch diameter (m), used in the contact curvatures
      real(wp) :: f_o = 0.52_wp             !< outer groove curvature factor (groove radius / D)
      real(wp) :: f_i = 0.52_wp             !< inner groove curvature factor
      real(wp) :: ball_mass = 0.0_wp        !< (kg)
      real(wp) :: e_ball = 2.0e11_wp, nu_ball = 0.25_wp    !< elastic constants of the balls
      real(wp) :: e_outer = 2.0e11_wp, nu_outer = 0.25_wp  !< outer race
      real(wp) :: e_inner = 2.0e11_wp, nu_inner = 0.25_wp  !< inner race
      real(wp) :: x_o = 0.0_wp, r_o = 0.0_wp  !< outer groove curvature centre (axial, radial) (m)
      real(wp) :: x_i = 0.0_wp, r_i = 0.0_wp  !< inner groove curvature centre in the inner race frame (m)
      real(wp) :: inner_race_mass = 0.0_wp    !< (kg), for the race weight
   end type ball_qs_bearing_t

   !> Loads and constraints on the inner race.
   type :: ball_qs_load_t
      real(wp) :: force(3) = 0.0_wp         !< applied force on the inner race, inertial x, y, z (N)
      real(wp) :: moment(3) = 0.0_wp        !< applied moment on the inner race (N m)
      real(wp) :: gravity(3) = 0.0_wp       !< gravity vector (m/s**2)
      logical :: solve_moment(2) = .false.  !< moment equilibrium about y, z (kFS4/kFS5 = 0)
      real(wp) :: misalignment(2) = 0.0_wp  !< prescribed theta_2, theta_3 when not solved (rad)
   end type ball_qs_load_t

   !> The equilibrium: per-ball arrays (ball k at azimuth 2 pi (k-1)/n) and the race state.
   type :: ball_qs_solution_t
      real(wp), allocatable :: azimuth(:)          !< phi_k (rad)
      real(wp), allocatable :: orbital_speed(:)    !< w_m used for the centrifugal force (rad/s)
      real(wp), allocatable :: x(:), r(:)          !< ball centre, axial and radial (m)
      real(wp), allocatable :: alpha_o(:), alpha_i(:)   !< contact angles (rad)
      real(wp), allocatable :: n_o(:, :), n_i(:, :)     !< (2, n) unit normals ball centre -> contact
      real(wp), allocatable :: q_o(:), q_i(:)      !< contact loads (N)
      real(wp), allocatable :: delta_o(:), delta_i(:)   !< geometric interactions (m)
      real(wp), allocatable :: k_o(:), k_i(:)      !< Hertz stiffness (N/m**1.5)
      real(wp), allocatable :: centrifugal(:)      !< m r w_m**2 (N)
      type(hertz_contact_t), allocatable :: c_o(:), c_i(:)  !< contact ellipses
      real(wp) :: u(5) = 0.0_wp                    !< inner race X, Y, Z (m), theta_2, theta_3 (rad)
      !> axial displacement of the inner race from its mounted, unloaded position (m):
      !> u(1) - mounted_axial_origin (the print's IRace axial Mass Center Position)
      real(wp) :: axial_displacement = 0.0_wp
      real(wp) :: inner_force(3) = 0.0_wp         !< force of the balls on the inner race (N)
      real(wp) :: inner_moment(3) = 0.0_wp        !< moment of the balls on the inner race (N m)
      real(wp) :: outer_force(3) = 0.0_wp         !< force of the balls on the outer race (N)
      real(wp) :: outer_moment(3) = 0.0_wp        !< moment of the balls on the outer race (N m)
      real(wp) :: race_residual(5) = 0.0_wp       !< inner race force/moment balance (N, N m)
      real(wp) :: max_ball_residual = 0.0_wp      !< largest ball force imbalance (N)
      integer :: iterations = 0                    !< race Newton iterations, all stiffness passes
   end type ball_qs_solution_t


contains

   !> The inner race's mounted, unloaded axial position u_x (m) in the frame of u: the race
   !> centred radially (Y = Z = 0), untilted, moved along +x until the balls just touch
   !> both mounted raceways (groove centre distance (f_o + f_i - 1) D), i.e. the axial play
   !> taken up towards +x:  u_x = sqrt(A**2 - (r_i - r_o)**2) - (x_i - x_o).  A bearing
   !> whose mounted radial clearance is negative (r_i - r_o > A) has no unloaded position;
   !> its origin is the axially centred one, x_i + u_x = x_o.  Zero for the unmounted
   !> geometry of adore_geometry_mounted's ball_groove_centres (both races touching along
   !> alpha0).
   pure function mounted_axial_origin(b) result(u_x)
      type(ball_qs_bearing_t), intent(in) :: b
      real(wp) :: u_x
      real(wp) :: a, dr

      a = (b%f_o + b%f_i - 1.0_wp)*b%d
      dr = b%r_i - b%r_o
      u_x = b%x_o - b%x_i
      if (abs(dr) < a) u_x = u_x + sqrt(a*a - dr*dr)
   end function mounted_axial_origin

   !> Hertz stiffness K (N/m**1.5) of a ball/race contact at contact angle alpha (rad).
   !>
   !> Curvatures of adore_contact_ball_race's ball_race_curvatures (Harris).  outer =
   !> .true. for the outer race.
   function contact_stiffness(b, alpha, outer, geo) result(k)
      type(ball_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: alpha
      logical, intent(in) :: outer
      type(hertz_geometry_t), intent(out), optional :: geo
      real(wp) :: k

      type(hertz_geometry_t) :: g
      logical :: ok

      if (outer) then
         call hertz_geometry(ball_race_curvatures(b%d, b%dm, b%f_o, alpha, .true.), b%e_ball, b%nu_ball, &
                             b%e_outer, b%nu_outer, g, ok)
      else
         call hertz_geometry(ball_race_curvatures(b%d, b%dm, b%f_i, alpha, .false.), b%e_ball, b%nu_ball, &
                             b%e_inner, b%nu_inner, g, ok)
      end if
      k = 0.0_wp
      if (ok) k = g%stiffness
      if (present(geo)) geo = g
   end function contact_stiffness

   !> Inner groove curvature centre (axial, radial) at azimuth phi for race position u,
   !> and its sensitivity S = d(centre)/du (2 x 5).
   pure subroutine inner_groove_centre(b, phi, u, c, s)
      type(ball_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: phi, u(5)
      real(wp), intent(out) :: c(2), s(2, 5)

      s(1, :) = [1.0_wp, 0.0_wp, 0.0_wp, b%r_i*cos(phi), b%r_i*sin(phi)]
      s(2, :) = [0.0_wp, -sin(phi), cos(phi), -b%x_i*cos(phi), -b%x_i*sin(phi)]
      c = [b%x_i, b%r_i] + matmul(s, u)
   end subroutine inner_groove_centre

   !> Contact force on the ball f = -Q a/|a| (N) and its Jacobian df/da for a = B - C.
   pure subroutine contact_force(a, clearance_radius, k, f, dfda, q, delta)
      real(wp), intent(in) :: a(2), clearance_radius, k
      real(wp), intent(out) :: f(2), dfda(2, 2), q, delta

      real(wp) :: la, e(2), dq

      la = norm2(a)
      e = a/la
      delta = la - clearance_radius
      f = 0.0_wp
      dfda = 0.0_wp
      q = 0.0_wp
      if (delta <= 0.0_wp) return
      q = k*delta**1.5_wp
      dq = 1.5_wp*k*sqrt(delta)
      f = -q*e
      dfda(1, 1) = -(dq*e(1)*e(1) + q/la*(1.0_wp - e(1)*e(1)))
      dfda(2, 2) = -(dq*e(2)*e(2) + q/la*(1.0_wp - e(2)*e(2)))
      dfda(1, 2) = -(dq*e(1)*e(2) - q/la*e(1)*e(2))
      dfda(2, 1) = dfda(1, 2)
   end subroutine contact_force

   !> Ball force balance R_b (N) (eqs 65-66) and its Jacobian dR_b/dB for a ball at
   !> B = (x, r) between groove centres c_o, c_i, with stiffnesses k_o, k_i, mass m and
   !> orbital speed w (rad/s).  Also returns the inner contact's df/da (k_mat_i).
   pure subroutine ball_residual(b, bpos, c_o, c_i, k_o, k_i, w, res, jac, k_mat_i)
      type(ball_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: bpos(2), c_o(2), c_i(2), k_o, k_i, w
      real(wp), intent(out) :: res(2), jac(2, 2), k_mat_i(2, 2)

      real(wp) :: f_o(2), f_i(2), k_mat_o(2, 2), q, delta

      call contact_force(bpos - c_o, (b%f_o - 0.5_wp)*b%d, k_o, f_o, k_mat_o, q, delta)
      call contact_force(bpos - c_i, (b%f_i - 0.5_wp)*b%d, k_i, f_i, k_mat_i, q, delta)
      res = f_o + f_i + [0.0_wp, b%ball_mass*bpos(2)*w**2]
      jac = k_mat_o + k_mat_i
      jac(2, 2) = jac(2, 2) + b%ball_mass*w**2
   end subroutine ball_residual

   !> Put one ball in equilibrium for fixed groove centres (Newton with step halving).
   pure subroutine solve_ball(b, c_o, c_i, k_o, k_i, w, bpos, jac, k_mat_i, res_norm)
      type(ball_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: c_o(2), c_i(2), k_o, k_i, w
      real(wp), intent(inout) :: bpos(2)
      real(wp), intent(out) :: jac(2, 2), k_mat_i(2, 2), res_norm

      real(wp) :: res(2), step(2), trial(2), res_t(2), jac_t(2, 2), kmi_t(2, 2), tol
      integer :: it, half
      logical :: ok

      tol = 1.0e-13_wp*max(1.0_wp, b%ball_mass*norm2(c_o)*w**2)
      call ball_residual(b, bpos, c_o, c_i, k_o, k_i, w, res, jac, k_mat_i)
      do it = 1, 100
         res_norm = norm2(res)
         if (res_norm <= tol) return
         call solve_dense(2, jac, -res, step, ok)
         if (.not. ok) then
            ! no contact carries load: move the ball towards the outer groove until it touches
            step = (c_o - bpos)
            step = step*(1.0_wp - ((b%f_o - 0.5_wp)*b%d + 1.0e-9_wp*b%d)/max(norm2(step), tiny(1.0_wp)))
         end if
         if (norm2(step) <= 1.0e-15_wp*b%dm) return   ! converged to round-off
         do half = 0, 40
            trial = bpos + step*0.5_wp**half
            call ball_residual(b, trial, c_o, c_i, k_o, k_i, w, res_t, jac_t, kmi_t)
            if (norm2(res_t) < res_norm) exit
         end do
         if (norm2(res_t) >= res_norm) return          ! no descent left: round-off level
         bpos = trial
         res = res_t
         jac = jac_t
         k_mat_i = kmi_t
      end do
      res_norm = norm2(res)
   end subroutine solve_ball

   !> Inner race force/moment balance (N, N m) and its Jacobian d/du for race position u,
   !> putting every ball in equilibrium first (ball positions updated in sol).
   !> res = [Fx, Fy, Fz, My, Mz] of balls + applied load + race weight.
   subroutine race_residual(b, ld, u, sol, res, jac)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_load_t), intent(in) :: ld
      real(wp), intent(in) :: u(5)
      type(ball_qs_solution_t), intent(inout) :: sol
      real(wp), intent(out) :: res(5), jac(5, 5)

      real(wp) :: c_o(2), c_i(2), s(2, 5), bpos(2), jb(2, 2), kmi(2, 2), jb_inv(2, 2)
      real(wp) :: db(2, 5), dg(2, 5), g(2), f_i(2), kmat(2, 2), q, delta, phi, det, mphi
      real(wp) :: dm(5), rn, weight(3)
      integer :: k

      weight = b%inner_race_mass*ld%gravity
      res = 0.0_wp
      res(1:3) = ld%force + weight
      res(4:5) = ld%moment(2:3)
      jac = 0.0_wp
      sol%max_ball_residual = 0.0_wp
      c_o = [b%x_o, b%r_o]
      do k = 1, b%n_balls
         phi = sol%azimuth(k)
         call inner_groove_centre(b, phi, u, c_i, s)
         bpos = [sol%x(k), sol%r(k)]
         call solve_ball(b, c_o, c_i, sol%k_o(k), sol%k_i(k), sol%orbital_speed(k), bpos, jb, kmi, rn)
         sol%max_ball_residual = max(sol%max_ball_residual, rn)
         sol%x(k) = bpos(1)
         sol%r(k) = bpos(2)
         ! force of the ball on the inner race (meridian components) g = -f_i
         call contact_force(bpos - c_i, (b%f_i - 0.5_wp)*b%d, sol%k_i(k), f_i, kmat, q, delta)
         g = -f_i
         det = jb(1, 1)*jb(2, 2) - jb(1, 2)*jb(2, 1)
         if (abs(det) > 0.0_wp) then
            jb_inv = reshape([jb(2, 2), -jb(2, 1), -jb(1, 2), jb(1, 1)], [2, 2])/det
            db = matmul(jb_inv, matmul(kmi, s))
         else
            db = 0.0_wp
         end if
         dg = -matmul(kmi, db - s)
         ! to inertial components: e_x, e_r = (0, -sin phi, cos phi)
         res(1) = res(1) + g(1)
         res(2) = res(2) - g(2)*sin(phi)
         res(3) = res(3) + g(2)*cos(phi)
         jac(1, :) = jac(1, :) + dg(1, :)
         jac(2, :) = jac(2, :) - dg(2, :)*sin(phi)
         jac(3, :) = jac(3, :) + dg(2, :)*cos(phi)
         ! moment about the race centre, force applied at the groove centre:
         ! M = m_phi (0, -cos phi, -sin phi), m_phi = C_ax g_rad - C_rad g_ax
         mphi = c_i(1)*g(2) - c_i(2)*g(1)
         dm = s(1, :)*g(2) + c_i(1)*dg(2, :) - s(2, :)*g(1) - c_i(2)*dg(1, :)
         res(4) = res(4) - mphi*cos(phi)
         res(5) = res(5) - mphi*sin(phi)
         jac(4, :) = jac(4, :) - dm*cos(phi)
         jac(5, :) = jac(5, :) - dm*sin(phi)
      end do
   end subroutine race_residual

   !> Solve the quasi-static equilibrium of the ball bearing (report section 3.1).
   !>
   !> orbital_speed(n): ball orbital speeds w_m (rad/s) that set the centrifugal forces.
   !> On entry sol may hold a previous solution (warm start: allocated arrays of the right
   !> size and u are kept); otherwise the solver starts from the free contact geometry.
   subroutine solve_ball_equilibrium(b, ld, orbital_speed, sol, error)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_load_t), intent(in) :: ld
      real(wp), intent(in) :: orbital_speed(:)
      type(ball_qs_solution_t), intent(inout) :: sol
      type(error_type), allocatable, intent(out) :: error

      integer :: n, k, pass, it, nfree, half
      integer :: idx(5)
      real(wp) :: res(5), jac(5, 5), step(5), u_trial(5), res_t(5), jac_t(5, 5)
      real(wp) :: fscale, mscale, norm_r, norm_t, change
      real(wp), allocatable :: jr(:, :), rr(:), st(:)
      logical :: ok, warm, rebracketed
      character(len=160) :: msg

      n = b%n_balls
      if (n < 1 .or. size(orbital_speed) /= n) then
         call engine_error(error, "ball equilibrium: number of balls and orbital speeds disagree")
         return
      end if
      warm = .false.
      if (allocated(sol%x)) warm = size(sol%x) == n
      if (.not. warm) call start_solution(b, ld, sol)
      sol%orbital_speed = orbital_speed

      ! unknowns: translations always, misalignments when moment equilibrium is asked for
      nfree = 3
      idx(1:3) = [1, 2, 3]
      do k = 1, 2
         if (ld%solve_moment(k)) then
            nfree = nfree + 1
            idx(nfree) = 3 + k
         else
            sol%u(3 + k) = ld%misalignment(k)
         end if
      end do
      allocate (jr(nfree, nfree), rr(nfree), st(nfree))
      fscale = max(norm2(ld%force), b%ball_mass*b%dm*maxval(abs(orbital_speed))**2, 1.0_wp)
      mscale = fscale*b%dm

      sol%iterations = 0
      do pass = 1, 20
         if (.not. warm .and. pass == 1) call axial_start(b, ld, sol)
         rebracketed = .false.
         call race_residual(b, ld, sol%u, sol, res, jac)
         do it = 1, 60
            norm_r = scaled_norm(res)
            if (norm_r <= 1.0e-12_wp) exit
            jr = jac(idx(1:nfree), idx(1:nfree))
            rr = res(idx(1:nfree))
            call solve_dense(nfree, jr, -rr, st, ok)
            if (.not. ok) then
               ! No ball carries load in some direction (a light load inside the clearance):
               ! the race is free there.  A Levenberg-Marquardt step (J + mu I, mu a small
               ! fraction of the largest stiffness) moves it along the residual until balls
               ! take the load; the step halving below keeps each move an improvement.
               jr = jac(idx(1:nfree), idx(1:nfree))
               do k = 1, nfree
                  jr(k, k) = jr(k, k) - LM_DAMPING*max(maxval(abs(jr)), tiny(1.0_wp))
               end do
               call solve_dense(nfree, jr, -rr, st, ok)
            end if
            ! a step that is not finite or longer than a ball diameter: the race has left the
            ! balls (a warm start at higher orbital speeds, whose centrifugal forces lift the
            ! balls off a lightly loaded inner race; no inner contact left to give a
            ! stiffness).  Bracket the race position along the load again, as a cold start
            ! does, once per stiffness pass.
            if (ok) ok = all(ieee_is_finite(st)) .and. maxval(abs(st(1:3))) <= b%d
            if (.not. ok .and. .not. rebracketed) then
               call axial_start(b, ld, sol)
               rebracketed = .true.
               call race_residual(b, ld, sol%u, sol, res, jac)
               cycle
            end if
            if (.not. ok) then
               call engine_error(error, "ball equilibrium: the inner race Jacobian is singular "// &
                                 "(no ball carries load in some direction)")
               return
            end if
            step = 0.0_wp
            step(idx(1:nfree)) = st
            do half = 0, 30
               u_trial = sol%u + step*0.5_wp**half
               call race_residual(b, ld, u_trial, sol, res_t, jac_t)
               norm_t = scaled_norm(res_t)
               if (norm_t < norm_r .or. half == 30) exit
            end do
            sol%u = u_trial
            res = res_t
            jac = jac_t
            sol%iterations = sol%iterations + 1
         end do
         call update_contacts(b, sol, fscale, change)
         if (change <= 1.0e-13_wp) exit
      end do
      call race_residual(b, ld, sol%u, sol, res, jac)
      call update_contacts(b, sol, fscale, change)
      sol%race_residual = res
      if (.not. (scaled_norm(res) <= 1.0e-9_wp .and. change <= 1.0e-10_wp)) then   ! NaN fails too
         write (msg, '(a,es10.3,a)') "ball equilibrium did not converge (relative race residual ", &
            scaled_norm(res), ")"
         call engine_error(error, trim(msg))
         return
      end if
      call race_loads(b, sol)
      sol%axial_displacement = sol%u(1) - mounted_axial_origin(b)

   contains

      pure function scaled_norm(r) result(v)
         real(wp), intent(in) :: r(5)
         real(wp) :: v
         real(wp) :: w(5)
         w = [fscale, fscale, fscale, mscale, mscale]
         v = maxval(abs(r(idx(1:nfree)))/w(idx(1:nfree)))
      end function scaled_norm

   end subroutine solve_ball_equilibrium

   !> Initial guess: every ball touching both races at the free contact geometry.
   subroutine start_solution(b, ld, sol)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_load_t), intent(in) :: ld
      type(ball_qs_solution_t), intent(inout) :: sol

      integer :: n, k
      real(wp) :: axis(2), alpha0

      n = b%n_balls
      if (allocated(sol%x)) deallocate (sol%azimuth, sol%orbital_speed, sol%x, sol%r, sol%alpha_o, &
                                        sol%alpha_i, sol%n_o, sol%n_i, sol%q_o, sol%q_i, sol%delta_o, &
                                        sol%delta_i, sol%k_o, sol%k_i, sol%centrifugal, sol%c_o, sol%c_i)
      allocate (sol%azimuth(n), sol%orbital_speed(n), sol%x(n), sol%r(n), sol%alpha_o(n), sol%alpha_i(n), &
                sol%n_o(2, n), sol%n_i(2, n), sol%q_o(n), sol%q_i(n), sol%delta_o(n), sol%delta_i(n), &
                sol%k_o(n), sol%k_i(n), sol%centrifugal(n), sol%c_o(n), sol%c_i(n))
      sol%azimuth = [(2.0_wp*pi*real(k - 1, wp)/real(n, wp), k=1, n)]
      sol%u = 0.0_wp
      sol%u(4:5) = ld%misalignment
      ! the line through the two groove centres gives the free contact angle
      axis = [b%x_i - b%x_o, b%r_i - b%r_o]
      alpha0 = atan2(abs(axis(1)), abs(axis(2)))
      do k = 1, n
         sol%x(k) = b%x_o + (b%f_o - 0.5_wp)*b%d*sin(alpha0)*sign(1.0_wp, -axis(1))
         sol%r(k) = b%r_o - (b%f_o - 0.5_wp)*b%d*cos(alpha0)
         sol%alpha_o(k) = alpha0
         sol%alpha_i(k) = alpha0
      end do
      sol%k_o = [(contact_stiffness(b, alpha0, .true.), k=1, n)]
      sol%k_i = [(contact_stiffness(b, alpha0, .false.), k=1, n)]
      sol%q_o = 0.0_wp
      sol%q_i = 0.0_wp
   end subroutine start_solution

   !> Starting race position: move the inner race along the applied force direction until
   !> the balls carry the applied force (bisection), so that Newton starts with loaded balls.
   subroutine axial_start(b, ld, sol)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_load_t), intent(in) :: ld
      type(ball_qs_solution_t), intent(inout) :: sol

      real(wp) :: dir(3), lo, hi, mid, res(5), jac(5, 5), u0(5), total(3)
      integer :: it

      total = ld%force + b%inner_race_mass*ld%gravity
      if (norm2(total) <= 0.0_wp) return
      dir = total/norm2(total)
      u0 = sol%u
      ! bracket [lo, hi]: the load wins at lo, the balls push back harder at hi
      lo = -1.0e-4_wp*b%d
      do it = 1, 60
         if (push(lo) > 0.0_wp) exit
         lo = 2.0_wp*lo
      end do
      hi = 1.0e-3_wp*b%d
      do it = 1, 60
         if (push(hi) < 0.0_wp) exit
         hi = 2.0_wp*hi
      end do
      do it = 1, 60
         mid = 0.5_wp*(lo + hi)
         if (push(mid) < 0.0_wp) then
            hi = mid
         else
            lo = mid
         end if
      end do
      sol%u = u0
      sol%u(1:3) = u0(1:3) + hi*dir

   contains

      !> Net force along dir with the race moved by s along dir (>0: load still wins).
      function push(s) result(p)
         real(wp), intent(in) :: s
         real(wp) :: p
         real(wp) :: u(5)
         u = u0
         u(1:3) = u0(1:3) + s*dir
         call race_residual(b, ld, u, sol, res, jac)
         p = dot_product(res(1:3), dir)
      end function push

   end subroutine axial_start

   !> Contact loads, angles, deflections and stiffness at the current ball positions;
   !> change = largest change of a contact force that the stiffness update makes, relative
   !> to the load scale fscale (N): |dK/K| Q/fscale.  A contact without load has no force to
   !> change (the contact angle, hence K, of a ball floating in the unloaded zone is
   !> undetermined and must not hold up the race equilibrium); a loaded contact counts in
   !> proportion to the load it carries.
   subroutine update_contacts(b, sol, fscale, change)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_solution_t), intent(inout) :: sol
      real(wp), intent(in) :: fscale
      real(wp), intent(out) :: change

      real(wp) :: c_o(2), c_i(2), s(2, 5), a(2), e(2), k_new
      type(hertz_geometry_t) :: geo
      integer :: k

      change = 0.0_wp
      c_o = [b%x_o, b%r_o]
      do k = 1, b%n_balls
         call inner_groove_centre(b, sol%azimuth(k), sol%u, c_i, s)
         ! outer contact
         a = [sol%x(k), sol%r(k)] - c_o
         e = a/norm2(a)
         sol%n_o(:, k) = e
         sol%alpha_o(k) = atan2(abs(e(1)), abs(e(2)))
         sol%delta_o(k) = norm2(a) - (b%f_o - 0.5_wp)*b%d
         sol%q_o(k) = sol%k_o(k)*max(sol%delta_o(k), 0.0_wp)**1.5_wp
         k_new = contact_stiffness(b, sol%alpha_o(k), .true., geo)
         sol%c_o(k) = hertz_contact(geo, sol%q_o(k))
         change = max(change, abs(k_new - sol%k_o(k))/k_new*sol%q_o(k)/fscale)
         sol%k_o(k) = k_new
         ! inner contact
         a = [sol%x(k), sol%r(k)] - c_i
         e = a/norm2(a)
         sol%n_i(:, k) = e
         sol%alpha_i(k) = atan2(abs(e(1)), abs(e(2)))
         sol%delta_i(k) = norm2(a) - (b%f_i - 0.5_wp)*b%d
         sol%q_i(k) = sol%k_i(k)*max(sol%delta_i(k), 0.0_wp)**1.5_wp
         k_new = contact_stiffness(b, sol%alpha_i(k), .false., geo)
         sol%c_i(k) = hertz_contact(geo, sol%q_i(k))
         change = max(change, abs(k_new - sol%k_i(k))/k_new*sol%q_i(k)/fscale)
         sol%k_i(k) = k_new
         sol%centrifugal(k) = b%ball_mass*sol%r(k)*sol%orbital_speed(k)**2
      end do
   end subroutine update_contacts

   !> Forces and moments of the balls on both races (inertial frame, about the race centres).
   subroutine race_loads(b, sol)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_solution_t), intent(inout) :: sol

      real(wp) :: c_i(2), s(2, 5), g(2), mphi, phi, er(3)
      integer :: k

      sol%inner_force = 0.0_wp
      sol%inner_moment = 0.0_wp
      sol%outer_force = 0.0_wp
      sol%outer_moment = 0.0_wp
      do k = 1, b%n_balls
         phi = sol%azimuth(k)
         er = [0.0_wp, -sin(phi), cos(phi)]
         call inner_groove_centre(b, phi, sol%u, c_i, s)
         g = sol%q_i(k)*sol%n_i(:, k)      ! on the inner race: +Q a/|a|
         sol%inner_force = sol%inner_force + [g(1), 0.0_wp, 0.0_wp] + g(2)*er
         mphi = c_i(1)*g(2) - c_i(2)*g(1)
         sol%inner_moment = sol%inner_moment + mphi*[0.0_wp, -cos(phi), -sin(phi)]
         g = sol%q_o(k)*sol%n_o(:, k)      ! on the outer race
         sol%outer_force = sol%outer_force + [g(1), 0.0_wp, 0.0_wp] + g(2)*er
         mphi = b%x_o*g(2) - b%r_o*g(1)
         sol%outer_moment = sol%outer_moment + mphi*[0.0_wp, -cos(phi), -sin(phi)]
      end do
   end subroutine race_loads

end module adore_quasistatic_ball_equilibrium
