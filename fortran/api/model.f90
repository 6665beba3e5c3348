!> Flat f2py wrapper of the fitted traction curve (fortran/model/, module pyadore._engine;
!> pyadore.plots.traction).  SI units; ends with (status, message).

!> Traction coefficient of the fitted curve at slips u (m/s): kappa(i) = kappa(u(i)).
subroutine adore_model_traction_eval(coef, u, n, kappa, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK
   use adore_tribology_traction_fit, only: traction_coefficient
   implicit none
   real(wp), intent(in) :: coef(4)
   integer, intent(in) :: n
   real(wp), intent(in) :: u(n)
   real(wp), intent(out) :: kappa(n)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   status = ADORE_OK
   message = ""
   kappa = traction_coefficient(coef(1), coef(2), coef(3), coef(4), u)
end subroutine adore_model_traction_eval
