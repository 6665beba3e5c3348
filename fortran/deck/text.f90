!> The deck as text: every line of the deck file, with its path, read in one go.
!>
!> This is the first stage of ADRIN (input): the file is checked to be a readable,
!> non-empty text file and split into lines.  Record parsing works on these lines,
!> so every field keeps its line number for error messages, and the print file's
!> "Listing of input data records" reproduces the lines verbatim.
module adore_deck_text
   use adore_core_error, only: error_type, input_error
   use adore_core_os, only: read_whole_file
   use adore_core_strings, only: itoa
   implicit none
   private

   public :: deck_line_t, deck_text_t, read_deck_text, first_invalid_utf8

   !> One line of the deck, without its line terminator.
   type :: deck_line_t
      character(len=:), allocatable :: s
   end type deck_line_t

   !> All lines of a deck file and the path it was read from.
   type :: deck_text_t
      character(len=:), allocatable :: path
      type(deck_line_t), allocatable :: lines(:)
   end type deck_text_t

contains

   !> Read the deck file `path` into `text`.
   !>
   !> Input errors: the file is missing or unreadable, empty (no non-blank line),
   !> or not text (NUL bytes or other control characters than TAB/CR/LF/FF).
   subroutine read_deck_text(path, text, error)
      character(len=*), intent(in) :: path
      type(deck_text_t), intent(out) :: text
      type(error_type), allocatable, intent(out) :: error

      character(len=:), allocatable :: buffer
      character(len=:), allocatable :: iomsg_text
      integer :: nbytes, i, nlines, start, line_end
      logical :: exists, any_content

      text%path = path
      if (len_trim(path) == 0) then
         call input_error(error, "deck file: no path given")
         return
      end if
      inquire (file=path, exist=exists)
      if (.not. exists) then
         call input_error(error, path//": deck file not found")
         return
      end if
      call read_whole_file(path, buffer, iomsg_text)
      if (len(iomsg_text) > 0) then
         call input_error(error, path//": deck file: "//iomsg_text)
         return
      end if
      nbytes = len(buffer)

      ! Text check: the first offending byte is reported by line and column.
      nlines = 1
      start = 1
      do i = 1, nbytes
         select case (iachar(buffer(i:i)))
         case (10)
            nlines = nlines + 1
            start = i + 1
         case (9, 12, 13)
         case (0:8, 11, 14:31, 127)
            call input_error(error, path//":"//itoa(nlines)//":"//itoa(i - start + 1)// &
                             ": not a text file (control byte "//itoa(iachar(buffer(i:i)))// &
                             "); an ADORE deck is plain text")
            return
         end select
      end do

      ! Split into lines at LF; a CR before the LF is dropped; a final line
      ! terminator does not start a new line.
      if (nbytes > 0) then
         if (buffer(nbytes:nbytes) == achar(10)) nlines = nlines - 1
      else
         nlines = 0
      end if
      allocate (text%lines(nlines))
      any_content = .false.
      start = 1
      do i = 1, nlines
         line_end = index(buffer(start:), achar(10))
         if (line_end == 0) then
            line_end = nbytes + 1
         else
            line_end = start + line_end - 1
         end if
         ! buffer(start:line_end-1) is the line without its LF
         text%lines(i)%s = buffer(start:line_end - 1)
         if (len(text%lines(i)%s) > 0) then
            if (text%lines(i)%s(len(text%lines(i)%s):) == achar(13)) &
               text%lines(i)%s = text%lines(i)%s(:len(text%lines(i)%s) - 1)
         end if
         if (len_trim(text%lines(i)%s) > 0) any_content = .true.
         start = line_end + 1
      end do
      if (.not. any_content) then
         call input_error(error, path//": deck file is empty (no records)")
         return
      end if
   end subroutine read_deck_text

   !> Line and column (1-based) of the first byte sequence of `text` that is not valid
   !> UTF-8; line = col = 0 when every line is valid UTF-8.
   pure subroutine first_invalid_utf8(text, line, col)
      type(deck_text_t), intent(in) :: text
      integer, intent(out) :: line, col
      integer :: l, i, c, n, k, lo, hi

      line = 0
      col = 0

      do l = 1, size(text%lines)
         associate (s => text%lines(l)%s)
            i = 1
            do while (i <= len(s))
               c = iachar(s(i:i))
               lo = 128
               hi = 191
               select case (c)
               case (0:127); n = 0
               case (194:223); n = 1
               case (224); n = 2; lo = 160
               case (225:236, 238:239); n = 2
               case (237); n = 2; hi = 159
               case (240); n = 3; lo = 144
               case (241:243); n = 3
               case (244); n = 3; hi = 143
               case default; n = -1
               end select
               do k = 1, n
                  if (i + k > len(s)) then
                     n = -1
                     exit
                  end if
                  c = iachar(s(i + k:i + k))
                  if (c < lo .or. c > hi) then
                     n = -1
                     exit
                  end if
                  lo = 128
                  hi = 191
               end do
               if (n < 0) then
                  line = l
                  col = i
                  return
               end if
               i = i + n + 1
            end do
         end associate
      end do
   end subroutine first_invalid_utf8

end module adore_deck_text
