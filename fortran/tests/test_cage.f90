!> Engine unit tests of the cage at step 0 (fortran/cage/step0.f90): independent
!> geometry checks only (a centred cage, a whirl offset, the land play); the comparison
!> with the report is in tests/test_cage_step0.py.
program test_cage
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_cage_step0, only: guide_land_t, cage_input_t, cage_step0_t, solve_cage_step0, &
                               cage_initial_state, cage_state_t, POCKET_BALL, POCKET_RECTANGULAR, &
                               GUIDE_INNER, GUIDE_OUTER
   implicit none

   integer, parameter :: n = 12
   real(wp), parameter :: d = 0.02_wp, pitch_r = 0.07_wp, c = 1.0e-3_wp
   real(wp), parameter :: cage_od = 0.15_wp, cage_id = 0.13_wp     ! R_c = 0.07

   call test_centred_cage_gives_uniform_clearances()
   call test_whirl_offset_gives_sine_clearance()
   call test_open_start_scales_the_offset()
   call test_axial_offset_turns_the_contact_angle()
   call test_land_play_and_gap()
   call test_initial_speeds()
   call test_bad_input_is_an_input_error()

   call finish("cage")

contains

   !> n elements on the pitch circle at axial x (m), radial r.
   subroutine ring_of_elements(x, r, centres, azimuth)
      real(wp), intent(in) :: x(n), r
      real(wp), intent(out) :: centres(3, n), azimuth(n)
      integer :: k
      azimuth = [(2.0_wp*pi*(k - 1)/n, k=1, n)]
      centres(1, :) = x
      centres(2, :) = -r*sin(azimuth)
      centres(3, :) = r*cos(azimuth)
   end subroutine ring_of_elements

   subroutine solve(inp, x, kind, s, lands, race_centre, growth, open_start)
      type(cage_input_t), intent(in) :: inp
      real(wp), intent(in) :: x(n)
      integer, intent(in) :: kind
      type(cage_step0_t), intent(out) :: s
      type(guide_land_t), intent(in), optional :: lands(:)
      real(wp), intent(in), optional :: race_centre(3, 2), growth(2)
      logical, intent(in), optional :: open_start
      real(wp) :: centres(3, n), azimuth(n), rc(3, 2), g(2)
      type(guide_land_t) :: none(0)
      type(error_type), allocatable :: error
      call ring_of_elements(x, pitch_r, centres, azimuth)
      rc = 0.0_wp
      g = 0.0_wp
      if (present(race_centre)) rc = race_centre
      if (present(growth)) g = growth
      if (present(lands)) then
         call solve_cage_step0(inp, centres, azimuth, 100.0_wp, d, kind, c, cage_od, cage_id, lands, rc, g, s, error, &
                               open_start)
      else
         call solve_cage_step0(inp, centres, azimuth, 100.0_wp, d, kind, c, cage_od, cage_id, none, rc, g, s, error, &
                               open_start)
      end if
      call check(.not. allocated(error), "solve_cage_step0 succeeds")
   end subroutine solve

   subroutine test_centred_cage_gives_uniform_clearances()
      type(cage_input_t) :: inp
      type(cage_step0_t) :: s
      real(wp) :: x(n)
      x = 0.0_wp
      call solve(inp, x, POCKET_BALL, s)
      call check(all(abs(s%pocket(1, :)%geo_int - 0.5_wp*c) < 1.0e-15_wp), "centred ball cage: gap c/2 in every pocket")
      call check(all(abs(s%pocket(1, :)%pos(3)) < 1.0e-15_wp), "centred: ball centres on the pocket origin radius")
      call check(all(abs(hypot(s%pocket(1, :)%pos(1), s%pocket(1, :)%pos(2)) - 0.5_wp*d) < 1.0e-15_wp), &
                 "centred: contact point D/2 from the pocket axis")
      call check(.not. any(s%pocket%in_contact), "centred: no contact")
      call solve(inp, x, POCKET_RECTANGULAR, s)
      call check(all(abs(s%pocket%geo_int - 0.5_wp*c) < 1.0e-15_wp), "centred roller cage: both walls at c/2")
   end subroutine test_centred_cage_gives_uniform_clearances

   !> A cage offset e along -z (orbital 180 deg): pocket k moves by e sin(psi) along its
   !> tangent, the gap to the near wall is c/2 - e |sin psi|, the radial coordinate
   !> r - R_c + e cos psi; the rectangular pocket's two walls c/2 -+ e sin psi.
   subroutine test_whirl_offset_gives_sine_clearance()
      type(cage_input_t) :: inp
      type(cage_step0_t) :: s
      real(wp) :: x(n), psi, e
      integer :: k
      e = 3.0e-4_wp
      inp%centre = [0.0_wp, 0.0_wp, -e]
      x = 0.0_wp
      call solve(inp, x, POCKET_BALL, s)
      call check(abs(s%state%orbital_angle - pi) < 1.0e-12_wp, "offset -z: orbital angle 180 deg")
      do k = 1, n
         psi = 2.0_wp*pi*(k - 1)/n
         call check(abs(s%pocket(1, k)%geo_int - (0.5_wp*c - e*abs(sin(psi)))) < 1.0e-12_wp, &
                    "ball gap c/2 - e |sin psi|")
         call check(abs(s%pocket(1, k)%pos(3) - (pitch_r - 0.25_wp*(cage_od + cage_id) + e*cos(psi))) < 1.0e-12_wp, &
                    "contact z = r - R_c + e cos psi")
      end do
      call check(abs(s%pocket(1, 4)%theta) < 1.0e-9_wp, "psi 90: contact on +y_p (theta 0)")
      call check(abs(s%pocket(1, 10)%theta - pi) < 1.0e-9_wp, "psi 270: contact on -y_p (theta 180)")
      call solve(inp, x, POCKET_RECTANGULAR, s)
      do k = 1, n
         psi = 2.0_wp*pi*(k - 1)/n
         call check(abs(s%pocket(1, k)%geo_int - (0.5_wp*c - e*sin(psi))) < 1.0e-12_wp, "roller end 1: c/2 - e sin psi")
         call check(abs(s%pocket(2, k)%geo_int - (0.5_wp*c + e*sin(psi))) < 1.0e-12_wp, "roller end 2: c/2 + e sin psi")
         call check(abs(s%pocket(1, k)%pos(3) + s%pocket(2, k)%pos(3)) < 1.0e-15_wp, "roller ends: z mirrored")
      end do
      ! an offset beyond the pocket clearance is an interference at psi = 90 deg
      inp%centre = [0.0_wp, 0.0_wp, -0.8_wp*c]
      call solve(inp, x, POCKET_BALL, s)
      call check(s%pocket(1, 4)%in_contact .and. s%pocket(1, 4)%geo_int < 0.0_wp, "offset > c/2: interference")
      call check(.not. s%pocket(1, 1)%in_contact, "psi 0: still clear")
   end subroutine test_whirl_offset_gives_sine_clearance

   !> open_start: an offset e = 0.8 c along -z puts the ball at psi = 90 deg e - c/2 into its
   !> pocket (gap c/2 - e |sin psi|); the start scales the offset to the largest with every gap
   !> open, c/2 / e = 0.625 (the ball at 90 deg then just touches), the whirl speed from that
   !> centre.  An offset inside the clearance is kept as it is.
   subroutine test_open_start_scales_the_offset()
      type(cage_input_t) :: inp
      type(cage_step0_t) :: s, kept
      real(wp) :: x(n)
      x = 0.0_wp
      inp%centre = [0.0_wp, 0.0_wp, -0.8_wp*c]
      call solve(inp, x, POCKET_BALL, s, open_start=.true.)
      call check(abs(s%start_scale - 0.625_wp) < 1.0e-12_wp, "open start: offset scaled by c/2 / e")
      call check(all(s%pocket(1, :)%geo_int >= 0.0_wp), "open start: every pocket gap open")
      call check(abs(s%pocket(1, 4)%geo_int) < 1.0e-14_wp, "open start: the ball at 90 deg touches")
      call check(abs(s%state%centre(3) + 0.5_wp*c) < 1.0e-14_wp, "open start: centre at -c/2")
      call check(abs(norm2(s%state%velocity) - s%state%whirl_speed*0.5_wp*c) < 1.0e-12_wp*s%state%whirl_speed, &
                 "open start: whirl velocity from the scaled radius")
      inp%centre = [0.0_wp, 0.0_wp, -0.3_wp*c]
      call solve(inp, x, POCKET_BALL, s, open_start=.true.)
      call solve(inp, x, POCKET_BALL, kept)
      call check(s%start_scale == 1.0_wp .and. all(s%state%centre == kept%state%centre), &
                 "open start: an offset inside the clearance kept")
   end subroutine test_open_start_scales_the_offset

   !> Balls axially off the cage by a cos(psi), cage centred: ball 1 touches the pocket
   !> axially (theta 270, contact x = a + D/2), the ball opposite at theta 90.
   subroutine test_axial_offset_turns_the_contact_angle()
      type(cage_input_t) :: inp
      type(cage_step0_t) :: s
      real(wp) :: x(n), a
      integer :: k
      a = 2.0e-5_wp
      x = [(a*cos(2.0_wp*pi*(k - 1)/n), k=1, n)] + 1.0e-3_wp
      call solve(inp, x, POCKET_BALL, s)
      call check(abs(s%state%centre(1) - 1.0e-3_wp) < 1.0e-15_wp, "cage axially at the mean ball position")
      call check(abs(s%pocket(1, 1)%theta - 1.5_wp*pi) < 1.0e-9_wp, "ball 1: theta 270 deg")
      call check(abs(s%pocket(1, 7)%theta - 0.5_wp*pi) < 1.0e-9_wp, "ball 7: theta 90 deg")
      call check(abs(s%pocket(1, 1)%pos(1) - (a + 0.5_wp*d)) < 1.0e-12_wp, "ball 1: contact x = a + D/2")
      call check(abs(s%pocket(1, 1)%geo_int - (0.5_wp*c - a)) < 1.0e-12_wp, "ball 1: gap c/2 - a")
      call check(all(s%pocket(1, :)%phi == 0.0_wp), "cylindrical pocket: phi 0")
   end subroutine test_axial_offset_turns_the_contact_angle

   !> Land: play = clearance - 2 growth (inner race) / + 2 growth (outer race, growth < 0
   !> = shrink); gap = play/2 - |cage - race centre|, the cage placed from the guiding race.
   subroutine test_land_play_and_gap()
      type(cage_input_t) :: inp
      type(cage_step0_t) :: s
      type(guide_land_t) :: lands(2)
      real(wp) :: x(n), rc(3, 2)
      x = 0.0_wp
      lands(1) = guide_land_t(GUIDE_INNER, 0.13_wp, 8.0e-3_wp, 0.0_wp, 1.5e-3_wp)
      lands(2) = guide_land_t(GUIDE_OUTER, 0.15_wp, 8.0e-3_wp, 0.0_wp, 1.0e-3_wp)
      rc(:, 1) = 0.0_wp
      rc(:, 2) = [0.0_wp, 0.0_wp, 1.0e-5_wp]
      inp%centre = [0.0_wp, 0.0_wp, -6.0e-4_wp]
      call solve(inp, x, POCKET_BALL, s, lands, rc, [-2.0e-6_wp, 3.0e-5_wp])
      call check(abs(s%state%centre(3) - (-5.9e-4_wp)) < 1.0e-15_wp, "cage placed from the guiding (inner) race")
      call check(abs(s%land(1)%effective_play - (1.5e-3_wp - 6.0e-5_wp)) < 1.0e-15_wp, "inner land play")
      call check(abs(s%land(1)%geo_int - (0.5_wp*(1.5e-3_wp - 6.0e-5_wp) - 6.0e-4_wp)) < 1.0e-15_wp, "inner land gap")
      call check(abs(s%land(2)%effective_play - (1.0e-3_wp - 4.0e-6_wp)) < 1.0e-15_wp, "outer land play")
      call check(abs(s%land(2)%geo_int - (0.5_wp*(1.0e-3_wp - 4.0e-6_wp) - 5.9e-4_wp)) < 1.0e-15_wp, "outer land gap")
      call check(s%land(2)%in_contact .and. .not. s%land(1)%in_contact, "outer land interferes, inner clear")
   end subroutine test_land_play_and_gap

   subroutine test_initial_speeds()
      type(cage_input_t) :: inp
      type(cage_state_t) :: st
      ! Rec 9.5.1 field 1 is not the whirl's radius (Appendix D: 2.5e-4 m against a 5e-5 m
      ! land clearance): the centre whirls about the axis on the circle through its position
      inp%whirl_radius = 3.0e-4_wp
      inp%whirl_ratio = 0.5_wp
      inp%epicyclic_ratio = 2.0_wp
      inp%centre = [0.0_wp, -1.0e-4_wp, 0.0_wp]      ! on +90 deg
      st = cage_initial_state(inp, [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, 100.0_wp)
      call check(abs(st%angular_speed - 200.0_wp) < 1.0e-12_wp, "angular = ratio x epicyclic")
      call check(abs(st%whirl_speed - 100.0_wp) < 1.0e-12_wp, "whirl = ratio x angular")
      call check(abs(st%orbital_angle - 0.5_wp*pi) < 1.0e-12_wp, "orbital angle from +z towards -y")
      ! at 90 deg the tangent of a +x rotation is -z
      call check(maxval(abs(st%velocity - [0.0_wp, 0.0_wp, -1.0e-2_wp])) < 1.0e-15_wp, &
                 "whirl velocity = whirl speed x the centre's radius (1e-4 m), whirl rate = 0.5 x angular")
   end subroutine test_initial_speeds

   subroutine test_bad_input_is_an_input_error()
      type(cage_input_t) :: inp
      type(cage_step0_t) :: s
      type(guide_land_t) :: lands(1)
      type(error_type), allocatable :: error
      real(wp) :: centres(3, n), azimuth(n), x(n), rc(3, 2)
      x = 0.0_wp
      rc = 0.0_wp
      call ring_of_elements(x, pitch_r, centres, azimuth)
      lands(1) = guide_land_t(3, 0.13_wp, 8.0e-3_wp, 0.0_wp, 1.5e-3_wp)
      call solve_cage_step0(inp, centres, azimuth, 1.0_wp, d, POCKET_BALL, c, cage_od, cage_id, lands, &
                            rc, [0.0_wp, 0.0_wp], s, error)
      call check(allocated(error), "guide type 3 refused")
      call solve_cage_step0(inp, centres, azimuth, 1.0_wp, d, POCKET_BALL, c, cage_id, cage_od, lands(1:0), &
                            rc, [0.0_wp, 0.0_wp], s, error)
      call check(allocated(error), "cage OD < ID refused")
   end subroutine test_bad_input_is_an_input_error

end program test_cage
