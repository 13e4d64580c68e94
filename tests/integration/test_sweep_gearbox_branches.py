"""Nonlinear branch sweeps of a gearbox case: every speed of the branch at its own predicted steady temperatures
(thermogear.sweep.branches, issue 28)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import thermogear.simulation  # noqa: F401  (registers the "gearbox" temperature model)
from thermogear.case import load_case
from thermogear.simulation import Simulation
from thermogear.sweep import Study
from thermogear.sweep.branches import branch_study

CASE = Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"
SPEEDS = [500.0, 1000.0, 1400.0]
pytestmark = pytest.mark.filterwarnings("ignore")  # the case's own extrapolation warnings (Sainsot fit, viscosity)


@pytest.fixture(scope="module")
def case():
    return load_case(CASE)


@pytest.fixture(scope="module")
def branches(case):
    return branch_study(Study.define(case, {"speed_rpm": SPEEDS}, model="thermal"), "both", workers=1)


def test_each_speed_is_the_case_made_at_that_speed(case, branches):
    # the gearbox case's temperatures follow the speed: each point equals the periodic response of the case made at
    # its speed (its own steady temperatures), solved on its own; the orbit is unique here (no coexistence), so the
    # branch's Newton, seeded by the neighbour, lands on the same orbit: agreement to the shooting tolerance
    for speed in SPEEDS:
        alone = Simulation(case.with_changes(**{"operating.speed_rpm": speed}), "thermal").run(method="periodic")
        assert alone.metrics["branch"] == "unique"
        for direction in ("up", "down"):
            kv = float(branches["kv"].sel(direction=direction, model="thermal", speed_rpm=speed))
            assert kv == pytest.approx(float(alone.metrics["kv"]), rel=1e-7), (speed, direction)


def test_the_mesh_follows_the_temperatures(branches):
    # hotter at higher speed (more loss): E(T) falls, so the natural frequency of each speed's mesh falls
    natural = branches["natural_frequency_hz"].sel(model="thermal").values
    assert np.all(np.isfinite(natural)) and np.all(np.diff(natural) < 0.0)
    assert set(branches["response"].values.ravel().astype(str)) == {"periodic"}


def test_a_speed_whose_temperatures_jam_is_marked_and_the_others_computed(case):
    # 25 μm of backlash at 20 °C: the steady state at 1400 rpm (pinion about 97 °C with the paper's friction law,
    # which runs hotter than the loss model's default, Schlenk's) closes it by about 3 μm, 500 rpm leaves about 16 μm
    # (30 μm jammed with one shaft node, whose gears ran 5 K hotter; now 1400 rpm would leave 1.9 μm)
    tight = case.with_changes(**{"gears.backlash_normal_um": 25.0, "gearbox.friction_model": "paper"})
    data = branch_study(Study.define(tight, {"speed_rpm": [500.0, 1400.0]}, model="thermal"), "both", workers=1)
    jammed = data["jammed"].sel(model="thermal").values
    assert jammed.tolist() == [0, 1]
    hot = data.sel(speed_rpm=1400.0, model="thermal")
    assert np.all(np.isnan(hot["kv"].values)) and set(hot["response"].values.astype(str)) == {"jammed"}
    cold = data.sel(speed_rpm=500.0, model="thermal")
    assert np.all(np.isfinite(cold["kv"].values)) and np.all(cold["converged"].values == 1)
