!> Loads on one cylindrical roller at any state (issue #26): its race contacts by slices at
!> any roller attitude and race misalignment, their traction by the run's law, its pocket
!> contact in a rectangular or cylindrical (kPocType -1) cage pocket, its ends on the race
!> flanges (adore_contact_roller_flange, flange_loads), gravity; the reactions on the races
!> and the cage.
!>
!> Frame: the orbit-following frame of the roller (report eq 54 as for the balls): azimuth
!> phi from +z towards -y, e_r = (0, -sin phi, cos phi), e_t = e_x x e_r the orbit
!> direction, e_x the bearing axis.  Roller state (roller_pose_t): centre x e_x + r e_r,
!> rates (xdot, rdot, phidot); attitude by tilt gamma (rotation about e_t: the axis rises by
!> gamma x along e_r) and skew zeta (rotation about e_r: axis e_x - zeta e_t), small
!> angles; their rates gammadot, zetadot in the orbit frame; W the roller's spin relative
!> to the orbit frame (about its axis).
!>
!> Race contacts: adore_quasistatic_roller_equilibrium's roller_contacts (the step-0 slice
!> model: crown profile, interference per slice, Palmgren slice load), with the inner race
!> radial offset u_r and tilt t_r at the roller's azimuth, the roller's tilt and skew and
!> its axial offset from each race (the permissible contact ends shift with it).  Normal
!> damping: stiffness-proportional, beta (k0 hdot0 + k1 hdot1) (N) and beta (k1 hdot0 +
!> k2 hdot1) (N m) from the slice stiffness integrals (as the ball's contact damping,
!> docs/dynamics.md); the damped load is kept >= 0.
!> Slip (report eqs 2-3 on each slice, two components): along e_t the rolling slip of
!> adore_tribology_roller_traction's line_slip with each race's contact point at the roller's
!> surface point, radius r + rho(x) (outer) or r - rho(x) (inner), i.e. the difference of the
!> two surfaces' velocities (so that the traction's power balances: the dissipation eq 4
!> equals the work taken from the races minus the roller's kinetic energy gain, tested),
!> minus zetadot x and the race's tangential velocity; along e_x the skewed roller's surface speed +-zeta W rho, the tilt rate's
!> -+gammadot rho and the roller's axial velocity relative to the race.  Traction on the race
!> t = kappa(|u|) q u/|u| (the run's law); on the roller -t.  Power eq 4 per slice.
!> Moments on the roller about its centre of a slice force f = -t w (on the roller) at
!> x e_x + s rho e_r (s = +1 outer, -1 inner):  M_x = s rho f_t (spin), M_r = -x f_t (skew:
!> the lever arms of the slice tractions), M_t = -s rho f_x; the normal slice loads give
!> M_t = M_i - M_o with M = sum w q x (the tilt equation of step 0).
!> Pocket (rectangular, kPocType 0 taken as flat walls at +-(D + c)/2 from the pocket's
!> radial mid-plane through the cage centre C, adore_cage_step0's roller_pocket_contacts):
!> the roller's offset from the mid-plane d_t = r sin(phi - psi) - C . e_t(psi) (psi the
!> pocket azimuth; C = 0 for a centred cage), each wall's interference
!> along the roller axis -(c/2 -+ (d_t - zeta x)) on slices, Palmgren slice loads in the
!> roller/cage contact modulus, Coulomb friction mu (Rec 10.5.1B A) against the sliding of
!> the roller surface over the wall (regularised below SLIP_REG).  Units SI.
module adore_forces_roller_bearing
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: cross
   use adore_contact_line_slices, only: line_contact_t, profile_drop, line_stiffness, roller_profile_t
   use adore_quasistatic_roller_equilibrium, only: roller_qs_bearing_t, roller_contacts
   use adore_tribology_traction_law, only: traction_law_t, law_kappa
   use adore_tribology_roller_traction, only: roller_spin_t, line_slip, RACE_OUTER, RACE_INNER
   use adore_contact_roller_flange, only: roller_flange_set_t, flange_contact_t, flange_contact
   implicit none
   private

   public :: roller_force_model_t, roller_pose_t, race_pose_t, roller_loads_t
   public :: roller_loads, orbit_axes, cylindrical_pocket_loads

   integer, parameter, public :: POCKET_SLICES = 8
   integer, parameter, public :: MAX_FLANGES = 4   !< two ends x two races
   real(wp), parameter :: SLIP_REG = 1.0e-3_wp   !< friction regularisation speed (m/s)

   !> What does not change with the state.
   type :: roller_force_model_t
      type(roller_qs_bearing_t) :: qs            !< slice contact model of step 0
      type(traction_law_t) :: law                !< the run's traction law
      real(wp) :: damping = 0.0_wp               !< beta (s) of the normal damping
      real(wp) :: speed(2) = 0.0_wp              !< outer, inner race speed (rad/s)
      real(wp) :: misalignment(2) = 0.0_wp       !< inner race theta_2, theta_3 (rad)
      real(wp) :: gravity(3) = 0.0_wp            !< (m/s**2)
      real(wp) :: mass = 0.0_wp                  !< roller mass (kg)
      logical :: pocket = .true.                 !< pocket contacts on
      real(wp) :: pocket_clearance = 0.0_wp      !< total tangential play of a pocket (m)
      real(wp) :: pocket_length = 0.0_wp         !< length of the roller touching a pocket wall (m)
      real(wp) :: pocket_k = 0.0_wp              !< Palmgren slice constant roller/cage (N/m**(19/9))
      real(wp) :: pocket_friction = 0.0_wp       !< Coulomb coefficient (Rec 10.5.1B A)
      type(roller_flange_set_t) :: flanges       !< roller end / flange contacts (none allocated: no flanges)
      integer :: pocket_type = 0                 !< kPocType: 0 rectangular, -1 cylindrical (report 4.4.11)
      real(wp) :: pocket_radius = 0.0_wp         !< radius of the pockets' centres (the cylindrical pocket's axis, m)
   end type roller_force_model_t

   !> One roller's state in its orbit frame.
   type :: roller_pose_t
      real(wp) :: x = 0.0_wp, r = 0.0_wp, phi = 0.0_wp           !< (m, m, rad)
      real(wp) :: xdot = 0.0_wp, rdot = 0.0_wp, phidot = 0.0_wp  !< (m/s, m/s, rad/s)
      real(wp) :: tilt = 0.0_wp, skew = 0.0_wp                   !< gamma, zeta (rad)
      real(wp) :: tiltdot = 0.0_wp, skewdot = 0.0_wp             !< (rad/s), orbit frame
      real(wp) :: spin = 0.0_wp                                  !< W relative to the orbit frame (rad/s)
   end type roller_pose_t

   !> The inner race and the cage as one roller sees them.
   type :: race_pose_t
      real(wp) :: position(3) = 0.0_wp, velocity(3) = 0.0_wp    !< inner race centre (m, m/s)
      real(wp) :: pocket_azimuth = 0.0_wp                        !< psi of the roller's pocket (rad)
      real(wp) :: cage_speed = 0.0_wp                            !< cage angular speed about x (rad/s)
      real(wp) :: cage_position(3) = 0.0_wp                      !< cage centre, inertial (m; 0 for a centred cage)
      real(wp) :: cage_velocity(3) = 0.0_wp                      !< cage centre velocity, inertial (m/s)
      !> the cage's axis (1, a_y, a_z): its small tilt, inertial transverse components (rad)
      real(wp) :: cage_tilt(2) = 0.0_wp
      !> the cage's angular velocity normal to its axis, inertial (0, w_y, w_z) (rad/s)
      real(wp) :: cage_omega_t(3) = 0.0_wp
   end type race_pose_t

   !> The loads of one roller.  Forces and moments on the roller in orbit-frame components
   !> (x, r, t); reactions on the races and the cage inertial (N, N m about the bearing axis
   !> point of the body's centre plane).
   type :: roller_loads_t
      type(line_contact_t) :: c(2)               !< outer, inner slice contacts
      real(wp) :: load(2) = 0.0_wp               !< damped normal loads (N)
      real(wp), allocatable :: traction(:, :, :) !< (slice, t/x, race) traction on the race (N/m)
      real(wp), allocatable :: slip(:, :, :)     !< (slice, t/x, race) slip (m/s)
      real(wp) :: power(2) = 0.0_wp              !< race contact losses (W), eq 4
      real(wp) :: sliding(2) = 0.0_wp            !< sum w |u| q (N m/s)
      real(wp) :: max_slip(2) = 0.0_wp           !< largest |u| (m/s)
      real(wp) :: pocket_load(2) = 0.0_wp        !< wall at -e_t (end 1), +e_t (end 2) (N)
      real(wp) :: pocket_gap(2) = 0.0_wp         !< geometric gap at the pocket centre plane (m; < 0 interference)
      real(wp) :: pocket_power = 0.0_wp          !< pocket friction loss (W)
      real(wp) :: flange_load(MAX_FLANGES) = 0.0_wp   !< damped normal load of each flange of the set (N)
      real(wp) :: flange_axial(MAX_FLANGES) = 0.0_wp  !< its axial component on the roller (N)
      real(wp) :: flange_height(MAX_FLANGES) = 0.0_wp !< its contact height from the raceway (m)
      real(wp) :: flange_power = 0.0_wp          !< flange contacts' traction loss (W)
      real(wp) :: flange_race_power(2) = 0.0_wp  !< its part at the outer, inner race's flanges (W)
      logical :: flange_off_face = .false.       !< a loaded contact point off the face or the end's cap
      real(wp) :: force(3) = 0.0_wp              !< on the roller, (x, r, t) (N)
      real(wp) :: moment(3) = 0.0_wp             !< on the roller about its centre, (x, r, t) (N m)
      real(wp) :: race_force(3, 2) = 0.0_wp      !< on the outer, inner race, inertial (N)
      real(wp) :: race_torque(2) = 0.0_wp        !< about the bearing axis on outer, inner race (N m)
      real(wp) :: cage_torque = 0.0_wp           !< pocket contact torque on the cage about its centre's x axis (N m)
      real(wp) :: cage_force(3) = 0.0_wp         !< pocket contact force on the cage, inertial (N)
      !> the pocket reactions' moment on the cage about its centre, inertial (N m; its x
      !> component is cage_torque)
      real(wp) :: cage_moment(3) = 0.0_wp
   end type roller_loads_t

