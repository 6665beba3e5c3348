"""pyadore.plots and `pyadore plot`: every plotted line holds the data it claims (checked
against the print tables read independently), every figure type renders to PNG, a figure
set is one PDF page per figure, and a failed PDF leaves no file."""

from __future__ import annotations

import math
import os
import shutil
import subprocess
import warnings
from pathlib import Path

import matplotlib.image
import numpy as np
import pandas as pd
import pypdf
import pytest
from click.testing import CliRunner
from matplotlib.figure import Figure

import pyadore
from pyadore import plots
from pyadore.cli import cli
from pyadore.errors import MissingSeriesError, MissingSeriesWarning
from pyadore.printout import read_print

import probes


ROOT = Path(__file__).resolve().parent.parent
GOLDEN_BALL = ROOT / "golden" / "appendix_c_ball.prt"
GOLDEN_ROLLER = ROOT / "golden" / "appendix_d_roller.prt"
TABLE = "# slip (m/s), traction coefficient\n0.0 0.0\n0.05 0.09\n0.2 0.1\n1.0 0.085\n3.0 0.08\n"


@pytest.fixture(scope="module")
def ball_print(tmp_path_factory, ball_deck) -> Path:
    """Print file of the ball deck's step-0 run (what `make run` writes)."""
    out = tmp_path_factory.mktemp("plots") / "appendix_c_ball.prt"
    pyadore.run(ball_deck, steps=0, out=out)
    return out


@pytest.fixture(scope="module")
def roller_result(tmp_path_factory, roller_deck):
    return pyadore.run(roller_deck, steps=0, out=tmp_path_factory.mktemp("plots") / "appendix_d_roller.prt")


