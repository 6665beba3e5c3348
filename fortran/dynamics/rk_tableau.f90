!> Butcher tableaux of the explicit embedded Runge-Kutta pairs of the integrator.
!>
!> A pair advances y with the weights b (order p) and estimates the local error with
!> e = b - b_hat, the difference to an embedded solution of order p_hat = p - 1
!> ("local extrapolation": the higher order is propagated).  Both pairs here are FSAL
!> (first same as last): the last stage is evaluated at (t + h, y_new), so it is the first
!> stage of the next step.  Sources: Hairer, Norsett & Wanner, Solving Ordinary
!> Differential Equations I, 2nd ed. (1993), section II.5, Table 5.2 (Dormand-Prince 5(4));
!> Bogacki & Shampine, Appl. Math. Lett. 2 (1989) 321-325 (the 3(2) pair).
module adore_dynamics_rk_tableau
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: rk_tableau_t, dormand_prince_54, bogacki_shampine_32

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

contains

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
