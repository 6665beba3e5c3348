"""Deep-groove power loss of the dynamics against the SKF friction model (issue #28 item 2;
docs/tribology.md, "Rolling resistance").  Not part of `make test`.

The shipped deep-groove radial deck (25 x 62 mm, 7 balls of 11.5 mm on a 43.5 mm pitch
diameter, MIL-L-7808 at 323 K: nu = 9.11 mm**2/s) at 3 speeds x 3 radial loads, each run
for REVOLUTIONS shaft revolutions with and without the EHD rolling resistance run option;
the engine's power loss is the time average over the last half of the run (the run
note's balance, pyadore.api.parse_balance: race contacts + their damping + cage contacts).

SKF model (SKF rolling bearings catalogue, "Friction", the SKF model for calculating the
frictional moment; deep groove ball bearings with F_a = 0):
    M = phi_ish phi_rs G_rr (nu n)**0.6 + G_sl mu_sl                          (N mm)
    G_rr = R1 d_m**1.96 F_r**0.54,   G_sl = S1 d_m**-0.26 F_r**(5/3)
    mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,   phi_bl = exp(-2.6e-8 (n nu)**1.4 d_m)
    phi_ish = 1 / (1 + 1.84e-9 (n d_m)**1.28 nu**0.64)
    phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z / (2 (D - d))))
    power = M n pi / 30 / 1000                                                (W)
n in r/min, nu in mm**2/s, lengths in mm, loads in N.  Constants: R1 = 3.9e-7, S1 =
3.23e-3 (the catalogue's row of the 62 series; the deck's 25 x 62 mm
is a 6305 of the 63 series, whose row was not at hand), mu_bl = 0.15, mu_EHL = 0.04
(synthetic oil), K_rs = 3e-8 (oil jet / low oil level), K_z = 3.1 (deep groove ball
bearings); no seals, no drag losses (no oil bath).

Palmgren's model, the second published model (Harris & Kotzalas, Rolling Bearing Analysis,
5th ed. 2007, Essential Concepts, the friction chapter; coefficients as quoted there, not
checked against the book's text on this machine):
    M = M0 + M1                                                                (N mm)
    M0 = 1e-7 f0 (nu n)**(2/3) d_m**3  (nu n >= 2000),   160e-7 f0 d_m**3  (below)
    M1 = f1 F_beta d_m,   f1 = z (F_s / C_s)**y
f0 = 2 (deep groove ball bearing, oil bath; 4 for oil jet or a vertical shaft), z = 0.0005
and y = 0.55 (deep groove: z 0.0004-0.0006), F_beta = F_s = F_r (radial load), C_s the
static capacity: 14 820 N, the engine's ISO 76 capacity of this deck
(bench/results/operating_points.json; a catalogue 6305: 11.6 kN).

The engine's loss is decomposed by mechanism from the run's element file (time averages over
the same window, separated contacts counted as 0): the outer and inner race contacts' heat
(traction, and the rolling resistance where the option is on: the difference of the two
runs), the cage contacts' work (the run note's balance) and the contact damping.

    .venv/bin/python bench/skf_friction.py [--revolutions 2] [--workers 1]
    .venv/bin/python bench/skf_friction.py --hand      # the hand calculations only (no runs)
    .venv/bin/python bench/skf_friction.py --step0 --boundary-friction 0.1    # step 0 only
    # boundary friction in the time steps (its stiffer slip wants a smaller largest step):
    .venv/bin/python bench/skf_friction.py --revolutions 1 --boundary-friction 0.1 --step-max 0.03 \
        --with-rolling-only
    # the EHD film's limiting shear stress (run option limiting_shear, Lambda; 0: off)
    .venv/bin/python bench/skf_friction.py --limiting-shear 0.08
Results: docs/operating-points.md, "Deep-groove friction by mechanism".
"""

from __future__ import annotations

import argparse
import itertools
import json
import math
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DECK = ROOT / "decks" / "examples" / "deep_groove_radial.inp"
SPEEDS = (1000.0, 3000.0, 10000.0)     # r/min
LOADS = (300.0, 1000.0, 3000.0)        # N radial
GEOMETRY = {"d": 25.0, "D": 62.0, "dm": 43.5}   # mm
SKF = {"R1": 3.9e-7, "S1": 3.23e-3, "mu_bl": 0.15, "mu_ehl": 0.04, "K_rs": 3.0e-8, "K_z": 3.1}
BALL_M = {"D": 11.5e-3, "dm": 43.5e-3}         # m: the deck's ball diameter and pitch diameter
PALMGREN = {"f0": 2.0, "z": 0.0005, "y": 0.55, "C0": 14820.0}


