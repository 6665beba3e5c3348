!> Flat-array unpacking shared by the f2py wrappers of both extension modules (pyadore._engine:
!> fortran/api/; pyadore._probes: fortran/api/probes/).
module adore_api_unpack
   use adore_core_kinds, only: wp
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t, ball_qs_load_t
   use adore_geometry_mounted, only: ball_groove_centres
   use adore_core_error, only: error_type, input_error
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t
   use adore_model_bearing, only: bearing_t, ROLLER_BEARING
   use adore_model_from_deck, only: read_bearing
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   implicit none
   private

   public :: adore_qs_unpack, roller_start_from_deck, contact_from_geom, traction_result

contains

   !> Build the solver's bearing and load types from the flat arrays.
   subroutine adore_qs_unpack(n, geom, load, solve_moment, b, ld)
      integer, intent(in) :: n
      real(wp), intent(in) :: geom(13), load(11)
      integer, intent(in) :: solve_moment(2)
      type(ball_qs_bearing_t), intent(out) :: b
      type(ball_qs_load_t), intent(out) :: ld
      real(wp) :: centres(2, 2)

      b%n_balls = n
      b%d = geom(1)
      b%dm = geom(2)
      b%f_o = geom(3)
      b%f_i = geom(4)
      b%ball_mass = geom(6)
      b%e_ball = geom(7)
      b%nu_ball = geom(8)
      b%e_outer = geom(9)
      b%nu_outer = geom(10)
      b%e_inner = geom(9)
      b%nu_inner = geom(10)
      b%inner_race_mass = geom(13)
      centres = ball_groove_centres(b%d, b%dm, b%f_o, b%f_i, geom(5), geom(11), geom(12))
      b%x_o = centres(1, 1)
      b%r_o = centres(2, 1)
      b%x_i = centres(1, 2)
      b%r_i = centres(2, 2)
      ld%force = load(1:3)
      ld%moment = load(4:6)
      ld%gravity = load(7:9)
      ld%misalignment = load(10:11)
      ld%solve_moment = solve_moment /= 0
   end subroutine adore_qs_unpack

   !> Read a roller deck and solve its step 0 for the roller wrappers: input errors for a
   !> non-roller deck, more rollers than nmax rows, growth_count outside 1..2.
   subroutine roller_start_from_deck(deck_path, nmax, growth_count, b, s, error, spin_method, misalignment)
      character(len=*), intent(in) :: deck_path
      integer, intent(in) :: nmax, growth_count
      type(bearing_t), intent(out) :: b
      type(roller_step0_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: spin_method
      real(wp), intent(in), optional :: misalignment(2)   !< inner race about y, z (rad)

      if (growth_count < 1 .or. growth_count > 2) then
         call input_error(error, "roller step 0: growth_count must be 1 or 2")
         return
      end if
      call read_bearing(deck_path, b, error)
      if (allocated(error)) return
      if (b%bearing_type /= ROLLER_BEARING) then
         call input_error(error, trim(deck_path)//": not a roller-bearing deck (Rec 3.2 bearing_type /= 2)")
      else if (b%n_elements > nmax) then
         call input_error(error, "roller step 0: more rollers than rows given (nmax)")
      else
         call solve_roller_step0(b, s, error, growth_count, spin_method, misalignment)
      end if
   end subroutine roller_start_from_deck

   !> Ball/race contact from the flat geometry vector of the tribology wrappers:
   !> [side (+1 outer, -1 inner), alpha (rad), rho (m), r_b (m), w_x, w_r (rad/s),
   !> Omega - w_m (rad/s), a (m), Q (N)].
   pure function contact_from_geom(g) result(c)
      real(wp), intent(in) :: g(9)
      type(ball_race_contact_t) :: c
      c%side = nint(g(1))
      c%alpha = g(2)
      c%rho = g(3)
      c%r_b = g(4)
      c%omega = g(5:6)
      c%race_speed = g(7)
      c%a = g(8)
      c%load = g(9)
   end function contact_from_geom

   !> The flat result vector of the contact traction wrappers: [force (N), coefficient,
   !> power (W), max slip, centre slip, rolling speed (m/s), spin (rad/s), spin/roll, R_x (m),
   !> n rolling points, s1, s2 (m), node slip (m/s), node coefficient] with the print node's
   !> slip and local coefficient (adore_tribology_slip's print_slip_node) given apart.
   pure function traction_result(t, node_slip, node_coefficient) result(r)
      type(contact_traction_t), intent(in) :: t
      real(wp), intent(in) :: node_slip, node_coefficient
      real(wp) :: r(15)
      r = [t%force, t%coefficient, t%power, t%max_slip, t%centre_slip, t%rolling_speed, t%spin, &
           t%spin_roll, t%rx, real(t%n_rolling, wp), t%rolling_points, node_slip, node_coefficient, &
           t%sliding]
   end function traction_result

end module adore_api_unpack
