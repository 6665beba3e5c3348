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
   use adore_core_error, only: error_type, engine_error
   use adore_core_strings, only: itoa
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER
   use adore_model_condition, only: condition_of, default_constraints
   use adore_model_run_options, only: STEPS_FROM_DECK
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_state_bearing_state, only: bearing_state_t, body_azimuth, set_packed_temperatures
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, guide_land_pairs, total_power_loss
   use adore_forces_ball_power, only: ball_balance_values, N_BALANCE, BAL_DRIVE, BAL_RACE_HEAT, BAL_DAMPING, &
                                      BAL_CAGE_WORK, BAL_CAGE_HEAT, BAL_ENERGY, BAL_INNER_FORCE, BAL_OUTER_FORCE
   use adore_tribology_wear, only: archard_wear_rate
   use adore_quasistatic_ball_start, only: start_method_from_name
   use adore_start_ball_step0, only: ball_step0_t, solve_ball_step0, BALL_START_METHOD
   use adore_dynamics_integrator, only: integrator_t, INT_METHOD_BS32, INT_METHOD_DP54, INT_METHOD_ROS34PW2, &
                                        INT_METHOD_ARK436
   use adore_dynamics_ball_system, only: ball_system_t, start_ball_dynamics, ball_int_method
   use adore_bearings_system, only: bearing_system_t
   use adore_output_step_report, only: write_ball_step0
   use adore_output_ball_dynamic_report, only: write_ball_step, dynamic_speed_ratios
   use adore_output_run_history, only: run_history_t, new_ball_history, record_ball_history, ball_element_row
   use adore_output_ball_contact_print, only: contact_print_t, ball_contact_print
   implicit none
   private

   public :: ball_kind_t, ball_averaged_values

   !> Positions in the vector of ball_averaged_values: power loss (W), the three speed
   !> ratios, the outer and inner race wear (m**3/s), then each ball's wear (m**3/s).
   integer, parameter, public :: AVG_POWER = 1, AVG_RATIOS = 2, AVG_RACE_WEAR = 5, AVG_BALL_WEAR = 7

   !> A ball bearing run.
   type, extends(bearing_system_t) :: ball_kind_t
      type(ball_step0_t) :: step0           !< the quasi-static start
      type(ball_system_t) :: eom            !< the equations of motion (model data inside)
      real(wp), allocatable :: azimuth(:)   !< each ball's orbital position, unwrapped (rad)
      real(wp), allocatable :: last(:)      !< each ball's orbital position at the last step (rad)
      real(wp) :: axial_origin = 0.0_wp     !< the print's axial origin of the balls (m)
      real(wp) :: clearance = 0.0_wp        !< guide land diametral clearance (m; NaN: no land)
   contains
      procedure :: eval => ball_eval
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
      procedure :: n_balance => ball_n_balance
      procedure :: balance_values => ball_balance
      procedure :: balance_text => ball_balance_text
   end type ball_kind_t