contains

   !> e_r and e_t (inertial) at azimuth phi (rad).
   pure subroutine orbit_axes(phi, e_r, e_t)
      real(wp), intent(in) :: phi
      real(wp), intent(out) :: e_r(3), e_t(3)
      e_r = [0.0_wp, -sin(phi), cos(phi)]
      e_t = [0.0_wp, -cos(phi), -sin(phi)]
   end subroutine orbit_axes

   !> All loads of roller p with the inner race and cage of a (module header).
   pure subroutine roller_loads(m, p, a, ld)
      type(roller_force_model_t), intent(in) :: m
      type(roller_pose_t), intent(in) :: p
      type(race_pose_t), intent(in) :: a
      type(roller_loads_t), intent(out) :: ld
      type(roller_qs_bearing_t) :: qs
      real(wp) :: e_r(3), e_t(3), e_x(3), u_r, ur_dot, t_r, v_t, hdot(2, 2), f_t, f_x, rho, s, kap, umag
      real(wp) :: f(3)
      type(roller_spin_t) :: k
      integer :: j, i, n

      e_x = [1.0_wp, 0.0_wp, 0.0_wp]
      call orbit_axes(p%phi, e_r, e_t)
      u_r = dot_product(a%position, e_r)
      ur_dot = dot_product(a%velocity, e_r)
      t_r = -(m%misalignment(1)*cos(p%phi) + m%misalignment(2)*sin(p%phi))
      qs = m%qs
      ! permissible contact ends in roller coordinates: the races' ends move by the roller's
      ! axial offset, the roller's ends stay
      qs%lim_o = shifted(qs%lim_o, p%x)
      qs%lim_i = shifted(qs%lim_i, p%x - a%position(1))
      call roller_contacts(qs, p%r, p%tilt, u_r, t_r, p%skew, ld%c(1), ld%c(2))
      hdot(:, 1) = [p%rdot, p%tiltdot]
      hdot(:, 2) = [ur_dot - p%rdot, -p%tiltdot]
      n = 0
      if (allocated(ld%c(1)%x)) n = size(ld%c(1)%x)
      allocate (ld%traction(n, 2, 2), ld%slip(n, 2, 2))
      ld%traction = 0.0_wp
      ld%slip = 0.0_wp
      ! normal loads: outer pushes the roller along -e_r, inner along +e_r; moments about e_t
      do j = 1, 2
         associate (c => ld%c(j))
            s = merge(1.0_wp, -1.0_wp, j == 1)
            if (.not. c%in_contact) cycle
            ld%load(j) = max(c%load + m%damping*(c%k0*hdot(1, j) + c%k1*hdot(2, j)), 0.0_wp)
            ld%force(2) = ld%force(2) - s*ld%load(j)
            if (ld%load(j) > 0.0_wp) ld%moment(3) = ld%moment(3) - s*(c%moment + m%damping*(c%k1*hdot(1, j) + &
                                                                                          c%k2*hdot(2, j)))
         end associate
      end do
      ! traction by slices
      v_t = dot_product(a%velocity, e_t)
      do j = 1, 2
         associate (c => ld%c(j))
            if (.not. c%in_contact) cycle
            s = merge(1.0_wp, -1.0_wp, j == 1)
            k%d = m%qs%d
            k%spin = p%spin
            k%race_speed = [m%speed(1) - p%phidot, m%speed(2) - p%phidot]
            ! the land's pure rolling on the race point at radius r +- D/2 (line_slip adds the
            ! profile drop to both surfaces)
            if (j == 1) then
               k%rolling_spin = k%race_speed(1)*(p%r + 0.5_wp*m%qs%d)/(0.5_wp*m%qs%d)
            else
               k%rolling_spin = -k%race_speed(2)*(p%r - 0.5_wp*m%qs%d)/(0.5_wp*m%qs%d)
            end if
            do i = 1, n
               if (.not. (c%q(i) > 0.0_wp)) cycle
               rho = 0.5_wp*m%qs%d - profile_drop(m%qs%profile, c%x(i))
               ld%slip(i, 1, j) = line_slip(m%qs%profile, k, merge(RACE_OUTER, RACE_INNER, j == 1), c%x(i)) &
                                  - p%skewdot*c%x(i) - merge(0.0_wp, v_t, j == 1)
               ld%slip(i, 2, j) = s*(p%skew*p%spin*rho - p%tiltdot*rho) + p%xdot - merge(0.0_wp, a%velocity(1), j == 1)
               umag = hypot(ld%slip(i, 1, j), ld%slip(i, 2, j))
               if (umag <= 0.0_wp) cycle
               kap = law_kappa(m%law, umag)
               ! q scaled by the damped load (the damping acts on the whole contact)
               ld%traction(i, :, j) = kap*c%q(i)*(ld%load(j)/c%load)*ld%slip(i, :, j)/umag
               ld%power(j) = ld%power(j) + c%weight(i)*kap*umag*c%q(i)*(ld%load(j)/c%load)
               ld%sliding(j) = ld%sliding(j) + c%weight(i)*umag*c%q(i)
               ld%max_slip(j) = max(ld%max_slip(j), umag)
               f_t = -c%weight(i)*ld%traction(i, 1, j)     ! on the roller
               f_x = -c%weight(i)*ld%traction(i, 2, j)
               ld%force(3) = ld%force(3) + f_t
               ld%force(1) = ld%force(1) + f_x
               ! moment of (f_x e_x + f_t e_t) at x e_x + s rho e_r
               ld%moment(1) = ld%moment(1) + s*rho*f_t
               ld%moment(2) = ld%moment(2) - c%x(i)*f_t
               ld%moment(3) = ld%moment(3) - s*rho*f_x
               ! the race's torque about the axis: its point at radius r + s rho
               ld%race_torque(j) = ld%race_torque(j) - (p%r + s*rho)*f_t
            end do
         end associate
      end do
      ! reactions on the races (inertial)
      do j = 1, 2
         s = merge(1.0_wp, -1.0_wp, j == 1)
         f = s*ld%load(j)*e_r
         if (allocated(ld%c(j)%weight)) f = f + sum(ld%c(j)%weight*ld%traction(:, 1, j))*e_t + &
                                            sum(ld%c(j)%weight*ld%traction(:, 2, j))*e_x
         ld%race_force(:, j) = f
      end do
      ! gravity
      ld%force = ld%force + m%mass*[m%gravity(1), dot_product(m%gravity, e_r), dot_product(m%gravity, e_t)]
      if (m%pocket .and. m%pocket_type == 0) call pocket_with_cage_moment(m, p, a, e_r, e_t, ld)
      if (m%pocket .and. m%pocket_type == -1) call cylindrical_pocket_loads(m, p, a, ld)
      if (allocated(m%flanges%flange)) call flange_loads(m, p, a, e_r, e_t, ld)
   contains
      pure function shifted(lim, dx) result(l2)
         real(wp), intent(in) :: lim(2), dx
         real(wp) :: l2(2)
         l2 = [max(lim(1) - dx, -0.5_wp*m%qs%profile%length), min(lim(2) - dx, 0.5_wp*m%qs%profile%length)]
      end function shifted
   end subroutine roller_loads

   !> The roller in its rectangular pocket (module header): loads of both walls by slices,
   !> friction, the reactions' torque on the cage.
   pure subroutine pocket_loads(m, p, a, e_r, e_t, ld)
      type(roller_force_model_t), intent(in) :: m
      type(roller_pose_t), intent(in) :: p
      type(race_pose_t), intent(in) :: a
      real(wp), intent(in) :: e_r(3), e_t(3)
      type(roller_loads_t), intent(inout) :: ld
      real(wp) :: d_t, xs, w, delta, q, v(2), vmag, fr(2), fn, mom_r, pt(3), fc(3), beta_r, skew, wall(3)
      integer :: end, i
      real(wp) :: sgn

      d_t = p%r*sin(p%phi - a%pocket_azimuth) + a%cage_position(2)*cos(a%pocket_azimuth) + &
            a%cage_position(3)*sin(a%pocket_azimuth)
      ! a tilted cage (axis (1, a_y, a_z), rotation vector (0, -a_z, a_y)) turns its walls about
      ! the pocket's radial axis by beta_r: the wall at axial distance X from the cage centre
      ! moves by -X beta_r along e_t, the roller's offset from it grows by X beta_r
      beta_r = a%cage_tilt(1)*cos(a%pocket_azimuth) + a%cage_tilt(2)*sin(a%pocket_azimuth)
      skew = p%skew
      if (beta_r /= 0.0_wp) then
         d_t = d_t + (p%x - a%cage_position(1))*beta_r
         skew = p%skew - beta_r
      end if
      w = m%pocket_length/POCKET_SLICES
      ! end 1: the wall on the -e_t side, end 2: on the +e_t side (adore_cage_step0)
      ld%pocket_gap = [0.5_wp*m%pocket_clearance + d_t, 0.5_wp*m%pocket_clearance - d_t]
      do end = 1, 2
         sgn = merge(-1.0_wp, 1.0_wp, end == 1)    ! side of the wall along e_t
         fn = 0.0_wp
         mom_r = 0.0_wp
         do i = 1, POCKET_SLICES
            xs = -0.5_wp*m%pocket_length + (real(i, wp) - 0.5_wp)*w
            delta = sgn*(d_t - skew*xs) - 0.5_wp*m%pocket_clearance
            if (delta <= 0.0_wp) cycle
            q = m%pocket_k*delta**(10.0_wp/9.0_wp)*w
            fn = fn + q
            ! force -sgn q e_t at x e_x: moment about e_r = sgn x q (x e_x cross e_t = -e_r)
            mom_r = mom_r + sgn*xs*q
         end do
         ld%pocket_load(end) = fn
         if (fn <= 0.0_wp) cycle
         ld%force(3) = ld%force(3) - sgn*fn
         ld%moment(2) = ld%moment(2) + mom_r
         if (beta_r /= 0.0_wp) then
            ! the tilted wall's normal e_t + beta_r e_x: its axial part, at sgn D/2 e_t
            ld%force(1) = ld%force(1) - sgn*fn*beta_r
            ld%moment(2) = ld%moment(2) - 0.5_wp*m%qs%d*fn*beta_r
         end if
         ! sliding of the roller surface at sgn D/2 e_t over the wall: radial rdot - sgn (W_abs -
         ! w_cage) D/2, axial xdot
         v = [p%xdot - a%cage_velocity(1), p%rdot - dot_product(a%cage_velocity, e_r) - &
              sgn*(p%spin + p%phidot - a%cage_speed)*0.5_wp*m%qs%d]
         if (any(a%cage_omega_t /= 0.0_wp)) then
            ! the wall point's velocity from the cage's transverse rotation
            wall = cross(a%cage_omega_t, [p%x - a%cage_position(1), 0.0_wp, 0.0_wp] + p%r*e_r + &
                         sgn*0.5_wp*m%qs%d*e_t - [0.0_wp, a%cage_position(2), a%cage_position(3)])
            v = v - [wall(1), dot_product(wall, e_r)]
         end if
         vmag = hypot(v(1), v(2))
         fr = -m%pocket_friction*fn*v/sqrt(vmag**2 + SLIP_REG**2)
         ld%pocket_power = ld%pocket_power + m%pocket_friction*fn*vmag**2/sqrt(vmag**2 + SLIP_REG**2)
         ld%force(1) = ld%force(1) + fr(1)
         ld%force(2) = ld%force(2) + fr(2)
         ! moments of the friction at sgn D/2 e_t: (sgn D/2 e_t) x (fr_x e_x + fr_r e_r)
         ld%moment(1) = ld%moment(1) - sgn*0.5_wp*m%qs%d*fr(2)
         ld%moment(2) = ld%moment(2) + sgn*0.5_wp*m%qs%d*fr(1)
         ! reaction on the cage at the contact point (torque about the cage centre's x axis)
         pt = p%r*e_r + sgn*0.5_wp*m%qs%d*e_t - a%cage_position
         fc = sgn*fn*e_t - fr(2)*e_r - fr(1)*[1.0_wp, 0.0_wp, 0.0_wp]
         if (beta_r /= 0.0_wp) fc(1) = fc(1) + sgn*fn*beta_r
         ld%cage_torque = ld%cage_torque + dot_product(cross(pt, fc), [1.0_wp, 0.0_wp, 0.0_wp])
         ld%cage_force = ld%cage_force + fc
      end do
   end subroutine pocket_loads

   !> The rectangular pocket's loads (pocket_loads) and the moment of their reactions on the
   !> cage about its centre C (ld%cage_moment, inertial, N m): minus the pocket's force F and
   !> moment M on the roller moved from the roller centre R to C, -(M + (R - C) x F) - the
   !> normal loads' axial lever arms on a tilted or axially displaced cage included.
   pure subroutine pocket_with_cage_moment(m, p, a, e_r, e_t, ld)
      type(roller_force_model_t), intent(in) :: m
      type(roller_pose_t), intent(in) :: p
      type(race_pose_t), intent(in) :: a
      real(wp), intent(in) :: e_r(3), e_t(3)
      type(roller_loads_t), intent(inout) :: ld
      real(wp) :: f0(3), m0(3), df(3), dm(3), rc(3)
      f0 = ld%force
      m0 = ld%moment
      call pocket_loads(m, p, a, e_r, e_t, ld)
      df = ld%force - f0
      dm = ld%moment - m0
      df = df(1)*[1.0_wp, 0.0_wp, 0.0_wp] + df(2)*e_r + df(3)*e_t
      dm = dm(1)*[1.0_wp, 0.0_wp, 0.0_wp] + dm(2)*e_r + dm(3)*e_t
      rc = [p%x, 0.0_wp, 0.0_wp] + p%r*e_r - a%cage_position
      ld%cage_moment = -(dm + cross(rc, df))
   end subroutine pocket_with_cage_moment

   !> The roller in its cylindrical pocket (kPocType -1, report 4.4.11: a roller guided cage):
   !> the pocket a cylinder of diameter D + c (c the pocket clearance, Rec 7.1) whose axis is
   !> the cage's pocket axis: through P0 = C + R_p e_r(psi) (C the cage centre, R_p the pocket
   !> radius, psi the pocket's azimuth; P0 shifted axially by the tilt, R_p (a_y sin psi -
   !> a_z cos psi)), along the cage's axis (1, a_y, a_z) (small tilt; for the centred cage the
   !> bearing axis).  In the roller's orbit frame, on POCKET_SLICES slices over the roller
   !> length less its corner radii, the roller axis is offset from the pocket axis by
   !> e(x) = (r - R_p cos(phi - psi) + gamma x - C_r - d_x a_r, R_p sin(phi - psi) - zeta x -
   !> C_t - d_x a_t), with C_r, C_t the cage centre's and a_r, a_t the cage axis' orbit-frame
   !> components and d_x the slice's axial distance from P0; the slice interference is
   !> |e| - c/2 along n = e/|e| made normal to the pocket axis (its axial part -(n_r a_r +
   !> n_t a_t)) (the conformal internal line contact: the same Palmgren slice law in the
   !> roller/cage contact modulus as the rectangular pocket's walls).  Friction: Coulomb mu
   !> (Rec 10.5.1B A) against the sliding of the roller surface over the pocket, axially xdot
   !> and around the pocket tau = e_x x n: (rdot, r (phidot - w_c)) . tau + (W_abs - w_c) D/2,
   !> less the cage's own motion at the contact point (its centre's velocity, its transverse
   !> rotation, and w_c e_x x (-C)), regularised below SLIP_REG.  The reactions on the cage:
   !> force, moment about C (inertial), torque about C's x axis.  pocket_load and pocket_gap:
   !> end 1 the slices at x < 0, end 2 those at x > 0 (load, N) and the least gap of each half (m).
   pure subroutine cylindrical_pocket_loads(m, p, a, ld)
      type(roller_force_model_t), intent(in) :: m
      type(roller_pose_t), intent(in) :: p
      type(race_pose_t), intent(in) :: a
      type(roller_loads_t), intent(inout) :: ld
      real(wp) :: w, xs, e(2), emag, n(3), tau(3), delta, q, v(2), vmag, fx, ft, f(3), pt(3), mom(3)
      real(wp) :: e_r(3), e_t(3), c_r, c_t, a_r, a_t, p0x, f_in(3), pt_in(3), u_c(3), tau_in(3)
      logical :: moving_cage
      integer :: i, h
      call orbit_axes(p%phi, e_r, e_t)
      c_r = dot_product(a%cage_position, e_r)
      c_t = dot_product(a%cage_position, e_t)
      a_r = dot_product([0.0_wp, a%cage_tilt], e_r)
      a_t = dot_product([0.0_wp, a%cage_tilt], e_t)
      p0x = a%cage_position(1) + m%pocket_radius*(a%cage_tilt(1)*sin(a%pocket_azimuth) - &
                                                  a%cage_tilt(2)*cos(a%pocket_azimuth))
      moving_cage = any(a%cage_position /= 0.0_wp) .or. any(a%cage_velocity /= 0.0_wp) .or. &
                    any(a%cage_omega_t /= 0.0_wp)
      w = m%pocket_length/POCKET_SLICES
      ld%pocket_gap = huge(1.0_wp)
      do i = 1, POCKET_SLICES
         xs = -0.5_wp*m%pocket_length + (real(i, wp) - 0.5_wp)*w
         h = merge(1, 2, xs < 0.0_wp)
         e = [p%r - m%pocket_radius*cos(p%phi - a%pocket_azimuth) + p%tilt*xs, &
              m%pocket_radius*sin(p%phi - a%pocket_azimuth) - p%skew*xs]
         e = e - [c_r, c_t] - (p%x + xs - p0x)*[a_r, a_t]
         emag = norm2(e)
         ld%pocket_gap(h) = min(ld%pocket_gap(h), 0.5_wp*m%pocket_clearance - emag)
         delta = emag - 0.5_wp*m%pocket_clearance
         if (delta <= 0.0_wp .or. emag <= 0.0_wp) cycle
         q = m%pocket_k*delta**(10.0_wp/9.0_wp)*w
         n = [-(e(1)*a_r + e(2)*a_t)/emag, e(1)/emag, e(2)/emag]
         tau = [0.0_wp, -n(3), n(2)]
         ld%pocket_load(h) = ld%pocket_load(h) + q
         ! sliding of the roller surface over the pocket: axial, around the pocket
         v = [p%xdot, p%rdot*tau(2) + p%r*(p%phidot - a%cage_speed)*tau(3) + &
              (p%spin + p%phidot - a%cage_speed)*0.5_wp*m%qs%d]
         pt_in = (p%x + xs)*[1.0_wp, 0.0_wp, 0.0_wp] + (p%r + 0.5_wp*m%qs%d*n(2))*e_r + 0.5_wp*m%qs%d*n(3)*e_t
         if (moving_cage) then
            ! the cage's own motion at the contact point beyond its turning about the bearing axis
            u_c = a%cage_velocity + cross(a%cage_omega_t, pt_in - a%cage_position) - &
                  cross([a%cage_speed, 0.0_wp, 0.0_wp], a%cage_position)
            tau_in = tau(2)*e_r + tau(3)*e_t
            v = v - [u_c(1), dot_product(u_c, tau_in)]
         end if
         vmag = hypot(v(1), v(2))
         fx = -m%pocket_friction*q*v(1)/sqrt(vmag**2 + SLIP_REG**2)
         ft = -m%pocket_friction*q*v(2)/sqrt(vmag**2 + SLIP_REG**2)
         ld%pocket_power = ld%pocket_power + m%pocket_friction*q*vmag**2/sqrt(vmag**2 + SLIP_REG**2)
         f = -q*n + fx*[1.0_wp, 0.0_wp, 0.0_wp] + ft*tau
         ld%force = ld%force + f
         ! moment about the roller centre of f at x e_x + (D/2) n
         mom = cross([xs, 0.5_wp*m%qs%d*n(2), 0.5_wp*m%qs%d*n(3)], f)
         ld%moment = ld%moment + mom
         ! the reaction -f on the cage at the contact point: force, moment about the cage
         ! centre (inertial), its x part the torque about the cage centre's x axis
         f_in = f(1)*[1.0_wp, 0.0_wp, 0.0_wp] + f(2)*e_r + f(3)*e_t
         ld%cage_force = ld%cage_force - f_in
         mom = cross(pt_in - a%cage_position, -f_in)
         ld%cage_moment = ld%cage_moment + mom
         if (moving_cage) then
            ld%cage_torque = ld%cage_torque + mom(1)
         else
            pt = [xs, p%r + 0.5_wp*m%qs%d*n(2), 0.5_wp*m%qs%d*n(3)]
            ld%cage_torque = ld%cage_torque - (pt(2)*f(3) - pt(3)*f(2))
         end if
      end do
   end subroutine cylindrical_pocket_loads

   !> The roller's ends against the race flanges (adore_contact_roller_flange; docs/rollers.md,
   !> "Flanges"): each contact's Hertz load with the stiffness-proportional damping of the
   !> slices (beta k ddelta/dt, kept >= 0), its traction by the run's law against the sliding
   !> of the roller end over the flange, t = kappa(|u|) Q u/|u| opposing u; the force and its
   !> moment about the roller centre on the roller, the reaction on the race.
   pure subroutine flange_loads(m, p, a, e_r, e_t, ld)
      type(roller_force_model_t), intent(in) :: m
      type(roller_pose_t), intent(in) :: p
      type(race_pose_t), intent(in) :: a
      real(wp), intent(in) :: e_r(3), e_t(3)
      type(roller_loads_t), intent(inout) :: ld
      type(flange_contact_t) :: c
      real(wp) :: centre(3), axis(3), v(3), omega(3), o(3), v_o(3), w_o, q, um, kap, f(3)
      integer :: i, j
      centre = [p%x, p%r, 0.0_wp]
      axis = [1.0_wp, p%tilt, -p%skew]
      axis = axis/norm2(axis)
      v = [p%xdot, p%rdot, p%r*p%phidot]
      omega = [p%phidot + p%spin, p%spin*p%tilt + p%skewdot, -p%spin*p%skew + p%tiltdot]
      do i = 1, size(m%flanges%flange)
         j = m%flanges%flange(i)%race
         if (j == 1) then
            o = 0.0_wp
            v_o = 0.0_wp
         else
            o = [a%position(1), dot_product(a%position, e_r), dot_product(a%position, e_t)]
            v_o = [a%velocity(1), dot_product(a%velocity, e_r), dot_product(a%velocity, e_t)]
         end if
         w_o = m%speed(j)
         call flange_contact(m%flanges, m%flanges%flange(i), centre, axis, v, omega, o, v_o, w_o, c)
         if (.not. (c%delta > 0.0_wp)) cycle
         q = max(c%load + m%damping*c%stiffness*c%rate, 0.0_wp)
         ld%flange_load(i) = q
         ld%flange_height(i) = c%height
         if (q <= 0.0_wp) cycle
         if (.not. c%on_face) ld%flange_off_face = .true.
         f = q*c%normal
         um = norm2(c%slip)
         if (um > 0.0_wp) then
            kap = law_kappa(m%law, um)
            f = f - kap*q*c%slip/um
            ld%flange_power = ld%flange_power + kap*q*um
            ld%flange_race_power(j) = ld%flange_race_power(j) + kap*q*um
         end if
         ld%flange_axial(i) = f(1)
         ld%force = ld%force + f
         ld%moment = ld%moment + cross(c%point - centre, f)
         ! the reaction -f on the race at the contact point (inertial; torque about the axis)
         ld%race_force(:, j) = ld%race_force(:, j) - (f(1)*[1.0_wp, 0.0_wp, 0.0_wp] + f(2)*e_r + f(3)*e_t)
         ld%race_torque(j) = ld%race_torque(j) - (c%point(2)*f(3) - c%point(3)*f(2))
      end do
   end subroutine flange_loads

end module adore_forces_roller_bearing