@pytest.fixture(scope="module")
def table_file(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("plots") / "table.txt"
    path.write_text(TABLE)
    return path


def synthetic_history(n: int = 200, elements: int = 3) -> pd.DataFrame:
    """A time history following the documented contract (docs/plots.md), as the dynamics
    will record it: smooth signals with known values."""
    t = np.linspace(0.0, 0.05, n)
    w = 2.0 * np.pi * 150.0
    cols = {
        "total_power_loss_W": 550.0 + 20.0 * np.exp(-t / 0.01),
        "exit_fluid_temp_K": 323.0 + 200.0 * t,
        "cage_y_m": -5.0e-4 * np.sin(w * t),
        "cage_z_m": 5.0e-4 * np.cos(w * t),
        "cage_whirl_velocity_m_s": 5.0e-4 * w * np.ones(n),
        "cage_radial_velocity_m_s": 1.0e-3 * np.sin(3.0 * w * t),
        "guide_clearance_m": np.full(n, 1.5e-3),
        "land1_force_N": np.maximum(0.0, 40.0 * np.sin(w * t)),
        "land2_force_N": np.maximum(0.0, -30.0 * np.sin(w * t)),
    }
    for k, body in enumerate(("re", "cage", "outer_race", "inner_race", "housing", "shaft")):
        cols[f"bulk_temp_{body}_K"] = 323.0 + (5.0 + k) * 100.0 * t
    for k, body in enumerate(("re", "cage", "outer_race", "inner_race")):
        cols[f"wear_rate_{body}_m3_s"] = 10.0 ** (-12 - k) * (1.0 + np.exp(-t / 0.01))
    for e in range(1, elements + 1):
        for r, scale in (("outer", 1.0), ("inner", 1.7)):
            cols[f"re{e}_contact_loss_{r}_W"] = scale * (16.0 + e + np.sin(w * t))
            cols[f"re{e}_contact_temp_rise_{r}_K"] = scale * (0.6 + 0.1 * np.cos(w * t))
            cols[f"re{e}_contact_temp_{r}_K"] = 323.0 + scale * 300.0 * t
        cols[f"pocket{e}_force_N"] = np.where(np.sin(w * t + e) > 0.95, 12.0 * e, 0.0)
    return pd.DataFrame(cols, index=pd.Index(t, name="time_s"))


def lines_of(ax):
    """The data lines of an axes (no legend proxies), as [(label, x, y)]."""
    return [(ln.get_label(), np.asarray(ln.get_xdata(), float), np.asarray(ln.get_ydata(), float))
            for ln in ax.get_lines()]


def expected_loads(path, step, race):
    """(position mod 360, load) of every element with both printed, sorted: read here from
    the print's table, independently of pyadore.plots."""
    table = read_print(path).step(step).table("re_contact")
    pos = table["orbital_position_deg"].to_numpy(float)
    q = table[f"contact_load_{race}_N"].to_numpy(float)
    ok = np.isfinite(pos) & np.isfinite(q)
    pairs = sorted(zip(np.mod(pos[ok], 360.0), q[ok]))
    return np.array([p for p, _ in pairs]), np.array([v for _, v in pairs])


def render(fig, path: Path) -> np.ndarray:
    """Save ``fig`` as PNG and read it back: the image must not be blank."""
    fig.savefig(path, format="png", dpi=60)
    image = matplotlib.image.imread(path)
    assert image.shape[0] > 100 and image.shape[1] > 100
    assert np.ptp(image[..., :3]) > 0.5  # not one colour
    return image


# --- type 1: load distribution -------------------------------------------------------------


def test_load_distribution_lines_are_the_printed_loads(ball_print):
    fig = plots.load_distribution(ball_print, compare=GOLDEN_BALL)
    axes = fig.get_axes()
    assert len(axes) == 2
    for ax, race in zip(axes, ("outer", "inner")):
        (label0, x0, y0), (label1, x1, y1) = lines_of(ax)
        ex, ey = expected_loads(ball_print, 0, race)
        np.testing.assert_array_equal(x0, ex)
        np.testing.assert_array_equal(y0, ey)
        gx, gy = expected_loads(GOLDEN_BALL, 0, race)
        np.testing.assert_array_equal(x1, gx)
        np.testing.assert_array_equal(y1, gy)
        assert label0 == f"{ball_print}, step 0" and label1 == f"{GOLDEN_BALL}, step 0"
        assert ax.get_ylabel() == "Contact load (N)"
        assert ax.get_title() == f"{race.capitalize()} race contact"
    assert axes[1].get_xlabel() == "Ball orbital position (deg)"
    assert "load distribution" in fig._suptitle.get_text()
    # the run has all 18 balls, the golden file leaves out the loads it did not transcribe
    assert len(lines_of(axes[0])[0][1]) == 18


def test_load_distribution_step_choice(ball_print):
    fig = plots.load_distribution(GOLDEN_BALL, step=2500, race="inner")
    (_label, x, y), = lines_of(fig.get_axes()[0])
    ex, ey = expected_loads(GOLDEN_BALL, 2500, "inner")
    np.testing.assert_array_equal(x, ex)
    np.testing.assert_array_equal(y, ey)
    assert x.max() < 360.0  # orbital positions past one revolution are wrapped
    with pytest.raises(MissingSeriesError, match=r"no step 7; its printed steps are 0, 2500"):
        plots.load_distribution(GOLDEN_BALL, step=7)
    # the compared run printed only step 0: it is drawn at its first step
    fig = plots.load_distribution(GOLDEN_BALL, step=2500, compare=ball_print, race="outer")
    labels = [ln[0] for ln in lines_of(fig.get_axes()[0])]
    assert labels == [f"{GOLDEN_BALL}, step 2500", f"{ball_print}, step 0"]


def test_load_distribution_into_given_axes(ball_print):
    fig = Figure()
    ax = fig.add_subplot()
    assert plots.load_distribution(ball_print, race="outer", ax=ax) is fig
    assert ax.get_title() == "Ball/race load distribution at the outer race contact"
    with pytest.raises(ValueError, match="needs 2 axes"):
        plots.load_distribution(ball_print, ax=ax)


# --- type 10: traction-slip curve ------------------------------------------------------------


def test_traction_curve_is_the_echoed_curve(roller_result):
    fig = plots.traction_slip(roller_result)
    (label, u, kappa), = lines_of(fig.get_axes()[0])
    echo = read_print(roller_result.print_path).echo
    a, b, c, d = (echo[f"lubrication_parameters.re_race1[{k}]"] for k in (6, 7, 8, 9))
    np.testing.assert_allclose(kappa, (a + b * u) * np.exp(-c * u) + d, rtol=1e-13, atol=1e-15)
    # the deck's Rec 10.1B: 0 at zero slip, maximum 0.1 at 0.2 m/s, 0.08 at infinite slip
    assert kappa[0] == pytest.approx(0.0, abs=1e-5)
    assert kappa.max() == pytest.approx(0.1, abs=1e-4)
    assert u[np.argmax(kappa)] == pytest.approx(0.2, abs=u[1])
    assert u[-1] == pytest.approx(2.0, rel=1e-3)  # ten times the slip of maximum traction
    assert kappa[-1] == pytest.approx(0.08, abs=2e-4)
    assert label == "RE/RACE curve"
    ax = fig.get_axes()[0]
    assert ax.get_xlabel() == "Slip velocity (m/s)" and ax.get_ylabel() == "Traction coefficient (-)"


def test_traction_table_of_the_run_and_of_a_file(roller_deck, table_file, tmp_path):
    out = tmp_path / "roller_table.prt"
    pyadore.run(roller_deck, steps=0, out=out, traction_table=table_file)
    fig = plots.traction_slip(out)
    lines = lines_of(fig.get_axes()[0])
    nodes = np.loadtxt(table_file)
    (tl, tu, tk), (hl, hu, hk), (cl, _cu, _ck) = lines
    np.testing.assert_array_equal(tu, nodes[:, 0])
    np.testing.assert_array_equal(tk, nodes[:, 1])
    assert tl == "ADRX7 table" and cl == "RE/RACE curve, replaced by the table"
    # beyond the last point the engine holds the last coefficient
    assert hu[0] == 3.0 and hu[-1] == pytest.approx(1.25 * 3.0) and np.all(hk == 0.08)
    # a bad ADRX7 listing is a located one-line error
    text = out.read_text().splitlines()
    bad = next(k for k, s in enumerate(text) if s.strip().startswith("2.00000E-01"))
    text[bad] = "  2.00000E-01  garbage"
    broken = tmp_path / "broken.prt"
    broken.write_text("\n".join(text) + "\n")
    with pytest.raises(pyadore.AdoreInputError, match=rf"broken.prt: line {bad + 1}: expected a traction-slip"):
        plots.traction_slip(broken)
    # a table file given to the figure (read by the engine's reader)
    fig = plots.traction_slip(GOLDEN_BALL, table=table_file)
    (label, u, k), _hold = lines_of(fig.get_axes()[0])
    np.testing.assert_array_equal(u, nodes[:, 0])
    assert label == f"ADRX7 table {table_file}"


def test_traction_ball_run_draws_the_ehd_model_at_its_most_loaded_ball(ball_print):
    """A model-3 run: its deck curve labelled not used, and the EHD model's coefficient at
    the most loaded ball's two contacts (load, semi-axes, film x thermal factor, contact
    temperature of the print); each point is the engine's EHD traction of that contact
    under a uniform slip, |net traction| / load, checked here at three slips with the
    other EHD wrapper (ehd_contact_traction); the coefficient vanishes with the slip."""
    from pyadore import _core
    from pyadore.printout import read_print

    fig = plots.traction_slip(ball_print)
    lines = lines_of(fig.get_axes()[0])
    assert "not used" in lines[0][0]
    ehd = [line for line in lines if line[0].startswith("EHD model 3")]
    assert [label.split()[5] for label, _u, _k in ehd] == ["outer", "inner"]
    step = read_print(ball_print).steps[0]
    contact, traction, thermal = (step.tables[n] for n in ("re_contact", "re_traction", "re_thermal"))
    k = contact["contact_load_inner_N"].astype(float).idxmax()
    lub = _core.lubricant(1, float(thermal.at[k, "contact_temp_inner_K"]))
    for (label, u, kappa), side, tag in zip(ehd, (1, -1), ("outer", "inner")):
        assert f"ball {k} {tag}" in label
        assert kappa[0] == 0.0 and np.all(kappa[1:] > 0.0)
        for i in (5, 30, 90):
            w = -u[i] / 0.09525
            res = probes.ehd_contact_traction(side, 0.0, 0.009525, 0.09525, (w, 0.0), w,
                                             float(contact.at[k, f"major_half_width_{tag}_m"]),
                                             float(contact.at[k, f"contact_load_{tag}_N"]),
                                             (lub["eta_t"], lub["alpha_t"], lub["beta_t"], lub["conductivity"]),
                                             float(traction.at[k, f"film_thickness_{tag}_m"])
                                             * float(traction.at[k, f"thermal_red_fac_{tag}"]),
                                             float(contact.at[k, f"minor_half_width_{tag}_m"]))
            assert kappa[i] == pytest.approx(abs(res["force"]) / float(contact.at[k, f"contact_load_{tag}_N"]),
                                             rel=1e-12)


def test_traction_missing_curve_is_one_line():
    with pytest.raises(MissingSeriesError) as info:
        plots.traction_slip(GOLDEN_ROLLER)
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith("figure type 10 (traction-slip curve)") and "A, B, C, D" in msg


# --- types 2-9: time histories ---------------------------------------------------------------


def test_history_from_the_golden_print_is_the_printed_values():
    h = plots.history_from_print(read_print(GOLDEN_BALL))
    assert list(h.index) == [0.0, 0.08612] and list(h["step"]) == [0, 2500]
    assert list(h["total_power_loss_W"]) == [546.4, 567.7]
    assert list(h["bulk_temp_inner_race_K"]) == [323.0, 351.4]
    assert list(h["bulk_temp_housing_K"]) == [323.0, 346.8]
    assert math.isnan(h["exit_fluid_temp_K"].iloc[0]) and h["exit_fluid_temp_K"].iloc[1] == 341.9  # 0 K = not yet
    assert list(h["re1_contact_loss_inner_W"]) == [31.65, 27.35]
    assert list(h["re1_contact_temp_outer_K"]) == [323.0, 342.8]
    assert list(h["pocket1_force_N"]) == [0.0, 0.0]
    # the cage at step 0: radial 5.9e-4 m at orbital 180 deg, i.e. at -z
    assert h["cage_y_m"].iloc[0] == pytest.approx(0.0, abs=1e-19)
    assert h["cage_z_m"].iloc[0] == pytest.approx(-5.9e-4, rel=1e-12)
    assert h["cage_whirl_velocity_m_s"].iloc[0] == pytest.approx(5.9e-4 * 9140.0 * 2 * math.pi / 60, rel=1e-12)


def test_power_loss_line_is_the_printed_total():
    fig = plots.power_loss(GOLDEN_BALL)
    ax = fig.get_axes()[0]
    (label, x, y), = lines_of(ax)
    assert list(x) == [0.0, 86.12] and list(y) == [546.4, 567.7]   # time in ms
    # two printed steps are two markers, not a line claiming the values between them
    line, = ax.get_lines()
    assert line.get_linestyle() == "None" and line.get_marker() == "o"
    assert ax.get_xlabel() == "Time (ms)" and ax.get_ylabel() == "Total power loss (W)"
    assert ax.get_title() == "Overall power loss"
    assert [t.get_text().replace("\n", " ") for t in ax.get_legend().get_texts()] == ["total power loss",
                                                                   f"{GOLDEN_BALL} (printed steps 0, 2500)"]


def test_step0_print_has_no_time_history(ball_print):
    with pytest.raises(MissingSeriesError) as info:
        plots.bulk_temperatures(ball_print)
    msg = str(info.value)
    assert msg == (f"figure type 4 (bulk temperatures vs time): {ball_print} has only step 0; the time history "
                   "needs the time integration (two or more printed steps)")


def test_missing_series_is_named():
    with pytest.raises(MissingSeriesError, match=r"figure type 8 \(cage whirl orbit\): .* no cage mass-centre "
                                                 r"position at two or more printed times \(steps 0, 2500\)"):
        plots.cage_orbit(GOLDEN_BALL)
    with pytest.warns(MissingSeriesWarning, match="no exit fluid temperature"):
        plots.bulk_temperatures(GOLDEN_BALL)


def test_every_history_type_draws_the_contract_columns(tmp_path):
    h = synthetic_history()
    t = h.index.to_numpy()
    checks = {
        plots.power_loss: [["total_power_loss_W"]],
        plots.wear_rates: [[f"wear_rate_{b}_m3_s" for b in ("re", "cage", "outer_race", "inner_race")]],
        plots.bulk_temperatures: [[f"bulk_temp_{b}_K" for b in ("re", "cage", "outer_race", "inner_race",
                                                                 "housing", "shaft")] + ["exit_fluid_temp_K"]],
        plots.race_contacts: [[f"re1_{q}_{r}_{u}" for r in ("outer", "inner")]
                              for q, u in (("contact_loss", "W"), ("contact_temp_rise", "K"), ("contact_temp", "K"))],
        plots.cage_velocities: [["cage_whirl_velocity_m_s", "cage_radial_velocity_m_s"]],
        plots.cage_land_force: [["land1_force_N", "land2_force_N"]],
        plots.pocket_force: [["pocket1_force_N"]],
    }
    for func, panels in checks.items():
        fig = func(h)
        axes = fig.get_axes()
        assert len(axes) == len(panels), func.__name__
        for ax, columns in zip(axes, panels):
            lines = lines_of(ax)
            assert len(lines) == len(columns), func.__name__
            for (_label, x, y), column in zip(lines, columns):
                np.testing.assert_array_equal(x, t * 1e3)   # ms
                np.testing.assert_array_equal(y, h[column].to_numpy())
            assert ax.get_ylabel().endswith(")"), ax.get_ylabel()  # a unit on every axis
        assert axes[-1].get_xlabel() == "Time (ms)"
        render(fig, tmp_path / f"{func.__name__}.png")
    assert plots.wear_rates(h).get_axes()[0].get_yscale() == "log"  # four decades


def test_orbit_is_to_scale_with_its_clearance_circle(tmp_path):
    h = synthetic_history()
    fig = plots.cage_orbit(h)
    ax = fig.get_axes()[0]
    (path_label, y, z), (_s, y0, z0), (_e, y1, z1), (circle_label, cy, cz), _centre = lines_of(ax)
    assert (y0[0], z0[0], y1[0], z1[0]) == (y[0], z[0], y[-1], z[-1])   # start and end markers
    np.testing.assert_allclose(y, h["cage_y_m"].to_numpy() * 1e3, rtol=1e-15)
    np.testing.assert_allclose(z, h["cage_z_m"].to_numpy() * 1e3, rtol=1e-15)
    np.testing.assert_allclose(np.hypot(cy, cz), 0.75, rtol=1e-12)  # radius = diametral clearance / 2, mm
    assert "r = 0.75 mm" in circle_label
    assert ax.get_aspect() == 1.0
    image = render(fig, tmp_path / "orbit.png")
    # equal aspect: the drawn axes box is square on the page
    bbox = ax.get_window_extent()
    assert bbox.width == pytest.approx(bbox.height, rel=0.01)
    assert image.shape[0] > 0


def test_compare_draws_the_second_run_dashed():
    h = synthetic_history()
    h2 = h.copy()
    h2["total_power_loss_W"] = h2["total_power_loss_W"] + 10.0
    fig = plots.power_loss(h, compare=h2, label="thermal off", compare_label="thermal on")
    ax = fig.get_axes()[0]
    (l0, x0, y0), (l1, x1, y1) = lines_of(ax)
    np.testing.assert_array_equal(y1, h2["total_power_loss_W"].to_numpy())
    styles = [ln.get_linestyle() for ln in ax.get_lines()]
    assert styles == ["-", "--"]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["total power loss", "thermal off", "thermal on"]


def test_a_result_carrying_its_time_history_is_plotted_from_it(roller_result):
    h = synthetic_history()
    roller_result.time_history = h
    try:
        fig = plots.power_loss(roller_result)
    finally:
        del roller_result.time_history
    (_l, x, y), = lines_of(fig.get_axes()[0])
    np.testing.assert_array_equal(y, h["total_power_loss_W"].to_numpy())
    with pytest.raises(MissingSeriesError, match="only step 0"):
        plots.power_loss(roller_result)


# --- sets, files and the command line -------------------------------------------------------


def pdf_pages(path: Path) -> int:
    """Pages of a PDF (pypdf reads the whole file: a cut file fails here); every page
    rendered by pdftoppm when it is installed."""
    reader = pypdf.PdfReader(str(path), strict=True)
    for page in reader.pages:
        assert page.get_contents() is not None
    if shutil.which("pdftoppm"):
        out = subprocess.run(["pdftoppm", "-r", "20", "-png", str(path), str(path.with_suffix(""))],
                             capture_output=True, text=True, timeout=120)
        assert out.returncode == 0, out.stderr
        assert len(list(path.parent.glob(path.stem + "-*.png"))) == len(reader.pages)
    return len(reader.pages)


def test_cli_plot_step0_run_writes_the_two_pages_it_supports(ball_print, tmp_path):
    out = tmp_path / "report.pdf"
    res = CliRunner().invoke(cli, ["plot", str(ball_print), "--set", "report", "-o", str(out)])
    assert res.exit_code == 0, res.output
    assert pdf_pages(out) == 2
    assert "figures written" in res.stdout and "figure types 1, 10" in res.stdout
    skipped = [ln for ln in res.stderr.splitlines() if ln.startswith("pyadore: skipped")]
    # the eight time-history figure types share one reason: one line
    assert len(skipped) == 1 and skipped[0].startswith("pyadore: skipped figure types 2-9 (")
    assert "only step 0" in skipped[0]
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".part")]


