!> The thermal model of a roller run (issues #26, #27; bearings/roller_thermal.f90,
!> docs/thermal.md "Roller runs") on Appendix D (Rec 2.5: heat averaged every 0.857 ms, the
!> geometry updated from the first update on) through the run's time loop: the update
!> schedule, the heat balance of every update, the averaged heat against the bearing's power
!> loss integrated independently from the time history, the geometry update (ADRC2) and the
!> load-holding constraint.
program test_roller_thermal
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_test_support, only: check, finish, get_decks_dir
   use adore_model_bearing, only: bearing_t, BODY_INNER
   use adore_model_from_deck, only: read_bearing
   use adore_model_run_options, only: run_options_t, set_run_option
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_thermal_distortion, only: distorted_bearing
   use adore_dynamics_integrator, only: integrator_t, DERIV_OK
   use adore_dynamics_roller_system, only: ROLLER_SIZE, RACE_OFFSET
   use adore_bearings_system, only: bearing_system_t
   use adore_bearings_select, only: new_bearing_system
   use adore_bearings_roller, only: roller_kind_t
   use adore_bearings_thermal_run, only: THERMAL_TEMPERATURES, THERMAL_GEOMETRY
   use adore_output_run_history, only: run_history_t
   use adore_driver_time_loop, only: run_time_loop
   implicit none

   real(wp), parameter :: interval = 8.57e-4_wp
   character(len=:), allocatable :: decks

   call get_decks_dir(decks)
   call test_heat_against_the_power_loss()
   call test_geometry_update_holds_the_load()
   call finish("roller thermal")

