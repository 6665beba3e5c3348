!> Mass and principal moments of inertia of the bearing elements (SI units).
!>
!> Moments are returned as [I_x, I_y, I_z] about the principal axes through the mass
!> centre, x being the axis of symmetry (bearing axis for cage and races, roller axis
!> for a roller), as in the ADORE 5.0 echo "INERTIAL PARAMETERS".  Formulas: the
!> standard solid sphere, solid cylinder and hollow cylinder.  Findings from the
!> Appendix C/D echo (see docs in each procedure):
!>   * ball: solid sphere;
!>   * cage: hollow cylinder OD/ID/width minus n straight pockets through the radial
!>     wall (ball: cylinder of diameter D + pocket clearance I; roller: rectangle
!>     (D + pocket clearance I) x (L + pocket clearance II)); the moments are those of
!>     the plain hollow cylinder scaled to the reduced mass;
!>   * races: plain hollow cylinders between the raceway (groove-bottom) diameter and
!>     the bearing OD / bore, no shoulders, no groove;
!>   * roller: moments of the solid cylinder D x L; the mass printed by ADORE is
!>     0.44 % below rho pi D**2 L / 4 for the Appendix D roller, a reduction that is
!>     not identified (see roller_moments).
module adore_model_inertia
   use adore_core_kinds, only: wp
   use adore_core_constants, only: pi
   use adore_core_error, only: error_type, input_error
   implicit none
   private

   public :: sphere_inertia, solid_cylinder_inertia, hollow_cylinder_inertia
   public :: hollow_cylinder_moments, roller_moments
   public :: ball_cage_inertia, roller_cage_inertia
   public :: check_positive


contains

   !> Solid sphere of diameter d (m), density rho (kg/m**3):
   !> m = rho pi d**3 / 6, I_x = I_y = I_z = (2/5) m (d/2)**2.
   pure subroutine sphere_inertia(d, rho, mass, moments)
      real(wp), intent(in) :: d, rho
      real(wp), intent(out) :: mass, moments(3)

      mass = rho*pi*d**3/6.0_wp
      moments = 0.4_wp*mass*(0.5_wp*d)**2
   end subroutine sphere_inertia

   !> Principal moments (kg m**2) of a hollow cylinder of mass m (kg), outer and inner
   !> diameters d_out, d_in and length w (m), axis x:
   !> I_x = m (Ro**2 + Ri**2) / 2,  I_y = I_z = m (3 (Ro**2 + Ri**2) + w**2) / 12.
   pure function hollow_cylinder_moments(mass, d_out, d_in, w) result(moments)
      real(wp), intent(in) :: mass, d_out, d_in, w
      real(wp) :: moments(3)
      real(wp) :: r2

      r2 = 0.25_wp*(d_out**2 + d_in**2)
      moments(1) = 0.5_wp*mass*r2
      moments(2) = mass*(3.0_wp*r2 + w**2)/12.0_wp
      moments(3) = moments(2)
   end function hollow_cylinder_moments

   !> Homogeneous hollow cylinder (d_out, d_in, length w in m; rho in kg/m**3):
   !> m = rho pi (d_out**2 - d_in**2) w / 4 and the moments of hollow_cylinder_moments.
   !> Used for the races (raceway diameter to OD or bore, race width).
   pure subroutine hollow_cylinder_inertia(d_out, d_in, w, rho, mass, moments)
      real(wp), intent(in) :: d_out, d_in, w, rho
      real(wp), intent(out) :: mass, moments(3)

      mass = rho*0.25_wp*pi*(d_out**2 - d_in**2)*w
      moments = hollow_cylinder_moments(mass, d_out, d_in, w)
   end subroutine hollow_cylinder_inertia

   !> Homogeneous solid cylinder of diameter d and length l (m), density rho:
   !> m = rho pi d**2 l / 4, I_x = m r**2 / 2, I_y = I_z = m (3 r**2 + l**2) / 12.
   pure subroutine solid_cylinder_inertia(d, l, rho, mass, moments)
      real(wp), intent(in) :: d, l, rho
      real(wp), intent(out) :: mass, moments(3)

      call hollow_cylinder_inertia(d, 0.0_wp, l, rho, mass, moments)
   end subroutine solid_cylinder_inertia

   !> Moments (kg m**2) of a roller of mass m (kg), diameter d and length l (m), taken
   !> as those of a solid cylinder d x l of that mass.  Reproduces the Appendix D echo
   !> from its printed mass; how ADORE reduces the mass below rho pi d**2 l / 4
   !> (corner radii, crown?) is not identified, so the mass is an argument here.
   pure function roller_moments(mass, d, l) result(moments)
      real(wp), intent(in) :: mass, d, l
      real(wp) :: moments(3)

      moments = hollow_cylinder_moments(mass, d, 0.0_wp, l)
   end function roller_moments

   !> Ball-bearing cage (m): hollow cylinder d_out/d_in/width w minus n cylindrical
   !> pockets of diameter pocket_d (= ball diameter + pocket clearance) bored straight
   !> through the radial wall (length (d_out - d_in)/2); rho in kg/m**3.
   !> m = rho [pi (d_out**2 - d_in**2) w / 4 - n pi pocket_d**2 (d_out - d_in) / 8];
   !> moments of the plain hollow cylinder with mass m.  Reproduces Appendix C.
   pure subroutine ball_cage_inertia(d_out, d_in, w, n, pocket_d, rho, mass, moments)
      real(wp), intent(in) :: d_out, d_in, w, pocket_d, rho
      integer, intent(in) :: n
      real(wp), intent(out) :: mass, moments(3)

      mass = rho*(0.25_wp*pi*(d_out**2 - d_in**2)*w &
                  - real(n, wp)*0.25_wp*pi*pocket_d**2*0.5_wp*(d_out - d_in))
      moments = hollow_cylinder_moments(mass, d_out, d_in, w)
   end subroutine ball_cage_inertia

   !> Roller-bearing cage (m): hollow cylinder d_out/d_in/width w minus n rectangular
   !> pockets pocket_c x pocket_a (circumferential = roller diameter + pocket clearance
   !> I, axial = roller length + pocket clearance II) straight through the radial wall.
   !> m = rho [pi (d_out**2 - d_in**2) w / 4 - n pocket_c pocket_a (d_out - d_in) / 2];
   !> moments of the plain hollow cylinder with mass m.  Reproduces Appendix D.
   pure subroutine roller_cage_inertia(d_out, d_in, w, n, pocket_c, pocket_a, rho, mass, moments)
      real(wp), intent(in) :: d_out, d_in, w, pocket_c, pocket_a, rho
      integer, intent(in) :: n
      real(wp), intent(out) :: mass, moments(3)

      mass = rho*(0.25_wp*pi*(d_out**2 - d_in**2)*w &
                  - real(n, wp)*pocket_c*pocket_a*0.5_wp*(d_out - d_in))
      moments = hollow_cylinder_moments(mass, d_out, d_in, w)
   end subroutine roller_cage_inertia

   !> Input check shared by the inertia models: error unless every value is > 0
   !> (names(i) labels values(i) in the message).  Also catches NaN.
   subroutine check_positive(values, names, error)
      real(wp), intent(in) :: values(:)
      character(len=*), intent(in) :: names(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      character(len=32) :: buf

      do i = 1, size(values)
         if (.not. (values(i) > 0.0_wp)) then
            write (buf, "(es12.5)") values(i)
            call input_error(error, trim(names(i))//" must be positive, got "//trim(adjustl(buf)))
            return
         end if
      end do
   end subroutine check_positive

end module adore_model_inertia
