!> Flash temperature rise of a ball/race contact with the heat of its EHD film (report
!> 2.7-2.8, eqs 35-36): the film shear of adore_tribology_ehd_traction (traction model 3)
!> as the heat flux on strips across the minor axis, each strip by eq 35
!> (adore_tribology_flash).  Units SI.
module adore_tribology_ehd_flash
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_tribology_flash, only: strip_temperature_rise, flash_trapezoid_weights
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_slip, major_axis_nodes
   use adore_tribology_ehd_traction, only: ehd_rheology_t, film_shear_stress, ehd_contact_traction, film_constants, &
                                           limited_shear, &
                                           thermal_film_shear
   implicit none
   private

   public :: ehd_temperature_rise

contains

   !> Average (eq 36) and largest flash temperature rise (K) of contact c with the heat of
   !> its EHD film: flux q = tau(p, u) |u| (W/m**2; tau capped at Lambda p with a limiting
   !> shear stress, limited_shear) on strips across the minor axis at the
   !> n_gauss Gauss points per slip zone of the major axis, ny >= 2 uniform points per
   !> strip, each strip by eq 35 (adore_tribology_flash); rheo, h, b as ehd_contact_traction;
   !> u1, u2 surface speeds (m/s) and th1, th2 = [density, heat capacity, conductivity] of
   !> the two bodies.  Without dt_max the average alone, by the trapezoid weights of
   !> adore_tribology_flash's flash_trapezoid_weights (O(ny) per strip, the same sum).
   subroutine ehd_temperature_rise(c, rheo, h, b, n_gauss, ny, u1, u2, th1, th2, dt_avg, dt_max, error)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b, u1, u2, th1(3), th2(3)
      integer, intent(in) :: n_gauss, ny
      real(wp), intent(out) :: dt_avg
      real(wp), intent(out), optional :: dt_max
      type(error_type), allocatable, intent(out) :: error
      type(contact_traction_t) :: t
      real(wp), allocatable :: x(:), w(:), eta(:), q(:), dt(:), p(:), cw(:)
      real(wp) :: u, ek, bk, p0, strip, denom, amp, zeta
      integer :: j, i, half_ny

      dt_avg = 0.0_wp
      if (present(dt_max)) dt_max = 0.0_wp
      call ehd_contact_traction(c, rheo, h, b, 1, 1, t, error)      ! validates the inputs
      if (allocated(error)) return
      if (ny < 2 .or. n_gauss < 1 .or. .not. (minval(th1) > 0.0_wp .and. minval(th2) > 0.0_wp .and. &
                                               abs(u1) + abs(u2) > 0.0_wp)) then
         call input_error(error, "EHD temperature: need n_gauss >= 1, ny >= 2, positive thermal properties "// &
                          "and a moving surface")
         return
      end if
      call major_axis_nodes(c, n_gauss, t, x, w)
      allocate (eta(ny), q(ny), dt(ny), p(ny), cw(ny))
      eta = [(-1.0_wp + 2.0_wp*real(i - 1, wp)/real(ny - 1, wp), i=1, ny)]
      if (.not. present(dt_max)) call flash_trapezoid_weights(ny, cw)
      half_ny = (ny + 1)/2
      call film_constants(rheo, h, amp, zeta)
      denom = sqrt(pi*th1(1)*th1(2)*th1(3)*abs(u1)) + sqrt(pi*th2(1)*th2(2)*th2(3)*abs(u2))
      p0 = 1.5_wp*c%load/(pi*c%a*b)
      do j = 1, size(x)
         ek = 1.0_wp - (x(j)/c%a)**2
         if (ek <= 0.0_wp) cycle
         u = contact_slip(c, x(j))
         bk = b*sqrt(ek)
         p = p0*sqrt(ek)*sqrt(max(1.0_wp - eta**2, 0.0_wp))
         if (rheo%limiting_shear > 0.0_wp) then
            ! with a limiting shear stress (run option limiting_shear): the capped film's heat
            q = limited_shear(film_shear_stress(rheo%eta_w*exp(rheo%alpha*p), rheo%beta, rheo%conductivity, u, h), &
                              rheo%limiting_shear, p)*abs(u)
         else if (present(dt_max)) then
            q = film_shear_stress(rheo%eta_w*exp(rheo%alpha*p), rheo%beta, rheo%conductivity, u, h)*abs(u)
         else if (rheo%beta > 0.0_wp) then
            ! the flux is even across the strip: half of it, mirrored.  film_shear_stress at
            ! eta_w exp(alpha p) as the strip traction's amp E shear_shape(zeta |u| E) with
            ! E = exp(alpha p / 2) (film_constants: no square roots or divisions a point;
            ! equal to round-off, test_tribology; issue #30)
            q(1:half_ny) = thermal_film_shear(amp, zeta, exp(0.5_wp*rheo%alpha*p(1:half_ny)), u)*abs(u)
            q(ny:half_ny + 1:-1) = q(1:ny - half_ny)
         else
            q(1:half_ny) = film_shear_stress(rheo%eta_w*exp(rheo%alpha*p(1:half_ny)), rheo%beta, rheo%conductivity, &
                                             u, h)*abs(u)
            q(ny:half_ny + 1:-1) = q(1:ny - half_ny)
         end if
         if (present(dt_max)) then
            call strip_temperature_rise(bk, eta, q, u1, u2, th1, th2, dt)
            strip = bk*(sum(dt) - 0.5_wp*(dt(1) + dt(ny)))*(eta(2) - eta(1))    ! trapezoid over y
            dt_max = max(dt_max, maxval(dt))
         else
            strip = bk*sqrt(bk)*dot_product(cw, q)/denom*(eta(2) - eta(1))
         end if
         dt_avg = dt_avg + w(j)*strip
      end do
      dt_avg = dt_avg/(pi*c%a*b)
   end subroutine ehd_temperature_rise

end module adore_tribology_ehd_flash
