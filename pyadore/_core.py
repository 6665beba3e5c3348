"""Thin layer over the f2py extension: status codes become exceptions.

Nothing else in pyadore imports ``pyadore._engine`` directly.  Every wrapper of the
extension returns ``(status, message)``; :func:`check` raises the matching
:class:`~pyadore.errors.AdoreError` subclass for a non-zero status.
"""

from __future__ import annotations

import math
import os
import tempfile

from .errors import (
    STATUS_ENGINE,
    STATUS_INPUT,
    STATUS_OK,
    AdoreEngineError,
    AdoreError,
    AdoreInputError,
)

__all__ = ["check", "run_file", "engine_version", "hertz_point", "ball_quasi_static",
           "ball_race_jacobian", "race_control", "mount_races", "ball_clearance", "roller_races",
           "body_inertia", "traction_fit", "traction_eval", "scale_factors", "LIFE_CONSTANT_NAMES",
           "life_default_constants", "ball_bearing_life", "deck_field_table", "ball_step0_from_deck",
           "fortran_print_step", "fortran_print_end", "fortran_print_echo",
           "film_thickness", "thermal_reduction_factor", "lubricant", "contact_traction", "contact_slip",
           "flash_rise", "contact_temperature_rise", "line_contact", "roller_step0_from_deck"]


def _engine():
    try:
        from . import _engine as engine
    except ImportError as exc:  # the package was installed without its extension
        raise AdoreEngineError(
            "the pyadore engine extension (pyadore._engine) is not built; "
            "run `make setup` (or `pip install -e .`) first"
        ) from exc
    return engine


def _text(value) -> str:
    if isinstance(value, bytes):
        value = value.decode("utf-8", errors="replace")
    return str(value).rstrip()


def check(status: int, message) -> None:
    """Raise the AdoreError subclass that ``status`` stands for (0: return)."""
    if status == STATUS_OK:
        return
    text = _text(message) or f"engine returned status {status}"
    if status == STATUS_INPUT:
        raise AdoreInputError(text)
    if status == STATUS_ENGINE:
        raise AdoreEngineError(text)
    raise AdoreError(f"{text} (unknown engine status {status})")


def run_file(deck_path: str | os.PathLike, out_path: str | os.PathLike, steps: int) -> None:
    """Run the engine on a deck file and write the print file (status checked)."""
    status, message = _engine().adore_run_file(os.fspath(deck_path), os.fspath(out_path), int(steps))
    check(int(status), message)


def engine_version() -> str:
    """Version string compiled into the engine."""
    return _text(_engine().adore_version())


def hertz_point(rho, e1: float, nu1: float, e2: float, nu2: float, load: float) -> dict:
    """Hertz point contact (engine module adore_contact_hertz) as a dict of SI values.

    rho: the four principal curvatures (1/m) [body 1 plane I, II, body 2 plane I, II],
    concave negative.  Keys: kappa, a_star, b_star, delta_star, semi_major (m),
    semi_minor (m), max_pressure (Pa), deflection (m), stiffness (N/m**1.5).
    """
    import numpy as np

    values, status, message = _engine().adore_hertz_point(
        np.asarray(rho, dtype=float), e1, nu1, e2, nu2, load)
    check(int(status), message)
    keys = ["kappa", "a_star", "b_star", "delta_star", "semi_major", "semi_minor",
            "max_pressure", "deflection", "stiffness"]
    return dict(zip(keys, (float(v) for v in values)))


BALL_QS_COLUMNS = ["x", "r", "alpha_o", "alpha_i", "q_o", "q_i", "delta_o", "delta_i",
                   "a_o", "a_i", "b_o", "b_i", "p_o", "p_i", "centrifugal"]


def _ball_qs_args(geom, load, solve_moment, orbital_speed):
    import numpy as np

    return (np.asarray(geom, dtype=float), np.asarray(load, dtype=float),
            np.asarray(solve_moment, dtype=np.int32), np.asarray(orbital_speed, dtype=float))


