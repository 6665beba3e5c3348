"""Figure type 10: the traction-slip relation of a run (report figure 32).

The traction coefficient against the slip speed of the RE/race contacts, from what the
run used:

* the deck's four-parameter curve kappa(u) = (A + B u) exp(-C u) + D (Rec 10.1B/10.1C),
  with A, B, C, D as the print's "LUBRICATION PARAMETERS" echo gives them (RE/RACE1 and
  RE/RACE2 rows), evaluated by the engine (``pyadore._core.traction_eval``, the same
  ``traction_coefficient`` the run uses);
* an ADRX7 traction-slip table (report 4.4.9): the one an engine print lists before its
  banner (the run used it) or a table file given with ``table=`` (read by the engine's
  reader, :func:`pyadore.read_traction_table`).  The engine interpolates it linearly in
  |u| and holds the last coefficient beyond the last point (docs/tribology.md), so the
  straight segments through the points, and the dashed level after the last one, are
  exactly the law the run evaluates.

* ADORE's EHD traction model (model 3, the ball deck's), whose traction depends on load,
  film and temperature: drawn at the printed step's most loaded ball, for its outer and
  inner race contact (load, Hertz semi-axes, film = isothermal film x thermal reduction
  factor, contact temperature from the print; the lubricant's traction rheology at that
  temperature from the engine's library), as the contact's traction coefficient
  (net traction / load) under a slip u uniform over the contact, computed by the engine's
  EHD contact traction (``_core.ehd_contact_method``, the step-0 print's 16 x 24
  quadrature).  The deck's curve is then drawn too, labelled as not used by the run.
"""

from __future__ import annotations

import math
import os
import warnings

import numpy as np
import pandas as pd

from ..errors import MissingSeriesError, MissingSeriesWarning
from . import style
from .sources import load

FIGURE = "figure type 10 (traction-slip curve)"
#: Points of a plotted curve.
CURVE_POINTS = 400
#: Echo names of the coefficients A, B, C, D and of kappa at zero slip, maximum, at
#: infinite slip and the slip at the maximum (m/s) of the RE/race rows.
_ECHO = "lubrication_parameters.{row}[{k}]"
_EHD_MODEL = 3


def _number(value) -> float:
    return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else math.nan


def echo_curves(source) -> dict[str, tuple[np.ndarray, float]]:
    """The RE/race traction curves of a print's echo: {row name: (coef [A, B, C, D],
    slip at maximum traction in m/s or NaN)}; one entry "RE/RACE" when both rows agree, a
    curve with an unknown coefficient left out."""
    if source.run is None:
        return {}
    curves = {}
    for row in ("re_race1", "re_race2"):
        coef = np.array([_number(source.run.echo.get(_ECHO.format(row=row, k=k))) for k in (6, 7, 8, 9)])
        if np.all(np.isfinite(coef)):
            curves[row.upper().replace("_", "/")] = (coef, _number(source.run.echo.get(_ECHO.format(row=row, k=5))))
    if len(curves) == 2 and np.array_equal(curves["RE/RACE1"][0], curves["RE/RACE2"][0]):
        curves = {"RE/RACE": curves["RE/RACE1"]}
    return curves


def traction_model(source) -> int | None:
    """Rec 10.0 traction model code of the deck the print lists (None without a listing)."""
    deck = source.deck()
    return None if deck is None else deck.get("10.0", "traction_model")


def curve_end(coef, u_max: float) -> float:
    """Slip (m/s) where a plotted curve ends: ten times the slip of maximum traction (the
    curve has settled to D within exp(-10) of its rise), 1 m/s without a maximum."""
    a, b, c, _d = coef
    if not math.isfinite(u_max) or u_max <= 0.0:
        u_max = (1.0 / c - a / b) if (b != 0.0 and c > 0.0) else math.nan
    return 10.0 * u_max if math.isfinite(u_max) and u_max > 0.0 else 1.0


