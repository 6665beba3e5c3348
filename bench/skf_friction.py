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

    .venv/bin/python bench/skf_friction.py [--revolutions 2] [--workers 1]
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


def _case(args) -> dict:
    speed, load, rolling, revolutions, exe = args
    from pyadore.api import parse_balance
    from pyadore.deck import read_deck

    deck = read_deck(DECK)
    deck.set("9.1.2", "inner_race_speed", speed)
    deck.set("9.1.1", "applied_force_z", load)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "case.inp"
        deck.save(path)
        # one thread a case: the pool's workers share the cores (docs/dynamics.md, "Threads")
        cmd = [exe, str(path), str(Path(tmp) / "case.prt"), "--revolutions", str(revolutions), "--threads", "1"]
        if rolling:
            cmd.append("--rolling-resistance")
        proc = subprocess.run(cmd, capture_output=True, text=True)
    row = {"speed_rpm": speed, "load_N": load, "rolling_resistance": rolling}
    bal = parse_balance(proc.stderr)
    if proc.returncode != 0 or bal is None:
        return row | {"error": proc.stderr.strip().splitlines()[-1][:300] if proc.stderr.strip() else "no balance"}
    return row | {"loss_W": bal["dissipation_W"], "drive_W": bal["drive_power_W"], "balance": bal}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--revolutions", type=float, default=2.0)
    ap.add_argument("--workers", type=int, default=1)
    ap.add_argument("--exe", default=os.environ.get("ADORE_EXE", str(ROOT / "build" / "native" / "adore")))
    a = ap.parse_args()
    from pyadore import _core

    nu = _core.lubricant(1, 323.0)["nu"] * 1e6      # mm**2/s
    cases = [(s, f, r, a.revolutions, a.exe) for s, f, r in itertools.product(SPEEDS, LOADS, (True, False))]
    with ProcessPoolExecutor(max_workers=a.workers) as pool:
        rows = list(pool.map(_case, cases))
    print(f"nu = {nu:.3f} mm^2/s; engine: time-averaged dissipation over the last half of {a.revolutions} revolutions")
    print("| speed (r/min) | load (N) | SKF total (W) | SKF rolling / sliding (W) | engine with rolling resistance (W) "
          "| ratio | engine without (W) |")
    print("|---|---|---|---|---|---|---|")
    for s, f in itertools.product(SPEEDS, LOADS):
        skf = skf_power(s, f, nu)
        on = next(r for r in rows if r["speed_rpm"] == s and r["load_N"] == f and r["rolling_resistance"])
        off = next(r for r in rows if r["speed_rpm"] == s and r["load_N"] == f and not r["rolling_resistance"])
        on_w = on.get("loss_W", float("nan"))
        off_w = off.get("loss_W", float("nan"))
        on["skf"] = skf
        print(f"| {s:.0f} | {f:.0f} | {skf['total_W']:.3g} | {skf['rolling_W']:.3g} / {skf['sliding_W']:.3g} | "
              f"{on_w:.3g} | {on_w / skf['total_W']:.2f} | {off_w:.3g} |")
    for r in rows:
        if "error" in r:
            print("failed:", r["speed_rpm"], r["load_N"], r["rolling_resistance"], r["error"])
    out = ROOT / "bench" / "results" / "skf_friction.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps({"nu_mm2_s": nu, "revolutions": a.revolutions, "rows": rows}, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
