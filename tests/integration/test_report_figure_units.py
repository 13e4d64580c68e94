"""Fig. 11 of a report (start-up and steady velocity) reads at a glance: both panels in the unit their numbers are
in, and one colour per model in both panels and the legend (issue 24, "reading the results")."""

from __future__ import annotations

import warnings
from types import SimpleNamespace

import numpy as np
import pytest
from matplotlib.colors import to_hex

from thermogear.case import load_case
from thermogear.report import figures
from thermogear.simulation import Simulation

COLOURS = {"elastic": to_hex("tab:blue"), "thermal": to_hex("tab:red")}


@pytest.fixture(scope="module", params=["linear", "nonlinear"])
def evaluation(request):
    """The responses fig. 9/11 need, for the paper's linear mesh and the default nonlinear one of a user's case
    (6 periods from rest: what the start-up panel shows)."""
    case = load_case("luo2019").with_changes(**{"dynamics.mesh": request.param, "dynamics.transient_periods": 6})
    responses, transients = {}, {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for model in ("elastic", "thermal"):
            simulation = Simulation(case, model)
            responses[model], transients[model] = simulation.run(), simulation.run("transient")
    return SimpleNamespace(responses=responses, transients=transients)


def _model(label: str) -> str:
    return next(model for model in COLOURS if label.startswith(model))


def test_fig11_panels_are_both_in_mm_per_s(evaluation):
    figure = figures.fig11(evaluation)
    start_up, steady = figure.axes
    for ax in (start_up, steady):
        assert "[mm/s]" in ax.get_ylabel()
    # the steady velocity in mm/s is the velocity of the response in m/s times 1000 (no panel left in m/s)
    peak = max(float(np.max(np.abs(r.velocity))) for r in evaluation.responses.values())
    drawn = max(float(np.max(np.abs(line.get_ydata()))) for line in steady.get_lines())
    assert drawn == pytest.approx(1e3 * peak, rel=1e-9)
    # the start-up from rest reaches at least the steady amplitude, in the same unit (not 1000 times less)
    assert max(float(np.max(np.abs(line.get_ydata()))) for line in start_up.get_lines()) >= 0.5 * drawn


@pytest.mark.parametrize("draw", [figures.fig9, figures.fig11])
def test_each_model_has_one_colour_in_both_panels_and_the_legend(evaluation, draw, tmp_path):
    figure = draw(evaluation)
    for ax in figure.axes:
        for line in ax.get_lines():
            if not line.get_label().startswith("_"):
                assert to_hex(line.get_color()) == COLOURS[_model(line.get_label())], line.get_label()
    figures.legends_below(figure)
    (legend,) = figure.legends
    labels = [text.get_text() for text in legend.get_texts()]
    assert any("from rest" in label for label in labels)  # the start-up lines are in the legend too
    for handle, label in zip(legend.legend_handles, labels):
        assert to_hex(handle.get_color()) == COLOURS[_model(label)], label
    import matplotlib.pyplot as plt

    plt.close(figure)
