!> The quasi-static solvers' models of a bearing: what the ball and roller equilibria need
!> of the bearing model (adore_model_bearing) in its mounted geometry
!> (adore_geometry_mounted), built in one place for the step-0 drivers.
module adore_quasistatic_models
   use adore_core_kinds, only: wp
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER
   use adore_model_scales, only: length_scale
   use adore_geometry_mounted, only: mounted_geometry_t
   use adore_contact_line_slices, only: roller_profile_t, contact_modulus, line_stiffness
   use adore_quasistatic_ball_equilibrium, only: ball_qs_bearing_t
   use adore_quasistatic_roller_equilibrium, only: roller_qs_bearing_t
   implicit none
   private

   public :: ball_qs_model, roller_qs_model

contains

   !> The ball equilibrium's model of ball bearing b in its mounted geometry g: ball size,
   !> pitch, groove curvatures and curvature centres, elastic constants, masses (SI).
   pure function ball_qs_model(b, g) result(q)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      type(ball_qs_bearing_t) :: q

      q%n_balls = b%n_elements
      q%d = b%d
      q%dm = b%dm
      q%f_o = b%ball%f_o
      q%f_i = b%ball%f_i
      q%ball_mass = b%mass(BODY_ELEMENT)
      q%e_ball = b%material(BODY_ELEMENT)%modulus
      q%nu_ball = b%material(BODY_ELEMENT)%poisson
      q%e_outer = b%material(BODY_OUTER)%modulus
      q%nu_outer = b%material(BODY_OUTER)%poisson
      q%e_inner = b%material(BODY_INNER)%modulus
      q%nu_inner = b%material(BODY_INNER)%poisson
      q%inner_race_mass = b%mass(BODY_INNER)
      q%x_o = g%groove_centre(1, 1)
      q%r_o = g%groove_centre(2, 1)
      q%x_i = g%groove_centre(1, 2)
      q%r_i = g%groove_centre(2, 2)
   end function ball_qs_model

   !> The quasi-static contact model of bearing b in its mounted geometry g (raceway radii
   !> moved by growth_count times the mounting, adore_geometry_mounted), n_sub slice zones.
   pure function roller_qs_model(b, g, n_sub) result(q)
      type(bearing_t), intent(in) :: b
      type(mounted_geometry_t), intent(in) :: g
      integer, intent(in) :: n_sub
      type(roller_qs_bearing_t) :: q
      real(wp) :: half, l_ref

      q%n_rollers = b%n_elements
      q%d = b%d
      q%profile = roller_profile_t(b%roller%roller_length, b%roller%roller_land, b%roller%crown_radius, b%roller%corner_radius)
      q%mass = b%mass(BODY_ELEMENT)   ! the crowned roller of the bearing model
      q%race_crown = b%roller%race_crown
      q%r_o = g%raceway_radius(1)
      q%r_i = g%raceway_radius(2)
      half = 0.5_wp*b%roller%roller_length
      q%lim_o = [-half, half]
      q%lim_i = [-half, half]
      associate (race_length => b%roller%race_length)
         if (race_length(1) > 0.0_wp) q%lim_o = max(-0.5_wp*race_length(1), min(0.5_wp*race_length(1), q%lim_o))
         if (race_length(2) > 0.0_wp) q%lim_i = max(-0.5_wp*race_length(2), min(0.5_wp*race_length(2), q%lim_i))
      end associate
      q%e_o = contact_modulus(b%material(BODY_ELEMENT)%modulus, b%material(BODY_ELEMENT)%poisson, &
                              b%material(BODY_OUTER)%modulus, b%material(BODY_OUTER)%poisson)
      q%e_i = contact_modulus(b%material(BODY_ELEMENT)%modulus, b%material(BODY_ELEMENT)%poisson, &
                              b%material(BODY_INNER)%modulus, b%material(BODY_INNER)%poisson)
      l_ref = length_scale(b%d)
      q%k_o = line_stiffness(q%e_o, l_ref)
      q%k_i = line_stiffness(q%e_i, l_ref)
      q%n_sub = n_sub
      q%inner_race_mass = b%mass(BODY_INNER)
   end function roller_qs_model

end module adore_quasistatic_models
