!> EHD traction of a ball/race contact: ADORE's traction model 3 ("EHD", report Table 5 and
!> section 5.3: a Newtonian lubricant film with its temperature and shear stress computed
!> through the film, with rheological constants regressed from traction data).
!>
!> Film shear (derived here; the report describes the model only in words): a Newtonian
!> film of thickness h sheared at the slip u, shear stress uniform across the film, heat
!> tau**2/eta conducted to both surfaces held at the wall temperature T_w, viscosity
!> eta = eta_w exp(-beta (T - T_w)).  The energy equation k T'' = -tau**2/eta is Bratu's
!> problem; its closed form gives
!>     sinh(c/2) = (|u|/2) sqrt(beta eta_w / (2 k)),   tau h = sqrt(2 k eta_w / beta) c / cosh(c/2),
!> which tends to the isothermal tau = eta_w |u| / h for small slip (c -> 0).
!> eta_w = eta_t exp(alpha_t p): the lubricant's traction viscosity at the local Hertz
!> pressure p (adore_tribology_film, lubricant_t).
!>
!> Contact: the slip u(s) along the major axis (adore_tribology_slip, eq 3) is taken as
!> uniform across the strip of half width b sqrt(1 - (s/a)**2); the strip's traction per
!> unit length is the integral of tau over the strip under the Hertz pressure
!> p0 sqrt(1 - (s/a)**2 - (y/b)**2); force and heat (eq 4) integrate the strips along the
!> major axis with Gauss-Legendre per slip zone (zones split at the pure-rolling points).
!> The printed "Trac Coeff" is the strip's traction over its load at the node of largest
!> |u| (the node whose |u| is the printed slip velocity); with the report's own step-0
!> speeds, loads and films this reproduces the printed ball/race traction coefficients
!> within 1.2 % and contact losses within 1.7 % (28 contacts, docs/tribology.md).
module adore_tribology_ehd_traction
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_core_quadrature, only: gauss_legendre
   use adore_tribology_ehd_strip_table, only: strip_log_shear_nodes, STRIP_A_MAX, STRIP_L_MIN, STRIP_L_MAX
   use adore_tribology_ehd_elastic, only: elastic_strip_ratio
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_slip, major_axis_nodes, &
                                   interior_extremum, contact_kinematics, rolling_zones, axis_nodes, cross_slip, &
                                  take_kinematics
   implicit none
   private

   public :: ehd_rheology_t, film_shear_stress, ehd_contact_traction, ehd_strip_traction
   public :: ehd_contact_traction_fast, ehd_contact_power, series_sin, series_cos_sin, film_constants, &
             thermal_film_shear, limited_shear

   !> Orders of the fast EHD traction (ehd_contact_traction_fast): Gauss points per slip
   !> zone in the angle phi of s = a sin(phi) along the major axis, and across each strip
   !> the table (EHD_STRIP_TABLE) or that many Gauss points on [0, pi/2] in the angle psi of
   !> y = b sin(psi) (tests/test_ehd_fast.py bounds its difference from the 16 x 24 reference)
   integer, parameter, public :: EHD_FAST_MAJOR = 16, EHD_FAST_STRIP = 0
   !> n_strip of ehd_contact_traction_fast that takes the strip integral from the table
   !> (adore_tribology_ehd_strip_table); EHD_STRIP_FALLBACK: its Gauss points on psi where
   !> A = alpha p / 2 is beyond the table (STRIP_A_MAX)
   integer, parameter, public :: EHD_STRIP_TABLE = 0
   integer, parameter :: EHD_STRIP_FALLBACK = 48
   !> n_strip = EHD_STRIP_TABLE's Gauss points on psi with a limiting shear stress (the table
   !> knows no cap): the cap flattens the exp(alpha p) peak, 24 points are within 5e-5 of the
   !> reference up to 3.7 GPa (16: 4e-4; test_limiting_shear, docs/tribology.md)
   integer, parameter :: EHD_STRIP_CAPPED = 24


   !> Rheology of the film at the wall temperature.
   type :: ehd_rheology_t
      real(wp) :: eta_w = 0.0_wp         !< traction viscosity at the wall temperature and p = 0 (Pa s)
      real(wp) :: alpha = 0.0_wp         !< traction pressure-viscosity coefficient (1/Pa)
      real(wp) :: beta = 0.0_wp          !< temperature-viscosity coefficient (1/K); 0: isothermal
      real(wp) :: conductivity = 0.0_wp  !< lubricant thermal conductivity (W/m/K)
      !> elastic shear modulus G of the film (Pa; run option film_shear_modulus): > 0 makes it
      !> a Maxwell film (adore_tribology_ehd_elastic); 0: the viscous film of ADORE's model 3
      real(wp) :: shear_modulus = 0.0_wp
      !> limiting shear stress coefficient Lambda (-; run option limiting_shear): > 0 caps the
      !> film's shear stress smoothly at tau_L = Lambda p, tau = tau_L tanh(tau_N / tau_L)
      !> (limited_shear; Bair & Winer 1979); 0: no cap, ADORE's model 3
      real(wp) :: limiting_shear = 0.0_wp
   end type ehd_rheology_t

