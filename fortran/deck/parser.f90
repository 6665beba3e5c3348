!> Parsing an ADORE deck's lines into a deck_t (adore_deck_deck_type): the engine's
!> counterpart of pyadore.deck's reader.
!>
!> The record sequence, the field layout, defaults, bounds and choices all come from the
!> generated table adore_deck_schema (fortran/deck/schema.f90, written from
!> pyadore/deck/records.py), and lines are cut exactly as pyadore/deck/tokenizer.py cuts
!> them, so both readers accept and reject the same decks with the same messages.
!>
!> Checks: non-text content (control bytes, invalid UTF-8), empty file, truncated file,
!> label-zone and tab format errors, text after the last field, unknown / missing /
!> surplus / out-of-order records, records required or forbidden by a flag or count,
!> bad integers and reals, blank required fields, and every value's range or choices
!> (adore_deck_ranges).  Not checked here: the relations between values (pitch between
!> bore and OD, elements fit, cage ID < OD, step order, traction peak...), which
!> adore_model_checks applies when the bearing model is built.  All problems are
!> collected, then returned as one input error (adore_deck_problems).
module adore_deck_parser
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_deck_text, only: deck_text_t, read_deck_text, first_invalid_utf8
   use adore_deck_schema, only: N_RECORDS, KIND_INT, KIND_REAL, KIND_TEXT, INT_WIDTH, REAL_WIDTH, &
                                TEXT_WIDTH, OP_NONE, OP_EQ, OP_NE, OP_LT, OP_LE, OP_GT, OP_GE, &
                                REC_ID, REC_TITLE, REC_WHEN_FIELD, REC_WHEN_OP, REC_WHEN_VALUE, &
                                REC_REPEAT, REC_FIRST_FIELD, REC_N_FIELDS, FLD_NAME, FLD_KIND, &
                                FLD_REQUIRED, FLD_DEFAULT_INT, FLD_DEFAULT_REAL, FLD_COUNT
   use adore_deck_tokenizer, only: split_label, cut_field, parse_int_field, parse_real_field, &
                                   is_blank, strip, lstrip_count, itoa
   use adore_core_strings, only: rstrip, quoted, first_non_ascii, utf8_code_point, upper
   use adore_deck_deck_type, only: deck_t, deck_record_t, deck_field_t, deck_find_first
   use adore_deck_problems, only: problem_list_t, add_problem, problems_error
   use adore_deck_ranges, only: check_ranges
   implicit none
   private

   !> Comparison operators of a record condition (schema REC_WHEN_OP), as Python prints them.
   character(len=2), parameter :: COND_OPS(6) = ["==", "!=", "< ", "<=", "> ", ">="]

   public :: read_deck, parse_deck

   !> A record the reader expects next.
   type :: expected_t
      integer :: spec = 0
      character(len=:), allocatable :: rid
   end type expected_t

   !> Everything one reading needs; a local variable of parse_deck (no module state).
   type :: reader_t
      integer :: idx = 0                           !< lines consumed so far
      type(problem_list_t) :: problems             !< everything found wrong so far
      integer :: counts(N_RECORDS) = 0
   end type reader_t

