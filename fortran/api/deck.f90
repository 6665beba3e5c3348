!> Flat f2py wrapper of the deck reader (module pyadore._engine).

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

!> The engine's cross-field checks of a deck (adore_model_checks::cross_field_checks) on
!> values given by the caller: values(k) is the first field named CHECK_FIELDS(k) in the
!> deck (schema SI units, integers as reals), have(k) /= 0 when it is present and readable.
!> Returns the n violated relations (at most nmax) in rule order: fields(i) the 1-based
!> index of the field each is reported at, messages the n messages, one a line.
subroutine adore_deck_cross_checks(nfield, values, have, nmax, n, fields, messages, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_ENGINE_ERROR
   use adore_core_strings, only: itoa
   use adore_model_checks, only: cross_field_checks, check_problem_t, N_CHECK_FIELDS
   implicit none
   integer, intent(in) :: nfield                      !< must be N_CHECK_FIELDS
   real(wp), intent(in) :: values(nfield)
   integer, intent(in) :: have(nfield)
   integer, intent(in) :: nmax                        !< room in fields
   integer, intent(out) :: n
   integer, intent(out) :: fields(nmax)
   character(len=16384), intent(out) :: messages
   integer, intent(out) :: status                     !< 0 ok, 2 engine failure (wrong sizes)
   character(len=2048), intent(out) :: message

   type(check_problem_t), allocatable :: problems(:)
   character(len=:), allocatable :: text
   integer :: k

   status = ADORE_OK
   message = ""
   messages = ""
   fields = 0
   n = 0
   if (nfield /= N_CHECK_FIELDS) then
      status = ADORE_ENGINE_ERROR
      message = "cross-field checks: "//itoa(nfield)//" values given, the rules read "//itoa(N_CHECK_FIELDS)
      return
   end if
   call cross_field_checks(values, have /= 0, problems)
   if (size(problems) > nmax) then
      status = ADORE_ENGINE_ERROR
      message = "cross-field checks: "//itoa(size(problems))//" problems, room for "//itoa(nmax)
      return
   end if
   n = size(problems)
   text = ""
   do k = 1, n
      fields(k) = problems(k)%field
      if (k > 1) text = text//new_line("a")
      text = text//problems(k)%message
   end do
   if (len(text) > len(messages)) then
      status = ADORE_ENGINE_ERROR
      message = "cross-field checks: the messages do not fit the buffer"
      return
   end if
   messages = text
end subroutine adore_deck_cross_checks

!> The names of the fields the cross-field checks read (what = 1: CHECK_FIELDS, in the
!> order of adore_deck_cross_checks' values) or the rules they apply (what = 2:
!> CHECK_RULES, for the documentation), one a line.
subroutine adore_deck_cross_check_names(what, text)
   use adore_model_checks, only: CHECK_FIELDS, CHECK_RULES
   implicit none
   integer, intent(in) :: what
   character(len=8192), intent(out) :: text
   character(len=:), allocatable :: s
   integer :: k

   s = ""
   if (what == 1) then
      do k = 1, size(CHECK_FIELDS)
         s = s//trim(CHECK_FIELDS(k))//new_line("a")
      end do
   else
      do k = 1, size(CHECK_RULES)
         s = s//trim(CHECK_RULES(k))//new_line("a")
      end do
   end if
   text = s
end subroutine adore_deck_cross_check_names
