!> Basic (Lundberg-Palmgren) rolling contact fatigue life, report section 3.2.
!>
!> AFRL-PR-WP-TR-2002-2042 (ADORE 5.0) eqs 73-76 and 102:
!>     N_LP = (Q_e / Q_c)**(-p)                                            (73)
!>     Q_c  = A (2f/(2f-1))**0.41 (1 +- gamma)**1.39 (D/d_m)**x D**1.8 n**(-1/3)  (74)
!>     Q_e  = 2a [ 1/(2a) int q**(pe) dx ]**(1/(pe))                        (75)
!>     Q_c  = B (1 +- gamma)**(29/27) (D/d_m)**(2/9) D**(29/27) l**(7/9) n**(-1/4) (76)
!>     N**(-e) = N_OR**(-e) + N_IR**(-e)                                    (102)
!> Lives are in millions of relative race revolutions (inner race relative to
!> outer race); life_hours converts them at the relative race speed.
!>
!> What the report leaves open (docs/life-model.md, "Basic life"):
!>  * x = 0.3, the Lundberg-Palmgren / Harris exponent of D/d_m (the text of
!>    eq 74 prints 0.39).  Literature value.
!>  * n = cycle_factor * (ball passes per relative revolution), cycle_factor = 2:
!>    the Lundberg-Palmgren constant (A ~ 98 N/mm**1.8) goes with Z (1 +- gamma),
!>    twice the passes.  Literature convention.
!>  * contacts of one race combine as
!>      rotating race:   1/N = sum_k 1/N_k   (cube-mean load; Lundberg-Palmgren)
!>      stationary race: N**(-e) = w sum_k N_k**(-e)
!>    with w = 1 (stationary_rule = 0, default) or w = m**(e-1) (stationary_rule
!>    = 1, the Lundberg-Palmgren / ISO 16281 10/3-power mean over the m rolling
!>    elements).  w = 1 is NOT Lundberg-Palmgren: it is the rule that reproduces
!>    the report's printed basic life; it gives a stationary race m**0.1 times
!>    the Lundberg-Palmgren life.
!>  * line contacts (eqs 75-76, line_contact_lp_life): with p e = 4.5 (p = 4,
!>    e = 9/8) the Lundberg-Palmgren lamina model makes Q_e/Q_c independent of
!>    the length l, provided eqs 75 and 76 use the same length.  ADORE does not:
!>    its printed roller life (Appendix D, 136.9 h) would need l of eq 76 = half
!>    the contact length (line_length_factor = 0.5), against the report's own text
!>    ("l is the length of contact").  The text wins where it speaks: the default
!>    is line_length_factor = 1 and the report's roller life is NOT reproduced
!>    (an open gap, docs/life-model.md "Roller bearings").  B = 1.6655e8 is the
!>    line constant the report's echo prints for its runs (the text quotes 1.98e8).
module adore_life_lundberg_palmgren
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: life_params_t, LIFE_N_CONSTANTS, life_params_from_array, life_params_to_array
   public :: reduced_modulus, pass_cycles, point_contact_capacity, line_contact_capacity
   public :: line_equivalent_load, contact_life, race_life, bearing_life, life_hours
   public :: ball_race_lp_life, line_contact_lp_life

   !> Fatigue model constants; defaults are the report's (section 3.2, Tables 3-4)
   !> or, where the report gives none, the Appendix C echo (FATIGUE PARAMETERS).
   type :: life_params_t
      ! --- Lundberg-Palmgren (eqs 73-76, 102)
      real(wp) :: a_point = 2.3615e7_wp          !< A, point-contact constant (N/m**1.8), eq 74
      real(wp) :: b_line = 1.6655e8_wp           !< B, line-contact constant (N/m**(50/27)), eq 76: the
                                                 !< ADORE echo's value (text: 1.98e8), see module doc
      real(wp) :: dm_exponent = 0.3_wp           !< exponent of D/d_m in eq 74 (text: 0.39, see module doc)
      real(wp) :: cycle_factor = 2.0_wp          !< n of eqs 74/76 = cycle_factor * ball passes per revolution
      real(wp) :: load_exp_point = 3.0_wp        !< p, point contact, eq 73
      real(wp) :: load_exp_line = 4.0_wp         !< p, line contact, eqs 73/75
      real(wp) :: weibull_e_point = 10.0_wp/9.0_wp  !< e, point contact (race and bearing), eq 102
      real(wp) :: weibull_e_line = 9.0_wp/8.0_wp    !< e, line contact, eqs 75/102
      ! --- Tallian life modification (eqs 77-109)
      real(wp) :: scale_a = 0.23_wp              !< A of eq 77 (dimensionless)
      real(wp) :: beta = 1.60_wp                 !< life dispersion exponent, eq 77
      real(wp) :: zeta = 7.33_wp                 !< stress/life exponent, eq 77
      real(wp) :: matrix_m = 1.197_wp            !< M, Table 3 (52100)
      real(wp) :: tau0 = 0.0_wp                  !< fatigue limit stress (Pa), eq 77
      real(wp) :: phi0lp_root_per_pa = 1.5985e-10_wp  !< Phi_0LP**(1/(beta zeta)) per Pa, step 6 of section 3.2
      real(wp) :: phi1_asperity = 1.50_wp        !< Phi_1a, eq 81
      real(wp) :: phi1_furrow = 1.50_wp          !< Phi_1f, eq 81
      real(wp) :: phi1_subsurface = 1.0_wp       !< Phi_1b, eq 82
      real(wp) :: processing_i = 0.077_wp        !< I, Table 4 (CVD_new), eq 89
      real(wp) :: phi2f_clean = 600.0_wp         !< Phi_2fclean, eq 90
      real(wp) :: contamination = 1.0_wp         !< C_cont, eq 90
      real(wp) :: spectrum_alpha = 40.0_wp       !< roughness spectrum width alpha, eq 86
      real(wp) :: sigma_rms = 1.0e-7_wp          !< composite RMS roughness height (m), eq 87 (Appendix C)
      real(wp) :: theta_rms = 4.11320e-2_wp      !< composite RMS slope (rad), eq 87 (Appendix C)
      real(wp) :: z_frac = 0.0270_wp             !< depth factor, eqs 95/97
      real(wp) :: mu_asperity = 0.10_wp          !< asperity traction coefficient mu_a, eqs 95/98
      real(wp) :: hoop_factor = 0.834_wp         !< weight of hoop stress in s_stat, eq 93
      real(wp) :: sigma_residual = 0.0_wp        !< residual stress (Pa), eq 93
      real(wp) :: e_prime = 2.0e11_wp/(2.0_wp*(1.0_wp - 0.25_wp**2))  !< E' (Pa), eq 98; steel/steel
      ! --- race summation (section 3.2 step 5; see race_life)
      real(wp) :: stationary_rule = 0.0_wp       !< race sum of a stationary race: 0 report (ADORE), 1 Lundberg-Palmgren
      ! --- line contacts (eqs 75-76; see line_contact_lp_life)
      real(wp) :: line_length_factor = 1.0_wp    !< l of eq 76 = factor * contact length 2a of eq 75:
                                                 !< 0.5 report (ADORE), 1 Lundberg-Palmgren
   end type life_params_t

   !> Number of constants in life_params_t, in the order of life_params_to_array.
   integer, parameter :: LIFE_N_CONSTANTS = 30

