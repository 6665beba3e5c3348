!> Print writer, part 1: the input listing and the ADORE 5.0 banner.
!>
!> Writers only format: they take what to print and a unit, and compute nothing.
!> Layout: docs/print-layout.md (transcribed from the report's Appendix C/D output).
module adore_output_banner
   use adore_deck_text, only: deck_text_t
   implicit none
   private

   public :: write_listing, write_banner

contains

   !> "Listing of input data records": every deck line, verbatim (ADORE prints the
   !> deck before its banner, report Appendix C/D).
   subroutine write_listing(unit, text)
      integer, intent(in) :: unit
      type(deck_text_t), intent(in) :: text
      integer :: i

      write (unit, "(a)") "Input from optional user subroutines"
      write (unit, "(a)") ""
      write (unit, "(a)") "Listing of input data records"
      write (unit, "(a)") ""
      do i = 1, size(text%lines)
         write (unit, "(a)") text%lines(i)%s
      end do
      write (unit, "(a)") ""
   end subroutine write_listing

   !> The program banner as the report prints it above the input echo.
   subroutine write_banner(unit)
      integer, intent(in) :: unit

      write (unit, "(a)") "ADVANCED DYNAMICS OF ROLLING ELEMENTS"
      write (unit, "(a)") "A Real Time Simulation of Rolling Bearing Performance"
      write (unit, "(a)") ""
      write (unit, "(a)") "[Version (ADORE 5.0)]"
      write (unit, "(a)") ""
   end subroutine write_banner

end module adore_output_banner
