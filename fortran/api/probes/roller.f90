!> Flat f2py wrappers of the roller-bearing line contact and step 0 (test-only module
!> pyadore._probes).

!> One roller/race line contact by slices (adore_contact_line_slices).
!>
!> profile(5) = [length, land, crown radius, corner radius -x, corner radius +x] (m);
!> h(3) = [approach (m), tilt (rad), curvature (1/m)]; lim(2): permissible ends (m);
!> e_star (Pa); r_eq (m); l_ref: slice reference length (m, <= 0: no K_L, use k_line);
!> k_line: K_L (N/m**(19/9)) when l_ref <= 0; n_sub zones of 4 Gauss points (4 n_sub <= nmax).
!> slices(nmax, 5): [x, weight, delta, q, b] of the n slices;
!> result(12) = [in contact (1/0), x1, x2, a, Q, M, max deflection, mean b, Q/(pi a b_m),
!>               peak pressure, k0, K_L].
subroutine adore_line_contact(profile, race_crown, h, lim, e_star, r_eq, l_ref, k_line, n_sub, nmax, n, &
                              slices, result, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_contact_line_slices, only: roller_profile_t, line_contact_t, line_contact, line_stiffness, &
                                        GAUSS_POINTS
   implicit none
   real(wp), intent(in) :: profile(5), race_crown, h(3), lim(2), e_star, r_eq, l_ref, k_line
   integer, intent(in) :: n_sub, nmax
   integer, intent(out) :: n
   real(wp), intent(out) :: slices(nmax, 5), result(12)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(roller_profile_t) :: p
   type(line_contact_t) :: c
   real(wp) :: k

   n = 0
   slices = 0.0_wp
   result = 0.0_wp
   status = ADORE_OK
   message = ""
   if (n_sub < 1 .or. GAUSS_POINTS*n_sub > nmax .or. e_star <= 0.0_wp .or. r_eq <= 0.0_wp .or. &
       profile(1) <= 0.0_wp .or. profile(3) <= 0.0_wp .or. race_crown <= 0.0_wp .or. lim(2) <= lim(1)) then
      status = ADORE_INPUT_ERROR
      message = "line contact: need n_sub >= 1 (4 n_sub <= nmax), E*, R', length, crown radii > 0, lim(1) < lim(2)"
      return
   end if
   p = roller_profile_t(profile(1), profile(2), profile(3), profile(4:5))
   k = k_line
   if (l_ref > 0.0_wp) k = line_stiffness(e_star, l_ref)
   call line_contact(p, race_crown, h, lim, k, r_eq, e_star, n_sub, c)
   n = size(c%x)
   slices(1:n, 1) = c%x
   slices(1:n, 2) = c%weight
   slices(1:n, 3) = c%delta
   slices(1:n, 4) = c%q
   slices(1:n, 5) = c%b
   result = [merge(1.0_wp, 0.0_wp, c%in_contact), c%limits(1), c%limits(2), c%half_length, c%load, &
             c%moment, c%max_deflection, c%mean_half_width, c%stress, c%peak_pressure, c%k0, k]
end subroutine adore_line_contact

!> Step 0 of a roller-bearing deck end to end (deck -> model -> mounting -> kinematics ->
!> quasi-static equilibrium with slice contacts).  growth_count: 2 = as ADORE 5.0 (report),
!> 1 = consistent clearance (see adore_start_roller_step0).
!>
!> rollers(nmax, 18): [azimuth (rad), r (m), tilt (rad), Q_o, Q_i (N), stress_o, stress_i (Pa),
!>   a_o, a_i, b_o, b_i (m, half contact length, mean half width), delta_o, delta_i (m, max
!>   interaction), centrifugal (N), orbital speed, spin speed (rad/s), peak p_o, p_i (Pa)];
!> slices(nmax, 12, 8): per roller [x, delta, b, q] outer then inner (m, m, m, N/m);
!> summary(23): [inner fit, outer fit, clearance, contact clearance, Y, Z (m),
!>   inner race force x, y, z (N), moment x, y, z (N m), race residual y, z (N),
!>   largest roller residual (N), race iterations, inner raceway growth, outer raceway
!>   shrink (m), K_L outer, K_L inner, basic life outer race, inner race, bearing (h;
!>   eqs 73, 75, 76, 102; huge = never fails)].
subroutine adore_roller_step0_deck(deck_path, growth_count, misalignment, nmax, n, rollers, slices, summary, &
                                   status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_model_bearing, only: bearing_t
   use adore_start_roller_step0, only: roller_step0_t
   use adore_api_unpack, only: roller_start_from_deck
   implicit none
   character(len=*), intent(in) :: deck_path
   integer, intent(in) :: growth_count, nmax
   real(wp), intent(in) :: misalignment(2)            !< inner race's prescribed misalignment about y, z (rad)
   integer, intent(out) :: n
   real(wp), intent(out) :: rollers(nmax, 18), slices(nmax, 12, 8), summary(23)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(bearing_t) :: b
   type(roller_step0_t) :: s
   type(error_type), allocatable :: error
   integer :: k

   n = 0
   rollers = 0.0_wp
   slices = 0.0_wp
   summary = 0.0_wp
   status = ADORE_OK
   message = ""
   call roller_start_from_deck(deck_path, nmax, growth_count, b, s, error, misalignment=misalignment)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   n = b%n_elements
   associate (e => s%equilibrium)
      do k = 1, n
         rollers(k, :) = [e%azimuth(k), e%r(k), e%tilt(k), e%c_o(k)%load, e%c_i(k)%load, &
                          e%c_o(k)%stress, e%c_i(k)%stress, e%c_o(k)%half_length, e%c_i(k)%half_length, &
                          e%c_o(k)%mean_half_width, e%c_i(k)%mean_half_width, e%c_o(k)%max_deflection, &
                          e%c_i(k)%max_deflection, e%centrifugal(k), e%orbital_speed(k), s%spin_speed, &
                          e%c_o(k)%peak_pressure, e%c_i(k)%peak_pressure]
         slices(k, :, 1) = e%c_o(k)%x
         slices(k, :, 2) = e%c_o(k)%delta
         slices(k, :, 3) = e%c_o(k)%b
         slices(k, :, 4) = e%c_o(k)%q
         slices(k, :, 5) = e%c_i(k)%x
         slices(k, :, 6) = e%c_i(k)%delta
         slices(k, :, 7) = e%c_i(k)%b
         slices(k, :, 8) = e%c_i(k)%q
      end do
      summary(1:4) = [s%mounting%inner_fit, s%mounting%outer_fit, s%mounting%clearance, s%contact_clearance]
      summary(5:6) = e%u
      summary(7:9) = e%inner_force
      summary(10:12) = e%inner_moment
      summary(13:14) = e%race_residual
      summary(15) = e%max_roller_residual
      summary(16) = real(e%iterations, wp)
      summary(17:18) = [s%mounting%inner_raceway_growth, s%mounting%outer_raceway_shrink]
      summary(19:20) = [s%model%k_o, s%model%k_i]
      summary(21:23) = [s%life%outer_hours, s%life%inner_hours, s%life%bearing_hours]
   end associate
end subroutine adore_roller_step0_deck
