!> Unit tests of the mixed-film traction of traction model 3 (docs/tribology.md, "Mixed
!> films"; adore_forces_race_contact's fluid_fraction and mixed_traction): the fluid
!> fraction's limits, its continuity with its slope at both ends of the mixed band, hand
!> values of the cubic, the step when there is no band; and the force assembly at every
!> Appendix C race contact with its films placed in the band: each contact's traction is
!> the blend of its EHD and its curve traction with the fluid fraction of its own film,
!> and the blended loads still satisfy the traction's power identity.  Run by `meson
!> test` with the decks/ directory as argument.
program test_mixed_film
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t, BODY_OUTER, BODY_INNER
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_state_bearing_state, only: bearing_state_t, RACE_OUTER
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, ball_bearing_loads, ball_race_pairs
   use adore_forces_race_contact, only: MIN_EHD_FILM, fluid_fraction, fluid_contact, lubricant_film, ehd_traction
   use adore_contact_ball_race, only: ball_race_pair_t, planar_contact
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t
   use adore_start_ball_step0, only: ball_step0_t
   use adore_test_support, only: check, finish
   use adore_test_ball_fixture, only: step0_state, appendix_c_race_control, loads_power
   implicit none

   type(bearing_t) :: b
   type(mounted_geometry_t) :: g
   type(ball_step0_t) :: s0

   call test_fluid_fraction()
   call appendix_c_race_control("mixed film", b, g, s0)
   call test_blend_at_appendix_c_contacts(b, g, step0_state(b, s0))
   call finish("mixed film")

contains

   !> fluid_fraction with sigma = 0.1 um, Lambda_b = 1, Lambda_f = 2 (the defaults): 0
   !> below and at the boundary film, 1 at and above the full film; just inside either end
   !> within 3 (eps / band)**2 of the end value and its one-sided slope -> 0 (the cubic's
   !> slope vanishes at both ends); hand values of s**2 (3 - 2 s): Lambda 1.25 -> 0.15625,
   !> 1.5 -> 0.5, 1.4 (h = 0.2 um reduced by phi = 0.7) -> 0.352; monotonic over the band.
   !> Without a band (full film at or below the boundary film) the step of session 13: 1 for
   !> every film at or above the boundary film.  Without a boundary film the band starts at
   !> the 1 nm floor (MIN_EHD_FILM).
   subroutine test_fluid_fraction()
      type(bearing_t) :: bb
      real(wp), parameter :: sigma = 1.0e-7_wp, eps = 1.0e-6_wp
      real(wp) :: f, f_prev, h
      integer :: i
      logical :: monotonic

      bb%boundary_film = 1.0_wp*sigma
      bb%full_film = 2.0_wp*sigma
      call check(fluid_fraction(bb, 0.5_wp*sigma, 1.0_wp) == 0.0_wp, "fluid fraction: 0 below the boundary film")
      call check(fluid_fraction(bb, sigma, 1.0_wp) == 0.0_wp, "fluid fraction: 0 at the boundary film")
      call check(fluid_fraction(bb, 2.0_wp*sigma, 1.0_wp) == 1.0_wp, "fluid fraction: 1 at the full film")
      call check(fluid_fraction(bb, 5.0_wp*sigma, 1.0_wp) == 1.0_wp, "fluid fraction: 1 above the full film")
      call check(fluid_fraction(bb, 0.0_wp, 1.0_wp) == 0.0_wp, "fluid fraction: 0 without a film")
      ! continuity and slope at the ends (band 0.1 um; eps of the band inside)
      f = fluid_fraction(bb, sigma*(1.0_wp + eps), 1.0_wp)
      write (*, "(a,2es12.4)") "fluid fraction just above the boundary film, bound ", f, 3.0_wp*eps**2
      call check(f > 0.0_wp .and. f <= 3.0_wp*eps**2*(1.0_wp + 1.0e-6_wp), &
                 "fluid fraction: continuous at the boundary film (f within 3 eps**2 of 0)")
      ! one-sided slope df/ds = f / eps at the end against 1.5 at mid band: -> 0 with eps
      call check(f/eps <= 1.0e-5_wp, "fluid fraction: its slope at the boundary film -> 0")
      f = fluid_fraction(bb, sigma*(2.0_wp - eps), 1.0_wp)
      write (*, "(a,2es12.4)") "1 - fluid fraction just below the full film, bound ", 1.0_wp - f, 3.0_wp*eps**2
      call check(f < 1.0_wp .and. 1.0_wp - f <= 3.0_wp*eps**2*(1.0_wp + 1.0e-3_wp), &
                 "fluid fraction: continuous at the full film (1 - f within 3 eps**2)")
      call check((1.0_wp - f)/eps <= 1.0e-5_wp, "fluid fraction: its slope at the full film -> 0")
      ! hand values (s = Lambda - 1 in this band)
      call check(abs(fluid_fraction(bb, 1.25_wp*sigma, 1.0_wp) - 0.15625_wp) <= 1.0e-14_wp, &
                 "fluid fraction: Lambda 1.25 -> 0.0625 x 2.5 = 0.15625")
      call check(abs(fluid_fraction(bb, 1.5_wp*sigma, 1.0_wp) - 0.5_wp) <= 1.0e-14_wp, &
                 "fluid fraction: Lambda 1.5 (mid band) -> 0.5")
      call check(abs(fluid_fraction(bb, 2.0_wp*sigma, 0.7_wp) - 0.352_wp) <= 1.0e-14_wp, &
                 "fluid fraction: film 0.2 um reduced by phi 0.7 (Lambda 1.4) -> 0.16 x 2.2 = 0.352")
      monotonic = .true.
      f_prev = 0.0_wp
      do i = 0, 200
         h = sigma*(0.9_wp + 1.2_wp*i/200.0_wp)
         f = fluid_fraction(bb, h, 1.0_wp)
         monotonic = monotonic .and. f >= f_prev .and. f >= 0.0_wp .and. f <= 1.0_wp
         f_prev = f
      end do
      call check(monotonic, "fluid fraction: in [0, 1] and non-decreasing in the film")
      ! no band: the step at the boundary film
      bb%full_film = 0.0_wp
      call check(fluid_fraction(bb, 0.999_wp*sigma, 1.0_wp) == 0.0_wp .and. &
                 fluid_fraction(bb, 1.001_wp*sigma, 1.0_wp) == 1.0_wp, &
                 "fluid fraction: full film at or below the boundary film: a step")
      ! no boundary film: the band starts at the 1 nm floor
      bb%boundary_film = 0.0_wp
      bb%full_film = 2.0_wp*sigma
      call check(fluid_fraction(bb, 0.5_wp*MIN_EHD_FILM, 1.0_wp) == 0.0_wp, "fluid fraction: 0 below 1 nm")
      h = MIN_EHD_FILM + 0.5_wp*(2.0_wp*sigma - MIN_EHD_FILM)
      call check(abs(fluid_fraction(bb, h, 1.0_wp) - 0.5_wp) <= 1.0e-14_wp, &
                 "fluid fraction: without a boundary film the band is 1 nm ... full film")
   end subroutine test_fluid_fraction

   !> Appendix C at its step-0 state (race control), its thermally reduced films 0.45-0.53 um,
   !> with a mixed band of 0.40-0.60 um: every loaded contact is in the band.  The force
   !> assembly's traction of each contact is then f x the EHD film's traction of the
   !> contact with f times its load (fluid_contact: f Q at f p_H, the same ellipse, slip and
   !> film, computed here by ehd_traction) + (1 - f) x its curve traction
   !> (a boundary film of 1 m: every contact on the curve) for the force, both moments and
   !> the heat alike, with f = fluid_fraction of the contact's own film (lubricant_film at
   !> its kinematics): to 1e-12 of the contact's largest term.  The film's heat at f p_H is
   !> below its heat at p_H (no band, the films sheared at Q), contact by contact: the
   !> viscosity exp(alpha p).  And with ball 1 disturbed (spin, velocity), the blended
   !> traction loads' mechanical power on the balls and races is minus their heat (the power
   !> identity of test_forces' traction power, which holds for each traction and so for
   !> their blend).
   subroutine test_blend_at_appendix_c_contacts(b, g, base)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(bearing_state_t), intent(in) :: base
      type(bearing_t) :: bm, be, bc
      type(bearing_state_t) :: st
      type(ball_bearing_loads_t) :: lm, le, lc, l0
      type(error_type), allocatable :: error
      real(wp) :: f, h, phi, scale, worst, f_min, f_max, p_mech, heat
      real(wp) :: blend(4), got(4), fluid_ratio(4)
      type(ball_race_pair_t) :: pairs(2)
      type(ball_race_contact_t) :: cj, cf
      type(contact_traction_t) :: tf
      integer :: k, j, n_mixed, race

      bm = b
      bm%boundary_film = 4.0e-7_wp
      bm%full_film = 6.0e-7_wp
      be = b
      be%boundary_film = 0.0_wp
      be%full_film = 0.0_wp
      bc = b
      bc%boundary_film = 1.0_wp
      call ball_bearing_loads(bm, g, base, lm, error, cage=.false.)
      if (.not. allocated(error)) call ball_bearing_loads(be, g, base, le, error, cage=.false.)
      if (.not. allocated(error)) call ball_bearing_loads(bc, g, base, lc, error, cage=.false.)
      if (allocated(error)) then
         call check(.false., "mixed film: the loads: "//error%message)
         return
      end if
      pairs = ball_race_pairs(bm, g)
      fluid_ratio = 0.0_wp
      worst = 0.0_wp
      f_min = 1.0_wp
      f_max = 0.0_wp
      n_mixed = 0
      do k = 1, size(base%elements)
         do j = 1, 2
            associate (c => lm%contacts(j, k))
               if (.not. c%load > 0.0_wp) cycle
               call lubricant_film(bm, base%temperature, le%traction(j, k), c%ellipse%semi_major/c%ellipse%semi_minor, &
                                   c%load, c%ellipse%max_pressure, merge(BODY_OUTER, BODY_INNER, j == RACE_OUTER), &
                                   h, phi, error)
               if (allocated(error)) then
                  call check(.false., "mixed film: the contact's film: "//error%message)
                  return
               end if
               f = fluid_fraction(bm, h, phi)
            end associate
            if (f > 0.0_wp .and. f < 1.0_wp) n_mixed = n_mixed + 1
            f_min = min(f_min, f)
            f_max = max(f_max, f)
            race = merge(BODY_OUTER, BODY_INNER, j == RACE_OUTER)
            cj = planar_contact(pairs(j), lm%contacts(j, k))
            call ehd_traction(bm, base%temperature, fluid_contact(cj, f), lm%contacts(j, k)%ellipse%semi_minor, race, &
                              h*phi, tf, error)
            if (allocated(error)) then
               call check(.false., "mixed film: the film's traction: "//error%message)
               return
            end if
            cf = fluid_contact(cj, f)
            call check(cf%load == f*cj%load .and. cf%a == cj%a .and. cf%rho == cj%rho, &
                       "mixed film: the fluid's contact carries f Q on the same ellipse")
            fluid_ratio = max(fluid_ratio, [tf%force, tf%force_cos, tf%force_sin, tf%power]/quantities(le, j, k))
            blend = f*[tf%force, tf%force_cos, tf%force_sin, tf%power] + (1.0_wp - f)*quantities(lc, j, k)
            got = quantities(lm, j, k)
            scale = max(maxval(abs(quantities(le, j, k))), maxval(abs(quantities(lc, j, k))))
            worst = max(worst, maxval(abs(got - blend))/scale)
         end do
      end do
      write (*, "(a,i0,a,2f8.4,a,es10.2)") "mixed film: ", n_mixed, " contacts in the band, fluid fraction ", &
         f_min, f_max, ", worst blend error ", worst
      call check(n_mixed == 2*size(base%elements), "mixed film: every loaded Appendix C contact in the band")
      call check(worst <= 1.0e-12_wp, "mixed film: traction = f EHD of f Q + (1 - f) curve with f of the contact's film")
      write (*, "(a,es10.2)") "mixed film: largest heat of the film sheared at f p_H over its heat at p_H ", &
         fluid_ratio(4)
      ! the viscosity exp(alpha p) falls with the pressure: at f p_H the film's shear heat is
      ! below its heat at the full Hertz pressure, contact by contact
      call check(fluid_ratio(4) < 1.0_wp, "mixed film: the film sheared at f p_H heats less than at p_H")

      ! the power identity with the blend
      st = base
      st%elements(1)%omega = st%elements(1)%omega + [300.0_wp, -800.0_wp, 1200.0_wp]
      st%elements(1)%velocity = st%elements(1)%velocity + [0.01_wp, -0.02_wp, 0.015_wp]
      call ball_bearing_loads(bm, g, st, l0, error, traction=.false., cage=.false.)
      if (.not. allocated(error)) call ball_bearing_loads(bm, g, st, lm, error, cage=.false.)
      if (allocated(error)) then
         call check(.false., "mixed film: the disturbed loads: "//error%message)
         return
      end if
      p_mech = loads_power(st, lm, l0)
      heat = sum(lm%heat)
      write (*, "(a,2es12.4)") "mixed film: traction power, mechanical and -heat (W) ", p_mech, -heat
      call check(heat > 0.0_wp .and. abs(p_mech + heat) <= 1.0e-10_wp*heat, &
                 "mixed film: mechanical power of the blended traction loads = -heat")
   end subroutine test_blend_at_appendix_c_contacts

   !> Force, its cos and sin moments and the heat of contact (j, k) of loads l.
   function quantities(l, j, k) result(q)
      type(ball_bearing_loads_t), intent(in) :: l
      integer, intent(in) :: j, k
      real(wp) :: q(4)
      q = [l%traction(j, k)%force, l%traction(j, k)%force_cos, l%traction(j, k)%force_sin, l%heat(j, k)]
   end function quantities


end program test_mixed_film
