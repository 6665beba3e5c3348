!> Rolling kinematics of a ball between two races (ADORE initial ball angular velocity,
!> report section 4.4.7, race-control option).
!>
!> In the frame that orbits with the ball (orbital speed w_m about the bearing axis x),
!> the ball spins at w_b about an axis in the meridian (x, r) plane at pitch angle beta:
!> Omega_b = w_b (cos beta, sin beta).  Race j turns at (w_j - w_m).  With the contact
!> normal n_j = (n_jx, n_jr) pointing from the ball centre to the contact centre, the
!> contact centre lies at radius R_j = r_b + D/2 n_jr and
!>     rolling (no slip in the rolling direction at the contact centre):
!>         w_b D/2 (cos beta n_jr - sin beta n_jx) = (w_j - w_m) R_j,      j = o, i
!>     race control on race c (no spin about the normal of that contact):
!>         w_b (cos beta n_cx + sin beta n_cr) + (w_m - w_c) n_cx = 0.
!> The first two equations are linear in (w_m, w_b) for a given beta; beta is found by
!> bisection on the spin equation.  Speeds in rad/s, lengths in m, angles in rad.
module adore_quasistatic_ball_kinematics
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: ball_kinematics_t, race_control_kinematics, CONTROL_OUTER, CONTROL_INNER

   integer, parameter :: CONTROL_OUTER = 1  !< no spin at the outer race contact
   integer, parameter :: CONTROL_INNER = 2  !< no spin at the inner race contact

   !> Result of the kinematic solution for one ball.
   type :: ball_kinematics_t
      real(wp) :: orbital_speed = 0.0_wp  !< w_m, ball orbital speed (rad/s)
      real(wp) :: spin_speed = 0.0_wp     !< w_b, ball angular speed relative to the orbit frame (rad/s)
      real(wp) :: pitch = 0.0_wp          !< beta, angle of the ball spin axis to the bearing axis (rad)
      logical :: ok = .false.             !< .false. when the equations are singular
   end type ball_kinematics_t

contains

   !> Ball orbital and spin speed under race control (report 4.4.7, option kAngVel = race control).
   !>
   !> d ball diameter (m); r_b radius of the ball centre (m); n_o, n_i unit vectors
   !> (axial, radial) from the ball centre to the outer/inner contact centre; w_o, w_i race
   !> speeds (rad/s); control = CONTROL_OUTER or CONTROL_INNER.
   pure function race_control_kinematics(d, r_b, n_o, n_i, w_o, w_i, control) result(k)
      real(wp), intent(in) :: d, r_b, n_o(2), n_i(2), w_o, w_i
      integer, intent(in) :: control
      type(ball_kinematics_t) :: k

      real(wp), parameter :: half_pi = 2.0_wp*atan(1.0_wp)
      integer, parameter :: n_scan = 720
      real(wp) :: lo, hi, mid, f_lo, f_mid, f_hi, b0, b1, best
      integer :: it, j

      ! Scan for sign changes of the spin that are not poles of the rolling equations
      ! (where their determinant vanishes); keep the root nearest to beta = 0.
      best = huge(1.0_wp)
      lo = 0.0_wp
      hi = 0.0_wp
      do j = 0, n_scan - 1
         b0 = -half_pi + 2.0_wp*half_pi*real(j, wp)/n_scan
         b1 = -half_pi + 2.0_wp*half_pi*real(j + 1, wp)/n_scan
         if (determinant(b0)*determinant(b1) <= 0.0_wp) cycle
         f_lo = spin_residual(b0)
         f_hi = spin_residual(b1)
         if (f_lo*f_hi > 0.0_wp) cycle
         if (min(abs(b0), abs(b1)) < best) then
            best = min(abs(b0), abs(b1))
            lo = b0
            hi = b1
         end if
      end do
      if (best == huge(1.0_wp)) return
      f_lo = spin_residual(lo)
      do it = 1, 200
         mid = 0.5_wp*(lo + hi)
         f_mid = spin_residual(mid)
         if (f_lo*f_mid <= 0.0_wp) then
            hi = mid
         else
            lo = mid
            f_lo = f_mid
         end if
         if (hi - lo < 1.0e-15_wp) exit
      end do
      k = rolling(0.5_wp*(lo + hi))

   contains

      !> (w_m, w_b) from the two rolling conditions for pitch angle beta.
      pure function rolling(beta) result(s)
         real(wp), intent(in) :: beta
         type(ball_kinematics_t) :: s
         real(wp) :: a11, a12, a21, a22, b1, b2, det, r_o, r_i

         r_o = r_b + 0.5_wp*d*n_o(2)
         r_i = r_b + 0.5_wp*d*n_i(2)
         ! unknowns (w_m, w_b):  w_b D/2 c_j + w_m R_j = w_j R_j
         a11 = r_o
         a12 = 0.5_wp*d*(cos(beta)*n_o(2) - sin(beta)*n_o(1))
         a21 = r_i
         a22 = 0.5_wp*d*(cos(beta)*n_i(2) - sin(beta)*n_i(1))
         b1 = w_o*r_o
         b2 = w_i*r_i
         det = a11*a22 - a12*a21
         s%pitch = beta
         if (abs(det) <= epsilon(1.0_wp)*(abs(a11*a22) + abs(a12*a21))) return
         s%orbital_speed = (b1*a22 - a12*b2)/det
         s%spin_speed = (a11*b2 - a21*b1)/det
         s%ok = .true.
      end function rolling

      !> Spin about the normal of the controlling contact for pitch angle beta (rad/s).
      pure function spin_residual(beta) result(f)
         real(wp), intent(in) :: beta
         real(wp) :: f, n(2), w_c
         type(ball_kinematics_t) :: s

         s = rolling(beta)
         if (control == CONTROL_INNER) then
            n = n_i
            w_c = w_i
         else
            n = n_o
            w_c = w_o
         end if
         f = s%spin_speed*(cos(beta)*n(1) + sin(beta)*n(2)) + (s%orbital_speed - w_c)*n(1)
      end function spin_residual

      !> Determinant of the rolling equations for pitch angle beta.
      pure function determinant(beta) result(det)
         real(wp), intent(in) :: beta
         real(wp) :: det
         det = (r_b + 0.5_wp*d*n_o(2))*0.5_wp*d*(cos(beta)*n_i(2) - sin(beta)*n_i(1)) &
               - 0.5_wp*d*(cos(beta)*n_o(2) - sin(beta)*n_o(1))*(r_b + 0.5_wp*d*n_i(2))
      end function determinant

   end function race_control_kinematics

end module adore_quasistatic_ball_kinematics
