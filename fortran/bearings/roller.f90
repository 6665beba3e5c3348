!> The cylindrical roller bearing as a bearing kind (adore_bearings_system): its quasi-static
!> start and step-0 print.  Its time integration is issue #26 [Roller dynamics]: until it
!> lands the kind keeps the base type's "no time integration" (dynamic_steps 0), the print
!> ends after step 0 and the run note says so.  No module state.
module adore_bearings_roller
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   use adore_model_condition, only: condition_of
   use adore_model_run_options, only: STEPS_FROM_DECK
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_bearings_system, only: bearing_system_t
   use adore_output_step_report, only: write_roller_step0
   implicit none
   private

   public :: roller_kind_t

   !> What a roller run says when time steps are asked for.
   character(len=*), parameter :: NO_DYNAMICS = "time integration of roller bearings is not implemented yet "// &
                                                "([Roller dynamics]); the print file ends after step 0 (the "// &
                                                "quasi-static start)"

   !> A cylindrical roller bearing run (step 0).
   type, extends(bearing_system_t) :: roller_kind_t
      type(roller_step0_t) :: step0         !< the quasi-static start
   contains
      procedure :: solve_start => roller_solve_start
      procedure :: write_start => roller_write_start
      procedure :: run_note => roller_run_note
   end type roller_kind_t

contains

   !> Step 0 (adore_start_roller_step0); the ball-only options are input errors.
   subroutine roller_solve_start(self, error)
      class(roller_kind_t), intent(inout) :: self
      type(error_type), allocatable, intent(out) :: error
      if (len_trim(self%options%ball_start) > 0) then
         call input_error(error, "the ball start option applies to ball bearings; this deck is a cylindrical "// &
                          "roller bearing (Rec 3.2)")
         return
      end if
      if (self%options%moment_equilibrium) then
         call input_error(error, "the moment equilibrium option applies to ball bearings; this deck is a "// &
                          "cylindrical roller bearing (Rec 3.2)")
         return
      end if
      self%condition = condition_of(self%bearing)
      call solve_roller_step0(self%bearing, self%step0, error)
   end subroutine roller_solve_start

   subroutine roller_write_start(self, unit)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: unit
      call write_roller_step0(unit, 0, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], self%bearing, self%step0)
   end subroutine roller_write_start

   !> The note when the options or the deck ask for time steps.
   subroutine roller_run_note(self, n_steps, text)
      class(roller_kind_t), intent(in) :: self
      integer, intent(in) :: n_steps
      character(len=:), allocatable, intent(out) :: text
      text = ""
      if (n_steps > 0) return
      if (self%options%steps > 0 .or. (self%options%steps == STEPS_FROM_DECK .and. self%bearing%controls%n_steps > 0)) &
         text = NO_DYNAMICS
   end subroutine roller_run_note

end module adore_bearings_roller