contains

   !> Read the deck file `path` into `deck`.  Input error (listing every problem) when the
   !> file is missing, not text, empty, truncated, or has malformed, missing, surplus or
   !> unknown records, unreadable or blank required values, or values out of range.
   subroutine read_deck(path, deck, error)
      character(len=*), intent(in) :: path
      type(deck_t), intent(out) :: deck
      type(error_type), allocatable, intent(out) :: error

      type(deck_text_t) :: text

      deck%path = path
      allocate (deck%records(0))
      call read_deck_text(path, text, error)
      if (allocated(error)) return
      call parse_deck(text, deck, error)
   end subroutine read_deck

   !> Parse deck text already read by read_deck_text (same checks as read_deck).
   subroutine parse_deck(text, deck, error)
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(out) :: deck
      type(error_type), allocatable, intent(out) :: error

      type(reader_t) :: rd
      type(expected_t) :: want
      integer :: s, i, n, l, c
      logical :: found, holds
      character(len=:), allocatable :: last

      rd%problems%path = text%path
      deck%path = text%path
      allocate (deck%records(size(text%lines) + 1))
      deck%n_records = 0

      call first_invalid_utf8(text, l, c)
      if (l > 0) call add_problem(rd%problems, text, 0, 0, kind="non_text", message="not a text file (invalid "// &
                                  "UTF-8 on line "//itoa(l)//", column "//itoa(c)//"): expected a text deck")
      if (rd%problems%n == 0) then
         if (all_blank(text)) then
            call add_problem(rd%problems, text, 0, 0, message= &
                             "empty file: expected an ADORE deck starting with Rec 1", kind="empty")
         else
            records: do s = 1, N_RECORDS
               if (REC_WHEN_OP(s) /= OP_NONE) then
                  call lookup_int(deck, trim(REC_WHEN_FIELD(s)), n, found)
                  if (.not. found) then
                     call stop_reading(trim(REC_WHEN_FIELD(s)))
                     exit records
                  end if
                  holds = compare(n, REC_WHEN_OP(s), REC_WHEN_VALUE(s))
                  if (.not. holds) cycle records
               end if
               if (len_trim(REC_REPEAT(s)) > 0) then
                  call lookup_int(deck, trim(REC_REPEAT(s)), n, found)
                  if (.not. found) then
                     call stop_reading(trim(REC_REPEAT(s)))
                     exit records
                  end if
                  do i = 1, n
                     want%spec = s
                     want%rid = occurrence_id(s, i)
                     if (.not. take(rd, text, deck, want)) exit records
                  end do
               else
                  want%spec = s
                  want%rid = trim(REC_ID(s))
                  if (.not. take(rd, text, deck, want)) exit records
               end if
            end do records
            if (s > N_RECORDS) call surplus(rd, text, deck)
            call check_ranges(rd%problems, text, deck)
         end if
      end if
      deck%records = deck%records(1:deck%n_records)
      if (rd%problems%n > 0) call problems_error(rd%problems, error)

   contains

      subroutine stop_reading(field)
         character(len=*), intent(in) :: field
         last = "start"
         if (deck%n_records > 0) last = deck%records(deck%n_records)%rid
         call add_problem(rd%problems, text, rd%idx, 1, record=last, message= &
                          "reading stopped: the records after this point depend on field "//field// &
                          ", which is missing or unreadable", kind="type")
      end subroutine stop_reading

   end subroutine parse_deck

   ! ======================================================================================
   ! Reading
   ! ======================================================================================

   !> Concrete id of occurrence `i` of repeated record `s` ("7.2.n" -> "7.2.<i>").
   pure function occurrence_id(s, i) result(rid)
      integer, intent(in) :: s, i
      character(len=len_trim(REC_ID(s)) - 1 + len(itoa(i))) :: rid
      rid = REC_ID(s)(1:len_trim(REC_ID(s)) - 1)//itoa(i)
   end function occurrence_id

   !> Schema index of a concrete record id (0 if unknown); case-sensitive, as Python's record_spec.
   pure integer function record_spec(rid)
      character(len=*), intent(in) :: rid
      character(len=:), allocatable :: sid, prefix, rest
      integer :: s
      do s = 1, N_RECORDS
         sid = trim(REC_ID(s))
         if (sid == rid .and. len(sid) == len(rid)) then
            record_spec = s
            return
         end if
         if (len_trim(REC_REPEAT(s)) > 0) then
            prefix = sid(1:len(sid) - 1)
            if (len(rid) > len(prefix)) then
               rest = rid(len(prefix) + 1:)
               if (rid(1:len(prefix)) == prefix .and. rest(1:1) /= "0" .and. &
                   verify(rest, "0123456789") == 0) then
                  record_spec = s
                  return
               end if
            end if
         end if
      end do
      record_spec = 0
   end function record_spec

   !> Occurrence number of a concrete id of a repeated record (0 for other records).
   pure integer function repeat_index(rid)
      character(len=*), intent(in) :: rid
      integer :: s, stat
      repeat_index = 0
      s = record_spec(rid)
      if (s == 0) return
      if (len_trim(REC_REPEAT(s)) == 0) return
      read (rid(index(rid, ".", back=.true.) + 1:), *, iostat=stat) repeat_index
      if (stat /= 0) repeat_index = 0
   end function repeat_index

   !> True when record `a` comes after record `b` in the fixed deck order.
   pure logical function after(a, b)
      character(len=*), intent(in) :: a, b
      integer :: sa, sb
      sa = record_spec(a)
      sb = record_spec(b)
      if (sa /= sb) then
         after = sa > sb
      else
         after = repeat_index(a) > repeat_index(b)
      end if
   end function after

   !> Evaluate `a op b`.
   pure logical function compare(a, op, b)
      integer, intent(in) :: a, op, b
      select case (op)
      case (OP_EQ); compare = a == b
      case (OP_NE); compare = a /= b
      case (OP_LT); compare = a < b
      case (OP_LE); compare = a <= b
      case (OP_GT); compare = a > b
      case (OP_GE); compare = a >= b
      case default; compare = .true.
      end select
   end function compare

   !> Text of condition of record `s`: "bearing_type == 1".
   pure function condition_text(s) result(t)
      integer, intent(in) :: s
      character(len=len_trim(REC_WHEN_FIELD(s)) + len_trim(COND_OPS(REC_WHEN_OP(s))) + 2 &
                    + len(itoa(REC_WHEN_VALUE(s)))) :: t
      t = trim(REC_WHEN_FIELD(s))//" "//trim(COND_OPS(REC_WHEN_OP(s)))//" "//itoa(REC_WHEN_VALUE(s))
   end function condition_text

   !> The first field called `name` read so far (first occurrence wins, as in Python's
   !> value dict): `found` when it exists, was readable and is an integer.
   pure subroutine lookup_int(deck, name, value, found)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: name
      integer, intent(out) :: value
      logical, intent(out) :: found
      integer :: r, f
      value = 0
      found = .false.
      call deck_find_first(deck, name, r, f)
      if (r == 0) return
      associate (fv => deck%records(r)%fields(f))
         found = fv%valid .and. fv%kind == KIND_INT
         if (found) value = fv%int_value
      end associate
   end subroutine lookup_int

   !> Value of `name` as Python would print it in a message ("2", or "None").
   pure function value_text(deck, name) result(t)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: name
      character(len=value_text_len(deck, name)) :: t
      integer :: v
      logical :: found
      call lookup_int(deck, name, v, found)
      t = "None"
      if (found) t = itoa(v)
   end function value_text

   !> Length of value_text(deck, name).
   pure integer function value_text_len(deck, name)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: name
      integer :: v
      logical :: found
      call lookup_int(deck, name, v, found)
      value_text_len = 4
      if (found) value_text_len = len(itoa(v))
   end function value_text_len

   !> Consume lines until `want` is read or declared missing; false at the end of the file.
   logical function take(rd, text, deck, want)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(inout) :: deck
      type(expected_t), intent(in) :: want

      character(len=:), allocatable :: label, lerr
      logical :: labelled
      integer :: offset, n, lineno

      take = .true.
      do
         n = size(text%lines)
         if (rd%idx >= n) then
            call add_problem(rd%problems, text, n + 1, 1, record=want%rid, kind="truncated", no_source=.true., &
                             message="truncated file: it ends after line "//itoa(n)//", expected Rec "// &
                             want%rid//" ("//trim(REC_TITLE(want%spec))//")")
            take = .false.
            return
         end if
         associate (line => text%lines(rd%idx + 1)%s)
            call split_label(line, labelled, label, offset, lerr)
            if (.not. labelled .or. upper(label) == upper(want%rid)) then
               call parse_record(rd, text, deck, want, line, offset, lerr, labelled)
               rd%idx = rd%idx + 1
               return
            end if
         end associate
         lineno = rd%idx + 1
         if (record_spec(label) == 0) then
            call add_problem(rd%problems, text, lineno, 5, record=label, kind="unknown_record", &
                             message="unknown record id 'Rec "//label//"': expected Rec "//want%rid//" here")
            rd%idx = rd%idx + 1
            cycle
         end if
         if (after(label, want%rid)) then
            call missing(rd, text, deck, want, lineno, label)
            return
         end if
         call unexpected(rd, text, deck, label, lineno, want)
         rd%idx = rd%idx + 1
      end do
   end function take

   !> Report record `want` missing before the record `found` on line `lineno`.
   subroutine missing(rd, text, deck, want, lineno, found)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(in) :: deck
      type(expected_t), intent(in) :: want
      integer, intent(in) :: lineno
      character(len=*), intent(in) :: found
      character(len=:), allocatable :: why, kind
      integer :: s

      s = want%spec
      why = ""
      kind = "missing_record"
      if (len_trim(REC_REPEAT(s)) > 0) then
         why = " ("//trim(REC_REPEAT(s))//" = "//value_text(deck, trim(REC_REPEAT(s)))// &
               " requires one record per land)"
         kind = "cross_field"
      else if (REC_WHEN_OP(s) /= OP_NONE) then
         why = " (required because "//condition_text(s)//": "//trim(REC_WHEN_FIELD(s))//" = "// &
               value_text(deck, trim(REC_WHEN_FIELD(s)))//")"
         kind = "cross_field"
      end if
      call add_problem(rd%problems, text, lineno, 1, record=want%rid, kind=kind, &
                       message="missing record: expected Rec "//want%rid//" ("//trim(REC_TITLE(s))// &
                       ") before Rec "//found//why)
   end subroutine missing

   !> Report record `label` (known id) on line `lineno` where `want` was expected.
   subroutine unexpected(rd, text, deck, label, lineno, want)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: label
      integer, intent(in) :: lineno
      type(expected_t), intent(in) :: want
      character(len=:), allocatable :: why, kind
      integer :: s, n
      logical :: found

      s = record_spec(label)
      kind = "surplus_record"
      why = "expected Rec "//want%rid//" here (record out of order or duplicated)"
      if (len_trim(REC_REPEAT(s)) > 0) then
         call lookup_int(deck, trim(REC_REPEAT(s)), n, found)
         if (found .and. repeat_index(label) > n) then
            kind = "cross_field"
            why = "expected no Rec "//label//": "//trim(REC_REPEAT(s))//" = "//itoa(n)
         end if
      else if (REC_WHEN_OP(s) /= OP_NONE) then
         call lookup_int(deck, trim(REC_WHEN_FIELD(s)), n, found)
         if (found) then
            if (.not. compare(n, REC_WHEN_OP(s), REC_WHEN_VALUE(s))) then
               kind = "cross_field"
               why = "expected no Rec "//label//": it requires "//condition_text(s)//", but "// &
                     trim(REC_WHEN_FIELD(s))//" = "//itoa(n)
            end if
         end if
      end if
      call add_problem(rd%problems, text, lineno, 1, record=label, kind=kind, message="unexpected record: "//why)
   end subroutine unexpected

   !> Report every non-blank line after the last record.
   subroutine surplus(rd, text, deck)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(in) :: deck
      character(len=:), allocatable :: last, label, lerr
      logical :: labelled
      integer :: i, offset

      last = "?"
      if (deck%n_records > 0) last = deck%records(deck%n_records)%rid
      do i = rd%idx + 1, size(text%lines)
         if (is_blank(text%lines(i)%s)) cycle
         call split_label(text%lines(i)%s, labelled, label, offset, lerr)
         if (labelled .and. record_spec(label) == 0) then
            call add_problem(rd%problems, text, i, 5, record=label, kind="unknown_record", &
                             message="unknown record id 'Rec "//label//"': expected end of deck after Rec "//last)
         else if (labelled) then
            call add_problem(rd%problems, text, i, 1, record=label, kind="surplus_record", &
                             message="surplus record: expected end of deck after Rec "//last)
         else
            call add_problem(rd%problems, text, i, 1, kind="surplus_record", &
                             message="surplus record: expected end of deck after Rec "//last)
         end if
      end do
   end subroutine surplus

   !> Cut one line into the fields of record `want` and append the record to `deck`.
   subroutine parse_record(rd, text, deck, want, line, offset, lerr, labelled)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(inout) :: deck
      type(expected_t), intent(in) :: want
      character(len=*), intent(in) :: line, lerr
      integer, intent(in) :: offset
      logical, intent(in) :: labelled

      type(deck_record_t) :: rec
      type(deck_field_t), allocatable :: fields(:)
      character(len=:), allocatable :: rest, full
      integer :: lineno, pos, f, s, n, i, j, nf, width, last_text, foreign, code, nbytes
      logical :: found, counted
      character(len=8) :: hex

      lineno = rd%idx + 1
      s = want%spec
      if (len(lerr) > 0) call add_problem(rd%problems, text, lineno, 1, record=want%rid, message=lerr, kind="format")
      if (index(line, achar(9)) > 0) &
         call add_problem(rd%problems, text, lineno, index(line, achar(9)), record=want%rid, kind="format", &
                          message="tab character: expected blanks (fields are fixed columns)")
      ! Numbers live in fixed ASCII columns (ADORE reads bytes): a non-ASCII character in a
      ! record without text fields is one problem, and its fields are left unread (their
      ! columns cannot be told apart); pyadore/deck/reader.py applies the same rule.
      foreign = 0
      if (.not. any(FLD_KIND(REC_FIRST_FIELD(s):REC_FIRST_FIELD(s) + REC_N_FIELDS(s) - 1) == KIND_TEXT)) &
         foreign = first_non_ascii(line, offset + 1)
      if (foreign > 0) then
         call utf8_code_point(line, foreign, code, nbytes)
         write (hex, "(z0.4)") code
         call add_problem(rd%problems, text, lineno, foreign, record=want%rid, kind="format", &
                          message="non-ASCII character '"//line(foreign:foreign + nbytes - 1)//"' (U+"// &
                          trim(hex)//"): expected ASCII digits, signs, points, exponent letters and blanks "// &
                          "(fields are fixed columns of ASCII characters)")
      end if
      allocate (fields(max(REC_N_FIELDS(s), 1)))
      nf = 0
      pos = offset
      last_text = 0
      specs: do f = REC_FIRST_FIELD(s), REC_FIRST_FIELD(s) + REC_N_FIELDS(s) - 1
         counted = len_trim(FLD_COUNT(f)) > 0
         n = 1
         if (counted) then
            if (foreign > 0) exit specs
            found = .false.
            do j = 1, nf
               if (fields(j)%name == trim(FLD_COUNT(f))) then
                  found = fields(j)%valid .and. fields(j)%kind == KIND_INT
                  n = fields(j)%int_value
                  exit
               end if
            end do
            if (.not. found .or. n < 0) then
               call add_problem(rd%problems, text, lineno, pos + 1, record=want%rid, field=trim(FLD_NAME(f)), &
                                kind="type", message="cannot read: its count "//trim(FLD_COUNT(f))// &
                                " is unreadable")
               exit specs
            end if
         end if
         do i = 1, n
            nf = nf + 1
            if (nf > size(fields)) call grow(fields)
            fields(nf)%name = trim(FLD_NAME(f))
            if (counted) fields(nf)%name = trim(FLD_NAME(f))//"["//itoa(i)//"]"
            width = field_width(f)
            if (foreign > 0) then
               call unread_field(f, cut_field(line, pos, width), lineno, pos + 1, fields(nf))
            else
               call read_field(rd, text, want%rid, f, cut_field(line, pos, width), lineno, pos + 1, fields(nf))
            end if
            if (FLD_KIND(f) == KIND_TEXT) last_text = nf
            pos = pos + width
         end do
      end do specs

      if (pos < len(line)) then
         rest = line(pos + 1:)
      else
         rest = ""
      end if
      if (.not. is_blank(rest) .and. foreign == 0) then
         i = pos + lstrip_count(rest) + 1
         if (last_text > 0) then
            full = strip(fields(last_text)%raw//rest)
            call add_problem(rd%problems, text, lineno, i, record=want%rid, field=fields(last_text)%name, &
                             shown=quoted(full), kind="range", &
                             message="expected at most "//itoa(TEXT_WIDTH)//" characters (run id is "// &
                             itoa(len(full))//" long)")
         else
            call add_problem(rd%problems, text, lineno, i, record=want%rid, kind="format", &
                             message="text after the last field (column "//itoa(pos)// &
                             "): expected at most "//itoa(nf)//" fields")
         end if
      end if

      rd%counts(s) = rd%counts(s) + 1
      rec%rid = want%rid
      rec%spec = s
      rec%occurrence = rd%counts(s)
      rec%line = lineno
      rec%source = ""
      if (lineno <= size(text%lines)) rec%source = text%lines(lineno)%s
      rec%labelled = labelled
      rec%n_fields = nf
      rec%fields = fields(1:nf)
      deck%n_records = deck%n_records + 1
      deck%records(deck%n_records) = rec
   end subroutine parse_record

   !> Double the size of `fields`, keeping its content.
   subroutine grow(fields)
      type(deck_field_t), allocatable, intent(inout) :: fields(:)
      type(deck_field_t), allocatable :: tmp(:)
      allocate (tmp(2*size(fields)))
      tmp(1:size(fields)) = fields
      call move_alloc(tmp, fields)
   end subroutine grow

   !> Width in columns of field spec `f`.
   pure integer function field_width(f)
      integer, intent(in) :: f
      select case (FLD_KIND(f))
      case (KIND_INT); field_width = INT_WIDTH
      case (KIND_REAL); field_width = REAL_WIDTH
      case default; field_width = TEXT_WIDTH
      end select
   end function field_width

   !> Field spec `f` with text `tok` (starting in column `col`) left unread, with no problem of
   !> its own (its line holds a non-ASCII character, already reported); read_field's start.
   subroutine unread_field(f, tok, lineno, col, fv)
      integer, intent(in) :: f, lineno, col
      character(len=*), intent(in) :: tok
      type(deck_field_t), intent(inout) :: fv
      fv%kind = FLD_KIND(f)
      fv%spec = f
      fv%line = lineno
      fv%col = col
      fv%raw = tok
      fv%text_value = ""
      fv%blank = .false.
      fv%valid = .false.
   end subroutine unread_field

   !> Convert the text `tok` (starting in column `col`) of field spec `f` into `fv`.
   subroutine read_field(rd, text, rid, f, tok, lineno, col, fv)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      character(len=*), intent(in) :: rid, tok
      integer, intent(in) :: f, lineno, col
      type(deck_field_t), intent(inout) :: fv
      character(len=:), allocatable :: msg, kind, shown
      logical :: blank
      integer :: lead

      call unread_field(f, tok, lineno, col, fv)
      msg = ""
      select case (FLD_KIND(f))
      case (KIND_TEXT)
         fv%text_value = rstrip(tok)
         fv%blank = is_blank(tok)
         fv%valid = .true.
         return
      case (KIND_INT)
         call parse_int_field(tok, fv%int_value, blank, msg)
      case default
         call parse_real_field(tok, fv%real_value, blank, msg)
      end select
      fv%blank = blank
      if (blank) then
         if (FLD_REQUIRED(f)) then
            msg = "expected a value (the field is required and has no default)"
         else
            fv%int_value = FLD_DEFAULT_INT(f)
            fv%real_value = FLD_DEFAULT_REAL(f)
         end if
      end if
      fv%valid = len(msg) == 0
      if (fv%valid) return
      kind = "type"
      if (blank) kind = "missing_value"
      lead = 0
      if (.not. is_blank(tok)) lead = lstrip_count(tok)
      shown = "(blank)"
      if (.not. is_blank(tok)) shown = quoted(strip(tok))
      call add_problem(rd%problems, text, lineno, col + lead, record=rid, field=fv%name, shown=shown, &
                       message=msg, kind=kind)
   end subroutine read_field

   ! ======================================================================================
   ! Small text helpers
   ! ======================================================================================

   !> True when every line is blank.
   pure logical function all_blank(text)
      type(deck_text_t), intent(in) :: text
      integer :: i
      all_blank = .true.
      do i = 1, size(text%lines)
         if (.not. is_blank(text%lines(i)%s)) then
            all_blank = .false.
            return
         end if
      end do
   end function all_blank

end module adore_deck_parser
