!> Print writer, part 3: the input echo (banner box and the seven echo blocks).
!>
!> Formats an echo_data_t (echo_data.f90) line for line as the golden files show it
!> (docs/print-layout.md section 3; labels and headings from layout.f90, generated
!> from pyadore/printout/echo_layout.py).  pyadore.printout.echo_writer.format_echo is the
!> Python reference; tests/test_print_writer.py proves the two byte-identical.
!> Reals are (1X,ES12.5) (NaN prints "NaN"), integers I12 / I9 / I6 / I3 as documented.
module adore_output_print_echo
   use adore_core_kinds, only: wp
   use adore_output_echo_data, only: echo_data_t
   use adore_output_print_tables, only: int_field
   use adore_output_layout, only: ELEMENT_ROLLER, ECHO_COPYRIGHT, ECHO_BOX_RULE, ECHO_BOX_TYPE_TEXT, &
      ECHO_BOX_MODE_TEXT, ECHO_BOX_RUN_TEXT, ECHO_BLOCK_TITLE, ECHO_GEOM_BALL_LABEL, ECHO_GEOM_ROLLER_LABEL, &
      ECHO_CAGE_LABEL, ECHO_GUIDE_HEAD, ECHO_MAT_HEAD, ECHO_MAT_LABEL, ECHO_MAT_COUNT, ECHO_BODY_LABEL, &
      ECHO_INERTIA_HEAD, ECHO_PRINCIPAL_HEAD, ECHO_LUB_HEAD, ECHO_LUB_LABEL, ECHO_LUBRICANT_LABEL, &
      ECHO_FAT_HEAD, ECHO_RACE_LABEL, ECHO_FAT_TEXT_LABEL, ECHO_ASP_HEAD, ECHO_OPER_RACE_HEAD, &
      ECHO_OPER_LEFT_LABEL, ECHO_OPER_RIGHT_LABEL, ECHO_LOAD_FRACTION_LABEL, ECHO_HTC_LABEL, ECHO_FLAGS_LABEL, &
      ECHO_OPER_TEXT_LABEL, ECHO_VECTOR_HEAD, ECHO_VECTOR_LABEL, ECHO_SCALE_HEAD, ECHO_SCALE_LABEL, &
      ECHO_STEP_LABEL, ECHO_CONTROL_LABEL, ECHO_SCALE_RIGHT_LABEL, ECHO_ERROR_LIMIT_LABEL
   implicit none
   private

   public :: write_echo, write_banner_box

   integer, parameter :: BUF = 512
   integer, parameter :: SKIP = 0, REAL_CELL = 1, INT_CELL = 2

   !> A line being built: text and the next free column.
   type :: line_t
      character(len=BUF) :: s = ""
      integer :: pos = 1
   end type line_t

