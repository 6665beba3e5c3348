!> Internal clearance and raceway diameters of ball and roller bearings (SI units).
!>
!> Ball bearing (Harris & Kotzalas, Rolling Bearing Analysis, sec. 2.2-2.3): the
!> curvature centres of the two grooves lie (fo + fi - 1) D apart; with the unmounted
!> contact angle a0 the diametral play and end play are
!>     Pd = 2 (fo + fi - 1) D (1 - cos a0),   Pe = 2 (fo + fi - 1) D sin a0.
!> Both reproduce the ADORE 5.0 echo (DIA PLAY, END PLAY) of Appendix C.
module adore_model_clearance
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: ball_diametral_play, ball_end_play, ball_groove_diameters, roller_race_diameters

contains

   !> Unmounted diametral play Pd (m) of a ball bearing: 2 (fo+fi-1) D (1 - cos a0).
   !> d: ball diameter (m); fo, fi: outer/inner curvature factors; alpha0: free contact angle (rad).
   pure function ball_diametral_play(d, fo, fi, alpha0) result(pd)
      real(wp), intent(in) :: d, fo, fi, alpha0
      real(wp) :: pd

      pd = 2.0_wp*(fo + fi - 1.0_wp)*d*(1.0_wp - cos(alpha0))
   end function ball_diametral_play

   !> Unmounted end play Pe (m) of a ball bearing: 2 (fo+fi-1) D sin a0 (arguments as above).
   pure function ball_end_play(d, fo, fi, alpha0) result(pe)
      real(wp), intent(in) :: d, fo, fi, alpha0
      real(wp) :: pe

      pe = 2.0_wp*(fo + fi - 1.0_wp)*d*sin(alpha0)
   end function ball_end_play

   !> Groove-bottom diameters (m) of the outer and inner race of a ball bearing.
   !>
   !> The ball centre sits on the pitch circle dm and touches both grooves at the free
   !> contact angle a0, so each groove curvature centre lies (f - 1/2) D from the ball
   !> centre along the contact line:
   !>     d_outer = dm + D + 2 (fo - 1/2) D (1 - cos a0),
   !>     d_inner = dm - D - 2 (fi - 1/2) D (1 - cos a0).
   !> d_outer - d_inner - 2 D is the diametral play; the play is split between the races
   !> in the ratio (fo - 1/2) : (fi - 1/2), not half and half.  Derived here: it is the
   !> split that reproduces the race masses and inertias of the Appendix C echo.
   pure subroutine ball_groove_diameters(dm, d, fo, fi, alpha0, d_outer, d_inner)
      real(wp), intent(in) :: dm, d, fo, fi, alpha0
      real(wp), intent(out) :: d_outer, d_inner

      d_outer = dm + d + 2.0_wp*(fo - 0.5_wp)*d*(1.0_wp - cos(alpha0))
      d_inner = dm - d - 2.0_wp*(fi - 0.5_wp)*d*(1.0_wp - cos(alpha0))
   end subroutine ball_groove_diameters

   !> Raceway diameters (m) of a cylindrical roller bearing: dm +/- (D + Pd/2).
   !> dm: pitch diameter, d: roller diameter, pd: diametral play (all m).
   pure subroutine roller_race_diameters(dm, d, pd, d_outer, d_inner)
      real(wp), intent(in) :: dm, d, pd
      real(wp), intent(out) :: d_outer, d_inner

      d_outer = dm + d + 0.5_wp*pd
      d_inner = dm - d - 0.5_wp*pd
   end subroutine roller_race_diameters

end module adore_model_clearance
