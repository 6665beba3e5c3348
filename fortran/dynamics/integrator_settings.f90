!> The integrator's settings (Rec 1 INT METHOD, Rec 2.1 step control and pyadore's own
!> controls), its statistics ("Statistics of this Run"), the method codes and the flags a
!> derivative returns: the data the error-controlled integrator (adore_dynamics_integrator,
!> which re-exports all of it) is configured with and reports.
module adore_dynamics_integrator_settings
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: integrator_settings_t, integrator_stats_t
   public :: DERIV_OK, DERIV_REJECT_STEP, DERIV_FAIL
   public :: INT_METHOD_BS32, INT_METHOD_DP54, INT_METHOD_ROS34PW2, INT_METHOD_ARK436, ADORE_FORCED_ERR_CAP

   !> Flags a derivative returns: the values are good; the step must be rejected and retried
   !> smaller (report 4.4.12, abnormal cage contact); the model failed (the run stops).
   integer, parameter :: DERIV_OK = 0, DERIV_REJECT_STEP = 1, DERIV_FAIL = 2

   !> INT METHOD codes pyadore knows (Rec 1 field int_method): 3 Bogacki-Shampine 3(2),
   !> 5 Dormand-Prince 5(4).  Only 5 is attested (both decks); its meaning in ADORE is not.
   !> pyadore's own codes: 34 ROS34PW2, 43 ARK4(3)6L[2]SA (docs/integrator.md, "INT METHOD").
   integer, parameter :: INT_METHOD_BS32 = 3, INT_METHOD_DP54 = 5, INT_METHOD_ROS34PW2 = 34, INT_METHOD_ARK436 = 43

   !> The largest truncation error ADORE is attested to accept at the Rec 2.1 minimum step, as a
   !> ratio to the ERROR LIMIT: Appendix C prints Max Truncation 1.72086E-03 at ERROR LIMIT
   !> 1E-04 and Minimum Step Size = MINIMUM (docs/integrator.md, "Step control").  A forced step
   !> beyond it has no accuracy left: in ISO example 4 at 10 000 rpm and its static capacity one
   !> such step (171 times the limit) moved a ball 143 um axially in 171 ns and reversed its
   !> orbit (docs/operating-points.md, "Session 20").  Dimensionless.
   real(wp), parameter :: ADORE_FORCED_ERR_CAP = 1.72086e-3_wp/1.0e-4_wp

   !> Settings: Rec 1 int_method and Rec 2.1 (steps in the unit of t: ADORE's dimensionless tau).
   type :: integrator_settings_t
      integer :: int_method = INT_METHOD_DP54   !< Rec 1 int_method (INT METHOD)
      real(wp) :: h_initial = 0.0_wp            !< Rec 2.1 step_initial (INITIAL)
      real(wp) :: h_min = 0.0_wp                !< Rec 2.1 step_min (MINIMUM)
      real(wp) :: h_max = 0.0_wp                !< Rec 2.1 step_max (MAXIMUM)
      real(wp) :: error_limit = 0.0_wp          !< Rec 2.1 error_limit (ERROR LIMIT)
      real(wp) :: rel_weight = 1.0_wp           !< weight of |y| in the error scale (0: absolute only)
      !> At h_min with err > 1: .false. stops the run with an error; .true. accepts the step (err up to
      !> forced_err_cap) and counts it (stats%forced_at_h_min), as ADORE's Appendix C statistics suggest.
      logical :: accept_at_h_min = .false.
      !> Under accept_at_h_min: the largest error ratio (err, 1 = at the limit) accepted at h_min.
      !> An attempt at h_min with a larger err is halved below h_min (down to SUB_MIN_FLOOR of
      !> it), as one the derivative refuses; huge (the default): no cap.  The decks' runs take
      !> ADORE_FORCED_ERR_CAP, what ADORE's Appendix C run is attested to accept (issue #28).
      real(wp) :: forced_err_cap = huge(1.0_wp)
      integer :: max_rejections = 100           !< consecutive rejections of one step before an error
      !> Rosenbrock-W with Jacobian blocks: accepted steps a block Jacobian is kept (a W-method
      !> keeps its order with any W; a new one is also taken after a rejected step)
      integer :: jacobian_every = 10
      !> safety factor of the step-size controller (DOPRI5's 0.9; in (0, 1])
      real(wp) :: safety = 0.9_wp
      !> IMEX method with block Jacobians: when the first block Jacobian shows a relaxation rate
      !> -J_cc (unknown c of a block, c one of switch_columns, 1..m) above switch_stiffness / h_min,
      !> the run is integrated by the Rosenbrock-W method ROS34PW2 instead (on the same blocks,
      !> safety factor 0.9), from its first step: a mode the deck's minimum step cannot follow
      !> (issue #28; docs/integrator.md, "Step control").  0 (the default): never.
      real(wp) :: switch_stiffness = 0.0_wp
      integer, allocatable :: switch_columns(:)
      !> Power-balance control (issue #28): with the quadrature on (start_quadrature), an attempt
      !> is also rejected when the derivative's balance defect over the step (derivative_t%
      !> balance_defect: the energy change against the integral of its rates) exceeds
      !> balance_tolerance times the step's energy flow; the controller takes the larger of that
      !> ratio and the error test's.  Not at the minimum step.  0 (the default): off.
      real(wp) :: balance_tolerance = 0.0_wp
   end type integrator_settings_t

   !> Counts for "Statistics of this Run" (Appendix C) and diagnostics.
   type :: integrator_stats_t
      integer :: derivative_calls = 0       !< Total Derivative Calls
      integer :: accepted = 0               !< accepted steps
      integer :: rejected_error = 0         !< attempts rejected by the error test
      integer :: rejected_flag = 0          !< attempts refused by the derivative (4.4.12)
      integer :: rejected_nonfinite = 0     !< attempts with non-finite stages or result
      integer :: rejected_balance = 0       !< attempts rejected by the power-balance control
      integer :: forced_at_h_min = 0        !< steps accepted at h_min with err > 1 (accept_at_h_min)
      real(wp) :: forced_err_max = 0.0_wp   !< the largest err (1 = at the limit) of those steps
      !> steps accepted shorter than h_min after attempts the derivative refused or that were not
      !> finite at h_min (report 4.4.12's reduced step; accept_at_h_min only)
      integer :: below_h_min = 0
      !> those of them taken after an attempt at h_min whose error was above forced_err_cap
      integer :: below_h_min_error = 0
      integer :: forced_within_2 = 0        !< those of them with err <= 2
      !> per unknown: the forced steps whose error it led (the largest weighted component of the
      !> error estimate; allocated by init, n values), the diagnosis of issue #28
      integer, allocatable :: forced_lead(:)
      real(wp) :: h_min_used = huge(1.0_wp) !< Minimum Step Size (steps cut to land on t_out excluded)
      real(wp) :: h_max_used = 0.0_wp       !< Maximum Step Size (idem)
      real(wp) :: h_last = 0.0_wp           !< Last Step Size
      real(wp) :: max_truncation = 0.0_wp   !< Max Truncation: largest err * error_limit accepted
      integer :: jacobians = 0              !< block Jacobians evaluated (Rosenbrock-W)
      integer :: jacobian_calls = 0         !< derivative calls spent on them (in derivative_calls)
      !> the largest -J_cc h_min of settings%switch_columns at the first block Jacobian (the
      !> method switch's measure; 0 when not measured) and whether the run switched to ROS34PW2
      real(wp) :: switch_measure = 0.0_wp
      logical :: switched = .false.
   end type integrator_stats_t

end module adore_dynamics_integrator_settings
