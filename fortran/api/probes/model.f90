!> Flat f2py wrappers of the derived input quantities (fortran/model/, test-only module
!> pyadore._probes).  All SI (angles in rad); every wrapper ends with (status, message).

!> Ball bearing clearance: result = [Pd, Pe, d_outer_groove, d_inner_groove] (m).
subroutine adore_model_ball_clearance(dm, d, fo, fi, alpha0, result, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_model_clearance, only: ball_diametral_play, ball_end_play, ball_groove_diameters
   implicit none
   real(wp), intent(in) :: dm, d, fo, fi, alpha0
   real(wp), intent(out) :: result(4)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   if (.not. (dm > d .and. d > 0.0_wp .and. fo > 0.5_wp .and. fi > 0.5_wp)) then
      status = ADORE_INPUT_ERROR
      message = "ball clearance: need pitch diameter > ball diameter > 0 and curvature factors > 0.5"
      return
   end if
   result(1) = ball_diametral_play(d, fo, fi, alpha0)
   result(2) = ball_end_play(d, fo, fi, alpha0)
   call ball_groove_diameters(dm, d, fo, fi, alpha0, result(3), result(4))
end subroutine adore_model_ball_clearance

!> Roller bearing raceway diameters: result = [d_outer, d_inner] (m).
subroutine adore_model_roller_races(dm, d, pd, result, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_model_clearance, only: roller_race_diameters
   implicit none
   real(wp), intent(in) :: dm, d, pd
   real(wp), intent(out) :: result(2)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   if (.not. (dm > d .and. d > 0.0_wp)) then
      status = ADORE_INPUT_ERROR
      message = "roller races: need pitch diameter > roller diameter > 0"
      return
   end if
   call roller_race_diameters(dm, d, pd, result(1), result(2))
end subroutine adore_model_roller_races

!> Body inertia: kind 1 sphere (p1 = d), 2 solid cylinder (p1 = d, p2 = length),
!> 3 hollow cylinder (p1 = d_out, p2 = d_in, p3 = width), 4 ball cage (p1..p3 as 3,
!> p4 = pocket diameter), 5 roller cage (p1..p3 as 3, p4 = pocket circumferential,
!> p5 = pocket axial size), 6 roller moments of given mass (p1 = d, p2 = length,
!> rho = mass in kg); n = number of pockets.  result = [mass (kg), Ix, Iy, Iz (kg m**2)].
subroutine adore_model_inertia(kind, p, n, rho, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK, ADORE_INPUT_ERROR
   use adore_model_inertia, only: sphere_inertia, solid_cylinder_inertia, hollow_cylinder_inertia, &
                                  ball_cage_inertia, roller_cage_inertia, roller_moments, check_positive
   implicit none
   integer, intent(in) :: kind
   real(wp), intent(in) :: p(5)
   integer, intent(in) :: n
   real(wp), intent(in) :: rho
   real(wp), intent(out) :: result(4)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(error_type), allocatable :: error
   real(wp) :: mass, moments(3)

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   select case (kind)
   case (1)
      call check_positive([p(1), rho], [character(len=16) :: "diameter", "density"], error)
      if (.not. allocated(error)) call sphere_inertia(p(1), rho, mass, moments)
   case (2)
      call check_positive([p(1), p(2), rho], [character(len=16) :: "diameter", "length", "density"], error)
      if (.not. allocated(error)) call solid_cylinder_inertia(p(1), p(2), rho, mass, moments)
   case (3, 4, 5)
      call check_positive([p(1) - p(2), p(2), p(3), rho], &
                          [character(len=24) :: "outer - inner diameter", "inner diameter", "width", "density"], error)
      if (.not. allocated(error)) then
         select case (kind)
         case (3)
            call hollow_cylinder_inertia(p(1), p(2), p(3), rho, mass, moments)
         case (4)
            call check_positive([p(4), real(n, wp)], [character(len=24) :: "pocket diameter", "number of pockets"], error)
            if (.not. allocated(error)) call ball_cage_inertia(p(1), p(2), p(3), n, p(4), rho, mass, moments)
         case (5)
            call check_positive([p(4), p(5), real(n, wp)], &
                                [character(len=24) :: "pocket width", "pocket length", "number of pockets"], error)
            if (.not. allocated(error)) call roller_cage_inertia(p(1), p(2), p(3), n, p(4), p(5), rho, mass, moments)
         end select
         if (.not. allocated(error)) then
            if (.not. (mass > 0.0_wp)) then
               status = ADORE_INPUT_ERROR
               message = "cage inertia: the pockets remove all of the cage (mass <= 0)"
               return
            end if
         end if
      end if
   case (6)
      call check_positive([p(1), p(2), rho], [character(len=16) :: "diameter", "length", "mass"], error)
      if (.not. allocated(error)) then
         mass = rho
         moments = roller_moments(mass, p(1), p(2))
      end if
   case default
      status = ADORE_INPUT_ERROR
      message = "inertia: unknown body kind (1-6)"
      return
   end select
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   result = [mass, moments]
end subroutine adore_model_inertia

!> Traction curve fit: result = [A, B (s/m), C (s/m), D] from k0, kmax, kinf, umax (m/s).
subroutine adore_tribology_traction_fit(k0, kmax, kinf, umax, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_tribology_traction_fit, only: fit_traction_curve
   implicit none
   real(wp), intent(in) :: k0, kmax, kinf, umax
   real(wp), intent(out) :: result(4)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(error_type), allocatable :: error

   status = ADORE_OK
   message = ""
   call fit_traction_curve(k0, kmax, kinf, umax, result, error)
   if (allocated(error)) then
      call set_error(error, status, message)
   end if
end subroutine adore_tribology_traction_fit

!> Scale factors: result = [length (m), load (N), time (s)] from the rolling-element
!> diameter (m), mass (kg) and applied load vector [Fx, Fy, Fz] (N).
subroutine adore_model_scales(d_re, mass_re, load, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_model_scales, only: scale_factors
   implicit none
   real(wp), intent(in) :: d_re, mass_re, load(3)
   real(wp), intent(out) :: result(3)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(error_type), allocatable :: error

   status = ADORE_OK
   message = ""
   call scale_factors(d_re, mass_re, load, result, error)
   if (allocated(error)) then
      call set_error(error, status, message)
   end if
end subroutine adore_model_scales
