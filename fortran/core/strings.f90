!> Text helpers shared by the deck reader, the error messages and the f2py wrappers.
!>
!> Rule for this engine: no function returns a deferred-length `character(len=:),
!> allocatable` result.  gfortran 12 (Debian's compiler, the one CI uses) keeps the
!> length of such a result temporary in *static* storage at every call site (see the
!> `static integer(kind=8) slen.N` lines of `-fdump-tree-original`), even under
!> `-frecursive`; two Python threads reading decks at once then overwrote each other's
!> lengths and a field such as '4.5000E-02' came back "blank".  Every function here
!> declares its result length by a specification expression instead (computed by the
!> caller on its own stack); tests/test_engine_reentrancy.py checks the whole engine.
!> Pure procedures, no state.
module adore_core_strings
   implicit none
   private

   public :: is_space, is_blank, lstrip_count, strip, rstrip, itoa, quoted
   public :: join_words, trim_zeros, strip_inner, replaced, upper, lower
   public :: first_non_ascii, utf8_chars, utf8_char_start, utf8_code_point

contains

   !> True for the characters Python's str.strip() removes here (blank, TAB, LF, VT, FF, CR).
   elemental logical function is_space(c)
      character, intent(in) :: c
      is_space = c == " " .or. (iachar(c) >= 9 .and. iachar(c) <= 13)
   end function is_space

   !> True when `s` holds only white space (or nothing).
   pure logical function is_blank(s)
      character(len=*), intent(in) :: s
      is_blank = lstrip_count(s) == len(s)
   end function is_blank

   !> Number of leading white-space characters of `s`.
   pure integer function lstrip_count(s)
      character(len=*), intent(in) :: s
      integer :: i
      lstrip_count = len(s)
      do i = 1, len(s)
         if (.not. is_space(s(i:i))) then
            lstrip_count = i - 1
            return
         end if
      end do
   end function lstrip_count

   !> Position of the last non-white-space character of `s` (0 when blank).
   pure integer function last_nonspace(s)
      character(len=*), intent(in) :: s
      integer :: j
      do j = len(s), 1, -1
         if (.not. is_space(s(j:j))) exit
      end do
      last_nonspace = j
   end function last_nonspace

   !> `s` without leading and trailing white space (Python str.strip()).
   pure function strip(s) result(t)
      character(len=*), intent(in) :: s
      character(len=max(0, last_nonspace(s) - lstrip_count(s))) :: t
      t = s(lstrip_count(s) + 1:last_nonspace(s))
   end function strip

   !> `s` without trailing white space (Python str.rstrip()).
   pure function rstrip(s) result(t)
      character(len=*), intent(in) :: s
      character(len=last_nonspace(s)) :: t
      t = s(1:len(t))
   end function rstrip

   !> Number of characters of `i` written as I0.
   pure integer function itoa_len(i)
      integer, intent(in) :: i
      character(len=16) :: buf
      write (buf, "(i0)") i
      itoa_len = len_trim(buf)
   end function itoa_len

   !> Integer to left-aligned text (I0).
   pure function itoa(i) result(s)
      integer, intent(in) :: i
      character(len=itoa_len(i)) :: s
      write (s, "(i0)") i
   end function itoa

   !> Python repr() of a string: single quotes (double quotes if it holds a single quote).
   pure function quoted(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s) + 2) :: t
      if (index(s, "'") > 0 .and. index(s, '"') == 0) then
         t = '"'//s//'"'
      else
         t = "'"//s//"'"
      end if
   end function quoted

   !> Length of join_words(s).
   pure integer function join_words_len(s)
      character(len=*), intent(in) :: s
      integer :: i
      logical :: in_word
      join_words_len = 0
      in_word = .false.
      do i = 1, len(s)
         if (is_space(s(i:i))) then
            in_word = .false.
         else
            if (.not. in_word .and. join_words_len > 0) join_words_len = join_words_len + 1
            join_words_len = join_words_len + 1
            in_word = .true.
         end if
      end do
   end function join_words_len

   !> The words of `s` joined by single blanks (Python ' '.join(s.split())).
   pure function join_words(s) result(t)
      character(len=*), intent(in) :: s
      character(len=join_words_len(s)) :: t
      integer :: i, n
      logical :: in_word
      n = 0
      in_word = .false.
      do i = 1, len(s)
         if (is_space(s(i:i))) then
            in_word = .false.
         else
            if (.not. in_word .and. n > 0) then
               n = n + 1
               t(n:n) = " "
            end if
            n = n + 1
            t(n:n) = s(i:i)
            in_word = .true.
         end if
      end do
   end function join_words

   !> Length of trim_zeros(s).
   pure integer function trim_zeros_len(s)
      character(len=*), intent(in) :: s
      integer :: j
      j = len(s)
      if (index(s, ".") > 0) then
         do while (s(j:j) == "0")
            j = j - 1
         end do
         if (s(j:j) == ".") j = j - 1
      end if
      trim_zeros_len = j
   end function trim_zeros_len

   !> Remove trailing zeros after a decimal point, and the point itself if bare.
   pure function trim_zeros(s) result(t)
      character(len=*), intent(in) :: s
      character(len=trim_zeros_len(s)) :: t
      t = s(1:len(t))
   end function trim_zeros

   !> Number of blanks (" ") in `s`.
   pure integer function count_blanks(s)
      character(len=*), intent(in) :: s
      integer :: i
      count_blanks = 0
      do i = 1, len(s)
         if (s(i:i) == " ") count_blanks = count_blanks + 1
      end do
   end function count_blanks

   !> `s` with blanks removed.
   pure function strip_inner(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s) - count_blanks(s)) :: t
      integer :: i, n
      n = 0
      do i = 1, len(s)
         if (s(i:i) /= " ") then
            n = n + 1
            t(n:n) = s(i:i)
         end if
      end do
   end function strip_inner

   !> Copy of `s` with every character `from` replaced by `to` (e.g. '_' by '-' in an option
   !> name).
   pure function replaced(s, from, to) result(t)
      character(len=*), intent(in) :: s
      character(len=1), intent(in) :: from, to
      character(len=len(s)) :: t
      integer :: i
      t = s
      do i = 1, len(s)
         if (s(i:i) == from) t(i:i) = to
      end do
   end function replaced

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

   !> Lower-case ASCII copy of `s`.
   pure function lower(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i
      t = s
      do i = 1, len(s)
         if (s(i:i) >= "A" .and. s(i:i) <= "Z") t(i:i) = achar(iachar(s(i:i)) + 32)
      end do
   end function lower

   !> Byte index of the first non-ASCII byte of `s` at or after byte `from`, 0 if none.
   pure integer function first_non_ascii(s, from)
      character(len=*), intent(in) :: s
      integer, intent(in) :: from
      integer :: i
      first_non_ascii = 0
      do i = max(from, 1), len(s)
         if (iachar(s(i:i)) > 127) then
            first_non_ascii = i
            return
         end if
      end do
   end function first_non_ascii

   !> Number of characters of the UTF-8 text `s` (bytes that are not continuation bytes),
   !> the length Python's len() gives.
   pure integer function utf8_chars(s)
      character(len=*), intent(in) :: s
      integer :: i
      utf8_chars = 0
      do i = 1, len(s)
         if (iand(iachar(s(i:i)), 192) /= 128) utf8_chars = utf8_chars + 1
      end do
   end function utf8_chars

   !> Byte index where character `k` (1-based) of the UTF-8 text `s` starts; len(s) + 1
   !> when `s` has fewer than k characters.
   pure integer function utf8_char_start(s, k)
      character(len=*), intent(in) :: s
      integer, intent(in) :: k
      integer :: i, n
      n = 0
      do i = 1, len(s)
         if (iand(iachar(s(i:i)), 192) /= 128) then
            n = n + 1
            if (n == k) then
               utf8_char_start = i
               return
            end if
         end if
      end do
      utf8_char_start = len(s) + 1
   end function utf8_char_start

   !> Unicode code point of the UTF-8 character starting at byte `i` of `s` (valid UTF-8,
   !> checked when the deck was read); `nbytes` its length in bytes.
   pure subroutine utf8_code_point(s, i, code, nbytes)
      character(len=*), intent(in) :: s
      integer, intent(in) :: i
      integer, intent(out) :: code, nbytes
      integer :: b, k
      b = iachar(s(i:i))
      if (b < 128) then
         nbytes = 1
         code = b
      else if (b >= 240) then
         nbytes = 4
         code = iand(b, 7)
      else if (b >= 224) then
         nbytes = 3
         code = iand(b, 15)
      else
         nbytes = 2
         code = iand(b, 31)
      end if
      nbytes = min(nbytes, len(s) - i + 1)
      do k = i + 1, i + nbytes - 1
         code = ior(ishft(code, 6), iand(iachar(s(k:k)), 63))
      end do
   end subroutine utf8_code_point

end module adore_core_strings
