!> Experiment (docs/thermal.md, "Appendix C step 2500"): the thermal network fed with the
!> report's printed step-2500 contact losses (golden/appendix_c_ball.prt, section 1,
!> "Contact Loss (W)"; balls 12 and 18 are illegible in the text copy and get the mean of
!> the 16 printed balls - an experiment assumption, printed as such), compared with the
!> report's printed temperatures.  Not a test: it measures how far the network is.
!> Also Appendix D step 4000 (roller, air, no coolant flow), all its losses legible.
!> Build and run (from the repository root, after `make exe`):
!>   gfortran -O2 -Ibuild/native/libadore_engine.a.p tools/thermal_step2500.f90 \
!>     build/native/libadore_engine.a -o /tmp/thermal_step2500 && /tmp/thermal_step2500 decks
program thermal_step2500
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t, TEMP_HOUSING, TEMP_SHAFT, TEMP_ELEMENT, TEMP_CAGE, TEMP_OUTER, TEMP_INNER
   use adore_model_from_deck, only: read_bearing
   use adore_thermal_network, only: thermal_heat_t, thermal_options_t, thermal_field_t, solve_thermal_network
   use adore_thermal_march, only: solve_thermal_march
   use adore_thermal_distortion, only: distortion_t, thermal_distortion
   implicit none
   ! report step 2500, section 1: contact loss outer/inner (W), spin amplitude (rpm); 0 = illegible
   real(wp), parameter :: q_out(18) = [16.32_wp, 14.57_wp, 13.07_wp, 12.55_wp, 13.16_wp, 14.13_wp, 14.80_wp, &
      15.05_wp, 14.50_wp, 14.31_wp, 13.34_wp, 0.0_wp, 12.64_wp, 13.46_wp, 14.77_wp, 16.69_wp, 17.91_wp, 0.0_wp]
   real(wp), parameter :: q_in(18) = [27.35_wp, 22.71_wp, 18.22_wp, 14.32_wp, 11.45_wp, 8.797_wp, 7.595_wp, &
      7.474_wp, 8.171_wp, 7.608_wp, 8.763_wp, 0.0_wp, 14.11_wp, 18.80_wp, 23.05_wp, 27.25_wp, 30.93_wp, 0.0_wp]
   real(wp), parameter :: spin_rpm = 7.62e4_wp
   ! report step 2500 temperatures (K): exit, housing bulk/outer/inner, shaft bulk/outer/inner,
   ! outer race, inner race, cage
   real(wp), parameter :: report(10) = [341.9_wp, 346.8_wp, 345.7_wp, 348.0_wp, 329.3_wp, 349.6_wp, 317.4_wp, &
                                        349.0_wp, 351.4_wp, 342.0_wp]
   character(len=*), parameter :: names(10) = [character(len=16) :: "exit fluid", "housing bulk", "housing outer", &
      "housing inner", "shaft bulk", "shaft outer", "shaft inner", "outer race", "inner race", "cage"]
   type(bearing_t) :: b
   type(error_type), allocatable :: error
   type(thermal_heat_t) :: h
   type(thermal_options_t) :: opt
   character(len=256) :: decks
   real(wp) :: htc(4), bore(4)
   integer :: k

   call get_command_argument(1, decks)
   if (len_trim(decks) == 0) decks = "decks"
   call read_bearing(trim(decks)//"/appendix_c_ball.inp", b, error)
   if (allocated(error)) then
      print "(a)", error%message
      error stop 1
   end if
   allocate (h%outer(18), h%inner(18), h%pocket(18), h%drag(18))
   h%outer = q_out
   h%inner = q_in
   h%outer([12, 18]) = sum(q_out)/16.0_wp
   h%inner([12, 18]) = sum(q_in)/16.0_wp
   h%pocket = 0.0_wp     ! printed 0 at every pocket
   h%drag = 0.0_wp       ! illegible
   h%land = 0.0_wp       ! illegible
   print "(a,f8.2,a,f8.2,a)", "heat: 16 printed balls ", sum(q_out) + sum(q_in), " W; with balls 12, 18 assumed ", &
      sum(h%outer) + sum(h%inner), " W (report total power loss 567.7 W)"
   opt%reference_temperature = b%temperature(TEMP_HOUSING)
   opt%element_velocity = [(spin_rpm*pi/30.0_wp*0.5_wp*b%d, k = 1, 18)]
   ! boundary variants (docs/thermal.md): housing OD held at 323 K or behind a film h; shaft
   ! bore adiabatic or draining to 323 K through a conductance (W/K)
   htc = [0.0_wp, 300.0_wp, 300.0_wp, 400.0_wp]
   bore = [0.0_wp, 0.0_wp, 8.0_wp, 8.0_wp]
   do k = 1, 4
      opt%reference_htc = htc(k)
      opt%bore_conductance = bore(k)
      call run_case()
   end do
   call roller_step4000()

contains

   subroutine run_case()
      type(thermal_field_t) :: f
      type(distortion_t) :: d
      real(wp) :: mine(10)
      integer :: i
      call solve_thermal_network(b, h, opt, f, error)
      if (allocated(error)) then
         print "(a)", error%message
         return
      end if
      print "(/,a,es10.3,a,es10.3,a,i0)", "reference: housing OD film h = ", opt%reference_htc, &
         " W/(m^2 K) (0: OD held at 323 K); bore conductance ", opt%bore_conductance, " W/K; passes ", f%passes
      print "(a,4f9.2,a,es10.3)", "  heat W: generated, coolant, reference, bore ", f%q_generated, f%q_coolant, &
         f%q_reference, f%q_bore, "   mean HTC ", sum(f%htc)/18
      mine = [f%exit_temperature, f%housing(1), f%housing(2), f%housing(3), f%shaft(1), f%shaft(2), f%shaft(3), &
              f%temperature(TEMP_OUTER), f%temperature(TEMP_INNER), f%temperature(TEMP_CAGE)]
      do i = 1, 10
         print "(2x,a16,2f9.2,f8.2,a)", names(i), mine(i), report(i), 100.0_wp*(mine(i) - report(i))/report(i), " %"
      end do
      print "(a,18f6.1)", "  ball bulk: ", f%element_bulk
      print "(a,18f6.1)", "  contact o: ", f%contact_outer
      print "(a,18f6.1)", "  contact i: ", f%contact_inner
      d = thermal_distortion(b, f%temperature)
      print "(a,3es11.3,a)", "  ADRC2: outer fit, inner fit, clearance ", d%mounted%mounting%outer_fit, &
         d%mounted%mounting%inner_fit, d%clearance, "  (report 1.458e-5 -2.484e-5 1.537e-4)"
   end subroutine run_case

   !> Appendix D step 4000 (golden/appendix_d_roller.prt): the printed roller contact losses
   !> (all 16 legible, 0.97 W), air, no flow, housing OD at the room 294 K, spin 1.817e5 rpm.
   subroutine roller_step4000()
      real(wp), parameter :: qo(8) = [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp]
      real(wp), parameter :: lo(8) = [1.331e-2_wp, 1.331e-2_wp, 8.355e-2_wp, 2.700e-1_wp, 1.996e-1_wp, 2.793e-2_wp, &
                                      1.331e-2_wp, 1.331e-2_wp]
      real(wp), parameter :: li(8) = [0.0_wp, 0.0_wp, 2.412e-2_wp, 1.913e-1_wp, 1.173e-1_wp, 6.026e-4_wp, 0.0_wp, 0.0_wp]
      type(bearing_t) :: r
      type(thermal_heat_t) :: hr
      type(thermal_options_t) :: o
      type(thermal_field_t) :: f
      integer :: i
      call read_bearing(trim(decks)//"/appendix_d_roller.inp", r, error)
      if (allocated(error)) then
         print "(a)", error%message
         return
      end if
      hr%outer = lo + qo
      hr%inner = li
      allocate (hr%pocket(8), hr%drag(8))
      hr%pocket = 0.0_wp
      hr%drag = 0.0_wp
      o%reference_temperature = r%temperature(TEMP_HOUSING)
      o%element_velocity = [(1.817e5_wp*pi/30.0_wp*0.5_wp*r%d, i = 1, 8)]
      do i = 1, 2
         if (i == 1) then
            call solve_thermal_network(r, hr, o, f, error)
         else
            call solve_thermal_march(r, hr, o, f, error)
         end if
         if (allocated(error)) then
            print "(a)", error%message
            return
         end if
         print "(/,2a,f8.4,a)", trim(merge("network", "march  ", i == 1)), ": Appendix D step 4000: heat ", &
            f%q_generated, " W (report total power loss 0.9677 W)"
         print "(a,3f9.3)", "  exit, housing bulk, shaft bulk (report 293.9, 294.0, 293.9): ", f%exit_temperature, &
            f%housing(1), f%shaft(1)
         print "(a,3f9.3)", "  outer race, inner race, cage (report -, -, 293.9): ", f%temperature(TEMP_OUTER), &
            f%temperature(TEMP_INNER), f%temperature(TEMP_CAGE)
         print "(a,8f8.3)", "  roller bulk (report 294.0 294.0 294.0 293.9 293.6 293.6 293.9 294.0): ", f%element_bulk
         print "(a,es10.3,a)", "  mean HTC ", sum(f%htc)/8, " W/(m^2 K) (report 4.18e5)"
      end do
   end subroutine roller_step4000

end program thermal_step2500
