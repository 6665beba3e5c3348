!> Engine unit tests of the traction law (fortran/tribology/traction_law.f90) and the
!> traction-slip table file (fortran/deck/traction_table.f90, ADRX7): interpolation through
!> the nodes, the linear-interpolation error bound against the curve it samples, the
!> constant-coefficient identity power = mu * sliding, every rejected input, and the boundary
!> (Coulomb) law of the run option boundary_friction.
program test_traction_law
   use adore_test_support, only: check, finish
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, ADORE_INPUT_ERROR
   use adore_tribology_traction_fit, only: traction_coefficient
   use adore_tribology_traction_law, only: traction_law_t, curve_law, table_law, law_kappa, &
                                           law_slip_scale, boundary_law, LAW_TABLE, LAW_CURVE
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, contact_traction, SIDE_INNER, &
                                   print_slip_node
   use adore_deck_traction_table, only: read_traction_table
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none

   ! the Appendix D curve (k0 0, kmax 0.1, kinf 0.08, umax 0.2 m/s), fitted
   real(wp), parameter :: coef(4) = [-0.08_wp, 0.9572392597877629_wp, 8.589122562472975_wp, 0.08_wp]

   call test_nodes_and_midpoints()
   call test_table_of_the_curve()
   call test_constant_table_power()
   call test_rejected_tables()
   call test_file_reader()
   call test_boundary_law()
   call finish("traction law")

