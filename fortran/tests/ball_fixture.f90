!> Fixtures shared by the engine's unit-test programs of the ball bearing force assembly
!> (test_forces, test_traction_fast, test_cage_contacts, test_mixed_film): Appendix C's step
!> 0 under race control, the bearing state of a step-0 solution and the mechanical power of
!> a load difference on a body.
module adore_test_ball_fixture
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t
   use adore_state_bearing_state, only: bearing_state_t, new_bearing_state, RACE_OUTER, RACE_INNER
   use adore_start_ball_step0, only: ball_step0_t, solve_ball_step0
   use adore_core_error, only: error_type
   use adore_model_from_deck, only: read_bearing
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_quasistatic_ball_kinematics, only: CONTROL_OUTER
   use adore_test_support, only: check, finish, get_decks_dir
   use adore_state_bearing_state, only: body_state_t
   use adore_forces_ball_bearing, only: body_load_t, ball_bearing_loads_t
   use adore_core_rotation, only: quat_matrix
   implicit none
   private

   public :: step0_state, appendix_c_race_control, power_of, loads_power

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

   !> The Appendix C deck (decks/ directory of the test's argument) read, mounted and its
   !> step 0 solved under outer race control; a failure is reported and ends the test
   !> program `suite` (adore_test_support's finish).
   subroutine appendix_c_race_control(suite, b, g, s0)
      character(len=*), intent(in) :: suite
      type(bearing_t), intent(out) :: b
      type(mounted_geometry_t), intent(out) :: g
      type(ball_step0_t), intent(out) :: s0
      character(len=:), allocatable :: decks
      type(error_type), allocatable :: error
      call get_decks_dir(decks)
      call read_bearing(decks//"/appendix_c_ball.inp", b, error)
      call check(.not. allocated(error), "read the Appendix C deck")
      if (allocated(error)) call finish(suite)
      g = mount_geometry(b, b%temperature)
      call solve_ball_step0(b, s0, error, CONTROL_OUTER)
      call check(.not. allocated(error), "step 0 of Appendix C with race control")
      if (allocated(error)) call finish(suite)
   end subroutine appendix_c_race_control

   !> Mechanical power (W) of the load difference lw - lo on body bs (force . velocity +
   !> moment . inertial angular velocity): the traction power identity of test_forces and
   !> test_mixed_film.
   real(wp) function power_of(bs, lw, lo)
      type(body_state_t), intent(in) :: bs
      type(body_load_t), intent(in) :: lw, lo
      real(wp) :: r(3, 3)
      r = quat_matrix(bs%attitude)
      power_of = dot_product(lw%force - lo%force, bs%velocity) + &
                 dot_product(lw%moment - lo%moment, matmul(r, bs%omega))
   end function power_of

   !> Mechanical power (W) of the load difference lw - lo on every ball and both races of
   !> state st (power_of summed): with lo the loads without traction, the traction's power.
   real(wp) function loads_power(st, lw, lo)
      type(bearing_state_t), intent(in) :: st
      type(ball_bearing_loads_t), intent(in) :: lw, lo
      integer :: k, j
      loads_power = 0.0_wp
      do k = 1, size(st%elements)
         loads_power = loads_power + power_of(st%elements(k), lw%elements(k), lo%elements(k))
      end do
      do j = 1, 2
         loads_power = loads_power + power_of(st%races(j), lw%races(j), lo%races(j))
      end do
   end function loads_power

end module adore_test_ball_fixture
