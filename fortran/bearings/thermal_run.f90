!> The thermal model of a run, common to the bearing kinds (issue #27; report 2.10, 5.3, 5.5;
!> docs/thermal.md, "The wiring"): the modes, the heat of the interactions integrated over the
!> averaging interval of Rec 2.5 field 4 (by space-fixed location around the orbit or per
!> rolling element), the steady field (adore_thermal_march, ADRH1/ADRH3) solved at the end of
!> each interval with its heat balance checked, and the load-holding constraint of a geometry
!> update.  Each kind (bearings/ball_thermal.f90, bearings/roller_thermal.f90) supplies its
!> heat rates and its elements' azimuths and eq-18 velocities; its on_event hook calls
!> thermal_update and sets the new condition.
!>
!> Heat averaged by location (the default; docs/thermal.md, "Heat by location"): location j
!> sits at azimuth 2 pi (j - 1) / n (the elements' places at t = 0); at every accepted
!> instant each element's heat rates go to the two locations either side of its azimuth with
!> linear weights (summing to 1, so no heat is lost); the field is solved per location, and
!> at the update each element takes the field of the place it occupies then (the same
!> weights).  Report 2.3: conduction through the race "is carried out at each rolling element
!> location"; 2.10: "the local heat generations are first averaged".  `by_location =
!> .false.` averages each element's own heat instead.  No module state.
module adore_bearings_thermal_run
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_strings, only: upper
   use adore_core_linalg, only: solve_dense
   use adore_model_bearing, only: bearing_t
   use adore_model_run_options, only: run_options_t
   use adore_model_condition, only: operating_condition_t
   use adore_thermal_network, only: thermal_heat_t, thermal_options_t, thermal_field_t, default_thermal_options, &
                                    new_thermal_heat, FIELD_NETWORK
   use adore_thermal_march, only: solve_thermal_field
   use adore_thermal_drag, only: element_fluid_loss_t
   use adore_thermal_transient, only: thermal_transient_t, new_thermal_transient, thermal_transient_step
   implicit none
   private

   public :: thermal_run_t, new_thermal_run, thermal_run_for, thermal_condition, thermal_mode_of, thermal_accumulate
   public :: thermal_update, heat_total
   public :: location_weights, heat_by_location, at_locations, hold_race_load, net_force_i, thermal_run_text

   !> The thermal modes of a run: off (bulk temperatures fixed at Rec 2.7's), temperatures
   !> updated with the geometry held (report 5.3's first set), temperatures and geometry
   !> updated (its second set, Appendices C and D).
   integer, parameter, public :: THERMAL_OFF = 0, THERMAL_TEMPERATURES = 1, THERMAL_GEOMETRY = 2

   !> A run's thermal model (a kind extends it with what is its own).
   type :: thermal_run_t
      integer :: mode = THERMAL_OFF
      real(wp) :: interval = 0.0_wp          !< averaging interval (s), Rec 2.5 field 4
      real(wp) :: geometry_start = 0.0_wp    !< geometry updated from this time on (s), Rec 2.5 field 5
      !> lubricant volume fraction of the free space for drag and churning (Harris); the deck
      !> gives none (docs/thermal.md): 0
      real(wp) :: lubricant_fraction = 0.0_wp
      !> heat averaged per space-fixed location (default) or per element (module header)
      logical :: by_location = .true.
      type(thermal_options_t) :: options     !< the field's boundaries (default_thermal_options)
      type(thermal_heat_t) :: integral       !< heat over the current interval (J)
      type(thermal_heat_t) :: last           !< heat rates at the last accepted instant (W)
      real(wp) :: t_last = 0.0_wp            !< time of the last accepted instant (s)
      real(wp) :: elapsed = 0.0_wp           !< length of the current interval so far (s)
      logical :: have_last = .false.
      type(thermal_field_t) :: field         !< the last solved field
      logical :: have_field = .false.
      !> each element's drag, churning moment and loss at the last accepted state
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
   end type thermal_run_t

   abstract interface
      !> The net force (N) on a race at packed state y (its free translations changed by
      !> hold_race_load); ok false when the equations of motion fail there.
      subroutine net_force_i(y, force, ok)
         import :: wp
         real(wp), intent(in) :: y(:)
         real(wp), intent(out) :: force(3)
         logical, intent(out) :: ok
      end subroutine net_force_i
   end interface

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
   !> 2.5 fields 4 and 5, the field's default boundaries, nothing accumulated.
   function new_thermal_run(b, mode) result(th)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: mode
      type(thermal_run_t) :: th
      th%mode = mode
      th%interval = b%coolant%thermal_time(1)
      th%geometry_start = b%coolant%thermal_time(2)
      th%options = default_thermal_options(b)
      th%integral = new_thermal_heat(b%n_elements)
      th%last = new_thermal_heat(b%n_elements)
      allocate (th%fluid(b%n_elements), th%update_times(0))
      th%transient = new_thermal_transient(b)
   end function new_thermal_run

   !> The thermal model of a run of bearing b with run options opts (docs/thermal.md, "The
   !> wiring"): the mode of option thermal (thermal_mode_of), the field model of option
   !> thermal_field (the march, ADORE 5.0's, with its shaft bulk temperature as ADORE prints
   !> it; or the network), the housing film of option housing_htc and the transients of
   !> option thermal_transient.  Input error as
   !> thermal_mode_of.
   function thermal_run_for(b, opts, error) result(th)
      type(bearing_t), intent(in) :: b
      type(run_options_t), intent(in) :: opts
      type(error_type), allocatable, intent(out) :: error
      type(thermal_run_t) :: th
      integer :: mode
      call thermal_mode_of(opts%thermal, b, mode, error)
      if (allocated(error)) return
      th = new_thermal_run(b, mode)
      th%options%shaft_bulk_as_printed = .true.
      if (opts%thermal_field == "network") then
         th%options%field_model = FIELD_NETWORK
         th%options%shaft_bulk_as_printed = .false.
      end if
      th%options%reference_htc = opts%housing_htc
      th%transient_on = opts%thermal_transient
   end function thermal_run_for

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

   !> Heat rates per element (W; element k at azimuth phi(k), rad) as heat rates per
   !> space-fixed location (location_weights); the total is kept, the lands' heat is not per
   !> element.
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

   !> Per-location values v(n) (the field solved per location) read at each element's
   !> azimuth phi(k) (rad): the location weights' interpolation.
   pure function at_locations(v, phi) result(vb)
      real(wp), intent(in) :: v(:), phi(:)
      real(wp) :: vb(size(phi))
      integer :: k, j(2)
      real(wp) :: w(2)
      do k = 1, size(phi)
         call location_weights(phi(k), size(v), j, w)
         vb(k) = w(1)*v(j(1)) + w(2)*v(j(2))
      end do
   end function at_locations

   !> Add the heat rates `heat` (W) of the accepted instant `time` (s) to the interval's
   !> integral (trapezoidal rule with the previous instant; a rectangle for the first).
   subroutine thermal_accumulate(th, time, heat)
      class(thermal_run_t), intent(inout) :: th
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
   end subroutine thermal_accumulate

   !> Total heat (W or J) of a heat record.
   pure real(wp) function heat_total(h)
      type(thermal_heat_t), intent(in) :: h
      heat_total = sum(h%outer) + sum(h%inner) + sum(h%pocket) + sum(h%drag) + h%land
   end function heat_total

   !> The end of an interval (report 2.10 steps 2-9) for bearing b whose elements sit at
   !> azimuths phi (rad) with eq 18's velocities velocity (m/s; docs/thermal.md): the heat
   !> averaged over the interval, the field (th%options%field_model: the report's march or the
   !> network) solved for it - by location, each location's velocity the weighted mean of the
   !> elements there (else the mean of all) and each element given its place's field - the
   !> heat balance checked (th%balance, the worst so far), with transients (th%transient_on)
   !> the bodies relaxed toward the field over the interval, the integral restarted; time (s)
   !> recorded in th%update_times.  Engine error for an empty interval.
   subroutine thermal_update(th, b, phi, velocity, time, error)
      class(thermal_run_t), intent(inout) :: th
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: phi(:), velocity(:)
      real(wp), intent(in) :: time
      type(error_type), allocatable, intent(out) :: error
      type(thermal_heat_t) :: mean
      real(wp) :: leaving, w(2), wsum(size(phi)), vsum(size(phi)), v
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
      n = size(phi)
      th%options%element_velocity = velocity
      if (th%by_location) then
         ! each location's velocity: the elements' there now (weighted), else their mean
         wsum = 0.0_wp
         vsum = 0.0_wp
         do k = 1, n
            call location_weights(phi(k), n, j, w)
            do i = 1, 2   ! (one at a time: j(1) = j(2) when n = 1)
               wsum(j(i)) = wsum(j(i)) + w(i)
               vsum(j(i)) = vsum(j(i)) + w(i)*velocity(k)
            end do
         end do
         v = sum(velocity)/n
         th%options%element_velocity = v
         where (wsum > 0.0_wp) th%options%element_velocity = vsum/wsum
      end if
      call solve_thermal_field(b, mean, th%options, th%field, error)
      if (allocated(error)) return
      if (th%by_location) then
         ! each element takes the field of the place it occupies at the update
         th%field%contact_outer = at_locations(th%field%contact_outer, phi)
         th%field%contact_inner = at_locations(th%field%contact_inner, phi)
         th%field%mid = at_locations(th%field%mid, phi)
         th%field%element_bulk = at_locations(th%field%element_bulk, phi)
         th%field%htc = at_locations(th%field%htc, phi)
      end if
      ! with transients each element's (and body's) temperature relaxes toward its place's field
      if (th%transient_on) call thermal_transient_step(th%transient, b, th%options, th%elapsed, th%field, error)
      if (allocated(error)) return
      th%have_field = .true.
      th%updates = th%updates + 1
      th%update_times = [th%update_times, time]
      leaving = th%field%q_coolant + th%field%q_reference + th%field%q_bore
      th%balance = max(th%balance, abs(th%field%q_generated - leaving)/max(abs(th%field%q_generated), tiny(1.0_wp)))
      th%integral = new_thermal_heat(b%n_elements)
      th%elapsed = 0.0_wp
   end subroutine thermal_update

   !> The operating condition after an update at time `time` (s) of the run whose condition
   !> was c0: the bulk temperatures the last field's and, in THERMAL_GEOMETRY mode from the
   !> geometry start time on (a relative allowance of 1e-9 for the event times' round-off),
   !> the geometry's too (geometry: whether it is).
   function thermal_condition(th, c0, time, geometry) result(c)
      class(thermal_run_t), intent(in) :: th
      type(operating_condition_t), intent(in) :: c0
      real(wp), intent(in) :: time
      logical, intent(out) :: geometry
      type(operating_condition_t) :: c
      c = c0
      c%temperature = th%field%temperature
      geometry = th%mode == THERMAL_GEOMETRY .and. time >= th%geometry_start*(1.0_wp - 1.0e-9_wp)
      if (geometry) c%geometry_temperature = th%field%temperature
   end function thermal_condition

   !> The thermal model of a run in one line: the print listing's (listing: indented, upper
   !> case) or the run note's (a subroutine: a deferred-length function result would be
   !> static storage, fortran/core/strings.f90).
   subroutine thermal_run_text(th, listing, text)
      class(thermal_run_t), intent(in) :: th
      logical, intent(in) :: listing
      character(len=:), allocatable, intent(out) :: text
      character(len=12) :: dt, t0
      if (th%mode == THERMAL_OFF) then
         text = "thermal model off: bulk temperatures fixed at the initial ones (Rec 2.7)"
      else
         write (dt, "(es10.3)") th%interval
         write (t0, "(es10.3)") th%geometry_start
         text = "thermal model on: heat averaged over "//trim(adjustl(dt))//" s, temperatures updated (Rec 2.5)"
         if (th%mode == THERMAL_GEOMETRY) then
            text = text//", geometry updated from "//trim(adjustl(t0))//" s with the applied load held"
         else
            text = text//", geometry held"
         end if
         if (th%transient_on) text = text//"; transients with lumped heat capacities"
      end if
      if (listing) then
         text = "  "//upper(text)
      end if
   end subroutine thermal_run_text

   !> The load-holding constraint of a geometry update (report 2.10 step 11, 5.3 "an
   !> equilibrium constraint is applied to move the races and maintain the thrust and radial
   !> loads", 5.5 "a quasi-static constraint"): the race's free translations (free(3): x, y,
   !> z at y(i0 + 1:i0 + 3), m) moved, the rest of the packed state y held (the elements and
   !> every velocity), until the race's net force (net_force at y: its contacts and the
   !> applied load, N) is below 1e-6 of scale (N, the applied load).  Newton with a
   !> forward-difference Jacobian (step 1e-9 m) and step halving until the net force
   !> decreases (a barely touching contact is nearly without stiffness: a full step would
   !> overshoot; a state outside the contact models counts as no decrease); a race clear of
   !> every element (no stiffness) moves along the net force - then the applied load - by
   !> 1 um, doubled at each such step.  initial: the largest |net force| / scale a geometry
   !> update left before the solve (kept), residual: the worst final one (kept), solves:
   !> counted.  Engine error when
   !> the evaluation at the start fails or the iteration does not converge in 100 steps.
   subroutine hold_race_load(net_force, y, i0, free, scale, initial, residual, solves, error)
      procedure(net_force_i) :: net_force
      real(wp), intent(inout) :: y(:)
      integer, intent(in) :: i0
      logical, intent(in) :: free(3)
      real(wp), intent(in) :: scale
      real(wp), intent(inout) :: initial, residual
      integer, intent(inout) :: solves
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: h = 1.0e-9_wp
      real(wp) :: f(3), f1(3), jac(3, 3), dx(3), y0, clear, lambda, x0(3)
      logical :: ok, stiff
      integer :: iter, j, m, k, idx(3)
      m = count(free)
      if (m == 0) return
      idx(1:m) = pack([1, 2, 3], free)
      clear = 1.0e-6_wp
      call net_force(y, f, ok)
      if (.not. ok) then
         call engine_error(error, "load-holding constraint: the equations of motion failed")
         return
      end if
      initial = max(initial, norm2(f(idx(1:m)))/scale)
      do iter = 1, 100
         if (norm2(f(idx(1:m))) <= 1.0e-6_wp*scale) exit
         if (iter == 100) then
            call engine_error(error, "load-holding constraint: no equilibrium of the race after 100 Newton "// &
                              "steps (net force "//show(norm2(f))//" N)")
            return
         end if
         stiff = .true.
         do j = 1, m
            y0 = y(i0 + idx(j))
            y(i0 + idx(j)) = y0 + h
            call net_force(y, f1, ok)
            y(i0 + idx(j)) = y0
            stiff = stiff .and. ok
            if (ok) jac(1:m, j) = (f1(idx(1:m)) - f(idx(1:m)))/h
         end do
         if (stiff) call solve_dense(m, jac(1:m, 1:m), -f(idx(1:m)), dx(1:m), stiff)
         x0(1:m) = y(i0 + idx(1:m))
         if (.not. stiff) then          ! clear of every element: along the net force
            y(i0 + idx(1:m)) = x0(1:m) + clear*f(idx(1:m))/norm2(f(idx(1:m)))
            clear = 2.0_wp*clear
            call net_force(y, f1, ok)
            if (ok) f = f1
            if (.not. ok) y(i0 + idx(1:m)) = x0(1:m)
            cycle
         end if
         clear = 1.0e-6_wp
         lambda = 1.0_wp
         do k = 1, 40                   ! halve the step until the net force decreases
            y(i0 + idx(1:m)) = x0(1:m) + lambda*dx(1:m)
            call net_force(y, f1, ok)
            if (ok) then
               if (norm2(f1(idx(1:m))) < norm2(f(idx(1:m)))) exit
            end if
            lambda = 0.5_wp*lambda
         end do
         if (.not. ok) then
            y(i0 + idx(1:m)) = x0(1:m)
            call engine_error(error, "load-holding constraint: no state of the race along the Newton step "// &
                              "is within the contact models (net force "//show(norm2(f))//" N)")
            return
         end if
         f = f1
      end do
      solves = solves + 1
      residual = max(residual, norm2(f(idx(1:m)))/scale)
   contains

      function show(x) result(text)
         real(wp), intent(in) :: x
         character(len=16) :: text
         write (text, "(es10.3)") x
      end function show

   end subroutine hold_race_load

end module adore_bearings_thermal_run
