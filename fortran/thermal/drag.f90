!> Drag and churning of the rolling elements in the lubricant (the print's section-1 Drag,
!> Chrn Mom and Net Loss (Drag+Chur) columns).  The report gives no model; standard
!> published ones are used (docs/thermal.md):
!> * drag (Harris & Kotzalas, Rolling Bearing Analysis, 5th ed. 2006, "Advanced concepts",
!>   ch. 5, ball drag in an oil-air mixture): F = 1/2 rho_e C_D A V**2, A = pi D**2/4
!>   (ball) or D L (roller broadside), V the element centre's speed relative to the
!>   mixture (Harris: d_m omega_m / 2 with the mixture at rest), rho_e = X rho the density
!>   of the mixture, X the lubricant's volume fraction in the bearing's free space;
!>   Re = rho_e V D / mu.
!>   Sphere: C_D = 24/Re (1 + 0.15 Re**0.687) for Re <= 1000 (Schiller & Naumann 1933;
!>   Clift, Grace & Weber, Bubbles, Drops and Particles, 1978, Table 5.2), C_D = 0.44 for
!>   1000 < Re <= 2e5 (Newton's regime; the two meet within 0.5 %); beyond 2e5 (drag
!>   crisis) the value at 2e5 is kept and in_range is .false..
!>   Cylinder in crossflow: C_D = 1 + 10 Re**(-2/3) (White, Fluid Mechanics, eq. 7.56,
!>   1 <= Re <= 2e5), Re below 1 by Lamb's Oseen result is not attempted (in_range false).
!> * churning moment of the element's spin (Lamb, Hydrodynamics, 6th ed. 1932, art. 334):
!>   a sphere of radius R spinning at omega in a viscous fluid, M = 8 pi mu R**3 omega;
!>   a cylinder, M = 4 pi mu R**2 omega L.  Creeping flow: valid for Re_w = omega R**2 / nu
!>   <= 1 (in_range false beyond, where it is a lower bound); the mixture's viscosity is
!>   the lubricant's (mu X).
!> * loss (W) = F V + M omega.
!> Units SI.
module adore_thermal_drag
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_thermal_convection, only: fluid_properties_t
   implicit none
   private

   public :: sphere_drag_coefficient, cylinder_drag_coefficient, element_drag, churning_moment
   public :: element_fluid_loss_t, element_fluid_loss

   !> One element's losses in the lubricant: the print's Drag, Chrn Mom and Net Loss.
   type :: element_fluid_loss_t
      real(wp) :: drag = 0.0_wp        !< N
      real(wp) :: moment = 0.0_wp      !< churning moment (N m)
      real(wp) :: loss = 0.0_wp        !< drag power + churning power (W)
      logical :: in_range = .true.     !< both models within their ranges
   end type element_fluid_loss_t

contains

   !> Drag coefficient of a sphere at Reynolds number re (module header); in_range false
   !> above 2e5.
   pure subroutine sphere_drag_coefficient(re, cd, in_range)
      real(wp), intent(in) :: re
      real(wp), intent(out) :: cd
      logical, intent(out) :: in_range
      real(wp) :: r
      in_range = re <= 2.0e5_wp
      r = min(max(re, tiny(1.0_wp)), 2.0e5_wp)
      if (r <= 1000.0_wp) then
         cd = 24.0_wp/r*(1.0_wp + 0.15_wp*r**0.687_wp)
      else
         cd = 0.44_wp
      end if
   end subroutine sphere_drag_coefficient

   !> Drag coefficient of a cylinder in crossflow at Reynolds number re (White eq. 7.56);
   !> in_range false outside 1 <= re <= 2e5 (clamped).
   pure subroutine cylinder_drag_coefficient(re, cd, in_range)
      real(wp), intent(in) :: re
      real(wp), intent(out) :: cd
      logical, intent(out) :: in_range
      real(wp) :: r
      in_range = re >= 1.0_wp .and. re <= 2.0e5_wp
      r = min(max(re, 1.0_wp), 2.0e5_wp)
      cd = 1.0_wp + 10.0_wp*r**(-2.0_wp/3.0_wp)
   end subroutine cylinder_drag_coefficient

   !> Drag force (N, opposing v) of a rolling element of diameter d (m) and length length
   !> (m; 0: ball) moving at v (m/s) relative to a lubricant of density rho (kg/m**3) and
   !> viscosity mu (Pa s) filling the volume fraction fraction of the free space (Harris &
   !> Kotzalas); in_range: the drag coefficient's range held.
   pure subroutine element_drag(d, length, v, rho, mu, fraction, force, in_range)
      real(wp), intent(in) :: d, length, v, rho, mu, fraction
      real(wp), intent(out) :: force
      logical, intent(out) :: in_range
      real(wp) :: rho_e, re, cd, area

      rho_e = fraction*rho
      force = 0.0_wp
      in_range = .true.
      if (rho_e <= 0.0_wp .or. v == 0.0_wp) return
      re = rho_e*abs(v)*d/mu
      if (length > 0.0_wp) then
         call cylinder_drag_coefficient(re, cd, in_range)
         area = d*length
      else
         call sphere_drag_coefficient(re, cd, in_range)
         area = 0.25_wp*pi*d*d
      end if
      force = 0.5_wp*rho_e*cd*area*v*v
   end subroutine element_drag

   !> Churning moment (N m, opposing omega) of an element of diameter d (m), length length
   !> (m; 0: ball) spinning at omega (rad/s) relative to a lubricant of viscosity mu (Pa s)
   !> and density rho, volume fraction fraction (Lamb's creeping-flow moment); in_range false
   !> when omega R**2 / nu > 1.
   pure subroutine churning_moment(d, length, omega, rho, mu, fraction, moment, in_range)
      real(wp), intent(in) :: d, length, omega, rho, mu, fraction
      real(wp), intent(out) :: moment
      logical, intent(out) :: in_range
      real(wp) :: r, mu_e

      r = 0.5_wp*d
      mu_e = fraction*mu
      moment = 0.0_wp
      in_range = .true.
      if (mu_e <= 0.0_wp) return
      if (length > 0.0_wp) then
         moment = 4.0_wp*pi*mu_e*r*r*abs(omega)*length
      else
         moment = 8.0_wp*pi*mu_e*r**3*abs(omega)
      end if
      in_range = abs(omega)*r*r*rho/mu <= 1.0_wp
   end subroutine churning_moment

   !> Drag, churning moment and their loss (W) of an element of diameter d, length length (m;
   !> 0: ball) whose centre moves at v (m/s) and which spins at omega (rad/s) relative to a
   !> lubricant of properties props filling the fraction fraction of the free space: F V + M omega.
   pure function element_fluid_loss(d, length, v, omega, props, fraction) result(r)
      real(wp), intent(in) :: d, length, v, omega, fraction
      type(fluid_properties_t), intent(in) :: props
      type(element_fluid_loss_t) :: r
      logical :: ok_d, ok_m
      call element_drag(d, length, v, props%density, props%viscosity, fraction, r%drag, ok_d)
      call churning_moment(d, length, omega, props%density, props%viscosity, fraction, r%moment, ok_m)
      r%loss = r%drag*abs(v) + r%moment*abs(omega)
      r%in_range = ok_d .and. ok_m
   end function element_fluid_loss

end module adore_thermal_drag
