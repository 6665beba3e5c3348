!> Engine unit tests of the roller/race slice traction (fortran/tribology/roller_traction.f90):
!> independent checks only (closed forms, a fine uniform quadrature, the moment balance);
!> the comparison with the report is in tests/test_roller_tribology.py.
program test_roller_traction
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_contact_line_slices, only: roller_profile_t, line_contact_t, line_contact, profile_drop
   use adore_tribology_roller_traction, only: roller_spin_t, line_traction_t, line_slip, line_traction, &
                                              roller_traction_moment, roller_equilibrium_spin, &
                                              RACE_OUTER, RACE_INNER
   use adore_tribology_traction_law, only: curve_law
   implicit none

   ! the Appendix D roller and traction curve (k0 0, kmax 0.1, kinf 0.08, umax 0.2 m/s)
   type(roller_profile_t), parameter :: prof = roller_profile_t(8.0e-3_wp, 2.0e-3_wp, 0.25_wp, [2.5e-4_wp, 2.5e-4_wp])
   real(wp), parameter :: coef(4) = [-0.08_wp, 0.9572392597877629_wp, 8.589122562472975_wp, 0.08_wp]
   real(wp), parameter :: k_line = 2.0e9_wp, e_star = 1.1e11_wp
   type(roller_spin_t), parameter :: kin = roller_spin_t(8.0e-3_wp, -19025.97_wp, -19025.97_wp, &
                                                        [-2983.3_wp, 4347.0_wp])

   call test_slip_closed_form()
   call test_power_converges_to_fine_quadrature()
   call test_equilibrium_spin_balances_the_moment()

   call finish("roller traction")

contains

   function contact(h0, n_sub) result(c)
      real(wp), intent(in) :: h0
      integer, intent(in) :: n_sub
      type(line_contact_t) :: c
      call line_contact(prof, 1.0e10_wp, [h0, 0.0_wp, 0.0_wp], [-4.0e-3_wp, 4.0e-3_wp], k_line, 3.5e-3_wp, &
                        e_star, n_sub, c)
   end function contact

   !> Rolling start: zero slip on the land, p (W - w_j) on the crown; a spin change dW
   !> adds +-dW D/2 on both races.
   subroutine test_slip_closed_form()
      type(roller_spin_t) :: k
      real(wp) :: x, p
      x = 1.9e-3_wp
      p = profile_drop(prof, x)
      call check(line_slip(prof, kin, RACE_OUTER, 0.5e-3_wp) == 0.0_wp, "outer land rolls")
      call check(line_slip(prof, kin, RACE_INNER, -0.9e-3_wp) == 0.0_wp, "inner land rolls")
      call check(abs(line_slip(prof, kin, RACE_OUTER, x) + p*(kin%spin - kin%race_speed(1))) < 1.0e-15_wp, &
                 "outer crown slip")
      call check(abs(line_slip(prof, kin, RACE_INNER, x) - p*(kin%spin - kin%race_speed(2))) < 1.0e-15_wp, &
                 "inner crown slip")
      k = kin
      k%spin = kin%spin + 10.0_wp
      call check(abs(line_slip(prof, k, RACE_OUTER, 0.0_wp) - 10.0_wp*4.0e-3_wp) < 1.0e-12_wp, "spin change, outer")
      call check(abs(line_slip(prof, k, RACE_INNER, 0.0_wp) + 10.0_wp*4.0e-3_wp) < 1.0e-12_wp, "spin change, inner")
   end subroutine test_slip_closed_form

   !> The 12-slice power (ADORE's grid) against 800 equal zones x 4 Gauss points, and the
   !> fine rule against 1600 zones (converged).
   subroutine test_power_converges_to_fine_quadrature()
      type(line_traction_t) :: t12, tf, tff
      call line_traction(prof, kin, RACE_OUTER, contact(5.7e-6_wp, 3), curve_law(coef), t12)
      call line_traction(prof, kin, RACE_OUTER, contact(5.7e-6_wp, 800), curve_law(coef), tf)
      call line_traction(prof, kin, RACE_OUTER, contact(5.7e-6_wp, 1600), curve_law(coef), tff)
      call check(tf%power > 0.0_wp, "power > 0")
      call check(abs(tff%power/tf%power - 1.0_wp) < 1.0e-5_wp, "fine quadrature converged")
      call check(abs(t12%power/tf%power - 1.0_wp) < 0.03_wp, "12 slices within 3 % of the fine quadrature")
      call check(abs(t12%force/tf%force - 1.0_wp) < 0.03_wp, "12-slice force within 3 %")
      print "(a,3es14.6)", "  power 12 slices / fine / finer (W):", t12%power, tf%power, tff%power
   end subroutine test_power_converges_to_fine_quadrature

   !> The spin found balances the moment; the moment decreases through the root.
   subroutine test_equilibrium_spin_balances_the_moment()
      type(line_contact_t) :: co, ci
      type(error_type), allocatable :: error
      real(wp) :: w, res, m0, scale
      type(line_traction_t) :: to
      co = contact(5.7e-6_wp, 3)
      ci = contact(4.3e-6_wp, 3)
      m0 = roller_traction_moment(prof, kin, kin%spin, co, ci, curve_law(coef), 0.0_wp)
      call line_traction(prof, kin, RACE_OUTER, co, curve_law(coef), to)
      scale = abs(to%moment)
      call roller_equilibrium_spin(prof, kin, co, ci, curve_law(coef), 0.0_wp, 0.2_wp, w, res, error)
      call check(.not. allocated(error), "spin found")
      print "(a,4es14.6)", "  M0, scale, residual, dW:", m0, scale, res, w - kin%spin
      call check(abs(res) <= 1.0e-9_wp*scale, "moment residual")
      call check(abs(roller_traction_moment(prof, kin, w, co, ci, curve_law(coef), 0.0_wp)) <= 1.0e-9_wp*scale, &
                 "moment at the returned spin")
      call check(m0 < 0.0_wp .and. w < kin%spin, "rolling start: both races speed the roller up (along -x)")
      call check(roller_traction_moment(prof, kin, w - 1.0_wp, co, ci, curve_law(coef), 0.0_wp) > 0.0_wp .and. &
                 roller_traction_moment(prof, kin, w + 1.0_wp, co, ci, curve_law(coef), 0.0_wp) < 0.0_wp, "moment sign change")
   end subroutine test_equilibrium_spin_balances_the_moment

end program test_roller_traction
