!> The printed tables of one step (sections 1-4) assembled from the bearing model and the
!> solution at that step (no formatting here, no physics): write_ball_step0 and
!> write_roller_step0 from the quasi-static start, with the step number and the step header
!> values (tau, time, race rotations) passed by the caller.
!>
!> A value pyadore does not compute yet (cage contact forces and their wear, the roller's modified
!> life, deck fields whose meaning is not identified) is left as
!> IEEE NaN / INT_NOT_COMPUTED and prints "NaN": the print never shows a made-up number.
module adore_output_step_report
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi, rad_to_deg, rad_s_to_rpm
   use adore_model_bearing, only: bearing_t, &
                                   TEMP_CAGE, TEMP_ELEMENT, TEMP_HOUSING, TEMP_INNER, TEMP_OUTER, TEMP_SHAFT
   use adore_output_layout, only: INT_NOT_COMPUTED, N_PERFORMANCE
   use adore_output_print_tables, only: write_step
   use adore_start_ball_step0, only: ball_step0_t
   use adore_start_roller_step0, only: roller_step0_t
   use adore_thermal_network, only: thermal_field_t
   use adore_thermal_drag, only: element_fluid_loss_t
   use adore_cage_step0, only: cage_step0_t
   implicit none
   private

   public :: thermal_columns, write_ball_step0, write_roller_step0, cage_tables, race_rows, speed_ratios


