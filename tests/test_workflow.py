"""Issue #29's workflow items: one option vocabulary (Deck.set by field name, pyadore.run of
a Deck with overrides, sweep ranges, `plot --history-element/--steps`), `diff` of two runs
(brief, neutral names, text fields), figure options (window, limits, one figure, labels,
one line per skip reason, readable sweep axes), the diametral clearance of a ball deck."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

import pyadore
from pyadore.cli import cli
from pyadore.deck import DeckFieldError, read_deck
from pyadore.errors import AdoreInputError
from pyadore.printout import read_print
from pyadore.sweeps.grid import SweepError, make_cases, parse_vary

ROOT = Path(__file__).resolve().parent.parent
RADIAL = ROOT / "decks" / "examples" / "deep_groove_radial.inp"
GOLDEN_BALL = ROOT / "golden" / "appendix_c_ball.prt"


# -- Deck.set / lookup by field name ------------------------------------------------------------
def test_deck_set_by_field_name_as_lookup_takes_it(ball_deck):
    deck = read_deck(ball_deck)
    deck.set("inner_race_speed", 15000)
    assert deck.lookup("inner_race_speed") == 15000.0 and isinstance(deck.lookup("inner_race_speed"), float)
    deck.set("9.1.1", "applied_force_x", 500.0)           # the record-id form still works
    assert deck.get("9.1.1", "applied_force_x") == 500.0
    with pytest.raises(DeckFieldError, match="did you mean inner_race_speed"):
        deck.set("inner_race_sped", 1.0)
    with pytest.raises(KeyError):                          # DeckFieldError is a KeyError too
        deck.set("no_such_field_at_all", 1.0)


def test_deck_set_needs_rec_slash_field_where_several_records_have_it(ball_deck):
    deck = read_deck(ball_deck)
    with pytest.raises(DeckFieldError, match="several records.*7.2.1/guide_land_clearance"):
        deck.set("guide_land_clearance", 1e-4)
    deck.set("7.2.2/guide_land_clearance", 1.5e-4)
    assert deck.lookup("7.2.2/guide_land_clearance") == 1.5e-4
    assert deck.get("7.2.1", "guide_land_clearance") != 1.5e-4


# -- diametral clearance ----------------------------------------------------------------------
def test_diametral_clearance_sets_the_free_contact_angle():
    """docs/examples.md's numbers: A = (0.53 + 0.52 - 1) 11.5 mm; 10 um -> 7.5614 deg,
    50 um -> 16.957 deg (cos alpha0 = 1 - P_d / (2 A), by hand)."""
    deck = read_deck(RADIAL)
    a = (0.53 + 0.52 - 1.0) * 11.5e-3
    for clearance, angle in ((10e-6, 7.5614), (50e-6, 16.957), (0.0, 0.0)):
        deck.set("diametral_clearance", clearance)
        assert deck.get("5A", "free_contact_angle") == pytest.approx(angle, abs=1e-3)
        back = 2 * a * (1 - math.cos(math.radians(deck.get("5A", "free_contact_angle"))))
        assert deck.lookup("diametral_clearance") == pytest.approx(back, rel=1e-12)
        assert deck.lookup("diametral_clearance") == pytest.approx(clearance, rel=1e-4, abs=1e-12)
    with pytest.raises(AdoreInputError, match="must be >= 0"):
        deck.set("diametral_clearance", -1e-6)


def test_diametral_clearance_of_a_roller_deck_is_refused(roller_deck):
    deck = read_deck(roller_deck)
    with pytest.raises(AdoreInputError, match="ball bearing's field"):
        deck.set("diametral_clearance", 1e-5)
    assert deck.lookup("diametral_clearance") is None


# -- sweep value ranges -------------------------------------------------------------------------
def test_sweep_range_start_stop_count(ball_deck):
    deck = read_deck(ball_deck)
    assert parse_vary("inner_race_speed=10000:25000:4", deck).values == (10000.0, 15000.0, 20000.0, 25000.0)
    assert parse_vary("inner_race_speed=1000,10000:20000:3", deck).values == (1000.0, 10000.0, 15000.0, 20000.0)
    # 0.1 steps land on round numbers, both ends included
    assert parse_vary("applied_force_x=0.1:0.5:5", deck).values == (0.1, 0.2, 0.3, 0.4, 0.5)
    for bad, why in (("inner_race_speed=1:2", "START:STOP:COUNT"), ("inner_race_speed=1:2:1", "COUNT >= 2"),
                     ("inner_race_speed=a:2:3", "numbers"), ("n_rolling_elements=10:15:3", "integer")):
        with pytest.raises(SweepError, match=why):
            parse_vary(bad, deck)


def test_sweep_varies_the_diametral_clearance():
    deck = read_deck(RADIAL)
    varied = parse_vary("diametral_clearance=0:50e-6:3", deck)
    assert varied.values == (0.0, 25e-6, 50e-6) and varied.unit == "m"
    from pyadore.sweeps.grid import case_deck_text

    cases = make_cases([varied])
    text = case_deck_text(RADIAL.read_text(), str(RADIAL), [varied], cases[2])
    from pyadore.deck import parse_text

    case, problems = parse_text(text, "case")
    assert not problems and case.get("5A", "free_contact_angle") == pytest.approx(16.957, abs=1e-3)
    with pytest.raises(SweepError, match="same deck field"):
        make_cases([varied, parse_vary("free_contact_angle=1,2,3", deck)])


def test_case_decks_from_one_parsed_base_equal_those_parsed_per_case():
    """A sweep parses its base deck once; each case's values are set and then restored, so every
    case deck (a derived field and a plain one among the varied) equals the one built from the text."""
    from pyadore.deck import parse_text
    from pyadore.sweeps.grid import case_deck_text

    text = RADIAL.read_text()
    deck, problems = parse_text(text, str(RADIAL))
    assert not problems
    varied = [parse_vary("diametral_clearance=0:50e-6:3", deck), parse_vary("inner_race_speed=1000,9000", deck)]
    cases = make_cases(varied)
    shared = [case_deck_text(text, str(RADIAL), varied, c, base=deck) for c in cases]
    assert shared == [case_deck_text(text, str(RADIAL), varied, c) for c in cases]
    assert len(set(shared)) == len(cases)
    from pyadore.deck.writer import format_deck

    assert format_deck(deck) == text            # the base deck is as read after the cases


# -- pyadore.run of a Deck, overrides ------------------------------------------------------------
def test_run_takes_a_deck_object_and_overrides(ball_deck, tmp_path):
    deck = read_deck(ball_deck)
    res = pyadore.run(deck, steps=0, out=tmp_path / "a.prt", overrides={"inner_race_speed": 15000})
    assert res.deck_path == Path(ball_deck)
    assert deck.lookup("inner_race_speed") == 20000.0       # the Deck given is not changed
    listing = res.text.split("ADVANCED DYNAMICS")[0]
    assert "1.5000E+04" in listing and "2.0000E+04" not in listing.split("Rec 9.1")[0].split("Rec 5A")[-1]
    base = pyadore.run(ball_deck, steps=0, out=tmp_path / "b.prt")
    p15, p20 = read_print(res.print_path), read_print(base.print_path)
    # the faster shaft loses more power: the override reached the engine
    assert p15.steps[0].tables != {} and res.text != base.text
    with pytest.raises(AdoreInputError, match="did you mean"):
        pyadore.run(ball_deck, steps=0, out=tmp_path / "c.prt", overrides={"inner_race_sped": 1.0})
    with pytest.raises(AdoreInputError, match="a real field"):
        pyadore.run(ball_deck, steps=0, out=tmp_path / "c.prt", overrides={"inner_race_speed": "fast"})
    with pytest.raises(AdoreInputError, match="deck file path or a pyadore.deck.Deck"):
        pyadore.run(12345, steps=0)
    del p20


# -- plot options -----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def short_print(tmp_path_factory, short_ball_deck):
    """The short Appendix C run's print with its plot-data file."""
    out = tmp_path_factory.mktemp("wf") / "short.prt"
    pyadore.run(short_ball_deck, out=out, progress=False)
    return out