contains

   !> Shear stress (Pa) of a Newtonian film of thickness h (m) sheared at slip u (m/s),
   !> wall viscosity eta_w (Pa s), temperature-viscosity coefficient beta (1/K),
   !> conductivity k_f (W/m/K): the closed form of the module header (isothermal for beta = 0).
   elemental function film_shear_stress(eta_w, beta, k_f, u, h) result(tau)
      real(wp), intent(in) :: eta_w, beta, k_f, u, h
      real(wp) :: tau
      real(wp) :: c

      if (beta <= 0.0_wp) then
         tau = eta_w*abs(u)/h
         return
      end if
      c = 0.5_wp*abs(u)*sqrt(beta*eta_w/(2.0_wp*k_f))      ! sinh(c/2) with c of the header
      tau = sqrt(2.0_wp*k_f*eta_w/beta)/h*shear_shape(c)
   end function film_shear_stress

   !> The film's shear stress (Pa) under a limiting shear stress (run option limiting_shear;
   !> not in ADORE 5.0): tau_L tanh(tau_n / tau_L), tau_L = lambda p, for the film's own
   !> shear stress tau_n (Pa, >= 0) at the local pressure p (Pa) with the coefficient lambda
   !> (-; Bair & Winer 1979, Evans & Johnson 1986: 0.05-0.1): smooth, slope 1 at small stress,
   !> never above tau_L (docs/tribology.md, "Limiting shear stress").  lambda <= 0: tau_n
   !> itself (no cap); p <= 0 with a cap: 0 (no pressure, no shear strength).
   elemental function limited_shear(tau_n, lambda, p) result(tau)
      real(wp), intent(in) :: tau_n, lambda, p
      real(wp) :: tau, tau_l
      if (lambda <= 0.0_wp) then
         tau = tau_n
         return
      end if
      tau_l = lambda*p
      if (tau_l > 0.0_wp) then
         tau = tau_l*tanh(tau_n/tau_l)
      else
         tau = 0.0_wp
      end if
   end function limited_shear

   !> Shear stress (Pa) of the thermal film (beta > 0) with film_constants' amp (Pa) and zeta
   !> (s/m) at E = exp(alpha p / 2) (-) and slip u (m/s): amp E shear_shape(zeta |u| E), the
   !> strip traction's form of film_shear_stress(eta_w E**2, ...) (equal to round-off); for
   !> z = zeta |u| E >= 0.5 asinh(z) = log(z + sqrt(1 + z**2)), whose square root the shape's
   !> denominator shares (no cancellation there; a log instead of libm's asinh).
   elemental function thermal_film_shear(amp, zeta, e_half, u) result(tau)
      real(wp), intent(in) :: amp, zeta, e_half, u
      real(wp) :: tau, z, s
      z = zeta*abs(u)*e_half
      if (z < 0.5_wp) then
         tau = amp*e_half*shear_shape(z)
      else
         s = sqrt(1.0_wp + z*z)
         tau = amp*e_half*(2.0_wp*log(z + s)/s)
      end if
   end function thermal_film_shear

   !> 2 asinh(z) / sqrt(1 + z**2) = c / cosh(c/2) with sinh(c/2) = z; 2 z for tiny z.
   elemental function shear_shape(z) result(g)
      real(wp), intent(in) :: z
      real(wp) :: g
      if (z < 1.0e-8_wp) then
         g = 2.0_wp*z
      else
         g = 2.0_wp*asinh(z)/sqrt(1.0_wp + z*z)
      end if
   end function shear_shape

   !> Traction, heat and kinematics of contact c with an EHD film of thickness h (m) and
   !> rheology rheo; b: semi-minor axis (m); n_gauss points per slip zone along the major
   !> axis, n_strip across each strip.  t%coefficient = net traction / load, t%power (W) =
   !> integral of f |u| ds (eq 4).  Input error for bad data.
   !> transverse (m/s), when given: the two-dimensional traction (report eq 5; the slip
   !> across the rolling direction u_m(psi) = m1 + m2 cos psi + m3 sin psi, psi = s / rho,
   !> of adore_contact_ball_race's transverse_coeff): each strip is sheared at the slip
   !> vector's |u| = |(u(s), u_m)| and its traction f(|u|) acts along (u, u_m) / |u|; force,
   !> force_cos, force_sin from the rolling part, t%cross_force from the transverse part,
   !> power and sliding from |u| (adore_tribology_slip's contact_traction).
   subroutine ehd_contact_traction(c, rheo, h, b, n_gauss, n_strip, t, error, transverse)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b
      integer, intent(in) :: n_gauss, n_strip
      type(contact_traction_t), intent(out) :: t
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: transverse(3)
      real(wp), allocatable :: x(:), w(:)
      real(wp) :: u, f, q, y(n_strip), wy(n_strip), um, us, cs, sn
      integer :: j, m

      call check_ehd_inputs(c, rheo, h, b, n_gauss, n_strip, error)
      if (allocated(error)) return
      call major_axis_nodes(c, n_gauss, t, x, w)
      call strip_rule(n_strip, y, wy, m)
      if (present(transverse)) then
         t%max_slip = max(hypot(contact_slip(c, -c%a), cross_slip(transverse, -c%a/c%rho)), &
                          hypot(contact_slip(c, c%a), cross_slip(transverse, c%a/c%rho)))
         do j = 1, size(x)
            u = contact_slip(c, x(j))
            cs = cos(x(j)/c%rho)
            sn = sin(x(j)/c%rho)
            um = transverse(1) + transverse(2)*cs + transverse(3)*sn
            us = hypot(u, um)
            call strip_traction(c, rheo, h, b, y(1:m), wy(1:m), x(j), us, f, q)
            t%power = t%power + f*us*w(j)
            t%sliding = t%sliding + us*0.75_wp*c%load/c%a*(1.0_wp - (x(j)/c%a)**2)*w(j)
            t%max_slip = max(t%max_slip, us)
            if (us <= 0.0_wp) cycle
            t%force = t%force + f*w(j)*u/us
            t%force_cos = t%force_cos + f*w(j)*u/us*cs
            t%force_sin = t%force_sin + f*w(j)*u/us*sn
            t%cross_force = t%cross_force + f*w(j)*um/us*[1.0_wp, cs, sn]
         end do
         call interior_extremum(c, t%max_slip)     ! |u| >= |u_r| there
         t%coefficient = t%force/c%load
         return
      end if
      t%max_slip = max(abs(contact_slip(c, -c%a)), abs(contact_slip(c, c%a)))
      do j = 1, size(x)
         u = contact_slip(c, x(j))
         call strip_traction(c, rheo, h, b, y(1:m), wy(1:m), x(j), u, f, q)
         t%force = t%force + sign(f, u)*w(j)
         t%force_cos = t%force_cos + sign(f, u)*w(j)*cos(x(j)/c%rho)
         t%force_sin = t%force_sin + sign(f, u)*w(j)*sin(x(j)/c%rho)
         t%power = t%power + f*abs(u)*w(j)
         t%sliding = t%sliding + abs(u)*0.75_wp*c%load/c%a*(1.0_wp - (x(j)/c%a)**2)*w(j)   ! Hertz strip load
         t%max_slip = max(t%max_slip, abs(u))
      end do
      call interior_extremum(c, t%max_slip)
      t%coefficient = t%force/c%load
   end subroutine ehd_contact_traction

   !> The EHD traction of contact c as ehd_contact_traction, fast: the square-root edges of
   !> the Hertz ellipse are taken out by s = a sin(phi) along the major axis (zones still
   !> split at the pure-rolling points, graded there), so that Gauss-Legendre converges fast
   !> in phi: n_major points per zone (default EHD_FAST_MAJOR).  Across each strip
   !> (n_strip = EHD_STRIP_TABLE, the default) the integral of the film shear is the table
   !> of adore_tribology_ehd_strip_table, S = 2 Z exp(G(A, ln Z)), A = alpha p_c / 2,
   !> Z = zeta |u| (p_c the strip's centre pressure; Gauss on psi with EHD_STRIP_FALLBACK
   !> points for A beyond the table); n_strip >= 1: Gauss on psi in [0, pi/2] of
   !> y = b' sin(psi) with n_strip points.  Same outputs as ehd_contact_traction (force,
   !> force_cos, force_sin, power, sliding, max_slip, kinematics); input error for bad data.
   !> rheo%shear_modulus > 0: each strip times its Maxwell film's ratio (adore_tribology_ehd_elastic).
   !> rheo%limiting_shear > 0: the table knows no cap, every strip by the Gauss rule on psi
   !> (EHD_STRIP_CAPPED points for n_strip = EHD_STRIP_TABLE), each point capped (limited_shear);
   !> the zones graded at the pure-rolling points over the cap's saturation layer, out to the
   !> thermal layer's extent (add_sub).
   !> transverse (m/s), when given: the two-dimensional traction as ehd_contact_traction's
   !> (each strip's integral at the slip vector's |u|, its traction along (u, u_m) / |u|,
   !> t%cross_force), on the same nodes: the zones and their grading follow the pure-rolling
   !> points of the rolling slip u(s), where the traction turns fastest.  kinematics, when
   !> given: contact_kinematics(c) (its centre kinematics are taken from it).  A contact without
   !> pure-rolling point whose |u| dips inside (two rolling points merged or just apart, as
   !> under race control) is split and graded at the dip (slip_minimum): plain Gauss in phi
   !> missed that layer by up to 4e-3 of the force (docs/dynamics.md).  extremes = .false.:
   !> t%max_slip is not computed (left 0; the end slips, the nodes' largest |u| and the
   !> interior extremum skipped), every other output the same bit for bit: for a caller that
   !> does not use it (the force assembly, adore_forces_race_contact's ehd_traction; issue #30).
   subroutine ehd_contact_traction_fast(c, rheo, h, b, t, error, n_major, n_strip, transverse, kinematics, extremes)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b
      type(contact_traction_t), intent(out) :: t
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: n_major, n_strip
      real(wp), intent(in), optional :: transverse(3)
      !> contact_kinematics of c, when the caller has it (its fields are taken, not recomputed)
      type(contact_traction_t), intent(in), optional :: kinematics
      !> .false.: t%max_slip not computed (left 0); default .true.
      logical, intent(in), optional :: extremes
      !> extent of a graded layer at a pure-rolling point, in units of its width 1 / K
      real(wp), parameter :: LAYER = 20.0_wp
      integer, parameter :: MAX_FAST = 64, MAX_NODES = 8*MAX_FAST
      integer :: q_
      !> the Taylor coefficients of cos and sin in psi**2: (-1)**k / (2k)! and (-1)**k / (2k + 1)!
      real(wp), parameter :: COS_C(9) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 1.0_wp), q_ = 1, 9)]
      real(wp), parameter :: SIN_C(8) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 2.0_wp), q_ = 1, 8)]
      real(wp), parameter :: Z_MIN = exp(STRIP_L_MIN)
      real(wp) :: xq(MAX_FAST, 2), wq(MAX_FAST, 2), yg(MAX_FAST), wy(MAX_FAST), cy(MAX_FAST), evs(MAX_FAST)
      real(wp), dimension(MAX_NODES) :: phi, wn, cphi, ct, st, u, f, aa, zz, lz, g, us, um, cps, sps
      real(wp) :: edges(4), p0, amp, zeta, lo, hi, rs, sub(3, 8), vmax, ev, fac, pe, kp, sp, fr, fm, sliding, ca, sa, x, x2, ue
      real(wp) :: umax, ce, se, u_end(2)
      real(wp) :: polar(2)          ! rolling_zones' polar form of u(s), for interior_extremum
      real(wp) :: s_last, k_last   ! add_sub's last rolling point (m) and its layer's inverse width (1/rad)
      real(wp) :: kx_last          ! and the inverse width (1/rad) of its graded extent (add_graded's kx)
      integer :: nm, nh, ns, nq, nz, z, j, nsub, n, m, sub_rule(8), nleft
      logical :: ext

      nm = EHD_FAST_MAJOR
      ns = EHD_FAST_STRIP
      if (present(n_major)) nm = n_major
      if (present(n_strip)) ns = n_strip
      ext = .true.
      if (present(extremes)) ext = extremes
      call check_ehd_inputs(c, rheo, h, b, nm, merge(1, ns, ns == EHD_STRIP_TABLE), error)
      if (allocated(error)) return
      if (nm > MAX_FAST .or. ns > MAX_FAST) then
         call input_error(error, "EHD traction (fast): need 1 to 64 Gauss points per zone and per strip")
         return
      end if
      nh = max(1, (nm + 1)/2)             ! a half of a zone between two rolling points
      call gauss_legendre(nm, xq(1:nm, 1), wq(1:nm, 1))
      call gauss_legendre(nh, xq(1:nh, 2), wq(1:nh, 2))
      if (c%trig_of == c%alpha) then
         sa = c%sin_cos(1)             ! the contact geometry's (planar_contact), the same values
         ca = c%sin_cos(2)
      else
         ca = cos(c%alpha)
         sa = sin(c%alpha)
      end if
      if (present(kinematics)) then
         call take_kinematics(kinematics, t)
      else
         call contact_kinematics(c, t, [sa, ca])
      end if
      call rolling_zones(c, edges, nz, t%n_rolling, t%rolling_points, polar)
      p0 = 1.5_wp*c%load/(pi*c%a*b)
      call film_constants(rheo, h, amp, zeta)
      rs = c%race_speed
      ! the rule on psi: n_strip points, or the table's fallback where A is beyond it
      nq = 0
      ! (the table knows no limiting shear stress: with one, the fallback rule at every node)
      if (ns /= EHD_STRIP_TABLE .or. 0.5_wp*rheo%alpha*p0 > STRIP_A_MAX .or. rheo%limiting_shear > 0.0_wp) then
         nq = merge(EHD_STRIP_FALLBACK, ns, ns == EHD_STRIP_TABLE)
         if (ns == EHD_STRIP_TABLE .and. rheo%limiting_shear > 0.0_wp) nq = EHD_STRIP_CAPPED
         call gauss_legendre(nq, yg(1:nq), wy(1:nq))
         ! psi = pi/4 (1 + y) on [0, pi/2]; dy' = cos(psi) dpsi; both halves of the strip
         cy(1:nq) = cos(0.25_wp*pi*(1.0_wp + yg(1:nq)))
         wy(1:nq) = 2.0_wp*0.25_wp*pi*wy(1:nq)*cy(1:nq)
      end if
      ! sub-zones in phi: a zone that ends at a pure-rolling point is graded there (the
      ! film's shear saturates within |u| ~ 1 / (zeta E) of it); one between two rolling
      ! points is halved first
      nsub = 0
      s_last = huge(1.0_wp)
      k_last = 0.0_wp
      kx_last = 0.0_wp
      do z = 1, nz
         ! the ends -a, a: asin(-1), asin(1) = -pi/2, pi/2 (libm's are the doubles nearest)
         lo = -0.5_wp*pi
         hi = 0.5_wp*pi
         if (z > 1) lo = asin(max(-1.0_wp, min(1.0_wp, edges(z)/c%a)))
         if (z < nz) hi = asin(max(-1.0_wp, min(1.0_wp, edges(z + 1)/c%a)))
         if (z > 1 .and. z < nz) then
            call add_sub((lo + hi)*0.5_wp, lo, edges(z), 2)
            call add_sub((lo + hi)*0.5_wp, hi, edges(z + 1), 2)
         else if (z > 1) then
            call add_sub(hi, lo, edges(z), 1)
         else if (z < nz) then
            call add_sub(lo, hi, edges(z + 1), 1)
         else if (slip_minimum(pe, kp)) then
            ! no pure-rolling point, but |u| dips inside (the two rolling points merged or
            ! just apart, e.g. race control): split and graded at the dip
            call add_graded(lo, pe, kp, 1)
            call add_graded(hi, pe, kp, 1)
         else
            call add_sub(lo, hi, huge(1.0_wp), 1)
         end if
      end do
      ! the nodes phi(1:n) and weights wn(1:n) (rad) of every sub-zone
      n = 0
      do z = 1, nsub
         associate (pf => sub(1, z), pr => sub(2, z), kp => sub(3, z), r => sub_rule(z))
            m = merge(nm, nh, r == 1)
            ! vmax = asinh(kp |pf - pr|) by its logarithm (kp |pf - pr| <= 2 LAYER: add_graded),
            ! equal to round-off where it is used (vmax > 1); a plain sub-zone (kp = 0): none
            vmax = 0.0_wp
            ev = 1.0_wp
            if (kp > 0.0_wp) then
               ev = kp*abs(pf - pr) + sqrt(1.0_wp + (kp*abs(pf - pr))**2)      ! e**vmax
               vmax = log(ev)
            end if
            if (kp > 0.0_wp .and. vmax > 1.0_wp) then
               ! v in [0, vmax]: ev = e**v, sinh(v) = (ev - 1 / ev) / 2, cosh(v) = (ev + 1 / ev) / 2;
               ! the Gauss nodes pair up (x_(m+1-j) = -x_j), so e**v of the upper half is
               ! e**vmax / e**v of the lower: one exp for two nodes
               do j = 1, (m + 1)/2
                  evs(j) = exp(0.5_wp*vmax*(1.0_wp + xq(j, r)))
               end do
               ! e**vmax: the logarithm's argument above (no exp; equal to round-off)
               do j = (m + 1)/2 + 1, m
                  evs(j) = ev/evs(m + 1 - j)
               end do
               do j = 1, m
                  phi(n + j) = pr + sign(1.0_wp, pf - pr)*0.5_wp*(evs(j) - 1.0_wp/evs(j))/kp
                  wn(n + j) = 0.25_wp*vmax*wq(j, r)*(evs(j) + 1.0_wp/evs(j))/kp
               end do
            else
               do j = 1, m
                  phi(n + j) = 0.5_wp*(pf + pr) + 0.5_wp*(pf - pr)*xq(j, r)
                  wn(n + j) = 0.5_wp*abs(pf - pr)*wq(j, r)
               end do
            end if
            n = n + m
         end associate
      end do
      ! the strips at the nodes: loops the compiler vectorises (libmvec's log and exp, one call
      ! each; sin(phi) and cos, sin of s / rho by their series), the sums below in node order.
      ! sin(phi) by taylor_sin (ten multiply-adds a node instead of libmvec's sin; issue #30)
      do j = 1, n
         sp = taylor_sin(phi(j))                              ! sin(phi) = s / a
         cphi(j) = sqrt((1.0_wp - sp)*(1.0_wp + sp))          ! cos(phi) >= 0 on [-pi/2, pi/2]
         phi(j) = c%a*sp/c%rho                                ! now the angle psi = s / rho
         wn(j) = wn(j)*c%a*cphi(j)                            ! ds = a cos(phi) dphi
         aa(j) = 0.5_wp*rheo%alpha*p0*cphi(j)
      end do
      ! cos, sin of psi = s / rho (|psi| < a / rho < 1) by their Taylor series (Horner in psi**2
      ! to psi**18 / 18! and psi**17 / 17!: truncation below 1 / 19! < 8.3e-18 for |psi| < 1),
      ! and of the angle theta = alpha + psi by angle addition: multiply-adds, no sin/cos calls
      ! the slips at the ends s = -a, a (contact_slip, cross_slip there): cos and sin of
      ! alpha -+ a / rho by angle addition from those of alpha and a / rho (one sincos
      ! instead of four; equal to round-off).  Here, after the loop of sin(phi): computed
      ! before it, gcc no longer vectorises that loop ("latch block not empty")
      if (ext) then
         ce = cos(c%a/c%rho)
         se = sin(c%a/c%rho)
         u_end = c%side*c%rho*(c%omega(1) - rs)*[ca*ce + sa*se, ca*ce - sa*se] &
                 - c%side*c%rho*c%omega(2)*[sa*ce - ca*se, sa*ce + ca*se] - rs*c%r_b
         if (present(transverse)) then
            t%max_slip = max(hypot(u_end(1), transverse(1) + transverse(2)*ce - transverse(3)*se), &
                             hypot(u_end(2), transverse(1) + transverse(2)*ce + transverse(3)*se))
         else
            t%max_slip = max(abs(u_end(1)), abs(u_end(2)))
         end if
      end if
      if (c%a <= 0.4_wp*c%rho) then
         ! |psi| <= 0.4 (the decks' balls: a / rho <= 0.3): to psi**14 / 14! and psi**13 / 13!,
         ! truncation below 0.4**16 / 16! < 2.1e-20 and 0.4**15 / 15! < 8.2e-19 (< 0.01 ulp)
         do j = 1, n
            x = phi(j)
            x2 = x*x
            cps(j) = 1.0_wp + x2*(COS_C(1) + x2*(COS_C(2) + x2*(COS_C(3) + x2*(COS_C(4) + x2*(COS_C(5) &
                     + x2*(COS_C(6) + x2*COS_C(7)))))))
            sps(j) = x + x*x2*(SIN_C(1) + x2*(SIN_C(2) + x2*(SIN_C(3) + x2*(SIN_C(4) + x2*(SIN_C(5) &
                     + x2*SIN_C(6))))))
            ct(j) = ca*cps(j) - sa*sps(j)
            st(j) = sa*cps(j) + ca*sps(j)
         end do
      else
         do j = 1, n
            x = phi(j)
            x2 = x*x
            cps(j) = 1.0_wp + x2*(COS_C(1) + x2*(COS_C(2) + x2*(COS_C(3) + x2*(COS_C(4) + x2*(COS_C(5) &
                     + x2*(COS_C(6) + x2*(COS_C(7) + x2*(COS_C(8) + x2*COS_C(9)))))))))
            sps(j) = x + x*x2*(SIN_C(1) + x2*(SIN_C(2) + x2*(SIN_C(3) + x2*(SIN_C(4) + x2*(SIN_C(5) &
                     + x2*(SIN_C(6) + x2*(SIN_C(7) + x2*SIN_C(8))))))))
            ct(j) = ca*cps(j) - sa*sps(j)
            st(j) = sa*cps(j) + ca*sps(j)
         end do
      end if
      if (present(transverse)) then
         ! the slip vector's length (sqrt: slips in m/s, far from over- or underflow)
         do j = 1, n
            u(j) = c%side*c%rho*(c%omega(1) - rs)*ct(j) - c%side*c%rho*c%omega(2)*st(j) - rs*c%r_b
            um(j) = transverse(1) + transverse(2)*cps(j) + transverse(3)*sps(j)
            us(j) = sqrt(u(j)*u(j) + um(j)*um(j))
         end do
      else
         u(1:n) = c%side*c%rho*(c%omega(1) - rs)*ct(1:n) - c%side*c%rho*c%omega(2)*st(1:n) - rs*c%r_b
         us(1:n) = abs(u(1:n))
      end if
      ! the strip traction per unit length f = b cos(phi) x the integral of tau across the
      ! strip (strip_traction): by the table, S = 2 Z exp(G(A, ln Z)), else, or where A is
      ! beyond the table, by the rule
      if (ns == EHD_STRIP_TABLE .and. .not. rheo%limiting_shear > 0.0_wp) then
         if (rheo%beta > 0.0_wp) then
            do j = 1, n
               zz(j) = zeta*us(j)
               lz(j) = log(max(zz(j), Z_MIN))
            end do
            fac = 2.0_wp*amp*b
         else
            ! isothermal: the integral of E**2 across the strip is exp(G) at Z -> 0
            zz(1:n) = us(1:n)
            lz(1:n) = STRIP_L_MIN
            fac = rheo%eta_w/h*b
         end if
         ! the table at the nodes in its domain (G is flat below STRIP_L_MIN), in one call
         ! (strip_log_shear_nodes: strip_log_shear's bits), then the nodes beyond it
         call strip_log_shear_nodes(n, aa, lz, g, nleft)
         if (nleft > 0) then
            do j = 1, n
               if (aa(j) > STRIP_A_MAX) then
                  g(j) = 0.0_wp
               else if (lz(j) > STRIP_L_MAX) then
                  g(j) = log(2.0_wp*(lz(j) + log(2.0_wp) + 0.25_wp*pi*aa(j))) - 2.0_wp*lz(j)
               end if
            end do
         end if
         do j = 1, n
            f(j) = fac*cphi(j)*zz(j)*exp(g(j))
         end do
      end if
      if (nq > 0) then
         do j = 1, n
            if (rheo%limiting_shear > 0.0_wp) then
               f(j) = b*cphi(j)*strip_rule_capped(aa(j), us(j), p0*cphi(j))
            else if (ns /= EHD_STRIP_TABLE .or. aa(j) > STRIP_A_MAX) then
               f(j) = b*cphi(j)*strip_rule_integral(aa(j), us(j))
            end if
         end do
      end if
      ! the film's elasticity: each strip's Maxwell-film ratio (half width b' = b cos(phi))
      if (rheo%shear_modulus > 0.0_wp) then
         ue = abs(t%rolling_speed)*rheo%eta_w/(rheo%shear_modulus*b)
         do j = 1, n
            if (cphi(j) > 0.0_wp) f(j) = f(j)*elastic_strip_ratio(aa(j), zeta*us(j), rheo%beta > 0.0_wp, ue/cphi(j))
         end do
      end if
      ! force, its moments cos(s / rho) = cos(theta - alpha), sin(s / rho), heat (eq 4), sliding
      f(1:n) = f(1:n)*wn(1:n)
      if (present(transverse)) then
         ! the traction along the slip vector: its rolling (u / |u|) and transverse parts (no
         ! division by 0 where the slip vanishes: |u|, |u_m| <= |u| there); one pass, each
         ! sum from 0 in node order as the intrinsic sum
         t%force = 0.0_wp
         t%force_cos = 0.0_wp
         t%force_sin = 0.0_wp
         t%cross_force = 0.0_wp
         t%power = 0.0_wp
         sliding = 0.0_wp
         do j = 1, n
            fr = f(j)*u(j)/max(us(j), tiny(1.0_wp))
            fm = f(j)*um(j)/max(us(j), tiny(1.0_wp))
            t%force = t%force + fr
            t%force_cos = t%force_cos + fr*cps(j)
            t%force_sin = t%force_sin + fr*sps(j)
            t%cross_force(1) = t%cross_force(1) + fm
            t%cross_force(2) = t%cross_force(2) + fm*cps(j)
            t%cross_force(3) = t%cross_force(3) + fm*sps(j)
            t%power = t%power + f(j)*us(j)
            sliding = sliding + us(j)*cphi(j)**2*wn(j)
         end do
      else
         t%force = sum(sign(f(1:n), u(1:n)))
         t%force_cos = sum(sign(f(1:n), u(1:n))*cps(1:n))
         t%force_sin = sum(sign(f(1:n), u(1:n))*sps(1:n))
         t%power = sum(f(1:n)*us(1:n))
         sliding = sum(us(1:n)*cphi(1:n)**2*wn(1:n))
      end if
      t%sliding = 0.75_wp*c%load/c%a*sliding    ! Hertz strip load
      if (ext) then
         ! the largest |u| (exact in any order: a loop gcc vectorises, where maxval is scalar)
         umax = t%max_slip
         do j = 1, n
            umax = max(umax, us(j))
         end do
         t%max_slip = umax
         call interior_extremum(c, t%max_slip, polar)
      end if
      t%coefficient = t%force/c%load

   contains

      !> A sub-zone of phi from pf (free end) to pr, graded at pr when s_r (m) is a
      !> pure-rolling point (huge(): no grading): sinh grading with the inverse width
      !> zeta |du/ds| E_max a cos(phi) of the shear's saturation layer (1/rad); rule 1: nm
      !> points, rule 2 (a half zone): nh.
      subroutine add_sub(pf, pr, s_r, rule)
         real(wp), intent(in) :: pf, pr, s_r
         integer, intent(in) :: rule
         real(wp) :: dudx, cs(2), cp
         if (s_r == huge(1.0_wp) .or. (rheo%beta <= 0.0_wp .and. .not. rheo%limiting_shear > 0.0_wp)) then
            call add_graded(pf, pr, 0.0_wp, rule)
            return
         end if
         ! the zones on both sides of a rolling point (and the halves of a zone between two)
         ! meet there in turn: its layer width once, for both.  sin, cos of theta = alpha +
         ! s_r / rho by angle addition from alpha's and the series of s_r / rho (|s_r / rho|
         ! < a / rho < 1): no sincos (issue #30; equal to round-off: test_traction_fast)
         if (s_r /= s_last) then
            cp = cos(pr)
            cs = cos_sin_series(s_r/c%rho, c%a <= 0.4_wp*c%rho)
            dudx = (-c%side*c%rho*(c%omega(1) - rs)*(sa*cs(1) + ca*cs(2)) &
                    - c%side*c%rho*c%omega(2)*(ca*cs(1) - sa*cs(2)))/c%rho
            s_last = s_r
            k_last = zeta*abs(dudx)*exp(0.5_wp*rheo%alpha*p0*cp)*c%a*cp
            ! a limiting shear stress saturates the film where its Newtonian stress eta_w E**2
            ! |u| / h reaches Lambda p_c (p_c = p0 cos(phi), the strip's centre): within
            ! |u| = Lambda p_c h / (eta_w E**2) of the rolling point, often far thinner than the
            ! thermal layer.  The thinner of the two is graded (cos(phi) cancels), out to the
            ! thermal layer's extent kx_last (the strip's off-centre points, at lower pressure,
            ! saturate at larger slips); isothermal: the cap's own extent
            kx_last = k_last
            if (rheo%limiting_shear > 0.0_wp) k_last = max(k_last, abs(dudx)*c%a*rheo%eta_w* &
                                                           exp(rheo%alpha*p0*cp)/(rheo%limiting_shear*p0*h))
            if (.not. kx_last > 0.0_wp) kx_last = k_last
         end if
         if (rheo%limiting_shear > 0.0_wp) then
            call add_graded(pf, pr, k_last, rule, kx_last)
         else
            call add_graded(pf, pr, k_last, rule)
         end if
      end subroutine add_sub

      !> A sub-zone of phi from pf (free end) to pr, graded at pr with the inverse layer
      !> width k (1/rad; 0: not graded), rule as add_sub; a layer much thinner than the
      !> zone is graded up to LAYER / k from pr and the rest of the zone is plain; kx (1/rad,
      !> <= k), when given: graded up to LAYER / kx (a limiting shear stress's layer, k, inside
      !> the thermal film's, kx).
      subroutine add_graded(pf, pr, k, rule, kx)
         real(wp), intent(in) :: pf, pr, k
         integer, intent(in) :: rule
         real(wp), intent(in), optional :: kx
         real(wp) :: ke
         ke = k
         if (present(kx)) ke = kx
         nsub = nsub + 1
         sub(:, nsub) = [pf, pr, k]
         sub_rule(nsub) = rule
         if (ke*abs(pf - pr) > 2.0_wp*LAYER) then
            ! the layer graded up to LAYER / K from pr, the rest of the zone plain
            sub(1, nsub) = pr + sign(LAYER/ke, pf - pr)
            nsub = nsub + 1
            sub(:, nsub) = [pf, sub(1, nsub - 1), 0.0_wp]
            sub_rule(nsub) = rule
         end if
      end subroutine add_graded

      !> The interior minimum of the slip vector's length (a zone without pure-rolling
      !> point whose rolling slip u(s) has its extremum inside the contact, thermal film
      !> only): its position pe (phi, rad) and the inverse width k (1/rad) of the layer
      !> where the shear changes, |u - u_e| <= max(|u_e|, 1 / (zeta E)) with u - u_e =
      !> u'' (s - s_e)**2 / 2 (E at the strip's centre).  False when there is none.
      logical function slip_minimum(pe, k)
         real(wp), intent(out) :: pe, k
         real(wp) :: aa, bb, th, s_e, ue, d2u, e_max, width, u_sat
         integer :: m
         slip_minimum = .false.
         pe = 0.0_wp
         k = 0.0_wp
         if (rheo%beta <= 0.0_wp .and. .not. rheo%limiting_shear > 0.0_wp) return
         aa = c%side*c%rho*(c%omega(1) - rs)
         bb = -c%side*c%rho*c%omega(2)
         if (hypot(aa, bb) <= 0.0_wp) return
         do m = -3, 3
            th = atan2(bb, aa) + pi*m            ! u'(s) = 0
            s_e = (th - c%alpha)*c%rho
            if (abs(s_e) >= c%a) cycle
            pe = asin(s_e/c%a)
            if (present(transverse)) then
               ue = hypot(contact_slip(c, s_e), cross_slip(transverse, s_e/c%rho))
            else
               ue = abs(contact_slip(c, s_e))
            end if
            d2u = abs(aa*cos(th) + bb*sin(th))/c%rho**2
            e_max = exp(0.5_wp*rheo%alpha*p0*cos(pe))
            if (.not. (d2u > 0.0_wp)) return
            if (rheo%limiting_shear > 0.0_wp) then
               ! the film's saturation under the cap, |u| = Lambda p_c h / (eta_w E**2) (add_sub),
               ! or the thermal one where it is thinner
               u_sat = rheo%limiting_shear*p0*cos(pe)*h/(rheo%eta_w*e_max*e_max)
               if (rheo%beta > 0.0_wp) u_sat = min(u_sat, 1.0_wp/(zeta*e_max))
               width = sqrt(2.0_wp*max(ue, u_sat)/d2u)
            else
               width = sqrt(2.0_wp*max(ue, 1.0_wp/(zeta*e_max))/d2u)     ! in s (m)
            end if
            k = c%a*cos(pe)/width
            slip_minimum = .true.
            return
         end do
      end function slip_minimum

      !> Integral of tau h / h (Pa) over y' in [-1, 1] across a strip with A = alpha p_c / 2
      !> and slip u (m/s) by the rule (cy, wy) on psi (strip_traction).
      function strip_rule_integral(aa, u) result(f)
         real(wp), intent(in) :: aa, u
         real(wp) :: f
         real(wp) :: e_half, zq, sq
         integer :: i
         f = 0.0_wp
         do i = 1, nq
            e_half = exp(aa*cy(i))
            if (rheo%beta > 0.0_wp) then
               zq = zeta*abs(u)*e_half
               sq = sqrt(1.0_wp + zq*zq)
               ! shear_shape(z) = 2 asinh(z) / sqrt(1 + z**2), asinh by its logarithm: its
               ! absolute error stays ~eps (relative eps / z at small z, where the shear is small)
               f = f + wy(i)*amp*e_half*(2.0_wp*log(zq + sq)/sq)
            else
               f = f + wy(i)*rheo%eta_w*e_half*e_half*abs(u)/h
            end if
         end do
      end function strip_rule_integral

      !> strip_rule_integral with the limiting shear stress: each point's tau capped at tau_L =
      !> Lambda p_c cos(psi) (p_c the strip's centre pressure, Pa), tau_L tanh(tau / tau_L)
      !> (limited_shear) with tanh(x) = (1 - e) / (1 + e), e = exp(-2 min(x, 40)): loops of
      !> exp, log and sqrt that gcc vectorises (libmvec); equal to limited_shear to an
      !> absolute ~eps tau_L a point (test_limiting_shear: fast against reference).
      function strip_rule_capped(aa, u, pc) result(f)
         real(wp), intent(in) :: aa, u, pc
         real(wp) :: f
         real(wp), dimension(MAX_FAST) :: e_half, tau, tl, e
         real(wp) :: zu
         integer :: i
         do i = 1, nq
            e_half(i) = exp(aa*cy(i))
         end do
         if (rheo%beta > 0.0_wp) then
            zu = zeta*abs(u)
            do i = 1, nq
               tau(i) = amp*e_half(i)*(2.0_wp*log(zu*e_half(i) + sqrt(1.0_wp + (zu*e_half(i))**2)) &
                                       /sqrt(1.0_wp + (zu*e_half(i))**2))
            end do
         else
            do i = 1, nq
               tau(i) = rheo%eta_w*e_half(i)*e_half(i)*abs(u)/h
            end do
         end if
         ! tau / tau_L <= 40 before the division (no overflow where tau_L -> 0); tanh(40) = 1
         do i = 1, nq
            tl(i) = max(rheo%limiting_shear*pc*cy(i), tiny(1.0_wp))
            e(i) = exp(-2.0_wp*min(tau(i), 40.0_wp*tl(i))/tl(i))
         end do
         f = 0.0_wp
         do i = 1, nq
            f = f + wy(i)*tl(i)*(1.0_wp - e(i))/(1.0_wp + e(i))
         end do
      end function strip_rule_capped

   end subroutine ehd_contact_traction_fast

   !> [cos(x), sin(x)] (-) for |x| < 1 (rad) as the fast traction computes them at a
   !> pure-rolling point (cos_sin_series; public for its test): short for |x| <= 0.4.
   pure function series_cos_sin(x, short) result(cs)
      real(wp), intent(in) :: x
      logical, intent(in) :: short
      real(wp) :: cs(2)
      cs = cos_sin_series(x, short)
   end function series_cos_sin

   !> [cos(x), sin(x)] (-) for |x| < 1 (rad; x = s / rho on the major axis) by the Taylor
   !> series of the fast traction's nodes: short (|x| <= 0.4, the contacts with a <= 0.4 rho):
   !> to x**14 / 14! and x**13 / 13! (truncation below 2.1e-20 and 8.2e-19), else to
   !> x**18 / 18! and x**17 / 17! (below 8.3e-18); private, so that gcc inlines it.
   pure function cos_sin_series(x, short) result(cs)
      real(wp), intent(in) :: x
      logical, intent(in) :: short
      real(wp) :: cs(2), x2
      integer :: q_
      real(wp), parameter :: COS_C(9) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 1.0_wp), q_ = 1, 9)]
      real(wp), parameter :: SIN_C(8) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 2.0_wp), q_ = 1, 8)]
      x2 = x*x
      if (short) then
         cs(1) = 1.0_wp + x2*(COS_C(1) + x2*(COS_C(2) + x2*(COS_C(3) + x2*(COS_C(4) + x2*(COS_C(5) &
                 + x2*(COS_C(6) + x2*COS_C(7)))))))
         cs(2) = x + x*x2*(SIN_C(1) + x2*(SIN_C(2) + x2*(SIN_C(3) + x2*(SIN_C(4) + x2*(SIN_C(5) &
                 + x2*SIN_C(6))))))
      else
         cs(1) = 1.0_wp + x2*(COS_C(1) + x2*(COS_C(2) + x2*(COS_C(3) + x2*(COS_C(4) + x2*(COS_C(5) &
                 + x2*(COS_C(6) + x2*(COS_C(7) + x2*(COS_C(8) + x2*COS_C(9)))))))))
         cs(2) = x + x*x2*(SIN_C(1) + x2*(SIN_C(2) + x2*(SIN_C(3) + x2*(SIN_C(4) + x2*(SIN_C(5) &
                 + x2*(SIN_C(6) + x2*(SIN_C(7) + x2*SIN_C(8))))))))
      end if
   end function cos_sin_series

   !> sin(x) (-) for |x| <= pi/2 (rad) as the fast traction computes it at every node
   !> (taylor_sin; public for its test).
   elemental real(wp) function series_sin(x) result(y)
      real(wp), intent(in) :: x
      y = taylor_sin(x)
   end function series_sin

   !> sin(x) (-) for |x| <= pi/2 (rad) by its Taylor series to x**21 / 21! (Horner in x**2;
   !> truncation below (pi/2)**23 / 23! < 1.2e-18): ten multiply-adds, which gcc inlines and
   !> vectorises (private: a public procedure is not inlined under -fPIC), for the fast
   !> traction's sin(phi) at every node (issue #30); within 2.3e-16 of libm's sin there
   !> (test_traction_fast).
   elemental real(wp) function taylor_sin(x) result(y)
      real(wp), intent(in) :: x
      integer :: q_
      real(wp), parameter :: C(10) = [((-1.0_wp)**q_/gamma(2.0_wp*q_ + 2.0_wp), q_ = 1, 10)]
      real(wp) :: x2
      x2 = x*x
      y = x + x*x2*(C(1) + x2*(C(2) + x2*(C(3) + x2*(C(4) + x2*(C(5) + x2*(C(6) + x2*(C(7) + x2*(C(8) &
          + x2*(C(9) + x2*C(10))))))))))
   end function taylor_sin

   !> Power (W) of contact c with the EHD film: ehd_contact_traction's t%power, the same
   !> nodes and sums bit for bit, without the other integrals (the minimum-dissipation
   !> search's objective).  Input error for bad data.
   subroutine ehd_contact_power(c, rheo, h, b, n_gauss, n_strip, power, error)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b
      integer, intent(in) :: n_gauss, n_strip
      real(wp), intent(out) :: power
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: x(3*max(n_gauss, 0)), w(3*max(n_gauss, 0)), y(n_strip), wy(n_strip), u, f, q
      integer :: n, j, m

      power = 0.0_wp
      call check_ehd_inputs(c, rheo, h, b, n_gauss, n_strip, error)
      if (allocated(error)) return
      call axis_nodes(c, n_gauss, x, w, n)
      call strip_rule(n_strip, y, wy, m)
      do j = 1, n
         u = contact_slip(c, x(j))
         call strip_traction(c, rheo, h, b, y(1:m), wy(1:m), x(j), u, f, q)
         power = power + f*abs(u)*w(j)
      end do
   end subroutine ehd_contact_power

   !> Input error unless contact c, film h (m), rheology, semi-minor axis b (m) and the
   !> quadrature orders n_major, n_strip (>= 1) are valid for the EHD traction.
   subroutine check_ehd_inputs(c, rheo, h, b, n_major, n_strip, error)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b
      integer, intent(in) :: n_major, n_strip
      type(error_type), allocatable, intent(out) :: error
      if (.not. (c%rho > 0.0_wp .and. c%a > 0.0_wp .and. c%a < c%rho .and. c%load > 0.0_wp &
                 .and. c%r_b > c%rho .and. abs(c%side) == 1 .and. b > 0.0_wp)) then
         call engine_error(error, "EHD traction: the contact is outside the model (need 0 < a < rho < r_b, "// &
                           "b > 0, load > 0): a conformity, fit or speed beyond the Hertz contact")
         return
      end if
      if (.not. (h > 0.0_wp .and. rheo%eta_w > 0.0_wp .and. rheo%alpha >= 0.0_wp .and. rheo%beta >= 0.0_wp &
                 .and. (rheo%beta == 0.0_wp .or. rheo%conductivity > 0.0_wp))) then
         call input_error(error, "EHD traction: need film h > 0, viscosity > 0, alpha, beta >= 0, conductivity > 0")
         return
      end if
      if (n_major < 1 .or. n_strip < 1) then
         call input_error(error, "EHD traction: need at least one Gauss point per zone and per strip")
         return
      end if
   end subroutine check_ehd_inputs

   !> The EHD traction of contact c (as ehd_contact_traction) at the node s (m) of the major
   !> axis with slip u (m/s): the strip's traction f (N/m) and load q (N/m), with n_strip
   !> points across the strip.  The print's local traction coefficient is f / q at the
   !> print node (adore_tribology_slip's print_slip_node).
   subroutine ehd_strip_traction(c, rheo, h, b, n_strip, s, u, f, q)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b, s, u
      integer, intent(in) :: n_strip
      real(wp), intent(out) :: f, q
      real(wp) :: y(n_strip), wy(n_strip)
      integer :: m
      call strip_rule(n_strip, y, wy, m)
      call strip_traction(c, rheo, h, b, y(1:m), wy(1:m), s, u, f, q)
   end subroutine ehd_strip_traction

   !> The n-point Gauss-Legendre rule across a strip folded onto y >= 0 (the integrand is
   !> even in y): nodes y(1:m) with doubled weights, the centre node of an odd rule once.
   pure subroutine strip_rule(n, y, wy, m)
      integer, intent(in) :: n
      real(wp), intent(out) :: y(n), wy(n)
      integer, intent(out) :: m
      integer :: i
      call gauss_legendre(n, y, wy)
      m = 0
      do i = 1, n
         if (y(i) < 0.0_wp) cycle
         m = m + 1
         y(m) = y(i)
         wy(m) = merge(wy(i), 2.0_wp*wy(i), y(i) == 0.0_wp)
      end do
   end subroutine strip_rule

   !> Constants of the thermal film shear of the module header for film h (m): tau h / h =
   !> amp shear_shape(zeta |u| E) (amp in Pa, zeta in s/m); both 0 for an isothermal film.
   pure subroutine film_constants(rheo, h, amp, zeta)
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h
      real(wp), intent(out) :: amp, zeta
      amp = 0.0_wp
      zeta = 0.0_wp
      if (rheo%beta > 0.0_wp) then
         amp = sqrt(2.0_wp*rheo%conductivity*rheo%eta_w/rheo%beta)/h
         zeta = 0.5_wp*sqrt(rheo%beta*rheo%eta_w/(2.0_wp*rheo%conductivity))
      end if
   end subroutine film_constants

   !> Traction f (N/m) and load q (N/m) of the strip across the Hertz ellipse at node s (m)
   !> of the major axis, slip u (m/s), folded strip rule (y, wy): tau h = amp E
   !> shear_shape(zeta |u| E), E = exp(alpha p / 2) (module header with eta_w(p) =
   !> eta_w E**2); Newtonian tau = eta_w E**2 |u| / h when beta = 0; capped at Lambda p
   !> (limited_shear) when rheo%limiting_shear > 0; times the Maxwell film's ratio
   !> (adore_tribology_ehd_elastic, of the uncapped film: docs/tribology.md, "Limiting shear
   !> stress") when rheo%shear_modulus > 0.
   pure subroutine strip_traction(c, rheo, h, b, y, wy, s, u, f, q)
      type(ball_race_contact_t), intent(in) :: c
      type(ehd_rheology_t), intent(in) :: rheo
      real(wp), intent(in) :: h, b, y(:), wy(:), s, u
      real(wp), intent(out) :: f, q
      real(wp) :: xi2, half, p0, p, e_half, tau, amp, zeta
      type(contact_traction_t) :: kin
      integer :: i

      p0 = 1.5_wp*c%load/(pi*c%a*b)
      call film_constants(rheo, h, amp, zeta)
      xi2 = (s/c%a)**2
      half = b*sqrt(1.0_wp - xi2)
      f = 0.0_wp
      q = 0.0_wp
      do i = 1, size(y)
         p = p0*sqrt((1.0_wp - xi2)*(1.0_wp - y(i)**2))
         e_half = exp(0.5_wp*rheo%alpha*p)
         if (rheo%beta > 0.0_wp) then
            tau = amp*e_half*shear_shape(zeta*abs(u)*e_half)
         else
            tau = rheo%eta_w*e_half*e_half*abs(u)/h
         end if
         if (rheo%limiting_shear > 0.0_wp) tau = limited_shear(tau, rheo%limiting_shear, p)
         f = f + half*wy(i)*tau
         q = q + half*wy(i)*p
      end do
      if (rheo%shear_modulus > 0.0_wp .and. half > 0.0_wp) then
         ! the Maxwell film (adore_tribology_ehd_elastic) at the contact's entraining speed
         call contact_kinematics(c, kin)
         f = f*elastic_strip_ratio(0.5_wp*rheo%alpha*p0*sqrt(1.0_wp - xi2), zeta*abs(u), rheo%beta > 0.0_wp, &
                                   abs(kin%rolling_speed)*rheo%eta_w/(rheo%shear_modulus*half))
      end if
   end subroutine strip_traction

end module adore_tribology_ehd_traction
