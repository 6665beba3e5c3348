!> The quasi-static start of a ball bearing: mechanics and kinematics made consistent
!> (ADORE step 0; report sections 3.1 and 4.4.7).
!>
!> The centrifugal force of each ball depends on its orbital speed, and the orbital speed
!> (race control) depends on the contact angles: solve the equilibrium for the current
!> speeds, update the speeds from the contact angles, and repeat until the speeds change
!> by less than 1e-12 relative (race control) or 1e-7 (minimum dissipation, whose search
!> locates a minimum to ~sqrt(epsilon); it also stops when the speed change moves no
!> centrifugal force by more than MECH_TOL of the load scale).  The equilibrium is
!> warm-started from the previous pass.  Balls whose inner contact carries no load, or less
!> than UNLOADED_FRACTION of the largest, have no traction to set their speed: they orbit
!> with the cage, keep the spin-axis pitch of the last loaded ball and roll on the outer
!> race (unloaded_kinematics; docs/examples.md).
!> The report's start chooses the spin-axis pitch by minimum contact dissipation
!> (MIN_DISSIPATION, needs the traction curve); race control (CONTROL_OUTER,
!> CONTROL_INNER) is ADORE's kAngVel alternative.
module adore_quasistatic_ball_start
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error, input_error
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t, ball_qs_load_t, ball_qs_solution_t, &
                                                 solve_ball_equilibrium
   use adore_quasistatic_ball_kinematics, only: ball_kinematics_t, race_control_kinematics, &
                                                MIN_DISSIPATION, CONTROL_OUTER, CONTROL_INNER, &
                                                min_dissipation_kinematics, ehd_films_t
   use adore_tribology_traction_law, only: traction_law_t
   implicit none
   private

   public :: ball_start_t, solve_ball_start, is_loaded, start_contact_load
   public :: MIN_DISSIPATION, CONTROL_OUTER, CONTROL_INNER, START_NAMES, start_method_from_name, &
             start_method_title

   !> Run-option names of the start hypotheses (report 4.4.7), the default first, and their
   !> codes.
   character(len=*), parameter :: START_NAMES(3) = [character(len=18) :: &
                                  "dissipation", "outer-race-control", "inner-race-control"]
   integer, parameter :: START_CODES(3) = [MIN_DISSIPATION, CONTROL_OUTER, CONTROL_INNER]
   !> A ball whose inner contact load is at most this fraction of the largest inner contact
   !> load is carried by the cage: its speed is set by the cage, not by its own traction
   !> (unloaded_kinematics; docs/examples.md).  Not only an unloaded ball: a ball in the
   !> unloaded zone that touches the inner race lightly (a combined load with clearance at
   !> 60 000 rpm: 70 N against 9.9 kN, at a 61 deg inner contact angle) has its own rolling
   !> orbital speed far from the cage's (34 380 against 22 530 rpm), which its light contact
   !> cannot hold against the cage; started with it, it crossed its pocket clearance at
   !> 21 m/s and the run stopped ("abnormal cage contact"; docs/operating-points.md, "Balls
   !> the cage carries").  5 %: the measured grid cases need more than 1 % (0.7 % and 3.7 %
   !> balls both hit their pockets at 1 %)
   real(wp), parameter :: UNLOADED_FRACTION = 5.0e-2_wp
   !> The speeds and the equilibrium are also consistent when the last speed change moves
   !> no centrifugal force by more than this fraction of the load scale (1000 times below
   !> the print's 5 digits): lightly loaded balls have a flat dissipation minimum, located
   !> only to ~1e-4 of their speed, and their speeds need not settle further
   real(wp), parameter :: MECH_TOL = 1.0e-8_wp
   !> Minimum dissipation only: when the passes do not settle (ISO example 1 at 10 000 rpm,
   !> 1 N, +20 um fit: every ball preloaded alike by the fit, pitch 0, the orbital speeds
   !> moving by 1e-7 to 3e-4 relative from pass to pass without end; why the search's speed
   !> jitters there is not identified), the pass whose speed change moved the centrifugal
   !> forces least is taken if that change is at most this fraction of the equilibrium's
   !> largest contact load (100 times below the print's 4 digits); docs/operating-points.md,
   !> "Orbital speeds that jitter"
   real(wp), parameter :: JITTER_TOL = 1.0e-6_wp

   !> The consistent start: equilibrium plus the kinematics of every ball.
   type :: ball_start_t
      type(ball_qs_solution_t) :: equilibrium
      type(ball_kinematics_t), allocatable :: kinematics(:)
      integer :: passes = 0                !< mechanics/kinematics passes
      !> 0, or when the passes did not settle: the centrifugal change of the pass taken,
      !> relative to the largest contact load (at most JITTER_TOL)
      real(wp) :: jitter = 0.0_wp
   end type ball_start_t

contains

   !> The start hypothesis named `name` (one of START_NAMES, case as given): method =
   !> CONTROL_OUTER, CONTROL_INNER or MIN_DISSIPATION; input error naming the choices.
   subroutine start_method_from_name(name, method, error)
      character(len=*), intent(in) :: name
      integer, intent(out) :: method
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      method = MIN_DISSIPATION
      do k = 1, size(START_NAMES)
         if (trim(adjustl(name)) == trim(START_NAMES(k))) then
            method = START_CODES(k)
            return
         end if
      end do
      call input_error(error, "ball start: expected one of "//trim(START_NAMES(1))//", "// &
                       trim(START_NAMES(2))//", "//trim(START_NAMES(3))//", got '"//trim(name)//"'")
   end subroutine start_method_from_name

   !> The print's one-line description of start hypothesis `method` (upper case, as the
   !> echo's labels).
   pure function start_method_title(method) result(title)
      integer, intent(in) :: method
      character(len=64) :: title

      select case (method)
      case (CONTROL_OUTER)
         title = "OUTER RACE CONTROL (NO SPIN AT THE OUTER RACE CONTACT)"
      case (CONTROL_INNER)
         title = "INNER RACE CONTROL (NO SPIN AT THE INNER RACE CONTACT)"
      case default
         title = "MINIMUM CONTACT DISSIPATION (REPORT 4.4.7)"
      end select
   end function start_method_title

   !> Solve the coupled start for race speeds w_outer, w_inner (rad/s); control selects
   !> the kinematic hypothesis: CONTROL_OUTER, CONTROL_INNER (race control) or
   !> MIN_DISSIPATION (report 4.4.7; needs law, the RE/race traction law: the deck's curve or
   !> a traction-slip table).
   !> ehd(k): ball k's EHD films - minimum dissipation of the EHD traction (model 3)
   !> instead of the curve; guess: a previous start, whose speeds and pitches seed this one;
   !> centrifugal_tol: the consistency test on the centrifugal forces (default MECH_TOL; a tighter
   !> value checks the early exit, tests/test_examples.py).
   subroutine solve_ball_start(b, ld, w_outer, w_inner, control, start, error, law, ehd, guess, centrifugal_tol)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_load_t), intent(in) :: ld
      real(wp), intent(in) :: w_outer, w_inner
      integer, intent(in) :: control
      type(traction_law_t), intent(in), optional :: law
      type(ball_start_t), intent(out) :: start
      type(error_type), allocatable, intent(out) :: error
      type(ehd_films_t), intent(in), optional :: ehd(:)
      type(ball_start_t), intent(in), optional :: guess
      real(wp), intent(in), optional :: centrifugal_tol

      real(wp), allocatable :: speed(:), new_speed(:), best_speed(:)
      real(wp) :: d_i(2), d_o(2), change, previous, previous_speed, tol, fscale, mech, mtol, jitter, best_jitter
      type(ball_kinematics_t), allocatable :: best_kinematics(:)
      integer :: pass, k
      logical :: first
      logical, allocatable :: loaded(:)

      if (control == MIN_DISSIPATION .and. .not. present(law)) then
         call engine_error(error, "ball start: minimum dissipation needs the traction law")
         return
      end if
      ! a minimum is located to ~sqrt(epsilon) of its argument: looser consistency test
      tol = merge(1.0e-7_wp, 1.0e-12_wp, control == MIN_DISSIPATION)
      mtol = MECH_TOL
      if (present(centrifugal_tol)) mtol = centrifugal_tol
      allocate (speed(b%n_balls), new_speed(b%n_balls), start%kinematics(b%n_balls))
      if (w_outer == 0.0_wp .and. w_inner == 0.0_wp) then
         ! both races at rest: the static solution, balls at rest (no slip, no loss, no
         ! centrifugal force); there are no speeds to search for
         speed = 0.0_wp
         start%kinematics = ball_kinematics_t(ok=.true.)
         start%passes = 1
         call solve_ball_equilibrium(b, ld, speed, start%equilibrium, error)
         return
      end if
      ! first guess: the epicyclic speed of a ball at the pitch diameter and zero angles
      speed = 0.5_wp*(w_inner*(1.0_wp - b%d/b%dm) + w_outer*(1.0_wp + b%d/b%dm))
      if (present(guess)) then
         speed = guess%kinematics%orbital_speed
         start%kinematics = guess%kinematics
      end if
      best_jitter = huge(1.0_wp)
      do pass = 1, 50
         call solve_ball_equilibrium(b, ld, speed, start%equilibrium, error)
         if (allocated(error)) return
         if (pass == 1) then
            loaded = is_loaded(start%equilibrium%q_i)
         else
            loaded = stays_loaded(start%equilibrium%q_i, loaded)
         end if
         do k = 1, b%n_balls
            if (.not. loaded(k)) cycle
            d_o = start%equilibrium%n_o(:, k)
            d_i = start%equilibrium%n_i(:, k)
            if (control == MIN_DISSIPATION) then
               associate (e => start%equilibrium)
                  first = pass == 1 .and. .not. present(guess)
                  previous = start%kinematics(k)%pitch   ! later passes: search near it
                  previous_speed = start%kinematics(k)%spin_speed
                  if (present(ehd)) then
                     if (first) then
                        call min_dissipation_kinematics(b%d, e%r(k), d_o, d_i, w_outer, w_inner, &
                                                        [e%c_o(k)%semi_major, e%c_i(k)%semi_major], &
                                                        [e%q_o(k), e%q_i(k)], law, start%kinematics(k), error, &
                                                        ehd=ehd(k))
                     else
                        call min_dissipation_kinematics(b%d, e%r(k), d_o, d_i, w_outer, w_inner, &
                                                        [e%c_o(k)%semi_major, e%c_i(k)%semi_major], &
                                                        [e%q_o(k), e%q_i(k)], law, start%kinematics(k), error, &
                                                        previous, ehd(k), hint_speed=previous_speed)
                     end if
                  else if (first) then
                     call min_dissipation_kinematics(b%d, e%r(k), d_o, d_i, w_outer, w_inner, &
                                                     [e%c_o(k)%semi_major, e%c_i(k)%semi_major], &
                                                     [e%q_o(k), e%q_i(k)], law, start%kinematics(k), error)
                  else
                     call min_dissipation_kinematics(b%d, e%r(k), d_o, d_i, w_outer, w_inner, &
                                                     [e%c_o(k)%semi_major, e%c_i(k)%semi_major], &
                                                     [e%q_o(k), e%q_i(k)], law, start%kinematics(k), error, &
                                                     previous, hint_speed=previous_speed)
                  end if
               end associate
               if (allocated(error)) return
            else
               start%kinematics(k) = race_control_kinematics(b%d, start%equilibrium%r(k), d_o, d_i, &
                                                             w_outer, w_inner, control)
            end if
            if (.not. start%kinematics(k)%ok) then
               call engine_error(error, "ball start: race control kinematics has no solution")
               return
            end if
            new_speed(k) = start%kinematics(k)%orbital_speed
         end do
         call unloaded_kinematics(loaded, b, start%equilibrium, w_outer, start%kinematics)
         new_speed = start%kinematics%orbital_speed
         change = maxval(abs(new_speed - speed), mask=loaded)/max(maxval(abs(new_speed)), tiny(1.0_wp))
         ! what the speed change does to the mechanics: the change of the centrifugal
         ! forces relative to the load scale of the equilibrium
         fscale = max(norm2(ld%force), b%ball_mass*b%dm*maxval(abs(new_speed))**2, 1.0_wp)
         ! (minimum dissipation only: race control has no search jitter and settles to 1e-12)
         mech = huge(1.0_wp)
         if (control == MIN_DISSIPATION) &
            mech = maxval(b%ball_mass*start%equilibrium%r*abs(new_speed**2 - speed**2))/fscale
         if (control == MIN_DISSIPATION) then
            ! the same change against the equilibrium's own load scale (its largest contact)
            jitter = mech*fscale/max(fscale, start_contact_load(start))
            if (jitter < best_jitter) then
               best_jitter = jitter
               best_speed = new_speed
               best_kinematics = start%kinematics
            end if
         end if
         speed = new_speed
         start%passes = pass
         if (change <= tol .or. mech <= mtol) exit
      end do
      if (change > tol .and. mech > mtol) then
         if (.not. best_jitter <= JITTER_TOL) then
            call engine_error(error, "ball start: orbital speeds and equilibrium did not become consistent")
            return
         end if
         ! the passes jitter within JITTER_TOL: the least moving pass (documented fallback)
         speed = best_speed
         start%kinematics = best_kinematics
         start%jitter = best_jitter
      end if
      ! final equilibrium at the converged speeds
      call solve_ball_equilibrium(b, ld, speed, start%equilibrium, error)
   end subroutine solve_ball_start

   !> The largest race contact load (N) of the start s (outer or inner, any ball): the load
   !> scale of the time integration when it exceeds the applied load (adore_model_scales).
   pure function start_contact_load(s) result(q)
      type(ball_start_t), intent(in) :: s
      real(wp) :: q
      q = 0.0_wp
      if (allocated(s%equilibrium%q_o)) q = max(q, maxval(s%equilibrium%q_o, mask=s%equilibrium%q_o == s%equilibrium%q_o))
      if (allocated(s%equilibrium%q_i)) q = max(q, maxval(s%equilibrium%q_i, mask=s%equilibrium%q_i == s%equilibrium%q_i))
   end function start_contact_load

   !> The balls whose inner race contact carries load: more than UNLOADED_FRACTION of the
   !> largest inner contact load q_i (N).  Only these have a traction that sets their speed.
   !> With no inner contact loaded at all every ball counts as loaded (each then needs its
   !> own kinematics; the minimum-dissipation search reports a ball without any load).
   pure function is_loaded(q_i) result(loaded)
      real(wp), intent(in) :: q_i(:)
      logical :: loaded(size(q_i))
      loaded = q_i > UNLOADED_FRACTION*maxval(q_i)
      if (.not. any(loaded)) loaded = .true.
   end function is_loaded

   !> The loaded balls of a later pass (is_loaded with hysteresis): a ball the cage carried
   !> in the last pass counts as loaded again only above twice UNLOADED_FRACTION of the largest
   !> inner load q_i (N).  Without it a ball whose load sits at the threshold changed class
   !> from pass to pass (its speed with it) and the passes never settled (Appendix C at
   !> 20 000 rpm, 3 kN radial and 3 kN axial: "orbital speeds and equilibrium did not become
   !> consistent", the step-0 sweep of bench/sweep_bench.py).
   pure function stays_loaded(q_i, was_loaded) result(loaded)
      real(wp), intent(in) :: q_i(:)
      logical, intent(in) :: was_loaded(:)
      logical :: loaded(size(q_i))
      loaded = merge(q_i > UNLOADED_FRACTION*maxval(q_i), q_i > 2.0_wp*UNLOADED_FRACTION*maxval(q_i), was_loaded)
      if (.not. any(loaded)) loaded = .true.
   end function stays_loaded

   !> Kinematic state of the unloaded balls (the rule of docs/examples.md): an unloaded ball
   !> is carried by the cage, so its orbital speed w_m is the cage speed, the mean orbital
   !> speed of the loaded balls (rad/s); its spin axis keeps the pitch beta of its last
   !> loaded state, that of the nearest loaded ball behind it in the orbit direction (ball
   !> k - 1, k - 2, ..., cyclic, when the balls orbit towards increasing azimuth; k + 1, ...
   !> when they orbit the other way); its spin speed
   !> w_b makes it roll at the centre of the one contact that still carries load, the outer
   !> one pressed by the centrifugal force (the rolling equation of race_control_kinematics,
   !> j = o: the least dissipation there at the given w_m and beta).  Without an outer
   !> contact normal (degenerate) the spin speed is held too.  Loaded balls are left as they
   !> are; with no loaded ball nothing changes.
   pure subroutine unloaded_kinematics(loaded, b, e, w_outer, kin)
      logical, intent(in) :: loaded(:)
      type(ball_qs_bearing_t), intent(in) :: b
      type(ball_qs_solution_t), intent(in) :: e
      real(wp), intent(in) :: w_outer
      type(ball_kinematics_t), intent(inout) :: kin(:)
      real(wp) :: cage, beta, arm, r_c
      integer :: k, j, n, src, back

      n = size(loaded)
      if (all(loaded) .or. .not. any(loaded)) return
      cage = sum(kin%orbital_speed, mask=loaded)/count(loaded)
      ! "behind" in the orbit direction: lower azimuth when the balls orbit towards
      ! increasing azimuth (cage > 0), higher when they orbit the other way
      back = merge(-1, 1, cage >= 0.0_wp)
      do k = 1, n
         if (loaded(k)) cycle
         src = k
         do j = 1, n - 1
            src = modulo(k - 1 + back*j, n) + 1
            if (loaded(src)) exit
         end do
         beta = kin(src)%pitch
         kin(k)%orbital_speed = cage
         kin(k)%pitch = beta
         kin(k)%spin_speed = kin(src)%spin_speed
         arm = 0.5_wp*b%d*(cos(beta)*e%n_o(2, k) - sin(beta)*e%n_o(1, k))
         r_c = e%r(k) + 0.5_wp*b%d*e%n_o(2, k)
         if (abs(arm) > 0.0_wp) kin(k)%spin_speed = (w_outer - cage)*r_c/arm
         kin(k)%power = 0.0_wp
         kin(k)%ok = .true.
      end do
   end subroutine unloaded_kinematics

end module adore_quasistatic_ball_start
