!> Butcher tableaux of the explicit embedded Runge-Kutta pairs of the integrator.
!>
!> A pair advances y with the weights b (order p) and estimates the local error with
!> e = b - b_hat, the difference to an embedded solution of order p_hat = p - 1
!> ("local extrapolation": the higher order is propagated).  Both pairs here are FSAL
!> (first same as last): the last stage is evaluated at (t + h, y_new), so it is the first
!> stage of the next step.  Sources: Hairer, Norsett & Wanner, Solving Ordinary
!> Differential Equations I, 2nd ed. (1993), section II.5, Table 5.2 (Dormand-Prince 5(4));
!> Bogacki & Shampine, Appl. Math. Lett. 2 (1989) 321-325 (the 3(2) pair).
!>
!> Also the linearly implicit Rosenbrock-W method ROS34PW2 (Rang & Angermann, BIT 45 (2005)
!> 761-787, Table 4.3 and eq 4.1): 4 stages, order 3 for any approximation W of the Jacobian
!> (a W-method), embedded order 2, L-stable and stiffly accurate.  rosenbrock_tableau_t holds
!> it in the transformed variables of Hairer & Wanner, Solving ODEs II, 2nd ed., section
!> IV.7, eqs 7.25-7.26, which need no Jacobian-vector products.
module adore_dynamics_rk_tableau
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: rk_tableau_t, dormand_prince_54, bogacki_shampine_32
   public :: rosenbrock_tableau_t, ros34pw2, ark_tableau_t, ark436l2sa

   !> One explicit embedded pair: s stages, a (s x s, strictly lower), b, c, e = b - b_hat.
   type :: rk_tableau_t
      character(len=:), allocatable :: name   !< e.g. "Dormand-Prince 5(4)"
      integer :: stages = 0                   !< s, the FSAL stage included
      integer :: order = 0                    !< p, order of the propagated solution
      integer :: error_order = 0              !< p_hat + 1: the error estimate is O(h**error_order)
      real(wp), allocatable :: a(:, :)        !< stage coefficients a(i, j), j < i
      real(wp), allocatable :: b(:)           !< weights of the propagated solution (= a(s, :))
      real(wp), allocatable :: c(:)           !< stage times as fractions of h
      real(wp), allocatable :: e(:)           !< error weights b - b_hat
   end type rk_tableau_t

   !> One Rosenbrock(-W) method in transformed variables (HNW II, IV.7 eq 7.25): with
   !> (1/(h gamma) - J) u_i = f(t + c_i h, y + sum_j a_ij u_j) + sum_j (cc_ij / h) u_j,
   !> y_new = y + sum_i m_i u_i and the error estimate sum_i e_i u_i.
   type :: rosenbrock_tableau_t
      character(len=:), allocatable :: name   !< e.g. "ROS34PW2"
      integer :: stages = 0                   !< s
      integer :: order = 0                    !< p of y_new (as a W-method)
      integer :: error_order = 0              !< the error estimate is O(h**error_order)
      real(wp) :: gamma = 0.0_wp              !< the diagonal gamma_ii
      real(wp), allocatable :: a(:, :)        !< a = alpha Gamma**-1 (strictly lower)
      real(wp), allocatable :: cc(:, :)       !< cc = diag(1/gamma) - Gamma**-1 (strictly lower)
      real(wp), allocatable :: c(:)           !< stage times as fractions of h (row sums of alpha)
      real(wp), allocatable :: m(:)           !< m = b Gamma**-1
      real(wp), allocatable :: e(:)           !< e = (b - b_hat) Gamma**-1
   end type rosenbrock_tableau_t

   !> One additive Runge-Kutta pair (IMEX): an explicit table ae and an ESDIRK table ai (explicit
   !> first stage, constant diagonal gamma) sharing c, b and the embedded b_hat.
   type :: ark_tableau_t
      character(len=:), allocatable :: name
      integer :: stages = 0
      integer :: order = 0
      integer :: error_order = 0              !< the error estimate is O(h**error_order)
      real(wp) :: gamma = 0.0_wp              !< the diagonal of ai
      real(wp), allocatable :: ae(:, :)       !< explicit table (strictly lower)
      real(wp), allocatable :: ai(:, :)       !< implicit table (lower, diagonal gamma from stage 2)
      real(wp), allocatable :: c(:), b(:), e(:)   !< stage times, weights, e = b - b_hat
   end type ark_tableau_t

