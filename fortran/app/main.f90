!> The standalone `adore` program:
!> `adore DECK [OUT.prt] [--steps N] [--traction-table FILE] [--ball-start NAME] [--moment-equilibrium]
!> [--traction-1d]`.
!>
!> The only place that ends the process: exit code 0 ok, 1 bad input, 2 engine failure.
program adore
   use adore_core_error, only: error_type, input_error, ADORE_OK
   use adore_core_version, only: adore_version_string
   use adore_driver_run, only: run_deck, STEPS_FROM_DECK, TIME_STEPS_IMPLEMENTED
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   implicit none

   type(error_type), allocatable :: error
   character(len=:), allocatable :: deck_path, out_path, arg, table_path, ball_start
   integer :: i, nargs, steps, stat, dot, integrated
   logical :: moments, two_d

   integrated = 0
   steps = STEPS_FROM_DECK
   deck_path = ""
   table_path = ""
   ball_start = ""
   moments = .false.
   two_d = .true.
   out_path = ""
   nargs = command_argument_count()
   i = 1
   do while (i <= nargs)
      call get_arg(i, arg)
      select case (arg)
      case ("-h", "--help")
         call usage(output_unit)
         call exit_with(ADORE_OK)
      case ("--version")
         write (output_unit, "(a)") "adore (pyadore) "//adore_version_string
         call exit_with(ADORE_OK)
      case ("--steps")
         call option_value(i, "--steps", "a value", arg, error)
         if (allocated(error)) exit
         read (arg, *, iostat=stat) steps
         if (stat /= 0) then
            call input_error(error, "--steps: expected an integer, got '"//arg//"'")
            exit
         end if
      case ("--traction-table")
         call option_value(i, "--traction-table", "a file", table_path, error)
         if (allocated(error)) exit
      case ("--moment-equilibrium")
         moments = .true.
      case ("--traction-1d")
         two_d = .false.
      case ("--ball-start")
         call option_value(i, "--ball-start", "a start hypothesis name", ball_start, error)
         if (allocated(error)) exit
      case default
         if (len(deck_path) == 0) then
            deck_path = arg
         else if (len(out_path) == 0) then
            out_path = arg
         else
            call input_error(error, "unexpected argument '"//arg//"'")
            exit
         end if
      end select
      i = i + 1
   end do

   if (.not. allocated(error)) then
      if (len(deck_path) == 0) then
         call usage(error_unit)
         call input_error(error, "no deck file given")
      end if
   end if
   if (.not. allocated(error)) then
      if (len(out_path) == 0) then
         ! Default print file: the deck path with its extension replaced by .prt
         dot = index(deck_path, ".", back=.true.)
         if (dot > index(deck_path, "/", back=.true.) + 1) then
            out_path = deck_path(:dot - 1)//".prt"
         else
            out_path = deck_path//".prt"
         end if
      end if
      call run_deck(deck_path, out_path, steps, error, table_path, ball_start, moments, integrated, two_d)
   end if

   if (allocated(error)) then
      write (error_unit, "(a)") "adore: error: "//error%message
      call exit_with(error%stat)
   end if
   write (output_unit, "(a)") "print file written: "//out_path
   ! what the print holds, when it is not what was asked for (pyadore/api.py says the same)
   if (steps == STEPS_FROM_DECK .and. TIME_STEPS_IMPLEMENTED == 0) then
      write (error_unit, "(a)") "adore: note: time integration is opt-in (--steps N) while [Dynamics] is in "// &
         "progress; the print file ends after step 0 (the quasi-static start)"
   else if (steps > 0 .and. integrated == 0) then
      write (error_unit, "(a)") "adore: note: time integration of roller bearings is not implemented yet; "// &
         "the print file ends after step 0 (the quasi-static start)"
   else if (integrated > 0) then
      write (error_unit, "(a)") "adore: note: dynamics in progress (issue #20): no cage contacts, thermal model off"
   end if
   call exit_with(ADORE_OK)

contains

   !> The value after option `name` at argument i (i moves to it); input error when it is
   !> missing or blank, saying that the option needs `what`.
   subroutine option_value(i, name, what, value, error)
      integer, intent(inout) :: i
      character(len=*), intent(in) :: name, what
      character(len=:), allocatable, intent(out) :: value
      type(error_type), allocatable, intent(out) :: error

      if (i == command_argument_count()) then
         call input_error(error, name//" needs "//what)
         return
      end if
      i = i + 1
      call get_arg(i, value)
      if (len_trim(value) == 0) call input_error(error, name//": expected "//what//", got a blank argument")
   end subroutine option_value

   subroutine get_arg(n, value)
      integer, intent(in) :: n
      character(len=:), allocatable, intent(out) :: value
      integer :: length

      call get_command_argument(n, length=length)
      allocate (character(len=length) :: value)
      call get_command_argument(n, value)
   end subroutine get_arg

   subroutine usage(unit)
      integer, intent(in) :: unit
      write (unit, "(a)") "usage: adore DECK [OUT.prt] [--steps N] [--traction-table FILE] [--ball-start NAME]"// &
         " [--moment-equilibrium] [--traction-1d]"
      write (unit, "(a)") "  runs an ADORE deck and writes its print file (default: DECK with .prt)"
      write (unit, "(a)") "  --steps N                N > 0: integrate N time steps after step 0 (ball decks; opt-in"
      write (unit, "(a)") "                           dynamics, issue #20 in progress: no cage contacts, thermal off);"
      write (unit, "(a)") "                           0 = quasi-static start only; -1 = as the deck says (default:"
      write (unit, "(a)") "                           step 0 only while the dynamics is in progress)"
      write (unit, "(a)") "  --traction-table FILE    traction-slip table (slip m/s, coefficient per line; ADRX7)"
      write (unit, "(a)") "                           replacing the deck's RE/race traction model"
      write (unit, "(a)") "  --ball-start NAME        initial ball angular velocity (report 4.4.7): dissipation"
      write (unit, "(a)") "                           (default, minimum contact dissipation), outer-race-control"
      write (unit, "(a)") "                           or inner-race-control (ball decks only)"
      write (unit, "(a)") "  --moment-equilibrium     solve the inner race's misalignment for moment equilibrium"
      write (unit, "(a)") "                           (ADORE kFS4 = kFS5 = 0) instead of prescribing it zero (ball decks)"
      write (unit, "(a)") "  --traction-1d            developer option of the dynamics: one-dimensional race traction"
      write (unit, "(a)") "                           (slip along the rolling direction only, report eq 1) instead of"
      write (unit, "(a)") "                           the two-dimensional default (docs/dynamics.md)"
   end subroutine usage

   !> End the process with exit status `code` and nothing printed by the runtime.
   subroutine exit_with(code)
      integer, intent(in) :: code
      stop code, quiet=.true.
   end subroutine exit_with

end program adore
