!> The cylindrical roller bearing as a bearing kind (adore_bearings_system): its quasi-static
!> start and step-0 print, its equations of motion (adore_dynamics_roller_system on the loads
!> of adore_forces_roller_bearing, issue #26), its printed steps (the step-0 layout filled from
!> the dynamic state, adore_output_roller_dynamic_report) and its time history.  No module
!> state.
module adore_bearings_roller
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_strings, only: itoa
   use adore_core_threads, only: run_threads
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_INNER, BODY_OUTER, TEMP_ELEMENT, TEMP_OUTER, &
                                  TEMP_INNER
   use adore_model_condition, only: operating_condition_t, condition_of, default_constraints, dof_constraints_t, &
                                    cage_option_free, deck_constraints
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_thermal_distortion, only: distortion_t, distorted_bearing, thermal_distortion
   use adore_thermal_network, only: thermal_heat_t
   use adore_quasistatic_models, only: roller_qs_model
   use adore_forces_ball_bearing, only: guide_land_pairs
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_dynamics_integrator, only: integrator_t, DERIV_OK, INT_METHOD_ARK436, INT_METHOD_ROS34PW2
   use adore_dynamics_roller_system, only: roller_system_t, start_roller_dynamics, roller_pose, ROLLER_SIZE, R_PHI, &
                                           R_PHIDOT, CAGE_OFFSET, RACE_OFFSET, roller_unknown_name
   use adore_bearings_system, only: bearing_system_t, run_int_method, asked_steps, adopt_failure
   use adore_bearings_thermal_run, only: thermal_run_t, thermal_run_for, thermal_accumulate, thermal_run_text, &
                                         thermal_condition, hold_race_load, THERMAL_OFF
   use adore_bearings_roller_thermal, only: roller_heat_rates, roller_thermal_update
   use adore_output_step_report, only: write_roller_step0
   use adore_output_run_history, only: run_history_t, add_history_column, set_history_value
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
      real(wp) :: tau = 0.0_wp              !< its dimensionless time
      real(wp), allocatable :: azimuth(:)   !< each roller's orbital position, unwrapped (rad)
      real(wp), allocatable :: last(:)      !< at the last step (rad)
      type(thermal_run_t) :: thermal        !< the thermal model (adore_bearings_thermal_run)
      !> the mounted geometry the equations of motion run in (step 0's until a geometry update)
      type(mounted_geometry_t) :: geometry
      !> the load-holding constraint of the geometry updates: the largest |net force| /
      !> |applied load| an update left before it, the worst after it, the solves done
      real(wp) :: hold_initial = 0.0_wp
      real(wp) :: hold_residual = 0.0_wp
      integer :: hold_solves = 0
   contains
      procedure :: eval => roller_eval
      procedure :: unknown_name => roller_kind_unknown_name
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
      procedure :: on_event => roller_on_event
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

   !> The name of unknown i of the packed state (roller_unknown_name), e.g. "roller 3's spin".
   subroutine roller_kind_unknown_name(self, i, name)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: i
      character(len=:), allocatable, intent(out) :: name
      call roller_unknown_name(self%eom%n, i, name)
   end subroutine roller_kind_unknown_name

   !> What the time integration leaves out or assumes (blank without time steps).
   subroutine roller_run_note(self, n_steps, text)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      character(len=:), allocatable :: dof
      text = ""
      if (n_steps < 1) return
      call thermal_run_text(self%thermal, .false., text)
      if (self%thermal%mode /= THERMAL_OFF) text = text//" (roller runs: docs/thermal.md, Roller runs)"
      if (self%eom%cage_free) then
         text = text//"; cage free in all six degrees of freedom (report 4.4.6), on its pockets and guide lands"
         if (self%options%integrator == "deck" .and. &
             run_int_method("deck", self%bearing%controls%int_method) == INT_METHOD_ARK436) &
            text = text//", integrated by ROS34PW2 (the deck's INT METHOD with a free roller cage: the IMEX ARK4 "// &
                   "holds spurious pocket contacts at the deck's error limit; --integrator ark4 for it)"
         if (self%eom%adore_whirl) then
            text = text//", its centre in ADORE's whirl coordinates (r'' = F_r/m, r psi'' = F_t/m: no centripetal "// &
                   "or Coriolis acceleration, report 4.4.4; cage_whirl=inertial for Newton's); "
         else
            text = text//", its centre by Newton's inertial equations (cage_whirl=inertial); "
         end if
      else
         text = text//"; cage centred, turning about its axis only (translation and tilt constrained, report "// &
                "4.4.6); "
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
      call thermal_run_text(self%thermal, .true., text)
      text = text//lf
      if (self%eom%cage_free) then
         text = text//"  CAGE FREE: ALL SIX DEGREES OF FREEDOM INTEGRATED, ON ITS POCKETS AND GUIDE LANDS "// &
                "(REPORT 4.4.6"
         if (self%options%cage == "deck") text = text//"; AS THE DECK'S REC 3.3 SAYS"
         text = text//")"//lf
         if (self%eom%adore_whirl) text = text//"  CAGE MASS CENTRE IN ADORE'S WHIRL COORDINATES (REPORT 4.4.4; "// &
                "NO CENTRIPETAL OR CORIOLIS TERMS, docs/cage.md)"//lf
      else
         text = text//"  CAGE CENTRED ON THE BEARING AXIS, TURNING ABOUT IT ONLY (DOF CONSTRAINT, REPORT 4.4.6)"//lf
      end if
      if (self%bearing%roller%pocket_type == -1) then
         text = text//"  CYLINDRICAL ROLLER POCKETS (KPOCTYPE -1, REPORT 4.4.11)"//lf
      else
         text = text//"  RECTANGULAR ROLLER POCKETS AS FLAT WALLS (docs/rollers.md, Roller dynamics)"//lf
      end if
      if (any(self%bearing%roller%flange)) text = text//"  ROLLER END / FLANGE CONTACTS: SPHERICAL ENDS ON "// &
                                                  "LAID-BACK FLANGES (REC 5B.2, docs/rollers.md, Flanges)"//lf
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
      self%tau = t
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
   !> option cage (report 4.4.6): centred turning about its axis only; free (or deck, the
   !> default, with Rec 3.3 all zero or Appendix D's) free in all six DOFs from the deck's Rec 9.5.1
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
      method = run_int_method(self%options%integrator, self%bearing%controls%int_method)
      ! a free cage under the deck's INT METHOD 5: the Rosenbrock-W ROS34PW2, not the IMEX
      ! ARK4, which at the deck's error limit holds pocket contacts the accurate integrations
      ! do not have (docs/rollers.md, "The free roller cage's pocket episode")
      if (cage_free .and. self%options%integrator == "deck" .and. method == INT_METHOD_ARK436) &
         method = INT_METHOD_ROS34PW2
      associate (s => self%step0, e => self%step0%equilibrium)
         call start_roller_dynamics(self%bearing, mount_geometry(self%bearing, self%bearing%temperature, 2), &
                                    s%model, e%azimuth, e%r, e%tilt, e%orbital_speed, &
                                    (self%bearing%speed_outer - e%orbital_speed)*(2.0_wp*e%r + self%bearing%d)/ &
                                    self%bearing%d, e%u, &
                                    s%cage%state%angle(1), s%cage%state%angular_speed, self%eom, it, y, error, &
                                    int_method=method, cage_free=cage_free, &
                                    cage_start=[s%cage%state%centre(2:3), s%cage%state%velocity(2:3)], &
                                    axial=e%x, race_axial=e%u_axial)
         if (allocated(error)) return
         self%eom%adore_whirl = self%options%cage_whirl == "adore"   ! sys is intent(out) there
         self%eom%threads = run_threads(self%options%threads)
         self%azimuth = e%azimuth
         self%last = e%azimuth
      end associate
      self%time_scale = self%eom%time_scale
      call roller_constraints(self%bearing, cage_free, self%condition%constraints, error)
      if (allocated(error)) return
      self%eom%constraints = self%condition%constraints
      self%y = y
      self%geometry = mount_geometry(self%bearing, self%bearing%temperature, 2)
      ! the thermal model (docs/thermal.md, "Roller runs"): an event at the end of every
      ! averaging interval; the field model and the housing film as for the ball; the roller's
      ! traction law (the deck's curve or table) has no temperature in it, so the run option
      ! thermal_traction changes nothing here
      self%thermal = thermal_run_for(self%bearing, self%options, error)
      if (allocated(error)) return
      if (self%thermal%mode /= THERMAL_OFF) then
         self%event_start = self%thermal%interval
         self%event_period = self%thermal%interval
      end if
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

   !> Each roller's orbital position unwrapped (the state carries it unwrapped already); with
   !> the thermal model on, the heat rates of the accepted state integrated.
   subroutine roller_accepted(self)
      class(roller_kind_t), intent(inout) :: self
      integer :: n
      type(thermal_heat_t) :: heat
      n = self%eom%n
      self%azimuth = self%y(R_PHI:ROLLER_SIZE*n:ROLLER_SIZE)
      self%last = self%azimuth
      ! the thermal model's heat of this accepted state (its time, s)
      if (self%thermal%mode /= THERMAL_OFF) then
         call roller_heat_rates(self%thermal, self%bearing, self%eom, self%y, heat)
         call thermal_accumulate(self%thermal, self%tau*self%time_scale, heat)
      end if
   end subroutine roller_accepted

   !> A printed time step: the step-0 layout at the last evaluated state, in the geometry the
   !> equations of motion run in (fits and clearance of a geometry update); with the thermal
   !> model on, the rollers' drag and churning and, from the first update on, the last field
   !> (contact and bulk temperatures, HTC, exit fluid, housing, shaft, races and cage).
   subroutine roller_write_step(self, unit, step, t, mean)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: t, mean(:)
      type(roller_step0_t) :: s, s0
      type(error_type), allocatable :: error
      real(wp) :: time, header(4)
      time = t*self%time_scale
      if (self%thermal%geometry_updates > 0) then
         s0 = self%step0
         s0%model = self%eom%model%qs
         s0%mounting = self%geometry%mounting
         call roller_step_view(self%bearing, self%eom, self%y, self%azimuth, s0, s, error)
      else
         call roller_step_view(self%bearing, self%eom, self%y, self%azimuth, self%step0, s, error)
      end if
      ! a flash-temperature error leaves those columns at their step-0 values; the rest prints
      if (allocated(error)) deallocate (error)
      if (size(mean) < RAVG_CAGE) return
      associate (b => self%bearing, th => self%thermal)
         header = [t, time, b%speed_outer*time/(2.0_wp*pi), b%speed_inner*time/(2.0_wp*pi)]
         if (th%mode == THERMAL_OFF) then
            call write_roller_step0(unit, step, header, b, s)
         else if (.not. th%have_field) then      ! before the first update: no field yet
            call write_roller_step0(unit, step, header, b, s, th%fluid)
         else
            call write_roller_step0(unit, step, header, b, s, th%fluid, th%field)
         end if
      end associate
   end subroutine roller_write_step

   !> The roller history (new_roller_history) with the options' element and stride; with the
   !> thermal model on, a column exit_fluid_temp_K.
   subroutine roller_new_history(self, h, n_steps, error)
      class(roller_kind_t), intent(in) :: self
      type(run_history_t), intent(out) :: h
      integer, intent(in) :: n_steps
      type(error_type), allocatable, intent(out) :: error
      call new_roller_history(h, self%bearing, n_steps, self%options%history_element, error, &
                              self%options%history_stride)
      if (allocated(error)) return
      if (self%thermal%mode /= THERMAL_OFF) call add_history_column(h, "exit_fluid_temp_K")
   end subroutine roller_new_history

   !> A history row at the last evaluated state (record_roller_history, at the condition's
   !> bulk temperatures); with the thermal model on, its exit fluid temperature and the
   !> history element's contact temperatures from the last field (NaN / the bulk ones before
   !> the first field).
   subroutine roller_record_row(self, h, step, t, mean)
      class(roller_kind_t), intent(in) :: self
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: t, mean(:)
      character(len=:), allocatable :: e
      call record_roller_history(h, step, t*self%time_scale, self%bearing, self%eom, self%y, self%condition%temperature)
      if (size(mean) < 0) return
      if (self%thermal%mode == THERMAL_OFF) return
      call set_history_value(h, "exit_fluid_temp_K", ieee_value(1.0_wp, ieee_quiet_nan))
      if (.not. self%thermal%have_field) return
      e = itoa(h%element)
      associate (f => self%thermal%field, ld => self%eom%loads(h%element))
         call set_history_value(h, "exit_fluid_temp_K", f%exit_temperature)
         if (ld%load(1) > 0.0_wp) call set_history_value(h, "re"//e//"_contact_temp_outer_K", &
                                                         f%contact_outer(h%element))
         if (ld%load(2) > 0.0_wp) call set_history_value(h, "re"//e//"_contact_temp_inner_K", &
                                                         f%contact_inner(h%element))
      end associate
   end subroutine roller_record_row

   !> The equations of motion in self%condition: its load on the inner race and its degrees
   !> of freedom; the geometry mounted at its geometry temperatures (roller_geometry) once
   !> they differ from the initial ones.  Input error when the cage is freed or constrained
   !> beyond what the roller model has.
   subroutine roller_mount(self, y, error)
      class(roller_kind_t), intent(inout) :: self
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      associate (c => self%condition)
         if (.not. c%constraints%cage%rotation(1) .or. &
             any([c%constraints%cage%translation, c%constraints%cage%rotation(2:3)] .neqv. self%eom%cage_free)) then
            call input_error(error, "roller bearing: the cage turns about its axis and, run option cage=free, "// &
                             "is free in all six degrees of freedom; other cage constraints are not modelled")
            return
         end if
         self%eom%force = c%force
         self%eom%constraints = c%constraints
         if (any(c%geometry_temperature /= self%bearing%temperature) .or. self%thermal%geometry_updates > 0) &
            call roller_geometry(self, c%geometry_temperature)
      end associate
      if (size(y) < 0) call engine_error(error, "roller bearing: empty state")
   end subroutine roller_mount

   !> The roller bearing's geometry at bulk temperatures temperature(7) (K; ADRC2, report 2.9,
   !> 4.3; docs/thermal.md "Roller runs"): the fits changed by the differential expansion
   !> (distorted_bearing), the races mounted with them (Lame, spin; raceways moved by twice
   !> the mounting as at step 0) and grown freely, the roller grown freely in diameter and
   !> length (every length of its profile by alpha dT, Timoshenko & Goodier ch. 13), the
   !> pocket clearance by the cage's and the roller's growth (thermal_distortion), the guide
   !> lands in the mounted raceways; the slice contact model rebuilt on them.
   subroutine roller_geometry(self, temperature)
      class(roller_kind_t), intent(inout) :: self
      real(wp), intent(in) :: temperature(:)
      type(bearing_t) :: bt
      type(distortion_t) :: dist
      real(wp) :: e
      bt = distorted_bearing(self%bearing, temperature)
      self%geometry = mount_geometry(bt, temperature, 2)
      e = self%bearing%material(BODY_ELEMENT)%expansion*(temperature(TEMP_ELEMENT) - &
                                                        self%bearing%temperature(TEMP_ELEMENT))
      bt%d = self%geometry%element_diameter
      bt%roller%roller_length = bt%roller%roller_length*(1.0_wp + e)
      bt%roller%roller_land = bt%roller%roller_land*(1.0_wp + e)
      bt%roller%crown_radius = bt%roller%crown_radius*(1.0_wp + e)
      bt%roller%corner_radius = bt%roller%corner_radius*(1.0_wp + e)
      self%eom%model%qs = roller_qs_model(bt, self%geometry, self%step0%model%n_sub)
      dist = thermal_distortion(self%bearing, temperature)
      self%eom%model%pocket_clearance = dist%pocket_clearance
      self%eom%model%pocket_length = bt%roller%roller_length - sum(bt%roller%corner_radius)
      self%eom%lands = guide_land_pairs(bt, self%geometry, temperature)
   end subroutine roller_geometry

   !> The thermal update at the end of an averaging interval (time s, state y at tau = time /
   !> T; report 2.10 steps 2-12, 5.5): the field solved with the heat averaged over the
   !> interval (roller_thermal_update), the bulk temperatures set; in THERMAL_GEOMETRY mode
   !> from the geometry start time on, the geometry mounted at them (roller_geometry) and the
   !> inner race moved so that its rollers carry the applied load (hold_race_load).  Nothing
   !> without a thermal model.
   subroutine roller_on_event(self, time, it, y, error)
      class(roller_kind_t), intent(inout) :: self
      real(wp), intent(in) :: time
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      type(operating_condition_t) :: c
      real(wp) :: dydt(size(y)), t, f(3)
      logical :: geometry, free(3)
      if (self%thermal%mode == THERMAL_OFF) return
      call roller_thermal_update(self%thermal, self%bearing, self%eom, y, time, error)
      if (allocated(error)) return
      c = thermal_condition(self%thermal, self%condition, time, geometry)
      if (geometry) self%thermal%geometry_updates = self%thermal%geometry_updates + 1
      call self%set_condition(c, it, y, error)
      if (allocated(error)) return
      if (.not. geometry) return
      t = time/self%time_scale
      ! the race moves where its rollers hold it: radially, and axially only on flanges (without
      ! them nothing but the applied load acts along the axis)
      free = self%condition%constraints%inner%translation .and. [any(self%bearing%roller%flange), .true., .true.]
      call hold_race_load(net_force, y, ROLLER_SIZE*self%eom%n + RACE_OFFSET, free, &
                          max(norm2(self%condition%force), tiny(1.0_wp)), self%hold_initial, self%hold_residual, &
                          self%hold_solves, error)
      if (allocated(error)) return
      ! the equations of motion's loads and self%y at the state the run goes on from
      call net_force(y, f, geometry)
      call it%restart(it%h_next)
   contains

      !> The net force (N) on the inner race at (t, yy): its mass times its acceleration
      !> (adore_dynamics_roller_system); ok false when the equations of motion fail there.
      subroutine net_force(yy, force, ok)
         real(wp), intent(in) :: yy(:)
         real(wp), intent(out) :: force(3)
         logical, intent(out) :: ok
         integer :: flag, r0
         call self%eval(t, yy, dydt, flag)
         ok = flag == DERIV_OK
         force = 0.0_wp
         r0 = ROLLER_SIZE*self%eom%n + RACE_OFFSET
         if (ok) force = self%bearing%mass(BODY_INNER)*dydt(r0 + 4:r0 + 6)/self%time_scale
      end subroutine net_force

   end subroutine roller_on_event

end module adore_bearings_roller
