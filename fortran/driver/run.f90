!> Run one deck from file to print file: the engine's top-level procedure (ADORE main).
!>
!> Flow: read the deck (text, then records: adore_deck_reader) → (model, quasi-static start, dynamics: later issues) → print.
!> The print file is written under `<out>.part` and renamed to `<out>` only when the
!> run succeeded; on any error the partial file is deleted, so no half-written
!> output ever poses as a good one.  No state outlives the call.
module adore_driver_run
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_os, only: rename_file, delete_file
   use adore_deck_text, only: deck_text_t, read_deck_text
   use adore_deck_reader, only: deck_t, parse_deck
   use adore_output_banner, only: write_listing, write_banner
   implicit none
   private

   public :: run_deck, STEPS_FROM_DECK

   !> `steps` value meaning "as many steps as the deck asks for".
   integer, parameter :: STEPS_FROM_DECK = -1

contains

   !> Run the deck at `deck_path` and write the print file `out_path`.
   !>
   !> steps: STEPS_FROM_DECK (-1) for the deck's own count, 0 for the quasi-static
   !> start only, n > 0 to stop after n time steps.
   subroutine run_deck(deck_path, out_path, steps, error)
      character(len=*), intent(in) :: deck_path, out_path
      integer, intent(in) :: steps
      type(error_type), allocatable, intent(out) :: error

      type(deck_text_t) :: text
      type(deck_t) :: deck
      character(len=:), allocatable :: part_path
      character(len=256) :: iomsg
      integer :: unit, stat
      logical :: ok

      if (steps < STEPS_FROM_DECK) then
         call input_error(error, "steps must be -1 (from the deck), 0 (quasi-static start "// &
                          "only) or a positive number of time steps")
         return
      end if
      if (len_trim(out_path) == 0) then
         call input_error(error, "print file: no output path given")
         return
      end if

      call read_deck_text(deck_path, text, error)
      if (allocated(error)) return
      ! Records and values (same checks as read_deck; the text is not read twice).  A
      ! malformed deck stops here, before any print file exists.
      call parse_deck(text, deck, error)
      if (allocated(error)) return

      part_path = trim(out_path)//".part"
      open (newunit=unit, file=part_path, status="replace", action="write", &
            form="formatted", iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call input_error(error, trim(out_path)//": cannot write print file: "//trim(iomsg))
         return
      end if

      call write_listing(unit, text)
      call write_banner(unit)

      close (unit, iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         call delete_file(part_path)
         call engine_error(error, trim(out_path)//": cannot close print file: "//trim(iomsg))
         return
      end if
      call rename_file(part_path, trim(out_path), ok)
      if (.not. ok) then
         call delete_file(part_path)
         call engine_error(error, trim(out_path)//": cannot move the finished print file into place")
         return
      end if
   end subroutine run_deck

end module adore_driver_run
