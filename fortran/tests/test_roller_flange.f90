!> Engine unit tests of the roller end / flange contacts (fortran/contact/roller_flange.f90,
!> the flange hook of fortran/forces/roller_bearing.f90) and of the flanged example deck
!> decks/examples/cylindrical_roller_nup_combined.inp against hand calculations
!> (docs/rollers.md, "Flanges"): the geometry of the laid-back face and the Hertz load of
!> the end sphere, the force and moment on the roller, the axial load of the inner race
!> carried by the flange contacts and each roller's axial and tilt balance.
program test_roller_flange
   use adore_test_support, only: check, finish, get_decks_dir
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type
   use adore_model_bearing, only: bearing_t
   use adore_model_from_deck, only: read_bearing
   use adore_geometry_mounted, only: mount_geometry
   use adore_contact_line_slices, only: profile_drop, roller_profile_t
   use adore_contact_roller_flange, only: roller_flange_set_t, flange_contact_t, roller_flanges, flange_contact
   use adore_start_roller_step0, only: roller_step0_t, solve_roller_step0
   use adore_forces_roller_bearing, only: roller_pose_t, race_pose_t, roller_loads_t, roller_loads, &
                                          roller_force_model_t, cylindrical_pocket_loads, POCKET_SLICES, orbit_axes
   use adore_dynamics_integrator, only: integrator_t
   use adore_dynamics_roller_system, only: roller_system_t, start_roller_dynamics, roller_pose, ROLLER_SIZE, &
                                           R_TILT, R_SKEW, R_X, RACE_OFFSET
   implicit none

   character(len=:), allocatable :: decks
   type(error_type), allocatable :: error

   call get_decks_dir(decks)
   call test_face_geometry_and_hertz()
   call test_cylindrical_pocket()
   call test_example_deck()
   call finish("roller flanges")