def test_cli_plot_golden_with_compare_as_pngs(ball_print, tmp_path):
    out = tmp_path / "figs"
    res = CliRunner().invoke(cli, ["plot", str(GOLDEN_BALL), "--compare", str(ball_print), "-o", str(out)])
    assert res.exit_code == 0, res.output
    names = sorted(p.name for p in out.iterdir())
    assert names == ["01-load-distribution.png", "02-power-loss.png", "04-bulk-temperatures.png",
                     "05-race-contacts.png", "09-pocket-force.png"]
    for p in out.iterdir():
        assert matplotlib.image.imread(p).shape[0] > 100
    # the step-0 run is compared where it has data (type 1; its step-0 values as one marker) and named
    # where it has none
    # named by its folder and file stem in legends and messages (its stem is the golden file's)
    assert (f"figure type 4 (bulk temperatures vs time): {ball_print.parent.name}/{ball_print.stem} has no exit "
            "fluid temperature at any "
            "printed time; plotted without") in res.stderr
    fig = plots.power_loss(GOLDEN_BALL, compare=ball_print)
    _golden, (_l, x, y) = lines_of(fig.get_axes()[0])
    printed = read_print(ball_print).step(0).table("performance").at["bearing", "total_power_loss_W"]
    assert list(x) == [0.0] and list(y) == [printed]
    marker = fig.get_axes()[0].get_lines()[1]
    assert marker.get_linestyle() == "None" and marker.get_marker() == "s"


