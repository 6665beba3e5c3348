!> Flat f2py boundary of the engine (module pyadore._engine).
!>
!> External subroutines with scalars and fixed-length strings only; each builds the
!> engine's derived types inside, calls the library and returns a status code
!> (0 ok, 1 input error, 2 engine failure) and a message.  Nothing here stops the
!> process.  The interface seen by Python is declared in _engine.pyf.

!> Run a deck and write its print file (see adore_driver_run::run_deck).
subroutine adore_run_file(deck_path, out_path, steps, traction_table, ball_start, moment_equilibrium, traction_2d, &
                          status, message)
   use adore_core_error, only: error_type, ADORE_OK
   use adore_api_status, only: set_error
   use adore_driver_run, only: run_deck
   implicit none
   character(len=*), intent(in) :: deck_path   !< deck file path
   character(len=*), intent(in) :: out_path    !< print file path to write
   integer, intent(in) :: steps                !< -1 deck's count, 0 quasi-static only, n steps (ball decks)
   character(len=*), intent(in) :: traction_table  !< traction-slip table file (ADRX7); blank: none
   character(len=*), intent(in) :: ball_start      !< ball start hypothesis name (report 4.4.7); blank: default
   integer, intent(in) :: moment_equilibrium   !< 1: moment equilibrium of the inner race (kFS4 = kFS5 = 0); 0: prescribed
   integer, intent(in) :: traction_2d          !< 1: two-dimensional race traction (the default); 0: the 1-D developer option
   integer, intent(out) :: status              !< 0 ok, 1 input error, 2 engine failure
   character(len=16384), intent(out) :: message !< error message, blank on success

   type(error_type), allocatable :: error

   call run_deck(deck_path, out_path, steps, error, traction_table, ball_start, moment_equilibrium /= 0, &
                 traction_2d=traction_2d /= 0)
   status = ADORE_OK
   message = ""
   if (allocated(error)) then
      call set_error(error, status, message)
   end if
end subroutine adore_run_file

!> Time steps a run with the deck's own count integrates (0: such a print ends after step 0
!> while [Dynamics] is in progress; explicit steps > 0 integrate opt-in on ball decks).
subroutine adore_time_steps_implemented(n)
   use adore_driver_run, only: TIME_STEPS_IMPLEMENTED
   implicit none
   integer, intent(out) :: n

   n = TIME_STEPS_IMPLEMENTED
end subroutine adore_time_steps_implemented

!> The engine's version string.
subroutine adore_version(version)
   use adore_core_version, only: adore_version_string
   implicit none
   character(len=32), intent(out) :: version

   version = adore_version_string
end subroutine adore_version
