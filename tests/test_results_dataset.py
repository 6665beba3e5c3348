"""A run's full results (issue #29 items 1-3): Result.dataset (xarray, dimensions time,
element, race), its netCDF file beside the print, Result.mean time averages, and the print's
dynamic-step columns that now come from the same computation."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pyadore
from pyadore.errors import AdoreInputError

STEPS = 400


@pytest.fixture(scope="module")
def run400(tmp_path_factory, ball_deck):
    """Appendix C for 400 steps through Python (the acceptance run of issue #29)."""
    return pyadore.run(ball_deck, steps=STEPS, out=tmp_path_factory.mktemp("run400") / "c400.prt", progress=False)


def test_dataset_shape_every_step(run400):
    ds = run400.dataset
    assert ds is not None
    assert ds.sizes["element"] == 18 and ds.sizes["race"] == 2
    assert list(ds["race"].values) == ["outer", "inner"]
    # every step: step 0 and each of the 400 time steps, once, in time order
    assert ds["step"].values.tolist() == list(range(STEPS + 1))
    assert np.all(np.diff(ds["time"].values) > 0)
    for name in ("contact_load_N", "contact_angle_rad", "slip_velocity_m_s", "traction_coefficient", "power_loss_W",
                 "film_thickness_m", "thermal_reduction_factor", "temperature_rise_K"):
        assert ds[name].dims == ("time", "element", "race"), name
        assert ds[name].attrs["units"]
        finite = np.isfinite(ds[name].values).all(axis=(1, 2))
        # every contact of Appendix C is loaded: all computed at every step, but the flash
        # temperature rise, computed at the printed steps (0 and the last here) only
        expected = np.isin(ds["step"].values, [0, STEPS]) if name == "temperature_rise_K" else True
        assert np.array_equal(finite, np.broadcast_to(expected, finite.shape)), name
    for name in ("orbital_speed_rad_s", "orbital_position_rad", "axial_position_m", "radial_position_m"):
        assert ds[name].dims == ("time", "element"), name
    for name in ("cage_whirl_speed_rad_s", "inner_race_x_m", "total_power_loss_W", "bulk_temp_cage_K"):
        assert ds[name].dims == ("time",), name
    assert ds.attrs["run_complete"] == 1 and ds.attrs["title"] == "Ball Bearing Test Case kGeoMod=100"
    # the time history stays, on the same times
    assert np.array_equal(run400.time_history.index.to_numpy(), ds["time"].values)


def _close(a: float, printed: float) -> bool:
    """a printed as ES10.3 gives `printed`: within half a unit of its 4th digit."""
    if math.isnan(printed):
        return math.isnan(a)
    return abs(a - printed) <= 5.0001e-4 * abs(printed) + 1e-300


def test_last_step_equals_print(run400):
    ds = run400.dataset.isel(time=-1)
    step = run400.print_run().step(STEPS)
    deg, rpm = 180.0 / math.pi, 30.0 / math.pi
    checks = {
        ("re_contact", "orbital_position_deg"): ds["orbital_position_rad"] * deg,
        ("re_motion", "orbital_velocity_rpm"): ds["orbital_speed_rad_s"] * rpm,
    }
    for r, race in enumerate(("outer", "inner")):
        c = ds.isel(race=r)
        checks.update({
            ("re_contact", f"contact_angle_{race}_deg"): c["contact_angle_rad"] * deg,
            ("re_contact", f"contact_load_{race}_N"): c["contact_load_N"],
            ("re_contact", f"contact_stress_{race}_Pa"): c["max_pressure_Pa"],
            ("re_contact", f"major_half_width_{race}_m"): c["semi_major_m"],
            ("re_contact", f"minor_half_width_{race}_m"): c["semi_minor_m"],
            ("re_motion", f"spin_roll_{race}"): c["spin_roll"],
            ("re_motion", f"contact_loss_{race}_W"): c["power_loss_W"],
            ("re_traction", f"slip_velocity_{race}_m_s"): c["slip_velocity_m_s"],
            ("re_traction", f"trac_coeff_{race}"): c["traction_coefficient"],
            ("re_traction", f"film_thickness_{race}_m"): c["film_thickness_m"],
            ("re_traction", f"thermal_red_fac_{race}"): c["thermal_reduction_factor"],
            ("re_thermal", f"contact_temp_rise_{race}_K"): c["temperature_rise_K"],
        })
    bad = []
    for (table, column), values in checks.items():
        printed = step.table(table)[column].to_numpy(dtype=float)
        mine = np.asarray(values, dtype=float)
        assert len(printed) == 18
        assert np.isfinite(printed).all(), (table, column)     # every ball is loaded in Appendix C
        bad += [(table, column, k + 1, mine[k], printed[k]) for k in range(18) if not _close(mine[k], printed[k])]
    assert not bad, bad[:5]
    # the whole-bearing power loss of section 4
    perf = step.table("performance")
    assert _close(float(ds["total_power_loss_W"]), float(perf.loc["bearing", "total_power_loss_W"]))


def test_netcdf_reopens(run400):
    from pyadore.results import read_results, results_path

    path = run400.results_path
    assert path == results_path(run400.print_path) and path.is_file()
    back = read_results(path)
    assert back.sizes == run400.dataset.sizes
    assert back.attrs["run_complete"] == 1
    for name, var in run400.dataset.data_vars.items():
        np.testing.assert_array_equal(back[name].values, var.values, err_msg=name)   # full precision, NaN alike
    np.testing.assert_array_equal(back["time"].values, run400.dataset["time"].values)


def test_netcdf_writer_matches_xarrays(run400, tmp_path):
    """The run's netCDF file, written by scipy's netCDF writer without xarray (issue #29's
    start-up), against the file xarray's writer gives for the same dataset (the writer
    before): the same dimensions, global attributes and variables, each with the same
    dimensions, type, attributes and values; and the same dataset when xarray reopens them."""
    import xarray as xr
    from scipy.io import netcdf_file

    reference = tmp_path / "by_xarray.nc"
    run400.dataset.to_netcdf(reference, engine="scipy", format="NETCDF3_64BIT")
    with netcdf_file(reference, mmap=False) as a, netcdf_file(run400.results_path, mmap=False) as b:
        assert b.version_byte == a.version_byte == 2            # netCDF 3, 64-bit offsets
        assert b.dimensions == a.dimensions and b._attributes == a._attributes
        assert set(b.variables) == set(a.variables) and len(a.variables) > 50
        for name, va in a.variables.items():
            vb = b.variables[name]
            assert (vb.dimensions, vb.typecode()) == (va.dimensions, va.typecode()), name
            assert repr(vb._attributes) == repr(va._attributes), name      # the NaN fill value as text
            np.testing.assert_array_equal(vb.data, va.data, err_msg=name)  # every value, NaN alike
    with xr.open_dataset(reference, engine="scipy") as a, xr.open_dataset(run400.results_path, engine="scipy") as b:
        xr.testing.assert_identical(b.load(), a.load())
    # the writer given the xarray.Dataset itself writes the same bytes as from the run's arrays
    from pyadore.results import write_netcdf

    again = write_netcdf(run400.dataset, tmp_path / "from_dataset.nc")
    assert again.read_bytes() == run400.results_path.read_bytes() == reference.read_bytes()


def _python_lines(code: str, *args) -> list[str]:
    """The lines ``code`` prints, run by a fresh interpreter with ``args`` as its argv[1:]."""
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-c", code, *map(str, args)], capture_output=True, text=True,
                          check=True).stdout.split("\n")


