!> The time histories of a ball bearing run (issue #20 item 6): what the report's figures
!> 16-23 plot, recorded during the time loop and written to the plot-data file beside the
!> print (docs/plots.md, "The plot-data file").
!>
!> Rows: step 0 (the dynamics' initial state), every `stride`-th accepted step, every
!> printed step and the last step; stride = 1 up to HISTORY_ROWS steps, else the smallest
!> stride that keeps the regular rows within HISTORY_ROWS.  Columns (SI units, named as
!> docs/plots.md's time-history table): time, step, total power loss, the six bulk
!> temperatures, the time-averaged wear rates of the balls (mean), outer and inner race,
!> the cage mass centre (y, z) and its whirl and radial velocity, the guide clearance, the
!> force at each guide land, and for one chosen ball its contact load, loss and contact
!> temperature at both races and its pocket force.  A quantity the engine does not compute
!> (flash temperature rise, exit fluid temperature, cage wear) has no column.
!>
!> Beside it, at the same rows, the element record (issue #29 item 1): every ball's race
!> contacts, speeds and positions, the cage and the races, written to the element file
!> beside the print (element_file_name; docs/results.md), which pyadore turns into its
!> xarray dataset and netCDF file.  Its columns are named `quantity_unit` for a body,
!> `quantity_unit:k` for ball k and `quantity_unit:outer:k` / `quantity_unit:inner:k` for
!> ball k's contact with a race (ELEMENT_NAMES, CONTACT_NAMES, BODY_NAMES).
!>
!> The record is a derived type owned by the caller (no module state); it is allocated once
!> at the start of a run (new_ball_history), recording a row allocates nothing.
module adore_output_run_history
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_strings, only: itoa
   use adore_core_os, only: rename_file, delete_file
   use adore_model_bearing, only: bearing_t, BODY_OUTER, BODY_INNER, TEMP_ELEMENT, TEMP_CAGE, TEMP_OUTER, &
                                   TEMP_INNER, TEMP_HOUSING, TEMP_SHAFT
   use adore_core_rotation, only: quat_matrix
   use adore_state_bearing_state, only: bearing_state_t, RACE_OUTER, RACE_INNER
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, total_power_loss
   use adore_forces_race_contact, only: wall_temperature
   use adore_output_ball_contact_print, only: contact_print_t
   implicit none
   private

   public :: run_history_t, history_shape, check_history_element, new_ball_history, history_due, record_ball_history, &
             write_history_csv, history_file_name, history_columns_text, element_file_name, beside_file_name, &
             write_element_file, ball_element_row, add_history_column, set_history_value, set_step0_row

   !> Regular rows of a history at most (the stride grows beyond HISTORY_ROWS steps).
   integer, parameter, public :: HISTORY_ROWS = 10000
   !> Length of a column name.
   integer, parameter, public :: HISTORY_NAME_LEN = 40
   !> Columns before the guide lands: time, step, power, 6 bulk temperatures, 3 wear rates,
   !> 4 cage columns, the guide clearance.
   integer, parameter :: C_TIME = 1, C_STEP = 2, C_POWER = 3, C_BULK = 4, C_WEAR = 10, C_CAGE = 13, &
                         C_CLEARANCE = 17, N_FIXED = 17
   !> Columns of the chosen rolling element: contact load, loss and temperature at both
   !> races, pocket force.
   integer, parameter :: N_ELEMENT = 7

   !> The element record's columns of each ball (`name:k`), of each of its race contacts
   !> (`name:outer:k`, `name:inner:k`) and of the cage and races (`name`), SI units.
   integer, parameter :: N_BALL = 9, N_CONTACT = 12, N_BODY = 16
   character(len=*), parameter :: RACE_NAMES(2) = ["outer", "inner"]
   character(len=32), parameter :: ELEMENT_NAMES(N_BALL) = [character(len=32) :: &
      "orbital_position_rad", "orbital_speed_rad_s", "axial_position_m", "radial_position_m", &
      "angular_velocity_x_rad_s", "angular_velocity_y_rad_s", "angular_velocity_z_rad_s", &
      "spin_amplitude_rad_s", "pocket_force_N"]
   character(len=32), parameter :: CONTACT_NAMES(N_CONTACT) = [character(len=32) :: &
      "contact_load_N", "contact_angle_rad", "max_pressure_Pa", "semi_major_m", "semi_minor_m", &
      "slip_velocity_m_s", "traction_coefficient", "spin_roll", "power_loss_W", "film_thickness_m", &
      "thermal_reduction_factor", "temperature_rise_K"]
   character(len=40), parameter :: BODY_NAMES(N_BODY) = [character(len=40) :: &
      "cage_x_m", "cage_y_m", "cage_z_m", "cage_velocity_x_m_s", "cage_velocity_y_m_s", "cage_velocity_z_m_s", &
      "cage_angular_velocity_x_rad_s", "cage_angular_velocity_y_rad_s", "cage_angular_velocity_z_rad_s", &
      "cage_whirl_speed_rad_s", "inner_race_x_m", "inner_race_y_m", "inner_race_z_m", &
      "inner_race_angular_velocity_x_rad_s", "outer_race_angular_velocity_x_rad_s", "total_power_loss_W"]

   !> The recorded time history of one run.
   type :: run_history_t
      integer :: element = 1                 !< rolling element of the per-element columns
      integer :: stride = 1                  !< every stride-th step is a row (and printed ones, the last)
      integer :: rows = 0                    !< rows recorded so far
      integer :: n_lands = 0                 !< guide lands (one force column each)
      !> the row being recorded is a printed step (the time loop sets it before each row):
      !> the element record's costly columns are computed only there (ball_element_row)
      logical :: printed = .false.
      character(len=HISTORY_NAME_LEN), allocatable :: names(:)   !< column names (docs/plots.md)
      real(wp), allocatable :: values(:, :)  !< (row capacity, column): rows 1..rows are recorded
      !> the element record at the same rows (empty for a kind without one): column names
      !> (module header) and values (row capacity, column)
      character(len=HISTORY_NAME_LEN), allocatable :: element_names(:)
      real(wp), allocatable :: elements(:, :)
   end type run_history_t

contains

   !> Row capacity, number of columns and stride of the history of a run of n_steps time steps
   !> printed every print_interval steps (Rec 1 data_control_2; 0: the last only) of a
   !> bearing with n_lands guide lands; `requested` > 0 (run option history_stride) sets the
   !> stride, 0 or absent: the automatic one.
   pure subroutine history_shape(n_steps, print_interval, n_lands, rows, cols, stride, requested)
      integer, intent(in) :: n_steps, print_interval, n_lands
      integer, intent(out) :: rows, cols, stride
      integer, intent(in), optional :: requested
      integer :: printed
      stride = max(1, (n_steps + HISTORY_ROWS - 1)/HISTORY_ROWS)
      if (present(requested)) then
         if (requested > 0) stride = requested
      end if
      printed = 0
      if (print_interval > 0) printed = n_steps/print_interval
      rows = 2 + n_steps/stride + printed
      cols = N_FIXED + max(n_lands, 0) + N_ELEMENT
   end subroutine history_shape

   !> An input error unless `element` is a rolling element of bearing b (1..n_elements): the
   !> time history's element of any kind.
   subroutine check_history_element(b, element, error)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: element
      type(error_type), allocatable, intent(out) :: error
      if (element < 1 .or. element > b%n_elements) &
         call input_error(error, "time history element "//itoa(element)//": the bearing has rolling elements 1 to "// &
                          itoa(b%n_elements))
   end subroutine check_history_element

   !> The empty history of a run of ball bearing b over n_steps steps, with the per-element
   !> columns of rolling element `element` (1..n_elements; input error otherwise) and the
   !> element record of every ball; stride > 0: every stride-th step is a row (history_shape).
   subroutine new_ball_history(h, b, n_steps, element, error, stride)
      type(run_history_t), intent(out) :: h
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: n_steps, element
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: stride
      integer :: rows, cols, k, j, i, c
      character(len=:), allocatable :: e

      call check_history_element(b, element, error)
      if (allocated(error)) return
      call history_shape(n_steps, b%controls%print_interval, b%n_lands, rows, cols, h%stride, stride)
      h%element = element
      h%n_lands = b%n_lands
      allocate (h%names(cols), h%values(rows, cols))
      h%names(C_TIME:C_CLEARANCE) = [character(len=HISTORY_NAME_LEN) :: "time_s", "step", "total_power_loss_W", &
                                     "bulk_temp_re_K", "bulk_temp_cage_K", "bulk_temp_outer_race_K", &
                                     "bulk_temp_inner_race_K", "bulk_temp_housing_K", "bulk_temp_shaft_K", &
                                     "wear_rate_re_m3_s", "wear_rate_outer_race_m3_s", "wear_rate_inner_race_m3_s", &
                                     "cage_y_m", "cage_z_m", "cage_whirl_velocity_m_s", "cage_radial_velocity_m_s", &
                                     "guide_clearance_m"]
      do k = 1, h%n_lands
         h%names(N_FIXED + k) = "land"//itoa(k)//"_force_N"
      end do
      e = itoa(element)
      h%names(N_FIXED + h%n_lands + 1:) = [character(len=HISTORY_NAME_LEN) :: &
                                           "re"//e//"_contact_load_outer_N", "re"//e//"_contact_load_inner_N", &
                                           "re"//e//"_contact_loss_outer_W", "re"//e//"_contact_loss_inner_W", &
                                           "re"//e//"_contact_temp_outer_K", "re"//e//"_contact_temp_inner_K", &
                                           "pocket"//e//"_force_N"]
      allocate (h%element_names(N_BODY + b%n_elements*(N_BALL + 2*N_CONTACT)), &
                h%elements(rows, N_BODY + b%n_elements*(N_BALL + 2*N_CONTACT)))
      h%element_names(:N_BODY) = BODY_NAMES
      c = N_BODY
      do k = 1, b%n_elements
         e = itoa(k)
         do i = 1, N_BALL
            h%element_names(c + i) = trim(ELEMENT_NAMES(i))//":"//e
         end do
         c = c + N_BALL
         do j = 1, 2
            do i = 1, N_CONTACT
               h%element_names(c + i) = trim(CONTACT_NAMES(i))//":"//trim(RACE_NAMES(j))//":"//e
            end do
            c = c + N_CONTACT
         end do
      end do
   end subroutine new_ball_history

   !> Record the element row of the row just recorded (record_ball_history) of a ball
   !> bearing at state s, with the force assembly's loads there, each ball's orbital
   !> position azimuth(k) unwrapped since the start (rad) and the printed tribology p of
   !> its race contacts (adore_output_ball_contact_print).  Values as the print shows them,
   !> in SI units and at full precision: contact angle |alpha| (rad), Hertz load, pressure
   !> and semi-axes as computed (0 where unloaded), the tribology NaN where unloaded (and
   !> the flash temperature rise NaN but at printed rows, h%printed: it is the costly one);
   !> positions and velocities inertial (m, m/s, rad/s; ball angular velocity in body =
   !> inertial components at the start's attitude: body frame rotated to inertial); spin
   !> amplitude = |omega - omega_orbit e_x| (rad/s); cage whirl speed (r x v)_x / r**2.
   !> Nothing happens for a history without an element record.
   subroutine ball_element_row(h, s, loads, azimuth, p)
      type(run_history_t), intent(inout) :: h
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(in) :: azimuth(:)
      type(contact_print_t), intent(in) :: p
      real(wp) :: w(3), r2, w_orb, nan, rot(3, 3)
      integer :: row, k, j, c

      if (.not. allocated(h%elements)) return
      if (size(h%elements, 2) == 0) return
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      row = h%rows
      associate (v => h%elements)
         associate (cg => s%cage, ir => s%races(RACE_INNER), orr => s%races(RACE_OUTER))
            v(row, 1:3) = cg%position
            v(row, 4:6) = cg%velocity
            rot = quat_matrix(cg%attitude)    ! named: a function result inside matmul is a heap temporary
            v(row, 7:9) = matmul(rot, cg%omega)
            v(row, 10) = orbit_speed(cg%position, cg%velocity)
            v(row, 11:13) = ir%position
            v(row, 14) = ir%omega(1)
            v(row, 15) = orr%omega(1)
         end associate
         v(row, 16) = total_power_loss(loads)
         c = N_BODY
         do k = 1, size(azimuth)
            associate (ball => s%elements(k))
               rot = quat_matrix(ball%attitude)
               w = matmul(rot, ball%omega)
               r2 = ball%position(2)**2 + ball%position(3)**2
               w_orb = orbit_speed(ball%position, ball%velocity)
               v(row, c + 1) = azimuth(k)
               v(row, c + 2) = w_orb
               v(row, c + 3) = ball%position(1)
               v(row, c + 4) = sqrt(r2)
               v(row, c + 5:c + 7) = w
               v(row, c + 8) = norm2(w - [w_orb, 0.0_wp, 0.0_wp])
               v(row, c + 9) = 0.0_wp
               if (allocated(loads%pockets)) v(row, c + 9) = norm2(loads%pockets(k)%force_ball)
            end associate
            c = c + N_BALL
            do j = 1, 2
               associate (ct => loads%contacts(j, k))
                  v(row, c + 1:c + 5) = [ct%load, abs(ct%alpha), ct%ellipse%max_pressure, ct%ellipse%semi_major, &
                                         ct%ellipse%semi_minor]
                  v(row, c + 6:c + 12) = nan
                  if (ct%load > 0.0_wp) then
                     v(row, c + 6:c + 12) = [p%slip(j, k), p%coefficient(j, k), loads%traction(j, k)%spin_roll, &
                                             loads%heat(j, k), p%film(j, k), p%thermal_factor(j, k), &
                                             p%temp_rise(j, k)]
                  end if
               end associate
               c = c + N_CONTACT
            end do
         end do
      end associate
   end subroutine ball_element_row

   !> Orbital angular velocity (rad/s) about the bearing axis of a point at position x with
   !> velocity u: (r x u)_x / r**2 with r = (0, x_y, x_z); 0 on the axis.
   pure real(wp) function orbit_speed(x, u)
      real(wp), intent(in) :: x(3), u(3)
      real(wp) :: r2
      r2 = x(2)**2 + x(3)**2
      orbit_speed = 0.0_wp
      if (r2 > 0.0_wp) orbit_speed = (x(2)*u(3) - x(3)*u(2))/r2
   end function orbit_speed

   !> Whether step `step` of n_steps is a row: every stride-th step, a printed step, the last.
   pure logical function history_due(h, step, n_steps, printed)
      type(run_history_t), intent(in) :: h
      integer, intent(in) :: step, n_steps
      logical, intent(in) :: printed
      history_due = printed .or. step == n_steps .or. mod(step, h%stride) == 0
   end function history_due

   !> Record step `step` at time `time` (s) of a ball bearing at state s with the loads of
   !> the force assembly at that state; wear(n) and race_wear(2) (outer, inner) are the
   !> time-averaged wear rates since the start (m**3/s), clearance the guide land's
   !> diametral clearance (m; NaN without a guide land).  The values are those the print
   !> shows at a printed step (adore_output_ball_dynamic_report): contact load as computed,
   !> loss and contact temperature NaN at an unloaded contact; land and pocket forces are
   !> the magnitudes of the contact force on the cage and on the ball (0 when the run has no
   !> cage contacts: ball_system_t%cage); cage whirl and radial velocity are the components
   !> of the mass-centre velocity across and along its radius in the transverse plane (0 on
   !> the axis).  A row beyond the capacity doubles it (a run to a simulated time has no
   !> step count to size it by; history_shape's count holds for a run of steps).
   subroutine record_ball_history(h, step, time, s, loads, wear, race_wear, clearance)
      type(run_history_t), intent(inout) :: h
      integer, intent(in) :: step
      real(wp), intent(in) :: time
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(in) :: wear(:), race_wear(2), clearance
      real(wp) :: r, nan
      integer :: row, j, k, c

      if (h%rows >= size(h%values, 1)) call grow_history(h)
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      h%rows = h%rows + 1
      row = h%rows
      associate (v => h%values)
         v(row, C_TIME) = time
         v(row, C_STEP) = real(step, wp)
         v(row, C_POWER) = total_power_loss(loads)
         v(row, C_BULK:C_BULK + 5) = s%temperature([TEMP_ELEMENT, TEMP_CAGE, TEMP_OUTER, TEMP_INNER, TEMP_HOUSING, &
                                                     TEMP_SHAFT])
         v(row, C_WEAR) = sum(wear)/size(wear)
         v(row, C_WEAR + 1:C_WEAR + 2) = race_wear
         associate (p => s%cage%position, u => s%cage%velocity)
            r = hypot(p(2), p(3))
            v(row, C_CAGE:C_CAGE + 1) = p(2:3)
            v(row, C_CAGE + 2:C_CAGE + 3) = 0.0_wp
            if (r > 0.0_wp) v(row, C_CAGE + 2:C_CAGE + 3) = [p(2)*u(3) - p(3)*u(2), p(2)*u(2) + p(3)*u(3)]/r
         end associate
         v(row, C_CLEARANCE) = clearance
         do k = 1, h%n_lands
            v(row, N_FIXED + k) = 0.0_wp
            if (allocated(loads%lands)) v(row, N_FIXED + k) = norm2(loads%lands(k)%force_cage)
         end do
         c = N_FIXED + h%n_lands
         k = h%element
         do j = 1, 2
            v(row, c + j) = loads%contacts(j, k)%load
            v(row, c + 2 + j) = nan
            v(row, c + 4 + j) = nan
            if (.not. (loads%contacts(j, k)%load > 0.0_wp)) cycle
            v(row, c + 2 + j) = loads%heat(j, k)
            v(row, c + 4 + j) = wall_temperature(s%temperature, merge(BODY_OUTER, BODY_INNER, j == 1))
         end do
         v(row, c + 7) = 0.0_wp
         if (allocated(loads%pockets)) v(row, c + 7) = norm2(loads%pockets(k)%force_ball)
      end associate
   end subroutine record_ball_history

   !> Append column `name` (NaN in every row so far) to history h: a quantity of the bearing
   !> kind's own (the thermal model's exit fluid temperature); the kind sets it in every
   !> row it records (set_history_value).
   subroutine add_history_column(h, name)
      type(run_history_t), intent(inout) :: h
      character(len=*), intent(in) :: name
      real(wp), allocatable :: values(:, :)
      allocate (values(size(h%values, 1), size(h%values, 2) + 1))
      values(:, :size(h%values, 2)) = h%values
      values(:, size(values, 2)) = ieee_value(1.0_wp, ieee_quiet_nan)
      call move_alloc(values, h%values)
      h%names = [character(len=HISTORY_NAME_LEN) :: h%names, name]
   end subroutine add_history_column

   !> Set column `name` of the last recorded row of h to value (nothing when h has no such
   !> column or no row).
   subroutine set_history_value(h, name, value)
      type(run_history_t), intent(inout) :: h
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: value
      integer :: c
      if (h%rows < 1) return
      c = findloc(h%names, name, 1)
      if (c > 0) h%values(h%rows, c) = value
   end subroutine set_history_value

   !> Replace the whole-bearing and chosen-element values of h's last row (step 0) with those
   !> of the step-0 solution the print shows (issue #29): power (W), the mean ball wear and
   !> the race wear (m**3/s), the cage centre's (y, z) (m) and its whirl and radial velocity
   !> (m/s), each guide land's contact force land_force(n_lands) (N), the chosen element's
   !> contact loads, losses (W; NaN unloaded) and contact temperatures (K; NaN unloaded)
   !> of the outer and inner race and its pocket force (N).  Time, step, bulk temperatures
   !> and the guide clearance stay (the same at both).
   subroutine set_step0_row(h, power, wear, race_wear, cage_yz, cage_velocity, land_force, load, loss, temp, &
                            pocket_force)
      type(run_history_t), intent(inout) :: h
      real(wp), intent(in) :: power, wear, race_wear(2), cage_yz(2), cage_velocity(2), land_force(:)
      real(wp), intent(in) :: load(2), loss(2), temp(2), pocket_force
      integer :: row, c
      if (h%rows < 1) return
      row = h%rows
      associate (v => h%values)
         v(row, C_POWER) = power
         v(row, C_WEAR) = wear
         v(row, C_WEAR + 1:C_WEAR + 2) = race_wear
         v(row, C_CAGE:C_CAGE + 1) = cage_yz
         v(row, C_CAGE + 2:C_CAGE + 3) = cage_velocity
         v(row, N_FIXED + 1:N_FIXED + min(h%n_lands, size(land_force))) = land_force(1:min(h%n_lands, size(land_force)))
         c = N_FIXED + h%n_lands
         v(row, c + 1:c + 2) = load
         v(row, c + 3:c + 4) = loss
         v(row, c + 5:c + 6) = temp
         v(row, c + 7) = pocket_force
      end associate
   end subroutine set_step0_row

   !> Double the row capacity of h, keeping its rows.
   subroutine grow_history(h)
      type(run_history_t), intent(inout) :: h
      real(wp), allocatable :: values(:, :)
      allocate (values(max(2*size(h%values, 1), 16), size(h%values, 2)))
      values(1:h%rows, :) = h%values(1:h%rows, :)
      call move_alloc(values, h%values)
      if (allocated(h%elements)) then
         allocate (values(size(h%values, 1), size(h%elements, 2)))
         values(1:h%rows, :) = h%elements(1:h%rows, :)
         call move_alloc(values, h%elements)
      end if
   end subroutine grow_history

   !> The plot-data file of print file print_path: its name with the extension (after the
   !> last dot of the file name) replaced by ".hist.csv".
   subroutine history_file_name(print_path, path)
      character(len=*), intent(in) :: print_path
      character(len=:), allocatable, intent(out) :: path
      call beside_file_name(print_path, ".hist.csv", path)
   end subroutine history_file_name

   !> The file of print file print_path with the extension (after the last dot of the file
   !> name; none: at its end) replaced by `suffix` (".hist.csv", ".elements.bin", ".nc").
   subroutine beside_file_name(print_path, suffix, path)
      character(len=*), intent(in) :: print_path, suffix
      character(len=:), allocatable, intent(out) :: path
      integer :: dot
      dot = index(print_path, ".", back=.true.)
      if (dot > index(print_path, "/", back=.true.) + 1) then
         path = print_path(:dot - 1)//suffix
      else
         path = trim(print_path)//suffix
      end if
   end subroutine beside_file_name

   !> The column names joined by commas (the plot-data file's header line).
   subroutine history_columns_text(h, text)
      type(run_history_t), intent(in) :: h
      character(len=:), allocatable, intent(out) :: text
      integer :: k
      text = trim(h%names(1))
      do k = 2, size(h%names)
         text = text//","//trim(h%names(k))
      end do
   end subroutine history_columns_text

   !> The element file of print file print_path (docs/results.md): its name with the
   !> extension replaced by ".elements.bin".
   subroutine element_file_name(print_path, path)
      character(len=*), intent(in) :: print_path
      character(len=:), allocatable, intent(out) :: path
      call beside_file_name(print_path, ".elements.bin", path)
   end subroutine element_file_name

   !> Write the plot-data file `path` (docs/plots.md): the header line of column names, then
   !> one line per recorded row, the step as an integer and every other value with 17
   !> significant digits (ES24.16E3: the file gives back the recorded doubles exactly; NaN
   !> as "NaN").  incomplete non-blank: the run stopped early; a last line
   !> "# RUN INCOMPLETE<incomplete>" says so, as the print's last line does.  Written under
   !> path.part and renamed onto path when complete.
   subroutine write_history_csv(h, path, incomplete, error)
      type(run_history_t), intent(in) :: h
      character(len=*), intent(in) :: path, incomplete
      type(error_type), allocatable, intent(out) :: error
      call write_table(h%names, h%values, h%rows, path, "plot-data file", incomplete, error)
   end subroutine write_history_csv

   !> Write the element file `path` (docs/results.md) of history h, under path.part renamed
   !> onto path when complete: three text lines - "ADORE ELEMENT RECORD 1 <rows> <columns>
   !> <LE|BE>" (format version, byte order of the values), the column names joined by
   !> commas (time_s, step, then the element record's), "COMPLETE" or "RUN
   !> INCOMPLETE<incomplete>" for a run that stopped early - each ended by a line feed, then
   !> rows x columns IEEE doubles, row after row: every recorded value exactly (a text
   !> table of them would cost more than the run's time steps to format).  Nothing is
   !> written for a history without an element record.
   subroutine write_element_file(h, path, incomplete, error)
      use, intrinsic :: iso_fortran_env, only: int8, int32
      type(run_history_t), intent(in) :: h
      character(len=*), intent(in) :: path, incomplete
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: lf = achar(10)
      character(len=:), allocatable :: header
      character(len=256) :: iomsg
      real(wp), allocatable :: row(:)
      integer :: unit, stat, i, k, bad
      logical :: ok

      if (.not. allocated(h%elements)) return
      if (size(h%elements, 2) == 0) return
      header = "ADORE ELEMENT RECORD 1 "//itoa(h%rows)//" "//itoa(size(h%elements, 2) + 2)//" "// &
               merge("LE", "BE", transfer(1_int32, 1_int8) == 1_int8)//lf//trim(h%names(C_TIME))//","// &
               trim(h%names(C_STEP))
      do k = 1, size(h%element_names)
         header = header//","//trim(h%element_names(k))
      end do
      if (len_trim(incomplete) > 0) then
         header = header//lf//"RUN INCOMPLETE"//trim(incomplete)//lf
      else
         header = header//lf//"COMPLETE"//lf
      end if
      open (newunit=unit, file=path//".part", status="replace", action="write", access="stream", &
            form="unformatted", iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call input_error(error, path//": cannot write the element file: "//trim(iomsg))
         return
      end if
      write (unit, iostat=stat) header
      bad = stat
      ! each row copied into a contiguous vector first: the same bytes, and libgfortran writes
      ! a strided section value by value (~140 instructions a value, the run's second largest
      ! serial cost after the integrator's linear algebra)
      allocate (row(size(h%elements, 2)))
      do i = 1, h%rows
         row = h%elements(i, :)
         write (unit, iostat=stat) h%values(i, C_TIME), h%values(i, C_STEP), row
         if (stat /= 0) bad = stat
      end do
      close (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0 .or. bad /= 0) then
         if (stat == 0) iomsg = "write error"
         call delete_file(path//".part")
         call engine_error(error, path//": cannot write the element file: "//trim(iomsg))
         return
      end if
      call rename_file(path//".part", path, ok)
      if (.not. ok) then
         call delete_file(path//".part")
         call engine_error(error, path//": cannot move the finished element file into place")
      end if
   end subroutine write_element_file

   !> Write the table of column names `names` (time and step among them, columns C_TIME and
   !> C_STEP) to `path` under path.part (write_history_csv).
   subroutine write_table(names, values, rows, path, what, incomplete, error)
      character(len=*), intent(in) :: names(:)
      real(wp), intent(in) :: values(:, :)
      integer, intent(in) :: rows
      character(len=*), intent(in) :: path, what, incomplete
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: header, line, cells, row_format
      character(len=256) :: iomsg
      integer :: unit, stat, i, k, bad, pos, m
      logical :: ok

      open (newunit=unit, file=path//".part", status="replace", action="write", form="formatted", &
            iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call input_error(error, path//": cannot write the "//what//": "//trim(iomsg))
         return
      end if
      header = trim(names(1))
      do k = 2, size(names)
         header = header//","//trim(names(k))
      end do
      write (unit, "(a)", iostat=stat) header
      bad = stat
      ! one line of at most 25 characters a value, filled in place and written at once; the
      ! row's values formatted by one internal write into 25-character cells (es24.16e3, the
      ! step i24, each and a blank), then each cell's text without its blanks: the same text as
      ! a write per value, a quarter fewer instructions (the per-value write statements'
      ! set-up; the number conversions remain the file's cost)
      m = size(values, 2)
      allocate (character(len=25*m) :: line, cells)
      row_format = "("
      do k = 1, m
         row_format = row_format//trim(merge("i24      ", "es24.16e3", k == C_STEP))//",1x"//trim(merge(",", ")", k < m))
      end do
      do i = 1, rows
         pos = 0
         if (m >= C_STEP) then
            write (cells, row_format) values(i, :C_STEP - 1), nint(values(i, C_STEP)), values(i, C_STEP + 1:)
         else
            write (cells, row_format) values(i, :)
         end if
         do k = 1, m
            call put(cells(25*(k - 1) + 1:25*k - 1))
         end do
         write (unit, "(a)", iostat=stat) line(:pos - 1)
         if (stat /= 0) bad = stat
      end do
      if (len_trim(incomplete) > 0) write (unit, "(a)", iostat=stat) "# RUN INCOMPLETE"//trim(incomplete)
      if (stat /= 0) bad = stat
      close (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0 .or. bad /= 0) then
         if (stat == 0) iomsg = "write error"
         call delete_file(path//".part")
         call engine_error(error, path//": cannot write the "//what//": "//trim(iomsg))
         return
      end if
      call rename_file(path//".part", path, ok)
      if (.not. ok) then
         call delete_file(path//".part")
         call engine_error(error, path//": cannot move the finished "//what//" into place")
      end if

   contains

      !> Append the value text c (blanks removed) and a comma to the line.
      subroutine put(c)
         character(len=*), intent(in) :: c
         integer :: a, n
         a = verify(c, " ")
         n = len_trim(c) - a + 1
         line(pos + 1:pos + n + 1) = c(a:a + n - 1)//","
         pos = pos + n + 1
      end subroutine put

   end subroutine write_table

end module adore_output_run_history
