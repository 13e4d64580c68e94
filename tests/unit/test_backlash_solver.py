"""Exact event-driven backlash solver, shooting and classification, on a textbook single-mesh oscillator.

The textbook system (Kahraman & Singh 1990 type): me = 1 kg, mean stiffness k0 = 1e8 N/m (ω_n = 1e4 rad/s),
w = 1e3 N (static deflection x_st = 10 μm), stiffness k0·(1 + ε·cos 2πτ/T) and a transmission-error excitation
e(τ) = a·x_st·sin 2πτ/T on the driving flank, e' = −e on the back flank (a pitch-type error shifts both flanks
together, so the local clearance stays j), all piecewise constant on ``n`` equal intervals.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from thermogear.dynamics import MeshDynamicsProblem, periodic_steady_state
from thermogear.dynamics.backlash.backlash_metrics import history_forces, orbit_metrics
from thermogear.dynamics.backlash.backlash_periodic import (backlash_flow, backlash_transient, periodic_response,
                                                   shoot)
from thermogear.dynamics.periodic_orbits.periodic_batch import periodic_steady_state_batch
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.response import compute_metrics
from thermogear.dynamics.results.spectra import harmonic_spectrum
from thermogear.dynamics.transients.backlash_reference import reference_backlash_solve_ivp
from thermogear.errors import ModelLimitError

from backlash_textbook import FORCE, K0, MASS, X_STATIC, textbook_problem


def textbook(ratio, zeta=0.05, **options):
    """The textbook oscillator (module ``backlash_textbook``) with this file's damping ratio 0.05."""
    return textbook_problem(ratio, zeta, **options)


# ---------------------------------------------------------------- agreement with the linear solver
def test_no_contact_loss_equals_the_linear_periodic_solution():
    # square wave, no deviation, load large against the vibration: the teeth never separate, so the nonlinear
    # model is the linear one and the exact solvers must agree to rounding (1e-6 leaves 8 orders of margin)
    linear = MeshDynamicsProblem.square_wave(mass=MASS, mesh_period=2 * np.pi / (0.3 * 1e4), contact_ratio=1.6,
                                             single_stiffness=K0, double_stiffness=1.5 * K0,
                                             single_damping=2e3, double_damping=2e3, force=FORCE)
    problem = BacklashMeshProblem.from_linear(linear, backlash=X_STATIC)
    orbit = periodic_response(problem, samples_per_interval=64)
    # the linear orbit sampled 128 times finer: each interval spans ω·h ≈ 8–13 rad, so its sampled peak is low by
    # at most (13/8192)²/8 ≈ 3e-7 of the swing, below the 1e-6 compared (our maxima are the exact extrema of x)
    reference = periodic_steady_state(linear, samples_per_interval=64 * 128)
    grid = orbit.history.kind == 0
    assert orbit.response == "periodic" and orbit.converged and orbit.switch_times.size == 0
    scale = np.max(np.abs(reference.displacement))
    np.testing.assert_allclose(orbit.history.displacement[grid], reference.displacement[::128], rtol=0,
                               atol=1e-6 * scale)
    linear_metrics = compute_metrics(linear, reference.time, reference.displacement, reference.velocity,
                                     reference.interval, reference.multipliers)
    metrics = orbit_metrics(orbit)
    assert metrics["contact_loss_fraction"] == 0.0 and not metrics["back_side_contact"]
    assert metrics["kv"] == pytest.approx(linear_metrics["kv"], rel=1e-6)
    assert metrics["max_mesh_force"] == pytest.approx(linear_metrics["max_system_load"], rel=1e-6)
    np.testing.assert_allclose(np.abs(orbit.multipliers), np.abs(reference.multipliers), rtol=1e-9)


def test_very_large_backlash_gives_the_one_sided_solution():
    # with j = 1000 x_st the back flank is out of reach: the orbit must equal the one-sided (impact-free) model,
    # i.e. the same problem with no back-flank stiffness at all, to rounding
    problem = textbook(1.0, deviation=0.5, backlash=1000.0)
    one_sided = problem.with_changes(back_pair_stiffness=np.zeros_like(problem.pair_stiffness))
    orbit, reference = periodic_response(problem), periodic_response(one_sided)
    metrics = orbit_metrics(orbit)
    assert metrics["contact_loss_fraction"] > 0.1  # the driving flank does separate
    assert not metrics["back_side_contact"]
    np.testing.assert_allclose(orbit.initial_state, reference.initial_state, rtol=1e-12, atol=1e-20)


