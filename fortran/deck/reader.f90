!> Reading an ADORE deck into derived types: the engine's counterpart of pyadore.deck.
!>
!> The record sequence, the field layout, defaults, bounds and choices all come from the
!> generated table adore_deck_schema (fortran/deck/schema_table.f90, written from
!> pyadore/deck/records.py), and lines are cut exactly as pyadore/deck/tokenizer.py cuts
!> them, so both readers accept and reject the same decks with the same messages.
!>
!> Checks: non-text content (control bytes, invalid UTF-8), empty file, truncated file,
!> label-zone and tab format errors, text after the last field, unknown / missing /
!> surplus / out-of-order records, records required or forbidden by a flag or count,
!> bad integers and reals, blank required fields, and every value's range or choices.
!> Not checked here: the cross-field consistency checks of pyadore/deck/validate.py
!> (CROSS_CHECKS: pitch between bore and OD, elements fit, cage ID < OD, step order,
!> traction peak...): adore_model_bearing's check_values applies them, in the same words, when
!> it builds the bearing model.  All problems are collected, then returned as one input error
!> whose message lists each as Python's Problem.format() does:
!>
!>     deck.inp:11:24  Rec 5A  field pitch_diameter = '1.4OOOE-01': expected a real number (E11.4)
!>         Rec 5A       1.9050E-02 1.4OOOE-01 2.5000E+01 ...
!>                        ^
!>
!> Record ids: a repeated record has the schema id "7.2.n" and concrete ids 7.2.1, 7.2.2...
!> The accessors take either a concrete id ("7.2.2"), the schema id ("7.2.n") or the
!> schema id without its ".n" ("7.2"); with the last two, `occurrence` selects the land.
!> Repeated fields are named as in pyadore.deck.field_table: "guide_type[1]", "guide_type[2]".
!> Values are in the schema's units (SI: m, K, s, N, rpm, deg; see docs/deck-format.md).
module adore_deck_reader
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_deck_text, only: deck_text_t, read_deck_text
   use adore_deck_schema, only: N_RECORDS, KIND_INT, KIND_REAL, KIND_TEXT, INT_WIDTH, REAL_WIDTH, &
                                TEXT_WIDTH, OP_NONE, OP_EQ, OP_NE, OP_LT, OP_LE, OP_GT, OP_GE, &
                                REC_ID, REC_TITLE, REC_WHEN_FIELD, REC_WHEN_OP, REC_WHEN_VALUE, &
                                REC_REPEAT, REC_FIRST_FIELD, REC_N_FIELDS, FLD_NAME, FLD_KIND, &
                                FLD_REQUIRED, FLD_DEFAULT_INT, FLD_DEFAULT_REAL, FLD_DEFAULT_TEXT, &
                                FLD_HAS_LO, FLD_LO, FLD_LO_OPEN, FLD_HAS_HI, FLD_HI, FLD_HI_OPEN, &
                                FLD_FIRST_CHOICE, FLD_N_CHOICES, CHOICES, FLD_COUNT, FLD_RANGE_TEXT, &
                                FLD_MEANING
   use adore_deck_tokenizer, only: split_label, cut_field, parse_int_field, parse_real_field, &
                                   is_blank, strip, lstrip_count, show_real, itoa
   use adore_core_strings, only: rstrip, quoted
   implicit none
   private

   !> Comparison operators of a record condition (schema REC_WHEN_OP), as Python prints them.
   character(len=2), parameter :: COND_OPS(6) = ["==", "!=", "< ", "<=", "> ", ">="]

   public :: deck_field_t, deck_record_t, deck_t
   public :: read_deck, parse_deck, deck_has, deck_count
   public :: deck_get_real, deck_get_int, deck_get_text
   public :: deck_collect_real, deck_collect_int, deck_collect_text
   public :: deck_field_problem
   public :: FIELD_INT, FIELD_REAL, FIELD_TEXT

   !> Field kinds of deck_field_t%kind.
   integer, parameter :: FIELD_INT = KIND_INT, FIELD_REAL = KIND_REAL, FIELD_TEXT = KIND_TEXT

   !> One field of a record: its value (in the member matching `kind`), where it was read.
   type :: deck_field_t
      character(len=:), allocatable :: name        !< "pitch_diameter", "guide_type[2]"
      integer :: kind = KIND_REAL                  !< FIELD_INT, FIELD_REAL or FIELD_TEXT
      integer :: int_value = 0                     !< value of an integer field
      real(wp) :: real_value = 0.0_wp              !< value of a real field (schema unit)
      character(len=:), allocatable :: text_value  !< value of a text field
      logical :: valid = .false.                   !< false when the text could not be read
      logical :: blank = .false.                   !< blank in the file (default taken)
      integer :: line = 0                          !< 1-based line of the deck file
      integer :: col = 0                           !< 1-based first column of the field
      integer :: spec = 0                          !< index into the FLD_* schema table
      character(len=:), allocatable :: raw         !< the field's text as in the file
   end type deck_field_t

   !> One record: concrete id ("7.2.2"), occurrence among records of its type, fields.
   type :: deck_record_t
      character(len=:), allocatable :: rid         !< concrete record id
      integer :: spec = 0                          !< index into the REC_* schema table
      integer :: occurrence = 1                    !< 1-based among records of the same type
      integer :: line = 0                          !< 1-based line of the deck file
      character(len=:), allocatable :: source      !< that line as in the file (for messages)
      logical :: labelled = .false.                !< the line carried a `Rec <id>` label
      integer :: n_fields = 0
      type(deck_field_t), allocatable :: fields(:)
   end type deck_record_t

   !> A deck: its records in deck order and the path it was read from.
   type :: deck_t
      character(len=:), allocatable :: path
      integer :: n_records = 0
      type(deck_record_t), allocatable :: records(:)
   end type deck_t

   !> One problem found in the deck (fields of pyadore.deck.model.Problem).
   type :: problem_t
      integer :: line = 0, col = 0
      character(len=:), allocatable :: record, field, shown, message, kind, source
      logical :: has_record = .false., has_field = .false., has_source = .false.
   end type problem_t

   !> A record the reader expects next.
   type :: expected_t
      integer :: spec = 0
      character(len=:), allocatable :: rid
   end type expected_t

   !> Everything one reading needs; a local variable of parse_deck (no module state).
   type :: reader_t
      character(len=:), allocatable :: path
      integer :: idx = 0                           !< lines consumed so far
      integer :: n_problems = 0
      type(problem_t), allocatable :: problems(:)
      integer :: counts(N_RECORDS) = 0
   end type reader_t

