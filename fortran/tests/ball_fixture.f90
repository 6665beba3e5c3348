!> Fixtures shared by the engine's unit-test programs of the ball bearing force assembly
!> (test_forces, test_traction_fast): the bearing state of a step-0 solution.
module adore_test_ball_fixture
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t
   use adore_state_bearing_state, only: bearing_state_t, new_bearing_state, RACE_OUTER, RACE_INNER
   use adore_driver_ball_step0, only: ball_step0_t
   implicit none
   private

   public :: step0_state

contains

   !> The bearing state of the step-0 solution: balls at their equilibrium positions,
   !> orbiting at w_m with the start's spin (w_b, pitch), races at their speeds, the inner
   !> race at its equilibrium offset (no misalignment in the deck).
   function step0_state(b, s0) result(st)
      type(bearing_t), intent(in) :: b
      type(ball_step0_t), intent(in) :: s0
      type(bearing_state_t) :: st
      real(wp) :: phi, e_r(3), e_t(3), e_x(3), r
      integer :: k

      st = new_bearing_state(b%n_elements)
      st%temperature = b%temperature
      e_x = [1.0_wp, 0.0_wp, 0.0_wp]
      associate (e => s0%start%equilibrium, kin => s0%start%kinematics)
         do k = 1, b%n_elements
            phi = e%azimuth(k)
            r = e%r(k)
            e_r = [0.0_wp, -sin(phi), cos(phi)]
            e_t = [0.0_wp, -cos(phi), -sin(phi)]
            st%elements(k)%position = e%x(k)*e_x + r*e_r
            st%elements(k)%velocity = kin(k)%orbital_speed*r*e_t
            st%elements(k)%omega = (kin(k)%orbital_speed + kin(k)%spin_speed*cos(kin(k)%pitch))*e_x + &
                                   kin(k)%spin_speed*sin(kin(k)%pitch)*e_r
         end do
         st%races(RACE_OUTER)%omega = [b%speed_outer, 0.0_wp, 0.0_wp]
         st%races(RACE_INNER)%omega = [b%speed_inner, 0.0_wp, 0.0_wp]
         st%races(RACE_INNER)%position = e%u(1:3)
      end associate
   end function step0_state

end module adore_test_ball_fixture
