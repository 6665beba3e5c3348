!> Engine unit tests of the derived input quantities (fortran/model/): independent
!> checks only (closed forms, defining conditions, input errors); the comparison with
!> the report's echo is in tests/test_model_echo.py.
program test_model
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, ADORE_INPUT_ERROR
   use adore_model_clearance, only: ball_diametral_play, ball_end_play, ball_groove_diameters, &
                                    roller_race_diameters
   use adore_model_inertia, only: sphere_inertia, solid_cylinder_inertia, hollow_cylinder_inertia, &
                                  ball_cage_inertia, roller_cage_inertia, roller_moments
   use adore_tribology_traction_fit, only: fit_traction_curve, traction_coefficient, traction_slope
   use adore_model_scales, only: scale_factors
   implicit none


   call test_clearance()
   call test_inertia()
   call test_traction_fit()
   call test_traction_errors()
   call test_scales()

   call finish("model")

contains

   logical function close(a, b, rtol)
      real(wp), intent(in) :: a, b, rtol
      close = abs(a - b) <= rtol*max(abs(a), abs(b), tiny(1.0_wp))
   end function close

   subroutine test_clearance()
      real(wp) :: d, fo, fi, a0, pd, pe, dout, din, x, y
      d = 0.02_wp; fo = 0.52_wp; fi = 0.53_wp; a0 = 0.4_wp
      pd = ball_diametral_play(d, fo, fi, a0)
      pe = ball_end_play(d, fo, fi, a0)
      ! Geometry: curvature centres A = (fo+fi-1) d apart; radial and axial projections.
      x = (fo + fi - 1.0_wp)*d
      call check(close(pd/2.0_wp, x - x*cos(a0), 1.0e-14_wp), "Pd/2 = A (1 - cos a0)")
      call check(close(pe/2.0_wp, x*sin(a0), 1.0e-14_wp), "Pe/2 = A sin a0")
      call check(close((pd/2.0_wp - x)**2 + (pe/2.0_wp)**2, x**2, 1.0e-12_wp), "(Pd/2 - A)^2 + (Pe/2)^2 = A^2")
      call check(ball_diametral_play(d, fo, fi, 0.0_wp) == 0.0_wp, "zero contact angle, zero play")
      call ball_groove_diameters(0.1_wp, d, fo, fi, a0, dout, din)
      call check(close(dout - din - 2.0_wp*d, pd, 1.0e-9_wp), "groove diameters differ by 2 D + Pd")
      call check(close((dout - 0.1_wp - d)/(0.1_wp - d - din), (fo - 0.5_wp)/(fi - 0.5_wp), 1.0e-9_wp), &
                 "play split in ratio (fo - 1/2) : (fi - 1/2)")
      call roller_race_diameters(0.05_wp, 0.01_wp, 4.0e-5_wp, x, y)
      call check(close(x, 0.06002_wp, 1.0e-14_wp) .and. close(y, 0.03998_wp, 1.0e-14_wp), "roller raceways")
   end subroutine test_clearance

   subroutine test_inertia()
      real(wp) :: m, mom(3), m2, mom2(3), r, ro, ri, w, rho
      rho = 8000.0_wp; r = 0.01_wp
      call sphere_inertia(2.0_wp*r, rho, m, mom)
      call check(close(m, rho*4.0_wp/3.0_wp*pi*r**3, 1.0e-14_wp), "sphere mass 4/3 pi r^3 rho")
      call check(all(abs(mom - 0.4_wp*m*r**2) <= 1.0e-14_wp*mom), "sphere I = 2/5 m r^2")
      ! Hollow cylinder = solid(ro) - solid(ri), mass and moments additive.
      ro = 0.05_wp; ri = 0.03_wp; w = 0.02_wp
      call hollow_cylinder_inertia(2.0_wp*ro, 2.0_wp*ri, w, rho, m, mom)
      call solid_cylinder_inertia(2.0_wp*ro, w, rho, m2, mom2)
      block
         real(wp) :: m3, mom3(3)
         call solid_cylinder_inertia(2.0_wp*ri, w, rho, m3, mom3)
         call check(close(m, m2 - m3, 1.0e-13_wp), "hollow cylinder mass = difference of solids")
         call check(close(mom(1), mom2(1) - mom3(1), 1.0e-12_wp), "hollow cylinder Ix = difference of solids")
         call check(close(mom(2), mom2(2) - mom3(2), 1.0e-12_wp), "hollow cylinder Iy = difference of solids")
      end block
      call check(close(mom2(1), 0.5_wp*m2*ro**2, 1.0e-14_wp), "solid cylinder Ix = m r^2 / 2")
      call check(close(mom2(2), m2*(3.0_wp*ro**2 + w**2)/12.0_wp, 1.0e-14_wp), "solid cylinder Iy")
      call check(mom(2) == mom(3), "Iy = Iz")
      ! Cage without pockets is the hollow cylinder; pockets remove n*pi/4 d^2 t of volume.
      call ball_cage_inertia(2.0_wp*ro, 2.0_wp*ri, w, 0, 0.01_wp, rho, m2, mom2)
      call check(close(m2, m, 1.0e-14_wp) .and. all(abs(mom2 - mom) <= 1.0e-14_wp*mom), "cage, no pockets")
      call ball_cage_inertia(2.0_wp*ro, 2.0_wp*ri, w, 10, 0.01_wp, rho, m2, mom2)
      call check(close(m - m2, rho*10*pi/4*0.01_wp**2*(ro - ri), 1.0e-12_wp), "ball cage pocket volume")
      call roller_cage_inertia(2.0_wp*ro, 2.0_wp*ri, w, 10, 0.01_wp, 0.012_wp, rho, m2, mom2)
      call check(close(m - m2, rho*10*0.01_wp*0.012_wp*(ro - ri), 1.0e-12_wp), "roller cage pocket volume")
      call check(close(mom2(1)/m2, mom(1)/m, 1.0e-14_wp), "cage radius of gyration unchanged by pockets")
      mom = roller_moments(2.0_wp, 0.01_wp, 0.02_wp)
      call check(close(mom(1), 0.5_wp*2.0_wp*0.005_wp**2, 1.0e-14_wp), "roller Ix")
   end subroutine test_inertia

   subroutine test_traction_fit()
      real(wp) :: cases(4, 5), coef(4), k0, kmax, kinf, umax
      type(error_type), allocatable :: error
      integer :: i
      ! (k0, kmax, kinf, umax): k0 < kinf, k0 > kinf, k0 = kinf, extremes.
      cases = reshape([0.0_wp, 0.02_wp, 0.016_wp, 1.0_wp, &
                       0.05_wp, 0.08_wp, 0.01_wp, 0.3_wp, &
                       0.03_wp, 0.07_wp, 0.03_wp, 2.0_wp, &
                       0.0_wp, 0.1_wp, 0.0999_wp, 1.0e-3_wp, &
                       0.0999_wp, 0.1_wp, 0.0_wp, 5.0_wp], [4, 5])
      do i = 1, size(cases, 2)
         k0 = cases(1, i); kmax = cases(2, i); kinf = cases(3, i); umax = cases(4, i)
         call fit_traction_curve(k0, kmax, kinf, umax, coef, error)
         call check(.not. allocated(error), "traction fit accepts a valid case")
         if (allocated(error)) cycle
         call check(coef(3) > 0.0_wp, "C > 0")
         call check(abs(traction_coefficient(coef(1), coef(2), coef(3), coef(4), 0.0_wp) - k0) <= 1.0e-13_wp, &
                    "kappa(0) = k0")
         call check(abs(traction_coefficient(coef(1), coef(2), coef(3), coef(4), 1.0e3_wp*umax + 1.0e3_wp/coef(3)) &
                        - kinf) <= 1.0e-12_wp, "kappa(inf) = kinf")
         call check(abs(traction_coefficient(coef(1), coef(2), coef(3), coef(4), umax) - kmax) <= 1.0e-12_wp, &
                    "kappa(umax) = kmax")
         call check(abs(traction_slope(coef(1), coef(2), coef(3), umax))*umax <= 1.0e-12_wp, "kappa'(umax) = 0")
         call check(traction_coefficient(coef(1), coef(2), coef(3), coef(4), 0.9_wp*umax) < kmax .and. &
                    traction_coefficient(coef(1), coef(2), coef(3), coef(4), 1.1_wp*umax) < kmax, "umax is a maximum")
      end do
   end subroutine test_traction_fit

   subroutine test_traction_errors()
      real(wp) :: coef(4)
      type(error_type), allocatable :: error
      call fit_traction_curve(0.0_wp, 0.02_wp, 0.016_wp, 0.0_wp, coef, error)
      call check(allocated(error), "umax = 0 rejected")
      if (allocated(error)) call check(error%stat == ADORE_INPUT_ERROR .and. index(error%message, "slip") > 0, &
                                       "umax error is an input error naming the slip")
      call fit_traction_curve(0.0_wp, 0.016_wp, 0.016_wp, 1.0_wp, coef, error)
      call check(allocated(error), "kmax = kinf rejected")
      call fit_traction_curve(0.03_wp, 0.02_wp, 0.01_wp, 1.0_wp, coef, error)
      call check(allocated(error), "kmax < k0 rejected")
      if (allocated(error)) call check(index(error%message, "maximum") > 0, "kmax error message")
   end subroutine test_traction_errors

   subroutine test_scales()
      real(wp) :: s(3)
      type(error_type), allocatable :: error
      call scale_factors(0.02_wp, 0.5_wp, [100.0_wp, 30.0_wp, 40.0_wp], s, error)
      call check(.not. allocated(error), "scales accepted")
      call check(close(s(1), 0.01_wp, 1.0e-15_wp), "length scale = radius")
      call check(close(s(2), 100.0_wp, 1.0e-15_wp), "load scale = max(axial, radial)")
      call check(close(s(3)**2*s(2), 0.5_wp*s(1), 1.0e-14_wp), "T^2 F = m L")
      call scale_factors(0.02_wp, 0.5_wp, [0.0_wp, 0.0_wp, 0.0_wp], s, error)
      call check(allocated(error), "zero load rejected")
      ! a tilting moment counts as the ball load M / arm on the pitch circle; a torque about
      ! the axis (Mx) loads no contact and does not count
      call scale_factors(0.02_wp, 0.5_wp, [0.01_wp, 0.0_wp, 0.0_wp], s, error, [7.0_wp, 3.0_wp, 4.0_wp], 0.025_wp)
      call check(.not. allocated(error), "moment scales accepted")
      call check(close(s(2), 5.0_wp/0.025_wp, 1.0e-15_wp), "load scale = |(My, Mz)| / arm")
      call scale_factors(0.02_wp, 0.5_wp, [300.0_wp, 0.0_wp, 0.0_wp], s, error, [0.0_wp, 3.0_wp, 4.0_wp], 0.025_wp)
      call check(close(s(2), 300.0_wp, 1.0e-15_wp), "a larger force keeps the load scale")
      ! the start's largest contact load, when larger than the applied load, is the scale
      ! (a light load on a bearing preloaded by its fit); a smaller one changes nothing
      call scale_factors(0.02_wp, 0.5_wp, [1.0_wp, 0.0_wp, 0.0_wp], s, error, contact=12.0_wp)
      call check(close(s(2), 12.0_wp, 1.0e-15_wp), "load scale = the larger contact load")
      call check(close(s(3)**2*s(2), 0.5_wp*s(1), 1.0e-14_wp), "T^2 F = m L with the contact load")
      call scale_factors(0.02_wp, 0.5_wp, [4500.0_wp, 0.0_wp, 0.0_wp], s, error, contact=2474.0_wp)
      call check(close(s(2), 4500.0_wp, 1.0e-15_wp), "a smaller contact load keeps the applied load's scale")
      call scale_factors(0.02_wp, 0.5_wp, [0.0_wp, 0.0_wp, 0.0_wp], s, error, contact=12.0_wp)
      call check(allocated(error), "zero applied load still rejected")
   end subroutine test_scales

end program test_model