contains

   ! ======================================================================================
   ! Public procedures
   ! ======================================================================================

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
      integer :: s, i, n
      logical :: found, holds
      character(len=:), allocatable :: last

      rd%path = text%path
      deck%path = text%path
      allocate (rd%problems(16))
      allocate (deck%records(size(text%lines) + 1))
      deck%n_records = 0

      call check_utf8(rd, text)
      if (rd%n_problems == 0) then
         if (all_blank(text)) then
            call add_problem(rd, text, 0, 0, message= &
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
            call check_ranges(rd, text, deck)
         end if
      end if
      deck%records = deck%records(1:deck%n_records)
      if (rd%n_problems > 0) call problems_error(rd, error)

   contains

      subroutine stop_reading(field)
         character(len=*), intent(in) :: field
         last = "start"
         if (deck%n_records > 0) last = deck%records(deck%n_records)%rid
         call add_problem(rd, text, rd%idx, 1, record=last, message= &
                          "reading stopped: the records after this point depend on field "//field// &
                          ", which is missing or unreadable", kind="type")
      end subroutine stop_reading

   end subroutine parse_deck

   !> True when the deck holds at least one record `rid` (concrete "7.2.2", schema "7.2.n" or "7.2").
   logical function deck_has(deck, rid)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid
      deck_has = deck_count(deck, rid) > 0
   end function deck_has

   !> Number of records `rid` in the deck: deck_count(deck, "7.2") (or "7.2.n") counts
   !> 7.2.1, 7.2.2, ... (one per guide land); a concrete id counts 0 or 1.
   integer function deck_count(deck, rid)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid
      integer :: r
      deck_count = 0
      if (.not. allocated(deck%records)) return
      do r = 1, deck%n_records
         if (record_matches(deck%records(r), rid)) deck_count = deck_count + 1
      end do
   end function deck_count

   !> Value of real field `field` of record `rid` (its `occurrence`, 1-based, default 1),
   !> in the schema's SI unit.  Engine error naming rid and field if absent or not real.
   subroutine deck_get_real(deck, rid, field, value, error, occurrence)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      real(wp), intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: occurrence
      integer :: r, f

      value = 0.0_wp
      call find_field(deck, rid, field, KIND_REAL, r, f, error, occurrence)
      if (allocated(error)) return
      value = deck%records(r)%fields(f)%real_value
   end subroutine deck_get_real

   !> Value of integer field `field` of record `rid` (occurrence as for deck_get_real).
   subroutine deck_get_int(deck, rid, field, value, error, occurrence)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      integer, intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: occurrence
      integer :: r, f

      value = 0
      call find_field(deck, rid, field, KIND_INT, r, f, error, occurrence)
      if (allocated(error)) return
      value = deck%records(r)%fields(f)%int_value
   end subroutine deck_get_int

   !> Value of text field `field` of record `rid` (the run id; trailing blanks removed).
   subroutine deck_get_text(deck, rid, field, value, error, occurrence)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      character(len=:), allocatable, intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: occurrence
      integer :: r, f

      value = ""
      call find_field(deck, rid, field, KIND_TEXT, r, f, error, occurrence)
      if (allocated(error)) return
      value = deck%records(r)%fields(f)%text_value
   end subroutine deck_get_text

   ! ======================================================================================
   ! Access helpers
   ! ======================================================================================

   !> Does record `rec` answer to `rid` (concrete id, schema id, or schema id without ".n")?
   pure logical function record_matches(rec, rid)
      type(deck_record_t), intent(in) :: rec
      character(len=*), intent(in) :: rid
      character(len=:), allocatable :: sid
      sid = trim(REC_ID(rec%spec))
      record_matches = rec%rid == rid .or. sid == rid
      if (.not. record_matches .and. len_trim(REC_REPEAT(rec%spec)) > 0) &
         record_matches = sid(1:len(sid) - 2) == rid
   end function record_matches

   !> deck_get_real for reading many fields in a row: does nothing once `error` holds a
   !> failure (the first one is kept); with if_present = .true. an absent record leaves
   !> `value` unchanged instead of failing.
   subroutine deck_collect_real(deck, rid, field, value, error, occurrence, if_present)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      real(wp), intent(inout) :: value
      type(error_type), allocatable, intent(inout) :: error
      integer, intent(in), optional :: occurrence
      logical, intent(in), optional :: if_present
      type(error_type), allocatable :: e
      real(wp) :: v

      if (allocated(error)) return
      if (present(if_present)) then
         if (if_present .and. .not. deck_has(deck, rid)) return
      end if
      call deck_get_real(deck, rid, field, v, e, occurrence)
      if (allocated(e)) then
         call move_alloc(e, error)
      else
         value = v
      end if
   end subroutine deck_collect_real

   !> deck_get_int in the manner of deck_collect_real.
   subroutine deck_collect_int(deck, rid, field, value, error, occurrence, if_present)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      integer, intent(inout) :: value
      type(error_type), allocatable, intent(inout) :: error
      integer, intent(in), optional :: occurrence
      logical, intent(in), optional :: if_present
      type(error_type), allocatable :: e
      integer :: v

      if (allocated(error)) return
      if (present(if_present)) then
         if (if_present .and. .not. deck_has(deck, rid)) return
      end if
      call deck_get_int(deck, rid, field, v, e, occurrence)
      if (allocated(e)) then
         call move_alloc(e, error)
      else
         value = v
      end if
   end subroutine deck_collect_int

   !> deck_get_text in the manner of deck_collect_real.
   subroutine deck_collect_text(deck, rid, field, value, error)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      character(len=:), allocatable, intent(inout) :: value
      type(error_type), allocatable, intent(inout) :: error
      type(error_type), allocatable :: e
      character(len=:), allocatable :: v

      if (allocated(error)) return
      call deck_get_text(deck, rid, field, v, e)
      if (allocated(e)) then
         call move_alloc(e, error)
      else
         value = v
      end if
   end subroutine deck_collect_text

   !> Locate field `field` of the `occurrence`-th record answering to `rid`.
   subroutine find_field(deck, rid, field, kind, r, f, error, occurrence)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: rid, field
      integer, intent(in) :: kind
      integer, intent(out) :: r, f
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: occurrence
      integer :: occ, seen
      character(len=*), parameter :: KIND_NAME(3) = ["integer", "real   ", "text   "]

      occ = 1
      if (present(occurrence)) occ = occurrence
      f = 0
      seen = 0
      if (allocated(deck%records)) then
         do r = 1, deck%n_records
            if (.not. record_matches(deck%records(r), rid)) cycle
            seen = seen + 1
            if (seen == occ) exit
         end do
      end if
      if (seen < occ .or. occ < 1) then
         call engine_error(error, "deck: Rec "//rid//" field "//field//": no such record (occurrence "// &
                           itoa(occ)//"; the deck has "//itoa(seen)//")")
         r = 0
         return
      end if
      do f = 1, deck%records(r)%n_fields
         if (deck%records(r)%fields(f)%name == field) exit
      end do
      if (f > deck%records(r)%n_fields) then
         call engine_error(error, "deck: Rec "//deck%records(r)%rid//" field "//field// &
                           ": no such field in this record")
         return
      end if
      associate (fv => deck%records(r)%fields(f))
         if (fv%kind /= kind) then
            call engine_error(error, "deck: Rec "//deck%records(r)%rid//" field "//field//": is "// &
                              trim(KIND_NAME(fv%kind))//", not "//trim(KIND_NAME(kind)))
         else if (.not. fv%valid) then
            call engine_error(error, "deck: Rec "//deck%records(r)%rid//" field "//field// &
                              ": has no value (it could not be read)")
         end if
      end associate
   end subroutine find_field

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
      do r = 1, deck%n_records
         do f = 1, deck%records(r)%n_fields
            associate (fv => deck%records(r)%fields(f))
               if (fv%name /= name) cycle
               found = fv%valid .and. fv%kind == KIND_INT
               if (found) value = fv%int_value
               return
            end associate
         end do
      end do
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
            call add_problem(rd, text, n + 1, 1, record=want%rid, kind="truncated", no_source=.true., &
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
            call add_problem(rd, text, lineno, 5, record=label, kind="unknown_record", &
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
      call add_problem(rd, text, lineno, 1, record=want%rid, kind=kind, &
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
      call add_problem(rd, text, lineno, 1, record=label, kind=kind, message="unexpected record: "//why)
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
            call add_problem(rd, text, i, 5, record=label, kind="unknown_record", &
                             message="unknown record id 'Rec "//label//"': expected end of deck after Rec "//last)
         else if (labelled) then
            call add_problem(rd, text, i, 1, record=label, kind="surplus_record", &
                             message="surplus record: expected end of deck after Rec "//last)
         else
            call add_problem(rd, text, i, 1, kind="surplus_record", &
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
      integer :: lineno, pos, f, s, n, i, j, nf, width, last_text
      logical :: found, counted

      lineno = rd%idx + 1
      s = want%spec
      if (len(lerr) > 0) call add_problem(rd, text, lineno, 1, record=want%rid, message=lerr, kind="format")
      if (index(line, achar(9)) > 0) &
         call add_problem(rd, text, lineno, index(line, achar(9)), record=want%rid, kind="format", &
                          message="tab character: expected blanks (fields are fixed columns)")
      allocate (fields(max(REC_N_FIELDS(s), 1)))
      nf = 0
      pos = offset
      last_text = 0
      specs: do f = REC_FIRST_FIELD(s), REC_FIRST_FIELD(s) + REC_N_FIELDS(s) - 1
         counted = len_trim(FLD_COUNT(f)) > 0
         n = 1
         if (counted) then
            found = .false.
            do j = 1, nf
               if (fields(j)%name == trim(FLD_COUNT(f))) then
                  found = fields(j)%valid .and. fields(j)%kind == KIND_INT
                  n = fields(j)%int_value
                  exit
               end if
            end do
            if (.not. found .or. n < 0) then
               call add_problem(rd, text, lineno, pos + 1, record=want%rid, field=trim(FLD_NAME(f)), &
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
            call read_field(rd, text, want%rid, f, cut_field(line, pos, width), lineno, pos + 1, fields(nf))
            if (FLD_KIND(f) == KIND_TEXT) last_text = nf
            pos = pos + width
         end do
      end do specs

      if (pos < len(line)) then
         rest = line(pos + 1:)
      else
         rest = ""
      end if
      if (.not. is_blank(rest)) then
         i = pos + lstrip_count(rest) + 1
         if (last_text > 0) then
            full = strip(fields(last_text)%raw//rest)
            call add_problem(rd, text, lineno, i, record=want%rid, field=fields(last_text)%name, &
                             shown=quoted(full), kind="range", &
                             message="expected at most "//itoa(TEXT_WIDTH)//" characters (run id is "// &
                             itoa(len(full))//" long)")
         else
            call add_problem(rd, text, lineno, i, record=want%rid, kind="format", &
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

      fv%kind = FLD_KIND(f)
      fv%spec = f
      fv%line = lineno
      fv%col = col
      fv%raw = tok
      fv%text_value = ""
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
      call add_problem(rd, text, lineno, col + lead, record=rid, field=fv%name, shown=shown, &
                       message=msg, kind=kind)
   end subroutine read_field

   !> Range and choice checks of every readable number (pyadore/deck/validate.py _ranges).
   subroutine check_ranges(rd, text, deck)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      type(deck_t), intent(in) :: deck
      integer :: r, k, f, lead
      real(wp) :: v
      logical :: ok
      character(len=:), allocatable :: shown

      do r = 1, deck%n_records
         do k = 1, deck%records(r)%n_fields
            associate (fv => deck%records(r)%fields(k))
               if (.not. fv%valid .or. fv%kind == KIND_TEXT) cycle
               f = fv%spec
               if (fv%kind == KIND_INT) then
                  v = real(fv%int_value, wp)
                  shown = itoa(fv%int_value)
               else
                  v = fv%real_value
                  shown = show_real(v)
               end if
               if (FLD_N_CHOICES(f) > 0) then
                  ok = fv%kind == KIND_INT .and. &
                       any(CHOICES(FLD_FIRST_CHOICE(f):FLD_FIRST_CHOICE(f) + FLD_N_CHOICES(f) - 1) == fv%int_value)
               else
                  ok = .true.
                  if (FLD_HAS_LO(f)) ok = ok .and. merge(v > FLD_LO(f), v >= FLD_LO(f), FLD_LO_OPEN(f))
                  if (FLD_HAS_HI(f)) ok = ok .and. merge(v < FLD_HI(f), v <= FLD_HI(f), FLD_HI_OPEN(f))
               end if
               if (ok) cycle
               lead = 0
               if (.not. is_blank(fv%raw)) lead = lstrip_count(fv%raw)
               call add_problem(rd, text, fv%line, fv%col + lead, record=deck%records(r)%rid, &
                                field=fv%name, shown=shown, kind="range", &
                                message="expected "//trim(FLD_RANGE_TEXT(f))//" ("//trim(FLD_MEANING(f))//")")
            end associate
         end do
      end do
   end subroutine check_ranges

   ! ======================================================================================
   ! Problems
   ! ======================================================================================

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
   subroutine add_problem(rd, text, line, col, message, kind, record, field, shown, no_source)
      type(reader_t), intent(inout) :: rd
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
      if (rd%n_problems == size(rd%problems)) rd%problems = [rd%problems, rd%problems]
      rd%n_problems = rd%n_problems + 1
      rd%problems(rd%n_problems) = p
   end subroutine add_problem

   !> One problem as Python's Problem.format(): location, record, field = value, message,
   !> then the offending line and a caret under the column.
   subroutine format_problem(path, p, s)
      character(len=*), intent(in) :: path
      type(problem_t), intent(in) :: p
      character(len=:), allocatable, intent(out) :: s
      character(len=:), allocatable :: shown
      integer :: i

      if (p%line > 0) then
         s = path//":"//itoa(p%line)//":"//itoa(p%col)
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
      s = s//new_line("a")//"    "//shown//new_line("a")//"    "//repeat(" ", max(p%col - 1, 0))//"^"
   end subroutine format_problem

   !> Sort the problems by line (line 0 last) and column, stably, and build the input error.
   subroutine problems_error(rd, error)
      type(reader_t), intent(inout) :: rd
      type(error_type), allocatable, intent(out) :: error
      type(problem_t) :: p
      character(len=:), allocatable :: msg, line
      integer :: i, j

      do i = 2, rd%n_problems
         p = rd%problems(i)
         j = i - 1
         do while (j >= 1)
            if (.not. later(rd%problems(j), p)) exit
            rd%problems(j + 1) = rd%problems(j)
            j = j - 1
         end do
         rd%problems(j + 1) = p
      end do
      msg = rd%path//": "//itoa(rd%n_problems)//" problem(s) reading the deck"
      do i = 1, rd%n_problems
         call format_problem(rd%path, rd%problems(i), line)
         msg = msg//new_line("a")//line
      end do
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

   !> A non-text problem for the first byte sequence that is not valid UTF-8.
   subroutine check_utf8(rd, text)
      type(reader_t), intent(inout) :: rd
      type(deck_text_t), intent(in) :: text
      integer :: l, i, c, n, k, lo, hi

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
                  call add_problem(rd, text, 0, 0, kind="non_text", message="not a text file (invalid "// &
                                   "UTF-8 on line "//itoa(l)//", column "//itoa(i)//"): expected a text deck")
                  return
               end if
               i = i + n + 1
            end do
         end associate
      end do
   end subroutine check_utf8

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

   !> Upper-case ASCII copy of `s`.
   pure function upper(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i
      t = s
      do i = 1, len(s)
         if (s(i:i) >= "a" .and. s(i:i) <= "z") t(i:i) = achar(iachar(s(i:i)) - 32)
      end do
   end function upper

end module adore_deck_reader
