!> What a ball run records and reports: the values averaged between printed steps
!> (ball_averaged_values at the last evaluated state), the accepted state's bookkeeping, the
!> printed time steps, the time history with its step-0 row, and the run's balance
!> (adore_forces_ball_power) with its note line.  A submodule of adore_bearings_ball: the
!> ball kind's lifecycle (start, dynamics, mounting, events) stays in the parent.
submodule(adore_bearings_ball) adore_bearings_ball_results
   use adore_core_threads, only: team_threads
   implicit none

contains

   module procedure ball_n_values
      ball_n_values = AVG_BALL_WEAR - 1 + 2*self%bearing%n_elements + max(self%bearing%n_lands, 0)
   end procedure ball_n_values

   !> ball_averaged_values at the last evaluated state.
   module procedure ball_values
      if (self%tribology_current) then
         call ball_averaged_values(self%bearing, self%eom%geometry, self%eom%state, self%eom%loads, v, &
                                   self%eom%lubricant_temperature, self%tribology)
      else
         call ball_averaged_values(self%bearing, self%eom%geometry, self%eom%state, self%eom%loads, v, &
                                   self%eom%lubricant_temperature)
      end if
   end procedure ball_values

   !> Each ball's orbital position unwrapped from step to step (a step moves a ball far
   !> less than half a revolution); the accepted state's printed tribology (no flash), which
   !> its averages and history row share.
   module procedure ball_accepted
      type(thermal_heat_t) :: heat
      integer :: k
      ! the thermal model's heat of this accepted state (its time: the state's, s)
      if (self%thermal%mode /= THERMAL_OFF) then
         call ball_heat_rates(self%thermal, self%bearing, self%eom%state, self%eom%loads, heat)
         call ball_thermal_accumulate(self%thermal, self%eom%state%time, heat)
      end if
      do k = 1, self%bearing%n_elements
         associate (phi => body_azimuth(self%eom%state%elements(k)))
            self%azimuth(k) = self%azimuth(k) + (modulo(phi - self%last(k) + pi, 2.0_wp*pi) - pi)
            self%last(k) = phi
         end associate
      end do
      call ball_contact_print(self%bearing, self%eom%geometry, self%eom%state, self%eom%loads, self%tribology, &
                              flash=.false., lubricant_temperature=self%eom%lubricant_temperature, &
                              threads=team_threads(self%eom%team, self%eom%threads))   ! the calls' choice
      self%tribology_current = .true.
   end procedure ball_accepted

   !> A printed time step (adore_output_ball_dynamic_report) at the last evaluated state.
   module procedure ball_write_step
      real(wp) :: time, header(4), life, cage_avg(3)
      type(bearing_state_t) :: rates
      integer :: n
      time = t*self%time_scale
      ! Section 3's cage MC acceleration is force / mass (plus gravity), as the report prints it
      ! (Appendix C step 2500: (0, 0, -9.810) m/s**2 on its whirl); in ADORE's whirl coordinates
      ! the state's rate adds whirl_frame_acceleration, which no force causes (docs/dynamics.md)
      rates = self%eom%rates
      if (self%eom%cage .and. self%eom%adore_whirl .and. .not. self%eom%cage_spin_only) &
         rates%cage%velocity(2:3) = rates%cage%velocity(2:3) - &
                                    whirl_frame_acceleration(self%eom%state%cage%position(2:3), &
                                                             self%eom%state%cage%velocity(2:3), self%eom%whirl_blend)
      associate (b => self%bearing, th => self%thermal)
         n = b%n_elements
         header = [t, time, b%speed_outer*time/(2.0_wp*pi), b%speed_inner*time/(2.0_wp*pi)]
         life = ieee_value(1.0_wp, ieee_quiet_nan)                 ! Palmgren-Miner: t / integral dt/L
         if (mean(AVG_DAMAGE) > 0.0_wp) life = 1.0_wp/mean(AVG_DAMAGE)
         cage_avg = [life, mean(AVG_CAGE_WEAR), mean(AVG_EXCURSION)]
         associate (ball_wear => mean(AVG_BALL_WEAR:AVG_BALL_WEAR + n - 1), &
                    race_wear => mean(AVG_RACE_WEAR:AVG_RACE_WEAR + 1), summary => mean(AVG_POWER:AVG_RATIOS + 2), &
                    pocket_wear => mean(AVG_BALL_WEAR + n:AVG_BALL_WEAR + 2*n - 1), &
                    land_wear => mean(AVG_BALL_WEAR + 2*n:))
            if (th%mode == THERMAL_OFF) then
               call write_ball_step(unit, step, header, b, self%eom%geometry, self%eom%state, rates, &
                                    self%eom%loads, self%azimuth, self%axial_origin, ball_wear, race_wear, summary, &
                                    pocket_wear, land_wear, cage_avg, &
                                    lubricant_temperature=self%eom%lubricant_temperature, threads=self%eom%threads)
            else if (.not. th%have_field) then      ! before the first update: no field yet
               call write_ball_step(unit, step, header, b, self%eom%geometry, self%eom%state, rates, &
                                    self%eom%loads, self%azimuth, self%axial_origin, ball_wear, race_wear, summary, &
                                    pocket_wear, land_wear, cage_avg, th%fluid, &
                                    lubricant_temperature=self%eom%lubricant_temperature, threads=self%eom%threads)
            else
               call write_ball_step(unit, step, header, b, self%eom%geometry, self%eom%state, rates, &
                                    self%eom%loads, self%azimuth, self%axial_origin, ball_wear, race_wear, summary, &
                                    pocket_wear, land_wear, cage_avg, th%fluid, th%field, &
                                    self%eom%lubricant_temperature, self%eom%threads)
            end if
         end associate
      end associate
   end procedure ball_write_step

   !> The ball history (new_ball_history) with the options' element and stride; with the
   !> thermal model on, a column exit_fluid_temp_K.
   module procedure ball_new_history
      call new_ball_history(h, self%bearing, n_steps, self%options%history_element, error, &
                            self%options%history_stride)
      if (allocated(error)) return
      if (self%thermal%mode /= THERMAL_OFF) call add_history_column(h, "exit_fluid_temp_K")
   end procedure ball_new_history

   !> A history row and its element row (ball_element_row, with the printed tribology of
   !> the race contacts; the flash temperature rise at printed rows only, h%printed) at the
   !> last evaluated state; with the thermal model on, its exit fluid temperature and the
   !> history element's contact temperatures from the last field.
   module procedure ball_record_row
      type(contact_print_t) :: tribology
      character(len=:), allocatable :: e
      call record_ball_history(h, step, t*self%time_scale, self%eom%state, self%eom%loads, &
                               mean(AVG_BALL_WEAR:AVG_BALL_WEAR + self%bearing%n_elements - 1), &
                               mean(AVG_RACE_WEAR:AVG_RACE_WEAR + 1), self%clearance)
      if (step == 0) call step0_history_values(self, h)
      if (self%tribology_current .and. .not. h%printed) then
         tribology = self%tribology          ! the same numbers: flash only at printed rows
      else
         call ball_contact_print(self%bearing, self%eom%geometry, self%eom%state, self%eom%loads, tribology, &
                                 flash=h%printed, lubricant_temperature=self%eom%lubricant_temperature, &
                                 threads=team_threads(self%eom%team, self%eom%threads))
      end if
      call ball_element_row(h, self%eom%state, self%eom%loads, self%azimuth, tribology)
      ! the thermal model's exit fluid temperature and the history element's contact
      ! temperatures (the network's contact nodes; NaN / the bulk ones before the first field)
      if (self%thermal%mode /= THERMAL_OFF) then
         call set_history_value(h, "exit_fluid_temp_K", ieee_value(1.0_wp, ieee_quiet_nan))
         if (self%thermal%have_field) then
            e = itoa(h%element)
            associate (f => self%thermal%field)
               call set_history_value(h, "exit_fluid_temp_K", f%exit_temperature)
               call set_history_value(h, "re"//e//"_contact_temp_outer_K", f%contact_outer(h%element))
               call set_history_value(h, "re"//e//"_contact_temp_inner_K", f%contact_inner(h%element))
            end associate
         end if
      end if
   end procedure ball_record_row

   !> The plot-data row of step 0 from the step-0 solution the print shows (set_step0_row),
   !> not from the dynamics' initial state (issue #29: the two differ by the dynamic model's
   !> contact forces and traction at the quasi-static positions): power, wear, cage centre
   !> and velocity, guide-land forces and the chosen element's loads, losses and contact
   !> temperatures of step 0's print.  A contact force step 0 does not compute (a cage
   !> contact, printed NaN) is NaN here too.
   subroutine step0_history_values(self, h)
      class(ball_kind_t), intent(in) :: self
      type(run_history_t), intent(inout) :: h
      real(wp) :: nan, r, lands(max(self%bearing%n_lands, 0)), pocket, q(2), loss(2), temp(2)
      integer :: k, j
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      k = h%element
      associate (s0 => self%step0, e => self%step0%start%equilibrium, c => self%step0%cage)
         lands = nan
         if (allocated(c%land)) then
            do j = 1, min(size(lands), size(c%land))
               if (.not. c%land(j)%in_contact) lands(j) = 0.0_wp
            end do
         end if
         pocket = nan
         if (allocated(c%pocket)) then
            if (size(c%pocket, 2) >= k) then
               if (.not. c%pocket(1, k)%in_contact) pocket = 0.0_wp
            end if
         end if
         q = [e%q_o(k), e%q_i(k)]
         loss = nan
         temp = nan
         do j = 1, 2
            if (.not. (q(j) > 0.0_wp)) cycle
            loss(j) = s0%loss(j, k)
            temp(j) = s0%contact_temp(j, k)
         end do
         r = hypot(c%state%centre(2), c%state%centre(3))
         call set_step0_row(h, s0%power_loss, sum(s0%wear)/size(s0%wear), s0%race_wear, c%state%centre(2:3), &
                            [r*c%state%whirl_speed, 0.0_wp], lands, q, loss, temp, pocket)
      end associate
   end subroutine step0_history_values

   module procedure ball_n_balance
      ball_n_balance = N_BALANCE + 0*self%bearing%n_elements
   end procedure ball_n_balance

   !> adore_forces_ball_power's balance values at the last evaluated state (the equations
   !> of motion's loads, the condition's applied load; a free cage in ADORE's whirl
   !> coordinates with the acceleration they add, whose power is the balance's whirl-frame
   !> line).
   module procedure ball_balance
      real(wp) :: a(3)
      associate (e => self%eom)
         a = 0.0_wp
         if (e%cage .and. e%adore_whirl .and. .not. e%cage_spin_only) &
            a(2:3) = whirl_frame_acceleration(e%state%cage%position(2:3), e%state%cage%velocity(2:3), e%whirl_blend)
         v = ball_balance_values(e%bearing, e%state, e%loads, a)
      end associate
   end procedure ball_balance

   !> The run note's balance line over the window [window(1), window(2)] (tau) from the
   !> window's means of the balance values and their first and last values: drive power
   !> against the dissipation (contacts and cage, contact damping) and the mechanical
   !> energy's rate of change (adore_forces_ball_power: drive = dissipation + dE/dt); the
   !> inner race's mean contact force against the applied load and its weight (the residual
   !> is m dv/dt averaged: the race's momentum change over the window, printed beside it - a
   !> race vibrating at the ball passage leaves it where the window is short or the load
   !> light), the outer race's against the housing's share; the power of the
   !> terms a free cage's whirl coordinates omit (P_frame, adore_forces_ball_power: 0 by
   !> Newton's equations); the closure (drive - dissipation - dE/dt - P_frame) /
   !> max(|drive|, dissipation, 1 uW), flagged above 1 % with the hint (the time loop's: what
   !> limited the window's steps, adore_driver_time_loop's closure_hint).
   module procedure ball_balance_text
      character(len=900) :: buf
      real(wp) :: seconds, dissipation, rate, carried(3), housing(3), closure
      integer :: stat
      associate (b => self%eom%bearing)
         seconds = (window(2) - window(1))*self%time_scale
         dissipation = mean(BAL_RACE_HEAT) + mean(BAL_DAMPING) + mean(BAL_CAGE_WORK)
         rate = (last(BAL_ENERGY) - first(BAL_ENERGY))/seconds
         ! what the inner race's contacts carry: the applied load and the race's weight; the
         ! outer race's: that and the balls' weight (the cage's own constraint holds its weight)
         carried = b%force + b%mass(BODY_INNER)*b%gravity
         housing = carried + b%n_elements*b%mass(BODY_ELEMENT)*b%gravity
         write (buf, "(a,es10.4,a,es10.4,a,es10.3,a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es11.4,a,es11.4,"// &
                "a,es11.4,a,es11.4,a,3es12.4,a,3es12.4,a,es10.3,a,es10.3,a,3es12.4,a,3es12.4,a,es10.3,a)", iostat=stat) &
            "balance over the last half of the run (t ", window(1)*self%time_scale, " to ", window(2)*self%time_scale, &
            " s, ", seconds*abs(b%speed_inner - b%speed_outer)/(2.0_wp*pi), " shaft revolutions): drive power ", &
            mean(BAL_DRIVE), " W, dissipation ", dissipation, " W (race contacts ", mean(BAL_RACE_HEAT), &
            " W, contact damping ", mean(BAL_DAMPING), " W, cage contacts ", mean(BAL_CAGE_WORK), &
            " W of which friction heat ", mean(BAL_CAGE_HEAT), " W), energy change ", rate, &
            " W, whirl frame ", mean(BAL_WHIRL_FRAME), " W, drive/dissipation ", &
            mean(BAL_DRIVE)/dissipation, "; inner race contact force", mean(BAL_INNER_FORCE:BAL_INNER_FORCE + 2), &
            " N against applied load and weight", carried, " N, residual ", &
            norm2(mean(BAL_INNER_FORCE:BAL_INNER_FORCE + 2) + carried), " N (the race's momentum change over "// &
            "the window", norm2(last(BAL_INNER_MOMENTUM:BAL_INNER_MOMENTUM + 2) - &
                                first(BAL_INNER_MOMENTUM:BAL_INNER_MOMENTUM + 2))/seconds, " N); outer race contact force", &
            mean(BAL_OUTER_FORCE:BAL_OUTER_FORCE + 2), " N against", -housing, " N, residual ", &
            norm2(mean(BAL_OUTER_FORCE:BAL_OUTER_FORCE + 2) - housing), " N"
         text = trim(buf)
         ! the closure: Newton-Euler makes it 0 up to the integration error (issue #28);
         ! below a microwatt (a shaft at rest) there is nothing to balance
         closure = (mean(BAL_DRIVE) - dissipation - rate - mean(BAL_WHIRL_FRAME))/ &
                   max(abs(mean(BAL_DRIVE)), dissipation, MIN_BALANCED_POWER)
         write (buf, "(a,es10.3)", iostat=stat) "; closure (drive - dissipation - energy change - whirl frame)"// &
            "/max(|drive|, dissipation, 1 uW) ", closure
         text = text//trim(buf)
         if (abs(closure) > 0.01_wp) text = text//", above 0.01: the time steps do not resolve the power balance "// &
                                            "("//hint//"; docs/operating-points.md)"
      end associate
   end procedure ball_balance_text

   !> The power balance's defect over a time step of h (tau) for the integrator's balance
   !> control (run option balance_tolerance; issue #28), from the balance values g0 at its start
   !> and g1 at its end and their integral q over it (W tau): defect (J) = the mechanical
   !> energy's change - (drive - dissipation - whirl frame) integrated, the per-step share of
   !> the run note's closure numerator (ball_balance_text; Newton-Euler make it 0 up to the
   !> integration error), against flow (J) = the step's gross drive, dissipation and whirl-frame
   !> work, at least MIN_BALANCED_POWER over the step.
   module procedure ball_balance_defect
      integer, parameter :: flows(5) = [BAL_DRIVE, BAL_RACE_HEAT, BAL_DAMPING, BAL_CAGE_WORK, BAL_WHIRL_FRAME]
      real(wp) :: net
      net = q(BAL_DRIVE) - q(BAL_RACE_HEAT) - q(BAL_DAMPING) - q(BAL_CAGE_WORK) - q(BAL_WHIRL_FRAME)
      defect = (g1(BAL_ENERGY) - g0(BAL_ENERGY)) - self%time_scale*net
      flow = self%time_scale*max(sum(abs(q(flows))), MIN_BALANCED_POWER*h)
   end procedure ball_balance_defect

end submodule adore_bearings_ball_results
