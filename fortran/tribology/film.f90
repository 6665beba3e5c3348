!> Lubricant film of a ball/race contact: isothermal central film thickness (Hamrock and
!> Dowson), the inlet-shear thermal reduction factor (Gupta et al.) and the lubricant
!> properties they need (the deck's lubricant code, Rec 10.0).
!>
!> Sources
!>   Film:  B. J. Hamrock, D. Dowson, "Isothermal elastohydrodynamic lubrication of point
!>          contacts, Part III - fully flooded results", J. Lubr. Technol. 99 (1977) 264-276:
!>            h_c / R_x = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)),
!>          U = eta0 u / (E' R_x), G = alpha E', W = Q / (E' R_x**2), u = mean entraining
!>          speed (u_1 + u_2)/2, k = a/b (semi-major over semi-minor), E' = 2 / ((1 - nu1**2)/E1
!>          + (1 - nu2**2)/E2).  The report prints this as "Iso Lub Film".
!>   Thermal reduction (report "Thermal Red Fac"): P. K. Gupta, H. S. Cheng, D. Zhu,
!>          N. H. Forster, J. B. Schrand, "Viscoelastic effects in MIL-L-7808-type lubricant,
!>          Part I: analytical formulation", Tribology Trans. 35 (1992) 269-274:
!>            phi_T = (1 - 13.2 (p_h/E') L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64),
!>          L = eta0 beta u**2 / K_f (thermal loading), S = slide-to-roll ratio.
!>          This is the form that reproduces the Appendix C print: with one constant
!>          eta0 beta / K_f the printed factors of all 36 step-0 contacts follow from the
!>          printed loads and speeds to 1 % (tests/test_tribology.py).
!>   MIL-L-7808 viscosity: MIL-PRF-7808 / MIL-L-7808K, Table I, grade 3 limits: kinematic
!>          viscosity >= 11.5 mm**2/s at 40 C and >= 3.0 mm**2/s at 100 C (specification
!>          minima, not a measured oil), joined by the ASTM D341 (Walther) line
!>          log10 log10(nu + 0.7) = A - B log10(T), nu in mm**2/s, T in K.
!>   Not sourced (explicit inputs, no defaults): pressure-viscosity coefficient alpha,
!>          density, thermal conductivity of MIL-L-7808.  The report's prints do not give
!>          them and no citable value was found while writing this module.
module adore_tribology_film
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: lubricant_t, LUBRICANT_MIL_L_7808
   public :: central_film_thickness, thermal_loading, thermal_reduction_factor
   public :: lubricant_from_code, walther_lubricant, kinematic_viscosity, dynamic_viscosity
   public :: temperature_viscosity_coefficient

   !> Lubricant code of MIL-L-7808 in this library (Rec 10.0 field 2; the Appendix C ball
   !> deck carries 1 and its echo prints "LUBRICANT: MIL-L-7808").
   integer, parameter :: LUBRICANT_MIL_L_7808 = 1

   !> Lubricant properties: Walther viscosity line and the constants of the film models.
   type :: lubricant_t
      character(len=32) :: name = ""
      real(wp) :: walther_a = 0.0_wp  !< A of log10 log10(nu + 0.7) = A - B log10(T)  (nu mm**2/s)
      real(wp) :: walther_b = 0.0_wp  !< B of the same line
      real(wp) :: density = 0.0_wp    !< kg/m**3 (taken as temperature independent)
      real(wp) :: alpha = 0.0_wp      !< pressure-viscosity coefficient, 1/Pa
      real(wp) :: conductivity = 0.0_wp  !< thermal conductivity K_f, W/(m K)
   end type lubricant_t

contains

   !> Hamrock-Dowson isothermal central film thickness (m) of an elliptical EHD contact.
   !> rx: effective radius in the rolling direction (m); k: ellipticity a/b (-); u: mean
   !> entraining speed (m/s); q: normal load (N); e_prime: E' (Pa); eta0: inlet viscosity
   !> (Pa s); alpha: pressure-viscosity coefficient (1/Pa).  Input error for non-positive data.
   subroutine central_film_thickness(rx, k, u, q, e_prime, eta0, alpha, h, error)
      real(wp), intent(in) :: rx, k, u, q, e_prime, eta0, alpha
      real(wp), intent(out) :: h
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: su, sg, sw

      h = 0.0_wp
      if (.not. (rx > 0.0_wp .and. k > 0.0_wp .and. u > 0.0_wp .and. q > 0.0_wp .and. &
                 e_prime > 0.0_wp .and. eta0 > 0.0_wp .and. alpha > 0.0_wp)) then
         call input_error(error, "film thickness: need R_x, k, u, Q, E', eta0, alpha all > 0")
         return
      end if
      su = eta0*u/(e_prime*rx)
      sg = alpha*e_prime
      sw = q/(e_prime*rx*rx)
      h = rx*2.69_wp*su**0.67_wp*sg**0.53_wp*sw**(-0.067_wp)*(1.0_wp - 0.61_wp*exp(-0.73_wp*k))
   end subroutine central_film_thickness

   !> Thermal loading L = eta0 beta u**2 / K_f (-) of Gupta et al. (1992): eta0 (Pa s),
   !> beta temperature-viscosity coefficient (1/K), u mean entraining speed (m/s), K_f (W/m/K).
   elemental function thermal_loading(eta0, beta, u, k_f) result(l)
      real(wp), intent(in) :: eta0, beta, u, k_f
      real(wp) :: l
      l = eta0*beta*u*u/k_f
   end function thermal_loading

   !> Inlet-shear thermal reduction factor phi_T (-) of the isothermal film (Gupta et al.
   !> 1992, module header): p_h max Hertz pressure (Pa), e_prime E' (Pa), l thermal loading,
   !> s slide-to-roll ratio |u_1 - u_2| / u (-).  Clipped below at 0 (the fit's numerator
   !> changes sign only far outside its range).
   elemental function thermal_reduction_factor(p_h, e_prime, l, s) result(phi)
      real(wp), intent(in) :: p_h, e_prime, l, s
      real(wp) :: phi
      real(wp) :: la, sa

      la = max(l, 0.0_wp)
      sa = abs(s)
      phi = (1.0_wp - 13.2_wp*(p_h/e_prime)*la**0.42_wp) / &
            (1.0_wp + 0.213_wp*(1.0_wp + 2.23_wp*sa**0.83_wp)*la**0.64_wp)
      phi = max(phi, 0.0_wp)
   end function thermal_reduction_factor

   !> Lubricant whose Walther line passes through (t1, nu1) and (t2, nu2) (K, m**2/s),
   !> with density (kg/m**3), alpha (1/Pa) and conductivity (W/m/K) as given.
   subroutine walther_lubricant(name, t1, nu1, t2, nu2, density, alpha, conductivity, lub, error)
      character(len=*), intent(in) :: name
      real(wp), intent(in) :: t1, nu1, t2, nu2, density, alpha, conductivity
      type(lubricant_t), intent(out) :: lub
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: z1, z2

      if (.not. (t1 > 0.0_wp .and. t2 > 0.0_wp .and. t1 /= t2 .and. nu1 > 0.0_wp .and. nu2 > 0.0_wp)) then
         call input_error(error, "lubricant: need two distinct positive temperatures and positive viscosities")
         return
      end if
      if (.not. (density > 0.0_wp .and. alpha > 0.0_wp .and. conductivity > 0.0_wp)) then
         call input_error(error, "lubricant "//trim(name)//": density, pressure-viscosity coefficient and "// &
                          "thermal conductivity are required inputs (> 0)")
         return
      end if
      z1 = log10(log10(nu1*1.0e6_wp + 0.7_wp))
      z2 = log10(log10(nu2*1.0e6_wp + 0.7_wp))
      lub%name = name
      lub%walther_b = (z1 - z2)/(log10(t2) - log10(t1))
      lub%walther_a = z1 + lub%walther_b*log10(t1)
      lub%density = density
      lub%alpha = alpha
      lub%conductivity = conductivity
   end subroutine walther_lubricant

   !> Lubricant of the library for the deck's lubricant code (Rec 10.0).  Only the
   !> viscosity-temperature line is sourced (module header); density (kg/m**3), alpha (1/Pa)
   !> and conductivity (W/m/K) are explicit inputs.  Input error for an unknown code.
   subroutine lubricant_from_code(code, density, alpha, conductivity, lub, error)
      integer, intent(in) :: code
      real(wp), intent(in) :: density, alpha, conductivity
      type(lubricant_t), intent(out) :: lub
      type(error_type), allocatable, intent(out) :: error
      character(len=80) :: buf

      select case (code)
      case (LUBRICANT_MIL_L_7808)
         ! MIL-L-7808 grade 3 specification minima: 11.5 mm**2/s at 40 C, 3.0 mm**2/s at 100 C
         call walther_lubricant("MIL-L-7808", 313.15_wp, 11.5e-6_wp, 373.15_wp, 3.0e-6_wp, &
                                density, alpha, conductivity, lub, error)
      case default
         write (buf, "(a,i0)") "lubricant library: unknown lubricant code ", code
         call input_error(error, trim(buf))
      end select
   end subroutine lubricant_from_code

   !> Kinematic viscosity (m**2/s) of the lubricant at temperature t (K), ASTM D341 line.
   elemental function kinematic_viscosity(lub, t) result(nu)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      real(wp) :: nu
      nu = (10.0_wp**(10.0_wp**(lub%walther_a - lub%walther_b*log10(t))) - 0.7_wp)*1.0e-6_wp
   end function kinematic_viscosity

   !> Dynamic viscosity (Pa s) at temperature t (K): density times kinematic viscosity.
   elemental function dynamic_viscosity(lub, t) result(eta)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      real(wp) :: eta
      eta = lub%density*kinematic_viscosity(lub, t)
   end function dynamic_viscosity

   !> Temperature-viscosity coefficient beta = -d ln(eta)/dT (1/K) at t (K), analytic
   !> derivative of the Walther line (density taken constant).
   elemental function temperature_viscosity_coefficient(lub, t) result(beta)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      real(wp) :: beta
      real(wp) :: nu_cst, lg
      ! w = log10(nu + 0.7) = 10**(A - B log10 T);  dw/dT = -B w / T
      ! d nu/dT = ln(10) (nu + 0.7) dw/dT;  beta = -(d nu/dT) / nu
      nu_cst = kinematic_viscosity(lub, t)*1.0e6_wp
      lg = log10(nu_cst + 0.7_wp)
      beta = log(10.0_wp)*(nu_cst + 0.7_wp)*lub%walther_b*lg/(t*nu_cst)
   end function temperature_viscosity_coefficient

end module adore_tribology_film
