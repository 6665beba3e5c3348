!> The standalone `adore` program:
!> `adore DECK [OUT.prt] [--steps N] [--history-element N] [--traction-table FILE] [--ball-start NAME]
!> [--moment-equilibrium] [--substeps N] [--traction-1d]`.
!>
!> The only place that ends the process: exit code 0 ok, 1 bad input, 2 engine failure
!> (including a time integration that stopped early or was interrupted: its print is kept
!> and ends with "*** RUN INCOMPLETE").

!> The program's progress line and Ctrl-C (process state of the standalone program only,
!> never of the engine): during a time integration a line "step n/N, simulated time, ETA"
!> on stderr,
!> rewritten in place at most twice a second, when stderr is a terminal; Ctrl-C
!> (fortran/app/sigint.c) makes the progress callback ask the run to stop.
module adore_app_progress
   use, intrinsic :: iso_c_binding, only: c_int
   use, intrinsic :: iso_fortran_env, only: error_unit, int64, real64
   implicit none
   private

   public :: show_progress, install_interrupt, end_progress_line

   interface
      subroutine adore_sigint_install() bind(c, name="adore_sigint_install")
      end subroutine adore_sigint_install
      function adore_sigint_received() result(flag) bind(c, name="adore_sigint_received")
         import :: c_int
         integer(c_int) :: flag
      end function adore_sigint_received
   end interface

   logical :: tty = .false.               !< stderr is a terminal
   integer(int64) :: started = -1         !< clock count at the first step
   integer(int64) :: shown = -1           !< clock count of the last line written
   logical :: line_open = .false.         !< a progress line waits for its newline

contains

   !> Catch Ctrl-C (sigint.c) and find out whether stderr is a terminal (gfortran's ISATTY).
   subroutine install_interrupt()
      call adore_sigint_install()
      tty = isatty(unit=error_unit)
   end subroutine install_interrupt

   !> The time loop's callback (adore_driver_ball_dynamics' run_progress): the progress line
   !> on a terminal; stop = 1 after Ctrl-C.
   subroutine show_progress(step, n_steps, tau, time, stop)
      integer, intent(in) :: step, n_steps
      real(real64), intent(in) :: tau, time
      integer, intent(out) :: stop
      integer(int64) :: now, rate
      real(real64) :: elapsed
      character(len=160) :: text

      stop = 0
      if (adore_sigint_received() /= 0) stop = 1
      if (.not. tty) return
      call system_clock(now, rate)
      if (started < 0) started = now
      if (stop == 0 .and. step < n_steps .and. shown >= 0 .and. now - shown < rate/2) return
      shown = now
      elapsed = real(now - started, real64)/real(rate, real64)
      write (text, "(a,i0,a,i0,a,es10.4,a,es10.4,a)") "adore: step ", step, "/", n_steps, ", simulated time ", &
         time, " s (tau ", tau, ")"
      if (step > 1 .and. step < n_steps) write (text, "(a,a,i0,a)") trim(text), ", ETA ", &
         nint(elapsed*real(n_steps - step, real64)/real(step - 1, real64)), " s"
      write (error_unit, "(a,a,a)", advance="no") achar(13), trim(text), "   "
      line_open = .true.
      if (stop /= 0 .or. step == n_steps) then
         write (error_unit, "(a)") ""
         line_open = .false.
      end if
      flush (error_unit)
   end subroutine show_progress

   !> End a progress line still open (a run that stopped by an error) with its newline.
   subroutine end_progress_line()
      if (line_open) write (error_unit, "(a)") ""
      line_open = .false.
   end subroutine end_progress_line

end module adore_app_progress

