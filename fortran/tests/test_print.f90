!> Unit tests of the print writer (fortran/output/print_tables.f90): the field rules of
!> docs/print-layout.md - NaN prints "NaN", a value or integer too wide prints asterisks,
!> INT_NOT_COMPUTED prints "NaN" - on lines written to a scratch file and read back.
!> (Byte-identity with the Python writer on the golden files: tests/test_print_writer.py.)
program test_print
   use adore_test_support, only: check, finish
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_output_layout, only: INT_NOT_COMPUTED, TABLE_RACE_CAGE, TABLE_SUMMARY, STEP_HEADING
   use adore_output_print_tables, only: int_field, write_table, write_termination, write_step_header
   use adore_output_echo_data, only: echo_data_t, echo_data_init
   use adore_output_print_echo, only: write_echo
   implicit none

   real(wp) :: nan

   nan = ieee_value(1.0_wp, ieee_quiet_nan)
   call test_int_field()
   call test_rows()
   call test_echo_defaults()

   call finish("print")

contains

   subroutine test_int_field()
      call check(int_field(7, 3) == "  7", "I3 of 7")
      call check(int_field(1000, 3) == "***", "I3 overflow of 1000")
      call check(int_field(-100, 3) == "***", "I3 overflow of -100")
      call check(int_field(INT_NOT_COMPUTED, 3) == "NaN", "I3 not computed")
      call check(int_field(INT_NOT_COMPUTED, 13) == "          NaN", "I13 not computed")
      call check(int_field(INT_NOT_COMPUTED, 2) == "**", "I2 not computed is too narrow")
   end subroutine test_int_field

   !> Read every line of a scratch unit back.
   subroutine read_back(unit, lines, n)
      integer, intent(in) :: unit
      character(len=256), intent(out) :: lines(:)
      integer, intent(out) :: n
      integer :: ios

      rewind (unit)
      n = 0
      do
         read (unit, "(a)", iostat=ios) lines(n + 1)
         if (ios /= 0) exit
         n = n + 1
         if (n == size(lines)) exit
      end do
   end subroutine read_back

   subroutine test_rows()
      integer :: unit, n
      character(len=256) :: lines(40)

      open (newunit=unit, status="scratch", action="readwrite")
      call write_table(unit, TABLE_RACE_CAGE, [1, 100000], &
                       reshape([1.0_wp, 2.0_wp, nan, -1.5e-120_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, &
                                0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], [2, 7]), reshape([0, INT_NOT_COMPUTED], [2, 1]))
      call write_table(unit, TABLE_SUMMARY, [2500], reshape([8.612e-2_wp, (0.0_wp, n = 1, 9)], [1, 10]))
      call write_termination(unit, 2500, -353.4_wp)
      call write_step_header(unit, 0, [0.0_wp, nan, 0.0_wp, 0.0_wp], "Run")
      call read_back(unit, lines, n)
      close (unit)
      call check(n == 3 + 2 + 4 + 1 + 1 + 5, "line count")
      call check(lines(4) == "    1  0  1.000E+00        NaN  0.000E+00  0.000E+00  0.000E+00  0.000E+00  0.000E+00", &
                 "race_cage row 1: NaN value")
      call check(lines(5) == "*****NaN  2.000E+00 -1.500-120  0.000E+00  0.000E+00  0.000E+00  0.000E+00  0.000E+00", &
                 "race_cage row 2: I5 overflow, code not computed, three-digit exponent")
      call check(lines(10) == "  2500  8.612E-02  0.000E+00  0.000E+00  0.000E+00  0.000E+00  0.000E+00  0.000E+00" // &
                 "  0.000E+00  0.000E+00  0.000E+00", "summary row")
      call check(lines(11) == "     Normal termination: Last Step Number =    2500     Final Time = **********", &
                 "ES10.4 overflow of a negative final time")
      call check(lines(12) == STEP_HEADING, "step heading")
      call check(lines(14) == "     0  0.000E+00        NaN      0.000E+00      0.000E+00  Run", "step header values")
   end subroutine test_rows

   !> A fresh echo record prints every real as NaN (not computed) and skips the optional lines.
   subroutine test_echo_defaults()
      type(echo_data_t) :: e
      integer :: unit, n
      character(len=256) :: lines(200)

      e = echo_data_init()
      e%n_elements = 18
      e%bearing_type = "BALL"
      e%program_mode = 1
      e%run_id = "Run"
      open (newunit=unit, status="scratch", action="readwrite")
      call write_echo(unit, e)
      call read_back(unit, lines, n)
      close (unit)
      call check(lines(1) == "Copyright Pradeep K Gupta Inc", "copyright line")
      call check(lines(4)(1:53) == "*  Bearing Type = BALL        Program Mode = 1     Ru", "banner box")
      call check(len_trim(lines(4)) == 120 .and. lines(4)(120:120) == "*", "banner box closes in column 120")
      call check(lines(7) == "BEARING GEOMETRY" .and. lines(8) == "----------------", "first block title")
      call check(lines(10) == " NO OF BALLS                   18 OUTER CUR FAC                NaN OUTER FIT (m)" // &
                 "                NaN SHAFT OD (m)                 NaN", "item line with NaN values")
      call check(n == 127 - 2 - 2 - 1, "echo line count without guide lands, lubricant and heat transfer lines")
      call check(lines(n) == "" .and. lines(n - 1)(1:12) == " ERROR LIMIT", "echo ends with the controls")
   end subroutine test_echo_defaults

end program test_print
