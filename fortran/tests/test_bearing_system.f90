!> A toy bearing kind for the bearing-system seam (issue #24): a mass on a spring, x'' = -k x
!> with k = the condition's force(1) (N/m, unit mass), in seconds (time scale 1).  It plugs
!> into the run's time loop with no edit to it; its events record their times and, when
!> asked, change the condition (the stiffness) through set_condition.
module adore_test_toy_kind
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_dynamics_integrator, only: integrator_t, integrator_settings_t, DERIV_OK
   use adore_bearings_system, only: bearing_system_t
   use adore_model_condition, only: operating_condition_t
   use adore_output_run_history, only: run_history_t
   implicit none
   private

   public :: toy_kind_t

   type, extends(bearing_system_t) :: toy_kind_t
      real(wp) :: stiffness = 1.0_wp          !< k (1/s**2) in use by eval
      real(wp) :: x(2) = 0.0_wp               !< last evaluated state
      integer :: n_events = 0
      real(wp) :: event_times(16) = 0.0_wp
      !> at event number change_at, the condition's stiffness becomes new_stiffness
      integer :: change_at = 0
      real(wp) :: new_stiffness = 1.0_wp
   contains
      procedure :: eval => toy_eval
      procedure :: solve_start => toy_solve_start
      procedure :: write_start => toy_write_start
      procedure :: run_note => toy_note
      procedure :: dynamic_steps => toy_steps
      procedure :: start_dynamics => toy_start_dynamics
      procedure :: n_values => toy_n_values
      procedure :: averaged_values => toy_values
      procedure :: write_step => toy_write_step
      procedure :: new_history => toy_new_history
      procedure :: record_row => toy_record_row
      procedure :: mount => toy_mount
      procedure :: on_event => toy_on_event
   end type toy_kind_t

contains

   subroutine toy_eval(self, t, y, dydt, flag)
      class(toy_kind_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      dydt = [y(2), -self%stiffness*y(1)] + 0.0_wp*t
      self%x = y
      flag = DERIV_OK
   end subroutine toy_eval

   subroutine toy_solve_start(self, error)
      class(toy_kind_t), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
      self%condition%force(1) = 1.0_wp
      self%stiffness = 1.0_wp
      if (.false.) allocate (error)
   end subroutine toy_solve_start

   subroutine toy_write_start(self, unit)
      class(toy_kind_t), intent(in) :: self
      integer, intent(in) :: unit
      write (unit, "(a,es24.16)") "TOY STEP 0 K = ", self%stiffness
   end subroutine toy_write_start

   subroutine toy_note(self, n_steps, text)
      class(toy_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      text = ""
      if (n_steps > 0 .and. self%stiffness > 0.0_wp) text = "toy"
   end subroutine toy_note

   integer function toy_steps(self)
      class(toy_kind_t), intent(in) :: self
      toy_steps = self%options%steps
   end function toy_steps

   subroutine toy_start_dynamics(self, it, y, error)
      class(toy_kind_t), intent(inout) :: self
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      y = [1.0_wp, 0.0_wp]
      self%time_scale = 1.0_wp
      call it%init(2, integrator_settings_t(int_method=5, h_initial=0.05_wp, h_min=1.0e-8_wp, h_max=0.05_wp, &
                                            error_limit=1.0e-10_wp), error)
   end subroutine toy_start_dynamics

   integer function toy_n_values(self)
      class(toy_kind_t), intent(in) :: self
      toy_n_values = 1 + 0*self%n_events
   end function toy_n_values

   !> The spring energy per unit mass.
   subroutine toy_values(self, v)
      class(toy_kind_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      v(1) = 0.5_wp*(self%x(2)**2 + self%stiffness*self%x(1)**2)
   end subroutine toy_values

   subroutine toy_write_step(self, unit, step, t, mean)
      class(toy_kind_t), intent(in) :: self
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: t, mean(:)
      write (unit, "(a,i0,3es24.16)") "TOY STEP ", step, t, self%x(1), mean(1)
   end subroutine toy_write_step

   subroutine toy_new_history(self, h, n_steps, error)
      class(toy_kind_t), intent(in) :: self
      type(run_history_t), intent(out) :: h
      integer, intent(in) :: n_steps
      type(error_type), allocatable, intent(out) :: error
      allocate (h%names(3), h%values(n_steps + 2 + 0*self%n_events, 3))
      h%names = [character(len=len(h%names)) :: "time_s", "step", "x"]
      if (.false.) allocate (error)
   end subroutine toy_new_history

   subroutine toy_record_row(self, h, step, t, mean)
      class(toy_kind_t), intent(in) :: self
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: t, mean(:)
      if (h%rows >= size(h%values, 1) .or. size(mean) < 1) return
      h%rows = h%rows + 1
      h%values(h%rows, :) = [t, real(step, wp), self%x(1)]
   end subroutine toy_record_row

   !> The condition's stiffness in use.
   subroutine toy_mount(self, y, error)
      class(toy_kind_t), intent(inout) :: self
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      self%stiffness = self%condition%force(1)
      if (.false.) y = 0.0_wp
      if (.false.) allocate (error)
   end subroutine toy_mount

   subroutine toy_on_event(self, time, it, y, error)
      class(toy_kind_t), intent(inout) :: self
      real(wp), intent(in) :: time
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      type(operating_condition_t) :: c
      self%n_events = self%n_events + 1
      self%event_times(min(self%n_events, size(self%event_times))) = time
      if (self%n_events == self%change_at) then
         c = self%condition
         c%force(1) = self%new_stiffness
         call self%set_condition(c, it, y, error)
      end if
   end subroutine toy_on_event

end module adore_test_toy_kind

!> The bearing-system seam (issue #24): a toy kind through the run's time loop (events,
!> a condition change), and the ball kind's condition change on Appendix C (the new mounted
!> geometry used from the next stage on, no stale first-same-as-last stage; an unchanged
!> condition changes nothing).
program test_bearing_system
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_test_support, only: check, finish, get_decks_dir
   use adore_model_bearing, only: bearing_t, TEMP_OUTER, BODY_INNER
   use adore_model_from_deck, only: read_bearing
   use adore_model_run_options, only: run_options_t, set_run_option, run_options_from_text
   use adore_model_condition, only: operating_condition_t
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_thermal_distortion, only: distorted_bearing
   use adore_state_bearing_state, only: bearing_state_t, unpack_state, RACE_INNER
   use adore_dynamics_integrator, only: integrator_t, integrator_settings_t, DERIV_OK
   use adore_bearings_system, only: bearing_system_t
   use adore_bearings_select, only: new_bearing_system
   use adore_bearings_ball, only: ball_kind_t
   use adore_bearings_ball_thermal, only: THERMAL_GEOMETRY, location_weights, heat_by_location, ball_thermal_t, &
                                          ball_thermal_accumulate
   use adore_thermal_network, only: thermal_heat_t, new_thermal_heat
   use adore_core_constants, only: pi
   use adore_output_run_history, only: run_history_t
   use adore_driver_time_loop, only: run_time_loop
   use adore_test_toy_kind, only: toy_kind_t
   implicit none

   call test_toy_kind_through_the_time_loop()
   call test_toy_events_and_condition_change()
   call test_run_options_text()
   call test_ball_condition_change()
   call test_heat_by_location()
   call test_ball_thermal_run()
   call finish("bearing system")

contains

   !> The toy runs 40 steps of 0.05 s through run_time_loop: x(t) = cos(t) within 1e-8, every
   !> step printed (print interval 1) and recorded, the termination line written.
   subroutine test_toy_kind_through_the_time_loop()
      type(toy_kind_t) :: toy
      type(integrator_t) :: it
      type(run_history_t) :: h
      type(error_type), allocatable :: error
      real(wp), allocatable :: y(:)
      character(len=:), allocatable :: incomplete
      character(len=200) :: line
      integer :: unit, n_lines, n_steps_printed, stat

      toy%options%steps = 40
      toy%bearing%controls%print_interval = 1
      call toy%solve_start(error)
      call toy%start_dynamics(it, y, error)
      call check(.not. allocated(error), "toy: start")
      call toy%new_history(h, toy%dynamic_steps(), error)
      open (newunit=unit, status="scratch", action="readwrite")
      call run_time_loop(unit, toy, it, y, toy%dynamic_steps(), h, incomplete, error)
      call check(.not. allocated(error), "toy: the time loop runs a kind it does not know")
      call check(h%rows == 41, "toy: a history row at step 0 and every step")
      call check(h%values(41, 1) > 0.1_wp, "toy: the run moves on")
      call check(abs(y(1) - cos(h%values(41, 1))) < 1.0e-8_wp, "toy: x(t) = cos(t) at the last step")
      call check(h%values(41, 3) == y(1), "toy: the last row is the last state")
      rewind (unit)
      n_lines = 0
      n_steps_printed = 0
      do
         read (unit, "(a)", iostat=stat) line
         if (stat /= 0) exit
         n_lines = n_lines + 1
         if (index(line, "TOY STEP ") == 1) n_steps_printed = n_steps_printed + 1
      end do
      close (unit)
      call check(n_steps_printed == 40, "toy: every step printed by the kind's write_step")
      call check(len(incomplete) == 0, "toy: the run completed")
   end subroutine test_toy_kind_through_the_time_loop

   !> Events every 0.3 s from 0.25 s land steps exactly on their times; at the third event
   !> (0.85 s) the stiffness becomes 4 through set_condition, and from then on the solution
   !> is the analytic one of the new spring (x = A cos(2 (t - t3)) + B/2 sin(2 (t - t3))).
   subroutine test_toy_events_and_condition_change()
      type(toy_kind_t) :: toy
      type(integrator_t) :: it
      type(run_history_t) :: h
      type(error_type), allocatable :: error
      real(wp), allocatable :: y(:)
      character(len=:), allocatable :: incomplete
      real(wp) :: t3, a, b, t_end
      integer :: unit, k

      toy%options%steps = 150
      toy%event_start = 0.25_wp
      toy%event_period = 0.3_wp
      toy%change_at = 3
      toy%new_stiffness = 4.0_wp
      call toy%solve_start(error)
      call toy%start_dynamics(it, y, error)
      call toy%new_history(h, 200, error)
      open (newunit=unit, status="scratch", action="readwrite")
      call run_time_loop(unit, toy, it, y, toy%dynamic_steps(), h, incomplete, error)
      close (unit)
      call check(.not. allocated(error), "events: the run completes")
      call check(toy%n_events >= 5, "events: at least five events")
      call check(toy%event_times(3) == 0.85_wp .or. abs(toy%event_times(3) - 0.85_wp) < 1.0e-12_wp, &
                 "events: the change at 0.85 s")
      do k = 1, min(toy%n_events, 5)
         call check(abs(toy%event_times(k) - (0.25_wp + 0.3_wp*(k - 1))) < 1.0e-12_wp, &
                    "events: event at its time exactly")
      end do
      call check(toy%stiffness == 4.0_wp .and. toy%condition%force(1) == 4.0_wp, "events: the new condition is in use")
      ! the analytic solution: cos(t) up to t3, then the stiffer spring from that state
      t3 = 0.85_wp
      a = cos(t3)
      b = -sin(t3)
      t_end = h%values(h%rows, 1)
      call check(t_end > t3 + 0.3_wp, "events: the run goes on past the change")
      call check(abs(y(1) - (a*cos(2.0_wp*(t_end - t3)) + b/2.0_wp*sin(2.0_wp*(t_end - t3)))) < 1.0e-8_wp, &
                 "events: after the change the solution is the new spring's (no stale stage)")
   end subroutine test_toy_events_and_condition_change

   !> The run options' text form: every row of the table settable, bad lines all reported.
   subroutine test_run_options_text()
      type(run_options_t) :: o
      type(error_type), allocatable :: error
      call run_options_from_text("steps=12"//new_line("a")//"substeps=3"//new_line("a")//"ball_start=outer-race-control"// &
                                 new_line("a")//"moment_equilibrium=true"//new_line("a")//"traction_2d=false"// &
                                 new_line("a")//"history_element=4"//new_line("a")//"traction_table=t.txt", o, error)
      call check(.not. allocated(error), "options: the text form is read")
      call check(o%steps == 12 .and. o%substeps == 3 .and. o%history_element == 4, "options: integers")
      call check(trim(o%ball_start) == "outer-race-control" .and. trim(o%traction_table) == "t.txt", "options: texts")
      call check(o%moment_equilibrium .and. .not. o%traction_2d, "options: flags")
      call set_run_option(o, "traction-1d", "true", error)
      call check(.not. allocated(error) .and. .not. o%traction_2d, "options: the off-flag spelling")
      call run_options_from_text("substeps=0"//new_line("a")//"colour=red"//new_line("a")//"steps", o, error)
      call check(allocated(error), "options: bad lines are an error")
      if (allocated(error)) then
         call check(index(error%message, "substeps") > 0 .and. index(error%message, "colour") > 0 .and. &
                    index(error%message, "'steps'") > 0, "options: every bad line named in one error")
      end if
   end subroutine test_run_options_text

   !> The ball kind hands the integrator its equations' border shares (the arrowhead
   !> Jacobian's border rows C_b, docs/integrator.md "The arrowhead"): after a step they are
   !> available, not all zero, and those of ball_system_t's own border_shares bit for bit
   !> (before session 18 the kind did not forward them and every run had C_b = 0).
   subroutine check_border_shares_forwarded(sys, n)
      class(bearing_system_t), intent(in) :: sys
      integer, intent(in) :: n
      real(wp), allocatable :: s_kind(:, :), s_eom(:, :)
      logical :: ok_kind, ok_eom
      select type (sys)
      type is (ball_kind_t)
         allocate (s_kind(size(sys%eom%jacobian_border), n), s_eom(size(sys%eom%jacobian_border), n))
         s_kind = 0.0_wp
         call sys%border_shares(s_kind, ok_kind)
         call sys%eom%border_shares(s_eom, ok_eom)
         call check(ok_kind .and. ok_eom, "ball: the kind's border shares available to the integrator")
         call check(all(s_kind == s_eom) .and. any(s_kind /= 0.0_wp), &
                    "ball: the kind's border shares are its equations' (nonzero)")
      class default
         call check(.false., "ball: border shares of the ball kind")
      end select
   end subroutine check_border_shares_forwarded

   !> Appendix C: after 20 steps the outer race gets 30 K warmer through set_condition.  The
   !> system is mounted at the new temperatures (geometry bit for bit mount_geometry's, the
   !> state's temperatures in y), the integrator restarted: its next step equals, bit for bit,
   !> the step of a brand-new integrator (no cached stage at all) from the same state and step
   !> size, and differs from a step that kept the stale first stage.  An unchanged condition
   !> changes nothing: the following steps are bit for bit those of a copy not told.
   subroutine test_ball_condition_change()
      class(bearing_system_t), allocatable :: sys, stale, untold
      type(integrator_t) :: it, it_stale, it_untold
      type(run_options_t) :: opts
      type(bearing_t) :: b
      type(error_type), allocatable :: error
      type(operating_condition_t) :: c
      type(mounted_geometry_t) :: g, g0
      type(bearing_state_t) :: s
      real(wp), allocatable :: y(:), y_stale(:), y_untold(:)
      real(wp) :: t, t_stale, t_untold, h, p_inner(3), v_inner(3)
      character(len=:), allocatable :: decks
      integer :: i, calls

      call get_decks_dir(decks)
      call read_bearing(decks//"/appendix_c_ball.inp", b, error)
      call check(.not. allocated(error), "ball: read Appendix C")
      if (allocated(error)) return
      opts%steps = 30
      call new_bearing_system(b, opts, sys, error)
      call check(.not. allocated(error), "ball: the kind picked by the deck")
      select type (sys)
      type is (ball_kind_t)
      class default
         call check(.false., "ball: Rec 3.2 = 1 gives the ball kind")
      end select
      call sys%solve_start(error)
      call sys%start_dynamics(it, y, error)
      call check(.not. allocated(error), "ball: start")
      if (allocated(error)) return
      t = 0.0_wp
      do i = 1, 20
         call it%step(sys, t, y, error)
      end do
      call check(.not. allocated(error), "ball: 20 steps")
      call check_border_shares_forwarded(sys, b%n_elements)

      ! an unchanged condition: nothing happens (no restart, no extra evaluation)
      allocate (untold, source=sys)
      it_untold = it
      y_untold = y
      t_untold = t
      calls = it%stats%derivative_calls
      call sys%set_condition(sys%condition, it, y, error)
      call check(it%stats%derivative_calls == calls .and. it%fsal_valid, "ball: unchanged condition, no restart")
      do i = 1, 3
         call it%step(sys, t, y, error)
         call it_untold%step(untold, t_untold, y_untold, error)
      end do
      call check(all(y == y_untold) .and. t == t_untold, "ball: unchanged condition, the same steps bit for bit")

      ! the change: the outer race 30 K warmer
      c = sys%condition
      c%temperature(TEMP_OUTER) = c%temperature(TEMP_OUTER) + 30.0_wp
      c%geometry_temperature = c%temperature          ! the geometry follows (ADRC2)
      h = it%h_next
      call sys%set_condition(c, it, y, error)
      call check(.not. allocated(error), "ball: condition changed")
      call check(.not. it%fsal_valid, "ball: the integrator's cached stage dropped")
      select type (sys)
      type is (ball_kind_t)
         g = mount_geometry(distorted_bearing(b, c%temperature), c%temperature)
         call check(all(sys%eom%geometry%groove_centre == g%groove_centre) .and. &
                    sys%eom%geometry%element_diameter == g%element_diameter, &
                    "ball: the equations of motion use the geometry mounted at the new temperatures")
         g0 = mount_geometry(b, b%temperature)
         call check(any(sys%eom%geometry%groove_centre /= g0%groove_centre), &
                    "ball: 30 K on the outer race moves its groove")
         s = sys%eom%state
         call unpack_state(y, t, s)
         call check(all(s%temperature == c%temperature), "ball: the state's temperatures are the new ones")
      end select
      call compare_with_a_new_integrator(sys, it, t, y, h, "temperature")

      ! a change the state vector does not show (the applied load): the restart is what
      ! keeps the cached stage out; a copy that kept it steps elsewhere
      allocate (stale, source=sys)
      it_stale = it
      y_stale = y
      t_stale = t
      c%force(1) = c%force(1) + 200.0_wp
      h = it%h_next
      call sys%set_condition(c, it, y, error)
      call check(.not. allocated(error), "ball: load changed")
      stale%condition = c
      call stale%mount(y_stale, error)
      call it_stale%step(stale, t_stale, y_stale, error)
      call compare_with_a_new_integrator(sys, it, t, y, h, "load")
      call check(any(y_stale /= y), "ball: a stale first stage would give another step (the test can see it)")

      ! a change of the degrees of freedom: the inner race held in translation from now on
      ! (its position and velocity then stay exactly as they are)
      c%constraints%inner%translation = .false.
      call sys%set_condition(c, it, y, error)
      call check(.not. allocated(error) .and. .not. it%fsal_valid, "ball: constraints changed, integrator restarted")
      call unpack_state(y, t, s)
      p_inner = s%races(RACE_INNER)%position
      v_inner = s%races(RACE_INNER)%velocity
      do i = 1, 3
         call it%step(sys, t, y, error)
      end do
      call unpack_state(y, t, s)
      call check(.not. allocated(error), "ball: steps with the inner race held")
      call check(all(s%races(RACE_INNER)%position == p_inner) .and. all(s%races(RACE_INNER)%velocity == v_inner), &
                 "ball: the held inner race keeps its position and velocity")


   end subroutine test_ball_condition_change

   !> The next step of sys (integrator it, from t, y) equals bit for bit that of a brand-new
   !> integrator (no cached stage) on a copy of the system, from the same state and step h.
   subroutine compare_with_a_new_integrator(sys, it, t, y, h, what)
      class(bearing_system_t), intent(inout) :: sys
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: t, y(:)
      real(wp), intent(in) :: h
      character(len=*), intent(in) :: what
      class(bearing_system_t), allocatable :: fresh
      type(integrator_t) :: it_fresh
      type(error_type), allocatable :: error
      real(wp), allocatable :: y_fresh(:)
      real(wp) :: t_fresh
      allocate (fresh, source=sys)
      y_fresh = y
      t_fresh = t
      call it_fresh%init(size(y), it%settings, error, scale=it%scale)
      ! the same method: the linearly implicit ones with the system's Jacobian blocks
      if (it%jac%bordered()) then
         call it_fresh%set_jacobian_blocks(it%jac%first, it%jac%m, it%jac%cols, error, border=it%jac%border)
      else if (it%jac%active()) then
         call it_fresh%set_jacobian_blocks(it%jac%first, it%jac%m, it%jac%cols, error)
      end if
      call it_fresh%restart(h)
      call it%step(sys, t, y, error)
      call it_fresh%step(fresh, t_fresh, y_fresh, error)
      call check(.not. allocated(error), "ball: a step after the "//what//" change")
      call check(all(y == y_fresh) .and. t == t_fresh, &
                 "ball: the step after the "//what//" change equals a brand-new integrator's bit for bit")
   end subroutine compare_with_a_new_integrator

   !> The heat averaged by location (bearings/ball_thermal.f90, docs/thermal.md "Heat by
   !> location"): a ball at location j's azimuth 2 pi (j - 1) / n puts all its heat there; a
   !> ball a quarter of the way to the next location splits it 3/4 : 1/4; the last location
   !> wraps to the first; balls rotated by one place give their heat to the next location;
   !> every ball's heat kept (the total within round-off), the lands' too.
   subroutine test_heat_by_location()
      integer, parameter :: n = 6
      type(thermal_heat_t) :: h, loc
      integer :: j(2), k
      real(wp) :: w(2), phi(n), q(n)
      call location_weights(2.0_wp*pi*2/n, n, j, w)
      call check(j(1) == 3 .and. abs(w(1) - 1.0_wp) < 1.0e-12_wp, "location: a ball at location 3's azimuth")
      call location_weights(2.0_wp*pi*(2.25_wp)/n, n, j, w)
      call check(j(1) == 3 .and. j(2) == 4 .and. abs(w(1) - 0.75_wp) < 1.0e-12_wp .and. &
                 abs(w(2) - 0.25_wp) < 1.0e-12_wp, "location: a quarter of the way splits 3/4 : 1/4")
      call location_weights(-2.0_wp*pi*0.5_wp/n, n, j, w)
      call check(j(1) == n .and. j(2) == 1 .and. abs(w(1) - 0.5_wp) < 1.0e-12_wp, &
                 "location: the last location wraps to the first (negative azimuth)")
      h = new_thermal_heat(n)
      q = [(10.0_wp + k, k = 1, n)]
      h%outer = q
      h%inner = 2.0_wp*q
      h%pocket = 0.1_wp*q
      h%land = 3.0_wp
      ! balls at their own locations rotated by one: ball k at location k + 1
      phi = [(2.0_wp*pi*k/n, k = 1, n)]
      loc = heat_by_location(h, phi)
      call check(all(abs(loc%outer - cshift(q, -1)) < 1.0e-12_wp) .and. all(abs(loc%inner - 2.0_wp*cshift(q, -1)) &
                 < 1.0e-12_wp), "location: each ball's heat at the location it occupies")
      phi = phi + 0.37_wp
      loc = heat_by_location(h, phi)
      call check(abs(sum(loc%outer) - sum(q)) < 1.0e-12_wp*sum(q) .and. abs(sum(loc%pocket) - 0.1_wp*sum(q)) &
                 < 1.0e-12_wp*sum(q) .and. loc%land == 3.0_wp, "location: the heat is kept")
      call test_location_average_closed_form()
   end subroutine test_heat_by_location

   !> A heat pattern fixed in space, q(phi) = a + c cos(phi) per ball, and n balls orbiting
   !> uniformly through m whole spacings (Delta = 2 pi / n): the heat averaged by location j
   !> (linear weights, trapezoidal rule) is (1/Delta) integral of the hat (1 - |u|/Delta) times
   !> q(phi_j + u) over |u| < Delta = a + c cos(phi_j) (sin(Delta/2)/(Delta/2))**2, the
   !> pattern at the place, not each ball's own mean over its path.  Within 1e-6 of c with
   !> 2000 steps per spacing (the trapezoidal rule's error, O(step**2)).
   subroutine test_location_average_closed_form()
      integer, parameter :: n = 18, m = 3, steps = 2000*m
      real(wp), parameter :: a = 20.0_wp, c = 10.0_wp
      type(ball_thermal_t) :: th
      type(thermal_heat_t) :: h
      real(wp) :: delta, t, phi(n), mean(n), want(n), omega
      integer :: i, k
      delta = 2.0_wp*pi/n
      omega = 1.0_wp
      th%integral = new_thermal_heat(n)
      th%last = new_thermal_heat(n)
      do i = 0, steps
         t = m*delta/omega*i/steps
         phi = [(delta*(k - 1) + omega*t, k = 1, n)]
         h = new_thermal_heat(n)
         h%outer = a + c*cos(phi)
         call ball_thermal_accumulate(th, t, heat_by_location(h, phi))
      end do
      mean = th%integral%outer/th%elapsed
      want = [(a + c*cos(delta*(k - 1))*(sin(0.5_wp*delta)/(0.5_wp*delta))**2, k = 1, n)]
      call check(maxval(abs(mean - want)) <= 1.0e-6_wp*c, "location: a space-fixed pattern averaged by place "// &
                 "= the pattern smoothed by the hat, a + c cos(phi_j) sinc(Delta/2)**2")
   end subroutine test_location_average_closed_form

   !> Appendix C with its own thermal model (Rec 2.5: heat averaged every 3 ms, geometry
   !> updated from 30 ms) through run_time_loop to 33.5 ms: eleven updates at 3, 6, ... 33 ms
   !> (the deck's times, to 1e-12 relative); at every update the heat generated leaves
   !> through the coolant, the reference and the bore within 1e-6 (relative); the bulk
   !> temperatures of the condition and of the state are the last field's; the geometry
   !> updated at 30 and 33 ms only, mounted at those temperatures with the ADRC2 fits; the
   !> geometry change disturbs the inner race's equilibrium (net force > 1 % of the applied
   !> load before the constraint) and the constraint leaves at most 1e-6 of it; one more
   !> update at the end, then the equations of motion evaluated from outside: the inner race's
   !> net force (mass x acceleration) at most 1e-6 of the applied load.
   subroutine test_ball_thermal_run()
      class(bearing_system_t), allocatable :: sys
      type(integrator_t) :: it
      type(run_options_t) :: opts
      type(bearing_t) :: b
      type(run_history_t) :: h
      type(error_type), allocatable :: error
      type(mounted_geometry_t) :: g
      type(bearing_state_t) :: s
      real(wp), allocatable :: y(:)
      character(len=:), allocatable :: decks, incomplete
      real(wp) :: net(3)
      real(wp), allocatable :: dydt(:)
      integer :: unit, k, flag

      call get_decks_dir(decks)
      call read_bearing(decks//"/appendix_c_ball.inp", b, error)
      if (allocated(error)) return
      call check(b%coolant%thermal_time(1) == 3.0e-3_wp .and. b%coolant%thermal_time(2) == 3.0e-2_wp, &
                 "thermal: Rec 2.5's times read")
      opts%duration = 3.35e-2_wp
      call set_run_option(opts, "thermal", "deck", error)
      call check(.not. allocated(error), "thermal: run option thermal=deck")
      call new_bearing_system(b, opts, sys, error)
      call sys%solve_start(error)
      call sys%start_dynamics(it, y, error)
      call check(.not. allocated(error), "thermal: start")
      if (allocated(error)) return
      call sys%new_history(h, 100, error)
      allocate (dydt(size(y)))
      open (newunit=unit, status="scratch", action="readwrite")
      call run_time_loop(unit, sys, it, y, 100, h, incomplete, error, t_end=opts%duration/sys%time_scale)
      close (unit)
      call check(.not. allocated(error), "thermal: the run to 33.5 ms completes")
      select type (sys)
      type is (ball_kind_t)
         associate (th => sys%thermal)
            call check(th%mode == THERMAL_GEOMETRY, "thermal: the deck's mode is temperatures and geometry")
            call check(th%updates == 11, "thermal: eleven updates by 33.5 ms")
            do k = 1, min(th%updates, 11)
               call check(abs(th%update_times(k) - 3.0e-3_wp*k) <= 1.0e-12_wp*3.0e-3_wp*k, &
                          "thermal: update at the deck's time")
            end do
            call check(th%balance <= 1.0e-6_wp, "thermal: heat generated = heat leaving at every update")
            call check(th%field%q_generated > 100.0_wp, "thermal: the bearing generates heat")
            call check(all(sys%condition%temperature == th%field%temperature), &
                       "thermal: the condition's temperatures are the last field's")
            s = sys%eom%state
            call unpack_state(y, 0.0_wp, s, sys%eom%orbit_frame)
            call check(all(s%temperature == th%field%temperature), "thermal: the state's temperatures too")
            call check(th%geometry_updates == 2, "thermal: geometry updated at 30 and 33 ms only")
            call check(all(sys%condition%geometry_temperature == th%field%temperature), &
                       "thermal: the geometry at the last field's temperatures")
            g = mount_geometry(distorted_bearing(b, th%field%temperature), th%field%temperature)
            call check(sys%eom%geometry%mounting%clearance == g%mounting%clearance .and. &
                       sys%eom%geometry%mounting%outer_fit == g%mounting%outer_fit, &
                       "thermal: the equations of motion use the distorted geometry (ADRC2)")
            call check(sys%hold_solves == 2, "thermal: the load-holding constraint at each geometry update")
            call check(sys%hold_initial > 1.0e-2_wp, "thermal: a geometry update disturbs the inner race")
            call check(sys%hold_residual <= 1.0e-6_wp, "thermal: after the constraint the contacts carry the "// &
                       "applied load (residual <= 1e-6)")
         end associate
         ! one more update at the run's end (its heat since 33 ms), checked from outside: the
         ! equations of motion at the state it leaves give the inner race no net force
         call sys%on_event(opts%duration, it, y, error)
         call check(.not. allocated(error), "thermal: an update at the end of the run")
         call check(sys%thermal%updates == 12 .and. sys%hold_solves == 3, "thermal: the update re-mounted and held")
         call sys%eval(opts%duration/sys%time_scale, y, dydt, flag)
         call check(flag == DERIV_OK, "thermal: the state after the update evaluates")
         net = b%mass(BODY_INNER)*sys%eom%rates%races(RACE_INNER)%velocity
         call check(norm2(net) <= 1.0e-6_wp*norm2(b%force), "thermal: the inner race in equilibrium with the "// &
                    "applied load after the geometry update (eval, residual <= 1e-6)")
      end select
   end subroutine test_ball_thermal_run


end program test_bearing_system
