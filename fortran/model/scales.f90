!> Scale factors of the ADORE 5.0 equations of motion (echo "SCALE FACTORS").
!>
!> Identified from the Appendix C and D echoes (both reproduced):
!>   LENGTH  L = rolling-element radius D/2                (9.525E-03, 4.0E-03 m)
!>   TIME    T = sqrt(m L / F), m = rolling-element mass   (2.43679E-04, 7.15843E-05 s)
!>   LOAD    F = largest applied load: both decks agree with
!>               max(|Fx|, sqrt(Fy**2 + Fz**2))  (axial vs radial resultant) and equally
!>               with max(|Fx|, |Fy|, |Fz|); the decks (4500/0/2000 N and 0/0/1000 N)
!>               cannot tell the two apart, nor say what ADORE does at zero load.
!>               pyadore's extension (docs/operating-points.md, "Load scale of a moment
!>               load"): a tilting moment M (about y, z) counts as the ball load M / (dm / 2)
!>               it puts on the pitch circle, so a moment-loaded bearing gets the time scale
!>               of its contact loads; neither appendix deck has a moment, their scales stay.
!>               Also pyadore's (docs/operating-points.md, "Load scale of the start's
!>               contacts"): when the start's largest contact load is larger (a light load
!>               on a bearing preloaded by its fit, centrifugal loads at speed), that load,
!>               so that the time scale follows what the contacts carry.  Appendix C's
!>               largest contact load (2 474 N) is below its 4 500 N: its scale stays.
module adore_model_scales
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: length_scale, load_scale, time_scale, scale_factors

contains

   !> Length scale (m): rolling-element radius, d_re / 2 (d_re: ball or roller diameter).
   pure function length_scale(d_re) result(l)
      real(wp), intent(in) :: d_re
      real(wp) :: l

      l = 0.5_wp*d_re
   end function length_scale

   !> Load scale (N) from the applied load vector [Fx (axial), Fy, Fz]:
   !> max(|Fx|, sqrt(Fy**2 + Fz**2)).  Choice between this and the largest component
   !> is not proven by the report (see module header).  With the applied moment
   !> [Mx, My, Mz] (N m) and the pitch radius arm (m): also sqrt(My**2 + Mz**2) / arm.
   !> With contact (N), the start's largest rolling-element contact load: also that.
   pure function load_scale(load, moment, arm, contact) result(f)
      real(wp), intent(in) :: load(3)
      real(wp), intent(in), optional :: moment(3), arm, contact
      real(wp) :: f

      f = max(abs(load(1)), hypot(load(2), load(3)))
      if (present(moment) .and. present(arm)) then
         if (arm > 0.0_wp) f = max(f, hypot(moment(2), moment(3))/arm)
      end if
      if (present(contact)) then
         ! only with an applied load: a deck without one stays refused (scale_factors)
         if (f > 0.0_wp .and. contact < huge(1.0_wp)) f = max(f, contact)
      end if
   end function load_scale

   !> Time scale (s): sqrt(m L / F), m rolling-element mass (kg), L (m), F (N).
   pure function time_scale(mass_re, l, f) result(t)
      real(wp), intent(in) :: mass_re, l, f
      real(wp) :: t

      t = sqrt(mass_re*l/f)
   end function time_scale

   !> scales = [L (m), F (N), T (s)] from rolling-element diameter (m), mass (kg) and the
   !> applied load vector (N) (and, when given, the applied moment (N m) with the pitch
   !> radius arm (m), and the start's largest contact load (N): load_scale).  Input error for
   !> a non-positive diameter or mass, or a zero applied load (the scale is then undefined
   !> here: ADORE's rule is not known).
   subroutine scale_factors(d_re, mass_re, load, scales, error, moment, arm, contact)
      real(wp), intent(in) :: d_re, mass_re, load(3)
      real(wp), intent(out) :: scales(3)
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: moment(3), arm, contact

      scales = 0.0_wp
      if (.not. (d_re > 0.0_wp .and. mass_re > 0.0_wp)) then
         call input_error(error, "scale factors: rolling-element diameter and mass must be positive")
         return
      end if
      scales(1) = length_scale(d_re)
      scales(2) = load_scale(load, moment, arm, contact)
      if (.not. (scales(2) > 0.0_wp)) then
         call input_error(error, "scale factors: the applied load is zero, the load scale is undefined")
         return
      end if
      scales(3) = time_scale(mass_re, scales(1), scales(2))
   end subroutine scale_factors

end module adore_model_scales