def test_cli_plot_runs_a_deck(short_roller_deck, tmp_path):
    """A roller deck (Appendix D cut to 60 steps) is run and plotted: its time figures too
    (issue #26: figure types 1, 2, 4-10 but the wear rates, 3, which the roller run's
    figures 33-44 do not have; the centred cage's 6-8 say it is centred)."""
    out = tmp_path / "roller.pdf"
    res = CliRunner().invoke(cli, ["plot", str(short_roller_deck), "-o", str(out)])
    assert res.exit_code == 0, res.output
    assert "running it as a deck" in res.stderr
    assert "figure types 1, 2, 4, 5, 6, 7, 8, 9, 10" in res.output
    assert pdf_pages(out) == 9


def test_cli_plot_nothing_to_plot_exits_1(tmp_path):
    lines = GOLDEN_ROLLER.read_text().splitlines()
    step = [k for k, s in enumerate(lines) if s.startswith("  step        tau")]
    second = next(k for k in step if lines[k + 2].split()[0] != "0")
    end = next(s for s in lines if "Normal termination" in s)
    cut = tmp_path / "roller_step0.prt"
    cut.write_text("\n".join(lines[:second] + ["", end, ""]) + "\n")
    out = tmp_path / "none.pdf"
    res = CliRunner().invoke(cli, ["plot", str(cut), "--step", "3", "-o", str(out)])
    assert res.exit_code == 1
    assert "no figure of set 'report' can be made" in res.stderr
    assert "Traceback" not in res.output and not out.exists()
    res = CliRunner().invoke(cli, ["plot", str(tmp_path / "missing.prt")])
    assert res.exit_code == 1 and "cannot read" in res.stderr and "Traceback" not in res.output
    res = CliRunner().invoke(cli, ["plot", str(GOLDEN_BALL), "--set", "nope", "-o", str(out)])
    assert res.exit_code == 1 and "unknown figure set 'nope'" in res.stderr