def ball_quasi_static(geom, load, solve_moment, orbital_speed) -> dict:
    """Quasi-static ball-bearing equilibrium (engine module adore_quasistatic_ball_equilibrium).

    geom(13), load(11), solve_moment(2) as documented in fortran/api/quasistatic.f90;
    orbital_speed: per-ball orbital speeds (rad/s).  Returns per-ball arrays under the
    names of BALL_QS_COLUMNS (SI, angles in rad) and the race results ``u`` (5),
    ``inner_force``, ``inner_moment``, ``outer_force``, ``outer_moment`` (3 each),
    ``race_residual`` (5), ``max_ball_residual`` and ``iterations``.
    """
    balls, race, status, message = _engine().adore_ball_qs(*_ball_qs_args(geom, load, solve_moment,
                                                                          orbital_speed))
    check(int(status), message)
    out = {name: balls[:, k].copy() for k, name in enumerate(BALL_QS_COLUMNS)}
    out.update(u=race[0:5].copy(), inner_force=race[5:8].copy(), inner_moment=race[8:11].copy(),
               outer_force=race[11:14].copy(), outer_moment=race[14:17].copy(),
               race_residual=race[17:22].copy(), max_ball_residual=float(race[22]),
               iterations=int(race[23]))
    return out


def ball_race_jacobian(geom, load, solve_moment, orbital_speed, u):
    """Inner race residual (5) and analytic Jacobian (5 x 5) at race position ``u``."""
    import numpy as np

    res, jac, status, message = _engine().adore_ball_race_jacobian(
        *_ball_qs_args(geom, load, solve_moment, orbital_speed), np.asarray(u, dtype=float))
    check(int(status), message)
    return res.copy(), jac.copy()


def race_control(d, r_b, n_o, n_i, w_o, w_i, control: int):
    """Race-control ball kinematics: (orbital speed, spin speed (rad/s), pitch (rad))."""
    import numpy as np

    kin, status, message = _engine().adore_race_control(
        float(d), float(r_b), np.asarray(n_o, dtype=float), np.asarray(n_i, dtype=float),
        float(w_o), float(w_i), int(control))
    check(int(status), message)
    return float(kin[0]), float(kin[1]), float(kin[2])


def mount_races(rings, fits, speeds, dia_play: float) -> dict:
    """Effective fits, raceway displacements and internal clearance (adore_mounting_fits).

    rings: 4 rows (shaft, inner race, outer race, housing) of [inner diameter, outer
    diameter (m), E (Pa), nu, density (kg/m**3)]; fits, speeds: [inner, outer] (m, rad/s).
    """
    import numpy as np

    result, status, message = _engine().adore_mount_races(
        np.asarray(rings, dtype=float).T.copy(order="F"), np.asarray(fits, dtype=float),
        np.asarray(speeds, dtype=float), float(dia_play))
    check(int(status), message)
    keys = ["inner_fit", "outer_fit", "inner_pressure", "outer_pressure", "inner_raceway_growth",
            "outer_raceway_shrink", "clearance"]
    return dict(zip(keys, (float(v) for v in result)))
# --- derived input quantities (engine modules fortran/model/) -------------------------

_INERTIA_KINDS = {"sphere": 1, "solid_cylinder": 2, "hollow_cylinder": 3, "ball_cage": 4,
                  "roller_cage": 5, "roller_moments": 6}


def ball_clearance(pitch_dia: float, ball_dia: float, fo: float, fi: float, alpha0: float) -> dict:
    """Ball bearing clearance (SI, alpha0 in rad): keys dia_play, end_play,
    outer_groove_dia, inner_groove_dia (m)."""
    values, status, message = _engine().adore_model_ball_clearance(pitch_dia, ball_dia, fo, fi, alpha0)
    check(int(status), message)
    keys = ["dia_play", "end_play", "outer_groove_dia", "inner_groove_dia"]
    return dict(zip(keys, (float(v) for v in values)))


def roller_races(pitch_dia: float, roller_dia: float, dia_play: float) -> tuple[float, float]:
    """Raceway diameters (outer, inner) in m of a cylindrical roller bearing."""
    values, status, message = _engine().adore_model_roller_races(pitch_dia, roller_dia, dia_play)
    check(int(status), message)
    return float(values[0]), float(values[1])


