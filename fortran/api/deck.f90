!> Flat f2py wrappers of the engine's cross-field deck checks (module pyadore._engine;
!> pyadore validate, pyadore.deck.docgen).

!> The engine's cross-field checks of a deck (adore_model_checks::cross_field_checks) on
!> values given by the caller: values(k) is the first field named CHECK_FIELDS(k) in the
!> deck (schema SI units, integers as reals), have(k) /= 0 when it is present and readable.
!> Returns the n violated relations (at most nmax) in rule order: fields(i) the 1-based
!> index of the field each is reported at, warning(i) 1 for a warning (a legal but
!> implausible value; the run goes on) and 0 for an error, messages the n messages, one a line.
subroutine adore_deck_cross_checks(nfield, values, have, nmax, n, fields, warning, messages, status, message)
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
   integer, intent(out) :: warning(nmax)
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
   warning = 0
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
      warning(k) = merge(1, 0, problems(k)%warning)
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
