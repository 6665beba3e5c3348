!> The standalone `adore` program:
!> `adore DECK [OUT.prt] [--steps N] [--history-element N] [--traction-table FILE] [--ball-start NAME]
!> [--moment-equilibrium] [--substeps N] [--traction-1d]`.
!>
!> The only place that ends the process: exit code 0 ok, 1 bad input (the run's paths
!> included: adore_output_run_files), 2 engine failure (including a time integration that
!> stopped early: its print is kept and ends with "*** RUN INCOMPLETE").  A stop signal
!> (SIGINT/Ctrl-C, SIGTERM, SIGHUP; fortran/app/sigint.c) stops the run at its next step
!> boundary and the program then ends by that signal (a shell shows 128 + its number: 130,
!> 143, 129): the print kept and marked incomplete when the run stopped after its second
!> time step or later, no print at all when it stopped before its first time step ended,
!> the complete print when the signal came after the last step.  Before the run starts the
!> output path is cleared (an older print never poses as this run's).

!> The program's progress line and stop signals (process state of the standalone program
!> only, never of the engine): during a time integration a line "step n/N, simulated time,
!> ETA" on stderr, rewritten in place at most twice a second, when stderr is a terminal; a
!> stop signal (fortran/app/sigint.c) makes the progress callback ask the run to stop.
module adore_app_progress
   use, intrinsic :: iso_c_binding, only: c_int
   use, intrinsic :: iso_fortran_env, only: error_unit, int64, real64
   implicit none
   private

   public :: show_progress, install_signals, end_progress_line, signal_received, signal_name, exit_by_signal, &
             last_step, stop_asked

   interface
      subroutine adore_signals_install() bind(c, name="adore_signals_install")
      end subroutine adore_signals_install
      function adore_signal_received() result(sig) bind(c, name="adore_signal_received")
         import :: c_int
         integer(c_int) :: sig
      end function adore_signal_received
      function adore_signal_kind() result(kind) bind(c, name="adore_signal_kind")
         import :: c_int
         integer(c_int) :: kind
      end function adore_signal_kind
      subroutine adore_signal_exit(sig) bind(c, name="adore_signal_exit")
         import :: c_int
         integer(c_int), value :: sig
      end subroutine adore_signal_exit
   end interface

   logical :: tty = .false.               !< stderr is a terminal
   integer(int64) :: started = -1         !< clock count at the first step
   integer(int64) :: shown = -1           !< clock count of the last line written
   logical :: line_open = .false.         !< a progress line waits for its newline
   integer :: last_step = 0               !< the last time step the callback was called after
   logical :: stop_asked = .false.        !< the callback asked the run to stop (a signal)