program adore
   use adore_core_error, only: error_type, input_error, ADORE_OK
   use adore_core_version, only: adore_version_string
   use adore_core_strings, only: replaced
   use adore_driver_run, only: run_deck
   use adore_model_run_options, only: run_options_t, set_run_option, option_index, OPTION_TABLE, N_OPTIONS, &
                                      OPTION_FLAG, OPTION_FLAG_OFF, option_spec_t
   use adore_output_run_history, only: history_file_name
   use adore_app_progress, only: show_progress, install_interrupt, end_progress_line
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   implicit none

   type(error_type), allocatable :: error
   type(run_options_t) :: opts
   character(len=:), allocatable :: deck_path, out_path, arg, value, note, hist_path
   integer :: i, nargs, dot, integrated, k

   integrated = 0
   deck_path = ""
   out_path = ""
   value = ""
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
      case default
         if (len(arg) > 2 .and. arg(1:min(2, len(arg))) == "--") then
            ! a run option of the table (adore_model_run_options): --name value, a flag alone
            k = option_index(arg(3:))
            if (k == 0) then
               call input_error(error, "unknown option '"//arg//"' (adore --help lists them)")
               exit
            end if
            if (OPTION_TABLE(k)%kind == OPTION_FLAG .or. OPTION_TABLE(k)%kind == OPTION_FLAG_OFF) then
               value = "true"
            else
               call option_value(i, arg, "a value ("//trim(OPTION_TABLE(k)%metavar)//")", value, error)
               if (allocated(error)) exit
            end if
            call set_run_option(opts, arg(3:), value, error)
            if (allocated(error)) exit
         else if (len(deck_path) == 0) then
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
      call install_interrupt()
      call run_deck(deck_path, out_path, opts, error, integrated, note=note, progress=show_progress)
      call end_progress_line()
   end if

   if (allocated(error)) then
      write (error_unit, "(a)") "adore: error: "//error%message
      call exit_with(error%stat)
   end if
   write (output_unit, "(a)") "print file written: "//out_path
   if (integrated > 0) then
      call history_file_name(out_path, hist_path)
      write (output_unit, "(a)") "plot-data file written: "//hist_path
   end if
   ! what the run does not do that a user may expect (pyadore's Result.notes say the same)
   if (allocated(note)) then
      if (len_trim(note) > 0) write (error_unit, "(a)") "adore: note: "//note
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

   !> The command line: the deck, the print file and every run option of the table
   !> (adore_model_run_options), one line of help each.
   subroutine usage(unit)
      integer, intent(in) :: unit
      character(len=:), allocatable :: flag
      type(option_spec_t) :: o
      integer :: k
      write (unit, "(a)") "usage: adore DECK [OUT.prt] [options]"
      write (unit, "(a)") "  runs an ADORE deck and writes its print file (default: DECK with .prt) and, when it"
      write (unit, "(a)") "  integrates time steps, its plot-data file beside it (OUT.hist.csv; docs/plots.md)"
      write (unit, "(a)") "options:"
      do k = 1, N_OPTIONS
         o = OPTION_TABLE(k)
         block
            if (o%kind == OPTION_FLAG_OFF) then
               flag = "--"//replaced(trim(o%flag), "_", "-")
            else
               flag = "--"//replaced(trim(o%name), "_", "-")
            end if
            if (len_trim(o%metavar) > 0) flag = flag//" "//trim(o%metavar)
            write (unit, "(2x,a,t27,a)") flag, trim(o%help)
            if (len_trim(o%default) > 0 .and. o%kind /= OPTION_FLAG .and. o%kind /= OPTION_FLAG_OFF) &
               write (unit, "(t27,a)") "(default: "//trim(o%default)//")"
         end block
      end do
   end subroutine usage


   !> End the process with exit status `code` and nothing printed by the runtime.
   !> Ctrl-C during a time integration (fortran/app/sigint.c) stops the run after its step:
   !> exit status 2, the print kept with its "*** RUN INCOMPLETE" line.
   subroutine exit_with(code)
      integer, intent(in) :: code
      stop code, quiet=.true.
   end subroutine exit_with

end program adore
