!> Flat f2py wrapper of the ball-bearing step 0 from a deck (module pyadore._engine;
!> bench/run_bench.py).

!> Step 0 of a ball-bearing deck, end to end: read the deck, build the model, mount the
!> races, solve the consistent start (race control) and the basic life.
!>
!> nmax: rows of balls (>= number of balls); n: number of balls.
!> balls(nmax, 37): [orbital position (rad), x, r (m), alpha_o, alpha_i (rad), Q_o, Q_i (N),
!>   p_o, p_i (Pa), a_o, a_i, b_o, b_i, delta_o, delta_i (m), orbital speed, spin speed (rad/s),
!>   pitch (rad), slip_o, slip_i (m/s), trac_o, trac_i (-), spin/roll o, i (-), loss_o, loss_i (W),
!>   film_o, film_i (m), thermal factor o, i (-), temperature rise o, i (K), sliding o, i
!>   (integral of |u| dQ, N m/s), wear rate (m**3/s), traction on the race o, i along the
!>   orbit direction e_x x e_r (N); NaN film and temperature columns for
!>   an unlubricated deck]
!> summary(19) = bearing power loss (W), summary(20) = modified (Tallian) life (h)
!> summary(20): [inner fit, outer fit, clearance (m), basic life, basic life outer, inner (h),
!>   inner race u(5), inner force(3), inner moment(3), passes]
subroutine adore_ball_step0_deck(deck_path, nmax, mech_tol, moments, n, balls, summary, status, message)
   use adore_core_kinds, only: wp
   use adore_api_status, only: set_error
   use adore_core_error, only: error_type, ADORE_OK, ADORE_INPUT_ERROR
   use adore_model_bearing, only: bearing_t, BALL_BEARING
   use adore_model_from_deck, only: read_bearing
   use adore_start_ball_step0, only: ball_step0_t, solve_ball_step0
   implicit none
   character(len=*), intent(in) :: deck_path
   integer, intent(in) :: nmax
   real(wp), intent(in) :: mech_tol                   !< start consistency test; <= 0: the default
   integer, intent(in) :: moments                     !< /= 0: moment equilibrium (kFS4 = kFS5 = 0)
   integer, intent(out) :: n
   real(wp), intent(out) :: balls(nmax, 37), summary(20)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message

   type(bearing_t) :: b
   type(ball_step0_t) :: s
   type(error_type), allocatable :: error

   n = 0
   balls = 0.0_wp
   summary = 0.0_wp
   status = ADORE_OK
   message = ""
   call read_bearing(deck_path, b, error)
   if (.not. allocated(error)) then
      if (b%bearing_type /= BALL_BEARING) then
         status = ADORE_INPUT_ERROR
         message = trim(deck_path)//": not a ball-bearing deck (Rec 3.2 bearing_type /= 1)"
         return
      end if
      if (b%n_elements > nmax) then
         status = ADORE_INPUT_ERROR
         message = "ball step 0: more balls than rows given (nmax)"
         return
      end if
      if (mech_tol > 0.0_wp) then
         call solve_ball_step0(b, s, error, moment_equilibrium=moments /= 0, centrifugal_tol=mech_tol)
      else
         call solve_ball_step0(b, s, error, moment_equilibrium=moments /= 0)
      end if
   end if
   if (allocated(error)) then
      call set_error(error, status, message)
      return
   end if
   n = b%n_elements
   associate (e => s%start%equilibrium)
      balls(1:n, 1) = e%azimuth
      balls(1:n, 2) = e%x
      balls(1:n, 3) = e%r
      balls(1:n, 4) = e%alpha_o
      balls(1:n, 5) = e%alpha_i
      balls(1:n, 6) = e%q_o
      balls(1:n, 7) = e%q_i
      balls(1:n, 8) = e%c_o%max_pressure
      balls(1:n, 9) = e%c_i%max_pressure
      balls(1:n, 10) = e%c_o%semi_major
      balls(1:n, 11) = e%c_i%semi_major
      balls(1:n, 12) = e%c_o%semi_minor
      balls(1:n, 13) = e%c_i%semi_minor
      balls(1:n, 14) = e%delta_o
      balls(1:n, 15) = e%delta_i
      balls(1:n, 16) = s%start%kinematics%orbital_speed
      balls(1:n, 17) = s%start%kinematics%spin_speed
      balls(1:n, 18) = s%start%kinematics%pitch
      balls(1:n, 19:20) = transpose(s%slip)
      balls(1:n, 21:22) = transpose(s%trac_coeff)
      balls(1:n, 23:24) = transpose(s%spin_roll)
      balls(1:n, 25:26) = transpose(s%loss)
      balls(1:n, 27:28) = transpose(s%film)
      balls(1:n, 29:30) = transpose(s%thermal_factor)
      balls(1:n, 31:32) = transpose(s%temp_rise)
      balls(1:n, 33:34) = transpose(s%sliding)
      balls(1:n, 35) = s%wear
      balls(1:n, 36:37) = transpose(s%traction)
      summary(19) = s%power_loss
      summary(20) = s%modified_life_hours
      summary(1:3) = [s%mounting%inner_fit, s%mounting%outer_fit, s%mounting%clearance]
      summary(4:6) = [s%basic_life_hours, s%basic_life_outer, s%basic_life_inner]
      summary(7:11) = e%u
      summary(12:14) = e%inner_force
      summary(15:17) = e%inner_moment
      summary(18) = real(s%start%passes, wp)
   end associate
end subroutine adore_ball_step0_deck