contains

   !> An aligned roller (D 7.5 mm, L 8 mm, R_e 60 mm) pushed axially against an inner-race
   !> flange laid back by theta: the interference is the axial push beyond the play times
   !> cos theta, the contact height D/2 - R_e sin theta, the load Hertz's with the
   !> equivalent sphere sqrt(R_x R_y) by hand; at theta = 0 the exact sphere on a plane.
   subroutine test_face_geometry_and_hertz()
      type(roller_flange_set_t) :: s
      type(flange_contact_t) :: c
      real(wp), parameter :: d = 7.5e-3_wp, l = 8.0e-3_wp, re = 0.06_wp, cl = 4.0e-5_wp, es = 1.0e11_wp
      real(wp), parameter :: r_i = 0.019_wp, push = 2.0e-6_wp
      real(wp) :: theta, centre(3), q, rc, ry, reff
      integer :: k
      do k = 1, 2
         theta = merge(0.0_wp, 2.5_wp*pi/180.0_wp, k == 1)
         s = roller_flanges(d, l, [3.0e-4_wp, 3.0e-4_wp], re, reshape([.false., .false., .true., .false.], [2, 2]), &
                            [4.0e-3_wp, 4.0e-3_wp], [theta, theta], [cl, cl], [0.0265_wp, r_i], [es, es])
         call check(size(s%flange) == 1 .and. s%flange(1)%race == 2 .and. s%flange(1)%side == -1, "one inner flange at -x")
         ! the roller moved along -x by the half play and push: interference push cos theta
         centre = [-(0.5_wp*cl + push), r_i + 0.5_wp*d, 0.0_wp]
         call flange_contact(s, s%flange(1), centre, [1.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], &
                             [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], [0.0_wp, 0.0_wp, 0.0_wp], 0.0_wp, c)
         call check(abs(c%delta - push*cos(theta)) < 1.0e-12_wp, "interference = axial push x cos(lay-back angle)")
         call check(abs(c%height - (0.5_wp*d - re*sin(theta))) < 1.0e-12_wp, "contact height D/2 - R_e sin theta")
         call check(c%on_face, "contact on the face")
         rc = r_i + c%height
         ry = 1.0_wp/(1.0_wp/re + sin(theta)/rc)
         reff = sqrt(re*ry)
         q = 4.0_wp/3.0_wp*es*sqrt(reff)*(push*cos(theta))**1.5_wp
         ! 1e-9: the face position holds R_e/cos theta - R_e (0.06 m) against delta = 2 um
         call check(abs(c%load - q) < 1.0e-9_wp*q, "Hertz load of the equivalent sphere by hand")
         call check(abs(c%normal(1) - cos(theta)) < 1.0e-15_wp .and. abs(c%normal(2) - sin(theta)) < 1.0e-15_wp, &
                    "normal towards the roller: (cos theta, sin theta)")
         if (k == 1) call check(abs(c%load - 4.0_wp/3.0_wp*es*sqrt(re)*push**1.5_wp) < 1.0e-9_wp*q, &
                                "theta = 0: the sphere-on-plane law (4/3) E* sqrt(R) delta**1.5")
         print "(a,f5.2,a,es11.4,a,es11.4,a)", "  flange at ", theta*180.0_wp/pi, " deg: load ", c%load, &
            " N, height ", c%height, " m"
      end do
   end subroutine test_face_geometry_and_hertz

   !> The cylindrical pocket (kPocType -1) by hand: a roller of 7.5 mm in a pocket of
   !> 7.6 mm (c = 0.1 mm) on a pocket radius of 23.5 mm; centred it touches nothing (gap
   !> c/2 at both halves); pushed by delta0 = 5 um beyond the gap along the orbit (e_t) or
   !> radially (e_r), untilted, every slice has delta0: the normal force is K delta0**(10/9)
   !> L_p against the push, the friction mu N against the sliding of the roller surface
   !> (spin relative to the cage times D/2, regularised: factor v/sqrt(v**2 + 1e-6)), its
   !> moment about the roller axis -mu N D/2, and the cage's torque the reaction's about the
   !> bearing axis.
   subroutine test_cylindrical_pocket()
      type(roller_force_model_t) :: m
      type(roller_pose_t) :: p
      type(race_pose_t) :: a
      type(roller_loads_t) :: ld
      real(wp), parameter :: rp = 0.0235_wp, cl = 1.0e-4_wp, d0 = 5.0e-6_wp, mu = 0.05_wp, w_rel = 100.0_wp
      real(wp) :: dphi, fn, ff, torque
      m%qs%d = 7.5e-3_wp
      m%pocket_type = -1
      m%pocket_radius = rp
      m%pocket_clearance = cl
      m%pocket_length = 8.0e-3_wp - 6.0e-4_wp
      m%pocket_k = 3.0e10_wp
      m%pocket_friction = mu
      a%pocket_azimuth = 0.3_wp
      a%cage_speed = 150.0_wp
      ! centred
      p = roller_pose_t(x=0.0_wp, r=rp, phi=0.3_wp, phidot=150.0_wp, spin=w_rel)
      call cylindrical_pocket_loads(m, p, a, ld)
      call check(all(abs(ld%pocket_gap - 0.5_wp*cl) < 1.0e-15_wp) .and. all(ld%pocket_load == 0.0_wp), &
                 "centred roller: gap c/2 at both halves, no load")
      fn = m%pocket_k*d0**(10.0_wp/9.0_wp)*m%pocket_length
      ff = mu*fn*w_rel*0.5_wp*m%qs%d/sqrt((w_rel*0.5_wp*m%qs%d)**2 + 1.0e-6_wp)
      ! pushed along +e_t: the pocket axis at (r, t) = (R_p cos dphi, -R_p sin dphi)
      dphi = asin((0.5_wp*cl + d0)/rp)
      p%phi = a%pocket_azimuth + dphi
      p%r = rp*cos(dphi)
      ld = roller_loads_t()
      call cylindrical_pocket_loads(m, p, a, ld)
      print "(a,2es13.5,a,2es13.5,a)", "  cylindrical pocket, orbit push: load ", sum(ld%pocket_load), fn, &
         " N (run, hand); friction ", ld%force(2), ff, " N"
      call check(abs(sum(ld%pocket_load) - fn) < 1.0e-12_wp*fn .and. abs(ld%pocket_load(1) - ld%pocket_load(2)) < &
                 1.0e-12_wp*fn, "orbit push: load K delta0**(10/9) L_p, shared by the halves")
      call check(abs(ld%force(3) + fn) < 1.0e-12_wp*fn, "orbit push: normal force against the push")
      ! tau = e_x x e_t = -e_r: sliding (W_abs - w_c) D/2 along tau, friction along -tau = +e_r
      call check(abs(ld%force(2) - ff) < 1.0e-12_wp*fn, "orbit push: Coulomb friction mu N against the sliding")
      call check(abs(ld%moment(1) + ff*0.5_wp*m%qs%d) < 1.0e-12_wp*fn*m%qs%d, "orbit push: spin moment -mu N D/2")
      call check(all(abs(ld%moment(2:3)) < 1.0e-12_wp*fn*m%qs%d), "orbit push, aligned roller: no tilt or skew moment")
      ! cage torque about the axis: reaction (N e_t - ff e_r) at the point r e_r + D/2 e_t
      torque = p%r*fn + 0.5_wp*m%qs%d*ff
      call check(abs(ld%cage_torque - torque) < 1.0e-12_wp*fn*rp, "orbit push: the cage's torque by hand")
      call check(abs(ld%pocket_power - ff*w_rel*0.5_wp*m%qs%d) < 1.0e-9_wp*ff*w_rel*m%qs%d, &
                 "orbit push: friction loss mu N v")
      ! pushed radially outwards (the roller guided cage holds the roller radially)
      p%phi = a%pocket_azimuth
      p%r = rp + 0.5_wp*cl + d0
      p%spin = 0.0_wp
      p%phidot = a%cage_speed
      ld = roller_loads_t()
      call cylindrical_pocket_loads(m, p, a, ld)
      call check(abs(ld%force(2) + fn) < 1.0e-12_wp*fn .and. abs(ld%force(3)) < 1.0e-12_wp*fn .and. &
                 ld%pocket_power == 0.0_wp, "radial push: load K delta0**(10/9) L_p inwards, no sliding, no friction")
      call check(size(ld%pocket_load) == 2 .and. POCKET_SLICES > 0, "pocket halves")
      call test_cylindrical_pocket_free_cage(m)
   end subroutine test_cylindrical_pocket

   !> The cylindrical pocket of a free cage by hand (docs/rollers.md, "The cylindrical pocket"):
   !> (1) the cage displaced by c/2 + delta0 along e_t(psi), the roller centred on the centred
   !> cage's pocket axis: every slice has delta0, the load K delta0**(10/9) L_p pushes the
   !> roller along +e_t, the cage takes -N e_t and the torque -R_p N about its centre's axis,
   !> the friction mu N against the sliding (W - w_c) D/2 - w_c (c/2 + delta0) (the cage
   !> centre's offset turning at w_c); (2) the cage tilted by beta about e_r(psi)
   !> (axis (1, beta cos psi, beta sin psi)), the roller centred: the slices at |x| >
   !> c/(2 beta) touch, q = K (beta |x| - c/2)**(10/9) w, and the cage's moment about e_r is
   !> sum (-|x| q + beta (D/2) q) (the slice loads' lever arms and the tilted normal's axial
   !> part), against the tilt, as the rectangular pocket's.
   subroutine test_cylindrical_pocket_free_cage(m0)
      type(roller_force_model_t), intent(in) :: m0
      type(roller_force_model_t) :: m
      type(roller_pose_t) :: p
      type(race_pose_t) :: a
      type(roller_loads_t) :: ld
      real(wp), parameter :: d0 = 5.0e-6_wp, w_rel = 100.0_wp, wc = 150.0_wp
      real(wp) :: e_r(3), e_t(3), fn, v, ff, beta, w, xs, delta, q, hand_q, hand_m
      integer :: i
      m = m0
      a = race_pose_t()
      a%pocket_azimuth = 0.3_wp
      a%cage_speed = wc
      call orbit_axes(a%pocket_azimuth, e_r, e_t)
      ! (1) displaced cage
      a%cage_position = (0.5_wp*m%pocket_clearance + d0)*e_t
      p = roller_pose_t(x=0.0_wp, r=m%pocket_radius, phi=a%pocket_azimuth, phidot=wc, spin=w_rel)
      call cylindrical_pocket_loads(m, p, a, ld)
      fn = m%pocket_k*d0**(10.0_wp/9.0_wp)*m%pocket_length
      v = w_rel*0.5_wp*m%qs%d - wc*(0.5_wp*m%pocket_clearance + d0)
      ff = m%pocket_friction*fn*v/sqrt(v**2 + 1.0e-6_wp)
      print "(a,2es13.5,a,2es13.5,a)", "  cylindrical pocket, cage displaced: load ", sum(ld%pocket_load), fn, &
         " N (run, hand); friction ", -ld%force(2), ff, " N"
      call check(abs(sum(ld%pocket_load) - fn) < 1.0e-9_wp*fn .and. abs(ld%force(3) - fn) < 1.0e-9_wp*fn, &
                 "displaced cage: the pocket pushes the roller along +e_t with K delta0**(10/9) L_p")
      call check(all(abs(ld%cage_force + fn*e_t - ff*e_r) < 1.0e-9_wp*fn), &
                 "displaced cage: the cage takes the reaction (normal and friction)")
      call check(abs(ld%force(2) + ff) < 1.0e-9_wp*fn, "displaced cage: friction mu N against the sliding "// &
                 "(W - w_c) D/2 - w_c (c/2 + delta0) by hand")
      call check(abs(ld%cage_torque - ld%cage_moment(1)) < 1.0e-12_wp*fn*m%pocket_radius .and. &
                 abs(ld%cage_torque - (-m%pocket_radius*fn + ff*(0.5_wp*m%qs%d + 0.5_wp*m%pocket_clearance + d0))) < &
                 1.0e-9_wp*fn*m%pocket_radius, "displaced cage: torque about the cage centre's axis by hand")
      ! (2) tilted cage, no friction
      m%pocket_friction = 0.0_wp
      a%cage_position = 0.0_wp
      beta = 2.0_wp*m%pocket_clearance/m%pocket_length
      a%cage_tilt = beta*[cos(a%pocket_azimuth), sin(a%pocket_azimuth)]
      p%spin = 0.0_wp
      ld = roller_loads_t()
      call cylindrical_pocket_loads(m, p, a, ld)
      w = m%pocket_length/POCKET_SLICES
      hand_q = 0.0_wp
      hand_m = 0.0_wp
      do i = 1, POCKET_SLICES
         xs = -0.5_wp*m%pocket_length + (real(i, wp) - 0.5_wp)*w
         delta = beta*abs(xs) - 0.5_wp*m%pocket_clearance
         if (delta <= 0.0_wp) cycle
         q = m%pocket_k*delta**(10.0_wp/9.0_wp)*w
         hand_q = hand_q + q
         hand_m = hand_m - abs(xs)*q + beta*0.5_wp*m%qs%d*q
      end do
      print "(a,es11.4,a,es12.5,a,es12.5,a)", "  cylindrical pocket, cage tilted ", beta, " rad: moment on the cage ", &
         dot_product(ld%cage_moment, e_r), " N m (hand ", hand_m, ")"
      call check(abs(sum(ld%pocket_load) - hand_q) < 1.0e-12_wp*hand_q .and. &
                 abs(ld%pocket_load(1) - ld%pocket_load(2)) < 1.0e-12_wp*hand_q, &
                 "tilted cage: both halves press the roller with the hand slice loads")
      call check(abs(dot_product(ld%cage_moment, e_r) - hand_m) < 1.0e-10_wp*abs(hand_m) .and. hand_m < 0.0_wp, &
                 "tilted cage: the pocket moment on the cage = the slice loads' lever arms by hand, against the tilt")
      call check(all(abs(ld%cage_force) < 1.0e-12_wp*hand_q), "tilted cage, centred roller: no net force")
   end subroutine test_cylindrical_pocket_free_cage

   !> The flanged example deck (NUP type, 5 kN radial + 0.5 kN axial, 3000 rpm) integrated
   !> past its start transient, then averaged (docs/rollers.md, "Flanges").
   subroutine test_example_deck()
      type(bearing_t) :: b
      type(roller_step0_t) :: s0
      type(roller_system_t) :: sys
      type(integrator_t) :: it
      real(wp), allocatable :: y(:), dydt(:), fl(:, :), fax(:, :), slice_m(:), flange_m(:), hgt(:, :)
      real(wp) :: t, t_avg, t_end, dt, t_last, axial_on_race, total, theta, lc, q, m_hand, m_slices, loaded_share
      real(wp) :: axial_now, axial_prev
      logical :: have_prev
      real(wp) :: worst_axial, worst_tilt, tilt_num, tilt_den, tilt_avg
      integer :: k, n, flag, i, j

      call read_bearing(decks//"/examples/cylindrical_roller_nup_combined.inp", b, error)
      call check(.not. allocated(error), "flanged example deck read")
      if (allocated(error)) return
      call check(all(b%roller%flange), "four flanges")
      call solve_roller_step0(b, s0, error)
      call check(.not. allocated(error), "example step 0 solved")
      if (allocated(error)) return
      call test_flanged_step0(b, s0)
      associate (e => s0%equilibrium)
         call start_roller_dynamics(b, mount_geometry(b, b%temperature, 2), s0%model, e%azimuth, e%r, e%tilt, &
                                    e%orbital_speed, s0%roller_spin, e%u, 0.0_wp, s0%cage%state%angular_speed, &
                                    sys, it, y, error, axial=e%x, race_axial=e%u_axial)
      end associate
      call check(.not. allocated(error), "example dynamics started")
      if (allocated(error)) return
      n = sys%n
      allocate (dydt(size(y)), fl(4, n), fax(4, n), slice_m(n), flange_m(n), hgt(4, n))
      fl = 0.0_wp; fax = 0.0_wp; slice_m = 0.0_wp; flange_m = 0.0_wp; hgt = 0.0_wp
      ! the start's flange loss (step 0's kinematics) against the dynamics' first evaluation
      ! started from the same state and spin (the run's start takes the spin from the roller
      ! centre's radius, step 0 from the outer raceway's: 89.471 W against 89.519 W)
      call sys%eval(0.0_wp, y, dydt, flag)
      print "(a,f10.4,a,f10.4,a)", "  flange loss at the start: step 0 ", s0%flange_power, " W, dynamics at t = 0 ", &
         sum(sys%loads(:)%flange_power), " W"
      call check(abs(s0%flange_power - sum(sys%loads(:)%flange_power)) < 1.0e-9_wp*s0%flange_power .and. &
                 s0%flange_power > 0.0_wp, "step 0's flange loss = the dynamics' at the same start state")
      axial_on_race = 0.0_wp
      axial_prev = 0.0_wp
      have_prev = .false.
      t = 0.0_wp
      t_avg = 3.0e-3_wp/sys%time_scale
      t_end = 12.0e-3_wp/sys%time_scale
      t_last = 0.0_wp
      total = 0.0_wp
      tilt_num = 0.0_wp
      tilt_den = 0.0_wp
      theta = b%roller%flange_angle(1)
      lc = b%roller%roller_length - 2.0_wp*b%roller%end_radius*(1.0_wp - cos(theta))
      do while (t < t_end .and. .not. allocated(error))
         call it%step(sys, t, y, error, t_limit=t_end)
         if (t <= t_avg) then
            t_last = t
            cycle
         end if
         dt = t - t_last
         t_last = t
         call sys%eval(t, y, dydt, flag)
         total = total + dt
         ! the trapezoidal rule over the accepted steps (the end-point sum biased the averages
         ! of the vibrating loads by about 1 %, differently in release and debug builds)
         axial_now = sum([(sys%loads(k)%race_force(1, 2), k=1, n)])
         if (have_prev) axial_on_race = axial_on_race + 0.5_wp*dt*(axial_now + axial_prev)
         if (.not. have_prev) total = 0.0_wp
         do k = 1, n
            associate (ld => sys%loads(k))
               if (have_prev .and. ld%load(2) > 0.1_wp*b%force(3)/n) then
                  call tilt_terms(b, sys%model%qs%profile, theta, lc, ld, m_hand, m_slices)
                  tilt_num = tilt_num + dt*(m_hand + m_slices)
                  tilt_den = tilt_den + dt*m_hand
               end if
               fl(:, k) = fl(:, k) + dt*ld%flange_load
               fax(:, k) = fax(:, k) + dt*ld%flange_axial
               hgt(:, k) = hgt(:, k) + dt*ld%flange_height
            end associate
         end do
         axial_prev = axial_now
         have_prev = .true.
      end do
      call check(.not. allocated(error), "example integrated to 12 ms")
      if (allocated(error)) return
      fax = fax/total
      axial_on_race = axial_on_race/total
      ! (1) the inner race's axial balance, time-averaged: the rollers' reactions (flanges and
      ! slice traction) carry the applied axial load
      print "(a,f10.4,a,f10.4,a)", "  axial reaction of the rollers on the inner race ", axial_on_race, &
         " N, of its flange contacts ", -sum(fax(3:4, :)), " N (applied 500 N)"
      call check(abs(axial_on_race + b%force(1)) < 0.01_wp*b%force(1), &
                 "time-averaged axial reaction of the rollers = the applied axial load within 1 %")
      ! (2), (3) each roller at the last state: its axial balance (inner flange = outer flange)
      ! and its tilt balance: the flange pair's couple by hand, Q (cos theta (D - h_i - h_o) -
      ! sin theta L_c) with L_c = L - 2 R_e (1 - cos theta) the contact points' axial distance,
      ! against the slices' tilt moment M_i - M_o plus the couple of their axial tractions
      ! (the skewed roller's), sum -s rho f_x by hand
      call sys%eval(t, y, dydt, flag)
      theta = b%roller%flange_angle(1)
      lc = b%roller%roller_length - 2.0_wp*b%roller%end_radius*(1.0_wp - cos(theta))
      loaded_share = 0.0_wp
      worst_axial = 0.0_wp
      worst_tilt = 0.0_wp
      print "(a)", "  roller  azimuth(deg) radial load(N) flange loads in/out(N)  couple by hand / slices, "// &
         "all loads' tilt moment (N m)"
      do k = 1, n
         associate (ld => sys%loads(k))
            call tilt_terms(b, sys%model%qs%profile, theta, lc, ld, m_hand, m_slices)
            print "(i7,f12.2,f14.2,2f11.3,3f12.5)", k, modulo(y(ROLLER_SIZE*(k - 1) + 3)*180.0_wp/pi, 360.0_wp), &
               ld%load(1), ld%flange_load(3), ld%flange_load(2), m_hand, -m_slices, ld%moment(3)
            if (ld%load(2) > 0.1_wp*b%force(3)/n) then
               loaded_share = loaded_share + ld%flange_axial(3)
               worst_axial = max(worst_axial, abs(ld%flange_axial(3) + ld%flange_axial(2))/ld%flange_axial(3))
               worst_tilt = max(worst_tilt, abs(m_hand + m_slices)/m_hand)
            end if
         end associate
      end do
      tilt_avg = tilt_num/tilt_den
      print "(a,f8.2,a,f8.2,a,f7.3,a,f7.3,a,f7.3,a)", "  loaded rollers' inner flanges carry ", &
         100.0_wp*loaded_share/b%force(1), " % of the axial load (all rollers ", 100.0_wp*sum(sys%loads(:)%flange_axial(3))/ &
         b%force(1), " %); worst axial balance ", 100.0_wp*worst_axial, " %, worst tilt balance ", 100.0_wp*worst_tilt, &
         " % (last state; time average over the loaded rollers ", 100.0_wp*tilt_avg, " %)"
      call check(loaded_share > 0.9_wp*sum(sys%loads(:)%flange_axial(3)), &
                 "the loaded zone's flange contacts carry over 90 % of the flanges' axial load")
      call check(worst_axial < 0.02_wp, "each loaded roller: inner and outer flange axial forces equal within 2 %")
      ! time-averaged over 3-12 ms (the last state's worst, 4.4 % from the flangeless start and
      ! 5.5 % from the flanged one, includes the roller's instantaneous tilt acceleration)
      call check(abs(tilt_avg) < 0.05_wp, "the loaded rollers, time-averaged: the slices' tilt moment balances the "// &
                 "flange couple by hand within 5 %")
      call compare_with_step0(b, s0, sys, y, sum(fax(3:4, :)), axial_on_race)
   end subroutine test_example_deck

   !> Roller loads ld's tilt terms (bearing b, roller profile p, lay-back angle theta (rad),
   !> contact points' axial distance lc (m)): the flange pair's couple by hand m_hand and the
   !> slices' tilt moment m_slices (normal M_i - M_o plus the axial tractions' couple) (N m).
   subroutine tilt_terms(b, p, theta, lc, ld, m_hand, m_slices)
      type(bearing_t), intent(in) :: b
      type(roller_profile_t), intent(in) :: p
      real(wp), intent(in) :: theta, lc
      type(roller_loads_t), intent(in) :: ld
      real(wp), intent(out) :: m_hand, m_slices
      real(wp) :: q
      integer :: i, j
      q = 0.5_wp*(ld%flange_load(2) + ld%flange_load(3))
      m_hand = q*(cos(theta)*(b%d - ld%flange_height(2) - ld%flange_height(3)) - sin(theta)*lc)
      m_slices = ld%c(2)%moment - ld%c(1)%moment
      do j = 1, 2
         do i = 1, size(ld%c(j)%x)
            m_slices = m_slices + merge(1.0_wp, -1.0_wp, j == 1)*(0.5_wp*b%d - &
                       profile_drop(p, ld%c(j)%x(i)))*ld%c(j)%weight(i)*ld%traction(i, 2, j)
         end do
      end do
   end subroutine tilt_terms

   !> The flanged start (adore_quasistatic_roller_flange_equilibrium) by hand: the inner race's
   !> axial balance as the hand sum of the inner flange loads' axial components Q cos theta
   !> (the face normal (-s cos theta, s_r sin theta)), each roller's axial balance (inner =
   !> outer flange), its radial balance with the flanges' radial components Q s_r sin theta,
   !> and its tilt balance: the flange pair's couple by hand Q (cos theta (D - h_i - h_o) -
   !> sin theta L_c), L_c = L - 2 R_e (1 - cos theta), against the slices' M_i - M_o.
   subroutine test_flanged_step0(b, s0)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(in) :: s0
      real(wp) :: theta, lc, axial_hand, q, m_hand, m_slices, radial, worst_axial, worst_radial, worst_tilt, w2m
      integer :: k, i
      call check(allocated(s0%equilibrium%flange_load) .and. allocated(s0%flanges%flange), &
                 "flanged deck: step 0 solves the flange contacts")
      if (.not. allocated(s0%equilibrium%flange_load)) return
      theta = b%roller%flange_angle(1)
      lc = b%roller%roller_length - 2.0_wp*b%roller%end_radius*(1.0_wp - cos(theta))
      axial_hand = 0.0_wp
      worst_axial = 0.0_wp
      worst_radial = 0.0_wp
      worst_tilt = 0.0_wp
      print "(a)", "  step 0: roller  azimuth  radial load(N)  flange loads in/out(N)  tilt(rad)  couple hand / slices (N m)"
      associate (e => s0%equilibrium, f => s0%flanges%flange)
         do k = 1, size(e%x)
            w2m = s0%model%mass*e%orbital_speed(k)**2*e%r(k)
            radial = e%c_i(k)%load - e%c_o(k)%load + w2m
            do i = 1, size(f)
               q = e%flange_load(i, k)
               if (f(i)%race == 2) axial_hand = axial_hand + q*cos(f(i)%angle)*real(f(i)%side, wp)
               radial = radial + q*merge(1.0_wp, -1.0_wp, f(i)%race == 2)*sin(f(i)%angle)
            end do
            worst_axial = max(worst_axial, abs(sum(e%flange_axial(:, k))))
            worst_radial = max(worst_radial, abs(radial)/max(e%c_o(k)%load, 1.0_wp))
            q = 0.5_wp*(e%flange_load(2, k) + e%flange_load(3, k))
            m_hand = q*(cos(theta)*(b%d - e%flange_height(2, k) - e%flange_height(3, k)) - sin(theta)*lc)
            m_slices = e%c_i(k)%moment - e%c_o(k)%moment
            print "(i15,f9.2,f16.3,2f12.4,es11.3,2f10.5)", k, e%azimuth(k)*180.0_wp/pi, e%c_i(k)%load, &
               e%flange_load(3, k), e%flange_load(2, k), e%tilt(k), m_hand, -m_slices
            if (e%c_i(k)%load > 0.1_wp*b%force(3)/size(e%x)) worst_tilt = max(worst_tilt, abs(m_hand + m_slices)/m_hand)
         end do
         ! the inner race's -x flange (side -1) pushes along +x: -s Q cos theta on the roller
         print "(a,f12.6,a,es10.3,a,es10.3,a,f7.3,a)", "  step 0: inner flanges' axial load by hand ", -axial_hand, &
            " N (applied 500 N); worst roller axial imbalance ", worst_axial, " N, radial ", worst_radial, &
            " of its load; worst tilt balance ", 100.0_wp*worst_tilt, " %"
         call check(abs(-axial_hand - b%force(1)) < 1.0e-8_wp*b%force(1), &
                    "step 0: the inner flange loads' axial components (hand sum) carry the applied axial load")
         call check(abs(e%inner_force(1) + b%force(1)) < 1.0e-8_wp*b%force(1), &
                    "step 0: the rollers' axial force on the inner race balances the applied load")
         ! K_REG (1 N/m) times the pinched roller's few-um gap difference
         call check(worst_axial < 1.0e-4_wp, "step 0: each roller's flange forces balance axially")
         ! the hand sum takes the face normal in the roller's meridian plane; the engine's leans by
         ! the inner race offset's tangential part over the radius (u_t/R ~ 1e-4)
         call check(worst_radial < 1.0e-6_wp, "step 0: each roller's radial balance with the flanges' radial "// &
                    "components Q sin theta by hand")
         call check(worst_tilt < 0.01_wp, "step 0: each loaded roller's slice tilt moment balances the flange couple "// &
                    "by hand within 1 %")
         call check(all(e%flange_load(1, :) == 0.0_wp) .and. all(e%flange_load(4, :) == 0.0_wp), &
                    "step 0: the load goes through the inner race's -x and the outer race's +x flanges")
      end associate
   end subroutine test_flanged_step0

   !> The flanged start against the dynamics' time average (docs/rollers.md, "Flanges at
   !> step 0"): the axial load each roller's inner flange carries, as its share of the inner
   !> flanges' total at its azimuth (the quasi-static loads interpolated over azimuth), at the
   !> dynamics' last state; the inner race's axial reaction.
   subroutine compare_with_step0(b, s0, sys, y, dyn_flange_axial, dyn_axial)
      type(bearing_t), intent(in) :: b
      type(roller_step0_t), intent(in) :: s0
      type(roller_system_t), intent(in) :: sys
      real(wp), intent(in) :: y(:), dyn_flange_axial, dyn_axial
      real(wp) :: phi, qs_share, dyn_share, dyn_total, qs_total, a, worst, pitch
      integer :: k, j, n
      n = sys%n
      pitch = 2.0_wp*pi/n
      associate (e => s0%equilibrium)
         qs_total = sum(e%flange_load(3, :))
         dyn_total = sum(sys%loads(:)%flange_load(3))
         worst = 0.0_wp
         print "(a)", "  roller  azimuth(deg)  inner flange share: dynamics (last state) / step 0 (interpolated)"
         do k = 1, n
            phi = modulo(y(ROLLER_SIZE*(k - 1) + 3), 2.0_wp*pi)
            j = int(phi/pitch)
            a = phi/pitch - j
            qs_share = ((1.0_wp - a)*e%flange_load(3, j + 1) + a*e%flange_load(3, modulo(j + 1, n) + 1))/qs_total
            dyn_share = sys%loads(k)%flange_load(3)/dyn_total
            print "(i8,f14.2,2f12.4)", k, phi*180.0_wp/pi, dyn_share, qs_share
            if (dyn_share > 0.1_wp) worst = max(worst, abs(dyn_share - qs_share)/dyn_share)
         end do
         print "(a,f9.3,a,f9.3,a,f9.3,a,f7.2,a)", "  inner flanges' axial push on the rollers: step 0 ", &
            sum(e%flange_axial(3:4, :)), " N, dynamics (averaged) ", dyn_flange_axial, &
            " N; the rollers' axial reaction on the race: dynamics ", -dyn_axial, &
            " N; worst share difference of the loaded rollers ", 100.0_wp*worst, " %"
         call check(abs(sum(e%flange_axial(3:4, :)) - b%force(1)) < 1.0e-8_wp*b%force(1), &
                    "step 0: the inner flanges carry the applied axial load")
         ! the dynamics' flanges carry 130 % of it, the slices' axial traction of the skewed
         ! rollers the rest (docs/rollers.md, "Flanges"): the shares, not the totals, compare
         call check(worst < 0.05_wp, "the loaded rollers' inner flange shares: step 0 against the dynamics within 5 %")
      end associate
   end subroutine compare_with_step0

end program test_roller_flange
