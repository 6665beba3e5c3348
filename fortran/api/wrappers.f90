!> Flat f2py boundary of the engine (module pyadore._engine).
!>
!> External subroutines with scalars and fixed-length strings only; each builds the
!> engine's derived types inside, calls the library and returns a status code
!> (0 ok, 1 input error, 2 engine failure) and a message.  Nothing here stops the
!> process.  The interface seen by Python is declared in _engine.pyf.

!> The run of a deck behind adore_run_file and adore_run_file_progress: the run options
!> from their text, the run's paths checked and the output path cleared
!> (adore_output_run_files, as the standalone program does), run_deck, its outputs as
!> status, message, counts and note.
module adore_api_run
   use adore_core_error, only: error_type, ADORE_OK
   use adore_api_status, only: set_error
   use adore_driver_run, only: run_deck, run_progress
   use adore_output_run_files, only: check_run_paths, clear_run_outputs
   use adore_model_run_options, only: run_options_t, run_options_from_text
   use adore_output_run_history, only: run_history_t
   implicit none
   private

   public :: run_with_options

contains

   !> run_deck(deck_path, out_path, options) with the run options as "name=value" lines
   !> (adore_model_run_options): the steps integrated, the rows of the time history the run
   !> wrote to its plot-data file (0: none written), the run's note, status and message.  The
   !> time history reaches Python through the plot-data file, every value to its last digit
   !> (ES24.16E3, adore_output_run_history), so the deck is read once per run.
   subroutine run_with_options(deck_path, out_path, options, integrated, history_rows, note, status, message, &
                               progress)
      character(len=*), intent(in) :: deck_path, out_path, options
      integer, intent(out) :: integrated, history_rows, status
      character(len=*), intent(out) :: note, message
      procedure(run_progress), optional :: progress
      type(error_type), allocatable :: error
      type(run_history_t) :: history
      type(run_options_t) :: opts
      character(len=:), allocatable :: run_note

      integrated = 0
      history_rows = 0
      call run_options_from_text(options, opts, error)
      if (.not. allocated(error)) call check_run_paths(deck_path, out_path, opts%traction_table, error)
      if (.not. allocated(error)) then
         call clear_run_outputs(out_path)
         call run_deck(deck_path, out_path, opts, error, integrated, history, run_note, progress)
      end if
      status = ADORE_OK
      message = ""
      note = ""
      if (allocated(run_note)) note = run_note
      history_rows = history%rows
      if (allocated(error)) call set_error(error, status, message)
   end subroutine run_with_options

end module adore_api_run

!> Run a deck and write its print file and, with time steps, its plot-data file (see
!> adore_driver_run::run_deck): integrated = steps after step 0, history_rows = rows of the
!> plot-data file written (0: none), note = what the run does not do (blank: nothing).  No
!> progress callback (thread-safe).
subroutine adore_run_file(deck_path, out_path, options, integrated, history_rows, note, status, message)
   use adore_api_run, only: run_with_options
   implicit none
   character(len=*), intent(in) :: deck_path   !< deck file path
   character(len=*), intent(in) :: out_path    !< print file path to write
   character(len=*), intent(in) :: options     !< run options, "name=value" lines (adore_model_run_options)
   integer, intent(out) :: integrated          !< time steps after step 0
   integer, intent(out) :: history_rows        !< rows of the plot-data file written (0: none)
   character(len=4096), intent(out) :: note    !< what the run does not do; blank: nothing
   integer, intent(out) :: status              !< 0 ok, 1 input error, 2 engine failure
   character(len=16384), intent(out) :: message !< error message, blank on success

   call run_with_options(deck_path, out_path, options, integrated, history_rows, note, status, message)
end subroutine adore_run_file

!> adore_run_file with a progress callback: progress(step, n_steps, tau, time, stop) after
!> every accepted time step (adore_driver_time_loop's run_progress); stop /= 0 ends the
!> run there, incomplete ("interrupted", status 2).  Not thread-safe (the callback is Python).
subroutine adore_run_file_progress(deck_path, out_path, options, integrated, history_rows, note, status, message, &
                                   progress)
   use adore_api_run, only: run_with_options
   use adore_driver_run, only: run_progress
   implicit none
   character(len=*), intent(in) :: deck_path, out_path, options
   integer, intent(out) :: integrated, history_rows, status
   character(len=4096), intent(out) :: note
   character(len=16384), intent(out) :: message
   procedure(run_progress) :: progress

   call run_with_options(deck_path, out_path, options, integrated, history_rows, note, status, message, progress)
end subroutine adore_run_file_progress

!> The run option table (adore_model_run_options' OPTION_TABLE), for pyadore's keyword
!> checks and click options: per option its name, kind (1 integer, 2 text, 3 flag, 4 flag
!> whose `flag` spelling sets it false, 5 choice), default, minimum, off-flag, value name,
!> choices (comma-separated) and help line.
subroutine adore_run_option_table(nmax, n, names, kinds, defaults, minimums, flags, metavars, choices, helps)
   use adore_model_run_options, only: OPTION_TABLE, N_OPTIONS
   implicit none
   integer, intent(in) :: nmax
   integer, intent(out) :: n
   character(len=24), intent(out) :: names(nmax), defaults(nmax), flags(nmax)
   integer, intent(out) :: kinds(nmax), minimums(nmax)
   character(len=8), intent(out) :: metavars(nmax)
   character(len=64), intent(out) :: choices(nmax)
   character(len=160), intent(out) :: helps(nmax)
   integer :: k

   n = min(N_OPTIONS, nmax)
   names = ""
   defaults = ""
   flags = ""
   metavars = ""
   choices = ""
   helps = ""
   kinds = 0
   minimums = 0
   do k = 1, n
      names(k) = OPTION_TABLE(k)%name
      kinds(k) = OPTION_TABLE(k)%kind
      defaults(k) = OPTION_TABLE(k)%default
      minimums(k) = OPTION_TABLE(k)%minimum
      flags(k) = OPTION_TABLE(k)%flag
      metavars(k) = OPTION_TABLE(k)%metavar
      choices(k) = OPTION_TABLE(k)%choices
      helps(k) = OPTION_TABLE(k)%help
   end do
end subroutine adore_run_option_table

!> The engine's version string.
subroutine adore_version(version)
   use adore_core_version, only: adore_version_string
   implicit none
   character(len=32), intent(out) :: version

   version = adore_version_string
end subroutine adore_version
