!> The tribology of one rolling-element/race contact at any state: lubricant film and its
!> thermal reduction, the choice between the deck's traction law and the EHD film
!> traction (model 3), the EHD traction itself, the flash temperature rise and the wall
!> temperature, all from the bearing model and the current bulk temperatures.
!>
!> ADORE's ADRD with ADRH2 for one contact (report 2.1, 2.6-2.8): the procedures the
!> step-0 start calls for every ball (adore_start_ball_step0) and the force assembly
!> calls at any state (adore_forces_ball_bearing).  temperature(7): the bulk temperatures
!> in the bearing model's TEMP_* order (K); race: BODY_OUTER or BODY_INNER.  Units SI.
module adore_forces_race_contact
   use adore_core_kinds, only: wp
   use adore_core_error, only: error_type, engine_error
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, TEMP_ELEMENT, TEMP_OUTER, TEMP_INNER
   use adore_tribology_slip, only: ball_race_contact_t, contact_traction_t, major_axis_nodes, contact_slip, &
                                   print_slip_node
   use adore_tribology_traction_law, only: LAW_CURVE, law_kappa
   use adore_tribology_film, only: central_film_thickness, thermal_loading, thermal_reduction_factor, &
                                   rolling_resistance_force, &
                                   dynamic_viscosity, temperature_viscosity_coefficient, traction_viscosity, &
                                   THERMAL_LOADING_SCALE, viscosity_in_range
   use adore_tribology_ehd_traction, only: ehd_rheology_t, ehd_contact_traction, ehd_strip_traction, &
                                           ehd_contact_traction_fast
   use adore_tribology_ehd_flash, only: ehd_temperature_rise
   use adore_tribology_flash, only: FLASH_POINTS, contact_temperature_rise
   use adore_contact_line_slices, only: line_contact_t
   use adore_tribology_roller_traction, only: line_traction_t
   implicit none
   private

   public :: ehd_traction_model, wall_temperature, wall_rheology, thermal_properties, lubricant_film, &
             ehd_film_present, ehd_traction, ehd_flash, law_flash, line_flash, printed_slip, &
             rolling_resistance, fluid_fraction, fluid_contact, mixed_traction

   !> Gauss points per slip zone of the printed contact tribology: the report's printed slip
   !> velocity is the largest |u| at the nodes of the 4-point rule (docs/tribology.md).
   integer, parameter, public :: PRINT_GAUSS = 4
   !> Gauss points per slip zone and across each strip of the EHD traction's loss and force
   integer, parameter, public :: EHD_GAUSS = 16, EHD_STRIP = 24
   !> The thinnest film (m) the EHD traction shears: 1 nm, below any ground surface's
   !> roughness (a film parameter h / sigma << 1 is boundary lubrication).  The Newtonian
   !> film's traction slope grows as 1/h, so a film of picometres (a ball's micro-motion on
   !> a shaft at rest entrains a little oil) made the traction stiff without bound and the
   !> time steps of a shaft at rest failed (docs/operating-points.md); such contacts take
   !> the deck's curve.  Films of the decks' running speeds are 1e-8 ... 1e-6 m.
   real(wp), parameter, public :: MIN_EHD_FILM = 1.0e-9_wp
   !> Rec 10.0 traction_model of the EHD film traction (report Table 5, model 3)
   integer, parameter, public :: TRACTION_EHD = 3

