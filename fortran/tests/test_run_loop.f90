!> Unit tests of the run loop's bookkeeping (issue #20 items 5, 6): the time averages since
!> the start (adore_driver_time_average) against exact integrals, and the time history's
!> rows (adore_output_run_history: stride, capacity, the plot-data file's name and text).
program test_run_loop
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_driver_time_average, only: time_average_t
   use adore_output_run_history, only: run_history_t, history_shape, history_due, history_file_name, &
                                       write_history_csv, HISTORY_ROWS
   use adore_driver_time_loop, only: closure_hint
   use adore_test_support, only: check, finish
   implicit none

   call test_averages_are_exact_for_linear_values()
   call test_averages_weight_by_time()
   call test_history_rows()
   call test_history_file()
   call test_closure_hint()
   call finish("run loop")

contains

   !> f(t) = (2 + 3 t, 5): the trapezoidal rule is exact for linear values, so the mean over
   !> [0, t] is 2 + 1.5 t after any steps; at t = 0 the mean is the value.
   subroutine test_averages_are_exact_for_linear_values()
      type(time_average_t) :: a
      real(wp) :: mean(2), t, h(4)
      integer :: i
      call a%start([2.0_wp, 5.0_wp])
      call a%mean(mean)
      call check(all(mean == [2.0_wp, 5.0_wp]), "average at t = 0 is the value")
      h = [0.1_wp, 0.7_wp, 0.05_wp, 1.3_wp]
      t = 0.0_wp
      do i = 1, size(h)
         t = t + h(i)
         call a%add(h(i), [2.0_wp + 3.0_wp*t, 5.0_wp])
         call a%mean(mean)
         call check(abs(mean(1) - (2.0_wp + 1.5_wp*t)) < 1e-14_wp, "linear value: mean = f(t/2)")
         call check(abs(mean(2) - 5.0_wp) < 1e-14_wp, "constant value: mean = value")
      end do
      call check(abs(a%elapsed - sum(h)) < 1e-15_wp, "elapsed time = sum of the steps")
   end subroutine test_averages_are_exact_for_linear_values

   !> A value that is 1 for a long step and 0 for a short one: the mean is time-weighted
   !> (not the mean over the steps).
   subroutine test_averages_weight_by_time()
      type(time_average_t) :: a
      real(wp) :: mean(1)
      call a%start([1.0_wp])
      call a%add(3.0_wp, [1.0_wp])      ! 1 over [0, 3]
      call a%add(1.0_wp, [1.0_wp])      ! 1 over [3, 4]
      call a%mean(mean)
      call check(abs(mean(1) - 1.0_wp) < 1e-15_wp, "constant 1 stays 1")
      call a%start([0.0_wp])
      call a%add(1.0_wp, [0.0_wp])
      call a%add(1.0_wp, [2.0_wp])       ! ramp 0 -> 2 over [1, 2]: integral 1
      call a%add(2.0_wp, [2.0_wp])       ! 2 over [2, 4]: integral 4
      call a%mean(mean)
      call check(abs(mean(1) - 5.0_wp/4.0_wp) < 1e-15_wp, "time-weighted mean 5/4")
   end subroutine test_averages_weight_by_time

   !> Every step a row up to HISTORY_ROWS steps; beyond, the stride keeps the regular rows
   !> within HISTORY_ROWS; printed steps and the last are rows too, within the capacity.
   subroutine test_history_rows()
      type(run_history_t) :: h
      integer :: rows, cols, stride, n, count, i
      integer :: cases(4, 2)
      cases = reshape([2500, 10000, 25001, 1000000, 500, 7, 1000, 0], [4, 2])
      do n = 1, 4
         call history_shape(cases(n, 1), cases(n, 2), 2, rows, cols, stride)
         h%stride = stride
         call check(cols == 17 + 2 + 7, "columns: 17 + lands + 7")
         call check(cases(n, 1)/stride <= HISTORY_ROWS, "regular rows within HISTORY_ROWS")
         call check(stride == 1 .eqv. cases(n, 1) <= HISTORY_ROWS, "stride 1 up to HISTORY_ROWS steps")
         count = 1                              ! step 0
         do i = 1, cases(n, 1)
            if (history_due(h, i, cases(n, 1), cases(n, 2) > 0 .and. mod(i, max(cases(n, 2), 1)) == 0)) &
               count = count + 1
         end do
         call check(count <= rows, "the capacity holds every row")
         if (stride == 1) call check(count == cases(n, 1) + 1, "stride 1: every step")
      end do
      call check(history_due(h, cases(4, 1), cases(4, 1), .false.), "the last step is a row")
   end subroutine test_history_rows

   !> The file name beside a print and the text: header, rows, the incomplete line.
   subroutine test_history_file()
      type(run_history_t) :: h
      type(error_type), allocatable :: error
      character(len=:), allocatable :: path
      character(len=200) :: line
      integer :: unit, stat
      real(wp) :: x
      call history_file_name("out/appendix_c_ball.prt", path)
      call check(path == "out/appendix_c_ball.hist.csv", "history file name replaces the extension")
      call history_file_name("out.d/run", path)
      call check(path == "out.d/run.hist.csv", "history file name of a print without extension")
      allocate (h%names(3), h%values(2, 3))
      h%names = [character(len=40) :: "time_s", "step", "x_W"]
      h%rows = 2
      h%values(1, :) = [0.0_wp, 0.0_wp, 1.0_wp/3.0_wp]
      h%values(2, :) = [1.5e-3_wp, 7.0_wp, -2.5e10_wp]
      call write_history_csv(h, "test_run_loop.hist.csv", " after step 7 (tau = 1.0000E+00): test", error)
      call check(.not. allocated(error), "history file written")
      open (newunit=unit, file="test_run_loop.hist.csv", status="old", action="read", iostat=stat)
      call check(stat == 0, "history file exists")
      read (unit, "(a)") line
      call check(line == "time_s,step,x_W", "header line")
      read (unit, "(a)") line
      call check(line(1:2) == "0.", "first row starts with time 0")
      call check(index(line, ",0,") > 0, "step written as an integer")
      read (line(index(line, ",", back=.true.) + 1:), *) x
      call check(x == 1.0_wp/3.0_wp, "17 significant digits give the double back")
      read (unit, "(a)") line
      read (unit, "(a)") line
      call check(line == "# RUN INCOMPLETE after step 7 (tau = 1.0000E+00): test", "incomplete line last")
      close (unit, status="delete")
   end subroutine test_history_file

   !> The run note's hint when a window's balances do not close (issue #28): the limit that
   !> held the window's steps.  Steps forced at the minimum (ISO example 4 at 10 000 rpm and its
   !> static capacity: 111 of the window's 150) point to the minimum step, also when some steps
   !> reached the maximum; else steps at the maximum (Appendix C: 125 of 1 250) to the maximum
   !> step; else steps that met the error limit to the error limit.  Under the power-balance
   !> control every unforced step met its tolerance: the tolerance.
   subroutine test_closure_hint()
      character(len=:), allocatable :: hint
      call closure_hint(150, 111, 0, hint)
      call check(index(hint, "111 of the window's 150 time steps accepted at the minimum step") > 0 .and. &
                 index(hint, "smaller Rec 2.1 minimum step") > 0 .and. index(hint, "maximum step") == 0, &
                 "closure hint, forced steps: the minimum step: "//hint)
      call closure_hint(10, 3, 5, hint)
      call check(index(hint, "smaller Rec 2.1 minimum step") > 0 .and. index(hint, "maximum step") == 0, &
                 "closure hint, forced steps and steps at the maximum: the minimum step: "//hint)
      call closure_hint(1250, 0, 125, hint)
      call check(index(hint, "125 of the window's 1250 time steps at the maximum step") > 0 .and. &
                 index(hint, "smaller Rec 2.1 maximum step does") > 0 .and. index(hint, "minimum step") == 0, &
                 "closure hint, steps at the maximum: the maximum step: "//hint)
      call closure_hint(40, 0, 0, hint)
      call check(index(hint, "smaller Rec 2.1 error limit") > 0 .and. index(hint, "maximum step does") == 0 .and. &
                 index(hint, "minimum step resolves") == 0, "closure hint, steps within the limits: the error limit: "//hint)
      call closure_hint(150, 0, 90, hint, 3.0e-3_wp)
      call check(index(hint, "met the balance tolerance 3.00E-03 each: a smaller balance_tolerance does") > 0 .and. &
                 index(hint, "maximum step") == 0, "closure hint, balance control: the tolerance: "//hint)
      call closure_hint(150, 0, 0, hint, 3.0e-3_wp, 12)
      call check(index(hint, "12 of the window's 150 time steps at the minimum step, where the balance control stops"// &
                       ": a smaller Rec 2.1 minimum step does") > 0, "closure hint, balance control at the minimum "// &
                 "step: the minimum step: "//hint)
      call closure_hint(150, 4, 90, hint, 3.0e-3_wp, 12)
      call check(index(hint, "smaller Rec 2.1 minimum step") > 0 .and. index(hint, "balance") == 0, &
                 "closure hint, balance control and forced steps: the minimum step: "//hint)
   end subroutine test_closure_hint

end program test_run_loop
