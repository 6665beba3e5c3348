!> Mounting of a bearing model: its shaft, races and housing as elastic rings of their
!> materials, pressed together and spun (adore_mounting_fits); shared by the ball and
!> roller starts.
module adore_driver_mount
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t, BODY_OUTER, BODY_INNER, BODY_SHAFT, BODY_HOUSING
   use adore_mounting_fits, only: ring_t, mounting_t, mount_races
   implicit none
   private

   public :: mount_bearing

contains

   !> Effective fits, raceway displacements and internal clearance of bearing b at its
   !> race speeds: shaft shaft ID..OD, inner race bore..raceway, outer race raceway..OD,
   !> housing bearing OD..housing OD (Rec 4; raceway diameters from the model).
   function mount_bearing(b) result(m)
      type(bearing_t), intent(in) :: b
      type(mounting_t) :: m

      m = mount_races(ring_of(b%shaft_id, b%shaft_od, BODY_SHAFT), &
                      ring_of(b%shaft_od, b%inner_raceway_dia, BODY_INNER), &
                      ring_of(b%outer_raceway_dia, b%bearing_od, BODY_OUTER), &
                      ring_of(b%bearing_od, b%housing_od, BODY_HOUSING), &
                      b%fit_inner, b%fit_outer, b%speed_inner, b%speed_outer, b%dia_play)

   contains

      !> An elastic ring of body `body`'s material between two diameters (m).
      function ring_of(d_in, d_out, body) result(r)
         real(wp), intent(in) :: d_in, d_out
         integer, intent(in) :: body
         type(ring_t) :: r
         r = ring_t(d_in, d_out, b%material(body)%modulus, b%material(body)%poisson, b%material(body)%density)
      end function ring_of

   end function mount_bearing

end module adore_driver_mount
