"""Whirl-stability measures of the cage over a run's time window (issue #25 item 5).

The report judges a cage by its mass-centre whirl (4.4.4, 5.3): a stable cage "whirls at a
fairly constant velocity with practically no radial velocity", its orbit inside the
clearance circle with "little or no contact at the guide land"; an unstable one's orbit
"will disintegrate into an erratic motion".  :func:`cage_stability` turns those words
into numbers from a run's dataset (:func:`pyadore.results.results_dataset`):

* ``mean_whirl_radius_m``: time mean of the mass centre's distance from the bearing axis
  (the report's figures 22 and 30 draw that orbit); whirl speed and radial velocity are
  taken about the axis too;
* ``whirl_speed_ratio``: time mean of the whirl angular speed (tangential velocity over
  radius) over the time mean of the cage's angular velocity about its axis (4.4.4: 1 for
  the most stable cage);
* ``whirl_speed_cv``: standard deviation over mean of the whirl angular speed;
* ``radial_velocity_ratio``: rms of the radial velocity over the mean |tangential velocity|;
* ``max_whirl_radius_ratio``: the largest eccentricity about the guiding race's centre
  over the guide land's radial clearance;
* ``land_contact_fraction``: the fraction of the window's time with that eccentricity beyond
  90 % of the radial clearance (the film gap below 10 % of the clearance: near-contact);
* ``cage_stability``: 1.0 (stable) when every one of the issue's acceptance bounds holds -
  whirl_speed_cv < 0.2, radial_velocity_ratio < 0.2, max_whirl_radius_ratio < 1,
  land_contact_fraction < 0.1 - else 0.0 (erratic); NaN for a cage that does not whirl
  (held centred: radius below 1 um throughout).

The window is the second half of the run's time (the issue's acceptance: "over the second
half of the run"), time-weighted by the trapezoidal rule over the recorded rows.  The
radial clearance is half the plot-data file's ``guide_clearance_m`` (the guide lands'
effective diametral play).  The guiding race (``guide``): "inner" (Rec 7.0 guide type 2:
eccentricity about the inner race's centre, which moves by tens of micrometres under load)
or "outer" (type 1: the fixed outer race, the bearing axis).
"""

from __future__ import annotations

import math

__all__ = ["STABILITY_COLUMNS", "cage_stability"]

#: The measures, in the order of the sweep summary's columns.
STABILITY_COLUMNS = ("mean_whirl_radius_m", "whirl_speed_ratio", "whirl_speed_cv", "radial_velocity_ratio",
                     "max_whirl_radius_ratio", "land_contact_fraction", "cage_stability")

#: A cage whose mass centre stays this close to the axis (m) does not whirl (held centred).
CENTRED_RADIUS = 1.0e-6


def _weights(t: np.ndarray) -> np.ndarray:
    """Trapezoidal weights of samples at times t (sum = t[-1] - t[0])."""
    import numpy as np

    w = np.zeros_like(t)
    dt = np.diff(t)
    w[:-1] += 0.5 * dt
    w[1:] += 0.5 * dt
    return w


def cage_stability(ds, fraction: float = 0.5, guide: str = "inner") -> dict:
    """The :data:`STABILITY_COLUMNS` of dataset ``ds`` over the last ``fraction`` of its
    time (default: the second half), the land measures about the ``guide`` race ("inner"
    or "outer").  NaN everywhere for a dataset without the cage's position and velocity or
    with fewer than three rows in the window."""
    import numpy as np  # here: the sweep command's client imports this module for its columns only

    if guide not in ("inner", "outer"):
        raise ValueError(f"guide must be 'inner' or 'outer', got {guide!r}")
    out = {c: math.nan for c in STABILITY_COLUMNS}
    need = ("cage_y_m", "cage_z_m", "cage_velocity_y_m_s", "cage_velocity_z_m_s", "cage_angular_velocity_x_rad_s")
    if ds is None or any(n not in ds for n in need):
        return out
    t = ds["time"].to_numpy().astype(float)
    if len(t) < 3 or not t[-1] > t[0]:
        return out
    keep = t >= t[-1] - fraction * (t[-1] - t[0])
    if keep.sum() < 3:
        return out
    t = t[keep]
    y, z = (ds[n].to_numpy().astype(float)[keep] for n in ("cage_y_m", "cage_z_m"))
    vy, vz = (ds[n].to_numpy().astype(float)[keep] for n in ("cage_velocity_y_m_s", "cage_velocity_z_m_s"))
    spin = ds["cage_angular_velocity_x_rad_s"].to_numpy().astype(float)[keep]
    if "outer_race_angular_velocity_x_rad_s" in ds:
        spin = spin - ds["outer_race_angular_velocity_x_rad_s"].to_numpy().astype(float)[keep]
    w = _weights(t)
    total = float(w.sum())
    r = np.hypot(y, z)
    out["mean_whirl_radius_m"] = float(np.sum(w * r) / total)
    clearance = math.nan
    if "guide_clearance_m" in ds:
        clearance = 0.5 * float(np.nanmean(ds["guide_clearance_m"].to_numpy().astype(float)[keep]))
    e = r
    if guide == "inner" and "inner_race_y_m" in ds and "inner_race_z_m" in ds:
        e = np.hypot(y - ds["inner_race_y_m"].to_numpy().astype(float)[keep],
                     z - ds["inner_race_z_m"].to_numpy().astype(float)[keep])
    if math.isfinite(clearance) and clearance > 0:
        out["max_whirl_radius_ratio"] = float(e.max() / clearance)
        out["land_contact_fraction"] = float(np.sum(w * (e > 0.9 * clearance)) / total)
    if r.max() < CENTRED_RADIUS:
        return out
    rs = np.where(r > 0, r, np.nan)
    v_t = (y * vz - z * vy) / rs        # tangential (whirl) velocity, m/s
    v_r = (y * vy + z * vz) / rs        # radial velocity, m/s
    whirl = v_t / rs                    # whirl angular speed, rad/s
    ok = np.isfinite(whirl)
    wk = w[ok] / w[ok].sum()
    mean_whirl = float(np.sum(wk * whirl[ok]))
    mean_spin = float(np.sum(w * spin) / total)
    out["whirl_speed_ratio"] = mean_whirl / mean_spin if mean_spin != 0 else math.nan
    out["whirl_speed_cv"] = float(math.sqrt(np.sum(wk * (whirl[ok] - mean_whirl) ** 2)) / abs(mean_whirl)) \
        if mean_whirl != 0 else math.nan
    mean_vt = float(np.sum(wk * np.abs(v_t[ok])))
    out["radial_velocity_ratio"] = float(math.sqrt(np.sum(wk * v_r[ok] ** 2)) / mean_vt) if mean_vt > 0 else math.nan
    bounds = (out["whirl_speed_cv"] < 0.2, out["radial_velocity_ratio"] < 0.2,
              not out["max_whirl_radius_ratio"] >= 1.0, not out["land_contact_fraction"] >= 0.1)
    out["cage_stability"] = 1.0 if all(bounds) else 0.0
    return out
