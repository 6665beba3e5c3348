!> Print writer, part 1: the input listing and the ADORE 5.0 banner.
!>
!> Writers only format: they take what to print and a unit, and compute nothing.
!> Layout: docs/print-layout.md (transcribed from the report's Appendix C/D output).
module adore_output_banner
   use adore_core_kinds, only: wp
   use adore_deck_text, only: deck_text_t
   use adore_tribology_traction_law, only: traction_law_t, LAW_TABLE
   implicit none
   private

   public :: write_listing, write_banner

contains

   !> "Input from optional user subroutines" (the time integration when the run has time
   !> steps: its step count, substeps and the bearing kind's lines on its physics; the ball
   !> start hypothesis when a run option replaced the default, start_title non-blank;
   !> moment equilibrium of the inner race when the run option asked for it; a
   !> traction-slip table of ADRX7, report 4.4.9, when the run has one: its file and points,
   !> slip in m/s) and the "Listing of input data records": every deck line, verbatim (ADORE
   !> prints the deck before its banner, report Appendix C/D).
   subroutine write_listing(unit, text, traction, traction_path, start_title, moment_equilibrium, dynamics_steps, &
                            substeps, dynamics_lines, duration, revolutions, threads)
      integer, intent(in) :: unit
      type(deck_text_t), intent(in) :: text
      type(traction_law_t), intent(in), optional :: traction
      character(len=*), intent(in), optional :: traction_path
      character(len=*), intent(in), optional :: start_title
      !> .true. when the run option asked for moment equilibrium of the inner race
      logical, intent(in), optional :: moment_equilibrium
      !> time steps of the run (absent or 0: none)
      integer, intent(in), optional :: dynamics_steps
      !> integrator steps per time step (absent or 1: no substeps)
      integer, intent(in), optional :: substeps
      !> the bearing kind's lines on the physics of its time integration, each ending in LF
      character(len=*), intent(in), optional :: dynamics_lines
      !> a run to a simulated time: that time (s) and the shaft's revolutions in it
      real(wp), intent(in), optional :: duration, revolutions
      !> threads of the time steps' derivative (run option threads, adore_core_threads)
      integer, intent(in), optional :: threads
      character(len=16) :: num
      integer :: i

      write (unit, "(a)") "Input from optional user subroutines"
      write (unit, "(a)") ""
      if (present(dynamics_steps)) then
         if (dynamics_steps > 0) then
            if (present(duration) .and. present(revolutions)) then
               write (num, "(f16.3)") revolutions
               write (unit, "(a,es11.4,a)") "TIME INTEGRATION: TO", duration, " S SIMULATED TIME ("// &
                  trim(adjustl(num))//" SHAFT REVOLUTIONS), THE LAST STEP ENDING THERE"
            else
               write (unit, "(a,i0,a)") "TIME INTEGRATION: ", dynamics_steps, " TIME STEPS"
            end if
            if (present(substeps)) then
               if (substeps > 1) write (unit, "(a,i0,a)") "  ", substeps, " SUBSTEPS IN EACH TIME STEP (REPORT 4.4.5)"
            end if
            if (present(dynamics_lines)) write (unit, "(a)", advance="no") dynamics_lines
            if (present(threads)) write (unit, "(a,i0,a)") "  DERIVATIVE ON ", threads, &
               trim(merge(" THREAD  ", " THREADS ", threads == 1))//" (RUN OPTION THREADS; THE RESULTS ARE THE SAME "// &
               "ON ANY NUMBER)"
            write (unit, "(a)") ""
         end if
      end if
      if (present(start_title)) then
         if (len_trim(start_title) > 0) then
            write (unit, "(a)") "INITIAL BALL ANGULAR VELOCITY: "//trim(start_title)//","
            write (unit, "(a)") "  REPLACES THE MINIMUM-DISSIPATION START (REPORT 4.4.7)"
            write (unit, "(a)") ""
         end if
      end if
      if (present(moment_equilibrium)) then
         if (moment_equilibrium) then
            write (unit, "(a)") "QUASI-STATIC MOMENT CONSTRAINTS: MOMENT EQUILIBRIUM OF THE INNER RACE ABOUT Y AND Z"
            write (unit, "(a)") "  (ADORE kFS4 = kFS5 = 0), REPLACES THE PRESCRIBED ZERO MISALIGNMENT"
            write (unit, "(a)") ""
         end if
      end if
      if (present(traction) .and. present(traction_path)) then
         if (traction%kind == LAW_TABLE) then
            write (unit, "(a,i0,a)") "ADRX7 TRACTION-SLIP TABLE (", size(traction%slip), &
               " POINTS), RE/RACE CONTACTS, REPLACES THE TRACTION MODEL OF REC 10.0"
            write (unit, "(a)") "FILE: "//traction_path
            write (unit, "(a)") "   SLIP (m/s)   TRAC COEFF"
            do i = 1, size(traction%slip)
               write (unit, "(2(1x,es12.5))") traction%slip(i), traction%kappa(i)
            end do
            write (unit, "(a)") ""
         end if
      end if
      write (unit, "(a)") "Listing of input data records"
      write (unit, "(a)") ""
      do i = 1, size(text%lines)
         write (unit, "(a)") text%lines(i)%s
      end do
      write (unit, "(a)") ""
   end subroutine write_listing

   !> The program banner as the report prints it above the input echo.
   subroutine write_banner(unit)
      integer, intent(in) :: unit

      write (unit, "(a)") "ADVANCED DYNAMICS OF ROLLING ELEMENTS"
      write (unit, "(a)") "A Real Time Simulation of Rolling Bearing Performance"
      write (unit, "(a)") ""
      write (unit, "(a)") "[Version (ADORE 5.0)]"
      write (unit, "(a)") ""
   end subroutine write_banner

end module adore_output_banner