def _stopping_deck(tmp_path, ball_deck):
    """Appendix C with Rec 2.1 fixed at 5 000 tau: its time integration stops after step 0
    (refused down to 1/1024 of the minimum, report 4.4.12's reduced step)."""
    deck = tmp_path / "step5.inp"
    deck.write_text(ball_deck.read_text().replace("Rec 2.1      5.0000E-02 5.0000E-03 3.0000E-01",
                                                  "Rec 2.1      5.0000E+03 5.0000E+03 5.0000E+03", 1))
    return deck


def test_run_imports_no_xarray(tmp_path, short_ball_deck):
    """A run with time steps writes its netCDF file without importing xarray, pandas or dask (issue #29: their first import cost about 2 s); its dataset and time
    history are built when first asked for."""
    code = ("import sys, pyadore\n"
            "r = pyadore.run(sys.argv[1], out=sys.argv[2], progress=False)\n"
            "assert r.results_path.is_file() and r.history_path.is_file() and r.arrays.sizes['element'] == 18\n"
            "heavy = ('xarray', 'pandas', 'dask', 'scipy.io', 'scipy.sparse')\n"
            "print(' '.join(h for h in heavy if h in sys.modules) or '-')\n"
            "print(r.dataset.sizes['time'] == len(r.time_history), 'xarray' in sys.modules)\n")
    out = _python_lines(code, short_ball_deck, tmp_path / "s.prt")
    assert out[0] == "-", out
    assert out[1] == "True True"


