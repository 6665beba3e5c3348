!> The files of a run, checked and cleared before it starts (issue #28 item 4).
!>
!> A run reads its deck (and, as a run option, a traction-slip table) and writes its print
!> file OUT and, with time steps, its plot-data file and element file beside it
!> (history_file_name, element_file_name), each first under its ".part" name; pyadore
!> writes the run's netCDF file (results_file_name) beside them after the run.
!> check_run_paths refuses, before anything is read or written, the paths a run cannot use:
!>
!> * an input that exists but is not a regular file: a FIFO (the reader would wait for a
!>   writer for ever), a directory, a device;
!> * an output that is one of the inputs (`adore deck.inp deck.inp`, `-o deck.inp`, a
!>   deck named like the default print file): the run would overwrite it;
!> * an output that is a directory or another non-regular file (the finished file could
!>   not be moved there: found only after every time step otherwise);
!> * an output directory that does not exist or cannot be written.
!>
!> clear_run_outputs then removes what an earlier run left at the output path (print,
!> plot-data file, element file, netCDF file and their ".part" files), so that a run that is refused, fails or is
!> stopped never leaves an older print or plot-data file posing as its own.  The two
!> front ends (app/main.f90, api/wrappers.f90) call both before run_deck.  No state.
module adore_output_run_files
   use adore_core_error, only: error_type, input_error
   use adore_core_os, only: path_kind, canonical_path, writable_directory, delete_file, &
                            PATH_MISSING, PATH_REGULAR, PATH_DIRECTORY, PATH_FIFO, PATH_DEVICE, PATH_SOCKET
   use adore_output_run_history, only: history_file_name, element_file_name, beside_file_name
   implicit none
   private

   public :: check_run_paths, clear_run_outputs, run_output_path, results_file_name, N_RUN_OUTPUTS

   !> Suffix of a file while it is written (renamed onto its name when complete).
   character(len=*), parameter :: PART = ".part"
   !> The files a run writes (run_output_path): print, plot-data file, element file,
   !> netCDF file, each followed by its name while being written.
   integer, parameter :: N_RUN_OUTPUTS = 8

contains

   !> File k (1..N_RUN_OUTPUTS) a run with print file out_path may write: the print, the
   !> plot-data file, the element file, the netCDF file (odd k), each being written (even
   !> k); what names it.
   subroutine run_output_path(out_path, k, path, what)
      character(len=*), intent(in) :: out_path
      integer, intent(in) :: k
      character(len=:), allocatable, intent(out) :: path
      character(len=32), intent(out), optional :: what
      character(len=32) :: name

      select case (k)
      case (1, 2)
         path = trim(out_path)
         name = "print file"
      case (3, 4)
         call history_file_name(trim(out_path), path)
         name = "plot-data file"
      case (5, 6)
         call element_file_name(trim(out_path), path)
         name = "element file"
      case default
         call results_file_name(trim(out_path), path)
         name = "netCDF file"
      end select
      if (mod(k, 2) == 0) then
         path = path//PART
         name = trim(name)//" being written"
      end if
      if (present(what)) what = name
   end subroutine run_output_path

   !> The netCDF file of the results of print file print_path (pyadore writes it, docs/results.md):
   !> its name with the extension replaced by ".nc".
   subroutine results_file_name(print_path, path)
      character(len=*), intent(in) :: print_path
      character(len=:), allocatable, intent(out) :: path
      call beside_file_name(print_path, ".nc", path)
   end subroutine results_file_name

   !> Input error when the run of deck_path into out_path (table_path: the traction-slip
   !> table, blank for none) cannot use its paths (see the module's list); the message names
   !> the file and what is wrong with it.  Nothing is read or written.
   subroutine check_run_paths(deck_path, out_path, table_path, error)
      character(len=*), intent(in) :: deck_path, out_path, table_path
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: path, dir
      character(len=32) :: what
      integer :: k, kind, slash

      call check_input(deck_path, "deck", error)
      if (allocated(error)) return
      if (len_trim(table_path) > 0) then
         call check_input(table_path, "traction-slip table", error)
         if (allocated(error)) return
      end if
      if (len_trim(out_path) == 0) then
         call input_error(error, "print file: no output path given")
         return
      end if
      do k = 1, N_RUN_OUTPUTS
         call run_output_path(out_path, k, path, what)
         call check_not_input(path, trim(what), deck_path, "deck", error)
         if (allocated(error)) return
         if (len_trim(table_path) > 0) then
            call check_not_input(path, trim(what), table_path, "traction-slip table", error)
            if (allocated(error)) return
         end if
         kind = path_kind(path)
         if (kind /= PATH_MISSING .and. kind /= PATH_REGULAR) then
            call input_error(error, path//": the "//trim(what)//" would replace "//trim(kind_words(kind))// &
                             ": give the path of a file")
            return
         end if
      end do
      slash = index(trim(out_path), "/", back=.true.)
      if (slash == 0) then
         dir = "."
      else if (slash == 1) then
         dir = "/"
      else
         dir = out_path(:slash - 1)
      end if
      if (.not. writable_directory(dir)) then
         kind = path_kind(dir)
         if (kind == PATH_MISSING) then
            call input_error(error, trim(out_path)//": cannot write print file: the output directory "//dir// &
                             " does not exist")
         else if (kind /= PATH_DIRECTORY) then
            call input_error(error, trim(out_path)//": cannot write print file: "//dir//" is not a directory")
         else
            call input_error(error, trim(out_path)//": cannot write print file: no permission to create files "// &
                             "in the output directory "//dir)
         end if
      end if
   end subroutine check_run_paths

   !> Remove the files an earlier run left at print path out_path (run_output_path), regular
   !> files only: best effort, as a new run starts.
   subroutine clear_run_outputs(out_path)
      character(len=*), intent(in) :: out_path
      character(len=:), allocatable :: path
      integer :: k

      if (len_trim(out_path) == 0) return
      do k = 1, N_RUN_OUTPUTS
         call run_output_path(out_path, k, path)
         if (path_kind(path) == PATH_REGULAR) call delete_file(path)
      end do
   end subroutine clear_run_outputs

   !> Input error when the input `path` (a `what`) exists but is not a regular file.  A
   !> missing file passes: its reader says so.
   subroutine check_input(path, what, error)
      character(len=*), intent(in) :: path, what
      type(error_type), allocatable, intent(out) :: error
      integer :: kind

      kind = path_kind(trim(path))
      if (kind /= PATH_MISSING .and. kind /= PATH_REGULAR) &
         call input_error(error, trim(path)//": the "//what//" is "//trim(kind_words(kind))//", not a regular file: "// &
                          "give the "//what//" file itself")
   end subroutine check_input

   !> Input error when the output `path` (a `what`) is the input file `input` (an
   !> `input_what`): the same name, or the same file once links are resolved.
   subroutine check_not_input(path, what, input, input_what, error)
      character(len=*), intent(in) :: path, what, input, input_what
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: a, b
      logical :: ok_a, ok_b, same

      same = trim(path) == trim(input)
      if (.not. same) then
         if (path_kind(path) /= PATH_MISSING) then
            call canonical_path(path, a, ok_a)
            call canonical_path(trim(input), b, ok_b)
            same = ok_a .and. ok_b .and. a == b
         end if
      end if
      if (same) call input_error(error, path//": the "//what//" would overwrite the "//input_what//" "// &
                                 trim(input)//": give another output path")
   end subroutine check_not_input

   !> "a directory", "a FIFO (named pipe)", ... for a path_kind (blank-padded: trim it).  A
   !> fixed length: gfortran keeps a deferred-length result's length in static storage.
   function kind_words(kind) result(words)
      integer, intent(in) :: kind
      character(len=24) :: words

      select case (kind)
      case (PATH_DIRECTORY)
         words = "a directory"
      case (PATH_FIFO)
         words = "a FIFO (named pipe)"
      case (PATH_DEVICE)
         words = "a device"
      case (PATH_SOCKET)
         words = "a socket"
      case default
         words = "a special file"
      end select
   end function kind_words

end module adore_output_run_files
