!> Small file-system helpers bound to the C library (rename, remove).
!>
!> Used to publish an output file atomically: the print file is written under a
!> temporary name and renamed only when complete, so a failed run never leaves a
!> half-written file posing as a good one.
module adore_core_os
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   implicit none
   private

   public :: rename_file, delete_file

   interface
      function c_rename(old, new) result(rc) bind(c, name="rename")
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: rc
      end function c_rename
      function c_remove(path) result(rc) bind(c, name="remove")
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: rc
      end function c_remove
   end interface

contains

   !> Rename (move) file `old` to `new`, replacing `new`; ok is .false. on failure.
   subroutine rename_file(old, new, ok)
      character(len=*), intent(in) :: old, new
      logical, intent(out) :: ok

      ok = c_rename(old//c_null_char, new//c_null_char) == 0
   end subroutine rename_file

   !> Delete a file if it exists; failures are ignored (best-effort clean-up).
   subroutine delete_file(path)
      character(len=*), intent(in) :: path
      integer(c_int) :: rc

      rc = c_remove(path//c_null_char)
   end subroutine delete_file

end module adore_core_os
