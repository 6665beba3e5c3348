!> Unit tests of the cage's whirl on its guide lands (issue #20, report 4.4.4), on the
!> Appendix C cage (inner-race guided, two lands, MIL-L-7808 at 323 K):
!> * static load capacity: at the closed-form equilibrium of Ocvirk's short bearing
!>   (Hamrock, Fundamentals of Fluid Film Lubrication, NASA RP-1255 1991: eccentricity
!>   ratio from W = eta w R L**3/(4 c**2) eps/(1 - eps**2)**2 sqrt(16 eps**2 + pi**2 (1 - eps**2)),
!>   attitude angle tan(phi) = pi sqrt(1 - eps**2)/(4 eps)) the two land films of
!>   adore_contact_cage_land carry the cage's weight, through the full 3-D routine (which
!>   body is the journal, the sense of rotation);
!> * the film feeds a whirl slower than the mean surface speed wbar = (w_race + w_cage)/2 and
!>   brakes a faster one: the film's power on the whirling cage has the sign of wbar - psidot
!>   and is linear in it (the half-Sommerfeld film of the short bearing);
!> * the report's start whirl (4.4.4: whirl velocity = cage angular velocity, Rec 9.5.1
!>   offset) needs a centripetal force m r W**2 that the land films at that state supply
!>   only in small part: without pocket contact the cage leaves that circle (orbit radius
!>   +1 % within a fraction of a whirl period);
!> * the free cage (land films and gravity; race and cage spinning at their start speeds)
!>   has two attractors: Ocvirk's static equilibrium is stable (pushed by 1 um, the cage
!>   stays within 1 % of it, no whirl), and a cage dropped from the race centre at rest
!>   overshoots it into the half-frequency whirl (oil whip) psidot = wbar on the clearance
!>   circle: the circular whirl that the films carry without any pocket contact; on it the
!>   cage keeps its orbit radius within 1 % and the film force equals m e psidot**2.
!> Run by `meson test` with the decks/ directory as argument.
!> The cage alone on its guide lands for the tests: translation in the plane normal to the
!> bearing axis under the land films and gravity, the inner race fixed at the origin and
!> both spins held (state y = (y, z, v_y, v_z), SI).
module test_cage_whirl_free_cage
   use adore_core_kinds, only: wp
   use adore_contact_cage_land, only: cage_land_pair_t, cage_land_geometry_t, cage_land_contact
   use adore_state_bearing_state, only: body_state_t
   use adore_dynamics_integrator, only: derivative_t, DERIV_OK
   implicit none
   private
   public :: free_cage_t, land_force_on_cage

   !> The cage on its lands (kg, rad/s, m/s**2).
   type, extends(derivative_t) :: free_cage_t
      type(cage_land_pair_t), allocatable :: lands(:)
      real(wp) :: mass = 1.0_wp, w_race = 0.0_wp, w_cage = 0.0_wp, gravity(3) = 0.0_wp
   contains
      procedure :: eval => free_cage_eval
   end type free_cage_t

contains

   !> Total land force (N) on the cage at position (y, z) and velocity (v_y, v_z) of y.
   function land_force_on_cage(sys, y) result(f)
      type(free_cage_t), intent(in) :: sys
      real(wp), intent(in) :: y(4)
      real(wp) :: f(3)
      type(body_state_t) :: cage, race
      type(cage_land_geometry_t) :: c
      integer :: k
      race%omega = [sys%w_race, 0.0_wp, 0.0_wp]
      cage%omega = [sys%w_cage, 0.0_wp, 0.0_wp]
      cage%position = [0.0_wp, y(1), y(2)]
      cage%velocity = [0.0_wp, y(3), y(4)]
      f = 0.0_wp
      do k = 1, size(sys%lands)
         call cage_land_contact(sys%lands(k), cage, race, c)
         f = f + c%force_cage
      end do
   end function land_force_on_cage

   subroutine free_cage_eval(self, t, y, dydt, flag)
      class(free_cage_t), intent(inout) :: self
      real(wp), intent(in) :: t
      real(wp), intent(in) :: y(:)
      real(wp), intent(out) :: dydt(:)
      integer, intent(out) :: flag
      real(wp) :: f(3)
      f = land_force_on_cage(self, y(1:4)) + self%mass*self%gravity
      dydt(1:4) = [y(3), y(4), f(2)/self%mass, f(3)/self%mass]
      flag = DERIV_OK
   end subroutine free_cage_eval

