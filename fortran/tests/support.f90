!> Shared helpers of the engine's unit-test programs (fortran/tests): a failure counter,
!> check() and the final verdict.  Test code only; the engine library keeps no state.
module adore_test_support
   implicit none
   private

   public :: check, finish, get_decks_dir, near

   !> Failed checks of this test program so far.
   integer :: failures = 0

contains

   !> Count and report a failed condition (the test program goes on).
   subroutine check(cond, what)
      logical, intent(in) :: cond
      character(len=*), intent(in) :: what
      if (.not. cond) then
         failures = failures + 1
         write (*, "(a)") "FAIL: "//what
      end if
   end subroutine check

   !> Whether a and b agree within relative tolerance rtol (of the larger magnitude).
   pure logical function near(a, b, rtol)
      use adore_core_kinds, only: wp
      real(wp), intent(in) :: a, b, rtol
      near = abs(a - b) <= rtol*max(abs(a), abs(b), tiny(1.0_wp))
   end function near

   !> Print the verdict of test program `suite`; exit status 1 when a check failed.
   subroutine finish(suite)
      character(len=*), intent(in) :: suite
      if (failures > 0) then
         write (*, "(i0,a)") failures, " "//suite//" test(s) failed"
         error stop 1
      end if
      write (*, "(a)") "all "//suite//" tests passed"
   end subroutine finish

   !> The decks/ directory: the program's first argument (meson passes it), else "decks".
   subroutine get_decks_dir(path)
      character(len=:), allocatable, intent(out) :: path
      integer :: n
      call get_command_argument(1, length=n)
      allocate (character(len=n) :: path)
      if (n > 0) call get_command_argument(1, path)
      if (n == 0) path = "decks"
   end subroutine get_decks_dir

end module adore_test_support