contains

   !> Flat copy of the constants (for the f2py wrappers), in declaration order:
   !> a_point, b_line, dm_exponent, cycle_factor, load_exp_point, load_exp_line,
   !> weibull_e_point, weibull_e_line, scale_a, beta, zeta, matrix_m, tau0,
   !> phi0lp_root_per_pa, phi1_asperity, phi1_furrow, phi1_subsurface, processing_i,
   !> phi2f_clean, contamination, spectrum_alpha, sigma_rms, theta_rms, z_frac,
   !> mu_asperity, hoop_factor, sigma_residual, e_prime, stationary_rule,
   !> line_length_factor (units as in life_params_t).
   pure function life_params_to_array(params) result(v)
      type(life_params_t), intent(in) :: params
      real(wp) :: v(LIFE_N_CONSTANTS)

      v = [params%a_point, params%b_line, params%dm_exponent, params%cycle_factor, &
           params%load_exp_point, params%load_exp_line, params%weibull_e_point, params%weibull_e_line, &
           params%scale_a, params%beta, params%zeta, params%matrix_m, params%tau0, &
           params%phi0lp_root_per_pa, params%phi1_asperity, params%phi1_furrow, params%phi1_subsurface, &
           params%processing_i, params%phi2f_clean, params%contamination, params%spectrum_alpha, &
           params%sigma_rms, params%theta_rms, params%z_frac, params%mu_asperity, params%hoop_factor, &
           params%sigma_residual, params%e_prime, params%stationary_rule, params%line_length_factor]
   end function life_params_to_array

   !> Constants from a flat array in the order of life_params_to_array.
   pure function life_params_from_array(v) result(params)
      real(wp), intent(in) :: v(LIFE_N_CONSTANTS)
      type(life_params_t) :: params

      params%a_point = v(1); params%b_line = v(2); params%dm_exponent = v(3); params%cycle_factor = v(4)
      params%load_exp_point = v(5); params%load_exp_line = v(6)
      params%weibull_e_point = v(7); params%weibull_e_line = v(8)
      params%scale_a = v(9); params%beta = v(10); params%zeta = v(11); params%matrix_m = v(12)
      params%tau0 = v(13); params%phi0lp_root_per_pa = v(14)
      params%phi1_asperity = v(15); params%phi1_furrow = v(16); params%phi1_subsurface = v(17)
      params%processing_i = v(18); params%phi2f_clean = v(19); params%contamination = v(20)
      params%spectrum_alpha = v(21); params%sigma_rms = v(22); params%theta_rms = v(23)
      params%z_frac = v(24); params%mu_asperity = v(25); params%hoop_factor = v(26)
      params%sigma_residual = v(27); params%e_prime = v(28); params%stationary_rule = v(29)
      params%line_length_factor = v(30)
   end function life_params_from_array

   !> E' of eq 98 (Pa): 1/E' = (1-nu1**2)/E1 + (1-nu2**2)/E2, E in Pa.
   pure function reduced_modulus(e1, nu1, e2, nu2) result(ep)
      real(wp), intent(in) :: e1, nu1, e2, nu2
      real(wp) :: ep

      ep = 1.0_wp/((1.0_wp - nu1*nu1)/e1 + (1.0_wp - nu2*nu2)/e2)
   end function reduced_modulus

   !> Ball passes over one point of a race per relative race revolution (-).
   !>
   !> |omega_orbit - omega_race| / |omega_inner - omega_outer| for one rolling
   !> element; any consistent speed unit.  0 when the races do not turn relative
   !> to each other.  Pure rolling gives (1 -+ gamma)/2 (outer/inner race).
   elemental function pass_cycles(orbital_speed, race_speed, inner_speed, outer_speed) result(n)
      real(wp), intent(in) :: orbital_speed, race_speed, inner_speed, outer_speed
      real(wp) :: n

      n = 0.0_wp
      if (abs(inner_speed - outer_speed) > 0.0_wp) n = abs(orbital_speed - race_speed)/abs(inner_speed - outer_speed)
   end function pass_cycles

   !> Point-contact load capacity Q_c (N) of one race contact, eq 74.
   !>
   !> f: groove curvature factor; alpha: contact angle (rad); d_ball, d_pitch (m);
   !> passes: ball passes per relative revolution (pass_cycles); outer selects
   !> the + sign of (1 +- gamma), gamma = D cos(alpha)/d_m.  No passes
   !> (passes <= 0) gives huge(1.0_wp): the contact is never cycled.
   elemental function point_contact_capacity(params, f, alpha, d_ball, d_pitch, passes, outer) result(qc)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: f, alpha, d_ball, d_pitch, passes
      logical, intent(in) :: outer
      real(wp) :: qc

      real(wp) :: gamma, sgn

      qc = huge(1.0_wp)
      if (passes <= 0.0_wp) return
      gamma = d_ball*cos(alpha)/d_pitch
      sgn = merge(1.0_wp, -1.0_wp, outer)
      qc = params%a_point*(2.0_wp*f/(2.0_wp*f - 1.0_wp))**0.41_wp*(1.0_wp + sgn*gamma)**1.39_wp &
           *(d_ball/d_pitch)**params%dm_exponent*d_ball**1.8_wp &
           *(params%cycle_factor*passes)**(-1.0_wp/3.0_wp)
   end function point_contact_capacity

   !> Line-contact load capacity Q_c (N) of one race contact, eq 76.
   !>
   !> alpha: contact angle (rad); d_roller, d_pitch, length l (m); passes as for
   !> point_contact_capacity; outer selects the + sign of (1 +- gamma).
   !> No passes (passes <= 0) gives huge(1.0_wp): the contact is never cycled.
   elemental function line_contact_capacity(params, alpha, d_roller, d_pitch, length, passes, outer) result(qc)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: alpha, d_roller, d_pitch, length, passes
      logical, intent(in) :: outer
      real(wp) :: qc

      real(wp) :: gamma, sgn

      qc = huge(1.0_wp)
      if (passes <= 0.0_wp) return
      gamma = d_roller*cos(alpha)/d_pitch
      sgn = merge(1.0_wp, -1.0_wp, outer)
      qc = params%b_line*(1.0_wp + sgn*gamma)**(29.0_wp/27.0_wp)*(d_roller/d_pitch)**(2.0_wp/9.0_wp) &
           *d_roller**(29.0_wp/27.0_wp)*length**(7.0_wp/9.0_wp) &
           *(params%cycle_factor*passes)**(-0.25_wp)
   end function line_contact_capacity

   !> Equivalent load Q_e (N) of a line contact from slice load intensities, eq 75.
   !>
   !> q(:) load intensity (N/m) on slices of width dx(:) (m) covering the contact
   !> length 2a = sum(dx); p load exponent, e Weibull slope.  0 for an empty contact.
   pure function line_equivalent_load(q, dx, p, e) result(qe)
      real(wp), intent(in) :: q(:), dx(:), p, e
      real(wp) :: qe

      real(wp) :: length, pe

      qe = 0.0_wp
      length = sum(dx)
      if (length <= 0.0_wp .or. size(q) /= size(dx)) return
      pe = p*e
      qe = length*(sum(max(q, 0.0_wp)**pe*dx)/length)**(1.0_wp/pe)
   end function line_equivalent_load

   !> Life N_LP (10**6 relative revolutions) of one line contact of a roller with
   !> slices, eqs 73, 75, 76: N = (Q_e/Q_c)**(-p_line).
   !>
   !> q(:) load per unit length (N/m) on slices of width dx(:) (m; sum(dx) is the
   !> contact length 2a of eq 75); alpha contact angle (rad, 0 for a cylindrical
   !> roller bearing); d_roller, d_pitch (m); passes and outer as for
   !> line_contact_capacity.  l of eq 76 is params%line_length_factor * sum(dx).
   !> An empty or never-cycled contact returns huge(1.0_wp) ("never fails").
   pure function line_contact_lp_life(params, q, dx, alpha, d_roller, d_pitch, passes, outer) result(n)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: q(:), dx(:), alpha, d_roller, d_pitch, passes
      logical, intent(in) :: outer
      real(wp) :: n

      real(wp) :: length, qe, qc

      n = huge(1.0_wp)
      length = sum(dx)
      if (size(q) /= size(dx) .or. length <= 0.0_wp) return
      qe = line_equivalent_load(q, dx, params%load_exp_line, params%weibull_e_line)
      qc = line_contact_capacity(params, alpha, d_roller, d_pitch, params%line_length_factor*length, passes, outer)
      n = contact_life(qe, qc, params%load_exp_line)
   end function line_contact_lp_life

   !> Life N_LP of one contact (10**6 relative revolutions), eq 73: (q/qc)**(-p).
   !>
   !> An unloaded or never-cycled contact (q <= 0, qc = huge) returns
   !> huge(1.0_wp), meaning "never fails".
   elemental function contact_life(q, qc, p) result(n)
      real(wp), intent(in) :: q, qc, p
      real(wp) :: n

      if (q <= 0.0_wp .or. qc >= huge(1.0_wp)) then
         n = huge(1.0_wp)
      else
         n = (q/qc)**(-p)
      end if
   end function contact_life

   !> Race life (10**6 relative revolutions) from its contact lives (same unit).
   !>
   !> Rotating race (turns relative to the load): 1/N = sum 1/N_k.  Stationary
   !> race: N**(-e) = w sum N_k**(-e), w = 1 (lp_average false: the rule that
   !> reproduces the report) or w = m**(e-1), m = size(lives) (lp_average true:
   !> Lundberg-Palmgren, N = (mean (Q_k/Q_c)**(p e))**(-1/e) with the race
   !> capacity).  Section 3.2 step 5 only says "appropriate summation"; see the
   !> module doc.  Contacts with life huge(1.0_wp) (unloaded) add nothing; with no
   !> loaded contact the race life is huge(1.0_wp).
   pure function race_life(lives, rotating, e, lp_average) result(n)
      real(wp), intent(in) :: lives(:), e
      logical, intent(in) :: rotating, lp_average
      real(wp) :: n

      real(wp) :: s
      integer :: k

      s = 0.0_wp
      do k = 1, size(lives)
         if (lives(k) >= huge(1.0_wp) .or. lives(k) <= 0.0_wp) cycle
         if (rotating) then
            s = s + 1.0_wp/lives(k)
         else
            s = s + lives(k)**(-e)
         end if
      end do
      if (.not. rotating .and. lp_average) s = s*real(size(lives), wp)**(e - 1.0_wp)
      if (s <= 0.0_wp) then
         n = huge(1.0_wp)
      else if (rotating) then
         n = 1.0_wp/s
      else
         n = s**(-1.0_wp/e)
      end if
   end function race_life

   !> Bearing life from the two race lives (any one unit), eq 102:
   !> N**(-e) = N_outer**(-e) + N_inner**(-e).  A race with life huge() is ignored.
   elemental function bearing_life(n_outer, n_inner, e) result(n)
      real(wp), intent(in) :: n_outer, n_inner, e
      real(wp) :: n

      real(wp) :: s

      s = 0.0_wp
      if (n_outer < huge(1.0_wp)) s = s + n_outer**(-e)
      if (n_inner < huge(1.0_wp)) s = s + n_inner**(-e)
      if (s <= 0.0_wp) then
         n = huge(1.0_wp)
      else
         n = s**(-1.0_wp/e)
      end if
   end function bearing_life

   !> Hours from 10**6 relative race revolutions at relative speed rpm (rev/min).
   elemental function life_hours(n_mrev, relative_rpm) result(hours)
      real(wp), intent(in) :: n_mrev, relative_rpm
      real(wp) :: hours

      if (n_mrev >= huge(1.0_wp) .or. relative_rpm <= 0.0_wp) then
         hours = huge(1.0_wp)
      else
         hours = n_mrev*1.0e6_wp/(60.0_wp*abs(relative_rpm))
      end if
   end function life_hours

   !> Basic life of one ball bearing race (10**6 relative revolutions), eqs 73-74.
   !>
   !> q, alpha, passes: per ball load (N), contact angle (rad) and ball passes per
   !> relative revolution; f groove curvature factor, d_ball, d_pitch (m); outer
   !> selects the race; rotating: race turns relative to the load (race sum as
   !> race_life, params%stationary_rule).  Returns the contact lives and the race life.
   pure subroutine ball_race_lp_life(params, q, alpha, passes, f, d_ball, d_pitch, outer, rotating, &
                                     lives, n_race)
      type(life_params_t), intent(in) :: params
      real(wp), intent(in) :: q(:), alpha(:), passes(:), f, d_ball, d_pitch
      logical, intent(in) :: outer, rotating
      real(wp), intent(out) :: lives(size(q))
      real(wp), intent(out) :: n_race

      lives = contact_life(q, point_contact_capacity(params, f, alpha, d_ball, d_pitch, passes, outer), &
                           params%load_exp_point)
      n_race = race_life(lives, rotating, params%weibull_e_point, params%stationary_rule > 0.5_wp)
   end subroutine ball_race_lp_life

end module adore_life_lundberg_palmgren
