!> Gauss-Legendre quadrature nodes and weights (used by the contact integrals, report
!> section 2.1: Gaussian quadrature in each zone between pure-rolling points).
!>
!> The rules of the orders the engine uses in its inner loops (TABLED_ORDERS) are
!> compile-time tables written by gauss_legendre_newton itself with 18 significant digits
!> (es25.17: every double round-trips), so a tabled rule is bit-identical to the Newton
!> one (fortran/tests/test_tribology.f90 checks it) without its cost at every call.
module adore_core_quadrature
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   implicit none
   private

   public :: gauss_legendre, gauss_legendre_newton

   !> orders held as tables (any other order is computed by Newton iteration)
   integer, parameter, public :: TABLED_ORDERS(7) = [4, 6, 8, 10, 12, 16, 24]

   ! ---- tables written by gauss_legendre_newton (do not edit by hand)
   real(wp), parameter :: X4(4) = [ &
      -8.61136311594052573E-001_wp, &
      -3.39981043584856313E-001_wp, &
       3.39981043584856313E-001_wp, &
       8.61136311594052573E-001_wp ]
   real(wp), parameter :: W4(4) = [ &
       3.47854845137453739E-001_wp, &
       6.52145154862546428E-001_wp, &
       6.52145154862546428E-001_wp, &
       3.47854845137453739E-001_wp ]
   real(wp), parameter :: X6(6) = [ &
      -9.32469514203152050E-001_wp, &
      -6.61209386466264593E-001_wp, &
      -2.38619186083196932E-001_wp, &
       2.38619186083196932E-001_wp, &
       6.61209386466264593E-001_wp, &
       9.32469514203152050E-001_wp ]
   real(wp), parameter :: W6(6) = [ &
       1.71324492379170495E-001_wp, &
       3.60761573048138606E-001_wp, &
       4.67913934572691259E-001_wp, &
       4.67913934572691259E-001_wp, &
       3.60761573048138606E-001_wp, &
       1.71324492379170495E-001_wp ]
   real(wp), parameter :: X8(8) = [ &
      -9.60289856497536287E-001_wp, &
      -7.96666477413626839E-001_wp, &
      -5.25532409916328991E-001_wp, &
      -1.83434642495649780E-001_wp, &
       1.83434642495649780E-001_wp, &
       5.25532409916328991E-001_wp, &
       7.96666477413626839E-001_wp, &
       9.60289856497536287E-001_wp ]
   real(wp), parameter :: W8(8) = [ &
       1.01228536290376786E-001_wp, &
       2.22381034453374454E-001_wp, &
       3.13706645877887380E-001_wp, &
       3.62683783378361990E-001_wp, &
       3.62683783378361990E-001_wp, &
       3.13706645877887380E-001_wp, &
       2.22381034453374454E-001_wp, &
       1.01228536290376786E-001_wp ]
   real(wp), parameter :: X10(10) = [ &
      -9.73906528517171743E-001_wp, &
      -8.65063366688984536E-001_wp, &
      -6.79409568299024436E-001_wp, &
      -4.33395394129247158E-001_wp, &
      -1.48874338981631216E-001_wp, &
       1.48874338981631216E-001_wp, &
       4.33395394129247158E-001_wp, &
       6.79409568299024436E-001_wp, &
       8.65063366688984536E-001_wp, &
       9.73906528517171743E-001_wp ]
   real(wp), parameter :: W10(10) = [ &
       6.66713443086837110E-002_wp, &
       1.49451349150580531E-001_wp, &
       2.19086362515982180E-001_wp, &
       2.69266719309996239E-001_wp, &
       2.95524224714752926E-001_wp, &
       2.95524224714752926E-001_wp, &
       2.69266719309996239E-001_wp, &
       2.19086362515982180E-001_wp, &
       1.49451349150580531E-001_wp, &
       6.66713443086837110E-002_wp ]
   real(wp), parameter :: X12(12) = [ &
      -9.81560634246719244E-001_wp, &
      -9.04117256370474798E-001_wp, &
      -7.69902674194304693E-001_wp, &
      -5.87317954286617483E-001_wp, &
      -3.67831498998180184E-001_wp, &
      -1.25233408511468941E-001_wp, &
       1.25233408511468941E-001_wp, &
       3.67831498998180184E-001_wp, &
       5.87317954286617483E-001_wp, &
       7.69902674194304693E-001_wp, &
       9.04117256370474798E-001_wp, &
       9.81560634246719244E-001_wp ]
   real(wp), parameter :: W12(12) = [ &
       4.71753363865084624E-002_wp, &
       1.06939325995318177E-001_wp, &
       1.60078328543346332E-001_wp, &
       2.03167426723065841E-001_wp, &
       2.33492536538354584E-001_wp, &
       2.49147045813402884E-001_wp, &
       2.49147045813402884E-001_wp, &
       2.33492536538354584E-001_wp, &
       2.03167426723065841E-001_wp, &
       1.60078328543346332E-001_wp, &
       1.06939325995318177E-001_wp, &
       4.71753363865084624E-002_wp ]
   real(wp), parameter :: X16(16) = [ &
      -9.89400934991649939E-001_wp, &
      -9.44575023073232600E-001_wp, &
      -8.65631202387831755E-001_wp, &
      -7.55404408355002999E-001_wp, &
      -6.17876244402643771E-001_wp, &
      -4.58016777657227370E-001_wp, &
      -2.81603550779258915E-001_wp, &
      -9.50125098376374405E-002_wp, &
       9.50125098376374405E-002_wp, &
       2.81603550779258915E-001_wp, &
       4.58016777657227370E-001_wp, &
       6.17876244402643771E-001_wp, &
       7.55404408355002999E-001_wp, &
       8.65631202387831755E-001_wp, &
       9.44575023073232600E-001_wp, &
       9.89400934991649939E-001_wp ]
   real(wp), parameter :: W16(16) = [ &
       2.71524594117518517E-002_wp, &
       6.22535239386477757E-002_wp, &
       9.51585116824928967E-002_wp, &
       1.24628971255533946E-001_wp, &
       1.49595988816576819E-001_wp, &
       1.69156519395002425E-001_wp, &
       1.82603415044923612E-001_wp, &
       1.89450610455068474E-001_wp, &
       1.89450610455068474E-001_wp, &
       1.82603415044923612E-001_wp, &
       1.69156519395002425E-001_wp, &
       1.49595988816576819E-001_wp, &
       1.24628971255533946E-001_wp, &
       9.51585116824928967E-002_wp, &
       6.22535239386477757E-002_wp, &
       2.71524594117518517E-002_wp ]
   real(wp), parameter :: X24(24) = [ &
      -9.95187219997021311E-001_wp, &
      -9.74728555971309474E-001_wp, &
      -9.38274552002732798E-001_wp, &
      -8.86415527004401071E-001_wp, &
      -8.20001985973902947E-001_wp, &
      -7.40124191578554358E-001_wp, &
      -6.48093651936975546E-001_wp, &
      -5.45421471388839563E-001_wp, &
      -4.33793507626045183E-001_wp, &
      -3.15042679696163397E-001_wp, &
      -1.91118867473616311E-001_wp, &
      -6.40568928626056300E-002_wp, &
       6.40568928626056300E-002_wp, &
       1.91118867473616311E-001_wp, &
       3.15042679696163397E-001_wp, &
       4.33793507626045183E-001_wp, &
       5.45421471388839563E-001_wp, &
       6.48093651936975546E-001_wp, &
       7.40124191578554358E-001_wp, &
       8.20001985973902947E-001_wp, &
       8.86415527004401071E-001_wp, &
       9.38274552002732798E-001_wp, &
       9.74728555971309474E-001_wp, &
       9.95187219997021311E-001_wp ]
   real(wp), parameter :: W24(24) = [ &
       1.23412297999856476E-002_wp, &
       2.85313886289338126E-002_wp, &
       4.42774388174196759E-002_wp, &
       5.92985849154366584E-002_wp, &
       7.33464814110802721E-002_wp, &
       8.61901615319532188E-002_wp, &
       9.76186521041136762E-002_wp, &
       1.07444270115965620E-001_wp, &
       1.15505668053725613E-001_wp, &
       1.21670472927803350E-001_wp, &
       1.25837456346828386E-001_wp, &
       1.27938195346752243E-001_wp, &
       1.27938195346752243E-001_wp, &
       1.25837456346828386E-001_wp, &
       1.21670472927803350E-001_wp, &
       1.15505668053725613E-001_wp, &
       1.07444270115965620E-001_wp, &
       9.76186521041136762E-002_wp, &
       8.61901615319532188E-002_wp, &
       7.33464814110802721E-002_wp, &
       5.92985849154366584E-002_wp, &
       4.42774388174196759E-002_wp, &
       2.85313886289338126E-002_wp, &
       1.23412297999856476E-002_wp ]

