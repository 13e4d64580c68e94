"""Fixed-step RK4 transients (numba and plain Python) and the SciPy reference, against closed forms and the exact
periodic orbit. Same synthetic scale as test_dynamics_periodic: me = 1 kg, f_n = 100 Hz, w = 100 N."""

from __future__ import annotations

import re

import numpy as np
import pytest

from thermogear.dynamics import (MeshDynamicsProblem, largest_safe_step, periodic_steady_state, reference_solve_ivp,
                                 transient_from_rest, transient_python)
from thermogear.dynamics.transients.transient import DEFAULT_OMEGA_STEP, default_steps_per_interval
from thermogear.errors import ProblemError

MASS = 1.0
OMEGA = 2.0 * np.pi * 100.0
STIFFNESS = MASS * OMEGA**2
FORCE = 100.0
STATIC = FORCE / STIFFNESS


def constant_problem(damping_ratio: float, period: float = 2e-3, intervals: int = 3) -> MeshDynamicsProblem:
    nodes = np.linspace(0.0, period, intervals + 1)
    damping = 2.0 * damping_ratio * MASS * OMEGA
    return MeshDynamicsProblem(mass=MASS, nodes=nodes, stiffness=np.full(intervals, STIFFNESS),
                               damping=np.full(intervals, damping), force=FORCE,
                               contact_count=np.ones(intervals, dtype=int))


def square_wave(frequency_ratio: float = 0.3, damping_ratio: float = 0.05,
                stiffness_ratio: float = 1.5) -> MeshDynamicsProblem:
    damping = 2.0 * damping_ratio * MASS * OMEGA
    return MeshDynamicsProblem.square_wave(
        mass=MASS, mesh_period=1.0 / (100.0 * frequency_ratio), contact_ratio=1.6, single_stiffness=STIFFNESS,
        double_stiffness=stiffness_ratio * STIFFNESS, single_damping=damping,
        double_damping=damping * np.sqrt(stiffness_ratio), force=FORCE)


def step_response(time: np.ndarray, damping_ratio: float) -> np.ndarray:
    """Closed-form x(t) of me·ẍ + c·ẋ + k·x = w from rest, under-damped or undamped (ζ < 1)."""
    sigma = damping_ratio * OMEGA
    omega_d = OMEGA * np.sqrt(1.0 - damping_ratio**2)
    return STATIC * (1.0 - np.exp(-sigma * time) * (np.cos(omega_d * time) + sigma / omega_d * np.sin(omega_d * time)))


# ------------------------------------------------------------------------------ SDOF limits from rest
@pytest.mark.parametrize("damping_ratio", [0.0, 0.1])
def test_rk4_from_rest_follows_the_closed_form_step_response(damping_ratio):
    # undamped: x = (w/k)(1 − cos ωt), oscillating between 0 and 2w/k for ever; damped: decays onto w/k
    problem = constant_problem(damping_ratio)
    history = transient_from_rest(problem, periods=10)
    expected = step_response(history.time, damping_ratio)
    # default step ω·h <= 0.05: RK4 error per step ~ (ωh)^5/120 ≈ 3e-9, over ~1300 steps a few 1e-6 of w/k
    assert np.abs(history.displacement - expected).max() < 1e-5 * STATIC


@pytest.mark.parametrize("damping_ratio", [0.0, 0.1])
def test_solve_ivp_reference_follows_the_closed_form_step_response(damping_ratio):
    problem = constant_problem(damping_ratio)
    history = reference_solve_ivp(problem, periods=4, rtol=1e-11, samples_per_interval=16)
    expected = step_response(history.time, damping_ratio)
    assert np.abs(history.displacement - expected).max() < 1e-8 * STATIC


# ------------------------------------------------------------------------------ against the periodic orbit
def test_rk4_from_rest_converges_to_the_periodic_orbit():
    problem = square_wave()
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    steps = 8 * 40  # a multiple of the orbit's samples, so the last period lands on the orbit's sample times
    history = transient_from_rest(problem, periods=25, steps_per_interval=steps)
    time, x, v, _ = history.last_period()
    np.testing.assert_allclose(time[::40], orbit.time, rtol=1e-12)
    scale = np.abs(orbit.displacement).max()
    assert np.abs(x[::40] - orbit.displacement).max() / scale < 1e-6
    assert np.abs(v[::40] - orbit.velocity).max() / np.abs(orbit.velocity).max() < 1e-6
    change = history.convergence()
    assert change[0] > 1e-2 and change[-1] < 1e-7  # it settles period after period


def test_rk4_is_fourth_order_when_the_steps_sit_on_the_nodes():
    # one period from the exact periodic state: the distance of the end state from the start state is the
    # global RK4 error. Halving h must divide it by ~2^4.
    problem = square_wave()
    orbit = periodic_steady_state(problem, samples_per_interval=1)
    x0, v0 = orbit.initial_state
    errors = []
    for steps in (64, 128, 256):
        history = transient_from_rest(problem, periods=1, steps_per_interval=steps, x0=x0, v0=v0)
        errors.append(np.hypot(history.displacement[-1] - x0, (history.velocity[-1] - v0) / OMEGA))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert errors[-1] > 1e-9 * STATIC  # ~3e-7 of w/k: far above round-off, so the ratios measure truncation
    assert np.all((orders > 3.5) & (orders < 4.5)), orders