end module test_cage_whirl_free_cage

program test_cage_whirl
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_model_bearing, only: BODY_CAGE, bearing_t
   use adore_model_from_deck, only: read_bearing
   use adore_geometry_mounted, only: mounted_geometry_t, mount_geometry
   use adore_forces_ball_bearing, only: guide_land_pairs
   use adore_dynamics_integrator, only: integrator_t, integrator_settings_t
   use adore_start_ball_step0, only: ball_step0_t, solve_ball_step0
   use adore_test_support, only: check, finish, get_decks_dir
   use test_cage_whirl_free_cage, only: free_cage_t, land_force_on_cage
   implicit none

   character(len=:), allocatable :: decks
   type(bearing_t) :: b
   type(mounted_geometry_t) :: g
   type(ball_step0_t) :: s0
   type(error_type), allocatable :: error
   type(free_cage_t) :: cage
   real(wp) :: c, wbar

   call get_decks_dir(decks)
   call read_bearing(decks//"/appendix_c_ball.inp", b, error)
   call check(.not. allocated(error), "read the Appendix C deck")
   if (allocated(error)) call finish("cage whirl")
   g = mount_geometry(b, b%temperature)
   call solve_ball_step0(b, s0, error)
   call check(.not. allocated(error), "step 0 of Appendix C")
   if (allocated(error)) call finish("cage whirl")
   cage%lands = guide_land_pairs(b, g, b%temperature)
   cage%lands%oil_layer = huge(1.0_wp)        ! the flooded film is these tests' subject
   cage%mass = b%mass(BODY_CAGE)
   cage%w_race = b%speed_inner
   cage%w_cage = s0%cage%state%angular_speed
   cage%gravity = b%gravity
   c = cage%lands(1)%clearance
   wbar = 0.5_wp*(cage%w_race + cage%w_cage)
   write (*, "(a,f8.3,a,f8.2,a,f8.4,a,f8.2,a,f8.2,a)") "Appendix C cage: m ", cage%mass, " kg, c ", c*1e6, &
      " um, eta ", cage%lands(1)%viscosity*1e3, " mPa s, race ", cage%w_race, " rad/s, cage ", cage%w_cage, " rad/s"

   call test_static_capacity()
   call test_whirl_power()
   call test_held_whirl_film_force()
   call test_report_whirl_needs_a_centripetal_force()
   call test_static_equilibrium_is_stable()
   call test_half_frequency_whirl()
   call finish("cage whirl")

contains

   !> Ocvirk's load capacity (N) of one land at eccentricity ratio eps (Hamrock 1991),
   !> w = sum of the surface speeds (rad/s).
   pure real(wp) function ocvirk_load(eps, w)
      real(wp), intent(in) :: eps, w
      associate (p => cage%lands(1))
         ocvirk_load = p%viscosity*w*p%radius*p%width**3/(4.0_wp*p%clearance**2)*eps/(1.0_wp - eps**2)**2 &
                       *sqrt(16.0_wp*eps**2 + pi**2*(1.0_wp - eps**2))
      end associate
   end function ocvirk_load

   !> The closed-form equilibrium of the cage's weight on its lands (no whirl): the cage at
   !> e = race - cage = c eps e_e with e_e at phi + 90 deg from +y towards +z (the film force
   !> on the race, the journal, points down), the film force on the cage equal to minus the
   !> weight.
   subroutine test_static_capacity()
      real(wp) :: eps, phi, beta, y(4), f(3), weight(3)
      eps = ocvirk_eps()
      phi = atan(pi*sqrt(1.0_wp - eps**2)/(4.0_wp*eps))
      beta = phi + 0.5_wp*pi
      y = [-c*eps*cos(beta), -c*eps*sin(beta), 0.0_wp, 0.0_wp]
      f = land_force_on_cage(cage, y)
      weight = cage%mass*cage%gravity
      write (*, "(a,f8.5,a,f7.2,a,2es11.3,a,es9.2)") "static: Ocvirk eps ", eps, ", attitude ", phi*180/pi, &
         " deg; cage at (y, z) ", y(1:2), " m; |film + weight|/weight ", norm2(f + weight)/norm2(weight)
      call check(norm2(f + weight) <= 1.0e-9_wp*norm2(weight), &
                 "static: the land films carry the cage weight at Ocvirk's eccentricity and attitude angle")
   end subroutine test_static_capacity

   !> The cage whirling on a circle of eccentricity ratio 0.5 about the race at psidot:
   !> the film's power F.v on the cage is positive below wbar, zero at wbar, negative above,
   !> and linear in wbar - psidot.
   subroutine test_whirl_power()
      real(wp) :: r, p(5), psidot(5), y(4), lin
      integer :: i
      r = 0.5_wp*c
      psidot = wbar*[0.0_wp, 0.5_wp, 1.0_wp, 1.5_wp, 2.0_wp]
      do i = 1, 5
         ! cage at -r e_z about the race, moving along x x (-e_z) = +e_y ... at psidot r
         y = [0.0_wp, -r, psidot(i)*r, 0.0_wp]
         p(i) = dot_product(land_force_on_cage(cage, y), [0.0_wp, y(3), y(4)])
      end do
      write (*, "(a,5es11.3,a)") "whirl power at psidot/wbar = 0, 0.5, 1, 1.5, 2: ", p, " W"
      call check(p(2) > 0.0_wp .and. p(4) < 0.0_wp, "whirl: the film feeds a whirl below wbar, brakes one above")
      call check(abs(p(3)) <= 1.0e-12_wp*abs(p(2)), "whirl: no film force at the half-frequency whirl")
      ! F_t is linear in wbar - psidot and P = F_t psidot r: P(1.5 wbar) = -3 P(0.5 wbar)
      lin = -3.0_wp*p(2)
      call check(abs(p(4) - lin) <= 1.0e-12_wp*abs(lin), "whirl: film force linear in wbar - psidot")
   end subroutine test_whirl_power

   !> A cage held on a circular whirl of eccentricity ratio eps at whirl speed psidot about
   !> the race reproduces the short bearing's closed form (Hamrock 1991; Childs 1993 ch. 3:
   !> in the frame turning with the whirl the film sees the surface speeds w - psidot, so
   !> Ocvirk's static forces hold with w replaced by 2 (wbar - psidot)): per land the radial
   !> force (towards the race centre) eta w R L**3 eps**2/(c**2 (1 - eps**2)**2) and the
   !> tangential force pi eta w R L**3 eps/(4 c**2 (1 - eps**2)**1.5), along the whirl below
   !> wbar and against it above; at eps = 0.2, 0.5, 0.8 and psidot/wbar = 0, 0.5, 1.5.
   subroutine test_held_whirl_film_force()
      real(wp) :: eps(3), ratio(3), y(4), f(3), fr, ft, w, worst
      integer :: i, j, k
      eps = [0.2_wp, 0.5_wp, 0.8_wp]
      ratio = [0.0_wp, 0.5_wp, 1.5_wp]
      worst = 0.0_wp
      do i = 1, 3
         do j = 1, 3
            ! cage at -r e_z about the race, moving along +e_y: whirl about +x at psidot
            y = [0.0_wp, -eps(i)*c, ratio(j)*wbar*eps(i)*c, 0.0_wp]
            f = land_force_on_cage(cage, y)
            w = 2.0_wp*(wbar - ratio(j)*wbar)
            fr = 0.0_wp
            ft = 0.0_wp
            do k = 1, size(cage%lands)
               associate (p => cage%lands(k))
                  fr = fr + p%viscosity*abs(w)*p%radius*p%width**3*eps(i)**2/(p%clearance**2*(1.0_wp - eps(i)**2)**2)
                  ft = ft + sign(1.0_wp, w)*pi*p%viscosity*abs(w)*p%radius*p%width**3*eps(i) &
                       /(4.0_wp*p%clearance**2*(1.0_wp - eps(i)**2)**1.5_wp)
               end associate
            end do
            ! radial: towards the race centre (+e_z); tangential: along the whirl (+e_y)
            worst = max(worst, abs(f(3) - fr)/hypot(fr, ft), abs(f(2) - ft)/hypot(fr, ft), abs(f(1))/hypot(fr, ft))
            if (i == 2 .and. j == 2) write (*, "(a,2f10.4,a,2f10.4,a)") "held whirl eps 0.5, psidot = wbar/2: "// &
               "film (radial, tangential) ", f(3), f(2), " N; closed form ", fr, ft, " N"
         end do
      end do
      write (*, "(a,es9.2)") "held whirl: worst deviation from the closed form over 9 states (of |F|): ", worst
      call check(worst <= 1.0e-10_wp, "held whirl: the land films' force equals the whirling short bearing's closed form")
   end subroutine test_held_whirl_film_force

   !> The report's start whirl (4.4.4; cage_step0: the Rec 9.5.1 centre, whirl velocity =
   !> angular velocity) as a circular orbit about the guiding race, without pocket contact:
   !> the centripetal force m r W**2 against the land films' radial force, and the orbit
   !> radius after a twentieth of a whirl period.
   subroutine test_report_whirl_needs_a_centripetal_force()
      type(integrator_t) :: it
      real(wp) :: r, w, y(4), f(3), need, t, t_end, r_end
      r = norm2(s0%cage%state%centre(2:3) - s0%start%equilibrium%u(2:3))
      w = s0%cage%state%whirl_speed
      y = [0.0_wp, -r, w*r, 0.0_wp]
      f = land_force_on_cage(cage, y)
      need = cage%mass*r*w**2
      call it%init(4, integrator_settings_t(h_initial=1.0e-7_wp, h_min=1.0e-14_wp, h_max=1.0e-5_wp, &
                   error_limit=1.0e-9_wp, rel_weight=0.0_wp), error, scale=[c, c, c*w, c*w])
      call check(.not. allocated(error), "report whirl: integrator set up")
      if (allocated(error)) return
      t = 0.0_wp
      t_end = 0.05_wp*2.0_wp*pi/w
      do while (t < t_end)
         call it%step(cage, t, y, error, t_limit=t_end)
         if (allocated(error)) exit
      end do
      call check(.not. allocated(error), "report whirl: integrated")
      r_end = hypot(y(1), y(2))
      write (*, "(a,f8.2,a,f8.2,a,f8.1,a,f7.2,a,f7.2,a)") "report whirl: r ", r*1e6, " um, W ", w, &
         " rad/s: needs m r W**2 = ", need, " N, the land films give ", f(3), &
         " N towards the race; orbit radius after 1/20 whirl period +", 100*(r_end/r - 1), " %"
      call check(f(3) > 0.0_wp .and. f(3) < 0.05_wp*need, "report whirl: the land films supply under 5 % of its centripetal force")
      call check(r_end > 1.01_wp*r, "report whirl: without pocket contact the cage leaves the circle (+1 %)")
   end subroutine test_report_whirl_needs_a_centripetal_force

   !> Eccentricity ratio of Ocvirk's static equilibrium of the cage's weight (bisection).
   real(wp) function ocvirk_eps()
      real(wp) :: lo, hi, w_land
      integer :: i
      w_land = cage%mass*norm2(cage%gravity)/size(cage%lands)
      lo = 0.0_wp
      hi = 0.999_wp
      do i = 1, 200
         ocvirk_eps = 0.5_wp*(lo + hi)
         if (ocvirk_load(ocvirk_eps, cage%w_race + cage%w_cage) > w_land) then
            hi = ocvirk_eps
         else
            lo = ocvirk_eps
         end if
      end do
   end function ocvirk_eps

   !> Integrate the free cage from y to t_end (s); over the last n_last whirl periods 2 pi/wbar
   !> the extremes of orbit radius r = |cage - race| and whirl rate psidot, and the largest
   !> relative difference between the film force and m r psidot**2.
   subroutine free_orbit(y, t_end, n_last, r_min, r_max, w_min, w_max, f_err, steps)
      real(wp), intent(inout) :: y(4)
      real(wp), intent(in) :: t_end, n_last
      real(wp), intent(out) :: r_min, r_max, w_min, w_max, f_err
      integer, intent(out) :: steps
      type(integrator_t) :: it
      real(wp) :: t, t_avg, r, psidot, f(3)
      r_min = huge(1.0_wp)
      r_max = 0.0_wp
      w_min = huge(1.0_wp)
      w_max = -huge(1.0_wp)
      f_err = 0.0_wp
      steps = 0
      call it%init(4, integrator_settings_t(h_initial=1.0e-7_wp, h_min=1.0e-14_wp, h_max=1.0e-5_wp, &
                   error_limit=1.0e-8_wp, rel_weight=0.0_wp), error, scale=[c, c, c*wbar, c*wbar])
      if (allocated(error)) return
      t = 0.0_wp
      t_avg = t_end - n_last*2.0_wp*pi/wbar
      do while (t < t_end)
         call it%step(cage, t, y, error, t_limit=t_end)
         if (allocated(error)) return
         if (t < t_avg) cycle
         r = hypot(y(1), y(2))
         psidot = (y(1)*y(4) - y(2)*y(3))/r**2
         f = land_force_on_cage(cage, y)
         r_min = min(r_min, r)
         r_max = max(r_max, r)
         w_min = min(w_min, psidot)
         w_max = max(w_max, psidot)
         f_err = max(f_err, abs(norm2(f + cage%mass*cage%gravity)/max(cage%mass*r*psidot**2, tiny(1.0_wp)) - 1.0_wp))
      end do
      steps = it%stats%accepted
   end subroutine free_orbit

   !> The free cage started at Ocvirk's static equilibrium with a 1 um push down stays
   !> there: over the last 10 periods of 2 pi/wbar after 0.05 s its distance from the race
   !> centre is within 1 % of c eps and its whirl rate under 1 % of wbar.
   subroutine test_static_equilibrium_is_stable()
      real(wp) :: y(4), eps, beta, r_min, r_max, w_min, w_max, f_err
      integer :: steps
      eps = ocvirk_eps()
      beta = atan(pi*sqrt(1.0_wp - eps**2)/(4.0_wp*eps)) + 0.5_wp*pi
      y = [-c*eps*cos(beta), -c*eps*sin(beta) - 1.0e-6_wp, 0.0_wp, 0.0_wp]
      call free_orbit(y, 0.05_wp, 10.0_wp, r_min, r_max, w_min, w_max, f_err, steps)
      call check(.not. allocated(error), "static equilibrium: integrated")
      if (allocated(error)) return
      write (*, "(a,f8.2,a,2f8.2,a,2f8.3,a,i0)") "free cage from Ocvirk's equilibrium (r ", c*eps*1e6, &
         " um) + 1 um: orbit ", r_min*1e6, r_max*1e6, " um, whirl ", w_min, w_max, " rad/s; steps ", steps
      call check(r_min >= 0.99_wp*c*eps .and. r_max <= 1.01_wp*c*eps, &
                 "static equilibrium: stable, the cage stays within 1 % of Ocvirk's eccentricity")
      call check(max(abs(w_min), abs(w_max)) <= 0.01_wp*wbar, "static equilibrium: no whirl")
   end subroutine test_static_equilibrium_is_stable

   !> The free cage dropped from the race centre at rest falls, overshoots its static
   !> equilibrium and ends in the half-frequency whirl (module header): over the last 2
   !> periods of 0.05 s (it reaches the whirl after about 0.04 s) the whirl rate is within 1 % of wbar, the orbit radius within 1 %
   !> (max/min) on the clearance circle, the film force within 2 % of m r psidot**2.
   subroutine test_half_frequency_whirl()
      real(wp) :: y(4), r_min, r_max, w_min, w_max, f_err
      integer :: steps
      y = 0.0_wp
      call free_orbit(y, 0.05_wp, 2.0_wp, r_min, r_max, w_min, w_max, f_err, steps)
      call check(.not. allocated(error), "half-frequency whirl: integrated")
      if (allocated(error)) then
         write (*, "(a)") error%message
         return
      end if
      write (*, "(a,2f9.2,a,f8.2,a,2f8.2,a,f7.4,a,i0)") "free cage dropped from the centre: whirl ", w_min, w_max, &
         " rad/s (wbar ", wbar, "), orbit ", r_min*1e6, r_max*1e6, " um; |F|/(m r psidot**2) - 1 <= ", f_err, &
         "; steps ", steps
      call check(w_min > 0.99_wp*wbar .and. w_max < 1.01_wp*wbar, "half-frequency whirl: whirl rate within 1 % of wbar")
      call check(r_max <= 1.01_wp*r_min, "half-frequency whirl: the cage keeps its orbit radius within 1 %")
      call check(r_min > 0.98_wp*c, "half-frequency whirl: on the clearance circle")
      call check(f_err <= 0.02_wp, "half-frequency whirl: the film force is the centripetal force m r psidot**2")
   end subroutine test_half_frequency_whirl

end program test_cage_whirl