# ---------------------------------------------------------------- against solve_ivp with event location
@pytest.mark.parametrize("deviation, backlash, mode, back_contact", [
    (0.3, 1.0, "always", False),  # contact loss only
    (0.5, 0.1, "always", True),  # contact loss and back-flank impacts
    (0.5, 0.1, "in_contact", True),
])
def test_against_solve_ivp_with_events(deviation, backlash, mode, back_contact):
    problem = textbook(0.9, zeta=0.08, deviation=deviation, backlash=backlash, n=16, mode=mode)
    orbit = periodic_response(problem)
    metrics = orbit_metrics(orbit)
    assert orbit.converged and metrics["contact_loss_fraction"] > 0.05
    assert metrics["back_side_contact"] is back_contact
    # 30 periods from rest at ζ = 0.08: the free transient decays by exp(−ζ·ω_n·29·T) ≈ 1e-7; the last period is
    # compared. The reference samples 8 points per interval (ω·h/8 ≈ 0.05 rad), so its peaks are low by up to
    # (0.05)²/8 ≈ 3e-4 of the swing: 1e-3 on peak-to-peak and on the force (the brief asks 1 %)
    periods = 30
    reference = reference_backlash_solve_ivp(problem, periods, rtol=1e-9)
    start = (periods - 1) * problem.period
    last = reference["time"] >= start * (1.0 - 1e-12)
    x, v = reference["displacement"][last], reference["velocity"][last]
    local = reference["time"][last] - start
    # a sample on a node (up to the rounding of q·T + node) belongs to the interval it starts
    nudge = 1e-9 * problem.period
    interval = np.clip(np.searchsorted(problem.nodes, local + nudge, side="right") - 1, 0,
                       problem.interval_count - 1)
    on_node = (np.abs(local - problem.nodes[interval]) < nudge) & (interval > 0)

    samples = SimpleNamespace(  # both one-sided limits at the nodes, as the solver's own history holds them
        displacement=np.concatenate([x, x[on_node]]), velocity=np.concatenate([v, v[on_node]]),
        interval=np.concatenate([interval, interval[on_node] - 1]))
    force, _ = history_forces(problem, samples)
    assert np.ptp(x) == pytest.approx(metrics["dte_peak_to_peak"], rel=1e-3)
    assert np.max(force) == pytest.approx(metrics["max_mesh_force"], rel=1e-3)
    # the same contact switches: solve_ivp's event location at rtol 1e-9 against the exact root
    switches = reference["switch_times"][reference["switch_times"] >= start] - start
    np.testing.assert_allclose(switches, orbit.switch_times, rtol=0, atol=1e-6 * problem.period)


# ---------------------------------------------------------------- variational matrix
@pytest.mark.parametrize("mode", ["always", "in_contact"])
def test_monodromy_matches_finite_differences_of_the_flow(mode):
    problem = textbook(0.9, deviation=0.5, backlash=0.1, mode=mode)  # contact loss and back-flank impacts
    orbit = periodic_response(problem)
    assert orbit.switch_times.size >= 4
    state = np.array(orbit.initial_state)
    _, matrix, info = backlash_flow(problem, state)
    assert info["back_contact_time"] > 0.0
    scale = np.array([problem.displacement_scale, problem.velocity_scale])
    columns = []
    for j in range(2):
        step = np.zeros(2)
        step[j] = 1e-6 * scale[j]  # central differences: truncation ~(1e-6)² relative, rounding ~1e-16/1e-6
        columns.append((backlash_flow(problem, state + step)[0] - backlash_flow(problem, state - step)[0])
                       / (2.0 * step[j]))
    finite = np.column_stack(columns)
    # compare in scaled units (x by x_st, v by x_st·ω_n) so the four entries are commensurate
    scaled = np.diag(1.0 / scale) @ (finite - matrix) @ np.diag(scale)
    assert np.max(np.abs(scaled)) < 1e-6 * np.max(np.abs(np.diag(1.0 / scale) @ matrix @ np.diag(scale)))
    if mode == "always":
        # Liouville: det M = exp(−∫ tr A) = exp(−Σ c·h/me) whatever the switches (the saltation matrices are I)
        expected = np.exp(-np.sum(problem.damping * problem.durations) / problem.mass)
        assert np.linalg.det(matrix) == pytest.approx(expected, rel=1e-10)
    else:
        # in free flight c = 0, so det M = exp(−∫ c_eff/me) is larger than with damping always on
        assert np.linalg.det(matrix) > np.exp(-np.sum(problem.damping * problem.durations) / problem.mass)


