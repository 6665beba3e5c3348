!> The relations between deck values that the bearing model needs (check_values): the
!> engine's cross-field checks of a deck, collected and reported all at once, each at its
!> deck field with a caret, in the words of pyadore validate.
module adore_model_checks
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   use adore_deck_deck_type, only: deck_t, deck_collect_real
   use adore_deck_problems, only: deck_field_problem
   use adore_deck_tokenizer, only: show_real, itoa
   use adore_model_bearing, only: bearing_t, BALL_BEARING
   use adore_model_scales, only: load_scale
   implicit none
   private

   public :: check_values

contains

   !> The relations between deck values the physics needs (envelope and ring geometry for
   !> the mounting, inertia and contacts; the traction curve's peak; the step sizes): input
   !> error listing every violated relation at once, each at its deck field with a caret.
   !> These are pyadore/deck/validate.py's CROSS_CHECKS, in the same words (the deck
   !> reader does not port them; pyadore validate reports them with the record checks),
   !> plus a positive wall for both races, which the mounting's thick-ring formulas divide
   !> by (inner raceway diameter > bore, outer raceway diameter < bearing OD), and a
   !> non-zero applied force (the echo's load scale; ADORE's rule without one is unknown).
   subroutine check_values(deck, b, error)
      type(deck_t), intent(in) :: deck
      type(bearing_t), intent(in) :: b
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: msg, rec5, dname, text, rec10
      integer :: n, n_max
      real(wp) :: chord, step(3)

      rec5 = merge("5A", "5B", b%bearing_type == BALL_BEARING)
      dname = merge("ball_diameter  ", "roller_diameter", b%bearing_type == BALL_BEARING)
      dname = trim(dname)
      msg = ""
      n = 0
      call less("4", "shaft_inner_diameter", b%shaft_id, "shaft_outer_diameter", b%shaft_od, &
                "a hollow shaft's bore is inside its OD")
      call less("4", "shaft_outer_diameter", b%shaft_od, "bearing_outer_diameter", b%bearing_od, &
                "bore inside the bearing OD")
      call less("4", "bearing_outer_diameter", b%bearing_od, "housing_outer_diameter", b%housing_od, &
                "bearing inside the housing")
      if (.not. (b%shaft_od < b%dm .and. b%dm < b%bearing_od)) &
         call add(rec5, "pitch_diameter", "expected between the bore (shaft_outer_diameter = "// &
                  show_real(b%shaft_od)//") and bearing_outer_diameter = "//show_real(b%bearing_od))
      if (.not. b%d < 0.5_wp*(b%bearing_od - b%shaft_od)) &
         call add(rec5, dname, "expected < (bearing_outer_diameter - shaft_outer_diameter)/2 = "// &
                  show_real(0.5_wp*(b%bearing_od - b%shaft_od))//" (the element must fit between bore and OD)")
      if (b%n_elements >= 2 .and. b%dm > 0.0_wp) then
         chord = b%dm*sin(pi/b%n_elements)
         if (.not. chord > b%d) then
            n_max = 1
            if (b%d < b%dm) n_max = max(int(pi/asin(min(b%d/b%dm, 1.0_wp))), 1)
            call add("3.2", "n_rolling_elements", "expected at most "//itoa(n_max)//": "// &
                     itoa(b%n_elements)//" elements of "//dname//" = "//show_real(b%d)// &
                     " m do not fit around pitch_diameter = "//show_real(b%dm)//" m (spacing "// &
                     show_real(chord)//" m)")
         end if
      end if
      call less("7.1", "cage_inner_diameter", b%cage_id, "cage_outer_diameter", b%cage_od, &
                "cage ID inside cage OD")
      if (b%cage_id < b%cage_od .and. .not. (b%cage_id < b%dm .and. b%dm < b%cage_od)) &
         call add(rec5, "pitch_diameter", "expected between cage_inner_diameter = "//show_real(b%cage_id)// &
                  " and cage_outer_diameter = "//show_real(b%cage_od))
      ! the races' walls, once the envelope itself is ordered (as validate.py's _race_walls)
      if (b%shaft_od < b%dm .and. b%dm < b%bearing_od .and. b%d < 0.5_wp*(b%bearing_od - b%shaft_od)) then
         if (.not. b%inner_raceway_dia > b%shaft_od) &
            call add(rec5, "pitch_diameter", "the inner race has no wall: its raceway diameter "// &
                     show_real(b%inner_raceway_dia)//" m is not above the bore (shaft_outer_diameter = "// &
                     show_real(b%shaft_od)//")")
         if (.not. b%outer_raceway_dia < b%bearing_od) &
            call add(rec5, "pitch_diameter", "the outer race has no wall: its raceway diameter "// &
                     show_real(b%outer_raceway_dia)//" m is not below bearing_outer_diameter = "// &
                     show_real(b%bearing_od))
      end if
      call deck_collect_real(deck, "2.1", "step_initial", step(1), error)
      call deck_collect_real(deck, "2.1", "step_min", step(2), error)
      call deck_collect_real(deck, "2.1", "step_max", step(3), error)
      if (allocated(error)) return
      if (.not. (step(2) <= step(1) .and. step(1) <= step(3))) &
         call add("2.1", "step_initial", "expected between step_min = "//show_real(step(2))// &
                  " and step_max = "//show_real(step(3)))
      rec10 = merge("10.1C", "10.1B", b%bearing_type == BALL_BEARING)
      associate (k => b%traction_input)
         if (k(1) > k(2) .or. k(3) > k(2)) &
            call add(rec10, "max_traction", "expected >= "//show_real(max(k(1), k(3)))// &
                     " (the maximum of the traction-slip curve)")
      end associate
      if (.not. load_scale(b%force) > 0.0_wp) &
         call add("9.1.1", "applied_force_x", "expected a non-zero applied force (applied_force_x, "// &
                  "applied_force_y and applied_force_z are all 0): the echo's LOAD scale factor, the largest "// &
                  "applied load, is undefined for an unloaded bearing (ADORE's rule for one is not known)")
      if (n > 0) call input_error(error, deck%path//": "//itoa(n)// &
                                  " problem(s) in the deck's values"//msg)

   contains

      !> Field a of record rid must be below field b (both of record rid).
      subroutine less(rid, a, va, bname, vb, what)
         character(len=*), intent(in) :: rid, a, bname, what
         real(wp), intent(in) :: va, vb
         if (va < vb) return
         call add(rid, a, "expected < "//bname//" = "//show_real(vb)//" ("//what//")")
      end subroutine less

      subroutine add(rid, field, message)
         character(len=*), intent(in) :: rid, field, message
         call deck_field_problem(deck, rid, field, message, text)
         msg = msg//new_line("a")//text
         n = n + 1
      end subroutine add

   end subroutine check_values

end module adore_model_checks
