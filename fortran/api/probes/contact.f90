!> Flat f2py wrappers of the contact mechanics (test-only module pyadore._probes).

!> Hertz point contact for curvatures rho (1/m), elastic constants and load q (N).
!>
!> result = [kappa, a*, b*, delta*, a (m), b (m), p_max (Pa), delta (m), K_n (N/m**1.5)].
subroutine adore_hertz_point(rho, e1, nu1, e2, nu2, q, result, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_contact_hertz, only: hertz_geometry_t, hertz_contact_t, hertz_geometry, hertz_contact
   implicit none
   real(wp), intent(in) :: rho(4)
   real(wp), intent(in) :: e1, nu1, e2, nu2, q
   real(wp), intent(out) :: result(9)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(hertz_geometry_t) :: geo
   type(hertz_contact_t) :: c
   logical :: ok

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   call hertz_geometry(rho, e1, nu1, e2, nu2, geo, ok)
   if (.not. ok) then
      status = ADORE_INPUT_ERROR
      message = "hertz: curvatures do not form a convex point contact (need sum rho > 0 and F(rho) < 1)"
      return
   end if
   c = hertz_contact(geo, q)
   result = [geo%kappa, geo%a_star, geo%b_star, geo%delta_star, c%semi_major, c%semi_minor, &
             c%max_pressure, c%deflection, geo%stiffness]
end subroutine adore_hertz_point
