"""Figure types 2-5: the bearing's performance against time (report figures 16-19, 24-27,
33-35, 39-41): total power loss, time-averaged wear rates, bulk temperatures and one
rolling element's race contacts.  Data: the time-history table of
:mod:`pyadore.plots.history` (a run's own, or the printed steps of its print file).
"""

from __future__ import annotations

from . import style
from .history import BULK_BODIES, RACES, WEAR_BODIES
from .timeplot import Panel, history_figure, runs_and_histories


def thermal_reason(source, what: str) -> str:
    """Why the temperatures of a run stay constant, from its print's run conditions: the
    thermal model was off ("" when the print does not say so)."""
    if not getattr(source, "thermal_off", False):
        return ""
    if what == "bulk":
        return "the thermal model is off in this run (bulk temperatures fixed at the initial ones, deck Rec 2.7)"
    return "the thermal model is off in this run (contact temperature = the initial bulk temperature)"


@style.styled
def power_loss(source, *, compare=None, label: str | None = None, compare_label: str | None = None, ax=None):
    """Figure type 2: total power loss (W) of the bearing vs time (s) (report figs 16, 24,
    33, 39; column total_power_loss_W).  ``compare`` overlays a second run, dashed."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    panels = [Panel("Total power loss", "W", (("total_power_loss_W", "total power loss"),))]
    return history_figure("figure type 2 (total power loss vs time)", "total power loss",
                          "Overall power loss", panels, pairs, ax)


@style.styled
def wear_rates(source, *, compare=None, label: str | None = None, compare_label: str | None = None, ax=None):
    """Figure type 3: time-averaged wear rates (m**3/s) of the rolling elements (mean),
    cage and races vs time (s) (report figs 17, 25; columns wear_rate_<body>_m3_s); a
    logarithmic axis when the rates are positive and span more than two decades."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    series = tuple((f"wear_rate_{b}_m3_s", name) for b, name in WEAR_BODIES.items())
    panels = [Panel("Wear rate averaged from t = 0", "m**3/s", series, log=True, noun="wear rate")]
    return history_figure("figure type 3 (time-averaged wear rates vs time)", "time-averaged wear rate",
                          "Time-averaged wear rates", panels, pairs, ax)


@style.styled
def bulk_temperatures(source, *, compare=None, label: str | None = None, compare_label: str | None = None,
                      ax=None):
    """Figure type 4: bulk temperatures (K) of the rolling elements (mean), cage, races,
    housing and shaft, with the exit fluid temperature, vs time (s) (report figs 18, 26,
    34, 40; columns bulk_temp_<body>_K, exit_fluid_temp_K)."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    series = tuple((f"bulk_temp_{b}_K", name) for b, name in BULK_BODIES.items())
    series += (("exit_fluid_temp_K", "exit fluid temperature"),)
    panels = [Panel("Temperature", "K", series, constant_reason=thermal_reason(pairs[0][0], "bulk"))]
    return history_figure("figure type 4 (bulk temperatures vs time)", "bulk temperature",
                          "Computed bulk temperatures", panels, pairs, ax)


@style.styled
def race_contacts(source, *, element: int = 1, compare=None, label: str | None = None,
                  compare_label: str | None = None, ax=None):
    """Figure type 5: one rolling element's outer and inner race contacts vs time (s):
    contact loss (W), contact temperature rise (K) and contact temperature (K), three
    panels (report figs 19, 27, 35, 41; columns re<element>_contact_loss_<race>_W,
    re<element>_contact_temp_rise_<race>_K, re<element>_contact_temp_<race>_K).  ``ax``:
    three axes."""
    pairs = runs_and_histories(source, compare, label, compare_label)
    word = pairs[0][0].element_word()

    def panel(quantity, what, unit, reason=""):
        return Panel(quantity, unit, tuple((f"re{element}_{what}_{r}_{unit}", f"{r} race") for r in RACES),
                     constant_reason=reason)

    panels = [panel("Contact loss", "contact_loss", "W"),
              panel("Contact temperature rise", "contact_temp_rise", "K"),
              panel("Contact temperature", "contact_temp", "K", thermal_reason(pairs[0][0], "contact"))]
    return history_figure(f"figure type 5 ({word} {element} race contacts vs time)",
                          f"race contact data of {word} {element}",
                          f"Typical {word}/race interaction ({word} {element})", panels, pairs, ax)
