!> Print writer, part 2: the printed steps (step header, the tables of sections 1, 1a, 2,
!> 3 and 4), the termination line and the run statistics.
!>
!> Writers only format: they take a unit and plain values and compute nothing.  Layout:
!> docs/print-layout.md, as data in layout.f90 (generated from
!> pyadore/printout/layout.py); pyadore.printout.writer is the Python reference, and
!> tests/test_print_writer.py proves the two byte-identical on the golden files.
!>
!> Numbers use the documented edit descriptors (1X,ES10.3 in tables), so a value too
!> wide prints asterisks and IEEE NaN - a value the engine does not compute - prints
!> "NaN" right-aligned, as gfortran writes it.  An integer equal to INT_NOT_COMPUTED
!> prints "NaN" right-aligned too.  Lines are written without trailing blanks.
module adore_output_print_tables
   use adore_core_kinds, only: wp
   use adore_output_layout, only: INT_NOT_COMPUTED, NOT_COMPUTED_TOKEN, STEP_HEADING, STEP_UNITS, STEP_RULE, &
      SECTION_TITLE_1, SECTION_TITLE_1A, SECTION_TITLE_2, SECTION_TITLE_3, SECTION_TITLE_4, &
      TABLE_RE_CONTACT, TABLE_RE_MOTION, TABLE_RE_TRACTION, TABLE_RE_THERMAL, TABLE_SLICES, TABLE_RE_CAGE, &
      TABLE_RE_CAGE_ROLLER, TABLE_RACE_CAGE, TABLE_BODIES, TABLE_LOADS, TABLE_ACCELERATIONS, TABLE_SUMMARY, &
      N_TABLES, LABEL_RE_END, TABLE_NCOL, TABLE_NCODE, TABLE_LABEL_KIND, TABLE_LABEL_WIDTH, &
      TABLE_HEAD_FIRST, TABLE_HEAD_COUNT, HEADING_LINE, BODY_ROW, LOAD_ROW, ACC_ROW, N_PERFORMANCE, &
      RIGHT_LABEL, LOADS_RIGHT_COL, ACC_RIGHT_COL, LOADS_RIGHT_LINE, LOADS_RIGHT_CELL, ACC_RIGHT_LINE, &
      ACC_RIGHT_CELL, TERMINATION_STEP_TEXT, TERMINATION_TIME_TEXT, STATISTICS_TITLE, STATISTICS_LABEL
   implicit none
   private

   public :: write_step_header, write_section_title, write_table, write_text_table, write_section3
   public :: write_step, write_termination, write_statistics, int_field, table_shape_ok

   !> Longest line a writer builds (a printed line is at most 132 characters; the step
   !> header carries the run id, which may be longer).
   integer, parameter :: BUF = 512

