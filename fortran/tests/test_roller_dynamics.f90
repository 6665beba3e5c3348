!> Engine unit tests of the roller bearing's dynamics (fortran/forces/roller_bearing.f90,
!> fortran/dynamics/roller_system.f90): independent checks only - symmetry, hand sums of the
!> slice forces' lever arms, the quasi-static solution, the gyroscopic closed form, energy
!> and momentum balances.  The comparison with the report's Appendix D print is in
!> tests/test_roller_dynamics.py.  The rates on several threads (run option threads) equal
!> those on one bit for bit.
program test_roller_dynamics
   use, intrinsic :: iso_fortran_env, only: int64
   use adore_test_support, only: check, finish, get_decks_dir
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t
   use adore_model_from_deck, only: read_bearing
   use adore_geometry_mounted, only: mount_geometry
   use adore_contact_line_slices, only: profile_drop
   use adore_tribology_traction_law, only: law_kappa
   use adore_quasistatic_roller_equilibrium, only: roller_qs_load_t, roller_qs_solution_t, solve_roller_equilibrium
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_forces_roller_bearing, only: roller_pose_t, race_pose_t, roller_loads_t, roller_loads
   use adore_dynamics_integrator, only: integrator_t
   use adore_dynamics_roller_system, only: roller_system_t, start_roller_dynamics, roller_pose, ROLLER_SIZE, &
                                           R_TILT, R_SKEW, R_PHI, RACE_OFFSET, CAGE_POS_OFFSET, CAGE_OFFSET, &
                                           CAGE_TILT_OFFSET, roller_unknown_name, R_SPIN, R_RDOT, roller_state_size
   use adore_model_condition, only: body_dof_t
   implicit none

   character(len=:), allocatable :: decks
   type(bearing_t) :: b
   type(roller_step0_t) :: s0
   type(error_type), allocatable :: error

   call get_decks_dir(decks)
   call read_bearing(decks//"/appendix_d_roller.inp", b, error)
   call check(.not. allocated(error), "Appendix D deck read")
   call solve_roller_step0(b, s0, error)
   call check(.not. allocated(error), "Appendix D step 0 solved")
   if (allocated(error)) call finish("roller dynamics")

   call test_tilted_race_moments()
   call test_gyroscopic_moment()
   call test_power_balance()
   call test_radial_load_stays_untilted()
   call test_averaged_loads_match_quasistatic()
   call test_held_cage_land_film()
   call test_free_cage_pockets()
   call test_free_cage_nutation()
   call test_tilted_cage_pocket_moment()
   call test_threads_same_rates()
   call test_unknown_names()

   call finish("roller dynamics")

contains

   !> test_unknown_names: roller_unknown_name of unknown i of 14 rollers (blank-padded).
   function rname(i) result(name)
      integer, intent(in) :: i
      character(len=80) :: name
      character(len=:), allocatable :: text
      call roller_unknown_name(14, i, text)
      name = text
   end function rname

   !> roller_unknown_name (the run note's forced-step diagnosis, issue #28) at the indices the
   !> equations of motion read: a roller's spin and radial velocity, the inner race's position
   !> z, the cage's angle, centre y and tilt y, and outside the vector.
   subroutine test_unknown_names()
      integer, parameter :: n = 14
      call check(rname(ROLLER_SIZE*2 + R_SPIN) == "roller 3's spin" .and. &
                 rname(R_RDOT) == "roller 1's radial velocity" .and. &
                 rname(ROLLER_SIZE*n + RACE_OFFSET + 3) == "the inner race's position z" .and. &
                 rname(ROLLER_SIZE*n + CAGE_OFFSET + 1) == "the cage's angle" .and. &
                 rname(ROLLER_SIZE*n + CAGE_POS_OFFSET + 1) == "the cage's centre y" .and. &
                 rname(ROLLER_SIZE*n + CAGE_TILT_OFFSET + 2) == "the cage's axis tilt y" .and. &
                 rname(roller_state_size(n)) == "the cage's angular velocity z" .and. &
                 rname(roller_state_size(n) + 1) == "unknown 173", &
                 "roller_unknown_name: the packed layout's names")
   end subroutine test_unknown_names

   !> The start's system (no pocket contacts when pockets is .false.).
   subroutine start(sys, it, y, pockets, cage_free)
      type(roller_system_t), intent(out) :: sys
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      logical, intent(in) :: pockets
      logical, intent(in), optional :: cage_free
      associate (e => s0%equilibrium)
         call start_roller_dynamics(b, mount_geometry(b, b%temperature, 2), s0%model, e%azimuth, e%r, e%tilt, &
                                    e%orbital_speed, s0%roller_spin, e%u, 0.0_wp, s0%cage%state%angular_speed, &
                                    sys, it, y, error, cage_free=cage_free)
      end associate
      call check(.not. allocated(error), "dynamics started")
      sys%model%pocket = pockets
   end subroutine start

   !> A race tilted by 2e-4 rad about y: roller 1 (azimuth 0, loaded) has slice loads growing
   !> along its axis; the skew moment on it equals the hand sum of the slice tractions' lever
   !> arms, sum w x t_t (t_t = kappa(|u|) q u_t/|u|, the slip by hand from the kinematic
   !> surface points), and the tilt moment the difference of the slice load moments M_i - M_o.
   !> Without the race tilt (and skew) the skew moment vanishes.
   subroutine test_tilted_race_moments()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:)
      type(roller_pose_t) :: p
      type(race_pose_t) :: a
      type(roller_loads_t) :: ld, ld0
      real(wp) :: hand_skew, hand_tilt, rho, u, w_o, w_i, kap, q
      integer :: i, j

      call start(sys, it, y, .false.)
      p = roller_pose(y, 1)
      a%position = y(ROLLER_SIZE*sys%n + RACE_OFFSET + 1:ROLLER_SIZE*sys%n + RACE_OFFSET + 3)
      call roller_loads(sys%model, p, a, ld0)
      call check(abs(ld0%moment(2)) < 1.0e-12_wp*ld0%load(1)*b%roller%roller_length, &
                 "aligned races: no skew moment on the loaded roller")
      sys%model%misalignment = [2.0e-4_wp, 0.0_wp]
      call roller_loads(sys%model, p, a, ld)
      call check(ld%c(2)%q(size(ld%c(2)%q)) /= ld%c(2)%q(1), "tilted race: slice loads vary along the roller")
      w_o = b%speed_outer - p%phidot
      w_i = b%speed_inner - p%phidot
      hand_skew = 0.0_wp
      hand_tilt = 0.0_wp
      do j = 1, 2
         do i = 1, size(ld%c(j)%x)
            q = ld%c(j)%q(i)
            if (q <= 0.0_wp) cycle
            rho = 0.5_wp*b%d - profile_drop(s0%model%profile, ld%c(j)%x(i))
            if (j == 1) then
               u = p%spin*rho - w_o*(p%r + rho)
            else
               u = -p%spin*rho - w_i*(p%r - rho)
            end if
            kap = law_kappa(b%race_traction, abs(u))
            hand_skew = hand_skew + ld%c(j)%weight(i)*ld%c(j)%x(i)*kap*q*sign(1.0_wp, u)
            hand_tilt = hand_tilt + merge(-1.0_wp, 1.0_wp, j == 1)*ld%c(j)%weight(i)*ld%c(j)%x(i)*q
         end do
      end do
      call check(abs(hand_skew) > 1.0e-6_wp, "tilted race: a skew moment appears")
      call check(abs(ld%moment(2) - hand_skew) <= 1.0e-9_wp*abs(hand_skew), &
                 "skew moment = hand sum of the slice tractions' lever arms")
      call check(abs(ld%moment(3) - hand_tilt) <= 1.0e-9_wp*abs(hand_tilt), "tilt moment = M_i - M_o of the slices")
      print "(a,es12.4,a,es12.4,a)", "  tilted race 2e-4 rad: skew moment ", ld%moment(2), " N m, tilt moment ", &
         ld%moment(3), " N m"
   end subroutine test_tilted_race_moments

   !> An unloaded roller (no contact) orbiting with a steady tilt gamma and the kinematics of
   !> the module header needs M_t = (I_a W_abs - I_t phidot) phidot gamma: with that moment
   !> applied (here: its absence read from the rates), d(omega_t)/dt = -M_t/I_t exactly.
   subroutine test_gyroscopic_moment()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: gam, w_abs, phidot, expected
      integer :: flag, k

      call start(sys, it, y, .false.)
      allocate (dydt(size(y)))
      gam = 1.0e-4_wp
      k = 5                         ! an unloaded roller: lift it off both races
      associate (v => y(ROLLER_SIZE*(k - 1) + 1:ROLLER_SIZE*k))
         v(2) = v(2) - 5.0e-6_wp    ! 2.4 um off the outer race, 2.9 um off the inner
         v(R_TILT) = gam
         v(10) = -v(6)*gam          ! steady tilt in the orbit frame
         phidot = v(6)
         w_abs = v(11)
      end associate
      sys%model%gravity = 0.0_wp
      call sys%eval(0.0_wp, y, dydt, flag)
      call check(sys%loads(k)%load(1) == 0.0_wp .and. sys%loads(k)%load(2) == 0.0_wp, "lifted roller is unloaded")
      call check(dydt(ROLLER_SIZE*(k - 1) + R_TILT) == 0.0_wp .and. dydt(ROLLER_SIZE*(k - 1) + R_SKEW) == 0.0_wp, &
                 "steady tilt: no tilt or skew rate")
      expected = -(sys%inertia(1)*w_abs - sys%inertia(2)*phidot)*phidot*gam/sys%inertia(2)
      call check(abs(dydt(ROLLER_SIZE*(k - 1) + 9)/sys%time_scale - expected) <= 1.0e-12_wp*abs(expected), &
                 "gyroscopic moment of the tilted orbiting roller (I_a W - I_t phidot) phidot gamma")
   end subroutine test_gyroscopic_moment

   !> Energy: at the start (no roller or race translation, aligned, no pockets, gravity or
   !> damping) the traction's dissipation (eq 4 by slices) equals the power the races' torques
   !> take from their drives minus the rate of the rollers' kinetic energy, computed from the
   !> equations of motion's rates: sum Omega_j T_j + sum dKE/dt + losses = 0.
   subroutine test_power_balance()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: ke_rate, race_power, loss, v(ROLLER_SIZE), d(ROLLER_SIZE)
      integer :: flag, k

      call start(sys, it, y, .false.)
      allocate (dydt(size(y)))
      sys%model%gravity = 0.0_wp
      sys%model%damping = 0.0_wp
      y(R_TILT:ROLLER_SIZE*sys%n:ROLLER_SIZE) = 0.0_wp
      y(10:ROLLER_SIZE*sys%n:ROLLER_SIZE) = 0.0_wp
      call sys%eval(0.0_wp, y, dydt, flag)
      dydt = dydt/sys%time_scale
      ke_rate = 0.0_wp
      race_power = 0.0_wp
      loss = 0.0_wp
      do k = 1, sys%n
         v = y(ROLLER_SIZE*(k - 1) + 1:ROLLER_SIZE*k)
         d = dydt(ROLLER_SIZE*(k - 1) + 1:ROLLER_SIZE*k)
         ke_rate = ke_rate + sys%model%mass*(v(5)*d(5) + v(4)*d(4) + v(2)*v(6)*(v(5)*v(6) + v(2)*d(6))) + &
                   sys%inertia(1)*v(11)*d(11) + sys%inertia(2)*(v(9)*d(9) + v(10)*d(10))
         race_power = race_power + sum([b%speed_outer, b%speed_inner]*sys%loads(k)%race_torque)
         loss = loss + sum(sys%loads(k)%power)
      end do
      print "(a,3es13.5,a)", "  power: races ", race_power, ke_rate, loss, " W (race drives, roller KE rate, loss)"
      call check(loss > 0.1_wp, "the start dissipates")
      call check(abs(race_power + ke_rate + loss) <= 1.0e-9_wp*(abs(race_power) + abs(ke_rate) + loss), &
                 "power balance: race work = roller kinetic energy rate + slice dissipation")
   end subroutine test_power_balance

   !> Pure radial load, aligned races: integrated over a quarter revolution of the cage the
   !> rollers stay untilted and unskewed (to round-off), and the axial momentum stays zero.
   subroutine test_radial_load_stays_untilted()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:)
      real(wp) :: t, t_end
      integer :: k

      call start(sys, it, y, .true.)
      t = 0.0_wp
      t_end = 0.25_wp*2.0_wp*pi/abs(s0%orbital_speed)/sys%time_scale
      do while (t < t_end .and. .not. allocated(error))
         call it%step(sys, t, y, error, t_limit=t_end)
      end do
      call check(.not. allocated(error), "quarter cage revolution integrated")
      do k = 1, sys%n
         call check(abs(y(ROLLER_SIZE*(k - 1) + R_TILT)) < 1.0e-12_wp .and. &
                    abs(y(ROLLER_SIZE*(k - 1) + R_SKEW)) < 1.0e-12_wp, "roller stays untilted and unskewed")
         call check(abs(y(ROLLER_SIZE*(k - 1) + 1)) < 1.0e-15_wp, "roller stays axially centred")
      end do
      print "(a,es10.3,a,es10.3,a)", "  radial load: largest tilt ", maxval(abs(y(R_TILT:ROLLER_SIZE*sys%n:ROLLER_SIZE))), &
         " rad, largest skew ", maxval(abs(y(R_SKEW:ROLLER_SIZE*sys%n:ROLLER_SIZE))), " rad"
   end subroutine test_radial_load_stays_untilted

   !> Time-averaged slice loads against the quasi-static solution at the same speeds: over
   !> the accepted steps of a run, the quasi-static equilibrium (adore_quasistatic_roller_
   !> equilibrium) of the rollers at the same orbital phase (the applied load turned by
   !> the mean roller phase, the rollers at their equal spacing) and orbital speeds; the
   !> time averages of every roller's outer and inner contact load agree within 2 % of the
   !> largest load.
   subroutine test_averaged_loads_match_quasistatic()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dyn(:, :), qs(:, :), w(:), dydt(:)
      type(roller_qs_load_t) :: ld
      type(roller_qs_solution_t) :: sol
      real(wp) :: t, t_end, t_avg, dt, alpha, t_last, worst
      integer :: k, n

      call start(sys, it, y, .true.)
      n = sys%n
      allocate (dyn(2, n), qs(2, n), w(n), dydt(size(y)))
      dyn = 0.0_wp
      qs = 0.0_wp
      t = 0.0_wp
      t_avg = 2.0_wp           ! let the start's transient settle (tau)
      t_end = t_avg + 0.5_wp*2.0_wp*pi/abs(s0%orbital_speed)/sys%time_scale
      t_last = 0.0_wp
      do while (t < t_end .and. .not. allocated(error))
         call it%step(sys, t, y, error, t_limit=t_end)
         if (t <= t_avg) then
            t_last = t
            cycle
         end if
         dt = t - t_last
         t_last = t
         ! the loads at the accepted state
         call sys%eval(t, y, dydt, k)
         alpha = sum(y(R_PHI:ROLLER_SIZE*n:ROLLER_SIZE) - s0%equilibrium%azimuth)/n
         ld%force(1) = b%force(1)
         ld%force(2:3) = [b%force(2)*cos(alpha) + b%force(3)*sin(alpha), -b%force(2)*sin(alpha) + b%force(3)*cos(alpha)]
         w = y(6:ROLLER_SIZE*n:ROLLER_SIZE)
         call solve_roller_equilibrium(s0%model, ld, w, sol, error)
         if (allocated(error)) exit
         do k = 1, n
            dyn(:, k) = dyn(:, k) + dt*sys%loads(k)%load
            qs(:, k) = qs(:, k) + dt*[sol%c_o(k)%load, sol%c_i(k)%load]
         end do
      end do
      call check(.not. allocated(error), "run and quasi-static solutions")
      worst = maxval(abs(dyn - qs))/maxval(qs)
      print "(a,f7.3,a)", "  time-averaged contact loads vs quasi-static: worst ", 100.0_wp*worst, " % of the largest"
      call check(worst < 0.02_wp, "time-averaged roller loads within 2 % of the quasi-static solution")
   end subroutine test_averaged_loads_match_quasistatic

   !> A held roller cage (free, zero velocity) at eccentricity ratio eps off its outer-race
   !> guide lands, the lands given a lubricant (Appendix D runs dry): each land's film force is
   !> the short (Ocvirk) bearing's closed form F_e = -eta w R L**3 eps**2/(c**2 (1 - eps**2)**2),
   !> F_t = pi eta w R L**3 eps/(4 c**2 (1 - eps**2)**1.5), w the cage speed (the outer race
   !> is at rest), at eps = 0.2, 0.5, 0.8 and two directions; with the pockets off the cage's
   !> acceleration is the lands' force over its mass plus gravity.
   subroutine test_held_cage_land_film()
      real(wp), parameter :: eta = 0.01_wp, eps_list(3) = [0.2_wp, 0.5_wp, 0.8_wp], dirs(2) = [0.0_wp, 2.0_wp]
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: e_e(3), e_t(3), f_e, f_t, w, c, fe_exp, ft_exp, total(3), worst, acc(2)
      integer :: flag, k, i, j, g0

      call start(sys, it, y, .false., cage_free=.true.)
      call check(.not. allocated(error), "free cage started")
      call check(size(sys%lands) == 2 .and. .not. any(sys%lands%race_is_journal), &
                 "Appendix D: two outer-race guide lands")
      sys%lands%viscosity = eta
      sys%lands%oil_layer = huge(1.0_wp)       ! flooded: the closed form's film
      allocate (dydt(size(y)))
      g0 = ROLLER_SIZE*sys%n + CAGE_POS_OFFSET
      w = y(ROLLER_SIZE*sys%n + CAGE_OFFSET + 2)
      worst = 0.0_wp
      do i = 1, size(eps_list)
         do j = 1, size(dirs)
            associate (ld => sys%lands(1))
               c = ld%clearance
               e_e = [0.0_wp, cos(dirs(j)), sin(dirs(j))]
               e_t = [0.0_wp, -e_e(3), e_e(2)]
               y(g0 + 1:g0 + 2) = eps_list(i)*c*e_e(2:3)
               y(g0 + 3:g0 + 4) = 0.0_wp
               call sys%eval(0.0_wp, y, dydt, flag)
               call check(flag == 0, "held cage evaluated")
               fe_exp = -eta*w*ld%radius*ld%width**3*eps_list(i)**2/(c**2*(1.0_wp - eps_list(i)**2)**2)
               ft_exp = pi*eta*w*ld%radius*ld%width**3*eps_list(i)/(4.0_wp*c**2*(1.0_wp - eps_list(i)**2)**1.5_wp)
            end associate
            total = 0.0_wp
            do k = 1, size(sys%lands)
               ! the journal is the cage: its film force is the land's hydro force
               f_e = dot_product(sys%land(k)%hydro_force, e_e)
               f_t = dot_product(sys%land(k)%hydro_force, e_t)
               worst = max(worst, abs(f_e - fe_exp)/abs(fe_exp), abs(abs(f_t) - ft_exp)/ft_exp)
               total = total + sys%land(k)%force_cage
            end do
            acc = dydt(g0 + 3:g0 + 4)/sys%time_scale
            call check(all(abs(acc - (total(2:3)/sys%cage_mass + sys%model%gravity(2:3))) <= &
                           1.0e-12_wp*(norm2(total)/sys%cage_mass + 10.0_wp)), &
                       "held cage: acceleration = land forces / mass + gravity")
         end do
      end do
      print "(a,es10.3)", "  held roller cage, land film vs Ocvirk closed form: worst relative error ", worst
      call check(worst < 1.0e-10_wp, "held roller cage: each land's film force = the short-bearing closed form")
   end subroutine test_held_cage_land_film

   !> The free cage's pockets: shifting the cage by d along a pocket's e_t changes that
   !> roller's pocket gaps by -+d (pocket frame through the cage centre); a roller pressed
   !> into a wall gives the cage the opposite force (action = reaction with the roller's
   !> pocket force) and the torque of that force about the cage centre.
   subroutine test_free_cage_pockets()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: gap0(2), d, e_t(3), psi
      integer :: flag, g0

      call start(sys, it, y, .true., cage_free=.true.)
      allocate (dydt(size(y)))
      g0 = ROLLER_SIZE*sys%n + CAGE_POS_OFFSET
      y(g0 + 1:g0 + 4) = 0.0_wp
      call sys%eval(0.0_wp, y, dydt, flag)
      gap0 = sys%loads(1)%pocket_gap
      psi = sys%pocket_azimuth(1) + y(ROLLER_SIZE*sys%n + CAGE_OFFSET + 1)
      e_t = [0.0_wp, -cos(psi), -sin(psi)]
      d = 1.0e-5_wp
      y(g0 + 1:g0 + 2) = d*e_t(2:3)
      call sys%eval(0.0_wp, y, dydt, flag)
      call check(abs(sys%loads(1)%pocket_gap(1) - (gap0(1) - d)) < 1.0e-15_wp .and. &
                 abs(sys%loads(1)%pocket_gap(2) - (gap0(2) + d)) < 1.0e-15_wp, &
                 "cage shifted along the pocket's e_t: the pocket gaps change by -+d")
      ! push the cage into roller 1 by 2 um beyond its gap on the -e_t wall (end 1)
      d = gap0(1) + 2.0e-6_wp
      y(g0 + 1:g0 + 2) = d*e_t(2:3)
      call sys%eval(0.0_wp, y, dydt, flag)
      call check(sys%loads(1)%pocket_load(1) > 0.0_wp, "cage pressed onto roller 1: pocket contact")
      print "(a,es11.4,a)", "  cage pressed 2 um onto roller 1: pocket force ", sys%loads(1)%pocket_load(1), " N"
      call check(abs(dot_product(sys%loads(1)%cage_force, e_t) + sys%loads(1)%pocket_load(1)) <= &
                 1.0e-12_wp*sys%loads(1)%pocket_load(1), "pocket force on the cage = -(force on the roller)")
   end subroutine test_free_cage_pockets

   !> The free cage's axial motion and tilt with nothing touching it (pockets off, the cage
   !> centred inside its dry lands, gravity off), started with a transverse angular velocity
   !> w0 about y and an axial velocity v0: the closed form of the torque-free symmetric top at
   !> small tilt - its transverse angular velocity turns at nu = I_a W_c / I_t,
   !> w = w0 (cos nu t, sin nu t), the axis a_y = (w0/nu)(1 - cos nu t), a_z = -(w0/nu) sin nu t,
   !> the transverse kinetic energy I_t |w|**2 / 2 and the spin W_c constant - and the centre
   !> moving axially at v0.  Over 2 ms (about 1.8 nutation periods).
   subroutine test_free_cage_nutation()
      real(wp), parameter :: w0 = 2.0_wp, v0 = 1.0e-3_wp
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:)
      real(wp) :: t, t_end, nu, wc, ts, amp, err_a, err_w, ke0, ke
      integer :: g0, t0, c0

      call start(sys, it, y, .false., cage_free=.true.)
      ! the rollers as Appendix D's Rec 3.3 holds them (no effect on the untouched cage)
      sys%constraints%elements = body_dof_t([.false., .true., .true.], [.true., .false., .false.])
      sys%model%gravity = 0.0_wp
      g0 = ROLLER_SIZE*sys%n + CAGE_POS_OFFSET
      t0 = ROLLER_SIZE*sys%n + CAGE_TILT_OFFSET
      c0 = ROLLER_SIZE*sys%n + CAGE_OFFSET
      y(g0 + 1:g0 + 4) = 0.0_wp
      y(t0 + 1:t0 + 6) = [0.0_wp, 0.0_wp, 0.0_wp, v0, w0, 0.0_wp]
      wc = y(c0 + 2)
      nu = sys%cage_inertia*wc/sys%cage_inertia_t
      amp = w0/nu
      ke0 = 0.5_wp*sys%cage_inertia_t*w0**2
      t = 0.0_wp
      t_end = 2.0e-3_wp/sys%time_scale
      do while (t < t_end .and. .not. allocated(error))
         call it%step(sys, t, y, error, t_limit=t_end)
      end do
      call check(.not. allocated(error), "free cage nutation integrated")
      ts = t*sys%time_scale
      err_a = maxval(abs(y(t0 + 2:t0 + 3) - amp*[1.0_wp - cos(nu*ts), -sin(nu*ts)]))/amp
      err_w = maxval(abs(y(t0 + 5:t0 + 6) - w0*[cos(nu*ts), sin(nu*ts)]))/w0
      ke = 0.5_wp*sys%cage_inertia_t*sum(y(t0 + 5:t0 + 6)**2)
      print "(a,f9.1,a,es9.2,a,es9.2,a,es9.2,a,es9.2)", "  free cage nutation: nu ", nu, " rad/s, tilt error ", &
         err_a, ", rate error ", err_w, ", energy drift ", abs(ke - ke0)/ke0, ", spin drift ", abs(y(c0 + 2) - wc)/wc
      call check(err_a < 1.0e-5_wp .and. err_w < 1.0e-5_wp, "free cage: nutation at I_a W_c / I_t (closed form)")
      call check(abs(ke - ke0) < 1.0e-6_wp*ke0, "free cage: transverse kinetic energy conserved")
      call check(abs(y(c0 + 2) - wc) <= 1.0e-12_wp*wc, "free cage: spin unchanged without torque")
      call check(abs(y(t0 + 1) - v0*ts) < 1.0e-9_wp*v0*ts .and. abs(y(t0 + 4) - v0) < 1.0e-12_wp, &
                 "free cage: axial motion at its start velocity")
   end subroutine test_free_cage_nutation

   !> A cage held tilted (axis (1, a_y, 0): a rotation a_y about z) in Appendix D's pockets,
   !> pocket friction off: roller 1's pocket (azimuth 0, e_r = +z) has its walls turned by
   !> beta_r = a_y about e_r, so both walls press the roller's ends over |x| > c/(2 a_y).  The
   !> moment on the cage about its centre along e_r is, by hand, the slice loads' axial lever
   !> arms plus the tilted walls' axial force at the pocket's half width,
   !> M_r = -sum |x_s| q_s + a_y (D/2) sum q_s, q_s = K (a_y |x_s| - c/2)**(10/9) w (Palmgren);
   !> it opposes the tilt; its axial component about the axis equals the cage torque; the
   !> cage's tilt rates take the sum of the pockets' moments.
   subroutine test_tilted_cage_pocket_moment()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: a_y, c, w, xs, delta, q, hand_m, hand_q, e_r(3), mom_sum(3), wy_rate
      integer :: flag, g0, t0, c0, i, k

      call start(sys, it, y, .true., cage_free=.true.)
      sys%model%pocket_friction = 0.0_wp
      allocate (dydt(size(y)))
      g0 = ROLLER_SIZE*sys%n + CAGE_POS_OFFSET
      t0 = ROLLER_SIZE*sys%n + CAGE_TILT_OFFSET
      c0 = ROLLER_SIZE*sys%n + CAGE_OFFSET
      y(g0 + 1:g0 + 4) = 0.0_wp
      y(c0 + 1) = 0.0_wp
      c = sys%model%pocket_clearance
      a_y = 2.0_wp*c/sys%model%pocket_length
      y(t0 + 1:t0 + 6) = [0.0_wp, a_y, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
      call check(abs(sys%pocket_azimuth(1)) < 1.0e-15_wp .and. abs(y(R_PHI)) < 1.0e-15_wp, "roller 1 at azimuth 0")
      call sys%eval(0.0_wp, y, dydt, flag)
      call check(flag == 0, "tilted cage evaluated")
      w = sys%model%pocket_length/8.0_wp
      hand_m = 0.0_wp
      hand_q = 0.0_wp
      do i = 1, 8
         xs = -0.5_wp*sys%model%pocket_length + (real(i, wp) - 0.5_wp)*w
         delta = a_y*abs(xs) - 0.5_wp*c
         if (delta <= 0.0_wp) cycle
         q = sys%model%pocket_k*delta**(10.0_wp/9.0_wp)*w
         hand_q = hand_q + q
         hand_m = hand_m - abs(xs)*q + a_y*0.5_wp*sys%model%qs%d*q
      end do
      e_r = [0.0_wp, 0.0_wp, 1.0_wp]
      associate (ld => sys%loads(1))
         print "(a,es11.4,a,es11.4,a,es11.4,a)", "  cage tilted ", a_y, " rad: roller 1's pocket moment on the cage ", &
            dot_product(ld%cage_moment, e_r), " N m (hand ", hand_m, " N m)"
         call check(abs(sum(ld%pocket_load) - hand_q) <= 1.0e-12_wp*hand_q .and. &
                    abs(ld%pocket_load(1) - ld%pocket_load(2)) <= 1.0e-12_wp*hand_q, &
                    "tilted cage: both walls press roller 1 with the hand slice loads")
         call check(abs(dot_product(ld%cage_moment, e_r) - hand_m) <= 1.0e-10_wp*abs(hand_m) .and. hand_m < 0.0_wp, &
                    "tilted cage: pocket moment on the cage = the slice loads' lever arms (hand), against the tilt")
         call check(abs(ld%cage_moment(1) - ld%cage_torque) <= 1.0e-12_wp*(abs(ld%cage_torque) + abs(hand_m)), &
                    "tilted cage: the pocket moment's axial part is the cage torque")
      end associate
      mom_sum = 0.0_wp
      do k = 1, sys%n
         mom_sum = mom_sum + sys%loads(k)%cage_moment
      end do
      ! no land contact (centred cage, dry): w_z' = M_z / I_t (w = 0), against the tilt
      wy_rate = dydt(t0 + 6)/sys%time_scale
      call check(abs(wy_rate - mom_sum(3)/sys%cage_inertia_t) <= 1.0e-12_wp*abs(mom_sum(3)/sys%cage_inertia_t) &
                 .and. mom_sum(3) < 0.0_wp, "tilted cage: transverse angular acceleration = pocket moments / I_t")
   end subroutine test_tilted_cage_pocket_moment

   !> The equations of motion on several threads (roller_system_t%threads; run option
   !> threads): at a state where every roller differs (its radius, tilt, skew, axial position
   !> and rates off the start's) with a free, displaced cage, the rates and every roller's
   !> loads on 2 and 5 threads equal those on one bit for bit.
   subroutine test_threads_same_rates()
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), d1(:), dn(:)
      integer :: flag, k, nt, i0
      logical :: same
      real(wp), allocatable :: f1(:), fn(:)

      call start(sys, it, y, .true., cage_free=.true.)
      if (allocated(error)) return
      do k = 1, sys%n
         i0 = ROLLER_SIZE*(k - 1)
         y(i0 + 1) = y(i0 + 1) + 2.0e-6_wp*sin(1.0_wp*k)
         y(i0 + 2) = y(i0 + 2) + 1.0e-6_wp*cos(2.0_wp*k)
         y(i0 + R_TILT) = 1.0e-4_wp*sin(3.0_wp*k)
         y(i0 + R_SKEW) = 1.0e-4_wp*cos(5.0_wp*k)
         y(i0 + 5) = 1.0e-3_wp*sin(7.0_wp*k)
      end do
      y(ROLLER_SIZE*sys%n + CAGE_POS_OFFSET + 1:ROLLER_SIZE*sys%n + CAGE_POS_OFFSET + 2) = [3.0e-6_wp, -2.0e-6_wp]
      ! the cage turned by 0.6 of its pockets' play at the pitch radius: every pocket pushes
      y(ROLLER_SIZE*sys%n + CAGE_OFFSET + 1) = y(ROLLER_SIZE*sys%n + CAGE_OFFSET + 1) + &
                                               0.6_wp*sys%model%pocket_clearance/y(2)
      allocate (d1(size(y)), dn(size(y)))
      call sys%eval(0.0_wp, y, d1, flag)
      f1 = [(sys%loads(k)%force, sys%loads(k)%moment, sys%loads(k)%race_force(:, 2), k=1, sys%n)]
      call check(count(sys%loads%cage_torque /= 0.0_wp) > sys%n/2, "threads: the rollers load their pockets")
      do nt = 2, 5, 3
         sys%threads = nt
         call sys%eval(0.0_wp, y, dn, flag)
         fn = [(sys%loads(k)%force, sys%loads(k)%moment, sys%loads(k)%race_force(:, 2), k=1, sys%n)]
         same = all(transfer(d1, [0_int64]) == transfer(dn, [0_int64])) .and. &
                all(transfer(f1, [0_int64]) == transfer(fn, [0_int64]))
         call check(same, "threads: the rates on 1 and "//achar(48 + nt)//" threads are the same bit for bit")
      end do
   end subroutine test_threads_same_rates

end program test_roller_dynamics
