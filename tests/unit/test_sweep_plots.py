"""Study plots read at a glance: axes scaled to the valid points, the others marked at the edge, both models of a
branch study, resonance speeds marked with labels that do not overlap (constructed datasets: exact values)."""

from __future__ import annotations

import itertools

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from thermogear.sweep.branch_plots import plot_branches  # noqa: E402
from thermogear.sweep.plots import plot_speed_response  # noqa: E402

TEETH = 27
NATURAL = {"elastic": 6000.0, "thermal": 5600.0}  # [Hz]: n_1 = 13 333 and 12 444 rpm, 7 % apart


def _linear_dataset():
    import xarray as xr

    speeds = np.linspace(3000.0, 16000.0, 131)
    kv = np.stack([1.0 + 0.3 * np.sin(speeds / 2000.0), 1.1 + 0.3 * np.cos(speeds / 2000.0)])
    contact_loss = np.zeros_like(kv, dtype=np.int8)
    near = (speeds > 12000.0) & (speeds < 13800.0)
    kv[:, near] = 600.0  # the linear model's Kv where the teeth separate: hundreds
    contact_loss[:, near] = 1
    shape = kv.shape
    return xr.Dataset(
        {"kv": (("model", "speed_rpm"), kv), "stable": (("model", "speed_rpm"), np.ones(shape, dtype=np.int8)),
         "contact_loss": (("model", "speed_rpm"), contact_loss),
         "jammed": (("model", "speed_rpm"), np.zeros(shape, dtype=np.int8)),
         "natural_frequency_hz": (("model", "speed_rpm"), np.array([[NATURAL["elastic"]], [NATURAL["thermal"]]])
                                  * np.ones(shape)),
         "mesh_frequency_hz": ("speed_rpm", TEETH * speeds / 60.0)},
        coords={"model": ["elastic", "thermal"], "speed_rpm": speeds})


def _labels_overlap(figure) -> list[tuple[str, str]]:
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    texts = [t for ax in figure.axes for t in ax.texts if t.get_text().startswith("j=")]
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in texts]
    return [(a, b) for (a, box_a), (b, box_b) in itertools.combinations(boxes, 2) if box_a.overlaps(box_b)]


def test_the_linear_speed_plot_is_scaled_to_the_valid_points():
    dataset = _linear_dataset()
    figure = plot_speed_response(dataset, quantities=("kv",))
    try:
        axis = figure.axes[0]
        low, high = axis.get_ylim()
        # valid Kv spans 0.7–1.4; the limits add 8 % of that range: Kv = 600 would flatten the curves to zero
        assert 0.6 < low < 0.75 and 1.39 < high < 1.5
        edge = [line for line in axis.get_lines() if line.get_marker() == "^"]
        assert edge and all(np.allclose(line.get_ydata(), high) for line in edge)  # marked on the upper edge
        invalid = int((dataset["contact_loss"] == 1).sum())  # 17 speeds × 2 models
        assert sum(len(line.get_xdata()) for line in edge) == invalid  # every invalid point, on the edge
        assert not _labels_overlap(figure)
        texts = {t.get_text() for t in axis.texts}
        assert {"j=1 e", "j=1 t", "j=2 e", "j=2 t"} <= texts
    finally:
        plt.close(figure)


def _branch_dataset():
    import xarray as xr

    speeds = np.linspace(5000.0, 16000.0, 45)
    low = 20e-6 + 1e-9 * (speeds - 5000.0) / 10.0
    dte = np.empty((2, 2, speeds.size))
    dte[0] = low
    dte[1] = low
    dte[1, :, (speeds > 9000) & (speeds < 12000)] *= 4.0  # the down branch rides high over a band
    converged = np.ones_like(dte)
    converged[0, 1, 10] = 0.0  # one non-periodic point of the thermal up sweep, its value far off
    dte[0, 1, 10] = 5e-3
    dims = ("direction", "model", "speed_rpm")
    return xr.Dataset(
        {"dte_peak_to_peak": (dims, dte), "kv": (dims, 1.0 + dte / 20e-6 * 0.2), "converged": (dims, converged),
         "contact_loss_fraction": (dims, np.where(dte > 30e-6, 0.4, 0.0)),
         "back_side_contact": (dims, np.zeros_like(dte)),
         "natural_frequency_hz": (("model", "speed_rpm"), np.array([[NATURAL["elastic"]], [NATURAL["thermal"]]])
                                  * np.ones((2, speeds.size))),
         "mesh_frequency_hz": ("speed_rpm", TEETH * speeds / 60.0)},
        coords={"direction": ["up", "down"], "model": ["elastic", "thermal"], "speed_rpm": speeds},
        attrs={"case": "constructed", "load": "constant torque"})


def test_the_branch_plot_draws_both_models_and_their_resonances():
    figure = plot_branches(_branch_dataset())
    try:
        axis = figure.axes[0]
        labels = {line.get_label() for line in axis.get_lines()}
        assert {"elastic, speed up", "elastic, speed down", "thermal, speed up", "thermal, speed down"} <= labels
        vertical = sorted(float(line.get_xdata()[0]) for line in axis.get_lines()
                          if line.get_linestyle() == ":" and len(line.get_xdata()) == 2)
        expected = sorted(60.0 * f / (TEETH * j) for f in NATURAL.values() for j in (1, 2))
        in_range = [speed for speed in expected if 5000.0 <= speed <= 16000.0]
        assert vertical == pytest.approx(in_range, rel=1e-12)
        # scaled to the converged points (20–84 μm): the non-periodic 5000 μm sits on the edge, not in the range
        assert axis.get_ylim()[1] < 100.0
        assert not _labels_overlap(figure)
    finally:
        plt.close(figure)
