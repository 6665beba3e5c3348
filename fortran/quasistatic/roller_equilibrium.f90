!> Quasi-static equilibrium of a cylindrical roller bearing at high speed (ADORE
!> ADRA4/ADRG0 for line contacts; report section 3.1 with the slice contacts of
!> Appendix B, adore_contact_line_slices).
!>
!> Roller k sits at azimuth phi_k = 2 pi (k-1)/n, measured from the inertial z axis towards
!> -y (as eq 54 for balls); its radial unit vector is e_r = (0, -sin phi, cos phi).  Its
!> unknowns are the radial position r of its centre and its tilt gamma (the roller axis
!> rises by gamma x at axial station x); its skew zeta (about e_r) is prescribed.  The
!> radius of the roller axis at station x is
!>     rho(x) = sqrt((r + gamma x)**2 + (zeta x)**2) ~ r + gamma x + zeta**2 x**2/(2 r)
!> (sections taken normal to the bearing radius: error O(D/2 angle**2)), so the slice
!> interactions with the outer race (radius R_o, fixed) and the inner race (radius R_i,
!> displaced radially by u_r(phi) = -Y sin phi + Z cos phi and tilted by
!> t_r(phi) = -(theta_2 cos phi + theta_3 sin phi)) are
!>     delta_o(x) = rho(x) + D/2 - R_o - p(x) - x**2/(2 R_co)
!>     delta_i(x) = R_i + u_r + t_r x - rho(x) + D/2 - p(x) - x**2/(2 R_ci).
!> Roller equilibrium (eqs 65-66 for a line contact): radial force Q_i - Q_o + m r w_m**2
!> = 0 and tilting moment M_i - M_o = 0 (M = integral q x dx).  Gyroscopic moments vanish
!> (spin and orbit axes parallel), tractions and flange loads are not part of the
!> equations (the report's deck has no flange contact at step 0).
!> Inner race equilibrium (eqs 68-70, radial part): the slice loads of all rollers plus
!> the applied load and the race weight balance in y and z; axial position and
!> misalignment are prescribed (report 4.4.1: rollers run with prescribed misalignment;
!> a cylindrical bearing without flanges carries no axial load).  The roller moments on
!> the race are returned as reactions.
!> Solution as the ball case: two Newton-Raphson levels with analytic Jacobians (slice
!> stiffness integrals k_n = integral dq/ddelta x**n dx), roller 2 x 2 inside, race 2 x 2
!> outside with dR/du from the implicit function theorem.  The Jacobians are those of the
!> contact integrals (boundary terms vanish: q = 0 at the contact ends); on the 12-point
!> grid, whose nodes move with the ends, the tilt cross terms of the discrete sums differ
!> from them, which slows Newton near a tilted solution but not its result (the
!> residuals are exact).  Units SI.
module adore_quasistatic_roller_equilibrium
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error, input_error
   use adore_core_linalg, only: solve_dense
   use adore_contact_line_slices, only: roller_profile_t, line_contact_t, line_contact
   implicit none
   private

   public :: roller_qs_bearing_t, roller_qs_load_t, roller_qs_solution_t
   public :: solve_roller_equilibrium, roller_contacts, solve_roller, clear_reactions, add_slice_reactions

   !> Bearing data needed by the quasi-static solution (m, kg, Pa).
   type :: roller_qs_bearing_t
      integer :: n_rollers = 0
      real(wp) :: d = 0.0_wp                 !< roller diameter D
      real(wp) :: mass = 0.0_wp              !< roller mass
      type(roller_profile_t) :: profile
      real(wp) :: race_crown(2) = 1.0e10_wp  !< outer, inner race crown radii
      real(wp) :: r_o = 0.0_wp, r_i = 0.0_wp !< outer / inner raceway radii in the contact geometry
      real(wp) :: lim_o(2) = 0.0_wp, lim_i(2) = 0.0_wp   !< permissible contact ends (m)
      real(wp) :: k_o = 0.0_wp, k_i = 0.0_wp !< slice stiffness K_L (N/m**(19/9))
      real(wp) :: e_o = 0.0_wp, e_i = 0.0_wp !< contact moduli E* (Pa)
      integer :: n_sub = 3                   !< slice zones (4 Gauss points each)
      real(wp) :: inner_race_mass = 0.0_wp
   end type roller_qs_bearing_t

   !> Loads and prescribed motions of the inner race and rollers.
   type :: roller_qs_load_t
      real(wp) :: force(3) = 0.0_wp          !< applied force on the inner race, x, y, z (N)
      real(wp) :: gravity(3) = 0.0_wp        !< (m/s**2)
      real(wp) :: misalignment(2) = 0.0_wp   !< inner race theta_2, theta_3 (rad)
      real(wp) :: skew = 0.0_wp              !< roller skew zeta (rad), all rollers
   end type roller_qs_load_t

   !> The equilibrium (per-roller arrays, roller k at azimuth 2 pi (k-1)/n).
   type :: roller_qs_solution_t
      real(wp), allocatable :: azimuth(:), orbital_speed(:)   !< (rad, rad/s)
      real(wp), allocatable :: r(:), tilt(:)                  !< roller centre radius (m), tilt (rad)
      real(wp), allocatable :: centrifugal(:)                 !< m r w_m**2 (N)
      type(line_contact_t), allocatable :: c_o(:), c_i(:)     !< slice contacts
      real(wp) :: u(2) = 0.0_wp              !< inner race Y, Z (m)
      real(wp) :: inner_force(3) = 0.0_wp    !< force of the rollers on the inner race (N)
      real(wp) :: inner_moment(3) = 0.0_wp   !< their moment about the race centre (N m)
      real(wp) :: outer_force(3) = 0.0_wp    !< force of the rollers on the outer race (N)
      real(wp) :: outer_moment(3) = 0.0_wp
      !> roller end / flange contacts (flanged bearings, adore_quasistatic_roller_flange_equilibrium;
      !> unallocated without flanges): each roller's axial position (m), the inner race's axial
      !> position (m), per flange of the set and roller its Hertz load (N), axial force on the
      !> roller (N) and contact height above (inner) / below (outer) the raceway (m)
      real(wp), allocatable :: x(:)
      real(wp) :: u_axial = 0.0_wp
      real(wp), allocatable :: flange_load(:, :), flange_axial(:, :), flange_height(:, :)
      real(wp) :: race_residual(2) = 0.0_wp  !< inner race y, z force balance (N)
      real(wp) :: max_roller_residual = 0.0_wp   !< largest roller force imbalance (N)
      integer :: iterations = 0
   end type roller_qs_solution_t


contains

   !> Slice contacts of one roller: state (r, gamma), inner race offset u_r (m) and tilt
   !> t_r (rad) at its azimuth, skew zeta (rad).
   pure subroutine roller_contacts(b, r, gamma, u_r, t_r, zeta, c_o, c_i)
      type(roller_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: r, gamma, u_r, t_r, zeta
      type(line_contact_t), intent(out) :: c_o, c_i
      real(wp) :: h2, req_o, req_i

      h2 = zeta**2/max(r, tiny(1.0_wp))
      req_o = 1.0_wp/(2.0_wp/b%d - 1.0_wp/b%r_o)
      req_i = 1.0_wp/(2.0_wp/b%d + 1.0_wp/b%r_i)
      call line_contact(b%profile, b%race_crown(1), [r + 0.5_wp*b%d - b%r_o, gamma, h2], b%lim_o, &
                        b%k_o, req_o, b%e_o, b%n_sub, c_o)
      call line_contact(b%profile, b%race_crown(2), [b%r_i + u_r - r + 0.5_wp*b%d, t_r - gamma, -h2], &
                        b%lim_i, b%k_i, req_i, b%e_i, b%n_sub, c_i)
   end subroutine roller_contacts

   !> Equilibrium of one roller (radial force and tilting moment) for the race state
   !> (u_r, t_r) at its azimuth and orbital speed w (rad/s).  r, gamma: start in, solution
   !> out.  dr(2, 2): d(r, gamma)/d(u_r, t_r); dq(2): dQ_i/d(u_r, t_r) including the roller
   !> response; dm(2): the same for M_i.  ok = .false. when Newton fails.
   pure subroutine solve_roller(b, u_r, t_r, zeta, w, r, gamma, c_o, c_i, fc, dq, dm, ok)
      type(roller_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: u_r, t_r, zeta, w
      real(wp), intent(inout) :: r, gamma
      type(line_contact_t), intent(out) :: c_o, c_i
      real(wp), intent(out) :: fc, dq(2), dm(2)
      logical, intent(out) :: ok

      real(wp) :: g(2), jac(2, 2), step(2), gnew(2), scale, lsc, r_try, g_try, mw2, t, dr(2, 2), rhs(2, 2)
      type(line_contact_t) :: to, ti
      integer :: it, ls
      logical :: solved

      ok = .false.
      mw2 = b%mass*w**2
      lsc = 0.5_wp*b%profile%length
      call roller_contacts(b, r, gamma, u_r, t_r, zeta, c_o, c_i)
      if (.not. (c_o%in_contact .or. c_i%in_contact)) then
         ! free roller: put it on the outer race (centrifugal side), zero loads
         r = r - c_o%max_deflection
         call roller_contacts(b, r, gamma, u_r, t_r, zeta, c_o, c_i)
      end if
      do it = 1, 100
         fc = mw2*r
         g = [c_i%load - c_o%load + fc, (c_i%moment - c_o%moment)/lsc]
         scale = max(fc + c_o%load + c_i%load, 1.0e-9_wp)   ! N
         jac(1, :) = [-c_i%k0 - c_o%k0 + mw2, -c_i%k1 - c_o%k1]
         jac(2, :) = [-c_i%k1 - c_o%k1, -c_i%k2 - c_o%k2]/lsc
         if (maxval(abs(g)) <= 1.0e-12_wp*scale) then
            ok = .true.
            exit
         end if
         if (.not. (c_o%in_contact .or. c_i%in_contact)) then
            if (fc <= 0.0_wp) then      ! no speed, no contact: the roller floats at the outer race
               ok = .true.
               exit
            end if
            r = r - c_o%max_deflection + 1.0e-9_wp*b%d
            call roller_contacts(b, r, gamma, u_r, t_r, zeta, c_o, c_i)
            cycle
         end if
         if (c_o%k2 + c_i%k2 <= 0.0_wp) jac(2, :) = [0.0_wp, 1.0_wp]   ! single point: tilt free
         call solve_dense(2, jac, -g, step, solved)
         if (.not. solved) return
         if (abs(step(1)) <= 4.0_wp*spacing(r) .and. abs(step(2))*lsc <= 4.0_wp*spacing(r)) then
            ok = .true.      ! round-off floor of r reached
            exit
         end if
         ! backtracking on the residual
         t = 1.0_wp
         do ls = 1, 30
            r_try = r + t*step(1)
            call roller_contacts(b, r_try, gamma + t*step(2), u_r, t_r, zeta, to, ti)
            gnew = [ti%load - to%load + mw2*r_try, (ti%moment - to%moment)/lsc]
            g_try = maxval(abs(gnew))
            if (g_try < maxval(abs(g)) .or. t < 1.0e-6_wp) exit
            t = 0.5_wp*t
         end do
         r = r_try
         gamma = gamma + t*step(2)
         c_o = to
         c_i = ti
      end do
      if (.not. ok) return
      fc = mw2*r
      ! response to the race: jac * d(r, gamma) = -dG/d(u_r, t_r)
      rhs(:, 1) = -[c_i%k0, c_i%k1/lsc]
      rhs(:, 2) = -[c_i%k1, c_i%k2/lsc]
      dr = 0.0_wp
      if (c_i%in_contact) then
         call solve_dense(2, jac, rhs(:, 1), dr(:, 1), solved)
         if (solved) call solve_dense(2, jac, rhs(:, 2), dr(:, 2), solved)
         if (.not. solved) dr = 0.0_wp
      end if
      ! Q_i(u_r, t_r, r, gamma): dQ_i = k0 du_r + k1 dt_r - k0 dr - k1 dgamma
      dq(1) = c_i%k0 - c_i%k0*dr(1, 1) - c_i%k1*dr(2, 1)
      dq(2) = c_i%k1 - c_i%k0*dr(1, 2) - c_i%k1*dr(2, 2)
      dm(1) = c_i%k1 - c_i%k1*dr(1, 1) - c_i%k2*dr(2, 1)
      dm(2) = c_i%k2 - c_i%k1*dr(1, 2) - c_i%k2*dr(2, 2)
   end subroutine solve_roller

   !> Equilibrium of the bearing for orbital speeds w(n) (rad/s): every roller in radial
   !> and tilting equilibrium, the inner race in y/z force equilibrium (section 3.1).
   subroutine solve_roller_equilibrium(b, ld, w, s, error)
      type(roller_qs_bearing_t), intent(in) :: b
      type(roller_qs_load_t), intent(in) :: ld
      real(wp), intent(in) :: w(:)
      type(roller_qs_solution_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error

      real(wp) :: res(2), jac(2, 2), step(2), rnew(2), u_try(2), load_scale, t, gap_step
      real(wp), allocatable :: r0(:), g0(:)
      integer :: it, ls, n
      logical :: ok, solved

      n = b%n_rollers
      if (n < 1 .or. size(w) /= n .or. b%d <= 0.0_wp .or. b%r_o <= b%r_i) then
         call input_error(error, "roller equilibrium: need rollers, one orbital speed each and R_o > R_i")
         return
      end if
      allocate (s%azimuth(n), s%orbital_speed(n), s%r(n), s%tilt(n), s%centrifugal(n), s%c_o(n), s%c_i(n))
      allocate (r0(n), g0(n))
      s%azimuth = [(2.0_wp*pi*real(it - 1, wp)/real(n, wp), it=1, n)]
      s%orbital_speed = w
      s%r = b%r_o - 0.5_wp*b%d + 1.0e-4_wp*b%d
      s%tilt = 0.0_wp
      s%u = 0.0_wp
      load_scale = max(norm2(ld%force(2:3) + b%inner_race_mass*ld%gravity(2:3)), &
                       maxval(b%mass*w**2*b%r_o), 1.0e-3_wp)
      gap_step = 1.0e-4_wp*b%d

      call evaluate(s%u, res, jac, ok)
      if (.not. ok) return
      do it = 1, 200
         s%iterations = it
         if (maxval(abs(res)) <= 1.0e-13_wp*load_scale) exit
         call race_step(jac, res, gap_step, step, solved)
         if (solved .and. maxval(abs(step)) <= 4.0_wp*spacing(b%r_o)) exit   ! round-off floor
         t = 1.0_wp
         r0 = s%r
         g0 = s%tilt
         do ls = 1, 40
            u_try = s%u + t*step
            s%r = r0
            s%tilt = g0
            call evaluate(u_try, rnew, jac, ok)
            if (.not. ok) return
            if (maxval(abs(rnew)) < maxval(abs(res)) .or. .not. solved .or. t < 1.0e-8_wp) exit
            t = 0.5_wp*t
         end do
         s%u = u_try
         res = rnew
      end do
      s%race_residual = res
      if (maxval(abs(res)) > 1.0e-10_wp*load_scale) then
         call engine_error(error, "roller equilibrium: inner race Newton iterations did not converge")
         return
      end if

   contains

      !> Newton step of the race for residual res (N) and Jacobian jac (N/m, symmetric,
      !> negative semi-definite), both y, z.  solved = .false. when no roller touches the
      !> inner race (jac = 0): then a step of gap (m) along the unbalanced load.  When the
      !> rollers in contact all lie on one diameter (e.g. one roller under a light load
      !> along it) jac is singular: no stiffness across that diameter.  The step is then
      !> split along jac's eigenvectors: the stiff direction gets its Newton step, the free
      !> one a step of gap along its unbalanced load, none when that is converged (so the
      !> iteration cannot cycle through the clearance on round-off).
      subroutine race_step(jac, res, gap, step, solved)
         real(wp), intent(in) :: jac(2, 2), res(2), gap
         real(wp), intent(out) :: step(2)
         logical, intent(out) :: solved
         real(wp) :: stiff, lam(2), v(2, 2), half, mean, root, r_k
         integer :: k

         call solve_dense(2, jac, -res, step, solved)
         if (solved) return
         stiff = maxval(abs(jac))
         if (.not. stiff > 0.0_wp) then
            ! no inner race contact yet: move the race along the unbalanced load
            step = res/max(norm2(res), tiny(1.0_wp))*gap
            return
         end if
         ! eigenpairs of the symmetric 2 x 2 jac
         mean = 0.5_wp*(jac(1, 1) + jac(2, 2))
         half = 0.5_wp*(jac(1, 1) - jac(2, 2))
         root = hypot(half, 0.5_wp*(jac(1, 2) + jac(2, 1)))
         lam = [mean + root, mean - root]
         if (root > 0.0_wp) then
            v(:, 1) = [half + root, 0.5_wp*(jac(1, 2) + jac(2, 1))]
            if (norm2(v(:, 1)) <= 1.0e-12_wp*root) v(:, 1) = [0.5_wp*(jac(1, 2) + jac(2, 1)), root - half]
            v(:, 1) = v(:, 1)/norm2(v(:, 1))
         else
            v(:, 1) = [1.0_wp, 0.0_wp]
         end if
         v(:, 2) = [-v(2, 1), v(1, 1)]
         step = 0.0_wp
         do k = 1, 2
            r_k = dot_product(v(:, k), res)
            if (abs(lam(k)) > 1.0e-9_wp*stiff) then
               step = step - r_k/lam(k)*v(:, k)
            else if (abs(r_k) > 1.0e-13_wp*load_scale) then
               step = step + sign(gap, r_k)*v(:, k)
            end if
         end do
         solved = .true.
      end subroutine race_step

      !> Solve all rollers for race position u; race residual res and Jacobian jac.
      subroutine evaluate(u, res, jac, ok)
         real(wp), intent(in) :: u(2)
         real(wp), intent(out) :: res(2), jac(2, 2)
         logical, intent(out) :: ok
         real(wp) :: sp, cp, u_r, t_r, fc, dq(2), dm(2)
         integer :: k

         res = 0.0_wp
         jac = 0.0_wp
         call clear_reactions(s)
         do k = 1, n
            sp = sin(s%azimuth(k))
            cp = cos(s%azimuth(k))
            u_r = -u(1)*sp + u(2)*cp
            t_r = -(ld%misalignment(1)*cp + ld%misalignment(2)*sp)
            call solve_roller(b, u_r, t_r, ld%skew, w(k), s%r(k), s%tilt(k), s%c_o(k), s%c_i(k), &
                              fc, dq, dm, ok)
            if (.not. ok) then
               call engine_error(error, "roller equilibrium: a roller has no equilibrium (Newton failed)")
               return
            end if
            s%centrifugal(k) = fc
            s%max_roller_residual = max(s%max_roller_residual, abs(s%c_i(k)%load - s%c_o(k)%load + fc))
            ! rollers push the inner race along -e_r, the outer race along +e_r
            call add_slice_reactions(s, k, sp, cp)
            ! d(u_r)/d(Y, Z) = (-sp, cp)
            jac(1, :) = jac(1, :) + sp*dq(1)*[-sp, cp]
            jac(2, :) = jac(2, :) - cp*dq(1)*[-sp, cp]
         end do
         res = s%inner_force(2:3) + ld%force(2:3) + b%inner_race_mass*ld%gravity(2:3)
      end subroutine evaluate

   end subroutine solve_roller_equilibrium

   !> Zero the race reactions and the roller residual of s before a sweep over the rollers.
   pure subroutine clear_reactions(s)
      type(roller_qs_solution_t), intent(inout) :: s
      s%inner_force = 0.0_wp
      s%inner_moment = 0.0_wp
      s%outer_force = 0.0_wp
      s%outer_moment = 0.0_wp
      s%max_roller_residual = 0.0_wp
   end subroutine clear_reactions

   !> Add roller k's slice reactions to the races' forces (N) and moments (N m) of s: the
   !> rollers push the inner race along -e_r, the outer race along +e_r (sp, cp: sin, cos of
   !> its azimuth).
   pure subroutine add_slice_reactions(s, k, sp, cp)
      type(roller_qs_solution_t), intent(inout) :: s
      integer, intent(in) :: k
      real(wp), intent(in) :: sp, cp
      s%inner_force(2:3) = s%inner_force(2:3) + s%c_i(k)%load*[sp, -cp]
      s%inner_moment(2:3) = s%inner_moment(2:3) + s%c_i(k)%moment*[cp, sp]
      s%outer_force(2:3) = s%outer_force(2:3) + s%c_o(k)%load*[-sp, cp]
      s%outer_moment(2:3) = s%outer_moment(2:3) - s%c_o(k)%moment*[cp, sp]
   end subroutine add_slice_reactions

end module adore_quasistatic_roller_equilibrium
