!> Range and choice checks of every readable number of a parsed deck, against the bounds
!> and choices of the generated schema table (adore_deck_schema), in pyadore/deck's words.
module adore_deck_ranges
   use adore_core_kinds, only: wp
   use adore_deck_text, only: deck_text_t
   use adore_deck_schema, only: KIND_INT, KIND_TEXT, FLD_HAS_LO, FLD_LO, FLD_LO_OPEN, FLD_HAS_HI, FLD_HI, &
                                FLD_HI_OPEN, FLD_FIRST_CHOICE, FLD_N_CHOICES, CHOICES, FLD_RANGE_TEXT, &
                                FLD_MEANING
   use adore_deck_deck_type, only: deck_t
   use adore_deck_problems, only: problem_list_t, add_problem
   use adore_deck_tokenizer, only: is_blank, lstrip_count, show_real, itoa
   implicit none
   private

   public :: check_ranges

contains

   !> Range and choice checks of every readable number (pyadore/deck/validate.py _ranges).
   subroutine check_ranges(problems, text, deck)
      type(problem_list_t), intent(inout) :: problems
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
               call add_problem(problems, text, fv%line, fv%col + lead, record=deck%records(r)%rid, &
                                field=fv%name, shown=shown, kind="range", &
                                message="expected "//trim(FLD_RANGE_TEXT(f))//" ("//trim(FLD_MEANING(f))//")")
            end associate
         end do
      end do
   end subroutine check_ranges

end module adore_deck_ranges
