!> Kinds used throughout the engine: one working precision for all reals.
module adore_core_kinds
   use, intrinsic :: iso_fortran_env, only: real64
   implicit none
   private

   public :: wp

   !> Working precision: IEEE double, as ADORE 5.0 (Appendix A declares real(8)).
   integer, parameter :: wp = real64

end module adore_core_kinds
