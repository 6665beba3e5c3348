!> The threads of a run's derivative (run option `threads`, docs/dynamics.md, "Threads"):
!> the rolling elements' contact work of every derivative call is shared by an OpenMP team,
!> each element's loads in its own slot and every sum over the elements taken afterwards in
!> a fixed order, so that a run's results are the same bit for bit on any number of threads.
!> Built without OpenMP (no -fopenmp), every run has one thread.  No module state.
module adore_core_threads
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private

   public :: run_threads

contains

   !> The threads a run takes for the run option `threads` = requested: requested when > 0;
   !> for 0 (the default) OMP_NUM_THREADS when the environment sets it (its first value, as
   !> the OpenMP run-time read it), else 1: on the 2-core machines measured, two threads were
   !> slower than one (docs/dynamics.md, "Threads").  1 in a build without OpenMP.
   integer function run_threads(requested) result(n)
      integer, intent(in) :: requested
      integer :: length, stat
      n = 1
      length = 0
      stat = 1
      !$ if (requested > 0) then
      !$    n = requested
      !$ else
      !$    call get_environment_variable("OMP_NUM_THREADS", length=length, status=stat)
      !$    if (stat == 0 .and. length > 0) then
      !$       n = omp_get_max_threads()
      !$    end if
      !$ end if
      n = max(n, 1)
   end function run_threads

end module adore_core_threads
