!> Flat f2py wrapper of the deck reader (test-only module pyadore._probes): the deck's
!> field table as the Fortran reader sees it.

!> Read the deck `deck_path` with the engine's reader (adore_deck_parser::read_deck) and
!> write its field table to `table_path`: one line per field, in deck order,
!>     rid <TAB> occurrence <TAB> name <TAB> kind <TAB> value
!> with occurrence 0-based among records of the same type (as pyadore.deck.field_table),
!> kind int/real/text and the value as i0, es24.16 (17 significant digits: the exact
!> double) or the text itself.  Values in the schema's SI units.
subroutine adore_deck_table(deck_path, table_path, status, message)
   use adore_core_error, only: error_type, ADORE_OK, ADORE_INPUT_ERROR
   use adore_api_status, only: set_error
   use adore_core_strings, only: itoa
   use adore_deck_deck_type, only: deck_t, FIELD_INT, FIELD_REAL
   use adore_deck_parser, only: read_deck
   implicit none
   character(len=*), intent(in) :: deck_path    !< deck file to read
   character(len=*), intent(in) :: table_path   !< text file to write the field table to
   integer, intent(out) :: status               !< 0 ok, 1 input error, 2 engine failure
   character(len=16384), intent(out) :: message !< error message, blank on success

   type(deck_t) :: deck
   type(error_type), allocatable :: error
   character(len=256) :: iomsg
   character(len=40) :: buf
   integer :: unit, stat, r, f
   character(len=1), parameter :: TAB = achar(9)
   character(len=4), parameter :: KIND_NAME(3) = ["int ", "real", "text"]

   status = ADORE_OK
   message = ""
   call read_deck(deck_path, deck, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   open (newunit=unit, file=table_path, status="replace", action="write", form="formatted", &
         iostat=stat, iomsg=iomsg)
   if (stat /= 0) then
      status = ADORE_INPUT_ERROR
      message = trim(table_path)//": cannot write the field table: "//trim(iomsg)
      return
   end if
   do r = 1, deck%n_records
      do f = 1, deck%records(r)%n_fields
         associate (rec => deck%records(r), fv => deck%records(r)%fields(f))
            select case (fv%kind)
            case (FIELD_INT)
               write (buf, "(i0)") fv%int_value
            case (FIELD_REAL)
               write (buf, "(es24.16)") fv%real_value
            case default
               buf = ""
            end select
            if (fv%kind == FIELD_INT .or. fv%kind == FIELD_REAL) then
               write (unit, "(a)") rec%rid//TAB//itoa(rec%occurrence - 1)//TAB//fv%name//TAB// &
                  trim(KIND_NAME(fv%kind))//TAB//trim(adjustl(buf))
            else
               write (unit, "(a)") rec%rid//TAB//itoa(rec%occurrence - 1)//TAB//fv%name//TAB// &
                  trim(KIND_NAME(fv%kind))//TAB//fv%text_value
            end if
         end associate
      end do
   end do
   close (unit)
end subroutine adore_deck_table
