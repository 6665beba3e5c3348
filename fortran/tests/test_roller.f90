!> Engine unit tests of the roller line contact and equilibrium (fortran/contact/line_slices.f90,
!> fortran/quasistatic/roller_equilibrium.f90): independent checks only (closed forms,
!> defining conditions, finite differences); the comparison with the report is in
!> tests/test_roller_step0.py.
program test_roller
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_contact_line_slices, only: roller_profile_t, line_contact_t, profile_drop, roller_mass, &
                                        contact_modulus, line_stiffness, line_contact
   use adore_quasistatic_roller_equilibrium, only: roller_qs_bearing_t, roller_qs_load_t, &
                                                   roller_qs_solution_t, solve_roller_equilibrium, &
                                                   solve_roller, roller_contacts
   implicit none


   call test_profile_and_mass()
   call test_roller_response_matches_finite_differences()
   call test_misaligned_race()
   call test_skew_shortens_the_inner_contact()

   call finish("roller")

contains

   !> The Appendix D roller as a contact model (growth applied as in the report).
   function appendix_d() result(b)
      type(roller_qs_bearing_t) :: b
      b%n_rollers = 8
      b%d = 8.0e-3_wp
      b%profile = roller_profile_t(8.0e-3_wp, 2.0e-3_wp, 0.25_wp, [2.5e-4_wp, 2.5e-4_wp])
      b%mass = roller_mass(b%profile, b%d, 3200.0_wp)
      b%r_o = 0.5_wp*51.02e-3_wp
      b%r_i = 0.5_wp*34.98e-3_wp + 2.0_wp*1.1130e-5_wp
      b%lim_o = [-4.0e-3_wp, 4.0e-3_wp]
      b%lim_i = b%lim_o
      b%e_o = contact_modulus(3.1e11_wp, 0.26_wp, 2.0e11_wp, 0.25_wp)
      b%e_i = b%e_o
      b%k_o = line_stiffness(b%e_o, 4.0e-3_wp)
      b%k_i = b%k_o
   end function appendix_d

   subroutine test_profile_and_mass()
      type(roller_profile_t) :: p, straight
      p = roller_profile_t(8.0e-3_wp, 2.0e-3_wp, 0.25_wp, [2.5e-4_wp, 2.5e-4_wp])
      call check(profile_drop(p, 0.9e-3_wp) == 0.0_wp, "no drop on the land")
      call check(abs(profile_drop(p, -2.0e-3_wp) - 3.0e-6_wp/0.5_wp) < 1.0e-18_wp, "crown arc centred on the mid-plane")
      call check(abs(profile_drop(p, 4.0e-3_wp) - ((16.0e-6_wp - 1.0e-6_wp)/0.5_wp + 2.5e-4_wp)) < 1.0e-15_wp, &
                 "corner arc adds its radius at the end face")
      call check(abs(roller_mass(p, 8.0e-3_wp, 3200.0_wp)/1.28108e-3_wp - 1.0_wp) < 1.0e-4_wp, &
                 "crowned roller mass is the echo's RE mass")
      straight = roller_profile_t(8.0e-3_wp, 8.0e-3_wp, 1.0e10_wp, [0.0_wp, 0.0_wp])
      call check(abs(roller_mass(straight, 8.0e-3_wp, 3200.0_wp)/(3200.0_wp*pi*16.0e-6_wp*8.0e-3_wp) - 1.0_wp) &
                 < 1.0e-13_wp, "straight roller mass = rho pi D**2 L / 4")
   end subroutine test_profile_and_mass

   !> d(Q_i, M_i)/d(u_r, t_r) with the roller re-solved, against central differences.
   !> The analytic derivatives are those of the contact integrals (the boundary terms vanish,
   !> q = 0 at the contact ends); the finite differences see the discrete rule whose nodes
   !> move with the ends, so a fine rule is used (observed 0.02-0.7 %; on ADORE's 12-point
   !> grid the cross terms differ by up to 35 %, which only slows Newton down).
   subroutine test_roller_response_matches_finite_differences()
      type(roller_qs_bearing_t) :: b
      type(line_contact_t) :: co, ci
      real(wp) :: r, g, fc, dq0(2), dm0(2), qp, qm, mp, mm, h, w, hs
      logical :: ok
      integer :: j

      b = appendix_d()
      b%n_sub = 200
      w = 2983.3_wp
      h = 1.0e-9_wp
      r = b%r_o - 0.5_wp*b%d
      g = 0.0_wp
      call solve_roller(b, 3.0e-6_wp, 2.0e-4_wp, 0.0_wp, w, r, g, co, ci, fc, dq0, dm0, ok)
      call check(ok, "roller equilibrium converges")
      call check(abs(ci%load - co%load + fc) < 1.0e-8_wp*fc, "roller radial balance")
      call check(abs(ci%moment - co%moment) < 1.0e-10_wp, "roller moment balance")
      call check(abs(g) > 1.0e-6_wp, "a tilted race tilts the roller")
      do j = 1, 2
         hs = merge(h, h/4.0e-3_wp, j == 1)    ! tilt step: h at the roller end
         call resolve(b, w, r, g, j, hs, qp, mp)
         call resolve(b, w, r, g, j, -hs, qm, mm)
         call check(abs((qp - qm)/(2.0_wp*hs) - dq0(j)) < 1.0e-2_wp*abs(dq0(j)), "dQ_i/du analytic = finite difference")
         call check(abs((mp - mm)/(2.0_wp*hs) - dm0(j)) < 1.0e-2_wp*abs(dm0(j)), &
                    "dM_i/du analytic = finite difference")
      end do

   end subroutine test_roller_response_matches_finite_differences

   !> Inner contact load and moment of the roller re-solved at (u_r, t_r) = (3e-6, 2e-4)
   !> with component jj moved by step, from the start (r, g).
   subroutine resolve(b, w, r, g, jj, step, q, m)
      type(roller_qs_bearing_t), intent(in) :: b
      real(wp), intent(in) :: w, r, g, step
      integer, intent(in) :: jj
      real(wp), intent(out) :: q, m
      type(line_contact_t) :: co, ci
      real(wp) :: u(2), rr, gg, fc, dq(2), dm(2)
      logical :: ok
      u = [3.0e-6_wp, 2.0e-4_wp]
      u(jj) = u(jj) + step
      rr = r
      gg = g
      call solve_roller(b, u(1), u(2), 0.0_wp, w, rr, gg, co, ci, fc, dq, dm, ok)
      q = ci%load
      m = ci%moment
   end subroutine resolve

   !> A prescribed misalignment: forces still balance, rollers tilt, and the rollers' moment
   !> on the inner race opposes the misalignment.
   subroutine test_misaligned_race()
      type(roller_qs_bearing_t) :: b
      type(roller_qs_load_t) :: ld
      type(roller_qs_solution_t) :: s
      type(error_type), allocatable :: error
      real(wp) :: w(8)

      b = appendix_d()
      ld%force = [0.0_wp, 0.0_wp, 1000.0_wp]
      ld%misalignment = [3.0e-4_wp, 0.0_wp]
      w = 2983.3_wp
      call solve_roller_equilibrium(b, ld, w, s, error)
      call check(.not. allocated(error), "misaligned equilibrium converges")
      if (allocated(error)) return
      call check(maxval(abs(s%inner_force(2:3) + ld%force(2:3))) <= 1.0e-8_wp*1000.0_wp, "race force balance")
      call check(abs(s%tilt(1)) > 1.0e-6_wp, "loaded roller follows the tilted race")
      call check(s%inner_moment(2) < 0.0_wp, "roller moment opposes theta_2 > 0")
      call check(abs(s%inner_moment(3)) < 1.0e-6_wp*abs(s%inner_moment(2)), "no moment about z for theta_2 only")
   end subroutine test_misaligned_race

   subroutine test_skew_shortens_the_inner_contact()
      type(roller_qs_bearing_t) :: b
      type(line_contact_t) :: o0, i0, o1, i1
      real(wp) :: r
      b = appendix_d()
      r = b%r_o - 0.5_wp*b%d + 2.0e-6_wp
      call roller_contacts(b, r, 0.0_wp, 4.0e-6_wp, 0.0_wp, 0.0_wp, o0, i0)
      call roller_contacts(b, r, 0.0_wp, 4.0e-6_wp, 0.0_wp, 0.02_wp, o1, i1)
      call check(o1%load > o0%load .and. i1%load < i0%load, "skew loads the outer ends, unloads the inner ends")
      call check(o1%half_length > o0%half_length .and. i1%half_length < i0%half_length, "skew changes contact lengths")
   end subroutine test_skew_shortens_the_inner_contact

end program test_roller
