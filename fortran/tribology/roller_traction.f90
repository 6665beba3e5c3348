!> Roller/race traction by slices (report section 2.1, eqs 1-4, applied to the line
!> contact of Appendix B; test roller bearing of section 5.4 and its Appendix D print).
!>
!> Frame: the one orbiting with the roller (orbital speed w_m about the bearing axis x);
!> e_r the roller's radial unit vector, e_t = e_x x e_r the rolling (orbit) direction.
!> The roller spins at W (about +x, the print's amplitude |W| with theta 180 deg when
!> W < 0), race j at w_j = Omega_j - w_m.  A slice at axial position x touches the race at
!> the undeformed roller surface, radius rho(x) = D/2 - p(x) (p the profile drop of
!> adore_contact_line_slices).  The rolling slip (roller minus race surface speed along e_t)
!> is, with W0 the spin of pure rolling of the land (p = 0) on the raceways:
!>     outer:  u_o(x) =  (W - W0) D/2 - p(x) (W - w_o)
!>     inner:  u_i(x) = -(W - W0) D/2 + p(x) (W - w_i)
!> i.e. the race point's radius changes with p as the roller point's (the slip of the
!> crowned part grows with p times the relative angular speed of roller and race).
!> INFERRED from the Appendix D print (roller 1: W0 the outer-race-control spin,
!> W = W0): its slice traction loads are exactly 0 on the land of both races (pure rolling
!> of the land, although the raceway radii of the contact geometry would make the inner
!> land slide by ~0.1 m/s) and its printed slip velocities are p(x1) |W - w_o| and
!> p(x1) |W - w_i| at the outermost slice x1 (within 0.1 %; |W| alone misses by 16 % / 7 %).
!>
!> Traction (eq 1, one-dimensional): the roller pulls the race along e_t with
!> t(x) = kappa(|u|) sign(u) q(x) (N/m), kappa the traction law (the deck's
!> curve or a traction-slip table, `adore_tribology_traction_law`);
!> the race pulls the roller with -t.  Power (eq 4): integral of kappa |u| q dx.  Integrals
!> are sums over the contact's slices (its quadrature grid, Gauss points per zone).
!> Moment on the roller about its axis (e_r x e_t = e_x):
!>     M = - sum w rho t_o + sum w rho t_i      (outer point at +rho e_r, inner at -rho e_r)
!> Units SI (m, m/s, rad/s, N, N/m, N m, W).
module adore_tribology_roller_traction
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error, engine_error
   use adore_contact_line_slices, only: roller_profile_t, line_contact_t, profile_drop
   use adore_tribology_traction_law, only: traction_law_t, law_kappa
   implicit none
   private

   public :: roller_spin_t, line_traction_t
   public :: line_slip, line_traction, roller_traction_moment, roller_equilibrium_spin

   integer, parameter, public :: RACE_OUTER = 1   !< outer race contact
   integer, parameter, public :: RACE_INNER = 2   !< inner race contact

   !> Kinematics of one roller in its orbiting frame (rad/s, m).
   type :: roller_spin_t
      real(wp) :: d = 0.0_wp              !< roller diameter D
      real(wp) :: spin = 0.0_wp           !< W, roller angular speed about +x
      real(wp) :: rolling_spin = 0.0_wp   !< W0, pure rolling of the land on the raceways
      real(wp) :: race_speed(2) = 0.0_wp  !< w_j = Omega_j - w_m, outer (1), inner (2)
   end type roller_spin_t

   !> Traction of one roller/race line contact.
   type :: line_traction_t
      real(wp), allocatable :: slip(:)       !< u at the slices (m/s)
      real(wp), allocatable :: kappa(:)      !< kappa(|u|) at the slices (-)
      real(wp), allocatable :: traction(:)   !< t = kappa sign(u) q, on the race along e_t (N/m)
      real(wp) :: force = 0.0_wp             !< sum w t: on the race along e_t (N)
      real(wp) :: moment = 0.0_wp            !< moment on the roller about +x (N m)
      real(wp) :: power = 0.0_wp             !< sum w kappa |u| q (W), eq 4
      real(wp) :: sliding = 0.0_wp           !< sum w |u| q (N m/s): the Archard wear's load x slip
      real(wp) :: max_slip = 0.0_wp          !< largest |u| over the slices (m/s): printed Slip Velocity
      real(wp) :: max_slip_kappa = 0.0_wp    !< kappa(max_slip): printed Trac Coeff
      real(wp) :: net_coefficient = 0.0_wp   !< |force| / load (-), not printed (diagnostic)
   end type line_traction_t