def body_inertia(kind: str, params, rho: float, n: int = 0) -> tuple[float, list[float]]:
    """Mass (kg) and principal moments [Ix, Iy, Iz] (kg m**2) of a body.

    kind / params (m): ``sphere`` [d]; ``solid_cylinder`` [d, length];
    ``hollow_cylinder`` [d_out, d_in, width]; ``ball_cage`` [d_out, d_in, width,
    pocket_dia] with n pockets; ``roller_cage`` [d_out, d_in, width, pocket_circ,
    pocket_axial] with n pockets; ``roller_moments`` [d, length] with ``rho`` the mass (kg).
    """
    import numpy as np

    p = np.zeros(5)
    p[: len(params)] = params
    values, status, message = _engine().adore_model_inertia(_INERTIA_KINDS[kind], p, int(n), rho)
    check(int(status), message)
    return float(values[0]), [float(v) for v in values[1:]]


def traction_fit(k0: float, kmax: float, kinf: float, umax: float) -> tuple[float, float, float, float]:
    """Coefficients (A, B, C, D) of kappa(u) = (A + B u) exp(-C u) + D (B, C in s/m)."""
    values, status, message = _engine().adore_model_traction_fit(k0, kmax, kinf, umax)
    check(int(status), message)
    return tuple(float(v) for v in values)


def traction_eval(coef, u):
    """kappa(u) of the traction curve with coef = (A, B, C, D); u array-like (m/s)."""
    import numpy as np

    kappa, status, message = _engine().adore_model_traction_eval(
        np.asarray(coef, dtype=float), np.atleast_1d(np.asarray(u, dtype=float)))
    check(int(status), message)
    return kappa


def scale_factors(re_dia: float, re_mass: float, load) -> tuple[float, float, float]:
    """Scale factors (length m, load N, time s) from the rolling-element diameter and
    mass and the applied load vector [Fx, Fy, Fz] (N)."""
    import numpy as np

    values, status, message = _engine().adore_model_scales(re_dia, re_mass, np.asarray(load, dtype=float))
    check(int(status), message)
    return tuple(float(v) for v in values)
#: Names of the fatigue model constants, in the engine's order (life_params_to_array in
#: fortran/life/lundberg_palmgren.f90); units SI.  docs/life-model.md explains each.
LIFE_CONSTANT_NAMES = (
    "a_point", "b_line", "dm_exponent", "cycle_factor", "load_exp_point", "load_exp_line",
    "weibull_e_point", "weibull_e_line", "scale_a", "beta", "zeta", "matrix_m", "tau0",
    "phi0lp_root_per_pa", "phi1_asperity", "phi1_furrow", "phi1_subsurface", "processing_i",
    "phi2f_clean", "contamination", "spectrum_alpha", "sigma_rms", "theta_rms", "z_frac",
    "mu_asperity", "hoop_factor", "sigma_residual", "e_prime", "stationary_rule",
    "line_length_factor",
)

_HUGE = 1.0e300  # the engine's huge(1.0_wp) ("never fails") is returned as math.inf


def life_default_constants() -> dict:
    """Default fatigue model constants of the engine (report section 3.2), by name."""
    values = _engine().adore_life_default_constants()
    return dict(zip(LIFE_CONSTANT_NAMES, (float(v) for v in values)))


def _finite_life(value: float) -> float:
    value = float(value)
    return math.inf if value >= _HUGE else value