contains

   subroutine put(unit, line)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: line

      write (unit, "(a)") trim(line)
   end subroutine put

   subroutine add(l, text)
      type(line_t), intent(inout) :: l
      character(len=*), intent(in) :: text

      l%s(l%pos:) = text
      l%pos = l%pos + len(text)
   end subroutine add

   subroutine add_real(l, x)
      type(line_t), intent(inout) :: l
      real(wp), intent(in) :: x

      write (l%s(l%pos:l%pos + 11), "(ES12.5)") x
      l%pos = l%pos + 12
   end subroutine add_real

   !> n x (1X,ES12.5)
   subroutine add_values(l, x)
      type(line_t), intent(inout) :: l
      real(wp), intent(in) :: x(:)
      integer :: k

      do k = 1, size(x)
         call add(l, " ")
         call add_real(l, x(k))
      end do
   end subroutine add_values

   subroutine add_ints(l, iv, width)
      type(line_t), intent(inout) :: l
      integer, intent(in) :: iv(:), width
      integer :: k

      do k = 1, size(iv)
         call add(l, int_field(iv(k), width))
      end do
   end subroutine add_ints

   !> Item cells (1X,A<w>,ES12.5) / (1X,A<w>,I12) / 1+w+12 blanks; w = len(labels).
   subroutine put_items(unit, labels, kinds, x, iv)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: labels(:)
      integer, intent(in) :: kinds(:), iv(:)
      real(wp), intent(in) :: x(:)
      type(line_t) :: l
      integer :: k

      do k = 1, size(labels)
         select case (kinds(k))
         case (REAL_CELL)
            call add(l, " " // labels(k))
            call add_real(l, x(k))
         case (INT_CELL)
            call add(l, " " // labels(k) // int_field(iv(k), 12))
         case default
            call add(l, repeat(" ", 1 + len(labels) + 12))
         end select
      end do
      call put(unit, l%s)
   end subroutine put_items

   !> (1X,A<w>,n(1X,ES12.5))
   subroutine put_matrix_line(unit, label, x)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: label
      real(wp), intent(in) :: x(:)
      type(line_t) :: l

      call add(l, " " // label)
      call add_values(l, x)
      call put(unit, l%s)
   end subroutine put_matrix_line

   subroutine put_rows(unit, labels, x)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: labels(:)
      real(wp), intent(in) :: x(:, :)
      integer :: k

      do k = 1, size(labels)
         call put_matrix_line(unit, labels(k), x(:, k))
      end do
   end subroutine put_rows

   subroutine put_lines(unit, lines)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: lines(:)
      integer :: k

      do k = 1, size(lines)
         call put(unit, lines(k))
      end do
   end subroutine put_lines

   subroutine put_title(unit, title)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: title

      call put(unit, title)
      call put(unit, repeat("-", len_trim(title)))
      call put(unit, "")
   end subroutine put_title

   !> (1X,A<w>,n(Iw)) integer list
   subroutine put_ints_line(unit, label, iv, width)
      integer, intent(in) :: unit, iv(:), width
      character(len=*), intent(in) :: label
      type(line_t) :: l

      call add(l, " " // label)
      call add_ints(l, iv, width)
      call put(unit, l%s)
   end subroutine put_ints_line

   !> Copyright line and the starred box
   !> ('*  Bearing Type = ',A12,'Program Mode = ',I1,5X,'Run Id = ',A,T120,'*').
   subroutine write_banner_box(unit, e)
      integer, intent(in) :: unit
      type(echo_data_t), intent(in) :: e
      character(len=120) :: box
      character(len=12) :: bearing_type

      bearing_type = e%bearing_type(1:len(bearing_type))
      box = ECHO_BOX_TYPE_TEXT // bearing_type // ECHO_BOX_MODE_TEXT // int_field(e%program_mode, 1) // &
            "     " // ECHO_BOX_RUN_TEXT // trim(e%run_id)
      box(120:120) = "*"
      call put(unit, ECHO_COPYRIGHT)
      call put(unit, "")
      call put(unit, ECHO_BOX_RULE)
      call put(unit, box)
      call put(unit, ECHO_BOX_RULE)
      call put(unit, "")
   end subroutine write_banner_box

   !> The banner box and the seven echo blocks, ending with the blank line before the first step.
   subroutine write_echo(unit, e)
      integer, intent(in) :: unit
      type(echo_data_t), intent(in) :: e
      integer, parameter :: R = REAL_CELL, I = INT_CELL
      real(wp), parameter :: z = 0.0_wp
      type(line_t) :: l
      real(wp) :: left(5), right(2, 4)
      integer :: k

      call write_banner_box(unit, e)
      ! -- bearing geometry
      call put_title(unit, ECHO_BLOCK_TITLE(1))
      if (e%element_kind == ELEMENT_ROLLER) then
         associate (g => ECHO_GEOM_ROLLER_LABEL)
            call put_items(unit, g(1:4), [I, R, R, R], [z, e%pitch_dia, e%fit(1), e%shaft_od], [e%n_elements, 0, 0, 0])
            call put_items(unit, g(5:8), [R, R, R, R], [e%element_dia, e%crown_rad, e%fit(2), e%shaft_id], [0, 0, 0, 0])
            call put_items(unit, g(9:12), [R, R, R, R], [e%roller_len, e%cor_rad(1), e%dia_play, e%bearing_od], &
                           [0, 0, 0, 0])
            call put_items(unit, g(13:16), [R, R, R, R], [e%cen_land, e%cor_rad(2), e%race_crown(1), e%housing_od], &
                           [0, 0, 0, 0])
            call put_items(unit, g(17:20), [R, R, R, R], [e%outer_len(1), e%inner_len(1), e%race_crown(2), &
                           e%width(1)], [0, 0, 0, 0])
            call put_items(unit, g(21:24), [R, R, SKIP, R], [e%outer_len(2), e%inner_len(2), z, e%width(2)], &
                           [0, 0, 0, 0])
         end associate
      else
         associate (g => ECHO_GEOM_BALL_LABEL)
            call put_items(unit, g(1:4), [I, R, R, R], [z, e%cur_fac(1), e%fit(1), e%shaft_od], [e%n_elements, 0, 0, 0])
            call put_items(unit, g(5:8), [R, R, R, R], [e%element_dia, e%cur_fac(2), e%fit(2), e%shaft_id], [0, 0, 0, 0])
            call put_items(unit, g(9:12), [R, R, R, R], [e%pitch_dia, e%dia_play, e%width(1), e%bearing_od], &
                           [0, 0, 0, 0])
            call put_items(unit, g(13:16), [R, R, R, R], [e%contact_angle, e%end_play, e%width(2), e%housing_od], &
                           [0, 0, 0, 0])
         end associate
      end if
      call put(unit, "")
      associate (g => ECHO_CAGE_LABEL)
         call put_items(unit, g(1:4), [R, R, R, R], [e%cage_od, e%cage_width, e%poc_cls(1), e%race_cls(1)], [0, 0, 0, 0])
         call put_items(unit, g(5:8), [R, R, R, R], [e%cage_id, e%seg_cut, e%poc_cls(2), e%race_cls(2)], [0, 0, 0, 0])
         call put_items(unit, g(9:12), [R, I, I, I], [e%cage_cone, z, z, z], &
                        [0, e%pocket_shape, e%n_lands, e%n_cage_segs])
      end associate
      call put(unit, "")
      call put_lines(unit, ECHO_GUIDE_HEAD)
      do k = 1, min(e%n_guide, size(e%guide_land))
         l = line_t()
         call add(l, int_field(e%guide_land(k), 9) // int_field(e%guide_type(k), 9))
         call add_values(l, e%guide(:, k))
         call put(unit, l%s)
      end do
      call put(unit, "")
      ! -- material properties
      call put_title(unit, ECHO_BLOCK_TITLE(2))
      call put(unit, ECHO_MAT_HEAD)
      do k = 1, size(ECHO_MAT_LABEL)
         call put_matrix_line(unit, ECHO_MAT_LABEL(k), e%material(1:ECHO_MAT_COUNT(k), k))
      end do
      call put(unit, "")
      ! -- inertial parameters
      call put_title(unit, ECHO_BLOCK_TITLE(3))
      call put_lines(unit, ECHO_INERTIA_HEAD)
      call put_rows(unit, ECHO_BODY_LABEL, e%inertia)
      call put(unit, "")
      call put_lines(unit, ECHO_PRINCIPAL_HEAD)
      call put_rows(unit, ECHO_BODY_LABEL, e%principal)
      call put(unit, "")
      ! -- lubrication parameters
      call put_title(unit, ECHO_BLOCK_TITLE(4))
      call put_lines(unit, ECHO_LUB_HEAD)
      call put_rows(unit, ECHO_LUB_LABEL, e%lubrication)
      call put(unit, "")
      if (len_trim(e%lubricant) > 0) then
         call put(unit, " " // ECHO_LUBRICANT_LABEL(1) // e%lubricant)
         call put(unit, "")
      end if
      ! -- fatigue parameters
      call put_title(unit, ECHO_BLOCK_TITLE(5))
      call put_lines(unit, ECHO_FAT_HEAD)
      call put_rows(unit, ECHO_RACE_LABEL, e%fatigue)
      call put(unit, "")
      call put(unit, " " // ECHO_FAT_TEXT_LABEL(1) // e%weibull_slope)
      call put(unit, " " // ECHO_FAT_TEXT_LABEL(2) // e%life_mod_code)
      call put(unit, "")
      call put_lines(unit, ECHO_ASP_HEAD)
      call put_rows(unit, ECHO_RACE_LABEL, e%asperity)
      call put(unit, "")
      ! -- initial operating conditions
      call put_title(unit, ECHO_BLOCK_TITLE(6))
      call put(unit, " " // e%title)
      call put(unit, "")
      call put(unit, ECHO_OPER_RACE_HEAD)
      left = [e%room_temp, e%housing_temp, e%shaft_temp, e%re_temp, e%cage_temp]
      right = reshape([e%race_speed, e%race_temp, e%misalign_y, e%misalign_z], [2, 4])
      do k = 1, size(right, 2)   ! outer race cell, then the inner race value
         l = line_t()
         call add(l, " " // ECHO_OPER_LEFT_LABEL(k))
         call add_real(l, left(k))
         call add(l, " " // ECHO_OPER_RIGHT_LABEL(k))
         call add_real(l, right(1, k))
         call add_values(l, right(2:2, k))
         call put(unit, l%s)
      end do
      call put_items(unit, ECHO_OPER_LEFT_LABEL(5:5), [R], left(5:5), [0])
      call put(unit, "")
      call put_ints_line(unit, ECHO_FLAGS_LABEL(1), e%qs_constraints(1:min(e%n_qs, size(e%qs_constraints))), 3)
      call put_items(unit, ECHO_LOAD_FRACTION_LABEL, [R], [e%load_fraction], [0])
      call put_ints_line(unit, ECHO_FLAGS_LABEL(2), e%trans_constraints, 3)
      call put_ints_line(unit, ECHO_FLAGS_LABEL(3), e%rot_constraints, 3)
      call put(unit, " " // ECHO_OPER_TEXT_LABEL(1) // e%coolant_type)
      if (len_trim(e%node_base_temp) > 0) call put(unit, " " // ECHO_OPER_TEXT_LABEL(2) // e%node_base_temp)
      call put(unit, " " // ECHO_OPER_TEXT_LABEL(3) // e%vary_geometry)
      if (e%print_htc /= 0) call put_items(unit, ECHO_HTC_LABEL, [R], [e%heat_trans_coeff], [0])
      call put(unit, "")
      call put(unit, ECHO_VECTOR_HEAD)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(1), e%applied_load)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(2), e%rel_disp)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(3), e%applied_moment)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(4), e%gravity)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(5), e%cage_position)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(6), e%cage_angle)
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(7), [e%whirl_ratio])
      call put_matrix_line(unit, ECHO_VECTOR_LABEL(8), [e%epicyclic_ratio])
      call put(unit, "")
      ! -- scale factors and output controls
      call put_title(unit, ECHO_BLOCK_TITLE(7))
      call put(unit, ECHO_SCALE_HEAD)
      l = line_t()
      call add(l, " " // ECHO_SCALE_LABEL(1))
      call add_real(l, e%scale_length)
      call add(l, " " // ECHO_STEP_LABEL(1))
      call add_real(l, e%step_min)
      call add(l, " " // ECHO_SCALE_RIGHT_LABEL(1) // int_field(e%n_steps, 12))
      call put(unit, l%s)
      l = line_t()
      call add(l, " " // ECHO_SCALE_LABEL(2))
      call add_real(l, e%scale_load)
      call add(l, " " // ECHO_STEP_LABEL(2))
      call add_real(l, e%step_max)
      call add(l, " " // ECHO_CONTROL_LABEL(1))
      call add_ints(l, e%data_control, 6)
      call put(unit, l%s)
      l = line_t()
      call add(l, " " // ECHO_SCALE_LABEL(3))
      call add_real(l, e%scale_time)
      call add(l, " " // ECHO_STEP_LABEL(3))
      call add_real(l, e%step_initial)
      call add(l, " " // ECHO_CONTROL_LABEL(2))
      call add_ints(l, e%auto_plots, 6)
      call put(unit, l%s)
      l = line_t()
      call add(l, " " // ECHO_ERROR_LIMIT_LABEL(1))
      call add_real(l, e%error_limit)
      call add(l, " " // ECHO_SCALE_RIGHT_LABEL(2) // int_field(e%int_method, 12))
      call put(unit, l%s)
      call put(unit, "")
   end subroutine write_echo

end module adore_output_print_echo