contains

   !> Catch the stop signals (sigint.c) and find out whether stderr is a terminal
   !> (gfortran's ISATTY).
   subroutine install_signals()
      call adore_signals_install()
      tty = isatty(unit=error_unit)
   end subroutine install_signals

   !> .true. once a stop signal came.
   logical function signal_received()
      signal_received = adore_signal_received() /= 0
   end function signal_received

   !> The name of the stop signal that came ("" if none).
   function signal_name() result(name)
      character(len=:), allocatable :: name
      select case (adore_signal_kind())
      case (1)
         name = "SIGINT (Ctrl-C)"
      case (2)
         name = "SIGTERM"
      case (3)
         name = "SIGHUP"
      case default
         name = ""
      end select
   end function signal_name

   !> End the process by the stop signal that came (sigint.c: its default action; exit
   !> status 128 + its number should that not end it).
   subroutine exit_by_signal()
      call adore_signal_exit(adore_signal_received())
   end subroutine exit_by_signal

   !> The time loop's callback (adore_driver_time_loop's run_progress): the progress line
   !> on a terminal; stop = 1 once a stop signal came, unless this is the last step (the
   !> run then ends complete).
   subroutine show_progress(step, n_steps, tau, time, stop)
      integer, intent(in) :: step, n_steps
      real(real64), intent(in) :: tau, time
      integer, intent(out) :: stop
      integer(int64) :: now, rate
      real(real64) :: elapsed
      character(len=160) :: text
      integer :: stat

      stop = 0
      last_step = step
      if (adore_signal_received() /= 0 .and. step < n_steps) stop = 1
      if (stop /= 0) stop_asked = .true.
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
      ! iostat: a terminal that hung up (SIGHUP) must not end the run with a runtime error
      write (error_unit, "(a,a,a)", advance="no", iostat=stat) achar(13), trim(text), "   "
      line_open = .true.
      if (stop /= 0 .or. step == n_steps) then
         write (error_unit, "(a)", iostat=stat) ""
         line_open = .false.
      end if
      flush (error_unit, iostat=stat)
   end subroutine show_progress

   !> End a progress line still open (a run that stopped by an error) with its newline.
   subroutine end_progress_line()
      integer :: stat
      if (line_open) write (error_unit, "(a)", iostat=stat) ""
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
   use adore_output_run_history, only: history_file_name, element_file_name
   use adore_output_run_files, only: check_run_paths, clear_run_outputs
   use adore_app_progress, only: show_progress, install_signals, end_progress_line, signal_received, signal_name, &
                                 exit_by_signal, last_step, stop_asked
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   implicit none

   type(error_type), allocatable :: error
   type(run_options_t) :: opts
   character(len=:), allocatable :: deck_path, out_path, arg, value, note, hist_path
   integer :: i, nargs, dot, integrated, k

   ! first of all: a stop signal from now on ends the program only where its files allow
   call install_signals()
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
      ! the paths before anything is read or written (a FIFO deck, -o DECK, -o DIR), then
      ! the output path cleared: an older print never poses as this run's
      call check_run_paths(deck_path, out_path, trim(opts%traction_table), error)
   end if
   if (.not. allocated(error)) then
      call clear_run_outputs(out_path)
      if (.not. signal_received()) then
         call run_deck(deck_path, out_path, opts, error, integrated, note=note, progress=show_progress)
         call end_progress_line()
      end if
      if (signal_received()) call stopped_by_signal()
   end if

   if (allocated(error)) then
      write (error_unit, "(a)") "adore: error: "//error%message
      call exit_with(error%stat)
   end if
   write (output_unit, "(a)") "print file written: "//out_path
   call history_file_name(out_path, hist_path)
   if (integrated > 0) write (output_unit, "(a)") "plot-data file written: "//hist_path
   call element_file_name(out_path, hist_path)
   if (integrated > 0) write (output_unit, "(a)") "element file written: "//hist_path
   ! what the run does not do that a user may expect (pyadore's Result.notes say the same)
   if (allocated(note)) then
      if (len_trim(note) > 0) write (error_unit, "(a)") "adore: note: "//note
   end if
   call exit_with(ADORE_OK)

contains

   !> A stop signal came before or during the run: say what became of it on stderr and end
   !> the process by that signal.  Stopped (or ended) before its first time step ended: no
   !> file is left (the run's outputs are removed).  Stopped later: the print and
   !> plot-data file are kept, marked incomplete (the run's error says where).  The signal
   !> came after the last step: the run's files are complete.  A failure of the run itself
   !> (not the stop) is reported first.
   subroutine stopped_by_signal()
      character(len=:), allocatable :: name
      integer :: stat

      name = signal_name()
      if (allocated(error) .and. .not. stop_asked) &
         write (error_unit, "(a)", iostat=stat) "adore: error: "//error%message
      if (last_step <= 1) then
         call clear_run_outputs(out_path)
         write (error_unit, "(a)", iostat=stat) "adore: stopped by "//name//" before the first time step "// &
            "ended: no print file written ("//out_path//")"
      else if (stop_asked .and. allocated(error)) then
         write (error_unit, "(a)", iostat=stat) "adore: stopped by "//name//": "//error%message
      else if (.not. allocated(error)) then
         call history_file_name(out_path, hist_path)
         write (error_unit, "(a)", iostat=stat) "adore: "//name//" came after the last time step: the print "// &
            "file "//out_path//" and its plot-data file "//hist_path//" are complete"
      else
         write (error_unit, "(a)", iostat=stat) "adore: stopped by "//name
      end if
      flush (error_unit, iostat=stat)
      flush (output_unit, iostat=stat)
      call exit_by_signal()
   end subroutine stopped_by_signal

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
            if (len(flag) > 23) then
               ! a flag and metavar past the help column: the help on its own line below
               write (unit, "(2x,a)") flag
               write (unit, "(t27,a)") trim(o%help)
            else
               write (unit, "(2x,a,t27,a)") flag, trim(o%help)
            end if
            if (len_trim(o%default) > 0 .and. o%kind /= OPTION_FLAG .and. o%kind /= OPTION_FLAG_OFF) &
               write (unit, "(t27,a)") "(default: "//trim(o%default)//")"
         end block
      end do
   end subroutine usage


   !> End the process with exit status `code` and nothing printed by the runtime.  (A stop
   !> signal ends it by that signal instead: stopped_by_signal.)
   subroutine exit_with(code)
      integer, intent(in) :: code
      stop code, quiet=.true.
   end subroutine exit_with

end program adore
