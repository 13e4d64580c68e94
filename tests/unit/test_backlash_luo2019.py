"""The backlash solver on a real gear problem: the luo2019 pair (elastic model), with a normal backlash of 100 μm.

The solver is gear-agnostic: it takes the arrays of ``Simulation(case, "elastic").problem`` (1024 intervals per
mesh period, two pair slots) and adds the backlash; no deviation (the elastic model has none).
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermogear.dynamics import periodic_steady_state
from thermogear.dynamics.backlash.backlash_metrics import orbit_metrics
from thermogear.dynamics.backlash.backlash_periodic import backlash_transient, periodic_response
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.response import compute_metrics
from thermogear.errors import ModelLimitError

BACKLASH = 100e-6  # [m]


def luo2019_problem(case, speed_rpm=None):
    from thermogear.simulation import Simulation

    if speed_rpm is not None:
        case = case.with_changes(**{"operating.speed_rpm": speed_rpm})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the case's own extrapolation warnings are tested elsewhere
        return Simulation(case, "elastic").problem


def test_luo2019_at_2000_rpm_equals_the_linear_solution(luo2019):
    linear = luo2019_problem(luo2019)
    problem = BacklashMeshProblem.from_linear(linear, backlash=BACKLASH)
    orbit = periodic_response(problem, samples_per_interval=4)
    reference = periodic_steady_state(linear, samples_per_interval=4)
    assert orbit.response == "periodic" and orbit.converged and orbit.switch_times.size == 0
    grid = orbit.history.kind == 0
    scale = np.max(np.abs(reference.displacement))
    # both solvers are exact: they differ by rounding only; 1e-6 relative is the brief's bound
    np.testing.assert_allclose(orbit.history.displacement[grid], reference.displacement, rtol=0, atol=1e-6 * scale)
    fine = periodic_steady_state(linear, samples_per_interval=64)
    linear_metrics = compute_metrics(linear, fine.time, fine.displacement, fine.velocity, fine.interval,
                                     fine.multipliers)
    metrics = orbit_metrics(orbit)
    # 64 samples per interval of ω·h ≈ 0.05 rad leave the linear peak low by (0.05/64)²/8 ≈ 1e-7 of the swing
    assert metrics["kv"] == pytest.approx(linear_metrics["kv"], rel=1e-6)
    assert metrics["max_mesh_force"] == pytest.approx(linear_metrics["max_system_load"], rel=1e-6)
    assert metrics["contact_loss_fraction"] == 0.0 and not metrics["back_side_contact"]


def test_luo2019_near_primary_resonance_loses_contact_and_stays_finite(luo2019):
    linear = luo2019_problem(luo2019, 13000.0)
    assert 0.9 < linear.frequency_ratio < 1.05  # near the primary resonance (0.149 at 2000 rpm)
    problem = BacklashMeshProblem.from_linear(linear, backlash=BACKLASH)
    orbit = periodic_response(problem)
    metrics = orbit_metrics(orbit)
    assert orbit.converged and orbit.response in ("periodic", "subharmonic")
    assert orbit.largest_multiplier < 1.0
    assert metrics["contact_loss_fraction"] > 0.0
    for name in ("kv", "max_mesh_force", "dte_peak_to_peak", "dte_rms", "dte_mean"):
        assert np.isfinite(metrics[name])
    # the teeth cannot pull: without back-flank contact (none here) the mesh force stays >= 0 (to rounding)
    assert not metrics["back_side_contact"]
    assert metrics["min_mesh_force"] >= -1e-9 * metrics["static_load"]
    # the linear model has no steady state here at all (a Floquet multiplier > 1: ModelLimitError), the backlash
    # bounds the motion
    with pytest.raises(ModelLimitError, match="parametric instability"):
        periodic_steady_state(linear)
    # the exact transient from rest (Luo & Li start) is finite and settles near the orbit's swing
    history = backlash_transient(problem, 60, samples_per_interval=1)
    assert np.all(np.isfinite(history.displacement))
    last = history.time >= 59 * problem.period
    assert np.ptp(history.displacement[last]) == pytest.approx(metrics["dte_peak_to_peak"], rel=0.05)