def skf_power(n: float, fr: float, nu: float, g=GEOMETRY, c=SKF) -> dict:
    """The SKF model's power loss (W) of a deep groove ball bearing at n r/min, radial load
    fr (N) and kinematic viscosity nu (mm**2/s), with its rolling and sliding parts."""
    dm = g["dm"]
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu ** 0.64)
    phi_rs = math.exp(-c["K_rs"] * nu * n * (g["d"] + g["D"]) * math.sqrt(c["K_z"] / (2.0 * (g["D"] - g["d"]))))
    m_rr = phi_ish * phi_rs * c["R1"] * dm ** 1.96 * fr ** 0.54 * (nu * n) ** 0.6
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * c["mu_bl"] + (1.0 - phi_bl) * c["mu_ehl"]
    m_sl = c["S1"] * dm ** -0.26 * fr ** (5.0 / 3.0) * mu_sl
    to_w = n * math.pi / 30.0 / 1000.0
    return {"rolling_W": m_rr * to_w, "sliding_W": m_sl * to_w, "total_W": (m_rr + m_sl) * to_w}


def palmgren_power(n: float, fr: float, nu: float, g=GEOMETRY, c=PALMGREN) -> dict:
    """Palmgren's power loss (W) of a radially loaded deep groove ball bearing at n r/min,
    radial load fr (N), kinematic viscosity nu (mm**2/s): the load-independent M0 (viscous)
    and the load-dependent M1 parts and their sum (module header)."""
    dm = g["dm"]
    m0 = 1e-7 * c["f0"] * (nu * n) ** (2.0 / 3.0) * dm ** 3 if nu * n >= 2000.0 else 160e-7 * c["f0"] * dm ** 3
    m1 = c["z"] * (fr / c["C0"]) ** c["y"] * fr * dm
    to_w = n * math.pi / 30.0 / 1000.0
    return {"M0_W": m0 * to_w, "M1_W": m1 * to_w, "total_W": (m0 + m1) * to_w}


def _race_heats(print_path: Path, t_start: float) -> dict:
    """Time averages (W) from t_start to the run's end of the outer and inner race contacts'
    heat, summed over the balls (a separated contact counts 0), from the run's element file."""
    import numpy as np

    from pyadore.results import read_element_file, element_path

    values, columns, _ = read_element_file(element_path(print_path))
    t = values[:, 0]
    keep = t >= t_start
    out = {}
    for race in ("outer", "inner"):
        cols = [i for i, c in enumerate(columns) if c.startswith(f"power_loss_W:{race}:")]
        heat = np.nan_to_num(values[:, cols]).sum(axis=1)
        out[f"{race}_W"] = float(np.trapezoid(heat[keep], t[keep]) / (t[keep][-1] - t[keep][0]))
    return out


def _case(args) -> dict:
    speed, load, rolling, revolutions, exe, mu_b, step_max, lam = args
    from pyadore.api import parse_balance
    from pyadore.deck import read_deck

    deck = read_deck(DECK)
    deck.set("9.1.2", "inner_race_speed", speed)
    deck.set("9.1.1", "applied_force_z", load)
    if step_max:
        # a smaller largest step (Rec 2.1, in time scales): boundary friction's stiff slip
        deck.set("2.1", "step_initial", min(step_max, float(deck.lookup("step_initial"))))
        deck.set("2.1", "step_max", step_max)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "case.inp"
        deck.save(path)
        # one thread a case: the pool's workers share the cores (docs/performance.md, "Threads")
        cmd = [exe, str(path), str(Path(tmp) / "case.prt"), "--revolutions", str(revolutions), "--threads", "1"]
        if rolling:
            cmd.append("--rolling-resistance")
        if mu_b > 0.0:
            cmd += ["--boundary-friction", str(mu_b)]
        if lam > 0.0:
            cmd += ["--limiting-shear", str(lam)]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        row = {"speed_rpm": speed, "load_N": load, "rolling_resistance": rolling}
        bal = parse_balance(proc.stderr)
        if proc.returncode != 0 or bal is None:
            return row | {"error": proc.stderr.strip().splitlines()[-1][:300] if proc.stderr.strip() else "no balance"}
        races = _race_heats(Path(tmp) / "case.prt", bal["window_s"][0])
    return row | {"loss_W": bal["dissipation_W"], "drive_W": bal["drive_power_W"], "balance": bal} | races


