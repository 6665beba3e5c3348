!> Race mounting: press fits, centrifugal growth and the operating internal clearance
!> (section 3 of the print: Outer/Inner Race Fit, Internal Clearance).
!>
!> Plane-stress thick-cylinder (Lamé) and rotating-disc formulas (Timoshenko & Goodier,
!> Theory of Elasticity, ch. 4; Harris & Kotzalas, Rolling Bearing Analysis, ch. 8 "fits"):
!> * free radial growth of an annulus a <= r <= b spinning at w (rad/s):
!>     u(r) = rho w**2 r / (8 E) [ (3+nu)(1-nu)(a**2+b**2) + (1+nu)(3+nu) a**2 b**2 / r**2
!>                                 - (1-nu**2) r**2 ]
!> * interface pressure of a diametral interference I between an inner body (radii c..a)
!>   and an outer body (radii a..b):
!>     I / (2 a) = p [ ((b**2+a**2)/(b**2-a**2) + nu_out)/E_out + ((a**2+c**2)/(a**2-c**2) - nu_in)/E_in ]
!> * radial displacement of the free surface of each body under p (outer surface of the
!>   outer body grows by 2 p a**2 b/(E (b**2-a**2)); inner surface of the inner body
!>   shrinks by 2 p a**2 c/(E (a**2-c**2))).
!> * hoop stress at the bore r = a of a ring a <= r <= b with pressures p_a (bore), p_b
!>   (outside), spinning at w (plane stress):
!>     sigma(a) = (p_a (a**2 + b**2) - 2 p_b b**2) / (b**2 - a**2) + rho w**2 / 4 [(3+nu) b**2 + (1-nu) a**2]
!>   the largest hoop stress of the ring; the report prints it as the races' section-2
!>   "Stress" (Appendix C: IRace 1.184E+08 = fit + spin at the bore, ORace -6.402E+06 = fit
!>   at the raceway; Appendix D IRace 1.532E+08).
!> The rotating inner race and shaft: the effective fit is the mounted interference less
!> the difference of their free centrifugal growths at the bore; the raceway then grows by
!> the race's free centrifugal growth plus the growth from the effective fit.  The outer
!> race (not rotating here) is pressed into the housing.  The internal (diametral)
!> clearance is the unmounted diametral play less twice the two raceway displacements.
!> A race is represented by an equivalent ring (bore..raceway-side diameter), lengths m.
module adore_geometry_fits
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: ring_t, mounting_t, mount_races, spin_growth, fit_pressure, bore_hoop_stress

   !> An elastic ring (annulus) of a material.
   type :: ring_t
      real(wp) :: inner_diameter = 0.0_wp   !< (m), 0 for a solid shaft
      real(wp) :: outer_diameter = 0.0_wp   !< (m)
      real(wp) :: modulus = 2.0e11_wp       !< E (Pa)
      real(wp) :: poisson = 0.25_wp         !< nu
      real(wp) :: density = 7750.0_wp       !< (kg/m**3)
   end type ring_t

   !> Result of mounting the two races.
   type :: mounting_t
      real(wp) :: inner_fit = 0.0_wp         !< effective diametral fit on the shaft (m, <0: loose)
      real(wp) :: outer_fit = 0.0_wp         !< effective diametral fit in the housing (m)
      real(wp) :: inner_pressure = 0.0_wp    !< shaft/inner race interface pressure (Pa)
      real(wp) :: outer_pressure = 0.0_wp    !< housing/outer race interface pressure (Pa)
      real(wp) :: inner_raceway_growth = 0.0_wp   !< radial growth of the inner raceway (m)
      real(wp) :: inner_hoop_stress = 0.0_wp  !< inner race hoop stress at its bore (Pa)
      real(wp) :: outer_hoop_stress = 0.0_wp  !< outer race hoop stress at its bore, the raceway (Pa)
      real(wp) :: outer_raceway_shrink = 0.0_wp   !< radial inward motion of the outer raceway (m)
      real(wp) :: clearance = 0.0_wp         !< operating internal diametral clearance (m)
   end type mounting_t

