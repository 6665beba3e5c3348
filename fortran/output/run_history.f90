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
   use adore_state_bearing_state, only: bearing_state_t
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, total_power_loss
   use adore_forces_race_contact, only: wall_temperature
   implicit none
   private

   public :: run_history_t, history_shape, new_ball_history, history_due, record_ball_history, &
             write_history_csv, history_file_name, history_columns_text

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

   !> The recorded time history of one run.
   type :: run_history_t
      integer :: element = 1                 !< rolling element of the per-element columns
      integer :: stride = 1                  !< every stride-th step is a row (and printed ones, the last)
      integer :: rows = 0                    !< rows recorded so far
      integer :: n_lands = 0                 !< guide lands (one force column each)
      character(len=HISTORY_NAME_LEN), allocatable :: names(:)   !< column names (docs/plots.md)
      real(wp), allocatable :: values(:, :)  !< (row capacity, column): rows 1..rows are recorded
   end type run_history_t

contains

   !> Row capacity, number of columns and stride of the history of a run of n_steps time steps
   !> printed every print_interval steps (Rec 1 data_control_2; 0: the last only) of a
   !> bearing with n_lands guide lands.
   pure subroutine history_shape(n_steps, print_interval, n_lands, rows, cols, stride)
      integer, intent(in) :: n_steps, print_interval, n_lands
      integer, intent(out) :: rows, cols, stride
      integer :: printed
      stride = max(1, (n_steps + HISTORY_ROWS - 1)/HISTORY_ROWS)
      printed = 0
      if (print_interval > 0) printed = n_steps/print_interval
      rows = 2 + n_steps/stride + printed
      cols = N_FIXED + max(n_lands, 0) + N_ELEMENT
   end subroutine history_shape

   !> The empty history of a run of ball bearing b over n_steps steps, with the per-element
   !> columns of rolling element `element` (1..n_elements; input error otherwise).
   subroutine new_ball_history(h, b, n_steps, element, error)
      type(run_history_t), intent(out) :: h
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: n_steps, element
      type(error_type), allocatable, intent(out) :: error
      integer :: rows, cols, k
      character(len=:), allocatable :: e

      if (element < 1 .or. element > b%n_elements) then
         call input_error(error, "time history element "//itoa(element)//": the bearing has rolling elements 1 to "// &
                          itoa(b%n_elements))
         return
      end if
      call history_shape(n_steps, b%controls%print_interval, b%n_lands, rows, cols, h%stride)
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
   end subroutine new_ball_history

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

   !> Double the row capacity of h, keeping its rows.
   subroutine grow_history(h)
      type(run_history_t), intent(inout) :: h
      real(wp), allocatable :: values(:, :)
      allocate (values(max(2*size(h%values, 1), 16), size(h%values, 2)))
      values(1:h%rows, :) = h%values(1:h%rows, :)
      call move_alloc(values, h%values)
   end subroutine grow_history

   !> The plot-data file of print file print_path: its name with the extension (after the
   !> last dot of the file name) replaced by ".hist.csv".
   subroutine history_file_name(print_path, path)
      character(len=*), intent(in) :: print_path
      character(len=:), allocatable, intent(out) :: path
      integer :: dot
      dot = index(print_path, ".", back=.true.)
      if (dot > index(print_path, "/", back=.true.) + 1) then
         path = print_path(:dot - 1)//".hist.csv"
      else
         path = trim(print_path)//".hist.csv"
      end if
   end subroutine history_file_name

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
      character(len=:), allocatable :: header
      character(len=32) :: cell
      character(len=256) :: iomsg
      integer :: unit, stat, i, k, bad
      logical :: ok

      open (newunit=unit, file=path//".part", status="replace", action="write", form="formatted", &
            iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call input_error(error, path//": cannot write the plot-data file: "//trim(iomsg))
         return
      end if
      call history_columns_text(h, header)
      write (unit, "(a)", iostat=stat) header
      bad = stat
      do i = 1, h%rows
         do k = 1, size(h%names)
            if (k == C_STEP) then
               write (cell, "(i0)") nint(h%values(i, k))
            else
               write (cell, "(es24.16e3)") h%values(i, k)
            end if
            if (k > 1) write (unit, "(a)", advance="no", iostat=stat) ","
            write (unit, "(a)", advance="no", iostat=stat) trim(adjustl(cell))
         end do
         write (unit, "(a)", iostat=stat) ""
         if (stat /= 0) bad = stat
      end do
      if (len_trim(incomplete) > 0) write (unit, "(a)", iostat=stat) "# RUN INCOMPLETE"//trim(incomplete)
      if (stat /= 0) bad = stat
      close (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0 .or. bad /= 0) then
         if (stat == 0) iomsg = "write error"
         call delete_file(path//".part")
         call engine_error(error, path//": cannot write the plot-data file: "//trim(iomsg))
         return
      end if
      call rename_file(path//".part", path, ok)
      if (.not. ok) then
         call delete_file(path//".part")
         call engine_error(error, path//": cannot move the finished plot-data file into place")
      end if
   end subroutine write_history_csv

end module adore_output_run_history
