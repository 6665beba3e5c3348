"""Generate fortran/tribology/ehd_strip_table.f90: the across-strip integral of the EHD
film shear as a compile-time table (issue #16; docs/tribology.md, "The fast EHD contact
traction").

The strip integral.  At a node of the major axis the thermal film shear of
adore_tribology_ehd_traction, tau h = amp E g(Z E) with E = exp(alpha p / 2), Z = zeta |u|,
g(z) = 2 asinh(z) / sqrt(1 + z**2), integrated across the strip y = b' sin(psi) under the
Hertz pressure p = p_c cos(psi) (p_c the pressure at the strip's centre) is

    S(A, Z) = integral over y' in [-1, 1] of E g(Z E) dy' = (2 / Z) W(A, L),
    W(A, L) = integral_0^{pi/2} H(L + A cos psi) cos psi dpsi,      A = alpha p_c / 2, L = ln Z,
    H(x) = e**x g(e**x) = 2 theta tanh(theta),  theta = asinh(e**x),

a weighted mean of one universal function H (the integral of cos psi is 1): it depends on
the lubricant, film and contact only through the two dimensionless numbers A and L.  The
table holds G(A, L) = ln W - 2 L (so that S = 2 Z exp(G), no division, and G tends to a
constant as Z -> 0) on a uniform grid of step H_STEP in A and L, and the engine
interpolates it by the tensor-product Lagrange polynomial of degree DEGREE (3: 4 x 4 nodes
around the point) over the domain A in [0, A_MAX], L in [L_MIN, L_MAX]; the grid carries
(DEGREE + 1) / 2 extra nodes on every side so the stencil is always centred.  G has the
singularities of H at x = +-i pi / 2 (e**x = +-i) within its strip of features, so its
interpolation needs a step of a fraction of 1: measured (this script, --degree, --step),
degree 5 on 0.25: 1.6e-5; degree 5 on 0.2: 4.4e-6 (9849 values); degree 7 on 0.25: 2.8e-6
(6897 values, but 8 x 8 nodes: 13 % slower per contact); degree 3 on 0.2: 7.9e-5; degree 3
on 0.1: 5.2e-6; degree 3 on 0.08: 2.1e-6 (55025 values, 430 KB; the default since issue #30:
more accurate than degree 5 on 0.2 with 16 instead of 36 nodes a point, 181 -> ~80
instructions a point).  Outside the domain (each error
measured below and written into the table's header):

* L < L_MIN (= -A_MAX - 8): G(A, L) = G(A, L_MIN); H(x) = 2 e**(2x) (1 - 2/3 e**(2x) + ...)
  so the error is about e**(2 (L + A)) <= e**-16 there.
* L > L_MAX = 8: W = 2 (L + ln 2 + A pi / 4), since H(x) = 2 (x + ln 2) + O(x e**(-2x)).
* A > A_MAX: no table (the engine falls back to Gauss quadrature across the strip).

The values of G come from composite Gauss-Legendre (16 panels x 40 points in psi, converged
to ~1e-14 against 32 x 80).  The interpolation error is measured here, by the engine's own
algorithm, at the centre of every grid cell and at 20000 random points of the domain, and
written into the table's header: the table's error bound.

Run: `python tools/ehd_strip_table.py` (rewrites the Fortran file; numpy only).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "fortran" / "tribology" / "ehd_strip_table.f90"

H_STEP = 0.08         # grid step in A and L
A_MAX = 12.0          # the table's range of A = alpha p_c / 2
L_MIN, L_MAX = -A_MAX - 8.0, 8.0
DEGREE = 3            # Lagrange degree per axis (odd): 4 x 4 nodes


def _grid():
    """Margin, origin and size of the grid for DEGREE and H_STEP."""
    global MARGIN, A0, L0, NA, NL
    MARGIN = (DEGREE + 1) // 2
    A0 = -MARGIN * H_STEP
    L0 = L_MIN - MARGIN * H_STEP
    NA = int(round(A_MAX / H_STEP)) + 1 + 2 * MARGIN
    NL = int(round((L_MAX - L_MIN) / H_STEP)) + 1 + 2 * MARGIN


_grid()


def _psi_rule(panels=16, points=40):
    """Composite Gauss-Legendre on psi in [0, pi/2]: cos(psi) and weights x cos(psi)."""
    xg, wg = np.polynomial.legendre.leggauss(points)
    edges = np.linspace(0.0, math.pi / 2, panels + 1)
    psi = np.concatenate([0.5 * (b - a) * xg + 0.5 * (a + b) for a, b in zip(edges[:-1], edges[1:])])
    w = np.concatenate([0.5 * (b - a) * wg for a, b in zip(edges[:-1], edges[1:])])
    return np.cos(psi), w * np.cos(psi)


def big_h(x):
    """H(x) = e**x g(e**x) = 2 theta tanh(theta), theta = asinh(e**x)."""
    theta = np.arcsinh(np.exp(x))
    return 2.0 * theta * np.tanh(theta)


def g_exact(a, l, rule=None):
    """G(A, L) = ln W(A, L) - 2 L by the composite quadrature (arrays broadcast)."""
    c, wc = rule or _psi_rule()
    a, l = np.broadcast_arrays(np.asarray(a, float), np.asarray(l, float))
    out = np.empty(a.shape)
    flat_a, flat_l, flat_o = a.ravel(), l.ravel(), out.reshape(-1)
    for k0 in range(0, flat_a.size, 2000):
        sl = slice(k0, k0 + 2000)
        x = flat_l[sl, None] + flat_a[sl, None] * c[None, :]
        flat_o[sl] = np.log(big_h(x) @ wc) - 2.0 * flat_l[sl]
    return out


def lagrange(t):
    """Weights of the nodes 0..DEGREE at t (array) of the Lagrange polynomial of DEGREE."""
    t = np.asarray(t, float)[..., None]
    k = np.arange(DEGREE + 1)
    w = np.ones(t.shape[:-1] + (DEGREE + 1,))
    for m in range(DEGREE + 1):
        fac = np.where(k == m, 1.0, (t - m) / np.where(k == m, 1.0, k - m))
        w = w * fac
    return w


def interpolate(table, a, l):
    """The engine's interpolation (ehd_strip_table's strip_log_shear) of G at (a, l)."""
    ta = (np.asarray(a, float) - A0) / H_STEP
    tl = (np.asarray(l, float) - L0) / H_STEP
    ia = np.floor(ta).astype(int) - (DEGREE - 1) // 2
    il = np.floor(tl).astype(int) - (DEGREE - 1) // 2
    wa, wl = lagrange(ta - ia), lagrange(tl - il)
    out = np.zeros(np.shape(ta))
    for i in range(DEGREE + 1):
        for j in range(DEGREE + 1):
            out += wa[..., i] * wl[..., j] * table[ia + i, il + j]
    return out


def build():
    """The table (NA x NL, A by rows) and its measured errors."""
    a_grid = A0 + H_STEP * np.arange(NA)
    l_grid = L0 + H_STEP * np.arange(NL)
    table = g_exact(a_grid[:, None], l_grid[None, :])
    # check: the centre of every cell of the domain, and random points
    ac = np.arange(H_STEP / 2, A_MAX, H_STEP)
    lc = np.arange(L_MIN + H_STEP / 2, L_MAX, H_STEP)
    rng = np.random.default_rng(20261124)
    ar = np.concatenate([np.repeat(ac, lc.size), rng.uniform(0.0, A_MAX, 20000)])
    lr = np.concatenate([np.tile(lc, ac.size), rng.uniform(L_MIN, L_MAX, 20000)])
    err_table = float(np.abs(interpolate(table, ar, lr) - g_exact(ar, lr)).max())
    # below L_MIN: G flat; above L_MAX: the asymptote (relative error of W = error of G)
    aa = np.linspace(0.0, A_MAX, 49)
    err_low = max(float(np.abs(g_exact(aa, L_MIN) - g_exact(aa, L_MIN - d)).max()) for d in (1.0, 5.0, 30.0))
    err_high = 0.0
    for lh in (L_MAX, L_MAX + 2.0, L_MAX + 10.0):
        w_asym = 2.0 * (lh + math.log(2.0) + aa * math.pi / 4)
        err_high = max(err_high, float(np.abs(np.log(w_asym) - 2.0 * lh - g_exact(aa, lh)).max()))
    # the quadrature that made the table, against one twice as fine
    fine = _psi_rule(32, 80)
    err_quad = float(np.abs(g_exact(ar[::50], lr[::50]) - g_exact(ar[::50], lr[::50], fine)).max())
    return table, dict(table=err_table, low=err_low, high=err_high, quadrature=err_quad)


def fortran(table, err):
    """Text of the Fortran module."""
    bound = float(f"{err['table']:.1e}")
    lines = [
        "!> The across-strip integral of the EHD film shear as a compile-time table (issue #16).",
        "!> GENERATED by tools/ehd_strip_table.py: do not edit by hand (that script documents the",
        "!> algebra and the error measurement).",
        "!>",
        "!> G(A, L) = ln W(A, L) - 2 L with W(A, L) = integral_0^{pi/2} H(L + A cos psi) cos psi dpsi,",
        "!> H(x) = 2 theta tanh(theta), theta = asinh(e**x): the strip integral of the thermal film",
        "!> shear (adore_tribology_ehd_traction) is S = 2 Z exp(G) for A = alpha p_c / 2 (p_c the",
        "!> strip's centre pressure) and Z = zeta |u| = e**L.  Grid step STRIP_H in A and L,",
        f"!> degree-{DEGREE} Lagrange interpolation ({DEGREE + 1} x {DEGREE + 1} nodes) on A in [0, STRIP_A_MAX],",
        "!> L in [STRIP_L_MIN, STRIP_L_MAX].  Measured errors of G (= relative errors of S):",
        f"!>   interpolation, at every cell centre and 20000 random points:  {err['table']:.2e}",
        f"!>   L < STRIP_L_MIN taken as STRIP_L_MIN (G flat):                {err['low']:.2e}",
        f"!>   L > STRIP_L_MAX by the asymptote W = 2 (L + ln 2 + A pi / 4):  {err['high']:.2e}",
        f"!>   table values (composite Gauss, against twice as fine):      {err['quadrature']:.2e}",
        "module adore_tribology_ehd_strip_table",
        "   use, intrinsic :: iso_c_binding, only: c_int, c_double",
        "   use adore_core_kinds, only: wp",
        "   implicit none",
        "   private",
        "",
        "   public :: strip_log_shear, strip_log_shear_nodes",
        "",
        "   !> grid step (in A and L), range of A, range of L = ln Z of the table; STRIP_ERROR:",
        "   !> the measured bound of the interpolation error of G (relative error of S)",
        f"   real(wp), parameter, public :: STRIP_H = {H_STEP!r}_wp, STRIP_A_MAX = {A_MAX!r}_wp",
        f"   real(wp), parameter, public :: STRIP_L_MIN = {L_MIN!r}_wp, STRIP_L_MAX = {L_MAX!r}_wp",
        f"   real(wp), parameter, public :: STRIP_ERROR = {bound!r}_wp",
        f"   real(wp), parameter :: A0 = {A0!r}_wp, L0 = {L0!r}_wp, INV_H = 1.0_wp/STRIP_H",
        f"   integer, parameter :: NA = {NA}, NL = {NL}",
        "",
    ]
    names = []
    for i in range(NA):
        name = f"G_A{i:02d}"
        names.append(name)
        vals = [f"{v:.17e}_wp" for v in table[i]]
        lines.append(f"   real(wp), parameter :: {name}(NL) = [ &")
        for k in range(0, len(vals), 4):
            chunk = ", ".join(vals[k:k + 4])
            lines.append(f"      {chunk}" + (", &" if k + 4 < len(vals) else " ]"))
    lines.append("   !> G at L0 + STRIP_H (l - 1), A0 + STRIP_H (a - 1)")
    lines.append("   real(wp), parameter :: TABLE(NL, NA) = reshape([ &")
    for k in range(0, NA, 8):
        chunk = ", ".join(names[k:k + 8])
        lines.append(f"      {chunk}" + (", &" if k + 8 < NA else "], [NL, NA])"))
    lines += [
        "",
    ] + _kernel_interface() + [
        "contains",
        "",
    ] + _evaluator() + _nodes() + [
        "end module adore_tribology_ehd_strip_table",
        "",
    ]
    return "\n".join(lines)


def _evaluator():
    """Fortran lines of strip_log_shear: the Lagrange weights as prefix and suffix products,
    computed for A and L together as pairs (the compiler packs them: the same operations on
    each, so the same bits as one axis at a time), the columns of A combined first, then
    along L."""
    n, c, p = DEGREE + 1, (DEGREE - 1) // 2, DEGREE
    inv = []
    for k in range(n):
        den = math.prod(k - m for m in range(n) if m != k)
        inv.append(f"{'-' if den < 0 else ''}1.0_wp/{abs(den)}.0_wp")
    names = [f"x{k}" for k in range(n)] + [f"p{k}" for k in range(2, p + 1)]
    names += [f"s{k}" for k in range(p - 1)] + [f"w{k}" for k in range(n)]
    lines = [
        "   !> G(A, L) (dimensionless) for A in [0, STRIP_A_MAX] and L in [STRIP_L_MIN, STRIP_L_MAX]",
        f"   !> (the caller keeps to that domain): Lagrange interpolation of degree {DEGREE} of the",
        f"   !> table on the {n} x {n} nodes around (A, L): weight k of the nodes 0..{p} at t in",
        f"   !> [{c}, {c + 1}) is prod_{{m /= k}} (t - m) / (k - m); element 1 of each pair is along A,",
        "   !> element 2 along L.",
        "   pure function strip_log_shear(a, l) result(g)",
        "      real(wp), intent(in) :: a, l",
        "      real(wp) :: g",
        "      real(wp) :: t(2)",
    ]
    for k in range(0, len(names), 10):
        lines.append("      real(wp), dimension(2) :: " + ", ".join(names[k:k + 10]))
    lines += [
        f"      real(wp) :: v({n})",
        "      integer :: i(2)",
        "      t = [(a - A0)*INV_H, (l - L0)*INV_H]",
        f"      i = int(t) - {c}",
        "      x0 = t - i",
    ]
    lines += [f"      x{k} = x0 - {k}.0_wp" for k in range(1, n)]
    # prefix products p_k = x_0 ... x_(k-1) (p_1 = x_0), suffix s_k = x_(k+1) ... x_p (s_(p-1) = x_p)
    pre = lambda k: "x0" if k == 1 else f"p{k}"
    suf = lambda k: f"x{p}" if k == p - 1 else f"s{k}"
    lines += [f"      p{k} = {pre(k - 1)}*x{k - 1}" for k in range(2, p + 1)]
    lines += [f"      s{k} = {suf(k + 1)}*x{k + 1}" for k in range(p - 2, -1, -1)]
    lines.append(f"      w0 = ({inv[0]})*s0")
    lines += [f"      w{k} = ({inv[k]})*{pre(k)}*{suf(k)}" for k in range(1, p)]
    lines.append(f"      w{p} = ({inv[p]})*p{p}")
    lines.append(f"      v = w0(1)*TABLE(i(2) + 1:i(2) + {n}, i(1) + 1) &")
    for k in range(1, n):
        lines.append(f"          + w{k}(1)*TABLE(i(2) + 1:i(2) + {n}, i(1) + {k + 1})" + (" &" if k < p else ""))
    terms = [f"w{k}(2)*v({k + 1})" for k in range(n)]
    lines.append("      g = " + " + ".join(terms[:4]) + (" &" if n > 4 else ""))
    for k in range(4, n, 4):
        lines.append("          + " + " + ".join(terms[k:k + 4]) + (" &" if k + 4 < n else ""))
    lines += ["   end function strip_log_shear", ""]
    return lines


def _kernel_interface():
    """The C kernel's interface (fortran/tribology/ehd_strip_kernel.c: degree 3 only)."""
    if DEGREE != 3:
        return []
    return [
        "   interface",
        "      !> fortran/tribology/ehd_strip_kernel.c: strip_log_shear at nodes, the same bits",
        "      integer(c_int) function strip_kernel(n, a, l, g, table, nl, a0, l0, inv_h, a_max, l_min, l_max) &",
        "         bind(c, name=\"adore_strip_log_shear_nodes\")",
        "         import :: c_int, c_double",
        "         integer(c_int), value :: n, nl",
        "         real(c_double), intent(in) :: a(*), l(*), table(*)",
        "         real(c_double), intent(inout) :: g(*)",
        "         real(c_double), value :: a0, l0, inv_h, a_max, l_min, l_max",
        "      end function strip_kernel",
        "   end interface",
        "",
    ]


