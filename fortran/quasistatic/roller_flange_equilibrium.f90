!> The quasi-static start of a flanged cylindrical roller bearing (issue #26; docs/rollers.md,
!> "Flanges at step 0"): every roller in radial, tilting and axial equilibrium under its
!> slice contacts (adore_quasistatic_roller_equilibrium's roller_contacts), its centrifugal
!> force and its roller end / flange contacts (adore_contact_roller_flange's flange_contact,
!> the dynamics' geometry and Hertz law), the inner race in force equilibrium along x, y and z
!> under the applied load: the flanges carry the axial load at step 0.
!>
!> Per roller the unknowns are z = (r, gamma, x): centre radius, tilt about e_t (the axis
!> rises by gamma x along e_r, as adore_forces_roller_bearing) and axial position; the
!> residuals, in the orbit frame (e_x, e_r, e_t) of the roller:
!>     G1 = Q_i - Q_o + m w**2 r + F_r            (radial force, N)
!>     G2 = (M_i - M_o + M_t) / (L/2)             (tilt moment about e_t over the half length, N)
!>     G3 = F_x + K_REG (g_+ - g_-)/2             (axial force, N)
!> with F, M_t the flange contacts' force and moment about the roller centre (no flange
!> friction: the step-0 start leaves traction out of the equilibrium, as for the slices).
!> g_-, g_+: the axial gaps (m; < 0 interference) from the roller end at -x / +x to the
!> nearest flange face on that side, -delta/cos theta.  K_REG = 1 N/m is a regularising
!> spring that centres a roller touching no flange in its free axial play (its axial position
!> is otherwise undetermined); on a roller pinched between its flanges it biases the axial
!> force by K_REG times a few um, i.e. 1e-6 N against loads of tens of N (with flanges on
!> one side only the spring pulls the roller to the races' mid-position x = u_x/2).  Roller skew is 0 (as the flangeless start); the races' flanges do not tilt
!> with a prescribed misalignment (the dynamics' flange model has the same simplification).
!> The permissible slice contact ends move with the roller's axial offset from each race
!> (as the dynamics).  Newton with central finite-difference Jacobians and backtracking, a
!> 2 x 2 per roller (r, gamma; its x solved inside by a bracketed Newton with the analytic
!> slope, roller_axial) inside a 3 x 3 of the inner race (its x, y, z); the race's axial stiffness
!> is 0 until the rollers touch both flanges: it then moves by AXIAL_GAP_STEP along its
!> unbalanced axial load.  Units SI.
module adore_quasistatic_roller_flange_equilibrium
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, engine_error, input_error
   use adore_core_linalg, only: solve_dense
   use adore_core_rotation, only: cross
   use adore_contact_line_slices, only: line_contact_t
   use adore_contact_roller_flange, only: roller_flange_set_t, flange_contact_t, flange_contact
   use adore_quasistatic_roller_equilibrium, only: roller_qs_bearing_t, roller_qs_load_t, roller_qs_solution_t, &
                                                   roller_contacts, clear_reactions, add_slice_reactions
   implicit none
   private

   public :: solve_flanged_equilibrium, flanged_roller_residual

   real(wp), parameter, public :: K_REG = 1.0_wp        !< regularising axial spring (N/m)
   real(wp), parameter :: AXIAL_GAP_STEP = 1.0e-3_wp    !< race's axial step without flange stiffness (x D)
   !> Newton steps below STEP_FLOOR D (m) are the round-off floor: the slice and flange
   !> interferences are differences of lengths ~0.02-0.06 m (spacing ~1e-17 m), a light
   !> contact's load then carries a relative round-off of ~1e-10
   real(wp), parameter :: STEP_FLOOR = 1.0e-13_wp

contains

   !> Residuals g (N; module header) of one roller at state z = (r (m), gamma (rad), x (m))
   !> against the inner race at u = (x, r, t) in the roller's orbit frame (m), race tilt t_r
   !> (rad) at its azimuth, orbital speed w (rad/s); its slice contacts c_o, c_i, its flange
   !> contacts fl (one per flange of f), the flanges' force fsum and moment msum about the
   !> roller centre (N, N m; orbit frame); g3x: dG3/dx (N/m; delta's x derivative -n_x).
   pure subroutine flanged_roller_residual(b, f, u, t_r, w, z, g, c_o, c_i, fl, fsum, msum, g3x)
      type(roller_qs_bearing_t), intent(in) :: b
      type(roller_flange_set_t), intent(in) :: f
      real(wp), intent(in) :: u(3), t_r, w, z(3)
      real(wp), intent(out) :: g(3), fsum(3), msum(3)
      real(wp), intent(out), optional :: g3x   !< dG3/dx (N/m): -sum k cos**2 theta - K_REG
      type(line_contact_t), intent(out) :: c_o, c_i
      type(flange_contact_t), intent(out) :: fl(:)
      type(roller_qs_bearing_t) :: q
      real(wp) :: axis(3), centre(3), o(3), zero(3), force(3), gap(2)
      integer :: i, k
      zero = 0.0_wp
      q = b
      q%lim_o = shifted(b%lim_o, z(3))
      q%lim_i = shifted(b%lim_i, z(3) - u(1))
      call roller_contacts(q, z(1), z(2), u(2), t_r, 0.0_wp, c_o, c_i)
      centre = [z(3), z(1), 0.0_wp]
      axis = [1.0_wp, z(2), 0.0_wp]
      axis = axis/norm2(axis)
      fsum = 0.0_wp
      msum = 0.0_wp
      if (present(g3x)) g3x = -K_REG
      do i = 1, size(f%flange)
         o = zero
         if (f%flange(i)%race == 2) o = u
         call flange_contact(f, f%flange(i), centre, axis, zero, zero, o, zero, 0.0_wp, fl(i))
         if (fl(i)%load > 0.0_wp) then
            force = fl(i)%load*fl(i)%normal
            fsum = fsum + force
            msum = msum + cross(fl(i)%point - centre, force)
            if (present(g3x)) g3x = g3x - fl(i)%stiffness*fl(i)%normal(1)**2
         end if
      end do
      g(1) = c_i%load - c_o%load + b%mass*w**2*z(1) + fsum(2)
      g(2) = (c_i%moment - c_o%moment + msum(3))/(0.5_wp*b%profile%length)
      ! the free axial play's ends: the nearest flange face's gap along x on each side
      gap = huge(1.0_wp)
      do i = 1, size(f%flange)
         k = merge(1, 2, f%flange(i)%side < 0)
         gap(k) = min(gap(k), -fl(i)%delta/cos(f%flange(i)%angle))
      end do
      if (all(gap < huge(1.0_wp))) then
         g(3) = fsum(1) + K_REG*0.5_wp*(gap(2) - gap(1))
      else
         g(3) = fsum(1) - K_REG*(z(3) - 0.5_wp*u(1))
      end if
   contains
      pure function shifted(lim, dx) result(l2)
         real(wp), intent(in) :: lim(2), dx
         real(wp) :: l2(2)
         l2 = [max(lim(1) - dx, -0.5_wp*b%profile%length), min(lim(2) - dx, 0.5_wp*b%profile%length)]
      end function shifted
   end subroutine flanged_roller_residual

   !> The axial position z(3) (m) of one roller at z(1:2) where its axial residual G3 = 0
   !> (module header): G3 decreases with x (dG3/dx = -sum k cos**2 theta - K_REG), so Newton
   !> with that analytic slope inside a bracket that bisection keeps (the flange's Hertz
   !> onset makes a finite difference over x useless there).  Residuals, contacts as
   !> flanged_roller_residual at the solution.
   pure subroutine roller_axial(b, f, u, t_r, w, z, g, c_o, c_i, fl, fsum, msum)
      type(roller_qs_bearing_t), intent(in) :: b
      type(roller_flange_set_t), intent(in) :: f
      real(wp), intent(in) :: u(3), t_r, w
      real(wp), intent(inout) :: z(3)
      real(wp), intent(out) :: g(3), fsum(3), msum(3)
      type(line_contact_t), intent(out) :: c_o, c_i
      type(flange_contact_t), intent(out) :: fl(:)
      real(wp) :: lo, hi, slope, xn
      integer :: it
      lo = -huge(1.0_wp)
      hi = huge(1.0_wp)
      do it = 1, 100
         call flanged_roller_residual(b, f, u, t_r, w, z, g, c_o, c_i, fl, fsum, msum, slope)
         if (abs(g(3)) <= 1.0e-12_wp*max(sum(fl%load), 1.0e-3_wp)) return
         if (g(3) > 0.0_wp) then
            lo = z(3)
         else
            hi = z(3)
         end if
         xn = z(3) - g(3)/slope
         if (.not. (xn > lo .and. xn < hi)) xn = 0.5_wp*(lo + hi)
         if (abs(xn - z(3)) <= STEP_FLOOR*b%d) return
         z(3) = xn
      end do
   end subroutine roller_axial

   !> Equilibrium of one flanged roller (module header) against the race at u (orbit frame,
   !> m), tilt t_r (rad), orbital speed w (rad/s); z = (r, gamma, x): start in, solution out.
   !> Newton on (r, gamma) with central finite differences, x solved inside each evaluation
   !> (roller_axial).  ok = .false. when Newton fails.
   pure subroutine solve_flanged_roller(b, f, u, t_r, w, z, c_o, c_i, fl, fsum, msum, ok)
      type(roller_qs_bearing_t), intent(in) :: b
      type(roller_flange_set_t), intent(in) :: f
      real(wp), intent(in) :: u(3), t_r, w
      real(wp), intent(inout) :: z(3)
      type(line_contact_t), intent(out) :: c_o, c_i
      type(flange_contact_t), intent(out) :: fl(:)
      real(wp), intent(out) :: fsum(3), msum(3)
      logical, intent(out) :: ok
      type(line_contact_t) :: to, ti
      type(flange_contact_t) :: ft(size(fl))
      real(wp) :: g(3), gp(3), gm(3), gt(3), jac(2, 2), step(2), h(2), zp(3), zt(3), t, scale, fs(3), ms(3), lsc
      integer :: it, k, ls
      logical :: solved

      ok = .false.
      lsc = 0.5_wp*b%profile%length
      h = 1.0e-7_wp*b%d*[1.0_wp, 1.0_wp/lsc]
      call roller_axial(b, f, u, t_r, w, z, g, c_o, c_i, fl, fsum, msum)
      do it = 1, 100
         if (.not. (c_o%in_contact .or. c_i%in_contact)) then
            if (b%mass*w**2 <= 0.0_wp) then      ! no speed, no contact: the roller floats
               ok = .true.
               return
            end if
            ! free roller: put it on the outer race (centrifugal side)
            z(1) = z(1) - c_o%max_deflection + 1.0e-9_wp*b%d
            call roller_axial(b, f, u, t_r, w, z, g, c_o, c_i, fl, fsum, msum)
            cycle
         end if
         scale = max(b%mass*w**2*abs(z(1)) + c_o%load + c_i%load + sum(fl%load), 1.0e-9_wp)
         if (maxval(abs(g(1:2))) <= 1.0e-11_wp*scale) then
            ok = .true.
            return
         end if
         do k = 1, 2
            zp = z
            zp(k) = z(k) + h(k)
            call roller_axial(b, f, u, t_r, w, zp, gp, to, ti, ft, fs, ms)
            zp = z
            zp(k) = z(k) - h(k)
            call roller_axial(b, f, u, t_r, w, zp, gm, to, ti, ft, fs, ms)
            jac(:, k) = (gp(1:2) - gm(1:2))/(2.0_wp*h(k))
         end do
         call solve_dense(2, jac, -g(1:2), step, solved)
         if (.not. solved) return
         if (maxval(abs(step*[1.0_wp, lsc])) <= STEP_FLOOR*b%d) then
            ok = .true.      ! round-off floor of the contact loads reached
            return
         end if
         t = 1.0_wp
         do ls = 1, 30
            zt = z
            zt(1:2) = z(1:2) + t*step
            call roller_axial(b, f, u, t_r, w, zt, gt, to, ti, ft, fs, ms)
            if (maxval(abs(gt(1:2))) < maxval(abs(g(1:2))) .or. t < 1.0e-6_wp) exit
            t = 0.5_wp*t
         end do
         z = zt
         g = gt
         c_o = to
         c_i = ti
         fl = ft
         fsum = fs
         msum = ms
      end do
      ! the last iterate: accepted at the round-off level of light contacts' loads
      ok = maxval(abs(g(1:2))) <= 1.0e-9_wp*max(b%mass*w**2*abs(z(1)) + c_o%load + c_i%load + sum(fl%load), 1.0e-9_wp)
   end subroutine solve_flanged_roller

   !> Equilibrium of the flanged bearing (module header) with flanges f for orbital speeds
   !> w(n) (rad/s): every roller in radial, tilt and axial equilibrium, the inner race in
   !> x, y, z force equilibrium under ld%force (N); the inner race's misalignment prescribed
   !> (section 4.4.1).  Fills s as solve_roller_equilibrium plus the axial positions and
   !> flange loads; the race forces and moments include the flange reactions.
   subroutine solve_flanged_equilibrium(b, f, ld, w, s, error)
      type(roller_qs_bearing_t), intent(in) :: b
      type(roller_flange_set_t), intent(in) :: f
      type(roller_qs_load_t), intent(in) :: ld
      real(wp), intent(in) :: w(:)
      type(roller_qs_solution_t), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error

      real(wp) :: uu(3), res(3), rnew(3), rp(3), rm(3), jac(3, 3), step(3), u_try(3), load_scale, t, h, applied(3)
      real(wp), allocatable :: r0(:), g0(:), x0(:)
      integer :: it, ls, n, nf, k
      logical :: ok, solved

      n = b%n_rollers
      if (.not. allocated(f%flange)) then
         call input_error(error, "flanged roller equilibrium: no flanges")
         return
      end if
      nf = size(f%flange)
      if (n < 1 .or. size(w) /= n .or. b%d <= 0.0_wp .or. b%r_o <= b%r_i) then
         call input_error(error, "roller equilibrium: need rollers, one orbital speed each and R_o > R_i")
         return
      end if
      allocate (s%azimuth(n), s%orbital_speed(n), s%r(n), s%tilt(n), s%centrifugal(n), s%c_o(n), s%c_i(n), s%x(n))
      allocate (s%flange_load(nf, n), s%flange_axial(nf, n), s%flange_height(nf, n))
      allocate (r0(n), g0(n), x0(n))
      s%azimuth = [(2.0_wp*pi*real(it - 1, wp)/real(n, wp), it=1, n)]
      s%orbital_speed = w
      s%r = b%r_o - 0.5_wp*b%d + 1.0e-4_wp*b%d
      s%tilt = 0.0_wp
      s%x = 0.0_wp
      applied = ld%force + b%inner_race_mass*ld%gravity
      load_scale = max(norm2(applied), maxval(b%mass*w**2*b%r_o), 1.0e-3_wp)
      h = 1.0e-7_wp*b%d
      uu = 0.0_wp

      call evaluate(uu, res, ok)
      if (.not. ok) return
      do it = 1, 200
         s%iterations = it
         if (maxval(abs(res)) <= 1.0e-11_wp*load_scale) exit
         ! central differences over the rollers' re-solved equilibria (from the same start)
         r0 = s%r
         g0 = s%tilt
         x0 = s%x
         do k = 1, 3
            u_try = uu
            u_try(k) = uu(k) + h
            call evaluate(u_try, rp, ok)
            if (.not. ok) return
            call restore()
            u_try(k) = uu(k) - h
            call evaluate(u_try, rm, ok)
            if (.not. ok) return
            call restore()
            jac(:, k) = (rp - rm)/(2.0_wp*h)
         end do
         call race_step(jac, res, step, solved)
         if (solved .and. maxval(abs(step)) <= STEP_FLOOR*b%d) then   ! round-off floor
            ! the difference quotients left s at a perturbed race: back to uu
            call restore()
            call evaluate(uu, res, ok)
            if (.not. ok) return
            exit
         end if
         t = 1.0_wp
         do ls = 1, 40
            u_try = uu + t*step
            call restore()
            call evaluate(u_try, rnew, ok)
            if (.not. ok) return
            if (maxval(abs(rnew)) < maxval(abs(res)) .or. .not. solved .or. t < 1.0e-8_wp) exit
            t = 0.5_wp*t
         end do
         uu = u_try
         res = rnew
      end do
      s%u = uu(2:3)
      s%u_axial = uu(1)
      s%race_residual = res(2:3)
      if (maxval(abs(res)) > 1.0e-8_wp*load_scale) then
         call engine_error(error, "flanged roller equilibrium: inner race Newton iterations did not converge")
         return
      end if

   contains

      subroutine restore()
         s%r = r0
         s%tilt = g0
         s%x = x0
      end subroutine restore

      !> Newton step of the race (x, y, z) for residual res (N), Jacobian jac (N/m).  Without
      !> flange contact the axial row is 0: the race then moves AXIAL_GAP_STEP D along its
      !> unbalanced axial load and its radial step solves the y, z block (or moves 1e-4 D
      !> along the unbalanced radial load when that is singular too); solved = .false. then.
      subroutine race_step(jac, res, step, solved)
         real(wp), intent(in) :: jac(3, 3), res(3)
         real(wp), intent(out) :: step(3)
         logical, intent(out) :: solved
         logical :: ok2
         if (abs(jac(1, 1)) > 1.0e-9_wp*maxval(abs(jac))) then
            call solve_dense(3, jac, -res, step, solved)
            if (solved) return
         end if
         solved = .false.
         step(1) = 0.0_wp
         if (abs(res(1)) > 1.0e-11_wp*load_scale) step(1) = sign(AXIAL_GAP_STEP*b%d, res(1))
         call solve_dense(2, jac(2:3, 2:3), -res(2:3), step(2:3), ok2)
         if (.not. ok2) step(2:3) = res(2:3)/max(norm2(res(2:3)), tiny(1.0_wp))*1.0e-4_wp*b%d
      end subroutine race_step

      !> Solve all rollers for the race at u = (x, y, z) (m); race residual res (N): the
      !> rollers' force on the inner race plus the applied load.
      subroutine evaluate(u, res, ok)
         real(wp), intent(in) :: u(3)
         real(wp), intent(out) :: res(3)
         logical, intent(out) :: ok
         type(flange_contact_t) :: fl(nf)
         real(wp) :: sp, cp, uo(3), t_r, z(3), fsum(3), msum(3), e_r(3), e_t(3), fr(3), arm(3)
         integer :: k, i, j
         call clear_reactions(s)
         do k = 1, n
            sp = sin(s%azimuth(k))
            cp = cos(s%azimuth(k))
            e_r = [0.0_wp, -sp, cp]
            e_t = [0.0_wp, -cp, -sp]
            uo = [u(1), dot_product(u, e_r), dot_product(u, e_t)]
            t_r = -(ld%misalignment(1)*cp + ld%misalignment(2)*sp)
            z = [s%r(k), s%tilt(k), s%x(k)]
            call solve_flanged_roller(b, f, uo, t_r, w(k), z, s%c_o(k), s%c_i(k), fl, fsum, msum, ok)
            if (.not. ok) then
               call engine_error(error, "flanged roller equilibrium: a roller has no equilibrium (Newton failed)")
               return
            end if
            s%r(k) = z(1)
            s%tilt(k) = z(2)
            s%x(k) = z(3)
            s%centrifugal(k) = b%mass*w(k)**2*z(1)
            s%max_roller_residual = max(s%max_roller_residual, abs(s%c_i(k)%load - s%c_o(k)%load + &
                                                                   s%centrifugal(k) + fsum(2)), abs(fsum(1)))
            call add_slice_reactions(s, k, sp, cp)
            ! flanges: the reaction -Q n at the contact point, moment about the race centre
            do i = 1, nf
               s%flange_load(i, k) = fl(i)%load
               s%flange_axial(i, k) = fl(i)%load*fl(i)%normal(1)
               s%flange_height(i, k) = fl(i)%height
               if (.not. (fl(i)%load > 0.0_wp)) cycle
               j = f%flange(i)%race
               fr = -fl(i)%load*fl(i)%normal
               arm = fl(i)%point
               if (j == 2) arm = arm - uo
               arm = cross(arm, fr)
               fr = fr(1)*[1.0_wp, 0.0_wp, 0.0_wp] + fr(2)*e_r + fr(3)*e_t
               arm = arm(1)*[1.0_wp, 0.0_wp, 0.0_wp] + arm(2)*e_r + arm(3)*e_t
               if (j == 2) then
                  s%inner_force = s%inner_force + fr
                  s%inner_moment = s%inner_moment + arm
               else
                  s%outer_force = s%outer_force + fr
                  s%outer_moment = s%outer_moment + arm
               end if
            end do
         end do
         res = s%inner_force + applied
      end subroutine evaluate

   end subroutine solve_flanged_equilibrium

end module adore_quasistatic_roller_flange_equilibrium
