!> Basic (Lundberg-Palmgren) fatigue life of a cylindrical roller bearing from its
!> slice contacts (AFRL-PR-WP-TR-2002-2042 section 3.2, eqs 73, 75, 76, 102).
!>
!> Per roller/race contact k (adore_contact_line_slices, line_contact_t):
!>     Q_e,k = 2a [1/(2a) sum_j q_j**(p e) w_j]**(1/(p e))                     (75)
!>     Q_c,k = B (1 +- gamma)**(29/27) (D/d_m)**(2/9) D**(29/27) l**(7/9) n_k**(-1/4)  (76)
!>     N_k   = (Q_e,k / Q_c,k)**(-p)                                          (73)
!> with the slice loads per unit length q_j (N/m) and Gauss weights w_j (m, sum = 2a),
!> contact angle 0 (gamma = D/d_m), l = params%line_length_factor * 2a and
!> n_k = cycle_factor * passes (pass_cycles).  Races combine as race_life (rotating:
!> 1/N = sum 1/N_k; stationary: params%stationary_rule) with e = weibull_e_line, the
!> bearing by eq 102 with the same e.  The choices that reproduce the report and their
!> literature alternatives are in adore_life_lundberg_palmgren and docs/life-model.md.
module adore_life_roller
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_contact_line_slices, only: line_contact_t
   use adore_life_lundberg_palmgren, only: life_params_t, line_contact_lp_life, race_life, pass_cycles, &
                                           bearing_life, life_hours
   implicit none
   private

   public :: roller_lives_t, roller_race_lp_life, roller_bearing_lp_life


   !> Basic lives of a roller bearing.  huge(1.0_wp) means "never fails".
   type :: roller_lives_t
      real(wp) :: outer_hours = 0.0_wp     !< outer race (h)
      real(wp) :: inner_hours = 0.0_wp     !< inner race (h)
      real(wp) :: bearing_hours = 0.0_wp   !< bearing, eq 102 (h)
      real(wp) :: outer_mrev = 0.0_wp      !< outer race (10**6 relative race revolutions)
      real(wp) :: inner_mrev = 0.0_wp      !< inner race (10**6 relative race revolutions)
      real(wp) :: bearing_mrev = 0.0_wp    !< bearing (10**6 relative race revolutions)
   end type roller_lives_t

contains

   !> Basic life of one race of a cylindrical roller bearing (10**6 relative race
   !> revolutions), eqs 73, 75, 76 and the race summation of race_life.
   !>
   !> contacts(k): roller k's slice contact with this race (slice loads q in N/m, weights
   !> in m); passes(k): roller passes over a race point per relative revolution
   !> (pass_cycles); d_roller, d_pitch (m); outer: outer race (+ sign of 1 +- gamma);
   !> rotating: the race turns relative to the load.  lives(k): contact lives (huge for a
   !> contact out of contact); n_race: the race life.
   pure subroutine roller_race_lp_life(params, contacts, passes, d_roller, d_pitch, outer, rotating, lives, n_race)
      type(life_params_t), intent(in) :: params
      type(line_contact_t), intent(in) :: contacts(:)
      real(wp), intent(in) :: passes(:), d_roller, d_pitch
      logical, intent(in) :: outer, rotating
      real(wp), intent(out) :: lives(size(contacts))
      real(wp), intent(out) :: n_race

      integer :: k

      lives = huge(1.0_wp)
      do k = 1, size(contacts)
         if (.not. contacts(k)%in_contact .or. .not. allocated(contacts(k)%q) .or. &
             .not. allocated(contacts(k)%weight)) cycle
         lives(k) = line_contact_lp_life(params, contacts(k)%q, contacts(k)%weight, 0.0_wp, d_roller, d_pitch, &
                                         passes(k), outer)
      end do
      n_race = race_life(lives, rotating, params%weibull_e_line, params%stationary_rule > 0.5_wp)
   end subroutine roller_race_lp_life

   !> Basic life of a cylindrical roller bearing (outer, inner race and bearing; hours and
   !> 10**6 relative race revolutions), eqs 73, 75, 76, 102.
   !>
   !> c_o(k), c_i(k): roller k's outer and inner slice contacts; orbital_speed(k), and the
   !> race speeds outer_speed, inner_speed (rad/s); d_roller, d_pitch (m).  The applied
   !> load is fixed in space, so a race rotates relative to the load when its speed is not
   !> zero.  Hours are counted at the relative race speed |inner - outer|; races that do not
   !> turn relative to each other never fail (huge).
   pure subroutine roller_bearing_lp_life(params, c_o, c_i, orbital_speed, outer_speed, inner_speed, &
                                          d_roller, d_pitch, lives)
      type(life_params_t), intent(in) :: params
      type(line_contact_t), intent(in) :: c_o(:), c_i(:)
      real(wp), intent(in) :: orbital_speed(:), outer_speed, inner_speed, d_roller, d_pitch
      type(roller_lives_t), intent(out) :: lives

      real(wp) :: lives_o(size(c_o)), lives_i(size(c_i)), rel_rpm

      call roller_race_lp_life(params, c_o, pass_cycles(orbital_speed, outer_speed, inner_speed, outer_speed), &
                               d_roller, d_pitch, .true., outer_speed /= 0.0_wp, lives_o, lives%outer_mrev)
      call roller_race_lp_life(params, c_i, pass_cycles(orbital_speed, inner_speed, inner_speed, outer_speed), &
                               d_roller, d_pitch, .false., inner_speed /= 0.0_wp, lives_i, lives%inner_mrev)
      lives%bearing_mrev = bearing_life(lives%outer_mrev, lives%inner_mrev, params%weibull_e_line)
      rel_rpm = abs(inner_speed - outer_speed)*30.0_wp/pi
      lives%outer_hours = life_hours(lives%outer_mrev, rel_rpm)
      lives%inner_hours = life_hours(lives%inner_mrev, rel_rpm)
      lives%bearing_hours = life_hours(lives%bearing_mrev, rel_rpm)
   end subroutine roller_bearing_lp_life

end module adore_life_roller