def test_plot_element_is_a_deprecated_alias_of_history_element(short_print, tmp_path):
    res = CliRunner().invoke(cli, ["plot", str(short_print), "--figure", "5", "--element", "1",
                                   "-o", str(tmp_path / "a.png")])
    assert res.exit_code == 0, res.output
    assert "--element is deprecated; use --history-element" in res.stderr
    res = CliRunner().invoke(cli, ["plot", str(short_print), "--figure", "5", "--element", "1",
                                   "--history-element", "2", "-o", str(tmp_path / "a.png")])
    assert res.exit_code == 1 and "disagree" in res.stderr
    res = CliRunner().invoke(cli, ["plot", str(short_print), "--figure", "race-contacts",
                                   "--history-element", "1", "-o", str(tmp_path / "b.png")])
    assert res.exit_code == 0, res.output
    assert "deprecated" not in res.stderr and (tmp_path / "b.png").stat().st_size > 10000


def test_plot_one_figure_window_limits_and_labels(short_print, tmp_path):
    from pyadore.plots import make_set

    full = make_set(short_print, figures=[2]).figures[0][1]
    t_end = full.axes[0].lines[0].get_xdata()[-1]
    made = make_set(short_print, figures=["power-loss"], window=(0.5e-3 * t_end, None), ylim=(0, 900),
                    label="variant A")
    assert [t.number for t, _f in made.figures] == [2]
    ax = made.figures[0][1].axes[0]
    x = ax.lines[0].get_xdata()
    assert x.min() >= 0.5 * t_end - 1e-9 and x.max() == pytest.approx(t_end)
    assert ax.get_ylim() == (0, 900)
    res = CliRunner().invoke(cli, ["plot", str(short_print), "--figure", "2", "--compare", str(short_print),
                                   "--label", "base", "--compare-label", "variant", "--window", f"{0.5e-3 * t_end:.6g}:",
                                   "-o", str(tmp_path / "p.png")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "p.png").is_file() and "figure type 2" in res.stdout
    res = CliRunner().invoke(cli, ["plot", str(short_print), "--figure", "2", "--t-start", "0.002",
                                   "--t-end", "0.001", "-o", str(tmp_path / "q.png")])
    assert res.exit_code == 1 and "high end must be above" in res.stderr and "Traceback" not in res.output
    res = CliRunner().invoke(cli, ["plot", str(short_print), "--figure", "11", "-o", str(tmp_path / "r.png")])
    assert res.exit_code == 1 and "unknown figure '11'" in res.stderr
    res = CliRunner().invoke(cli, ["plot", str(short_print), "-o", str(tmp_path / "all.png")])
    assert res.exit_code == 1 and "choose it with --figure" in res.stderr


def test_plot_default_labels_are_file_names_not_paths(short_print, tmp_path):
    from pyadore.cli import _run_labels

    assert _run_labels(short_print, None) == ("short", None)
    assert _run_labels(Path("out/appendix_c_ball.prt"), GOLDEN_BALL) == ("out/appendix_c_ball",
                                                                          "golden/appendix_c_ball")


def test_plot_a_deck_with_steps(short_ball_deck, tmp_path):
    res = CliRunner().invoke(cli, ["plot", str(short_ball_deck), "--steps", "20", "--figure", "2",
                                   "-o", str(tmp_path / "p.png")])
    assert res.exit_code == 0, res.output
    assert "running it as a deck" in res.stderr and (tmp_path / "p.png").is_file()


# -- diff of two runs -------------------------------------------------------------------------------
def test_diff_two_runs_brief_neutral_names_and_text_fields(ball_deck, tmp_path):
    a = pyadore.run(ball_deck, steps=0, out=tmp_path / "base.prt").print_path
    deck = read_deck(ball_deck)
    b = pyadore.run(deck, steps=0, out=tmp_path / "faster.prt", overrides={"inner_race_speed": 22000}).print_path
    text = b.read_text()
    first = text.index("ADVANCED DYNAMICS")
    # a different run title in b (the banner's run identification line)
    from pyadore.printout import read_print as rp

    title = rp(a).echo["banner.run_id"]
    assert title and title in text[first:]
    b.write_text(text[:first] + text[first:].replace(title, "FASTER VARIANT".ljust(len(title))[:len(title)], 1))
    assert rp(b).echo["banner.run_id"] != title
    res = CliRunner().invoke(cli, ["diff", str(a), str(b), "--brief"])
    assert res.exit_code == 1, res.output
    out = res.stdout
    assert out.startswith(f"base: {a}\nfaster: {b}\n")
    assert "golden" not in out.replace(str(ROOT / "golden" / "tolerances.toml"), "")
    assert "text fields that differ:\n  banner.run_id:" in out
    assert "inf" not in out                       # no text field as an infinite relative error
    lines = out.splitlines()
    assert len(lines) < 45 and "more column(s)" in out
    rows = [ln for ln in lines if ln.startswith("  ") and "/" in ln.split()[1]]
    assert rows and all(int(r.split()[1].split("/")[0]) > 0 for r in rows)
    # identical numbers, another title: within, exit 0 (the run title never fails)
    c = tmp_path / "retitled.prt"
    ta = a.read_text()
    fa = ta.index("ADVANCED DYNAMICS")
    c.write_text(ta[:fa] + ta[fa:].replace(title, "RETITLED".ljust(len(title))[:len(title)], 1))
    res = CliRunner().invoke(cli, ["diff", str(a), str(c)])
    assert res.exit_code == 0, res.output
    assert "base:" in res.stdout and "retitled:" in res.stdout and "text fields that differ" in res.stdout


def test_diff_against_golden_keeps_the_golden_names(tmp_path):
    copy = tmp_path / "golden_copy.prt"
    shutil.copy(GOLDEN_BALL, copy)
    res = CliRunner().invoke(cli, ["diff", str(copy), str(GOLDEN_BALL), "--brief"])
    assert res.exit_code == 0, res.output
    assert res.stdout.startswith(f"run: {copy}\ngolden: {GOLDEN_BALL}\n")
    res = CliRunner().invoke(cli, ["diff", str(copy), str(GOLDEN_BALL), "--brief", "--format", "json"])
    assert res.exit_code == 2 and "Traceback" not in res.output


# -- sweep axes ------------------------------------------------------------------------------------
def test_sweep_axes_in_scaled_si_units_with_field_names():
    import pandas as pd

    from pyadore.plots.sweep import plot_sweep, si_scale

    assert si_scale("Pa", [1.5e9, 2.9e9]) == (1e9, "GPa")
    assert si_scale("m", [0.0, 10e-6, 50e-6]) == (1e-6, "\u00b5m")
    assert si_scale("N", [1000.0, 4000.0]) == (1.0, "N")
    assert si_scale("rpm", [10000.0, 25000.0]) == (1.0, "rpm")
    frame = pd.DataFrame({"case": ["c1", "c2", "c3"], "inner_race_speed": [1e4, 2e4, 3e4],
                          "status": ["ok"] * 3, "max_contact_stress_Pa": [1.51e9, 1.53e9, 1.56e9]})
    fig = plot_sweep(frame, x="inner_race_speed", y="max_contact_stress_Pa")
    ax = fig.axes[0]
    assert ax.get_ylabel() == "Largest contact stress (GPa)"
    assert ax.get_xlabel() == "Inner race speed (rpm)"
    assert list(ax.lines[0].get_ydata()) == pytest.approx([1.51, 1.53, 1.56])
    fig.canvas.draw()
    assert ax.yaxis.get_major_formatter().get_offset() == ""


# -- imports on demand --------------------------------------------------------------------------------
def test_run_steps_0_imports_no_table_or_figure_library(ball_deck, tmp_path):
    """`pyadore run --steps 0` needs the engine, click and pyadore's own modules: the engine's
    shared object is called without numpy (pyadore/_core/lite.py), and pandas, matplotlib,
    xarray and scipy are imported only by what uses them (the start-up time is measured in
    bench/run_bench.py, `startup`)."""
    import subprocess
    import sys

    res = subprocess.run([sys.executable, "-X", "importtime", "-m", "pyadore", "run", str(ball_deck), "--steps", "0",
                          "-o", str(tmp_path / "x.prt")], capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr[-2000:]
    imported = {line.split("|")[-1].strip() for line in res.stderr.splitlines() if line.startswith("import time:")}
    assert "pyadore._core.lite" in imported and "pyadore.api" in imported  # the trace is the run's
    assert (tmp_path / "x.prt").is_file()
    heavy = sorted(m for m in imported if m.split(".")[0] in ("pandas", "matplotlib", "xarray", "scipy", "numpy"))
    assert heavy == []
    assert "importlib.metadata" not in imported                           # --version only when asked


def test_run_command_ends_without_the_interpreter_clean_up_with_its_files_complete(short_ball_deck, tmp_path):
    """`pyadore run` ends by os._exit once its output is flushed (pyadore/__main__.py,
    _exit_now; docs/sweeps.md "Scaling, eighteenth session"): its print, plot-data and netCDF files are those
    of the same run through the API, byte for byte, its stdout lines are all there through a
    pipe, and a refused run still exits 1 with its message."""
    import subprocess
    import sys

    out = tmp_path / "cli.prt"
    res = subprocess.run([sys.executable, "-m", "pyadore", "run", str(short_ball_deck), "-o", str(out)],
                         capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr[-2000:]
    api = pyadore.run(short_ball_deck, out=tmp_path / "api.prt", progress=False)
    assert res.stdout.splitlines() == [f"print file written: {out}",
                                       f"plot-data file written: {out.with_suffix('.hist.csv')}",
                                       f"results written: {out.with_suffix('.nc')} (netCDF; docs/results.md)"]
    assert out.read_bytes() == api.print_path.read_bytes()
    assert out.with_suffix(".hist.csv").read_bytes() == api.history_path.read_bytes()
    cli_nc, api_nc = out.with_suffix(".nc").read_bytes(), api.results_path.read_bytes()
    assert len(cli_nc) == len(api_nc) > 1000
    import xarray as xr

    with xr.open_dataset(out.with_suffix(".nc")) as a, xr.open_dataset(api.results_path) as b:
        assert a.equals(b)
    bad = subprocess.run([sys.executable, "-m", "pyadore", "run", str(tmp_path / "nope.inp"), "-o",
                          str(tmp_path / "n.prt")], capture_output=True, text=True, timeout=600)
    assert bad.returncode == 1 and "pyadore: error:" in bad.stderr


def test_sweep_takes_a_deck_object_and_a_range(tmp_path):
    deck = read_deck(RADIAL)
    deck.set("applied_force_z", 2000.0)
    frame = pyadore.sweep(deck, {"diametral_clearance": "0:20e-6:2"}, tmp_path / "s", steps=0, workers=1,
                          progress=False)
    assert list(frame["status"]) == ["ok", "ok"] and list(frame["diametral_clearance"]) == [0.0, 20e-6]
    case = read_deck(tmp_path / "s" / "cases" / "case_0002" / "deck.inp")
    assert case.lookup("applied_force_z") == 2000.0          # the Deck's own change is in every case
    assert case.lookup("diametral_clearance") == pytest.approx(20e-6, rel=1e-4)
    # a larger clearance at the same radial load: fewer balls carry it, the largest load grows
    assert frame["max_contact_load_N"].iloc[1] > frame["max_contact_load_N"].iloc[0]
