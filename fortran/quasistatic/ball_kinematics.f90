!> Rolling kinematics of a ball between two races (ADORE initial ball angular velocity,
!> report section 4.4.7, race-control option).
!>
!> In the frame that orbits with the ball (orbital speed w_m about the bearing axis x),
!> the ball spins at w_b about an axis in the meridian (x, r) plane at pitch angle beta:
!> Omega_b = w_b (cos beta, sin beta).  Race j turns at (w_j - w_m).  With the contact
!> normal n_j = (n_jx, n_jr) pointing from the ball centre to the contact centre, the
!> contact centre lies at radius R_j = r_b + D/2 n_jr and
!>     rolling (no slip in the rolling direction at the contact centre):
!>         w_b D/2 (cos beta n_jr - sin beta n_jx) = (w_j - w_m) R_j,      j = o, i
!>     race control on race c (no spin about the normal of that contact):
!>         w_b (cos beta n_cx + sin beta n_cr) + (w_m - w_c) n_cx = 0.
!> The first two equations are linear in (w_m, w_b) for a given beta; beta is found by
!> bisection on the spin equation.  Speeds in rad/s, lengths in m, angles in rad.
!>
!> Minimum dissipation (report 4.4.7, the ADORE 5.0 default): the inner race contact rolls
!> at its centre (first equation, j = i), and the pitch beta and spin speed w_b minimise the
!> power lost in both race contacts (eq 4 with the deck's traction curve, zone-split Gauss,
!> adore_tribology_slip; with an EHD film, traction model 3, the fast EHD quadrature of
!> adore_tribology_ehd_traction).  For each beta of a grid the best w_b is found by golden section;
!> the minimum over beta is bracketed on the grid, located by parabolic interpolation and
!> polished by golden section inside the bracket.  Why the inner contact: the Appendix C
!> step 0 (the report's printed speeds and contact angles) rolls at the inner contact centre
!> to print precision (rolling radius within 2e-6 m of D/2 for all balls), while its outer
!> centre slides at -0.14 to -0.23 m/s; see docs/tribology.md.
module adore_quasistatic_ball_kinematics
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction_fast
   use adore_tribology_traction_law, only: traction_law_t
   use adore_tribology_slip, only: ball_race_contact_t, contact_power, contact_traction_t, SIDE_OUTER, SIDE_INNER
   use adore_quasistatic_ball_min_dissipation, only: brent_minimum, newton_minimum_2d
   implicit none
   private

   public :: ball_kinematics_t, race_control_kinematics, CONTROL_OUTER, CONTROL_INNER
   public :: MIN_DISSIPATION, min_dissipation_kinematics, ball_contacts, dissipation, ehd_films_t

   integer, parameter :: CONTROL_OUTER = 1  !< no spin at the outer race contact
   integer, parameter :: CONTROL_INNER = 2  !< no spin at the inner race contact
   integer, parameter :: MIN_DISSIPATION = 3  !< inner centre rolling, least contact power loss
   integer, parameter :: N_GAUSS_MIN = 4    !< Gauss points per slip zone (as the report prints)

   !> The EHD film of a ball's two race contacts (outer first) for the minimum-dissipation
   !> search with traction model 3: rheology at the wall temperature, film h (m, the
   !> thermally reduced central film; 0: no film, the deck's curve), semi-minor axis b (m)
   !> and the fluid fraction (mixed lubrication: the power is fluid times the EHD film's at
   !> fluid times the load plus 1 - fluid times the curve's; 1: a full film; docs/tribology.md,
   !> "Mixed films"),
   !> held fixed in the search.
   type :: ehd_films_t
      type(ehd_rheology_t) :: rheo(2)
      real(wp) :: h(2) = 0.0_wp
      real(wp) :: b(2) = 0.0_wp
      real(wp) :: fluid(2) = 1.0_wp
   end type ehd_films_t

   !> Result of the kinematic solution for one ball.
   type :: ball_kinematics_t
      real(wp) :: orbital_speed = 0.0_wp  !< w_m, ball orbital speed (rad/s)
      real(wp) :: spin_speed = 0.0_wp     !< w_b, ball angular speed relative to the orbit frame (rad/s)
      real(wp) :: pitch = 0.0_wp          !< beta, angle of the ball spin axis to the bearing axis (rad)
      real(wp) :: power = 0.0_wp          !< power lost in both race contacts (W), minimum dissipation only
      logical :: ok = .false.             !< .false. when the equations are singular
   end type ball_kinematics_t

contains

   !> Ball orbital and spin speed under race control (report 4.4.7, option kAngVel = race control).
   !>
   !> d ball diameter (m); r_b radius of the ball centre (m); n_o, n_i unit vectors
   !> (axial, radial) from the ball centre to the outer/inner contact centre; w_o, w_i race
   !> speeds (rad/s); control = CONTROL_OUTER or CONTROL_INNER.
   pure function race_control_kinematics(d, r_b, n_o, n_i, w_o, w_i, control) result(k)
      real(wp), intent(in) :: d, r_b, n_o(2), n_i(2), w_o, w_i
      integer, intent(in) :: control
      type(ball_kinematics_t) :: k

      real(wp), parameter :: half_pi = 2.0_wp*atan(1.0_wp)
      integer, parameter :: n_scan = 720
      real(wp) :: lo, hi, mid, f_lo, f_mid, f_hi, b0, b1, best
      integer :: it, j

      ! Scan for sign changes of the spin that are not poles of the rolling equations
      ! (where their determinant vanishes); keep the root nearest to beta = 0.
      best = huge(1.0_wp)
      lo = 0.0_wp
      hi = 0.0_wp
      do j = 0, n_scan - 1
         b0 = -half_pi + 2.0_wp*half_pi*real(j, wp)/n_scan
         b1 = -half_pi + 2.0_wp*half_pi*real(j + 1, wp)/n_scan
         if (determinant(b0)*determinant(b1) <= 0.0_wp) cycle
         f_lo = spin_residual(b0)
         f_hi = spin_residual(b1)
         if (f_lo*f_hi > 0.0_wp) cycle
         if (min(abs(b0), abs(b1)) < best) then
            best = min(abs(b0), abs(b1))
            lo = b0
            hi = b1
         end if
      end do
      if (best == huge(1.0_wp)) return
      f_lo = spin_residual(lo)
      do it = 1, 200
         mid = 0.5_wp*(lo + hi)
         f_mid = spin_residual(mid)
         if (f_lo*f_mid <= 0.0_wp) then
            hi = mid
         else
            lo = mid
            f_lo = f_mid
         end if
         if (hi - lo < 1.0e-15_wp) exit
      end do
      k = rolling(0.5_wp*(lo + hi))

   contains

      !> (w_m, w_b) from the two rolling conditions for pitch angle beta.
      pure function rolling(beta) result(s)
         real(wp), intent(in) :: beta
         type(ball_kinematics_t) :: s
         real(wp) :: a11, a12, a21, a22, b1, b2, det, r_o, r_i

         r_o = r_b + 0.5_wp*d*n_o(2)
         r_i = r_b + 0.5_wp*d*n_i(2)
         ! unknowns (w_m, w_b):  w_b D/2 c_j + w_m R_j = w_j R_j
         a11 = r_o
         a12 = 0.5_wp*d*(cos(beta)*n_o(2) - sin(beta)*n_o(1))
         a21 = r_i
         a22 = 0.5_wp*d*(cos(beta)*n_i(2) - sin(beta)*n_i(1))
         b1 = w_o*r_o
         b2 = w_i*r_i
         det = a11*a22 - a12*a21
         s%pitch = beta
         if (abs(det) <= epsilon(1.0_wp)*(abs(a11*a22) + abs(a12*a21))) return
         s%orbital_speed = (b1*a22 - a12*b2)/det
         s%spin_speed = (a11*b2 - a21*b1)/det
         s%ok = .true.
      end function rolling

      !> Spin about the normal of the controlling contact for pitch angle beta (rad/s).
      pure function spin_residual(beta) result(f)
         real(wp), intent(in) :: beta
         real(wp) :: f, n(2), w_c
         type(ball_kinematics_t) :: s

         s = rolling(beta)
         if (control == CONTROL_INNER) then
            n = n_i
            w_c = w_i
         else
            n = n_o
            w_c = w_o
         end if
         f = s%spin_speed*(cos(beta)*n(1) + sin(beta)*n(2)) + (s%orbital_speed - w_c)*n(1)
      end function spin_residual

      !> Determinant of the rolling equations for pitch angle beta.
      pure function determinant(beta) result(det)
         real(wp), intent(in) :: beta
         real(wp) :: det
         det = (r_b + 0.5_wp*d*n_o(2))*0.5_wp*d*(cos(beta)*n_i(2) - sin(beta)*n_i(1)) &
               - 0.5_wp*d*(cos(beta)*n_o(2) - sin(beta)*n_o(1))*(r_b + 0.5_wp*d*n_i(2))
      end function determinant

   end function race_control_kinematics

   !> The two race contacts of a ball turning at pitch beta (rad) and speed w_b (rad/s)
   !> with orbital speed w_m (rad/s): contact(1) outer, contact(2) inner, for
   !> adore_tribology_slip.  a(2), q(2): semi-major axes (m) and loads (N), outer first.
   pure function ball_contacts(d, r_b, n_o, n_i, w_o, w_i, a, q, beta, w_b, w_m) result(c)
      real(wp), intent(in) :: d, r_b, n_o(2), n_i(2), w_o, w_i, a(2), q(2), beta, w_b, w_m
      type(ball_race_contact_t) :: c(2)

      c(1) = ball_race_contact_t(SIDE_OUTER, atan2(n_o(1), n_o(2)), 0.5_wp*d, r_b, &
                                 w_b*[cos(beta), sin(beta)], w_o - w_m, a(1), q(1))
      c(2) = ball_race_contact_t(SIDE_INNER, atan2(-n_i(1), -n_i(2)), 0.5_wp*d, r_b, &
                                 w_b*[cos(beta), sin(beta)], w_i - w_m, a(2), q(2))
   end function ball_contacts

   !> Power (W) lost in the loaded race contacts (load > 0 and a > 0) of the ball state
   !> (beta, w_b, w_m): eq (4) with the traction law `law`, n_gauss points per slip zone; with
   !> the EHD film traction (model 3) instead when ehd is present (a contact with a film:
   !> ehd_contact_traction_fast's power, its own quadrature; in mixed lubrication its fluid
   !> fraction of that power at the fluid's share of the load plus the rest of the law's).
   subroutine dissipation(d, r_b, n_o, n_i, w_o, w_i, a, q, law, n_gauss, beta, w_b, w_m, p, error, ehd)
      real(wp), intent(in) :: d, r_b, n_o(2), n_i(2), w_o, w_i, a(2), q(2), beta, w_b, w_m
      type(traction_law_t), intent(in) :: law
      integer, intent(in) :: n_gauss
      real(wp), intent(out) :: p
      type(error_type), allocatable, intent(out) :: error
      type(ehd_films_t), intent(in), optional :: ehd
      type(ball_race_contact_t) :: c(2), cf
      type(contact_traction_t) :: t
      real(wp) :: pj, pl
      integer :: j

      p = 0.0_wp
      c = ball_contacts(d, r_b, n_o, n_i, w_o, w_i, a, q, beta, w_b, w_m)
      do j = 1, 2
         if (.not. (q(j) > 0.0_wp .and. a(j) > 0.0_wp)) cycle
         if (present(ehd)) then
            if (ehd%h(j) > 0.0_wp) then
               ! the EHD power by the dynamics' fast quadrature (graded at the pure-rolling
               ! points, the Hertz edges taken out): within 3e-5 of a 32 x 64 point rule and
               ! smooth in the pitch.  n_gauss plain Gauss points per slip zone were not: at
               ! 4 x 8 points the power jumped by up to 9 % where the zones split (two
               ! spurious minima 0.9 deg apart that the start flipped between;
               ! docs/operating-points.md, "Two pitch minima")
               ! mixed lubrication: the film sheared at its share fluid x the load (fluid x
               ! the Hertz pressure), blended with the law's power (docs/tribology.md, "Mixed
               ! films"; adore_forces_race_contact's fluid_contact and mixed_traction)
               cf = c(j)
               if (ehd%fluid(j) < 1.0_wp) cf%load = ehd%fluid(j)*c(j)%load
               call ehd_contact_traction_fast(cf, ehd%rheo(j), ehd%h(j), ehd%b(j), t, error)
               pj = t%power
               if (ehd%fluid(j) < 1.0_wp .and. .not. allocated(error)) then
                  call contact_power(c(j), law, 1.0_wp, n_gauss, pl, error)
                  pj = ehd%fluid(j)*pj + (1.0_wp - ehd%fluid(j))*pl
               end if
            else
               ! a contact without an EHD film: the deck's traction curve (docs/tribology.md)
               call contact_power(c(j), law, 1.0_wp, n_gauss, pj, error)
            end if
         else
            call contact_power(c(j), law, 1.0_wp, n_gauss, pj, error)
         end if
         if (allocated(error)) return
         p = p + pj
      end do
   end subroutine dissipation

   !> Ball orbital speed, spin speed and pitch by minimum contact dissipation (report
   !> 4.4.7): inner contact centre in pure rolling, (beta, w_b) minimising the power of
   !> both race contacts.  Arguments as race_control_kinematics plus a(2), q(2): semi-major
   !> axes (m) and loads (N) of the outer and inner contact; law: the traction law (the
   !> deck's curve, Rec 10.1, or a traction-slip table), or the EHD film traction when ehd is given.
   !> Fast search (default): Newton's method on the stationarity conditions of the power in
   !> (pitch, spin speed), adore_quasistatic_ball_min_dissipation, from `hint` (the pitch
   !> of a previous solution) or from the best point of a 1 deg grid of pitch in
   !> [-30, 30] deg (spin speed by a 1-D Newton at each); it places the minimum of the same
   !> power to ~1e-10, and falls back to the reference search when it fails or leaves the
   !> reference's search box.  Reference search (reference = .true.): pitch on that grid
   !> (within +-4 deg of `hint` when given), best spin speed by golden section at each,
   !> refined by parabolic interpolation and golden section.
   !> Input error when neither contact is loaded or the inner contact geometry is degenerate.
   subroutine min_dissipation_kinematics(d, r_b, n_o, n_i, w_o, w_i, a, q, law, k, error, hint, ehd, reference, &
                                         hint_speed)
      real(wp), intent(in) :: d, r_b, n_o(2), n_i(2), w_o, w_i, a(2), q(2)
      type(traction_law_t), intent(in) :: law
      type(ball_kinematics_t), intent(out) :: k
      type(error_type), allocatable, intent(out) :: error
      !> pitch (rad) of a previous solution: the grid search is then limited to +-4 degrees
      !> around it (the start's later passes move the minimum by far less)
      real(wp), intent(in), optional :: hint
      !> the EHD film of both contacts: the power is the EHD traction's (model 3)
      type(ehd_films_t), intent(in), optional :: ehd
      !> .true.: the reference search (grid and golden sections) instead of Newton's method
      logical, intent(in), optional :: reference
      !> spin speed w_b (rad/s) of the previous solution whose pitch is `hint`: Newton starts
      !> there (the fast search)
      real(wp), intent(in), optional :: hint_speed

      real(wp), parameter :: step = pi/180.0_wp
      integer, parameter :: n_full = 61, n_near = 9
      real(wp), parameter :: gr = 0.5_wp*(sqrt(5.0_wp) - 1.0_wp)
      real(wp) :: betas(n_full), powers(n_full), speeds(n_full), scale, lo, hi, x1, x2, f1, f2, bp, den, centre
      real(wp) :: beta_fixed, speed_fixed
      integer :: j, i, it, n_grid
      logical :: done

      if (.not. ((q(1) > 0.0_wp .and. a(1) > 0.0_wp) .or. (q(2) > 0.0_wp .and. a(2) > 0.0_wp))) then
         block
            character(len=160) :: buf
            write (buf, "(a,4es10.2)") " (outer load, semi-major axis; inner load, semi-major axis:", q(1), a(1), &
               q(2), a(2)
            call input_error(error, "minimum dissipation kinematics: no loaded race contact"//trim(buf)//" N, m)")
         end block
         return
      end if
      if (.not. (d > 0.0_wp .and. r_b + 0.5_wp*d*n_i(2) > 0.0_wp)) then
         call input_error(error, "minimum dissipation kinematics: degenerate inner contact geometry")
         return
      end if
      ! speed scale: the spin speed of a ball rolling on the inner race at zero pitch
      scale = abs((w_i - w_o)*(r_b + 0.5_wp*d*n_i(2))/(0.5_wp*d))
      if (scale <= 0.0_wp) scale = 1.0_wp
      n_grid = n_full
      centre = 0.0_wp
      if (present(hint)) then
         n_grid = n_near
         centre = step*nint(hint/step)
      end if
      do j = 1, n_grid
         betas(j) = centre + (j - 1 - (n_grid - 1)/2)*step
      end do
      done = .false.
      if (present(reference)) done = reference
      if (.not. done) then
         call newton_search(done)
         if (allocated(error) .or. done) return
      end if
      do j = 1, n_grid
         call best_speed(betas(j), speeds(j), powers(j))
         if (allocated(error)) return
      end do
      i = minloc(powers(1:n_grid), 1)
      i = min(max(i, 2), n_grid - 1)
      ! parabolic interpolation through the grid minimum and its neighbours ...
      den = powers(i - 1) - 2.0_wp*powers(i) + powers(i + 1)
      bp = betas(i)
      if (den > 0.0_wp) bp = betas(i) + 0.5_wp*step*(powers(i - 1) - powers(i + 1))/den
      ! ... polished by golden section on the bracket [beta(i-1), beta(i+1)]
      lo = betas(i - 1)
      hi = betas(i + 1)
      x1 = hi - gr*(hi - lo)
      x2 = lo + gr*(hi - lo)
      call best_speed(x1, k%spin_speed, f1)
      call best_speed(x2, k%spin_speed, f2)
      do it = 1, 60
         if (allocated(error)) return
         if (f1 <= f2) then
            hi = x2
            x2 = x1
            f2 = f1
            x1 = hi - gr*(hi - lo)
            call best_speed(x1, k%spin_speed, f1)
         else
            lo = x1
            x1 = x2
            f1 = f2
            x2 = lo + gr*(hi - lo)
            call best_speed(x2, k%spin_speed, f2)
         end if
         if (hi - lo < 1.0e-9_wp) exit
      end do
      if (allocated(error)) return
      bp = 0.5_wp*(lo + hi)
      call best_speed(bp, k%spin_speed, k%power)
      if (allocated(error)) return
      k%pitch = bp
      k%orbital_speed = inner_rolling_orbit(bp, k%spin_speed)
      k%ok = .true.

   contains

      !> The fast search (see above): k filled and done = .true. on success.
      subroutine newton_search(done)
         logical, intent(out) :: done
         real(wp), parameter :: h = 1.0e-4_wp, tol = 1.0e-8_wp, max_step = 0.5_wp
         real(wp) :: lo2(2), hi2(2), y0(2), y(2), f, x, best, s_turn
         integer :: j, n_eval
         logical :: ok, failed

         done = .false.
         ! scaled variables: pitch in steps (deg), spin speed in units of `scale`
         s_turn = sign(1.0_wp, w_i - w_o)
         lo2 = [betas(1)/step, min(-1.5_wp*s_turn, -0.5_wp*s_turn)]
         hi2 = [betas(n_grid)/step, max(-1.5_wp*s_turn, -0.5_wp*s_turn)]
         if (present(hint)) then
            y0(1) = min(max(hint/step, lo2(1)), hi2(1))
            if (present(hint_speed)) then
               ! from the previous solution itself (its basin: the state moved little)
               y0(2) = min(max(hint_speed/scale, lo2(2)), hi2(2))
               call newton_minimum_2d(power_objective, y0, lo2, hi2, h, tol, max_step, y, f, ok, failed, n_eval)
               if (failed) return
               if (ok) call verified(y, f, ok, failed)
               if (failed) return
               if (ok) then
                  call accept(y, f)
                  done = .true.
                  return
               end if
            end if
         else
            ! the pitch grid of the reference search, best spin speed at each (in a narrow
            ! interval about the neighbouring pitch's), to start Newton in the basin of the
            ! least power
            best = huge(1.0_wp)
            x = huge(1.0_wp)
            do j = 1, n_grid
               beta_fixed = betas(j)
               call best_scaled_speed(x, lo2(2), hi2(2), 1.0e-4_wp, x, f, failed)
               if (failed) return
               if (f < best) then
                  best = f
                  y0(1) = betas(j)/step
               end if
            end do
         end if
         beta_fixed = y0(1)*step
         x = huge(1.0_wp)
         call best_scaled_speed(x, lo2(2), hi2(2), 1.0e-7_wp, y0(2), f, failed)
         if (failed) return
         call newton_minimum_2d(power_objective, y0, lo2, hi2, h, tol, max_step, y, f, ok, failed, n_eval)
         if (failed .or. .not. ok) return
         call verified(y, f, ok, failed)
         if (failed .or. .not. ok) return
         call accept(y, f)
         done = .true.

      end subroutine newton_search

      !> Newton's stationary point y (power f) checked along the spin speed: Brent's method
      !> at its pitch, within 0.03 of its spin speed, must not find a power lower by more
      !> than DISSIPATION_CHECK relative (a kink of the power - a contact zone or film table
      !> boundary - can make the difference Hessian huge and the Newton step vanish away
      !> from the minimum).  ok = .false.: not a minimum, the caller's reference search
      !> takes over.
      subroutine verified(y, f, ok, failed)
         real(wp), intent(in) :: y(2), f
         logical, intent(out) :: ok, failed
         real(wp), parameter :: DISSIPATION_CHECK = 1.0e-6_wp
         real(wp) :: xb, fb
         beta_fixed = y(1)*step
         call brent_minimum(speed_objective, y(2) - 0.03_wp, y(2) + 0.03_wp, 1.0e-7_wp, xb, fb, failed)
         ok = .not. failed .and. .not. (fb < f - DISSIPATION_CHECK*abs(f))
         if (.not. ok) return
         speed_fixed = y(2)
         call brent_minimum(pitch_objective, y(1) - 0.5_wp, y(1) + 0.5_wp, 1.0e-7_wp, xb, fb, failed)
         ok = .not. failed .and. .not. (fb < f - DISSIPATION_CHECK*abs(f))
      end subroutine verified

      !> Power (W) at pitch x*step and spin speed speed_fixed*scale (the pitch check).
      subroutine pitch_objective(x, f, failed)
         real(wp), intent(in) :: x
         real(wp), intent(out) :: f
         logical, intent(out) :: failed
         f = power_at(x*step, speed_fixed*scale)
         failed = allocated(error)
      end subroutine pitch_objective

      !> k from the scaled minimum y (pitch in steps, spin speed in units of scale), power f (W)
      subroutine accept(y, f)
         real(wp), intent(in) :: y(2), f
         k%pitch = y(1)*step
         k%spin_speed = y(2)*scale
         k%power = f
         k%orbital_speed = inner_rolling_orbit(k%pitch, k%spin_speed)
         k%ok = .true.
      end subroutine accept

      !> Least power f over the scaled spin speed at pitch beta_fixed: x (to tol) by Brent's
      !> method within 0.03 of x_near (a neighbouring solution), or over the whole search
      !> interval [lo, hi] when x_near is huge() or the minimum lies on the narrow interval's end.
      subroutine best_scaled_speed(x_near, lo, hi, tol, x, f, failed)
         real(wp), intent(in) :: x_near, lo, hi, tol
         real(wp), intent(out) :: x, f
         logical, intent(out) :: failed
         real(wp) :: l, u
         if (x_near < huge(1.0_wp)) then
            l = max(x_near - 0.03_wp, lo)
            u = min(x_near + 0.03_wp, hi)
            call brent_minimum(speed_objective, l, u, tol, x, f, failed)
            if (failed) return
            if (x - l > 10.0_wp*tol .and. u - x > 10.0_wp*tol) return
         end if
         call brent_minimum(speed_objective, lo, hi, tol, x, f, failed)
      end subroutine best_scaled_speed

      !> Power (W) at pitch beta_fixed and spin speed x*scale (Newton's scaled variable).
      subroutine speed_objective(x, f, failed)
         real(wp), intent(in) :: x
         real(wp), intent(out) :: f
         logical, intent(out) :: failed
         f = power_at(beta_fixed, x*scale)
         failed = allocated(error)
      end subroutine speed_objective

      !> Power (W) at pitch y(1)*step and spin speed y(2)*scale (Newton's scaled variables).
      subroutine power_objective(y, f, failed)
         real(wp), intent(in) :: y(2)
         real(wp), intent(out) :: f
         logical, intent(out) :: failed
         f = power_at(y(1)*step, y(2)*scale)
         failed = allocated(error)
      end subroutine power_objective

      !> Orbital speed (rad/s) for which the inner contact centre rolls at (beta, w_b).
      pure function inner_rolling_orbit(beta, w_b) result(w_m)
         real(wp), intent(in) :: beta, w_b
         real(wp) :: w_m
         w_m = w_i - w_b*0.5_wp*d*(cos(beta)*n_i(2) - sin(beta)*n_i(1))/(r_b + 0.5_wp*d*n_i(2))
      end function inner_rolling_orbit

      !> Least power p (W) over the spin speed w_b (rad/s) at pitch beta (golden section on
      !> w_b in -scale*[0.5, 1.5], the ball turning against the inner race).
      subroutine best_speed(beta, w_b, p)
         real(wp), intent(in) :: beta
         real(wp), intent(out) :: w_b, p
         real(wp) :: l, h, y1, y2, g1, g2
         integer :: m

         l = -1.5_wp*scale*sign(1.0_wp, w_i - w_o)
         h = -0.5_wp*scale*sign(1.0_wp, w_i - w_o)
         y1 = h - gr*(h - l)
         y2 = l + gr*(h - l)
         g1 = power_at(beta, y1)
         g2 = power_at(beta, y2)
         do m = 1, 80
            if (allocated(error)) return
            if (g1 <= g2) then
               h = y2
               y2 = y1
               g2 = g1
               y1 = h - gr*(h - l)
               g1 = power_at(beta, y1)
            else
               l = y1
               y1 = y2
               g1 = g2
               y2 = l + gr*(h - l)
               g2 = power_at(beta, y2)
            end if
            if (abs(h - l) < 1.0e-9_wp*scale) exit
         end do
         w_b = 0.5_wp*(l + h)
         p = power_at(beta, w_b)
      end subroutine best_speed

      !> Power (W) of both contacts at (beta, w_b) with the inner centre rolling.
      function power_at(beta, w_b) result(p)
         real(wp), intent(in) :: beta, w_b
         real(wp) :: p
         p = 0.0_wp
         if (allocated(error)) return
         call dissipation(d, r_b, n_o, n_i, w_o, w_i, a, q, law, N_GAUSS_MIN, beta, w_b, &
                          inner_rolling_orbit(beta, w_b), p, error, ehd)
      end function power_at

   end subroutine min_dissipation_kinematics

end module adore_quasistatic_ball_kinematics
