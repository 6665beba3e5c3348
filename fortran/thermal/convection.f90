!> Convective heat transfer to the coolant (ADORE's ADRH3, report section 2.6): the
!> dimensionless groups (eqs 18-20), the Nusselt correlations for spheres and cylinders in
!> air and in liquids (eqs 21-26, Table 1) and the properties of air (eq 27, Table 2).
!>
!> Table 1 (report 2.6.3, "Coefficients of Heat Transfer Coefficients for Cylinders in
!> Air") is Hilpert's cylinder-in-crossflow table, Nu = C Re**n, in its original air form
!> (no Pr factor): 0.4-4: 0.891/0.330, 4-40: 0.821/0.385, 40-4000: 0.615/0.466,
!> 4000-40000: 0.174/0.618, 40000-400000: 0.0239/0.805 (Kreith, Principles of Heat
!> Transfer; Incropera & DeWitt's Table 7.2 is the same table with C divided by Pr**(1/3)).
!> Table 2 (report 2.6.5, "Physical Properties of Air", its ref [10] p. 483 in SI) gives c_p, mu and k at 16
!> temperatures 88.88 ... 922.22 K; they are interpolated linearly in T here.  Air density:
!> eq 27, rho = 353/T (ideal gas at one atmosphere).
!>
!> Range limits (the report's): eq 21 25 <= Re <= 1e5, eq 22 1 <= Re <= 25, Table 1
!> 0.4 <= Re <= 4e5, Table 2 88.88 <= T <= 922.22 K.  Outside them a correlation is
!> evaluated at the nearest limit (Re or T clamped) and in_range is returned .false.; eqs 23
!> and 25 are stated for all Reynolds numbers.  Where two Table 1 rows meet (Re = 4, 40,
!> 4000, 40000) the upper row is used; the rows agree there within 0.8 %.
!> Units SI: velocity m/s, length m, h W/(m**2 K).
module adore_thermal_convection
   use adore_core_kinds, only: wp
   use adore_tribology_film, only: lubricant_t, dynamic_viscosity
   implicit none
   private

   public :: fluid_properties_t, air_properties, lubricant_properties
   public :: reynolds_number, prandtl_number, htc_from_nusselt
   public :: nusselt_sphere_air, nusselt_sphere_liquid, nusselt_cylinder_air
   public :: nusselt_cylinder_liquid, nusselt_cylinder_liquid_table, heat_transfer_coefficient
   public :: SHAPE_SPHERE, SHAPE_CYLINDER, FLUID_AIR, FLUID_LIQUID
   public :: AIR_TABLE_T, AIR_TABLE_CP, AIR_TABLE_MU, AIR_TABLE_K, CYL_TABLE_RE, CYL_TABLE_C, CYL_TABLE_N

   integer, parameter :: SHAPE_SPHERE = 1, SHAPE_CYLINDER = 2
   integer, parameter :: FLUID_AIR = 1, FLUID_LIQUID = 2

   !> Report Table 2: temperature (K), specific heat (J/(kg K)), viscosity (Pa s), thermal
   !> conductivity (W/(m K)) of air.
   real(wp), parameter :: AIR_TABLE_T(16) = [88.88_wp, 144.44_wp, 200.0_wp, 227.77_wp, 273.33_wp, &
      311.11_wp, 366.66_wp, 422.22_wp, 477.77_wp, 533.33_wp, 588.88_wp, 644.44_wp, 700.0_wp, &
      755.55_wp, 811.11_wp, 922.22_wp]
   real(wp), parameter :: AIR_TABLE_CP(16) = [1.0019409e3_wp, 1.0019409e3_wp, 1.0019409e3_wp, &
      1.0023596e3_wp, 1.0031970e3_wp, 1.0052905e3_wp, 1.0098962e3_wp, 1.0136644e3_wp, 1.0241318e3_wp, &
      1.0358553e3_wp, 1.0484163e3_wp, 1.0613959e3_wp, 1.0743754e3_wp, 1.0877737e3_wp, 1.1011721e3_wp, &
      1.1250377e3_wp]
   real(wp), parameter :: AIR_TABLE_MU(16) = [6.3274590e-6_wp, 1.0008138e-5_wp, 1.3316613e-5_wp, &
      1.4888138e-5_wp, 1.7245428e-5_wp, 1.9023733e-5_wp, 2.1546445e-5_wp, 2.3903733e-5_wp, 2.6054243e-5_wp, &
      2.8080685e-5_wp, 3.0024413e-5_wp, 3.1844074e-5_wp, 3.3622379e-5_wp, 3.5317973e-5_wp, 3.6889498e-5_wp, &
      3.9991194e-5_wp]
   real(wp), parameter :: AIR_TABLE_K(16) = [8.2733628e-3_wp, 1.3206225e-2_wp, 1.8000622e-2_wp, &
      2.0423783e-2_wp, 2.4231607e-2_wp, 2.7174014e-2_wp, 3.1328006e-2_wp, 3.5308913e-2_wp, 3.8943654e-2_wp, &
      4.2578392e-2_wp, 4.6040051e-2_wp, 4.9328627e-2_wp, 5.2444120e-2_wp, 5.5386531e-2_wp, 5.8328938e-2_wp, &
      6.3867588e-2_wp]
   !> Report Table 1: the lower Reynolds number of each row (the last row ends at 4e5), C, n.
   real(wp), parameter :: CYL_TABLE_RE(6) = [0.4_wp, 4.0_wp, 40.0_wp, 4000.0_wp, 40000.0_wp, 400000.0_wp]
   real(wp), parameter :: CYL_TABLE_C(5) = [0.891_wp, 0.821_wp, 0.615_wp, 0.174_wp, 0.0239_wp]
   real(wp), parameter :: CYL_TABLE_N(5) = [0.330_wp, 0.385_wp, 0.466_wp, 0.618_wp, 0.805_wp]

   !> Properties of a fluid at one temperature.
   type :: fluid_properties_t
      real(wp) :: density = 0.0_wp        !< kg/m**3
      real(wp) :: viscosity = 0.0_wp      !< dynamic viscosity mu_f (Pa s)
      real(wp) :: conductivity = 0.0_wp   !< k_f (W/(m K))
      real(wp) :: heat_capacity = 0.0_wp  !< c_p (J/(kg K))
   end type fluid_properties_t

contains

   !> Air at temperature t (K): density by eq 27, c_p, mu, k by Table 2 (linear in T);
   !> in_range .false. when t lies outside the table (then its end value is used).
   pure subroutine air_properties(t, props, in_range)
      real(wp), intent(in) :: t
      type(fluid_properties_t), intent(out) :: props
      logical, intent(out) :: in_range
      real(wp) :: tc, w
      integer :: i

      in_range = t >= AIR_TABLE_T(1) .and. t <= AIR_TABLE_T(16)
      tc = min(max(t, AIR_TABLE_T(1)), AIR_TABLE_T(16))
      do i = 1, 14
         if (tc < AIR_TABLE_T(i + 1)) exit
      end do
      i = min(i, 15)
      w = (tc - AIR_TABLE_T(i))/(AIR_TABLE_T(i + 1) - AIR_TABLE_T(i))
      props%density = 353.0_wp/tc
      props%heat_capacity = (1.0_wp - w)*AIR_TABLE_CP(i) + w*AIR_TABLE_CP(i + 1)
      props%viscosity = (1.0_wp - w)*AIR_TABLE_MU(i) + w*AIR_TABLE_MU(i + 1)
      props%conductivity = (1.0_wp - w)*AIR_TABLE_K(i) + w*AIR_TABLE_K(i + 1)
   end subroutine air_properties

   !> A liquid lubricant of the library at temperature t (K): its density, heat capacity and
   !> conductivity (constants of adore_tribology_film) and its viscosity at t, ambient pressure.
   elemental function lubricant_properties(lub, t) result(props)
      type(lubricant_t), intent(in) :: lub
      real(wp), intent(in) :: t
      type(fluid_properties_t) :: props
      props = fluid_properties_t(lub%density, dynamic_viscosity(lub, t, 0.0_wp), lub%conductivity, &
                                 lub%heat_capacity)
   end function lubricant_properties

   !> Reynolds number Re = V rho D / mu (eq 18): velocity v (m/s), length d (m).
   elemental function reynolds_number(props, v, d) result(re)
      type(fluid_properties_t), intent(in) :: props
      real(wp), intent(in) :: v, d
      real(wp) :: re
      re = abs(v)*props%density*d/props%viscosity
   end function reynolds_number

   !> Prandtl number Pr = c_p mu / k (eq 20).
   elemental function prandtl_number(props) result(pr)
      type(fluid_properties_t), intent(in) :: props
      real(wp) :: pr
      pr = props%heat_capacity*props%viscosity/props%conductivity
   end function prandtl_number

   !> Heat transfer coefficient h = Nu k_f / D (eq 19), W/(m**2 K).
   elemental function htc_from_nusselt(nu, props, d) result(h)
      real(wp), intent(in) :: nu, d
      type(fluid_properties_t), intent(in) :: props
      real(wp) :: h
      h = nu*props%conductivity/d
   end function htc_from_nusselt

   !> Sphere in air: eq 21 (25 <= Re <= 1e5) Nu = 0.37 Re**0.6; eq 22 (1 <= Re <= 25)
   !> Nu = Re Pr (2.2/Re + 0.48/Re**0.5).  Re outside [1, 1e5] is clamped (in_range false).
   pure subroutine nusselt_sphere_air(re, pr, nu, in_range)
      real(wp), intent(in) :: re, pr
      real(wp), intent(out) :: nu
      logical, intent(out) :: in_range
      real(wp) :: r
      in_range = re >= 1.0_wp .and. re <= 1.0e5_wp
      r = min(max(re, 1.0_wp), 1.0e5_wp)
      if (r >= 25.0_wp) then
         nu = 0.37_wp*r**0.6_wp
      else
         nu = r*pr*(2.2_wp/r + 0.48_wp/sqrt(r))
      end if
   end subroutine nusselt_sphere_air

   !> Sphere in a liquid, any Re (eq 23): Nu = Pr**0.3 (0.97 + 0.68 Re**0.5).
   elemental function nusselt_sphere_liquid(re, pr) result(nu)
      real(wp), intent(in) :: re, pr
      real(wp) :: nu
      nu = pr**0.3_wp*(0.97_wp + 0.68_wp*sqrt(re))
   end function nusselt_sphere_liquid

   !> Cylinder in air (eq 24, Table 1): Nu = C Re**n, 0.4 <= Re <= 4e5 (clamped outside,
   !> in_range false).
   pure subroutine nusselt_cylinder_air(re, nu, in_range)
      real(wp), intent(in) :: re
      real(wp), intent(out) :: nu
      logical, intent(out) :: in_range
      real(wp) :: r
      integer :: i
      in_range = re >= CYL_TABLE_RE(1) .and. re <= CYL_TABLE_RE(6)
      r = min(max(re, CYL_TABLE_RE(1)), CYL_TABLE_RE(6))
      i = table1_row(r)
      nu = CYL_TABLE_C(i)*r**CYL_TABLE_N(i)
   end subroutine nusselt_cylinder_air

   !> Cylinder in a liquid, any Re (eq 25, the one the report uses): Nu = (0.35 + 0.56 Re**0.5) Pr**0.31.
   elemental function nusselt_cylinder_liquid(re, pr) result(nu)
      real(wp), intent(in) :: re, pr
      real(wp) :: nu
      nu = (0.35_wp + 0.56_wp*sqrt(re))*pr**0.31_wp
   end function nusselt_cylinder_liquid

   !> Cylinder in a liquid, the alternative of eq 26: Nu = 1.1 C Re**n Pr**0.31 with Table 1
   !> (not the report's choice; kept for comparison).  Clamped as eq 24.
   pure subroutine nusselt_cylinder_liquid_table(re, pr, nu, in_range)
      real(wp), intent(in) :: re, pr
      real(wp), intent(out) :: nu
      logical, intent(out) :: in_range
      call nusselt_cylinder_air(re, nu, in_range)
      nu = 1.1_wp*nu*pr**0.31_wp
   end subroutine nusselt_cylinder_liquid_table

   !> The Table 1 row of Reynolds number r (within the table's range).
   pure integer function table1_row(r) result(i)
      real(wp), intent(in) :: r
      do i = 5, 1, -1
         if (r >= CYL_TABLE_RE(i)) return
      end do
      i = 1
   end function table1_row

   !> Heat transfer coefficient h (W/(m**2 K)) of a body of shape SHAPE_SPHERE or
   !> SHAPE_CYLINDER, characteristic length d (m), in a fluid of kind FLUID_AIR or
   !> FLUID_LIQUID with properties props, at characteristic velocity v (m/s): eqs 18-25
   !> as the report uses them (cylinders in liquid by eq 25).  in_range: the correlation's
   !> range held.
   pure subroutine heat_transfer_coefficient(shape, fluid, props, v, d, h, in_range)
      integer, intent(in) :: shape, fluid
      type(fluid_properties_t), intent(in) :: props
      real(wp), intent(in) :: v, d
      real(wp), intent(out) :: h
      logical, intent(out) :: in_range
      real(wp) :: re, pr, nu

      re = reynolds_number(props, v, d)
      pr = prandtl_number(props)
      in_range = .true.
      if (shape == SHAPE_SPHERE .and. fluid == FLUID_AIR) then
         call nusselt_sphere_air(re, pr, nu, in_range)
      else if (shape == SHAPE_SPHERE) then
         nu = nusselt_sphere_liquid(re, pr)
      else if (fluid == FLUID_AIR) then
         call nusselt_cylinder_air(re, nu, in_range)
      else
         nu = nusselt_cylinder_liquid(re, pr)
      end if
      h = htc_from_nusselt(nu, props, d)
   end subroutine heat_transfer_coefficient

end module adore_thermal_convection
