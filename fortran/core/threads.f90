!> The threads of a run's derivative (run option `threads`, docs/performance.md, "Threads"):
!> the rolling elements' contact work of every derivative call is shared by an OpenMP team,
!> each element's loads in its own slot and every sum over the elements taken afterwards in
!> a fixed order, so that a run's results are the same bit for bit on any number of threads.
!> Built without OpenMP (no -fopenmp), every run has one thread.  No module state.
module adore_core_threads
   !$ use omp_lib, only: omp_get_max_threads, omp_get_num_procs
   implicit none
   private

   public :: run_threads, DEFAULT_THREADS_CAP

   !> the most threads a run takes by default (no OMP_NUM_THREADS, no `threads` option): the
   !> 18 balls of Appendix C on 4 threads are 5, 5, 4 and 4 balls, at most 3.6 times the
   !> speed of one; more threads would each get fewer balls while the serial part stays
   integer, parameter :: DEFAULT_THREADS_CAP = 4

contains

   !> The threads a run takes for the run option `threads` = requested: requested when > 0;
   !> for 0 (the default) OMP_NUM_THREADS when the environment sets it (its first value, as
   !> the OpenMP run-time read it), else the processors this process may run on, at most
   !> DEFAULT_THREADS_CAP.  1 in a build without OpenMP.
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
      !$    else
      !$       n = min(omp_get_num_procs(), DEFAULT_THREADS_CAP)
      !$    end if
      !$ end if
      n = max(n, 1)
   end function run_threads

end module adore_core_threads
