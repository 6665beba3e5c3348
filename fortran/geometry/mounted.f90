!> The mounted geometry of a bearing at given bulk temperatures: fits, centrifugal growth,
!> internal clearance, raceway radii and the ball grooves' curvature centres.
!>
!> mounted = f(bearing model, temperatures): the one place the physics gets raceway and
!> groove positions from, at step 0 and (later) at every derivative call, so that the
!> thermal model can change the geometry during a run.
!> * Mounting (adore_geometry_fits): shaft, inner race, outer race and housing as elastic
!>   rings of their Rec 8 materials, pressed together (Rec 9 fits) and spun at the race
!>   speeds.
!> * Thermal growth: until the report's thermal distortions (ADRC2, report 4.3) are built,
!>   each race ring and the rolling elements expand freely and uniformly from the deck's
!>   initial temperatures (Rec 2.7): a raceway radius r grows by alpha (T - T0) r, the
!>   element diameter by alpha (T - T0) D (alpha: Rec 8 expansion coefficient; Timoshenko
!>   & Goodier, Theory of Elasticity, ch. 13, free thermal expansion of a ring).  At the
!>   initial temperatures the growth is exactly zero, so step 0 is unchanged; the fits'
!>   change with differential expansion of shaft/race/housing waits for ADRC2
!>   (docs/architecture.md).
!> * Ball grooves: the curvature centres lie on the free contact angle line alpha0 through
!>   the ball centre at the pitch radius, (f - 1/2) D from it (outer: towards -x and the
!>   axis; inner: opposite), so the unmounted diametral play is 2 (f_o + f_i - 1) D
!>   (1 - cos alpha0); the mounted outer raceway moves in by the mounting's shrink, the
!>   inner raceway out by its growth.
!> * Roller raceways: radii from the model's raceway diameters moved by growth_count times
!>   the mounting's raceway displacements (growth_count = 2 reproduces the ADORE 5.0
!>   report, 1 is the consistent clearance; adore_start_roller_step0).
!> Units SI (m, K).
module adore_geometry_mounted
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_SHAFT, BODY_HOUSING, &
                                  TEMP_ELEMENT, TEMP_OUTER, TEMP_INNER
   use adore_geometry_fits, only: ring_t, mounting_t, mount_races
   implicit none
   private

   public :: mounted_geometry_t, mount_geometry, ball_groove_centres

   !> The mounted geometry (m).  Race frames: the outer race frame is the inertial frame
   !> at the bearing centre; the inner race frame sits at the inner race's mass centre.
   type :: mounted_geometry_t
      type(mounting_t) :: mounting                !< fits, pressures, raceway motions, clearance
      real(wp) :: element_diameter = 0.0_wp       !< ball or roller diameter at its temperature
      real(wp) :: groove_radius(2) = 0.0_wp       !< ball groove radii f D, outer and inner race
      !> ball groove curvature centres (axial, radial) in their race frames: (:, 1) outer, (:, 2) inner
      real(wp) :: groove_centre(2, 2) = 0.0_wp
      !> roller raceway radii, outer and inner race
      real(wp) :: raceway_radius(2) = 0.0_wp
      !> thermal radial growth of the outer and inner raceway from the initial temperatures
      real(wp) :: thermal_growth(2) = 0.0_wp
   end type mounted_geometry_t

contains

   !> Mounted geometry of bearing b at bulk temperatures temperature(7) (K, the bearing
   !> model's TEMP_* order).  growth_count (default 1): times the mounting's raceway
   !> displacements move the roller raceways (module header).
   pure function mount_geometry(b, temperature, growth_count) result(g)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      integer, intent(in), optional :: growth_count
      type(mounted_geometry_t) :: g
      real(wp) :: n_growth, d_t(3)

      n_growth = 1.0_wp
      if (present(growth_count)) n_growth = real(growth_count, wp)
      d_t = [temperature(TEMP_ELEMENT) - b%temperature(TEMP_ELEMENT), temperature(TEMP_OUTER) - &
             b%temperature(TEMP_OUTER), temperature(TEMP_INNER) - b%temperature(TEMP_INNER)]
      g%mounting = mount_races(ring_of(b%shaft_id, b%shaft_od, BODY_SHAFT), &
                               ring_of(b%shaft_od, b%inner_raceway_dia, BODY_INNER), &
                               ring_of(b%outer_raceway_dia, b%bearing_od, BODY_OUTER), &
                               ring_of(b%bearing_od, b%housing_od, BODY_HOUSING), &
                               b%fit_inner, b%fit_outer, b%speed_inner, b%speed_outer, b%dia_play)
      g%element_diameter = b%d*(1.0_wp + b%material(BODY_ELEMENT)%expansion*d_t(1))
      g%thermal_growth = [b%material(BODY_OUTER)%expansion*d_t(2)*0.5_wp*b%outer_raceway_dia, &
                          b%material(BODY_INNER)%expansion*d_t(3)*0.5_wp*b%inner_raceway_dia]
      g%groove_radius = [b%ball%f_o*b%d*(1.0_wp + b%material(BODY_OUTER)%expansion*d_t(2)), &
                         b%ball%f_i*b%d*(1.0_wp + b%material(BODY_INNER)%expansion*d_t(3))]
      g%groove_centre = ball_groove_centres(b%d, b%dm, b%ball%f_o, b%ball%f_i, b%ball%alpha0, &
                                            g%mounting%inner_raceway_growth + g%thermal_growth(2), &
                                            g%mounting%outer_raceway_shrink - g%thermal_growth(1))
      g%raceway_radius = [0.5_wp*b%outer_raceway_dia - n_growth*g%mounting%outer_raceway_shrink + g%thermal_growth(1), &
                          0.5_wp*b%inner_raceway_dia + n_growth*g%mounting%inner_raceway_growth + g%thermal_growth(2)]

   contains

      !> An elastic ring of body `body`'s material between two diameters (m).
      pure function ring_of(d_in, d_out, body) result(r)
         real(wp), intent(in) :: d_in, d_out
         integer, intent(in) :: body
         type(ring_t) :: r
         r = ring_t(d_in, d_out, b%material(body)%modulus, b%material(body)%poisson, b%material(body)%density)
      end function ring_of

   end function mount_geometry

   !> Ball groove curvature centres (axial, radial; (:, 1) outer, (:, 2) inner, m) of balls
   !> of diameter d (m) on pitch diameter dm (m), groove curvature factors f_o, f_i, free
   !> contact angle alpha0 (rad), the inner raceway grown by inner_growth and the outer
   !> raceway moved in by outer_shrink (m, radial); module header.
   pure function ball_groove_centres(d, dm, f_o, f_i, alpha0, inner_growth, outer_shrink) result(c)
      real(wp), intent(in) :: d, dm, f_o, f_i, alpha0, inner_growth, outer_shrink
      real(wp) :: c(2, 2)
      c(1, 1) = -(f_o - 0.5_wp)*d*sin(alpha0)
      c(2, 1) = 0.5_wp*dm - (f_o - 0.5_wp)*d*cos(alpha0) - outer_shrink
      c(1, 2) = (f_i - 0.5_wp)*d*sin(alpha0)
      c(2, 2) = 0.5_wp*dm + (f_i - 0.5_wp)*d*cos(alpha0) + inner_growth
   end function ball_groove_centres

end module adore_geometry_mounted
