!> Fixed-field tokenising of deck lines, exactly as pyadore/deck/tokenizer.py does it.
!>
!> A line is cut into its optional `Rec <id>` label (columns 1-12) and fixed-width
!> fields (I6 integers, 11-column reals, A36 text).  Numbers are converted as Fortran
!> input editing would, with the same deliberate refusals as the Python reader:
!> run-together numbers (`0.0000E+00-6.0000E-04`) split by the fixed widths; `D`
!> exponents and sign-started exponents (`1.0-05`) are accepted; a blank field is
!> reported as blank (the caller applies the schema default); refused are reals without
!> a decimal point, two numbers in one field (`1 0`), tabs and non-finite values.
!> Pure procedures, no state.
module adore_deck_tokenizer
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use adore_core_kinds, only: wp
   use adore_deck_schema, only: LABEL_WIDTH, INT_WIDTH, REAL_WIDTH
   use adore_core_strings, only: is_space, is_blank, lstrip_count, strip, itoa, join_words, &
                                 trim_zeros, strip_inner, lower
   implicit none
   private

   public :: split_label, cut_field, parse_int_field, parse_real_field
   public :: is_blank, strip, lstrip_count, show_real, itoa

contains

   !> Split off the optional label: a line whose first four characters are `Rec `
   !> (any case) is labelled; its id is the first word in columns 5-12 and its data
   !> start after column 12 (`offset` = 12, 0-based); otherwise `offset` = 0.
   !> `message` describes stray text in the label zone (empty when there is none).
   pure subroutine split_label(line, labelled, label, offset, message)
      character(len=*), intent(in) :: line
      logical, intent(out) :: labelled
      character(len=:), allocatable, intent(out) :: label, message
      integer, intent(out) :: offset

      character(len=:), allocatable :: zone, rest
      integer :: i, j

      labelled = .false.
      label = ""
      message = ""
      offset = 0
      if (len(line) < 4) return
      if (lower(line(1:4)) /= "rec ") return
      labelled = .true.
      offset = LABEL_WIDTH
      zone = line(5:min(len(line), LABEL_WIDTH))
      i = lstrip_count(zone) + 1
      if (i > len(zone)) then
         message = "label 'Rec' without a record id"
         return
      end if
      j = i
      do while (j <= len(zone))
         if (is_space(zone(j:j))) exit
         j = j + 1
      end do
      label = zone(i:j - 1)
      rest = join_words(zone(j:))
      if (len(rest) > 0) then
         message = "text '"//rest//"' inside the label zone (columns 1-"//itoa(LABEL_WIDTH)// &
                   "); data fields start in column "//itoa(LABEL_WIDTH + 1)
      end if
   end subroutine split_label

   !> The raw text of the field of `width` columns starting after 0-based `pos`
   !> (shorter or empty past the end of the line, as a Fortran READ pads short records).
   pure function cut_field(line, pos, width) result(t)
      character(len=*), intent(in) :: line
      integer, intent(in) :: pos, width
      character(len=max(0, min(pos + width, len(line)) - min(pos + 1, len(line) + 1) + 1)) :: t
      t = line(min(pos + 1, len(line) + 1):min(pos + width, len(line)))
   end function cut_field

   !> Common checks of a numeric field: blank, tab, blanks inside.  `ok` false when
   !> the caller must stop (blank or message set); `s` is the stripped text.
   pure subroutine numeric_prelude(text, width, s, blank, message, ok)
      character(len=*), intent(in) :: text
      integer, intent(in) :: width
      character(len=:), allocatable, intent(out) :: s, message
      logical, intent(out) :: blank, ok
      integer :: i

      message = ""
      s = strip(text)
      blank = len(s) == 0
      ok = .false.
      if (blank) return
      if (index(text, achar(9)) > 0) then
         message = "expected no tab characters (fields are fixed columns)"
         return
      end if
      do i = 1, len(s)
         if (is_space(s(i:i))) then
            message = "expected one number in the "//itoa(width)//"-column field, found blanks "// &
                      "inside (free-format spacing? Fortran would ignore the blanks)"
            return
         end if
      end do
      ok = .true.
   end subroutine numeric_prelude

   !> Convert an I6 field.  `blank`: the field is empty (value 0, no message; the caller
   !> applies the default).  `message`: "expected ..." when the text is not an integer.
   pure subroutine parse_int_field(text, value, blank, message)
      character(len=*), intent(in) :: text
      integer, intent(out) :: value
      logical, intent(out) :: blank
      character(len=:), allocatable, intent(out) :: message

      character(len=:), allocatable :: s
      logical :: ok
      integer :: i, stat

      value = 0
      call numeric_prelude(text, INT_WIDTH, s, blank, message, ok)
      if (.not. ok) return
      i = 1
      if (s(1:1) == "+" .or. s(1:1) == "-") i = 2
      if (i > len(s) .or. verify(s(i:), "0123456789") /= 0) then
         message = "expected an integer (I"//itoa(INT_WIDTH)//", right-aligned)"
         return
      end if
      read (s, *, iostat=stat) value
      if (stat /= 0) message = "expected an integer (I"//itoa(INT_WIDTH)//", right-aligned)"
   end subroutine parse_int_field

   !> Convert an 11-column real field: `[+-]digits.digits` with an optional exponent
   !> `E`/`D` (`1.0E-05`, `1.0D-05`) or a bare signed exponent (`1.0-05`).  `blank` and
   !> `message` as for parse_int_field.
   subroutine parse_real_field(text, value, blank, message)
      character(len=*), intent(in) :: text
      real(wp), intent(out) :: value
      logical, intent(out) :: blank
      character(len=:), allocatable, intent(out) :: message

      character(len=:), allocatable :: s, mant, expo, buf
      logical :: ok
      integer :: i, n, ndig_before, ndig_after, stat, ev, order
      logical :: point, bare

      value = 0.0_wp
      call numeric_prelude(text, REAL_WIDTH, s, blank, message, ok)
      if (.not. ok) return
      n = len(s)
      i = 1
      if (s(1:1) == "+" .or. s(1:1) == "-") i = 2
      ndig_before = count_digits(s, i)
      i = i + ndig_before
      point = .false.
      ndig_after = 0
      if (i <= n) then
         if (s(i:i) == ".") then
            point = .true.
            i = i + 1
            ndig_after = count_digits(s, i)
            i = i + ndig_after
         end if
      end if
      mant = s(1:i - 1)
      expo = ""
      bare = .false.
      ok = ndig_before + ndig_after > 0
      if (ok .and. i <= n) then
         ! exponent: [EeDd][+-]?digits or [+-]digits
         if (index("EeDd", s(i:i)) > 0) then
            i = i + 1
            if (i <= n) then
               if (s(i:i) == "+" .or. s(i:i) == "-") i = i + 1
            end if
         else if (s(i:i) == "+" .or. s(i:i) == "-") then
            bare = .true.
            i = i + 1
         else
            ok = .false.
         end if
         if (ok) then
            ok = count_digits(s, i) > 0 .and. i + count_digits(s, i) == n + 1
            expo = "E"//s(len(mant) + 2:n)
            if (index("+-", s(len(mant) + 1:len(mant) + 1)) > 0) expo = "E"//s(len(mant) + 1:n)
         end if
      end if
      if (ok .and. point) then
         ! Refuse overflow before converting: reading it would raise IEEE overflow, which
         ! debug builds trap.  `order` is floor(log10(|value|)) from the digits.
         ev = 0
         if (len(expo) > 1) then
            read (expo(2:), *, iostat=stat) ev
            if (stat /= 0) then
               message = "expected a finite real number"
               return
            end if
         end if
         order = decimal_order(mant) + ev
         if (order >= 300) then
            stat = 1
            if (order < 309) then
               buf = mant//"E"//itoa(ev - 20)
               read (buf, *, iostat=stat) value
            end if
            if (stat /= 0 .or. abs(value) > huge(value)/1.0e20_wp) then
               value = 0.0_wp
               message = "expected a finite real number"
               return
            end if
         end if
         buf = mant//expo
         read (buf, *, iostat=stat) value
         if (stat /= 0) then
            message = "expected a finite real number"
         else if (.not. ieee_is_finite(value)) then
            message = "expected a finite real number"
         end if
         return
      end if
      if (ok .and. .not. point .and. .not. bare) then
         message = "expected a real with a decimal point (Fortran E"//itoa(REAL_WIDTH)// &
                   ".4 would read '"//s//"' with an implied decimal point)"
         return
      end if
      message = "expected a real number (E"//itoa(REAL_WIDTH)//".4)"
   end subroutine parse_real_field

   !> floor(log10(|x|)) of the decimal mantissa text `mant` ("12.5" -> 1, "0.05" -> -2);
   !> a very negative number for zero.
   pure integer function decimal_order(mant)
      character(len=*), intent(in) :: mant
      integer :: p, k
      p = index(mant, ".")
      if (p == 0) p = len(mant) + 1
      k = scan(mant, "123456789")
      if (k == 0) then
         decimal_order = -100000
      else if (k < p) then
         decimal_order = p - k - 1
      else
         decimal_order = p - k
      end if
   end function decimal_order

   !> Number of consecutive decimal digits in `s` starting at position `i`.
   pure integer function count_digits(s, i)
      character(len=*), intent(in) :: s
      integer, intent(in) :: i
      integer :: j
      count_digits = 0
      j = i
      do while (j <= len(s))
         if (s(j:j) < "0" .or. s(j:j) > "9") exit
         count_digits = count_digits + 1
         j = j + 1
      end do
   end function count_digits

   !> A real as Python formats it with "{:.6G}" (6 significant digits, trailing zeros
   !> removed; exponent form below 1E-4 and from 1E6 up): 0.146292, 1E+10, -9.81.
   pure function show_real(x) result(s)
      real(wp), intent(in) :: x
      character(len=g6_len(x)) :: s
      character(len=:), allocatable :: t
      call g6_text(x, t)
      s = t
   end function show_real

   !> Length of show_real(x).
   pure integer function g6_len(x)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: t
      call g6_text(x, t)
      g6_len = len(t)
   end function g6_len

   !> show_real's text of `x` into `s`.
   pure subroutine g6_text(x, s)
      real(wp), intent(in) :: x
      character(len=:), allocatable, intent(out) :: s
      character(len=32) :: buf
      character(len=:), allocatable :: digits, sign
      integer :: e, stat, p

      if (x == 0.0_wp) then
         s = merge("-0", " 0", sign_bit(x))
         s = strip(s)
         return
      end if
      if (.not. ieee_is_finite(x)) then
         s = "INF"
         if (x /= x) s = "NAN"
         return
      end if
      write (buf, "(es13.5e3)") abs(x)          ! d.ddddde+xxx, rounded to 6 digits
      buf = adjustl(buf)
      digits = buf(1:1)//buf(3:7)
      read (buf(9:12), *, iostat=stat) e
      sign = ""
      if (x < 0.0_wp) sign = "-"
      if (e >= -4 .and. e < 6) then
         if (e >= 0) then
            s = digits(1:e + 1)//"."//digits(e + 2:)
         else
            s = "0."//repeat("0", -e - 1)//digits
         end if
         s = trim_zeros(s)
      else
         s = trim_zeros(digits(1:1)//"."//digits(2:))
         p = abs(e)
         s = s//"E"//merge("+", "-", e >= 0)//merge("0", " ", p < 10)
         s = strip_inner(s)//itoa(p)
      end if
      s = sign//s
   end subroutine g6_text

   !> Sign bit of x (for -0.0).
   pure logical function sign_bit(x)
      real(wp), intent(in) :: x
      sign_bit = sign(1.0_wp, x) < 0.0_wp
   end function sign_bit

end module adore_deck_tokenizer
