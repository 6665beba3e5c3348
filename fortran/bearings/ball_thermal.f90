!> The thermal model wired into a ball bearing run (issue #27; report 2.10, 5.3, 5.5): the
!> heat of every interaction averaged over the interval of Rec 2.5 field 4, the steady
!> temperature field (adore_thermal_network, ADRH1/ADRH3) solved at the end of each
!> interval, and the drag and churning of the balls (adore_thermal_drag).
!>
!> The run's event hook (adore_bearings_system's on_event, every `interval` seconds) calls
!> ball_thermal_update; the ball kind (adore_bearings_ball) then sets the new bulk
!> temperatures as its operating condition and, in THERMAL_GEOMETRY mode from the geometry
!> start time (Rec 2.5 field 5) on, mounts the geometry at them (ADRC2) with the load-holding
!> constraint.  The deck fields and the modes: docs/thermal.md, "The wiring".
!>
!> Heat rates (W) at an accepted state: each ball's outer and inner race contact loss
!> (the force assembly's loads%heat), its pocket's power, all guide lands' power, the
!> ball's drag and churning loss; integrated over time by the trapezoidal rule between
!> accepted instants (the first interval of a run starts with a rectangle from t = 0).
!> Where the heat is averaged (docs/thermal.md, "Heat by location"): by default per
!> space-fixed location around the orbit, location j at azimuth 2 pi (j - 1) / n (the balls'
!> places at t = 0): at every accepted instant each ball's heat rates go to the two
!> locations either side of its azimuth with linear weights (summing to 1, so no heat is
!> lost); the field is solved per location, and at the update each ball takes the field of
!> the place it occupies then (the same weights).  Report 2.3: conduction through the race
!> "is carried out at each rolling element location, where the race surface temperature may
!> be different due to variation in contact load"; 2.10: "the local heat generations are
!> first averaged".  `by_location = .false.` averages each ball's own heat instead.
!> No module state: the record is part of the ball kind.
module adore_bearings_ball_thermal
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_model_bearing, only: bearing_t
   use adore_state_bearing_state, only: bearing_state_t, body_azimuth
   use adore_forces_ball_bearing, only: ball_bearing_loads_t
   use adore_thermal_network, only: thermal_heat_t, thermal_options_t, thermal_field_t, default_thermal_options, &
                                    new_thermal_heat
   use adore_thermal_march, only: solve_thermal_field
   use adore_thermal_convection, only: fluid_properties_t, lubricant_properties
   use adore_thermal_drag, only: element_fluid_loss_t, element_fluid_loss
   use adore_thermal_transient, only: thermal_transient_t, new_thermal_transient, thermal_transient_step
   implicit none
   private

   public :: ball_thermal_t, new_ball_thermal, thermal_mode_of, ball_heat_rates, ball_thermal_accumulate
   public :: ball_thermal_update, heat_total, location_weights, heat_by_location

   !> The thermal modes of a run: off (bulk temperatures fixed at Rec 2.7's), temperatures
   !> updated with the geometry held (report 5.3's first set), temperatures and geometry
   !> updated (its second set, Appendices C and D).
   integer, parameter, public :: THERMAL_OFF = 0, THERMAL_TEMPERATURES = 1, THERMAL_GEOMETRY = 2

   !> A run's thermal model.
   type :: ball_thermal_t
      integer :: mode = THERMAL_OFF
      real(wp) :: interval = 0.0_wp          !< averaging interval (s), Rec 2.5 field 4
      real(wp) :: geometry_start = 0.0_wp    !< geometry updated from this time on (s), Rec 2.5 field 5
      !> lubricant volume fraction of the free space for drag and churning (Harris); the deck
      !> gives none (docs/thermal.md): 0
      real(wp) :: lubricant_fraction = 0.0_wp
      !> heat averaged per space-fixed location (default) or per ball (module header)
      logical :: by_location = .true.
      type(thermal_options_t) :: options     !< the network's boundaries (default_thermal_options)
      type(thermal_heat_t) :: integral       !< heat over the current interval (J)
      type(thermal_heat_t) :: last           !< heat rates at the last accepted instant (W)
      real(wp) :: t_last = 0.0_wp            !< time of the last accepted instant (s)
      real(wp) :: elapsed = 0.0_wp           !< length of the current interval so far (s)
      logical :: have_last = .false.
      type(thermal_field_t) :: field         !< the last solved field
      logical :: have_field = .false.
      !> each ball's drag, churning moment and loss at the last accepted state
      type(element_fluid_loss_t), allocatable :: fluid(:)
      integer :: updates = 0                 !< fields solved
      real(wp), allocatable :: update_times(:)   !< the time of each update (s)
      integer :: geometry_updates = 0        !< geometry re-mounted
      !> worst relative heat balance |generated - (coolant + reference + bore)| / generated
      real(wp) :: balance = 0.0_wp
      !> thermal transients with lumped heat capacities (run option thermal_transient; not
      !> ADORE 5.0): each update relaxes the bodies toward the steady field (adore_thermal_transient)
      logical :: transient_on = .false.
      type(thermal_transient_t) :: transient
   end type ball_thermal_t

contains

   !> The mode of run option `option` ("off" or blank, "deck", "temperatures", "geometry")
   !> for bearing b: "deck" is THERMAL_GEOMETRY when Rec 2.5 field 4 (the averaging
   !> interval) is positive (both appendices echo VARY GEOMETRY WITH TEMPERATURE: Yes),
   !> otherwise off.
   !> Input error for a thermal mode without an averaging interval.
   subroutine thermal_mode_of(option, b, mode, error)
      character(len=*), intent(in) :: option
      type(bearing_t), intent(in) :: b
      integer, intent(out) :: mode
      type(error_type), allocatable, intent(out) :: error
      select case (trim(option))
      case ("temperatures")
         mode = THERMAL_TEMPERATURES
      case ("geometry")
         mode = THERMAL_GEOMETRY
      case ("deck")
         mode = THERMAL_OFF
         if (b%coolant%thermal_time(1) > 0.0_wp) mode = THERMAL_GEOMETRY
      case default
         mode = THERMAL_OFF
      end select
      if (mode /= THERMAL_OFF .and. .not. (b%coolant%thermal_time(1) > 0.0_wp)) then
         call input_error(error, "thermal model '"//trim(option)//"': Rec 2.5 field 4 (the heat averaging "// &
                          "interval, s) must be positive")
         mode = THERMAL_OFF
      end if
   end subroutine thermal_mode_of

   !> The thermal model of bearing b in mode `mode`: interval and geometry start from Rec
   !> 2.5 fields 4 and 5, the network's default boundaries, nothing accumulated.
   function new_ball_thermal(b, mode) result(th)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: mode
      type(ball_thermal_t) :: th
      th%mode = mode
      th%interval = b%coolant%thermal_time(1)
      th%geometry_start = b%coolant%thermal_time(2)
      th%options = default_thermal_options(b)
      th%integral = new_thermal_heat(b%n_elements)
      th%last = new_thermal_heat(b%n_elements)
      allocate (th%fluid(b%n_elements), th%update_times(0))
      th%transient = new_thermal_transient(b)
   end function new_ball_thermal

   !> The heat rates (W) of ball bearing b at state s with the force assembly's loads
   !> there (module header); each ball's drag and churning (th%fluid) as a side result:
   !> centre speed = orbital speed x pitch radius, spin = |omega|, the lubricant at the
   !> coolant's temperature (the last exit temperature, the inlet's before the first field).
   subroutine ball_heat_rates(th, b, s, loads, heat)
      type(ball_thermal_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      type(thermal_heat_t), intent(out) :: heat
      type(fluid_properties_t) :: props
      real(wp) :: t_fluid, v, r2
      integer :: k, n
      n = b%n_elements
      heat = new_thermal_heat(n)
      heat%outer = loads%heat(1, :)
      heat%inner = loads%heat(2, :)
      if (allocated(loads%pockets)) then
         if (size(loads%pockets) == n) heat%pocket = loads%pockets%power
      end if
      if (allocated(loads%lands)) heat%land = sum(loads%lands%power)
      t_fluid = b%coolant%inlet_temperature
      if (th%have_field) t_fluid = th%field%exit_temperature
      do k = 1, n
         th%fluid(k) = element_fluid_loss_t()
         if (.not. (th%lubricant_fraction > 0.0_wp .and. b%lubricant%density > 0.0_wp)) cycle
         props = lubricant_properties(b%lubricant, t_fluid)
         associate (e => s%elements(k))
            r2 = e%position(2)**2 + e%position(3)**2
            v = 0.0_wp
            if (r2 > 0.0_wp) v = (e%position(2)*e%velocity(3) - e%position(3)*e%velocity(2))/sqrt(r2)
            th%fluid(k) = element_fluid_loss(b%d, 0.0_wp, v, norm2(e%omega), props, th%lubricant_fraction)
         end associate
         heat%drag(k) = th%fluid(k)%loss
      end do
      if (th%by_location) heat = heat_by_location(heat, [(body_azimuth(s%elements(k)), k = 1, n)])
   end subroutine ball_heat_rates

   !> The two space-fixed locations either side of azimuth phi (rad) among n, location j at
   !> 2 pi (j - 1) / n, and the linear weights w (sum 1; all on j(1) at its own azimuth).
   pure subroutine location_weights(phi, n, j, w)
      real(wp), intent(in) :: phi
      integer, intent(in) :: n
      integer, intent(out) :: j(2)
      real(wp), intent(out) :: w(2)
      real(wp) :: x
      x = modulo(phi, 2.0_wp*pi)*n/(2.0_wp*pi)
      j(1) = min(int(x), n - 1)
      w(2) = min(max(x - j(1), 0.0_wp), 1.0_wp)
      w(1) = 1.0_wp - w(2)
      j(1) = j(1) + 1
      j(2) = modulo(j(1), n) + 1
   end subroutine location_weights

   !> Heat rates per ball (W; ball k at azimuth phi(k), rad) as heat rates per space-fixed
   !> location (location_weights); the total is kept, the lands' heat is not per ball.
   pure function heat_by_location(heat, phi) result(loc)
      type(thermal_heat_t), intent(in) :: heat
      real(wp), intent(in) :: phi(:)
      type(thermal_heat_t) :: loc
      integer :: k, i, n, j(2)
      real(wp) :: w(2)
      n = size(phi)
      loc = new_thermal_heat(n)
      loc%land = heat%land
      do k = 1, n
         call location_weights(phi(k), n, j, w)
         do i = 1, 2
            loc%outer(j(i)) = loc%outer(j(i)) + w(i)*heat%outer(k)
            loc%inner(j(i)) = loc%inner(j(i)) + w(i)*heat%inner(k)
            loc%pocket(j(i)) = loc%pocket(j(i)) + w(i)*heat%pocket(k)
            loc%drag(j(i)) = loc%drag(j(i)) + w(i)*heat%drag(k)
         end do
      end do
   end function heat_by_location

   !> Per-location values v(n) (the field solved per location) read at each ball's azimuth
   !> phi(k) (rad): the location weights' interpolation.
   pure function at_balls(v, phi) result(vb)
      real(wp), intent(in) :: v(:), phi(:)
      real(wp) :: vb(size(phi))
      integer :: k, j(2)
      real(wp) :: w(2)
      do k = 1, size(phi)
         call location_weights(phi(k), size(v), j, w)
         vb(k) = w(1)*v(j(1)) + w(2)*v(j(2))
      end do
   end function at_balls

   !> Add the heat rates `heat` (W) of the accepted instant `time` (s) to the interval's
   !> integral (trapezoidal rule with the previous instant; a rectangle for the first).
   subroutine ball_thermal_accumulate(th, time, heat)
      type(ball_thermal_t), intent(inout) :: th
      real(wp), intent(in) :: time
      type(thermal_heat_t), intent(in) :: heat
      real(wp) :: dt
      dt = time - th%t_last
      if (.not. th%have_last) th%last = heat
      th%integral%outer = th%integral%outer + 0.5_wp*dt*(th%last%outer + heat%outer)
      th%integral%inner = th%integral%inner + 0.5_wp*dt*(th%last%inner + heat%inner)
      th%integral%pocket = th%integral%pocket + 0.5_wp*dt*(th%last%pocket + heat%pocket)
      th%integral%drag = th%integral%drag + 0.5_wp*dt*(th%last%drag + heat%drag)
      th%integral%land = th%integral%land + 0.5_wp*dt*(th%last%land + heat%land)
      th%elapsed = th%elapsed + dt
      th%t_last = time
      th%last = heat
      th%have_last = .true.
   end subroutine ball_thermal_accumulate

   !> Total heat (W or J) of a heat record.
   pure real(wp) function heat_total(h)
      type(thermal_heat_t), intent(in) :: h
      heat_total = sum(h%outer) + sum(h%inner) + sum(h%pocket) + sum(h%drag) + h%land
   end function heat_total

   !> The end of an interval (report 2.10 steps 2-9): the heat averaged over it, the
   !> field (th%options%field_model: the report's march or the network) solved for it (eq 18's velocity of ball k = its spin surface speed
   !> |omega| D / 2 at state s, docs/thermal.md), the heat balance checked (th%balance, the
   !> worst so far), the integral restarted; time (s) recorded in th%update_times.  Engine
   !> error for an empty interval.
   subroutine ball_thermal_update(th, b, s, time, error)
      type(ball_thermal_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      real(wp), intent(in) :: time
      type(error_type), allocatable, intent(out) :: error
      type(thermal_heat_t) :: mean
      real(wp) :: leaving, w(2), wsum(b%n_elements), vsum(b%n_elements), phi(b%n_elements), v
      integer :: k, j(2), n, i
      if (.not. (th%elapsed > 0.0_wp)) then
         call engine_error(error, "thermal update: no heat averaged (empty interval)")
         return
      end if
      mean%outer = th%integral%outer/th%elapsed
      mean%inner = th%integral%inner/th%elapsed
      mean%pocket = th%integral%pocket/th%elapsed
      mean%drag = th%integral%drag/th%elapsed
      mean%land = th%integral%land/th%elapsed
      n = b%n_elements
      phi = [(body_azimuth(s%elements(k)), k = 1, n)]
      do k = 1, n
         th%options%element_velocity(k) = 0.5_wp*b%d*norm2(s%elements(k)%omega)
      end do
      if (th%by_location) then
         ! each location's velocity: the balls' there now (weighted), else their mean
         wsum = 0.0_wp
         vsum = 0.0_wp
         do k = 1, n
            call location_weights(phi(k), n, j, w)
            do i = 1, 2   ! (one at a time: j(1) = j(2) when n = 1)
               wsum(j(i)) = wsum(j(i)) + w(i)
               vsum(j(i)) = vsum(j(i)) + w(i)*th%options%element_velocity(k)
            end do
         end do
         v = sum(th%options%element_velocity)/n
         th%options%element_velocity = v
         where (wsum > 0.0_wp) th%options%element_velocity = vsum/wsum
      end if
      call solve_thermal_field(b, mean, th%options, th%field, error)
      if (allocated(error)) return
      if (th%by_location) then
         ! each ball takes the field of the place it occupies at the update
         th%field%contact_outer = at_balls(th%field%contact_outer, phi)
         th%field%contact_inner = at_balls(th%field%contact_inner, phi)
         th%field%mid = at_balls(th%field%mid, phi)
         th%field%element_bulk = at_balls(th%field%element_bulk, phi)
         th%field%htc = at_balls(th%field%htc, phi)
      end if
      ! with transients each ball's (and body's) temperature relaxes toward its place's field
      if (th%transient_on) call thermal_transient_step(th%transient, b, th%options, th%elapsed, th%field, error)
      if (allocated(error)) return
      th%have_field = .true.
      th%updates = th%updates + 1
      th%update_times = [th%update_times, time]
      leaving = th%field%q_coolant + th%field%q_reference + th%field%q_bore
      th%balance = max(th%balance, abs(th%field%q_generated - leaving)/max(abs(th%field%q_generated), tiny(1.0_wp)))
      th%integral = new_thermal_heat(b%n_elements)
      th%elapsed = 0.0_wp
   end subroutine ball_thermal_update

end module adore_bearings_ball_thermal
