"""Independent static reference for a ball bearing (not the engine's code): Hertz point
contact with exact complete elliptic integrals and the race equilibrium of Jones/Harris.

Written from the textbook equations (Harris & Kotzalas, *Rolling Bearing Analysis*,
5th ed., Essential Concepts, ch. 6-8 "Contact stress and deformation", "Distribution of
internal loading"; Hamrock & Brewe's exact ellipticity relation), for low speed: no
centrifugal force and no gyroscopic moment, so both contacts of a ball carry the same load
along the line of the two groove curvature centres.  It is an independent re-derivation,
not a published number.

Geometry (meridian plane of a ball at azimuth psi, measured from +z towards -y as the
engine's print): outer groove curvature centre C_o = (x_o, r_o); inner centre in the inner
race frame (x_i, r_i), both on the line of the free contact angle alpha0 through the ball
centre at the pitch radius (diametral play 2 (f_o + f_i - 1) D (1 - cos alpha0)).  The
inner race moves by (u_x, u_y, u_z) and rotates by theta_y, theta_z (exact rotation
matrices); its groove centre, projected on the ball's meridian plane, gives the centre
distance |C_i - C_o| = s; the total elastic approach is s - A, A = (f_o + f_i - 1) D, and
the load Q solves delta_o(Q, alpha) + delta_i(Q, alpha) = s - A.  Units SI.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, root
from scipy.special import ellipe, ellipk


def _ellipticity(rx: float, ry: float) -> tuple[float, float, float]:
    """k = a/b, first and second complete elliptic integrals (F, E) of a contact with
    effective radii rx (rolling direction) < ry: the exact relation
    ry/rx = (k**2 E - F) / (F - E)  (Hamrock & Brewe 1983, eq. 12, with m = 1 - 1/k**2)."""
    ratio = ry / rx
    if ratio <= 1.0 + 1e-12:                        # circular contact
        return 1.0, math.pi / 2.0, math.pi / 2.0

    def g(k):
        m = 1.0 - 1.0 / k**2
        f, e = ellipk(m), ellipe(m)
        return (k**2 * e - f) / (f - e) - ratio

    k = brentq(g, 1.0 + 1e-9, 100.0, xtol=1e-14, rtol=1e-14)
    m = 1.0 - 1.0 / k**2
    return k, float(ellipk(m)), float(ellipe(m))


def hertz_approach(q: float, curv: tuple[float, float], e_prime: float) -> float:
    """Elastic approach (m) of a point contact under load q (N): curvature sums in the
    rolling and transverse planes curv = (1/rx, 1/ry) (1/m), e_prime = 2/((1-nu1^2)/E1 +
    (1-nu2^2)/E2) (Pa).  delta = F [9/(2 E R) (Q/(pi k E'))**2]**(1/3), 1/R = 1/rx + 1/ry."""
    if q <= 0.0:
        return 0.0
    rx, ry = 1.0 / curv[0], 1.0 / curv[1]
    if ry < rx:
        rx, ry = ry, rx
    k, f, e = _ellipticity(rx, ry)
    r = 1.0 / (1.0 / rx + 1.0 / ry)
    return f * (9.0 / (2.0 * e * r) * (q / (math.pi * k * e_prime)) ** 2) ** (1.0 / 3.0)


class Bearing:
    """A ball bearing for the static reference: n balls of diameter d (m) at pitch diameter
    dm (m), groove curvature factors f_o, f_i, diametral play pd (m), steel E, nu;
    linear_rotation: the inner race's rotation linearised, I + [theta]x (the engine's small
    rotations, to measure what they neglect), else exact rotation matrices."""

    def __init__(self, n, d, dm, f_o, f_i, pd, e=2.0e11, nu=0.25, linear_rotation=False):
        self.n, self.d, self.dm, self.f_o, self.f_i = n, d, dm, f_o, f_i
        self.linear_rotation = linear_rotation
        a = (f_o + f_i - 1.0) * d
        self.a = a
        self.alpha0 = math.acos(1.0 - pd / (2.0 * a))
        self.x_o = -(f_o - 0.5) * d * math.sin(self.alpha0)
        self.r_o = 0.5 * dm - (f_o - 0.5) * d * math.cos(self.alpha0)
        self.x_i = (f_i - 0.5) * d * math.sin(self.alpha0)
        self.r_i = 0.5 * dm + (f_i - 0.5) * d * math.cos(self.alpha0)
        self.e_prime = 2.0 / (2.0 * (1.0 - nu**2) / e)
        self.psi = 2.0 * math.pi * np.arange(n) / n

    def curvatures(self, alpha: float, outer: bool) -> tuple[float, float]:
        """(rolling, transverse) curvature sums of a race contact at contact angle alpha."""
        g = self.d * math.cos(alpha) / self.dm
        ball = 2.0 / self.d
        if outer:
            return ball - 2.0 * g / (self.d * (1.0 + g)), ball - 1.0 / (self.f_o * self.d)
        return ball + 2.0 * g / (self.d * (1.0 - g)), ball - 1.0 / (self.f_i * self.d)

    def ball_load(self, approach: float, alpha: float) -> float:
        """Load Q (N) whose outer plus inner Hertz approaches equal `approach` (m)."""
        if approach <= 0.0:
            return 0.0
        co, ci = self.curvatures(alpha, True), self.curvatures(alpha, False)

        def h(q):
            return hertz_approach(q, co, self.e_prime) + hertz_approach(q, ci, self.e_prime) - approach

        hi = 1.0
        while h(hi) < 0.0:
            hi *= 2.0
        return brentq(h, 0.0, hi, xtol=1e-12, rtol=1e-14)

    def race_forces(self, u):
        """Force (N) and moment (N m, about the race centre) of the balls on the inner race
        displaced by u = (u_x, u_y, u_z, theta_y, theta_z); also the ball loads (N) and
        contact angles (rad)."""
        ux, uy, uz, ty, tz = u
        ry = np.array([[math.cos(ty), 0, math.sin(ty)], [0, 1, 0], [-math.sin(ty), 0, math.cos(ty)]])
        rz = np.array([[math.cos(tz), -math.sin(tz), 0], [math.sin(tz), math.cos(tz), 0], [0, 0, 1]])
        rot = rz @ ry
        if self.linear_rotation:
            rot = np.eye(3) + np.array([[0.0, -tz, ty], [tz, 0.0, 0.0], [-ty, 0.0, 0.0]])
        centre = np.array([ux, uy, uz])
        force, moment = np.zeros(3), np.zeros(3)
        loads, angles = [], []
        for p in self.psi:
            er = np.array([0.0, -math.sin(p), math.cos(p)])
            ex = np.array([1.0, 0.0, 0.0])
            ci = centre + rot @ (self.x_i * ex + self.r_i * er)
            cx, cr = ci @ ex, ci @ er
            v = np.array([cx - self.x_o, cr - self.r_o])
            s = float(np.hypot(*v))
            alpha = math.atan2(abs(v[0]), abs(v[1]))
            q = self.ball_load(s - self.a, alpha)
            f = -q * (v[0] * ex + v[1] * er) / s
            force += f
            moment += np.cross(ci - centre, f)
            loads.append(q)
            angles.append(alpha)
        return force, moment, np.array(loads), np.array(angles)

    def solve(self, force, moment=(0.0, 0.0, 0.0), tilt=False, start=None):
        """Race displacement u (m, rad) under the applied force (N) and moment (N m) on the
        inner race; tilt: solve theta_y, theta_z for moment equilibrium (else zero); start:
        a first u (default: along the applied force; a zero-clearance bearing under a pure
        moment needs a tilted one)."""
        force, moment = np.asarray(force, float), np.asarray(moment, float)
        lscale, fscale = 1e-6, max(np.linalg.norm(force), 1.0)
        mscale = fscale * self.dm / 2

        def unpack(z):
            u = np.zeros(5)
            u[:3] = z[:3] * lscale
            if tilt:
                u[3:] = z[3:] * lscale / (self.dm / 2)
            return u

        def res(z):
            f, m, _, _ = self.race_forces(unpack(z))
            r = list((f + force) / fscale)
            if tilt:
                r += list((m[1:] + moment[1:]) / mscale)
            return r

        # start: the load direction, far enough to load some balls
        z0 = np.zeros(5 if tilt else 3)
        z0[:3] = 5.0 * force / fscale
        if start is not None:
            z0[:3] = np.asarray(start[:3], float) / lscale
            if tilt:
                z0[3:] = np.asarray(start[3:], float) * (self.dm / 2) / lscale
        sol = root(res, z0, method="hybr", options={"xtol": 1e-13})
        if not sol.success or max(abs(np.array(res(sol.x)))) > 1e-9:
            sol = root(res, sol.x, method="lm", options={"xtol": 1e-14, "ftol": 1e-14})
        u = unpack(sol.x)
        _, _, q, alpha = self.race_forces(u)
        return u, q, alpha, max(abs(np.array(res(sol.x))))


# --- closed forms of the textbook load distribution (no 3-D equilibrium solver) ------------

def ball_stiffness(b: Bearing, alpha: float) -> float:
    """K (N/m**1.5) of one ball in series with both race contacts at contact angle alpha:
    Q = K delta**1.5, delta the total approach (Harris: K = (K_o**(-2/3) + K_i**(-2/3))**(-3/2));
    from the Hertz approach of a 1 N load (delta is proportional to Q**(2/3))."""
    delta_1n = (hertz_approach(1.0, b.curvatures(alpha, True), b.e_prime)
                + hertz_approach(1.0, b.curvatures(alpha, False), b.e_prime))
    return delta_1n ** -1.5


def stribeck_radial(b: Bearing, f_r: float) -> tuple[float, float, float]:
    """Zero clearance, pure radial load f_r (N) on Z balls at psi_j = 2 pi j / Z (Stribeck's
    analysis, Harris & Kotzalas ch. "Distribution of internal loading"): the ball at psi
    carries Q_max cos(psi)**1.5 where cos(psi) > 0, so f_r = Q_max sum cos(psi_j)**2.5 and the
    radial displacement is the approach of the most loaded ball, (Q_max / K)**(2/3).
    Returns (Q_max (N), radial displacement (m), Z Q_max / f_r); Z -> infinity gives
    1 / J_r(0.5) = 4.37 (Stribeck's constant, before his allowance for clearance: 5)."""
    c = np.cos(b.psi)
    s = float(np.sum(c[c > 0.0] ** 2.5))
    q_max = f_r / s
    return q_max, (q_max / ball_stiffness(b, 0.0)) ** (2.0 / 3.0), b.n * q_max / f_r


def radial_integral(eps: float = 0.5, n: int = 200001) -> float:
    """Sjovall's radial integral J_r(eps) = 1/(2 pi) int (1 - (1 - cos psi)/(2 eps))**1.5 cos psi
    over the loaded zone (point contact), by the trapezoidal rule on n points."""
    psi = np.linspace(-math.pi, math.pi, n)
    load = np.clip(1.0 - (1.0 - np.cos(psi)) / (2.0 * eps), 0.0, None) ** 1.5
    return float(np.trapezoid(load * np.cos(psi), psi) / (2.0 * math.pi))


def thrust_closed_form(b: Bearing, f_a: float) -> tuple[float, float, float]:
    """Pure thrust f_a (N) on Z equal balls (Harris's contact angle equation, solved for alpha):
    the groove centres keep their radial distance A cos(alpha0), so the total approach is
    A (cos(alpha0)/cos(alpha) - 1) and f_a = Z Q(alpha) sin(alpha) with Q = K(alpha) *
    approach**1.5 (K with the curvatures at alpha, not Harris's constant).  Returns
    (alpha (rad), Q (N), axial displacement (m) = A sin(alpha - alpha0) / cos(alpha))."""
    a, a0 = b.a, b.alpha0

    def g(alpha):
        approach = a * (math.cos(a0) / math.cos(alpha) - 1.0)
        return b.n * ball_stiffness(b, alpha) * approach ** 1.5 * math.sin(alpha) - f_a

    alpha = brentq(g, max(a0, 1e-9) + 1e-12, 1.4, xtol=1e-15, rtol=1e-15)
    q = f_a / (b.n * math.sin(alpha))
    return alpha, q, a * math.sin(alpha - a0) / math.cos(alpha)
