!> Power and force balances of a ball bearing at one state (issue #28 item 2): what the
!> drive gives, what the contacts dissipate, the mechanical energy stored in the bodies
!> and contacts, and the contact forces on each race, from the force assembly's loads
!> (adore_forces_ball_bearing) at that state.
!>
!> Power: the races turn at prescribed speeds (report 4.4.6: the inner race's rotation
!> held, the outer race fixed in the housing), so the drive supplies whatever torque the
!> contacts put on them; its power is
!>     P_drive = - sum_races M_c . omega_race
!> with M_c the moment of the bearing's contacts on the race (the loads' moment less the
!> applied moment of Rec 9.1.1) and omega_race its inertial angular velocity (W).  Energy
!> conservation of the bodies (Newton-Euler, adore_dynamics_ball_motion) gives exactly
!>     P_drive = P_loss + P_damping + dE/dt,
!>     E = sum_bodies (1/2 m v.v + 1/2 omega.I omega) + sum_contacts 2/5 K delta**2.5
!>         - sum_bodies m g.x - F_applied.x_inner,
!> P_loss the race contacts' heat plus the power the cage contacts take from the bodies
!> (their friction heat and the work of their normal forces: the pocket film's
!> isoviscous-rigid load, adore_contact_cage_pocket, is not derived from an energy and
!> does net work that the model's heat does not count), P_damping the work of the race
!> contacts' damping (beta k delta_dot**2), up to the small
!> non-conservative part of a Hertz stiffness that follows the contact angle.  Time-
!> averaged over a steady window dE/dt averages out: drive power = dissipation.
!> A free cage in ADORE's whirl coordinates (adore_dynamics_cage_whirl: r'' = F_r/m,
!> r psi'' = F_t/m) moves by F/m + a_w, a_w = -(v_t**2/r) e_r + (2 v_r v_t/r) e_t the
!> centripetal and Coriolis accelerations its polar equations omit (faded to 0 near the
!> axis).  Its kinetic energy then changes by F.v + m a_w.v, and
!>     m a_w.v = m (-(v_t**2/r) v_r + (2 v_r v_t/r) v_t) = m v_r v_t**2 / r
!> is power the whirl frame gives the cage that no force supplies (a cage free of force
!> keeps r' and psi', so its speed v_t = r psi' grows with r).  The balance reads
!>     P_drive = P_loss + P_damping + dE/dt + P_frame,    P_frame = -m a_w.v,
!> P_frame the whirl frame's power (0 by Newton's equations).
!> Forces: the contacts' force on the inner race balances the applied load and the race's
!> weight, on average, when the race does not accelerate; the outer race's contact force
!> is the housing's reaction.  No module state.
module adore_forces_ball_power
   use adore_core_kinds, only: wp
   use adore_core_rotation, only: quat_matrix
   use adore_model_bearing, only: bearing_t, BODY_ELEMENT, BODY_OUTER, BODY_INNER, BODY_CAGE
   use adore_state_bearing_state, only: bearing_state_t, body_state_t, RACE_OUTER, RACE_INNER
   use adore_contact_ball_race, only: contact_energy
   use adore_forces_ball_bearing, only: ball_bearing_loads_t, total_power_loss
   implicit none
   private

   public :: ball_balance_values, contact_power_sum, cage_contact_work

   !> Positions in the vector of ball_balance_values: drive power (W), heat of the race
   !> contacts (W), race contact damping (W), the power the cage contacts (pockets and guide
   !> lands, every force they exert) take from the bodies (W) and their friction heat (W),
   !> mechanical energy (J), contact force on the inner race (3, N), on the outer race (3, N),
   !> the whirl frame's power P_frame (W, module header), the inner race's momentum (3, N s: its
   !> change over a window over the window's duration is what its mean force misses of the load).
   integer, parameter, public :: BAL_DRIVE = 1, BAL_RACE_HEAT = 2, BAL_DAMPING = 3, BAL_CAGE_WORK = 4, &
                                 BAL_CAGE_HEAT = 5, BAL_ENERGY = 6, BAL_INNER_FORCE = 7, BAL_OUTER_FORCE = 10, &
                                 BAL_WHIRL_FRAME = 13, BAL_INNER_MOMENTUM = 14, N_BALANCE = 16

contains

   !> The balance quantities (module header) of ball bearing b at state s with the force
   !> assembly's loads there (after the gyroscopic restraint, when the run has it), into
   !> v(N_BALANCE) in the BAL_* order.  frame_acceleration (m/s**2, inertial components;
   !> default 0): what the cage's equations of motion add to its F/m (ADORE's whirl
   !> coordinates, adore_dynamics_cage_whirl's whirl_frame_acceleration), whose power
   !> -m a.v is BAL_WHIRL_FRAME.
   function ball_balance_values(b, s, loads, frame_acceleration) result(v)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp), intent(in), optional :: frame_acceleration(3)
      real(wp) :: v(N_BALANCE)
      real(wp) :: m_c(3), energy
      integer :: k, j

      v = 0.0_wp
      do j = RACE_OUTER, RACE_INNER
         m_c = loads%races(j)%moment
         if (j == RACE_INNER) m_c = m_c - b%moment
         v(BAL_DRIVE) = v(BAL_DRIVE) - dot_product(m_c, inertial_omega(s%races(j)))
      end do
      v(BAL_RACE_HEAT) = sum(loads%heat)
      v(BAL_DAMPING) = loads%damping_power
      v(BAL_CAGE_HEAT) = total_power_loss(loads) - v(BAL_RACE_HEAT)
      v(BAL_CAGE_WORK) = cage_contact_work(b, s, loads)
      energy = 0.0_wp
      do k = 1, size(s%elements)
         energy = energy + body_energy(s%elements(k), b%mass(BODY_ELEMENT), b%moments(:, BODY_ELEMENT))
         do j = 1, 2
            energy = energy + contact_energy(loads%contacts(j, k))
         end do
      end do
      energy = energy + body_energy(s%cage, b%mass(BODY_CAGE), b%moments(:, BODY_CAGE))
      energy = energy + body_energy(s%races(RACE_OUTER), b%mass(BODY_OUTER), b%moments(:, BODY_OUTER))
      energy = energy + body_energy(s%races(RACE_INNER), b%mass(BODY_INNER), b%moments(:, BODY_INNER))
      energy = energy - dot_product(b%force, s%races(RACE_INNER)%position)
      v(BAL_ENERGY) = energy
      v(BAL_INNER_FORCE:BAL_INNER_FORCE + 2) = loads%races(RACE_INNER)%force - b%mass(BODY_INNER)*b%gravity - b%force
      v(BAL_OUTER_FORCE:BAL_OUTER_FORCE + 2) = loads%races(RACE_OUTER)%force - b%mass(BODY_OUTER)*b%gravity
      v(BAL_INNER_MOMENTUM:BAL_INNER_MOMENTUM + 2) = b%mass(BODY_INNER)*s%races(RACE_INNER)%velocity
      if (present(frame_acceleration)) v(BAL_WHIRL_FRAME) = -b%mass(BODY_CAGE)*dot_product(frame_acceleration, &
                                                                                             s%cage%velocity)

   contains

      !> Kinetic energy of a body of mass m (kg) and principal moments inertia (kg m**2) and
      !> its potential energy in gravity (J).
      pure real(wp) function body_energy(body, m, inertia)
         type(body_state_t), intent(in) :: body
         real(wp), intent(in) :: m, inertia(3)
         body_energy = 0.5_wp*m*dot_product(body%velocity, body%velocity) + &
                       0.5_wp*sum(inertia*body%omega**2) - m*dot_product(b%gravity, body%position)
      end function body_energy

   end function ball_balance_values

   !> Power (W) of the contact loads on every body at state s: sum over the balls, the cage
   !> and both races of F_c.v + M_c.omega, with F_c, M_c the loads less gravity and the
   !> applied load.  For the force assembly this equals -(P_loss + P_damping + the Hertz
   !> loads' power sum Q d(delta)/dt): the test of its kinematic consistency.
   function contact_power_sum(b, s, loads) result(p)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp) :: p
      integer :: k
      p = 0.0_wp
      do k = 1, size(s%elements)
         p = p + body_power(s%elements(k), loads%elements(k)%force - b%mass(BODY_ELEMENT)*b%gravity, &
                            loads%elements(k)%moment)
      end do
      p = p + body_power(s%cage, loads%cage%force - b%mass(BODY_CAGE)*b%gravity, loads%cage%moment)
      p = p + body_power(s%races(RACE_OUTER), loads%races(RACE_OUTER)%force - b%mass(BODY_OUTER)*b%gravity, &
                         loads%races(RACE_OUTER)%moment)
      p = p + body_power(s%races(RACE_INNER), loads%races(RACE_INNER)%force - b%mass(BODY_INNER)*b%gravity - &
                         b%force, loads%races(RACE_INNER)%moment - b%moment)

   contains

      pure real(wp) function body_power(body, force, moment)
         type(body_state_t), intent(in) :: body
         real(wp), intent(in) :: force(3), moment(3)
         body_power = dot_product(force, body%velocity) + dot_product(moment, inertial_omega(body))
      end function body_power

   end function contact_power_sum

   !> Power (W) the cage contacts take from the bodies at state s: minus the power of every
   !> pocket force on its ball and on the cage and of every guide-land force on the cage and
   !> its race (friction heat, the work of the normal loads and of the land film).
   function cage_contact_work(b, s, loads) result(p)
      type(bearing_t), intent(in) :: b
      type(bearing_state_t), intent(in) :: s
      type(ball_bearing_loads_t), intent(in) :: loads
      real(wp) :: p
      integer :: k, j
      p = 0.0_wp
      if (allocated(loads%pockets)) then
         do k = 1, size(loads%pockets)
            associate (c => loads%pockets(k), ball => s%elements(k))
               p = p - dot_product(c%force_ball, ball%velocity) - dot_product(c%moment_ball, inertial_omega(ball)) &
                   - dot_product(c%force_cage, s%cage%velocity) - dot_product(c%moment_cage, inertial_omega(s%cage))
            end associate
         end do
      end if
      if (allocated(loads%lands)) then
         do k = 1, size(loads%lands)
            j = b%lands(k)%guide          ! GUIDE_OUTER/INNER = RACE_OUTER/INNER
            associate (c => loads%lands(k))
               p = p - dot_product(c%force_cage, s%cage%velocity) - dot_product(c%moment_cage, inertial_omega(s%cage)) &
                   - dot_product(c%force_race, s%races(j)%velocity) - dot_product(c%moment_race, &
                                                                                  inertial_omega(s%races(j)))
            end associate
         end do
      end if
   end function cage_contact_work

   !> A body's angular velocity in inertial components (rad/s).
   pure function inertial_omega(body) result(w)
      type(body_state_t), intent(in) :: body
      real(wp) :: w(3)
      w = matmul(quat_matrix(body%attitude), body%omega)
   end function inertial_omega

end module adore_forces_ball_power
