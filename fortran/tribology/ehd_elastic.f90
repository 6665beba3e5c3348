!> The EHD film's shear elasticity (run option `film_shear_modulus`; not in ADORE 5.0): a
!> Maxwell film in the strip model of adore_tribology_ehd_traction (docs/tribology.md,
!> "The film's elasticity").
!>
!> Johnson & Tevaarwerk, "Shear behaviour of elastohydrodynamic oil films", Proc. R. Soc.
!> Lond. A 356 (1977) 215-236: the film is a Maxwell fluid, the shear rate the sum of an
!> elastic and a viscous part, gamma_dot = (1/G) dtau/dt + F(tau).  In a steady rolling
!> contact the oil moves through the contact at the entraining speed U, d/dt = U d/dx,
!> and with the slip u across the film h (gamma_dot = u/h)
!>     (U/G) dtau/dx = u/h - F(tau),   tau = 0 at the inlet x = -b'.
!> The viscous part here is the engine's thermal Newtonian film at its secant viscosity
!> eta_a(x) = tau_N(x) h / |u| (tau_N the film shear of adore_tribology_ehd_traction at the
!> strip's slip and the local Hertz pressure): F(tau) = tau / eta_a.  Then
!>     dtau/dx = (tau_N(x) - tau) / lambda(x),   lambda = U eta_a / G,
!> the stress relaxes towards the viscous film's over the relaxation length lambda, and
!> tau_N / lambda = G |u| / (U h) is the same at every x.  Limits: lambda -> 0 (Deborah
!> number De = lambda / 2b' -> 0) gives tau = tau_N, today's film; lambda -> infinity the
!> elastic film tau = G (|u| / U) (x + b') / h.  At small slip tau_N = eta(x) |u| / h and
!> the strip's traction is linear in u with the slope (1/h) * integral of Phi dx,
!> (U/G) Phi' = 1 - Phi / eta(x), Phi(-b') = 0 (for uniform eta: eta [2b' - lambda
!> (1 - exp(-2b'/lambda))]).  The secant viscosity is the approximation: the heat of the
!> viscous part is that of the whole slip, exact in both limits (no elastic strain, or
!> a cold film at small slip).
!>
!> The strip is marched in psi (x = b' sin psi) on ELASTIC_INTERVALS equal intervals, lambda
!> constant on each at its midpoint value, exactly integrated there; the result is the
!> ratio R of the Maxwell film's strip integral to the viscous film's on the same
!> intervals, which multiplies the engine's accurate viscous strip integral (so R = 1,
!> today's law, where lambda is negligible).  Units: lengths in units of b'.
module adore_tribology_ehd_elastic
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   implicit none
   private

   public :: elastic_strip_ratio

   !> Intervals in psi across a strip (docs/tribology.md measures the convergence)
   integer, parameter, public :: ELASTIC_INTERVALS = 64
   !> Below this Lambda at the strip's centre the ratio is 1 (its change is below 1e-8)
   real(wp), parameter :: LAMBDA_NEGLIGIBLE = 1.0e-10_wp

contains

   !> Ratio R (-) of the strip integral of the Maxwell film's shear to the viscous film's
   !> (module header) for a strip with A = alpha p_c / 2 (p_c its centre Hertz pressure),
   !> Z = zeta |u| of the thermal film (s/m times m/s; ignored when not thermal) and
   !> lam0 = U eta_w / (G b') (the relaxation length at zero pressure over the strip's half
   !> width b'); n intervals across the strip (default ELASTIC_INTERVALS; even).  The
   !> secant viscosity over eta_w is E**2 asinh(Z E) / (Z E sqrt(1 + (Z E)**2)),
   !> E = exp(A cos psi) (E**2 when not thermal).
   pure function elastic_strip_ratio(aa, z, thermal, lam0, n) result(ratio)
      real(wp), intent(in) :: aa, z, lam0
      logical, intent(in) :: thermal
      integer, intent(in), optional :: n
      real(wp) :: ratio
      if (present(n)) then
         ratio = strip_march(aa, z, thermal, lam0, max(2, n))
      else
         ratio = strip_march(aa, z, thermal, lam0, ELASTIC_INTERVALS)
      end if
   end function elastic_strip_ratio

   !> elastic_strip_ratio on ni intervals (even: the strip's two halves mirror each other).
   pure function strip_march(aa, z, thermal, lam0, ni) result(ratio)
      real(wp), intent(in) :: aa, z, lam0
      logical, intent(in) :: thermal
      integer, intent(in) :: ni
      real(wp) :: ratio
      integer :: k, m
      real(wp) :: cmid((ni + 1)/2), dx((ni + 1)/2), lam((ni + 1)/2), mm((ni + 1)/2), e((ni + 1)/2), &
                  c1((ni + 1)/2), c2((ni + 1)/2), t_in, num, den, h
      integer :: k_
      !> cos(psi) at the midpoints of the inlet half's intervals and their widths in x / b'
      real(wp), parameter :: MID_COS(ELASTIC_INTERVALS/2) = [(cos(-0.5_wp*pi + (k_ - 0.5_wp)*pi/ELASTIC_INTERVALS), &
                                                            k_ = 1, ELASTIC_INTERVALS/2)]
      real(wp), parameter :: MID_DX(ELASTIC_INTERVALS/2) = [(sin(-0.5_wp*pi + k_*pi/ELASTIC_INTERVALS) &
                                                           - sin(-0.5_wp*pi + (k_ - 1)*pi/ELASTIC_INTERVALS), &
                                                           k_ = 1, ELASTIC_INTERVALS/2)]

      ratio = 1.0_wp
      if (lam0*secant(aa) < LAMBDA_NEGLIGIBLE) return
      m = (ni + 1)/2
      if (ni == ELASTIC_INTERVALS) then
         cmid = MID_COS
         dx = MID_DX
      else
         h = pi/ni
         do k = 1, m
            cmid(k) = cos(-0.5_wp*pi + (k - 0.5_wp)*h)
            dx(k) = sin(-0.5_wp*pi + k*h) - sin(-0.5_wp*pi + (k - 1)*h)
         end do
      end if
      ! the intervals' midpoint Lambda of the inlet half (the outlet half mirrors it), then
      ! m = dx / Lambda, e = exp(-m), c1 = (1 - e) / m, c2 = (m - 1 + e) / m**2 (series below
      ! m = 0.05: no cancellation), as array operations
      lam = lam0*secant(aa*cmid)
      mm = dx/lam
      e = exp(-min(mm, 700.0_wp))
      where (mm >= 0.05_wp)
         c1 = (1.0_wp - e)/mm
         c2 = (mm - 1.0_wp + e)/(mm*mm)
      elsewhere
         c1 = 1.0_wp + mm*(-1.0_wp/2 + mm*(1.0_wp/6 + mm*(-1.0_wp/24 + mm*(1.0_wp/120 + mm*(-1.0_wp/720 &
              + mm*(1.0_wp/5040 + mm*(-1.0_wp/40320)))))))
         c2 = 1.0_wp/2 + mm*(-1.0_wp/6 + mm*(1.0_wp/24 + mm*(-1.0_wp/120 + mm*(1.0_wp/720 + mm*(-1.0_wp/5040 &
              + mm*(1.0_wp/40320 + mm*(-1.0_wp/362880)))))))
      end where
      ! T = tau / s0 (units of b'): T_out = T_in e + dx c1, its integral T_in dx c1 + dx**2 c2
      t_in = 0.0_wp
      num = 0.0_wp
      do k = 1, m
         num = num + t_in*dx(k)*c1(k) + dx(k)*dx(k)*c2(k)
         t_in = t_in*e(k) + dx(k)*c1(k)
      end do
      do k = ni - m, 1, -1
         num = num + t_in*dx(k)*c1(k) + dx(k)*dx(k)*c2(k)
         t_in = t_in*e(k) + dx(k)*c1(k)
      end do
      den = 2.0_wp*sum(lam*dx)
      if (2*m /= ni) den = den - lam(m)*dx(m)
      ratio = num/den

   contains

      !> eta_a / eta_w at the centre-pressure exponent x = A cos psi: E**2 (isothermal) or
      !> E**2 asinh(Z E) / (Z E sqrt(1 + (Z E)**2))
      elemental real(wp) function secant(x)
         real(wp), intent(in) :: x
         real(wp) :: ee, w
         ee = exp(x)
         secant = ee*ee
         if (.not. thermal) return
         w = z*ee
         if (w < 1.0e-4_wp) then
            secant = secant*(1.0_wp - 2.0_wp*w*w/3.0_wp)
         else
            secant = secant*log(w + sqrt(1.0_wp + w*w))/(w*sqrt(1.0_wp + w*w))
         end if
      end function secant

   end function strip_march

end module adore_tribology_ehd_elastic
