!> Wear rates of the print's "Time Ave Wear Rate" columns: Archard's law
!>     dV/dt = k / H * integral of |u| dQ          (m**3/s)
!> with k the wear coefficient and H the hardness of the body that wears (Rec 8.n, echo
!> MATERIAL PROPERTIES), |u| the sliding speed and dQ the normal load over the contact.
!> The report names the column but prints no formula (issue: "Archard form with the
!> material wear coefficients and hardness").
!>
!> Hardness: the deck gives Rockwell C; ADORE 5.0 turns it into a pressure as
!> H = 10 RC kgf/mm**2 = RC * 9.80665E+07 Pa.  INFERRED from three independent rows of the
!> report's prints, each reproduced by this form with the body's own k and RC:
!>   * roller deck, cage land (RC 20, k 5E-4, friction 0.05 of Rec 10.5.n): 0.6903 W of loss
!>     is 13.81 N m/s of load x slip, giving 3.5196E-12 m**3/s against the printed 3.519E-12;
!>   * roller deck, rolling elements (ceramic Rec 8.1: RC 80, k 2E-6) with the engine's slices:
!>     1.389E-15 and 1.299E-16 against 1.390E-15 and 1.300E-16;
!>   * ball deck (steel RC 61, k 5E-6): the printed wear over the load x slip of both race
!>     contacts (the report's own speeds) is 8.30-8.34E-16 m**2/N for the 15 complete rows,
!>     k/H = 8.36E-16.
!> A Vickers conversion (HRC 61 -> HV 720) misses the ball rows by 15 % and the ceramic by
!> a factor 2; tests/test_wear.py keeps these checks.
!> Pure procedures, no state.
module adore_tribology_wear
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: rockwell_c_hardness, archard_wear_rate

   !> Pa per kgf/mm**2 (standard gravity 9.80665 m/s**2)
   real(wp), parameter, public :: KGF_PER_MM2 = 9.80665e6_wp

contains

   !> Hardness (Pa) of Rockwell C number rc, as ADORE 5.0 converts it: 10 rc kgf/mm**2.
   elemental function rockwell_c_hardness(rc) result(h)
      real(wp), intent(in) :: rc
      real(wp) :: h
      h = 10.0_wp*rc*KGF_PER_MM2
   end function rockwell_c_hardness

   !> Archard wear rate (m**3/s) of a body with wear coefficient k (-) and hardness rc
   !> (Rockwell C) under `sliding` = integral of |u| dQ (N m/s); 0 without sliding, NaN for
   !> a non-positive hardness (no wear rate can be given).
   elemental function archard_wear_rate(k, rc, sliding) result(rate)
      real(wp), intent(in) :: k, rc, sliding
      real(wp) :: rate
      if (rc > 0.0_wp) then
         rate = k*sliding/rockwell_c_hardness(rc)
      else
         rate = ieee_value(sliding, ieee_quiet_nan)
      end if
   end function archard_wear_rate

end module adore_tribology_wear