class _Boom(Exception):
    pass


def test_a_failing_figure_leaves_no_pdf(ball_print, tmp_path):
    good = plots.load_distribution(ball_print)
    bad = Figure()
    ax = bad.add_subplot()
    line, = ax.plot([0, 1], [0, 1])

    def explode(*_args, **_kwargs):
        raise _Boom("draw failed")

    line.draw = explode
    types = plots.FIGURE_TYPES
    target = tmp_path / "report.pdf"
    with pytest.raises(_Boom):
        plots.write_pdf([(types[0], good), (types[1], bad)], target)
    assert list(tmp_path.iterdir()) == []
    # an older file of the same name is left as it was
    target.write_bytes(b"old")
    with pytest.raises(_Boom):
        plots.write_pdf([(types[0], good), (types[1], bad)], target)
    assert target.read_bytes() == b"old" and sorted(p.name for p in tmp_path.iterdir()) == ["report.pdf"]
    plots.write_pdf([(types[0], good)], target)
    assert pdf_pages(target) == 1


def test_every_type_renders_once(ball_print, roller_result, tmp_path):
    """All ten figure types to PNG: 1 and 10 from run prints, 2-9 from the contract."""
    h = synthetic_history()
    figs = {1: plots.load_distribution(ball_print), 10: plots.traction_slip(roller_result)}
    for ftype in plots.FIGURE_TYPES:
        if ftype.number not in figs:
            figs[ftype.number] = ftype.function(h)
    paths = plots.write_pngs([(t, figs[t.number]) for t in plots.FIGURE_TYPES], tmp_path)
    assert [p.name for p in paths] == [plots.png_name(t) for t in plots.FIGURE_TYPES]
    for p in paths:
        image = matplotlib.image.imread(p)
        assert image.shape[0] > 300 and np.ptp(image[..., :3]) > 0.5
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        made = plots.make_set(h)
    assert [t.number for t, _f in made.figures] == [2, 3, 4, 5, 6, 7, 8, 9]
    assert [t.number for t, _r in made.skipped] == [1, 10]
    assert os.path.exists(paths[0])


