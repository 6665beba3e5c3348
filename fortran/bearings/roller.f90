!> The cylindrical roller bearing as a bearing kind (adore_bearings_system): its quasi-static
!> start and step-0 print, its equations of motion (adore_dynamics_roller_system on the loads
!> of adore_forces_roller_bearing, issue #26), its printed steps (the step-0 layout filled from
!> the dynamic state, adore_output_roller_dynamic_report) and its time history.  No module
!> state.
module adore_bearings_roller
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_model_bearing, only: bearing_t
   use adore_model_condition, only: condition_of, default_constraints, dof_constraints_t, &
                                    cage_option_free, deck_constraints
   use adore_geometry_mounted, only: mount_geometry
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_dynamics_integrator, only: integrator_t
   use adore_dynamics_roller_system, only: roller_system_t, start_roller_dynamics, ROLLER_SIZE, R_PHI, R_PHIDOT, &
                                           CAGE_OFFSET
   use adore_bearings_system, only: bearing_system_t, run_int_method, asked_steps, adopt_failure
   use adore_bearings_ball_thermal, only: thermal_mode_of, THERMAL_OFF
   use adore_output_step_report, only: write_roller_step0
   use adore_output_run_history, only: run_history_t
   use adore_output_roller_dynamic_report, only: roller_step_view, new_roller_history, record_roller_history, &
                                                 roller_total_power
   implicit none
   private

   public :: roller_kind_t

   !> Positions in the averaged values: total power loss (W), mean roller orbital speed and
   !> cage speed (rad/s).
   integer, parameter, public :: RAVG_POWER = 1, RAVG_ORBIT = 2, RAVG_CAGE = 3

   !> A cylindrical roller bearing run.
   type, extends(bearing_system_t) :: roller_kind_t
      type(roller_step0_t) :: step0         !< the quasi-static start
      type(roller_system_t) :: eom          !< the equations of motion
      real(wp), allocatable :: y(:)         !< the state of the last accepted step
      real(wp), allocatable :: azimuth(:)   !< each roller's orbital position, unwrapped (rad)
      real(wp), allocatable :: last(:)      !< at the last step (rad)
   contains
      procedure :: eval => roller_eval
      procedure :: solve_start => roller_solve_start
      procedure :: write_start => roller_write_start
      procedure :: run_note => roller_run_note
      procedure :: dynamic_steps => roller_dynamic_steps
      procedure :: start_dynamics => roller_start_dynamics
      procedure :: listing_lines => roller_listing_lines
      procedure :: n_values => roller_n_values
      procedure :: averaged_values => roller_values
      procedure :: accepted => roller_accepted
      procedure :: write_step => roller_write_step
      procedure :: new_history => roller_new_history
      procedure :: record_row => roller_record_row
      procedure :: mount => roller_mount
   end type roller_kind_t