contains

   !> Nodes x(1:n) (ascending) and weights w(1:n) of the n-point Gauss-Legendre rule on
   !> [-1, 1] (n >= 1): the table for the TABLED_ORDERS, else gauss_legendre_newton.
   pure subroutine gauss_legendre(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)

      select case (n)
      case (4)
         x = X4
         w = W4
      case (6)
         x = X6
         w = W6
      case (8)
         x = X8
         w = W8
      case (10)
         x = X10
         w = W10
      case (12)
         x = X12
         w = W12
      case (16)
         x = X16
         w = W16
      case (24)
         x = X24
         w = W24
      case default
         call gauss_legendre_newton(n, x, w)
      end select
   end subroutine gauss_legendre

   !> Nodes x(1:n) (ascending) and weights w(1:n) of the n-point Gauss-Legendre rule on
   !> [-1, 1]; Newton iteration on P_n from the Chebyshev guesses (n >= 1).
   pure subroutine gauss_legendre_newton(n, x, w)
      integer, intent(in) :: n
      real(wp), intent(out) :: x(n), w(n)
      real(wp) :: z, z1, p1, p2, p3, pp
      integer :: i, j, it

      do i = 1, (n + 1)/2
         z = cos(pi*(real(i, wp) - 0.25_wp)/(real(n, wp) + 0.5_wp))
         do it = 1, 100
            p1 = 1.0_wp
            p2 = 0.0_wp
            do j = 1, n
               p3 = p2
               p2 = p1
               p1 = ((2.0_wp*j - 1.0_wp)*z*p2 - (j - 1.0_wp)*p3)/real(j, wp)
            end do
            pp = real(n, wp)*(z*p1 - p2)/(z*z - 1.0_wp)
            z1 = z
            z = z1 - p1/pp
            if (abs(z - z1) <= 4.0_wp*epsilon(1.0_wp)) exit
         end do
         x(i) = -z
         x(n + 1 - i) = z
         w(i) = 2.0_wp/((1.0_wp - z*z)*pp*pp)
         w(n + 1 - i) = w(i)
      end do
   end subroutine gauss_legendre_newton

end module adore_core_quadrature
