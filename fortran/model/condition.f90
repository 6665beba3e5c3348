!> The operating condition of a run: what may change while the bearing runs (issue #24 item 3)
!> - the bulk temperatures (which set the mounted geometry: fits, growth, clearance; ADRC2),
!> the load applied to the inner race and the degrees of freedom of the cage and the races
!> (report 4.4.6's DOF constraints).  A bearing system owns one
!> (adore_bearings_system's set_condition re-mounts and restarts the integrator); the
!> thermal model and any periodic update change it through that one call.
module adore_model_condition
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, input_error
   use adore_model_bearing, only: bearing_t
   implicit none
   private

   public :: operating_condition_t, condition_of, same_condition
   public :: body_dof_t, dof_constraints_t, default_constraints, deck_constraints, cage_option_free

   !> Appendix D's Rec 3.3, the one nonzero pattern whose meaning the report's print identifies
   !> (docs/deck-format.md, Rec 3.3): the rolling elements' axial motion, tilt and skew held.
   integer, parameter, public :: REC3_3_ROLLERS_PLANAR(11) = [1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1]

   !> Which degrees of freedom of a body move under its loads (.true.: free): translation
   !> along x, y, z and angular acceleration about the body's x, y, z axes.  A constrained
   !> translation keeps its position and velocity; a constrained rotation keeps its angular
   !> velocity (the body still turns at it).
   type :: body_dof_t
      logical :: translation(3) = .true.
      logical :: rotation(3) = .true.
   end type body_dof_t

   !> The constraints of the bodies (report 4.4.6).
   type :: dof_constraints_t
      !> every rolling element: translation along the bearing axis, radially and along the orbit;
      !> rotation about its own axis and the two transverse axes (a roller's tilt and skew);
      !> all free by default (used by the roller kind, adore_dynamics_roller_system)
      type(body_dof_t) :: elements
      type(body_dof_t) :: cage
      !> fixed in the housing, turning at its Rec 9.1.2 speed
      type(body_dof_t) :: outer = body_dof_t([.false., .false., .false.], [.false., .false., .false.])
      !> translating freely under the applied load, turning at its prescribed speed with its
      !> misalignment held
      type(body_dof_t) :: inner = body_dof_t([.true., .true., .true.], [.false., .false., .false.])
   end type dof_constraints_t

   !> Bulk temperatures (K, the TEMP_* order of adore_model_bearing) and the load applied to
   !> the inner race (N, N m; inertial components).
   type :: operating_condition_t
      real(wp) :: temperature(7) = 293.0_wp
      !> the bulk temperatures the geometry is mounted at (K; ADRC2 distortion from the
      !> deck's initial temperatures): equal to `temperature` when the geometry follows the
      !> temperatures, the initial ones while it is held (thermal model, docs/thermal.md)
      real(wp) :: geometry_temperature(7) = 293.0_wp
      real(wp) :: force(3) = 0.0_wp
      real(wp) :: moment(3) = 0.0_wp
      type(dof_constraints_t) :: constraints
   end type operating_condition_t

contains

   !> The condition bearing b starts with (Rec 2.7 temperatures, Rec 9.0 / 11 loads).
   pure function condition_of(b) result(c)
      type(bearing_t), intent(in) :: b
      type(operating_condition_t) :: c
      c%temperature = b%temperature
      c%geometry_temperature = b%temperature
      c%force = b%force
      c%moment = b%moment
   end function condition_of

   !> Whether two conditions are equal value by value (a bitwise comparison: an unchanged
   !> condition changes nothing, not even the integrator's step).
   pure logical function same_condition(a, b)
      type(operating_condition_t), intent(in) :: a, b
      same_condition = all(a%temperature == b%temperature) .and. &
                       all(a%geometry_temperature == b%geometry_temperature) .and. all(a%force == b%force) .and. &
                       all(a%moment == b%moment) .and. same_dof(a%constraints%cage, b%constraints%cage) .and. &
                       same_dof(a%constraints%elements, b%constraints%elements) .and. &
                       same_dof(a%constraints%outer, b%constraints%outer) .and. &
                       same_dof(a%constraints%inner, b%constraints%inner)
   end function same_condition

   pure logical function same_dof(a, b)
      type(body_dof_t), intent(in) :: a, b
      same_dof = all(a%translation .eqv. b%translation) .and. all(a%rotation .eqv. b%rotation)
   end function same_dof

   !> The run's constraints (report 4.4.6, until Rec 3.3's flags are identified, issue #25):
   !> outer race fixed, inner race free in translation with its rotation prescribed, the cage
   !> free - or, cage_spin_only, centred and untilted, turning about its own axis.
   pure function default_constraints(cage_spin_only) result(c)
      logical, intent(in) :: cage_spin_only
      type(dof_constraints_t) :: c
      if (cage_spin_only) c%cage = body_dof_t([.false., .false., .false.], [.true., .false., .false.])
   end function default_constraints

   !> The constraints the deck asks for (report 4.4.6, "Arbitrary Constraints of
   !> Degrees-of-freedom"): Rec 3.3's eleven flags (bearing_t%dof_flags) read as a whole
   !> pattern, the one reading the evidence supports (docs/deck-format.md, Rec 3.3):
   !> * all zero: nothing constrained - the rolling elements and the cage free in all six
   !>   DOFs, the races as default_constraints;
   !> * 1 1 1 1 0 0 0 0 0 0 1 (Appendix D, report 4.4.6's own example "a perfectly aligned
   !>   cylindrical roller bearing with purely radial load"): every rolling element's axial
   !>   translation and its rotations about the two transverse axes (a roller's tilt and
   !>   skew) held, the cage free in all six DOFs (the report's step 4000 prints the rollers'
   !>   axial position, tilt and skew exactly 0 and its cage moved axially, -5.457e-8 m, with
   !>   a transverse angular acceleration under zero moment, i.e. tilting).
   !> Any other pattern is an input error naming its first nonzero field that Appendix D's
   !> pattern lacks (else its first nonzero field): which position constrains which DOF
   !> alone is not identified.
   subroutine deck_constraints(flags, c, error)
      integer, intent(in) :: flags(:)
      type(dof_constraints_t), intent(out) :: c
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: num
      integer :: k, i
      c = default_constraints(.false.)
      if (all(flags == 0)) return
      if (size(flags) == size(REC3_3_ROLLERS_PLANAR)) then
         if (all(flags == REC3_3_ROLLERS_PLANAR)) then
            c%elements = body_dof_t([.false., .true., .true.], [.true., .false., .false.])
            return
         end if
      end if
      ! the first nonzero field that Appendix D's pattern does not have, else the first nonzero
      ! field (the deck departs from all zeros there and is not Appendix D's pattern)
      k = 0
      do i = 1, size(flags)
         if (flags(i) == 0) cycle
         if (k == 0) k = i
         if (i > size(REC3_3_ROLLERS_PLANAR)) then
            k = i
            exit
         end if
         if (flags(i) /= REC3_3_ROLLERS_PLANAR(i)) then
            k = i
            exit
         end if
      end do
      write (num, "(i0,a,i0)") k, " = ", flags(k)
      call input_error(error, "Rec 3.3 field "//trim(num)//": of the DOF constraint flags (report 4.4.6) only "// &
                       "all zeros (nothing constrained) and Appendix D's 1 1 1 1 0 0 0 0 0 0 1 (the rolling "// &
                       "elements' axial motion, tilt and skew held) are identified (docs/deck-format.md, Rec 3.3)")
   end subroutine deck_constraints

   !> Whether the run option cage = option (report 4.4.6) frees the cage: "free" yes, "deck"
   !> as the deck's Rec 3.3 flags say (deck_constraints: all zero constrains nothing, a
   !> nonzero flag is an input error), anything else ("centred") no.
   subroutine cage_option_free(option, flags, free, error)
      character(len=*), intent(in) :: option
      integer, intent(in) :: flags(:)
      logical, intent(out) :: free
      type(error_type), allocatable, intent(out) :: error
      type(dof_constraints_t) :: deck_dof
      select case (option)
      case ("free")
         free = .true.
      case ("deck")
         call deck_constraints(flags, deck_dof, error)
         free = all(deck_dof%cage%translation) .and. .not. allocated(error)
      case default
         free = .false.
      end select
   end subroutine cage_option_free

end module adore_model_condition