def heathcote_free_rolling(q_in: float, a_in: float, q_out: float, a_out: float, speed: float, law,
                           n: int = 4001) -> dict:
    """Hand calculation of one ball at zero contact angle rolling freely between the races
    (inner race at speed r/min, outer at rest): the strip form of the differential (Heathcote)
    slip along each contact's major axis, points on the ball's surface (as the engine's strip
    traction, docs/tribology.md "Slip along the major axis"), the load per unit length of an
    elliptical Hertz contact 3 Q / (4 a) (1 - y**2 / a**2), y the arc length from the contact's
    centre (the surface point at angle y / (D/2) from the normal), the traction coefficient law(u)
    (odd in the slip u, m/s).  The cage speed and the ball's spin are those at which both
    contacts' net traction vanishes (no cage or drag force); returns them, each contact's
    pure-rolling points over a, its largest slip and its sliding power (W)."""
    import numpy as np
    from scipy.optimize import fsolve

    r, dm = BALL_M["D"] / 2.0, BALL_M["dm"]
    r_in, r_out = (dm - 2.0 * r) / 2.0, (dm + 2.0 * r) / 2.0
    w_i = speed * math.pi / 30.0
    y_in, y_out = np.linspace(-a_in, a_in, n), np.linspace(-a_out, a_out, n)
    q_i = 0.75 * q_in / a_in * (1.0 - (y_in / a_in) ** 2)
    q_o = 0.75 * q_out / a_out * (1.0 - (y_out / a_out) ** 2)

    def slips(w_c, w_b):
        rho_i, rho_o = r * np.cos(y_in / r), r * np.cos(y_out / r)
        return (w_i - w_c) * (r_in + r - rho_i) - w_b * rho_i, -w_c * (r_out - r + rho_o) + w_b * rho_o

    def net(x):
        u_i, u_o = slips(*x)
        return [np.trapezoid(law(u_i) * q_i, y_in) / q_in, np.trapezoid(law(u_o) * q_o, y_out) / q_out]

    w_c0 = w_i * (1.0 - 2.0 * r / dm) / 2.0
    w_c, w_b = fsolve(net, [w_c0, (w_i - w_c0) * r_in / r], xtol=1e-12)
    u_i, u_o = slips(w_c, w_b)

    def rolling_points(y, u, a):
        k = np.where(np.diff(np.sign(u)) != 0)[0]
        return [float((y[j] - u[j] * (y[j + 1] - y[j]) / (u[j + 1] - u[j])) / a) for j in k]

    return {"cage_rad_s": float(w_c), "ball_rad_s": float(w_b), "residual": [float(v) for v in net([w_c, w_b])],
            "inner_rolling_points": rolling_points(y_in, u_i, a_in),
            "outer_rolling_points": rolling_points(y_out, u_o, a_out),
            "inner_max_slip": float(abs(u_i).max()), "outer_max_slip": float(abs(u_o).max()),
            "inner_W": float(np.trapezoid(law(u_i) * u_i * q_i, y_in)),
            "outer_W": float(np.trapezoid(law(u_o) * u_o * q_o, y_out))}


def deck_curve(kappa0: float = 0.0, kappa_max: float = 0.02, kappa_inf: float = 0.016, u_max: float = 1.0):
    """The deck's traction-slip curve kappa(u) = (A + B u) exp(-C u) + D (Rec 10.1C, the
    deep-groove radial deck's values), odd in u."""
    import numpy as np
    from scipy.optimize import brentq

    a, d = kappa0 - kappa_inf, kappa_inf
    # maximum kappa_max at u_max: B = C (A + B u_max) and (A + B u_max) exp(-C u_max) = kappa_max - D
    c = brentq(lambda c: (a / (1.0 - c * u_max)) * math.exp(-c * u_max) - (kappa_max - d),
               1.0 / u_max + 1e-9, 50.0 / u_max)
    b = c * a / (1.0 - c * u_max)
    return lambda u: np.sign(u) * ((a + b * np.abs(u)) * np.exp(-c * np.abs(u)) + d)


