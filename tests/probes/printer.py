"""The engine's print writer, driven from Python (tests compare it with pyadore.printout)."""

from __future__ import annotations

import os

from .base import _probes, check


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

    from pyadore.printout.layout import INT_NOT_COMPUTED

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

    from pyadore.printout import layout as L

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
    status, message = _probes().adore_print_step(
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

    from pyadore.printout import layout as L
    from pyadore.printout.layout import INT_NOT_COMPUTED

    names = list(L.STATISTICS_LABELS.values())
    stats = np.array([float(statistics.get(n, float("nan"))) for n in names[:4]], dtype=float)
    calls = statistics.get(names[4])
    calls = INT_NOT_COMPUTED if calls is None or calls != calls else int(calls)
    status, message = _probes().adore_print_end(
        os.fspath(path), int(append), int(termination["last_step_number"]), float(termination["final_time"]),
        stats, calls)
    check(int(status), message)


def fortran_print_echo(path: str | os.PathLike, record: dict, append: bool = False) -> None:
    """Banner and input echo of an echo record (``pyadore.printout.echo_writer``) with the engine's writer."""
    import numpy as np

    from pyadore.printout.echo_writer import pack_echo

    from pyadore.printout.echo_layout import TEXT_LEN
    from pyadore.printout.layout import INT_NOT_COMPUTED

    texts, ints, reals = pack_echo(record)
    if any(len(s) > TEXT_LEN for s in texts):
        raise ValueError(f"echo texts are at most {TEXT_LEN} characters")
    ints = [INT_NOT_COMPUTED if v is None else v for v in ints]
    status, message = _probes().adore_print_echo(
        os.fspath(path), int(append), np.array([s.ljust(TEXT_LEN).encode("ascii") for s in texts], dtype="S80"),
        np.asarray(ints, dtype=np.int32), np.asarray(reals, dtype=float))
    check(int(status), message)


# --- step-0 tribology (engine modules adore_tribology_film / _slip / _flash) ---------------
