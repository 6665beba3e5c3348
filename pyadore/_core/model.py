"""The fitted traction curve kappa(u) (fortran/tribology/traction_fit.f90; pyadore.plots.traction)."""

from __future__ import annotations

from .base import _engine, check


def traction_eval(coef, u):
    """kappa(u) of the traction curve with coef = (A, B, C, D); u array-like (m/s)."""
    import numpy as np

    kappa, status, message = _engine().adore_model_traction_eval(
        np.asarray(coef, dtype=float), np.atleast_1d(np.asarray(u, dtype=float)))
    check(int(status), message)
    return kappa
