!> The relations between deck values that the bearing model needs: the one implementation
!> of the deck's cross-field checks (cross_field_checks).  The engine applies them when it
!> builds the bearing model (check_values: an input error listing every violated relation
!> at once, each at its deck field with a caret); `pyadore validate` calls the same rules
!> through the f2py wrapper adore_deck_cross_checks (fortran/api/deck.f90) and reports
!> them with its reading, range and record problems, so validate accepts exactly the decks
!> whose values the engine accepts.  Besides inconsistent values the rules hold what a
!> consistent deck asks and this engine cannot run: a bearing without applied force.
!>
!> The rules read the first field of each name in CHECK_FIELDS anywhere in the deck (as the
!> schema's record conditions see the values) and skip a relation one of whose values is
!> absent or unreadable (already reported by the reader).  CHECK_RULES describes them
!> (docs/deck-format.md).
module adore_model_checks
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_deck_deck_type, only: deck_t, deck_find_first, FIELD_INT, FIELD_REAL
   use adore_deck_problems, only: deck_field_problem
   use adore_deck_tokenizer, only: show_real, itoa
   use adore_model_clearance, only: ball_groove_diameters, roller_race_diameters
   use adore_model_scales, only: load_scale
   implicit none
   private

   public :: check_values, check_warnings, cross_field_checks, check_problem_t
   public :: N_CHECK_FIELDS, CHECK_FIELDS, N_CHECK_RULES, CHECK_RULES

   !> The deck fields the rules read, by name; v(k) / have(k) of cross_field_checks is field k.
   integer, parameter :: N_CHECK_FIELDS = 31
   character(len=*), parameter :: CHECK_FIELDS(N_CHECK_FIELDS) = [character(len=27) :: &
      "shaft_inner_diameter", "shaft_outer_diameter", "bearing_outer_diameter", "housing_outer_diameter", &
      "pitch_diameter", "ball_diameter", "roller_diameter", "n_rolling_elements", "cage_inner_diameter", &
      "cage_outer_diameter", "outer_curvature_factor", "inner_curvature_factor", "free_contact_angle", &
      "diametral_play", "step_min", "step_initial", "step_max", "traction_at_zero_slip", "max_traction", &
      "traction_at_infinite_slip", "applied_force_x", "applied_force_y", "applied_force_z", &
      "error_limit", "room_temperature", "housing_temperature", "shaft_temperature", &
      "rolling_element_temperature", "outer_race_temperature", "inner_race_temperature", "cage_whirl_radius"]
   integer, parameter :: SHAFT_ID = 1, SHAFT_OD = 2, BEARING_OD = 3, HOUSING_OD = 4, PITCH = 5, BALL_D = 6, &
                         ROLLER_D = 7, N_ELEMENTS = 8, CAGE_ID = 9, CAGE_OD = 10, F_OUTER = 11, F_INNER = 12, &
                         ALPHA0 = 13, DIA_PLAY = 14, STEP_MIN = 15, STEP_INITIAL = 16, STEP_MAX = 17, &
                         K_ZERO = 18, K_MAX = 19, K_INFINITE = 20, FORCE_X = 21, FORCE_Y = 22, FORCE_Z = 23, &
                         ERROR_LIMIT = 24, ROOM_T = 25, LAST_T = 30, WHIRL_R = 31

   !> The plausible range of a temperature (K): the lubricant and material data of the
   !> engine (the oils of tribology/film.f90, steels and ceramics) are those of bearings
   !> running between these bounds.
   real(wp), parameter :: PLAUSIBLE_T_MIN = 200.0_wp, PLAUSIBLE_T_MAX = 600.0_wp
   !> The largest plausible step_max (dimensionless time; the appendix decks use 0.3) and
   !> error_limit (the appendix decks use 1e-4).
   real(wp), parameter :: PLAUSIBLE_STEP_MAX = 10.0_wp, PLAUSIBLE_ERROR_LIMIT = 1.0e-2_wp

   !> What each rule requires, in the order the rules are applied.
   integer, parameter :: N_CHECK_RULES = 16
   character(len=*), parameter :: CHECK_RULES(N_CHECK_RULES) = [character(len=190) :: &
      "shaft_inner_diameter < shaft_outer_diameter: a hollow shaft's bore is inside its OD", &
      "shaft_outer_diameter < bearing_outer_diameter: bore inside the bearing OD", &
      "bearing_outer_diameter < housing_outer_diameter: bearing inside the housing", &
      "shaft_outer_diameter (bore) < pitch_diameter < bearing_outer_diameter.", &
      "element diameter < (bearing_outer_diameter - shaft_outer_diameter) / 2.", &
      "n elements of diameter D fit around the pitch circle: pitch_diameter * sin(pi/n) > D.", &
      "cage_inner_diameter < cage_outer_diameter: cage ID inside cage OD", &
      "cage_inner_diameter < pitch_diameter < cage_outer_diameter (the cage carries the elements).", &
      "inner raceway diameter > shaft_outer_diameter and outer raceway diameter < bearing_outer_diameter: "// &
      "both races have a wall (once bore < pitch < OD and the element fits radially).", &
      "step_min <= step_initial <= step_max.", &
      "max_traction > traction_at_zero_slip and > traction_at_infinite_slip (the traction-slip curve "// &
      "has its maximum at a positive slip).", &
      "applied_force_x, applied_force_y, applied_force_z not all 0: the echo's load scale (the largest "// &
      "applied load) is undefined for an unloaded bearing; ADORE's rule for one is not known.", &
      "warning: room_temperature and the Rec 2.7 temperatures between 200 K and 600 K (the lubricant and "// &
      "material data hold there).", &
      "warning: step_max <= 10 (dimensionless time; the appendix decks use 0.3).", &
      "warning: error_limit <= 1e-2 (the appendix decks use 1e-4).", &
      "warning: cage_whirl_radius below the cage's radial thickness (cage_outer_diameter - "// &
      "cage_inner_diameter) / 2 (report 4.4.4: a whirl inside the cage's clearances)."]

   !> One violated relation: the field it is reported at (index into CHECK_FIELDS) and why.
   type :: check_problem_t
      integer :: field = 0
      character(len=:), allocatable :: message
      logical :: warning = .false.   !< a legal but implausible value: reported, the run goes on
   end type check_problem_t

contains

   !> Apply every rule to the values v (SI units of the deck schema; integers as reals) of
   !> the fields CHECK_FIELDS, have(k) false where field k is absent or unreadable; the
   !> violated relations in rule order.  No state; nothing divides by a bad value.
   subroutine cross_field_checks(v, have, problems)
      real(wp), intent(in) :: v(N_CHECK_FIELDS)
      logical, intent(in) :: have(N_CHECK_FIELDS)
      type(check_problem_t), allocatable, intent(out) :: problems(:)
      character(len=:), allocatable :: dname
      integer :: n, n_max, de, k
      real(wp) :: chord, d_outer, d_inner, worst

      allocate (problems(0))
      de = merge(BALL_D, ROLLER_D, have(BALL_D))
      dname = trim(CHECK_FIELDS(de))
      call less(SHAFT_ID, SHAFT_OD, "a hollow shaft's bore is inside its OD")
      call less(SHAFT_OD, BEARING_OD, "bore inside the bearing OD")
      call less(BEARING_OD, HOUSING_OD, "bearing inside the housing")
      if (all(have([PITCH, SHAFT_OD, BEARING_OD]))) then
         if (.not. (v(SHAFT_OD) < v(PITCH) .and. v(PITCH) < v(BEARING_OD))) &
            call add(PITCH, "expected between the bore (shaft_outer_diameter = "// &
                     show_real(v(SHAFT_OD))//") and bearing_outer_diameter = "//show_real(v(BEARING_OD)))
      end if
      if (all(have([de, SHAFT_OD, BEARING_OD]))) then
         if (.not. v(de) < 0.5_wp*(v(BEARING_OD) - v(SHAFT_OD))) &
            call add(de, "expected < (bearing_outer_diameter - shaft_outer_diameter)/2 = "// &
                     show_real(0.5_wp*(v(BEARING_OD) - v(SHAFT_OD)))//" (the element must fit between bore and OD)")
      end if
      if (all(have([de, PITCH, N_ELEMENTS]))) then
         n = nint(v(N_ELEMENTS))
         if (n >= 2 .and. v(PITCH) > 0.0_wp) then
            chord = v(PITCH)*sin(pi/n)
            if (.not. chord > v(de)) then
               n_max = 1
               if (v(de) < v(PITCH)) n_max = max(int(pi/asin(min(v(de)/v(PITCH), 1.0_wp))), 1)
               call add(N_ELEMENTS, "expected at most "//itoa(n_max)//": "//itoa(n)//" elements of "//dname// &
                        " = "//show_real(v(de))//" m do not fit around pitch_diameter = "//show_real(v(PITCH))// &
                        " m (spacing "//show_real(chord)//" m)")
            end if
         end if
      end if
      call less(CAGE_ID, CAGE_OD, "cage ID inside cage OD")
      if (all(have([CAGE_ID, CAGE_OD, PITCH]))) then
         if (v(CAGE_ID) < v(CAGE_OD) .and. .not. (v(CAGE_ID) < v(PITCH) .and. v(PITCH) < v(CAGE_OD))) &
            call add(PITCH, "expected between cage_inner_diameter = "//show_real(v(CAGE_ID))// &
                     " and cage_outer_diameter = "//show_real(v(CAGE_OD)))
      end if
      call race_walls()
      if (all(have([STEP_MIN, STEP_INITIAL, STEP_MAX]))) then
         if (.not. (v(STEP_MIN) <= v(STEP_INITIAL) .and. v(STEP_INITIAL) <= v(STEP_MAX))) &
            call add(STEP_INITIAL, "expected between step_min = "//show_real(v(STEP_MIN))// &
                     " and step_max = "//show_real(v(STEP_MAX)))
      end if
      if (have(K_MAX)) then
         worst = -huge(1.0_wp)
         if (have(K_ZERO)) worst = v(K_ZERO)
         if (have(K_INFINITE)) worst = max(worst, v(K_INFINITE))
         if (.not. v(K_MAX) > worst) &
            call add(K_MAX, "expected > "//show_real(worst)//" (the maximum of the traction-slip curve, "// &
                     "at a positive slip)")
      end if
      if (all(have([FORCE_X, FORCE_Y, FORCE_Z]))) then
         if (.not. load_scale(v([FORCE_X, FORCE_Y, FORCE_Z])) > 0.0_wp) &
            call add(FORCE_X, "expected a non-zero applied force (applied_force_x, applied_force_y and "// &
                     "applied_force_z are all 0): the echo's LOAD scale factor, the largest applied load, is "// &
                     "undefined for an unloaded bearing (ADORE's rule for one is not known)")
      end if
      ! warnings: legal values no bearing runs at
      do k = ROOM_T, LAST_T
         if (.not. have(k)) cycle
         if (v(k) < PLAUSIBLE_T_MIN .or. v(k) > PLAUSIBLE_T_MAX) &
            call warn(k, "implausible temperature: outside "//show_real(PLAUSIBLE_T_MIN)//" to "// &
                      show_real(PLAUSIBLE_T_MAX)//" K, where the lubricant and material data hold")
      end do
      if (have(STEP_MAX)) then
         if (v(STEP_MAX) > PLAUSIBLE_STEP_MAX) &
            call warn(STEP_MAX, "implausible: a largest step above "//show_real(PLAUSIBLE_STEP_MAX)// &
                      " (dimensionless time; the appendix decks use 0.3) lets the error control alone limit the step")
      end if
      if (have(ERROR_LIMIT)) then
         if (v(ERROR_LIMIT) > PLAUSIBLE_ERROR_LIMIT) &
            call warn(ERROR_LIMIT, "implausible: an error limit above "//show_real(PLAUSIBLE_ERROR_LIMIT)// &
                      " (the appendix decks use 1e-4) lets the integration error, not the physics, shape the motion")
      end if
      if (all(have([WHIRL_R, CAGE_ID, CAGE_OD]))) then
         if (v(CAGE_OD) > v(CAGE_ID) .and. v(WHIRL_R) >= 0.5_wp*(v(CAGE_OD) - v(CAGE_ID))) &
            call warn(WHIRL_R, "implausible: the prescribed cage whirl orbit (report 4.4.4) is not below the "// &
                      "cage's radial thickness (cage_outer_diameter - cage_inner_diameter)/2 = "// &
                      show_real(0.5_wp*(v(CAGE_OD) - v(CAGE_ID)))//" m; a whirl lies inside the cage's clearances")
      end if

   contains

      !> Field a must be below field b; reported at a.
      subroutine less(a, b, what)
         integer, intent(in) :: a, b
         character(len=*), intent(in) :: what
         if (.not. (have(a) .and. have(b))) return
         if (v(a) < v(b)) return
         call add(a, "expected < "//trim(CHECK_FIELDS(b))//" = "//show_real(v(b))//" ("//what//")")
      end subroutine less

      !> Both races have a wall (the mounting's thick-ring formulas divide by its thickness),
      !> once the envelope itself is ordered; raceway diameters of adore_model_clearance.
      subroutine race_walls()
         if (.not. all(have([de, PITCH, SHAFT_OD, BEARING_OD]))) return
         if (.not. (v(SHAFT_OD) < v(PITCH) .and. v(PITCH) < v(BEARING_OD) .and. &
                    v(de) < 0.5_wp*(v(BEARING_OD) - v(SHAFT_OD)))) return
         if (de == BALL_D) then
            if (.not. all(have([F_OUTER, F_INNER, ALPHA0]))) return
            call ball_groove_diameters(v(PITCH), v(de), v(F_OUTER), v(F_INNER), v(ALPHA0)*pi/180.0_wp, &
                                       d_outer, d_inner)
         else
            if (.not. have(DIA_PLAY)) return
            call roller_race_diameters(v(PITCH), v(de), v(DIA_PLAY), d_outer, d_inner)
         end if
         if (.not. d_inner > v(SHAFT_OD)) &
            call add(PITCH, "the inner race has no wall: its raceway diameter "//show_real(d_inner)// &
                     " m is not above the bore (shaft_outer_diameter = "//show_real(v(SHAFT_OD))//")")
         if (.not. d_outer < v(BEARING_OD)) &
            call add(PITCH, "the outer race has no wall: its raceway diameter "//show_real(d_outer)// &
                     " m is not below bearing_outer_diameter = "//show_real(v(BEARING_OD)))
      end subroutine race_walls

      subroutine add(field, message)
         integer, intent(in) :: field
         character(len=*), intent(in) :: message
         call append(problems, field, message)
      end subroutine add

      subroutine warn(field, message)
         integer, intent(in) :: field
         character(len=*), intent(in) :: message
         call append(problems, field, message)
         problems(size(problems))%warning = .true.
      end subroutine warn

   end subroutine cross_field_checks

   !> Append the problem (field, message) to problems.
   subroutine append(problems, field, message)
      type(check_problem_t), allocatable, intent(inout) :: problems(:)
      integer, intent(in) :: field
      character(len=*), intent(in) :: message
      type(check_problem_t) :: p
      p%field = field
      p%message = message
      problems = [problems, p]
   end subroutine append

   !> The cross-field checks of a read deck: input error listing every violated relation at
   !> once, each at its deck field with a caret (adore_deck_problems' form), headed
   !> "<path>: <n> problem(s) in the deck's values".  Warnings (implausible values) do not
   !> make an error: check_warnings reports them.
   subroutine check_values(deck, error)
      type(deck_t), intent(in) :: deck
      type(error_type), allocatable, intent(out) :: error
      type(check_problem_t), allocatable :: problems(:)
      character(len=:), allocatable :: msg, text
      integer :: k, r, f, n

      call deck_problems(deck, problems)
      n = count(.not. problems%warning)
      if (n == 0) return
      msg = ""
      do k = 1, size(problems)
         if (problems(k)%warning) cycle
         call deck_find_first(deck, trim(CHECK_FIELDS(problems(k)%field)), r, f)
         call deck_field_problem(deck, deck%records(r)%rid, trim(CHECK_FIELDS(problems(k)%field)), &
                                 problems(k)%message, text)
         msg = msg//new_line("a")//text
      end do
      call input_error(error, deck%path//": "//itoa(n)//" problem(s) in the deck's values"//msg)
   end subroutine check_values

   !> The warnings of the cross-field checks (legal but implausible values) of a read deck,
   !> one line each ("<path>:<line>:<col>  Rec <id>  field <name> = <value>: <message>",
   !> without the source line), joined by "; "; empty when there is none.
   subroutine check_warnings(deck, warnings)
      type(deck_t), intent(in) :: deck
      character(len=:), allocatable, intent(out) :: warnings
      type(check_problem_t), allocatable :: problems(:)
      character(len=:), allocatable :: text
      integer :: k, r, f

      warnings = ""
      call deck_problems(deck, problems)
      do k = 1, size(problems)
         if (.not. problems(k)%warning) cycle
         call deck_find_first(deck, trim(CHECK_FIELDS(problems(k)%field)), r, f)
         call deck_field_problem(deck, deck%records(r)%rid, trim(CHECK_FIELDS(problems(k)%field)), &
                                 problems(k)%message, text)
         if (index(text, new_line("a")) > 0) text = text(1:index(text, new_line("a")) - 1)
         if (len(warnings) > 0) warnings = warnings//"; "
         warnings = warnings//text
      end do
   end subroutine check_warnings

   !> The cross-field rules applied to the first field of each name of CHECK_FIELDS in deck.
   subroutine deck_problems(deck, problems)
      type(deck_t), intent(in) :: deck
      type(check_problem_t), allocatable, intent(out) :: problems(:)
      real(wp) :: v(N_CHECK_FIELDS)
      logical :: have(N_CHECK_FIELDS)
      integer :: k, r, f

      v = 0.0_wp
      have = .false.
      do k = 1, N_CHECK_FIELDS
         call deck_find_first(deck, trim(CHECK_FIELDS(k)), r, f)
         if (r == 0) cycle
         associate (fv => deck%records(r)%fields(f))
            have(k) = fv%valid .and. (fv%kind == FIELD_INT .or. fv%kind == FIELD_REAL)
            if (fv%kind == FIELD_INT) v(k) = real(fv%int_value, wp)
            if (fv%kind == FIELD_REAL) v(k) = fv%real_value
         end associate
      end do
      call cross_field_checks(v, have, problems)
   end subroutine deck_problems

end module adore_model_checks
