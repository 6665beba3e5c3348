!> The error -> (status, message) conversion shared by the flat f2py wrappers.
module adore_api_status
   use adore_core_error, only: error_type
   implicit none
   private

   public :: set_error

contains

   !> Status code and message of `error` for a wrapper's output arguments; a message longer
   !> than the buffer is cut and says so (never silently).
   subroutine set_error(error, status, message)
      type(error_type), intent(in) :: error
      integer, intent(out) :: status
      character(len=*), intent(out) :: message
      character(len=*), parameter :: cut = new_line("a")//"... (message truncated)"

      status = error%stat
      if (len(error%message) > len(message)) then
         message = error%message(1:len(message) - len(cut))//cut
      else
         message = error%message
      end if
   end subroutine set_error

end module adore_api_status