def ball_bearing_life(q_outer, q_inner, alpha_outer, alpha_inner, orbital_speed, p_max_outer, p_max_inner, *,
                      d_ball: float, d_pitch: float, f_outer: float, f_inner: float,
                      outer_speed: float, inner_speed: float,
                      outer_rotating: bool = False, inner_rotating: bool = True,
                      lambda_outer=None, lambda_inner=None, mu_outer=None, mu_inner=None,
                      hoop_outer: float = 0.0, hoop_inner: float = 0.0, constants: dict | None = None) -> dict:
    """Basic (Lundberg-Palmgren) and modified (Tallian) life of a ball bearing, report eqs 73-109.

    Per rolling element k (equal-length sequences, in ball order): contact loads q (N),
    contact angles alpha (rad), orbital speed (rpm), max Hertz pressures p_max (Pa),
    film parameters lambda = film / composite RMS height (-; None or <= 0: no film) and
    EHD traction coefficients mu (-; None: 0).  Race data: hoop stresses (Pa), ball and
    pitch diameters (m), groove curvature factors f, race speeds (rpm), and whether each
    race turns relative to the load.  ``constants`` overrides defaults by name
    (:data:`LIFE_CONSTANT_NAMES`, :func:`life_default_constants`).

    Returns hours for ``basic_outer``, ``basic_inner``, ``basic`` (bearing, eq 102),
    ``modified_outer``, ``modified_inner``, ``modified``; the hazard ratios ``psi_outer``,
    ``psi_inner`` (eq 78); and ``lives_outer``, ``lives_inner``, the contact lives
    (10**6 relative revolutions, numpy arrays).  ``math.inf`` means "never fails".
    """
    import numpy as np

    q_outer = np.asarray(q_outer, dtype=float)
    m = q_outer.shape[0] if q_outer.ndim == 1 else -1
    if m < 1:
        raise AdoreInputError("life: per-element inputs must be non-empty 1-d sequences")

    def per_element(name, value, default):
        arr = np.full(m, default, dtype=float) if value is None else np.asarray(value, dtype=float)
        if arr.shape != (m,):
            raise AdoreInputError(f"life: {name} has shape {arr.shape}, expected ({m},) like q_outer")
        if not np.all(np.isfinite(arr)):
            raise AdoreInputError(f"life: {name} contains NaN or infinite values")
        return arr

    arrays = [per_element(name, value, 0.0) for name, value in (
        ("q_outer", q_outer), ("q_inner", q_inner), ("alpha_outer", alpha_outer), ("alpha_inner", alpha_inner),
        ("orbital_speed", orbital_speed), ("p_max_outer", p_max_outer), ("p_max_inner", p_max_inner))]
    arrays += [per_element(name, value, 0.0) for name, value in (
        ("lambda_outer", lambda_outer), ("lambda_inner", lambda_inner),
        ("mu_outer", mu_outer), ("mu_inner", mu_inner))]
    values = life_default_constants()
    unknown = sorted(set(constants or {}) - set(values))
    if unknown:
        raise AdoreInputError(f"life: unknown constant(s) {', '.join(unknown)}")
    values.update({k: float(v) for k, v in (constants or {}).items()})
    result, lives_o, lives_i, status, message = _engine().adore_life_ball_bearing(
        *arrays, float(hoop_outer), float(hoop_inner), float(d_ball), float(d_pitch), float(f_outer),
        float(f_inner), float(outer_speed), float(inner_speed), int(bool(outer_rotating)),
        int(bool(inner_rotating)), np.array([values[k] for k in LIFE_CONSTANT_NAMES], dtype=float))
    check(int(status), message)
    keys = ["basic_outer", "basic_inner", "basic", "modified_outer", "modified_inner", "modified"]
    out = {k: _finite_life(v) for k, v in zip(keys, result[:6])}
    out["psi_outer"], out["psi_inner"] = float(result[6]), float(result[7])
    out["lives_outer"] = np.where(lives_o >= _HUGE, np.inf, lives_o)
    out["lives_inner"] = np.where(lives_i >= _HUGE, np.inf, lives_i)
    return out


def deck_field_table(deck_path: str | os.PathLike) -> list[tuple[str, int, str, object]]:
    """Read a deck with the engine's Fortran reader and return its field table.

    Same shape as :func:`pyadore.deck.field_table`: ``(record id, occurrence, field name,
    value)`` per field in deck order, occurrence 0-based among records of the same type,
    value int, float (exact: written with 17 significant digits) or str in the schema's
    SI unit.  Raises :class:`AdoreInputError` listing every problem for a bad deck.
    """
    with tempfile.TemporaryDirectory(prefix="pyadore-deck-") as tmp:
        table = os.path.join(tmp, "fields.txt")
        status, message = _engine().adore_deck_table(os.fspath(deck_path), table)
        check(int(status), message)
        with open(table, encoding="utf-8") as fh:
            lines = fh.read().split("\n")
    out: list[tuple[str, int, str, object]] = []
    convert = {"int": int, "real": float, "text": str}
    for line in lines:
        if not line:
            continue
        rid, occ, name, kind, value = line.split("\t", 4)
        out.append((rid, int(occ), name, convert[kind](value.strip() if kind != "text" else value)))
    return out


