!> Flat f2py wrappers of the print writer (test-only module pyadore._probes): write a whole
!> step, the end of run, or the banner and input echo from plain arrays to a file, so that
!> Python can compare the Fortran writer with pyadore.printout.writer / echo_writer.
!> append /= 0 appends to the file, 0 replaces it.  Status 1 (input error) when the file
!> cannot be opened or the arrays do not fit the layout.

!> Open ``path`` for writing (append or replace); status/message set on failure.
subroutine adore_printer_open(path, append, unit, status, message)
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   implicit none
   character(len=*), intent(in) :: path
   integer, intent(in) :: append
   integer, intent(out) :: unit, status
   character(len=2048), intent(out) :: message
   integer :: ios
   character(len=512) :: iomsg

   status = ADORE_OK
   message = ""
   if (append /= 0) then
      open (newunit=unit, file=path, status="unknown", position="append", action="write", iostat=ios, iomsg=iomsg)
   else
      open (newunit=unit, file=path, status="replace", action="write", iostat=ios, iomsg=iomsg)
   end if
   if (ios /= 0) then
      status = ADORE_INPUT_ERROR
      message = path // ": cannot open the print file: " // trim(iomsg)
   end if
end subroutine adore_printer_open

!> One printed step (adore_output_print_tables::write_step); shapes as documented there:
!> re_*(nre, 11), slices(nslice, 10, msl) of which the first nsl are printed (msl >= 1:
!> f2py does not pass empty arrays), re_cage(ncage, 8), race_cage(nland, 7),
!> bodies(3, 11), loads(5, 6), accelerations(3, 7), performance(14), summary(nsum, 10).
subroutine adore_print_step(path, append, step, header, run_id, nre, re_no, re_contact, re_motion, re_traction, &
                            re_thermal, nslice, msl, nsl, slice_roller, slice_no, slices, roller, ncage, cage_el, &
                            cage_end, cage_code, re_cage, nland, land_no, land_code, race_cage, bodies, loads, &
                            accelerations, performance, nsum, sum_step, summary, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_output_print_tables, only: write_step
   implicit none
   character(len=*), intent(in) :: path, run_id
   integer, intent(in) :: append, step, nre, nslice, msl, nsl, roller, ncage, nland, nsum
   real(wp), intent(in) :: header(4)
   integer, intent(in) :: re_no(nre)
   real(wp), intent(in) :: re_contact(nre, 11), re_motion(nre, 11), re_traction(nre, 11), re_thermal(nre, 11)
   integer, intent(in) :: slice_roller(msl), slice_no(nslice)
   real(wp), intent(in) :: slices(nslice, 10, msl)
   integer, intent(in) :: cage_el(ncage), cage_end(ncage), cage_code(ncage)
   real(wp), intent(in) :: re_cage(ncage, 8)
   integer, intent(in) :: land_no(nland), land_code(nland)
   real(wp), intent(in) :: race_cage(nland, 7), bodies(3, 11), loads(5, 6), accelerations(3, 7), performance(14)
   integer, intent(in) :: sum_step(nsum)
   real(wp), intent(in) :: summary(nsum, 10)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   integer :: unit

   if (nsl < 0 .or. nsl > msl) then
      status = ADORE_INPUT_ERROR
      message = "print step: the number of slice tables exceeds the slice arrays"
      return
   end if
   call adore_printer_open(path, append, unit, status, message)
   if (status /= ADORE_OK) return
   call write_step(unit, step, header, run_id, re_no, re_contact, re_motion, re_traction, re_thermal, &
                   slice_roller(1:nsl), slice_no, slices(:, :, 1:nsl), roller, cage_el, cage_end, cage_code, re_cage, &
                   land_no, land_code, race_cage, bodies, loads, accelerations, performance, sum_step, summary)
   close (unit)
end subroutine adore_print_step

!> Termination line, a blank line and the run statistics
!> (stats = [minimum, maximum, last step size, max truncation]).
subroutine adore_print_end(path, append, last_step, final_time, stats, derivative_calls, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK
   use adore_output_print_tables, only: write_termination, write_statistics
   implicit none
   character(len=*), intent(in) :: path
   integer, intent(in) :: append, last_step, derivative_calls
   real(wp), intent(in) :: final_time, stats(4)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   integer :: unit

   call adore_printer_open(path, append, unit, status, message)
   if (status /= ADORE_OK) return
   call write_termination(unit, last_step, final_time)
   write (unit, "(a)") ""
   call write_statistics(unit, stats, derivative_calls)
   close (unit)
end subroutine adore_print_end

!> The banner (adore_output_banner::write_banner) and the input echo of a record given as
!> flat vectors: texts(ntext) (each at most 80 characters), ints(nint), reals(nreal) in
!> the field order of pyadore/printout/echo_layout.py (offsets ET_/EI_/ER_ of layout.f90).
subroutine adore_print_echo(path, append, ntext, texts, nint, ints, nreal, reals, status, message)
   use adore_core_kinds, only: wp
   use adore_core_error, only: ADORE_OK, ADORE_INPUT_ERROR
   use adore_output_banner, only: write_banner
   use adore_output_echo_data, only: echo_data_t, echo_data_init
   use adore_output_print_echo, only: write_echo
   use adore_output_layout, only: N_ECHO_TEXT, N_ECHO_INT, N_ECHO_REAL, ET_BEARING_TYPE, ET_RUN_ID, ET_TITLE, &
      ET_LUBRICANT, ET_WEIBULL_SLOPE, ET_LIFE_MOD_CODE, ET_COOLANT_TYPE, ET_NODE_BASE_TEMP, ET_VARY_GEOMETRY, &
      EI_ELEMENT_KIND, EI_PROGRAM_MODE, EI_N_ELEMENTS, EI_POCKET_SHAPE, EI_N_LANDS, EI_N_CAGE_SEGS, EI_N_GUIDE, &
      EI_GUIDE_LAND, EI_GUIDE_TYPE, EI_N_QS, EI_QS_CONSTRAINTS, EI_TRANS_CONSTRAINTS, EI_ROT_CONSTRAINTS, &
      EI_PRINT_HTC, EI_N_STEPS, EI_DATA_CONTROL, EI_AUTO_PLOTS, EI_INT_METHOD, ER_ELEMENT_DIA, ER_PITCH_DIA, &
      ER_CONTACT_ANGLE, ER_CUR_FAC, ER_DIA_PLAY, ER_END_PLAY, ER_FIT, ER_WIDTH, ER_SHAFT_OD, ER_SHAFT_ID, &
      ER_BEARING_OD, ER_HOUSING_OD, ER_ROLLER_LEN, ER_CEN_LAND, ER_OUTER_LEN, ER_INNER_LEN, ER_CROWN_RAD, &
      ER_COR_RAD, ER_RACE_CROWN, ER_CAGE_OD, ER_CAGE_ID, ER_CAGE_CONE, ER_CAGE_WIDTH, ER_SEG_CUT, ER_POC_CLS, &
      ER_RACE_CLS, ER_GUIDE, ER_MATERIAL, ER_INERTIA, ER_PRINCIPAL, ER_LUBRICATION, ER_FATIGUE, ER_ASPERITY, &
      ER_ROOM_TEMP, ER_HOUSING_TEMP, ER_SHAFT_TEMP, ER_RE_TEMP, ER_CAGE_TEMP, ER_RACE_SPEED, ER_RACE_TEMP, &
      ER_MISALIGN_Y, ER_MISALIGN_Z, ER_LOAD_FRACTION, ER_HEAT_TRANS_COEFF, ER_APPLIED_LOAD, ER_REL_DISP, &
      ER_APPLIED_MOMENT, ER_GRAVITY, ER_CAGE_POSITION, ER_CAGE_ANGLE, ER_WHIRL_RATIO, ER_EPICYCLIC_RATIO, &
      ER_SCALE_LENGTH, ER_SCALE_LOAD, ER_SCALE_TIME, ER_STEP_MIN, ER_STEP_MAX, ER_STEP_INITIAL, ER_ERROR_LIMIT
   implicit none
   character(len=*), intent(in) :: path
   integer, intent(in) :: append, ntext, nint, nreal
   character(len=80), intent(in) :: texts(ntext)
   integer, intent(in) :: ints(nint)
   real(wp), intent(in) :: reals(nreal)
   integer, intent(out) :: status
   character(len=2048), intent(out) :: message
   type(echo_data_t) :: e
   character(len=80) :: t(ntext)
   integer :: unit, k, j

   status = ADORE_INPUT_ERROR
   if (ntext /= N_ECHO_TEXT .or. nint /= N_ECHO_INT .or. nreal /= N_ECHO_REAL) then
      write (message, "(a,3(1x,i0),a,3(1x,i0))") "print echo: need texts, integers, reals of sizes", &
         N_ECHO_TEXT, N_ECHO_INT, N_ECHO_REAL, "; got", ntext, nint, nreal
      return
   end if
   t = texts
   do k = 1, ntext   ! C strings may arrive NUL-padded
      do j = 1, len(t(k))
         if (t(k)(j:j) == achar(0)) t(k)(j:j) = " "
      end do
   end do
   e = echo_data_init()
   e%bearing_type = t(ET_BEARING_TYPE); e%run_id = t(ET_RUN_ID); e%title = t(ET_TITLE)
   e%lubricant = t(ET_LUBRICANT); e%weibull_slope = t(ET_WEIBULL_SLOPE)
   e%life_mod_code = t(ET_LIFE_MOD_CODE); e%coolant_type = t(ET_COOLANT_TYPE)
   e%node_base_temp = t(ET_NODE_BASE_TEMP); e%vary_geometry = t(ET_VARY_GEOMETRY)

   e%element_kind = ints(EI_ELEMENT_KIND); e%program_mode = ints(EI_PROGRAM_MODE)
   e%n_elements = ints(EI_N_ELEMENTS); e%pocket_shape = ints(EI_POCKET_SHAPE); e%n_lands = ints(EI_N_LANDS)
   e%n_cage_segs = ints(EI_N_CAGE_SEGS); e%n_guide = ints(EI_N_GUIDE)
   e%guide_land = ints(EI_GUIDE_LAND:EI_GUIDE_LAND + size(e%guide_land) - 1)
   e%guide_type = ints(EI_GUIDE_TYPE:EI_GUIDE_TYPE + size(e%guide_type) - 1)
   e%n_qs = ints(EI_N_QS)
   e%qs_constraints = ints(EI_QS_CONSTRAINTS:EI_QS_CONSTRAINTS + size(e%qs_constraints) - 1)
   e%trans_constraints = ints(EI_TRANS_CONSTRAINTS:EI_TRANS_CONSTRAINTS + 5)
   e%rot_constraints = ints(EI_ROT_CONSTRAINTS:EI_ROT_CONSTRAINTS + 5)
   e%print_htc = ints(EI_PRINT_HTC); e%n_steps = ints(EI_N_STEPS)
   e%data_control = ints(EI_DATA_CONTROL:EI_DATA_CONTROL + 2)
   e%auto_plots = ints(EI_AUTO_PLOTS:EI_AUTO_PLOTS + 2)
   e%int_method = ints(EI_INT_METHOD)

   e%element_dia = reals(ER_ELEMENT_DIA); e%pitch_dia = reals(ER_PITCH_DIA)
   e%contact_angle = reals(ER_CONTACT_ANGLE); e%cur_fac = reals(ER_CUR_FAC:ER_CUR_FAC + 1)
   e%dia_play = reals(ER_DIA_PLAY); e%end_play = reals(ER_END_PLAY); e%fit = reals(ER_FIT:ER_FIT + 1)
   e%width = reals(ER_WIDTH:ER_WIDTH + 1); e%shaft_od = reals(ER_SHAFT_OD); e%shaft_id = reals(ER_SHAFT_ID)
   e%bearing_od = reals(ER_BEARING_OD); e%housing_od = reals(ER_HOUSING_OD)
   e%roller_len = reals(ER_ROLLER_LEN); e%cen_land = reals(ER_CEN_LAND)
   e%outer_len = reals(ER_OUTER_LEN:ER_OUTER_LEN + 1); e%inner_len = reals(ER_INNER_LEN:ER_INNER_LEN + 1)
   e%crown_rad = reals(ER_CROWN_RAD); e%cor_rad = reals(ER_COR_RAD:ER_COR_RAD + 1)
   e%race_crown = reals(ER_RACE_CROWN:ER_RACE_CROWN + 1)
   e%cage_od = reals(ER_CAGE_OD); e%cage_id = reals(ER_CAGE_ID); e%cage_cone = reals(ER_CAGE_CONE)
   e%cage_width = reals(ER_CAGE_WIDTH); e%seg_cut = reals(ER_SEG_CUT)
   e%poc_cls = reals(ER_POC_CLS:ER_POC_CLS + 1); e%race_cls = reals(ER_RACE_CLS:ER_RACE_CLS + 1)
   e%guide = reshape(reals(ER_GUIDE:ER_GUIDE + size(e%guide) - 1), shape(e%guide))
   e%material = reshape(reals(ER_MATERIAL:ER_MATERIAL + size(e%material) - 1), shape(e%material))
   e%inertia = reshape(reals(ER_INERTIA:ER_INERTIA + size(e%inertia) - 1), shape(e%inertia))
   e%principal = reshape(reals(ER_PRINCIPAL:ER_PRINCIPAL + size(e%principal) - 1), shape(e%principal))
   e%lubrication = reshape(reals(ER_LUBRICATION:ER_LUBRICATION + size(e%lubrication) - 1), shape(e%lubrication))
   e%fatigue = reshape(reals(ER_FATIGUE:ER_FATIGUE + size(e%fatigue) - 1), shape(e%fatigue))
   e%asperity = reshape(reals(ER_ASPERITY:ER_ASPERITY + size(e%asperity) - 1), shape(e%asperity))
   e%room_temp = reals(ER_ROOM_TEMP); e%housing_temp = reals(ER_HOUSING_TEMP); e%shaft_temp = reals(ER_SHAFT_TEMP)
   e%re_temp = reals(ER_RE_TEMP); e%cage_temp = reals(ER_CAGE_TEMP)
   e%race_speed = reals(ER_RACE_SPEED:ER_RACE_SPEED + 1); e%race_temp = reals(ER_RACE_TEMP:ER_RACE_TEMP + 1)
   e%misalign_y = reals(ER_MISALIGN_Y:ER_MISALIGN_Y + 1); e%misalign_z = reals(ER_MISALIGN_Z:ER_MISALIGN_Z + 1)
   e%load_fraction = reals(ER_LOAD_FRACTION); e%heat_trans_coeff = reals(ER_HEAT_TRANS_COEFF)
   e%applied_load = reals(ER_APPLIED_LOAD:ER_APPLIED_LOAD + 2); e%rel_disp = reals(ER_REL_DISP:ER_REL_DISP + 2)
   e%applied_moment = reals(ER_APPLIED_MOMENT:ER_APPLIED_MOMENT + 2); e%gravity = reals(ER_GRAVITY:ER_GRAVITY + 2)
   e%cage_position = reals(ER_CAGE_POSITION:ER_CAGE_POSITION + 2)
   e%cage_angle = reals(ER_CAGE_ANGLE:ER_CAGE_ANGLE + 2)
   e%whirl_ratio = reals(ER_WHIRL_RATIO); e%epicyclic_ratio = reals(ER_EPICYCLIC_RATIO)
   e%scale_length = reals(ER_SCALE_LENGTH); e%scale_load = reals(ER_SCALE_LOAD); e%scale_time = reals(ER_SCALE_TIME)
   e%step_min = reals(ER_STEP_MIN); e%step_max = reals(ER_STEP_MAX); e%step_initial = reals(ER_STEP_INITIAL)
   e%error_limit = reals(ER_ERROR_LIMIT)

   call adore_printer_open(path, append, unit, status, message)
   if (status /= ADORE_OK) return
   call write_banner(unit)
   call write_echo(unit, e)
   close (unit)
end subroutine adore_print_echo
