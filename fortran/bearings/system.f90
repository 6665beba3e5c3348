!> The bearing system: what every bearing kind provides to a run (issue #24 item 1).
!>
!> A bearing kind (ball, cylindrical roller, later tapered and spherical) extends
!> `bearing_system_t`, which extends the integrator's derivative (adore_dynamics_integrator's
!> derivative_t, the equations of motion dy/dtau in the report's dimensionless time).  The
!> run (adore_driver_run) picks the kind once (adore_bearings_select) and from then on talks
!> to it only through this interface: the quasi-static start and its print (step 0), the
!> time integration's initial state and integrator, the quantities averaged over time, a
!> printed time step, a time-history row, the lines the print's listing and the run note
!> say about the run.  The generic time loop (adore_driver_time_loop) drives any kind.
!>
!> The system owns its operating condition (adore_model_condition: bulk temperatures and
!> the applied load): set_condition re-mounts the geometry (the kind's `mount`) and restarts
!> the integrator, so no stage computed under the old condition is reused (the integrator's
!> first-same-as-last derivative is dropped).  An unchanged condition changes nothing.  The
!> time loop calls `on_event` at the system's event times (every event_period seconds of
!> simulated time from event_start; none while event_period is 0), landing a step exactly on
!> each: the hook of the thermal model and of any periodic update.  The balances (issue #28
!> item 2): a kind's balance_values at every accepted step (n_balance of them) are averaged
!> by the time loop over the run's balance window, and balance_text says what they add up
!> to (the run note).  No module state.
module adore_bearings_system
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error
   use adore_core_strings, only: itoa
   use adore_deck_tokenizer, only: show_real
   use adore_model_bearing, only: bearing_t
   use adore_model_condition, only: operating_condition_t, same_condition
   use adore_model_run_options, only: run_options_t, STEPS_FROM_DECK
   use adore_dynamics_integrator, only: derivative_t, integrator_t, DERIV_FAIL, INT_METHOD_BS32, INT_METHOD_DP54, &
                                        INT_METHOD_ROS34PW2, INT_METHOD_ARK436
   use adore_dynamics_ball_system, only: ball_int_method
   use adore_output_run_history, only: run_history_t
   implicit none
   private

   public :: bearing_system_t, run_int_method, asked_steps, adopt_failure

   !> What a kind without a time integration says when one is asked of it.
   character(len=*), parameter :: NO_DYNAMICS = "this bearing kind has no time integration yet"

   !> A bearing kind as the run sees it.
   type, abstract, extends(derivative_t) :: bearing_system_t
      !> the bearing model as the deck gives it (its temperatures are the initial ones, the
      !> reference of the thermal growth: adore_geometry_mounted)
      type(bearing_t) :: bearing
      !> the run's options (adore_model_run_options)
      type(run_options_t) :: options
      !> the operating condition the system is mounted in (set_condition)
      type(operating_condition_t) :: condition
      real(wp) :: time_scale = 1.0_wp      !< T (s) of one unit of tau (the echo's TIME scale)
      !> events (on_event): the first at event_start (s), then every event_period (s); none
      !> while event_period is 0
      real(wp) :: event_start = 0.0_wp, event_period = 0.0_wp
   contains
      procedure(solve_start_i), deferred :: solve_start
      procedure(write_start_i), deferred :: write_start
      procedure(text_i), deferred :: run_note
      ! a kind with a time integration overrides these; the defaults are a kind without one
      procedure :: eval => no_eval
      procedure :: dynamic_steps => no_dynamic_steps
      procedure :: start_dynamics => no_start_dynamics
      procedure :: listing_lines => no_text
      procedure :: n_values => no_values
      procedure :: averaged_values => no_averaged_values
      procedure :: accepted => no_accepted
      procedure :: write_step => no_write_step
      procedure :: new_history => no_new_history
      procedure :: record_row => no_record_row
      procedure :: mount => no_mount
      procedure :: n_balance => no_values
      procedure :: balance_values => no_averaged_values
      procedure :: balance_text => no_balance_text
      ! the integrator's quadrature (integrator_t%start_quadrature) is of the balance values
      procedure :: n_quadrature => system_n_quadrature
      procedure :: quadrature_values => system_quadrature_values
      procedure :: unknown_name => no_unknown_name
      procedure :: set_condition
      procedure :: on_event
      procedure :: start_load => no_start_load
   end type bearing_system_t

   abstract interface
      !> Step 0, the quasi-static start (report 3.1, 4.4.4, 4.4.7), of self%bearing under
      !> self%options.
      subroutine solve_start_i(self, error)
         import :: bearing_system_t, error_type
         class(bearing_system_t), intent(inout) :: self
         type(error_type), allocatable, intent(out) :: error
      end subroutine solve_start_i

      !> Print step 0 (the ADORE 5.0 layout) on unit.
      subroutine write_start_i(self, unit)
         import :: bearing_system_t
         class(bearing_system_t), intent(in) :: self
         integer, intent(in) :: unit
      end subroutine write_start_i

      !> Text about a run of n_steps time steps: the print listing's lines (LF-separated,
      !> each ending in LF; blank: none) or the run note (one line; blank: nothing to say).
      !> (Subroutines, not functions: no deferred-length function results, adore_core_strings.)
      subroutine text_i(self, n_steps, text)
         import :: bearing_system_t
         class(bearing_system_t), intent(in) :: self
         integer, intent(in) :: n_steps
         character(len=:), allocatable, intent(out) :: text
      end subroutine text_i
   end interface

contains

   !> The integration method (adore_dynamics_integrator's INT_METHOD_*) of the run option
   !> `integrator` (ark4, ros34pw2, dp5, bs3; anything else: the deck's Rec 1 INT METHOD
   !> deck_code as ball_int_method reads it, 5 = ARK4(3)6L IMEX), for every kind.
   pure integer function run_int_method(option, deck_code) result(method)
      character(len=*), intent(in) :: option
      integer, intent(in) :: deck_code
      select case (option)
      case ("ark4")
         method = INT_METHOD_ARK436
      case ("ros34pw2")
         method = INT_METHOD_ROS34PW2
      case ("dp5")
         method = INT_METHOD_DP54
      case ("bs3")
         method = INT_METHOD_BS32
      case default
         method = ball_int_method(deck_code)
      end select
   end function run_int_method

   !> The time steps a run of bearing b asks for under options o: Rec 1 n_steps for
   !> STEPS_FROM_DECK, else the option's (never below 0).  What a kind with a time
   !> integration returns as its dynamic_steps.
   pure integer function asked_steps(b, o) result(n)
      type(bearing_t), intent(in) :: b
      type(run_options_t), intent(in) :: o
      if (o%steps == STEPS_FROM_DECK) then
         n = max(b%controls%n_steps, 0)
      else
         n = max(o%steps, 0)
      end if
   end function asked_steps

   !> The reason of the last failed evaluation of a kind's equations of motion eom as the
   !> kind's own (none when eom's last evaluation succeeded).
   subroutine adopt_failure(self, eom)
      class(bearing_system_t), intent(inout) :: self
      class(derivative_t), intent(in) :: eom
      if (allocated(eom%failure_reason)) then
         self%failure_reason = eom%failure_reason
      else if (allocated(self%failure_reason)) then
         deallocate (self%failure_reason)
      end if
   end subroutine adopt_failure

   !> Change the operating condition to c during a run at packed state y: the system is
   !> mounted anew (mount) and the integrator it restarted with its next step size kept, so
   !> that the next step evaluates every stage under c.  Nothing happens when c equals the
   !> current condition bit for bit.
   subroutine set_condition(self, c, it, y, error)
      class(bearing_system_t), intent(inout) :: self
      type(operating_condition_t), intent(in) :: c
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      if (same_condition(c, self%condition)) return
      self%condition = c
      call self%mount(y, error)
      if (allocated(error)) return
      call it%restart(it%h_next)
   end subroutine set_condition

   !> The event hook at simulated time `time` (s), state y at tau = t: the base does nothing.
   !> A kind (or its thermal model) overrides it, e.g. to set a new condition.
   subroutine on_event(self, time, it, y, error)
      class(bearing_system_t), intent(inout) :: self
      real(wp), intent(in) :: time
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
   end subroutine on_event

   ! --- a kind without a time integration (its run ends after step 0); the defaults leave
   ! --- their arguments unused (the compiler's unused-argument notes are expected here) ---

   !> No equations of motion: DERIV_FAIL.
   subroutine no_eval(self, t, y, dydt, flag)
      class(bearing_system_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      dydt = 0.0_wp
      flag = DERIV_FAIL
      self%failure_reason = NO_DYNAMICS//" (tau "//show_real(t)//", "//itoa(size(y))//" unknowns)"
   end subroutine no_eval

   !> No time steps.
   integer function no_dynamic_steps(self) result(n)
      class(bearing_system_t), intent(in) :: self
      n = 0
   end function no_dynamic_steps

   !> An engine error: the kind has no time integration.
   !> The start's largest contact load (N) that the time scale takes when it exceeds the
   !> applied load (adore_model_scales); 0: a kind whose scale is the applied load's.
   real(wp) function no_start_load(self) result(q)
      class(bearing_system_t), intent(in) :: self
      q = 0.0_wp
   end function no_start_load

   subroutine no_start_dynamics(self, it, y, error)
      class(bearing_system_t), intent(inout) :: self
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      allocate (y(0))
      it%n = 0
      self%time_scale = 1.0_wp
      call engine_error(error, NO_DYNAMICS)
   end subroutine no_start_dynamics

   !> Nothing to say.
   subroutine no_text(self, n_steps, text)
      class(bearing_system_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      text = ""
   end subroutine no_text

   !> No averaged quantities.
   integer function no_values(self) result(n)
      class(bearing_system_t), intent(in) :: self
      n = 0
   end function no_values

   subroutine no_averaged_values(self, v)
      class(bearing_system_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      v = self%time_scale*0.0_wp
   end subroutine no_averaged_values

   !> The integrator's quadrature values (adore_dynamics_integrator's start_quadrature): the
   !> system's balance values (n_balance, balance_values), integrated over the balance window
   !> by the method's own stage weights (adore_driver_time_loop).
   integer function system_n_quadrature(self) result(n)
      class(bearing_system_t), intent(in) :: self
      n = self%n_balance()
   end function system_n_quadrature

   subroutine system_quadrature_values(self, v)
      class(bearing_system_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      call self%balance_values(v)
   end subroutine system_quadrature_values

   subroutine no_accepted(self)
      class(bearing_system_t), intent(inout) :: self
   end subroutine no_accepted

   subroutine no_write_step(self, unit, step, t, mean)
      class(bearing_system_t), intent(in) :: self
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: t, mean(:)
   end subroutine no_write_step

   !> An engine error: the kind has no time history.
   subroutine no_new_history(self, h, n_steps, error)
      class(bearing_system_t), intent(in) :: self
      type(run_history_t), intent(out) :: h
      integer, intent(in) :: n_steps
      type(error_type), allocatable, intent(out) :: error
      h%rows = 0
      call engine_error(error, NO_DYNAMICS//" ("//itoa(n_steps)//" steps asked, "// &
                        itoa(self%bearing%n_elements)//" rolling elements)")
   end subroutine no_new_history

   subroutine no_record_row(self, h, step, t, mean)
      class(bearing_system_t), intent(in) :: self
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: t, mean(:)
   end subroutine no_record_row

   !> No balance to report (hint: what resolves an unbalanced window, the time loop's; unused).
   subroutine no_balance_text(self, window, mean, first, last, hint, text)
      class(bearing_system_t), intent(in) :: self
      real(wp), intent(in) :: window(2), mean(:), first(:), last(:)
      character(len=*), intent(in) :: hint
      character(len=:), allocatable, intent(out) :: text
      text = ""
   end subroutine no_balance_text

   !> The name of unknown i of the system's packed state vector, for messages (issue #28's
   !> forced-step diagnosis); a kind without time integration: "unknown i".
   subroutine no_unknown_name(self, i, name)
      class(bearing_system_t), intent(in) :: self
      integer, intent(in) :: i
      character(len=:), allocatable, intent(out) :: name
      name = "unknown "//itoa(i)
   end subroutine no_unknown_name

   !> An engine error: nothing to mount without a time integration.
   subroutine no_mount(self, y, error)
      class(bearing_system_t), intent(inout) :: self
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      call engine_error(error, NO_DYNAMICS)
   end subroutine no_mount

end module adore_bearings_system