# --- a real dynamic run: the short Appendix C deck (60 steps) ---------------------------------

#: The time-history columns each figure function draws, per panel (ball element 1, two lands).
RUN_PANELS = {
    plots.power_loss: [["total_power_loss_W"]],
    plots.wear_rates: [["wear_rate_re_m3_s", "wear_rate_outer_race_m3_s", "wear_rate_inner_race_m3_s"]],
    plots.bulk_temperatures: [[f"bulk_temp_{b}_K" for b in ("re", "cage", "outer_race", "inner_race", "housing",
                                                            "shaft")]],
    plots.race_contacts: [["re1_contact_loss_outer_W", "re1_contact_loss_inner_W"],
                          ["re1_contact_temp_outer_K", "re1_contact_temp_inner_K"]],
    plots.cage_velocities: [["cage_whirl_velocity_m_s", "cage_radial_velocity_m_s"]],
    plots.cage_land_force: [["land1_force_N", "land2_force_N"]],
    plots.pocket_force: [["pocket1_force_N"]],
}


@pytest.fixture(scope="module")
def short_run(tmp_path_factory, short_ball_deck):
    """The short Appendix C run (time integration, cage contacts on, thermal model off):
    its Result, with the print and its plot-data file beside it."""
    return pyadore.run(short_ball_deck, out=tmp_path_factory.mktemp("plots_run") / "appendix_c_short.prt")