contains

   !> Step 0 (adore_start_roller_step0); the ball-only options are input errors.
   subroutine roller_solve_start(self, error)
      class(roller_kind_t), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
      if (len_trim(self%options%ball_start) > 0) then
         call input_error(error, "the ball start option applies to ball bearings; this deck is a cylindrical "// &
                          "roller bearing (Rec 3.2)")
         return
      end if
      if (self%options%moment_equilibrium) then
         call input_error(error, "the moment equilibrium option applies to ball bearings; this deck is a "// &
                          "cylindrical roller bearing (Rec 3.2)")
         return
      end if
      self%condition = condition_of(self%bearing)
      call solve_roller_step0(self%bearing, self%step0, error)
   end subroutine roller_solve_start

   subroutine roller_write_start(self, unit)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: unit
      call write_roller_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], self%bearing, self%step0)
   end subroutine roller_write_start

   !> What the time integration leaves out or assumes (blank without time steps).
   subroutine roller_run_note(self, n_steps, text)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      character(len=:), allocatable :: dof
      text = ""
      if (n_steps < 1) return
      if (self%eom%cage_free) then
         text = "thermal model off: bulk temperatures fixed at the initial ones (Rec 2.7); cage free in all six "// &
                "degrees of freedom (report 4.4.6), on its pockets and guide lands; "
      else
         text = "thermal model off: bulk temperatures fixed at the initial ones (Rec 2.7); cage centred, turning "// &
                "about its axis only (translation and tilt constrained, report 4.4.6); "
      end if
      if (self%bearing%roller%pocket_type == -1) then
         text = text//"cylindrical pockets (kPocType -1, Rec 5B.2)"
      else
         text = text//"rectangular pockets as flat walls (kPocType 0 not identified)"
      end if
      if (any(self%bearing%roller%flange)) then
         text = text//"; roller ends on the flanges of Rec 5B.2 (spherical ends, Hertz)"
      else
         text = text//"; no flanges"
      end if
      call roller_dof_note(self%condition%constraints, dof)
      text = text//dof
   end subroutine roller_run_note

   !> The print listing's lines on the physics of the time integration.
   subroutine roller_listing_lines(self, n_steps, text)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      character(len=*), parameter :: lf = new_line("a")
      text = ""
      if (n_steps < 1) return
      text = "  THERMAL MODEL OFF: BULK TEMPERATURES FIXED AT THE INITIAL ONES (REC 2.7)"//lf
      if (self%eom%cage_free) then
         text = text//"  CAGE FREE: ALL SIX DEGREES OF FREEDOM INTEGRATED, ON ITS POCKETS AND GUIDE LANDS "// &
                "(REPORT 4.4.6)"//lf
      else
         text = text//"  CAGE CENTRED ON THE BEARING AXIS, TURNING ABOUT IT ONLY (DOF CONSTRAINT, REPORT 4.4.6)"//lf
      end if
      if (self%bearing%roller%pocket_type == -1) then
         text = text//"  CYLINDRICAL ROLLER POCKETS (KPOCTYPE -1, REPORT 4.4.11)"//lf
      else
         text = text//"  RECTANGULAR ROLLER POCKETS AS FLAT WALLS (docs/dynamics.md, Roller dynamics)"//lf
      end if
      if (any(self%bearing%roller%flange)) text = text//"  ROLLER END / FLANGE CONTACTS: SPHERICAL ENDS ON "// &
                                                  "LAID-BACK FLANGES (REC 5B.2, docs/dynamics.md, Flanges)"//lf
   end subroutine roller_listing_lines

   !> dy/dtau of the equations of motion (adore_dynamics_roller_system).
   subroutine roller_eval(self, t, y, dydt, flag)
      class(roller_kind_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      call self%eom%eval(t, y, dydt, flag)
      call adopt_failure(self, self%eom)
      self%y = y
   end subroutine roller_eval

   !> The options' steps: Rec 1 n_steps for STEPS_FROM_DECK.
   integer function roller_dynamic_steps(self) result(n)
      class(roller_kind_t), intent(in) :: self
      n = asked_steps(self%bearing, self%options)
   end function roller_dynamic_steps

   !> The dynamics from the step-0 start: each roller at its equilibrium radius, tilt and
   !> orbital speed, its land spinning in pure rolling on the outer race (outer race control,
   !> as step 0; adore_forces_roller_bearing's slip), the inner race at its equilibrium, the cage at its step-0
   !> angle and speed; the pockets centred on the rollers at the start.  The cage by the run
   !> option cage (report 4.4.6): centred (default) turning about its axis only; free (or deck
   !> with Rec 3.3 all zero or Appendix D's) free in all six DOFs from the deck's Rec 9.5.1
   !> start whirl (adore_cage_step0's centre and velocity).
   subroutine roller_start_dynamics(self, it, y, error)
      class(roller_kind_t), intent(inout) :: self
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: method
      logical :: cage_free
      call cage_option_free(self%options%cage, self%bearing%dof_flags, cage_free, error)
      if (allocated(error)) return
      ! the thermal model is wired into the ball kind only (docs/thermal.md, "Open"): a roller
      ! run asked for it stops here rather than run without it
      call thermal_mode_of(self%options%thermal, self%bearing, method, error)
      if (allocated(error)) return
      if (method /= THERMAL_OFF) then
         call input_error(error, "thermal model '"//trim(self%options%thermal)//"': not available for roller "// &
                          "bearings yet (the roller kind has no thermal update; docs/thermal.md); run with "// &
                          "--thermal off")
         return
      end if
      method = run_int_method(self%options%integrator, self%bearing%controls%int_method)
      associate (s => self%step0, e => self%step0%equilibrium)
         call start_roller_dynamics(self%bearing, mount_geometry(self%bearing, self%bearing%temperature, 2), &
                                    s%model, e%azimuth, e%r, e%tilt, e%orbital_speed, &
                                    (self%bearing%speed_outer - e%orbital_speed)*(2.0_wp*e%r + self%bearing%d)/ &
                                    self%bearing%d, e%u, &
                                    s%cage%state%angle(1), s%cage%state%angular_speed, self%eom, it, y, error, &
                                    int_method=method, cage_free=cage_free, &
                                    cage_start=[s%cage%state%centre(2:3), s%cage%state%velocity(2:3)])
         if (allocated(error)) return
         self%azimuth = e%azimuth
         self%last = e%azimuth
      end associate
      self%time_scale = self%eom%time_scale
      call roller_constraints(self%bearing, cage_free, self%condition%constraints, error)
      if (allocated(error)) return
      self%eom%constraints = self%condition%constraints
      self%y = y
   end subroutine roller_start_dynamics

   !> The run's degrees of freedom (report 4.4.6): the rollers' as the deck's Rec 3.3 says
   !> (adore_model_condition's deck_constraints: all zero nothing held, Appendix D's
   !> 1 1 1 1 0 0 0 0 0 0 1 the rollers' axial motion, tilt and skew held; any other pattern an
   !> input error naming the field) whatever the run option cage; the cage by that option:
   !> turning about its axis, and when cage_free free in all six DOFs (both readings of
   !> Rec 3.3 leave the cage free).  Free, a
   !> flangeless roller's skew grows from round-off (docs/dynamics.md, Roller dynamics).
   subroutine roller_constraints(b, cage_free, c, error)
      type(bearing_t), intent(in) :: b
      logical, intent(in) :: cage_free
      type(dof_constraints_t), intent(out) :: c
      type(error_type), allocatable, intent(out) :: error
      type(dof_constraints_t) :: deck
      call deck_constraints(b%dof_flags, deck, error)
      if (allocated(error)) return
      c = default_constraints(.true.)
      if (cage_free) c%cage = deck%cage
      c%elements = deck%elements
   end subroutine roller_constraints

   !> The run note's words on the rollers' degrees of freedom (Rec 3.3, roller_constraints); a
   !> subroutine: no deferred-length function result (adore_core_strings).
   pure subroutine roller_dof_note(c, text)
      type(dof_constraints_t), intent(in) :: c
      character(len=:), allocatable, intent(out) :: text
      if (all(c%elements%translation) .and. all(c%elements%rotation)) then
         text = "; rollers free in all six degrees of freedom (Rec 3.3 all zero)"
      else
         text = "; rollers' axial motion, tilt and skew held (Rec 3.3 1 1 1 1 0 0 0 0 0 0 1, report 4.4.6)"
      end if
   end subroutine roller_dof_note

   integer function roller_n_values(self)
      class(roller_kind_t), intent(in) :: self
      roller_n_values = RAVG_CAGE
      if (self%eom%n < 0) roller_n_values = 0
   end function roller_n_values

   !> Total power loss, mean orbital speed and cage speed at the last evaluated state.
   subroutine roller_values(self, v)
      class(roller_kind_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      integer :: n
      n = self%eom%n
      v(RAVG_POWER) = roller_total_power(self%eom)
      v(RAVG_ORBIT) = sum(self%y(R_PHIDOT:ROLLER_SIZE*n:ROLLER_SIZE))/n
      v(RAVG_CAGE) = self%y(ROLLER_SIZE*n + CAGE_OFFSET + 2)
   end subroutine roller_values

   !> Each roller's orbital position unwrapped (the state carries it unwrapped already).
   subroutine roller_accepted(self)
      class(roller_kind_t), intent(inout) :: self
      integer :: n
      n = self%eom%n
      self%azimuth = self%y(R_PHI:ROLLER_SIZE*n:ROLLER_SIZE)
      self%last = self%azimuth
   end subroutine roller_accepted

   !> A printed time step: the step-0 layout at the last evaluated state.
   subroutine roller_write_step(self, unit, step, t, mean)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: t, mean(:)
      type(roller_step0_t) :: s
      type(error_type), allocatable :: error
      real(wp) :: time
      time = t*self%time_scale
      call roller_step_view(self%bearing, self%eom, self%y, self%azimuth, self%step0, s, error)
      ! a flash-temperature error leaves those columns at their step-0 values; the rest prints
      if (allocated(error)) deallocate (error)
      if (size(mean) < RAVG_CAGE) return
      associate (b => self%bearing)
         call write_roller_step0(unit, step, [t, time, b%speed_outer*time/(2.0_wp*pi), &
                                              b%speed_inner*time/(2.0_wp*pi)], b, s)
      end associate
   end subroutine roller_write_step

   subroutine roller_new_history(self, h, n_steps, error)
      class(roller_kind_t), intent(in) :: self
      type(run_history_t), intent(out) :: h
      integer, intent(in) :: n_steps
      type(error_type), allocatable, intent(out) :: error
      call new_roller_history(h, self%bearing, n_steps, self%options%history_element, error, &
                              self%options%history_stride)
   end subroutine roller_new_history

   subroutine roller_record_row(self, h, step, t, mean)
      class(roller_kind_t), intent(in) :: self
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: t, mean(:)
      call record_roller_history(h, step, t*self%time_scale, self%bearing, self%eom, self%y)
      if (size(mean) < 0) return
   end subroutine roller_record_row

   !> The condition's load on the inner race and its degrees of freedom (the geometry stays
   !> the step-0 mounting: the thermal re-mounting of a roller run is not done; an input error
   !> when the condition's temperatures differ from the initial ones or the cage is freed).
   subroutine roller_mount(self, y, error)
      class(roller_kind_t), intent(inout) :: self
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      associate (c => self%condition)
         if (any(c%temperature /= self%bearing%temperature)) then
            call input_error(error, "roller bearing: a change of the bulk temperatures during the run is not "// &
                             "modelled (thermal re-mounting of roller bearings)")
            return
         end if
         if (.not. c%constraints%cage%rotation(1) .or. &
             any([c%constraints%cage%translation, c%constraints%cage%rotation(2:3)] .neqv. self%eom%cage_free)) then
            call input_error(error, "roller bearing: the cage turns about its axis and, run option cage=free, "// &
                             "is free in all six degrees of freedom; other cage constraints are not modelled")
            return
         end if
         self%eom%force = c%force
         self%eom%constraints = c%constraints
      end associate
      if (size(y) < 0) call engine_error(error, "roller bearing: empty state")
   end subroutine roller_mount

end module adore_bearings_roller
