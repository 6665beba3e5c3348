"""A run's full results as an :class:`xarray.Dataset`, its netCDF file, and time averages.

A ball run with time steps writes, beside its print and plot-data file, the element file
``<print stem>.elements.bin`` (the engine's element record, every value exactly:
every ball's race contacts, speeds and positions, the cage and the races, at every recorded
step; docs/results.md).  :func:`results_arrays` turns it and the plot-data file into numpy
arrays (:class:`ResultArrays`), :func:`results_dataset` into one :class:`xarray.Dataset`
with dimensions ``time``, ``element`` and ``race``; :func:`write_netcdf` writes either as
``<print stem>.nc`` (netCDF 3, 64-bit offsets, through scipy's netCDF writer) and
:func:`time_mean` takes the time-weighted averages :meth:`pyadore.Result.mean` gives.

xarray is imported on demand: a run reads its results into :class:`ResultArrays` and writes
the netCDF file from them; the dataset is built when first asked for (the first import of
xarray costs about 2 s where dask is installed: docs/performance.md).
"""

from __future__ import annotations

import functools
import math
import os
import re
from pathlib import Path

import numpy as np

from .errors import AdoreInputError

__all__ = ["element_path", "results_path", "read_element_file", "results_arrays", "results_dataset", "write_netcdf",
           "read_results", "time_mean", "time_means", "ResultArrays", "Variable", "RACES"]

#: The race dimension's labels, in the engine's order (RACE_OUTER = 1, RACE_INNER = 2).
RACES = ("outer", "inner")

#: Units of a column name's last underscore-separated words (the engine's `quantity_unit`).
_UNITS = (("_rad_s", "rad/s"), ("_m_s", "m/s"), ("_m3_s", "m**3/s"), ("_rad", "rad"), ("_deg", "deg"),
          ("_Pa", "Pa"), ("_N", "N"), ("_W", "W"), ("_K", "K"), ("_m", "m"), ("_s", "s"))


def _beside(print_path, suffix: str) -> Path:
    p = Path(os.fspath(print_path))
    return p.with_name((p.stem if p.suffix and p.stem else p.name) + suffix)


def element_path(print_path) -> Path:
    """The element file of print file ``print_path``: ``<stem>.elements.bin``."""
    return _beside(print_path, ".elements.bin")


def results_path(print_path) -> Path:
    """The netCDF file of print file ``print_path``: ``<stem>.nc``."""
    return _beside(print_path, ".nc")


def _unit(name: str) -> str:
    for suffix, unit in _UNITS:
        if name.endswith(suffix):
            return unit
    return "1"


def read_element_file(path):
    """The element file at ``path`` (docs/results.md): (values array rows x columns, column
    names, "" or the reason the run stopped early: ``RUN INCOMPLETE after step ...``).
    Raises AdoreInputError naming the file when it is not a complete element file."""
    p = Path(os.fspath(path))
    try:
        data = p.read_bytes()
    except OSError as exc:
        raise AdoreInputError(f"{p}: cannot read the element file ({exc.strerror or exc})") from None
    lines = data.split(b"\n", 3)
    head = lines[0].decode("ascii", "replace").split() if lines else []
    if len(lines) < 4 or head[:4] != ["ADORE", "ELEMENT", "RECORD", "1"] or len(head) != 7 or \
            head[6] not in ("LE", "BE"):
        raise AdoreInputError(f"{p}: not an element file (expected the first line 'ADORE ELEMENT RECORD 1 ...')")
    rows, cols = int(head[4]), int(head[5])
    columns = lines[1].decode("ascii").split(",")
    state = lines[2].decode("ascii", "replace")
    body = lines[3]
    if len(columns) != cols or columns[:2] != ["time_s", "step"] or len(body) != 8 * rows * cols:
        raise AdoreInputError(f"{p}: the element file is cut short or inconsistent ({len(body)} bytes of values, "
                              f"{rows} x {cols} doubles announced)")
    values = np.frombuffer(body, dtype="<f8" if head[6] == "LE" else ">f8").reshape(rows, cols).astype(float)
    incomplete = "" if state == "COMPLETE" else state.strip()
    return values, columns, incomplete


