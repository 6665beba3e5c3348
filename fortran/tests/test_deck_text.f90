!> Engine unit tests of the deck text reader and the error/run plumbing.
!> Run by `meson test` (pytest calls it from tests/test_fortran_units.py).
program test_deck_text
   use adore_test_support, only: check, finish
   use adore_core_error, only: error_type, ADORE_INPUT_ERROR
   use adore_deck_text, only: deck_text_t, read_deck_text
   use adore_driver_run, only: run_deck, run_options_t
   implicit none


   call test_missing_file()
   call test_empty_file()
   call test_blank_file()
   call test_binary_file()
   call test_lines_crlf_and_no_final_newline()
   call test_failed_run_leaves_no_output()

   call finish("engine")

contains

   subroutine write_bytes(path, bytes)
      character(len=*), intent(in) :: path, bytes
      integer :: unit
      open (newunit=unit, file=path, access="stream", form="unformatted", status="replace")
      write (unit) bytes
      close (unit)
   end subroutine write_bytes

   subroutine test_missing_file()
      type(deck_text_t) :: text
      type(error_type), allocatable :: error
      call read_deck_text("no/such/deck.inp", text, error)
      call check(allocated(error), "missing file gives an error")
      if (allocated(error)) then
         call check(error%stat == ADORE_INPUT_ERROR, "missing file is an input error")
         call check(index(error%message, "no/such/deck.inp") > 0, "message names the file")
      end if
   end subroutine test_missing_file

   subroutine test_empty_file()
      type(deck_text_t) :: text
      type(error_type), allocatable :: error
      call write_bytes("test_empty.inp", "")
      call read_deck_text("test_empty.inp", text, error)
      call check(allocated(error), "empty file gives an error")
      if (allocated(error)) call check(index(error%message, "empty") > 0, "message says empty")
   end subroutine test_empty_file

   subroutine test_blank_file()
      type(deck_text_t) :: text
      type(error_type), allocatable :: error
      call write_bytes("test_blank.inp", "   "//achar(10)//achar(10))
      call read_deck_text("test_blank.inp", text, error)
      call check(allocated(error), "blank file gives an error")
   end subroutine test_blank_file

   subroutine test_binary_file()
      type(deck_text_t) :: text
      type(error_type), allocatable :: error
      call write_bytes("test_binary.inp", "1 0 0"//achar(10)//"ab"//achar(0)//"c")
      call read_deck_text("test_binary.inp", text, error)
      call check(allocated(error), "binary file gives an error")
      if (allocated(error)) then
         call check(index(error%message, "test_binary.inp:2:3") > 0, &
                    "binary error points at line 2 column 3: "//error%message)
      end if
   end subroutine test_binary_file

   subroutine test_lines_crlf_and_no_final_newline()
      type(deck_text_t) :: text
      type(error_type), allocatable :: error
      call write_bytes("test_crlf.inp", "Rec 1"//achar(13)//achar(10)//achar(10)//"  last")
      call read_deck_text("test_crlf.inp", text, error)
      call check(.not. allocated(error), "CRLF deck reads")
      if (.not. allocated(error)) then
         call check(size(text%lines) == 3, "three lines")
         call check(text%lines(1)%s == "Rec 1" .and. len(text%lines(1)%s) == 5, "CR dropped")
         call check(len(text%lines(2)%s) == 0, "empty middle line kept")
         call check(text%lines(3)%s == "  last", "last line without newline kept")
      end if
   end subroutine test_lines_crlf_and_no_final_newline

   subroutine test_failed_run_leaves_no_output()
      type(error_type), allocatable :: error
      logical :: exists
      call run_deck("test_binary.inp", "test_failed.prt", run_options_t(), error)
      call check(allocated(error), "run of a bad deck fails")
      inquire (file="test_failed.prt", exist=exists)
      call check(.not. exists, "no print file after a failed run")
      inquire (file="test_failed.prt.part", exist=exists)
      call check(.not. exists, "no partial print file after a failed run")
   end subroutine test_failed_run_leaves_no_output

end program test_deck_text
