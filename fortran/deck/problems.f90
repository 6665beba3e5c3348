!> Problems found in a deck, collected and reported all at once as one input error whose
!> message lists each problem as Python's Problem.format() does:
!>
!>     deck.inp:11:24  Rec 5A  field pitch_diameter = '1.4OOOE-01': expected a real number (E11.4)
!>         Rec 5A       1.9050E-02 1.4OOOE-01 2.5000E+01 ...
!>                        ^
!>
!> Used by the parser (structure, types), the range checks and the model's cross-field checks.
module adore_deck_problems
   use adore_core_error, only: error_type, input_error
   use adore_deck_text, only: deck_text_t
   use adore_deck_schema, only: KIND_INT, KIND_REAL
   use adore_deck_deck_type, only: deck_t, record_matches
   use adore_deck_tokenizer, only: is_blank, lstrip_count, show_real, itoa
   use adore_core_strings, only: quoted, utf8_chars, utf8_char_start
   implicit none
   private

   public :: problem_t, problem_list_t
   public :: add_problem, format_problem, problems_error, deck_field_problem
   public :: MAX_SHOWN_PROBLEMS, SOURCE_WINDOW

   !> At most this many problems are listed in one message, the rest counted
   !> (pyadore/deck/problems.py: the same number).
   integer, parameter :: MAX_SHOWN_PROBLEMS = 50
   !> A source line longer than this many characters is shown as a window of this width
   !> around the caret, each cut end marked "..." (pyadore/deck/problems.py shown_source).
   integer, parameter :: SOURCE_WINDOW = 160

   !> One problem found in the deck (fields of pyadore.deck.model.Problem).
   type :: problem_t
      integer :: line = 0, col = 0
      character(len=:), allocatable :: record, field, shown, message, kind, source
      logical :: has_record = .false., has_field = .false., has_source = .false.
   end type problem_t

   !> The problems of one deck file, in the order found (problems_error sorts them).
   type :: problem_list_t
      character(len=:), allocatable :: path        !< deck file named in every message
      integer :: n = 0
      type(problem_t), allocatable :: items(:)
   end type problem_list_t

