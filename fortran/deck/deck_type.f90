!> The deck as derived types and their accessors: deck_t (records in deck order), each
!> record's fields with their values and where they were read.  Filled by the parser
!> (adore_deck_parser); read by the model with deck_get_* / deck_collect_*.
!>
!> Record ids: a repeated record has the schema id "7.2.n" and concrete ids 7.2.1, 7.2.2...
!> The accessors take either a concrete id ("7.2.2"), the schema id ("7.2.n") or the
!> schema id without its ".n" ("7.2"); with the last two, `occurrence` selects the land.
!> Repeated fields are named as in pyadore.deck.field_table: "guide_type[1]", "guide_type[2]".
!> Values are in the schema's units (SI: m, K, s, N, rpm, deg; see docs/deck-format.md).
module adore_deck_deck_type
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error
   use adore_deck_schema, only: KIND_INT, KIND_REAL, KIND_TEXT, REC_ID, REC_REPEAT
   use adore_core_strings, only: itoa
   implicit none
   private

   public :: deck_field_t, deck_record_t, deck_t
   public :: deck_has, deck_count, record_matches, deck_find_first
   public :: deck_get_real, deck_get_int, deck_get_text
   public :: deck_collect_real, deck_collect_int, deck_collect_text
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

contains

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

   !> Record r and field f of the first field called `name` anywhere in the deck, readable
   !> or not (r = f = 0 when there is none): the value the schema's record conditions and
   !> the cross-field checks see, as Python's Deck.lookup.
   pure subroutine deck_find_first(deck, name, r, f)
      type(deck_t), intent(in) :: deck
      character(len=*), intent(in) :: name
      integer, intent(out) :: r, f
      do r = 1, deck%n_records
         do f = 1, deck%records(r)%n_fields
            if (deck%records(r)%fields(f)%name == name) return
         end do
      end do
      r = 0
      f = 0
   end subroutine deck_find_first

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

end module adore_deck_deck_type
