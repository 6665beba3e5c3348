!> Flat f2py wrappers of the ball-bearing quasi-static solution (test-only module
!> pyadore._probes).
!>
!> geom(13) = [D, d_m, f_o, f_i, alpha0 (rad), ball mass (kg), E ball (Pa), nu ball,
!>             E races (Pa), nu races, inner raceway growth (m), outer raceway shrink (m),
!>             inner race mass (kg)]
!> load(11) = [force x, y, z (N), moment x, y, z (N m), gravity x, y, z (m/s**2),
!>             prescribed misalignment theta_2, theta_3 (rad)]
!> solve_moment(2): 1 = moment equilibrium about y / z (kFS4/kFS5 = 0), 0 = prescribed.

!> Quasi-static equilibrium of a ball bearing for given orbital speeds (rad/s),
!> report section 3.1 eqs 54-72.
!>
!> balls(n, 15): per ball [x, r (m), alpha_o, alpha_i (rad), Q_o, Q_i (N), delta_o,
!>   delta_i (m), a_o, a_i, b_o, b_i (m, major/minor half widths), p_o, p_i (Pa),
!>   centrifugal force (N)];
!> race(25): [u(5) (m, rad), inner force(3), inner moment(3), outer force(3),
!>   outer moment(3) (forces of the balls on the races, N, N m), race residual(5),
!>   largest ball residual (N), race Newton iterations].
subroutine adore_ball_qs(n, geom, load, solve_moment, orbital_speed, balls, race, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t, ball_qs_load_t, ball_qs_solution_t, &
                                                 solve_ball_equilibrium
   use adore_api_unpack, only: adore_qs_unpack
   implicit none
   integer, intent(in) :: n
   real(wp), intent(in) :: geom(13), load(11), orbital_speed(n)
   integer, intent(in) :: solve_moment(2)
   real(wp), intent(out) :: balls(n, 15), race(25)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(ball_qs_bearing_t) :: b
   type(ball_qs_load_t) :: ld
   type(ball_qs_solution_t) :: sol
   type(error_type), allocatable :: error

   status = ADORE_OK
   message = ""
   balls = 0.0_wp
   race = 0.0_wp
   call adore_qs_unpack(n, geom, load, solve_moment, b, ld)
   call solve_ball_equilibrium(b, ld, orbital_speed, sol, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   balls(:, 1) = sol%x
   balls(:, 2) = sol%r
   balls(:, 3) = sol%alpha_o
   balls(:, 4) = sol%alpha_i
   balls(:, 5) = sol%q_o
   balls(:, 6) = sol%q_i
   balls(:, 7) = sol%delta_o
   balls(:, 8) = sol%delta_i
   balls(:, 9) = sol%c_o%semi_major
   balls(:, 10) = sol%c_i%semi_major
   balls(:, 11) = sol%c_o%semi_minor
   balls(:, 12) = sol%c_i%semi_minor
   balls(:, 13) = sol%c_o%max_pressure
   balls(:, 14) = sol%c_i%max_pressure
   balls(:, 15) = sol%centrifugal
   race(1:5) = sol%u
   race(6:8) = sol%inner_force
   race(9:11) = sol%inner_moment
   race(12:14) = sol%outer_force
   race(15:17) = sol%outer_moment
   race(18:22) = sol%race_residual
   race(23) = sol%max_ball_residual
   race(24) = real(sol%iterations, wp)
end subroutine adore_ball_qs

!> Inner race residual (N, N m) and its analytic Jacobian at race position u (5), after
!> solving the equilibrium once (warm start for the ball positions), for checking the
!> Jacobian against finite differences.  Stiffnesses are those of the equilibrium.
subroutine adore_ball_race_jacobian(n, geom, load, solve_moment, orbital_speed, u, res, jac, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t, ball_qs_load_t, ball_qs_solution_t, &
                                                 solve_ball_equilibrium, race_residual
   use adore_api_unpack, only: adore_qs_unpack
   implicit none
   integer, intent(in) :: n
   real(wp), intent(in) :: geom(13), load(11), orbital_speed(n), u(5)
   integer, intent(in) :: solve_moment(2)
   real(wp), intent(out) :: res(5), jac(5, 5)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(ball_qs_bearing_t) :: b
   type(ball_qs_load_t) :: ld
   type(ball_qs_solution_t) :: sol
   type(error_type), allocatable :: error

   status = ADORE_OK
   message = ""
   res = 0.0_wp
   jac = 0.0_wp
   call adore_qs_unpack(n, geom, load, solve_moment, b, ld)
   call solve_ball_equilibrium(b, ld, orbital_speed, sol, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   call race_residual(b, ld, u, sol, res, jac)
end subroutine adore_ball_race_jacobian

!> Ball orbital speed, spin speed (rad/s) and spin-axis pitch (rad) under race control
!> (report 4.4.7).  n_o, n_i: unit vectors (axial, radial) ball centre -> contact;
!> control: 1 outer, 2 inner race control.  kin = [w_m, w_b, beta].
subroutine adore_race_control(d, r_b, n_o, n_i, w_o, w_i, control, kin, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_quasistatic_ball_kinematics, only: ball_kinematics_t, race_control_kinematics
   implicit none
   real(wp), intent(in) :: d, r_b, n_o(2), n_i(2), w_o, w_i
   integer, intent(in) :: control
   real(wp), intent(out) :: kin(3)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(ball_kinematics_t) :: k

   status = ADORE_OK
   message = ""
   k = race_control_kinematics(d, r_b, n_o, n_i, w_o, w_i, control)
   kin = [k%orbital_speed, k%spin_speed, k%pitch]
   if (.not. k%ok) then
      status = ADORE_INPUT_ERROR
      message = "race control kinematics: no solution for this contact geometry"
   end if
end subroutine adore_race_control

!> Race mounting: effective fits, raceway displacements and internal clearance
!> (fortran/geometry/fits.f90).  rings(5, 4): columns shaft, inner race, outer race,
!> housing; rows [inner diameter, outer diameter (m), E (Pa), nu, density (kg/m**3)]
!> (inner race outer diameter and outer race inner diameter: equivalent raceway-side
!> diameters).  fits = [inner, outer] mounted diametral interference (m);
!> speeds = [inner, outer] race speed (rad/s); dia_play: unmounted diametral play (m).
!> result(7) = [inner fit, outer fit (m), inner, outer interface pressure (Pa),
!> inner raceway growth, outer raceway shrink (m), internal clearance (m)].
subroutine adore_mount_races(rings, fits, speeds, dia_play, result, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_geometry_fits, only: ring_t, mounting_t, mount_races
   implicit none
   real(wp), intent(in) :: rings(5, 4), fits(2), speeds(2), dia_play
   real(wp), intent(out) :: result(7)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(ring_t) :: r(4)
   type(mounting_t) :: m
   integer :: j

   status = ADORE_OK
   message = ""
   result = 0.0_wp
   do j = 1, 4
      if (rings(2, j) <= rings(1, j) .or. rings(1, j) < 0.0_wp .or. rings(3, j) <= 0.0_wp) then
         status = ADORE_INPUT_ERROR
         message = "mounting: every ring needs 0 <= inner diameter < outer diameter and E > 0"
         return
      end if
      r(j) = ring_t(rings(1, j), rings(2, j), rings(3, j), rings(4, j), rings(5, j))
   end do
   m = mount_races(r(1), r(2), r(3), r(4), fits(1), fits(2), speeds(1), speeds(2), dia_play)
   result = [m%inner_fit, m%outer_fit, m%inner_pressure, m%outer_pressure, m%inner_raceway_growth, &
             m%outer_raceway_shrink, m%clearance]
end subroutine adore_mount_races
