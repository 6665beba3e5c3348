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

   public :: run_threads, team_join, team_t, team_threads, team_note, wall_seconds, DEFAULT_THREADS_CAP, &
             TEAM_JOIN_WAIT, TEAM_PROBE, TEAM_KEEP, TEAM_CUT, TEAM_BACKOFF

   !> the most threads a run takes by default (no OMP_NUM_THREADS, no `threads` option): the
   !> 18 balls of Appendix C on 4 threads are 5, 5, 4 and 4 balls, at most 3.6 times the
   !> speed of one; more threads would each get fewer balls while the serial part stays
   integer, parameter :: DEFAULT_THREADS_CAP = 4

   !> the longest the first thread waits (s), busy, in team_join for the others to finish their
   !> last items: about two balls' contacts of Appendix C (~10 us each); on a loaded machine,
   !> where another thread may have lost its core, at most this much CPU is spent a loop
   real(wp), parameter :: TEAM_JOIN_WAIT = 2.0e-5_wp

   !> calls of each measured window of team_t (one on the run's threads, one on a single
   !> thread), and calls run on the faster choice before both are measured again
   integer, parameter :: TEAM_PROBE = 32, TEAM_KEEP = 480

   !> a window on the threads ends early, and one thread is kept, once its calls have taken
   !> TEAM_CUT times the wall time of the whole last window on one thread: on a busy machine
   !> the threads' window costs about that much more than one thread's, not its full length
   real(wp), parameter :: TEAM_CUT = 1.5_wp

   !> one thread kept k times in a row is kept TEAM_KEEP * 2**min(k - 1, TEAM_BACKOFF) calls:
   !> while other work holds the cores, the threads are measured ever less often
   integer, parameter :: TEAM_BACKOFF = 3

   !> A run's choice between its threads and one thread for the derivative calls, measured as
   !> it goes (docs/performance.md, "Threads"): TEAM_PROBE calls on the run's threads, then
   !> TEAM_PROBE on one, then TEAM_KEEP calls on whichever took less wall time, and again.
   !> On a machine whose cores are free the threads win; when other work holds the cores,
   !> a parallel loop waits for a thread that has no core (measured: one thread 13-15 %
   !> faster then, 3 times with spinning threads) and the run goes on one; a window on the
   !> threads that has already cost TEAM_CUT times the last one-thread window ends there, and
   !> one thread kept again is kept longer (TEAM_BACKOFF).  The results are the same bit for
   !> bit either way.
   type :: team_t
      integer :: phase = 0                !< 0: not started; 1: measuring the threads; 2: one; 3: keeping
      integer :: left = 0                 !< calls left in the phase
      integer :: choice = 1               !< the threads of phase 3
      real(wp) :: seconds(2) = 0.0_wp     !< wall time of the windows: on the threads, on one
      integer :: kept_one = 0             !< phases 3 run on one thread (statistics)
      integer :: kept_many = 0            !< phases 3 run on the threads (statistics)
      integer :: streak = 0               !< one thread kept this many times in a row
      real(wp) :: one_window = 0.0_wp     !< wall time (s) of the last whole window on one thread
   end type team_t

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

   !> The threads for the next derivative call of a run on `threads` threads (team_t).
   pure integer function team_threads(team, threads) result(n)
      type(team_t), intent(in) :: team
      integer, intent(in) :: threads
      n = max(threads, 1)
      if (n == 1) return
      select case (team%phase)
      case (2)
         n = 1
      case (3)
         n = team%choice
      end select
   end function team_threads

   !> The wall time (s) of a derivative call made on team_threads(team, threads) threads:
   !> the windows' sums, the choice at the end of the second (or when the threads' window has
   !> cost TEAM_CUT times the last one-thread window), the phases' turns (team_t).
   pure subroutine team_note(team, threads, seconds)
      type(team_t), intent(inout) :: team
      integer, intent(in) :: threads
      real(wp), intent(in) :: seconds
      if (threads <= 1) return
      if (team%phase == 0) then
         team%phase = 1
         team%left = TEAM_PROBE
         team%seconds = 0.0_wp
      end if
      if (team%phase == 1 .or. team%phase == 2) team%seconds(team%phase) = team%seconds(team%phase) + seconds
      team%left = team%left - 1
      if (team%phase == 1 .and. team%one_window > 0.0_wp .and. team%left > 0) then
         ! the threads already slower than a whole window on one thread: keep one
         if (team%seconds(1) > TEAM_CUT*team%one_window) then
            call keep_one(team)
            return
         end if
      end if
      if (team%left > 0) return
      select case (team%phase)
      case (1)
         team%phase = 2
         team%left = TEAM_PROBE
      case (2)
         team%one_window = team%seconds(2)
         if (team%seconds(1) <= team%seconds(2)) then
            team%phase = 3
            team%left = TEAM_KEEP
            team%choice = threads
            team%kept_many = team%kept_many + 1
            team%streak = 0
         else
            call keep_one(team)
         end if
      case default
         team%phase = 1
         team%left = TEAM_PROBE
         team%seconds = 0.0_wp
      end select
   end subroutine team_note

   !> team_t: one thread for the next TEAM_KEEP * 2**min(streak, TEAM_BACKOFF) calls.
   pure subroutine keep_one(team)
      type(team_t), intent(inout) :: team
      team%phase = 3
      team%left = TEAM_KEEP*2**min(team%streak, TEAM_BACKOFF)
      team%choice = 1
      team%kept_one = team%kept_one + 1
      team%streak = team%streak + 1
   end subroutine keep_one

   !> Wall-clock seconds (omp_get_wtime; 0 without OpenMP, where every run has one thread).
   real(wp) function wall_seconds() result(t)
      t = 0.0_wp
      !$ t = omp_get_wtime()
   end function wall_seconds

end module adore_core_threads
