!> The ball bearing as a bearing kind (adore_bearings_system): its quasi-static start
!> (adore_start_ball_step0), its equations of motion (adore_dynamics_ball_system), its
!> printed steps (adore_output_step_report, adore_output_ball_dynamic_report), its time
!> history (adore_output_run_history) and what the run says about its physics.
!>
!> The run's physics defaults are the equations of motion's (docs/dynamics.md, "The run's
!> physics"); the run options (adore_model_run_options) choose the start hypothesis, the
!> moment equilibrium of the start and the 1-D traction developer option.  No module state.
module adore_bearings_ball
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error, input_error
   use adore_core_strings, only: itoa, upper
   use adore_core_threads, only: run_threads
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE
   use adore_model_condition, only: operating_condition_t, condition_of, default_constraints, cage_option_free, &
                                    dof_constraints_t, deck_constraints
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_state_bearing_state, only: bearing_state_t, body_azimuth, set_packed_temperatures, BODY_SIZE, RACE_INNER, &
                                        packed_name
   use adore_thermal_distortion, only: distorted_bearing
   use adore_thermal_network, only: thermal_heat_t
   use adore_bearings_ball_thermal, only: ball_thermal_t, ball_heat_rates, &
                                          ball_thermal_accumulate, ball_thermal_update, THERMAL_OFF
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, guide_land_pairs, total_power_loss
   use adore_bearings_thermal_run, only: hold_race_load, thermal_run_text, thermal_run_for, thermal_condition
   use adore_forces_ball_power, only: ball_balance_values, N_BALANCE, BAL_DRIVE, BAL_RACE_HEAT, BAL_DAMPING, &
                                      BAL_CAGE_WORK, BAL_CAGE_HEAT, BAL_ENERGY, BAL_INNER_FORCE, BAL_OUTER_FORCE, &
                                      BAL_WHIRL_FRAME, BAL_INNER_MOMENTUM
   use adore_dynamics_cage_whirl, only: whirl_frame_acceleration
   use adore_tribology_wear, only: archard_wear_rate
   use adore_quasistatic_ball_start, only: start_method_from_name, start_contact_load
   use adore_start_ball_step0, only: ball_step0_t, solve_ball_step0, BALL_START_METHOD
   use adore_dynamics_integrator, only: integrator_t, DERIV_OK
   use adore_dynamics_ball_system, only: ball_system_t, start_ball_dynamics
   use adore_bearings_system, only: bearing_system_t, run_int_method, asked_steps, adopt_failure
   use adore_output_step_report, only: write_ball_step0
   use adore_output_ball_dynamic_report, only: write_ball_step, dynamic_speed_ratios, dynamic_lives, orbital_speed, &
                                                pocket_excursion, cage_wear_sliding
   use adore_output_run_history, only: run_history_t, new_ball_history, record_ball_history, ball_element_row, &
                                       add_history_column, set_history_value, set_step0_row
   use adore_output_ball_contact_print, only: contact_print_t, ball_contact_print
   implicit none
   private

   public :: ball_kind_t, ball_averaged_values

   !> Positions in the vector of ball_averaged_values: power loss (W), the three speed
   !> ratios, the outer and inner race wear (m**3/s), the damage rate 1/L of the modified
   !> life (1/h), the cage's wear (m**3/s), the RE excursion (m), then each ball's wear, each
   !> pocket's wear and each guide land's wear (m**3/s).
   integer, parameter, public :: AVG_POWER = 1, AVG_RATIOS = 2, AVG_RACE_WEAR = 5, AVG_DAMAGE = 7, &
                                 AVG_CAGE_WEAR = 8, AVG_EXCURSION = 9, AVG_BALL_WEAR = 10
   !> Power (W) below which a run's balance has nothing to close (a shaft at rest).
   real(wp), parameter :: MIN_BALANCED_POWER = 1.0e-6_wp

   !> A ball bearing run.
   type, extends(bearing_system_t) :: ball_kind_t
      type(ball_step0_t) :: step0           !< the quasi-static start
      type(ball_system_t) :: eom            !< the equations of motion (model data inside)
      real(wp), allocatable :: azimuth(:)   !< each ball's orbital position, unwrapped (rad)
      real(wp), allocatable :: last(:)      !< each ball's orbital position at the last step (rad)
      real(wp) :: axial_origin = 0.0_wp     !< the print's axial origin of the balls (m)
      real(wp) :: clearance = 0.0_wp        !< guide land diametral clearance (m; NaN: no land)
      type(ball_thermal_t) :: thermal       !< the thermal model (adore_bearings_ball_thermal)
      !> worst relative equilibrium residual of the inner race after a load-holding solve
      !> (|net force| / |applied load|), and the solves done
      real(wp) :: hold_residual = 0.0_wp
      !> the largest |net force| / |applied load| a geometry update left before the solve
      real(wp) :: hold_initial = 0.0_wp
      integer :: hold_solves = 0
      !> the printed tribology (no flash) of the last accepted state (ball_accepted), reused
      !> by the averages and the history row of that state; current until the next
      !> evaluation, mounting or thermal event
      type(contact_print_t) :: tribology
      logical :: tribology_current = .false.
   contains
      procedure :: eval => ball_eval
      procedure :: border_shares => ball_border_shares
      procedure :: solve_start => ball_solve_start
      procedure :: write_start => ball_write_start
      procedure :: dynamic_steps => ball_dynamic_steps
      procedure :: start_dynamics => ball_start_dynamics
      procedure :: listing_lines => ball_listing_lines
      procedure :: run_note => ball_run_note
      procedure :: n_values => ball_n_values
      procedure :: averaged_values => ball_values
      procedure :: accepted => ball_accepted
      procedure :: write_step => ball_write_step
      procedure :: new_history => ball_new_history
      procedure :: record_row => ball_record_row
      procedure :: mount => ball_mount
      procedure :: on_event => ball_on_event
      procedure :: n_balance => ball_n_balance
      procedure :: balance_values => ball_balance
      procedure :: balance_text => ball_balance_text
      procedure :: balance_defect => ball_balance_defect
      procedure :: start_load => ball_start_load
      procedure :: unknown_name => ball_unknown_name
   end type ball_kind_t


   !> What a ball run records and reports - the averaged values, the accepted state, the printed
   !> steps, the time history and the balance: submodule adore_bearings_ball_results
   !> (fortran/bearings/ball_results.f90).
   interface
      !> The length of ball_averaged_values' vector for this bearing.
      module integer function ball_n_values(self)
         class(ball_kind_t), intent(in) :: self
      end function ball_n_values
      !> ball_averaged_values at the last evaluated state.
      module subroutine ball_values(self, v)
         class(ball_kind_t), intent(in) :: self
         real(wp), intent(out) :: v(:)
      end subroutine ball_values
      !> The accepted state: each ball's unwrapped orbital position and its printed tribology.
      module subroutine ball_accepted(self)
         class(ball_kind_t), intent(inout) :: self
      end subroutine ball_accepted
      !> A printed time step (adore_output_ball_dynamic_report) at the last evaluated state.
      module subroutine ball_write_step(self, unit, step, t, mean)
         class(ball_kind_t), intent(in) :: self
         integer, intent(in) :: unit, step
         real(wp), intent(in) :: t, mean(:)
      end subroutine ball_write_step
      !> The ball history (new_ball_history) with the options' element and stride.
      module subroutine ball_new_history(self, h, n_steps, error)
         class(ball_kind_t), intent(in) :: self
         type(run_history_t), intent(out) :: h
         integer, intent(in) :: n_steps
         type(error_type), allocatable, intent(out) :: error
      end subroutine ball_new_history
      !> A history row and its element row at the last evaluated state.
      module subroutine ball_record_row(self, h, step, t, mean)
         class(ball_kind_t), intent(in) :: self
         type(run_history_t), intent(inout) :: h
         integer, intent(in) :: step
         real(wp), intent(in) :: t, mean(:)
      end subroutine ball_record_row
      !> The number of balance values (adore_forces_ball_power's N_BALANCE).
      module integer function ball_n_balance(self)
         class(ball_kind_t), intent(in) :: self
      end function ball_n_balance
      !> adore_forces_ball_power's balance values at the last evaluated state.
      module subroutine ball_balance(self, v)
         class(ball_kind_t), intent(in) :: self
         real(wp), intent(out) :: v(:)
      end subroutine ball_balance
      !> The run note's balance line over the window [window(1), window(2)] (tau); hint: what
      !> resolves the window's steps when the closure misses (the time loop's, from its steps).
      module subroutine ball_balance_text(self, window, mean, first, last, hint, text)
         class(ball_kind_t), intent(in) :: self
         real(wp), intent(in) :: window(2), mean(:), first(:), last(:)
         character(len=*), intent(in) :: hint
         character(len=:), allocatable, intent(out) :: text
      end subroutine ball_balance_text
      !> The power balance's defect over a time step (J; the integrator's balance control).
      module subroutine ball_balance_defect(self, g0, g1, q, h, defect, flow)
         class(ball_kind_t), intent(in) :: self
         real(wp), intent(in) :: g0(:), g1(:), q(:), h
         real(wp), intent(out) :: defect, flow
      end subroutine ball_balance_defect
   end interface

