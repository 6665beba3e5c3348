!> A free cage's mass centre in its whirl plane, as ADORE integrates it (issue #25).
!>
!> Report 4.4.4: "if there are no cage interactions, the cage will whirl in a well defined
!> circular orbit, with the prescribed radius" - the cage's mass centre whirls at its
!> angular velocity on the prescribed circle with no force on it.  Its Appendix C print
!> says the same at step 2500: every pocket and land force 0, the cage's mass-centre
!> acceleration gravity alone, yet a steady whirl off the axis.  Newton's equations give a
!> force-free cage a straight line; a circle at radius r and whirl rate psi' needs the
!> centripetal force m r psi'**2 (338 N for Appendix C's start whirl).  Both statements hold
!> when the whirl radius r and angle psi are integrated as
!>     r'' = F_r / m,     r psi'' = F_t / m
!> (polar coordinates without the centripetal and Coriolis accelerations), the reading
!> docs/cage.md ("The cage's whirl frame") documents with its evidence.  In inertial
!> components the mass centre's acceleration is then F/m plus whirl_frame_acceleration.
module adore_dynamics_cage_whirl
   use adore_core_kinds, only: wp
   implicit none
   private

   public :: whirl_frame_acceleration

contains

   !> The acceleration (m/s**2, 2 components in the plane normal to the bearing axis) that
   !> ADORE's whirl coordinates add to F/m at the mass-centre position p (m, from the bearing
   !> axis) and velocity v (m/s): -(v_t**2 / r) e_r + (2 v_r v_t / r) e_t with e_r = p/r,
   !> e_t = e_x x e_r, v_r = v.e_r, v_t = v.e_t; so r'' = F_r/m and r psi'' = F_t/m (module
   !> header).  The whirl angle is undefined on the axis, where these terms grow without
   !> bound (v_t**2 / r for a cage passing near it): within r_blend (m; default 0) of the axis
   !> they are scaled by r / r_blend, so the cage crosses the axis by Newton's equations
   !> (docs/cage.md, "The cage's whirl frame"); zero below r = 1e-12 m.
   pure function whirl_frame_acceleration(p, v, r_blend) result(a)
      real(wp), intent(in) :: p(2), v(2)
      real(wp), intent(in), optional :: r_blend
      real(wp) :: a(2)
      real(wp) :: r, er(2), et(2), vr, vt
      r = norm2(p)
      a = 0.0_wp
      if (r < 1.0e-12_wp) return
      er = p/r
      et = [-er(2), er(1)]
      vr = dot_product(v, er)
      vt = dot_product(v, et)
      a = (-vt**2*er + 2.0_wp*vr*vt*et)/r
      if (present(r_blend)) then
         if (r < r_blend) a = a*(r/r_blend)
      end if
   end function whirl_frame_acceleration

end module adore_dynamics_cage_whirl