contains

   !> dy/dtau of the equations of motion (adore_dynamics_ball_system).
   subroutine ball_eval(self, t, y, dydt, flag)
      class(ball_kind_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      call self%eom%eval(t, y, dydt, flag)
      if (allocated(self%eom%failure_reason)) then
         self%failure_reason = self%eom%failure_reason
      else if (allocated(self%failure_reason)) then
         deallocate (self%failure_reason)
      end if
   end subroutine ball_eval

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

   !> Step 0 in the ADORE 5.0 layout.
   subroutine ball_write_start(self, unit)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: unit
      call write_ball_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], self%bearing, self%step0)
   end subroutine ball_write_start

   !> The options' steps: Rec 1 n_steps for STEPS_FROM_DECK.
   integer function ball_dynamic_steps(self) result(n)
      class(ball_kind_t), intent(in) :: self
      if (self%options%steps == STEPS_FROM_DECK) then
         n = max(self%bearing%controls%n_steps, 0)
      else
         n = max(self%options%steps, 0)
      end if
   end function ball_dynamic_steps

   !> The dynamics from the step-0 start (start_ball_dynamics) at the initial temperatures, in
   !> the geometry step 0 mounted (computed once).
   subroutine ball_start_dynamics(self, it, y, error)
      class(ball_kind_t), intent(inout) :: self
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: method
      select case (self%options%integrator)
      case ("ark4")
         method = INT_METHOD_ARK436
      case ("ros34pw2")
         method = INT_METHOD_ROS34PW2
      case ("dp5")
         method = INT_METHOD_DP54
      case ("bs3")
         method = INT_METHOD_BS32
      case default    ! the deck's INT METHOD (ball_int_method)
         method = ball_int_method(self%bearing%controls%int_method)
      end select
      call start_ball_dynamics(self%bearing, self%step0%geometry, self%step0%start, self%step0%cage, self%eom, it, y, &
                               error, two_d=self%options%traction_2d, orbit_frame=self%options%ball_frame == "orbit", &
                               int_method=method)
      if (allocated(error)) return
      self%time_scale = self%eom%time_scale
      self%eom%rolling_resistance = self%options%rolling_resistance
      ! the run's degrees of freedom are the condition's from now on (report 4.4.6)
      self%condition%constraints = default_constraints(self%eom%cage_spin_only)
      self%eom%constraints = self%condition%constraints
      associate (e => self%step0%start%equilibrium)
         self%axial_origin = e%u(1) - e%axial_displacement
         self%azimuth = e%azimuth
         self%last = e%azimuth
      end associate
      self%clearance = guide_clearance(self%bearing, self%step0%geometry, self%eom%state%temperature)
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
      text = "  THERMAL MODEL OFF: BULK TEMPERATURES FIXED AT THE INITIAL ONES (REC 2.7)"//lf
      associate (s => self%eom)
         if (.not. s%cage) text = text//"  CAGE CONTACTS OFF: NO POCKET OR GUIDE-LAND FORCES"//lf
         if (s%cage .and. s%cage_spin_only) text = text//"  CAGE CENTRED ON THE BEARING AXIS, TURNING ABOUT IT "// &
            "ONLY (DOF CONSTRAINT, REPORT 4.4.6)"//lf
         if (s%cage .and. .not. s%land_film) text = text//"  GUIDE-LAND FILM OFF: METALLIC GUIDE-LAND CONTACT "// &
            "ONLY (docs/dynamics.md, Cage dynamics)"//lf
         if (s%gyro_restraint) text = text//"  BALL GYROSCOPIC MOMENTS CARRIED BY THE RACES WITHOUT SLIP "// &
            "(docs/dynamics.md)"//lf
         if (s%contact_damping > 0.0_wp) then
            write (num, "(es10.3)") s%contact_damping
            text = text//"  BALL/RACE CONTACT DAMPING "//trim(adjustl(num))//" S (STIFFNESS-PROPORTIONAL, "// &
                   "docs/dynamics.md)"//lf
         end if
         if (s%rolling_resistance) text = text//"  EHD ROLLING RESISTANCE OF THE RACE CONTACTS (HOUPERT; "// &
            "docs/tribology.md)"//lf
         if (.not. s%traction_2d) text = text//"  ONE-DIMENSIONAL RACE TRACTION (SLIP ALONG THE ROLLING "// &
            "DIRECTION ONLY, REPORT EQ 1): DEVELOPER OPTION"//lf
      end associate
   end subroutine ball_listing_lines

   !> What the time integration leaves out or assumes (blank without time steps).
   subroutine ball_run_note(self, n_steps, text)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      text = ""
      if (n_steps < 1) return
      associate (s => self%eom)
         text = "thermal model off: bulk temperatures fixed at the initial ones (Rec 2.7)"
         if (.not. s%cage) text = text//"; cage contacts off (no pocket or guide-land forces)"
         if (s%cage .and. s%cage_spin_only) text = text//"; cage centred, turning about its axis only "// &
                                                   "(translation and tilt constrained, report 4.4.6)"
         if (s%cage .and. .not. s%land_film) text = text//"; guide-land film off (metallic land contact only)"
         if (s%gyro_restraint) text = text//"; ball gyroscopic moments carried by the races without slip"
         if (s%contact_damping > 0.0_wp) text = text//"; ball/race contact damping (stiffness-proportional)"
         if (s%rolling_resistance) text = text//"; EHD rolling resistance of the race contacts"
      end associate
   end subroutine ball_run_note

   integer function ball_n_values(self)
      class(ball_kind_t), intent(in) :: self
      ball_n_values = AVG_BALL_WEAR - 1 + self%bearing%n_elements
   end function ball_n_values

   !> ball_averaged_values at the last evaluated state.
   subroutine ball_values(self, v)
      class(ball_kind_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      call ball_averaged_values(self%bearing, self%eom%state, self%eom%loads, v)
   end subroutine ball_values

   !> Each ball's orbital position unwrapped from step to step (a step moves a ball far
   !> less than half a revolution).
   subroutine ball_accepted(self)
      class(ball_kind_t), intent(inout) :: self
      integer :: k
      do k = 1, self%bearing%n_elements
         associate (phi => body_azimuth(self%eom%state%elements(k)))
            self%azimuth(k) = self%azimuth(k) + (modulo(phi - self%last(k) + pi, 2.0_wp*pi) - pi)
            self%last(k) = phi
         end associate
      end do
   end subroutine ball_accepted

   !> A printed time step (adore_output_ball_dynamic_report) at the last evaluated state.
   subroutine ball_write_step(self, unit, step, t, mean)
      class(ball_kind_t), intent(in) :: self
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: t, mean(:)
      real(wp) :: time
      time = t*self%time_scale
      associate (b => self%bearing)
         call write_ball_step(unit, step, [t, time, b%speed_outer*time/(2.0_wp*pi), &
                                           b%speed_inner*time/(2.0_wp*pi)], &
                              b, self%eom%geometry, self%eom%state, self%eom%rates, self%eom%loads, self%azimuth, &
                              self%axial_origin, mean(AVG_BALL_WEAR:), mean(AVG_RACE_WEAR:AVG_RACE_WEAR + 1), &
                              mean(AVG_POWER:AVG_RATIOS + 2))
      end associate
   end subroutine ball_write_step

   !> The ball history (new_ball_history) with the options' element and stride.
   subroutine ball_new_history(self, h, n_steps, error)
      class(ball_kind_t), intent(in) :: self
      type(run_history_t), intent(out) :: h
      integer, intent(in) :: n_steps
      type(error_type), allocatable, intent(out) :: error
      call new_ball_history(h, self%bearing, n_steps, self%options%history_element, error, &
                            self%options%history_stride)
   end subroutine ball_new_history

   !> A history row and its element row (ball_element_row, with the printed tribology of
   !> the race contacts; the flash temperature rise at printed rows only, h%printed) at the
   !> last evaluated state.
   subroutine ball_record_row(self, h, step, t, mean)
      class(ball_kind_t), intent(in) :: self
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: t, mean(:)
      type(contact_print_t) :: tribology
      call record_ball_history(h, step, t*self%time_scale, self%eom%state, self%eom%loads, mean(AVG_BALL_WEAR:), &
                               mean(AVG_RACE_WEAR:AVG_RACE_WEAR + 1), self%clearance)
      call ball_contact_print(self%bearing, self%eom%geometry, self%eom%state, self%eom%loads, tribology, &
                              flash=h%printed)
      call ball_element_row(h, self%eom%state, self%eom%loads, self%azimuth, tribology)
   end subroutine ball_record_row

   integer function ball_n_balance(self)
      class(ball_kind_t), intent(in) :: self
      ball_n_balance = N_BALANCE + 0*self%bearing%n_elements
   end function ball_n_balance

   !> adore_forces_ball_power's balance values at the last evaluated state (the equations
   !> of motion's loads, the condition's applied load).
   subroutine ball_balance(self, v)
      class(ball_kind_t), intent(in) :: self
      real(wp), intent(out) :: v(:)
      v = ball_balance_values(self%eom%bearing, self%eom%state, self%eom%loads)
   end subroutine ball_balance

   !> The run note's balance line over the window [window(1), window(2)] (tau) from the
   !> window's means of the balance values and their first and last values: drive power
   !> against the dissipation (contacts and cage, contact damping) and the mechanical
   !> energy's rate of change (adore_forces_ball_power: drive = dissipation + dE/dt); the
   !> inner race's mean contact force against the applied load and its weight (the residual
   !> is m dv/dt averaged), the outer race's against the housing's share.
   subroutine ball_balance_text(self, window, mean, first, last, text)
      class(ball_kind_t), intent(in) :: self
      real(wp), intent(in) :: window(2), mean(:), first(:), last(:)
      character(len=:), allocatable, intent(out) :: text
      character(len=700) :: buf
      real(wp) :: seconds, dissipation, rate, carried(3), housing(3)
      integer :: stat
      associate (b => self%eom%bearing)
         seconds = (window(2) - window(1))*self%time_scale
         dissipation = mean(BAL_RACE_HEAT) + mean(BAL_DAMPING) + mean(BAL_CAGE_WORK)
         rate = (last(BAL_ENERGY) - first(BAL_ENERGY))/seconds
         ! what the inner race's contacts carry: the applied load and the race's weight; the
         ! outer race's: that and the balls' weight (the cage's own constraint holds its weight)
         carried = b%force + b%mass(BODY_INNER)*b%gravity
         housing = carried + b%n_elements*b%mass(BODY_ELEMENT)*b%gravity
         write (buf, "(a,es10.4,a,es10.4,a,f0.2,a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es11.4,"// &
                "a,f0.5,a,3es12.4,a,3es12.4,a,es10.3,a,3es12.4,a,3es12.4,a,es10.3,a)", iostat=stat) &
            "balance over the last half of the run (t ", window(1)*self%time_scale, " to ", window(2)*self%time_scale, &
            " s, ", seconds*abs(b%speed_inner - b%speed_outer)/(2.0_wp*pi), " shaft revolutions): drive power ", &
            mean(BAL_DRIVE), " W, dissipation ", dissipation, " W (race contacts ", mean(BAL_RACE_HEAT), &
            " W, contact damping ", mean(BAL_DAMPING), " W, cage contacts ", mean(BAL_CAGE_WORK), &
            " W of which friction heat ", mean(BAL_CAGE_HEAT), " W), energy change ", rate, " W, drive/dissipation ", &
            mean(BAL_DRIVE)/dissipation, "; inner race contact force", mean(BAL_INNER_FORCE:BAL_INNER_FORCE + 2), &
            " N against applied load and weight", carried, " N, residual ", &
            norm2(mean(BAL_INNER_FORCE:BAL_INNER_FORCE + 2) + carried), " N; outer race contact force", &
            mean(BAL_OUTER_FORCE:BAL_OUTER_FORCE + 2), " N against", -housing, " N, residual ", &
            norm2(mean(BAL_OUTER_FORCE:BAL_OUTER_FORCE + 2) - housing), " N"
         text = trim(buf)
      end associate
   end subroutine ball_balance_text

   !> The equations of motion in self%condition: the geometry mounted at its temperatures
   !> (adore_geometry_mounted: fits, growth, clearance from the initial temperatures), its
   !> load on the inner race, its degrees of freedom, the state's temperatures in y, the
   !> guide clearance anew.
   subroutine ball_mount(self, y, error)
      class(ball_kind_t), intent(inout) :: self
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      if (.not. allocated(self%eom%state%elements)) then
         call engine_error(error, "ball bearing: mount before the dynamics started")
         return
      end if
      associate (c => self%condition)
         self%eom%geometry = mount_geometry(self%bearing, c%temperature)
         self%eom%bearing%force = c%force
         self%eom%bearing%moment = c%moment
         self%eom%constraints = c%constraints
         call set_packed_temperatures(y, self%bearing%n_elements, c%temperature)
         self%clearance = guide_clearance(self%bearing, self%eom%geometry, c%temperature)
      end associate
   end subroutine ball_mount

   !> The quantities the print shows as time averages, at one state s of ball bearing b
   !> with the force assembly's loads there, into v (size AVG_BALL_WEAR - 1 + n): the total
   !> power loss of the race contacts (W), dynamic_speed_ratios, and the Archard wear rates
   !> (adore_tribology_wear, as step 0 computes them) of the outer and inner race (over all
   !> their contacts) and of each ball (over both its contacts), from each contact's
   !> integral of |slip| dQ of the rolling-direction traction model (0 where unloaded).
   subroutine ball_averaged_values(b, s, loads, v)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(out) :: v(:)
      integer :: k
      v(AVG_POWER) = total_power_loss(loads)
      v(AVG_RATIOS:AVG_RATIOS + 2) = dynamic_speed_ratios(b, s)
      v(AVG_RACE_WEAR) = archard_wear_rate(b%material(BODY_OUTER)%wear, b%material(BODY_OUTER)%hardness, &
                                           sum(loads%traction(1, :)%sliding))
      v(AVG_RACE_WEAR + 1) = archard_wear_rate(b%material(BODY_INNER)%wear, b%material(BODY_INNER)%hardness, &
                                               sum(loads%traction(2, :)%sliding))
      do k = 1, b%n_elements
         v(AVG_BALL_WEAR - 1 + k) = archard_wear_rate(b%material(BODY_ELEMENT)%wear, &
                                                      b%material(BODY_ELEMENT)%hardness, &
                                                      loads%traction(1, k)%sliding + loads%traction(2, k)%sliding)
      end do
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

end module adore_bearings_ball
