"""The sweep's fused kernel: its series transition against the closed form, and its other branches (the damping
force in the loads, a sample count that is not a power of two, speeds where the series does not hold) against one
Simulation per point."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.dynamics.linear_algebra.transition_2x2 import transition_2x2
from thermogear.dynamics.periodic_orbits.periodic_batch_metrics import _SERIES_DECAY, _SERIES_U, _step_transitions
from thermogear.sweep.study import Study

from sweep_paths import assert_fast_path_equals_simulation


def test_series_transition_equals_the_closed_form_to_rounding():
    # me = 1, h = 1: u = σ² − k spans the series range on both sides (under- and over-damped), σh up to its limit
    mass = np.ones(1)
    rows = []
    for sigma in np.linspace(0.0, _SERIES_DECAY, 9):
        for u in np.linspace(-_SERIES_U, _SERIES_U, 41):
            stiffness = sigma * sigma - u
            if stiffness <= 0.0:
                continue
            out = [np.empty(1) for _ in range(4)]
            _step_transitions(stiffness, 2.0 * sigma, mass, np.ones(1), 1.0, *out)
            rows.append((np.array([o[0] for o in out]), np.array(transition_2x2(stiffness, 2.0 * sigma, 1.0, 1.0))))
    assert len(rows) > 150  # k > 0 leaves out part of the over-damped side
    for series, closed in rows:
        # both are within a few ulp of expm(A h) (entries of order 1: |u|, σh <= 1/4): 1e-14 absolute is ~50 ulp
        assert np.all(np.abs(series - closed) <= 1e-14), (series, closed)


def test_outside_the_series_range_the_closed_form_is_taken():
    mass = np.ones(3)
    factor = np.array([1.0, 1.0, 1.0])
    out = [np.empty(3) for _ in range(4)]
    _step_transitions(4.0, 0.1, mass, factor, 1.0, *out)  # u = 0.0025 − 4: far outside, cos/sin of 2 rad
    expected = transition_2x2(4.0, 0.1, 1.0, 1.0)
    for entry, value in zip(out, expected):
        assert np.all(entry == value)  # the same function, bit for bit


@pytest.mark.parametrize("changes", [{"dynamics.include_damping_force": True},
                                     {"dynamics.samples_per_interval": 3},
                                     {"dynamics.include_damping_force": True, "dynamics.samples_per_interval": 5}])
def test_other_kernel_branches_equal_one_simulation_per_point(changes):
    case = load_case("luo2019").with_changes(**changes)
    study = Study.define(case, ["torque_nm=250,400", "speed_rpm=1500,4000,9000"], model="both", chunk_points=64)
    assert_fast_path_equals_simulation(study)


def test_very_low_and_high_speeds_equal_one_simulation_per_point():
    # at 20 rpm a sub-step spans a large part of a natural period (|u| > 1/4: the closed form), at 20 000 rpm a
    # tiny one (the series)
    study = Study.define(load_case("luo2019"), ["speed_rpm=20,300,20000"], model="both", chunk_points=64)
    fast = assert_fast_path_equals_simulation(study)
    assert np.all(fast["stable"] == 1), "unstable points would leave the comparison to NaN"


def test_the_kernel_compiles_the_metric_formulas_the_python_path_calls():
    # one definition (issue 33): the kernel's load and DTE statistics are the functions of metric_formulas, compiled
    from thermogear.dynamics.periodic_orbits import periodic_batch_metrics as kernel
    from thermogear.dynamics.results import metric_formulas
    from thermogear.dynamics.results.spectra import time_mean_and_rms

    assert kernel._mesh_load.py_func is metric_formulas.mesh_load
    assert kernel._mean_and_rms.py_func is metric_formulas.mean_and_rms
    # the kernel's one pass (moments about the first sample) and the Python path's two passes (about the mean) give
    # one mean and RMS; a signal far from zero checks that the shift keeps the cancellation small
    time = np.linspace(0.0, 1e-3, 801)
    signal = 3e-5 + 2e-6 * np.sin(2e3 * np.pi * time) + 5e-7 * np.cos(6e3 * np.pi * time)
    shifted = signal - signal[0]
    one_pass = kernel._mean_and_rms(signal[0], np.trapezoid(shifted, time), np.trapezoid(shifted**2, time), 1e-3)
    two_pass = time_mean_and_rms(time, signal)
    assert one_pass == pytest.approx(two_pass, rel=1e-12)
    assert two_pass[1] == pytest.approx(np.sqrt((2e-6**2 + 5e-7**2) / 2.0), rel=1e-6)  # the analytic RMS
    assert kernel._mesh_load(2.0, 3.0, 0.5, -4.0) == metric_formulas.mesh_load(2.0, 3.0, 0.5, -4.0) == 4.0