class Variable:
    """One variable of :class:`ResultArrays`: its dimension names, its numpy values and its
    attributes (``units``, ...); ``to_numpy()`` and ``dtype`` as an xarray variable has them."""

    __slots__ = ("dims", "values", "attrs")

    def __init__(self, dims, values, attrs=None) -> None:
        self.dims = tuple(dims)
        self.values = np.asarray(values)
        self.attrs = dict(attrs or {})

    def to_numpy(self) -> np.ndarray:
        return self.values

    @property
    def dtype(self):
        return self.values.dtype


class ResultArrays:
    """A run's full results as numpy arrays, without xarray (cheap to build: a run reads
    its element file into this, writes the netCDF file from it, and builds the
    :class:`xarray.Dataset` of :attr:`pyadore.Result.dataset` from it only when asked).
    ``data_vars`` and ``coords``: name -> :class:`Variable`; ``attrs``: the global
    attributes; ``ds[name]`` and ``name in ds`` as for a dataset; :meth:`to_dataset`."""

    def __init__(self, data_vars: dict, coords: dict, attrs: dict) -> None:
        self.data_vars = data_vars
        self.coords = coords
        self.attrs = attrs

    def __contains__(self, name) -> bool:
        return name in self.data_vars or name in self.coords

    def __getitem__(self, name) -> Variable:
        return self.data_vars[name] if name in self.data_vars else self.coords[name]

    @property
    def sizes(self) -> dict:
        """Dimension name -> length."""
        out = {}
        for var in (*self.coords.values(), *self.data_vars.values()):
            out.update(zip(var.dims, var.values.shape))
        return out

    @classmethod
    def from_dataset(cls, ds) -> "ResultArrays":
        """The arrays of an :class:`xarray.Dataset` (its coordinates, variables, attributes)."""
        return cls({n: Variable(v.dims, v.to_numpy(), v.attrs) for n, v in ds.data_vars.items()},
                   {n: Variable(v.dims, v.to_numpy(), v.attrs) for n, v in ds.coords.items()}, dict(ds.attrs))

    def to_dataset(self):
        """The :class:`xarray.Dataset` of these arrays (imports xarray)."""
        import xarray as xr

        return xr.Dataset({n: (v.dims, v.values, dict(v.attrs)) for n, v in self.data_vars.items()},
                          coords={n: (v.dims, v.values, dict(v.attrs)) for n, v in self.coords.items()},
                          attrs=dict(self.attrs))


def results_arrays(print_path, title: str = "", history: tuple | None = None) -> ResultArrays:
    """The full results of the run whose print file is ``print_path`` as numpy arrays
    (:class:`ResultArrays`; the variables, coordinates and attributes of
    :func:`results_dataset`), from its element file and plot-data file (or ``history``: that
    file's (values, column names) when already read), without xarray or pandas.  Raises
    AdoreInputError when the run wrote no element file."""
    from .timehistory import history_path, read_history_values

    path = element_path(print_path)
    if not path.is_file():
        raise AdoreInputError(f"{path}: no element file (a run without time steps, or of a bearing kind without "
                              "element results)")
    values, columns, incomplete = read_element_file(path)
    time = values[:, 0]
    step = np.rint(values[:, 1]).astype(np.int64)
    n = max((int(c.rsplit(":", 1)[1]) for c in columns if ":" in c), default=0)
    data = {}
    contact_names, element_names, body_names = [], [], []
    index = {c: i for i, c in enumerate(columns)}
    for c in columns[2:]:
        parts = c.split(":")
        if len(parts) == 3 and parts[2] == "1" and parts[1] == RACES[0]:
            contact_names.append(parts[0])
        elif len(parts) == 2 and parts[1] == "1":
            element_names.append(parts[0])
        elif len(parts) == 1:
            body_names.append(c)
    for name in contact_names:
        cols = [[index[f"{name}:{race}:{k}"] for race in RACES] for k in range(1, n + 1)]
        data[name] = Variable(("time", "element", "race"), values[:, np.array(cols)], {"units": _unit(name)})
    for name in element_names:
        cols = [index[f"{name}:{k}"] for k in range(1, n + 1)]
        data[name] = Variable(("time", "element"), values[:, cols], {"units": _unit(name)})
    for name in body_names:
        data[name] = Variable(("time",), values[:, index[name]], {"units": _unit(name)})
    hist = history_path(print_path)
    if history is None and hist.is_file():
        history = read_history_values(hist)[:2]
    if history is not None:
        hvalues, hcolumns = history
        if len(hvalues) == len(time) and np.array_equal(hvalues[:, 0], time):
            for j, name in enumerate(hcolumns):
                # the time history's one-ball columns are in the per-element variables
                if j == 0 or name == "step" or name in data or re.match(r"(re|pocket)\d+_", name):
                    continue
                data[name] = Variable(("time",), hvalues[:, j], {"units": _unit(name)})
    attrs = {"title": title, "print_file": str(Path(os.fspath(print_path))), "run_complete": int(not incomplete),
             "incomplete": incomplete, "source": "pyadore (ADORE 5.0 rebuild); docs/results.md",
             "Conventions": "CF-1.8"}
    coords = {"time": Variable(("time",), time, {"units": "s", "long_name": "simulated time"}),
              "element": Variable(("element",), np.arange(1, n + 1), {"long_name": "rolling element"}),
              "race": Variable(("race",), np.array(RACES)),
              "step": Variable(("time",), step, {"long_name": "time step"})}
    return ResultArrays(data, coords, attrs)