def test_numba_rk4_equals_the_plain_python_loop_to_round_off():
    problem = square_wave(0.7, damping_ratio=0.02)
    compiled = transient_from_rest(problem, periods=3, steps_per_interval=40)
    plain = transient_python(problem, periods=3, steps_per_interval=40)
    np.testing.assert_array_equal(compiled.time, plain.time)
    np.testing.assert_array_equal(compiled.interval, plain.interval)
    scale = np.abs(plain.displacement).max()
    assert np.abs(compiled.displacement - plain.displacement).max() <= 1e-13 * scale
    assert np.abs(compiled.velocity - plain.velocity).max() <= 1e-13 * np.abs(plain.velocity).max()
    assert compiled.method == "transient_rk4" and plain.method == "transient_rk4_python"


def test_rk4_and_reference_share_the_sample_grid():
    problem = square_wave()
    rk4 = transient_from_rest(problem, periods=2, steps_per_interval=64)
    reference = reference_solve_ivp(problem, periods=2, samples_per_interval=64)
    np.testing.assert_allclose(rk4.time, reference.time, rtol=1e-13, atol=0.0)
    np.testing.assert_array_equal(rk4.interval, reference.interval)
    # 64 steps: ω·h <= 0.27, RK4 error ~ (ωh)^4/120 per radian of motion, over ~80 rad: ~1e-4 of w/k
    assert np.abs(rk4.displacement - reference.displacement).max() < 1e-3 * STATIC


# ------------------------------------------------------------------------------ step-size rule
def test_too_coarse_a_step_is_refused_with_the_largest_safe_step():
    problem = square_wave(0.3, stiffness_ratio=1.5)
    omega_max = np.sqrt(1.5 * STIFFNESS / MASS)  # the double-contact interval is the stiffest
    assert largest_safe_step(problem) == pytest.approx(1.0 / omega_max, rel=1e-12)
    shortest = problem.durations.max()  # the longest interval sets the step for a given count
    coarse = int(np.floor(shortest * OMEGA / 1.5))  # ω·h ≈ 1.5 on the single-contact interval
    with pytest.raises(ProblemError) as error:
        transient_from_rest(problem, periods=1, steps_per_interval=coarse)
    message = str(error.value)
    stated = float(re.search(r"largest safe step ([0-9.eE+-]+) s", message).group(1))
    assert stated == pytest.approx(1.0 / omega_max, rel=1e-3)  # printed with 4 significant digits
    needed = int(re.search(r">= (\d+)", message).group(1))
    transient_from_rest(problem, periods=1, steps_per_interval=needed)  # the stated count is accepted
    with pytest.raises(ProblemError):
        transient_from_rest(problem, periods=1, steps_per_interval=needed - 1)


def test_largest_safe_step_of_an_over_damped_interval_uses_the_fast_root():
    # ζ = 5: the eigenvalues are real, −σ ± sqrt(σ² − ω²); the fast one sets the limit
    problem = constant_problem(5.0)
    sigma = 5.0 * OMEGA
    assert largest_safe_step(problem) == pytest.approx(1.0 / (sigma + np.sqrt(sigma**2 - OMEGA**2)), rel=1e-12)


def test_default_step_keeps_omega_h_below_the_default_bound():
    problem = square_wave(0.3, stiffness_ratio=2.0)
    steps = default_steps_per_interval(problem)
    omega = np.sqrt(problem.stiffness / MASS)
    assert np.max(omega * problem.durations / steps) <= DEFAULT_OMEGA_STEP
    assert np.max(omega * problem.durations / (steps - 1)) > DEFAULT_OMEGA_STEP  # and is the smallest such count
    assert transient_from_rest(problem, periods=1).steps_per_interval == steps


# ------------------------------------------------------------------------------ history helpers and input checks
def test_history_period_views():
    problem = square_wave()
    history = transient_from_rest(problem, periods=4, steps_per_interval=20)
    assert history.samples_per_period == 40
    assert history.time.size == 4 * 40 + 1
    starts = history.period_start_states()
    assert starts.shape == (5, 2)
    np.testing.assert_array_equal(starts[0], [0.0, 0.0])
    time, x, _, interval = history.last_period()
    assert time[0] == 0.0 and time[-1] == pytest.approx(problem.period, rel=1e-12)
    assert x[0] == starts[-2, 0] and x[-1] == starts[-1, 0]
    assert interval[0] == 0 and interval[-1] == problem.interval_count - 1
    assert history.convergence().shape == (4,)


@pytest.mark.parametrize("kwargs, key", [({"periods": 0}, "periods"), ({"periods": 1.5}, "periods"),
                                         ({"periods": 1, "steps_per_interval": 0}, "steps_per_interval"),
                                         ({"periods": 1, "x0": np.nan}, "x0"),
                                         ({"periods": 10**9}, "periods")])
def test_bad_transient_arguments_are_refused(kwargs, key):
    with pytest.raises(ProblemError, match=key):
        transient_from_rest(square_wave(), **kwargs)


@pytest.mark.parametrize("kwargs, key", [({"periods": 0}, "periods"), ({"periods": 1, "rtol": 2.0}, "rtol")])
def test_bad_reference_arguments_are_refused(kwargs, key):
    with pytest.raises(ProblemError, match=key):
        reference_solve_ivp(square_wave(), **kwargs)