BALL_STEP0_COLUMNS = ["azimuth", "x", "r", "alpha_o", "alpha_i", "q_o", "q_i", "p_o", "p_i", "a_o", "a_i",
                      "b_o", "b_i", "delta_o", "delta_i", "orbital_speed", "spin_speed", "pitch",
                      "slip_o", "slip_i", "trac_o", "trac_i", "spin_roll_o", "spin_roll_i", "loss_o", "loss_i"]
BALL_STEP0_SUMMARY = ["inner_fit", "outer_fit", "clearance", "basic_life_h", "basic_life_outer_h",
                      "basic_life_inner_h", "u_x", "u_y", "u_z", "theta_y", "theta_z", "inner_force_x",
                      "inner_force_y", "inner_force_z", "inner_moment_x", "inner_moment_y", "inner_moment_z",
                      "passes", "power_loss"]


def ball_step0_from_deck(deck_path: str | os.PathLike, nmax: int = 200) -> tuple[dict, dict]:
    """Step 0 of a ball-bearing deck computed by the engine end to end (SI, angles in rad):
    per-ball arrays (BALL_STEP0_COLUMNS) and scalars (BALL_STEP0_SUMMARY)."""
    n, balls, summary, status, message = _engine().adore_ball_step0_deck(os.fspath(deck_path), int(nmax))
    check(int(status), message)
    per_ball = {name: balls[: int(n), k].copy() for k, name in enumerate(BALL_STEP0_COLUMNS)}
    return per_ball, {name: float(summary[k]) for k, name in enumerate(BALL_STEP0_SUMMARY)}
# ----------------------------------------------------------------------------- print writer
def _plain(frame, markers, what: str):
    """Values of a table frame as floats; markers unknown/overflow cannot cross to Fortran."""
    import numpy as np

    if markers is not None:
        bad = markers.isin(["unknown", "overflow"]).to_numpy()
        if bad.any():
            raise ValueError(f"{what}: unknown or overflow markers cannot be printed by the engine writer; "
                             "replace them by values first")
    return np.asarray(frame.to_numpy(dtype=float), dtype=float)


def _codes(values):
    import numpy as np

    from .printout.layout import INT_NOT_COMPUTED

    v = np.asarray(values, dtype=float)
    out = np.where(np.isnan(v), INT_NOT_COMPUTED, np.nan_to_num(v)).astype(np.int64)
    return out.astype(np.int32)


