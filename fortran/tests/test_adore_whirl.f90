!> Unit tests of a free cage's mass centre in ADORE's whirl coordinates
!> (adore_dynamics_cage_whirl, report 4.4.4), against closed forms:
!> * on a circular whirl the added acceleration is the centripetal one, -r psidot**2 e_r:
!>   a cage free of force keeps its circle (the report's "if there are no cage interactions,
!>   the cage will whirl in a well defined circular orbit, with the prescribed radius");
!> * a purely radial motion gets nothing added (no whirl, no Coriolis term);
!> * integrated (classical RK4) with no force for 20.3 whirl periods from a state with both a
!>   radial and a whirl velocity, the motion is r = r0 + rdot0 t, psi = psi0 + psidot0 t
!>   (r'' = 0, r psi'' = 0), where Newton's straight line would leave the circle;
!> * on that motion the kinetic energy changes by what the frame's acceleration gives,
!>   the balance's whirl-frame power a_w.v = v_r v_t**2 / r (adore_forces_ball_power):
!>   the closed form 1/2 psidot0**2 (r**2 - r0**2) per unit mass and the trapezoidal
!>   integral of v_r v_t**2 / r along the path.
program test_adore_whirl
   use adore_core_kinds, only: wp
   use adore_dynamics_cage_whirl, only: whirl_frame_acceleration
   use adore_test_support, only: check, finish
   implicit none
   real(wp), parameter :: pi = acos(-1.0_wp)

   call test_circle()
   call test_radial()
   call test_force_free_motion()
   call finish("test_adore_whirl")

contains

   subroutine test_circle()
      real(wp) :: r, w, psi, p(2), v(2), a(2)
      r = 5.9e-4_wp
      w = 958.0_wp
      psi = 0.7_wp
      p = r*[cos(psi), sin(psi)]
      v = r*w*[-sin(psi), cos(psi)]
      a = whirl_frame_acceleration(p, v)
      write (*, "(a,2es12.4,a,es12.4)") "circle: added acceleration ", a, " m/s**2; r psidot**2 = ", r*w**2
      call check(norm2(a + r*w**2*[cos(psi), sin(psi)]) <= 1e-12_wp*r*w**2, &
                 "circular whirl: the added acceleration is the centripetal -r psidot**2 e_r")
      call check(all(whirl_frame_acceleration([0.0_wp, 0.0_wp], v) == 0.0_wp), "on the axis: nothing added")
   end subroutine test_circle

   subroutine test_radial()
      real(wp) :: p(2), a(2)
      p = [3.0e-4_wp, -4.0e-4_wp]
      a = whirl_frame_acceleration(p, 0.2_wp*p/norm2(p))
      call check(norm2(a) <= 1e-12_wp*0.2_wp**2/norm2(p), "radial motion: no whirl term (round-off of 0.2 m/s radial)")
   end subroutine test_radial

   !> y = (p, v); dv/dt = whirl_frame_acceleration (no force)
   subroutine test_force_free_motion()
      real(wp) :: y(4), k1(4), k2(4), k3(4), k4(4), h, t, r0, rdot0, psi0, psidot0, r_end, psi_end, r, psi
      real(wp) :: work, p_old, ke0, ke
      integer :: i, n
      r0 = 2.0e-4_wp
      rdot0 = 1.0e-3_wp
      psi0 = 0.3_wp
      psidot0 = 958.0_wp
      y(1:2) = r0*[cos(psi0), sin(psi0)]
      y(3:4) = rdot0*[cos(psi0), sin(psi0)] + r0*psidot0*[-sin(psi0), cos(psi0)]
      t = 20.3_wp*2.0_wp*pi/psidot0
      n = 200000
      h = t/n
      ke0 = 0.5_wp*dot_product(y(3:4), y(3:4))
      work = 0.0_wp
      p_old = frame_power(y)
      do i = 1, n
         k1 = rate(y)
         k2 = rate(y + 0.5_wp*h*k1)
         k3 = rate(y + 0.5_wp*h*k2)
         k4 = rate(y + h*k3)
         y = y + h*(k1 + 2.0_wp*k2 + 2.0_wp*k3 + k4)/6.0_wp
         work = work + 0.5_wp*h*(p_old + frame_power(y))
         p_old = frame_power(y)
      end do
      ke = 0.5_wp*dot_product(y(3:4), y(3:4))
      r = norm2(y(1:2))
      r_end = r0 + rdot0*t
      psi = atan2(y(2), y(1))
      psi_end = modulo(psi0 + psidot0*t + pi, 2.0_wp*pi) - pi
      write (*, "(a,2es16.8,a,2f14.10)") "force-free, 20.3 periods: r ", r, r_end, " m; psi ", psi, psi_end
      call check(abs(r - r_end) <= 1e-9_wp*r_end, "force-free: r = r0 + rdot0 t (r'' = 0)")
      call check(abs(psi - psi_end) <= 1e-7_wp, "force-free: psi = psi0 + psidot0 t (r psi'' = 0)")
      write (*, "(a,3es16.8)") "force-free: kinetic energy change, closed form, frame work (J/kg) ", ke - ke0, &
         0.5_wp*psidot0**2*(r_end**2 - r0**2), work
      call check(abs((ke - ke0) - 0.5_wp*psidot0**2*(r_end**2 - r0**2)) <= 1e-8_wp*(ke - ke0), &
                 "force-free: kinetic energy change 1/2 psidot0**2 (r**2 - r0**2)")
      call check(abs(work - (ke - ke0)) <= 1e-8_wp*(ke - ke0), &
                 "force-free: the frame's work (integral of v_r v_t**2 / r) is the kinetic energy change")
   end subroutine test_force_free_motion

   !> a_w.v = v_r v_t**2 / r per unit mass at y = (p, v) (m**2/s**3).
   pure real(wp) function frame_power(y)
      real(wp), intent(in) :: y(4)
      real(wp) :: e_r(2), v_r, v_t
      e_r = y(1:2)/norm2(y(1:2))
      v_r = dot_product(y(3:4), e_r)
      v_t = y(4)*e_r(1) - y(3)*e_r(2)
      frame_power = v_r*v_t**2/norm2(y(1:2))
   end function frame_power

   pure function rate(y) result(d)
      real(wp), intent(in) :: y(4)
      real(wp) :: d(4)
      d(1:2) = y(3:4)
      d(3:4) = whirl_frame_acceleration(y(1:2), y(3:4))
   end function rate

end program test_adore_whirl
