!> Flat f2py boundary of the engine (module pyadore._engine).
!>
!> External subroutines with scalars and fixed-length strings only; each builds the
!> engine's derived types inside, calls the library and returns a status code
!> (0 ok, 1 input error, 2 engine failure) and a message.  Nothing here stops the
!> process.  The interface seen by Python is declared in _engine.pyf.

!> The run of a deck behind adore_run_file and adore_run_file_progress: run_deck, then its
!> time history copied into the caller's arrays.
module adore_api_run
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error, ADORE_OK
   use adore_api_status, only: set_error
   use adore_driver_run, only: run_deck, run_progress
   use adore_model_run_options, only: run_options_t, run_options_from_text
   use adore_output_run_history, only: run_history_t, history_columns_text
   implicit none
   private

   public :: run_into_arrays

contains

   !> run_deck(deck_path, out_path, options, ...) with the run options as "name=value"
   !> lines (adore_model_run_options), the time history in hist(1:n_rows, 1:n_cols) (rows x
   !> cols from adore_run_plan), its column names joined by commas in columns, the steps
   !> integrated, the run's note, status and message.  On an early stop (status 2) the
   !> arrays hold the history up to the last accepted step.
   subroutine run_into_arrays(deck_path, out_path, options, rows, cols, hist, n_rows, n_cols, columns, integrated, &
                              note, status, message, progress)
      character(len=*), intent(in) :: deck_path, out_path, options
      integer, intent(in) :: rows, cols
      real(wp), intent(out) :: hist(rows, cols)
      integer, intent(out) :: n_rows, n_cols, integrated, status
      character(len=*), intent(out) :: columns, note, message
      procedure(run_progress), optional :: progress
      type(error_type), allocatable :: error
      type(run_history_t) :: history
      type(run_options_t) :: opts
      character(len=:), allocatable :: text, run_note

      integrated = 0
      call run_options_from_text(options, opts, error)
      if (.not. allocated(error)) call run_deck(deck_path, out_path, opts, error, integrated, history, run_note, progress)
      status = ADORE_OK
      message = ""
      note = ""
      if (allocated(run_note)) note = run_note
      hist = 0.0_wp
      n_rows = 0
      n_cols = 0
      columns = ""
      if (allocated(history%values)) then
         n_rows = history%rows
         n_cols = size(history%values, 2)
         call history_columns_text(history, text)
         if (n_rows > rows .or. n_cols > cols .or. len(text) > len(columns)) then
            if (.not. allocated(error)) call engine_error(error, "time history: larger than its plan ("// &
                                                          "adore_run_plan); the history is not returned")
            n_rows = 0
            n_cols = 0
         else
            hist(1:n_rows, 1:n_cols) = history%values(1:n_rows, :)
            columns = text
         end if
      end if
      if (allocated(error)) call set_error(error, status, message)
   end subroutine run_into_arrays

end module adore_api_run

!> What a run of the deck will do (see adore_driver_run::run_plan): time steps after step
!> 0 and the shape (rows, cols) of its time history, for the arrays of adore_run_file.
subroutine adore_run_plan(deck_path, options, n_steps, rows, cols, status, message)
   use adore_core_error, only: error_type, ADORE_OK
   use adore_api_status, only: set_error
   use adore_driver_run, only: run_plan
   use adore_model_run_options, only: run_options_t, run_options_from_text
   implicit none
   character(len=*), intent(in) :: deck_path   !< deck file path
   character(len=*), intent(in) :: options     !< run options, "name=value" lines (adore_model_run_options)
   integer, intent(out) :: n_steps             !< time steps the run integrates after step 0
   integer, intent(out) :: rows, cols          !< time history capacity (0, 0 without time steps)
   integer, intent(out) :: status              !< 0 ok, 1 input error, 2 engine failure
   character(len=16384), intent(out) :: message !< error message, blank on success
   type(error_type), allocatable :: error
   type(run_options_t) :: opts

   n_steps = 0
   rows = 0
   cols = 0
   call run_options_from_text(options, opts, error)
   if (.not. allocated(error)) call run_plan(deck_path, opts, n_steps, rows, cols, error)
   status = ADORE_OK
   message = ""
   if (allocated(error)) call set_error(error, status, message)
end subroutine adore_run_plan

!> Run a deck and write its print file (see adore_driver_run::run_deck) and return its time
!> history: hist(rows, cols) as planned by adore_run_plan, n_rows x n_cols of it filled,
!> columns = the column names joined by commas, integrated = steps after step 0, note =
!> what the run does not do (blank: nothing).  No progress callback (thread-safe).
subroutine adore_run_file(deck_path, out_path, options, rows, cols, hist, n_rows, n_cols, columns, integrated, note, &
                          status, message)
   use adore_core_kinds, only: wp
   use adore_api_run, only: run_into_arrays
   implicit none
   character(len=*), intent(in) :: deck_path   !< deck file path
   character(len=*), intent(in) :: out_path    !< print file path to write
   character(len=*), intent(in) :: options     !< run options, "name=value" lines (adore_model_run_options)
   integer, intent(in) :: rows, cols           !< history capacity (adore_run_plan)
   real(wp), intent(out) :: hist(rows, cols)   !< the time history (SI units, docs/plots.md)
   integer, intent(out) :: n_rows, n_cols      !< its filled part
   character(len=8192), intent(out) :: columns !< column names, comma-separated
   integer, intent(out) :: integrated          !< time steps after step 0
   character(len=1024), intent(out) :: note    !< what the run does not do; blank: nothing
   integer, intent(out) :: status              !< 0 ok, 1 input error, 2 engine failure
   character(len=16384), intent(out) :: message !< error message, blank on success

   call run_into_arrays(deck_path, out_path, options, rows, cols, hist, n_rows, n_cols, columns, integrated, note, &
                        status, message)
end subroutine adore_run_file

!> adore_run_file with a progress callback: progress(step, n_steps, tau, time, stop) after
!> every accepted time step (adore_driver_ball_dynamics' run_progress); stop /= 0 ends the
!> run there, incomplete ("interrupted", status 2).  Not thread-safe (the callback is Python).
subroutine adore_run_file_progress(deck_path, out_path, options, rows, cols, hist, n_rows, n_cols, columns, &
                                   integrated, note, status, message, progress)
   use adore_core_kinds, only: wp
   use adore_api_run, only: run_into_arrays
   use adore_driver_run, only: run_progress
   implicit none
   character(len=*), intent(in) :: deck_path, out_path, options
   integer, intent(in) :: rows, cols
   real(wp), intent(out) :: hist(rows, cols)
   integer, intent(out) :: n_rows, n_cols, integrated, status
   character(len=8192), intent(out) :: columns
   character(len=1024), intent(out) :: note
   character(len=16384), intent(out) :: message
   procedure(run_progress) :: progress

   call run_into_arrays(deck_path, out_path, options, rows, cols, hist, n_rows, n_cols, columns, integrated, note, &
                        status, message, progress)
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
