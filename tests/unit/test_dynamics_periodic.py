"""Exact periodic steady state (Floquet / monodromy, Floquet (1883)) on synthetic problems with closed forms.

Units: a 1 kg equivalent mass with a 100 Hz natural frequency (k = (2π·100)² N/m) and a 100 N load keep the
numbers readable; nothing in the solver depends on the scale.
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from scipy.linalg import expm

from thermogear.dynamics import (MeshDynamicsProblem, evaluate_orbit, floquet_multipliers, periodic_steady_state,
                                 periodic_steady_state_batch, reference_solve_ivp)
from thermogear.dynamics.periodic_orbits.periodic import monodromy, periodic_initial_state
from thermogear.errors import ProblemError, ModelLimitError

MASS = 1.0  # [kg]
OMEGA = 2.0 * np.pi * 100.0  # natural circular frequency of the single-contact stiffness [rad/s]
STIFFNESS = MASS * OMEGA**2  # [N/m]
FORCE = 100.0  # [N]


def constant_problem(damping_ratio: float, period: float = 3.7e-3, intervals: int = 5) -> MeshDynamicsProblem:
    """Constant k and c on ``intervals`` uneven intervals (the nodes must not matter)."""
    nodes = period * np.concatenate([[0.0], np.cumsum(np.arange(1, intervals + 1))]) / np.sum(
        np.arange(1, intervals + 1))
    damping = 2.0 * damping_ratio * MASS * OMEGA
    return MeshDynamicsProblem(mass=MASS, nodes=nodes, stiffness=np.full(intervals, STIFFNESS),
                               damping=np.full(intervals, damping), force=FORCE,
                               contact_count=np.ones(intervals, dtype=int))


def square_wave(frequency_ratio: float, damping_ratio: float = 0.05, stiffness_ratio: float = 1.5,
                contact_ratio: float = 1.6) -> MeshDynamicsProblem:
    """Square-wave mesh stiffness: single k, double stiffness_ratio·k; mesh frequency = ratio × 100 Hz."""
    damping = 2.0 * damping_ratio * MASS * OMEGA
    return MeshDynamicsProblem.square_wave(
        mass=MASS, mesh_period=1.0 / (100.0 * frequency_ratio), contact_ratio=contact_ratio,
        single_stiffness=STIFFNESS, double_stiffness=stiffness_ratio * STIFFNESS, single_damping=damping,
        double_damping=damping * np.sqrt(stiffness_ratio), force=FORCE)


# ------------------------------------------------------------------------------ closed-form transition matrix
@pytest.mark.parametrize("damping_ratio", [0.0, 0.02, 0.7, 1.0, 1.0 + 1e-9, 3.0, 40.0])
def test_one_interval_transition_equals_the_matrix_exponential(damping_ratio):
    # under-damped, critical (the Taylor-series branch), just over-damped and heavily over-damped intervals
    problem = constant_problem(damping_ratio, intervals=1)
    a = np.array([[0.0, 1.0], [-STIFFNESS / MASS, -problem.damping[0] / MASS]])
    matrix, _ = monodromy(problem)
    expected = expm(a * problem.period)
    scale = np.abs(expected).max()
    np.testing.assert_allclose(matrix, expected, rtol=0.0, atol=1e-12 * scale)


def test_monodromy_is_the_time_ordered_product_of_interval_exponentials():
    problem = square_wave(0.7)
    product = np.eye(2)
    for k, c, h in zip(problem.stiffness, problem.damping, problem.durations, strict=True):
        product = expm(np.array([[0.0, 1.0], [-k / MASS, -c / MASS]]) * h) @ product  # later intervals on the left
    matrix, _ = monodromy(problem)
    np.testing.assert_allclose(matrix, product, rtol=1e-11, atol=1e-11 * np.abs(product).max())


@pytest.mark.parametrize("frequency_ratio, damping_ratio", [(0.3, 0.05), (0.7, 0.01), (2.0, 0.005), (0.4, 2.0)])
def test_determinant_of_the_monodromy_is_liouvilles_exponential(frequency_ratio, damping_ratio):
    # det M = exp(∫ trace A dt) = exp(−Σ c_i h_i / me) for any coefficients, stable or not
    problem = square_wave(frequency_ratio, damping_ratio)
    matrix, _ = monodromy(problem)
    expected = np.exp(-np.sum(problem.damping * problem.durations) / MASS)
    assert np.linalg.det(matrix) == pytest.approx(expected, rel=1e-10)


# ------------------------------------------------------------------------------ constant coefficients
@pytest.mark.parametrize("damping_ratio", [0.02, 0.3, 1.0, 4.0])
def test_constant_coefficients_give_the_static_deflection(damping_ratio):
    problem = constant_problem(damping_ratio)
    orbit = periodic_steady_state(problem, samples_per_interval=16)
    static = FORCE / STIFFNESS
    np.testing.assert_allclose(orbit.displacement, static, rtol=1e-12)
    np.testing.assert_allclose(orbit.velocity, 0.0, atol=1e-12 * static * OMEGA)
    assert orbit.initial_state[0] == pytest.approx(static, rel=1e-12)


@pytest.mark.parametrize("damping_ratio", [0.02, 0.3, 0.999, 1.0, 4.0])
def test_constant_coefficients_multipliers_are_exponentials_of_the_eigenvalues(damping_ratio):
    # μ_i = exp(λ_i T) with λ = −σ ± sqrt(σ² − ω²) the eigenvalues of A (complex pair when under-damped)
    problem = constant_problem(damping_ratio)
    sigma = damping_ratio * OMEGA
    root = np.sqrt(complex(sigma**2 - OMEGA**2))
    expected = np.exp(np.array([-sigma + root, -sigma - root]) * problem.period)
    multipliers = floquet_multipliers(problem)
    # at critical damping M is a Jordan block: a rounding error ε in M moves its double eigenvalue by sqrt(ε),
    # so there the multipliers are only good to ~1e-8 relative (trace and determinant stay at ~1e-15)
    rtol = 3e-7 if damping_ratio == 1.0 else 1e-9
    np.testing.assert_allclose(np.sort_complex(multipliers), np.sort_complex(expected), rtol=rtol,
                               atol=1e-12 * np.abs(expected).max())
    assert np.abs(multipliers[0]) >= np.abs(multipliers[1])


def test_undamped_problem_is_refused_because_free_vibration_never_decays():
    # c = 0: |μ1·μ2| = det M = 1 (Liouville), so no multiplier lies strictly inside the unit circle and there is
    # no attracting periodic orbit, whatever rounding does to the moduli. The refusal must not depend on T.
    for period in (1e-3, 3.7e-3, 1e-2, 1.23e-2):
        problem = constant_problem(0.0, period=period)
        np.testing.assert_allclose(np.abs(floquet_multipliers(problem)), 1.0, atol=1e-12)
        with pytest.raises(ModelLimitError, match="undamped"):
            periodic_steady_state(problem)
        _, _, moduli = periodic_steady_state_batch(MASS, problem.nodes, problem.stiffness[None, :],
                                                   problem.damping[None, :], FORCE)
        assert moduli[0, 0] >= 1.0


# ------------------------------------------------------------------------------ square wave vs references
def test_periodic_orbit_equals_solve_ivp_started_on_it():
    problem = square_wave(0.3)
    orbit = periodic_steady_state(problem, samples_per_interval=32)
    reference = reference_solve_ivp(problem, periods=2, rtol=1e-11, samples_per_interval=32,
                                    x0=orbit.initial_state[0], v0=orbit.initial_state[1])
    for period in range(2):  # it stays on the orbit, period after period
        sl = slice(period * 64, period * 64 + 65)
        scale = np.abs(orbit.displacement).max()
        assert np.abs(reference.displacement[sl] - orbit.displacement).max() / scale < 1e-6
        scale_v = np.abs(orbit.velocity).max()
        assert np.abs(reference.velocity[sl] - orbit.velocity).max() / scale_v < 1e-6
    # the last sample closes the period: x(T) = x(0)
    assert orbit.displacement[-1] == pytest.approx(orbit.displacement[0], rel=1e-12)
    assert orbit.velocity[-1] == pytest.approx(orbit.velocity[0], rel=1e-10)


def test_solve_ivp_from_rest_converges_to_the_periodic_orbit():
    problem = square_wave(0.3)
    orbit = periodic_steady_state(problem, samples_per_interval=16)
    history = reference_solve_ivp(problem, periods=25, rtol=1e-11, samples_per_interval=16)
    _, x, _, _ = history.last_period()
    scale = np.abs(orbit.displacement).max()
    first = np.abs(history.displacement[:33] - orbit.displacement).max() / scale
    last = np.abs(x - orbit.displacement).max() / scale
    assert first > 0.1  # it really starts away from the orbit (at rest)
    assert last < 1e-6
    # and the distance shrinks by the largest Floquet multiplier per period (|μ| ≈ 0.30 here)
    modulus = np.abs(floquet_multipliers(problem)[0])
    starts = history.period_start_states()
    distance = np.hypot(starts[:, 0] - orbit.initial_state[0],
                        (starts[:, 1] - orbit.initial_state[1]) / OMEGA)
    assert distance[12] / distance[11] == pytest.approx(modulus, rel=0.05)


def test_evaluate_orbit_reproduces_the_samples_at_any_order_of_times():
    problem = square_wave(0.45)
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    order = np.random.default_rng(1).permutation(orbit.time.size - 1)
    x, v = evaluate_orbit(problem, orbit.initial_state, orbit.time[order])
    np.testing.assert_allclose(x, orbit.displacement[order], rtol=1e-12)
    np.testing.assert_allclose(v, orbit.velocity[order], rtol=1e-9, atol=1e-12 * np.abs(orbit.velocity).max())


def test_sample_count_does_not_change_the_orbit():
    problem = square_wave(0.45)
    coarse = periodic_steady_state(problem, samples_per_interval=4)
    fine = periodic_steady_state(problem, samples_per_interval=12)
    np.testing.assert_allclose(fine.displacement[::3], coarse.displacement, rtol=1e-12)
    assert fine.initial_state == coarse.initial_state


@pytest.mark.parametrize("samples", [0, -3, 2.5])
def test_bad_sample_count_is_refused(samples):
    with pytest.raises(ProblemError, match="samples_per_interval"):
        periodic_steady_state(square_wave(0.3), samples_per_interval=samples)


# ------------------------------------------------------------------------------ stability
def test_parametric_resonance_is_refused_with_the_multipliers_in_the_message():
    # stiffness modulated at twice the natural frequency (f_m ≈ 2 f_n of the mean stiffness), light damping:
    # the principal parametric resonance, where the zero state is unstable
    problem = square_wave(2.3, damping_ratio=0.005)
    assert problem.frequency_ratio == pytest.approx(2.0, abs=0.05)
    moduli = np.abs(floquet_multipliers(problem))
    assert moduli[0] > 1.05
    with pytest.raises(ModelLimitError) as error:
        periodic_steady_state(problem)
    message = str(error.value)
    assert "Floquet multiplier" in message
    printed = [float(v) for v in re.search(r"moduli \[([^\]]+)\]", message).group(1).split()]
    np.testing.assert_allclose(printed, moduli, rtol=1e-5)


def test_parametric_resonance_is_real_the_transient_grows_by_the_multiplier():
    # independent check of the verdict: the RK4-free SciPy reference from rest grows by |μ|max per period
    problem = square_wave(2.3, damping_ratio=0.005)
    modulus = np.abs(floquet_multipliers(problem)[0])
    history = reference_solve_ivp(problem, periods=40, rtol=1e-10, samples_per_interval=2)
    starts = history.period_start_states()
    size = np.hypot(starts[:, 0], starts[:, 1] / OMEGA)
    assert (size[40] / size[30]) ** 0.1 == pytest.approx(modulus, rel=0.01)


def test_stable_point_beside_the_resonance_is_accepted():
    problem = square_wave(1.2, damping_ratio=0.005)
    orbit = periodic_steady_state(problem)
    assert orbit.stable
    assert orbit.multipliers_abs[0] < 1.0
    assert np.all(np.isfinite(orbit.displacement))


def test_batch_equals_one_solve_per_point_and_marks_unstable_points():
    ratios = [0.3, 0.7, 2.3, 1.2]
    # the batch needs one node grid: scale the mass instead of the period (same dimensionless problem)
    base = square_wave(1.0, damping_ratio=0.005)
    masses = np.array([MASS * r**2 for r in ratios])  # f_n ∝ 1/sqrt(me): f_m/f_n scales with r
    x0, v0, moduli = periodic_steady_state_batch(masses, base.nodes, np.tile(base.stiffness, (4, 1)),
                                                 np.tile(base.damping, (4, 1)), FORCE)
    for j, mass in enumerate(masses):
        problem = MeshDynamicsProblem(mass=mass, nodes=base.nodes, stiffness=base.stiffness, damping=base.damping,
                                      force=FORCE, contact_count=base.contact_count)
        expected_moduli = np.abs(floquet_multipliers(problem))
        np.testing.assert_allclose(moduli[j], expected_moduli, rtol=1e-12)
        if expected_moduli[0] < 1.0:
            (x_ref, v_ref), _ = periodic_initial_state(problem)
            assert x0[j] == pytest.approx(x_ref, rel=1e-12)
            assert v0[j] == pytest.approx(v_ref, rel=1e-9, abs=1e-12 * OMEGA * FORCE / STIFFNESS)
        else:
            assert np.isnan(x0[j]) and np.isnan(v0[j])
    assert moduli[2, 0] > 1.0  # the parametric resonance is in the batch


def test_batch_refuses_bad_shapes_and_values():
    base = square_wave(0.3)
    with pytest.raises(ProblemError, match="nodes"):
        periodic_steady_state_batch(MASS, base.nodes[:-1], base.stiffness[None, :], base.damping[None, :], FORCE)
    with pytest.raises(ProblemError):
        periodic_steady_state_batch(MASS, base.nodes, -base.stiffness[None, :], base.damping[None, :], FORCE)
    with pytest.raises(ProblemError):
        periodic_steady_state_batch(MASS, base.nodes, np.array([[np.nan, 1.0]]), base.damping[None, :], FORCE)


@pytest.mark.parametrize("damping_ratio, stiffness", [(50.0, STIFFNESS), (0.01, 1e6 * STIFFNESS),
                                                      (1e-6, STIFFNESS)])
def test_extreme_but_valid_coefficients_give_finite_orbits(damping_ratio, stiffness):
    # heavily over-damped (exponentials that would overflow if written as cosh/sinh), very stiff (ω·T ≈ 4e3),
    # and nearly undamped: the orbit is finite and closes on itself
    damping = 2.0 * damping_ratio * MASS * OMEGA
    problem = MeshDynamicsProblem(mass=MASS, nodes=[0.0, 4e-3, 1e-2], stiffness=[stiffness, 1.4 * stiffness],
                                  damping=[damping, damping], force=FORCE, contact_count=[1, 2])
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    assert np.all(np.isfinite(orbit.displacement)) and np.all(np.isfinite(orbit.velocity))
    assert orbit.displacement[-1] == pytest.approx(orbit.displacement[0], rel=1e-9)
