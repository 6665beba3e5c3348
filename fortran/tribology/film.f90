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
!>   Lubricant library (report Appendix C echo, text-copy lines 3112-3115, "LUBRICATION
!>          PARAMETERS", MIL-L-7808): reference viscosity 8.61565E-03 Pa s, pressure
!>          coefficient 1.07562E-08 1/Pa, temperature coefficient 2.96433E+03 K (higher-order
!>          and cross coefficients printed as 0), density 9.45429E+02 kg/m**3, heat capacity
!>          1.83610E+03 J/kg/K.  The reference temperature prints as "?.?3000E+02 (K)" (head
!>          lost): 323 K is taken, the Appendix C deck's temperatures (Rec 2.7) - with it the
!>          echo's eta0 and alpha give every printed "Iso Lub Film" of step 0 within 0.9 %
!>          (tests/test_tribology.py), and its 40 C viscosity (12.2 mm**2/s) meets the
!>          MIL-PRF-7808 grade-3 minimum of 11.5 mm**2/s.  Viscosity:
!>            eta(p, T) = eta_ref exp(alpha p + B (1/T - 1/T_ref)),  beta = B / T**2.
!>          Traction rheology (ADORE's "rheological constants", second echoed block, name
!>          illegible): traction viscosity 8.15882E-02 Pa s, its pressure coefficient
!>          5.22140E-09 1/Pa and temperature coefficient 4.25519E-02 1/K at 323 K,
!>          eta_t(p, T) = eta_t,ref exp(alpha_t p - beta_t (T - T_ref)) (used by
!>          adore_tribology_ehd_traction).
!>          Thermal conductivity: the echo prints "?.???18E-01 (W/m/K)" (head lost).  K_f =
!>          0.1425185 W/m/K is MIL-L-7808's tabulated conductivity (0.1448548 at 311 K,
!>          0.133952 at 367 K) interpolated to 323 K, as in the public ADORE-style lubricant
!>          library of github.com/Baomaokuan/Bearing (Oil_properties.py, mil_l_7808, commit
!>          1e2291218dc1), whose MIL-L-7808 fits also give every legible echo value above at
!>          323 K to print precision; its tail "...18E-01" is the echo's.
!>   Thermal loading scale (CALIBRATED): with K_f as above, L = eta0 beta u**2 / K_f puts
!>          the printed thermal reduction factors 9.5 % off; ADORE's thermal loading is
!>          larger by the factor THERMAL_LOADING_SCALE, calibrated on ONE contact (ball 10,
!>          outer race, report's own step 0); the other 29 printed contacts test it
!>          (docs/tribology.md).
module adore_tribology_film
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: lubricant_t, LUBRICANT_MIL_L_7808
   public :: central_film_thickness, thermal_loading, thermal_reduction_factor, rolling_resistance_force
   public :: lubricant_from_code, kinematic_viscosity, dynamic_viscosity
   public :: temperature_viscosity_coefficient, traction_viscosity, viscosity_in_range

   !> The largest exponent of the viscosity fit exp(alpha p + B (1/T - 1/T_ref)) (e**230 ~
   !> 1e100 times the reference viscosity): far beyond it (an oil near 0 K) the fit has no
   !> meaning; dynamic_viscosity clamps the exponent there so that no arithmetic overflows,
   !> and viscosity_in_range tells the callers that must refuse such a state.
   real(wp), parameter, public :: VISCOSITY_EXPONENT_MAX = 230.0_wp

   !> Lubricant code of MIL-L-7808 in this library (Rec 10.0 field 2; the Appendix C ball
   !> deck carries 1 and its echo prints "LUBRICANT: MIL-L-7808").
   integer, parameter :: LUBRICANT_MIL_L_7808 = 1
   !> Factor on Gupta's thermal loading that reproduces ADORE's printed thermal reduction
   !> factors, CALIBRATED on one contact (module header, docs/tribology.md).
   real(wp), parameter, public :: THERMAL_LOADING_SCALE = 1.2321_wp

   !> Lubricant properties of the library (viscosity law in the module header).
   type :: lubricant_t
      character(len=32) :: name = ""
      real(wp) :: t_ref = 0.0_wp         !< reference temperature (K)
      real(wp) :: eta_ref = 0.0_wp       !< dynamic viscosity at t_ref and p = 0 (Pa s)
      real(wp) :: alpha = 0.0_wp         !< pressure-viscosity coefficient (1/Pa)
      real(wp) :: b_temp = 0.0_wp        !< temperature coefficient B of exp(B (1/T - 1/T_ref)) (K)
      real(wp) :: density = 0.0_wp       !< kg/m**3
      real(wp) :: heat_capacity = 0.0_wp !< J/(kg K)
      real(wp) :: conductivity = 0.0_wp  !< thermal conductivity K_f, W/(m K)
      real(wp) :: eta_t_ref = 0.0_wp     !< traction viscosity at t_ref and p = 0 (Pa s)
      real(wp) :: alpha_t = 0.0_wp       !< traction pressure-viscosity coefficient (1/Pa)
      real(wp) :: beta_t = 0.0_wp        !< traction temperature-viscosity coefficient (1/K)
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
      ! U**0.67 G**0.53 W**-0.067 as one exp of the logarithms (three logs and an exp instead
      ! of three pow; equal to round-off, 1e-14 relative: test_tribology's film checks)
      h = rx*2.69_wp*exp(0.67_wp*log(su) + 0.53_wp*log(sg) - 0.067_wp*log(sw))*(1.0_wp - 0.61_wp*exp(-0.73_wp*k))
   end subroutine central_film_thickness

   !> Hydrodynamic (EHD) rolling resistance force (N) of an elliptical contact: the force
   !> the inlet's pressure-driven flow opposes to rolling, after Houpert as given by Harris &
   !> Kotzalas (Rolling Bearing Analysis, 5th ed., "Advanced Concepts of Bearing Technology",
   !> ch. 4, hydrodynamic rolling force of a ball/raceway contact):
   !>     F_R = 2.86 E' R_x**2 k**0.348 G**0.022 U**0.66 W**0.47,
   !> U, G, W as the Hamrock-Dowson film (central_film_thickness: U = eta0 u / (E' R_x),
   !> G = alpha E', W = Q / (E' R_x**2)); its power loss is F_R u (docs/tribology.md,
   !> "Rolling resistance").  Arguments as central_film_thickness; 0 for a contact without
   !> load or entraining speed.
   elemental function rolling_resistance_force(rx, k, u, q, e_prime, eta0, alpha) result(f)
      real(wp), intent(in) :: rx, k, u, q, e_prime, eta0, alpha
      real(wp) :: f
      f = 0.0_wp
      if (.not. (rx > 0.0_wp .and. k > 0.0_wp .and. abs(u) > 0.0_wp .and. q > 0.0_wp .and. e_prime > 0.0_wp &
                 .and. eta0 > 0.0_wp .and. alpha > 0.0_wp)) return
      f = 2.86_wp*e_prime*rx*rx*k**0.348_wp*(alpha*e_prime)**0.022_wp*(eta0*abs(u)/(e_prime*rx))**0.66_wp* &
          (q/(e_prime*rx*rx))**0.47_wp
   end function rolling_resistance_force

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
      real(wp) :: la, sa, ll, l42, l64, s83

      la = max(l, 0.0_wp)
      sa = abs(s)
      ! L**0.42, L**0.64 from one log(L), S**0.83 = exp(0.83 log S) (no pow; equal to round-off)
      l42 = 0.0_wp
      l64 = 0.0_wp
      s83 = 0.0_wp
      if (la > 0.0_wp) then
         ll = log(la)
         l42 = exp(0.42_wp*ll)
         l64 = exp(0.64_wp*ll)
      end if
      if (sa > 0.0_wp) s83 = exp(0.83_wp*log(sa))
      phi = (1.0_wp - 13.2_wp*(p_h/e_prime)*l42) / &
            (1.0_wp + 0.213_wp*(1.0_wp + 2.23_wp*s83)*l64)
      phi = max(phi, 0.0_wp)
   end function thermal_reduction_factor

   !> Lubricant of the library for the deck's lubricant code (Rec 10.0 field 2; module
   !> header for the source of every constant).  Input error for an unknown code.
   subroutine lubricant_from_code(code, lub, error)
      integer, intent(in) :: code
      type(lubricant_t), intent(out) :: lub
      type(error_type), allocatable, intent(out) :: error
      character(len=80) :: buf

      select case (code)
      case (LUBRICANT_MIL_L_7808)
         lub = lubricant_t(name="MIL-L-7808", t_ref=323.0_wp, eta_ref=8.61565e-3_wp, alpha=1.07562e-8_wp, &
                           b_temp=2.96433e3_wp, density=9.45429e2_wp, heat_capacity=1.83610e3_wp, &
                           conductivity=0.1425185_wp, eta_t_ref=8.15882e-2_wp, alpha_t=5.22140e-9_wp, &
                           beta_t=4.25519e-2_wp)
      case default
         write (buf, "(a,i0,a,i0,a)") "lubricant library: unknown lubricant code ", code, &
            " (known: ", LUBRICANT_MIL_L_7808, " = MIL-L-7808)"
         call input_error(error, trim(buf))
      end select
   end subroutine lubricant_from_code

   !> Dynamic viscosity (Pa s) at temperature t (K) and pressure p (Pa):
   !> eta_ref exp(alpha p + B (1/t - 1/t_ref)).
   elemental function dynamic_viscosity(lub, t, p) result(eta)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t, p
      real(wp) :: eta
      eta = lub%eta_ref*exp(min(lub%alpha*p + lub%b_temp*(1.0_wp/t - 1.0_wp/lub%t_ref), VISCOSITY_EXPONENT_MAX))
   end function dynamic_viscosity

   !> True when the viscosity fit of lub is inside its meaningful range at temperature t
   !> (K) and pressure 0 (the exponent below VISCOSITY_EXPONENT_MAX; t > 0).
   elemental logical function viscosity_in_range(lub, t)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      viscosity_in_range = t > 0.0_wp
      if (viscosity_in_range) &
         viscosity_in_range = lub%b_temp*(1.0_wp/t - 1.0_wp/lub%t_ref) < VISCOSITY_EXPONENT_MAX
   end function viscosity_in_range

   !> Traction viscosity (Pa s) of the EHD traction model at temperature t (K), pressure 0:
   !> eta_t,ref exp(-beta_t (t - t_ref)).
   elemental function traction_viscosity(lub, t) result(eta)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      real(wp) :: eta
      eta = lub%eta_t_ref*exp(-lub%beta_t*(t - lub%t_ref))
   end function traction_viscosity

   !> Kinematic viscosity (m**2/s) at temperature t (K), ambient pressure.
   elemental function kinematic_viscosity(lub, t) result(nu)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      real(wp) :: nu
      nu = dynamic_viscosity(lub, t, 0.0_wp)/lub%density
   end function kinematic_viscosity

   !> Temperature-viscosity coefficient beta = -d ln(eta)/dT = B / t**2 (1/K) at t (K).
   elemental function temperature_viscosity_coefficient(lub, t) result(beta)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      real(wp) :: beta
      beta = lub%b_temp/(t*t)
   end function temperature_viscosity_coefficient

end module adore_tribology_film
