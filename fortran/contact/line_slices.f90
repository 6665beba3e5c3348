!> Roller/race line contact by slices (ADORE ADRC1 LineContact / NewContLmts, report
!> Appendix B).
!>
!> Along the roller axis (coordinate x, m, origin at the roller centre) the geometric
!> interaction of a roller with a race is
!>     delta(x) = h0 + h1 x + h2 x**2/2 - p(x) - x**2/(2 R_race_crown)
!> where h0 is the approach at the roller centre, h1 the relative tilt (roller tilt and
!> race misalignment), h2 the curvature of the approach (second-order skew term, see
!> adore_quasistatic_roller_equilibrium) and p(x) >= 0 the drop of the roller profile:
!> * central land |x| <= L_c/2: p = 0;
!> * crown (radius R_c) outside the land: p = (x**2 - (L_c/2)**2) / (2 R_c) - the crown
!>   arc is centred on the roller mid-plane and cut by the land.  This is the profile of
!>   ADORE 5.0: the Geo Int column of the report's section 1a (roller 1, both races)
!>   follows it to 2e-3 um, while an arc tangent to the land edge misses it by 0.8 um;
!> * corner radius r_k at end k: an extra drop r_k - sqrt(r_k**2 - s**2) over the last r_k
!>   of the length (s = distance into the corner zone), the corner face beyond.
!>
!> Contact length (NewContLmts): the two ends where delta = 0 are found by a coarse scan
!> and bisection between the permissible limits (roller ends, race land ends); the contact
!> zone is then cut into parts with the 4-point Gauss-Legendre rule in each.  ADORE's grid
!> xgl/wgl (n_sub = 3): zones of 1/4, 1/2 and 1/4 of the contact length - the report's
!> 12 slices (section 1a) sit at these Gauss points to the printed 4 digits; any other
!> n_sub gives n_sub equal zones (fine quadrature for checks).
!>
!> Slice load per unit length (constitutive relation of ADRC6, report Appendix B: the
!> load of a slice of reference length l_ref):
!>     q = K_L delta**(10/9),  K_L = (E*/E*_P) C_P**(-10/9) l_ref**(-1/9)
!> Palmgren's line-contact load-deflection (Palmgren, Ball and Roller Bearing
!> Engineering, 1959; Harris & Kotzalas eq. 6.41: delta[mm] = 3.84e-5 Q[N]**0.9 / l[mm]**0.8
!> for steel) evaluated for a slice of length l_ref and scaled linearly in the contact
!> modulus E* = 1/((1-nu1**2)/E1 + (1-nu2**2)/E2), referred to steel E = 206 GPa,
!> nu = 0.3 (E*_P).  ADORE calls ADRC6 with unit length in its dimensionless units, so
!> l_ref is the run's length scale (D/2).  With these K_L reproduces the report's slice
!> loads and deflections to 0.05 % (exponent 10/9 fitted from them: 1.1111).
!> Slice half width and peak pressure: Hertz line contact (Johnson, Contact Mechanics,
!> eq. 4.43): b = sqrt(4 q R'/(pi E*)), p0 = 2 q/(pi b), with R' the rolling-direction
!> equivalent radius.  Contact totals as ADRC1: Q = integral q dx, a = half contact
!> length, mean half width b_m = integral b dx / (2 a), stress Q/(pi a b_m).
!> Units SI: m, N, N/m, Pa.
module adore_contact_line_slices
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   implicit none
   private

   public :: roller_profile_t, line_contact_t
   public :: profile_drop, contact_modulus, line_stiffness, line_half_width, palmgren_load
   public :: line_contact, roller_mass, GAUSS_POINTS

   real(wp), parameter :: palmgren_c = 3.84e-5_wp*1.0e-3_wp*(1.0e3_wp)**(-0.8_wp)  !< SI: m N**-0.9 m**0.8
   real(wp), parameter :: palmgren_e_star = 2.06e11_wp/(2.0_wp*(1.0_wp - 0.3_wp**2))
   real(wp), parameter :: exponent = 10.0_wp/9.0_wp
   integer, parameter :: GAUSS_POINTS = 4
   real(wp), parameter :: gauss_x(4) = [-0.861136311594052575_wp, -0.339981043584856265_wp, &
                                        0.339981043584856265_wp, 0.861136311594052575_wp]
   real(wp), parameter :: gauss_w(4) = [0.347854845137453857_wp, 0.652145154862546143_wp, &
                                        0.652145154862546143_wp, 0.347854845137453857_wp]

   !> Axial profile of a roller (m).
   type :: roller_profile_t
      real(wp) :: length = 0.0_wp           !< roller length L
      real(wp) :: land = 0.0_wp             !< central flat land length L_c
      real(wp) :: crown_radius = 1.0e10_wp  !< roller crown radius R_c
      real(wp) :: corner(2) = 0.0_wp        !< corner radii at the -x and +x ends
   end type roller_profile_t

   !> One roller/race line contact.
   type :: line_contact_t
      logical :: in_contact = .false.
      real(wp) :: limits(2) = 0.0_wp        !< contact zone ends x1 < x2 (m)
      real(wp) :: half_length = 0.0_wp      !< a = (x2 - x1)/2 (m)
      real(wp) :: load = 0.0_wp             !< Q = integral q dx (N)
      real(wp) :: moment = 0.0_wp           !< integral q x dx (N m)
      real(wp) :: k0 = 0.0_wp, k1 = 0.0_wp, k2 = 0.0_wp, k3 = 0.0_wp, k4 = 0.0_wp
      !< integral dq/ddelta x**n dx, n = 0..4 (N/m, N, N m, N m**2, N m**3)
      real(wp) :: max_deflection = 0.0_wp   !< largest delta over the slices, or the scan if no contact (m)
      real(wp) :: mean_half_width = 0.0_wp  !< b_m (m)
      real(wp) :: stress = 0.0_wp           !< Q / (pi a b_m) (Pa)
      real(wp) :: peak_pressure = 0.0_wp    !< largest slice p0 (Pa)
      real(wp), allocatable :: x(:)         !< slice (grid point) positions (m)
      real(wp), allocatable :: weight(:)    !< quadrature weights (m)
      real(wp), allocatable :: delta(:)     !< geometric interaction (m)
      real(wp), allocatable :: q(:)         !< load per unit length (N/m)
      real(wp), allocatable :: b(:)         !< Hertz half width (m)
   end type line_contact_t

contains

   !> Profile drop p(x) >= 0 (m) of roller profile p at axial position x (m); see the module
   !> header (land, crown arc centred on the mid-plane, corner radii).  Beyond the ends the
   !> drop is huge (no material).
   elemental function profile_drop(p, x) result(drop)
      type(roller_profile_t), intent(in) :: p
      real(wp), intent(in) :: x
      real(wp) :: drop
      real(wp) :: half, ax, s, rc
      integer :: k

      half = 0.5_wp*p%length
      ax = abs(x)
      drop = 0.0_wp
      if (ax > half) then
         drop = huge(1.0_wp)*1.0e-10_wp
         return
      end if
      if (ax > 0.5_wp*p%land) drop = (ax**2 - (0.5_wp*p%land)**2)/(2.0_wp*p%crown_radius)
      k = merge(1, 2, x < 0.0_wp)
      rc = p%corner(k)
      s = ax - (half - rc)
      if (rc > 0.0_wp .and. s > 0.0_wp) drop = drop + rc - sqrt(max(rc**2 - s**2, 0.0_wp))
   end function profile_drop

   !> Mass (kg) of a roller of diameter d (m) and density rho (kg/m**3) with the crowned
   !> profile p: rho integral pi (d/2 - p_crown(x))**2 dx, the land and crown only (corner
   !> radii not removed).  Reproduces the ADORE 5.0 echo mass of the Appendix D roller
   !> (1.28102e-3 vs 1.28108e-3 kg; the plain cylinder is 0.44 % heavier).
   pure function roller_mass(p, d, rho) result(m)
      type(roller_profile_t), intent(in) :: p
      real(wp), intent(in) :: d, rho
      real(wp) :: m
      type(roller_profile_t) :: crown_only
      real(wp) :: lo, hi, half, mid, x
      integer :: l, k, side
      integer, parameter :: panels = 64

      crown_only = p
      crown_only%corner = 0.0_wp
      m = 0.0_wp
      do side = -1, 1, 2          ! land half, then the crowned part, on each side
         do l = 1, panels + 1
            if (l == 1) then
               lo = 0.0_wp
               hi = min(0.5_wp*p%land, 0.5_wp*p%length)
            else
               lo = min(0.5_wp*p%land, 0.5_wp*p%length)
               lo = lo + (0.5_wp*p%length - lo)*real(l - 2, wp)/real(panels, wp)
               hi = min(0.5_wp*p%land, 0.5_wp*p%length)
               hi = hi + (0.5_wp*p%length - hi)*real(l - 1, wp)/real(panels, wp)
            end if
            half = 0.5_wp*(hi - lo)
            mid = 0.5_wp*(hi + lo)
            do k = 1, GAUSS_POINTS
               x = real(side, wp)*(mid + half*gauss_x(k))
               m = m + half*gauss_w(k)*pi*(0.5_wp*d - profile_drop(crown_only, x))**2
            end do
         end do
      end do
      m = rho*m
   end function roller_mass

   !> Contact modulus E* = 1/((1-nu1**2)/E1 + (1-nu2**2)/E2) (Pa).
   pure function contact_modulus(e1, nu1, e2, nu2) result(es)
      real(wp), intent(in) :: e1, nu1, e2, nu2
      real(wp) :: es
      es = 1.0_wp/((1.0_wp - nu1**2)/e1 + (1.0_wp - nu2**2)/e2)
   end function contact_modulus

   !> Slice stiffness constant K_L (N/m**(19/9)) of q = K_L delta**(10/9) for contact
   !> modulus e_star (Pa) and slice reference length l_ref (m): Palmgren scaled in E*.
   pure function line_stiffness(e_star, l_ref) result(k)
      real(wp), intent(in) :: e_star, l_ref
      real(wp) :: k
      k = (e_star/palmgren_e_star)*palmgren_c**(-exponent)*l_ref**(1.0_wp - exponent)
   end function line_stiffness

   !> Palmgren's closed form for a straight roller of effective length l (m) pressed by
   !> delta (m) (steel E* of Palmgren scaled to e_star, Pa): Q (N).
   pure function palmgren_load(e_star, delta, l) result(q)
      real(wp), intent(in) :: e_star, delta, l
      real(wp) :: q
      q = (e_star/palmgren_e_star)*(max(delta, 0.0_wp)*l**0.8_wp/palmgren_c)**exponent
   end function palmgren_load

   !> Hertz line contact half width b = sqrt(4 q R'/(pi E*)) (m) for load per unit
   !> length q (N/m), equivalent radius r_eq (m) and contact modulus e_star (Pa).
   pure function line_half_width(q, r_eq, e_star) result(b)
      real(wp), intent(in) :: q, r_eq, e_star
      real(wp) :: b
      b = sqrt(4.0_wp*max(q, 0.0_wp)*r_eq/(pi*e_star))
   end function line_half_width

   !> Line contact by slices (ADRC1 LineContact): contact limits, slice interactions,
   !> loads and half widths, totals and the stiffness integrals used by the Newton solvers.
   !>
   !> prof: roller profile; race_crown: race crown radius (m, 1e10 = straight);
   !> h(3): approach h0 (m), tilt h1 (rad), curvature h2 (1/m) of delta(x);
   !> lim(2): permissible contact ends (m); k_line: K_L (line_stiffness); r_eq: rolling
   !> direction equivalent radius (m); e_star: contact modulus (Pa); n_sub: number of
   !> zones, 4 Gauss points each (3: ADORE's grid, else equal zones).
   pure subroutine line_contact(prof, race_crown, h, lim, k_line, r_eq, e_star, n_sub, c)
      type(roller_profile_t), intent(in) :: prof
      real(wp), intent(in) :: race_crown, h(3), lim(2), k_line, r_eq, e_star
      integer, intent(in) :: n_sub
      type(line_contact_t), intent(out) :: c

      integer, parameter :: n_scan = 64
      real(wp) :: xs, ds, best, xbest, lo, hi, half, mid, xx, w, dq, qq
      integer :: k, l, n

      n = GAUSS_POINTS*max(n_sub, 1)
      allocate (c%x(n), c%weight(n), c%delta(n), c%q(n), c%b(n))
      c%x = 0.0_wp
      c%weight = 0.0_wp
      c%delta = 0.0_wp
      c%q = 0.0_wp
      c%b = 0.0_wp

      ! coarse scan for the largest interaction (coarse bounds of NewContLmts)
      best = -huge(1.0_wp)
      xbest = 0.0_wp
      do k = 0, n_scan
         xs = lim(1) + (lim(2) - lim(1))*real(k, wp)/real(n_scan, wp)
         ds = interaction(xs)
         if (ds > best) then
            best = ds
            xbest = xs
         end if
      end do
      if (lim(1) < 0.0_wp .and. lim(2) > 0.0_wp) then
         ds = interaction(0.0_wp)
         if (ds >= best) then
            best = ds
            xbest = 0.0_wp
         end if
      end if
      c%max_deflection = best
      if (best <= 0.0_wp) then
         c%limits = lim
         return
      end if

      ! contact ends: delta = 0 between the maximum and each permissible limit
      c%limits(1) = lim(1)
      if (interaction(lim(1)) <= 0.0_wp) c%limits(1) = root(lim(1), xbest)
      c%limits(2) = lim(2)
      if (interaction(lim(2)) <= 0.0_wp) c%limits(2) = root(lim(2), xbest)
      c%in_contact = .true.
      c%half_length = 0.5_wp*(c%limits(2) - c%limits(1))

      ! slices: zones x 4 Gauss points
      c%max_deflection = -huge(1.0_wp)
      do l = 1, max(n_sub, 1)
         call zone(l, lo, hi)
         half = 0.5_wp*(hi - lo)
         mid = 0.5_wp*(hi + lo)
         do k = 1, GAUSS_POINTS
            n = GAUSS_POINTS*(l - 1) + k
            xx = mid + half*gauss_x(k)
            w = half*gauss_w(k)
            c%x(n) = xx
            c%weight(n) = w
            c%delta(n) = interaction(xx)
            c%max_deflection = max(c%max_deflection, c%delta(n))
            qq = 0.0_wp
            dq = 0.0_wp
            if (c%delta(n) > 0.0_wp) then
               qq = k_line*c%delta(n)**exponent
               dq = exponent*qq/c%delta(n)
            end if
            c%q(n) = qq
            c%b(n) = line_half_width(qq, r_eq, e_star)
            c%load = c%load + w*qq
            c%moment = c%moment + w*qq*xx
            c%k0 = c%k0 + w*dq
            c%k1 = c%k1 + w*dq*xx
            c%k2 = c%k2 + w*dq*xx**2
            c%k3 = c%k3 + w*dq*xx**3
            c%k4 = c%k4 + w*dq*xx**4
            c%mean_half_width = c%mean_half_width + w*c%b(n)
            if (c%b(n) > 0.0_wp) c%peak_pressure = max(c%peak_pressure, 2.0_wp*qq/(pi*c%b(n)))
         end do
      end do
      c%mean_half_width = c%mean_half_width/(2.0_wp*c%half_length)
      if (c%mean_half_width > 0.0_wp) c%stress = c%load/(pi*c%half_length*c%mean_half_width)

   contains

      !> Ends (m) of slice zone l: ADORE's grid for n_sub = 3 (quarter, half, quarter of
      !> the contact length), equal zones otherwise.
      pure subroutine zone(l, z1, z2)
         integer, intent(in) :: l
         real(wp), intent(out) :: z1, z2
         real(wp), parameter :: adore_grid(4) = [0.0_wp, 0.25_wp, 0.75_wp, 1.0_wp]
         real(wp) :: f1, f2
         if (n_sub == 3) then
            f1 = adore_grid(l)
            f2 = adore_grid(l + 1)
         else
            f1 = real(l - 1, wp)/real(max(n_sub, 1), wp)
            f2 = real(l, wp)/real(max(n_sub, 1), wp)
         end if
         z1 = c%limits(1) + f1*(c%limits(2) - c%limits(1))
         z2 = c%limits(1) + f2*(c%limits(2) - c%limits(1))
      end subroutine zone

      !> delta(x) (m).
      pure function interaction(x) result(d)
         real(wp), intent(in) :: x
         real(wp) :: d
         d = h(1) + h(2)*x + 0.5_wp*h(3)*x**2 - profile_drop(prof, x) - x**2/(2.0_wp*race_crown)
      end function interaction

      !> Zero of delta between x_out (delta <= 0) and x_in (delta > 0) by bisection.
      pure function root(x_out, x_in) result(x0)
         real(wp), intent(in) :: x_out, x_in
         real(wp) :: x0
         real(wp) :: a, bb, m
         integer :: it
         a = x_out
         bb = x_in
         do it = 1, 200
            m = 0.5_wp*(a + bb)
            if (interaction(m) > 0.0_wp) then
               bb = m
            else
               a = m
            end if
            if (abs(bb - a) <= 1.0e-15_wp*max(abs(lim(1)), abs(lim(2)))) exit
         end do
         x0 = 0.5_wp*(a + bb)
      end function root

   end subroutine line_contact

end module adore_contact_line_slices
