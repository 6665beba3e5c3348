!> Thermal distortion of the bearing's geometry (ADORE's ADRC2, report 2.9 and 4.3): the
!> bulk temperatures of the thermal field change the fits, the rolling elements' size, the
!> raceways (hence the internal clearance) and the cage's clearances.
!>
!> Textbook free thermal expansion of rings and spheres (Timoshenko & Goodier, Theory of
!> Elasticity, ch. 13; Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., "Essential
!> concepts", ch. 8 on fits and thermal effects): each body expands uniformly, a diameter d
!> by alpha (T - T0) d, T0 the deck's initial temperature (Rec 2.7) of that body.
!> * fits: the press fit of two bodies changes by their differential expansion at the
!>   interface: inner race on the shaft d_bore (alpha_shaft dT_shaft - alpha_inner dT_inner),
!>   outer race in the housing D (alpha_outer dT_outer - alpha_housing dT_housing);
!> * the raceways, grooves and the element diameter grow freely, and the races are mounted
!>   again with the changed fits: both by adore_geometry_mounted's mount_geometry (Lame fits
!>   and free growth live there; this module only changes the fits it is given); the
!>   internal clearance is the mounting's less the free growth of the element and plus the
!>   free growth of the outer raceway less the inner's (diametral);
!> * cage: pocket diametral clearance changes by alpha_cage dT_cage (D + c_p) - alpha_el dT_el D
!>   (pocket diameter D + c_p); a guide land's diametral clearance by the differential
!>   growth of the cage and the guiding race at the land diameter d_l: inner-race guided
!>   (d_l = cage bore) (alpha_cage dT_cage - alpha_inner dT_inner) d_l, outer-race guided
!>   (d_l = cage OD) (alpha_outer dT_outer - alpha_cage dT_cage) d_l; the cage's diameters
!>   grow by alpha_cage dT_cage.
!> Units SI (m, K).
module adore_thermal_distortion
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE, BODY_SHAFT, &
                                  BODY_HOUSING, TEMP_HOUSING, TEMP_SHAFT, TEMP_ELEMENT, TEMP_CAGE, TEMP_OUTER, TEMP_INNER
   use adore_cage_step0, only: GUIDE_OUTER
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   implicit none
   private

   public :: distortion_t, thermal_distortion, distorted_bearing

   !> The bearing's geometry at the new bulk temperatures.
   type :: distortion_t
      real(wp) :: fit_inner = 0.0_wp          !< nominal diametral fit on the shaft (m), before spin
      real(wp) :: fit_outer = 0.0_wp          !< nominal diametral fit in the housing (m)
      real(wp) :: element_diameter = 0.0_wp   !< (m)
      !> operating internal diametral clearance (m): the mounting's (fits, spin) with the free
      !> thermal growth of both raceways and the element: c_mount + 2 (u_o - u_i) - 2 (D_T - D)
      real(wp) :: clearance = 0.0_wp
      real(wp) :: pocket_clearance = 0.0_wp   !< cage pocket diametral clearance (m)
      real(wp), allocatable :: land_clearance(:)   !< guide land diametral clearances (m)
      real(wp) :: cage_od = 0.0_wp, cage_id = 0.0_wp   !< (m)
      type(mounted_geometry_t) :: mounted     !< fits, raceways, clearance at speed (mount_geometry)
   end type distortion_t

contains

   !> The bearing model b with its fits changed by the differential expansion at bulk
   !> temperatures temperature(7) (K, TEMP_* order): what mount_geometry needs to mount the
   !> races at those temperatures (module header).
   pure function distorted_bearing(b, temperature) result(bt)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(bearing_t) :: bt
      bt = b
      bt%fit_inner = b%fit_inner + b%shaft_od*(strain(b, temperature, BODY_SHAFT, TEMP_SHAFT) - &
                                               strain(b, temperature, BODY_INNER, TEMP_INNER))
      bt%fit_outer = b%fit_outer + b%bearing_od*(strain(b, temperature, BODY_OUTER, TEMP_OUTER) - &
                                                 strain(b, temperature, BODY_HOUSING, TEMP_HOUSING))
   end function distorted_bearing

   !> Free thermal strain alpha (T - T0) of body `body` (BODY_*) whose bulk temperature is
   !> temperature(it) (it: TEMP_*), T0 the deck's initial temperature.
   pure real(wp) function strain(b, temperature, body, it)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      integer, intent(in) :: body, it
      strain = b%material(body)%expansion*(temperature(it) - b%temperature(it))
   end function strain

   !> Geometry of bearing b at bulk temperatures temperature(7) (K, TEMP_* order): fits,
   !> element size, mounted raceways and clearance, cage clearances (ADRC2, module header).
   pure function thermal_distortion(b, temperature) result(dist)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(distortion_t) :: dist
      type(bearing_t) :: bt
      real(wp) :: e_cage, e_el, e_in, e_out
      integer :: k

      bt = distorted_bearing(b, temperature)
      dist%fit_inner = bt%fit_inner
      dist%fit_outer = bt%fit_outer
      dist%mounted = mount_geometry(bt, temperature)
      dist%element_diameter = dist%mounted%element_diameter
      dist%clearance = dist%mounted%mounting%clearance + 2.0_wp*(dist%mounted%thermal_growth(1) - &
                       dist%mounted%thermal_growth(2)) - 2.0_wp*(dist%element_diameter - b%d)
      e_cage = strain(b, temperature, BODY_CAGE, TEMP_CAGE)
      e_el = strain(b, temperature, BODY_ELEMENT, TEMP_ELEMENT)
      e_in = strain(b, temperature, BODY_INNER, TEMP_INNER)
      e_out = strain(b, temperature, BODY_OUTER, TEMP_OUTER)
      dist%pocket_clearance = b%pocket_clearance(1) + e_cage*(b%d + b%pocket_clearance(1)) - e_el*b%d
      dist%cage_od = b%cage_od*(1.0_wp + e_cage)
      dist%cage_id = b%cage_id*(1.0_wp + e_cage)
      allocate (dist%land_clearance(b%n_lands))
      do k = 1, b%n_lands
         if (b%lands(k)%guide == GUIDE_OUTER) then
            dist%land_clearance(k) = b%lands(k)%clearance + (e_out - e_cage)*b%lands(k)%diameter
         else
            dist%land_clearance(k) = b%lands(k)%clearance + (e_cage - e_in)*b%lands(k)%diameter
         end if
      end do
   end function thermal_distortion

end module adore_thermal_distortion
