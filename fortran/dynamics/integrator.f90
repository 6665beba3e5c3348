!> The error-controlled integrator of the equations of motion (issue #20 item 3, issue #30 item 2).
!>
!> Design (ddeabm style): `integrator_t` owns its settings, its workspace (stage vectors
!> allocated once by init for n unknowns) and its statistics; the right-hand side is an
!> argument, an extension of the abstract type `derivative_t` whose deferred `eval` gives
!> dy/dt.  The model data travel inside the caller's extension, so there is no module state
!> and two integrations never share anything.
!>
!> The linearly implicit attempts live in the submodule adore_dynamics_integrator_implicit
!> (integrator_implicit.f90).
!>
!> Methods (Rec 1 field int_method, echo INT METHOD; see docs/dynamics.md for what is known
!> and what is assumed): 5 = Dormand-Prince 5(4), 3 = Bogacki-Shampine 3(2), both explicit,
!> embedded, FSAL, propagating the higher order; 34 = ROS34PW2 (pyadore's code, not an ADORE
!> value), a linearly implicit Rosenbrock-W method whose W uses the system's block-diagonal
!> Jacobian, optionally bordered (an arrowhead: set_jacobian_blocks; each block by finite
!> differences, all blocks at once, the border's rows from derivative_t%border_shares,
!> adore_dynamics_block_jacobian), which takes the stiff per-ball contact modes implicitly;
!> without blocks it is an explicit 4-stage method of order 3.  Step control (Rec 2.1): initial, minimum and
!> maximum step and ERROR LIMIT; weighted max-norm of the embedded error estimate,
!>     err = max_i |e_i| / (ERROR LIMIT * (scale_i + rel_weight * max(|y_i|, |y_new,i|))),
!> step accepted when err <= 1; PI step-size controller (Hairer, Norsett & Wanner, Solving ODEs I,
!> 2nd ed., section II.4, eq 4.13, with the constants of DOPRI5; Gustafsson, ACM TOMS 17 (1991)).
!> A derivative may refuse a step (DERIV_REJECT_STEP: abnormal rolling element/cage contact,
!> report section 4.4.12): the step is rejected and retried with half the step.
!> Library code: errors return through error_type, never stop.
module adore_dynamics_integrator
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_positive_inf
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_strings, only: itoa
   use adore_deck_tokenizer, only: show_real
   use adore_dynamics_rk_tableau, only: rk_tableau_t, dormand_prince_54, bogacki_shampine_32, &
                                        rosenbrock_tableau_t, ros34pw2, ark_tableau_t, ark436l2sa
   use adore_dynamics_block_jacobian, only: block_jacobian_t
   use adore_dynamics_derivative, only: derivative_t
   use adore_dynamics_integrator_settings, only: integrator_settings_t, integrator_stats_t, DERIV_OK, &
                                                 DERIV_REJECT_STEP, DERIV_FAIL, INT_METHOD_BS32, INT_METHOD_DP54, &
                                                 INT_METHOD_ROS34PW2, INT_METHOD_ARK436, ADORE_FORCED_ERR_CAP
   implicit none
   private

   public :: derivative_t, integrator_t, integrator_settings_t, integrator_stats_t
   public :: DERIV_OK, DERIV_REJECT_STEP, DERIV_FAIL
   public :: INT_METHOD_BS32, INT_METHOD_DP54, INT_METHOD_ROS34PW2, INT_METHOD_ARK436, ADORE_FORCED_ERR_CAP



   !> Step-size controller constants (DOPRI5's bounds of h_new/h; the safety factor is a setting).
   real(wp), parameter :: fac_min = 0.2_wp, fac_max = 10.0_wp
   !> Step reduction after a derivative refused the step (4.4.12 says "a reduced step").
   real(wp), parameter :: flag_cut = 0.5_wp
   !> under ADORE's rule (accept_at_h_min), the shortest retry of an attempt refused or not
   !> finite at h_min, as a fraction of h_min (report 4.4.12's reduced step; halved to it)
   real(wp), parameter :: SUB_MIN_FLOOR = 1.0_wp/1024.0_wp
   !> Lower bound of the previous error in the PI controller (DOPRI5's facold floor).
   real(wp), parameter :: err_floor = 1.0e-4_wp




   !> The integrator: settings, method, workspace, step proposal and statistics.
   type :: integrator_t
      type(integrator_settings_t) :: settings
      type(rk_tableau_t) :: tab
      type(rosenbrock_tableau_t) :: ros       !< the linearly implicit method (when rosenbrock)
      logical :: rosenbrock = .false.
      type(ark_tableau_t) :: ark              !< the additive (IMEX) method (when imex)
      logical :: imex = .false.
      type(block_jacobian_t) :: jac           !< Rosenbrock-W: the system's block Jacobian
      integer :: jac_age = -1                 !< accepted steps since jac was evaluated; < 0: none
      integer :: last = 0                     !< column of k holding f at the end of an attempt
      type(integrator_stats_t) :: stats
      integer :: n = 0                        !< number of unknowns
      real(wp) :: h_next = 0.0_wp             !< size of the next attempt
      real(wp), allocatable :: scale(:)       !< error scale per unknown (units of y), > 0
      real(wp), allocatable :: k(:, :)        !< stage derivatives, n x stages
      real(wp), allocatable :: u(:, :)        !< Rosenbrock stages (transformed, units of y);
                                              !< IMEX: J z_i of the stages (units of y per unit of t)
      real(wp), allocatable :: y_stage(:), y_new(:), y_err(:)
      real(wp), allocatable :: y_fsal(:)      !< the state at which k(:, 1) = f(t_fsal, y_fsal)
      real(wp) :: t_fsal = 0.0_wp
      logical :: fsal_valid = .false.
      !> The derivative's last evaluation by this integrator was at (t_fsal, y_fsal), so its
      !> border shares belong to the step's start (block_jacobian reuses them: one call less)
      logical :: shares_at_start = .false.
      logical :: evaluated_new = .false.      !< the last evaluation was end_of_attempt's, at (t_new, y_new)
      real(wp) :: t_new = 0.0_wp              !< the time of that evaluation
      !> the method's own quadrature of the derivative's quadrature_values (start_quadrature):
      !> their values at the stages (nq x columns of k: column j with k(:, j)) and their
      !> integral over the last accepted step (their units times the unit of t)
      logical :: quadrature = .false.
      real(wp), allocatable :: g(:, :)
      real(wp), allocatable :: q_step(:)
      real(wp) :: err_old = err_floor         !< previous accepted error (PI controller)
      real(wp) :: alpha = 0.0_wp, beta = 0.0_wp  !< PI exponents
      logical :: ready = .false.
   contains
      procedure :: init
      procedure :: step
      procedure :: advance
      procedure :: restart
      procedure :: set_jacobian_blocks
      procedure :: start_quadrature
      procedure :: quadrature_consistent
      !> private bindings: the submodule reaches them through the type (gfortran 12 does not
      !> export a private module procedure to a submodule's object file)
      procedure, private :: weighted_error
      procedure, private :: stop_error
   end type integrator_t

   !> The linearly implicit methods (Rosenbrock-W and IMEX) and their block Jacobian:
   !> submodule adore_dynamics_integrator_implicit (fortran/dynamics/integrator_implicit.f90).
   interface
      !> Jacobian blocks of the linearly implicit methods (nb blocks of m unknowns at first(:),
      !> columns cols(:)), bordered by the unknowns border(:) when given.
      module subroutine set_jacobian_blocks(self, first, m, cols, error, border)
         class(integrator_t), intent(inout) :: self
         integer, intent(in) :: first(:), m, cols(:)
         type(error_type), allocatable, intent(out) :: error
         integer, intent(in), optional :: border(:)
      end subroutine set_jacobian_blocks
      !> The block Jacobian at (t, y) by forward differences (k(:, 1) = f(t, y) given).
      module subroutine block_jacobian(self, deriv, t, y, error)
         class(integrator_t), intent(inout) :: self
         class(derivative_t), intent(inout) :: deriv
         real(wp), intent(in) :: t
         real(wp), intent(in) :: y(:)
         type(error_type), allocatable, intent(out) :: error
      end subroutine block_jacobian
      !> One Rosenbrock-W attempt of size h from (t, y) (HNW II, IV.7 eq 7.25).
      module subroutine attempt_rosenbrock(self, deriv, t, y, h, flag, err, accept)
         class(integrator_t), intent(inout) :: self
         class(derivative_t), intent(inout) :: deriv
         real(wp), intent(in) :: t, h
         real(wp), intent(in) :: y(:)
         integer, intent(out) :: flag
         real(wp), intent(out) :: err
         logical, intent(in) :: accept
      end subroutine attempt_rosenbrock
      !> One additive (IMEX) Runge-Kutta attempt of size h from (t, y) (Kennedy & Carpenter 2003).
      module subroutine attempt_imex(self, deriv, t, y, h, flag, err, accept)
         class(integrator_t), intent(inout) :: self
         class(derivative_t), intent(inout) :: deriv
         real(wp), intent(in) :: t, h
         real(wp), intent(in) :: y(:)
         integer, intent(out) :: flag
         real(wp), intent(out) :: err
         logical, intent(in) :: accept
      end subroutine attempt_imex
      !> At the first block Jacobian of an IMEX run: ROS34PW2 from this step on where the
      !> switch columns are stiff (settings%switch_stiffness).
      module subroutine stiffness_switch(self)
         class(integrator_t), intent(inout) :: self
      end subroutine stiffness_switch
   end interface

   !> The explicit pairs' attempt: submodule adore_dynamics_integrator_explicit
   !> (fortran/dynamics/integrator_explicit.f90).
   interface
      !> One attempt of size h from (t, y), k(:, 1) given: stages, y_new, the weighted error err.
      module subroutine attempt(self, deriv, t, y, h, flag, err)
         class(integrator_t), intent(inout) :: self
         class(derivative_t), intent(inout) :: deriv
         real(wp), intent(in) :: t, h
         real(wp), intent(in) :: y(:)
         integer, intent(out) :: flag
         real(wp), intent(out) :: err
      end subroutine attempt
   end interface

   !> The method's quadrature of the derivative's values: submodule
   !> adore_dynamics_integrator_quadrature (fortran/dynamics/integrator_quadrature.f90).
   interface
      !> Integrate the derivative's quadrature_values over every accepted step from the next
      !> one on (q_step); g0 the values at the state the next step starts from.
      module subroutine start_quadrature(self, g0)
         class(integrator_t), intent(inout) :: self
         real(wp), intent(in) :: g0(:)
      end subroutine start_quadrature
      !> Whether the stage quadrature is consistent with the method's steps (the IMEX method).
      module logical function quadrature_consistent(self)
         class(integrator_t), intent(in) :: self
      end function quadrature_consistent
      !> The quadrature of the values over the accepted step of size h into q_step.
      module subroutine step_quadrature(self, h)
         class(integrator_t), intent(inout) :: self
         real(wp), intent(in) :: h
      end subroutine step_quadrature
      !> The power-balance control's error ratio of the attempt of size h (1 = at
      !> settings%balance_tolerance; 0 without a balance): the derivative's balance defect over
      !> the step against tolerance times its flow.
      module real(wp) function balance_error(self, deriv, h)
         class(integrator_t), intent(inout) :: self
         class(derivative_t), intent(in) :: deriv
         real(wp), intent(in) :: h
      end function balance_error
   end interface

contains


   !> Check the settings, choose the method and allocate the workspace for n unknowns.
   !> scale(n) (units of y, > 0) sets the absolute part of the error test; default 1.
   subroutine init(self, n, settings, error, scale)
      class(integrator_t), intent(out) :: self
      integer, intent(in) :: n
      type(integrator_settings_t), intent(in) :: settings
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: scale(:)
      integer :: k
      character(len=:), allocatable :: msg

      associate (s => settings)
         select case (s%int_method)
         case (INT_METHOD_DP54)
            self%tab = dormand_prince_54()
         case (INT_METHOD_BS32)
            self%tab = bogacki_shampine_32()
         case (INT_METHOD_ROS34PW2)
            self%ros = ros34pw2()
            self%rosenbrock = .true.
         case (INT_METHOD_ARK436)
            self%ark = ark436l2sa()
            self%imex = .true.
         case default
            call input_error(error, "Rec 1 field int_method = "//itoa(s%int_method)// &
                             ": unknown integration method (INT METHOD); pyadore knows 5 (Dormand-Prince 5(4)) "// &
                             "and 3 (Bogacki-Shampine 3(2)), and its own 34 (ROS34PW2) and 43 (ARK4(3)6L[2]SA)")
            return
         end select
         if (.not. (s%h_min > 0.0_wp .and. s%h_min < huge(1.0_wp))) then
            msg = "Rec 2.1 field step_min = "
            call put_real(msg, s%h_min)
            msg = msg//": expected > 0"
         else if (.not. (s%h_max >= s%h_min .and. s%h_max < huge(1.0_wp))) then
            msg = "Rec 2.1 field step_max = "
            call put_real(msg, s%h_max)
            msg = msg//": expected >= step_min = "
            call put_real(msg, s%h_min)
         else if (.not. (s%h_initial >= s%h_min .and. s%h_initial <= s%h_max)) then
            msg = "Rec 2.1 field step_initial = "
            call put_real(msg, s%h_initial)
            msg = msg//": expected between step_min = "
            call put_real(msg, s%h_min)
            msg = msg//" and step_max = "
            call put_real(msg, s%h_max)
         else if (.not. (s%error_limit > 0.0_wp .and. s%error_limit < 1.0_wp)) then
            msg = "Rec 2.1 field error_limit = "
            call put_real(msg, s%error_limit)
            msg = msg//": expected > 0 and < 1"
         end if
         if (allocated(msg)) then
            call input_error(error, msg)
            return
         end if
         if (.not. (s%rel_weight >= 0.0_wp .and. s%max_rejections >= 1 .and. n >= 1 .and. s%jacobian_every >= 1 .and. &
                   s%safety > 0.0_wp .and. s%safety <= 1.0_wp .and. s%switch_stiffness >= 0.0_wp)) then
            call engine_error(error, "integrator: expected rel_weight >= 0, max_rejections >= 1, "// &
                              "jacobian_every >= 1, 0 < safety <= 1, switch_stiffness >= 0 and n >= 1 (n = "//itoa(n)// &
                              ", max_rejections = "//itoa(s%max_rejections)//")")
         end if
         if (allocated(error)) return
      end associate
      self%settings = settings
      self%n = n
      allocate (self%scale(n), source=1.0_wp)
      if (present(scale)) then
         if (size(scale) /= n) then
            call engine_error(error, "integrator: scale has "//itoa(size(scale))//" values for "// &
                              itoa(n)//" unknowns")
            return
         end if
         do k = 1, n
            if (.not. (scale(k) > 0.0_wp .and. scale(k) < huge(1.0_wp))) then
               msg = "integrator: error scale of unknown "//itoa(k)//" is "
               call put_real(msg, scale(k))
               call engine_error(error, msg//", expected > 0")
               return
            end if
         end do
         self%scale = scale
      end if
      if (self%rosenbrock) then
         ! k(:, 1): f at the start; k(:, 2): a stage's f; k(:, s + 1): f at y_new; u: the stages
         self%last = self%ros%stages + 1
         allocate (self%u(n, self%ros%stages))
         k = self%ros%error_order
      else if (self%imex) then
         ! k(:, i): f at stage i; k(:, s + 1): f at y_new; u(:, i): J z_i (also large enough for
         ! ROS34PW2's k and u after a switch: settings%switch_stiffness)
         self%last = self%ark%stages + 1
         allocate (self%u(n, self%ark%stages))
         k = self%ark%error_order
         if (settings%switch_stiffness > 0.0_wp) self%ros = ros34pw2()
      else
         self%last = self%tab%stages
         k = self%tab%error_order
      end if
      allocate (self%k(n, self%last), self%y_stage(n), self%y_new(n), self%y_err(n), self%y_fsal(n))
      allocate (self%stats%forced_lead(n), source=0)
      ! PI exponents for an error of order k = error_order: beta = 0.2/k, alpha = 1/k - 0.75 beta
      ! (for k = 5 these are DOPRI5's beta = 0.04, expo1 = 0.17)
      self%beta = 0.2_wp/k
      self%alpha = 1.0_wp/k - 0.75_wp*self%beta
      self%h_next = settings%h_initial
      self%ready = .true.
   end subroutine init

   !> Forget the first-same-as-last derivative and the controller's memory, e.g. after the model
   !> changed discontinuously (thermal geometry update); h (unit of t), if given, is the next attempt.
   subroutine restart(self, h)
      class(integrator_t), intent(inout) :: self
      real(wp), intent(in), optional :: h
      self%fsal_valid = .false.
      self%shares_at_start = .false.
      self%evaluated_new = .false.
      self%err_old = err_floor
      self%jac_age = -1
      if (present(h)) self%h_next = min(max(h, self%settings%h_min), self%settings%h_max)
   end subroutine restart

   !> Take one accepted step from (t, y), rejecting and retrying internally; t and y are
   !> updated.  With t_limit the step ends at t_limit at the latest (landing exactly on it).
   subroutine step(self, deriv, t, y, error, t_limit)
      class(integrator_t), intent(inout) :: self
      class(derivative_t), intent(inout) :: deriv
      real(wp), intent(inout) :: t
      real(wp), intent(inout) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: t_limit
      real(wp) :: h, h_plan, err, err_state, fac, fac_err, h_min, limit
      integer :: flag, tries
      logical :: clipped, rejected_before, forced, below_min, gross, gross_seen, at_min, balance_led
      character(len=:), allocatable :: why, over

      if (.not. self%ready) then
         call engine_error(error, "integrator: step called before init")
         return
      end if
      if (size(y) /= self%n) then
         call engine_error(error, "integrator: state has "//itoa(size(y))//" values, init was for "//itoa(self%n))
         return
      end if
      if (.not. (ieee_is_finite(t) .and. all(ieee_is_finite(y)))) then
         why = " (non-finite unknowns: "
         call put_bad(why, y)
         call stop_error(self, error, "non-finite state at the start of a step", t, self%h_next, why//")")
         return
      end if
      call first_stage(self, deriv, t, y, error)
      if (allocated(error)) return
      if (self%jac%active() .and. (self%jac_age < 0 .or. self%jac_age >= self%settings%jacobian_every)) then
         call block_jacobian(self, deriv, t, y, error)
         if (allocated(error)) return
         if (self%imex .and. self%settings%switch_stiffness > 0.0_wp .and. self%stats%accepted == 0) &
            call stiffness_switch(self)
      end if

      h_min = self%settings%h_min
      h_plan = min(self%h_next, self%settings%h_max)
      h = h_plan
      clipped = .false.
      if (present(t_limit)) then
         if (.not. t_limit > t) then
            call stop_error(self, error, "t_limit is not after t", t, h)
            return
         end if
         ! land on t_limit; stretch by up to 1 % (never beyond h_max) rather than leave a
         ! sliver of a step
         if (t + min(1.01_wp*h, self%settings%h_max) >= t_limit) then
            h = t_limit - t
            clipped = .true.
         end if
      end if
      rejected_before = .false.
      forced = .false.
      below_min = .false.
      gross_seen = .false.
      do tries = 0, self%settings%max_rejections
         gross = .false.
         ! at the minimum: h_min, or a step landing on t_limit that is longer only by the
         ! round-off of t (t_limit - t = h_min + a few ulp of t; without this such a step could
         ! be neither forced nor shortened, and was rejected max_rejections times)
         at_min = h <= h_min .or. (clipped .and. h - h_min <= 8.0_wp*spacing(abs(t) + h))
         if (self%rosenbrock) then
            call attempt_rosenbrock(self, deriv, t, y, h, flag, err, &
                                    self%settings%accept_at_h_min .and. at_min)
         else if (self%imex) then
            call attempt_imex(self, deriv, t, y, h, flag, err, self%settings%accept_at_h_min .and. at_min)
         else
            call attempt(self, deriv, t, y, h, flag, err)
         end if
         ! the power-balance control (settings%balance_tolerance) of an attempt the error test
         ! accepts (its stages' values at the step's end exist only then), not at the minimum
         ! step, for the linearly implicit methods (the explicit pairs step at their stability
         ! limit on the stiff runs: docs/integrator.md, "Power-balance control")
         err_state = err
         balance_led = .false.
         if (self%quadrature .and. self%settings%balance_tolerance > 0.0_wp .and. .not. at_min .and. &
             flag == DERIV_OK .and. (self%imex .or. self%rosenbrock)) then
            if (ieee_is_finite(err) .and. err <= 1.0_wp) then
               err = max(err, balance_error(self, deriv, h))
               balance_led = err > 1.0_wp
            end if
         end if
         if (flag == DERIV_FAIL) then
            call stop_error(self, error, "the derivative failed", t, h, deriv=deriv)
            return
         end if
         if (flag == DERIV_REJECT_STEP) then
            self%stats%rejected_flag = self%stats%rejected_flag + 1
            why = "the derivative refused the step (report 4.4.12)"
            ! its reason now: a Jacobian taken before the next attempt evaluates anew
            if (allocated(deriv%failure_reason)) why = why//": "//deriv%failure_reason
            fac = flag_cut
         else if (.not. ieee_is_finite(err)) then
            self%stats%rejected_nonfinite = self%stats%rejected_nonfinite + 1
            why = "non-finite state or derivative"
            fac = fac_min
         else if (err <= 1.0_wp) then
            exit
         else if (self%settings%accept_at_h_min .and. at_min .and. err <= self%settings%forced_err_cap) then
            ! at the minimum step (or a shorter step landing on t_limit): accept, counted
            forced = .true.
            exit
         else if (self%settings%accept_at_h_min .and. at_min) then
            ! at the minimum with an error beyond what ADORE is attested to accept: retried
            ! below it as a refused attempt (the halving below)
            gross = .true.
            gross_seen = .true.
            self%stats%rejected_error = self%stats%rejected_error + 1
            why = "truncation error estimate "
            call put_real(why, err*self%settings%error_limit)
            why = why//" above "
            call put_real(why, self%settings%forced_err_cap)
            why = why//" times the error limit "
            call put_real(why, self%settings%error_limit)
            fac = flag_cut
         else
            ! the error test's or the power-balance control's (settings%balance_tolerance) ratio
            if (balance_led) then
               self%stats%rejected_balance = self%stats%rejected_balance + 1
               why = "power balance defect "
               limit = self%settings%balance_tolerance
               over = " of the step's energy flow, above the balance tolerance "
            else
               self%stats%rejected_error = self%stats%rejected_error + 1
               why = "truncation error estimate "
               limit = self%settings%error_limit
               over = " above the error limit "
            end if
            call put_real(why, err*limit)
            why = why//over
            call put_real(why, limit)
            fac = max(fac_min, self%settings%safety/err**self%alpha)
         end if
         ! rejected: retry smaller, never below h_min; a Rosenbrock-W method with an old
         ! Jacobian takes a new one first
         rejected_before = .true.
         if (self%jac%active() .and. self%jac_age > 0) then
            call block_jacobian(self, deriv, t, y, error)
            if (allocated(error)) return
         end if
         if (at_min) then
            ! report 4.4.12: an attempt the derivative refuses (or that is not finite) is
            ! retried with a reduced step; under ADORE's rule (accept_at_h_min) below the
            ! minimum too, halving down to SUB_MIN_FLOOR of it (issue #28)
            if (.not. (self%settings%accept_at_h_min .and. (flag == DERIV_REJECT_STEP .or. &
                                                            .not. ieee_is_finite(err) .or. gross) .and. &
                       h > SUB_MIN_FLOOR*h_min*1.000001_wp)) then
               if (h < h_min) then
                  call stop_error(self, error, "step driven below the minimum step size (Rec 2.1 step_min) "// &
                                  "and refused down to 1/"//itoa(nint(1.0_wp/SUB_MIN_FLOOR))//" of it", t, h, ": "//why)
               else
                  call stop_error(self, error, "step driven below the minimum step size (Rec 2.1 step_min)", &
                                  t, h, ": "//why)
               end if
               return
            end if
            h = max(0.5_wp*h, SUB_MIN_FLOOR*h_min)
            below_min = .true.
         else
            h = max(fac*h, h_min)
         end if
         clipped = .false.
         if (present(t_limit)) then
            if (t + h >= t_limit) then      ! never step past t_limit
               h = t_limit - t
               clipped = .true.
            end if
         end if
      end do
      if (tries > self%settings%max_rejections) then
         call stop_error(self, error, itoa(tries)//" consecutive rejected attempts", t, h, "; last: "//why)
         return
      end if

      ! accepted: statistics, the new state, the next step (PI controller, HNW II.4 eq 4.13)
      associate (st => self%stats)
         st%accepted = st%accepted + 1
         if (below_min) st%below_h_min = st%below_h_min + 1
         if (below_min .and. gross_seen) st%below_h_min_error = st%below_h_min_error + 1
         if (forced) then
            st%forced_at_h_min = st%forced_at_h_min + 1
            st%forced_err_max = max(st%forced_err_max, err)
            if (err <= 2.0_wp) st%forced_within_2 = st%forced_within_2 + 1
            associate (i => error_leader(self, y))
               st%forced_lead(i) = st%forced_lead(i) + 1
            end associate
         end if
         st%h_last = h
         if (.not. clipped) then
            st%h_min_used = min(st%h_min_used, h)
            st%h_max_used = max(st%h_max_used, h)
         end if
         st%max_truncation = max(st%max_truncation, err_state*self%settings%error_limit)
      end associate
      if (clipped) then
         t = t_limit
      else
         t = t + h
      end if
      y = self%y_new
      if (self%quadrature) then
         call step_quadrature(self, h)
         self%g(:, 1) = self%g(:, self%last)
      end if
      self%k(:, 1) = self%k(:, self%last)
      self%shares_at_start = self%evaluated_new .and. t == self%t_new
      if (self%jac_age >= 0) self%jac_age = self%jac_age + 1
      self%y_fsal = y
      self%t_fsal = t
      fac_err = err**self%alpha
      fac = max(1.0_wp/fac_max, min(1.0_wp/fac_min, fac_err/self%err_old**self%beta/self%settings%safety))
      h = h/fac
      if (rejected_before) h = min(h, self%stats%h_last)
      self%err_old = max(err, err_floor)
      if (clipped) h = max(h, h_plan)   ! a step shortened to land on t_limit does not shrink the plan
      self%h_next = min(max(h, h_min), self%settings%h_max)
   end subroutine step



   !> Integrate from (t, y) to t_out (same unit as t), landing on it; t = t_out on return.
   subroutine advance(self, deriv, t, y, t_out, error)
      class(integrator_t), intent(inout) :: self
      class(derivative_t), intent(inout) :: deriv
      real(wp), intent(inout) :: t
      real(wp), intent(inout) :: y(:)
      real(wp), intent(in) :: t_out
      type(error_type), allocatable, intent(out) :: error

      if (t_out < t) then
         call stop_error(self, error, "t_out is before t (only forward integration)", t, t_out - t)
         return
      end if
      do while (t < t_out)
         call self%step(deriv, t, y, error, t_limit=t_out)
         if (allocated(error)) return
      end do
   end subroutine advance

   !> Make k(:, 1) = f(t, y), reusing the last stage of the previous step when (t, y) is its end.
   subroutine first_stage(self, deriv, t, y, error)
      class(integrator_t), intent(inout) :: self
      class(derivative_t), intent(inout) :: deriv
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: flag
      character(len=:), allocatable :: msg

      if (self%fsal_valid .and. t == self%t_fsal) then
         if (all(y == self%y_fsal)) return
      end if
      call deriv%eval(t, y, self%k(:, 1), flag)
      self%stats%derivative_calls = self%stats%derivative_calls + 1
      self%evaluated_new = .false.
      self%shares_at_start = .false.
      if (flag == DERIV_FAIL) then
         call stop_error(self, error, "the derivative failed", t, self%h_next, deriv=deriv)
      else if (flag == DERIV_REJECT_STEP) then
         call stop_error(self, error, "the derivative flags the state at the start of a step (report "// &
                         "4.4.12), which no smaller step can avoid", t, self%h_next, deriv=deriv)
      else if (.not. all(ieee_is_finite(self%k(:, 1)))) then
         msg = " (non-finite derivatives: "
         call put_bad(msg, self%k(:, 1))
         call stop_error(self, error, "non-finite derivative", t, self%h_next, msg//")")
      end if
      if (allocated(error)) return
      if (self%quadrature) call deriv%quadrature_values(self%g(:, 1))
      self%y_fsal = y
      self%t_fsal = t
      self%fsal_valid = .true.
      self%shares_at_start = .true.
   end subroutine first_stage


   !> The unknown leading the error test's norm of y_err for a step from y to y_new: the index of
   !> its largest weighted component (the first of equals).
   integer function error_leader(self, y) result(i)
      class(integrator_t), intent(in) :: self
      real(wp), intent(in) :: y(:)
      i = maxloc(abs(self%y_err)/(self%settings%error_limit* &
                                  (self%scale + self%settings%rel_weight*max(abs(y), abs(self%y_new)))), 1)
   end function error_leader

   !> The error test's norm of y_err (Rec 2.1 ERROR LIMIT; 1 = at the limit) for a step from y to y_new.
   real(wp) function weighted_error(self, y) result(err)
      class(integrator_t), intent(in) :: self
      real(wp), intent(in) :: y(:)
      err = maxval(abs(self%y_err)/(self%settings%error_limit* &
                                    (self%scale + self%settings%rel_weight*max(abs(y), abs(self%y_new)))))
   end function weighted_error

   !> An engine error "integration stopped: <what> at time t = .. (step h = .., after N accepted
   !> steps)<tail>" (t and h in the unit of t); with deriv, ": <its failure reason>" after it.
   subroutine stop_error(self, error, what, t, h, tail, deriv)
      class(integrator_t), intent(in) :: self
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: what
      real(wp), intent(in) :: t, h
      character(len=*), intent(in), optional :: tail
      class(derivative_t), intent(in), optional :: deriv
      character(len=:), allocatable :: msg
      msg = "integration stopped: "//what//" at time t = "
      call put_real(msg, t)
      msg = msg//" (step h = "
      call put_real(msg, h)
      msg = msg//", after "//itoa(self%stats%accepted)//" accepted steps)"
      if (present(tail)) msg = msg//tail
      if (present(deriv)) then
         if (allocated(deriv%failure_reason)) msg = msg//": "//deriv%failure_reason
      end if
      call engine_error(error, msg)
   end subroutine stop_error

   !> Append x to s as show_real writes it, or "non-finite".
   subroutine put_real(s, x)
      character(len=:), allocatable, intent(inout) :: s
      real(wp), intent(in) :: x
      if (ieee_is_finite(x)) then
         s = s//show_real(x)
      else
         s = s//"non-finite"
      end if
   end subroutine put_real

   !> Append the indices of the first (up to 5) non-finite values of x to s, e.g. "3, 7".
   subroutine put_bad(s, x)
      character(len=:), allocatable, intent(inout) :: s
      real(wp), intent(in) :: x(:)
      integer :: i, m
      m = 0
      do i = 1, size(x)
         if (ieee_is_finite(x(i))) cycle
         if (m > 0) s = s//", "
         s = s//itoa(i)
         m = m + 1
         if (m == 5) exit
      end do
   end subroutine put_bad

end module adore_dynamics_integrator