def test_short_run_lines_are_its_time_history(short_run):
    """Every line of types 2-7 and 9, drawn from the print file (which finds its plot-data
    file), is a column of the run's own time history: x = time in ms, y = the column; every
    column is drawn (series equal at every instant share one line naming them all)."""
    h = short_run.time_history
    assert h is not None and len(h) == 61 and list(h["step"]) == list(range(61))
    t_ms = h.index.to_numpy(float) * 1e3
    for func, panels in RUN_PANELS.items():
        fig = func(short_run.print_path)
        axes = fig.get_axes()
        assert len(axes) == len(panels), func.__name__
        for ax, columns in zip(axes, panels):
            lines = lines_of(ax)
            matched = set()
            for column in columns:
                y_expected = h[column].to_numpy(float)
                hits = [k for k, (_l, x, y) in enumerate(lines)
                        if np.array_equal(x, t_ms) and np.array_equal(y, y_expected)]
                assert hits, f"{func.__name__}: no line is {column}"
                matched.update(hits)
            assert matched == set(range(len(lines))), f"{func.__name__}: a line that is no column"
            assert ax.get_ylabel().endswith(")")
        assert axes[-1].get_xlabel() == "Time (ms)"
        title = fig._suptitle.get_text() if fig._suptitle else axes[0].get_title()
        assert title.endswith("with no thermal interactions"), title  # the print: thermal model off


def test_short_run_constant_and_equal_series_are_said(short_run):
    """Thermal model off: the six bulk temperatures are one line naming them (equal) and a
    note beside the axes says they are constant and why; equal land forces share a line."""
    h = short_run.time_history
    fig = plots.bulk_temperatures(short_run)
    ax = fig.get_axes()[0]
    (label, _x, y), = lines_of(ax)
    assert np.all(y == h["bulk_temp_re_K"].iloc[0])
    assert label == "rolling elements (mean), cage, outer race, inner race, housing, shaft (equal)"
    note = " ".join(t.get_text() for t in ax.texts).replace("\n", " ")
    assert f"constant, {h['bulk_temp_re_K'].iloc[0]:.6g} K, throughout the run" in note
    assert "thermal model is off" in note
    lands = lines_of(plots.cage_land_force(short_run).get_axes()[0])
    if np.array_equal(h["land1_force_N"].to_numpy(), h["land2_force_N"].to_numpy()):
        assert [ln[0] for ln in lands] == ["guide land 1, guide land 2 (equal)"]
    else:
        assert [ln[0] for ln in lands] == ["guide land 1", "guide land 2"]
    # a varying series has no note
    assert not plots.power_loss(short_run).get_axes()[0].texts


def test_short_run_orbit_to_scale(short_run, tmp_path):
    h = short_run.time_history
    fig = plots.cage_orbit(short_run)
    ax = fig.get_axes()[0]
    (_p, y, z), _start, _end, (circle, cy, cz), _centre = lines_of(ax)
    np.testing.assert_array_equal(y, h["cage_y_m"].to_numpy() * 1e3)
    np.testing.assert_array_equal(z, h["cage_z_m"].to_numpy() * 1e3)
    np.testing.assert_allclose(np.hypot(cy, cz), 0.5e3 * h["guide_clearance_m"].iloc[-1], rtol=1e-12)
    assert ax.get_aspect() == 1.0
    render(fig, tmp_path / "orbit.png")
    bbox = ax.get_window_extent()
    assert bbox.width == pytest.approx(bbox.height, rel=0.01)


