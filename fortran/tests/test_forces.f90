!> Unit tests of the 3-D ball/race contact and the ball bearing force assembly
!> (adore_contact_ball_race, adore_forces_ball_bearing) on the Appendix C deck:
!> * the planar special case: at the step-0 start (race control, the fast start), the 3-D
!>   contacts reproduce the equilibrium's loads and angles, the planar contacts of the
!>   start's kinematics, the ball and inner-race force balances and the race loads of the
!>   step-0 tribology (normal loads plus traction, section 3 of the print);
!> * a perturbed, non-equilibrium state (a ball displaced and spinning about a skewed
!>   axis, the inner race shifted and misaligned): the normal forces and moments equal
!>   minus the gradient of the contact energy (central finite differences, frozen K), and
!>   the contact loads (normal and traction) obey action = reaction in force and moment;
!> * the equations of motion (adore_dynamics_ball_motion): at the step-0 state the balls
!>   accelerate centripetally and the inner race not at all; a free asymmetric body keeps
!>   its inertial angular momentum and its attitude rate is R [omega]x;
!> * the two-dimensional traction (two_d): it opposes a spin about e_t, keeps action =
!>   reaction, and its fast quadrature agrees with the reference one within 1e-4 at every
!>   race contact at the step-0 state and at states slipping across the rolling direction.
!> * team_join (the end of a parallel loop's work): every thread but the first counted once;
!> * team_t (the run's threads or one, measured call by call): with synthetic call times it
!>   keeps the threads while they are faster, goes to one thread while one is, and measures
!>   both again after TEAM_KEEP calls;
!> * threads: the loads on 1, 2 and 5 threads are the same bit for bit (every body, contact,
!>   heat, pocket and land), and an error is the first ball's whichever thread met it;
!> * the Hertz ellipse (adore_contact_hertz): the bisection with its Newton shortcut gives
!>   the exhaustive bisection's ellipse bit for bit (the force assembly's cost).
!> Run by `meson test` with the decks/ directory as argument.
program test_forces
   use, intrinsic :: iso_fortran_env, only: int64
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_core_rotation, only: cross, quat_from_rotation_vector, quat_multiply
   use adore_model_bearing, only: BODY_CAGE, BODY_ELEMENT, BODY_INNER, BODY_OUTER, bearing_t
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, new_bearing_state, RACE_OUTER, RACE_INNER, &
                                        state_size, pack_state, unpack_state
   use adore_contact_ball_race, only: ball_race_pair_t, ball_race_geometry_t, ball_race_contact, planar_contact, &
                                      contact_energy
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, ball_bearing_loads, ball_race_pairs, &
                                        add_gyroscopic_restraint
   use adore_start_ball_step0, only: ball_step0_t
   use adore_quasistatic_ball_kinematics, only: ball_contacts
   use adore_tribology_slip, only: ball_race_contact_t
   use adore_dynamics_ball_motion, only: ball_bearing_rates, body_rates
   use adore_forces_ball_bearing, only: body_load_t
   use adore_state_bearing_state, only: body_state_t
   use adore_core_rotation, only: quat_matrix
   use adore_test_support, only: check, finish
   use adore_core_threads, only: team_join, team_t, team_threads, team_note, TEAM_PROBE, TEAM_KEEP, TEAM_CUT, &
                                 TEAM_BACKOFF
   use adore_test_ball_fixture, only: step0_state, appendix_c_race_control, power_of, loads_power
   implicit none

   type(bearing_t) :: b
   type(mounted_geometry_t) :: g
   type(error_type), allocatable :: error
   type(ball_step0_t) :: s0
   type(bearing_state_t) :: st

   call appendix_c_race_control("force assembly", b, g, s0)
   st = step0_state(b, s0)
   call test_pack_round_trip(st)
   call test_planar_special_case(b, g, s0, st)
   call test_perturbed_state(b, g, st)
   call test_motion_at_step0(b, g, s0, st)
   call test_two_dimensional_traction(b, g, st)
   call test_traction_power(b, g, st)
   call test_gyroscopic_restraint(b, g, st)
   call test_contact_damping(b, g, st)
   call test_free_body_rates()
   call test_threads_same_loads(b, g, st)
   call test_team_join()
   call test_team_choice()
   call finish("force assembly")

contains

   subroutine test_pack_round_trip(st)
      type(bearing_state_t), intent(in) :: st
      type(bearing_state_t) :: back
      real(wp), allocatable :: y(:), y2(:)
      allocate (y(state_size(size(st%elements))), y2(state_size(size(st%elements))))
      call pack_state(st, y)
      back = new_bearing_state(size(st%elements))
      call unpack_state(y, 0.0_wp, back)
      call pack_state(back, y2)
      call check(all(y == y2), "state pack/unpack round trip")
   end subroutine test_pack_round_trip

   !> The planar special case.  (a) Exact: with the inner race centred, every 3-D contact
   !> equals the meridian-plane contact of eqs 59-64 at the same ball position (angle,
   !> interaction, Hertz load with K at that angle) and its planar form equals the start's
   !> contact (ball_contacts) at the same speeds.  (b) At the step-0 state itself, whose
   !> inner race is offset by u: the equilibrium linearises the offset (S(phi) u), so the
   !> 3-D loads, the balls' and the inner race's balance and the section-3 race forces
   !> agree to the linearisation's order, (u_r**2 / r) / delta for loads and u_r / r for
   !> the race's rolling speed (u_r: radial offset, r: inner groove radius).
   subroutine test_planar_special_case(b, g, s0, st)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_step0_t), intent(in) :: s0
      type(bearing_state_t), intent(in) :: st
      type(bearing_state_t) :: centred
      type(ball_bearing_loads_t) :: ld
      type(ball_race_pair_t) :: pairs(2)
      type(ball_race_contact_t) :: ref(2), q
      real(wp) :: worst_q, worst_a, worst_w, worst_ball, worst_race, qmax, e_r(3), phi, f_ref(3), m_ref(3)
      real(wp) :: a(2), delta, alpha, load, u_r, tol_load, tol_speed, n_o(2), n_i(2), qq(2), aa(2)
      integer :: k, j

      pairs = ball_race_pairs(b, g)
      ! (a) exact reduction with the inner race centred
      centred = st
      centred%races(RACE_INNER)%position = 0.0_wp
      call ball_bearing_loads(b, g, centred, ld, error)
      call check(.not. allocated(error), "force assembly at the centred step-0 state")
      if (allocated(error)) return
      worst_q = 0.0_wp
      worst_a = 0.0_wp
      worst_w = 0.0_wp
      associate (e => s0%start%equilibrium, kin => s0%start%kinematics)
         do k = 1, b%n_elements
            do j = 1, 2
               a = [e%x(k), e%r(k)] - g%groove_centre(:, j)
               delta = norm2(a) - (g%groove_radius(j) - 0.5_wp*b%d)
               alpha = atan(abs(a(1))/abs(a(2)))
               load = ld%contacts(j, k)%stiffness*max(delta, 0.0_wp)**1.5_wp
               worst_q = max(worst_q, abs(ld%contacts(j, k)%load - load)/max(load, 1.0_wp), &
                             abs(ld%contacts(j, k)%delta - delta)/b%d)
               worst_a = max(worst_a, abs(abs(ld%contacts(j, k)%alpha) - alpha))
               aa(j) = ld%contacts(j, k)%ellipse%semi_major
               qq(j) = ld%contacts(j, k)%load
               if (j == 1) n_o = a/norm2(a)
               if (j == 2) n_i = a/norm2(a)
            end do
            ref = ball_contacts(b%d, e%r(k), n_o, n_i, b%speed_outer, b%speed_inner, aa, qq, &
                                kin(k)%pitch, kin(k)%spin_speed, kin(k)%orbital_speed)
            do j = 1, 2
               q = planar_contact(pairs(j), ld%contacts(j, k))
               worst_w = max(worst_w, maxval(abs([q%omega - ref(j)%omega, q%race_speed - ref(j)%race_speed])) &
                             /abs(b%speed_inner), abs(q%alpha - ref(j)%alpha), abs(q%r_b - ref(j)%r_b)/b%dm)
            end do
         end do
      end associate
      write (*, "(a,3es10.2)") "planar case, centred race: load/interaction, angle, planar contact ", &
         worst_q, worst_a, worst_w
      call check(worst_q < 1.0e-10_wp, "planar case: 3-D interaction and load = eqs 59-61 in the meridian plane")
      call check(worst_a < 1.0e-10_wp, "planar case: 3-D contact angle = eqs 62-63")
      call check(worst_w < 1.0e-10_wp, "planar case: planar form of the 3-D contact = the start's contact")

      ! (b) the step-0 state with its offset inner race
      call ball_bearing_loads(b, g, st, ld, error)
      call check(.not. allocated(error), "force assembly at the step-0 state")
      if (allocated(error)) return
      worst_q = 0.0_wp
      worst_ball = 0.0_wp
      qmax = maxval([s0%start%equilibrium%q_o, s0%start%equilibrium%q_i])
      associate (e => s0%start%equilibrium, kin => s0%start%kinematics)
         u_r = hypot(e%u(2), e%u(3))
         tol_load = 2.0_wp*1.5_wp*(u_r**2/g%groove_centre(2, 2))/minval([e%delta_o, e%delta_i])
         tol_speed = 2.0_wp*u_r/g%groove_centre(2, 2)
         do k = 1, b%n_elements
            worst_q = max(worst_q, abs(ld%contacts(1, k)%load - e%q_o(k))/qmax, &
                          abs(ld%contacts(2, k)%load - e%q_i(k))/qmax)
            ! ball balance: normal loads + centrifugal m r w_m**2 e_r = 0 (eqs 65-66)
            phi = e%azimuth(k)
            e_r = [0.0_wp, -sin(phi), cos(phi)]
            worst_ball = max(worst_ball, norm2(normal_force(ld, k) + b%mass(BODY_ELEMENT)*e%r(k)*kin(k)%orbital_speed**2*e_r) &
                                         /qmax)
         end do
         ! inner race: the balls' normal loads balance the applied load and the race weight
         f_ref = 0.0_wp
         do k = 1, b%n_elements
            f_ref = f_ref + ld%contacts(2, k)%load*ld%contacts(2, k)%normal
         end do
         worst_race = norm2(f_ref + b%force + b%mass(BODY_INNER)*b%gravity)/norm2(b%force)
      end associate
      write (*, "(a,3es10.2,a,2es10.2)") "planar case, step-0 state: load, ball balance, race balance ", &
         worst_q, worst_ball, worst_race, "; linearisation bounds ", tol_load, tol_speed
      call check(worst_q < tol_load, "step-0 state: 3-D loads = the equilibrium's to its linearisation order")
      call check(worst_ball < tol_load, "step-0 state: normal loads balance each ball's centrifugal force")
      call check(worst_race < tol_load, "step-0 state: the balls' loads balance the inner race's applied load")
      ! race forces = section 3's race loads of the step-0 tribology (normal + traction)
      worst_race = 0.0_wp
      do j = 1, 2
         worst_race = max(worst_race, norm2(ld%races(j)%force - race_weight(b, j) - &
                                            merge(b%force, [0.0_wp, 0.0_wp, 0.0_wp], j == RACE_INNER) - &
                                            s0%race_loads(1:3, j))/norm2(b%force))
      end do
      write (*, "(a,es10.2)") "step-0 state: race forces vs section 3 ", worst_race
      call check(worst_race < tol_load + tol_speed, "step-0 state: race forces = the step-0 race loads (normal + traction)")
      ! outer race moment about the origin (its mass centre): the step-0 print puts each
      ! traction at the contact centre; the assembly spreads it over the major axis, a
      ! difference of the order a/rho of the traction moment
      m_ref = s0%race_loads(4:6, 1)
      call check(norm2(ld%races(RACE_OUTER)%moment - m_ref) <= 0.05_wp*norm2(m_ref), &
                 "step-0 state: outer race moment = the step-0 race moment within the traction spread")
   end subroutine test_planar_special_case

   !> Sum of the normal contact forces on ball k.
   function normal_force(ld, k) result(f)
      type(ball_bearing_loads_t), intent(in) :: ld
      integer, intent(in) :: k
      real(wp) :: f(3)
      f = -ld%contacts(1, k)%load*ld%contacts(1, k)%normal - ld%contacts(2, k)%load*ld%contacts(2, k)%normal
   end function normal_force

   pure function race_weight(b, j) result(w)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: j
      real(wp) :: w(3)
      w = b%mass(merge(BODY_OUTER, BODY_INNER, j == RACE_OUTER))*b%gravity
   end function race_weight

   !> Total contact energy (J) at state st with the stiffness of each contact frozen at k_frozen.
   function total_energy(b, g, st, k_frozen) result(e)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: st
      real(wp), intent(in) :: k_frozen(:, :)
      real(wp) :: e
      type(ball_race_pair_t) :: pairs(2)
      type(ball_race_geometry_t) :: c
      integer :: k, j
      pairs = ball_race_pairs(b, g)
      e = 0.0_wp
      do k = 1, size(st%elements)
         do j = 1, 2
            call ball_race_contact(pairs(j), st%elements(k), st%races(j), c, k_frozen(j, k))
            e = e + contact_energy(c)
         end do
      end do
   end function total_energy

   subroutine test_perturbed_state(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_state_t) :: st, sp, sm
      type(ball_bearing_loads_t) :: ld
      real(wp), allocatable :: kf(:, :)
      real(wp) :: h, hr, grad(3), f(3), m(3), worst_f, worst_m, fscale, total_f(3), total_m(3), e_x(3)
      integer :: i, k, j

      st = base
      ! ball 1 displaced off its equilibrium and spinning about a skewed axis
      st%elements(1)%position = st%elements(1)%position + [4.0e-6_wp, -3.0e-6_wp, 5.0e-6_wp]
      st%elements(1)%omega = st%elements(1)%omega + [300.0_wp, -800.0_wp, 1200.0_wp]
      st%elements(1)%velocity = st%elements(1)%velocity + [0.01_wp, -0.02_wp, 0.015_wp]
      ! inner race shifted and misaligned about a skewed axis (exact rotation)
      st%races(RACE_INNER)%position = st%races(RACE_INNER)%position + [2.0e-6_wp, 1.0e-6_wp, -1.5e-6_wp]
      st%races(RACE_INNER)%attitude = quat_from_rotation_vector([1.0e-4_wp, 4.0e-4_wp, -3.0e-4_wp])
      st%races(RACE_INNER)%velocity = [0.0_wp, 0.003_wp, -0.001_wp]
      call ball_bearing_loads(b, g, st, ld, error)
      call check(.not. allocated(error), "force assembly at a perturbed state")
      if (allocated(error)) return
      call check(ld%contacts(1, 1)%load > 0.0_wp .and. ld%contacts(2, 1)%load > 0.0_wp, &
                 "perturbed ball 1 touches both races")
      allocate (kf(2, size(st%elements)))
      do k = 1, size(st%elements)
         do j = 1, 2
            kf(j, k) = ld%contacts(j, k)%stiffness
         end do
      end do
      fscale = maxval(ld%contacts%load)
      h = 1.0e-10_wp
      hr = 1.0e-9_wp
      ! normal force on ball 1 = -dE/dx
      grad = 0.0_wp
      do i = 1, 3
         sp = st
         sm = st
         sp%elements(1)%position(i) = sp%elements(1)%position(i) + h
         sm%elements(1)%position(i) = sm%elements(1)%position(i) - h
         grad(i) = (total_energy(b, g, sp, kf) - total_energy(b, g, sm, kf))/(2.0_wp*h)
      end do
      f = normal_force(ld, 1)
      worst_f = norm2(f + grad)/fscale
      ! normal force on the inner race = -dE/dc, moment = -dE/dtheta (small rotation in front)
      do i = 1, 3
         sp = st
         sm = st
         sp%races(RACE_INNER)%position(i) = sp%races(RACE_INNER)%position(i) + h
         sm%races(RACE_INNER)%position(i) = sm%races(RACE_INNER)%position(i) - h
         grad(i) = (total_energy(b, g, sp, kf) - total_energy(b, g, sm, kf))/(2.0_wp*h)
      end do
      f = 0.0_wp
      m = 0.0_wp
      do k = 1, size(st%elements)
         associate (c => ld%contacts(2, k))
            f = f + c%load*c%normal
            m = m + cross(c%point - st%races(RACE_INNER)%position, c%load*c%normal)
         end associate
      end do
      worst_f = max(worst_f, norm2(f + grad)/fscale)
      do i = 1, 3
         e_x = 0.0_wp
         e_x(i) = hr
         sp = st
         sm = st
         sp%races(RACE_INNER)%attitude = quat_multiply(quat_from_rotation_vector(e_x), st%races(RACE_INNER)%attitude)
         sm%races(RACE_INNER)%attitude = quat_multiply(quat_from_rotation_vector(-e_x), st%races(RACE_INNER)%attitude)
         grad(i) = (total_energy(b, g, sp, kf) - total_energy(b, g, sm, kf))/(2.0_wp*hr)
      end do
      worst_m = norm2(m + grad)/(fscale*0.5_wp*b%dm)
      write (*, "(a,2es10.2)") "perturbed state, worst force and moment vs -grad E: ", worst_f, worst_m
      call check(worst_f < 1.0e-5_wp, "perturbed: normal forces = -grad of the contact energy (ball and race)")
      call check(worst_m < 1.0e-5_wp, "perturbed: inner race moment = -d(energy)/d(rotation)")
      ! action = reaction over all contacts (normal and traction): the contact loads alone
      ! sum to zero force and zero moment about the origin
      call contact_load_sums(b, st, ld, total_f, total_m)
      ! the cage's pocket and guide-land contacts
      f = ld%cage%force - b%mass(BODY_CAGE)*b%gravity
      total_f = total_f + f
      total_m = total_m + ld%cage%moment + cross(st%cage%position, f)
      call check(norm2(total_f) < 1.0e-9_wp*fscale, "perturbed: contact forces sum to zero (action = reaction)")
      call check(norm2(total_m) < 1.0e-9_wp*fscale*b%dm, "perturbed: contact moments sum to zero")
      call check(abs(ld%traction(1, 1)%force) > 0.0_wp .and. norm2(ld%elements(1)%moment) > 0.0_wp, &
                 "perturbed: ball 1 carries traction and a traction moment")
      call check(norm2(ld%contacts(1, 1)%tangent_slip) > 0.0_wp, "perturbed: ball 1 slips at the outer race")
   end subroutine test_perturbed_state

   !> Sums of the race contacts' loads over the balls and races of state st: force (N) and
   !> moment about the origin (N m), gravity and the applied load taken out (action =
   !> reaction makes both zero).
   subroutine contact_load_sums(b, st, ld, total_f, total_m)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: st
      type(ball_bearing_loads_t), intent(in) :: ld
      real(wp), intent(out) :: total_f(3), total_m(3)
      real(wp) :: f(3), m(3)
      integer :: k, j
      total_f = 0.0_wp
      total_m = 0.0_wp
      do k = 1, size(st%elements)
         total_f = total_f + ld%elements(k)%force - b%mass(BODY_ELEMENT)*b%gravity
         total_m = total_m + ld%elements(k)%moment + cross(st%elements(k)%position, ld%elements(k)%force - &
                                                           b%mass(BODY_ELEMENT)*b%gravity)
      end do
      do j = 1, 2
         f = ld%races(j)%force - race_weight(b, j)
         m = ld%races(j)%moment
         if (j == RACE_INNER) then
            f = f - b%force
            m = m - b%moment
         end if
         total_f = total_f + f
         total_m = total_m + m + cross(st%races(j)%position, f)
      end do
   end subroutine contact_load_sums

   !> The two-dimensional traction (ball_bearing_loads' two_d): a spin of ball 1 about its
   !> outer contact's rolling direction e_t (an out-of-plane tilt of its spin axis) slips
   !> across the rolling direction; the 2-D traction opposes it (moment along e_t against the
   !> spin, more heat), which the 1-D traction (along e_t only) cannot: its moment has no e_t
   !> component.  Contact loads still sum to zero force and moment with it.
   subroutine test_two_dimensional_traction(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: l1, l2, l0
      real(wp) :: e_t(3), m1, m2, total_f(3), total_m(3)

      call ball_bearing_loads(b, g, base, l0, error, cage=.false., two_d=.true.)
      if (allocated(error)) return
      e_t = l0%contacts(1, 1)%rolling
      st = base
      st%elements(1)%omega = st%elements(1)%omega + 200.0_wp*e_t
      call ball_bearing_loads(b, g, st, l1, error, cage=.false.)
      call check(.not. allocated(error), "2-D traction: 1-D loads at the tilted spin")
      if (allocated(error)) return
      call ball_bearing_loads(b, g, st, l2, error, cage=.false., two_d=.true.)
      call check(.not. allocated(error), "2-D traction: 2-D loads at the tilted spin")
      if (allocated(error)) return
      m1 = dot_product(l1%elements(1)%moment, e_t)
      m2 = dot_product(l2%elements(1)%moment - l0%elements(1)%moment, e_t)
      write (*, "(a,3es11.3)") "2-D traction: ball 1 moment along e_t (1-D, 2-D change) and heat change (W) ", &
         m1, m2, sum(l2%heat(:, 1)) - sum(l0%heat(:, 1))
      call check(abs(m1) <= 1.0e-9_wp*norm2(l1%elements(1)%moment), "1-D traction: no moment along e_t")
      call check(m2 < 0.0_wp, "2-D traction: the moment along e_t opposes the out-of-plane spin")
      call check(sum(l2%heat(:, 1)) > sum(l0%heat(:, 1)), "2-D traction: the cross slip adds heat")
      call contact_load_sums(b, st, l2, total_f, total_m)
      call check(norm2(total_f) < 1.0e-9_wp*maxval(l2%contacts%load), "2-D traction: contact forces sum to zero")
      call check(norm2(total_m) < 1.0e-9_wp*maxval(l2%contacts%load)*b%dm, "2-D traction: contact moments sum to zero")
   end subroutine test_two_dimensional_traction

   !> Power balance of the race traction: the mechanical power of the traction loads on
   !> every body (force . velocity + moment . angular velocity, inertial components) is
   !> minus the heat the contacts generate, at the step-0 state and at a perturbed state
   !> (ball 1 spinning about a skewed axis), for the 1-D and the 2-D traction.  A moment
   !> with a wrong lever arm or sign would break it.
   subroutine test_traction_power(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: l0, l1
      real(wp) :: p_mech, heat
      integer :: icase
      logical :: two_d

      do icase = 1, 4
         st = base
         if (icase > 2) then
            st%elements(1)%omega = st%elements(1)%omega + [300.0_wp, -800.0_wp, 1200.0_wp]
            st%elements(1)%velocity = st%elements(1)%velocity + [0.01_wp, -0.02_wp, 0.015_wp]
         end if
         two_d = mod(icase, 2) == 0
         call ball_bearing_loads(b, g, st, l0, error, traction=.false., cage=.false.)
         if (allocated(error)) return
         call ball_bearing_loads(b, g, st, l1, error, cage=.false., two_d=two_d)
         if (allocated(error)) return
         p_mech = loads_power(st, l1, l0)
         heat = sum(l1%heat)
         write (*, "(a,l2,a,2es12.4,es10.2)") "traction power: perturbed, two_d", two_d, &
            "  mechanical, -heat (W), rel ", p_mech, -heat, abs(p_mech + heat)/heat
         call check(heat > 0.0_wp .and. abs(p_mech + heat) <= 1.0e-10_wp*heat, &
                    "traction power: mechanical power of the traction loads = -heat")
      end do
   end subroutine test_traction_power

   !> The balls' gyroscopic restraint (add_gyroscopic_restraint): on a ball orbiting at w_m
   !> with angular velocity w it adds J w_m (e_x x w); the moment does no work on the balls or
   !> races (power 0 to round-off), the contacts' moments still sum to zero, and it has the
   !> classical size J w_m w sin(beta) (Harris & Kotzalas) for the pitch beta of w.
   subroutine test_gyroscopic_restraint(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: l0, l1
      real(wp) :: p_mech, m_ref, w(3), w_m, r2, total_f(3), total_m(3), worst
      integer :: k, j

      st = base
      st%elements(1)%omega = st%elements(1)%omega + [300.0_wp, -800.0_wp, 1200.0_wp]
      call ball_bearing_loads(b, g, st, l0, error, cage=.false.)
      if (allocated(error)) return
      l1 = l0
      call add_gyroscopic_restraint(st, b%moments(1, BODY_ELEMENT), l1)
      p_mech = 0.0_wp
      worst = 0.0_wp
      do k = 1, size(st%elements)
         p_mech = p_mech + power_of(st%elements(k), l1%elements(k), l0%elements(k))
         associate (e => st%elements(k))
            r2 = e%position(2)**2 + e%position(3)**2
            w_m = (e%position(2)*e%velocity(3) - e%position(3)*e%velocity(2))/r2
            w = matmul(quat_matrix(e%attitude), e%omega)
            m_ref = b%moments(1, BODY_ELEMENT)*abs(w_m)*hypot(w(2), w(3))   ! J w_m |w| sin(beta)
         end associate
         worst = max(worst, abs(norm2(l1%elements(k)%moment - l0%elements(k)%moment) - m_ref)/m_ref)
      end do
      do j = 1, 2
         p_mech = p_mech + power_of(st%races(j), l1%races(j), l0%races(j))
      end do
      m_ref = b%moments(1, BODY_ELEMENT)*norm2(st%elements(1)%omega)*1000.0_wp
      write (*, "(a,es10.2,a,es10.2)") "gyroscopic restraint: power (W) ", p_mech, &
         ", worst |M_g| vs J w_m w sin(beta) ", worst
      call check(abs(p_mech) <= 1.0e-12_wp*m_ref, "gyroscopic restraint: no work on balls and races")
      call check(worst <= 1.0e-12_wp, "gyroscopic restraint: M_g = J w_m w sin(beta) on every ball")
      call contact_load_sums(b, st, l1, total_f, total_m)
      call check(norm2(total_f) < 1.0e-9_wp*maxval(l1%contacts%load), "gyroscopic restraint: forces sum to zero")
      call check(norm2(total_m) < 1.0e-9_wp*maxval(l1%contacts%load)*b%dm, &
                 "gyroscopic restraint: contact moments sum to zero")
   end subroutine test_gyroscopic_restraint

   !> Normal contact damping (ball_bearing_loads' damping): ball 1 moving at v along its outer
   !> contact normal approaches the outer race (and leaves the inner one); each contact j's
   !> normal force becomes max(Q_j + beta (1.5 Q_j / delta_j) (v . n_j), 0), so the ball's force
   !> changes by -sum_j (f_j - Q_j) n_j; the damping takes power out (force . velocity < 0);
   !> leaving fast, a contact's force is clamped at 0, never pulls.
   subroutine test_contact_damping(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      real(wp), parameter :: beta = 2.5e-6_wp
      real(wp) :: n(3), err(2), p
      type(ball_bearing_loads_t) :: l0
      integer :: icase

      call ball_bearing_loads(b, g, base, l0, error, traction=.false., cage=.false.)
      if (allocated(error)) return
      n = l0%contacts(1, 1)%normal                      ! ball centre -> outer contact
      do icase = 1, 2
         ! 1: approaching the outer race at 1 cm/s; 2: leaving it at 10 m/s (clamped)
         call damping_case(b, g, base, n, beta, merge(0.01_wp, -10.0_wp, icase == 1), err(icase), p)
         if (icase == 1) call check(p < 0.0_wp, "contact damping: it takes power out of the approaching ball")
      end do
      write (*, "(a,2es10.2)") "contact damping: force change vs max(Q + beta k v.n, 0), approaching and "// &
         "leaving (relative) ", err
      call check(err(1) < 1.0e-9_wp, "contact damping: the extra normal force is beta (1.5 Q / delta) d(delta)/dt")
      call check(err(2) < 1.0e-9_wp, "contact damping: a leaving contact's force is clamped at 0, never pulls")
   end subroutine test_contact_damping

   !> One case of test_contact_damping: ball 1 of state base moving at v (m/s) along n; rel =
   !> |change of its force - the expected change| / |expected|, power = change . velocity (W).
   subroutine damping_case(b, g, base, n, beta, v, rel, power)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      real(wp), intent(in) :: n(3), beta, v
      real(wp), intent(out) :: rel, power
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: lu, ld
      real(wp) :: expected(3), df(3), fj
      integer :: j
      st = base
      st%elements(1)%velocity = st%elements(1)%velocity + v*n
      call ball_bearing_loads(b, g, st, lu, error, traction=.false., cage=.false.)
      call ball_bearing_loads(b, g, st, ld, error, traction=.false., cage=.false., damping=beta)
      expected = 0.0_wp
      do j = 1, 2
         associate (c => lu%contacts(j, 1))
            fj = max(c%load + beta*1.5_wp*c%load/c%delta*dot_product(v*n, c%normal), 0.0_wp)
            expected = expected - (fj - c%load)*c%normal
         end associate
      end do
      df = ld%elements(1)%force - lu%elements(1)%force
      rel = norm2(df - expected)/max(norm2(expected), 1.0e-30_wp)
      power = dot_product(df, v*n)
   end subroutine damping_case


   !> Equations of motion at the step-0 state without traction: every ball accelerates
   !> towards the axis with its orbit's centripetal acceleration r w_m**2 and the inner
   !> race does not accelerate (the quasi-static equilibrium, eqs 65-72, seen from the
   !> inertial frame), to the equilibrium's linearisation order.
   subroutine test_motion_at_step0(b, g, s0, st)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_step0_t), intent(in) :: s0
      type(bearing_state_t), intent(in) :: st
      type(bearing_state_t) :: rates
      type(ball_bearing_loads_t) :: ld
      real(wp) :: worst, a_c, e_r(3), phi, tol
      integer :: k

      call ball_bearing_rates(b, g, st, rates, ld, error, traction=.false.)
      call check(.not. allocated(error), "equations of motion at the step-0 state")
      if (allocated(error)) return
      worst = 0.0_wp
      associate (e => s0%start%equilibrium, kin => s0%start%kinematics)
         tol = 2.0_wp*1.5_wp*(hypot(e%u(2), e%u(3))**2/g%groove_centre(2, 2))/minval([e%delta_o, e%delta_i])
         do k = 1, b%n_elements
            phi = e%azimuth(k)
            e_r = [0.0_wp, -sin(phi), cos(phi)]
            a_c = e%r(k)*kin(k)%orbital_speed**2
            ! normal loads + weight over the mass, less the weight's share
            worst = max(worst, norm2(rates%elements(k)%velocity - b%gravity + a_c*e_r)*b%mass(BODY_ELEMENT)/ &
                               maxval([e%q_o, e%q_i]))
            call check(all(rates%elements(k)%position == st%elements(k)%velocity), "ball position rate = velocity")
         end do
         write (*, "(a,2es10.2)") "step-0 motion: ball acceleration - centripetal (rel. to largest load), "// &
            "inner race acceleration (rel. to applied) ", worst, &
            norm2(rates%races(RACE_INNER)%velocity)*b%mass(BODY_INNER)/norm2(b%force)
         call check(worst < tol, "step-0 motion: balls accelerate centripetally (r w_m**2 towards the axis)")
         call check(norm2(rates%races(RACE_INNER)%velocity)*b%mass(BODY_INNER)/norm2(b%force) < tol, &
                    "step-0 motion: the inner race does not accelerate")
      end associate
      call check(all(rates%races(RACE_OUTER)%velocity == 0.0_wp) .and. all(rates%races(RACE_OUTER)%omega == 0.0_wp), &
                 "outer race fixed")
      call check(all(rates%races(RACE_INNER)%omega == 0.0_wp), "inner race turns at its prescribed speed")
   end subroutine test_motion_at_step0

   !> A free asymmetric body (no load) tumbling about a skewed axis: Euler's equations keep
   !> the inertial angular momentum R I omega constant, and the attitude rate is R [omega]x
   !> (central finite differences of R(q(t)) and of L(t) with the rates).
   subroutine test_free_body_rates()
      type(body_state_t) :: body, r, plus, minus
      type(body_load_t) :: none
      real(wp), parameter :: inertia(3) = [0.9_wp, 0.5_wp, 0.3_wp], dt = 1.0e-6_wp
      real(wp) :: l_plus(3), l_minus(3), rdot(3, 3), skew(3, 3), w(3)

      body%attitude = quat_from_rotation_vector([0.3_wp, -0.2_wp, 0.7_wp])
      body%omega = [3.0_wp, -5.0_wp, 2.0_wp]
      r = body_rates(body, none, 1.0_wp, inertia)
      plus = body
      minus = body
      plus%attitude = body%attitude + dt*r%attitude
      minus%attitude = body%attitude - dt*r%attitude
      plus%omega = body%omega + dt*r%omega
      minus%omega = body%omega - dt*r%omega
      l_plus = matmul(quat_matrix(plus%attitude), inertia*plus%omega)
      l_minus = matmul(quat_matrix(minus%attitude), inertia*minus%omega)
      call check(norm2(l_plus - l_minus)/(2.0_wp*dt) < 1.0e-6_wp*norm2(inertia*body%omega), &
                 "free body: inertial angular momentum constant (Euler's equations)")
      w = body%omega
      skew = reshape([0.0_wp, w(3), -w(2), -w(3), 0.0_wp, w(1), w(2), -w(1), 0.0_wp], [3, 3])
      rdot = (quat_matrix(plus%attitude) - quat_matrix(minus%attitude))/(2.0_wp*dt)
      call check(maxval(abs(rdot - matmul(quat_matrix(body%attitude), skew))) < 1.0e-6_wp*norm2(w), &
                 "free body: attitude rate dR/dt = R [omega]x")
   end subroutine test_free_body_rates

   !> team_join (adore_core_threads), the end of a parallel loop's work: in a region of 1, 2
   !> and 5 threads every thread but the first counts itself exactly once, and the first
   !> thread comes back (its wait is bounded) with the loop's results all in place.
   subroutine test_team_join()
      integer :: arrived, nt, k, done(20)
      integer :: teams(3) = [1, 2, 5]
      integer :: t
      do t = 1, size(teams)
         nt = teams(t)
         arrived = 0
         done = 0
         !$omp parallel num_threads(nt) default(shared) private(k)
         !$omp do schedule(dynamic, 1)
         do k = 1, size(done)
            done(k) = k
         end do
         !$omp end do nowait
         call team_join(arrived)
         !$omp end parallel
         call check(arrived == nt - 1 .and. all(done == [(k, k=1, size(done))]), &
                    "team_join: every thread but the first counted once on "//achar(48 + nt)//" threads")
      end do
   end subroutine test_team_join

   !> team_t's choice (adore_core_threads) with synthetic wall times: a run on 2 threads first
   !> measures TEAM_PROBE calls on 2 threads, then TEAM_PROBE on one, keeps the faster for
   !> TEAM_KEEP calls and measures again; a run on one thread never leaves it.
   subroutine test_team_choice()
      type(team_t) :: team
      integer :: k, n, seq(2*TEAM_PROBE + TEAM_KEEP + 1), cut, round, on_threads, kept
      real(wp) :: cost(2)
      logical :: ok
      ! 2 threads take 1.0 ms a call, one thread 1.6 ms: the threads are kept
      cost = [1.0e-3_wp, 1.6e-3_wp]
      do k = 1, size(seq)
         n = team_threads(team, 2)
         seq(k) = n
         call team_note(team, 2, cost(3 - n))
      end do
      call check(all(seq(1:TEAM_PROBE) == 2) .and. all(seq(TEAM_PROBE + 1:2*TEAM_PROBE) == 1) .and. &
                 all(seq(2*TEAM_PROBE + 1:2*TEAM_PROBE + TEAM_KEEP) == 2) .and. seq(size(seq)) == 2 .and. &
                 team%kept_many == 1 .and. team%kept_one == 0, &
                 "team: the faster threads kept for TEAM_KEEP calls after one window each, then measured again")
      ! the machine gets busy: 2 threads now take 2.0 ms a call, one thread 1.6 ms
      cost = [2.0e-3_wp, 1.6e-3_wp]
      do k = 1, 2*TEAM_PROBE + TEAM_KEEP
         n = team_threads(team, 2)
         seq(k) = n
         call team_note(team, 2, cost(3 - n))
      end do
      call check(all(seq(TEAM_PROBE:2*TEAM_PROBE - 1) == 1) .and. &
                 all(seq(2*TEAM_PROBE:2*TEAM_PROBE + TEAM_KEEP - 1) == 1) .and. team%kept_one == 1, &
                 "team: one thread kept while it is the faster")
      ! a busy machine: the threads take 5.0 ms a call, 3 times one thread's 1.6 ms.  Each
      ! window on the threads ends once it has cost TEAM_CUT times the last one-thread window
      ! (TEAM_PROBE calls of 1.6 ms), and one thread is kept twice as long each time, up to
      ! 2**TEAM_BACKOFF times TEAM_KEEP
      cost = [5.0e-3_wp, 1.6e-3_wp]
      cut = floor(TEAM_CUT*TEAM_PROBE*1.6_wp/5.0_wp) + 1
      team = team_t()
      ! the first measurement has no one-thread window to cut by: both windows whole
      do k = 1, 2*TEAM_PROBE + TEAM_KEEP
         call team_note(team, 2, cost(3 - team_threads(team, 2)))
      end do
      ok = team%kept_one == 1 .and. team%streak == 1 .and. team_threads(team, 2) == 2
      do round = 1, TEAM_BACKOFF + 2
         on_threads = 0
         do
            n = team_threads(team, 2)
            if (n == 1) exit
            on_threads = on_threads + 1
            call team_note(team, 2, cost(3 - n))
         end do
         kept = 0
         do while (team_threads(team, 2) == 1)
            kept = kept + 1
            call team_note(team, 2, cost(2))
         end do
         ok = ok .and. on_threads == cut .and. kept == TEAM_KEEP*2**min(round, TEAM_BACKOFF)
      end do
      call check(ok .and. team%kept_one == TEAM_BACKOFF + 3 .and. team%streak == TEAM_BACKOFF + 3, &
                 "team: on a busy machine the threads' windows end early and one thread is kept ever longer")
      ! the cores free again: the threads win their next window and the streak ends
      cost = [1.0e-3_wp, 1.6e-3_wp]
      do k = 1, 2*TEAM_PROBE
         call team_note(team, 2, cost(3 - team_threads(team, 2)))
      end do
      call check(team_threads(team, 2) == 2 .and. team%streak == 0, "team: the threads kept again once faster")
      team = team_t()
      call check(team_threads(team, 1) == 1, "team: a run on one thread stays on one")
   end subroutine test_team_choice

   !> The force assembly on several threads (ball_bearing_loads' threads; run option threads):
   !> at a state where every ball differs (each displaced and spinning off its start, the inner
   !> race shifted and misaligned, the cage turned) with 2-D traction, contact damping,
   !> rolling resistance and the cage contacts, the loads on 2 and 5 threads equal those on
   !> one bit for bit; with the lubricant near 0 K every contact's film fails and the error
   !> names ball 1 on any number of threads (a serial loop stops there first).  The balls'
   !> gyroscopic restraint taken inside the assembly (gyro_inertia, as the run takes it) equals
   !> add_gyroscopic_restraint after it on 1, 2 and 5 threads.
   subroutine test_threads_same_loads(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: l1, ln
      type(error_type), allocatable :: e1, en
      real(wp) :: cold(size(base%temperature))
      integer :: k, nt

      st = base
      do k = 1, size(st%elements)
         st%elements(k)%position = st%elements(k)%position + 1.0e-6_wp*[sin(1.0_wp*k), cos(2.0_wp*k), sin(3.0_wp*k)]
         st%elements(k)%velocity = st%elements(k)%velocity + 0.01_wp*[cos(1.0_wp*k), sin(2.0_wp*k), cos(3.0_wp*k)]
         st%elements(k)%omega = st%elements(k)%omega + 100.0_wp*[sin(5.0_wp*k), cos(7.0_wp*k), sin(11.0_wp*k)]
      end do
      st%races(RACE_INNER)%position = st%races(RACE_INNER)%position + [2.0e-6_wp, 1.0e-6_wp, -1.5e-6_wp]
      st%races(RACE_INNER)%attitude = quat_from_rotation_vector([1.0e-4_wp, 4.0e-4_wp, -3.0e-4_wp])
      st%cage%attitude = quat_from_rotation_vector([0.05_wp, 0.0_wp, 0.0_wp])
      call ball_bearing_loads(b, g, st, l1, e1, two_d=.true., damping=2.5e-6_wp, rolling=.true.)
      call check(.not. allocated(e1), "threads: force assembly on one thread")
      if (allocated(e1)) return
      call check(count(l1%contacts%load > 0.0_wp) > size(st%elements) .and. l1%damping_power /= 0.0_wp .and. &
                 any(l1%pockets%power > 0.0_wp), "threads: the state loads contacts, damping and pockets")
      do nt = 2, 5, 3
         call ball_bearing_loads(b, g, st, ln, en, two_d=.true., damping=2.5e-6_wp, rolling=.true., threads=nt)
         call check(.not. allocated(en), "threads: force assembly on several threads")
         if (allocated(en)) return
         call check(same_loads(l1, ln), "threads: the loads on 1 and "//achar(48 + nt)//" threads are the same bit for bit")
      end do
      ! the gyroscopic restraint inside the assembly (gyro_inertia: each ball's moment on its
      ! thread, the races' reactions after the balls) equals add_gyroscopic_restraint applied
      ! to the loads afterwards, bit for bit, on 1, 2 and 5 threads
      call add_gyroscopic_restraint(st, b%moments(1, BODY_ELEMENT), l1)
      do k = 1, 3
         nt = merge(1, merge(2, 5, k == 2), k == 1)      ! 1, 2, 5
         call ball_bearing_loads(b, g, st, ln, en, two_d=.true., damping=2.5e-6_wp, rolling=.true., threads=nt, &
                                 gyro_inertia=b%moments(1, BODY_ELEMENT))
         call check(.not. allocated(en), "threads: force assembly with the gyroscopic restraint")
         if (allocated(en)) return
         call check(same_loads(l1, ln), "threads: the gyroscopic restraint inside the assembly on "//achar(48 + nt)// &
                    " threads equals add_gyroscopic_restraint's bit for bit")
      end do
      cold = 1.0_wp
      call ball_bearing_loads(b, g, st, l1, e1, lubricant_temperature=cold)
      call ball_bearing_loads(b, g, st, ln, en, lubricant_temperature=cold, threads=5)
      call check(allocated(e1) .and. allocated(en), "threads: a lubricant at 1 K fails")
      if (.not. (allocated(e1) .and. allocated(en))) return
      call check(index(e1%message, "ball 1, outer race contact:") == 1 .and. e1%message == en%message, &
                 "threads: the error is ball 1's on any number of threads")

   end subroutine test_threads_same_loads

   !> Every body's loads, every contact's load, heat and traction force, every pocket's and
   !> land's force and power the same bit for bit in la and lb.
   logical function same_loads(la, lb) result(same)
      type(ball_bearing_loads_t), intent(in) :: la, lb
      integer :: k
      same = same_bits(la%cage%force, lb%cage%force) .and. same_bits(la%cage%moment, lb%cage%moment)
      do k = 1, 2
         same = same .and. same_bits(la%races(k)%force, lb%races(k)%force) .and. &
                same_bits(la%races(k)%moment, lb%races(k)%moment)
      end do
      do k = 1, size(la%elements)
         same = same .and. same_bits(la%elements(k)%force, lb%elements(k)%force) .and. &
                same_bits(la%elements(k)%moment, lb%elements(k)%moment) .and. &
                same_bits(la%contacts(:, k)%load, lb%contacts(:, k)%load) .and. &
                same_bits(la%heat(:, k), lb%heat(:, k)) .and. &
                same_bits(la%traction(:, k)%force, lb%traction(:, k)%force) .and. &
                same_bits(la%pockets(k)%force_cage, lb%pockets(k)%force_cage)
      end do
      same = same .and. same_bits([la%damping_power], [lb%damping_power]) .and. &
             same_bits(la%lands%power, lb%lands%power) .and. (la%abnormal .eqv. lb%abnormal)
   end function same_loads

   !> Whether x and y hold the same values bit for bit (tells -0 from 0; a NaN equals itself).
   pure logical function same_bits(x, y)
      real(wp), intent(in) :: x(:), y(:)
      same_bits = size(x) == size(y)
      if (same_bits) same_bits = all(transfer(x, [0_int64]) == transfer(y, [0_int64]))
   end function same_bits

end program test_forces
