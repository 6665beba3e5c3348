!> Traction-slip table file: the input of ADORE's user subroutine ADRX7 (report 4.4.9).
!>
!> ADORE reads the data of its user subroutines besides the deck ("Input from optional user
!> subroutines" in the print); the report gives no format, so pyadore's is a plain text file:
!> * one point per line: slip speed (m/s) and traction coefficient (-), separated by blanks
!>   or one comma;
!> * '#' starts a comment, blank lines are skipped;
!> * the first data line may instead be a header (its first character is a letter), e.g.
!>   "slip_m_s, kappa".
!> The points are checked by `check_traction_table` (>= 2 points, the first at zero slip,
!> slips increasing strictly, coefficients >= 0).  Errors give file:line:col and a caret.
module adore_deck_traction_table
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   use adore_core_strings, only: itoa
   use adore_deck_text, only: deck_text_t, read_deck_text
   use adore_tribology_traction_law, only: traction_law_t, table_law
   implicit none
   private

   public :: read_traction_table

contains

   !> Read the traction-slip table file `path` into `law` (kind LAW_TABLE).
   subroutine read_traction_table(path, law, error)
      character(len=*), intent(in) :: path
      type(traction_law_t), intent(out) :: law
      type(error_type), allocatable, intent(out) :: error

      type(deck_text_t) :: text
      character(len=:), allocatable :: line
      real(wp), allocatable :: slip(:), kappa(:)
      real(wp) :: v(2)
      integer :: i, n, nv, pos, col, hash
      logical :: first

      call read_deck_text(path, text, error)
      if (allocated(error)) then
         ! the text reader speaks of a "deck file"; this file is a table
         error%message = trim(replace_deck_word(error%message))
         return
      end if
      allocate (slip(size(text%lines)), kappa(size(text%lines)))
      n = 0
      first = .true.
      do i = 1, size(text%lines)
         line = text%lines(i)%s
         hash = index(line, "#")
         if (hash > 0) line = line(:hash - 1)
         pos = first_nonblank(line, 1)
         if (pos == 0) cycle
         if (first .and. is_letter(line(pos:pos))) then
            first = .false.
            cycle
         end if
         first = .false.
         nv = 0
         do
            pos = first_nonblank(line, pos)
            if (pos == 0) exit
            if (line(pos:pos) == "," .and. nv > 0) then
               pos = first_nonblank(line, pos + 1)
               if (pos == 0) then
                  call located(i, len(line) + 1, "expected a number after the comma")
                  return
               end if
            end if
            col = pos
            if (nv == 2) then
               call located(i, col, "expected two numbers (slip in m/s, traction coefficient); "// &
                            "found more")
               return
            end if
            call read_number(line, pos, v(nv + 1), col)
            if (col < 0) then
               call located(i, -col, "expected a number")
               return
            end if
            nv = nv + 1
         end do
         if (nv /= 2) then
            call located(i, len(line) + 1, "expected two numbers (slip in m/s, traction coefficient); "// &
                         "found one")
            return
         end if
         n = n + 1
         slip(n) = v(1)
         kappa(n) = v(2)
      end do
      call table_law(slip(:n), kappa(:n), path, law, error)

   contains

      subroutine located(line_no, column, message)
         integer, intent(in) :: line_no, column
         character(len=*), intent(in) :: message
         character(len=:), allocatable :: shown
         integer :: k

         shown = text%lines(line_no)%s
         do k = 1, len(shown)
            if (shown(k:k) == achar(9)) shown(k:k) = " "
         end do
         call input_error(error, path//":"//itoa(line_no)//":"//itoa(column)//": traction table: "// &
                          message//new_line("a")//"    "//shown//new_line("a")//"    "// &
                          repeat(" ", max(column - 1, 0))//"^")
      end subroutine located

   end subroutine read_traction_table

   !> Position of the first character at or after `from` that is neither blank nor TAB (0: none).
   pure integer function first_nonblank(s, from)
      character(len=*), intent(in) :: s
      integer, intent(in) :: from
      integer :: k

      first_nonblank = 0
      do k = max(from, 1), len(s)
         if (s(k:k) /= " " .and. s(k:k) /= achar(9)) then
            first_nonblank = k
            return
         end if
      end do
   end function first_nonblank

   elemental logical function is_letter(c)
      character, intent(in) :: c
      is_letter = (c >= "a" .and. c <= "z") .or. (c >= "A" .and. c <= "Z")
   end function is_letter

   !> Read the number starting at `pos` (a run of digits, sign, point and exponent letters);
   !> `pos` moves past it.  col = -pos of the token when it is not a number.
   subroutine read_number(s, pos, value, col)
      character(len=*), intent(in) :: s
      integer, intent(inout) :: pos
      real(wp), intent(out) :: value
      integer, intent(inout) :: col
      integer :: k, stat

      k = pos
      do while (k <= len(s))
         if (index("0123456789+-.eEdD", s(k:k)) == 0) exit
         k = k + 1
      end do
      value = 0.0_wp
      if (k == pos) then
         col = -pos
         return
      end if
      if (k <= len(s)) then
         if (s(k:k) /= " " .and. s(k:k) /= achar(9) .and. s(k:k) /= ",") then
            col = -pos
            return
         end if
      end if
      read (s(pos:k - 1), *, iostat=stat) value
      if (stat /= 0) then
         col = -pos
         return
      end if
      pos = k
   end subroutine read_number

   !> The text reader's messages say "deck file"; for this file they mean the table.
   pure function replace_deck_word(message) result(out)
      character(len=*), intent(in) :: message
      character(len=len(message) + 16) :: out
      integer :: k

      k = index(message, "deck file")
      if (k == 0) then
         out = message
      else
         out = message(:k - 1)//"traction table file"//message(k + 9:)
      end if
   end function replace_deck_word

end module adore_deck_traction_table