contains

   !> Write step 0 of a ball bearing (sections 1-4) from its quasi-static start s.
   subroutine write_ball_step0(unit, step, header, b, s)
      integer, intent(in) :: unit
      integer, intent(in) :: step           !< step number (0: the quasi-static start)
      !> step header: tau, time (s), outer and inner race rotations (rev); all 0 at step 0
      real(wp), intent(in) :: header(4)
      type(bearing_t), intent(in) :: b
      type(ball_step0_t), intent(in) :: s

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp), allocatable :: contact(:, :), motion(:, :), traction(:, :), thermal(:, :), re_cage(:, :)
      real(wp) :: slices(1, 10, 0), race_cage(max(b%n_lands, 1), 7), bodies(3, 11)
      real(wp) :: loads(5, 6), acc(3, 7), perf(N_PERFORMANCE), summary(1, 10), nan
      integer, allocatable :: re_no(:), cage_code(:), cage_end(:)
      integer :: n, k
      integer :: land_no(max(b%n_lands, 1)), land_code(max(b%n_lands, 1))

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      n = b%n_elements
      allocate (contact(n, 11), motion(n, 11), traction(n, 11), thermal(n, 11), re_cage(n, 8))
      allocate (re_no(n), cage_code(n), cage_end(n))
      re_no = [(k, k=1, n)]
      motion = nan
      traction = nan
      thermal = nan
      re_cage = nan
      cage_code = INT_NOT_COMPUTED
      cage_end = 0
      associate (e => s%start%equilibrium, kin => s%start%kinematics)
         contact(:, 1) = e%azimuth*deg
         contact(:, 2) = e%alpha_o*deg
         contact(:, 3) = e%alpha_i*deg
         contact(:, 4) = e%q_o
         contact(:, 5) = e%q_i
         contact(:, 6) = e%c_o%max_pressure
         contact(:, 7) = e%c_i%max_pressure
         contact(:, 8) = e%c_o%semi_major
         contact(:, 9) = e%c_i%semi_major
         contact(:, 10) = e%c_o%semi_minor
         contact(:, 11) = e%c_i%semi_minor
         motion(:, 1) = kin%orbital_speed*rpm
         motion(:, 2) = abs(kin%spin_speed)*rpm
         motion(:, 5:6) = 0.0_wp                       ! angular positions at time 0
         ! spin axis in the print's convention: omega = -amplitude (cos theta, sin theta)
         motion(:, 3) = atan2(-kin%spin_speed*sin(kin%pitch), -kin%spin_speed*cos(kin%pitch))*deg
         motion(:, 4) = 0.0_wp                         ! no out-of-plane component at step 0
         motion(:, 7) = s%spin_roll(1, :)
         motion(:, 8) = s%spin_roll(2, :)
         motion(:, 9) = s%loss(1, :)
         motion(:, 10) = s%loss(2, :)
         motion(:, 11) = s%wear                        ! Archard, adore_tribology_wear
         traction(:, 1) = s%slip(1, :)
         traction(:, 2) = s%slip(2, :)
         traction(:, 3) = s%trac_coeff(1, :)
         traction(:, 4) = s%trac_coeff(2, :)
         traction(:, 5) = s%film(1, :)
         traction(:, 6) = s%film(2, :)
         traction(:, 7) = s%thermal_factor(1, :)
         traction(:, 8) = s%thermal_factor(2, :)
         thermal(:, 2) = e%delta_o
         thermal(:, 3) = e%delta_i
         thermal(:, 4:5) = 0.0_wp                      ! rigid races: no race flexing
         ! Rel Axial Pos: the ball centre from the outer groove curvature-centre plane (as
         ! the dynamic steps; docs/print-layout.md)
         thermal(:, 1) = e%x - s%geometry%groove_centre(1, 1)
         thermal(:, 6) = s%temp_rise(1, :)
         thermal(:, 7) = s%temp_rise(2, :)
         thermal(:, 8) = s%contact_temp(1, :)
         thermal(:, 9) = s%contact_temp(2, :)
         ! section 2 bodies: Cage, ORace, IRace
         call race_rows(bodies, e%u(2:3), b%speed_outer, b%speed_inner)
         bodies(3, [1, 8, 9]) = [e%axial_displacement, e%u(4)*deg, e%u(5)*deg]  ! docs/examples.md
         bodies(2, 10) = s%mounting%outer_hoop_stress  ! largest hoop stress (adore_geometry_fits)
         bodies(3, 10) = s%mounting%inner_hoop_stress
         bodies(2:3, 11) = s%race_wear                 ! Archard over each race's contacts
         ! section 3: forces of the balls on the races and the reactions holding them
         loads = nan
         ! normal contact loads plus contact tractions (solve_ball_step0)
         loads(2, :) = s%race_loads(:, 1)
         loads(3, :) = s%race_loads(:, 2)
         loads(4, 1:3) = -(s%race_loads(1:3, 1) + s%outer_weight)
         loads(4, 4:6) = -s%race_loads(4:6, 1)
         loads(5, 1:3) = -(s%race_loads(1:3, 2) + s%inner_weight)
         loads(5, 4:6) = -s%race_loads(4:6, 2)
      end associate
      land_no = [(k, k=1, size(land_no))]
      call cage_tables(s%cage, cage_code, re_cage, land_code, race_cage, bodies(1, :))
      acc = nan
      acc(2, 1:6) = 0.0_wp                             ! quasi-static: races at rest / in equilibrium
      acc(3, 1:6) = 0.0_wp
      acc(2, 7) = b%temperature(TEMP_OUTER)
      acc(3, 7) = b%temperature(TEMP_INNER)
      call initial_thermal_state(b, s%cage, thermal, loads, acc, perf)
      perf(1) = s%basic_life_hours
      perf(2) = s%modified_life_hours
      perf(3) = s%mounting%outer_fit
      perf(4) = s%mounting%inner_fit
      perf(5) = s%mounting%clearance
      perf(6) = s%power_loss                           ! energy balance: sum of the contact losses
      summary = nan
      summary(1, 1:3) = header(2:4)                   ! time, race rotations
      summary(1, 5) = s%power_loss
      summary(1, 4) = s%modified_life_hours            ! the report's summary shows the modified life
      summary(1, 6:8) = speed_ratios(b, sum(s%start%kinematics%orbital_speed)/n, s%cage)
      summary(1, 9) = bodies(1, 11)                    ! cage wear: 0 without a cage contact
      call write_step(unit, step, header, b%run_id, re_no, contact, motion, traction, &
                      thermal, [integer ::], [integer ::], slices, 0, re_no, cage_end, cage_code, re_cage, &
                      land_no, land_code, race_cage, bodies, loads, acc, perf, [step], summary)
   end subroutine write_ball_step0

   !> Write step 0 of a cylindrical roller bearing (sections 1, 1a for roller 1, 2-4) from
   !> its quasi-static start s.  Section 1a: axial positions in each contact's frame (the
   !> inner contact's axis runs opposite to the outer one, as the report prints them) and
   !> loads per unit length in N/m for both races (the report's outer column appears to be
   !> scaled by the length scale D/2; pyadore prints N/m as the heading says - a known
   !> difference, see tests/test_run_golden.py).
   !> With the thermal model on (a roller run's printed steps; docs/thermal.md, "Roller runs"):
   !> fluid(n), each roller's drag, churning moment and their loss (added to the total power
   !> loss, their share of it the Churning Loss Fraction), and field, the last solved
   !> temperature field (each roller's contact node, bulk temperature and HTC, the exit fluid,
   !> housing and shaft temperatures, the races' and cage's bulk temperatures).
   subroutine write_roller_step0(unit, step, header, b, s, fluid, field)
      integer, intent(in) :: unit
      integer, intent(in) :: step           !< step number (0: the quasi-static start)
      !> step header: tau, time (s), outer and inner race rotations (rev); all 0 at step 0
      real(wp), intent(in) :: header(4)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(in) :: s
      type(element_fluid_loss_t), intent(in), optional :: fluid(:)
      type(thermal_field_t), intent(in), optional :: field

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp), allocatable :: contact(:, :), motion(:, :), traction(:, :), thermal(:, :), re_cage(:, :)
      real(wp), allocatable :: slices(:, :, :)
      real(wp) :: race_cage(max(b%n_lands, 1), 7), bodies(3, 11), loads(5, 6), acc(3, 7)
      real(wp) :: perf(N_PERFORMANCE), summary(1, 10), nan
      integer, allocatable :: re_no(:), slice_no(:), cage_el(:), cage_end(:), cage_code(:)
      integer :: land_no(max(b%n_lands, 1)), land_code(max(b%n_lands, 1))
      integer :: n, k, ns

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      n = b%n_elements
      allocate (contact(n, 11), motion(n, 11), traction(n, 11), thermal(n, 11))
      allocate (re_no(n), cage_el(2*n), cage_end(2*n), cage_code(2*n), re_cage(2*n, 8))
      re_no = [(k, k=1, n)]
      motion = nan
      traction = nan
      thermal = nan
      associate (e => s%equilibrium)
         ns = size(e%c_o(1)%x)
         allocate (slices(ns, 10, 1), slice_no(ns))
         slice_no = [(k, k=1, ns)]
         do k = 1, n
            contact(k, :) = [e%azimuth(k)*deg, 0.0_wp, 0.0_wp, e%c_o(k)%load, e%c_i(k)%load, &
                             e%c_o(k)%stress, e%c_i(k)%stress, e%c_o(k)%half_length, e%c_i(k)%half_length, &
                             e%c_o(k)%mean_half_width, e%c_i(k)%mean_half_width]
            thermal(k, 1) = 0.0_wp                    ! rollers axially centred at step 0 without flanges
            if (allocated(e%x)) thermal(k, 1) = e%x(k)  ! the flanged start's axial position
            thermal(k, 2) = e%c_o(k)%max_deflection
            thermal(k, 3) = e%c_i(k)%max_deflection
            thermal(k, 4:5) = 0.0_wp                  ! rigid races: no race flexing
            thermal(k, 6) = s%temp_rise(1, k)
            thermal(k, 7) = s%temp_rise(2, k)
            thermal(k, 8) = s%contact_temp(1, k)
            thermal(k, 9) = s%contact_temp(2, k)
         end do
         motion(:, 1) = e%orbital_speed*rpm
         ! each roller's spin (relative to its orbit frame): spin axis along -x or +x
         motion(:, 2) = abs(s%roller_spin)*rpm
         motion(:, 3) = merge(180.0_wp, 0.0_wp, s%roller_spin < 0.0_wp)
         motion(:, 4) = 0.0_wp                        ! no skew at the start
         motion(:, 5:6) = 0.0_wp                      ! angular positions at time 0
         motion(:, 7:8) = 0.0_wp                      ! cylindrical contact: no spin
         ! tribology (adore_tribology_roller_traction): printed slip = largest |u| over the
         ! slices, coefficient = kappa of it, contact loss = eq 4 summed over the slices
         motion(:, 9) = s%tr_o%power
         motion(:, 10) = s%tr_i%power
         motion(:, 11) = s%wear                       ! Archard, adore_tribology_wear
         traction(:, 1) = s%tr_o%max_slip
         traction(:, 2) = s%tr_i%max_slip
         traction(:, 3) = s%tr_o%max_slip_kappa
         traction(:, 4) = s%tr_i%max_slip_kappa
         slices = nan
         slices(:, 1, 1) = e%c_o(1)%x
         slices(:, 2, 1) = e%c_o(1)%delta
         slices(:, 3, 1) = e%c_o(1)%b
         slices(:, 4, 1) = e%c_o(1)%q
         slices(:, 6, 1) = -e%c_i(1)%x                ! in the inner contact frame (axis reversed)
         slices(:, 7, 1) = e%c_i(1)%delta
         slices(:, 8, 1) = e%c_i(1)%b
         slices(:, 9, 1) = e%c_i(1)%q
         ! traction on the race along the orbit direction, N/m (the report's outer column is
         ! scaled by D/2 as its normal load column)
         slices(:, 5, 1) = s%tr_o(1)%traction
         slices(:, 10, 1) = s%tr_i(1)%traction
         call race_rows(bodies, e%u, b%speed_outer, b%speed_inner)
         bodies(3, 1) = e%u_axial       ! 0 without flanges (no axial race motion); the flanged start's
         bodies(2, 10) = s%mounting%outer_hoop_stress
         bodies(3, 10) = s%mounting%inner_hoop_stress
         bodies(2:3, 11) = s%race_wear
         loads = nan
         ! normal slice loads plus slice tractions (roller_tribology); the start leaves
         ! race weights out, so the external loads balance the internal ones
         loads(2, :) = s%race_loads(:, 1)
         loads(3, :) = s%race_loads(:, 2)
         loads(4, :) = 0.0_wp - s%race_loads(:, 1)    ! (0 - x: no -0 printed)
         loads(5, :) = 0.0_wp - s%race_loads(:, 2)
      end associate
      cage_el = [(1 + (k - 1)/2, k=1, 2*n)]
      cage_end = [(1 + mod(k - 1, 2), k=1, 2*n)]
      land_no = [(k, k=1, size(land_no))]
      call cage_tables(s%cage, cage_code, re_cage, land_code, race_cage, bodies(1, :))
      acc = nan
      acc(2:3, 1:6) = 0.0_wp
      acc(2, 7) = b%temperature(TEMP_OUTER)
      acc(3, 7) = b%temperature(TEMP_INNER)
      call initial_thermal_state(b, s%cage, thermal, loads, acc, perf)
      perf(1) = s%basic_life_hours       ! eqs 73, 75, 76, 102 (adore_life_roller)
      perf(2) = s%modified_life_hours    ! NaN: no Tallian life for line contacts
      perf(3) = s%mounting%outer_fit
      perf(4) = s%mounting%inner_fit
      perf(5) = s%mounting%clearance
      perf(6) = s%power_loss             ! energy balance; NaN while a cage contact is not modelled
      call thermal_columns(traction, thermal, perf, fluid, field)
      if (present(field)) then                        ! the races' and cage's bulk temperatures
         acc(1, 7) = field%temperature(TEMP_CAGE)
         acc(2, 7) = field%temperature(TEMP_OUTER)
         acc(3, 7) = field%temperature(TEMP_INNER)
      end if
      summary = nan
      summary(1, 1:3) = header(2:4)                   ! time, race rotations
      summary(1, 5) = s%power_loss
      summary(1, 4) = s%basic_life_hours   ! no modified life for line contacts: the basic one, as printed
      summary(1, 6:8) = speed_ratios(b, sum(s%equilibrium%orbital_speed)/n, s%cage)
      summary(1, 9) = bodies(1, 11)      ! cage wear: NaN while a cage contact is not modelled
      call write_step(unit, step, header, b%run_id, re_no, contact, motion, traction, &
                      thermal, [1], slice_no, slices, 1, cage_el, cage_end, cage_code, re_cage, &
                      land_no, land_code, race_cage, bodies, loads, acc, perf, [step], summary)
      if (step == 0 .and. allocated(s%equilibrium%flange_load)) call write_roller_flanges(unit, s)
   end subroutine write_roller_step0

   !> The flanged start's roller end / flange contacts (adore_quasistatic_roller_flange_equilibrium),
   !> a block after step 0's sections (the report's print has no flange columns; docs/rollers.md,
   !> "Flanges at step 0"): per roller its axial position (m), tilt (rad) and each flange's Hertz
   !> load (N), then the inner race's axial position and the flanges' axial force on it (N).
   subroutine write_roller_flanges(unit, s)
      integer, intent(in) :: unit
      type(roller_step0_t), intent(in) :: s
      character(len=12) :: name(size(s%flanges%flange))
      integer :: i, k
      do i = 1, size(name)
         name(i) = trim(merge("Outer", "Inner", s%flanges%flange(i)%race == 1))//" "// &
                   trim(merge("-x", "+x", s%flanges%flange(i)%side < 0))
      end do
      write (unit, "(/a)") "  ROLLER END / FLANGE CONTACTS AT STEP 0 (QUASI-STATIC START, FLANGE LOADS IN N)"
      write (unit, "(a,*(a12))") "   RE No   Axial Pos        Tilt", (adjustr(name(i)), i=1, size(name))
      associate (e => s%equilibrium)
         do k = 1, size(e%x)
            write (unit, "(i8,2es12.4,*(es12.4))") k, e%x(k), e%tilt(k), e%flange_load(:, k)
         end do
         write (unit, "(a,es12.4,a,es12.4)") "   Inner race axial position ", e%u_axial, &
            "   flanges' axial force on it ", -sum(e%flange_axial, mask=spread(s%flanges%flange%race == 2, 2, size(e%x)))
      end associate
   end subroutine write_roller_flanges

   !> The thermal model's columns of a printed step (docs/thermal.md, "The wiring"), where
   !> given: fluid(n), each rolling element's drag, churning moment and their loss in
   !> section 1 (traction columns 9-11), added to the total power loss perf(6), their share of
   !> it the Churning Loss Fraction perf(7); field, the last solved temperature field: each
   !> element's contact node temperatures, bulk temperature and HTC (thermal columns 8-11),
   !> the exit fluid perf(8), housing perf(9:11) and shaft perf(12:14) temperatures (K).
   subroutine thermal_columns(traction, thermal, perf, fluid, field)
      real(wp), intent(inout) :: traction(:, :), thermal(:, :), perf(:)
      type(element_fluid_loss_t), intent(in), optional :: fluid(:)
      type(thermal_field_t), intent(in), optional :: field
      if (present(fluid)) then                        ! the thermal model's drag and churning
         traction(:, 9) = fluid%drag
         traction(:, 10) = fluid%moment
         traction(:, 11) = fluid%loss
         perf(6) = perf(6) + sum(fluid%loss)
         perf(7) = 0.0_wp
         if (perf(6) > 0.0_wp) perf(7) = sum(fluid%loss)/perf(6)
      end if
      if (present(field)) then                        ! the thermal model's last field
         thermal(:, 8) = field%contact_outer
         thermal(:, 9) = field%contact_inner
         thermal(:, 10) = field%element_bulk
         thermal(:, 11) = field%htc
         perf(8) = field%exit_temperature
         perf(9:11) = field%housing
         perf(12:14) = field%shaft
      end if
   end subroutine thermal_columns

   !> Section 2 cage rows from the step-0 cage c: RE/cage rows (one per ball, or end 1 and
   !> end 2 of each roller, in that order), race/cage rows (one per guide land; rows beyond
   !> the lands stay NaN) and the Cage row of the bodies table.
   !>
   !> Contact force, loss and wear rate are 0 and the code 0 where there is no contact
   !> (pocket and land: gap > 0, see adore_cage_step0); a contact needs the cage
   !> contact model: at step 0 NaN / not computed; in the roller dynamics' printed steps
   !> the pocket's force and loss (code 1; the wear rate NaN).  Land contact and attitude angles print 0 without contact
   !> (as the report's ball step 0), NaN with contact.  The cage's angular velocity is about
   !> +x (theta = phi = 0); its angular position theta, phi is 0 for an untilted cage (the
   !> mapping of Rec 9.5.1 angles y, z onto theta, phi is not identified: NaN otherwise).
   !> Hoop stress: not computed (NaN; the report prints 0 for the ball cage).
   subroutine cage_tables(c, code, re_cage, land_code, race_cage, cage_row)
      type(cage_step0_t), intent(in) :: c
      integer, intent(out) :: code(:), land_code(:)
      real(wp), intent(out) :: re_cage(:, :), race_cage(:, :), cage_row(:)

      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp) :: nan
      integer :: k, j, row
      logical :: any_contact, contact

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      code = INT_NOT_COMPUTED
      re_cage = nan
      land_code = INT_NOT_COMPUTED
      race_cage = nan
      cage_row = nan
      any_contact = .false.
      if (allocated(c%pocket)) then
         do k = 1, size(c%pocket, 2)
            do j = 1, size(c%pocket, 1)
               row = (k - 1)*size(c%pocket, 1) + j
               if (row > size(re_cage, 1)) cycle
               associate (p => c%pocket(j, k))
                  re_cage(row, 1) = p%geo_int
                  re_cage(row, 3) = p%theta*deg
                  re_cage(row, 4) = p%phi*deg
                  re_cage(row, 5) = p%pos(1)
                  re_cage(row, 6) = p%pos(3)
                  contact = p%in_contact
               end associate
               if (.not. contact) then
                  code(row) = 0
                  re_cage(row, [2, 7, 8]) = 0.0_wp
               else
                  any_contact = .true.
                  ! a contact with its force computed (the roller dynamics): code 1 as the
                  ! ball print's metallic contact, force and loss; the wear rate stays NaN
                  if (c%pocket(j, k)%force >= 0.0_wp) then
                     code(row) = 1
                     re_cage(row, 2) = c%pocket(j, k)%force
                     re_cage(row, 7) = c%pocket(j, k)%loss
                  end if
               end if
            end do
         end do
      end if
      if (allocated(c%land)) then
         do k = 1, min(size(c%land), size(race_cage, 1))
            race_cage(k, 1) = c%land(k)%geo_int
            race_cage(k, 5) = c%land(k)%effective_play
            if (.not. c%land(k)%in_contact) then
               land_code(k) = 0
               race_cage(k, [2, 3, 4, 6, 7]) = 0.0_wp
            else
               any_contact = .true.
            end if
         end do
      end if
      associate (st => c%state)
         cage_row(1) = st%centre(1)
         cage_row(2) = hypot(st%centre(2), st%centre(3))
         cage_row(3) = st%orbital_angle*deg
         cage_row(4) = st%whirl_speed*rpm
         cage_row(5) = abs(st%angular_speed)*rpm
         if (st%angular_speed >= 0.0_wp) cage_row(6:7) = 0.0_wp   ! along +x
         if (c%geometry_known) cage_row(8:9) = 0.0_wp
         if (.not. any_contact) cage_row(11) = 0.0_wp
      end associate
   end subroutine cage_tables

   !> Section 2's ORace and IRace rows (bodies rows 2, 3) at step 0, from the inner race's
   !> displacement u_yz = (Y, Z) (m) and the race speeds (rad/s): the outer race fixed at
   !> the origin, the inner race centre at radius |u_yz| and azimuth (from +z towards -y, as
   !> the elements and the cage) of u_yz; no orbital motion of either centre in the
   !> quasi-static start; both races untilted (the runs prescribe zero misalignment), so
   !> they spin about +x (theta 0; 180 deg for a negative speed), phi 0, at angular position
   !> 0.  The report prints exactly these for the roller run's inner race (0, 7.758E-06, 0,
   !> 0, 7.000E+04, 0, 0, 0, 0) and phi 0 for the ball run's outer race.  The inner race's
   !> axial position (its origin is not identified for the ball), hoop stress and wear are
   !> left NaN for the caller.
   subroutine race_rows(bodies, u_yz, w_outer, w_inner)
      real(wp), intent(inout) :: bodies(:, :)
      real(wp), intent(in) :: u_yz(2), w_outer, w_inner
      real(wp), parameter :: deg = rad_to_deg, rpm = rad_s_to_rpm
      real(wp) :: w(2)
      integer :: j

      bodies(2:3, :) = ieee_value(1.0_wp, ieee_quiet_nan)
      bodies(2, 1:3) = 0.0_wp
      bodies(3, 2) = hypot(u_yz(1), u_yz(2))
      bodies(3, 3) = 0.0_wp
      ! a lateral offset below 1e-9 of the displacement is round-off (the load's own plane, as
      ! the report's roller run prints 0): on the +z or -z axis, not 1e-11 or 360 deg by its sign
      if (bodies(3, 2) > 0.0_wp) then
         if (abs(u_yz(1)) <= 1.0e-9_wp*bodies(3, 2)) then
            bodies(3, 3) = merge(0.0_wp, 180.0_wp, u_yz(2) > 0.0_wp)
         else
            bodies(3, 3) = modulo(atan2(-u_yz(1), u_yz(2)), 2.0_wp*pi)*deg
         end if
      end if
      w = [w_outer, w_inner]
      do j = 1, 2
         bodies(j + 1, 4) = 0.0_wp
         bodies(j + 1, 5) = abs(w(j))*rpm
         bodies(j + 1, 6) = merge(180.0_wp, 0.0_wp, w(j) < 0.0_wp)
         bodies(j + 1, 7:9) = 0.0_wp
      end do
   end subroutine race_rows

   !> Step-0 values fixed by the deck alone, before any thermal solution or cage contact:
   !> the bodies' initial temperatures of Rec 2.7 (rolling elements' Bulk Temp, the cage's
   !> Bulk Temp, housing and shaft temperatures of section 3: ADORE's thermal nodes start
   !> at them; both report decks print them so at step 0), and, for a cage that touches
   !> nothing, zero cage forces and moments and an acceleration of gravity (Rec 11; no
   !> moment: no angular acceleration of the cage spinning about its axis of symmetry).
   !> perf is reset to NaN first; the rest of loads and acc is left as it is.
   subroutine initial_thermal_state(b, c, thermal, loads, acc, perf)
      type(bearing_t), intent(in) :: b
      type(cage_step0_t), intent(in) :: c
      real(wp), intent(inout) :: thermal(:, :), loads(:, :), acc(:, :)
      real(wp), intent(out) :: perf(:)
      perf = ieee_value(1.0_wp, ieee_quiet_nan)
      thermal(:, 10) = b%temperature(TEMP_ELEMENT)
      acc(1, 7) = b%temperature(TEMP_CAGE)
      perf(9:11) = b%temperature(TEMP_HOUSING)                    ! Hsng/Bulk, Hsng/Outer, Hsng/Inner
      perf(12:14) = b%temperature(TEMP_SHAFT)                   ! Shft/Bulk, Shft/Outer, Shft/Inner
      if (cage_free(c)) then
         loads(1, :) = 0.0_wp
         acc(1, 1:3) = b%gravity
         acc(1, 4:6) = 0.0_wp
      end if
   end subroutine initial_thermal_state

   !> True when the cage's geometry is modelled and it touches no rolling element and no land.
   pure logical function cage_free(c)
      type(cage_step0_t), intent(in) :: c
      cage_free = c%geometry_known
      if (allocated(c%pocket)) cage_free = cage_free .and. .not. any(c%pocket%in_contact)
      if (allocated(c%land)) cage_free = cage_free .and. .not. any(c%land%in_contact)
   end function cage_free

   !> Section 4 speed ratios at step 0 (time averages over one instant): mean rolling-element
   !> orbital speed, cage angular speed and cage whirl speed, each relative to the outer race
   !> over the inner race's speed relative to the outer race (both report decks turn the
   !> inner race only: 9139.7/20000 = 0.457 and 28490/70000 = 0.407 as printed); NaN when the
   !> races turn together.
   function speed_ratios(b, mean_orbital_speed, c) result(r)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: mean_orbital_speed   !< mean rolling-element orbital speed (rad/s)
      type(cage_step0_t), intent(in) :: c
      real(wp) :: r(3)
      real(wp) :: rel
      rel = b%speed_inner - b%speed_outer
      if (rel == 0.0_wp) then
         r = ieee_value(1.0_wp, ieee_quiet_nan)
         return
      end if
      r = ([mean_orbital_speed, c%state%angular_speed, c%state%whirl_speed] - b%speed_outer)/rel
   end function speed_ratios

end module adore_output_step_report
