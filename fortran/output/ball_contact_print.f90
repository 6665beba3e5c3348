!> The printed tribology of every ball/race contact at one integrated state (issue #29
!> item 3): slip velocity, traction coefficient, isothermal film, thermal reduction factor
!> and flash temperature rise, computed exactly as step 0 computes them
!> (adore_start_ball_step0's contact_tribology), but from the contacts of the force
!> assembly at that state instead of the quasi-static start.  The dynamic step's print
!> (adore_output_ball_dynamic_report) and the run's element record
!> (adore_output_run_history) both use it, so the two never disagree.  No module state.
module adore_output_ball_contact_print
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t, BODY_OUTER, BODY_INNER
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t
   use adore_contact_ball_race, only: ball_race_pair_t, planar_contact
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_kinematics
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, ball_race_pairs
   use adore_forces_race_contact, only: ehd_traction_model, lubricant_film, fluid_fraction, fluid_contact, &
                                        printed_slip, ehd_flash, law_flash
   implicit none
   private

   public :: contact_print_t, ball_contact_print

   !> The printed tribology of every race contact; (1, k) outer, (2, k) inner contact of
   !> ball k; NaN where the contact is unloaded or the quantity is not defined (film and
   !> thermal factor of an unlubricated deck).
   type :: contact_print_t
      real(wp), allocatable :: slip(:, :)            !< printed slip velocity |u| at the print node (m/s)
      real(wp), allocatable :: coefficient(:, :)     !< local traction coefficient there (-)
      real(wp), allocatable :: film(:, :)            !< isothermal central film thickness (m)
      real(wp), allocatable :: thermal_factor(:, :)  !< inlet thermal reduction factor (-)
      real(wp), allocatable :: temp_rise(:, :)       !< average flash temperature rise (K)
   end type contact_print_t

contains

   !> The printed tribology p of every race contact of ball bearing b (mounted geometry g)
   !> at state s with the force assembly's loads there (report 2.1 eqs 3-4 for the slip,
   !> 2.6 for the film and its thermal reduction factor, the run's traction law or the EHD
   !> film traction for the coefficient, the flash temperature of the run's model; all at
   !> the bulk temperatures of s, as the force assembly evaluates them).  A contact whose
   !> film or flash temperature cannot be computed keeps NaN there (the state's forces were
   !> computed, so this does not happen in a run that got here).  flash = .false.: the flash
   !> temperature rise is left NaN (it costs about four times the rest of a time step with
   !> the EHD traction: the element record computes it at printed steps only).
   !> lubricant_temperature: as the force assembly's (ball_bearing_loads; default the
   !> bulk temperatures of s).  threads (default 1): the balls on that many OpenMP threads,
   !> the same values bit for bit (run option threads).
   subroutine ball_contact_print(b, g, s, loads, p, flash, lubricant_temperature, threads)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      type(contact_print_t), intent(out) :: p
      logical, intent(in), optional :: flash
      real(wp), intent(in), optional :: lubricant_temperature(:)
      integer, intent(in), optional :: threads
      type(ball_race_pair_t) :: pairs(2)
      real(wp) :: nan, t_lub(size(s%temperature))
      integer :: n, k, n_threads
      logical :: ehd, with_flash

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      t_lub = s%temperature
      if (present(lubricant_temperature)) t_lub = lubricant_temperature
      n = size(loads%contacts, 2)
      allocate (p%slip(2, n), p%coefficient(2, n), p%film(2, n), p%thermal_factor(2, n), p%temp_rise(2, n), &
                source=nan)
      pairs = ball_race_pairs(b, g)
      ehd = ehd_traction_model(b)
      with_flash = .true.
      if (present(flash)) with_flash = flash
      ! each ball's contacts into its own slots, on threads threads (as the force assembly)
      n_threads = 1
      if (present(threads)) n_threads = max(threads, 1)
      if (n_threads > 1) then
         !$omp parallel do num_threads(n_threads) schedule(static, 1) default(shared) private(k)
         do k = 1, n
            call ball_print(k)
         end do
         !$omp end parallel do
      else
         do k = 1, n
            call ball_print(k)
         end do
      end if

   contains

      !> Ball k's two contacts (the procedure's header); run by one thread per ball.
      subroutine ball_print(k)
         integer, intent(in) :: k
         type(ball_race_contact_t) :: cj
         type(contact_traction_t) :: tk
         type(error_type), allocatable :: error
         real(wp) :: b_minor, p_h, h, f, rise, slip, coefficient
         integer :: j, race

         do j = 1, 2
            associate (c => loads%contacts(j, k))
               if (.not. (c%load > 0.0_wp .and. c%ellipse%semi_major > 0.0_wp)) cycle
               race = merge(BODY_OUTER, BODY_INNER, j == 1)
               cj = planar_contact(pairs(j), c)
               b_minor = c%ellipse%semi_minor
               p_h = c%ellipse%max_pressure
               call contact_kinematics(cj, tk)
               h = 0.0_wp
               if (b%lubricant_code /= 0) then
                  call lubricant_film(b, t_lub, tk, cj%a/b_minor, cj%load, p_h, race, p%film(j, k), &
                                      p%thermal_factor(j, k), error)
                  if (allocated(error)) then
                     p%film(j, k) = nan
                     p%thermal_factor(j, k) = nan
                     cycle
                  end if
               end if
               ! as step 0: the EHD flash with a film, the law's flash without one, a mixed
               ! film's blend of the two (docs/tribology.md, "Mixed films")
               f = 0.0_wp
               if (ehd) f = fluid_fraction(b, p%film(j, k), p%thermal_factor(j, k))
               if (f > 0.0_wp) then
                  h = p%film(j, k)*p%thermal_factor(j, k)
                  ! the film's share of the load (f Q at f p_H; the whole load for a full film)
                  if (with_flash) call ehd_flash(b, t_lub, fluid_contact(cj, f), b_minor, race, h, &
                                                 abs(tk%rolling_speed), p%temp_rise(j, k), error)
                  if (with_flash .and. f < 1.0_wp .and. .not. allocated(error)) then
                     call law_flash(b, cj, b_minor, p_h, race, abs(tk%rolling_speed), rise, error)
                     p%temp_rise(j, k) = f*p%temp_rise(j, k) + (1.0_wp - f)*rise
                  end if
               else if (with_flash) then
                  call law_flash(b, cj, b_minor, p_h, race, abs(tk%rolling_speed), p%temp_rise(j, k), error)
               end if
               if (allocated(error)) p%temp_rise(j, k) = nan
               ! the printed node of the traction used: model 3's with a film, else the curve's,
               ! a mixed film's blend of the two
               call printed_slip(b, t_lub, fluid_contact(cj, f), b_minor, race, h, h > 0.0_wp, p%slip(j, k), &
                                 p%coefficient(j, k))
               if (f > 0.0_wp .and. f < 1.0_wp) then
                  ! the film's node coefficient is over its share f of the strip's load
                  call printed_slip(b, t_lub, cj, b_minor, race, h, .false., slip, coefficient)
                  p%coefficient(j, k) = f*f*p%coefficient(j, k) + (1.0_wp - f)*coefficient
               end if
            end associate
         end do
      end subroutine ball_print

   end subroutine ball_contact_print

end module adore_output_ball_contact_print