contains

   !> ``Iw`` as Fortran writes it (asterisks when too wide), "NaN" for INT_NOT_COMPUTED.
   pure function int_field(value, width) result(s)
      integer, intent(in) :: value, width
      character(len=width) :: s
      character(len=16) :: fmt

      if (value == INT_NOT_COMPUTED) then
         if (width < len(NOT_COMPUTED_TOKEN)) then
            s = repeat("*", width)
         else
            s = repeat(" ", width - len(NOT_COMPUTED_TOKEN)) // NOT_COMPUTED_TOKEN
         end if
         return
      end if
      write (fmt, "('(I', I0, ')')") width
      write (s, fmt) value
   end function int_field

   subroutine put(unit, line)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: line

      write (unit, "(a)") trim(line)
   end subroutine put

   !> The step header block: headings, (I6,2(1X,ES10.3),2(5X,ES10.3),2X,A), rule, blank.
   !> header = [tau, time (s), outer race rotation (rev), inner race rotation (rev)].
   subroutine write_step_header(unit, step, header, run_id)
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: header(4)
      character(len=*), intent(in) :: run_id
      character(len=BUF) :: line

      call put(unit, STEP_HEADING)
      call put(unit, STEP_UNITS)
      line = int_field(step, 6)
      write (line(7:), "(2(1X,ES10.3),2(5X,ES10.3),2X,A)") header, trim(run_id)
      call put(unit, line)
      call put(unit, STEP_RULE)
      call put(unit, "")
   end subroutine write_step_header

   !> A section title and a blank line; section = "1", "1a", "2", "3" or "4"
   !> ("1a" is followed by the roller number, I0).
   subroutine write_section_title(unit, section, roller)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: section
      integer, intent(in), optional :: roller
      character(len=BUF) :: line

      select case (section)
      case ("1")
         line = SECTION_TITLE_1
      case ("1a")
         line = SECTION_TITLE_1A
         if (present(roller)) write (line(len(SECTION_TITLE_1A) + 1:), "(1X,I0)") roller
      case ("2")
         line = SECTION_TITLE_2
      case ("3")
         line = SECTION_TITLE_3
      case default
         line = SECTION_TITLE_4
      end select
      call put(unit, line)
      call put(unit, "")
   end subroutine write_section_title

   !> .true. when values(nrow, ncol) and codes(nrow, ncode) fit table ``table``.
   pure logical function table_shape_ok(table, nrow_values, ncol, ncode) result(ok)
      integer, intent(in) :: table, nrow_values, ncol, ncode

      ok = table >= 1 .and. table <= N_TABLES .and. nrow_values >= 0
      if (ok) ok = ncol == TABLE_NCOL(table) .and. ncode == TABLE_NCODE(table)
   end function table_shape_ok

   subroutine write_headings(unit, table)
      integer, intent(in) :: unit, table
      integer :: k

      do k = TABLE_HEAD_FIRST(table), TABLE_HEAD_FIRST(table) + TABLE_HEAD_COUNT(table) - 1
         call put(unit, HEADING_LINE(k))
      end do
   end subroutine write_headings

   !> Values part of a row: n x (1X,ES10.3) from column ``pos``.
   subroutine put_values(line, pos, values)
      character(len=*), intent(inout) :: line
      integer, intent(in) :: pos
      real(wp), intent(in) :: values(:)

      if (size(values) > 0) write (line(pos:), "(*(1X,ES10.3))") values
   end subroutine put_values

   !> A table with integer row labels (element, slice, land, step; roller tables: element
   !> and end): heading lines, then one row per label - label (I5/I6, or I5,I3), the I3
   !> code columns ``codes(nrow, ncode)`` and the values ``values(nrow, ncol)`` (1X,ES10.3).
   !> No blank line after the rows (as pyadore.printout.writer.format_table).
   subroutine write_table(unit, table, labels, values, codes, ends)
      integer, intent(in) :: unit, table
      integer, intent(in) :: labels(:)
      real(wp), intent(in) :: values(:, :)
      integer, intent(in), optional :: codes(:, :)
      integer, intent(in), optional :: ends(:)
      character(len=BUF) :: line
      integer :: i, k, pos, w

      call write_headings(unit, table)
      w = TABLE_LABEL_WIDTH(table)
      do i = 1, size(labels)
         line = int_field(labels(i), w)
         pos = w + 1
         if (TABLE_LABEL_KIND(table) == LABEL_RE_END) then
            if (present(ends)) line(pos:pos + 2) = int_field(ends(i), 3)
            pos = pos + 3
         end if
         if (present(codes)) then
            do k = 1, TABLE_NCODE(table)
               line(pos:pos + 2) = int_field(codes(i, k), 3)
               pos = pos + 3
            end do
         end if
         call put_values(line, pos, values(i, :))
         call put(unit, line)
      end do
   end subroutine write_table

   !> A table with text row labels (A5 bodies, A10 section 3 rows): headings and rows.
   subroutine write_text_table(unit, table, labels, values)
      integer, intent(in) :: unit, table
      character(len=*), intent(in) :: labels(:)
      real(wp), intent(in) :: values(:, :)
      character(len=BUF) :: line
      integer :: i, w

      call write_headings(unit, table)
      w = TABLE_LABEL_WIDTH(table)
      do i = 1, size(labels)
         line = labels(i)
         line(w + 1:) = ""
         call put_values(line, w + 1, values(i, :))
         call put(unit, line)
      end do
   end subroutine write_text_table

   !> One section 3 block: heading lines and rows with the labelled cells (T<col>,A30,1X,ES10.3).
   subroutine section3_block(unit, table, rows, values, col, cell_line, cell_index, performance)
      integer, intent(in) :: unit, table, col
      character(len=*), intent(in) :: rows(:)
      real(wp), intent(in) :: values(:, :), performance(:)
      integer, intent(in) :: cell_line(:), cell_index(:)
      character(len=BUF) :: line
      integer :: k, nh, c, w

      nh = TABLE_HEAD_COUNT(table)
      w = TABLE_LABEL_WIDTH(table)
      do k = 1, nh + size(rows)
         if (k <= nh) then
            line = HEADING_LINE(TABLE_HEAD_FIRST(table) + k - 1)
         else
            line = rows(k - nh)
            line(w + 1:) = ""
            call put_values(line, w + 1, values(k - nh, :))
         end if
         do c = 1, size(cell_line)
            if (cell_line(c) == k) write (line(col:), "(A30,1X,ES10.3)") RIGHT_LABEL(cell_index(c)), &
               performance(cell_index(c))
         end do
         call put(unit, line)
      end do
      call put(unit, "")
   end subroutine section3_block

   !> Section 3 (after its title): loads(5, 6) forces/moments of Cage, Int ORace, Int IRace,
   !> Ext ORace, Ext IRace; accelerations(3, 7) of Cage, ORace, IRace; performance(14) the
   !> labelled cells in the order of RIGHT_LABEL (pyadore layout PERFORMANCE_COLUMNS).
   subroutine write_section3(unit, loads, accelerations, performance)
      integer, intent(in) :: unit
      real(wp), intent(in) :: loads(:, :), accelerations(:, :), performance(N_PERFORMANCE)

      call section3_block(unit, TABLE_LOADS, LOAD_ROW, loads, LOADS_RIGHT_COL, LOADS_RIGHT_LINE, &
                          LOADS_RIGHT_CELL, performance)
      call section3_block(unit, TABLE_ACCELERATIONS, ACC_ROW, accelerations, ACC_RIGHT_COL, ACC_RIGHT_LINE, &
                          ACC_RIGHT_CELL, performance)
   end subroutine write_section3

   !> One printed step, every line of pyadore.printout.writer.format_step:
   !> section 1 (re_no(n), re_contact/re_motion/re_traction/re_thermal(n, 11)), section 1a
   !> per printed roller (slice_roller(m); slice_no(s); slices(s, 10, m)), section 2
   !> (RE/cage rows cage_el, cage_end (rollers only), cage_code, re_cage(:, 8); roller /= 0
   !> selects the roller variant; race/cage rows land_no, land_code, race_cage(:, 7);
   !> bodies(3, 11) of Cage, ORace, IRace), section 3 and section 4 (sum_step, summary(:, 10)).
   subroutine write_step(unit, step, header, run_id, re_no, re_contact, re_motion, re_traction, re_thermal, &
                         slice_roller, slice_no, slices, roller, cage_el, cage_end, cage_code, re_cage, &
                         land_no, land_code, race_cage, bodies, loads, accelerations, performance, &
                         sum_step, summary)
      integer, intent(in) :: unit, step
      real(wp), intent(in) :: header(4)
      character(len=*), intent(in) :: run_id
      integer, intent(in) :: re_no(:)
      real(wp), intent(in) :: re_contact(:, :), re_motion(:, :), re_traction(:, :), re_thermal(:, :)
      integer, intent(in) :: slice_roller(:), slice_no(:)
      real(wp), intent(in) :: slices(:, :, :)
      integer, intent(in) :: roller
      integer, intent(in) :: cage_el(:), cage_end(:), cage_code(:)
      real(wp), intent(in) :: re_cage(:, :)
      integer, intent(in) :: land_no(:), land_code(:)
      real(wp), intent(in) :: race_cage(:, :), bodies(:, :), loads(:, :), accelerations(:, :)
      real(wp), intent(in) :: performance(N_PERFORMANCE)
      integer, intent(in) :: sum_step(:)
      real(wp), intent(in) :: summary(:, :)
      integer :: k

      call write_step_header(unit, step, header, run_id)
      call write_section_title(unit, "1")
      call write_table(unit, TABLE_RE_CONTACT, re_no, re_contact)
      call put(unit, "")
      call write_table(unit, TABLE_RE_MOTION, re_no, re_motion)
      call put(unit, "")
      call write_table(unit, TABLE_RE_TRACTION, re_no, re_traction)
      call put(unit, "")
      call write_table(unit, TABLE_RE_THERMAL, re_no, re_thermal)
      call put(unit, "")
      do k = 1, size(slice_roller)
         call write_step_header(unit, step, header, run_id)
         call write_section_title(unit, "1a", slice_roller(k))
         call write_table(unit, TABLE_SLICES, slice_no, slices(:, :, k))
         call put(unit, "")
      end do
      call write_step_header(unit, step, header, run_id)
      call write_section_title(unit, "2")
      if (roller /= 0) then
         call write_table(unit, TABLE_RE_CAGE_ROLLER, cage_el, re_cage, reshape(cage_code, [size(cage_code), 1]), &
                          cage_end)
      else
         call write_table(unit, TABLE_RE_CAGE, cage_el, re_cage, reshape(cage_code, [size(cage_code), 1]))
      end if
      call put(unit, "")
      call write_table(unit, TABLE_RACE_CAGE, land_no, race_cage, reshape(land_code, [size(land_code), 1]))
      call put(unit, "")
      call write_text_table(unit, TABLE_BODIES, BODY_ROW, bodies)
      call put(unit, "")
      call write_step_header(unit, step, header, run_id)
      call write_section_title(unit, "3")
      call write_section3(unit, loads, accelerations, performance)
      call write_section_title(unit, "4")
      call write_table(unit, TABLE_SUMMARY, sum_step, summary)
      call put(unit, "")
   end subroutine write_step

   !> (5X,'Normal termination: Last Step Number =',I8,5X,'Final Time =',1X,ES10.4)
   subroutine write_termination(unit, last_step, final_time)
      integer, intent(in) :: unit, last_step
      real(wp), intent(in) :: final_time
      character(len=BUF) :: line

      write (line, "(5X,A,A,5X,A,1X,ES10.4)") TERMINATION_STEP_TEXT, int_field(last_step, 8), &
         TERMINATION_TIME_TEXT, final_time
      call put(unit, line)
   end subroutine write_termination

   !> "Statistics of this Run", a blank line, then (5X,A22,' =',1X,ES12.5) for
   !> stats = [minimum, maximum, last step size, max truncation] and
   !> (5X,A22,' =',I13) for the derivative calls.
   subroutine write_statistics(unit, stats, derivative_calls)
      integer, intent(in) :: unit
      real(wp), intent(in) :: stats(4)
      integer, intent(in) :: derivative_calls
      character(len=BUF) :: line
      integer :: k

      call put(unit, STATISTICS_TITLE)
      call put(unit, "")
      do k = 1, 4
         write (line, "(5X,A22,' =',1X,ES12.5)") STATISTICS_LABEL(k), stats(k)
         call put(unit, line)
      end do
      write (line, "(5X,A22,' =',A)") STATISTICS_LABEL(5), int_field(derivative_calls, 13)
      call put(unit, line)
   end subroutine write_statistics

end module adore_output_print_tables