contains

   !> Run Appendix D with run option thermal=`mode` to `duration` s (every step a history
   !> row); sys and its history h are returned.
   subroutine run_d(mode, duration, sys, h, it, y, ok)
      character(len=*), intent(in) :: mode
      real(wp), intent(in) :: duration
      class(bearing_system_t), allocatable, intent(out) :: sys
      type(run_history_t), intent(out) :: h
      type(integrator_t), intent(out) :: it
      real(wp), allocatable, intent(out) :: y(:)
      logical, intent(out) :: ok
      type(run_options_t) :: opts
      type(bearing_t) :: b
      type(error_type), allocatable :: error
      character(len=:), allocatable :: incomplete
      integer :: unit
      ok = .false.
      call read_bearing(decks//"/appendix_d_roller.inp", b, error)
      call check(.not. allocated(error), "Appendix D reads")
      if (allocated(error)) return
      call check(b%coolant%thermal_time(1) == interval .and. b%coolant%thermal_time(2) == interval, &
                 "roller thermal: Rec 2.5's times read")
      opts%duration = duration
      call set_run_option(opts, "thermal", mode, error)
      call check(.not. allocated(error), "roller thermal: run option thermal="//mode)
      if (allocated(error)) return
      call new_bearing_system(b, opts, sys, error)
      if (.not. allocated(error)) call sys%solve_start(error)
      if (.not. allocated(error)) call sys%start_dynamics(it, y, error)
      call check(.not. allocated(error), "roller thermal: start ("//mode//")")
      if (allocated(error)) return
      call sys%new_history(h, 100, error)
      open (newunit=unit, status="scratch", action="readwrite")
      call run_time_loop(unit, sys, it, y, 100, h, incomplete, error, t_end=opts%duration/sys%time_scale)
      close (unit)
      call check(.not. allocated(error), "roller thermal: the run completes ("//mode//")")
      ok = .not. allocated(error)
   end subroutine run_d

   !> Temperatures only (geometry held), to 2.1 intervals: two updates at the deck's times; the
   !> heat balance of each field (generated = coolant + housing + shaft) within 1e-6; the
   !> second field's heat generated equals the bearing's total power loss averaged over its
   !> interval by the trapezoidal rule on the time history's rows (every accepted step),
   !> within 1e-9: no interaction's heat is lost or counted twice (drag and churning 0: the
   !> deck gives no lubricant fraction); the condition's temperatures are the field's and the
   !> history's bulk temperatures step at the updates.
   subroutine test_heat_against_the_power_loss()
      class(bearing_system_t), allocatable :: sys
      type(run_history_t) :: h
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), t(:), p(:)
      real(wp) :: integral
      logical :: ok
      integer :: k, i_t, i_p
      call run_d("temperatures", 2.1_wp*interval, sys, h, it, y, ok)
      if (.not. ok) return
      select type (sys)
      type is (roller_kind_t)
         associate (th => sys%thermal)
            call check(th%mode == THERMAL_TEMPERATURES, "roller thermal: temperatures mode")
            call check(th%updates == 2, "roller thermal: two updates by 2.1 intervals")
            do k = 1, min(th%updates, 2)
               call check(abs(th%update_times(k) - interval*k) <= 1.0e-12_wp*interval*k, &
                          "roller thermal: update at the deck's time")
            end do
            call check(th%balance <= 1.0e-6_wp, "roller thermal: heat generated = heat leaving at every update")
            call check(th%geometry_updates == 0 .and. sys%hold_solves == 0, "roller thermal: geometry held")
            call check(all(sys%condition%temperature == th%field%temperature), &
                       "roller thermal: the condition's temperatures are the last field's")
            i_t = index_of(h, "time_s")
            i_p = index_of(h, "total_power_loss_W")
            t = h%values(1:h%rows, i_t)
            p = h%values(1:h%rows, i_p)
            integral = 0.0_wp
            do k = 2, h%rows
               if (t(k - 1) >= interval*(1.0_wp - 1.0e-12_wp) .and. t(k) <= 2.0_wp*interval*(1.0_wp + 1.0e-12_wp)) &
                  integral = integral + 0.5_wp*(t(k) - t(k - 1))*(p(k) + p(k - 1))
            end do
            write (*, "(a,es14.6,a,es14.6,a,es10.2)") "  roller thermal: second interval's heat ", &
               th%field%q_generated, " W, power loss averaged from the history ", integral/interval, &
               " W, balance ", th%balance
            call check(abs(th%field%q_generated - integral/interval) <= 1.0e-9_wp*th%field%q_generated, &
                       "roller thermal: heat averaged = the power loss averaged over the interval")
            call check(th%field%q_generated > 0.5_wp, "roller thermal: the bearing generates heat")
         end associate
      class default
         call check(.false., "roller thermal: Appendix D is the roller kind")
      end select
   end subroutine test_heat_against_the_power_loss

   !> The deck's mode (geometry from the first update), to 2.1 intervals: two updates, each
   !> with the geometry mounted at the field's temperatures (ADRC2: the equations of motion's
   !> slice model on the distorted mounting's raceways, the print's fits and clearance from it)
   !> and the load-holding constraint (the inner race's net force after it at most 1e-6 of
   !> the applied load; checked again from outside by evaluating the equations of motion).
   subroutine test_geometry_update_holds_the_load()
      class(bearing_system_t), allocatable :: sys
      type(run_history_t) :: h
      type(integrator_t) :: it
      type(mounted_geometry_t) :: g
      real(wp), allocatable :: y(:), dydt(:)
      real(wp) :: net(3)
      type(error_type), allocatable :: error
      logical :: ok
      integer :: flag, r0
      call run_d("deck", 2.1_wp*interval, sys, h, it, y, ok)
      if (.not. ok) return
      select type (sys)
      type is (roller_kind_t)
         associate (th => sys%thermal, b => sys%bearing)
            call check(th%mode == THERMAL_GEOMETRY, "roller thermal: the deck's mode is temperatures and geometry")
            call check(th%updates == 2 .and. th%geometry_updates == 2, "roller thermal: geometry at both updates")
            call check(th%balance <= 1.0e-6_wp, "roller thermal: heat balance at every update (geometry mode)")
            call check(all(sys%condition%geometry_temperature == th%field%temperature), &
                       "roller thermal: the geometry at the last field's temperatures")
            g = mount_geometry(distorted_bearing(b, th%field%temperature), th%field%temperature, 2)
            call check(sys%eom%model%qs%r_o == g%raceway_radius(1) .and. sys%eom%model%qs%r_i == &
                       g%raceway_radius(2) .and. sys%eom%model%qs%d == g%element_diameter, &
                       "roller thermal: the slice model on the distorted mounting's raceways and roller")
            call check(g%raceway_radius(1) /= sys%step0%model%r_o .and. g%mounting%inner_fit /= &
                       sys%step0%mounting%inner_fit, "roller thermal: the geometry changed from step 0's")
            call check(sys%geometry%mounting%outer_fit == g%mounting%outer_fit, &
                       "roller thermal: the print's fits from the distorted mounting")
            call check(sys%hold_solves == 2, "roller thermal: the load-holding constraint at each update")
            call check(sys%hold_residual <= 1.0e-6_wp, "roller thermal: the constraint leaves <= 1e-6 of the load")
            write (*, "(a,es10.3,a,es10.3)") "  roller thermal: the geometry updates left ", sys%hold_initial, &
               " of the applied load on the inner race; the constraint ", sys%hold_residual
         end associate
         ! one more update at the run's end (its heat since the last), checked from outside:
         ! the equations of motion at the state it leaves give the inner race no net force in
         ! the radial plane (the axis: no flange, no axial load, nothing acts)
         call sys%on_event(2.1_wp*interval, it, y, error)
         call check(.not. allocated(error), "roller thermal: an update at the end of the run")
         call check(sys%thermal%updates == 3 .and. sys%hold_solves == 3, "roller thermal: re-mounted and held")
         allocate (dydt(size(y)))
         call sys%eval(2.1_wp*interval/sys%time_scale, y, dydt, flag)
         call check(flag == DERIV_OK, "roller thermal: the state after the update evaluates")
         r0 = ROLLER_SIZE*sys%bearing%n_elements + RACE_OFFSET
         net = sys%bearing%mass(BODY_INNER)*dydt(r0 + 4:r0 + 6)/sys%time_scale
         call check(norm2(net(2:3)) <= 1.0e-6_wp*norm2(sys%bearing%force), "roller thermal: the inner race in "// &
                    "equilibrium with the applied load after the update (eval, residual <= 1e-6)")
      class default
         call check(.false., "roller thermal: Appendix D is the roller kind")
      end select
   end subroutine test_geometry_update_holds_the_load

   integer function index_of(h, name) result(i)
      type(run_history_t), intent(in) :: h
      character(len=*), intent(in) :: name
      do i = 1, size(h%names)
         if (trim(h%names(i)) == name) return
      end do
      i = 0
   end function index_of

end program test_roller_thermal
