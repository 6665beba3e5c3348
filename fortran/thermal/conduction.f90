!> Steady conduction through the bearing's solids (report sections 2.3-2.5):
!> * hollow cylinder (races, housing, shaft, cage), radii r2 < r1, inner surface at T2
!>   (report figure 4), heat q flowing outward through an angular sector theta (2 pi for a
!>   whole ring), length L, conductivity k:
!>     T(r)  = T2 - q/(theta L k) ln(r/r2)                                    (eq 11)
!>     T_av  = T2 - q/(theta L k) [r1 ln(r1/r2)/(r1 - r2) - 1]                (eq 12)
!>   T_av is the radius average of eq 11 (the report's bulk temperature).  The conductance
!>   between the surfaces is G = theta L k / ln(r1/r2).
!> * rolling element as a cylindrical core of length D and the element's volume
!>   (figure 5): A = pi D**2/6 (ball, eq 13), A = pi D L/4 (roller, eq 14); each contact
!>   conducts to the mid point through k A / D (eqs 15, 16); the bulk temperature is
!>   T_av = T0/2 + (T1 + T2)/4 (eq 17).
!> Units SI (m, K, W).
module adore_thermal_conduction
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   implicit none
   private

   public :: cylinder_temperature, cylinder_bulk, cylinder_conductance, cylinder_bulk_weight, cylinder_bulk_mirrored
   public :: element_core_area, element_conductance, element_bulk, element_surface_area

contains

   !> Temperature (K) at radius r (m) of a hollow cylinder whose inner surface r2 (m) is at
   !> t2 (K), carrying heat q (W, outward positive) through sector theta (rad), length
   !> length (m), conductivity k (W/(m K)): eq 11.
   elemental function cylinder_temperature(r, r2, t2, q, length, k, theta) result(t)
      real(wp), intent(in) :: r, r2, t2, q, length, k, theta
      real(wp) :: t
      t = t2 - q/(theta*length*k)*log(r/r2)
   end function cylinder_temperature

   !> Bulk (radius-average) temperature (K) of the hollow cylinder r2..r1 of eq 11: eq 12.
   elemental function cylinder_bulk(r1, r2, t2, q, length, k, theta) result(t)
      real(wp), intent(in) :: r1, r2, t2, q, length, k, theta
      real(wp) :: t
      t = t2 - q/(theta*length*k)*(r1*log(r1/r2)/(r1 - r2) - 1.0_wp)
   end function cylinder_bulk

   !> Conductance (W/K) between the surfaces r2 < r1 (m) of a hollow cylinder sector theta
   !> (rad), length length (m), conductivity k (W/(m K)): q = G (T2 - T1), from eq 11.
   elemental function cylinder_conductance(r1, r2, length, k, theta) result(g)
      real(wp), intent(in) :: r1, r2, length, k, theta
      real(wp) :: g
      g = theta*length*k/log(r1/r2)
   end function cylinder_conductance

   !> Weight w of eq 12 written in the surface temperatures: T_av = T2 + w (T1 - T2), with
   !> w = r1/(r1 - r2) - 1/ln(r1/r2) (radii m, r2 < r1); 1/2 in the thin-ring limit.
   elemental function cylinder_bulk_weight(r1, r2) result(w)
      real(wp), intent(in) :: r1, r2
      real(wp) :: w
      w = r1/(r1 - r2) - 1.0_wp/log(r1/r2)
   end function cylinder_bulk_weight

   !> The bulk temperature ADORE 5.0 prints for the shaft (Appendix C step 2500: surfaces
   !> 349.6 K outside, 317.4 K at the bore, bulk 329.3 K): eq 12's weight taken from the
   !> outer surface, T_av = T1 + w (T2 - T1), w of cylinder_bulk_weight(r1, r2) - eq 12 as
   !> written is T2 + w (T1 - T2) = 337.6 K there (docs/thermal.md).  Radii m, r2 < r1;
   !> t1 at r1, t2 at r2 (K).
   elemental function cylinder_bulk_mirrored(r1, r2, t1, t2) result(t)
      real(wp), intent(in) :: r1, r2, t1, t2
      real(wp) :: t
      t = t1 + cylinder_bulk_weight(r1, r2)*(t2 - t1)
   end function cylinder_bulk_mirrored

   !> Cross-section (m**2) of the rolling element's conduction core of length d: the
   !> element's volume over d.  Ball (length <= 0): pi d**2/6 (eq 13); roller of length
   !> length: pi d length/4 (eq 14).
   elemental function element_core_area(d, length) result(a)
      real(wp), intent(in) :: d, length
      real(wp) :: a
      if (length > 0.0_wp) then
         a = 0.25_wp*pi*d*length
      else
         a = pi*d*d/6.0_wp
      end if
   end function element_core_area

   !> Conductance (W/K) from one contact of a rolling element to its mid point, k A / D
   !> (eqs 15, 16): k (W/(m K)), d element diameter (m), length roller length (m, 0: ball).
   elemental function element_conductance(k, d, length) result(g)
      real(wp), intent(in) :: k, d, length
      real(wp) :: g
      g = k*element_core_area(d, length)/d
   end function element_conductance

   !> Surface (m**2) through which a rolling element convects (eqs 18-23): ball (length <= 0)
   !> pi d**2; roller of length `length` its side and both ends, pi d length + pi d**2/2.
   elemental function element_surface_area(d, length) result(a)
      real(wp), intent(in) :: d, length
      real(wp) :: a
      if (length > 0.0_wp) then
         a = pi*d*length + 0.5_wp*pi*d*d
      else
         a = pi*d*d
      end if
   end function element_surface_area

   !> Bulk temperature (K) of a rolling element from its mid-point temperature t0 and its
   !> contact temperatures t1, t2 (K): eq 17.
   elemental function element_bulk(t0, t1, t2) result(t)
      real(wp), intent(in) :: t0, t1, t2
      real(wp) :: t
      t = 0.5_wp*t0 + 0.25_wp*(t1 + t2)
   end function element_bulk

end module adore_thermal_conduction
