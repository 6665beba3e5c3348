!> Tallian life modification of the Lundberg-Palmgren life, report section 3.2.
!>
!> AFRL-PR-WP-TR-2002-2042 (ADORE 5.0) eqs 77-109:
!>     N_10 = 12 A M**(-1/beta) [N_LP**(-1/zeta) Psi**(1/(beta zeta))
!>                               - tau_0 Phi_0LP**(1/(beta zeta))]**(-zeta)     (77)
!>     Psi  = Phi~_T / Phi~_TLP                                                 (78)
!>     Phi_Tk   = Phi_4k sum_{i=a,b,f} Phi_1i Phi_2i Phi_3i                     (105)
!>     Phi_TLPk = Phi_4k Phi_2bLP Phi_3bLP,  Phi_3bLP = 0.39**(beta zeta)       (109)
!>     Phi_4k  ~ N_LP,k**(-beta)   (constant part cancels in Psi)               (100)
!>     rotating race:   Phi~ = beta/m (2 pi)**(1-beta) sum_k Phi_k (2 pi k/m)**(beta-1)  (104, 107)
!>     stationary race: Phi~ = beta/((beta-1) m) sum_k Phi_k                    (106, 108)
!> with the factors of eqs 81-99 (contact_hazard_products).  Stresses in Pa,
!> lives in 10**6 relative race revolutions.
!>
!> Choices where the text is garbled or silent (docs/life-model.md):
!>  * 1 - G(x) (eqs 83-85) is evaluated exactly, 0.5 erfc(x/sqrt 2).  The printed
!>    curve fit of eq 84 approximates the same Mills ratio only when read with
!>    exp(-0.75 x) (the text's + sign grows with x), with 1/sqrt(2 pi) in eq 85.
!>  * eq 83 holds for Lambda > 0.4; below, Lambda = 0.4 is used.  Lambda <= 0
!>    means "no film": mu_eff = mu_a and mu_EHD = 0 (text after eq 99).
!>  * eq 99 is undefined for Lambda > 4.3; the root is taken as 0 there
!>    (F_32 = exp(-15.5), i.e. mu_eff ~ 0: full film).
!>  * t_a, t_b, t_f are clamped at 0 before raising to beta zeta.
!>  * sigma in eq 86 is in mm (as the text says), converted from sigma_rms in m.
module adore_life_tallian
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_life_lundberg_palmgren, only: life_params_t
   implicit none
   private

   public :: gauss_upper_tail, asperity_count, stress_state
   public :: contact_hazard_products, race_psi, tallian_life, ball_race_modified_life


contains

   !> 1 - G(x), the upper tail of the standard Gaussian (eqs 83-85), exact.
   elemental function gauss_upper_tail(x) result(t)
      real(wp), intent(in) :: x
      real(wp) :: t

      t = 0.5_wp*erfc(x/sqrt(2.0_wp))
   end function gauss_upper_tail

   !> Asperity count D_s (-), eq 86: 0.0306 (sigma/theta)**(-2) alpha, sigma in mm.
   !>
   !> Uses params%sigma_rms (m, converted to mm), theta_rms (rad), spectrum_alpha.
   !> 0 when sigma_rms <= 0 (smooth surfaces have no asperity defects).
   pure function asperity_count(params) result(ds)
      type(life_params_t), intent(in) :: params
      real(wp) :: ds

      ds = 0.0_wp
      if (params%sigma_rms <= 0.0_wp) return
      ds = 0.0306_wp*(1.0e3_wp*params%sigma_rms/params%theta_rms)**(-2)*params%spectrum_alpha
   end function asperity_count

   !> Static stress ratio s_stat (-), eq 93: (sigma_res + 0.834 sigma_hoop)/p_max.
   !>
   !> sigma_hoop, p_max in Pa (residual stress and 0.834 from params); 0 for an
   !> unloaded contact (p_max <= 0).
   elemental function stress_state(params, p_max, sigma_hoop) result(s)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: p_max, sigma_hoop
      real(wp) :: s

      s = 0.0_wp
      if (p_max > 0.0_wp) s = (params%sigma_residual + params%hoop_factor*sigma_hoop)/p_max
   end function stress_state

   !> Hazard factor sums of one contact without Phi_4, eqs 81-99, 105, 109.
   !>
   !> p_max: maximum Hertz pressure (Pa); lambda: film thickness / composite RMS
   !> height (-, <= 0 for no film); mu_ehd: EHD traction coefficient (-);
   !> sigma_hoop: race hoop stress (Pa).  phi_sum = sum_{a,b,f} Phi_1 Phi_2 Phi_3
   !> (eq 105 / Phi_4), phi_sum_lp = Phi_2bLP Phi_3bLP = 0.39**(beta zeta) (eq 109 / Phi_4).
   !> An unloaded contact (p_max <= 0) gets phi_sum = 0.
   elemental subroutine contact_hazard_products(params, p_max, lambda, mu_ehd, sigma_hoop, phi_sum, phi_sum_lp)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: p_max, lambda, mu_ehd, sigma_hoop
      real(wp), intent(out) :: phi_sum, phi_sum_lp

      real(wp) :: bz, s, t_a, t_b, t_f, phi2a, phi2b, phi2f, f32, ratio, mu_eff, mu_film, lam

      bz = params%beta*params%zeta
      phi_sum_lp = 0.39_wp**bz                                            ! eq 109
      phi_sum = 0.0_wp
      if (p_max <= 0.0_wp) return                                         ! unloaded contact
      s = stress_state(params, p_max, sigma_hoop)                        ! eq 93

      t_b = 0.39_wp + 0.10_wp*s                                           ! eq 92
      phi2b = 1.0_wp*params%processing_i                                  ! eq 89, Phi_2bLP = 1

      t_f = 1.25_wp*params%z_frac + 1.22_wp*params%mu_asperity + 0.15_wp*s   ! eq 95
      phi2f = params%phi2f_clean*params%contamination                     ! eq 90

      if (lambda <= 0.0_wp) then                                          ! no lubricant film
         lam = 0.4_wp
         mu_eff = params%mu_asperity
         mu_film = 0.0_wp
      else
         lam = max(lambda, 0.4_wp)
         f32 = exp(-15.50_wp + 7.50_wp*sqrt(max(4.30_wp - lam, 0.0_wp)))      ! eq 99
         ratio = 0.05_wp*params%e_prime/p_max*params%theta_rms &
                 *(params%spectrum_alpha - 0.9_wp)**0.75_wp*f32           ! eq 98
         mu_eff = params%mu_asperity*min(ratio, 1.0_wp)
         mu_film = mu_ehd
      end if
      phi2a = asperity_count(params)*gauss_upper_tail(lam - 0.40_wp)      ! eq 83
      t_a = 1.25_wp*params%z_frac + 1.22_wp*(mu_eff + mu_film) + 0.15_wp*s   ! eq 97

      phi_sum = params%phi1_asperity*phi2a*max(t_a, 0.0_wp)**bz &         ! eqs 96, 105
                + params%phi1_subsurface*phi2b*max(t_b, 0.0_wp)**bz &     ! eq 91
                + params%phi1_furrow*phi2f*max(t_f, 0.0_wp)**bz           ! eq 94
   end subroutine contact_hazard_products

   !> Hazard ratio Psi of one race (-), eqs 78, 100, 104, 106-108.
   !>
   !> lives: contact LP lives N_LP,k (10**6 rev; huge() = unloaded, weight 0),
   !> in the race's contact order k = 1..m; phi_sum, phi_sum_lp from
   !> contact_hazard_products; rotating: race turns relative to the load
   !> (eqs 104/107, else 106/108).  1 when no contact is loaded.
   pure function race_psi(params, lives, phi_sum, phi_sum_lp, rotating) result(psi)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: lives(:), phi_sum(:), phi_sum_lp(:)
      logical, intent(in) :: rotating
      real(wp) :: psi

      real(wp) :: t, tlp, phi4, w
      integer :: k, m

      m = size(lives)
      t = 0.0_wp
      tlp = 0.0_wp
      do k = 1, m
         if (lives(k) >= huge(1.0_wp) .or. lives(k) <= 0.0_wp) cycle
         phi4 = lives(k)**(-params%beta)                                  ! eq 100
         if (rotating) then
            w = (2.0_wp*pi*real(k, wp)/real(m, wp))**(params%beta - 1.0_wp)   ! eqs 104, 107
         else
            w = 1.0_wp                                                    ! eqs 106, 108
         end if
         t = t + phi4*phi_sum(k)*w
         tlp = tlp + phi4*phi_sum_lp(k)*w
      end do
      ! the common prefactors beta/m (2 pi)**(1-beta) or beta/((beta-1) m) cancel in eq 78
      if (tlp <= 0.0_wp) then
         psi = 1.0_wp
      else
         psi = t/tlp
      end if
   end function race_psi

   !> Modified life N_10 (10**6 rev) of one race, eq 77, from its LP life
   !> n_lp (10**6 rev) and hazard ratio psi.  huge(1.0_wp) when the bracket of
   !> eq 77 is <= 0 (loading below the fatigue limit tau_0) or n_lp is huge.
   elemental function tallian_life(params, n_lp, psi) result(n10)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: n_lp, psi
      real(wp) :: n10

      real(wp) :: bz, bracket

      n10 = huge(1.0_wp)
      if (n_lp >= huge(1.0_wp) .or. n_lp <= 0.0_wp) return
      bz = params%beta*params%zeta
      bracket = n_lp**(-1.0_wp/params%zeta)*psi**(1.0_wp/bz) - params%tau0*params%phi0lp_root_per_pa
      if (bracket <= 0.0_wp) return
      n10 = 12.0_wp*params%scale_a*params%matrix_m**(-1.0_wp/params%beta)*bracket**(-params%zeta)
   end function tallian_life

   !> Modified life of one race (10**6 rev), section 3.2 steps 2-6.
   !>
   !> lives: contact LP lives (ball_race_lp_life); n_lp: race LP life; per contact
   !> p_max (Pa), lambda (-), mu_ehd (-); sigma_hoop: race hoop stress (Pa);
   !> rotating as for race_psi.  Returns Psi and N_10.
   pure subroutine ball_race_modified_life(params, lives, n_lp, p_max, lambda, mu_ehd, sigma_hoop, rotating, &
                                           psi, n10)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: lives(:), n_lp, p_max(:), lambda(:), mu_ehd(:), sigma_hoop
      logical, intent(in) :: rotating
      real(wp), intent(out) :: psi, n10

      real(wp) :: phi_sum(size(lives)), phi_sum_lp(size(lives))

      call contact_hazard_products(params, p_max, lambda, mu_ehd, sigma_hoop, phi_sum, phi_sum_lp)
      psi = race_psi(params, lives, phi_sum, phi_sum_lp, rotating)
      n10 = tallian_life(params, n_lp, psi)
   end subroutine ball_race_modified_life

end module adore_life_tallian
