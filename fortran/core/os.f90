!> Small file-system helpers bound to the C library (rename, remove, whole-file read).
!>
!> Used to publish an output file atomically: the print file is written under a
!> temporary name and renamed only when complete, so a failed run never leaves a
!> half-written file posing as a good one.  Input files are read with C stdio, not a
!> Fortran unit: the Fortran runtime refuses to connect one file to two units at once,
!> which made two threads reading the same deck fail.
module adore_core_os
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_size_t, c_associated, c_loc
   implicit none
   private

   public :: rename_file, delete_file, read_whole_file

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
      function c_fopen(path, mode) result(fp) bind(c, name="fopen")
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*), mode(*)
         type(c_ptr) :: fp
      end function c_fopen
      function c_fread(buf, size, n, fp) result(nread) bind(c, name="fread")
         import :: c_ptr, c_size_t
         type(c_ptr), value :: buf, fp
         integer(c_size_t), value :: size, n
         integer(c_size_t) :: nread
      end function c_fread
      function c_ferror(fp) result(rc) bind(c, name="ferror")
         import :: c_ptr, c_int
         type(c_ptr), value :: fp
         integer(c_int) :: rc
      end function c_ferror
      function c_fclose(fp) result(rc) bind(c, name="fclose")
         import :: c_ptr, c_int
         type(c_ptr), value :: fp
         integer(c_int) :: rc
      end function c_fclose
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

   !> Read the whole file `path` into `content` (bytes as characters).  `message` is
   !> empty on success, else what failed ("cannot open", "cannot read").
   subroutine read_whole_file(path, content, message)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: content
      character(len=:), allocatable, intent(out) :: message
      integer, parameter :: chunk_len = 65536
      character(kind=c_char, len=chunk_len), target :: chunk
      type(c_ptr) :: fp
      integer(c_size_t) :: got
      integer(c_int) :: rc, err

      content = ""
      message = ""
      fp = c_fopen(path//c_null_char, "rb"//c_null_char)
      if (.not. c_associated(fp)) then
         message = "cannot open the file"
         return
      end if
      do
         got = c_fread(c_loc(chunk), 1_c_size_t, int(chunk_len, c_size_t), fp)
         if (got > 0) content = content//chunk(1:int(got))
         if (got < int(chunk_len, c_size_t)) exit
      end do
      err = c_ferror(fp)
      rc = c_fclose(fp)
      if (err /= 0) message = "cannot read the file (a directory?)"
   end subroutine read_whole_file

end module adore_core_os
