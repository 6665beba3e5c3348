!> The input echo as a record of plain values: what the echo writer (print_echo.f90) prints.
!>
!> The physics side fills an echo_data_t (deck inputs and derived quantities in SI units,
!> as the print shows them); the writer only formats it.  A real it does not compute yet
!> stays IEEE NaN (the default here) and prints "NaN"; an integer it does not compute is
!> INT_NOT_COMPUTED.  Field names, sizes and their order in the flat vectors of the f2py
!> wrapper are those of pyadore/printout/echo_layout.py (offsets in layout.f90).
!> Matrices are (values per printed row, printed rows): material(:, k) is printed row k.
module adore_output_echo_data
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_output_layout, only: ECHO_TEXT_LEN, ECHO_MAX_GUIDE, ECHO_MAX_QS, ELEMENT_BALL
   implicit none
   private

   public :: echo_data_t, echo_data_init

   type :: echo_data_t
      ! -- banner and kind
      character(len=ECHO_TEXT_LEN) :: bearing_type = "", run_id = "", title = ""
      integer :: element_kind = ELEMENT_BALL        !< ELEMENT_BALL or ELEMENT_ROLLER (layout.f90)
      integer :: program_mode = 0
      ! -- bearing geometry (m, deg); index 1 = outer race, 2 = inner race
      integer :: n_elements = 0
      real(wp) :: element_dia, pitch_dia, contact_angle, cur_fac(2), dia_play, end_play, fit(2), width(2)
      real(wp) :: shaft_od, shaft_id, bearing_od, housing_od
      real(wp) :: roller_len, cen_land, outer_len(2), inner_len(2), crown_rad, cor_rad(2), race_crown(2)
      ! -- cage and guide lands (guide(:, k) = dia, cls, width, position of land k)
      real(wp) :: cage_od, cage_id, cage_cone, cage_width, seg_cut, poc_cls(2), race_cls(2)
      integer :: pocket_shape = 0, n_lands = 0, n_cage_segs = 0
      integer :: n_guide = 0
      integer :: guide_land(ECHO_MAX_GUIDE) = 0, guide_type(ECHO_MAX_GUIDE) = 0
      real(wp) :: guide(4, ECHO_MAX_GUIDE)
      ! -- material (RE, outer, inner, cage, shaft, housing) x 9 properties; inertia (mass,
      !    3 moments, 3 mass-to-geo-centre offsets) x (RE, cage, outer, inner); principal angles
      real(wp) :: material(6, 9), inertia(7, 4), principal(3, 4)
      ! -- lubrication (9 columns) x (RE/race1, RE/race2, RE/cage, race/cage); lubricant name
      real(wp) :: lubrication(9, 4)
      character(len=ECHO_TEXT_LEN) :: lubricant = ""   !< blank: the LUBRICANT line is not printed
      ! -- fatigue (5 columns) and asperity/material factors (8 columns) x (outer, inner)
      real(wp) :: fatigue(5, 2), asperity(8, 2)
      character(len=ECHO_TEXT_LEN) :: weibull_slope = "", life_mod_code = ""
      ! -- initial operating conditions
      real(wp) :: room_temp, housing_temp, shaft_temp, re_temp, cage_temp
      real(wp) :: race_speed(2), race_temp(2), misalign_y(2), misalign_z(2)
      integer :: n_qs = 0
      integer :: qs_constraints(ECHO_MAX_QS) = 0, trans_constraints(6) = 0, rot_constraints(6) = 0
      real(wp) :: load_fraction, heat_trans_coeff
      integer :: print_htc = 0                       !< /= 0: print HEAT TRANS COEFF
      character(len=ECHO_TEXT_LEN) :: coolant_type = "", vary_geometry = ""
      character(len=ECHO_TEXT_LEN) :: node_base_temp = ""   !< blank: the line is not printed
      real(wp) :: applied_load(3), rel_disp(3), applied_moment(3), gravity(3), cage_position(3), cage_angle(3)
      real(wp) :: whirl_ratio, epicyclic_ratio
      ! -- scale factors and output controls
      real(wp) :: scale_length, scale_load, scale_time, step_min, step_max, step_initial, error_limit
      integer :: n_steps = 0, data_control(3) = 0, auto_plots(3) = 0, int_method = 0
   end type echo_data_t

contains

   !> An echo record with every real NaN ("not computed"), integers 0 and texts blank.
   pure function echo_data_init() result(e)
      type(echo_data_t) :: e
      real(wp) :: nan

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      e%element_dia = nan; e%pitch_dia = nan; e%contact_angle = nan; e%cur_fac = nan
      e%dia_play = nan; e%end_play = nan; e%fit = nan; e%width = nan
      e%shaft_od = nan; e%shaft_id = nan; e%bearing_od = nan; e%housing_od = nan
      e%roller_len = nan; e%cen_land = nan; e%outer_len = nan; e%inner_len = nan
      e%crown_rad = nan; e%cor_rad = nan; e%race_crown = nan
      e%cage_od = nan; e%cage_id = nan; e%cage_cone = nan; e%cage_width = nan; e%seg_cut = nan
      e%poc_cls = nan; e%race_cls = nan; e%guide = nan
      e%material = nan; e%inertia = nan; e%principal = nan; e%lubrication = nan
      e%fatigue = nan; e%asperity = nan
      e%room_temp = nan; e%housing_temp = nan; e%shaft_temp = nan; e%re_temp = nan; e%cage_temp = nan
      e%race_speed = nan; e%race_temp = nan; e%misalign_y = nan; e%misalign_z = nan
      e%load_fraction = nan; e%heat_trans_coeff = nan
      e%applied_load = nan; e%rel_disp = nan; e%applied_moment = nan; e%gravity = nan
      e%cage_position = nan; e%cage_angle = nan; e%whirl_ratio = nan; e%epicyclic_ratio = nan
      e%scale_length = nan; e%scale_load = nan; e%scale_time = nan
      e%step_min = nan; e%step_max = nan; e%step_initial = nan; e%error_limit = nan
   end function echo_data_init

end module adore_output_echo_data
