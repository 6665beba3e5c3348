!> The cage at step 0 (ADORE section 4.4.4 cage initial conditions, 4.4.8 guide lands,
!> 4.4.11 pockets): its initial state from Rec 9.5.1 and the geometric interactions of the
!> rolling elements with the pockets and of the cage with the guide lands.  Pure geometry:
!> no contact forces (cage friction, Rec 10.5.x, and the contact stiffness are later work).
!>
!> Definitions, inferred from the report's step-0 prints (Appendix C ball, Appendix D
!> roller; the report text gives none of them):
!> * Cage position (print: Mass Center Position axial, radial, orbital).  The Rec 9.5.1
!>   centre (y, z) is relative to the centre of the guiding race (guide type of land 1):
!>   ball, inner race guided: -6.0e-4 + inner race 1.0e-5 = -5.90e-4, printed radial
!>   5.900e-4 at orbital 180 deg.  Roller, outer race guided: +5.0e-5 (its pocket
!>   positions need exactly 5.0e-5).  Axially the cage sits at the mean axial position of
!>   the rolling elements plus the Rec 9.5.1 x (ball: mean ball centre 4.274e-5 from the
!>   outer groove centre plane vs printed 4.285e-5; with Rec x = 0 "plus x" is not tested).
!>   Orbital angle: azimuth of the centre, from +z towards -y (as the RE azimuths).
!> * Cage speeds (print: Orbital Velocity, Angular Velocity Amplitude).  The epicyclic
!>   velocity is the mean RE orbital speed of the quasi-static start (ball: golden mean of
!>   the printed ball speeds 9139.7 rpm, printed 9.140e3; the epicyclic formula at alpha0
!>   gives 8767); cage angular velocity = Rec 9.5.1 ratio 3 x epicyclic, about +x; whirl
!>   (mass centre orbital) velocity = ratio 2 x angular velocity: the centre starts on the
!>   circle through its Rec 9.5.1 position about the bearing axis, moving tangentially at
!>   whirl velocity x that radius (report 4.4.4: "mass center whirl velocity ... equal to its
!>   angular velocity").  Rec 9.5.1 field 1 ("cage_whirl_radius") is not that radius and
!>   is not used: ball 6.636e-4 m against the printed position 5.900e-4 m, roller 2.5e-4 m
!>   against 5.0e-5 m and a land radial clearance of 5.0e-5 m (taken as the radius it
!>   launched Appendix D's cage at 5x its whirl rate; docs/dynamics.md).
!> * Pocket frame of pocket k at azimuth psi (the RE's azimuth plus the cage rotation about
!>   x): origin on the cage at radius R_c = (cage OD + cage ID)/4 along the radial line psi
!>   through the cage centre; x_p axial, z_p radial outward, y_p = z_p x x_p (at psi = 0 the
!>   inertial axes).  Contact Pos X, Z are the contact point's x_p, z_p.
!> * Ball, cylindrical pocket (axis z_p, diameter D + pocket clearance I): with the ball
!>   centre at (p_x, p_y, p_z) in the pocket frame, Geo Int = c/2 - hypot(p_x, p_y) with
!>   c the diametral pocket clearance: POSITIVE = CLEARANCE (all 18 balls of Appendix C
!>   have zero force with positive values; ball 9: 6.0e-4 - hypot(2.018e-4, 1.46e-5) =
!>   3.977e-4, printed 3.977e-4).  Contact normal n = (p_x, p_y)/|.| (the nearest wall
!>   point), Con Ang THETA = angle about +z_p from y_p (n = (-sin theta, cos theta)):
!>   balls 1/10 (no tangential offset, ball axially ahead/behind the cage) print 270/90,
!>   balls 3-7 near 0, 11-18 near 180.  PHI = 0 (the normal of a cylinder is normal to its
!>   axis).  Contact point = centre + D/2 n; z_p = the ball centre's (ball 1: 1.544e-3).
!> * Roller, rectangular pocket (kPocType 0; the echo prints POCKET SHAPE 0): flat walls
!>   y_p = +-(D + c)/2; end 1 = the wall on +y_p, end 2 = the wall on -y_p in the frame
!>   turned 180 deg about x_p (the report prints +z for end 1 and -z for end 2 with equal
!>   magnitudes); Geo Int = c/2 -+ p_y, THETA = PHI = 0, contact (p_x, -+D/2.., p_z).
!>   The contact positions z match the report (2.157e-4 .. 3.124e-4), its one legible
!>   Geo Int (roller 2 end 1, 2.243e-5) does not (1.46e-5 / 8.54e-5): unresolved.
!> * Guide land (Rec 7.2.n): effective diametral play = land clearance - 2 x radial growth
!>   of the guiding race (mounting + centrifugal, the raceway growth of the mounting; the
!>   cage's own centrifugal growth is not included: the roller's printed play 1.000e-4
!>   equals its clearance although its cage spins at 28490 rpm); Geo Int = play/2 -
!>   |cage centre - race centre| (radial; no tilt at step 0): ball land 1
!>   7.5e-4 - 2.79e-5 - 6.0e-4 = 1.221e-4, printed 1.217e-4.  Positive = clearance.
module adore_cage_step0
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: guide_land_t, cage_input_t, cage_state_t, pocket_contact_t, land_contact_t
   public :: cage_step0_t, solve_cage_step0
   public :: cage_initial_state, pocket_frame, ball_pocket_contact, roller_pocket_contacts, land_contact
   public :: GUIDE_OUTER, GUIDE_INNER, POCKET_BALL, POCKET_RECTANGULAR

   integer, parameter :: GUIDE_OUTER = 1, GUIDE_INNER = 2     !< Rec 7.0 guide type of a land
   integer, parameter :: POCKET_BALL = 1          !< cylindrical pocket along the cage radius (ball)
   integer, parameter :: POCKET_RECTANGULAR = 2   !< flat-walled pocket (roller, kPocType 0)


   !> One cage guide land (Rec 7.0 guide type, Rec 7.2.n), SI.
   type :: guide_land_t
      integer :: guide = GUIDE_INNER
      real(wp) :: diameter = 0.0_wp, width = 0.0_wp, position = 0.0_wp
      real(wp) :: clearance = 0.0_wp     !< diametral (m)
   end type guide_land_t

   !> Cage initial conditions, Rec 9.5.1 (angles in rad).
   type :: cage_input_t
      real(wp) :: whirl_radius = 0.0_wp
      real(wp) :: whirl_ratio = 1.0_wp        !< whirl / angular velocity
      real(wp) :: epicyclic_ratio = 1.0_wp    !< angular / epicyclic velocity
      real(wp) :: centre(3) = 0.0_wp          !< x: from the mean RE axial position; y, z: from the guiding race
      real(wp) :: angle(3) = 0.0_wp           !< angular position about x, y, z
   end type cage_input_t

   !> The cage's initial state, inertial frame (m, rad, rad/s).
   type :: cage_state_t
      real(wp) :: centre(3) = 0.0_wp          !< geometric = mass centre (the echo's offsets are 0)
      real(wp) :: orbital_angle = 0.0_wp      !< azimuth of the centre, from +z towards -y
      real(wp) :: angle(3) = 0.0_wp
      real(wp) :: epicyclic_speed = 0.0_wp    !< mean RE orbital speed
      real(wp) :: angular_speed = 0.0_wp      !< about +x
      real(wp) :: whirl_speed = 0.0_wp        !< orbital speed of the centre
      real(wp) :: velocity(3) = 0.0_wp        !< mass centre velocity
   end type cage_state_t

   !> One RE/pocket geometric interaction (pocket frame).
   type :: pocket_contact_t
      real(wp) :: geo_int = 0.0_wp            !< > 0 clearance, < 0 interference (m)
      real(wp) :: theta = 0.0_wp, phi = 0.0_wp   !< contact angles (rad)
      real(wp) :: pos(3) = 0.0_wp             !< contact point x_p, y_p, z_p (m)
      !> touching or interfering (geo_int <= 0 within round-off), as for the lands: at zero
      !> gap the report's roller 3 end 2 carries 15.16 N (its cage row, docs/tribology.md)
      !> while roller 7 end 1, also at zero gap, prints 0; a zero gap is a contact whose force
      !> needs the cage contact model (not done)
      logical :: in_contact = .false.
      !> the contact's force (N) and friction loss (W) when a contact model computed them
      !> (the roller dynamics' pocket contacts); < 0: not computed (step 0)
      real(wp) :: force = -1.0_wp
      real(wp) :: loss = -1.0_wp
   end type pocket_contact_t

   !> One cage/land geometric interaction.
   type :: land_contact_t
      real(wp) :: geo_int = 0.0_wp            !< > 0 clearance (m)
      real(wp) :: effective_play = 0.0_wp     !< effective diametral play (m)
      real(wp) :: eccentricity = 0.0_wp       !< |cage - race centre| in the radial plane (m)
      !> touching or interfering (geo_int <= 0 within round-off): the report's roller lands,
      !> at zero gap here, print a force 0.2052 N and a loss 0.6903 W (= 0.05 x force x cage
      !> surface speed at the land, Rec 10.5.2B coefficient 0.05): a contact
      logical :: in_contact = .false.
   end type land_contact_t

   !> Everything about the cage at step 0.
   type :: cage_step0_t
      type(cage_state_t) :: state
      logical :: geometry_known = .true.      !< .false.: cage tilted (Rec 9.5.1 y/z angle), not modelled
      integer :: pocket_kind = POCKET_BALL
      !> (n_ends, n): one contact per ball, two (end 1, end 2) per roller
      type(pocket_contact_t), allocatable :: pocket(:, :)
      type(land_contact_t), allocatable :: land(:)
      !> the factor (0..1) the Rec 9.5.1 centre offset from the guiding race was scaled by so
      !> that no pocket or land interferes at the start (solve_cage_step0's open_start); 1: as
      !> the deck says
      real(wp) :: start_scale = 1.0_wp
   end type cage_step0_t

contains

   !> The cage's initial state (section 4.4.4): centre from Rec 9.5.1 relative to the guiding
   !> race centre race_centre (y, z) and the mean RE axial position mean_re_axial; speeds from
   !> the mean RE orbital speed mean_orbital (rad/s).
   pure function cage_initial_state(inp, race_centre, mean_re_axial, mean_orbital) result(st)
      type(cage_input_t), intent(in) :: inp
      real(wp), intent(in) :: race_centre(3), mean_re_axial, mean_orbital
      type(cage_state_t) :: st
      real(wp) :: a

      st%centre(1) = mean_re_axial + inp%centre(1)
      st%centre(2:3) = race_centre(2:3) + inp%centre(2:3)
      st%orbital_angle = modulo(atan2(-st%centre(2), st%centre(3)), 2.0_wp*pi)
      st%angle = inp%angle
      st%epicyclic_speed = mean_orbital
      st%angular_speed = inp%epicyclic_ratio*mean_orbital
      st%whirl_speed = inp%whirl_ratio*st%angular_speed
      ! x x radial(a): the centre moves in the sense of the rotation about +x
      a = st%orbital_angle
      st%velocity = st%whirl_speed*hypot(st%centre(2), st%centre(3))*[0.0_wp, -cos(a), -sin(a)]
   end function cage_initial_state

   !> Coordinates in the pocket frame at azimuth psi (rad) of the inertial point p, for a
   !> cage centred at c with pocket radius r_c (see the module header).
   pure function pocket_frame(c, r_c, psi, p) result(q)
      real(wp), intent(in) :: c(3), r_c, psi, p(3)
      real(wp) :: q(3), d(3)
      d = p - c
      q(1) = d(1)
      q(2) = d(2)*cos(psi) + d(3)*sin(psi)
      q(3) = -d(2)*sin(psi) + d(3)*cos(psi) - r_c
   end function pocket_frame

   !> Ball in a cylindrical pocket: ball centre q in the pocket frame, ball diameter d,
   !> diametral pocket clearance c (pocket diameter d + c).
   pure function ball_pocket_contact(q, d, c) result(k)
      real(wp), intent(in) :: q(3), d, c
      type(pocket_contact_t) :: k
      real(wp) :: rho, n(2)

      rho = hypot(q(1), q(2))
      n = [0.0_wp, 1.0_wp]
      if (rho > 0.0_wp) n = q(1:2)/rho
      k%geo_int = 0.5_wp*c - rho
      k%theta = modulo(atan2(-n(1), n(2)), 2.0_wp*pi)
      k%phi = 0.0_wp
      k%pos = [q(1) + 0.5_wp*d*n(1), q(2) + 0.5_wp*d*n(2), q(3)]
      k%in_contact = k%geo_int <= round_off(d + c)
   end function ball_pocket_contact

   !> Roller in a rectangular pocket (walls y_p = +-(d + c)/2): end 1 (wall +y_p) and end 2
   !> (wall -y_p, its frame turned 180 deg about x_p); q the roller centre in the pocket frame.
   pure function roller_pocket_contacts(q, d, c) result(k)
      real(wp), intent(in) :: q(3), d, c
      type(pocket_contact_t) :: k(2)

      k(1)%geo_int = 0.5_wp*c - q(2)
      k(1)%pos = [q(1), q(2) + 0.5_wp*d, q(3)]
      k(2)%geo_int = 0.5_wp*c + q(2)
      k(2)%pos = [q(1), -(q(2) - 0.5_wp*d), -q(3)]
      k%theta = 0.0_wp
      k%phi = 0.0_wp
      k%in_contact = k%geo_int <= round_off(d + c)
   end function roller_pocket_contacts

   !> Cage/land interaction: cage centre cage_c, guiding race centre race_c, radial growth
   !> of the race's land surface growth (m, outward +).
   pure function land_contact(land, cage_c, race_c, growth) result(k)
      type(guide_land_t), intent(in) :: land
      real(wp), intent(in) :: cage_c(3), race_c(3), growth
      type(land_contact_t) :: k

      if (land%guide == GUIDE_INNER) then
         k%effective_play = land%clearance - 2.0_wp*growth      ! the race land grows into the cage bore
      else
         k%effective_play = land%clearance + 2.0_wp*growth      ! outer race land: outward growth opens it
      end if
      k%eccentricity = hypot(cage_c(2) - race_c(2), cage_c(3) - race_c(3))
      k%geo_int = 0.5_wp*k%effective_play - k%eccentricity
      k%in_contact = k%geo_int <= round_off(land%diameter)
   end function land_contact

   !> Round-off scale of a gap between bodies of size size_m (m): a few ulps of the size.
   pure function round_off(size_m) result(t)
      real(wp), intent(in) :: size_m
      real(wp) :: t
      t = 64.0_wp*epsilon(1.0_wp)*abs(size_m)
   end function round_off

   !> Cage state and geometric interactions at step 0.
   !>
   !> re_centre(3, n): RE centres (inertial; x in the print's axial frame: for a ball bearing
   !> from the outer groove curvature centre plane); azimuth(n): pocket k holds RE k
   !> at azimuth(k); mean_orbital: mean RE orbital speed (rad/s); d: RE diameter;
   !> pocket_kind, pocket_clearance (diametral); cage_od, cage_id; lands; race_centre(3, 2)
   !> and race_growth(2): outer (1) and inner (2) race centres and land radial growths.
   !> open_start (default .false.): when the Rec 9.5.1 centre puts a rolling element into its
   !> pocket or the cage into a land (a Geo Int below zero: interpenetrating bodies, which no
   !> state of rigid bodies in contact has; report 4.4.12 rejects such a contact as abnormal),
   !> the centre's offset from the guiding race is scaled down, direction kept, to the largest
   !> factor that leaves every gap open (bisection to 1e-12; s%start_scale), the speeds from
   !> that centre (a free cage's dynamic start; docs/cage.md, "The cage's degrees of
   !> freedom").
   subroutine solve_cage_step0(inp, re_centre, azimuth, mean_orbital, d, pocket_kind, &
                               pocket_clearance, cage_od, cage_id, lands, race_centre, race_growth, s, error, &
                               open_start)
      type(cage_input_t), intent(in) :: inp
      real(wp), intent(in) :: re_centre(:, :), azimuth(:), mean_orbital, d
      integer, intent(in) :: pocket_kind
      real(wp), intent(in) :: pocket_clearance, cage_od, cage_id
      type(guide_land_t), intent(in) :: lands(:)
      real(wp), intent(in) :: race_centre(3, 2), race_growth(2)
      type(cage_step0_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: open_start

      integer :: n, k, guide, iter
      real(wp) :: r_c, q(3), p(3), nan, lo, hi
      type(cage_input_t) :: scaled

      n = size(azimuth)
      if (size(re_centre, 1) /= 3 .or. size(re_centre, 2) /= n .or. n < 1) then
         call input_error(error, "cage: need one rolling-element centre per pocket")
         return
      end if
      if (cage_od <= cage_id .or. cage_id <= 0.0_wp .or. d <= 0.0_wp .or. pocket_clearance < 0.0_wp) then
         call input_error(error, "cage: need 0 < cage ID < cage OD, an element diameter > 0 and a "// &
                          "pocket clearance >= 0 (Rec 7.1)")
         return
      end if
      if (pocket_kind /= POCKET_BALL .and. pocket_kind /= POCKET_RECTANGULAR) then
         call input_error(error, "cage: unknown pocket kind")
         return
      end if
      do k = 1, size(lands)
         if (lands(k)%guide /= GUIDE_OUTER .and. lands(k)%guide /= GUIDE_INNER) then
            call input_error(error, "cage: guide land type must be 1 (outer race) or 2 (inner race), Rec 7.0")
            return
         end if
         if (lands(k)%clearance < 0.0_wp) then
            call input_error(error, "cage: guide land clearance must be >= 0 (Rec 7.2.n)")
            return
         end if
      end do

      guide = GUIDE_INNER
      if (size(lands) > 0) guide = lands(1)%guide
      r_c = 0.25_wp*(cage_od + cage_id)
      call place(inp)
      if (.not. present(open_start)) return
      if (.not. open_start .or. .not. s%geometry_known .or. .not. interferes()) return
      ! the largest scale of the offset with every gap open (interference grows with the
      ! offset along its direction from the race, which carries the ball set's near centre)
      lo = 0.0_wp
      hi = 1.0_wp
      scaled = inp
      do iter = 1, 45
         scaled%centre(2:3) = 0.5_wp*(lo + hi)*inp%centre(2:3)
         call place(scaled)
         if (interferes()) then
            hi = 0.5_wp*(lo + hi)
         else
            lo = 0.5_wp*(lo + hi)
         end if
      end do
      scaled%centre(2:3) = lo*inp%centre(2:3)
      call place(scaled)
      s%start_scale = lo

   contains

      !> Whether a pocket or a land of s interferes (a Geo Int below zero).
      logical function interferes()
         interferes = any(s%pocket%geo_int < 0.0_wp)
         if (allocated(s%land)) interferes = interferes .or. any(s%land%geo_int < 0.0_wp)
      end function interferes

      !> s for the cage input c: the state, the pockets' and the lands' interactions.
      subroutine place(c)
         type(cage_input_t), intent(in) :: c
         if (allocated(s%pocket)) deallocate (s%pocket)
         if (allocated(s%land)) deallocate (s%land)
         s%state = cage_initial_state(c, race_centre(:, guide), sum(re_centre(1, :))/n, mean_orbital)
         s%pocket_kind = pocket_kind
         s%geometry_known = c%angle(2) == 0.0_wp .and. c%angle(3) == 0.0_wp

         if (pocket_kind == POCKET_BALL) then
            allocate (s%pocket(1, n))
         else
            allocate (s%pocket(2, n))
         end if
         do k = 1, n
            p = re_centre(:, k)
            q = pocket_frame(s%state%centre, r_c, azimuth(k) + c%angle(1), p)
            if (pocket_kind == POCKET_BALL) then
               s%pocket(1, k) = ball_pocket_contact(q, d, pocket_clearance)
            else
               s%pocket(:, k) = roller_pocket_contacts(q, d, pocket_clearance)
            end if
         end do
         if (.not. s%geometry_known) then
            nan = ieee_value(1.0_wp, ieee_quiet_nan)
            s%pocket%geo_int = nan
            s%pocket%theta = nan
            s%pocket%phi = nan
            do k = 1, 3
               s%pocket%pos(k) = nan
            end do
         end if

         allocate (s%land(size(lands)))
         do k = 1, size(lands)
            s%land(k) = land_contact(lands(k), s%state%centre, race_centre(:, lands(k)%guide), &
                                     race_growth(lands(k)%guide))
            if (.not. s%geometry_known) s%land(k)%geo_int = ieee_value(1.0_wp, ieee_quiet_nan)
         end do
      end subroutine place

   end subroutine solve_cage_step0

end module adore_cage_step0