def fortran_print_step(path: str | os.PathLike, step, append: bool = False) -> None:
    """Write ``step`` (a :class:`pyadore.printout.Step`) with the engine's print writer.

    The Fortran counterpart of ``pyadore.printout.writer.format_step`` (used to prove the
    two byte-identical).  NaN values (not computed) print ``NaN``; a NaN code prints
    ``NaN``.  Raises ValueError for unknown/overflow markers.
    """
    import numpy as np
    import pandas as pd

    from .printout import layout as L

    t, m = step.tables, step.markers
    hm = m.get("header", {})
    if any(hm.get(c) in ("unknown", "overflow") for c in L.HEADER_COLUMNS):
        raise ValueError(f"step {step.number} header: unknown or overflow markers cannot be printed")
    header = np.array([step.header[c] for c in L.HEADER_COLUMNS], dtype=float)
    re = {n: _plain(t[n], m.get(n), n) for n in ("re_contact", "re_motion", "re_traction", "re_thermal")}
    re_no = np.asarray(t["re_contact"].index, dtype=np.int32)
    names = sorted((n for n in t if n.startswith("slices_")), key=lambda n: int(n.split("_")[1]))
    slice_roller = np.array([int(n.split("_")[1]) for n in names], dtype=np.int32)
    if names:
        slice_no = np.asarray(t[names[0]].index, dtype=np.int32)
        slices = np.stack([_plain(t[n], m.get(n), n) for n in names], axis=2)
    else:
        slice_roller = np.zeros(1, dtype=np.int32)  # f2py passes no empty arrays: one unused slot
        slice_no = np.zeros(1, dtype=np.int32)
        slices = np.zeros((1, 10, 1))
    cage, cm = t["re_cage"], m.get("re_cage")
    roller = isinstance(cage.index, pd.MultiIndex)
    cage_vals = _plain(cage, cm, "re_cage")
    if roller:
        cage_el = np.array([i[0] for i in cage.index], dtype=np.int32)
        cage_end = np.array([i[1] for i in cage.index], dtype=np.int32)
    else:
        cage_el = np.asarray(cage.index, dtype=np.int32)
        cage_end = np.zeros(len(cage_el), dtype=np.int32)
    race, rm = t["race_cage"], m.get("race_cage")
    race_vals = _plain(race, rm, "race_cage")
    perf = t["performance"].reindex(columns=list(L.PERFORMANCE_COLUMNS))
    pm = m.get("performance")
    performance = _plain(perf, pm.reindex(columns=list(L.PERFORMANCE_COLUMNS)) if pm is not None else None,
                         "performance")[0]
    fixed = {}
    for name, rows in (("bodies", L.BODY_ROWS), ("loads", L.LOAD_ROWS), ("accelerations", L.ACC_ROWS)):
        if list(t[name].index) != list(rows):
            raise ValueError(f"step {step.number} {name}: rows must be {list(rows)}")
        fixed[name] = _plain(t[name], m.get(name), name)
    summ = t["summary"]
    status, message = _engine().adore_print_step(
        os.fspath(path), int(append), int(step.number), header, step.run_id,
        re_no, re["re_contact"], re["re_motion"], re["re_traction"], re["re_thermal"],
        len(names), slice_roller, slice_no, slices, int(roller),
        cage_el, cage_end, _codes(cage_vals[:, 0]), cage_vals[:, 1:],
        np.asarray(race.index, dtype=np.int32), _codes(race_vals[:, 0]), race_vals[:, 1:],
        fixed["bodies"], fixed["loads"], fixed["accelerations"], performance,
        np.asarray(summ.index, dtype=np.int32), _plain(summ, m.get("summary"), "summary"))
    check(int(status), message)


def fortran_print_end(path: str | os.PathLike, termination: dict, statistics: dict, append: bool = True) -> None:
    """Termination line, blank line and run statistics with the engine's print writer."""
    import numpy as np

    from .printout import layout as L
    from .printout.layout import INT_NOT_COMPUTED

    names = list(L.STATISTICS_LABELS.values())
    stats = np.array([float(statistics.get(n, float("nan"))) for n in names[:4]], dtype=float)
    calls = statistics.get(names[4])
    calls = INT_NOT_COMPUTED if calls is None or calls != calls else int(calls)
    status, message = _engine().adore_print_end(
        os.fspath(path), int(append), int(termination["last_step_number"]), float(termination["final_time"]),
        stats, calls)
    check(int(status), message)


def fortran_print_echo(path: str | os.PathLike, record: dict, append: bool = False) -> None:
    """Banner and input echo of an echo record (``pyadore.printout.echo_writer``) with the engine's writer."""
    import numpy as np

    from .printout.echo_writer import pack_echo

    from .printout.echo_layout import TEXT_LEN
    from .printout.layout import INT_NOT_COMPUTED

    texts, ints, reals = pack_echo(record)
    if any(len(s) > TEXT_LEN for s in texts):
        raise ValueError(f"echo texts are at most {TEXT_LEN} characters")
    ints = [INT_NOT_COMPUTED if v is None else v for v in ints]
    status, message = _engine().adore_print_echo(
        os.fspath(path), int(append), np.array([s.ljust(TEXT_LEN).encode("ascii") for s in texts], dtype="S80"),
        np.asarray(ints, dtype=np.int32), np.asarray(reals, dtype=float))
    check(int(status), message)