def curve_points(coef, u_end: float) -> tuple[np.ndarray, np.ndarray]:
    """(slip m/s, kappa) of the curve coef = [A, B, C, D] on [0, u_end], by the engine."""
    from .. import _core

    u = np.linspace(0.0, u_end, CURVE_POINTS)
    return u, np.asarray(_core.traction_eval(coef, u), float)


def table_points(table: pd.DataFrame, u_end: float) -> tuple[np.ndarray, np.ndarray]:
    """(slip m/s, kappa) of the table's points, then the last coefficient held to u_end."""
    u = table["slip_m_s"].to_numpy(float)
    k = table["kappa"].to_numpy(float)
    if u_end > u[-1]:
        u, k = np.append(u, u_end), np.append(k, k[-1])
    return u, k


def ehd_contact_curves(source, u_end: float, step=None) -> list[tuple[str, np.ndarray, np.ndarray]]:
    """[(label, slip m/s, traction coefficient)] of the EHD model 3 (module docstring) at the
    outer and inner contact of the most loaded ball of a printed step (default: the first);
    [] when the print lacks what the model needs (a deck listing with the lubricant and the
    ball diameter, the step's loads, semi-axes, films and contact temperatures)."""
    from .. import _core

    deck = source.deck()
    if deck is None or source.run is None or not source.run.steps:
        return []
    code, d_ball = deck.get("10.0", "lubricant_code"), deck.get("5A", "ball_diameter")
    if not code or not d_ball:
        return []
    steps = source.run.steps                      # {step number: printed step}
    st = steps.get(next(iter(steps)) if step is None else step)
    if st is None:
        return []
    try:
        contact, traction, thermal = st.tables["re_contact"], st.tables["re_traction"], st.tables["re_thermal"]
    except KeyError:
        return []
    k = contact["contact_load_inner_N"].astype(float).idxmax()
    curves = []
    u = np.linspace(0.0, u_end, CURVE_POINTS // 4 + 1)
    for side, tag in ((1, "outer"), (-1, "inner")):
        row = dict(load=float(contact.at[k, f"contact_load_{tag}_N"]), a=float(contact.at[k, f"major_half_width_{tag}_m"]),
                   b=float(contact.at[k, f"minor_half_width_{tag}_m"]),
                   film=float(traction.at[k, f"film_thickness_{tag}_m"]) * float(traction.at[k, f"thermal_red_fac_{tag}"]),
                   temp=float(thermal.at[k, f"contact_temp_{tag}_K"]))
        if not all(math.isfinite(v) and v > 0.0 for v in row.values()):
            continue
        lub = _core.lubricant(int(code), row["temp"])
        rheology = (lub["eta_t"], lub["alpha_t"], lub["beta_t"], lub["conductivity"])
        r_b = 5.0 * float(d_ball)        # any radius > D/2: a uniform slip u = -w r_b
        kappa = []
        for ui in u:
            w = -ui / r_b                 # ball and race turn alike but for the slip: u uniform
            res = _core.ehd_contact_method(side, 0.0, 0.5 * float(d_ball), r_b, (w, 0.0), w, row["a"],
                                           row["load"], rheology, row["film"], row["b"], method="reference",
                                           n_major=16, n_strip=24)
            kappa.append(abs(res["coefficient"]))
        curves.append((f"EHD model 3, ball {k} {tag} contact ({row['load']:.0f} N, film "
                       f"{row['film'] * 1e9:.0f} nm, {row['temp']:.0f} K)", u, np.array(kappa)))
    return curves


def _read_table(table) -> pd.DataFrame:
    if isinstance(table, pd.DataFrame):
        return table
    from ..api import read_traction_table

    return read_traction_table(os.fspath(table))


def _laws(run, table_arg):
    """[(label, kind, data)] of one run: kind "table" (DataFrame) or "curve" (coef, u_max)."""
    laws = []
    table = _read_table(table_arg) if table_arg is not None else run.traction_table
    if table is not None:
        where = "ADRX7 table" + (f" {os.fspath(table_arg)}" if isinstance(table_arg, (str, os.PathLike)) else "")
        laws.append((where, "table", table))
    model = traction_model(run)
    for row, (coef, u_max) in echo_curves(run).items():
        note = ""
        if table is not None:
            note = ", replaced by the table"
        elif model == _EHD_MODEL:
            note = ", not used: the run's traction is the EHD model 3"
        laws.append((f"{row} curve{note}", "curve", (coef, u_max)))
    return laws, model


@style.styled
def traction_slip(source, *, table=None, compare=None, label: str | None = None,
                  compare_label: str | None = None, ax=None):
    """Figure type 10: traction coefficient (-) vs slip speed (m/s) of the RE/race
    contacts (report fig 32): the deck's curve from the print's echo and the ADRX7 table
    the run used (or ``table=``, a table file or a DataFrame with slip_m_s, kappa).
    ``compare`` overlays a second run's laws (dashed).  Returns the figure; raises
    MissingSeriesError when neither a complete curve nor a table is known."""
    runs = [load(source, label)]
    if compare is not None:
        runs.append(load(compare, compare_label))
    per_run = []
    for i, run in enumerate(runs):
        laws, model = _laws(run, table if i == 0 else None)
        if not laws:
            message = (f"{FIGURE}: {run.label} has no complete RE/race traction curve (A, B, C, D of the echo's "
                       f"LUBRICATION PARAMETERS) and no traction-slip table")
            if i == 0:
                raise MissingSeriesError(message)
            warnings.warn(message, MissingSeriesWarning, stacklevel=2)
        per_run.append((run, laws, model))
    u_end = 0.0
    for _run, laws, _model in per_run:
        for _name, kind, data in laws:
            u_end = max(u_end, 1.25 * float(data["slip_m_s"].iloc[-1]) if kind == "table" else curve_end(*data))
    fig, axes, own = style.figure_axes(ax)
    a = axes[0]
    colour = 0
    several = sum(1 for _run, laws, _model in per_run if laws) > 1
    for i, (run, laws, model) in enumerate(per_run):
        prefix = f"{run.label}: " if several else ""
        for name, kind, data in laws:
            c = style.COLORS[colour % len(style.COLORS)]
            colour += 1
            if kind == "table":
                u, k = table_points(data, u_end)
                n = len(data)
                a.plot(u[:n], k[:n], style.line_style(i), marker="o", color=c, label=prefix + name)
                if len(u) > n:
                    a.plot(u[n - 1:], k[n - 1:], ":", color=c, label=prefix + "held beyond the last point")
            else:
                u, k = curve_points(data[0], u_end)
                a.plot(u, k, style.line_style(i), color=c, label=prefix + name)
        if model == _EHD_MODEL and not any(kind == "table" for _n, kind, _d in laws):
            ehd = ehd_contact_curves(run, u_end)
            for name, u, k in ehd:
                c = style.COLORS[colour % len(style.COLORS)]
                colour += 1
                a.plot(u, k, style.line_style(i), color=c, linewidth=2.0, label=prefix + name)
            if not ehd and i == 0:
                warnings.warn(f"{FIGURE}: {run.label} uses the EHD traction model 3, but its print lacks the "
                              "contact data (deck listing, loads, semi-axes, films, temperatures) to draw it; "
                              "plotted: the deck's curve", MissingSeriesWarning, stacklevel=2)
    a.set_xlim(0.0, u_end)
    a.set_ylim(bottom=0.0)
    a.set_xlabel(style.label("Slip velocity", "m/s"))
    a.set_ylabel(style.label("Traction coefficient", "-"))
    style.legend(a)
    style.title(fig, axes, own, "Traction-slip relation of the RE/race contacts")
    return fig
