"""Interference diagram: crossings of the mesh harmonics with the modes found by root-finding equal the closed form
n_c = 60·f_i/(j·z₁) where the modes do not move with speed; with the gyroscopic terms they do move and every crossing
still lies on its harmonic line."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from drivetrain_builders import geared_pair

from thermogear.drivetrain.campbell import campbell_diagram
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.errors import CaseError

TEETH = 20


@pytest.fixture(scope="module")
def assembled():
    return geared_pair(elements=2, bearing_damping=200.0).assemble()


def test_crossings_equal_the_closed_form_without_gyroscopic_terms(assembled):
    still = replace(assembled, gyroscopic=np.zeros_like(assembled.gyroscopic), _cache={})
    modes = drivetrain_modes(still, damped=True, count=6)
    speeds = np.linspace(100.0, 30000.0, 7)
    diagram = campbell_diagram(still, speeds, TEETH, harmonics=(1, 2), mode_count=6)
    expected = sorted(60.0 * f / (j * TEETH) for j in (1, 2) for f in modes.frequencies_hz
                      if speeds[0] < 60.0 * f / (j * TEETH) < speeds[-1])
    found = [crossing.speed_rpm for crossing in diagram.crossings]
    # Brent to xtol 3e-5 rpm on a function that is exactly linear in n here: 1e-9 relative is rounding only
    assert len(found) == len(expected) > 3
    assert found == pytest.approx(expected, rel=1e-9)
    assert np.ptp(diagram.frequencies_hz, axis=0).max() < 1e-9 * diagram.frequencies_hz.max()


def test_gyroscopic_terms_move_the_modes_and_crossings_lie_on_their_lines(assembled):
    speeds = np.linspace(100.0, 30000.0, 9)
    diagram = campbell_diagram(assembled, speeds, TEETH, harmonics=(1, 2, 3), mode_count=12)
    # the lateral modes split into forward and backward whirl as the shafts spin (Friswell et al. 2010 §3.6):
    # some frequency moves by more than 0.1 % over the range (measured: several %)
    assert (np.ptp(diagram.frequencies_hz, axis=0) / diagram.frequencies_hz.min(axis=0)).max() > 1e-3
    for crossing in diagram.crossings:
        line = crossing.harmonic * TEETH * crossing.speed_rpm / 60.0
        assert crossing.frequency_hz == pytest.approx(line, rel=1e-8)
        assert 0.0 <= crossing.mesh_share <= 1.0
    assert any(crossing.mesh_share > 0.5 for crossing in diagram.crossings)  # the mesh mode is met
    assert all(c.mesh_share >= 0.1 for c in diagram.tooth_critical(0.1))


def test_plot_returns_a_figure(assembled):
    import matplotlib

    matplotlib.use("Agg")
    diagram = campbell_diagram(assembled, np.linspace(100.0, 30000.0, 4), TEETH, mode_count=4)
    figure = diagram.plot_campbell()
    assert figure.axes and figure.axes[0].get_xlabel() == "pinion speed [rpm]"


def test_bad_input_is_named(assembled):
    with pytest.raises(CaseError, match="speeds_rpm"):
        campbell_diagram(assembled, np.array([100.0, 50.0]), TEETH)
    with pytest.raises(CaseError, match="teeth"):
        campbell_diagram(assembled, np.array([100.0, 500.0]), 0)
    with pytest.raises(CaseError, match="harmonics"):
        campbell_diagram(assembled, np.array([100.0, 500.0]), TEETH, harmonics=(0,))