def test_short_run_every_type_renders_and_the_pdf_is_whole(short_run, tmp_path):
    """The run's report set: all ten figure types, each rendered to PNG, and one PDF page
    each (pdftoppm renders every page when installed); the PDF gets the usual permissions."""
    made = plots.make_set(short_run.print_path)
    assert [t.number for t, _f in made.figures] == list(range(1, 11))
    for path in plots.write_pngs(made.figures, tmp_path / "png"):
        image = matplotlib.image.imread(path)
        assert image.shape[0] > 300 and np.ptp(image[..., :3]) > 0.5
    out = tmp_path / "report.pdf"
    res = CliRunner().invoke(cli, ["plot", str(short_run.print_path), "--set", "report", "-o", str(out)])
    assert res.exit_code == 0, res.output
    assert pdf_pages(out) == 10
    umask = os.umask(0)
    os.umask(umask)
    assert out.stat().st_mode & 0o777 == 0o666 & ~umask


def test_compare_with_golden_draws_its_printed_steps_as_markers(short_run):
    """The golden file (steps 0 and 2500) overlaid on a run: markers at its printed times,
    no line between them; a series it prints at one step only is one marker."""
    fig = plots.bulk_temperatures(short_run, compare=GOLDEN_BALL)
    ax = fig.get_axes()[0]
    golden = [ln for ln in ax.get_lines() if ln.get_linestyle() == "None"]
    assert golden and all(ln.get_marker() == "s" for ln in golden)
    exit_fluid = [ln for ln in golden if list(ln.get_ydata()) == [341.9]]
    assert len(exit_fluid) == 1 and list(exit_fluid[0].get_xdata()) == [86.12]   # step 2500 only (ms)
    legend = [t.get_text().replace("\n", " ") for t in ax.get_legend().get_texts()]
    assert f"{GOLDEN_BALL} (printed steps 0, 2500)" in legend
    # the run itself: one line
    assert len([ln for ln in ax.get_lines() if ln.get_linestyle() == "-"]) == 1


def test_display_thinning_keeps_the_envelope():
    """More than DISPLAY_POINTS points: a subset of the points, in order, holding the
    first, last, smallest and largest (display only; the table is not changed)."""
    from pyadore.plots.timeplot import DISPLAY_POINTS, display_indices

    rng = np.random.default_rng(3)
    y = np.cumsum(rng.normal(size=30_000))
    y[12_345] = 1e3
    keep = display_indices(y)
    assert len(keep) <= DISPLAY_POINTS and np.all(np.diff(keep) > 0)
    assert {0, len(y) - 1, int(np.argmin(y)), 12_345} <= set(keep.tolist())
    np.testing.assert_array_equal(display_indices(y[:100]), np.arange(100))
    h = synthetic_history(n=9_000)
    fig = plots.power_loss(h)
    (_l, x, yy), = lines_of(fig.get_axes()[0])
    assert len(x) <= DISPLAY_POINTS
    t = h.index.to_numpy() * 1e3
    idx = np.searchsorted(t, x)
    np.testing.assert_array_equal(t[idx], x)
    np.testing.assert_array_equal(h["total_power_loss_W"].to_numpy()[idx], yy)


def test_short_run_centred_cage_is_said(tmp_path, short_ball_deck):
    """A run's cage held centred (`cage="centred"`, its DOF constraint, listed in the print;
    the default is the deck's Rec 3.3, a free cage for Appendix C): the velocity and orbit
    figures say so beside the axes instead of a flat line and a point left unexplained."""
    short_run = pyadore.run(short_ball_deck, out=tmp_path / "centred.prt", cage="centred")
    h = short_run.time_history
    h = h[h["step"] > 0]   # step 0's row is the print's quasi-static cage, off the axis (docs/plots.md)
    assert (h["cage_y_m"] == 0).all() and (h["cage_whirl_velocity_m_s"] == 0).all()
    for fig in (plots.cage_velocities(short_run), plots.cage_orbit(short_run)):
        note = " ".join(t.get_text() for a in fig.get_axes() for t in a.texts).replace("\n", " ")
        assert "the cage is centred in this run (translation and tilt constrained, report 4.4.6)" in note
