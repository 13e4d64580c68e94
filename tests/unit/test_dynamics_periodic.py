"""Exact periodic steady state of the piecewise-constant mesh equation (physics.md §11)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import expm

from thermogear.dynamics import (MeshDynamicsProblem, evaluate_orbit, floquet_multipliers, periodic_steady_state,
                                 periodic_steady_state_batch, reference_solve_ivp)
from thermogear.dynamics.periodic import _transition, monodromy
from thermogear.errors import CaseError, ModelLimitError

FACE_WIDTH = 0.025


def luo_problem(mesh_frequency: float = 900.0, single_damping: float = 3.41e3, double_damping: float = 2.40e3,
                **changes: float) -> MeshDynamicsProblem:
    """physics.md §1.6 magnitudes: me = 0.359 kg, k = 1.32e10 / 2.25e10 N/m² × 25 mm, F_n = 10036.7 N."""
    values = dict(mass=0.359, mesh_period=1.0 / mesh_frequency, contact_ratio=1.6,
                  single_stiffness=1.32e10 * FACE_WIDTH, double_stiffness=2.25e10 * FACE_WIDTH,
                  single_damping=single_damping, double_damping=double_damping, force=10036.7,
                  face_width=FACE_WIDTH)
    values.update(changes)
    return MeshDynamicsProblem.square_wave(**values)


@pytest.mark.parametrize(("stiffness", "damping", "mass", "t"), [
    (5e8, 3.4e3, 0.359, 1e-4),      # under-damped, the gear case
    (5e8, 0.0, 0.359, 3e-4),        # undamped
    (1.0, 10.0, 1.0, 2.0),          # over-damped
    (1.0, 2.0, 1.0, 1.5),           # critically damped (series branch)
    (1.0, 2.0 + 1e-7, 1.0, 1.5),    # next to critical
    (1.0, 2.0 - 1e-7, 1.0, 1.5),
])
def test_closed_form_transition_matches_scipy_expm(stiffness, damping, mass, t):
    expected = expm(np.array([[0.0, 1.0], [-stiffness / mass, -damping / mass]]) * t)
    got = np.array(_transition(stiffness, damping, mass, t)).reshape(2, 2)
    np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())


def test_constant_stiffness_orbit_is_the_static_equilibrium():
    problem = MeshDynamicsProblem(mass=0.3, nodes=[0.0, 4e-4, 1e-3], stiffness=[5e8, 5e8], damping=[3e3, 3e3],
                                  force=1e4, contact_count=[1, 1])
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    np.testing.assert_allclose(orbit.displacement, 1e4 / 5e8, rtol=1e-12)
    np.testing.assert_allclose(orbit.velocity, 0.0, atol=1e-12)


def test_orbit_is_periodic_and_continuous():
    orbit = periodic_steady_state(luo_problem(), samples_per_interval=32)
    scale = np.abs(orbit.displacement).max()
    assert abs(orbit.displacement[-1] - orbit.displacement[0]) < 1e-12 * scale
    assert abs(orbit.velocity[-1] - orbit.velocity[0]) < 1e-12 * np.abs(orbit.velocity).max()
    assert orbit.time[0] == 0.0 and orbit.time[-1] == pytest.approx(1 / 900)
    assert orbit.stable and np.all(orbit.multipliers_abs < 1)


def test_multiplier_product_obeys_liouville():
    """det M = exp(−∫ c/me dτ) over one period (Liouville's formula): an independent check of the monodromy."""
    problem = luo_problem()
    matrix, _ = monodromy(problem)
    expected = np.exp(-np.dot(problem.damping, problem.durations) / problem.mass)
    assert np.linalg.det(matrix) == pytest.approx(expected, rel=1e-10)
    assert np.prod(np.abs(floquet_multipliers(problem))) == pytest.approx(expected, rel=1e-10)


def test_periodic_agrees_with_converged_solve_ivp_reference():
    problem = luo_problem()
    orbit = periodic_steady_state(problem, samples_per_interval=16)
    # the slowest mode decays by |μ|max ≈ 0.013 per period: 8 periods leave ~1e-15 of the start-up
    reference = reference_solve_ivp(problem, periods=8, rtol=1e-11, samples_per_interval=16)
    _, x, v, _ = reference.last_period()
    assert np.max(np.abs(x - orbit.displacement)) / np.max(np.abs(orbit.displacement)) < 1e-6
    assert np.max(np.abs(v - orbit.velocity)) / np.max(np.abs(orbit.velocity)) < 1e-6


def test_evaluate_orbit_reproduces_samples():
    problem = luo_problem()
    orbit = periodic_steady_state(problem, samples_per_interval=16)
    x, v = evaluate_orbit(problem, orbit.initial_state, orbit.time)
    np.testing.assert_allclose(x, orbit.displacement, rtol=1e-12)
    np.testing.assert_allclose(v, orbit.velocity, rtol=1e-10, atol=1e-12)


def test_parametric_resonance_is_refused_with_multipliers():
    """Mesh frequency near twice the natural frequency, light damping: principal parametric resonance."""
    problem = luo_problem(mesh_frequency=2.0 * luo_problem().natural_frequency, single_damping=300.0,
                          double_damping=300.0)
    assert np.abs(floquet_multipliers(problem)).max() > 1.0
    with pytest.raises(ModelLimitError, match="parametric instability.*multiplier"):
        periodic_steady_state(problem)


def test_undamped_problem_is_not_returned_as_orbit():
    """Without damping |μ| = 1: no attracting periodic orbit, refused rather than returned."""
    with pytest.raises(ModelLimitError):
        periodic_steady_state(luo_problem(single_damping=0.0, double_damping=0.0))


def test_batch_matches_single_solves_and_flags_instability():
    fn = luo_problem().natural_frequency
    problems = [luo_problem(), luo_problem(single_damping=5.7e3, double_damping=4.0e3),
                luo_problem(single_stiffness=1.0e10 * FACE_WIDTH),
                luo_problem(single_damping=300.0, double_damping=300.0)]
    unstable = luo_problem(mesh_frequency=2.0 * fn, single_damping=300.0, double_damping=300.0)
    stiffness = np.array([p.stiffness for p in problems] + [unstable.stiffness])
    damping = np.array([p.damping for p in problems] + [unstable.damping])
    # a batch shares one node grid; the unstable point has another mesh period, so it is a batch of its own
    x0, v0, moduli = periodic_steady_state_batch(0.359, problems[0].nodes, stiffness[:-1], damping[:-1], 10036.7)
    for j, problem in enumerate(problems):
        orbit = periodic_steady_state(problem)
        assert x0[j] == pytest.approx(orbit.initial_state[0], rel=1e-12)
        assert v0[j] == pytest.approx(orbit.initial_state[1], rel=1e-9, abs=1e-15)
        np.testing.assert_allclose(moduli[j], orbit.multipliers_abs, rtol=1e-9)
    x0, v0, moduli = periodic_steady_state_batch(0.359, unstable.nodes, stiffness[-1:], damping[-1:], [10036.7])
    assert moduli[0, 0] > 1.0 and np.isnan(x0[0])


@pytest.mark.parametrize(("changes", "key"), [
    ({"mass": 0.0}, "mass"),
    ({"mass": float("nan")}, "mass"),
    ({"nodes": [0.0, 2e-4, 1e-4]}, "nodes"),
    ({"nodes": [1e-5, 4e-4, 1e-3]}, "nodes[0]"),
    ({"stiffness": [5e8, 0.0]}, "stiffness"),
    ({"stiffness": [5e8, np.nan]}, "stiffness"),
    ({"stiffness": [5e8]}, "stiffness"),
    ({"damping": [-1.0, 3e3]}, "damping"),
    ({"force": -1.0}, "force"),
    ({"contact_count": [2, 0]}, "contact_count"),
    ({"pair_stiffness": [[2e8, 5e8], [2e8, 0.0]]}, "pair_stiffness"),
    ({"face_width": 0.0}, "face_width"),
])
def test_bad_problem_input_is_refused_with_key(changes, key):
    values = dict(mass=0.3, nodes=[0.0, 4e-4, 1e-3], stiffness=[8e8, 5e8], damping=[3e3, 3e3], force=1e4,
                  contact_count=[2, 1])
    values.update(changes)
    with pytest.raises(CaseError) as error:
        MeshDynamicsProblem(**values)
    assert error.value.key == key


def test_natural_frequency_and_ratio_from_mean_stiffness():
    problem = luo_problem()
    mean_k = (0.6 * 2.25e10 + 0.4 * 1.32e10) * FACE_WIDTH
    assert problem.natural_frequency == pytest.approx(np.sqrt(mean_k / 0.359) / (2 * np.pi), rel=1e-12)
    assert problem.frequency_ratio == pytest.approx(900.0 / problem.natural_frequency, rel=1e-12)
