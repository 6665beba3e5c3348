!> Flat f2py wrappers of the step-0 tribology building blocks (test-only module
!> pyadore._probes): film thickness, thermal reduction factor, contact slip / traction,
!> flash temperature, wear (report sections 2.1, 2.7-2.8).

!> Hamrock-Dowson central film thickness h (m); see adore_tribology_film.
subroutine adore_tribo_film(rx, k, u, q, e_prime, eta0, alpha, h, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_tribology_film, only: central_film_thickness
   implicit none
   real(wp), intent(in) :: rx, k, u, q, e_prime, eta0, alpha
   real(wp), intent(out) :: h
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error

   status = ADORE_OK
   message = ""
   call central_film_thickness(rx, k, u, q, e_prime, eta0, alpha, h, error)
   if (allocated(error)) then
      call set_error(error, status, message)
   end if
end subroutine adore_tribo_film

!> Thermal reduction factor phi(1:n) (Gupta et al. 1992) for max pressure p_h (Pa),
!> E' (Pa), thermal loading l(1:n) and slide-to-roll ratio s.
subroutine adore_tribo_thermal_factor(n, p_h, e_prime, l, s, phi, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_tribology_film, only: thermal_reduction_factor
   implicit none
   integer, intent(in) :: n
   real(wp), intent(in) :: p_h, e_prime, l(n), s
   real(wp), intent(out) :: phi(n)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   phi = 0.0_wp
   status = ADORE_INPUT_ERROR
   if (.not. (p_h > 0.0_wp .and. e_prime > 0.0_wp)) then
      message = "thermal reduction factor: need p_h > 0 and E' > 0"
   else if (.not. all(l >= 0.0_wp)) then
      message = "thermal reduction factor: thermal loading L must be >= 0"
   else
      status = ADORE_OK
      message = ""
      phi = thermal_reduction_factor(p_h, e_prime, l, s)
   end if
end subroutine adore_tribo_thermal_factor

!> Ball/race contact traction.  geom = [side (+1 outer, -1 inner), alpha (rad), rho (m),
!> r_b (m), w_x, w_r (rad/s), Omega - w_m (rad/s), a (m), Q (N)]; coef = [A, B, C, D].
!> result = [force (N), coefficient, power (W), max slip (m/s), centre slip (m/s),
!> rolling speed (m/s), spin (rad/s), spin/roll, R_x (m), n rolling points, s1, s2 (m)].
subroutine adore_tribo_contact(geom, coef, kappa_scale, n_gauss, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_traction, print_slip_node
   use adore_api_unpack, only: contact_from_geom, traction_result
   use adore_tribology_traction_law, only: curve_law, law_kappa
   implicit none
   real(wp), intent(in) :: geom(9), coef(4), kappa_scale
   integer, intent(in) :: n_gauss
   real(wp), intent(out) :: result(15)
   real(wp) :: s, u
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error
   type(ball_race_contact_t) :: c
   type(contact_traction_t) :: t

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   c = contact_from_geom(geom)
   call contact_traction(c, curve_law(coef), kappa_scale, n_gauss, t, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   call print_slip_node(c, n_gauss, s, u)
   result = traction_result(t, abs(u), kappa_scale*law_kappa(curve_law(coef), u))

end subroutine adore_tribo_contact

!> Slip u(s) (m/s) at major-axis positions s(1:n) (m); geom as in adore_tribo_contact.
subroutine adore_tribo_slip(geom, n, s, u, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_tribology_slip, only: ball_race_contact_t, contact_slip
   use adore_api_unpack, only: contact_from_geom
   implicit none
   real(wp), intent(in) :: geom(9)
   integer, intent(in) :: n
   real(wp), intent(in) :: s(n)
   real(wp), intent(out) :: u(n)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(ball_race_contact_t) :: c

   u = 0.0_wp
   status = ADORE_INPUT_ERROR
   if (nint(geom(1)) /= 1 .and. nint(geom(1)) /= -1) then
      message = "contact slip: side must be +1 (outer race) or -1 (inner race)"
      return
   else if (.not. (geom(3) > 0.0_wp .and. geom(4) > 0.0_wp .and. geom(8) > 0.0_wp)) then
      message = "contact slip: need rho > 0, ball centre radius > 0 and half width a > 0"
      return
   end if
   status = ADORE_OK
   message = ""

   c = contact_from_geom(geom)
   u = contact_slip(c, s)
end subroutine adore_tribo_slip

!> Dimensionless flash temperature rise (eq 53) on the grid xi(1:n) for flux q(1:n).
subroutine adore_tribo_flash_strip(n, xi, q, dt, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_tribology_flash, only: flash_rise_dimensionless
   implicit none
   integer, intent(in) :: n
   real(wp), intent(in) :: xi(n), q(n)
   real(wp), intent(out) :: dt(n)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   dt = 0.0_wp
   if (n < 2) then
      status = ADORE_INPUT_ERROR
      message = "flash temperature: need at least two grid points"
      return
   end if
   if (any(xi(2:n) <= xi(1:n - 1))) then
      status = ADORE_INPUT_ERROR
      message = "flash temperature: the grid xi must increase strictly"
      return
   end if
   status = ADORE_OK
   message = ""
   call flash_rise_dimensionless(xi, q, dt)
end subroutine adore_tribo_flash_strip

!> Contact temperature rise (eq 36): result = [average (K), largest (K)]; see
!> adore_tribology_flash.contact_temperature_rise for the arguments.
subroutine adore_tribo_contact_temperature(a, b, p0, m, xk, wk, g, u1, u2, th1, th2, ny, result, &
                                           status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_tribology_flash, only: contact_temperature_rise
   implicit none
   real(wp), intent(in) :: a, b, p0
   integer, intent(in) :: m
   real(wp), intent(in) :: xk(m), wk(m), g(m), u1, u2, th1(3), th2(3)
   integer, intent(in) :: ny
   real(wp), intent(out) :: result(2)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   call contact_temperature_rise(a, b, p0, xk, wk, g, u1, u2, th1, th2, ny, result(1), result(2), error)
   if (allocated(error)) then
      call set_error(error, status, message)
   end if
end subroutine adore_tribo_contact_temperature

!> Ball/race contact EHD traction (traction model 3, adore_tribology_ehd_traction): geom as
!> adore_tribo_contact; rheo = [eta_w (Pa s), alpha_t (1/Pa), beta_t (1/K), K_f (W/m/K)];
!> h film (m); b semi-minor axis (m).  result as adore_tribo_contact.
subroutine adore_tribo_ehd_contact(geom, rheo, h, b, n_gauss, n_strip, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, print_slip_node
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_strip_traction
   use adore_api_unpack, only: contact_from_geom, traction_result
   implicit none
   real(wp), intent(in) :: geom(9), rheo(4), h, b
   integer, intent(in) :: n_gauss, n_strip
   real(wp), intent(out) :: result(15)
   real(wp) :: s, u, f, q
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error
   type(ball_race_contact_t) :: c
   type(contact_traction_t) :: t

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   c = contact_from_geom(geom)
   call ehd_contact_traction(c, ehd_rheology_t(eta_w=rheo(1), alpha=rheo(2), beta=rheo(3), conductivity=rheo(4)), &
                             h, b, n_gauss, n_strip, t, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   call print_slip_node(c, n_gauss, s, u)
   call ehd_strip_traction(c, ehd_rheology_t(eta_w=rheo(1), alpha=rheo(2), beta=rheo(3), conductivity=rheo(4)), h, b, &
                  n_strip, s, u, f, q)
   result = traction_result(t, abs(u), f/q)
end subroutine adore_tribo_ehd_contact

!> Shear stress tau(n) (Pa) of a Newtonian film (thickness h, m) sheared at slips u(n)
!> (m/s); wall viscosity eta_w (Pa s), beta (1/K), K_f (W/m/K); film_shear_stress.
subroutine adore_tribo_film_shear(n, u, eta_w, beta, k_f, h, tau, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_tribology_ehd_traction, only: film_shear_stress
   implicit none
   integer, intent(in) :: n
   real(wp), intent(in) :: u(n), eta_w, beta, k_f, h
   real(wp), intent(out) :: tau(n)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   tau = 0.0_wp
   status = ADORE_OK
   message = ""
   if (.not. (eta_w > 0.0_wp .and. h > 0.0_wp .and. beta >= 0.0_wp .and. (beta == 0.0_wp .or. k_f > 0.0_wp))) then
      status = ADORE_INPUT_ERROR
      message = "film shear: need eta_w > 0, h > 0, beta >= 0 and K_f > 0"
      return
   end if
   tau = film_shear_stress(eta_w, beta, k_f, u, h)
end subroutine adore_tribo_film_shear

!> Flash temperature rise of a ball/race contact with its EHD heat (ehd_temperature_rise):
!> geom, rheo, h, b as adore_tribo_ehd_contact; u1, u2 (m/s); th1, th2 = [density, heat
!> capacity, conductivity]; result = [average, largest] rise (K).
subroutine adore_tribo_ehd_temperature(geom, rheo, h, b, n_gauss, ny, u1, u2, th1, th2, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_tribology_ehd_traction, only: ehd_rheology_t
   use adore_tribology_ehd_flash, only: ehd_temperature_rise
   use adore_api_unpack, only: contact_from_geom
   implicit none
   real(wp), intent(in) :: geom(9), rheo(4), h, b, u1, u2, th1(3), th2(3)
   integer, intent(in) :: n_gauss, ny
   real(wp), intent(out) :: result(2)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   call ehd_temperature_rise(contact_from_geom(geom), ehd_rheology_t(eta_w=rheo(1), alpha=rheo(2), beta=rheo(3), &
                             conductivity=rheo(4)), h, b, n_gauss, ny, u1, u2, th1, th2, result(1), result(2), error)
   if (allocated(error)) call set_error(error, status, message)
end subroutine adore_tribo_ehd_temperature

!> Archard wear rates rate(n) (m**3/s) of a body with wear coefficient k (-) and Rockwell C
!> hardness rc under sliding(n) = integral of |u| dQ (N m/s); hardness(Pa) as ADORE 5.0
!> converts rc (adore_tribology_wear).  Input error for k < 0, rc <= 0 or sliding < 0.
subroutine adore_tribo_wear(k, rc, n, sliding, hardness, rate, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_tribology_wear, only: rockwell_c_hardness, archard_wear_rate
   implicit none
   real(wp), intent(in) :: k, rc
   integer, intent(in) :: n
   real(wp), intent(in) :: sliding(n)
   real(wp), intent(out) :: hardness, rate(n)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   hardness = 0.0_wp
   rate = 0.0_wp
   status = ADORE_OK
   message = ""
   if (.not. (k >= 0.0_wp .and. rc > 0.0_wp .and. all(sliding >= 0.0_wp))) then
      status = ADORE_INPUT_ERROR
      message = "wear rate: need wear coefficient >= 0, Rockwell C hardness > 0 and sliding >= 0"
      return
   end if
   hardness = rockwell_c_hardness(rc)
   rate = archard_wear_rate(k, rc, sliding)
end subroutine adore_tribo_wear
