!> A printed time step and the time history of a cylindrical roller bearing (issue #26):
!> the dynamic state in the step-0 print's terms (roller_step_view fills an
!> adore_start_roller_step0 record from the state and the loads of adore_forces_roller_bearing,
!> which adore_output_step_report's write_roller_step0 prints in the ADORE 5.0 layout,
!> section 1a - the load along roller 1 - included), and the roller run's history rows.
!> No module state.
module adore_output_roller_dynamic_report
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_core_strings, only: itoa
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER, TEMP_ELEMENT, TEMP_CAGE, &
                                  TEMP_OUTER, TEMP_INNER, TEMP_HOUSING, TEMP_SHAFT
   use adore_tribology_traction_law, only: law_kappa
   use adore_life_lundberg_palmgren, only: life_params_t
   use adore_life_roller, only: roller_bearing_lp_life
   use adore_forces_race_contact, only: line_flash, wall_temperature
   use adore_tribology_roller_traction, only: line_traction_t
   use adore_forces_roller_bearing, only: roller_loads_t
   use adore_dynamics_roller_system, only: roller_system_t, roller_pose, ROLLER_SIZE, RACE_OFFSET, CAGE_OFFSET, &
                                           CAGE_POS_OFFSET, CAGE_TILT_OFFSET
   use adore_start_roller_step0, only: roller_step0_t, roller_wear
   use adore_output_run_history, only: run_history_t, history_shape, check_history_element
   implicit none
   private

   public :: roller_step_view, new_roller_history, record_roller_history, roller_total_power

   !> columns before the guide lands' forces, and after them
   integer, parameter :: N_FIRST = 32, N_LAST = 4