contains

   !> True when the race contacts of b use ADORE's EHD film traction (Rec 10.0 model 3 with
   !> a lubricant); a traction-slip table (ADRX7) replaces the deck's model, EHD included.
   pure logical function ehd_traction_model(b)
      type(bearing_t), intent(in) :: b
      ehd_traction_model = b%traction_model == TRACTION_EHD .and. b%race_traction%kind == LAW_CURVE .and. &
                           b%lubricant_code /= 0
   end function ehd_traction_model

   !> Wall temperature (K) of a race contact: mean of the element and race bulk
   !> temperatures.  At step 0 the contact temperature rise is not fed back (the report
   !> prints Contact Temp = 323 K, its deck temperature).
   pure function wall_temperature(temperature, race) result(t_w)
      real(wp), intent(in) :: temperature(:)
      integer, intent(in) :: race
      real(wp) :: t_w
      t_w = 0.5_wp*(temperature(TEMP_ELEMENT) + temperature(merge(TEMP_OUTER, TEMP_INNER, race == BODY_OUTER)))
   end function wall_temperature

   !> [density (kg/m**3), heat capacity (J/kg/K), conductivity (W/m/K)] of a body (Rec 8).
   pure function thermal_properties(b, body) result(th)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: body
      real(wp) :: th(3)
      th = [b%material(body)%density, b%material(body)%heat_capacity, b%material(body)%conductivity]
   end function thermal_properties

   !> The lubricant's traction rheology at the wall temperature of a race contact, with the
   !> film's shear modulus of the run (b%film_shear_modulus; 0: the viscous film) and its
   !> limiting shear stress coefficient (b%limiting_shear; 0: no cap).
   function wall_rheology(b, temperature, race) result(rheo)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      integer, intent(in) :: race
      type(ehd_rheology_t) :: rheo
      real(wp) :: t_w
      t_w = wall_temperature(temperature, race)
      rheo = ehd_rheology_t(eta_w=traction_viscosity(b%lubricant, t_w), alpha=b%lubricant%alpha_t, &
                            beta=b%lubricant%beta_t, conductivity=b%lubricant%conductivity, &
                            shear_modulus=b%film_shear_modulus, limiting_shear=b%limiting_shear)
   end function wall_rheology

   !> Film of one race contact (report 2.6): Hamrock-Dowson isothermal central film
   !> h (m) at the contact's entraining speed, R_x and ellipticity k_ell = a/b, load q (N),
   !> with the lubricant's viscosity at the inlet temperature (the wall temperature) and
   !> ambient pressure; the thermal reduction factor phi of Gupta et al. with beta = B/T**2
   !> at that temperature, Hertz pressure p_h (Pa) and the slide-to-roll ratio centre slip
   !> / entraining speed.
   subroutine lubricant_film(b, temperature, t, k_ell, q, p_h, race, h, phi, error)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(contact_traction_t), intent(in) :: t
      real(wp), intent(in) :: k_ell, q, p_h
      integer, intent(in) :: race
      real(wp), intent(out) :: h, phi
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: e_prime, t_in, eta, u
      character(len=400) :: buf
      integer :: stat

      e_prime = reduced_modulus(b, race)
      t_in = wall_temperature(temperature, race)
      if (.not. viscosity_in_range(b%lubricant, t_in)) then
         write (buf, "(3a,es10.3,a)", iostat=stat) "lubricant ", trim(b%lubricant%name), " at ", t_in, &
            " K (the mean of the rolling element's and the race's bulk temperatures, Rec 2.7): outside its "// &
            "viscosity fit exp(B (1/T - 1/T_ref)), which means nothing this near 0 K"
         call engine_error(error, trim(buf))
         return
      end if
      eta = dynamic_viscosity(b%lubricant, t_in, 0.0_wp)
      u = abs(t%rolling_speed)
      if (u == 0.0_wp) then
         ! no entraining speed (a shaft at rest): no film
         h = 0.0_wp
         phi = 1.0_wp
         return
      end if
      call central_film_thickness(t%rx, k_ell, u, q, e_prime, eta, b%lubricant%alpha, h, error)
      if (allocated(error)) return
      phi = thermal_reduction_factor(p_h, e_prime, THERMAL_LOADING_SCALE*thermal_loading(eta, &
                                     temperature_viscosity_coefficient(b%lubricant, t_in), u, &
                                     b%lubricant%conductivity), t%centre_slip/t%rolling_speed)
   end subroutine lubricant_film

   !> The EHD rolling resistance force f_r (N) of a race contact with kinematics t (its
   !> entraining speed and R_x), ellipticity k_ell, load q (N), maximum pressure p_h (Pa) on
   !> race (BODY_OUTER/INNER) at bulk temperatures temperature (K): rolling_resistance_force
   !> with the inlet viscosity at the wall temperature, reduced by the film's inlet-shear
   !> thermal factor phi_T (lubricant_film; docs/tribology.md, "Rolling resistance"); 0
   !> without a lubricant or entraining speed.
   subroutine rolling_resistance(b, temperature, t, k_ell, q, p_h, race, f_r, error)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(contact_traction_t), intent(in) :: t
      real(wp), intent(in) :: k_ell, q, p_h
      integer, intent(in) :: race
      real(wp), intent(out) :: f_r
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: h, phi, e_prime
      f_r = 0.0_wp
      if (b%lubricant_code == 0 .or. t%rolling_speed == 0.0_wp .or. .not. q > 0.0_wp) return
      call lubricant_film(b, temperature, t, k_ell, q, p_h, race, h, phi, error)
      if (allocated(error)) return
      e_prime = reduced_modulus(b, race)
      f_r = phi*rolling_resistance_force(t%rx, k_ell, t%rolling_speed, q, e_prime, &
                                         dynamic_viscosity(b%lubricant, wall_temperature(temperature, race), 0.0_wp), &
                                         b%lubricant%alpha)
   end subroutine rolling_resistance

   !> E' = 2 / ((1 - nu1**2)/E1 + (1 - nu2**2)/E2) (Pa) of the rolling element on race
   !> (BODY_OUTER/INNER): the Hamrock-Dowson reduced modulus (adore_tribology_film).
   pure real(wp) function reduced_modulus(b, race)
      type(bearing_t), intent(in) :: b
      integer, intent(in) :: race
      reduced_modulus = 2.0_wp/((1.0_wp - b%material(BODY_ELEMENT)%poisson**2)/b%material(BODY_ELEMENT)%modulus + &
                                (1.0_wp - b%material(race)%poisson**2)/b%material(race)%modulus)
   end function reduced_modulus

   !> True when a race contact of b has an EHD film to shear: the isothermal film h (m) times
   !> the thermal reduction factor phi is at least MIN_EHD_FILM and b%boundary_film (the
   !> run's boundary-lubrication film, Lambda_b sigma: the run option boundary_lambda,
   !> default 1, times the composite roughness; 0 turns it off) and finite.  Without one (no or almost no entraining
   !> speed: a shaft at rest, a ball's micro-motion at rest; Gupta's fit at 0 beyond its
   !> range of thermal loading, a lubricant far too viscous for the speed; or a film
   !> parameter below Lambda_b: boundary lubrication) traction model 3 takes the deck's
   !> traction curve for that contact (docs/tribology.md, "No EHD film", "Thin films").
   pure logical function ehd_film_present(b, h, phi)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: h, phi
      ehd_film_present = h*phi >= max(MIN_EHD_FILM, b%boundary_film) .and. h*phi < huge(1.0_wp)
   end function ehd_film_present

   !> Fluid fraction f (-) of a traction model 3 race contact with isothermal film h (m)
   !> and thermal reduction factor phi: the share of its traction the EHD film gives in
   !> mixed lubrication, the rest the deck's curve (mixed_traction; docs/tribology.md,
   !> "Mixed films").  With the thermally reduced film h_f = h phi, h_b = max(MIN_EHD_FILM,
   !> b%boundary_film) and h_full = b%full_film: 0 without an EHD film (ehd_film_present
   !> false: h_f < h_b), 1 at h_f >= h_full, between them the cubic f = s**2 (3 - 2 s),
   !> s = (h_f - h_b) / (h_full - h_b): continuous with its slope at both ends, so the
   !> traction has no step at the boundary film.  h_full <= h_b: 1 for every film present
   !> (no blend: the step at h_b).  With sigma the composite roughness, s is linear in the
   !> film parameter Lambda = h_f / sigma between Lambda_b and Lambda_f (run options
   !> boundary_lambda and full_film_lambda, defaults 1 and 2).
   pure real(wp) function fluid_fraction(b, h, phi) result(f)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: h, phi
      real(wp) :: h_b, s
      h_b = max(MIN_EHD_FILM, b%boundary_film)
      if (.not. ehd_film_present(b, h, phi)) then
         f = 0.0_wp
      else if (b%full_film <= h_b .or. h*phi >= b%full_film) then
         f = 1.0_wp
      else
         s = (h*phi - h_b)/(b%full_film - h_b)
         f = s*s*(3.0_wp - 2.0_wp*s)
      end if
   end function fluid_fraction

   !> The film's share of race contact cj in mixed lubrication (docs/tribology.md, "Mixed
   !> films"): the same contact (ellipse, kinematics) with the load f Q (N) at fluid fraction
   !> f, so its Hertz pressure is f p_H over the same ellipse - the load sharing of Johnson,
   !> Greenwood & Poon (1972) and Gelinck & Schipper (2000): the asperities carry (1 - f) Q,
   !> the film the rest at the pressure its viscosity exp(alpha p) sees.  f = 1 (a full
   !> film) or f = 0 (no film to shear): cj itself.
   pure function fluid_contact(cj, f) result(c)
      type(ball_race_contact_t), intent(in) :: cj
      real(wp), intent(in) :: f
      type(ball_race_contact_t) :: c
      c = cj
      if (f > 0.0_wp .and. f < 1.0_wp) c%load = f*cj%load
   end function fluid_contact

   !> The traction of a race contact in mixed lubrication (docs/tribology.md, "Mixed
   !> films"): f (the fluid fraction, 0 < f < 1) times the EHD film's traction `fluid` of the
   !> film's share of the load (fluid_contact: f Q at f p_H) plus 1 - f times the deck
   !> curve's `boundary` at the contact's load Q, for every force, moment and the heat (W);
   !> the coefficient is that force over Q (the film's own coefficient is over f Q); the
   !> sliding integral (N m/s, |u| dQ) is the whole contact's (the film's over f Q plus the
   !> curve's over the rest).  The weight f keeps the blend continuous with its slope where
   !> the film appears (f = 0) and at the full film.  The kinematic fields (slips, speeds,
   !> spin, R_x, the pure-rolling points) are the contact's own, taken from `fluid`.
   pure function mixed_traction(f, fluid, boundary) result(t)
      real(wp), intent(in) :: f
      type(contact_traction_t), intent(in) :: fluid, boundary
      type(contact_traction_t) :: t
      t = fluid
      t%force = f*fluid%force + (1.0_wp - f)*boundary%force
      t%force_cos = f*fluid%force_cos + (1.0_wp - f)*boundary%force_cos
      t%force_sin = f*fluid%force_sin + (1.0_wp - f)*boundary%force_sin
      t%cross_force = f*fluid%cross_force + (1.0_wp - f)*boundary%cross_force
      t%coefficient = f*f*fluid%coefficient + (1.0_wp - f)*boundary%coefficient
      t%power = f*fluid%power + (1.0_wp - f)*boundary%power
      t%sliding = fluid%sliding + (1.0_wp - f)*boundary%sliding
   end function mixed_traction

   !> EHD traction of one race contact cj (traction model 3, adore_tribology_ehd_traction):
   !> film h (m, the thermally reduced central film), semi-minor axis b_minor (m), the
   !> lubricant's traction rheology at the wall temperature; by the fast quadrature
   !> (ehd_contact_traction_fast, default) or, with reference = .true., by the reference
   !> quadrature of EHD_GAUSS x EHD_STRIP points (the step-0 print's).  transverse (m/s),
   !> when given: the two-dimensional traction of the slip along and across the rolling
   !> direction (u_m(psi) = m1 + m2 cos psi + m3 sin psi; report eq 5), t%cross_force;
   !> kinematics, when given: contact_kinematics(cj), for the fast traction to take.  The
   !> fast traction leaves t%max_slip at 0 (ehd_contact_traction_fast's extremes = .false.):
   !> the force assembly, its one caller, never reads it (the print's slip velocity is
   !> printed_slip's), and its end slips and interior extremum were ~2 % of a derivative
   !> call (issue #30).
   subroutine ehd_traction(b, temperature, cj, b_minor, race, h, t, error, reference, transverse, kinematics)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(ball_race_contact_t), intent(in) :: cj
      real(wp), intent(in) :: b_minor, h
      integer, intent(in) :: race
      type(contact_traction_t), intent(out) :: t
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: reference
      real(wp), intent(in), optional :: transverse(3)
      type(contact_traction_t), intent(in), optional :: kinematics
      logical :: ref
      ref = .false.
      if (present(reference)) ref = reference
      if (ref) then
         call ehd_contact_traction(cj, wall_rheology(b, temperature, race), h, b_minor, EHD_GAUSS, EHD_STRIP, t, error, &
                                   transverse)
      else
         call ehd_contact_traction_fast(cj, wall_rheology(b, temperature, race), h, b_minor, t, error, &
                                        transverse=transverse, kinematics=kinematics, extremes=.false.)
      end if
   end subroutine ehd_traction

   !> The printed "Slip Velocity" (m/s) and "Trac Coeff" of race contact cj: |u| at the
   !> print node (PRINT_GAUSS points per slip zone, adore_tribology_slip's print_slip_node)
   !> and the local traction coefficient there, of the run's law or, when ehd, of the EHD
   !> film (strip traction / strip load with film h, m, semi-minor axis b_minor, m; the
   !> rheology at the wall temperature of race).
   subroutine printed_slip(b, temperature, cj, b_minor, race, h, ehd, slip, coefficient)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(ball_race_contact_t), intent(in) :: cj
      real(wp), intent(in) :: b_minor, h
      integer, intent(in) :: race
      logical, intent(in) :: ehd
      real(wp), intent(out) :: slip, coefficient
      real(wp) :: s, u, f, q

      call print_slip_node(cj, PRINT_GAUSS, s, u)
      slip = abs(u)
      if (ehd) then
         call ehd_strip_traction(cj, wall_rheology(b, temperature, race), h, b_minor, EHD_STRIP, s, u, f, q)
         coefficient = f/q
      else
         coefficient = law_kappa(b%race_traction, u)
      end if
   end subroutine printed_slip

   !> Average flash temperature rise (K) of a race contact with its EHD heat (report
   !> 2.7-2.8, eqs 35-36): both surfaces moving at the entraining speed u_e (m/s), element
   !> and race materials of Rec 8.
   subroutine ehd_flash(b, temperature, cj, b_minor, race, h, u_e, rise, error)
      type(bearing_t), intent(in) :: b
      real(wp), intent(in) :: temperature(:)
      type(ball_race_contact_t), intent(in) :: cj
      real(wp), intent(in) :: b_minor, h, u_e
      integer, intent(in) :: race
      real(wp), intent(out) :: rise
      type(error_type), allocatable, intent(out) :: error
      call ehd_temperature_rise(cj, wall_rheology(b, temperature, race), h, b_minor, EHD_GAUSS, FLASH_POINTS, &
                                u_e, u_e, thermal_properties(b, BODY_ELEMENT), thermal_properties(b, race), &
                                rise, error=error)
   end subroutine ehd_flash

   !> Average flash temperature rise (K) of a race contact whose traction is the run's law
   !> (the deck's curve or a traction-slip table; report 2.7-2.8, eqs 35-36): strips along
   !> the major axis (EHD_GAUSS Gauss points per slip zone) carry the heat factor
   !> g = kappa(|u|) |u| (eq 29) over the Hertz ellipse (semi-minor axis b_minor, m; peak
   !> pressure p0, Pa), both surfaces at the entraining speed u_e (m/s): the roller run's
   !> model, with the ball's own slip along its major axis.
   subroutine law_flash(b, cj, b_minor, p0, race, u_e, rise, error)
      type(bearing_t), intent(in) :: b
      type(ball_race_contact_t), intent(in) :: cj
      real(wp), intent(in) :: b_minor, p0, u_e
      integer, intent(in) :: race
      real(wp), intent(out) :: rise
      type(error_type), allocatable, intent(out) :: error
      type(contact_traction_t) :: t
      real(wp), allocatable :: x(:), w(:), u(:)

      rise = 0.0_wp
      if (u_e == 0.0_wp) return      ! surfaces at rest: the flash model has no moving heat source
      call major_axis_nodes(cj, EHD_GAUSS, t, x, w)
      u = contact_slip(cj, x)
      call contact_temperature_rise(cj%a, b_minor, p0, x, w, law_kappa(b%race_traction, u)*abs(u), u_e, u_e, &
                                    thermal_properties(b, BODY_ELEMENT), thermal_properties(b, race), FLASH_POINTS, &
                                    rise, error=error)
   end subroutine law_flash

   !> Average flash temperature rise (K) of one roller/race line contact c with its slice
   !> tractions t (report 2.7-2.8, eqs 35-36): the contact as the ellipse the print reports
   !> (major half width a = half contact length, minor half width = mean slice half width,
   !> pressure p0 = printed contact stress, eq 36's 1/(pi a b)), one strip per slice at its
   !> position from the contact centre with the slice's heat factor kappa |u| (eq 29);
   !> both surfaces at the entraining speed (m/s) of roller spin w_r (rad/s) and race speed
   !> w_race = Omega - w_m (rad/s) at raceway radius r_race (m); race: BODY_OUTER or
   !> BODY_INNER.  0 without contact or heat.
   subroutine line_flash(b, c, t, race, r_race, w_race, w_r, rise, error)
      type(bearing_t), intent(in) :: b
      type(line_contact_t), intent(in) :: c
      type(line_traction_t), intent(in) :: t
      integer, intent(in) :: race
      real(wp), intent(in) :: r_race, w_race, w_r
      real(wp), intent(out) :: rise
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: u_e, centre

      rise = 0.0_wp
      if (.not. c%in_contact .or. t%power <= 0.0_wp) return
      u_e = 0.5_wp*(abs(w_r)*0.5_wp*b%d + abs(w_race)*r_race)
      centre = 0.5_wp*(c%limits(1) + c%limits(2))
      call contact_temperature_rise(c%half_length, c%mean_half_width, c%stress, c%x - centre, c%weight, &
                                    merge(t%kappa*abs(t%slip), 0.0_wp, c%q > 0.0_wp), u_e, u_e, &
                                    thermal_properties(b, BODY_ELEMENT), thermal_properties(b, race), FLASH_POINTS, &
                                    rise, error=error)
   end subroutine line_flash

end module adore_forces_race_contact