def test_switches_are_located_on_the_thresholds_and_transient_reaches_the_orbit():
    problem = textbook(1.0, deviation=0.3)
    orbit = periodic_response(problem)
    switches = orbit.history.kind == 1
    interval = orbit.history.interval[switches]
    # x is set to the threshold at each switch: the driving flank's e (no back contact here)
    np.testing.assert_array_equal(orbit.history.displacement[switches], problem.pair_deviation[0, interval])
    # the exact transient from rest settles on the shooting orbit
    history = backlash_transient(problem, 120)
    last = history.time >= 119 * problem.period * (1 - 1e-12)
    np.testing.assert_allclose(history.displacement[last][-1], orbit.initial_state[0], rtol=0,
                               atol=1e-9 * X_STATIC)  # ζ = 0.05: the transient decays by e^{−37} in 119 periods


# ---------------------------------------------------------------- subharmonic, non-periodic, unbounded
def test_subharmonic_at_the_principal_parametric_resonance():
    # Ω = 2 with ε = 0.3 and no error: the linear model is parametrically unstable (a multiplier > 1);
    # with backlash the motion is bounded on a period-2 orbit (teeth separate every other mesh period)
    problem = textbook(2.0, zeta=0.02, eps=0.3, deviation=0.0)
    linear = problem.linear_problem()
    _, _, moduli = periodic_steady_state_batch(linear.mass, linear.nodes, linear.stiffness[None],
                                               linear.damping[None], linear.force_per_interval[None])
    assert moduli[0, 0] > 1.0
    orbit = periodic_response(problem)
    assert orbit.response == "subharmonic" and orbit.period_count == 2 and orbit.converged
    assert orbit.largest_multiplier < 1.0 and orbit.residual < 1e-10
    state = np.array(orbit.initial_state)
    one_period = backlash_flow(problem, state, 1)[0]
    two_periods = backlash_flow(problem, state, 2)[0]
    assert np.abs(two_periods - state)[0] < 1e-9 * X_STATIC
    assert np.abs(one_period - state)[0] > 1e-2 * X_STATIC  # really period 2, not a period-1 orbit
    assert orbit_metrics(orbit)["contact_loss_fraction"] > 0.0


def test_non_periodic_response_is_classified_not_returned_as_an_orbit():
    problem = textbook(0.6, zeta=0.02, eps=0.1, deviation=3.0, backlash=2.0, n=16)
    orbit = periodic_response(problem, max_period_count=6)
    assert orbit.response == "non-periodic" and not orbit.converged
    assert np.all(np.isnan(orbit.multipliers)) and not orbit.stable
    assert np.all(np.isfinite(orbit.history.displacement))
    # independent check: the stroboscopic states of a long transient do not repeat after 1…6 periods
    history = backlash_transient(problem, 1200, samples_per_interval=1)
    strobe = (history.kind == 0) & (history.interval == 0)
    x = history.displacement[strobe][-300:] / problem.displacement_scale
    v = history.velocity[strobe][-300:] / problem.velocity_scale
    for lag in range(1, 7):
        assert np.min(np.hypot(x[lag:] - x[:-lag], v[lag:] - v[:-lag])) > 1e-3


def test_unbounded_growth_is_refused():
    # ε = 0.5 at Ω = 1.8 with ζ = 0.02: parametrically unstable and, since at large amplitude both flanks act
    # as one linear mesh, unbounded in the backlash model too
    with pytest.raises(ModelLimitError, match="without bound"):
        periodic_response(textbook(1.8, zeta=0.02, eps=0.5, deviation=0.0))


def test_shoot_from_a_far_state_converges_to_the_same_orbit():
    problem = textbook(1.0, deviation=0.3)
    orbit = periodic_response(problem)
    result = shoot(problem, (3.0 * X_STATIC, 0.0))
    assert result["converged"]
    np.testing.assert_allclose(result["state"], orbit.initial_state, rtol=1e-8)


def test_dte_spectrum_equals_the_linear_one_without_contact_loss():
    # constant stiffness, a small pitch-type error and no separation: the orbit is the linear one, so its mesh
    # harmonics equal those of the linear orbit. Both spectra interpolate their samples onto 1024 points; the
    # samples differ (ours add the extrema of x), a difference of order (ω·h/64)²/8 ≈ 1e-6 of the swing
    problem = textbook(0.7, eps=0.0, deviation=0.1)
    orbit = periodic_response(problem, samples_per_interval=64)
    metrics = orbit_metrics(orbit)
    assert metrics["contact_loss_fraction"] == 0.0
    linear = problem.linear_problem()
    reference = periodic_steady_state(linear, samples_per_interval=64)
    _, amplitudes = harmonic_spectrum(reference.time, reference.displacement, linear.period)
    swing = np.ptp(reference.displacement)
    np.testing.assert_allclose(metrics["dte_mesh_harmonics"], amplitudes[:9], rtol=0, atol=1e-5 * swing)
    assert metrics["dte_mesh_harmonics"][1] > 0.1 * swing  # the excitation's line is there
    assert metrics["dte_mean"] == pytest.approx(amplitudes[0], rel=1e-5)
