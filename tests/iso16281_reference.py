"""ISO/TS 16281's static load distribution of a ball bearing, written for the reference
comparison of tests/test_iso16281_reference.py (not the engine's code, not the cited
repository's code).

Equations as ISO/TS 16281 states them for ball bearings (the standard's rigid-ring load
distribution; the same race kinematics and equilibrium as Harris & Kotzalas, *Rolling
Bearing Analysis*, "Ball bearings under combined radial, thrust and moment load"):

* geometry: A = r_i + r_e - D_w (groove curvature centres), cos(alpha0) = 1 - s_r / (2 A)
  (s_r the diametral radial operating clearance), R_i = D_pw/2 + (r_i - D_w/2) cos(alpha0)
  (radius of the inner groove curvature centres), gamma = D_w cos(alpha) / D_pw at the
  *nominal* contact angle alpha;
* Hertz: curvature sums and differences at the inner (upper signs) and outer ring,
  sum_rho = 2/D_w (2 +- gamma/(1 -+ gamma) - D_w/(2 r)),
  F(rho) = (+-gamma/(1 -+ gamma) + D_w/(2 r)) / (2 +- gamma/(1 -+ gamma) - D_w/(2 r)),
  the ellipse ratio chi from F(rho) = 1 - 2/(chi**2 - 1) (K(chi)/E(chi) - 1) (K, E the
  complete elliptic integrals of modulus k**2 = 1 - 1/chi**2), and one ball's spring
  constant of both contacts in series
  c_p = 1.48 E/(1 - nu**2) [K_i (sum_rho_i/(chi_i**2 E_i))**(1/3) + K_e (...)**(1/3)]**(-3/2),
  Q = c_p delta**1.5 (the 1.48 is the exact Hertz constant 1.4811 rounded: -0.07 % in load);
* ball j at azimuth psi_j: with the inner ring displaced radially by (d_1, d_2), axially by
  d_a (from the position where every ball just touches at alpha0) and tilted by
  (theta_1, theta_2), its groove centre moves radially by d_r = d_1 cos psi + d_2 sin psi and
  axially by d_x = d_a + R_i (sin theta_1 cos psi + sin theta_2 sin psi);
  delta_j = sqrt((A cos a0 + d_r)**2 + (A sin a0 + d_x)**2) - A,
  alpha_j = atan2(A sin a0 + d_x, A cos a0 + d_r);
* equilibrium: F_1 = sum Q cos(alpha) cos(psi), F_2 = sum Q cos(alpha) sin(psi),
  F_a = sum Q sin(alpha), M_1 = D_pw/2 sum Q sin(alpha) cos(psi),
  M_2 = D_pw/2 sum Q sin(alpha) sin(psi).

The standard's planar form has one radial direction and one tilt; here both are kept (a
moment about the radial load's axis, the cited example 7, tilts the ring across the radial
load's plane).  Units: SI (m, N, Pa, rad).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, root
from scipy.special import ellipe, ellipk


def ellipse_ratio(f_rho: float) -> float:
    """Ellipse ratio chi = a/b of a point contact from its relative curvature difference F(rho)."""
    def g(chi):
        m = 1.0 - 1.0 / chi**2
        return 1.0 - 2.0 / (chi**2 - 1.0) * (ellipk(m) / ellipe(m) - 1.0) - f_rho

    return brentq(g, 1.0 + 1e-9, 200.0, xtol=1e-15, rtol=1e-15)


class IsoBallBearing:
    """A single-row ball bearing of ISO/TS 16281: z balls of diameter dw (m) on pitch diameter
    dpw (m), groove radii r_i, r_e (m), nominal contact angle alpha (rad), diametral radial
    operating clearance s_r (m), ring and ball material e (Pa), nu; ball 0 at azimuth psi0."""

    def __init__(self, z, dw, dpw, r_i, r_e, s_r, e, nu, alpha=0.0, psi0=0.0):
        self.z, self.dw, self.dpw = z, dw, dpw
        self.a = r_i + r_e - dw
        self.alpha0 = math.acos(1.0 - s_r / (2.0 * self.a))
        self.s_a = 2.0 * self.a * math.sin(self.alpha0)      # axial operating clearance (m)
        self.r_groove_i = 0.5 * dpw + (r_i - 0.5 * dw) * math.cos(self.alpha0)
        self.psi = psi0 + 2.0 * math.pi * np.arange(z) / z
        gamma = dw * math.cos(alpha) / dpw
        terms = 0.0
        for r, g in ((r_i, gamma / (1.0 - gamma)), (r_e, -gamma / (1.0 + gamma))):
            sum_rho = 2.0 / dw * (2.0 + g - dw / (2.0 * r))
            f_rho = (g + dw / (2.0 * r)) / (2.0 + g - dw / (2.0 * r))
            chi = ellipse_ratio(f_rho)
            m = 1.0 - 1.0 / chi**2
            terms += ellipk(m) * (sum_rho / (chi**2 * ellipe(m))) ** (1.0 / 3.0)
        self.c_p = 1.48 * e / (1.0 - nu**2) * terms ** -1.5    # N/m**1.5

    def balls(self, u):
        """Ball deflections (m), contact angles (rad) and loads (N) at the ring displacement
        u = (d_1, d_2, d_a, theta_1, theta_2) (m, rad)."""
        d1, d2, da, t1, t2 = u
        c, s = np.cos(self.psi), np.sin(self.psi)
        radial = self.a * math.cos(self.alpha0) + d1 * c + d2 * s
        axial = (self.a * math.sin(self.alpha0) + da
                 + self.r_groove_i * (math.sin(t1) * c + math.sin(t2) * s))
        delta = np.maximum(np.hypot(radial, axial) - self.a, 0.0)
        alpha = np.arctan2(axial, radial)
        return delta, alpha, self.c_p * delta**1.5

    def loads(self, u):
        """(F_1, F_2, F_a, M_1, M_2) (N, N m) the balls carry at the ring displacement u."""
        _, alpha, q = self.balls(u)
        c, s = np.cos(self.psi), np.sin(self.psi)
        qr, qa = q * np.cos(alpha), q * np.sin(alpha)
        h = 0.5 * self.dpw
        return np.array([qr @ c, qr @ s, qa.sum(), h * (qa @ c), h * (qa @ s)])

    def stiffness(self, u):
        """The analytic Jacobian d(F_1, F_2, F_a, M_1, M_2)/du (5 x 5; N/m, N/rad, N m/m,
        N m/rad) of loads at the ring displacement u; an unloaded ball contributes nothing."""
        d1, d2, da, t1, t2 = u
        c, s = np.cos(self.psi), np.sin(self.psi)
        radial = self.a * math.cos(self.alpha0) + d1 * c + d2 * s
        axial = (self.a * math.sin(self.alpha0) + da
                 + self.r_groove_i * (math.sin(t1) * c + math.sin(t2) * s))
        rho = np.hypot(radial, axial)
        delta = np.maximum(rho - self.a, 0.0)
        cos_a, sin_a = radial / rho, axial / rho
        q = self.c_p * delta**1.5
        dq = 1.5 * self.c_p * np.sqrt(delta)            # dQ/d(delta); d(delta)/d(R, X) = (cos, sin)
        # Q_r = Q cos(alpha), Q_a = Q sin(alpha) as functions of the groove centre's (R, X)
        qr_r = dq * cos_a * cos_a + q * sin_a * sin_a / rho
        qr_x = dq * cos_a * sin_a - q * cos_a * sin_a / rho
        qa_r = qr_x
        qa_x = dq * sin_a * sin_a + q * cos_a * cos_a / rho
        zero, one = np.zeros_like(c), np.ones_like(c)
        dr = np.array([c, s, zero, zero, zero])          # dR/du (5 x z)
        dx = np.array([zero, zero, one, self.r_groove_i * math.cos(t1) * c,
                       self.r_groove_i * math.cos(t2) * s])   # dX/du
        dqr = qr_r * dr + qr_x * dx                        # dQ_r/du (5 x z)
        dqa = qa_r * dr + qa_x * dx
        h = 0.5 * self.dpw
        return np.array([dqr @ c, dqr @ s, dqa.sum(axis=1), h * (dqa @ c), h * (dqa @ s)])

    def solve(self, load, start=(1e-5, 0.0, 1e-5, 0.0, 0.0)):
        """Ring displacement u (m, rad) carrying load = (F_1, F_2, F_a, M_1, M_2) (N, N m),
        the tilts free (moment equilibrium); returns u and the largest residual relative
        to the load scale max(|F|, |M|/(D_pw/2), 1 N).  The start must load some balls
        (a zero-clearance bearing has no stiffness at u = 0).  Powell's hybrid method (then
        Levenberg-Marquardt if it stalls) and a Newton polish, all on the analytic Jacobian
        `stiffness`."""
        load = np.asarray(load, float)
        h = 0.5 * self.dpw
        scale = max(np.abs(load[:3]).max(), np.abs(load[3:]).max() / h, 1.0)
        weights = np.array([1.0, 1.0, 1.0, 1.0 / h, 1.0 / h])
        unit = 1e-5 * weights                  # u = x * unit: displacements are some 10 um

        def residual(x):
            return (self.loads(x * unit) - load) * weights / scale

        def jacobian(x):
            # analytic: a forward-difference Jacobian steps sqrt(eps) |x_j|, round-off for the
            # out-of-plane d_2 and theta_2 that are ~0 at the solution (ex 5 stalled at 3e-7)
            return (weights / scale)[:, None] * self.stiffness(x * unit) * unit[None, :]

        x = np.asarray(start, float) / unit
        sol = root(residual, x, jac=jacobian, method="hybr", options={"xtol": 1e-14})
        x = sol.x
        if np.abs(residual(x)).max() > 1e-10:
            x = root(residual, x, jac=jacobian, method="lm", options={"xtol": 1e-15, "ftol": 1e-15}).x
        # polish: Newton steps on the analytic Jacobian while they reduce the residual
        f = residual(x)
        for _ in range(5):
            try:
                trial = x - np.linalg.solve(jacobian(x), f)
            except np.linalg.LinAlgError:
                break
            f_trial = residual(trial)
            if not np.abs(f_trial).max() < np.abs(f).max():
                break
            x, f = trial, f_trial
        return x * unit, float(np.abs(f).max())