def hand() -> None:
    """The hand calculations of docs/operating-points.md ("Deep-groove friction by mechanism"):
    ball 1 of the 1 000 r/min, 3 kN point (the engine's step-0 Hertz loads and semi-major
    axes: 1 955 N, a = 1.916 mm inner, 1.562 mm outer) rolling freely with the deck's curve
    and with the boundary law of the run option boundary_friction, mu (1 - exp(-|u| / u_b)),
    and a sharper Coulomb law, mu tanh(u / 0.01 mm/s)."""
    import numpy as np

    q, a_i, a_o = 1955.0, 1.916e-3, 1.562e-3
    laws = {"deck curve (Rec 10.1C)": deck_curve(),
            "boundary law 0.1, u_b 1 cm/s (the option's default slip)":
                lambda u: 0.1 * np.sign(u) * (1.0 - np.exp(-np.abs(u) / 1e-2)),
            "boundary law 0.1, u_b 1 mm/s": lambda u: 0.1 * np.sign(u) * (1.0 - np.exp(-np.abs(u) / 1e-3)),
            "boundary law 0.15 (SKF mu_bl), u_b 1 cm/s":
                lambda u: 0.15 * np.sign(u) * (1.0 - np.exp(-np.abs(u) / 1e-2)),
            "Coulomb 0.1, tanh(u / 0.01 mm/s)": lambda u: 0.1 * np.tanh(u / 1e-5)}
    for name, law in laws.items():
        h = heathcote_free_rolling(q, a_i, q, a_o, 1000.0, law)
        print(f"{name}: cage {h['cage_rad_s']:.4f} rad/s, ball {h['ball_rad_s']:.3f} rad/s; pure rolling at y/a = "
              f"{h['inner_rolling_points'][-1]:.4f} inner, {h['outer_rolling_points'][-1]:.4f} outer; largest slip "
              f"{h['inner_max_slip']:.4g} / {h['outer_max_slip']:.4g} m/s; sliding power {h['inner_W']:.4g} W inner, "
              f"{h['outer_W']:.4g} W outer")