contains

   !> Slip u(x) (m/s) of race `race` at axial position x (m) for profile prof and kinematics
   !> k (module header; eq 3, rolling component, line contact).
   elemental function line_slip(prof, k, race, x) result(u)
      type(roller_profile_t), intent(in) :: prof
      type(roller_spin_t), intent(in) :: k
      integer, intent(in) :: race
      real(wp), intent(in) :: x
      real(wp) :: u, p

      p = profile_drop(prof, x)
      if (race == RACE_OUTER) then
         u = (k%spin - k%rolling_spin)*0.5_wp*k%d - p*(k%spin - k%race_speed(1))
      else
         u = -(k%spin - k%rolling_spin)*0.5_wp*k%d + p*(k%spin - k%race_speed(2))
      end if
   end function line_slip

   !> Traction, power and moment of the line contact c (slices x, weights, q) with race
   !> `race` for kinematics k and traction law `law` (curve or table; eqs 1, 4).
   pure subroutine line_traction(prof, k, race, c, law, t)
      type(roller_profile_t), intent(in) :: prof
      type(roller_spin_t), intent(in) :: k
      integer, intent(in) :: race
      type(line_contact_t), intent(in) :: c
      type(traction_law_t), intent(in) :: law
      type(line_traction_t), intent(out) :: t
      real(wp), allocatable :: rho(:)
      real(wp) :: sgn
      integer :: n

      n = 0
      if (allocated(c%x)) n = size(c%x)
      allocate (t%slip(n), t%kappa(n), t%traction(n), rho(n))
      if (n == 0) return
      t%slip = line_slip(prof, k, race, c%x)
      t%kappa = law_kappa(law, t%slip)
      where (c%q > 0.0_wp)
         t%traction = t%kappa*sign(1.0_wp, t%slip)*c%q
      elsewhere
         t%traction = 0.0_wp
      end where
      where (t%slip == 0.0_wp) t%traction = 0.0_wp   ! no direction without slip (kappa(0) may be > 0)
      rho = 0.5_wp*k%d - profile_drop(prof, c%x)
      t%force = sum(c%weight*t%traction)
      sgn = merge(-1.0_wp, 1.0_wp, race == RACE_OUTER)
      t%moment = sgn*sum(c%weight*rho*t%traction)
      t%power = sum(c%weight*t%kappa*abs(t%slip)*max(c%q, 0.0_wp))
      t%sliding = sum(c%weight*abs(t%slip)*max(c%q, 0.0_wp))
      if (c%in_contact .and. c%load > 0.0_wp) then
         t%max_slip = maxval(abs(t%slip))
         t%max_slip_kappa = law_kappa(law, t%max_slip)
         t%net_coefficient = abs(t%force)/c%load
      end if
   end subroutine line_traction

   !> Moment (N m) about the roller axis of both race contacts at spin w (rad/s), other
   !> kinematics from k, plus an external moment m_ext (N m, e.g. cage friction).
   pure function roller_traction_moment(prof, k, w, c_o, c_i, law, m_ext) result(m)
      type(roller_profile_t), intent(in) :: prof
      type(roller_spin_t), intent(in) :: k
      type(traction_law_t), intent(in) :: law
      real(wp), intent(in) :: w, m_ext
      type(line_contact_t), intent(in) :: c_o, c_i
      real(wp) :: m
      type(roller_spin_t) :: kk
      type(line_traction_t) :: to, ti

      kk = k
      kk%spin = w
      call line_traction(prof, kk, RACE_OUTER, c_o, law, to)
      call line_traction(prof, kk, RACE_INNER, c_i, law, ti)
      m = to%moment + ti%moment + m_ext
   end function roller_traction_moment

   !> Roller spin W (rad/s) that balances the moment of the slice tractions of both races
   !> about the roller axis (plus m_ext, N m), the roller's rotational equilibrium of
   !> report 3.1 with the traction of eq 1.  Bracketed from W0 = k%rolling_spin in steps
   !> of u_step / (D/2) (u_step: a slip scale, m/s, e.g. the slip of maximum traction),
   !> then bisection to the round-off of W.  The root nearest to W0 is taken (kappa is
   !> not monotonic: a second root beyond the traction maximum may exist).  Engine error
   !> when no sign change is found within 60 steps; unloaded roller (no contact): W0.
   subroutine roller_equilibrium_spin(prof, k, c_o, c_i, law, m_ext, u_step, w, residual, error)
      type(roller_profile_t), intent(in) :: prof
      type(roller_spin_t), intent(in) :: k
      type(line_contact_t), intent(in) :: c_o, c_i
      type(traction_law_t), intent(in) :: law
      real(wp), intent(in) :: m_ext, u_step
      real(wp), intent(out) :: w, residual
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: w0, dw, lo, hi, m_lo, m_hi, m0, mid, m_mid
      integer :: it

      w0 = k%rolling_spin
      w = w0
      residual = 0.0_wp
      if (.not. (k%d > 0.0_wp .and. u_step > 0.0_wp)) then
         call input_error(error, "roller spin: need a roller diameter > 0 and a slip step > 0")
         return
      end if
      if (.not. (c_o%in_contact .or. c_i%in_contact)) return
      m0 = roller_traction_moment(prof, k, w0, c_o, c_i, law, m_ext)
      residual = m0
      if (m0 == 0.0_wp) return
      ! dM/dW < 0 on the rising part of the curve: M > 0 -> spin up (W larger)
      dw = sign(u_step/(0.5_wp*k%d), m0)*0.05_wp
      lo = w0
      m_lo = m0
      hi = w0
      m_hi = m0
      do it = 1, 60
         hi = lo + dw
         m_hi = roller_traction_moment(prof, k, hi, c_o, c_i, law, m_ext)
         if (sign(1.0_wp, m_hi) /= sign(1.0_wp, m_lo)) exit
         lo = hi
         m_lo = m_hi
         dw = 1.5_wp*dw
      end do
      if (sign(1.0_wp, m_hi) == sign(1.0_wp, m_lo)) then
         call engine_error(error, "roller spin: no moment balance found near the rolling spin")
         return
      end if
      do it = 1, 200
         mid = 0.5_wp*(lo + hi)
         m_mid = roller_traction_moment(prof, k, mid, c_o, c_i, law, m_ext)
         if (sign(1.0_wp, m_mid) == sign(1.0_wp, m_lo)) then
            lo = mid
            m_lo = m_mid
         else
            hi = mid
            m_hi = m_mid
         end if
         if (abs(hi - lo) <= 4.0_wp*spacing(max(abs(lo), abs(hi)))) exit
      end do
      if (abs(m_lo) <= abs(m_hi)) then
         w = lo
         residual = m_lo
      else
         w = hi
         residual = m_hi
      end if
   end subroutine roller_equilibrium_spin

end module adore_tribology_roller_traction
