!> Flat f2py wrappers of the tribology the package and the benchmark use (module
!> pyadore._engine): lubricant library, EHD contact traction by method and its timing,
!> traction-slip table files.

!> Lubricant of the library at temperature t (K) and pressure p (Pa): result =
!> [kinematic viscosity at p = 0 (m**2/s), dynamic viscosity at (t, p) (Pa s), beta (1/K),
!> alpha (1/Pa), conductivity (W/m/K), density (kg/m**3), heat capacity (J/kg/K), T_ref (K),
!> traction viscosity at t and p = 0 (Pa s), its pressure (1/Pa) and temperature (1/K) coefficients].
subroutine adore_tribo_lubricant(code, t, p, result, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK, input_error
   use adore_tribology_film, only: lubricant_t, lubricant_from_code, kinematic_viscosity, &
                                   dynamic_viscosity, temperature_viscosity_coefficient, traction_viscosity
   implicit none
   integer, intent(in) :: code
   real(wp), intent(in) :: t, p
   real(wp), intent(out) :: result(11)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error
   type(lubricant_t) :: lub

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   call lubricant_from_code(code, lub, error)
   if (.not. allocated(error) .and. .not. (t > 0.0_wp)) &
      call input_error(error, "lubricant: temperature must be > 0 K")
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   result = [kinematic_viscosity(lub, t), dynamic_viscosity(lub, t, p), &
             temperature_viscosity_coefficient(lub, t), lub%alpha, lub%conductivity, lub%density, &
             lub%heat_capacity, lub%t_ref, traction_viscosity(lub, t), lub%alpha_t, lub%beta_t]
end subroutine adore_tribo_lubricant

!> EHD contact traction by the reference quadrature (method 0: ehd_contact_traction with
!> n_major Gauss points per slip zone and n_strip across each strip) or the fast one
!> (method 1: ehd_contact_traction_fast with n_major, n_strip; 0 takes its defaults).
!> geom = [side (+1 outer, -1 inner), alpha (rad), rho (m), r_b (m), w_x, w_r (rad/s),
!> Omega - w_m (rad/s), a (m), Q (N)] (contact_from_geom, fortran/api/unpack.f90);
!> rheo = [eta_w (Pa s), alpha_t (1/Pa), beta_t (1/K), K_f (W/m/K)]; h film (m); b semi-minor
!> axis (m).  two_d = 1: the two-dimensional traction with
!> the transverse slip coefficients transverse (m/s; ehd_contact_traction's transverse);
!> 0: one-dimensional (transverse unused).  result = [force (N), force_cos (N), force_sin
!> (N), power (W), sliding (N m/s), max slip (m/s), coefficient, n rolling points,
!> cross_force(1:3) (N, 0 in one dimension)].
subroutine adore_tribo_ehd_contact_method(geom, rheo, h, b, method, n_major, n_strip, two_d, transverse, result, &
                                          status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK, input_error
   use adore_tribology_slip, only: contact_traction_t
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_contact_traction_fast, &
                                           EHD_FAST_MAJOR, EHD_FAST_STRIP
   use adore_api_unpack, only: contact_from_geom
   implicit none
   real(wp), intent(in) :: geom(9), rheo(4), h, b, transverse(3)
   integer, intent(in) :: method, n_major, n_strip, two_d
   real(wp), intent(out) :: result(11)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error
   type(contact_traction_t) :: t

   result = 0.0_wp
   status = ADORE_OK
   message = ""
   call ehd_method(contact_from_geom(geom), ehd_rheology_t(eta_w=rheo(1), alpha=rheo(2), beta=rheo(3), &
                   conductivity=rheo(4)), h, b, method, n_major, n_strip, t, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   result = [t%force, t%force_cos, t%force_sin, t%power, t%sliding, t%max_slip, t%coefficient, real(t%n_rolling, wp), &
             t%cross_force]

contains

   !> the contact by the chosen method
   subroutine ehd_method(c, rh, h, b, method, n_major, n_strip, t, error)
      use adore_tribology_slip, only: ball_race_contact_t
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rh
      real(wp), intent(in) :: h, b
      integer, intent(in) :: method, n_major, n_strip
      type(contact_traction_t), intent(out) :: t
      type(error_type), allocatable, intent(out) :: error
      select case (method*2 + merge(1, 0, two_d /= 0))
      case (0)
         call ehd_contact_traction(c, rh, h, b, n_major, n_strip, t, error)
      case (1)
         call ehd_contact_traction(c, rh, h, b, n_major, n_strip, t, error, transverse)
      case (2)
         call ehd_contact_traction_fast(c, rh, h, b, t, error, merge(n_major, EHD_FAST_MAJOR, n_major > 0), &
                                        merge(n_strip, EHD_FAST_STRIP, n_strip > 0))
      case (3)
         call ehd_contact_traction_fast(c, rh, h, b, t, error, merge(n_major, EHD_FAST_MAJOR, n_major > 0), &
                                        merge(n_strip, EHD_FAST_STRIP, n_strip > 0), transverse)
      case default
         call input_error(error, "EHD contact: method must be 0 (reference) or 1 (fast)")
      end select
   end subroutine ehd_method

end subroutine adore_tribo_ehd_contact_method

!> Mean CPU time (microseconds) of one EHD contact evaluation (force, moment and loss of one
!> ball/race contact), method 0 (reference, 16 x 24 points: EHD_GAUSS x EHD_STRIP) or 1
!> (fast, default orders), over n_rep evaluations; geom, rheo, h, b as
!> adore_tribo_ehd_contact_method.  For the benchmark (bench/run_bench.py), never for tests.
subroutine adore_tribo_ehd_contact_time(geom, rheo, h, b, method, n_rep, microseconds, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK, input_error
   use adore_tribology_slip, only: contact_traction_t, ball_race_contact_t
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_contact_traction_fast
   use adore_forces_race_contact, only: EHD_GAUSS, EHD_STRIP
   use adore_api_unpack, only: contact_from_geom
   implicit none
   real(wp), intent(in) :: geom(9), rheo(4), h, b
   integer, intent(in) :: method, n_rep
   real(wp), intent(out) :: microseconds
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(error_type), allocatable :: error
   type(contact_traction_t) :: t
   type(ball_race_contact_t) :: c
   type(ehd_rheology_t) :: rh
   real(wp) :: t0, t1, sink
   integer :: i

   microseconds = 0.0_wp
   status = ADORE_OK
   message = ""
   if (n_rep < 1 .or. (method /= 0 .and. method /= 1)) then
      call input_error(error, "EHD contact timing: need n_rep >= 1 and method 0 or 1")
      call set_error(error, status, message)
      return
   end if
   c = contact_from_geom(geom)
   rh = ehd_rheology_t(eta_w=rheo(1), alpha=rheo(2), beta=rheo(3), conductivity=rheo(4))
   sink = 0.0_wp
   call cpu_time(t0)
   do i = 1, n_rep
      c%load = geom(9)*(1.0_wp + 1.0e-12_wp*i)    ! a new state each time (nothing hoisted)
      if (method == 0) then
         call ehd_contact_traction(c, rh, h, b, EHD_GAUSS, EHD_STRIP, t, error)
      else
         call ehd_contact_traction_fast(c, rh, h, b, t, error)
      end if
      if (allocated(error)) then
         call set_error(error, status, message)
         return
      end if
      sink = sink + t%power + t%force_cos
   end do
   call cpu_time(t1)
   microseconds = (t1 - t0)/n_rep*1.0e6_wp
   if (.not. (sink == sink)) microseconds = -1.0_wp
end subroutine adore_tribo_ehd_contact_time

!> Traction-slip table file (ADRX7, adore_deck_traction_table): its n points, slip (m/s)
!> and kappa (-), checked as a run checks them.  Call with nmax = 0 for n alone, then with
!> nmax = n for the points.  Input error (message with file:line:col) for a bad file.
subroutine adore_tribo_traction_table(path, nmax, n, slip, kappa, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, ADORE_OK
   use adore_api_status, only: set_error
   use adore_tribology_traction_law, only: traction_law_t
   use adore_deck_traction_table, only: read_traction_table
   implicit none
   character(len=*), intent(in) :: path
   integer, intent(in) :: nmax
   integer, intent(out) :: n
   real(wp), intent(out) :: slip(nmax), kappa(nmax)
   integer, intent(out) :: status
   character(len=8192), intent(out) :: message
   type(error_type), allocatable :: error
   type(traction_law_t) :: law

   n = 0
   slip = 0.0_wp
   kappa = 0.0_wp
   status = ADORE_OK
   message = ""
   call read_traction_table(path, law, error)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   n = size(law%slip)
   if (nmax >= n) then
      slip(:n) = law%slip
      kappa(:n) = law%kappa
   end if
end subroutine adore_tribo_traction_table