def _nodes():
    """Fortran lines of strip_log_shear_nodes: the table at many nodes, by the C kernel
    (degree 3) or a loop of strip_log_shear (other degrees' trials)."""
    lines = [
        "   !> g(j) = strip_log_shear(a(j), max(l(j), STRIP_L_MIN)) (dimensionless) for every node j",
        "   !> with a(j) <= STRIP_A_MAX and l(j) <= STRIP_L_MAX, bit for bit; g(j) of the other nodes",
        "   !> is left as it was (NaN for a NaN argument); left: the number of those other nodes",
        "   !> (beyond the domain, not NaN).  The fast EHD traction's ~40 nodes a contact in one call",
        "   !> (issue #30).",
        "   subroutine strip_log_shear_nodes(n, a, l, g, left)",
        "      integer, intent(in) :: n",
        "      real(wp), intent(in) :: a(n), l(n)",
        "      real(wp), intent(inout) :: g(n)",
        "      integer, intent(out) :: left",
    ]
    if DEGREE == 3:
        lines += [
            "      left = 0",
            "      if (n < 1) return",
            "      left = strip_kernel(int(n, c_int), a, l, g, TABLE, int(NL, c_int), A0, L0, INV_H, STRIP_A_MAX, &",
            "                          STRIP_L_MIN, STRIP_L_MAX)",
        ]
    else:
        lines += [
            "      integer :: j",
            "      left = 0",
            "      do j = 1, n",
            "         if (a(j) <= STRIP_A_MAX .and. l(j) <= STRIP_L_MAX) then",
            "            g(j) = strip_log_shear(a(j), max(l(j), STRIP_L_MIN))",
            "         else if (isnan(a(j)) .or. isnan(l(j))) then",
            "            g(j) = a(j) + l(j)",
            "         else",
            "            left = left + 1",
            "         end if",
            "      end do",
        ]
    lines += ["   end subroutine strip_log_shear_nodes", ""]
    return lines


def main() -> int:
    """Write the table; `--degree P --step H --out FILE` for trials of other grids."""
    global DEGREE, H_STEP, OUT
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--degree", type=int, default=DEGREE)
    parser.add_argument("--step", type=float, default=H_STEP)
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args()
    DEGREE, H_STEP, OUT = args.degree, args.step, args.out.resolve()
    _grid()
    table, err = build()
    OUT.write_text(fortran(table, err))
    print(f"{OUT}: degree {DEGREE}, step {H_STEP}, {NA} x {NL} values; errors " + ", ".join(f"{k} {v:.2e}" for k, v in err.items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