# --- step-0 tribology (engine modules adore_tribology_film / _slip / _flash) ---------------

def film_thickness(rx: float, k: float, u: float, load: float, e_prime: float, eta0: float,
                   alpha: float) -> float:
    """Hamrock-Dowson isothermal central film thickness (m): R_x (m), ellipticity a/b,
    mean entraining speed (m/s), load (N), E' (Pa), eta0 (Pa s), alpha (1/Pa)."""
    h, status, message = _engine().adore_tribo_film(rx, k, u, load, e_prime, eta0, alpha)
    check(int(status), message)
    return float(h)


def thermal_reduction_factor(p_h: float, e_prime: float, loading, slide_roll: float = 0.0):
    """Gupta et al. (1992) inlet-shear thermal reduction factor for thermal loading(s) L."""
    import numpy as np

    phi, status, message = _engine().adore_tribo_thermal_factor(
        p_h, e_prime, np.atleast_1d(np.asarray(loading, float)), slide_roll)
    check(int(status), message)
    return phi


def lubricant(code: int, temperature: float, *, density: float, alpha: float, conductivity: float) -> dict:
    """Lubricant of the engine's library at temperature (K); density, alpha and conductivity
    are explicit inputs (not sourced).  Keys: nu (m**2/s), eta (Pa s), beta (1/K), alpha,
    conductivity, density."""
    values, status, message = _engine().adore_tribo_lubricant(int(code), temperature, density, alpha,
                                                              conductivity)
    check(int(status), message)
    return dict(zip(["nu", "eta", "beta", "alpha", "conductivity", "density"], map(float, values)))


CONTACT_TRACTION_KEYS = ["force", "coefficient", "power", "max_slip", "centre_slip", "rolling_speed", "spin",
                         "spin_roll", "rx", "n_rolling", "s1", "s2", "node_slip"]


def _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load):
    import numpy as np

    return np.array([float(side), alpha, rho, r_b, omega[0], omega[1], race_speed, a, load], dtype=float)


def contact_traction(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float,
                     load: float, coef, kappa_scale: float = 1.0, n_gauss: int = 16) -> dict:
    """Ball/race contact traction, power loss and kinematics (report eqs 1, 3, 4); side +1
    outer / -1 inner; omega = ball angular velocity (axial, radial) in the orbit frame
    (rad/s); race_speed = Omega - w_m (rad/s).  Keys: CONTACT_TRACTION_KEYS."""
    import numpy as np

    values, status, message = _engine().adore_tribo_contact(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, load), np.asarray(coef, float),
        kappa_scale, int(n_gauss))
    check(int(status), message)
    return dict(zip(CONTACT_TRACTION_KEYS, map(float, values)))


def contact_slip(side: int, alpha: float, rho: float, r_b: float, omega, race_speed: float, a: float, s):
    """Slip velocity (m/s) at major-axis positions s (m) (report eq 3, rolling component)."""
    import numpy as np

    u, status, message = _engine().adore_tribo_slip(
        _contact_geom(side, alpha, rho, r_b, omega, race_speed, a, 0.0), np.asarray(s, float))
    check(int(status), message)
    return u


def flash_rise(xi, q):
    """Dimensionless flash temperature rise (report eq 53) on the grid xi for flux q."""
    import numpy as np

    dt, status, message = _engine().adore_tribo_flash_strip(np.asarray(xi, float), np.asarray(q, float))
    check(int(status), message)
    return dt


def contact_temperature_rise(a: float, b: float, p0: float, xk, wk, g, u1: float, u2: float, th1, th2,
                             ny: int = 201) -> tuple[float, float]:
    """(average, largest) contact temperature rise (K), report eqs 35-36; see the engine's
    adore_tribology_flash.contact_temperature_rise."""
    import numpy as np

    values, status, message = _engine().adore_tribo_contact_temperature(
        a, b, p0, np.asarray(xk, float), np.asarray(wk, float), np.asarray(g, float), u1, u2,
        np.asarray(th1, float), np.asarray(th2, float), int(ny))
    check(int(status), message)
    return float(values[0]), float(values[1])