contains

   subroutine test_nodes_and_midpoints()
      type(traction_law_t) :: law
      type(error_type), allocatable :: error
      real(wp), parameter :: u(4) = [0.0_wp, 0.1_wp, 0.3_wp, 1.0_wp], k(4) = [0.02_wp, 0.1_wp, 0.09_wp, 0.05_wp]
      integer :: i

      call table_law(u, k, "nodes", law, error)
      call check(.not. allocated(error), "table: accepted")
      call check(law%kind == LAW_TABLE, "table: kind")
      do i = 1, 4
         call check(law_kappa(law, u(i)) == k(i), "table: node value reproduced")
         call check(law_kappa(law, -u(i)) == k(i), "table: kappa depends on |u|")
      end do
      call check(abs(law_kappa(law, 0.05_wp) - 0.06_wp) < 1.0e-15_wp, "table: midpoint 1")
      call check(abs(law_kappa(law, 0.2_wp) - 0.095_wp) < 1.0e-15_wp, "table: midpoint 2")
      call check(abs(law_kappa(law, 0.65_wp) - 0.07_wp) < 1.0e-15_wp, "table: midpoint 3")
      call check(law_kappa(law, 5.0_wp) == 0.05_wp, "table: held beyond the last node")
      call check(abs(law_slip_scale(law) - 0.1_wp) < 1.0e-15_wp, "table: slip scale = slip of max kappa")
      call check(abs(law_kappa(curve_law(coef), 0.2_wp) - 0.1_wp) < 1.0e-12_wp, "curve law: kmax at umax")
   end subroutine test_nodes_and_midpoints

   !> A table sampling the curve at spacing h differs from it by at most h**2/8 max|kappa''|
   !> (linear interpolation error); the bound is checked, and that it is not loose by 100x.
   subroutine test_table_of_the_curve()
      type(traction_law_t) :: law, curve
      type(error_type), allocatable :: error
      integer, parameter :: n = 201, m = 20001
      real(wp) :: u(n), k(n), h, x, err, d2, bound
      integer :: i

      h = 2.0_wp/(n - 1)
      u = [(h*(i - 1), i=1, n)]
      k = traction_coefficient(coef(1), coef(2), coef(3), coef(4), u)
      call table_law(u, k, "curve samples", law, error)
      call check(.not. allocated(error), "curve table: accepted")
      curve = curve_law(coef)
      err = 0.0_wp
      d2 = 0.0_wp
      do i = 1, m
         x = 2.0_wp*(i - 1)/(m - 1)
         err = max(err, abs(law_kappa(law, x) - law_kappa(curve, x)))
         ! kappa'' = (C**2 (A + B u) - 2 B C) exp(-C u)
         d2 = max(d2, abs((coef(3)**2*(coef(1) + coef(2)*x) - 2.0_wp*coef(2)*coef(3))*exp(-coef(3)*x)))
      end do
      bound = h**2/8.0_wp*d2
      call check(err <= bound, "curve table: error within h**2/8 max|kappa''|")
      call check(err >= 0.01_wp*bound, "curve table: the bound is not vacuous")
   end subroutine test_table_of_the_curve

   !> kappa = mu everywhere: the contact power is mu times the sliding integral of |u| dQ.
   subroutine test_constant_table_power()
      type(traction_law_t) :: law
      type(error_type), allocatable :: error
      type(ball_race_contact_t) :: c
      type(contact_traction_t) :: t
      real(wp), parameter :: mu = 0.07_wp
      real(wp) :: s_node, u_node

      call table_law([0.0_wp, 1.0_wp], [mu, mu], "constant", law, error)
      c%side = SIDE_INNER
      c%alpha = 0.48_wp
      c%rho = 0.009525_wp
      c%r_b = 0.07_wp
      c%omega = [-7800.0_wp, 1140.0_wp]
      c%race_speed = 1151.0_wp
      c%a = 1.25e-3_wp
      c%load = 770.0_wp
      call contact_traction(c, law, 1.0_wp, 24, t, error)
      call check(.not. allocated(error), "constant table: contact accepted")
      call check(t%sliding > 0.0_wp, "constant table: the contact slides")
      call check(abs(t%power - mu*t%sliding) <= 1.0e-12_wp*t%power, "constant table: power = mu * sliding")
      call print_slip_node(c, 24, s_node, u_node)
      call check(law_kappa(law, u_node) == mu, "constant table: printed coefficient = mu")
   end subroutine test_constant_table_power

   subroutine test_rejected_tables()
      type(traction_law_t) :: law
      type(error_type), allocatable :: error
      real(wp) :: nan

      nan = ieee_value(nan, ieee_quiet_nan)
      call table_law([0.0_wp], [0.1_wp], "t", law, error)
      call expect(error, "at least 2 points", "one point rejected")
      call table_law([0.1_wp, 0.2_wp], [0.1_wp, 0.1_wp], "t", law, error)
      call expect(error, "point 1: expected slip 0", "no zero-slip point rejected")
      call table_law([0.0_wp, 0.2_wp, 0.2_wp], [0.1_wp, 0.1_wp, 0.1_wp], "t", law, error)
      call expect(error, "point 3: expected a slip greater", "repeated slip rejected")
      call table_law([0.0_wp, 0.2_wp], [0.1_wp, -0.1_wp], "t", law, error)
      call expect(error, "point 2: expected a traction coefficient >= 0", "negative coefficient rejected")
      call table_law([0.0_wp, nan], [0.1_wp, 0.1_wp], "t", law, error)
      call expect(error, "point 2: expected finite", "NaN rejected")
      call table_law([0.0_wp, 1.0_wp], [0.1_wp], "t", law, error)
      call expect(error, "2 slip values but 1", "unequal lengths rejected")
   end subroutine test_rejected_tables

   !> The boundary (Coulomb) law of the run option boundary_friction: mu (1 - exp(-|u| / u_b)),
   !> 0 at zero slip, slope mu / u_b there, mu (1 - 1/e) at u_b, mu within 1e-12 at 30 u_b.
   subroutine test_boundary_law()
      type(traction_law_t) :: law
      real(wp), parameter :: mu = 0.1_wp, u_b = 0.01_wp, h = 1.0e-7_wp

      law = boundary_law(mu, u_b)
      call check(law%kind == LAW_CURVE, "boundary law: a curve")
      call check(law_kappa(law, 0.0_wp) == 0.0_wp, "boundary law: 0 at zero slip")
      call check(abs(law_kappa(law, h)/h - mu/u_b) < 1.0e-4_wp*mu/u_b, "boundary law: slope mu/u_b at zero")
      call check(abs(law_kappa(law, u_b) - mu*(1.0_wp - exp(-1.0_wp))) < 1.0e-15_wp, "boundary law: at u_b")
      call check(abs(law_kappa(law, -u_b) - law_kappa(law, u_b)) == 0.0_wp, "boundary law: kappa depends on |u|")
      call check(abs(law_kappa(law, 30.0_wp*u_b) - mu) < 1.0e-12_wp, "boundary law: mu beyond the slip")
   end subroutine test_boundary_law

   subroutine test_file_reader()
      type(traction_law_t) :: law
      type(error_type), allocatable :: error
      character(len=*), parameter :: path = "test_traction_law_table.txt"
      integer :: u_del

      call write_file(path, [character(len=40) :: "# measured at 323 K", "slip_m_s, kappa", &
                                                  "0.0, 0.0", "", "0.05  0.06   # rising", &
                                                  "2.0E-01,1.0E-01", "1 0.08"])
      call read_traction_table(path, law, error)
      call check(.not. allocated(error), "file: header, comments, blanks and commas accepted")
      if (.not. allocated(error)) then
         call check(size(law%slip) == 4, "file: four points")
         call check(all(law%slip == [0.0_wp, 0.05_wp, 0.2_wp, 1.0_wp]), "file: slips")
         call check(all(law%kappa == [0.0_wp, 0.06_wp, 0.1_wp, 0.08_wp]), "file: coefficients")
      end if

      call write_file(path, [character(len=20) :: "0 0", "0.1 abc"])
      call read_traction_table(path, law, error)
      call expect(error, path//":2:5: traction table: expected a number", "file: bad number located")
      if (allocated(error)) call check(index(error%message, "    0.1 abc"//new_line("a")//"        ^") > 0, &
                                       "file: caret under the column")
      call write_file(path, [character(len=20) :: "0 0 1"])
      call read_traction_table(path, law, error)
      call expect(error, path//":1:5: traction table: expected two numbers", "file: third number located")
      call write_file(path, [character(len=20) :: "0 0", "0.1"])
      call read_traction_table(path, law, error)
      call expect(error, path//":2:4: traction table: expected two numbers", "file: one number located")
      call write_file(path, [character(len=20) :: "0 0", "0.1 0.1", "0.1 0.2"])
      call read_traction_table(path, law, error)
      call expect(error, path//": traction table point 3: expected a slip greater", "file: table checks")
      call read_traction_table("no_such_traction_table.txt", law, error)
      call expect(error, "no_such_traction_table.txt: traction table file not found", "file: missing")
      open (newunit=u_del, file=path)
      close (u_del, status="delete")
   end subroutine test_file_reader

   subroutine write_file(path, lines)
      character(len=*), intent(in) :: path, lines(:)
      integer :: u, i

      open (newunit=u, file=path, status="replace", action="write")
      do i = 1, size(lines)
         write (u, "(a)") trim(lines(i))
      end do
      close (u)
   end subroutine write_file

   subroutine expect(error, text, what)
      type(error_type), allocatable, intent(in) :: error
      character(len=*), intent(in) :: text, what

      call check(allocated(error), what//": error raised")
      if (.not. allocated(error)) return
      call check(error%stat == ADORE_INPUT_ERROR, what//": input error")
      call check(index(error%message, text) > 0, what//": message has '"//text//"'")
      if (index(error%message, text) == 0) write (*, "(a)") "  got: "//error%message
   end subroutine expect

end program test_traction_law
