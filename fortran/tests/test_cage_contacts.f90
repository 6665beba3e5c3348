!> Unit tests of the cage contacts at any state (adore_contact_cage_pocket,
!> adore_contact_cage_land) and their place in the ball bearing's force assembly:
!> * metallic parts: the forces and moments on ball, cage and race equal minus the gradient
!>   of the contact energy (central finite differences), at a tilted, turned cage;
!> * action = reaction in force and moment with every part active (hydrodynamic, metallic,
!>   friction; whirl and squeeze velocities);
!> * a ball pushed into its pocket wall is pushed back; deep interference is abnormal (4.4.12)
!>   and the ball system's derivative refuses the step;
!> * the short-bearing film force against Ocvirk's closed form (Hamrock 1991) for pure
!>   rotation, and zero at the half-frequency whirl; equal to round-off to its nodes with
!>   sin and cos called at each (the angle-addition cut of issue #30);
!> * the starved land (lubricant layer h_oil): no force, torque or loss at gaps >= h_oil,
!>   force and torque continuous at the threshold, the flooded limit = Ocvirk and Petroff,
!>   the wetted-arc force and Couette factor against brute-force quadratures, the film's
!>   loss = its closed form and = minus the power of its loads on both bodies;
!> * a centred cage, balls on their pocket axes moving with the cage: zero cage force, the
!>   cage moment the lands' Couette (Petroff) torque (flooded lands), none with the
!>   default oil layer;
!> * at the step-0 state of Appendix C (race control) the pocket and land interactions equal
!>   adore_cage_step0's Geo Int values.
!> Run by `meson test` with the decks/ directory as argument.
program test_cage_contacts
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_core_rotation, only: cross, quat_from_rotation_vector, quat_multiply, quat_matrix
   use adore_model_bearing, only: BODY_CAGE, bearing_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, body_state_t, state_size, pack_state, RACE_INNER
   use adore_contact_cage_pocket, only: cage_pocket_pair_t, cage_pocket_geometry_t, cage_pocket_pair, &
                                        cage_pocket_contact, pocket_energy
   use adore_contact_cage_land, only: cage_land_pair_t, cage_land_geometry_t, cage_land_contact, land_energy, &
                                      short_bearing_force, wetted_half_angle, couette_integral
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, ball_bearing_loads, ball_pocket_pair, guide_land_pairs
   use adore_dynamics_ball_system, only: ball_system_t, new_ball_system, initial_ball_state
   use adore_dynamics_integrator, only: DERIV_OK, DERIV_REJECT_STEP
   use adore_start_ball_step0, only: ball_step0_t
   use adore_test_ball_fixture, only: appendix_c_race_control
   use adore_core_quadrature, only: gauss_legendre
   use adore_test_support, only: check, finish
   implicit none

   type(bearing_t) :: b
   type(mounted_geometry_t) :: g
   type(error_type), allocatable :: error
   type(ball_step0_t) :: s0

   call test_pocket_energy_gradient()
   call test_land_energy_gradient()
   call test_action_reaction()
   call test_pushed_back_and_abnormal()
   call test_pocket_against_hertz()
   call test_short_bearing_closed_form()
   call test_short_bearing_direct_form()
   call test_starved_land()

   call appendix_c_race_control("cage contacts", b, g, s0)
   call test_step0_geometry()
   call test_friction_from_deck()
   call test_centred_cage()
   call test_reject_step()
   call finish("cage contacts")

contains

   !> A steel ball of 12 mm in a pocket of clearance 0.5 mm at radius 40 mm (dry, no friction
   !> unless asked), eta: viscosity (Pa s), mu: friction.
   function test_pocket(eta, mu) result(p)
      real(wp), intent(in) :: eta, mu
      type(cage_pocket_pair_t) :: p
      p = cage_pocket_pair(0.012_wp, 5.0e-4_wp, 0.04_wp, 2.0e11_wp, 0.3_wp, 1.1e11_wp, 0.34_wp, eta, mu)
   end function test_pocket

   !> Cage turned and tilted, ball of pocket psi = 0.7 rad at the pocket centre plus offset
   !> (pocket frame: axial, tangential, radial), both moving.
   subroutine pocket_state(offset, ball, cage)
      real(wp), intent(in) :: offset(3)
      type(body_state_t), intent(out) :: ball, cage
      real(wp) :: rot(3, 3), psi
      psi = 0.7_wp
      cage%position = [1.0e-4_wp, -2.0e-4_wp, 3.0e-4_wp]
      cage%attitude = quat_from_rotation_vector([0.4_wp, 2.0e-3_wp, -1.0e-3_wp])
      cage%velocity = [0.01_wp, 0.5_wp, -0.3_wp]
      cage%omega = [900.0_wp, 0.5_wp, -0.2_wp]
      rot = quat_matrix(cage%attitude)
      ball%position = cage%position + matmul(rot, offset(1)*[1.0_wp, 0.0_wp, 0.0_wp] + &
                                             offset(2)*[0.0_wp, cos(psi), sin(psi)] + &
                                             (0.04_wp + offset(3))*[0.0_wp, -sin(psi), cos(psi)])
      ball%velocity = [0.02_wp, -1.5_wp, 2.0_wp]
      ball%attitude = quat_from_rotation_vector([0.1_wp, 0.2_wp, 0.3_wp])
      ball%omega = [3000.0_wp, -400.0_wp, 700.0_wp]
   end subroutine pocket_state

   !> Metallic pocket contact: force on ball and cage and moment on the cage = -grad E.
   subroutine test_pocket_energy_gradient()
      type(cage_pocket_pair_t) :: p
      type(body_state_t) :: ball, cage, bp, bm, cp, cm
      type(cage_pocket_geometry_t) :: c, c1, c2
      real(wp) :: h, hr, grad(3), gradc(3), gradm(3), e(3), fs
      integer :: i

      p = test_pocket(0.0_wp, 0.0_wp)
      call pocket_state([1.0e-4_wp, 2.5e-4_wp + 6.0e-6_wp, 1.0e-3_wp], ball, cage)
      call cage_pocket_contact(p, 0.7_wp, ball, cage, c)
      call check(c%metallic_load > 0.0_wp .and. c%gap < 0.0_wp, "pocket: the displaced ball interferes")
      h = 1.0e-10_wp
      hr = 1.0e-9_wp
      do i = 1, 3
         e = 0.0_wp
         e(i) = h
         bp = ball; bm = ball
         bp%position = ball%position + e
         bm%position = ball%position - e
         call cage_pocket_contact(p, 0.7_wp, bp, cage, c1)
         call cage_pocket_contact(p, 0.7_wp, bm, cage, c2)
         grad(i) = (pocket_energy(p, c1) - pocket_energy(p, c2))/(2.0_wp*h)
         cp = cage; cm = cage
         cp%position = cage%position + e
         cm%position = cage%position - e
         call cage_pocket_contact(p, 0.7_wp, ball, cp, c1)
         call cage_pocket_contact(p, 0.7_wp, ball, cm, c2)
         gradc(i) = (pocket_energy(p, c1) - pocket_energy(p, c2))/(2.0_wp*h)
         e = 0.0_wp
         e(i) = hr
         cp = cage; cm = cage
         cp%attitude = quat_multiply(quat_from_rotation_vector(e), cage%attitude)
         cm%attitude = quat_multiply(quat_from_rotation_vector(-e), cage%attitude)
         call cage_pocket_contact(p, 0.7_wp, ball, cp, c1)
         call cage_pocket_contact(p, 0.7_wp, ball, cm, c2)
         gradm(i) = (pocket_energy(p, c1) - pocket_energy(p, c2))/(2.0_wp*hr)
      end do
      fs = c%metallic_load
      write (*, "(a,3es10.2,a,es10.3,a)") "pocket -grad E: ball, cage force, cage moment ", &
         norm2(c%force_ball + grad)/fs, norm2(c%force_cage + gradc)/fs, norm2(c%moment_cage + gradm)/(fs*0.04_wp), &
         " (Q = ", fs, " N)"
      call check(norm2(c%force_ball + grad) < 1.0e-6_wp*fs, "pocket: force on the ball = -dE/dB")
      call check(norm2(c%force_cage + gradc) < 1.0e-6_wp*fs, "pocket: force on the cage = -dE/dC")
      call check(norm2(c%moment_cage + gradm) < 1.0e-6_wp*fs*0.04_wp, "pocket: moment on the cage = -dE/dtheta")
   end subroutine test_pocket_energy_gradient

   !> A land of an inner-race guided cage: R 50 mm, L 8 mm, radial clearance 0.3 mm.
   function test_land(eta, mu, journal_race) result(p)
      real(wp), intent(in) :: eta, mu
      logical, intent(in) :: journal_race
      type(cage_land_pair_t) :: p
      p%race_is_journal = journal_race
      p%radius = 0.05_wp
      p%width = 8.0e-3_wp
      p%clearance = 3.0e-4_wp
      p%e_star = 1.2e11_wp
      p%viscosity = eta
      p%friction = mu
   end function test_land

   !> Metallic land contact: forces on cage and race = -grad E (both guide types).
   subroutine test_land_energy_gradient()
      type(cage_land_pair_t) :: p
      type(body_state_t) :: cage, race, sp, sm
      type(cage_land_geometry_t) :: c, c1, c2
      real(wp) :: h, grad(3), gradr(3), e(3)
      integer :: i, kind

      do kind = 1, 2
         p = test_land(0.0_wp, 0.0_wp, kind == 1)
         race%position = [1.0e-5_wp, 2.0e-5_wp, -1.0e-5_wp]
         race%attitude = quat_from_rotation_vector([0.3_wp, 1.0e-4_wp, 0.0_wp])
         cage%position = race%position + [2.0e-4_wp, 2.1e-4_wp, -2.2e-4_wp]
         call cage_land_contact(p, cage, race, c)
         call check(c%metallic_load > 0.0_wp, "land: the displaced cage touches")
         h = 1.0e-10_wp
         do i = 1, 3
            e = 0.0_wp
            e(i) = h
            sp = cage; sm = cage
            sp%position = cage%position + e
            sm%position = cage%position - e
            call cage_land_contact(p, sp, race, c1)
            call cage_land_contact(p, sm, race, c2)
            grad(i) = (land_energy(c1) - land_energy(c2))/(2.0_wp*h)
            sp = race; sm = race
            sp%position = race%position + e
            sm%position = race%position - e
            call cage_land_contact(p, cage, sp, c1)
            call cage_land_contact(p, cage, sm, c2)
            gradr(i) = (land_energy(c1) - land_energy(c2))/(2.0_wp*h)
         end do
         write (*, "(a,i0,a,2es10.2,a,es10.3,a)") "land (guide ", kind, ") -grad E: cage, race force ", &
            norm2(c%force_cage + grad)/c%metallic_load, norm2(c%force_race + gradr)/c%metallic_load, &
            " (Q = ", c%metallic_load, " N)"
         call check(norm2(c%force_cage + grad) < 1.0e-6_wp*c%metallic_load, "land: force on the cage = -dE/dC")
         call check(norm2(c%force_race + gradr) < 1.0e-6_wp*c%metallic_load, "land: force on the race = -dE/dc")
      end do
   end subroutine test_land_energy_gradient

   !> Every part active: the pair's forces cancel and their moments about the origin cancel.
   subroutine test_action_reaction()
      type(cage_pocket_pair_t) :: p
      type(cage_land_pair_t) :: pl
      type(body_state_t) :: ball, cage, race
      type(cage_pocket_geometry_t) :: c
      type(cage_land_geometry_t) :: cl
      real(wp) :: f(3), m(3), scale
      integer :: kind, case

      p = test_pocket(5.0e-3_wp, 0.05_wp)
      do case = 1, 2
         if (case == 1) call pocket_state([1.0e-4_wp, 2.5e-4_wp + 6.0e-6_wp, 1.0e-3_wp], ball, cage)
         if (case == 2) call pocket_state([-0.5e-4_wp, -1.0e-4_wp, 0.0_wp], ball, cage)
         call cage_pocket_contact(p, 0.7_wp, ball, cage, c)
         f = c%force_ball + c%force_cage
         m = c%moment_ball + cross(ball%position, c%force_ball) + c%moment_cage + cross(cage%position, c%force_cage)
         scale = norm2(c%force_ball)
         write (*, "(a,i0,a,3es10.2)") "pocket case ", case, ": |F| (N), force and moment sums ", scale, &
            norm2(f)/scale, norm2(m)/(scale*0.04_wp)
         if (case == 1) call check(scale > 0.0_wp .and. norm2(c%friction_force) > 0.0_wp, &
                                   "pocket: metallic contact: force and friction")
         ! inside the clearance the film carries the ball without Coulomb friction
         if (case == 2) call check(scale > 0.0_wp .and. norm2(c%friction_force) == 0.0_wp, &
                                   "pocket: film only: force, no friction")
         call check(norm2(f) <= 1.0e-13_wp*scale, "pocket: forces on ball and cage cancel")
         call check(norm2(m) <= 1.0e-13_wp*scale*0.04_wp, "pocket: moments on ball and cage cancel")
      end do
      call check(c%metallic_load == 0.0_wp .and. c%hydro_load > 0.0_wp, "pocket: clearance, hydrodynamic force only")

      do kind = 1, 2
         do case = 1, 2
            pl = test_land(5.0e-3_wp, 0.05_wp, kind == 1)
            race%position = [1.0e-5_wp, 2.0e-5_wp, -1.0e-5_wp]
            race%attitude = quat_from_rotation_vector([0.3_wp, 1.0e-4_wp, 0.0_wp])
            race%omega = [1000.0_wp, 0.0_wp, 0.0_wp]
            race%velocity = [0.0_wp, 0.01_wp, 0.0_wp]
            cage%attitude = quat_from_rotation_vector([1.1_wp, -2.0e-4_wp, 1.0e-4_wp])
            cage%omega = [400.0_wp, 0.3_wp, 0.1_wp]
            cage%velocity = [1.0e-3_wp, 0.2_wp, -0.4_wp]
            cage%position = race%position + merge([2.0e-4_wp, 1.0e-4_wp, -1.5e-4_wp], &
                                                  [2.0e-4_wp, 2.1e-4_wp, -2.2e-4_wp], case == 1)
            call cage_land_contact(pl, cage, race, cl)
            f = cl%force_cage + cl%force_race
            m = cl%moment_cage + cross(cage%position, cl%force_cage) + cl%moment_race + &
                cross(race%position, cl%force_race)
            scale = norm2(cl%force_cage)
            write (*, "(a,i0,a,i0,a,3es10.2)") "land guide ", kind, " case ", case, &
               ": |F| (N), force and moment sums ", scale, norm2(f)/scale, norm2(m)/(scale*0.05_wp)
            call check(scale > 0.0_wp, "land: a force")
            call check(norm2(f) <= 1.0e-13_wp*scale, "land: forces on cage and race cancel")
            call check(norm2(m) <= 1.0e-12_wp*scale*0.05_wp, "land: moments on cage and race cancel")
            if (case == 2) call check(cl%metallic_load > 0.0_wp .and. norm2(cl%friction_force) > 0.0_wp, &
                                      "land: metallic contact with friction")
            if (case == 1) call check(cl%metallic_load == 0.0_wp .and. norm2(cl%hydro_force) > 0.0_wp, &
                                      "land: film only with clearance")
         end do
      end do
   end subroutine test_action_reaction

   !> A dry, frictionless ball pushed delta into its pocket wall: the metallic load equals
   !> Hertz's for a sphere of diameter D in a concave cylinder of diameter D + c (curvatures
   !> 2/D, 2/D; 0, -2/(D + c): Harris & Kotzalas ch. 6), computed here independently of
   !> adore_contact_hertz: the complete elliptic integrals by the trapezoidal rule (even and
   !> periodic integrand: exponential convergence), the ellipticity by bisection of
   !> F(rho) = ((k**2 + 1) E - 2 K)/((k**2 - 1) E), then
   !> Q = (2 sum rho/(3 C)) (2 delta/(delta* sum rho))**1.5, C = sum (1 - nu**2)/E.
   subroutine test_pocket_against_hertz()
      type(cage_pocket_pair_t) :: p
      type(body_state_t) :: ball, cage
      type(cage_pocket_geometry_t) :: c
      real(wp), parameter :: d = 0.012_wp, cl = 5.0e-4_wp
      real(wp) :: srho, frho, lo, hi, kap, ek, kk, dstar, comp, q, delta, worst
      real(wp), parameter :: deltas(3) = [1.0e-6_wp, 6.0e-6_wp, 2.0e-5_wp]
      integer :: i, it
      p = test_pocket(0.0_wp, 0.0_wp)
      srho = 4.0_wp/d - 2.0_wp/(d + cl)
      frho = (2.0_wp/(d + cl))/srho
      lo = 1.0_wp + 1.0e-9_wp
      hi = 100.0_wp
      do it = 1, 200
         kap = 0.5_wp*(lo + hi)
         call elliptic_trapezoid(1.0_wp - 1.0_wp/kap**2, kk, ek)
         if (((kap**2 + 1.0_wp)*ek - 2.0_wp*kk)/((kap**2 - 1.0_wp)*ek) < frho) then
            lo = kap
         else
            hi = kap
         end if
      end do
      call elliptic_trapezoid(1.0_wp - 1.0_wp/kap**2, kk, ek)
      dstar = (2.0_wp*kk/pi)*(pi/(2.0_wp*kap**2*ek))**(1.0_wp/3.0_wp)
      comp = (1.0_wp - 0.3_wp**2)/2.0e11_wp + (1.0_wp - 0.34_wp**2)/1.1e11_wp
      worst = 0.0_wp
      do i = 1, 3
         delta = deltas(i)
         call pocket_state([0.0_wp, 2.5e-4_wp + delta, 0.0_wp], ball, cage)
         ball%velocity = cage%velocity + cross(cage%omega, ball%position - cage%position)
         call cage_pocket_contact(p, 0.7_wp, ball, cage, c)
         q = (2.0_wp*srho/(3.0_wp*comp))*(2.0_wp*delta/(dstar*srho))**1.5_wp
         worst = max(worst, abs(c%metallic_load - q)/q)
         if (i == 2) write (*, "(a,f8.4,a,es12.5,a,es12.5,a)") "pocket vs Hertz: kappa ", kap, ", delta 6 um: Q ", &
            c%metallic_load, " N, Hertz ", q, " N"
      end do
      write (*, "(a,es9.2)") "pocket vs Hertz: worst relative deviation at delta = 1, 6, 20 um: ", worst
      call check(worst <= 1.0e-9_wp, "pocket: metallic load = Hertz's sphere in a concave cylinder")
   end subroutine test_pocket_against_hertz

   !> Complete elliptic integrals K(m), E(m) by the trapezoidal rule on [0, pi/2].
   subroutine elliptic_trapezoid(m, kk, ek)
      real(wp), intent(in) :: m
      real(wp), intent(out) :: kk, ek
      integer, parameter :: n = 4000
      real(wp) :: th, wgt, s
      integer :: j
      kk = 0.0_wp
      ek = 0.0_wp
      do j = 0, n
         th = 0.5_wp*pi*real(j, wp)/real(n, wp)
         wgt = merge(0.5_wp, 1.0_wp, j == 0 .or. j == n)
         s = 1.0_wp - m*sin(th)**2
         kk = kk + wgt/sqrt(s)
         ek = ek + wgt*sqrt(s)
      end do
      kk = kk*0.5_wp*pi/real(n, wp)
      ek = ek*0.5_wp*pi/real(n, wp)
   end subroutine elliptic_trapezoid

   !> A ball pushed into its pocket wall is pushed back (lubricated, with friction); deep
   !> interference is abnormal, shallow is not.
   subroutine test_pushed_back_and_abnormal()
      type(cage_pocket_pair_t) :: p
      type(body_state_t) :: ball, cage
      type(cage_pocket_geometry_t) :: c
      real(wp) :: y_p(3), dir(3), psi
      integer :: sgn

      p = test_pocket(5.0e-3_wp, 0.05_wp)
      psi = 0.7_wp
      do sgn = -1, 1, 2
         call pocket_state([0.0_wp, sgn*(2.5e-4_wp + 3.0e-6_wp), 0.0_wp], ball, cage)
         call cage_pocket_contact(p, psi, ball, cage, c)
         y_p = matmul(quat_matrix(cage%attitude), [0.0_wp, cos(psi), sin(psi)])
         dir = sgn*y_p
         call check(dot_product(c%force_ball, dir) < -0.9_wp*norm2(c%force_ball), &
                    "pocket: the ball pushed into the wall is pushed back")
         call check(c%metallic_load > 0.0_wp .and. .not. c%abnormal, "pocket: 3 um interference is normal")
      end do
      call pocket_state([0.0_wp, 2.5e-4_wp + 7.0e-5_wp, 0.0_wp], ball, cage)
      call cage_pocket_contact(p, psi, ball, cage, c)
      call check(c%abnormal, "pocket: interference of 28 % of the radial clearance is abnormal")
   end subroutine test_pushed_back_and_abnormal

   !> The film force against Ocvirk's closed form (pure rotation) and at half-frequency whirl.
   subroutine test_short_bearing_closed_form()
      type(cage_land_pair_t) :: p
      type(body_state_t) :: cage, race
      type(cage_land_geometry_t) :: cl
      real(wp) :: eps, w, f(2), fe, ft, worst, k, e_e(3), e_t(3)
      real(wp), parameter :: eps_list(4) = [0.1_wp, 0.4_wp, 0.7_wp, 0.9_wp]
      integer :: i

      p = test_land(4.0e-3_wp, 0.05_wp, .true.)
      w = 1500.0_wp
      worst = 0.0_wp
      do i = 1, 4
         eps = eps_list(i)
         k = p%viscosity*w*p%radius*p%width**3/p%clearance**2
         fe = -k*eps**2/(1.0_wp - eps**2)**2
         ft = pi*k*eps/(4.0_wp*(1.0_wp - eps**2)**1.5_wp)
         f = short_bearing_force(p, eps, 0.5_wp*w, 0.0_wp)
         worst = max(worst, abs(f(1) - fe)/abs(fe), abs(f(2) - ft)/abs(ft))
      end do
      ! the same through the 3-D contact: race journal at 1000 rad/s, cage at 500 rad/s, eps 0.6
      race%omega = [1000.0_wp, 0.0_wp, 0.0_wp]
      cage%omega = [500.0_wp, 0.0_wp, 0.0_wp]
      cage%position = [0.0_wp, 0.6_wp*p%clearance*cos(0.3_wp), 0.6_wp*p%clearance*sin(0.3_wp)]
      call cage_land_contact(p, cage, race, cl)
      eps = 0.6_wp
      k = p%viscosity*1500.0_wp*p%radius*p%width**3/p%clearance**2
      e_e = -cage%position/norm2(cage%position)      ! race (journal) centre - cage centre
      e_t = cross([1.0_wp, 0.0_wp, 0.0_wp], e_e)
      fe = -k*eps**2/(1.0_wp - eps**2)**2
      ft = pi*k*eps/(4.0_wp*(1.0_wp - eps**2)**1.5_wp)
      worst = max(worst, norm2(cl%force_race - (fe*e_e + ft*e_t))/hypot(fe, ft))
      write (*, "(a,es10.2)") "short bearing vs Ocvirk closed form (eps 0.1 .. 0.9, and 3-D), worst relative ", worst
      call check(worst < 1.0e-9_wp, "short bearing: film force = Hamrock's closed form")
      ! half-frequency whirl: the cage centre orbiting at wbar about the race carries no film
      cage%velocity = 750.0_wp*cross([1.0_wp, 0.0_wp, 0.0_wp], cage%position)  ! e = race - cage whirls at +750
      call cage_land_contact(p, cage, race, cl)
      write (*, "(a,es10.2)") "short bearing at half-frequency whirl: |F| / |F(no whirl)| ", &
         norm2(cl%hydro_force)/hypot(fe, ft)
      call check(norm2(cl%hydro_force) < 1.0e-12_wp*hypot(fe, ft), "short bearing: no film force at half-frequency whirl")
   end subroutine test_short_bearing_closed_form

   !> The short-bearing force (its nodes' cos and sin by angle addition) against the same
   !> panels with sin(theta - beta), cos(theta), sin(theta) called at every node (the form
   !> before issue #30's cut): equal to round-off over eps 0.02 .. 0.98, squeeze and whirl
   !> of either sign, flooded and starved lands (the difference relative to the larger of
   !> the force and the flooded land's: a starved arc's force can be a sliver of its integrand).
   subroutine test_short_bearing_direct_form()
      type(cage_land_pair_t) :: p, pf
      real(wp) :: f(2), fd(2), flooded(2), worst, eps, wb, ed
      real(wp), parameter :: oil(3) = [huge(1.0_wp), 3.0e-4_wp, 1.5e-4_wp]
      integer :: i, j, k, n
      worst = 0.0_wp
      n = 0
      p = test_land(4.0e-3_wp, 0.05_wp, .true.)
      do k = 1, 3
         p%oil_layer = oil(k)
         do i = 0, 24
            eps = 0.02_wp + 0.04_wp*i
            do j = -3, 3
               wb = 800.0_wp*(1.0_wp + 0.3_wp*j)
               ed = 400.0_wp*j
               f = short_bearing_force(p, eps, wb, ed)
               fd = direct_short_bearing(p, eps, wb, ed)
               pf = p
               pf%oil_layer = huge(1.0_wp)
               flooded = direct_short_bearing(pf, eps, wb, ed)
               if (norm2(fd) > 0.0_wp) then
                  worst = max(worst, norm2(f - fd)/max(norm2(fd), norm2(flooded)))
                  n = n + 1
               else
                  call check(norm2(f) == 0.0_wp, "short bearing: no force where the direct form has none")
               end if
            end do
         end do
      end do
      write (*, "(a,i0,a,es10.2)") "short bearing vs the direct-node form (", n, &
         " states), worst relative to max(|F|, |F flooded|) ", worst
      call check(n > 400, "short bearing: the direct-form comparison covers the states")
      call check(worst < 1.0e-13_wp, "short bearing: angle-addition nodes = direct sin/cos to round-off")
   end subroutine test_short_bearing_direct_form

   !> short_bearing_force with every node's sin(theta - beta), cos(theta), sin(theta) called
   !> (the reference of test_short_bearing_direct_form; 8 panels of 24 Gauss points).
   function direct_short_bearing(p, eps, wbar_minus_whirl, epsdot) result(f)
      type(cage_land_pair_t), intent(in) :: p
      real(wp), intent(in) :: eps, wbar_minus_whirl, epsdot
      integer, parameter :: NG = 24
      real(wp) :: f(2), a, bb, r0, beta, x(NG), w(NG), lo, hi, tw
      integer :: k
      f = 0.0_wp
      a = eps*wbar_minus_whirl
      bb = epsdot
      r0 = hypot(a, bb)
      if (.not. r0 > 0.0_wp .or. p%viscosity <= 0.0_wp) return
      beta = atan2(bb, a)
      tw = wetted_half_angle(p, eps)
      if (.not. tw > 0.0_wp) return
      call gauss_legendre(NG, x, w)
      if (tw >= pi) then
         f = direct_arc(beta + pi, pi, r0, beta, eps, x, w)
      else
         lo = modulo(beta + pi, 2.0_wp*pi)
         hi = lo + pi
         do k = 0, 1
            if (min(hi, tw + 2.0_wp*pi*k) > max(lo, -tw + 2.0_wp*pi*k)) &
               f = f + direct_arc(max(lo, -tw + 2.0_wp*pi*k), min(hi, tw + 2.0_wp*pi*k) - max(lo, -tw + 2.0_wp*pi*k), &
                                  r0, beta, eps, x, w)
         end do
      end if
      f = f*p%viscosity*p%radius*p%width**3/p%clearance**2
   end function direct_short_bearing

   !> The arc (t0, t0 + len) of direct_short_bearing: sin(theta - beta), cos and sin of
   !> theta called at each of NP x NG nodes (x, w: the NG-point rule).
   function direct_arc(t0, len, r0, beta, eps, x, w) result(g)
      real(wp), intent(in) :: t0, len, r0, beta, eps, x(:), w(:)
      integer, parameter :: NP = 8
      real(wp) :: g(2), hw, th, s, lo_k
      integer :: i, kk
      g = 0.0_wp
      hw = 0.5_wp*len/NP
      do kk = 1, NP
         lo_k = t0 + (kk - 1)*2.0_wp*hw
         do i = 1, size(x)
            th = lo_k + hw*(1.0_wp + x(i))
            s = r0*sin(th - beta)
            g = g + hw*w(i)*s/(1.0_wp - eps*cos(th))**3*[cos(th), sin(th)]
         end do
      end do
   end function direct_arc

   !> The starved land film (adore_contact_cage_land header): the film exists where the local
   !> gap h = c (1 - eps cos theta) is below the oil layer h_oil.
   subroutine test_starved_land()
      type(cage_land_pair_t) :: p, pf
      type(body_state_t) :: cage, race
      type(cage_land_geometry_t) :: cl, cf
      real(wp) :: eps, w, f(2), ref(2), th, dth, h, sc, tw, jnum, worst_f, worst_j, fprev, kf, loss_ref, pw, wbar
      real(wp) :: gaps(4), fmag(4)
      real(wp), parameter :: eps_list(3) = [0.85_wp, 0.9_wp, 0.97_wp]
      integer :: i, k, n

      w = 1500.0_wp
      p = test_land(4.0e-3_wp, 0.05_wp, .true.)
      p%oil_layer = 5.0e-5_wp                      ! 50 um of oil in c = 300 um
      ! 1. brute force: the Ocvirk pressure's resultant over {h < h_oil, S < 0} (midpoint rule
      !    over the whole circle, 4e6 cells: the wetted edges resolved to ~1e-5 of the arc)
      !    and J = int over h < h_oil of dtheta / (1 - eps cos theta), against the routines
      worst_f = 0.0_wp
      worst_j = 0.0_wp
      n = 4000000
      dth = 2.0_wp*pi/n
      do k = 1, 3
         eps = eps_list(k)
         ref = 0.0_wp
         jnum = 0.0_wp
         do i = 1, n
            th = -pi + (i - 0.5_wp)*dth
            h = 1.0_wp - eps*cos(th)
            if (h*p%clearance >= p%oil_layer) cycle
            jnum = jnum + dth/h
            sc = eps*0.5_wp*w*sin(th) - 0.1_wp*w*cos(th)     ! S/c with a squeeze rate epsdot = 0.1 w
            if (sc < 0.0_wp) ref = ref + dth*sc/h**3*[cos(th), sin(th)]
         end do
         ref = ref*p%viscosity*p%radius*p%width**3/p%clearance**2
         f = short_bearing_force(p, eps, 0.5_wp*w, 0.1_wp*w)
         worst_f = max(worst_f, norm2(f - ref)/norm2(ref))
         tw = wetted_half_angle(p, eps)
         worst_j = max(worst_j, abs(couette_integral(eps, tw) - jnum)/jnum)
      end do
      write (*, "(a,2es10.2)") "starved land vs brute-force quadrature: force, Couette factor (relative) ", &
         worst_f, worst_j
      call check(worst_f < 1.0e-4_wp, "starved land: wetted-arc force = the Ocvirk pressure over h < h_oil")
      call check(worst_j < 1.0e-4_wp, "starved land: Couette factor J = the closed form")

      ! 2. zero beyond the threshold, continuous at it (the wetted arc, and the torque with it,
      !    opens as sqrt(h_oil - gap)): race journal 1000 rad/s, cage 500 rad/s
      race%omega = [1000.0_wp, 0.0_wp, 0.0_wp]
      cage%omega = [500.0_wp, 0.0_wp, 0.0_wp]
      gaps = p%oil_layer*[1.5_wp, 1.0_wp, 1.0_wp - 1.0e-10_wp, 1.0_wp - 1.0e-2_wp]
      do k = 1, 4
         cage%position = [0.0_wp, 0.0_wp, p%clearance - gaps(k)]
         call cage_land_contact(p, cage, race, cl)
         fmag(k) = norm2(cl%force_cage) + abs(cl%moment_cage(1))/p%radius + abs(cl%film_loss)
      end do
      write (*, "(a,4es10.2)") "starved land, |F| + |T|/R + loss at gap/h_oil 1.5, 1, 1 - 1e-10, 1 - 1e-2: ", fmag
      call check(fmag(1) == 0.0_wp .and. fmag(2) == 0.0_wp, "starved land: no force, torque or loss at gap >= h_oil")
      call check(fmag(3) > 0.0_wp .and. fmag(3) < 1.0e-3_wp*fmag(4), "starved land: continuous at the threshold")
      fprev = 0.0_wp
      do k = 1, 20                                 ! the force grows as the gap closes
         cage%position = [0.0_wp, 0.0_wp, p%clearance - p%oil_layer*(1.0_wp - 0.05_wp*k)]
         call cage_land_contact(p, cage, race, cl)
         call check(norm2(cl%hydro_force) > fprev, "starved land: the film force grows as the gap closes")
         fprev = norm2(cl%hydro_force)
      end do

      ! 3. flooded limit: h_oil >= c (1 + eps) gives Ocvirk's force and Petroff's torque
      pf = p
      pf%oil_layer = 2.0_wp*p%clearance
      eps = 0.6_wp
      cage%position = [0.0_wp, 0.0_wp, eps*p%clearance]
      cage%velocity = 0.0_wp
      call cage_land_contact(pf, cage, race, cf)
      kf = pf%viscosity*1500.0_wp*pf%radius*pf%width**3/pf%clearance**2
      ref = [-kf*eps**2/(1.0_wp - eps**2)**2, pi*kf*eps/(4.0_wp*(1.0_wp - eps**2)**1.5_wp)]
      worst_f = abs(norm2(cf%hydro_force) - norm2(ref))/norm2(ref)
      sc = -2.0_wp*pi*pf%viscosity*pf%radius**3*pf%width*(-500.0_wp)/(pf%clearance*sqrt(1.0_wp - eps**2))
      ! the couples on journal (race) and bearing (cage) differ by e x F; their half-difference
      ! is the Couette (Petroff) torque on the cage
      worst_j = abs(0.5_wp*(cf%moment_cage(1) - cf%moment_race(1)) - sc)/abs(sc)
      write (*, "(a,2es10.2)") "flooded land vs Ocvirk force, Petroff torque (relative) ", worst_f, worst_j
      call check(worst_f < 1.0e-12_wp .and. worst_j < 1.0e-12_wp, "flooded land: Ocvirk force and Petroff torque")
      ! (the dry sliver at theta = pi closes as sqrt of the margin: 1e-13 leaves ~1e-6 rad)
      p%oil_layer = (1.0_wp + eps)*p%clearance*(1.0_wp - 1.0e-13_wp)
      call cage_land_contact(p, cage, race, cl)
      write (*, "(a,2es10.2)") "starved land just below the flooded limit: force, torque vs flooded (relative) ", &
         norm2(cl%force_cage - cf%force_cage)/norm2(cf%force_cage), &
         abs(cl%moment_cage(1) - cf%moment_cage(1))/abs(cf%moment_cage(1))
      call check(norm2(cl%force_cage - cf%force_cage) < 1.0e-6_wp*norm2(cf%force_cage) .and. &
                 abs(cl%moment_cage(1) - cf%moment_cage(1)) < 1.0e-6_wp*abs(cf%moment_cage(1)), &
                 "starved land: continuous at the flooded limit")

      ! 4. the film's loss: pure rotation at fixed e, loss = e F_t wbar + eta R**3 L J dw**2 / c
      !    (F_t the tangential film force on the journal), and = minus the power of its loads
      p%oil_layer = 1.0e-4_wp
      eps = 0.9_wp
      cage%position = [0.0_wp, 0.0_wp, eps*p%clearance]
      call cage_land_contact(p, cage, race, cl)
      wbar = 750.0_wp
      tw = wetted_half_angle(p, eps)
      f = short_bearing_force(p, eps, wbar, 0.0_wp)
      loss_ref = eps*p%clearance*f(2)*wbar + p%viscosity*p%radius**3*p%width*couette_integral(eps, tw)*500.0_wp**2/p%clearance
      write (*, "(a,2es12.4)") "starved land loss, closed form (W) ", cl%film_loss, loss_ref
      call check(cl%film_loss > 0.0_wp .and. abs(cl%film_loss - loss_ref) < 1.0e-12_wp*loss_ref, &
                 "starved land: loss = e F_t wbar + Couette")
      ! whirling and squeezing: the loss is what the loads take from cage and race
      cage%velocity = [0.0_wp, 0.05_wp, -0.02_wp]
      race%velocity = [0.0_wp, 0.0_wp, 0.01_wp]
      call cage_land_contact(p, cage, race, cl)
      pw = dot_product(cl%force_cage, cage%velocity) + dot_product(cl%moment_cage, cage%omega) + &
           dot_product(cl%force_race, race%velocity) + dot_product(cl%moment_race, race%omega)
      write (*, "(a,2es12.4)") "starved land whirling: film loss, minus the loads' power (W) ", cl%film_loss, -pw
      call check(cl%film_loss > 0.0_wp .and. abs(cl%film_loss + pw) < 1.0e-12_wp*cl%film_loss, &
                 "starved land: loss = minus the power of the film's loads")
   end subroutine test_starved_land

   !> At the step-0 state (initial_ball_state) the pocket and land interactions equal the
   !> step-0 cage geometry (adore_cage_step0 Geo Int).
   subroutine test_step0_geometry()
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: ld
      real(wp) :: worst_p, worst_l
      integer :: k

      st = initial_ball_state(b, g, s0%start, s0%cage)
      call ball_bearing_loads(b, g, st, ld, error, traction=.false.)
      call check(.not. allocated(error), "loads at the step-0 state")
      if (allocated(error)) return
      worst_p = 0.0_wp
      do k = 1, b%n_elements
         worst_p = max(worst_p, abs(ld%pockets(k)%gap - s0%cage%pocket(1, k)%geo_int))
      end do
      worst_l = 0.0_wp
      do k = 1, b%n_lands
         worst_l = max(worst_l, abs(ld%lands(k)%gap - s0%cage%land(k)%geo_int))
      end do
      write (*, "(a,2es10.2,a,f9.4,a)") "step-0 state vs cage_step0 Geo Int: pockets, lands (m) ", worst_p, worst_l, &
         "; ball 9 gap ", ld%pockets(9)%gap*1.0e3_wp, " mm (printed 3.977e-4 m)"
      call check(worst_p < 1.0e-12_wp, "step 0: pocket interactions = cage_step0 Geo Int")
      call check(worst_l < 1.0e-12_wp, "step 0: land interactions = cage_step0 Geo Int")
      call check(.not. ld%abnormal, "step 0: no abnormal cage contact")
   end subroutine test_step0_geometry

   !> The cage contacts' friction coefficients come from the deck: Rec 10.5.1B / 10.5.2B
   !> coefficient A (0.05 in Appendix C), and a changed model value reaches both pairs.
   subroutine test_friction_from_deck()
      type(bearing_t) :: b2
      type(cage_land_pair_t), allocatable :: lp(:)
      type(cage_pocket_pair_t) :: pp
      call check(all(b%cage_friction == [0.05_wp, 0.05_wp]), "friction: Rec 10.5.1B/2B coefficient A read (0.05)")
      b2 = b
      b2%cage_friction = [0.11_wp, 0.07_wp]
      lp = guide_land_pairs(b2, g, b2%temperature)
      pp = ball_pocket_pair(b2, g, b2%temperature)
      call check(pp%friction == 0.11_wp .and. all(lp%friction == 0.07_wp), &
                 "friction: the pocket and land pairs carry the model's coefficients")
   end subroutine test_friction_from_deck

   !> Cage centred on the guiding (inner) race, spinning at its initial angular speed
   !> without whirl, every ball on its pocket axis moving with the cage: no cage force; with
   !> flooded lands the cage moment about x is the lands' Couette torque
   !> -2 pi eta R**3 L (w_c - w_r) / c, with the default oil layer none.
   subroutine test_centred_cage()
      type(bearing_t) :: bf
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: ld
      type(cage_land_pair_t), allocatable :: lp(:)
      real(wp) :: rot(3, 3), psi, rp, w(3), torque, ref
      integer :: k

      st = initial_ball_state(b, g, s0%start, s0%cage)
      st%cage%position(2:3) = st%races(RACE_INNER)%position(2:3)
      st%cage%velocity = 0.0_wp
      st%cage%attitude = quat_from_rotation_vector([0.25_wp, 0.0_wp, 0.0_wp])
      st%races(RACE_INNER)%velocity = 0.0_wp
      rot = quat_matrix(st%cage%attitude)
      w = matmul(rot, st%cage%omega)
      rp = 0.25_wp*(b%cage_od + b%cage_id)
      do k = 1, b%n_elements
         psi = 2.0_wp*pi*(k - 1)/b%n_elements
         st%elements(k)%position = st%cage%position + matmul(rot, rp*[0.0_wp, -sin(psi), cos(psi)])
         st%elements(k)%velocity = cross(w, st%elements(k)%position - st%cage%position)
      end do
      ! the default oil layer (10 um) leaves the centred cage's 0.72 mm gaps dry
      call ball_bearing_loads(b, g, st, ld, error, traction=.false.)
      call check(.not. allocated(error), "loads at the centred cage")
      if (allocated(error)) return
      call check(all(ld%lands%film_loss == 0.0_wp) .and. all(ld%lands%moment_cage(1) == 0.0_wp) .and. &
                 all(ld%lands%force_cage(2) == 0.0_wp) .and. all(ld%lands%force_cage(3) == 0.0_wp), &
                 "centred cage, default oil layer: no land film (force, torque, loss)")
      ! flooded lands: the Couette torque
      bf = b
      bf%land_oil_layer = huge(1.0_wp)
      call ball_bearing_loads(bf, g, st, ld, error, traction=.false.)
      call check(.not. allocated(error), "loads at the centred cage")
      if (allocated(error)) return
      lp = guide_land_pairs(bf, g, st%temperature)
      ref = 0.0_wp
      do k = 1, size(lp)
         ref = ref - 2.0_wp*pi*lp(k)%viscosity*lp(k)%radius**3*lp(k)%width*(st%cage%omega(1) - &
                                                                            st%races(RACE_INNER)%omega(1))/lp(k)%clearance
      end do
      torque = ld%cage%moment(1)
      write (*, "(a,es10.2,a,2es12.4,a)") "centred cage: |cage force - weight| ", &
         norm2(ld%cage%force - b%mass(BODY_CAGE)*b%gravity), " N; moment x, Couette ", torque, ref, " N m"
      call check(norm2(ld%cage%force - b%mass(BODY_CAGE)*b%gravity) < 1.0e-12_wp, "centred cage: no cage contact force")
      call check(all(ld%pockets%metallic_load == 0.0_wp) .and. all(abs(ld%pockets%hydro_load) < 1.0e-12_wp), &
                 "centred cage: no pocket force")
      call check(ref /= 0.0_wp .and. abs(torque - ref) < 1.0e-12_wp*abs(ref), "centred cage: moment = Couette torque")
      call check(abs(ld%cage%moment(2)) + abs(ld%cage%moment(3)) < 1.0e-12_wp*abs(ref), "centred cage: no tilting moment")
   end subroutine test_centred_cage

   !> The ball system's derivative refuses a state with an abnormal pocket contact (4.4.12).
   subroutine test_reject_step()
      type(ball_system_t) :: sys
      type(bearing_state_t) :: st
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: n(3)
      integer :: flag

      sys = new_ball_system(b, g, 1.0_wp, traction=.false., cage=.true.)
      st = initial_ball_state(b, g, s0%start, s0%cage)
      allocate (y(state_size(b%n_elements)), dydt(state_size(b%n_elements)))
      call pack_state(st, y)
      call sys%eval(0.0_wp, y, dydt, flag)
      call check(flag == DERIV_OK, "step-0 state: the derivative accepts")
      ! ball 1 through its pocket wall, 40 % of the radial clearance deep
      n = sys%loads%pockets(1)%normal
      st%elements(1)%position = st%elements(1)%position + (sys%loads%pockets(1)%gap + &
                                                           0.2_wp*b%pocket_clearance(1))*n
      call pack_state(st, y)
      call sys%eval(0.0_wp, y, dydt, flag)
      call check(sys%loads%pockets(1)%abnormal, "deep pocket interference is abnormal")
      call check(flag == DERIV_REJECT_STEP, "abnormal cage contact: the derivative asks for a smaller step")
   end subroutine test_reject_step

end program test_cage_contacts