# --- roller bearings: line contact by slices, step 0 (fortran/contact/line_slices.f90,
# fortran/driver/roller_step0.f90) ---------------------------------------------------

LINE_CONTACT_RESULT = ["in_contact", "x1", "x2", "half_length", "load", "moment", "max_deflection",
                       "mean_half_width", "stress", "peak_pressure", "k0", "k_line"]


def line_contact(profile, race_crown: float, h, lim, e_star: float, r_eq: float, *, l_ref: float = 0.0,
                 k_line: float = 0.0, n_sub: int = 3) -> tuple[dict, dict]:
    """One roller/race line contact by slices (SI).

    profile: [length, land, crown radius, corner radius -x, corner radius +x] (m);
    h: [approach (m), tilt (rad), curvature (1/m)] of delta(x); lim: permissible ends (m);
    l_ref > 0: slice stiffness from Palmgren at reference length l_ref, else k_line.
    Returns (slices: x, weight, delta, q, b arrays; totals: LINE_CONTACT_RESULT).
    """
    import numpy as np

    nmax = 4 * int(n_sub)
    n, slices, result, status, message = _engine().adore_line_contact(
        np.asarray(profile, dtype=float), float(race_crown), np.asarray(h, dtype=float),
        np.asarray(lim, dtype=float), float(e_star), float(r_eq), float(l_ref), float(k_line),
        int(n_sub), nmax)
    check(int(status), message)
    cols = {name: slices[: int(n), k].copy() for k, name in enumerate(["x", "weight", "delta", "q", "b"])}
    return cols, {name: float(v) for name, v in zip(LINE_CONTACT_RESULT, result)}


ROLLER_STEP0_COLUMNS = ["azimuth", "r", "tilt", "q_o", "q_i", "p_o", "p_i", "a_o", "a_i", "b_o", "b_i",
                        "delta_o", "delta_i", "centrifugal", "orbital_speed", "spin_speed", "peak_o", "peak_i"]
ROLLER_STEP0_SLICES = ["x_o", "delta_o", "b_o", "q_o", "x_i", "delta_i", "b_i", "q_i"]
ROLLER_STEP0_SUMMARY = ["inner_fit", "outer_fit", "clearance", "contact_clearance", "u_y", "u_z",
                        "inner_force_x", "inner_force_y", "inner_force_z", "inner_moment_x", "inner_moment_y",
                        "inner_moment_z", "race_residual_y", "race_residual_z", "max_roller_residual",
                        "iterations", "inner_raceway_growth", "outer_raceway_shrink", "k_line_outer",
                        "k_line_inner", "basic_life_outer_h", "basic_life_inner_h", "basic_life_h"]


def roller_step0_from_deck(deck_path: str | os.PathLike, *, growth_count: int = 2,
                           nmax: int = 200) -> tuple[dict, dict, dict]:
    """Step 0 of a roller-bearing deck computed by the engine end to end (SI, rad, rad/s).

    growth_count 2 reproduces ADORE 5.0 (raceway growth applied twice in the contact
    geometry, see fortran/driver/roller_step0.f90), 1 is the consistent clearance.
    Returns (per-roller arrays ROLLER_STEP0_COLUMNS, per-roller slice arrays (n, 12)
    ROLLER_STEP0_SLICES, scalars ROLLER_STEP0_SUMMARY).
    """
    n, rollers, slices, summary, status, message = _engine().adore_roller_step0_deck(
        os.fspath(deck_path), int(growth_count), int(nmax))
    check(int(status), message)
    n = int(n)
    per_roller = {name: rollers[:n, k].copy() for k, name in enumerate(ROLLER_STEP0_COLUMNS)}
    per_slice = {name: slices[:n, :, k].copy() for k, name in enumerate(ROLLER_STEP0_SLICES)}
    return per_roller, per_slice, {name: float(summary[k]) for k, name in enumerate(ROLLER_STEP0_SUMMARY)}