def step0_losses(exe: str, mu_b: float, u_b: float | None = None, lam: float = 0.0) -> dict:
    """The quasi-static start's (step 0's) total power loss (W) of the deck at every point
    with the run option boundary_friction mu_b (0: the deck's curve) and boundary_slip u_b
    (m/s; None: its default) and limiting_shear lam (0: off): {(speed, load): W}.  Step 0 has
    no rolling resistance."""
    from pyadore.deck import read_deck
    from pyadore.printout import read_print

    out = {}
    for speed, load in itertools.product(SPEEDS, LOADS):
        deck = read_deck(DECK)
        deck.set("9.1.2", "inner_race_speed", speed)
        deck.set("9.1.1", "applied_force_z", load)
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "case.inp"
            deck.save(path)
            cmd = [exe, str(path), str(Path(tmp) / "case.prt"), "--steps", "0"]
            if mu_b > 0.0:
                cmd += ["--boundary-friction", str(mu_b)] + (["--boundary-slip", str(u_b)] if u_b else [])
            if lam > 0.0:
                cmd += ["--limiting-shear", str(lam)]
            proc = subprocess.run(cmd, capture_output=True, text=True)
            if proc.returncode != 0:
                out[(speed, load)] = float("nan")
                continue
            step = read_print(Path(tmp) / "case.prt").steps[0]
            out[(speed, load)] = float(step.table("performance")["total_power_loss_W"].iloc[0])
    return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--revolutions", type=float, default=2.0)
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--hand", action="store_true", help="print the hand calculations only")
    ap.add_argument("--boundary-friction", type=float, default=0.0,
                    help="the run option boundary_friction for every run (0: the deck's curve)")
    ap.add_argument("--boundary-slip", type=float, default=None, help="the run option boundary_slip (m/s)")
    ap.add_argument("--limiting-shear", type=float, default=0.0,
                    help="the run option limiting_shear (Lambda) for every run (0: off, the film uncapped)")
    ap.add_argument("--step-max", type=float, default=0.0,
                    help="the deck's largest time step (Rec 2.1, time scales; 0: the deck's 0.3)")
    ap.add_argument("--with-rolling-only", action="store_true", help="only the runs with rolling resistance")
    ap.add_argument("--step0", action="store_true",
                    help="only the quasi-static start's loss at every point (the deck's curve and boundary_friction)")
    ap.add_argument("--exe", default=os.environ.get("ADORE_EXE", str(ROOT / "build" / "native" / "adore")))
    a = ap.parse_args()
    if a.hand:
        hand()
        return 0
    from pyadore import _core

    if a.step0:
        nu = _core.lubricant(1, 323.0)["nu"] * 1e6
        curve = step0_losses(a.exe, 0.0, lam=a.limiting_shear)
        mu = step0_losses(a.exe, a.boundary_friction, a.boundary_slip, a.limiting_shear)
        print(f"step 0 (no rolling resistance); boundary_friction {a.boundary_friction:g}, boundary_slip "
              f"{a.boundary_slip or 'default'}, limiting_shear {a.limiting_shear:g}")
        print("| speed (r/min) | load (N) | SKF sliding (W) | Palmgren M1 (W) | step 0, deck's curve (W) "
              "| step 0, boundary friction (W) |")
        print("|---|---|---|---|---|---|")
        for s, f in itertools.product(SPEEDS, LOADS):
            print(f"| {s:.0f} | {f:.0f} | {skf_power(s, f, nu)['sliding_W']:.3g} | "
                  f"{palmgren_power(s, f, nu)['M1_W']:.3g} | {curve[(s, f)]:.3g} | {mu[(s, f)]:.3g} |")
        return 0

    nu = _core.lubricant(1, 323.0)["nu"] * 1e6      # mm**2/s
    cases = [(s, f, r, a.revolutions, a.exe, a.boundary_friction, a.step_max, a.limiting_shear)
             for s, f, r in itertools.product(SPEEDS, LOADS, (True,) if a.with_rolling_only else (True, False))]
    with ProcessPoolExecutor(max_workers=a.workers) as pool:
        rows = list(pool.map(_case, cases))
    print(f"nu = {nu:.3f} mm^2/s; engine: time-averaged dissipation over the last half of {a.revolutions} revolutions"
          f"; boundary_friction {a.boundary_friction:g}, boundary_slip {a.boundary_slip or 'default'}, "
          f"limiting_shear {a.limiting_shear:g}, "
          f"largest step {a.step_max or 'the deck'}s")
    print("| speed (r/min) | load (N) | SKF total (W) | SKF rolling / sliding (W) | Palmgren total (W) "
          "| Palmgren M0 / M1 (W) "
          "| engine with rolling resistance (W) | outer / inner race heat (W) | rolling resistance (on - off, W) "
          "| cage / damping (W) | engine / SKF | engine / Palmgren | engine without (W) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for s, f in itertools.product(SPEEDS, LOADS):
        skf = skf_power(s, f, nu)
        pal = palmgren_power(s, f, nu)
        on = next(r for r in rows if r["speed_rpm"] == s and r["load_N"] == f and r["rolling_resistance"])
        off = next((r for r in rows if r["speed_rpm"] == s and r["load_N"] == f and not r["rolling_resistance"]), {})
        on_w = on.get("loss_W", float("nan"))
        off_w = off.get("loss_W", float("nan"))
        on["skf"], on["palmgren"] = skf, pal
        bal = on.get("balance") or {}
        print(f"| {s:.0f} | {f:.0f} | {skf['total_W']:.3g} | {skf['rolling_W']:.3g} / {skf['sliding_W']:.3g} | "
              f"{pal['total_W']:.3g} | {pal['M0_W']:.3g} / {pal['M1_W']:.3g} | {on_w:.3g} | "
              f"{on.get('outer_W', float('nan')):.3g} / {on.get('inner_W', float('nan')):.3g} | {on_w - off_w:.3g} | "
              f"{bal.get('cage_work_W', float('nan')):.3g} / {bal.get('damping_W', float('nan')):.3g} | "
              f"{on_w / skf['total_W']:.2f} | {on_w / pal['total_W']:.2f} | {off_w:.3g} |")
    for r in rows:
        if "error" in r:
            print("failed:", r["speed_rpm"], r["load_N"], r["rolling_resistance"], r["error"])
    name = "skf_friction" + (f"_mu{a.boundary_friction:g}" if a.boundary_friction else "") \
        + (f"_ls{a.limiting_shear:g}" if a.limiting_shear else "") + ".json"
    out = ROOT / "bench" / "results" / name
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps({"nu_mm2_s": nu, "revolutions": a.revolutions, "boundary_friction": a.boundary_friction,
                               "limiting_shear": a.limiting_shear,
                               "rows": rows}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