def test_mean_last_revolution(run400):
    ds = run400.dataset
    mean = run400.mean(last_revolutions=1)
    t0, t1 = mean.attrs["t_start"], mean.attrs["t_end"]
    assert t1 == ds["time"].values[-1] and math.isclose(mean.attrs["revolutions"], 1.0, rel_tol=1e-9)
    # the window's series: the recorded rows inside it and the row before (its start is
    # interpolated between that row and the next)
    t = ds["time"].values
    first = max(int(np.searchsorted(t, t0, side="right")) - 1, 0)
    window = ds.isel(time=slice(first, None))
    checked = 0
    for name, var in mean.data_vars.items():
        lo = window[name].min("time", skipna=True).values
        hi = window[name].max("time", skipna=True).values
        m = var.values
        x = window[name].values
        # defined where some interval of the window has two finite ends; the flash
        # temperature rise is recorded at printed steps only (docs/results.md): no such interval
        has = np.any(np.isfinite(x[1:]) & np.isfinite(x[:-1]), axis=0)
        assert np.isfinite(m[has]).all(), name
        assert np.isnan(m[~has]).all(), name
        assert np.all(m[has] >= lo[has] - 1e-12 * np.abs(lo[has])), name
        assert np.all(m[has] <= hi[has] + 1e-12 * np.abs(hi[has])), name
        checked += int(has.sum())
    assert checked > 500
    assert mean["contact_load_N"].dims == ("element", "race")
    assert np.isfinite(mean["slip_velocity_m_s"].values).all() and np.isnan(mean["temperature_rise_K"].values).all()


def test_mean_time_weighted_closed_form():
    """Time weighting against a closed form: uneven rows of a linear and a step series."""
    import xarray as xr

    from pyadore.results import time_mean

    t = np.array([0.0, 1.0, 1.5, 4.0])
    ds = xr.Dataset({"x": ("time", 2.0 * t), "y": ("time", np.array([1.0, np.nan, 3.0, 3.0]))},
                    coords={"time": t})
    m = time_mean(ds, t_start=0.5, t_end=3.0)
    assert math.isclose(float(m["x"]), 2.0 * (0.5 + 3.0) / 2)          # mean of a line = its middle value
    assert math.isclose(float(m["y"]), 3.0)   # the intervals touching the NaN are left out
    assert math.isclose(float(time_mean(ds)["x"]), 4.0)
    with pytest.raises(AdoreInputError):
        time_mean(ds, t_start=-1.0)
    with pytest.raises(AdoreInputError):
        time_mean(ds, last_revolutions=1)          # no shaft speed in this dataset


def test_mean_beyond_run(run400):
    with pytest.raises(AdoreInputError, match="revolutions"):
        run400.mean(last_revolutions=100)


def test_history_stride_option(tmp_path, short_ball_deck):
    res = pyadore.run(short_ball_deck, out=tmp_path / "s.prt", progress=False, history_stride=7)
    steps = res.dataset["step"].values.tolist()
    # every 7th step, the printed ones (every 20th) and the last (60)
    assert steps == sorted({0, *range(7, 61, 7), 20, 40, 60})
    assert res.time_history["step"].tolist() == steps


def test_no_dataset_without_steps(tmp_path, ball_deck):
    res = pyadore.run(ball_deck, steps=0, out=tmp_path / "z.prt", progress=False)
    assert res.dataset is None and res.results_path is None
    assert not (tmp_path / "z.elements.bin").exists() and not (tmp_path / "z.nc").exists()
    with pytest.raises(AdoreInputError):
        res.mean(last_revolutions=1)