def results_dataset(print_path, title: str = ""):
    """The dataset of the run whose print file is ``print_path``, from its element file and
    plot-data file: coordinates ``time`` (s), ``element`` (1..n), ``race`` (outer, inner),
    ``step`` along time; per contact variables (time, element, race), per ball variables
    (time, element), the cage, races and whole bearing along time (each with ``units``).
    Attributes: ``title``, ``print_file``, ``run_complete`` (1, or 0 with ``incomplete``
    saying why the run stopped early).  Raises AdoreInputError when the run wrote no element
    file (a run without time steps, a roller run)."""
    return results_arrays(print_path, title=title).to_dataset()


@functools.lru_cache(maxsize=None)
def _netcdf_file():
    """scipy's netCDF 3 reader and writer (``scipy.io.netcdf_file``), loaded from its own
    module file ``scipy/io/_netcdf.py`` (which needs only numpy) without running the
    package ``scipy.io``, whose ``__init__`` imports scipy.sparse and the MATLAB, IDL and
    Matrix Market readers (docs/results.md, "Writing the netCDF file"); the package's
    import when scipy has moved that file."""
    import importlib.util
    import sys

    loaded = sys.modules.get("scipy.io._netcdf")
    if loaded is not None:
        return loaded.netcdf_file
    try:
        import scipy

        spec = importlib.util.spec_from_file_location("pyadore._scipy_netcdf",
                                                      Path(scipy.__file__).parent / "io" / "_netcdf.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module.netcdf_file
    except (ImportError, OSError, AttributeError):
        from scipy.io import netcdf_file

        return netcdf_file


def _attribute(value):
    """An attribute value as netCDF 3 holds it (no 64-bit integers: int32; floats: double)."""
    if isinstance(value, (bool, np.bool_)):
        return np.int8(value)
    if isinstance(value, (int, np.integer)):
        return np.int32(value)
    if isinstance(value, (float, np.floating)):
        return np.float64(value)
    return value


def _netcdf3_values(name: str, var: Variable) -> tuple[str, np.ndarray, tuple]:
    """(type code, values, extra dimension) of a variable as netCDF 3 holds it, encoded as
    xarray's writer encodes it: 64-bit integers as 32-bit ones (refused when they do not
    fit), text as characters (UTF-8) along a dimension ``string<longest>``."""
    v = var.values
    if v.dtype.kind in "US":
        raw = [str(x).encode("utf-8") if v.dtype.kind == "U" else bytes(x) for x in v.ravel()]
        width = max((len(b) for b in raw), default=1) or 1
        chars = np.zeros(v.shape + (width,), dtype="S1")
        flat = chars.reshape(-1, width)
        for i, b in enumerate(raw):
            flat[i, :len(b)] = np.frombuffer(b, dtype="S1")
        return "c", chars, (f"string{width}", width)
    if v.dtype.kind in "iu" or v.dtype.kind == "b":
        if v.size and (v.min() < np.iinfo(np.int32).min or v.max() > np.iinfo(np.int32).max):
            raise ValueError(f"{name}: integers beyond 32 bits cannot be written to netCDF 3")
        return "i", v.astype(np.int32), ()
    if v.dtype.kind == "f":
        return "d", v.astype(np.float64), ()
    raise ValueError(f"{name}: values of type {v.dtype} cannot be written to netCDF 3")


def write_netcdf(data, path) -> Path:
    """Write the results ``data`` (:class:`ResultArrays`, or an :class:`xarray.Dataset` of
    such variables) to the netCDF file ``path``: netCDF 3 with 64-bit offsets, written by
    scipy's netCDF writer with the CF encoding xarray gives the same dataset (floats with a
    NaN ``_FillValue``, the non-dimension coordinates named in each variable's
    ``coordinates``, text as UTF-8 characters, integers as 32-bit); ``xarray.open_dataset``
    reads back the same variables, dimensions and attributes.  No xarray is imported.
    Written under ``path.part``, renamed onto ``path`` when complete: a writer that fails or
    is stopped leaves no file posing as complete.  Returns the path."""
    if not isinstance(data, ResultArrays):
        data = ResultArrays.from_dataset(data)
    p = Path(os.fspath(path))
    part = p.with_name(p.name + ".part")
    dims = data.sizes
    # non-dimension coordinates, named in the "coordinates" attribute of the variables along them
    extra = [n for n, v in data.coords.items() if v.dims != (n,)]
    try:
        f = _netcdf_file()(os.fspath(part), "w", version=2, mmap=False)
        try:
            for name, size in dims.items():
                f.createDimension(name, size)
            items = [(n, v, False) for n, v in data.data_vars.items()] + \
                [(n, v, True) for n, v in data.coords.items()]
            for name, var, is_coord in items:
                code, values, more = _netcdf3_values(name, var)
                shape = var.dims
                if more:
                    if more[0] not in f.dimensions:
                        f.createDimension(*more)
                    shape = shape + (more[0],)
                out = f.createVariable(name, code, shape)
                attrs = dict(var.attrs)
                if not is_coord:
                    named = [c for c in extra if set(data.coords[c].dims) <= set(var.dims)]
                    if named:
                        attrs["coordinates"] = " ".join(named)
                if code == "d":
                    attrs["_FillValue"] = np.float64(np.nan)
                elif code == "c":
                    attrs["_Encoding"] = "utf-8"
                for key, value in attrs.items():
                    setattr(out, key, _attribute(value))
                if values.ndim:
                    out[:] = values
                else:
                    out.assignValue(values)
            for key, value in data.attrs.items():
                setattr(f, key, _attribute(value))
        finally:
            f.close()
        os.replace(part, p)
    except BaseException:
        part.unlink(missing_ok=True)
        raise
    return p


def read_results(path):
    """The dataset of a netCDF results file (``<print stem>.nc``), loaded into memory.  Check
    its ``run_complete`` attribute: 0 for a run that stopped early (``incomplete`` says why)."""
    import xarray as xr

    with xr.open_dataset(os.fspath(path), engine="scipy") as ds:
        return ds.load()


def time_mean(ds, last_revolutions: float | None = None, t_start: float | None = None,
              t_end: float | None = None):
    """Time-weighted averages of every variable of dataset ``ds`` over a time window: the
    last ``last_revolutions`` shaft (inner race) revolutions of the run, or [t_start, t_end]
    (s; either end defaults to the run's).  Each series is integrated by the trapezoidal rule
    over its recorded rows (the stride and the printed steps make them uneven), the window's
    ends linearly interpolated between rows, and divided by the time it covers; an interval
    with a NaN end (an unloaded contact's slip, say) is left out of both.  Returns a dataset
    of the averages (no ``time`` dimension) with attributes ``t_start``, ``t_end`` (s) and
    ``revolutions`` of the window.  Raises AdoreInputError for a window outside the run.
    ``ds``: an :class:`xarray.Dataset` or :class:`ResultArrays`."""
    import xarray as xr

    m = time_means(ds, last_revolutions=last_revolutions, t_start=t_start, t_end=t_end)
    return xr.Dataset({n: (v.dims, v.values, v.attrs) for n, v in m.data_vars.items()},
                      coords={n: (v.dims, v.values, v.attrs) for n, v in m.coords.items()}, attrs=m.attrs)


def time_means(ds, last_revolutions: float | None = None, t_start: float | None = None,
               t_end: float | None = None) -> ResultArrays:
    """The averages of :func:`time_mean` as :class:`ResultArrays` (no xarray imported)."""

    t = ds["time"].to_numpy()
    if len(t) < 2:
        raise AdoreInputError("time averages need at least two recorded times")
    speed = _shaft_speed(ds)
    if last_revolutions is not None:
        if t_start is not None or t_end is not None:
            raise AdoreInputError("give last_revolutions or a time window (t_start, t_end), not both")
        if not (last_revolutions > 0 and math.isfinite(last_revolutions)):
            raise AdoreInputError(f"last_revolutions must be a number > 0, got {last_revolutions!r}")
        if not speed > 0:
            raise AdoreInputError("last_revolutions needs a turning shaft (inner race)")
        t_end = float(t[-1])
        t_start = t_end - last_revolutions * 2.0 * math.pi / speed
        covered = (t[-1] - t[0]) * speed / (2.0 * math.pi)
        if t_start < t[0] - 1e-9 * (t_end - t[0]):
            raise AdoreInputError(f"the run covers {covered:.4g} shaft revolutions, fewer than the "
                                  f"{last_revolutions:g} asked for")
    t0 = float(t[0]) if t_start is None else float(t_start)
    t1 = float(t[-1]) if t_end is None else float(t_end)
    eps = 1e-12 * max(abs(float(t[-1])), 1e-300)
    if not (t0 >= t[0] - eps and t1 <= t[-1] + eps):
        raise AdoreInputError(f"time window [{t0:.6g}, {t1:.6g}] s is not inside the run's "
                              f"[{t[0]:.6g}, {t[-1]:.6g}] s")
    t0, t1 = max(t0, float(t[0])), min(t1, float(t[-1]))
    if not t1 > t0:
        raise AdoreInputError(f"time window [{t0:.6g}, {t1:.6g}] s is empty")
    inside = np.flatnonzero((t > t0) & (t < t1))
    nodes = np.concatenate([[t0], t[inside], [t1]])
    out = {}
    for name, var in ds.data_vars.items():
        if "time" not in var.dims or not np.issubdtype(var.dtype, np.number):
            continue
        x = np.moveaxis(var.to_numpy().astype(float), var.dims.index("time"), 0)
        lo = _interpolate(t, x, t0)
        hi = _interpolate(t, x, t1)
        y = np.concatenate([lo[None], x[inside], hi[None]])
        dt = np.diff(nodes).reshape((-1,) + (1,) * (y.ndim - 1))
        seg = 0.5 * (y[1:] + y[:-1])
        ok = np.isfinite(seg)
        covered = np.sum(np.where(ok, dt, 0.0), axis=0)
        with np.errstate(invalid="ignore", divide="ignore"):
            mean = np.where(covered > 0, np.sum(np.where(ok, seg * dt, 0.0), axis=0) / covered, np.nan)
        dims = tuple(d for d in var.dims if d != "time")
        out[name] = Variable(dims, mean, var.attrs)
    coords = {c: Variable(ds.coords[c].dims, ds.coords[c].to_numpy(), ds.coords[c].attrs) for c in ds.coords
              if "time" not in ds.coords[c].dims}
    attrs = dict(ds.attrs)
    attrs.update(t_start=t0, t_end=t1, revolutions=(t1 - t0) * speed / (2.0 * math.pi) if speed > 0 else math.nan)
    return ResultArrays(out, coords, attrs)


def _interpolate(t, x, at: float):
    """x (time first) linearly interpolated at time ``at`` (t ascending, t[0] <= at <= t[-1])."""
    i = int(np.searchsorted(t, at, side="right")) - 1
    i = min(max(i, 0), len(t) - 2)
    w = (at - t[i]) / (t[i + 1] - t[i]) if t[i + 1] > t[i] else 0.0
    if w == 0.0:
        return x[i]
    if w == 1.0:
        return x[i + 1]
    return (1.0 - w) * x[i] + w * x[i + 1]


def _shaft_speed(ds) -> float:
    """The shaft (inner race) speed relative to the outer race (rad/s), from the dataset's
    race angular velocities; NaN when it has none."""
    if "inner_race_angular_velocity_x_rad_s" not in ds or "outer_race_angular_velocity_x_rad_s" not in ds:
        return math.nan
    w = ds["inner_race_angular_velocity_x_rad_s"].to_numpy() - ds["outer_race_angular_velocity_x_rad_s"].to_numpy()
    return float(abs(np.nanmean(w)))