contains

   !> Total power loss (W) of the last evaluation: race contacts (eq 4), pockets, guide lands.
   pure real(wp) function roller_total_power(sys) result(p)
      type(roller_system_t), intent(in) :: sys
      integer :: k
      p = sys%land_power
      do k = 1, size(sys%loads)
         p = p + sum(sys%loads(k)%power) + sys%loads(k)%pocket_power + sys%loads(k)%flange_power
      end do
   end function roller_total_power

   !> The step-0 record s0 of bearing b brought to the dynamic state y of sys (its last
   !> evaluation's loads): azimuth (unwrapped, rad), radius, tilt, orbital speed, spin, slice
   !> contacts and tractions, losses, wear, flash temperature rise, race loads, basic life,
   !> pocket gaps, forces and friction losses and the cage speed.
   subroutine roller_step_view(b, sys, y, azimuth, s0, s, error)
      type(bearing_t), intent(in) :: b
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:), azimuth(:)
      type(roller_step0_t), intent(in) :: s0
      type(roller_step0_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error
      type(life_params_t) :: lp
      real(wp) :: w_r, c(3), v(3)
      integer :: k, n, j, r0
      n = sys%n
      s = s0
      r0 = ROLLER_SIZE*n + RACE_OFFSET
      s%equilibrium%u = y(r0 + 2:r0 + 3)
      do k = 1, n
         associate (p => roller_pose(y, k), ld => sys%loads(k), e => s%equilibrium)
            e%azimuth(k) = azimuth(k)
            e%r(k) = p%r
            e%tilt(k) = p%tilt
            e%orbital_speed(k) = p%phidot
            e%c_o(k) = ld%c(1)
            e%c_i(k) = ld%c(2)
            s%roller_spin(k) = p%spin
            call fill_traction(b, ld, 1, s%tr_o(k))
            call fill_traction(b, ld, 2, s%tr_i(k))
            do j = 1, 2
               s%cage%pocket(j, k)%geo_int = ld%pocket_gap(j)
               s%cage%pocket(j, k)%in_contact = ld%pocket_load(j) > 0.0_wp
               ! the pocket's force of this end and its share of the friction loss
               s%cage%pocket(j, k)%force = ld%pocket_load(j)
               s%cage%pocket(j, k)%loss = 0.0_wp
               if (sum(ld%pocket_load) > 0.0_wp) s%cage%pocket(j, k)%loss = ld%pocket_power*ld%pocket_load(j)/ &
                                                                            sum(ld%pocket_load)
            end do
            w_r = p%spin
            call line_flash(b, e%c_o(k), s%tr_o(k), BODY_OUTER, s%model%r_o, b%speed_outer - p%phidot, w_r, &
                            s%temp_rise(1, k), error)
            if (allocated(error)) return
            call line_flash(b, e%c_i(k), s%tr_i(k), BODY_INNER, s%model%r_i, b%speed_inner - p%phidot, w_r, &
                            s%temp_rise(2, k), error)
            if (allocated(error)) return
         end associate
      end do
      s%spin_speed = sum(s%roller_spin)/n
      s%contact_power = sum(s%tr_o%power) + sum(s%tr_i%power)
      s%power_loss = roller_total_power(sys)
      call roller_wear(b, s)
      s%race_loads = 0.0_wp
      do k = 1, n
         s%race_loads(1:3, 1) = s%race_loads(1:3, 1) + sys%loads(k)%race_force(:, 1)
         s%race_loads(1:3, 2) = s%race_loads(1:3, 2) + sys%loads(k)%race_force(:, 2)
         s%race_loads(4, :) = s%race_loads(4, :) + sys%loads(k)%race_torque
      end do
      ! the cage: centred on the axis (its constraint: no whirl, no mass-centre offset) or free
      ! in the radial plane
      s%cage%state%angular_speed = y(ROLLER_SIZE*n + CAGE_OFFSET + 2)
      call cage_motion(sys, y, c, v)
      s%cage%state%centre(2:3) = c(2:3)
      ! the free cage's axial position (Mass Center Position Axial; 0 for a centred cage)
      s%cage%state%centre(1) = y(ROLLER_SIZE*n + CAGE_TILT_OFFSET + 1)
      s%cage%state%velocity = v
      s%cage%state%whirl_speed = whirl_rate(c, v)
      s%cage%state%orbital_angle = 0.0_wp
      if (norm2(c) > 0.0_wp) s%cage%state%orbital_angle = modulo(atan2(-c(2), c(3)), 8.0_wp*atan(1.0_wp))
      if (allocated(sys%land) .and. allocated(s%cage%land)) then
         do k = 1, min(size(sys%land), size(s%cage%land))
            s%cage%land(k)%geo_int = sys%land(k)%gap
            s%cage%land(k)%eccentricity = sys%land(k)%eccentricity
            s%cage%land(k)%in_contact = sys%land(k)%gap <= 0.0_wp
         end do
      end if
      call roller_bearing_lp_life(lp, s%equilibrium%c_o, s%equilibrium%c_i, s%equilibrium%orbital_speed, &
                                  b%speed_outer, b%speed_inner, b%d, b%dm, s%life)
      s%basic_life_hours = s%life%bearing_hours
   end subroutine roller_step_view

   !> The printed traction of race j of bearing b from the loads' slices: the slip magnitude, the
   !> traction along e_t (N/m on the race), its force, loss and largest slip.
   subroutine fill_traction(b, ld, j, t)
      type(bearing_t), intent(in) :: b
      type(roller_loads_t), intent(in) :: ld
      integer, intent(in) :: j
      type(line_traction_t), intent(inout) :: t
      integer :: m
      m = size(ld%c(j)%x)
      if (allocated(t%slip)) deallocate (t%slip, t%kappa, t%traction)
      allocate (t%slip(m), t%kappa(m), t%traction(m))
      t%slip = hypot(ld%slip(:, 1, j), ld%slip(:, 2, j))
      t%kappa = law_kappa(b%race_traction, t%slip)
      t%traction = ld%traction(:, 1, j)
      t%force = sum(ld%c(j)%weight*t%traction)
      t%power = ld%power(j)
      t%sliding = ld%sliding(j)
      t%max_slip = ld%max_slip(j)
      t%max_slip_kappa = 0.0_wp
      t%net_coefficient = 0.0_wp
      if (ld%load(j) > 0.0_wp) then
         t%max_slip_kappa = law_kappa(b%race_traction, t%max_slip)
         t%net_coefficient = abs(t%force)/ld%load(j)
      end if
   end subroutine fill_traction

   !> The cage centre c (m) and its velocity v (m/s), inertial, at state y (0 for a centred cage).
   pure subroutine cage_motion(sys, y, c, v)
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: c(3), v(3)
      integer :: g0
      g0 = ROLLER_SIZE*sys%n + CAGE_POS_OFFSET
      c = [0.0_wp, y(g0 + 1), y(g0 + 2)]
      v = [0.0_wp, y(g0 + 3), y(g0 + 4)]
   end subroutine cage_motion

   !> Whirl rate (rad/s) about +x of a centre at c moving at v: (c x v)_x / |c|**2 (0 on the axis).
   pure real(wp) function whirl_rate(c, v)
      real(wp), intent(in) :: c(3), v(3)
      whirl_rate = 0.0_wp
      if (c(2)**2 + c(3)**2 > 0.0_wp) whirl_rate = (c(2)*v(3) - c(3)*v(2))/(c(2)**2 + c(3)**2)
   end function whirl_rate

   !> The empty history of a roller run of n_steps steps (stride > 0: every stride-th step a
   !> row, history_shape): time, step, total power loss, roller `element`'s race loads,
   !> losses, orbital speed and pocket force, the cage speed, the inner race's y, z, the
   !> total loss split into race contacts, pockets and guide lands, the bulk temperatures
   !> (the run's condition's), the cage centre's y, z, its whirl (tangential) and radial
   !> velocity, the diametral guide clearance, the whirl rate, the centre's velocity y, z, its
   !> axial position and tilt (rad, the angle of its axis from the bearing axis), each guide
   !> land's normal force (film + metal), and roller `element`'s contact temperature rise
   !> (flash, eqs 34-36) and contact temperature at both races (the figure types 33-44 of the
   !> report's roller run).
   subroutine new_roller_history(h, b, n_steps, element, error, stride)
      type(run_history_t), intent(out) :: h
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: n_steps, element
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: stride
      integer :: rows, cols, k
      character(len=:), allocatable :: e
      call check_history_element(b, element, error)
      if (allocated(error)) return
      call history_shape(n_steps, b%controls%print_interval, 0, rows, cols, h%stride, stride)
      h%element = element
      e = itoa(element)
      h%n_lands = b%n_lands
      allocate (h%names(N_FIRST + b%n_lands + N_LAST), h%values(rows, N_FIRST + b%n_lands + N_LAST))
      h%names(:N_FIRST) = [character(len=len(h%names)) :: "time_s", "step", "total_power_loss_W", &
                           "re"//e//"_contact_load_outer_N", "re"//e//"_contact_load_inner_N", &
                           "re"//e//"_contact_loss_outer_W", "re"//e//"_contact_loss_inner_W", &
                           "re"//e//"_orbital_speed_rad_s", "pocket"//e//"_force_N", &
                           "cage_angular_velocity_x_rad_s", "inner_race_y_m", "inner_race_z_m", &
                           "race_contact_loss_W", "pocket_loss_W", "land_loss_W", "flange_loss_W", &
                           "bulk_temp_re_K", "bulk_temp_cage_K", "bulk_temp_outer_race_K", &
                           "bulk_temp_inner_race_K", "bulk_temp_housing_K", "bulk_temp_shaft_K", &
                           "cage_y_m", "cage_z_m", "cage_whirl_velocity_m_s", "cage_radial_velocity_m_s", &
                           "guide_clearance_m", "cage_whirl_speed_rad_s", "cage_velocity_y_m_s", &
                           "cage_velocity_z_m_s", "cage_x_m", "cage_tilt_rad"]
      do k = 1, b%n_lands
         h%names(N_FIRST + k) = "land"//itoa(k)//"_force_N"
      end do
      h%names(N_FIRST + b%n_lands + 1:) = [character(len=len(h%names)) :: "re"//e//"_contact_temp_rise_outer_K", &
                                           "re"//e//"_contact_temp_rise_inner_K", "re"//e//"_contact_temp_outer_K", &
                                           "re"//e//"_contact_temp_inner_K"]
   end subroutine new_roller_history

   !> Record step `step` at time `time` (s): the last evaluation of sys (bearing b) at state y,
   !> the bearing's bulk temperatures `temperature` (K, TEMP_* order).  The history roller's
   !> contact temperature rise: the flash temperature of its slices (line_flash, as the
   !> print's); its contact temperature: the wall temperature, the mean of the roller's and
   !> the race's bulk temperatures (as step 0's; the thermal model's field replaces it:
   !> adore_bearings_roller); both NaN where the contact is unloaded.
   subroutine record_roller_history(h, step, time, b, sys, y, temperature)
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: time
      type(bearing_t), intent(in) :: b
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:), temperature(:)
      real(wp), allocatable :: values(:, :)
      real(wp) :: race_loss, c(3), v(3), rad, e_c(3), clearance, land(h%n_lands), rise(2), wall(2)
      integer :: r0, k, t0
      t0 = ROLLER_SIZE*sys%n + CAGE_TILT_OFFSET
      if (h%rows >= size(h%values, 1)) then
         allocate (values(max(2*size(h%values, 1), 16), size(h%values, 2)))
         values(1:h%rows, :) = h%values(1:h%rows, :)
         call move_alloc(values, h%values)
      end if
      h%rows = h%rows + 1
      r0 = ROLLER_SIZE*sys%n + RACE_OFFSET
      race_loss = 0.0_wp
      do k = 1, sys%n
         race_loss = race_loss + sum(sys%loads(k)%power)
      end do
      call cage_motion(sys, y, c, v)
      rad = norm2(c)
      e_c = 0.0_wp
      if (rad > 0.0_wp) e_c = c/rad
      ! whirl (tangential) velocity: along e_x x e_c; radial: along e_c
      clearance = ieee_value(0.0_wp, ieee_quiet_nan)
      land = 0.0_wp
      if (allocated(sys%lands)) then
         if (size(sys%lands) > 0) clearance = 2.0_wp*minval(sys%lands%clearance)
      end if
      if (allocated(sys%land)) then
         do k = 1, min(h%n_lands, size(sys%land))
            land(k) = norm2(sys%land(k)%hydro_force) + sys%land(k)%metallic_load
         end do
      end if
      call contact_temperatures(b, sys, y, h%element, temperature, rise, wall)
      associate (ld => sys%loads(h%element))
         h%values(h%rows, :) = [time, real(step, wp), roller_total_power(sys), ld%load, ld%power, &
                                y(ROLLER_SIZE*(h%element - 1) + 6), sum(ld%pocket_load), &
                                y(ROLLER_SIZE*sys%n + CAGE_OFFSET + 2), y(r0 + 2), y(r0 + 3), race_loss, &
                                sum([(sys%loads(k)%pocket_power, k=1, sys%n)]), sys%land_power, &
                                sum([(sys%loads(k)%flange_power, k=1, sys%n)]), &
                                temperature(TEMP_ELEMENT), temperature(TEMP_CAGE), temperature(TEMP_OUTER), &
                                temperature(TEMP_INNER), temperature(TEMP_HOUSING), temperature(TEMP_SHAFT), &
                                c(2), c(3), -e_c(3)*v(2) + e_c(2)*v(3), dot_product(e_c, v), clearance, &
                                whirl_rate(c, v), v(2), v(3), y(t0 + 1), norm2(y(t0 + 2:t0 + 3)), land, rise, &
                                wall]
      end associate
   end subroutine record_roller_history

   !> Roller k's contact temperature rise (K; flash, line_flash as the print's) and wall
   !> temperature (K; wall_temperature: the mean of its bulk temperature and the race's,
   !> temperature in TEMP_* order) at the outer (1) and inner (2) race, at state y of sys's last evaluation; NaN
   !> where the contact is unloaded (and the rise where the flash model fails).
   subroutine contact_temperatures(b, sys, y, k, temperature, rise, wall)
      type(bearing_t), intent(in) :: b
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:)
      integer, intent(in) :: k
      real(wp), intent(in) :: temperature(:)
      real(wp), intent(out) :: rise(2), wall(2)
      type(line_traction_t) :: tr
      type(error_type), allocatable :: error
      real(wp) :: r_race(2), speed(2)
      integer :: j, body(2)
      body = [BODY_OUTER, BODY_INNER]
      r_race = [sys%model%qs%r_o, sys%model%qs%r_i]
      speed = [b%speed_outer, b%speed_inner]
      rise = ieee_value(0.0_wp, ieee_quiet_nan)
      wall = rise
      associate (p => roller_pose(y, k), ld => sys%loads(k))
         do j = 1, 2
            if (.not. (ld%load(j) > 0.0_wp)) cycle
            wall(j) = wall_temperature(temperature, body(j))
            call fill_traction(b, ld, j, tr)
            call line_flash(b, ld%c(j), tr, body(j), r_race(j), speed(j) - p%phidot, p%spin, rise(j), error)
            if (allocated(error)) then
               rise(j) = ieee_value(0.0_wp, ieee_quiet_nan)
               deallocate (error)
            end if
         end do
      end associate
   end subroutine contact_temperatures

end module adore_output_roller_dynamic_report
