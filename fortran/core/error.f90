!> Error handling without stop: an allocatable error_type travels up to the caller.
!>
!> Library routines take `type(error_type), allocatable, intent(out) :: error`;
!> it stays unallocated on success.  Only the standalone program (app/main.f90)
!> turns an error into a process exit code; the f2py wrappers (api/) turn it into
!> a status code plus message for Python.
module adore_core_error
   implicit none
   private

   public :: error_type, input_error, engine_error
   public :: ADORE_OK, ADORE_INPUT_ERROR, ADORE_ENGINE_ERROR

   !> Status codes, shared with pyadore/errors.py and used as exit codes of `adore`.
   integer, parameter :: ADORE_OK = 0            !< success
   integer, parameter :: ADORE_INPUT_ERROR = 1   !< the input (deck, paths, options) is bad
   integer, parameter :: ADORE_ENGINE_ERROR = 2  !< the engine failed on accepted input

   !> An error: status code and a complete, user-readable message.
   type :: error_type
      integer :: stat = ADORE_ENGINE_ERROR
      character(len=:), allocatable :: message
   end type error_type

contains

   !> Create an input error (bad deck, missing file, bad option) with its message.
   subroutine input_error(error, message)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message

      allocate (error)
      error%stat = ADORE_INPUT_ERROR
      error%message = message
   end subroutine input_error

   !> Create an engine error (failure on accepted input) with its message.
   subroutine engine_error(error, message)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: message

      allocate (error)
      error%stat = ADORE_ENGINE_ERROR
      error%message = message
   end subroutine engine_error

end module adore_core_error
