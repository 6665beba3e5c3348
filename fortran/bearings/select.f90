!> The one place that maps a deck's bearing type (Rec 3.2) to its bearing kind
!> (adore_bearings_system): a new kind is a new module and one case here.
module adore_bearings_select
   use adore_core_error, only: error_type, input_error
   use adore_core_strings, only: itoa
   use adore_model_bearing, only: bearing_t, BALL_BEARING, ROLLER_BEARING
   use adore_model_run_options, only: run_options_t
   use adore_bearings_system, only: bearing_system_t
   use adore_bearings_ball, only: ball_kind_t
   use adore_bearings_roller, only: roller_kind_t
   implicit none
   private

   public :: new_bearing_system

contains

   !> The bearing system of bearing b (its kind by b%bearing_type) with the run options opts;
   !> input error for a bearing type without a kind.
   subroutine new_bearing_system(b, opts, sys, error)
      type(bearing_t), intent(in) :: b
      type(run_options_t), intent(in) :: opts
      class(bearing_system_t), allocatable, intent(out) :: sys
      type(error_type), allocatable, intent(out) :: error
      select case (b%bearing_type)
      case (BALL_BEARING)
         allocate (ball_kind_t :: sys)
      case (ROLLER_BEARING)
         allocate (roller_kind_t :: sys)
      case default
         call input_error(error, "bearing type "//itoa(b%bearing_type)//" (Rec 3.2): no model for it")
         return
      end select
      sys%bearing = b
      sys%options = opts
   end subroutine new_bearing_system

end module adore_bearings_select
