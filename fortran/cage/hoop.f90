!> The centrifugal hoop stress of a spinning cage: cage_hoop_stress.
!>
!> The report prints a cage hoop stress column without its formula; pyadore uses the
!> thin rotating ring (Timoshenko, Strength of Materials II, sec. 2 "rotating ring"):
!> sigma = rho v**2 = rho (omega r_m)**2 at the ring's mean radius r_m, the stress of a
!> free ring with no load but its own inertia (docs/print-layout.md, "Dynamic steps").
module adore_cage_hoop
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: cage_hoop_stress

contains

   !> Hoop stress (Pa, tensile > 0) of a thin ring of density rho (kg/m**3) between the
   !> diameters d_in and d_out (m) spinning at omega (rad/s): rho (omega (d_in + d_out)/4)**2.
   pure real(wp) function cage_hoop_stress(rho, d_in, d_out, omega)
      real(wp), intent(in) :: rho, d_in, d_out, omega
      cage_hoop_stress = rho*(omega*0.25_wp*(d_in + d_out))**2
   end function cage_hoop_stress

end module adore_cage_hoop
