!> The RE/race traction law: traction coefficient kappa as a function of the slip speed.
!>
!> Two kinds:
!> * the deck's four-parameter curve kappa(u) = (A + B u) exp(-C u) + D (Rec 10.1B/10.1C,
!>   fitted in `adore_tribology_traction_fit`);
!> * an arbitrary traction-slip table, ADORE's user subroutine ADRX7 (report 4.4.9: "compute
!>   the traction coefficient by interpolating this data").  The report gives no interpolation
!>   rule; pyadore's is: piecewise linear in the slip speed |u| (m/s) through the nodes, which
!>   start at u = 0 and increase strictly, and the last node's value held beyond the last
!>   node.  Linear interpolation adds no extremum the data do not have.
!>
!> kappa is the magnitude; callers give the traction the direction of the slip (eq 1).
module adore_tribology_traction_law
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   use adore_core_strings, only: itoa
   use adore_tribology_traction_fit, only: traction_coefficient
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private

   public :: traction_law_t, curve_law, table_law, law_kappa, law_slip_scale, check_traction_table
   public :: boundary_law
   public :: LAW_CURVE, LAW_TABLE

   integer, parameter :: LAW_CURVE = 1   !< four-parameter curve (Rec 10.1B/10.1C)
   integer, parameter :: LAW_TABLE = 2   !< traction-slip table (ADRX7)

   !> A traction law.  `coef` = [A, B, C, D] (B, C in s/m) for the curve; `slip` (m/s) and
   !> `kappa` (-) the table's nodes.
   type :: traction_law_t
      integer :: kind = LAW_CURVE
      real(wp) :: coef(4) = 0.0_wp
      real(wp), allocatable :: slip(:), kappa(:)
   end type traction_law_t

contains

   !> The law of the four-parameter curve coef = [A, B, C, D].
   pure function curve_law(coef) result(law)
      real(wp), intent(in) :: coef(4)
      type(traction_law_t) :: law

      law%kind = LAW_CURVE
      law%coef = coef
   end function curve_law

   !> Boundary (Coulomb) friction mu (1 - exp(-|u| / u_b)) as the four-parameter curve
   !> [A, B, C, D] = [-mu, 0, 1/u_b, mu]: kappa(0) = 0, rising over the slip u_b (m/s) to the
   !> coefficient mu (-) with no maximum (docs/tribology.md, "Boundary friction").
   pure function boundary_law(mu, u_b) result(law)
      real(wp), intent(in) :: mu, u_b
      type(traction_law_t) :: law

      law = curve_law([-mu, 0.0_wp, 1.0_wp/u_b, mu])
   end function boundary_law

   !> The law of a traction-slip table (slip in m/s, kappa dimensionless), checked with
   !> `check_traction_table`; `source` names the table in error messages.
   subroutine table_law(slip, kappa, source, law, error)
      real(wp), intent(in) :: slip(:), kappa(:)
      character(len=*), intent(in) :: source
      type(traction_law_t), intent(out) :: law
      type(error_type), allocatable, intent(out) :: error

      call check_traction_table(slip, kappa, source, error)
      if (allocated(error)) return
      law%kind = LAW_TABLE
      law%slip = slip
      law%kappa = kappa
   end subroutine table_law

   !> Input error unless the table has >= 2 nodes, equal lengths, finite values, slip(1) = 0,
   !> strictly increasing slips and kappa >= 0.  The message names `source` and the node.
   subroutine check_traction_table(slip, kappa, source, error)
      real(wp), intent(in) :: slip(:), kappa(:)
      character(len=*), intent(in) :: source
      type(error_type), allocatable, intent(out) :: error
      integer :: i

      if (size(slip) /= size(kappa)) then
         call input_error(error, source//": traction table: "//itoa(size(slip))//" slip values but "// &
                          itoa(size(kappa))//" traction coefficients")
         return
      end if
      if (size(slip) < 2) then
         call input_error(error, source//": traction table: expected at least 2 points (slip, "// &
                          "traction coefficient), got "//itoa(size(slip)))
         return
      end if
      do i = 1, size(slip)
         if (.not. (ieee_is_finite(slip(i)) .and. ieee_is_finite(kappa(i)))) then
            call input_error(error, source//": traction table point "//itoa(i)//": expected finite numbers")
            return
         end if
         if (kappa(i) < 0.0_wp) then
            call input_error(error, source//": traction table point "//itoa(i)//": expected a traction "// &
                             "coefficient >= 0 (the sign follows the slip)")
            return
         end if
      end do
      if (slip(1) /= 0.0_wp) then
         call input_error(error, source//": traction table point 1: expected slip 0 m/s (the table "// &
                          "starts at zero slip; give the traction coefficient there)")
         return
      end if
      do i = 2, size(slip)
         if (.not. (slip(i) > slip(i - 1))) then
            call input_error(error, source//": traction table point "//itoa(i)//": expected a slip "// &
                             "greater than that of point "//itoa(i - 1)//" (slips increase strictly)")
            return
         end if
      end do
   end subroutine check_traction_table

   !> Traction coefficient (-) of `law` at slip speed |u| (u in m/s).
   elemental function law_kappa(law, u) result(kappa)
      type(traction_law_t), intent(in) :: law
      real(wp), intent(in) :: u
      real(wp) :: kappa
      real(wp) :: s, t
      integer :: lo, hi, mid, n

      s = abs(u)
      if (law%kind /= LAW_TABLE) then
         kappa = traction_coefficient(law%coef(1), law%coef(2), law%coef(3), law%coef(4), s)
         return
      end if
      n = size(law%slip)
      if (s >= law%slip(n)) then
         kappa = law%kappa(n)
         return
      end if
      ! bisection: slip(lo) <= s < slip(hi)
      lo = 1
      hi = n
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (law%slip(mid) <= s) then
            lo = mid
         else
            hi = mid
         end if
      end do
      t = (s - law%slip(lo))/(law%slip(hi) - law%slip(lo))
      kappa = law%kappa(lo) + t*(law%kappa(hi) - law%kappa(lo))
   end function law_kappa

   !> A slip speed (m/s) on the scale where kappa changes, the step of slip searches: for
   !> the curve its slip of maximum traction 1/C - A/B (>= 1e-3 m/s; 0.1 m/s for a curve
   !> without maximum), for a table the slip of its largest coefficient (the first node
   !> past zero when kappa is largest at zero slip; >= 1e-3 m/s).
   pure function law_slip_scale(law) result(u)
      type(traction_law_t), intent(in) :: law
      real(wp) :: u
      integer :: i

      if (law%kind == LAW_TABLE) then
         i = maxloc(law%kappa, dim=1)
         if (i == 1) i = 2
         u = max(1.0e-3_wp, law%slip(i))
      else if (law%coef(2) /= 0.0_wp .and. law%coef(3) > 0.0_wp) then
         u = max(1.0e-3_wp, 1.0_wp/law%coef(3) - law%coef(1)/law%coef(2))
      else
         u = 0.1_wp
      end if
   end function law_slip_scale

end module adore_tribology_traction_law