contains

   !> A problem with field `field` of record `rid` (its `occurrence`) found after reading,
   !> such as a cross-field value the physics cannot use, formatted as the reader's own
   !> problems (Python's Problem.format()): `path:line:col  Rec id  field name = value:
   !> message`, the line and a caret under the field.
   subroutine deck_field_problem(deck, rid, field, message, text, occurrence)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field, message
      character(len=:), allocatable, intent(out) :: text
      integer, intent(in), optional :: occurrence
      type(problem_t) :: p
      integer :: r, f, occ, seen

      occ = 1
      if (present(occurrence)) occ = occurrence
      seen = 0
      do r = 1, deck%n_records
         if (.not. record_matches(deck%records(r), rid)) cycle
         seen = seen + 1
         if (seen < occ) cycle
         do f = 1, deck%records(r)%n_fields
            if (deck%records(r)%fields(f)%name /= field) cycle
            associate (rec => deck%records(r), fv => deck%records(r)%fields(f))
               p%line = fv%line
               p%col = fv%col
               if (.not. is_blank(fv%raw)) p%col = fv%col + lstrip_count(fv%raw)
               p%has_record = .true.
               p%record = rec%rid
               p%has_field = .true.
               p%field = fv%name
               select case (fv%kind)
               case (KIND_INT)
                  p%shown = itoa(fv%int_value)
               case (KIND_REAL)
                  p%shown = show_real(fv%real_value)
               case default
                  p%shown = quoted(fv%text_value)
               end select
               p%message = message
               p%kind = "cross_field"
               p%has_source = allocated(rec%source) .and. fv%line > 0
               if (p%has_source) p%source = rec%source
            end associate
            call format_problem(deck%path, p, text)
            return
         end do
         exit
      end do
      text = deck%path//"  Rec "//rid//"  field "//field//": "//message    ! not in the deck: no location
   end subroutine deck_field_problem

   !> Append a problem; the source line is that of `line` unless `no_source`.
   subroutine add_problem(list, text, line, col, message, kind, record, field, shown, no_source)
      type(problem_list_t), intent(inout) :: list
      type(deck_text_t), intent(in) :: text
      integer, intent(in) :: line, col
      character(len=*), intent(in) :: message, kind
      character(len=*), intent(in), optional :: record, field, shown
      logical, intent(in), optional :: no_source
      type(problem_t) :: p

      p%line = line
      p%col = col
      p%message = message
      p%kind = kind
      if (present(record)) then
         p%has_record = .true.
         p%record = record
      end if
      if (present(field)) then
         p%has_field = .true.
         p%field = field
         p%shown = "(blank)"
         if (present(shown)) p%shown = shown
      end if
      p%has_source = line > 0 .and. line <= size(text%lines)
      if (present(no_source)) p%has_source = p%has_source .and. .not. no_source
      if (p%has_source) p%source = text%lines(line)%s
      call append_problem(list, p)
   end subroutine add_problem

   !> Append problem p to list (the list grows as needed).
   subroutine append_problem(list, p)
      type(problem_list_t), intent(inout) :: list
      type(problem_t), intent(in) :: p
      if (.not. allocated(list%items)) allocate (list%items(16))
      if (list%n == size(list%items)) list%items = [list%items, list%items]
      list%n = list%n + 1
      list%items(list%n) = p
   end subroutine append_problem

   !> One problem as Python's Problem.format(): location, record, field = value, message,
   !> then the offending line and a caret under the column.  Columns are counted in
   !> characters (p%col is a byte column of the source line: they differ after a non-ASCII
   !> character); a line longer than SOURCE_WINDOW characters is shown as a window around
   !> the caret (Python's shown_source).
   subroutine format_problem(path, p, s)
      character(len=*), intent(in) :: path
      type(problem_t), intent(in) :: p
      character(len=:), allocatable, intent(out) :: s
      character(len=:), allocatable :: shown, head, tail
      integer :: i, col, n, first, last

      col = p%col
      if (p%has_source .and. p%col > 1) col = utf8_chars(p%source(1:min(p%col - 1, len(p%source)))) + 1 + &
                                                max(p%col - 1 - len(p%source), 0)
      if (p%line > 0) then
         s = path//":"//itoa(p%line)//":"//itoa(col)
      else
         s = path
      end if
      if (p%has_record) then
         if (len(p%record) > 0) s = s//"  Rec "//p%record
      end if
      if (p%has_field) s = s//"  field "//p%field//" = "//p%shown
      s = s//": "//p%message
      if (.not. p%has_source) return
      shown = p%source
      do i = 1, len(shown)
         if (shown(i:i) == achar(9)) shown(i:i) = " "
      end do
      n = utf8_chars(shown)
      if (n > SOURCE_WINDOW) then
         first = max(0, col - 1 - SOURCE_WINDOW/2)       ! characters cut at the start
         last = min(n, first + SOURCE_WINDOW)            ! last character shown
         first = max(0, last - SOURCE_WINDOW)
         head = ""
         tail = ""
         if (first > 0) head = "..."
         if (last < n) tail = "..."
         shown = head//shown(utf8_char_start(shown, first + 1):utf8_char_start(shown, last + 1) - 1)//tail
         col = col - first + len(head)
      end if
      s = s//new_line("a")//"    "//shown//new_line("a")//"    "//repeat(" ", max(col - 1, 0))//"^"
   end subroutine format_problem

   !> Sort the problems by line (line 0 last) and column, stably, and build the input error.
   subroutine problems_error(list, error)
      type(problem_list_t), intent(inout) :: list
      type(error_type), allocatable, intent(out) :: error
      type(problem_t) :: p
      character(len=:), allocatable :: msg, line
      integer :: i, j

      do i = 2, list%n
         p = list%items(i)
         j = i - 1
         do while (j >= 1)
            if (.not. later(list%items(j), p)) exit
            list%items(j + 1) = list%items(j)
            j = j - 1
         end do
         list%items(j + 1) = p
      end do
      msg = list%path//": "//itoa(list%n)//" problem(s) reading the deck"
      do i = 1, min(list%n, MAX_SHOWN_PROBLEMS)
         call format_problem(list%path, list%items(i), line)
         msg = msg//new_line("a")//line
      end do
      if (list%n > MAX_SHOWN_PROBLEMS) &
         msg = msg//new_line("a")//"... and "//itoa(list%n - MAX_SHOWN_PROBLEMS)//" more problem(s) not shown"
      call input_error(error, msg)
   end subroutine problems_error

   !> Sort order of problems: (line == 0, line, col).
   pure logical function later(a, b)
      type(problem_t), intent(in) :: a, b
      if ((a%line == 0) .neqv. (b%line == 0)) then
         later = a%line == 0
      else if (a%line /= b%line) then
         later = a%line > b%line
      else
         later = a%col > b%col
      end if
   end function later

end module adore_deck_problems
