"""Numba RK4 transient from rest and the solve_ivp reference."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics import (MeshDynamicsProblem, largest_safe_step, periodic_steady_state, reference_solve_ivp,
                                 transient_from_rest, transient_python)
from thermogear.errors import CaseError, ModelLimitError

FACE_WIDTH = 0.025


def luo_problem(mesh_frequency: float = 900.0, single_damping: float = 3.41e3, double_damping: float = 2.40e3,
                **changes: float) -> MeshDynamicsProblem:
    """physics.md §1.6 magnitudes (same helper as in test_dynamics_periodic.py; test files are independent)."""
    values = dict(mass=0.359, mesh_period=1.0 / mesh_frequency, contact_ratio=1.6,
                  single_stiffness=1.32e10 * FACE_WIDTH, double_stiffness=2.25e10 * FACE_WIDTH,
                  single_damping=single_damping, double_damping=double_damping, force=10036.7,
                  face_width=FACE_WIDTH)
    values.update(changes)
    return MeshDynamicsProblem.square_wave(**values)


def test_transient_starts_at_rest_and_converges_to_periodic_orbit():
    problem = luo_problem()
    history = transient_from_rest(problem, periods=12)
    assert history.displacement[0] == 0.0 and history.velocity[0] == 0.0
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    time, x, _, _ = history.last_period()
    x_rk = np.interp(orbit.time, time, x)  # fine RK4 grid (|λ|h <= 0.05): interpolation error ~1e-8 relative
    assert np.max(np.abs(x_rk - orbit.displacement)) / np.max(np.abs(orbit.displacement)) < 1e-6
    change = history.convergence()
    assert change[0] > 1e-2 and change[-1] < 1e-10  # a real start-up that dies out


def test_three_solvers_agree_on_the_node_states():
    problem = luo_problem()
    orbit = periodic_steady_state(problem, samples_per_interval=4)
    rk4 = transient_from_rest(problem, periods=10, steps_per_interval=4 * 150)
    reference = reference_solve_ivp(problem, periods=10, rtol=1e-11, samples_per_interval=4)
    x_rk = rk4.last_period()[1][:: rk4.steps_per_interval // 4]
    x_ref = reference.last_period()[1]
    scale = np.max(np.abs(orbit.displacement))
    assert np.max(np.abs(x_ref - orbit.displacement)) / scale < 1e-6
    assert np.max(np.abs(x_rk - orbit.displacement)) / scale < 1e-6
    assert np.max(np.abs(x_rk - x_ref)) / scale < 1e-6


def test_rk4_is_fourth_order():
    problem = luo_problem()
    # node states (the reference sampled once per interval) over 2 periods from rest
    exact = reference_solve_ivp(problem, periods=2, rtol=1e-13, samples_per_interval=1).displacement
    errors = []
    for steps in (100, 200, 400):
        history = transient_from_rest(problem, 2, steps)
        errors.append(np.max(np.abs(history.displacement[::steps] - exact)))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(np.abs(orders - 4.0) < 0.3), orders


def test_python_loop_is_the_same_computation():
    problem = luo_problem()
    compiled = transient_from_rest(problem, periods=2, steps_per_interval=60)
    plain = transient_python(problem, periods=2, steps_per_interval=60)
    np.testing.assert_allclose(plain.displacement, compiled.displacement, rtol=1e-12, atol=1e-18)
    np.testing.assert_array_equal(plain.interval, compiled.interval)
    assert plain.method != compiled.method


def test_too_coarse_step_is_refused_with_the_largest_safe_step():
    problem = luo_problem()
    with pytest.raises(CaseError, match="largest safe step") as error:
        transient_from_rest(problem, periods=2, steps_per_interval=3)
    assert f"{largest_safe_step(problem):.4g}" in str(error.value)
    needed = int(np.ceil(np.max(problem.durations) / largest_safe_step(problem)))
    transient_from_rest(problem, periods=1, steps_per_interval=needed)  # the stated limit is accepted


def test_steps_aligned_to_nodes():
    problem = luo_problem()
    history = transient_from_rest(problem, periods=3, steps_per_interval=50)
    node_samples = np.flatnonzero(np.diff(history.interval) != 0) + 1
    expected = (np.arange(3)[:, None] * problem.period + problem.nodes[None, :-1]).ravel()[1:]
    np.testing.assert_allclose(history.time[node_samples], expected, rtol=1e-12)


def test_unstable_transient_grows_and_overflow_is_not_returned():
    base = luo_problem()
    problem = luo_problem(mesh_frequency=2.0 * base.natural_frequency, single_damping=300.0,
                          double_damping=300.0)
    growth = transient_from_rest(problem, periods=40).period_start_states()
    assert abs(growth[-1, 0] - growth[-2, 0]) > abs(growth[2, 0] - growth[1, 0])
    with pytest.raises(ModelLimitError, match="unstable"):
        transient_from_rest(problem, periods=6000, steps_per_interval=20)


@pytest.mark.parametrize(("periods", "steps"), [(0, None), (2.5, None), (2, 0)])
def test_bad_run_settings_are_refused(periods, steps):
    with pytest.raises(CaseError):
        transient_from_rest(luo_problem(), periods=periods, steps_per_interval=steps)
