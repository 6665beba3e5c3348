!> Small file-system helpers bound to the C library (rename, remove, whole-file read, what
!> a path is, its canonical name).
!>
!> Used to publish an output file atomically: the print file is written under a
!> temporary name and renamed only when complete, so a failed run never leaves a
!> half-written file posing as a good one.  Input files are read with C stdio, not a
!> Fortran unit: the Fortran runtime refuses to connect one file to two units at once,
!> which made two threads reading the same deck fail.
module adore_core_os
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, c_size_t, c_associated, &
                                          c_loc, c_f_pointer
   implicit none
   private

   public :: rename_file, delete_file, read_whole_file, path_kind, canonical_path, writable_directory
   public :: PATH_MISSING, PATH_REGULAR, PATH_DIRECTORY, PATH_FIFO, PATH_DEVICE, PATH_SOCKET, PATH_OTHER

   !> What a path names (path_kind), after following symbolic links.
   integer, parameter :: PATH_MISSING = 0     !< nothing (or a path that cannot be looked at)
   integer, parameter :: PATH_REGULAR = 1     !< a regular file
   integer, parameter :: PATH_DIRECTORY = 2   !< a directory
   integer, parameter :: PATH_FIFO = 3        !< a named pipe (FIFO): reading it waits for a writer
   integer, parameter :: PATH_DEVICE = 4      !< a character or block device
   integer, parameter :: PATH_SOCKET = 5      !< a socket
   integer, parameter :: PATH_OTHER = 6       !< anything else

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
      function c_realpath(path, resolved) result(p) bind(c, name="realpath")
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*)
         type(c_ptr), value :: resolved
         type(c_ptr) :: p
      end function c_realpath
      function c_strlen(s) result(n) bind(c, name="strlen")
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
      subroutine c_free(p) bind(c, name="free")
         import :: c_ptr
         type(c_ptr), value :: p
      end subroutine c_free
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

   !> What `path` names, following symbolic links (PATH_MISSING, PATH_REGULAR, PATH_DIRECTORY,
   !> PATH_FIFO, PATH_DEVICE, PATH_SOCKET, PATH_OTHER); the path is looked at, never opened
   !> (opening a FIFO would wait for a writer).
   integer function path_kind(path) result(kind)
      character(len=*), intent(in) :: path
      integer :: values(13), rc, fmt

      kind = PATH_MISSING
      if (len_trim(path) == 0) return
      call stat(path, values, rc)            ! GNU extension: values(3) = st_mode
      if (rc /= 0) return
      fmt = iand(values(3), int(o'170000'))
      select case (fmt)
      case (int(o'100000'))
         kind = PATH_REGULAR
      case (int(o'040000'))
         kind = PATH_DIRECTORY
      case (int(o'010000'))
         kind = PATH_FIFO
      case (int(o'020000'), int(o'060000'))
         kind = PATH_DEVICE
      case (int(o'140000'))
         kind = PATH_SOCKET
      case default
         kind = PATH_OTHER
      end select
   end function path_kind

   !> The canonical absolute name of the existing `path` (symbolic links, "." and ".."
   !> resolved: C realpath); ok is .false. (resolved = "") when it cannot be resolved.
   subroutine canonical_path(path, resolved, ok)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: resolved
      logical, intent(out) :: ok
      type(c_ptr) :: p
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i

      resolved = ""
      ok = .false.
      if (len_trim(path) == 0) return
      p = c_realpath(path//c_null_char, c_null_ptr)
      if (.not. c_associated(p)) return
      n = int(c_strlen(p))
      call c_f_pointer(p, chars, [n])
      resolved = repeat(" ", n)
      do i = 1, n
         resolved(i:i) = chars(i)
      end do
      call c_free(p)
      ok = .true.
   end subroutine canonical_path

   !> .true. when `dir` is a directory the process may create files in (GNU ACCESS, W_OK
   !> and X_OK of access(2)).
   logical function writable_directory(dir) result(ok)
      character(len=*), intent(in) :: dir
      integer :: kind

      kind = path_kind(dir)
      ok = .false.
      if (kind == PATH_DIRECTORY) ok = access(dir, "wx") == 0
   end function writable_directory

end module adore_core_os