contains

   !> ARK4(3)6L[2]SA (Kennedy & Carpenter, Appl. Numer. Math. 44 (2003) 139-181, Tables 6-8;
   !> SUNDIALS ARKODE's ARK-6-3-4): 6 stages, order 4, embedded 3; the ESDIRK part L-stable
   !> and stiffly accurate.
   pure function ark436l2sa() result(tab)
      type(ark_tableau_t) :: tab
      tab%name = "ARK4(3)6L[2]SA"
      tab%stages = 6
      tab%order = 4
      tab%error_order = 4
      tab%gamma = 0.25_wp
      allocate (tab%ae(6, 6), tab%ai(6, 6), source=0.0_wp)
      tab%c = [0.0_wp, 0.5_wp, 83.0_wp/250, 31.0_wp/50, 17.0_wp/20, 1.0_wp]
      tab%ae(2, 1) = 0.5_wp
      tab%ae(3, 1:2) = [13861.0_wp/62500, 6889.0_wp/62500]
      tab%ae(4, 1:3) = [-116923316275.0_wp/2393684061468.0_wp, -2731218467317.0_wp/15368042101831.0_wp, &
                        9408046702089.0_wp/11113171139209.0_wp]
      tab%ae(5, 1:4) = [-451086348788.0_wp/2902428689909.0_wp, -2682348792572.0_wp/7519795681897.0_wp, &
                        12662868775082.0_wp/11960479115383.0_wp, 3355817975965.0_wp/11060851509271.0_wp]
      tab%ae(6, 1:5) = [647845179188.0_wp/3216320057751.0_wp, 73281519250.0_wp/8382639484533.0_wp, &
                        552539513391.0_wp/3454668386233.0_wp, 3354512671639.0_wp/8306763924573.0_wp, &
                        4040.0_wp/17871]
      tab%ai(2, 1:2) = [0.25_wp, 0.25_wp]
      tab%ai(3, 1:3) = [8611.0_wp/62500, -1743.0_wp/31250, 0.25_wp]
      tab%ai(4, 1:4) = [5012029.0_wp/34652500, -654441.0_wp/2922500, 174375.0_wp/388108, 0.25_wp]
      tab%ai(5, 1:5) = [15267082809.0_wp/155376265600.0_wp, -71443401.0_wp/120774400, 730878875.0_wp/902184768, &
                        2285395.0_wp/8070912, 0.25_wp]
      tab%b = [82889.0_wp/524892, 0.0_wp, 15625.0_wp/83664, 69875.0_wp/102672, -2260.0_wp/8211, 0.25_wp]
      tab%ai(6, :) = tab%b
      tab%e = tab%b - [4586570599.0_wp/29645900160.0_wp, 0.0_wp, 178811875.0_wp/945068544, &
                       814220225.0_wp/1159782912, -3700637.0_wp/11593932, 61727.0_wp/225920]
   end function ark436l2sa

   !> ROS34PW2 (Rang & Angermann 2005): 4 stages, W-order 3, embedded 2, L-stable, stiffly
   !> accurate (b = the last row of alpha + Gamma).
   pure function ros34pw2() result(tab)
      type(rosenbrock_tableau_t) :: tab
      real(wp) :: alpha(4, 4), gam(4, 4), b(4), b_hat(4)
      alpha = 0.0_wp
      gam = 0.0_wp
      alpha(2, 1) = 8.7173304301691801e-01_wp
      alpha(3, 1:2) = [8.4457060015369423e-01_wp, -1.1299064236484185e-01_wp]
      alpha(4, 1:3) = [0.0_wp, 0.0_wp, 1.0_wp]
      gam(2, 1) = -8.7173304301691801e-01_wp
      gam(3, 1:2) = [-9.0338057013044082e-01_wp, 5.4180672388095326e-02_wp]
      gam(4, 1:3) = [2.4212380706095346e-01_wp, -1.2232505839045147e+00_wp, 5.4526025533510214e-01_wp]
      b = [2.4212380706095346e-01_wp, -1.2232505839045147e+00_wp, 1.5452602553351020e+00_wp, &
           4.3586652150845900e-01_wp]
      b_hat = [3.7810903145819369e-01_wp, -9.6042292212423178e-02_wp, 0.5_wp, 2.1793326075422950e-01_wp]
      tab = rosenbrock_transformed("ROS34PW2", 3, 4.3586652150845900e-01_wp, alpha, gam, b, b_hat)
   end function ros34pw2

   !> The transformed tableau (HNW II, IV.7 eq 7.26) of the method (alpha, gamma on the
   !> diagonal with the strictly lower gam, weights b, embedded b_hat); error order p_hat + 1.
   pure function rosenbrock_transformed(name, p, gamma, alpha, gam, b, b_hat) result(tab)
      character(len=*), intent(in) :: name
      integer, intent(in) :: p
      real(wp), intent(in) :: gamma, alpha(:, :), gam(:, :), b(:), b_hat(:)
      type(rosenbrock_tableau_t) :: tab
      real(wp) :: g(size(b), size(b)), gi(size(b), size(b))
      integer :: s, i, j
      s = size(b)
      g = gam
      do i = 1, s
         g(i, i) = gamma
      end do
      ! inverse of the lower triangular Gamma, column by column (forward substitution)
      gi = 0.0_wp
      do j = 1, s
         gi(j, j) = 1.0_wp/gamma
         do i = j + 1, s
            gi(i, j) = -dot_product(g(i, j:i - 1), gi(j:i - 1, j))/gamma
         end do
      end do
      tab%name = name
      tab%stages = s
      tab%order = p
      tab%error_order = p
      tab%gamma = gamma
      tab%a = matmul(alpha, gi)
      tab%cc = -gi
      do i = 1, s
         tab%cc(i, i) = 0.0_wp
      end do
      tab%c = sum(alpha, dim=2)
      tab%m = matmul(b, gi)
      tab%e = matmul(b - b_hat, gi)
   end function rosenbrock_transformed

   !> Dormand-Prince 5(4), 7 stages with FSAL (HNW I, Table 5.2; the pair of DOPRI5 and ode45).
   pure function dormand_prince_54() result(tab)
      type(rk_tableau_t) :: tab
      tab%name = "Dormand-Prince 5(4)"
      tab%stages = 7
      tab%order = 5
      tab%error_order = 5
      allocate (tab%a(7, 7), source=0.0_wp)
      tab%c = [0.0_wp, 1.0_wp/5, 3.0_wp/10, 4.0_wp/5, 8.0_wp/9, 1.0_wp, 1.0_wp]
      tab%a(2, 1) = 1.0_wp/5
      tab%a(3, 1:2) = [3.0_wp/40, 9.0_wp/40]
      tab%a(4, 1:3) = [44.0_wp/45, -56.0_wp/15, 32.0_wp/9]
      tab%a(5, 1:4) = [19372.0_wp/6561, -25360.0_wp/2187, 64448.0_wp/6561, -212.0_wp/729]
      tab%a(6, 1:5) = [9017.0_wp/3168, -355.0_wp/33, 46732.0_wp/5247, 49.0_wp/176, -5103.0_wp/18656]
      tab%a(7, 1:6) = [35.0_wp/384, 0.0_wp, 500.0_wp/1113, 125.0_wp/192, -2187.0_wp/6784, 11.0_wp/84]
      tab%b = [tab%a(7, 1:6), 0.0_wp]
      tab%e = [71.0_wp/57600, 0.0_wp, -71.0_wp/16695, 71.0_wp/1920, -17253.0_wp/339200, 22.0_wp/525, &
               -1.0_wp/40]
   end function dormand_prince_54

   !> Bogacki-Shampine 3(2), 4 stages with FSAL (the pair of MATLAB's ode23).
   pure function bogacki_shampine_32() result(tab)
      type(rk_tableau_t) :: tab
      tab%name = "Bogacki-Shampine 3(2)"
      tab%stages = 4
      tab%order = 3
      tab%error_order = 3
      allocate (tab%a(4, 4), source=0.0_wp)
      tab%c = [0.0_wp, 1.0_wp/2, 3.0_wp/4, 1.0_wp]
      tab%a(2, 1) = 1.0_wp/2
      tab%a(3, 1:2) = [0.0_wp, 3.0_wp/4]
      tab%a(4, 1:3) = [2.0_wp/9, 1.0_wp/3, 4.0_wp/9]
      tab%b = [tab%a(4, 1:3), 0.0_wp]
      ! b_hat = [7/24, 1/4, 1/3, 1/8]
      tab%e = [2.0_wp/9 - 7.0_wp/24, 1.0_wp/3 - 1.0_wp/4, 4.0_wp/9 - 1.0_wp/3, -1.0_wp/8]
   end function bogacki_shampine_32

end module adore_dynamics_rk_tableau
