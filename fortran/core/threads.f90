!> The threads of a run's derivative (run option `threads`, docs/performance.md, "Threads"):
!> the rolling elements' contact work of every derivative call is shared by an OpenMP team,
!> each element's loads in its own slot and every sum over the elements taken afterwards in
!> a fixed order, so that a run's results are the same bit for bit on any number of threads.
!> Built without OpenMP (no -fopenmp), every run has one thread.  No module state.
module adore_core_threads
   use adore_core_kinds, only: wp
   !$ use omp_lib, only: omp_get_max_threads, omp_get_num_procs, omp_get_thread_num, omp_get_num_threads, omp_get_wtime
   implicit none
   private

   public :: run_threads, team_join, DEFAULT_THREADS_CAP, TEAM_JOIN_WAIT

   !> the most threads a run takes by default (no OMP_NUM_THREADS, no `threads` option): the
   !> 18 balls of Appendix C on 4 threads are 5, 5, 4 and 4 balls, at most 3.6 times the
   !> speed of one; more threads would each get fewer balls while the serial part stays
   integer, parameter :: DEFAULT_THREADS_CAP = 4

   !> the longest the first thread waits (s), busy, in team_join for the others to finish their
   !> last items: about two balls' contacts of Appendix C (~10 us each); on a loaded machine,
   !> where another thread may have lost its core, at most this much CPU is spent a loop
   real(wp), parameter :: TEAM_JOIN_WAIT = 2.0e-5_wp

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

   !> The end of a parallel loop's work (docs/performance.md, "Threads"), called by every
   !> thread of the team once its share is done (after a `nowait` worksharing loop, before the
   !> region's end): the other threads count themselves in arrived (shared, 0 at the region's
   !> start); the first thread waits, busy, until all the others have, at most TEAM_JOIN_WAIT
   !> seconds.  So the first thread, which carries the run on, usually reaches the region's
   !> closing barrier last and passes it without sleeping: under the passive wait policy a
   !> sleeping thread costs a futex wake-up and, on a virtual machine, the virtual CPU's
   !> return from halt (~20-50 us measured here).  The results do not depend on it.
   subroutine team_join(arrived)
      integer, intent(inout) :: arrived
      integer :: seen, others
      real(wp) :: start, now
      logical :: first
      first = .true.
      others = 0
      !$ first = omp_get_thread_num() == 0
      !$ others = omp_get_num_threads() - 1
      if (.not. first) then
         !$omp atomic update
         arrived = arrived + 1
         return
      end if
      start = 0.0_wp
      !$ start = omp_get_wtime()
      do
         !$omp atomic read
         seen = arrived
         if (seen >= others) exit
         now = start + 2.0_wp*TEAM_JOIN_WAIT
         !$ now = omp_get_wtime()
         if (now - start > TEAM_JOIN_WAIT) exit
      end do
   end subroutine team_join

end module adore_core_threads