def test_element_file_holds_the_print_values(run400):
    """The element file's header, its completeness line and its doubles: the contact loads
    of the last row are the dataset's, bit for bit."""
    from pyadore.results import element_path, read_element_file

    path = element_path(run400.print_path)
    values, columns, incomplete = read_element_file(path)
    assert incomplete == "" and columns[:2] == ["time_s", "step"] and values.shape == (STEPS + 1, len(columns))
    assert path.read_bytes().split(b"\n", 3)[2] == b"COMPLETE"
    k = columns.index("contact_load_N:inner:7")
    assert values[-1, k] == run400.dataset["contact_load_N"].sel(element=7, race="inner").values[-1]
    # a cut file is refused, never read as a shorter run
    cut = path.with_name("cut.elements.bin")
    cut.write_bytes(path.read_bytes()[:-8])
    with pytest.raises(AdoreInputError, match="cut short"):
        read_element_file(cut)


def test_failed_run_dataset_is_marked_incomplete(tmp_path, ball_deck):
    """A time integration that stops early (Rec 2.1 fixed at 5 000 tau): its dataset and netCDF
    file are kept with the steps done and say run_complete = 0 and why - never complete."""
    from pyadore.errors import AdoreEngineError
    from pyadore.results import read_results, results_path

    deck = _stopping_deck(tmp_path, ball_deck)
    out = tmp_path / "f.prt"
    with pytest.raises(AdoreEngineError, match="integration stopped") as info:
        pyadore.run(deck, steps=5, out=out, progress=False)
    ds = info.value.dataset
    assert ds.attrs["run_complete"] == 0 and ds.attrs["incomplete"].startswith("RUN INCOMPLETE after step 0")
    assert info.value.time_history["step"].tolist() == [0]
    back = read_results(results_path(out))
    assert back.attrs["run_complete"] == 0 and back["step"].values.tolist() == [0]


def test_sweep_time_averages_case_files_and_title(tmp_path, ball_deck):
    """A sweep of two speeds for 3.6 ms (1.2 and 0.3 shaft revolutions): each case
    keeps its print titled with its parameters, its time histories and netCDF results; the
    summary has the averages over the last revolution beside the last-step values (NaN for
    the case that covers less than one revolution)."""
    import pandas as pd

    from pyadore.results import read_results, time_mean

    frame = pyadore.sweep(ball_deck, {"inner_race_speed": [20000, 5000]}, tmp_path / "sw", duration=0.0036,
                          workers=1, progress=False)
    assert list(frame["status"]) == ["ok", "ok"]
    fast, slow = frame.iloc[0], frame.iloc[1]
    case = tmp_path / "sw" / "cases" / fast["case"]
    text = (case / "case.prt").read_text()
    assert "  Ball Bearing Test Case" not in text and "inner_race_speed=20000" in text
    ds = read_results(case / "case.nc")
    assert ds.attrs["title"] == "inner_race_speed=20000" and ds.sizes["element"] == 18
    assert pd.read_csv(case / "case.hist.csv")["time_s"].iloc[-1] == pytest.approx(0.0036, rel=1e-12)
    m = time_mean(ds, last_revolutions=1)
    assert fast["mean_total_power_loss_W"] == pytest.approx(float(m["total_power_loss_W"]), rel=1e-12)
    assert fast["mean_revolutions"] == pytest.approx(1.0)
    lo, hi = ds["total_power_loss_W"].min().item(), ds["total_power_loss_W"].max().item()
    assert lo <= fast["mean_total_power_loss_W"] <= hi
    assert 0.3 < fast["mean_cage_speed_ratio"] < 0.6 and fast["mean_max_contact_load_N"] > 0
    assert math.isnan(slow["mean_total_power_loss_W"]) and math.isnan(slow["mean_revolutions"])
    assert not math.isnan(slow["total_power_loss_W"])      # the last-step value stays


def test_failed_run_imports_no_xarray(tmp_path, ball_deck):
    """A run that fails builds neither its kept time history nor its dataset until asked
    (pandas and xarray stay unimported, as for a run that succeeds); asked, they hold the
    steps done."""
    deck = _stopping_deck(tmp_path, ball_deck)
    code = ("import sys, pyadore\n"
            "from pyadore.errors import AdoreEngineError\n"
            "try:\n"
            "    pyadore.run(sys.argv[1], steps=5, out=sys.argv[2], progress=False)\n"
            "except AdoreEngineError as exc:\n"
            "    print(' '.join(h for h in ('xarray', 'pandas') if h in sys.modules) or '-')\n"
            "    print(exc.dataset.attrs['run_complete'], len(exc.time_history), 'xarray' in sys.modules)\n")
    out = _python_lines(code, deck, tmp_path / "f.prt")
    assert out[0] == "-", out
    assert out[1] == "0 1 True", out

