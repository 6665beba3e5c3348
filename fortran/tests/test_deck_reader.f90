!> Engine unit tests of the deck tokenizer (adore_deck_tokenizer) and reader accessors
!> (adore_deck_deck_type, adore_deck_parser).  Run by `meson test` with the decks/ directory as argument;
!> pytest runs it from tests/test_engine_units.py.
program test_deck_reader
   use adore_test_support, only: check, finish, get_decks_dir
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, ADORE_INPUT_ERROR, ADORE_ENGINE_ERROR
   use adore_deck_tokenizer, only: split_label, cut_field, parse_int_field, parse_real_field, show_real
   use adore_deck_deck_type, only: deck_t, deck_has, deck_count, deck_get_real, deck_get_int, &
                                   deck_get_text
   use adore_deck_parser, only: read_deck
   implicit none

   character(len=:), allocatable :: decks

   call get_decks_dir(decks)
   call test_run_together_reals()
   call test_exponent_forms()
   call test_blank_and_bad_numbers()
   call test_integers()
   call test_labels()
   call test_show_real()
   call test_ball_deck_accessors()
   call test_roller_deck_accessors()
   call test_bad_deck_message()

   call finish("deck reader")

contains

   !> Real value of field `text` that must parse without message.
   subroutine expect_real(text, expected, what)
      character(len=*), intent(in) :: text, what
      real(wp), intent(in) :: expected
      real(wp) :: v
      logical :: blank
      character(len=:), allocatable :: msg
      call parse_real_field(text, v, blank, msg)
      call check(len(msg) == 0 .and. .not. blank, what//": accepted ("//msg//")")
      call check(v == expected, what//": value")
   end subroutine expect_real

   !> A real field that must be refused with a message containing `part`.
   subroutine expect_real_error(text, part, what)
      character(len=*), intent(in) :: text, part, what
      real(wp) :: v
      logical :: blank
      character(len=:), allocatable :: msg
      call parse_real_field(text, v, blank, msg)
      call check(index(msg, part) > 0, what//": message '"//msg//"' contains '"//part//"'")
   end subroutine expect_real_error

   subroutine test_run_together_reals()
      character(len=*), parameter :: line = " 0.0000E+00 0.0000E+00-6.0000E-04"
      character(len=*), parameter :: line2 = "1.46292E-011.30073E-01 3.6241E-02"
      call expect_real(cut_field(line, 0, 11), 0.0_wp, "first of three")
      call expect_real(cut_field(line, 22, 11), -6.0e-4_wp, "run-together negative third")
      call check(cut_field(line, 22, 11) == "-6.0000E-04", "fixed 11-column cut")
      call expect_real(cut_field(line2, 0, 11), 1.46292e-1_wp, "five decimals, no blank separator")
      call expect_real(cut_field(line2, 11, 11), 1.30073e-1_wp, "second of run-together pair")
      call check(cut_field(line, 33, 11) == "", "field past the end of the line is empty")
      call check(cut_field(line, 30, 11) == "-04", "field cut by the end of the line")
   end subroutine test_run_together_reals

   subroutine test_exponent_forms()
      call expect_real(" 1.0000D-05", 1.0e-5_wp, "D exponent")
      call expect_real(" 1.0000d+02", 100.0_wp, "lower-case d exponent")
      call expect_real("    1.0-05 ", 1.0e-5_wp, "sign-started exponent")
      call expect_real("   2.5E3   ", 2500.0_wp, "E exponent without sign")
      call expect_real("      -.5  ", -0.5_wp, "no digit before the point")
      call expect_real("        5. ", 5.0_wp, "no digit after the point")
      call expect_real("+9.8100E+00", 9.81_wp, "explicit plus sign")
   end subroutine test_exponent_forms

   subroutine test_blank_and_bad_numbers()
      real(wp) :: v
      logical :: blank
      character(len=:), allocatable :: msg
      call parse_real_field("           ", v, blank, msg)
      call check(blank .and. len(msg) == 0, "blank real field is blank, no message")
      call parse_real_field("", v, blank, msg)
      call check(blank .and. len(msg) == 0, "empty real field is blank")
      call expect_real_error("      12345", "with a decimal point", "real without a point")
      call expect_real_error("  1.0  2.0 ", "found blanks inside", "two numbers in one field")
      call expect_real_error(" 1.4OOOE-01", "expected a real number (E11.4)", "letter O")
      call expect_real_error("    12-05  ", "expected a real number (E11.4)", "no point, bare exponent")
      call expect_real_error(" 1.0"//achar(9)//"      ", "no tab", "tab inside")
      call expect_real_error("1.0E+999999", "finite", "overflow")
      call expect_real_error("  1.8E+308 ", "finite", "overflow just above huge")
      call expect_real("  1.7E+308 ", 1.7e308_wp, "large but finite")
      call expect_real("  1.0E-999 ", 0.0_wp, "underflow reads as zero (as Python's float)")
      call expect_real_error("     .     ", "expected a real number", "bare point")
   end subroutine test_blank_and_bad_numbers

   subroutine test_integers()
      integer :: i
      logical :: blank
      character(len=:), allocatable :: msg
      call parse_int_field("  2500", i, blank, msg)
      call check(i == 2500 .and. len(msg) == 0 .and. .not. blank, "integer 2500")
      call parse_int_field("    -2", i, blank, msg)
      call check(i == -2 .and. len(msg) == 0, "negative integer")
      call parse_int_field("      ", i, blank, msg)
      call check(blank .and. len(msg) == 0, "blank integer field is blank")
      call parse_int_field("  25.0", i, blank, msg)
      call check(index(msg, "expected an integer (I6, right-aligned)") > 0, "real text in an integer field")
      call parse_int_field("  1  0", i, blank, msg)
      call check(index(msg, "found blanks inside") > 0, "free-format integers")
   end subroutine test_integers

   subroutine test_labels()
      logical :: labelled
      character(len=:), allocatable :: label, msg
      integer :: offset
      call split_label("Rec 7.2.1    1.30073E-01", labelled, label, offset, msg)
      call check(labelled .and. label == "7.2.1" .and. offset == 12 .and. len(msg) == 0, "labelled line")
      call split_label("rec 5A      1.0", labelled, label, offset, msg)
      call check(labelled .and. label == "5A" .and. offset == 12, "lower-case label")
      call split_label("     1     0", labelled, label, offset, msg)
      call check(.not. labelled .and. offset == 0, "unlabelled line")
      call split_label("Rec 2.1 5.0E-02 1.0", labelled, label, offset, msg)
      call check(labelled .and. label == "2.1" .and. index(msg, "inside the label zone") > 0, &
                 "data inside the label zone")
      call split_label("Rec", labelled, label, offset, msg)
      call check(.not. labelled, "'Rec' alone is not a label")
   end subroutine test_labels

   subroutine test_show_real()
      call check(show_real(0.146292_wp) == "0.146292", "G6 fixed: "//show_real(0.146292_wp))
      call check(show_real(1.0e10_wp) == "1E+10", "G6 exponent: "//show_real(1.0e10_wp))
      call check(show_real(-9.81_wp) == "-9.81", "G6 negative: "//show_real(-9.81_wp))
      call check(show_real(1.5e-5_wp) == "1.5E-05", "G6 small: "//show_real(1.5e-5_wp))
      call check(show_real(123456.0_wp) == "123456", "G6 6 digits: "//show_real(123456.0_wp))
      call check(show_real(1234567.0_wp) == "1.23457E+06", "G6 7 digits: "//show_real(1234567.0_wp))
      call check(show_real(0.0_wp) == "0", "G6 zero: "//show_real(0.0_wp))
   end subroutine test_show_real

   subroutine test_ball_deck_accessors()
      type(deck_t) :: deck
      type(error_type), allocatable :: error
      real(wp) :: x
      integer :: i
      character(len=:), allocatable :: s

      call read_deck(decks//"/appendix_c_ball.inp", deck, error)
      call check(.not. allocated(error), "ball deck reads")
      if (allocated(error)) then
         write (*, "(a)") error%message
         return
      end if
      call check(deck%n_records == 25, "ball deck has 25 records")
      call check(deck_has(deck, "5A") .and. .not. deck_has(deck, "5B"), "ball deck: 5A, no 5B")
      call check(deck_count(deck, "7.2") == 2 .and. deck_count(deck, "7.2.n") == 2, "two guide lands")
      call check(deck_count(deck, "7.2.2") == 1 .and. deck_count(deck, "8.1") == 0, "concrete counts")
      call deck_get_real(deck, "5A", "pitch_diameter", x, error)
      call check(.not. allocated(error) .and. x == 0.14_wp, "pitch diameter 0.14 m")
      call deck_get_real(deck, "9.5.1", "cage_center_z", x, error)
      call check(.not. allocated(error) .and. x == -6.0e-4_wp, "run-together value read")
      call deck_get_real(deck, "7.2", "guide_land_position", x, error, occurrence=2)
      call check(.not. allocated(error) .and. x == 1.81204e-2_wp, "second guide land position")
      call deck_get_int(deck, "7.0", "guide_type[2]", i, error)
      call check(.not. allocated(error) .and. i == 2, "repeated field guide_type[2]")
      call deck_get_int(deck, "1", "n_steps", i, error)
      call check(.not. allocated(error) .and. i == 2500, "n_steps 2500")
      call deck_get_text(deck, "3.1", "run_id", s, error)
      call check(.not. allocated(error) .and. s == "Ball Bearing Test Case kGeoMod=100", "run id")
      call deck_get_real(deck, "2.4", "rec2_4_flag_4", x, error)
      call check(allocated(error), "integer field read as real is an error")
      call deck_get_int(deck, "2.4", "rec2_4_flag_4", i, error)
      call check(.not. allocated(error) .and. i == 0, "blank optional field takes default 0")
      call deck_get_real(deck, "5B", "roller_diameter", x, error)
      call check(allocated(error), "absent record is an error")
      if (allocated(error)) then
         call check(error%stat == ADORE_ENGINE_ERROR, "absent record: engine error")
         call check(index(error%message, "Rec 5B field roller_diameter") > 0, "error names rid and field")
      end if
      call deck_get_real(deck, "5A", "no_such_field", x, error)
      call check(allocated(error), "absent field is an error")
      if (allocated(error)) call check(index(error%message, "Rec 5A field no_such_field") > 0, &
                                       "error names the field")
      call deck_get_real(deck, "7.2", "guide_land_width", x, error, occurrence=3)
      call check(allocated(error), "occurrence beyond the count is an error")
   end subroutine test_ball_deck_accessors

   subroutine test_roller_deck_accessors()
      type(deck_t) :: deck
      type(error_type), allocatable :: error
      real(wp) :: x
      integer :: i

      call read_deck(decks//"/appendix_d_roller.inp", deck, error)
      call check(.not. allocated(error), "roller deck reads")
      if (allocated(error)) then
         write (*, "(a)") error%message
         return
      end if
      call check(deck_has(deck, "5B") .and. deck_has(deck, "5B.1") .and. deck_has(deck, "8.1"), &
                 "roller deck: 5B, 5B.1, 8.1")
      call check(.not. deck_has(deck, "10.3") .and. deck_has(deck, "10.1B"), "roller: 10.1B, no 10.3")
      call deck_get_int(deck, "3.2", "bearing_type", i, error)
      call check(.not. allocated(error) .and. i == 2, "bearing type 2")
      call deck_get_real(deck, "5B", "outer_race_crown_radius", x, error)
      call check(.not. allocated(error) .and. x == 1.0e10_wp, "crown radius 1E10")
      call deck_get_real(deck, "8.1", "elastic_modulus", x, error)
      call check(.not. allocated(error) .and. x == 3.1e11_wp, "ceramic modulus")
   end subroutine test_roller_deck_accessors

   subroutine test_bad_deck_message()
      type(deck_t) :: deck
      type(error_type), allocatable :: error
      character(len=*), parameter :: path = "test_deck_reader_bad.inp"
      integer :: unit

      open (newunit=unit, file=path, status="replace", action="write")
      write (unit, "(a)") "Rec 1            9     0     0     0     0     1   500     1     0     0     1  2500     0     5"
      write (unit, "(a)") "Rec 2.1      5.0000E-02 5.0000E-03 3.0OOOE-01"
      close (unit)
      call read_deck(path, deck, error)
      call check(allocated(error), "bad deck is rejected")
      if (allocated(error)) then
         call check(error%stat == ADORE_INPUT_ERROR, "bad deck: input error")
         call check(index(error%message, path//":1:18  Rec 1  field mode = 9: expected [-2, 2]") > 0, &
                    "range problem reported: "//error%message)
         call check(index(error%message, path//":2:36  Rec 2.1  field step_max = '3.0OOOE-01': "// &
                          "expected a real number (E11.4)") > 0, "type problem reported")
         call check(index(error%message, "truncated file: it ends after line 2, expected Rec 2.4") > 0, &
                    "truncation reported")
         call check(index(error%message, new_line("a")//"    "//repeat(" ", 17)//"^") > 0, "caret line")
      end if
      open (newunit=unit, file=path, status="old")
      close (unit, status="delete")
   end subroutine test_bad_deck_message

end program test_deck_reader
