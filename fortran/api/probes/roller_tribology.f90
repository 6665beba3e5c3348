!> Flat f2py wrapper of the roller step-0 tribology (test-only module pyadore._probes).

!> Step 0 of a roller-bearing deck with its slice tractions (adore_start_roller_step0,
!> adore_tribology_roller_traction).  growth_count as adore_roller_step0_deck; spin_method
!> 1 = pure rolling of the land (the report), 2 = traction moment balance per roller.
!>
!> rollers(nmax, 19): [spin (rad/s), moment residual (N m), tangential force on the roller
!>   (N), then outer, inner: max slip (m/s), kappa(max slip), power (W), force on the race
!>   (N), |force|/load, moment on the roller (N m) -- indices 4..8 outer, 9..13 inner,
!>   14 orbital speed (rad/s), 15, 16 sliding outer, inner (integral of |u| dQ, N m/s),
!>   17 wear rate of the roller (m**3/s), 18, 19 average flash temperature rise outer,
!>   inner (K, eqs 35-36)];
!> slices(nmax, 12, 8): per roller [x, weight, slip, traction] outer then inner
!>   (m, m, m/s, N/m; traction on the race along the orbit direction);
!> summary(3): [contact power (W), total power loss (W, NaN while a cage contact touches),
!>   rolling spin W0 (rad/s)].
subroutine adore_roller_step0_tribology(deck_path, growth_count, spin_method, nmax, n, rollers, slices, &
                                        summary, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK
   use adore_model_bearing, only: bearing_t
   use adore_start_roller_step0, only: roller_step0_t
   use adore_api_unpack, only: roller_start_from_deck
   implicit none
   character(len=*), intent(in) :: deck_path
   integer, intent(in) :: growth_count, spin_method, nmax
   integer, intent(out) :: n
   real(wp), intent(out) :: rollers(nmax, 19), slices(nmax, 12, 8), summary(3)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(bearing_t) :: b
   type(roller_step0_t) :: s
   type(error_type), allocatable :: error
   integer :: k, ns

   n = 0
   rollers = 0.0_wp
   slices = 0.0_wp
   summary = 0.0_wp
   status = ADORE_OK
   message = ""
   call roller_start_from_deck(deck_path, nmax, growth_count, b, s, error, spin_method)
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   n = b%n_elements
   do k = 1, n
      associate (o => s%tr_o(k), i => s%tr_i(k), e => s%equilibrium)
         rollers(k, :) = [s%roller_spin(k), s%moment_residual(k), s%tangential_force(k), &
                          o%max_slip, o%max_slip_kappa, o%power, o%force, o%moment, &
                          i%max_slip, i%max_slip_kappa, i%power, i%force, i%moment, e%orbital_speed(k), &
                          o%sliding, i%sliding, s%wear(k), s%temp_rise(:, k)]
         ns = min(12, size(e%c_o(k)%x))
         slices(k, 1:ns, 1) = e%c_o(k)%x(1:ns)
         slices(k, 1:ns, 2) = e%c_o(k)%weight(1:ns)
         slices(k, 1:ns, 3) = o%slip(1:ns)
         slices(k, 1:ns, 4) = o%traction(1:ns)
         ns = min(12, size(e%c_i(k)%x))
         slices(k, 1:ns, 5) = e%c_i(k)%x(1:ns)
         slices(k, 1:ns, 6) = e%c_i(k)%weight(1:ns)
         slices(k, 1:ns, 7) = i%slip(1:ns)
         slices(k, 1:ns, 8) = i%traction(1:ns)
      end associate
   end do
   summary = [s%contact_power, s%power_loss, s%spin_speed]
end subroutine adore_roller_step0_tribology
