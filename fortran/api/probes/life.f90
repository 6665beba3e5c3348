!> Flat f2py wrappers of the fatigue life model (test-only module pyadore._probes).

!> Default fatigue constants (report section 3.2, Tables 3-4, Appendix C echo).
!>
!> constants(30) in the order documented at life_params_to_array
!> (fortran/life/lundberg_palmgren.f90); units SI.
subroutine adore_life_default_constants(constants)
   use adore_core_kinds, only: wp
   use adore_life_lundberg_palmgren, only: life_params_t, life_params_to_array
   implicit none
   real(wp), intent(out) :: constants(30)

   type(life_params_t) :: defaults

   constants = life_params_to_array(defaults)   ! shapes checked at compile time (LIFE_N_CONSTANTS = 30)
end subroutine adore_life_default_constants

!> Basic (Lundberg-Palmgren) and modified (Tallian) life of a ball bearing,
!> report eqs 73-74, 77-109, 102.
!>
!> Per ball k = 1..m (in ball order, which weights eq 104 of a rotating race):
!> q_outer, q_inner contact loads (N); alpha_outer, alpha_inner contact angles
!> (rad); orbital_speed (rpm); p_max_outer, p_max_inner max Hertz pressure (Pa);
!> lambda_outer, lambda_inner film thickness / composite RMS height (-, <= 0:
!> no film); mu_outer, mu_inner EHD traction coefficients (-).
!> hoop_outer, hoop_inner race hoop stress (Pa); d_ball, d_pitch (m); f_outer,
!> f_inner groove curvature factors; outer_speed, inner_speed race speeds (rpm);
!> outer_rotating, inner_rotating = 1 when the race turns relative to the load;
!> constants(30) as adore_life_default_constants.
!> result = [basic outer, basic inner, basic bearing, modified outer,
!>           modified inner, modified bearing (all hours), Psi outer, Psi inner];
!> lives_outer, lives_inner: contact lives (10**6 relative revolutions).
!> A life of huge (1.8e308) means "never fails" (no loaded contact).
subroutine adore_life_ball_bearing(m, q_outer, q_inner, alpha_outer, alpha_inner, orbital_speed, &
                                   p_max_outer, p_max_inner, lambda_outer, lambda_inner, mu_outer, mu_inner, &
                                   hoop_outer, hoop_inner, d_ball, d_pitch, f_outer, f_inner, &
                                   outer_speed, inner_speed, outer_rotating, inner_rotating, constants, &
                                   result, lives_outer, lives_inner, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_life_lundberg_palmgren, only: life_params_t, life_params_from_array, pass_cycles, &
      ball_race_lp_life, bearing_life, life_hours
   use adore_life_tallian, only: ball_race_modified_life
   implicit none
   integer, intent(in) :: m
   real(wp), intent(in) :: q_outer(m), q_inner(m), alpha_outer(m), alpha_inner(m), orbital_speed(m)
   real(wp), intent(in) :: p_max_outer(m), p_max_inner(m), lambda_outer(m), lambda_inner(m)
   real(wp), intent(in) :: mu_outer(m), mu_inner(m)
   real(wp), intent(in) :: hoop_outer, hoop_inner, d_ball, d_pitch, f_outer, f_inner
   real(wp), intent(in) :: outer_speed, inner_speed
   integer, intent(in) :: outer_rotating, inner_rotating
   real(wp), intent(in) :: constants(30)
   real(wp), intent(out) :: result(8), lives_outer(m), lives_inner(m)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(life_params_t) :: p
   real(wp) :: n_o, n_i, m_o, m_i, psi_o, psi_i, rel

   result = 0.0_wp
   lives_outer = 0.0_wp
   lives_inner = 0.0_wp
   status = ADORE_INPUT_ERROR
   message = ""
   rel = abs(inner_speed - outer_speed)
   if (m < 1) then
      message = "life: need at least one rolling element"
   else if (any(alpha_outer /= alpha_outer) .or. any(alpha_inner /= alpha_inner) .or. &
            any(orbital_speed /= orbital_speed) .or. any(q_outer /= q_outer) .or. any(q_inner /= q_inner) .or. &
            any(p_max_outer /= p_max_outer) .or. any(p_max_inner /= p_max_inner)) then
      message = "life: loads, contact angles, orbital speeds and pressures must be numbers (NaN given)"
   else if (d_ball <= 0.0_wp .or. d_pitch <= d_ball) then
      message = "life: need 0 < ball diameter < pitch diameter"
   else if (f_outer <= 0.5_wp .or. f_inner <= 0.5_wp) then
      message = "life: groove curvature factors must exceed 0.5"
   else if (rel <= 0.0_wp) then
      message = "life: the races do not turn relative to each other (inner speed = outer speed)"
   else if (any(q_outer < 0.0_wp) .or. any(q_inner < 0.0_wp)) then
      message = "life: contact loads must be >= 0"
   else if (any(q_outer > 0.0_wp .and. p_max_outer <= 0.0_wp) .or. any(q_inner > 0.0_wp .and. p_max_inner <= 0.0_wp)) then
      message = "life: a loaded contact needs a maximum Hertz pressure > 0"
   else if (any(constants(1:12) <= 0.0_wp) .or. constants(10) <= 1.0_wp) then
      message = "life: constants 1-12 must be > 0 and beta (constant 10) > 1"
   else if (constants(22) < 0.0_wp .or. constants(23) <= 0.0_wp .or. constants(28) <= 0.0_wp) then
      message = "life: need sigma_rms >= 0, theta_rms > 0 and E' > 0 (constants 22, 23, 28)"
   else if (constants(29) /= 0.0_wp .and. constants(29) /= 1.0_wp) then
      message = "life: stationary_rule (constant 29) must be 0 (report) or 1 (Lundberg-Palmgren)"
   else if (.not. (constants(30) > 0.0_wp)) then
      message = "life: line_length_factor (constant 30) must be > 0"
   else
      status = ADORE_OK
   end if
   if (status /= ADORE_OK) return

   p = life_params_from_array(constants)
   call ball_race_lp_life(p, q_outer, alpha_outer, pass_cycles(orbital_speed, outer_speed, inner_speed, outer_speed), &
                          f_outer, d_ball, d_pitch, .true., outer_rotating /= 0, lives_outer, n_o)
   call ball_race_lp_life(p, q_inner, alpha_inner, pass_cycles(orbital_speed, inner_speed, inner_speed, outer_speed), &
                          f_inner, d_ball, d_pitch, .false., inner_rotating /= 0, lives_inner, n_i)
   call ball_race_modified_life(p, lives_outer, n_o, p_max_outer, lambda_outer, mu_outer, hoop_outer, &
                                outer_rotating /= 0, psi_o, m_o)
   call ball_race_modified_life(p, lives_inner, n_i, p_max_inner, lambda_inner, mu_inner, hoop_inner, &
                                inner_rotating /= 0, psi_i, m_i)
   result = [life_hours(n_o, rel), life_hours(n_i, rel), life_hours(bearing_life(n_o, n_i, p%weibull_e_point), rel), &
             life_hours(m_o, rel), life_hours(m_i, rel), life_hours(bearing_life(m_o, m_i, p%weibull_e_point), rel), &
             psi_o, psi_i]
end subroutine adore_life_ball_bearing