contains

   !> Free radial growth (m) at radius r (m) of ring g spinning at w (rad/s).
   pure function spin_growth(g, r, w) result(u)
      type(ring_t), intent(in) :: g
      real(wp), intent(in) :: r, w
      real(wp) :: u
      real(wp) :: a, b, nu

      a = 0.5_wp*g%inner_diameter
      b = 0.5_wp*g%outer_diameter
      nu = g%poisson
      u = g%density*w**2*r/(8.0_wp*g%modulus)*((3.0_wp + nu)*(1.0_wp - nu)*(a**2 + b**2) &
          - (1.0_wp - nu**2)*r**2)
      if (a > 0.0_wp) u = u + g%density*w**2*r/(8.0_wp*g%modulus)*(1.0_wp + nu)*(3.0_wp + nu)*a**2*b**2/r**2
   end function spin_growth

   !> Interface pressure (Pa) of diametral interference fit (m, <=0: none) between the
   !> inner body `inner` and the outer body `outer` (outer%inner_diameter = interface).
   pure function fit_pressure(inner, outer, fit) result(p)
      type(ring_t), intent(in) :: inner, outer
      real(wp), intent(in) :: fit
      real(wp) :: p
      real(wp) :: a, b, c, flex

      p = 0.0_wp
      if (fit <= 0.0_wp) return
      a = 0.5_wp*outer%inner_diameter
      b = 0.5_wp*outer%outer_diameter
      c = 0.5_wp*inner%inner_diameter
      flex = ((b**2 + a**2)/(b**2 - a**2) + outer%poisson)/outer%modulus &
             + ((a**2 + c**2)/(a**2 - c**2) - inner%poisson)/inner%modulus
      p = fit/(2.0_wp*a)/flex
   end function fit_pressure

   !> Mount both races: effective fits, raceway displacements and internal clearance.
   !>
   !> shaft, inner_race, outer_race, housing: the four rings (inner_race%outer_diameter and
   !> outer_race%inner_diameter are the equivalent raceway-side diameters); fit_inner,
   !> fit_outer: mounted diametral interferences (m); w_inner, w_outer: race speeds (rad/s);
   !> dia_play: unmounted diametral play (m).
   pure function mount_races(shaft, inner_race, outer_race, housing, fit_inner, fit_outer, &
                             w_inner, w_outer, dia_play) result(m)
      type(ring_t), intent(in) :: shaft, inner_race, outer_race, housing
      real(wp), intent(in) :: fit_inner, fit_outer, w_inner, w_outer, dia_play
      type(mounting_t) :: m
      real(wp) :: a, b, c

      ! inner race on the shaft
      a = 0.5_wp*inner_race%inner_diameter
      b = 0.5_wp*inner_race%outer_diameter
      m%inner_fit = fit_inner - 2.0_wp*(spin_growth(inner_race, a, w_inner) - spin_growth(shaft, a, w_inner))
      m%inner_pressure = fit_pressure(shaft, inner_race, m%inner_fit)
      m%inner_raceway_growth = spin_growth(inner_race, b, w_inner) &
                               + 2.0_wp*m%inner_pressure*a**2*b/(inner_race%modulus*(b**2 - a**2))
      ! outer race in the housing
      a = 0.5_wp*outer_race%outer_diameter
      c = 0.5_wp*outer_race%inner_diameter
      m%outer_fit = fit_outer - 2.0_wp*(spin_growth(outer_race, a, w_outer) - spin_growth(housing, a, w_outer))
      m%outer_pressure = fit_pressure(outer_race, housing, m%outer_fit)
      m%outer_raceway_shrink = 2.0_wp*m%outer_pressure*a**2*c/(outer_race%modulus*(a**2 - c**2)) &
                               - spin_growth(outer_race, c, w_outer)
      m%clearance = dia_play - 2.0_wp*(m%inner_raceway_growth + m%outer_raceway_shrink)
      m%inner_hoop_stress = bore_hoop_stress(inner_race, m%inner_pressure, 0.0_wp, w_inner)
      m%outer_hoop_stress = bore_hoop_stress(outer_race, 0.0_wp, m%outer_pressure, w_outer)
   end function mount_races

   !> Hoop stress (Pa) at the bore of ring g with pressure p_in on the bore and p_out
   !> outside (Pa), spinning at w (rad/s): Lame plus rotating disc (module header).
   pure function bore_hoop_stress(g, p_in, p_out, w) result(sigma)
      type(ring_t), intent(in) :: g
      real(wp), intent(in) :: p_in, p_out, w
      real(wp) :: sigma
      real(wp) :: a, b

      a = 0.5_wp*g%inner_diameter
      b = 0.5_wp*g%outer_diameter
      sigma = (p_in*(a**2 + b**2) - 2.0_wp*p_out*b**2)/(b**2 - a**2) &
              + 0.25_wp*g%density*w**2*((3.0_wp + g%poisson)*b**2 + (1.0_wp - g%poisson)*a**2)
   end function bore_hoop_stress

end module adore_geometry_fits
