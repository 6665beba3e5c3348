!> Flat-array unpacking shared by the quasi-static f2py wrappers (fortran/api/quasistatic.f90).
module adore_api_unpack
   use adore_core_kinds, only: wp
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t, ball_qs_load_t, set_groove_centres
   implicit none
   private

   public :: adore_qs_unpack

contains

   !> Build the solver's bearing and load types from the flat arrays.
   subroutine adore_qs_unpack(n, geom, load, solve_moment, b, ld)
      integer, intent(in) :: n
      real(wp), intent(in) :: geom(13), load(11)
      integer, intent(in) :: solve_moment(2)
      type(ball_qs_bearing_t), intent(out) :: b
      type(ball_qs_load_t), intent(out) :: ld

      b%n_balls = n
      b%d = geom(1)
      b%dm = geom(2)
      b%f_o = geom(3)
      b%f_i = geom(4)
      b%ball_mass = geom(6)
      b%e_ball = geom(7)
      b%nu_ball = geom(8)
      b%e_outer = geom(9)
      b%nu_outer = geom(10)
      b%e_inner = geom(9)
      b%nu_inner = geom(10)
      b%inner_race_mass = geom(13)
      call set_groove_centres(b, geom(5), geom(11), geom(12))
      ld%force = load(1:3)
      ld%moment = load(4:6)
      ld%gravity = load(7:9)
      ld%misalignment = load(10:11)
      ld%solve_moment = solve_moment /= 0
   end subroutine adore_qs_unpack

end module adore_api_unpack
