!> Basic (Lundberg-Palmgren) fatigue life of a ball bearing from its contact loads (report
!> eqs 73-74 and 102), shared by the quasi-static start (adore_start_ball_step0) and the
!> dynamic steps (adore_output_ball_dynamic_report): inner race rotating, outer race
!> stationary, as ADORE's start (docs/life-model.md).
module adore_life_ball_life
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_model_bearing, only: bearing_t
   use adore_life_lundberg_palmgren, only: life_params_t, ball_race_lp_life, pass_cycles, bearing_life, life_hours
   implicit none
   private

   public :: ball_basic_life

contains

   !> Basic life of ball bearing b with per-ball contact loads q_o, q_i (N), contact angles
   !> alpha_o, alpha_i (rad) and orbital speeds orbital (rad/s), life constants lp: the
   !> contact lives (10**6 relative revolutions) lives_o, lives_i, the race lives n_o, n_i
   !> and hours = [bearing, outer race, inner race] lives in hours at the races' relative
   !> speed (huge() for a race without load).
   pure subroutine ball_basic_life(b, lp, q_o, alpha_o, q_i, alpha_i, orbital, lives_o, lives_i, n_o, n_i, hours)
      type(bearing_t), intent(in) :: b
      type(life_params_t), intent(in) :: lp
      real(wp), intent(in) :: q_o(:), alpha_o(:), q_i(:), alpha_i(:), orbital(:)
      real(wp), intent(out) :: lives_o(size(q_o)), lives_i(size(q_i)), n_o, n_i, hours(3)
      real(wp) :: speed_rpm(size(orbital)), wi_rpm, wo_rpm

      speed_rpm = orbital*30.0_wp/pi
      wi_rpm = b%speed_inner*30.0_wp/pi
      wo_rpm = b%speed_outer*30.0_wp/pi
      call ball_race_lp_life(lp, q_o, alpha_o, pass_cycles(speed_rpm, wo_rpm, wi_rpm, wo_rpm), &
                             b%ball%f_o, b%d, b%dm, .true., .false., lives_o, n_o)
      call ball_race_lp_life(lp, q_i, alpha_i, pass_cycles(speed_rpm, wi_rpm, wi_rpm, wo_rpm), &
                             b%ball%f_i, b%d, b%dm, .false., .true., lives_i, n_i)
      hours = [life_hours(bearing_life(n_o, n_i, lp%weibull_e_point), wi_rpm - wo_rpm), &
               life_hours(n_o, wi_rpm - wo_rpm), life_hours(n_i, wi_rpm - wo_rpm)]
   end subroutine ball_basic_life

end module adore_life_ball_life