contains

   !> dy/dtau of the equations of motion (adore_dynamics_ball_system).
   subroutine ball_eval(self, t, y, dydt, flag)
      class(ball_kind_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      self%tribology_current = .false.
      call self%eom%eval(t, y, dydt, flag)
      call adopt_failure(self, self%eom)
   end subroutine ball_eval

   !> The equations of motion's border shares of the last evaluation (ball_system_t's: the
   !> integrator's border rows of the arrowhead Jacobian, docs/integrator.md "The arrowhead").
   subroutine ball_border_shares(self, shares, ok)
      class(ball_kind_t), intent(in) :: self
      real(wp), intent(out) :: shares(:, :)
      logical, intent(out) :: ok
      call self%eom%border_shares(shares, ok)
   end subroutine ball_border_shares

   !> The name of unknown i of the packed state (adore_state_bearing_state's packed_name: the
   !> balls in the frame the run packs them in), e.g. "ball 2's angular velocity (body x)".
   subroutine ball_unknown_name(self, i, name)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: i
      character(len=:), allocatable, intent(out) :: name
      call packed_name(i, self%bearing%n_elements, "ball", name, self%eom%orbit_frame)
   end subroutine ball_unknown_name

   !> Step 0: mounting, equilibrium, ball speeds (the options' start hypothesis, report
   !> 4.4.7; moment equilibrium when asked), tribology, life, cage.
   subroutine ball_solve_start(self, error)
      class(ball_kind_t), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
      integer :: start_method
      start_method = BALL_START_METHOD
      if (len_trim(self%options%ball_start) > 0) then
         call start_method_from_name(self%options%ball_start, start_method, error)
         if (allocated(error)) return
      end if
      self%condition = condition_of(self%bearing)
      call solve_ball_step0(self%bearing, self%step0, error, start_method, self%options%moment_equilibrium)
   end subroutine ball_solve_start

   !> The start's largest race contact load (N): the time scale's load when it exceeds the
   !> applied load (adore_model_scales).
   real(wp) function ball_start_load(self) result(q)
      class(ball_kind_t), intent(in) :: self
      q = start_contact_load(self%step0%start)
   end function ball_start_load

   !> Step 0 in the ADORE 5.0 layout.
   subroutine ball_write_start(self, unit)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: unit
      call write_ball_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], self%bearing, self%step0)
   end subroutine ball_write_start

   !> The options' steps: Rec 1 n_steps for STEPS_FROM_DECK.
   integer function ball_dynamic_steps(self) result(n)
      class(ball_kind_t), intent(in) :: self
      n = asked_steps(self%bearing, self%options)
   end function ball_dynamic_steps

   !> The dynamics from the step-0 start (start_ball_dynamics) at the initial temperatures, in
   !> the geometry step 0 mounted (computed once).
   subroutine ball_start_dynamics(self, it, y, error)
      class(ball_kind_t), intent(inout) :: self
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: method
      logical :: cage_free
      call cage_option_free(self%options%cage, self%bearing%dof_flags, cage_free, error)
      if (allocated(error)) return
      call ball_deck_dof_check(self%bearing%dof_flags, error)
      if (allocated(error)) return
      method = run_int_method(self%options%integrator, self%bearing%controls%int_method)
      call start_ball_dynamics(self%bearing, self%step0%geometry, self%step0%start, self%step0%cage_start, self%eom, it, y, &
                               error, two_d=self%options%traction_2d, orbit_frame=self%options%ball_frame == "orbit", &
                               int_method=method, cage_free=cage_free, &
                               adore_whirl=self%options%cage_whirl == "adore", &
                               method_switch=self%options%integrator == "deck", &
                               balance_tolerance=self%options%balance_tolerance)
      if (allocated(error)) return
      self%time_scale = self%eom%time_scale
      self%eom%rolling_resistance = self%options%rolling_resistance
      self%eom%threads = run_threads(self%options%threads)
      it%jac%threads = self%eom%threads      ! the integrator's block factors on the same team
      ! the run's degrees of freedom are the condition's from now on (report 4.4.6)
      self%condition%constraints = default_constraints(self%eom%cage_spin_only)
      self%eom%constraints = self%condition%constraints
      associate (e => self%step0%start%equilibrium)
         self%axial_origin = e%u(1) - e%axial_displacement
         self%azimuth = e%azimuth
         self%last = e%azimuth
      end associate
      self%clearance = guide_clearance(self%bearing, self%step0%geometry, self%eom%state%temperature)
      ! the thermal model (docs/thermal.md, "The wiring"): an event at the end of every
      ! averaging interval
      self%thermal%thermal_run_t = thermal_run_for(self%bearing, self%options, error)
      if (allocated(error)) return
      if (self%thermal%mode /= THERMAL_OFF) then
         self%event_start = self%thermal%interval
         self%event_period = self%thermal%interval
         ! ADORE 5.0's traction does not follow the computed temperatures (report 5.3: "the
         ! traction model constants are presently not subject to change as the bulk
         ! temperatures of the bearing elements vary"; 7 rec. 1): the race contacts'
         ! lubricant stays at the initial temperatures unless the run asks otherwise
         if (.not. self%options%thermal_traction) self%eom%lubricant_temperature = self%bearing%temperature
      end if
   end subroutine ball_start_dynamics

   !> The print listing's lines on the physics of the time integration.
   subroutine ball_listing_lines(self, n_steps, text)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      character(len=*), parameter :: lf = new_line("a")
      character(len=16) :: num
      text = ""
      if (n_steps < 1) return
      call thermal_text(self, .true., text)
      text = text//lf
      associate (s => self%eom)
         if (.not. s%cage) text = text//"  CAGE CONTACTS OFF: NO POCKET OR GUIDE-LAND FORCES"//lf
         if (s%cage .and. s%cage_spin_only) text = text//"  CAGE CENTRED ON THE BEARING AXIS, TURNING ABOUT IT "// &
            "ONLY (DOF CONSTRAINT, REPORT 4.4.6)"//lf
         if (s%cage .and. .not. s%cage_spin_only) then
            text = text//"  CAGE FREE: ALL SIX DEGREES OF FREEDOM INTEGRATED (REPORT 4.4.6"
            if (self%options%cage == "deck") text = text//"; AS THE DECK'S REC 3.3 SAYS"
            text = text//")"//lf
         end if
         if (s%cage .and. .not. s%cage_spin_only .and. s%adore_whirl) text = text//"  CAGE MASS CENTRE IN "// &
            "ADORE'S WHIRL COORDINATES (REPORT 4.4.4; NO CENTRIPETAL OR CORIOLIS TERMS, docs/cage.md)"//lf
         if (s%cage .and. .not. s%land_film) text = text//"  GUIDE-LAND FILM OFF: METALLIC GUIDE-LAND CONTACT "// &
            "ONLY (docs/cage.md, Cage dynamics)"//lf
         if (s%gyro_restraint) text = text//"  BALL GYROSCOPIC MOMENTS CARRIED BY THE RACES WITHOUT SLIP "// &
            "(docs/dynamics.md)"//lf
         if (s%contact_damping > 0.0_wp) then
            write (num, "(es10.3)") s%contact_damping
            text = text//"  BALL/RACE CONTACT DAMPING "//trim(adjustl(num))//" S (STIFFNESS-PROPORTIONAL, "// &
                   "docs/dynamics.md)"//lf
         end if
         if (s%rolling_resistance) text = text//"  EHD ROLLING RESISTANCE OF THE RACE CONTACTS (HOUPERT; "// &
            "docs/tribology.md)"//lf
         if (self%options%boundary_friction > 0.0_wp) then
            write (num, "(es10.3)") self%options%boundary_friction
            text = text//"  BOUNDARY FRICTION "//trim(adjustl(num))//" (COULOMB) WHERE THE DECK'S TRACTION CURVE "// &
                   "WOULD ACT (docs/tribology.md)"//lf
         end if
         if (.not. s%traction_2d) text = text//"  ONE-DIMENSIONAL RACE TRACTION (SLIP ALONG THE ROLLING "// &
            "DIRECTION ONLY, REPORT EQ 1): DEVELOPER OPTION"//lf
      end associate
   end subroutine ball_listing_lines

   !> What the time integration leaves out or assumes (blank without time steps).
   subroutine ball_run_note(self, n_steps, text)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      character(len=16) :: buf
      text = ""
      if (n_steps < 1) return
      associate (s => self%eom)
         call thermal_text(self, .false., text)
         if (.not. s%cage) text = text//"; cage contacts off (no pocket or guide-land forces)"
         if (s%cage .and. s%cage_spin_only) text = text//"; cage centred, turning about its axis only "// &
                                                   "(translation and tilt constrained, report 4.4.6)"
         if (s%cage .and. .not. s%cage_spin_only) text = text//"; cage free in all six degrees of freedom "// &
                                                   "(report 4.4.6)"
         if (s%cage .and. .not. s%cage_spin_only) then
            if (s%adore_whirl) then
               text = text//"; its mass centre in ADORE's whirl coordinates (r'' = F_r/m, r psi'' = F_t/m: "// &
                      "no centripetal or Coriolis acceleration, report 4.4.4; cage_whirl=inertial for Newton's)"
            else
               text = text//"; its mass centre by Newton's inertial equations (cage_whirl=inertial)"
            end if
            if (self%step0%cage_start%start_scale < 1.0_wp) then
               write (buf, "(f0.4)") self%step0%cage_start%start_scale
               text = text//"; the cage started at "//trim(buf)//" x its Rec 9.5.1 offset from the guiding "// &
                      "race: the deck's centre puts a ball into its pocket or the cage into a land (step 0's "// &
                      "negative Geo Int)"
            end if
         end if
         if (s%cage .and. .not. s%land_film) text = text//"; guide-land film off (metallic land contact only)"
         if (s%cage .and. s%land_film .and. .not. s%cage_spin_only) then
            write (buf, "(es10.3)") s%bearing%land_oil_layer
            text = text//"; guide-land film where the gap is below the lands' oil layer of "//trim(adjustl(buf))// &
                   " m (run option land_oil; docs/cage.md, starved land)"
         end if
         if (s%gyro_restraint) text = text//"; ball gyroscopic moments carried by the races without slip"
         if (s%contact_damping > 0.0_wp) text = text//"; ball/race contact damping (stiffness-proportional)"
         if (s%rolling_resistance) text = text//"; EHD rolling resistance of the race contacts"
         if (self%options%boundary_friction > 0.0_wp) text = text//"; boundary friction (Coulomb) where the "// &
                                                         "deck's traction curve would act"
      end associate
   end subroutine ball_run_note

   !> The thermal model of the run in one line (thermal_run_text): the print listing's
   !> (listing: indented, upper case) or the run note's.
   subroutine thermal_text(self, listing, text)
      class(ball_kind_t), intent(in) :: self
      logical, intent(in) :: listing
      character(len=:), allocatable, intent(out) :: text
      call thermal_run_text(self%thermal, listing, text)
   end subroutine thermal_text


   !> The equations of motion in self%condition: the geometry mounted at its temperatures
   !> (adore_geometry_mounted: fits, growth, clearance from the initial temperatures), its
   !> load on the inner race, its degrees of freedom, the state's temperatures in y, the
   !> guide clearance anew.
   subroutine ball_mount(self, y, error)
      class(ball_kind_t), intent(inout) :: self
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      self%tribology_current = .false.
      if (.not. allocated(self%eom%state%elements)) then
         call engine_error(error, "ball bearing: mount before the dynamics started")
         return
      end if
      associate (c => self%condition)
         ! the geometry at its own temperatures (ADRC2: the fits changed by the differential
         ! expansion, then mounted with the free growth; docs/thermal.md)
         if (all(c%geometry_temperature == self%bearing%temperature)) then
            self%eom%geometry = mount_geometry(self%bearing, c%geometry_temperature)
         else
            self%eom%geometry = mount_geometry(distorted_bearing(self%bearing, c%geometry_temperature), &
                                               c%geometry_temperature)
         end if
         self%eom%bearing%force = c%force
         self%eom%bearing%moment = c%moment
         self%eom%constraints = c%constraints
         call set_packed_temperatures(y, self%bearing%n_elements, c%temperature)
         self%clearance = guide_clearance(self%bearing, self%eom%geometry, c%temperature)
      end associate
   end subroutine ball_mount

   !> The thermal update at the end of an averaging interval (time s, state y at tau =
   !> time / T; report 2.10 steps 2-12): the network solved with the heat averaged over the
   !> interval, the bulk temperatures set; in THERMAL_GEOMETRY mode from the geometry start
   !> time on, the geometry mounted at them and the inner race moved so that its contacts
   !> carry the applied load (hold_applied_load).  Nothing without a thermal model.
   subroutine ball_on_event(self, time, it, y, error)
      class(ball_kind_t), intent(inout) :: self
      real(wp), intent(in) :: time
      type(integrator_t), intent(inout) :: it
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      type(operating_condition_t) :: c
      logical :: geometry
      self%tribology_current = .false.
      if (self%thermal%mode == THERMAL_OFF) return
      call ball_thermal_update(self%thermal, self%bearing, self%eom%state, time, error)
      if (allocated(error)) return
      c = thermal_condition(self%thermal, self%condition, time, geometry)
      call self%set_condition(c, it, y, error)
      if (allocated(error)) return
      if (geometry) then
         self%thermal%geometry_updates = self%thermal%geometry_updates + 1
         call hold_applied_load(self, time/self%time_scale, y, error)
         if (allocated(error)) return
         call it%restart(it%h_next)
      end if
   end subroutine ball_on_event

   !> The load-holding constraint of a geometry update (hold_race_load): the inner race's
   !> free translations in y (state at tau = t) moved, the balls and every velocity held,
   !> until the net force on the race (its contacts and the applied load) is below 1e-6 of
   !> the applied load.  The outer race is fixed in the housing.  self%hold_residual: the
   !> worst final |net force| / |applied load|.
   subroutine hold_applied_load(self, t, y, error)
      class(ball_kind_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: dydt(size(y))
      call hold_race_load(net_force, y, BODY_SIZE*(self%bearing%n_elements + 2), &
                          self%condition%constraints%inner%translation, &
                          max(norm2(self%condition%force), tiny(1.0_wp)), self%hold_initial, self%hold_residual, &
                          self%hold_solves, error)
      if (allocated(error) .and. allocated(self%eom%failure_reason)) then
         if (index(error%message, "equations of motion failed") > 0) &
            error%message = error%message//": "//self%eom%failure_reason
      end if
   contains

      !> The net force (N) on the inner race at (t, yy): its mass times its acceleration;
      !> ok false when the equations of motion fail there.
      subroutine net_force(yy, force, ok)
         real(wp), intent(in) :: yy(:)
         real(wp), intent(out) :: force(3)
         logical, intent(out) :: ok
         integer :: flag
         call self%eom%eval(t, yy, dydt, flag)
         ok = flag == DERIV_OK
         force = 0.0_wp
         if (ok) force = self%bearing%mass(BODY_INNER)*self%eom%rates%races(RACE_INNER)%velocity
      end subroutine net_force

   end subroutine hold_applied_load

   !> The quantities the print shows as time averages, at one state s of ball bearing b
   !> (mounted geometry g) with the force assembly's loads there, into v (size
   !> ball_n_values): the total power loss of the race contacts (W), dynamic_speed_ratios,
   !> the Archard wear rates (adore_tribology_wear, as step 0 computes them) of the outer and
   !> inner race (over all their contacts) and of each ball (over both its contacts), from
   !> each contact's integral of |slip| dQ of the rolling-direction traction model (0 where
   !> unloaded); the damage rate 1/L (1/h) of the modified life L of this state
   !> (dynamic_lives: its average inverted is the Palmgren-Miner life); the cage's Archard
   !> wear (cage material) of each pocket and guide land (cage_wear_sliding) and their sum;
   !> the RE excursion (pocket_excursion).  lubricant_temperature: as the force assembly's.
   !> tribology, when given: ball_contact_print's result (no flash) at this state.
   subroutine ball_averaged_values(b, g, s, loads, v, lubricant_temperature, tribology)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(out) :: v(:)
      real(wp), intent(in), optional :: lubricant_temperature(:)
      type(contact_print_t), intent(in), optional :: tribology
      type(contact_print_t) :: p
      real(wp) :: w_orb(b%n_elements), lives(2), pockets(b%n_elements), lands(max(b%n_lands, 0))
      integer :: k, n
      n = b%n_elements
      v(AVG_POWER) = total_power_loss(loads)
      v(AVG_RATIOS:AVG_RATIOS + 2) = dynamic_speed_ratios(b, s)
      v(AVG_RACE_WEAR) = archard_wear_rate(b%material(BODY_OUTER)%wear, b%material(BODY_OUTER)%hardness, &
                                           sum(loads%traction(1, :)%sliding))
      v(AVG_RACE_WEAR + 1) = archard_wear_rate(b%material(BODY_INNER)%wear, b%material(BODY_INNER)%hardness, &
                                               sum(loads%traction(2, :)%sliding))
      do k = 1, n
         v(AVG_BALL_WEAR - 1 + k) = archard_wear_rate(b%material(BODY_ELEMENT)%wear, &
                                                      b%material(BODY_ELEMENT)%hardness, &
                                                      loads%traction(1, k)%sliding + loads%traction(2, k)%sliding)
         w_orb(k) = orbital_speed(s%elements(k))
      end do
      if (present(tribology)) then
         lives = dynamic_lives(b, g, loads, tribology, w_orb)
      else
         call ball_contact_print(b, g, s, loads, p, flash=.false., lubricant_temperature=lubricant_temperature)
         lives = dynamic_lives(b, g, loads, p, w_orb)
      end if
      v(AVG_DAMAGE) = 0.0_wp
      if (lives(2) > 0.0_wp) v(AVG_DAMAGE) = 1.0_wp/lives(2)      ! an infinite life: no damage
      call cage_wear_sliding(b, loads, pockets, lands)
      v(AVG_BALL_WEAR + n:AVG_BALL_WEAR + 2*n - 1) = archard_wear_rate(b%material(BODY_CAGE)%wear, &
                                                                     b%material(BODY_CAGE)%hardness, pockets)
      v(AVG_BALL_WEAR + 2*n:) = archard_wear_rate(b%material(BODY_CAGE)%wear, b%material(BODY_CAGE)%hardness, lands)
      v(AVG_CAGE_WEAR) = sum(v(AVG_BALL_WEAR + n:))
      v(AVG_EXCURSION) = pocket_excursion(loads)
   end subroutine ball_averaged_values

   !> Diametral clearance (m) of the cage's guide: the smallest effective diametral play of
   !> its guide lands at bulk temperatures temperature (adore_forces_ball_bearing's land
   !> pairs); NaN without a guide land.
   function guide_clearance(b, g, temperature) result(c)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      real(wp), intent(in) :: temperature(:)
      real(wp) :: c
      if (b%n_lands < 1) then
         c = ieee_value(1.0_wp, ieee_quiet_nan)
         return
      end if
      associate (pairs => guide_land_pairs(b, g, temperature))
         c = 2.0_wp*minval(pairs%clearance)
      end associate
   end function guide_clearance

   !> Rec 3.3 read for the balls whatever the run option cage (report 4.4.6; adore_model_condition's
   !> deck_constraints): an unidentified pattern is an input error naming its field, and a
   !> pattern that holds rolling-element DOFs (Appendix D's, for rollers) too - the ball kind
   !> integrates every DOF of its balls.
   subroutine ball_deck_dof_check(flags, error)
      integer, intent(in) :: flags(:)
      type(error_type), allocatable, intent(out) :: error
      type(dof_constraints_t) :: deck
      call deck_constraints(flags, deck, error)
      if (allocated(error)) return
      if (.not. (all(deck%elements%translation) .and. all(deck%elements%rotation))) &
         call input_error(error, "Rec 3.3: the flags hold rolling-element degrees of freedom (report 4.4.6), "// &
                          "which the ball kind does not model (every ball DOF is integrated)")
   end subroutine ball_deck_dof_check

end module adore_bearings_ball
