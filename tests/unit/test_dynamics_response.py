"""Metrics, contact loss, spectra and netCDF of the dynamic response, and the input checks of the problem, on
synthetic problems whose answers are known in closed form (me = 1 kg, f_n = 100 Hz, w = 100 N)."""

from __future__ import annotations

import json
import os
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermogear.dynamics import (MeshDynamicsProblem, evaluate_orbit, periodic_steady_state, region_name,
                                 transient_from_rest)
from thermogear.dynamics.response import compute_metrics, response_from_orbit, response_from_transient
from thermogear.dynamics.results.spectra import harmonic_spectrum, signal_spectrum
from thermogear.errors import CaseError, ProblemError, ModelAssumptionWarning, ModelLimitError

MASS = 1.0
OMEGA = 2.0 * np.pi * 100.0
STIFFNESS = MASS * OMEGA**2
FORCE = 100.0


def square_wave(frequency_ratio: float = 0.3, damping_ratio: float = 0.05, stiffness_ratio: float = 1.5,
                face_width: float = 1.0) -> MeshDynamicsProblem:
    damping = 2.0 * damping_ratio * MASS * OMEGA
    return MeshDynamicsProblem.square_wave(
        mass=MASS, mesh_period=1.0 / (100.0 * frequency_ratio), contact_ratio=1.6, single_stiffness=STIFFNESS,
        double_stiffness=stiffness_ratio * STIFFNESS, single_damping=damping,
        double_damping=damping * np.sqrt(stiffness_ratio), force=FORCE, face_width=face_width)


def orbit_response(problem: MeshDynamicsProblem, samples: int = 64, include_damping_force: bool = False):
    return response_from_orbit(problem, periodic_steady_state(problem, samples_per_interval=samples),
                               include_damping_force=include_damping_force)


def dense(problem: MeshDynamicsProblem, initial_state, points: int = 2001):
    """Exact (t, x, ẋ) on ``points`` (odd) equal sub-samples of every interval, both ends included."""
    out = []
    for i in range(problem.interval_count):
        t = np.linspace(problem.nodes[i], problem.nodes[i + 1], points)
        x, v = evaluate_orbit(problem, initial_state, t)
        out.append((t, x, v))
    return out


def simpson(t: np.ndarray, y: np.ndarray) -> float:
    h = t[1] - t[0]
    return float(h / 3.0 * (y[0] + y[-1] + 4.0 * y[1:-1:2].sum() + 2.0 * y[2:-1:2].sum()))


# ------------------------------------------------------------------------------ metrics: closed-form cases
def test_constant_stiffness_gives_kv_one_and_no_vibration():
    problem = square_wave(stiffness_ratio=1.0)  # double = single stiffness: k constant, pairs share it
    response = orbit_response(problem)
    metrics = response.metrics
    assert metrics["kv"] == pytest.approx(1.0, rel=1e-12)
    assert metrics["kv_basis"] == "pair_loads"
    assert metrics["max_system_load_ratio"] == pytest.approx(1.0, rel=1e-12)
    for name in ("single", "double"):
        assert metrics["equilibrium_per_region"][name] == pytest.approx(FORCE / STIFFNESS, rel=1e-12)
        assert abs(metrics["amplitude_per_region"][name]) < 1e-12 * FORCE / STIFFNESS
    assert metrics["dte_mean"] == pytest.approx(FORCE / STIFFNESS, rel=1e-12)
    assert metrics["dte_rms"] < 1e-10 * FORCE / STIFFNESS
    assert metrics["dte_peak_to_peak"] < 1e-12 * FORCE / STIFFNESS
    assert not metrics["contact_loss"]["detected"] and metrics["valid"] and response.valid
    # in double contact each pair carries half the load, in single contact the whole
    pair = response.pair_loads()
    assert pair.max() == pytest.approx(FORCE, rel=1e-12)
    assert pair[1].max() == pytest.approx(0.5 * FORCE, rel=1e-12)


def test_equilibrium_per_region_is_the_static_deflection_of_each_region():
    response = orbit_response(square_wave(damping_ratio=0.15, stiffness_ratio=1.7))
    equilibrium = response.metrics["equilibrium_per_region"]
    assert equilibrium["single"] == pytest.approx(FORCE / STIFFNESS, rel=1e-14)
    assert equilibrium["double"] == pytest.approx(FORCE / (1.7 * STIFFNESS), rel=1e-14)


def test_equilibrium_of_a_region_is_the_time_mean_of_w_over_k():
    # a region made of several intervals with different k: the level is Σ (w/k_i)·h_i / Σ h_i over the region
    nodes = np.array([0.0, 1.0, 3.0, 4.0, 7.0, 8.0]) * 1e-3
    stiffness = STIFFNESS * np.array([2.0, 1.0, 1.2, 2.4, 1.8])
    contact = np.array([2, 1, 1, 2, 2])
    problem = MeshDynamicsProblem(mass=MASS, nodes=nodes, stiffness=stiffness, damping=np.full(5, 1000.0), force=FORCE,
                                  contact_count=contact)
    equilibrium = orbit_response(problem, samples=8).metrics["equilibrium_per_region"]
    h = np.diff(nodes)
    for count in (1, 2):
        region = contact == count
        expected = np.sum(FORCE / stiffness[region] * h[region]) / h[region].sum()
        assert equilibrium[region_name(count)] == pytest.approx(expected, rel=1e-14)
    # no pair stiffness: Kv falls back to the system load in single contact, where one pair carries it all
    metrics = orbit_response(problem, samples=8).metrics
    assert metrics["kv_basis"] == "system_load_in_single_contact"


def test_kv_is_the_largest_single_pair_load_over_the_static_load():
    problem = square_wave(0.3, damping_ratio=0.05, stiffness_ratio=1.5)
    response = orbit_response(problem, samples=512)
    metrics = response.metrics
    # independent: the exact orbit on 2001 points per interval, pair loads k_p·x with each interval's k_p
    pieces = dense(problem, response.initial_state)
    pair_max = max(problem.pair_stiffness[s, i] * pieces[i][1].max() for s in range(2) for i in range(2))
    system_max = max(problem.stiffness[i] * pieces[i][1].max() for i in range(2))
    # 512 samples per interval: ω·h <= 0.012, a sampled peak is low by at most ~(ωh)²/8 of the swing
    assert metrics["kv"] == pytest.approx(pair_max / FORCE, rel=1e-4)
    assert metrics["max_system_load_ratio"] == pytest.approx(system_max / FORCE, rel=1e-4)
    assert metrics["kv"] > 1.05  # the square wave excites a real dynamic overload here
    assert metrics["max_pair_load"] == pytest.approx(metrics["kv"] * FORCE, rel=1e-14)
    assert metrics["max_system_load"] > metrics["max_pair_load"]  # double contact: the system carries two pairs


def test_amplitude_is_peak_minus_equilibrium_per_region():
    problem = square_wave(0.3, damping_ratio=0.05, stiffness_ratio=1.5)
    response = orbit_response(problem, samples=512)
    pieces = dense(problem, response.initial_state)
    names = {2: "double", 1: "single"}
    for i, count in enumerate(problem.contact_count):
        name = names[int(count)]
        expected = pieces[i][1].max() - FORCE / problem.stiffness[i]
        assert response.metrics["amplitude_per_region"][name] == pytest.approx(expected, rel=1e-4)
        deviation = np.abs(pieces[i][1] - FORCE / problem.stiffness[i]).max()
        assert response.metrics["deviation_per_region"][name] == pytest.approx(deviation, rel=1e-4)


@pytest.mark.parametrize("force", [FORCE, np.array([80.0, 130.0])])
def test_period_mean_of_the_mesh_force_is_the_static_load(force):
    # me·ẍ integrates to zero over a period of the periodic orbit, so mean(k·x + c·ẋ) = mean(w) exactly
    problem = MeshDynamicsProblem.square_wave(mass=MASS, mesh_period=1.0 / 30.0, contact_ratio=1.6,
                                              single_stiffness=STIFFNESS, double_stiffness=1.5 * STIFFNESS,
                                              single_damping=200.0, double_damping=250.0, force=FORCE)
    if np.ndim(force):
        problem = MeshDynamicsProblem(mass=MASS, nodes=problem.nodes, stiffness=problem.stiffness,
                                      damping=problem.damping, force=force, contact_count=problem.contact_count)
    response = orbit_response(problem)
    total = 0.0
    stiffness_only = 0.0
    for i, (t, x, v) in enumerate(dense(problem, response.initial_state)):
        total += simpson(t, problem.stiffness[i] * x + problem.damping[i] * v)
        stiffness_only += simpson(t, problem.stiffness[i] * x)
    assert total / problem.period == pytest.approx(problem.static_load, rel=1e-9)
    # with c jumping at the nodes the mean of k·x alone is not w: the identity needs the damping force
    assert abs(stiffness_only / problem.period - problem.static_load) > 1e-6 * problem.static_load


def test_damping_force_option_adds_c_xdot_to_the_loads():
    problem = square_wave(0.3, damping_ratio=0.1)
    plain = orbit_response(problem)
    with_damping = orbit_response(problem, include_damping_force=True)
    np.testing.assert_allclose(with_damping.system_load() - plain.system_load(),
                               problem.damping[plain.interval] * plain.velocity, rtol=1e-12, atol=1e-9)
    assert with_damping.metrics["kv"] != plain.metrics["kv"]


def test_per_width_views_divide_by_the_face_width():
    metrics = orbit_response(square_wave(face_width=0.025)).metrics
    assert metrics["static_load_n_per_mm"] == pytest.approx(FORCE / 25.0, rel=1e-14)
    assert metrics["max_pair_load_n_per_mm"] == pytest.approx(metrics["max_pair_load"] / 25.0, rel=1e-14)


# ------------------------------------------------------------------------------ contact loss
def test_contact_loss_is_flagged_with_times_durations_and_minimum_force():
    # double contact twice as stiff, ζ = 0.08: the drop of the equilibrium from w/k to w/2k at the
    # single→double transition overshoots below zero (minimum force about −0.1 w)
    problem = square_wave(0.3, damping_ratio=0.08, stiffness_ratio=2.0)
    with pytest.warns(ModelAssumptionWarning, match="contact loss"):
        response = orbit_response(problem, samples=256)
    loss = response.metrics["contact_loss"]
    assert loss["detected"] and not response.metrics["valid"] and not response.valid
    assert any("contact loss" in message for message in response.warnings)
    assert len(loss["start_times"]) == len(loss["durations"]) >= 1
    assert loss["total_duration"] == pytest.approx(sum(loss["durations"]), rel=1e-14)
    assert 0.0 < loss["total_duration"] < problem.period
    pieces = dense(problem, response.initial_state)
    exact_min = min((problem.stiffness[i] * pieces[i][1]).min() for i in range(2))
    assert exact_min < 0.0
    # 256 samples per interval: ω·h ≈ 0.07, a sampled extreme is off by <= (ωh)²/8 ≈ 6e-4 of the ~100 N swing
    assert loss["min_force"] == pytest.approx(exact_min, abs=1e-3 * FORCE)
    assert loss["min_force"] >= exact_min
    assert loss["min_force_ratio"] == pytest.approx(loss["min_force"] / FORCE, rel=1e-14)
    # the separation starts and ends where the force crosses zero, and the force is negative in between
    step = problem.period / (2 * 256)
    for start, length in zip(loss["start_times"], loss["durations"], strict=True):
        x, _ = evaluate_orbit(problem, response.initial_state, np.array([start, start + 0.5 * length,
                                                                          start + length]))
        assert abs(x[0]) < 1e-3 * FORCE / STIFFNESS and abs(x[2]) < 1e-3 * FORCE / STIFFNESS
        assert x[1] < 0.0
        assert length > step


def test_a_nearby_point_that_stays_in_contact_is_not_flagged():
    # the same mesh with ζ = 0.1 instead of 0.08: the overshoot stops short of zero (minimum force about +0.06 w)
    problem = square_wave(0.3, damping_ratio=0.1, stiffness_ratio=2.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ModelAssumptionWarning)
        response = orbit_response(problem, samples=256)
    loss = response.metrics["contact_loss"]
    assert not loss["detected"] and loss["start_times"] == [] and loss["total_duration"] == 0.0
    assert 0.0 < loss["min_force"] < 0.1 * FORCE and response.valid and response.warnings == ()


def test_contact_loss_is_flagged_on_a_transient_response_too():
    problem = square_wave(0.3, damping_ratio=0.08, stiffness_ratio=2.0)
    history = transient_from_rest(problem, periods=12)
    with pytest.warns(ModelAssumptionWarning, match="contact loss"):
        response = response_from_transient(problem, history)
    assert response.metrics["contact_loss"]["detected"] and not response.valid
    assert response.metrics["transient_periods"] == 12


# ------------------------------------------------------------------------------ transient vs periodic metrics
def test_transient_response_settles_on_the_periodic_metrics():
    problem = square_wave(0.3, damping_ratio=0.05)
    periodic = orbit_response(problem, samples=320).metrics
    # 320 steps per interval: ω·h <= 0.05, the RK4 error stays near 1e-7 of the response
    history = transient_from_rest(problem, periods=25, steps_per_interval=320)
    transient = response_from_transient(problem, history).metrics
    for key in ("kv", "max_system_load_ratio", "dte_mean", "dte_rms", "dte_peak_to_peak"):
        assert transient[key] == pytest.approx(periodic[key], rel=1e-6), key
    assert transient["transient_last_period_change"] < 1e-7
    assert transient["floquet_multipliers_abs"] == pytest.approx(periodic["floquet_multipliers_abs"], rel=1e-12)


@pytest.mark.filterwarnings("ignore:contact loss:thermogear.errors.ModelAssumptionWarning")
def test_an_unstable_transient_is_marked_invalid():
    problem = square_wave(2.3, damping_ratio=0.005)
    history = transient_from_rest(problem, periods=5)
    with pytest.warns(ModelAssumptionWarning, match="parametric instability"):
        response = response_from_transient(problem, history)
    assert not response.metrics["stable"] and not response.valid


# ------------------------------------------------------------------------------ no NaN ever
@settings(max_examples=40, deadline=None)
@given(ratio=st.floats(0.05, 3.0), zeta=st.floats(1e-3, 3.0), stiffness_ratio=st.floats(1.0, 4.0),
       contact_ratio=st.floats(1.05, 1.95), force=st.floats(1e-3, 1e6))
def test_any_valid_square_wave_gives_finite_metrics_or_a_model_limit_error(ratio, zeta, stiffness_ratio,
                                                                           contact_ratio, force):
    damping = 2.0 * zeta * MASS * OMEGA
    problem = MeshDynamicsProblem.square_wave(
        mass=MASS, mesh_period=1.0 / (100.0 * ratio), contact_ratio=contact_ratio, single_stiffness=STIFFNESS,
        double_stiffness=stiffness_ratio * STIFFNESS, single_damping=damping, double_damping=damping, force=force)
    try:
        orbit = periodic_steady_state(problem, samples_per_interval=8)
    except ModelLimitError:
        return
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ModelAssumptionWarning)
        response = response_from_orbit(problem, orbit)
    assert np.all(np.isfinite(response.displacement)) and np.all(np.isfinite(response.velocity))
    text = json.dumps(response.metrics_json())
    assert "NaN" not in text and "Infinity" not in text


def test_non_finite_metrics_raise_instead_of_returning_nan():
    problem = square_wave()
    orbit = periodic_steady_state(problem, samples_per_interval=4)
    bad = orbit.displacement.copy()
    bad[3] = np.nan
    with pytest.raises(ModelLimitError, match="not finite"):
        compute_metrics(problem, orbit.time, bad, orbit.velocity, orbit.interval, orbit.multipliers)


# ------------------------------------------------------------------------------ problem input checks
def _arguments(**changes):
    arguments = {"mass": 1.0, "nodes": [0.0, 1e-3, 3e-3], "stiffness": [2e5, 1e5], "damping": [10.0, 8.0],
                 "force": 100.0, "contact_count": [2, 1]}
    arguments.update(changes)
    return arguments


@pytest.mark.parametrize("changes, key", [
    ({"mass": -1.0}, "mass"), ({"mass": 0.0}, "mass"), ({"mass": np.nan}, "mass"),
    ({"stiffness": [np.nan, 1e5]}, "stiffness"), ({"stiffness": [2e5, 0.0]}, "stiffness"),
    ({"stiffness": [2e5, 1e5, 1e5]}, "stiffness"), ({"damping": [10.0]}, "damping"),
    ({"damping": [-1.0, 8.0]}, "damping"), ({"damping": [np.inf, 8.0]}, "damping"),
    ({"nodes": [0.0, 3e-3, 1e-3]}, "nodes"), ({"nodes": [0.0, 1e-3, 1e-3]}, "nodes"),
    ({"nodes": [1e-4, 1e-3, 3e-3]}, "nodes[0]"), ({"nodes": [0.0]}, "nodes"), ({"nodes": [[0.0, 1e-3]]}, "nodes"),
    ({"nodes": [0.0, np.nan, 3e-3]}, "nodes"), ({"force": -5.0}, "force"), ({"force": np.nan}, "force"),
    ({"force": [100.0, 100.0, 100.0]}, "force"), ({"contact_count": [2]}, "contact_count"),
    ({"contact_count": [0, 1]}, "contact_count"), ({"contact_count": [1.5, 1]}, "contact_count"),
    ({"pair_stiffness": [[1e5, 1e5], [1e5, 1e5]]}, "pair_stiffness"),
    ({"pair_stiffness": [[1e5, 1e5], [1e5, 0.0]], "pair_damping": [[1.0], [1.0]]}, "pair_damping"),
    ({"pair_damping": [[5.0, 8.0], [5.0, 0.0]]}, "pair_damping"), ({"face_width": 0.0}, "face_width"),
])
def test_bad_problem_inputs_are_refused_naming_the_key(changes, key):
    with pytest.raises(ProblemError) as error:
        MeshDynamicsProblem(**_arguments(**changes))
    assert error.value.quantity == key  # a solver quantity, not a case-file key
    assert not isinstance(error.value, CaseError)
    assert error.value.allowed and error.value.reason


def test_problem_arrays_are_read_only_copies():
    stiffness = np.array([2e5, 1e5])
    problem = MeshDynamicsProblem(**_arguments(stiffness=stiffness))
    stiffness[0] = 1.0
    assert problem.stiffness[0] == 2e5
    with pytest.raises(ValueError):
        problem.stiffness[0] = 3.0


def test_derived_quantities_of_the_problem():
    problem = MeshDynamicsProblem(**_arguments())
    assert problem.period == 3e-3 and problem.mesh_frequency == pytest.approx(1.0 / 3e-3)
    assert problem.mean_stiffness == pytest.approx((2e5 * 1e-3 + 1e5 * 2e-3) / 3e-3)
    assert problem.natural_frequency == pytest.approx(np.sqrt(problem.mean_stiffness) / (2 * np.pi))
    assert problem.frequency_ratio == pytest.approx(problem.mesh_frequency / problem.natural_frequency)
    np.testing.assert_allclose(problem.static_transmission_error, [100.0 / 2e5, 100.0 / 1e5])
    assert problem.regions == (1, 2) and region_name(1) == "single" and region_name(2) == "double"
    assert region_name(7) == "7_pairs"
    with pytest.raises(ProblemError, match="contact_ratio"):
        MeshDynamicsProblem.square_wave(mass=1.0, mesh_period=1e-3, contact_ratio=2.2, single_stiffness=1e5,
                                        double_stiffness=2e5, single_damping=1.0, double_damping=1.0, force=1.0)


# ------------------------------------------------------------------------------ spectra
def test_spectrum_of_a_harmonically_forced_response_peaks_at_the_mesh_frequency():
    # constant k and c, load w0·(1 + a·sin 2πτ/T) held constant on each of N intervals: the load's fundamental is
    # a·w0·sin(π/N)/(π/N) (zero-order hold), so x has exactly the FRF amplitude at f_m and nothing else below
    # harmonic N − 1
    intervals, a, period = 256, 0.1, 1.0 / 37.0
    nodes = np.linspace(0.0, period, intervals + 1)
    middle = 0.5 * (nodes[1:] + nodes[:-1])
    force = FORCE * (1.0 + a * np.sin(2.0 * np.pi * middle / period))
    damping = 2.0 * 0.05 * MASS * OMEGA
    problem = MeshDynamicsProblem(mass=MASS, nodes=nodes, stiffness=np.full(intervals, STIFFNESS),
                                  damping=np.full(intervals, damping), force=force,
                                  contact_count=np.ones(intervals, dtype=int))
    response = orbit_response(problem, samples=4)
    frequency, amplitude = response.spectrum("displacement", points=1024)
    peak = 1 + int(np.argmax(amplitude[1:]))
    assert frequency[peak] == pytest.approx(problem.mesh_frequency, rel=1e-12)
    omega = 2.0 * np.pi / period
    hold = np.sin(np.pi / intervals) / (np.pi / intervals)
    expected = a * FORCE * hold / abs(STIFFNESS - MASS * omega**2 + 1j * damping * omega)
    assert amplitude[1] == pytest.approx(expected, rel=1e-6)
    assert amplitude[0] == pytest.approx(FORCE / STIFFNESS, rel=1e-9)
    assert np.all(amplitude[2:200] < 1e-6 * amplitude[1])
    _, load = response.spectrum("system_load", points=1024)
    assert 1 + int(np.argmax(load[1:])) == 1


def test_harmonic_and_signal_spectra_of_a_sine():
    period = 2e-3
    time = np.linspace(0.0, period, 401)
    frequency, amplitude = harmonic_spectrum(time, 3.0 + 0.7 * np.sin(2 * np.pi * 5 * time / period), period, 512)
    assert frequency[5] == pytest.approx(5 / period) and amplitude[5] == pytest.approx(0.7, rel=1e-3)
    assert amplitude[0] == pytest.approx(3.0, rel=1e-6)
    long = np.linspace(0.0, 0.5, 20001)
    frequency, amplitude = signal_spectrum(long, 0.7 * np.sin(2 * np.pi * 440.0 * long))
    assert frequency[np.argmax(amplitude)] == pytest.approx(440.0, abs=2.0)
    assert amplitude.max() == pytest.approx(0.7, rel=0.02)


def test_spectrum_refuses_an_unknown_quantity():
    with pytest.raises(ProblemError, match="quantity"):
        orbit_response(square_wave(), samples=4).spectrum("temperature")


# ------------------------------------------------------------------------------ export
def test_netcdf_round_trip_keeps_arrays_and_metrics(tmp_path):
    import xarray as xr

    problem = square_wave(0.3, face_width=0.025)
    history = transient_from_rest(problem, periods=6, steps_per_interval=32)
    response = response_from_transient(problem, history)
    target = response.save(tmp_path / "nested" / "response.nc")
    assert sorted(os.listdir(target.parent)) == ["response.nc"]  # no temporary file left behind
    with xr.open_dataset(target, engine="h5netcdf") as dataset:
        loaded = dataset.load()
    np.testing.assert_array_equal(loaded["displacement"].values, response.displacement)
    np.testing.assert_array_equal(loaded["velocity"].values, response.velocity)
    np.testing.assert_array_equal(loaded["time"].values, response.time)
    np.testing.assert_array_equal(loaded["pair_load"].values, response.pair_loads())
    np.testing.assert_array_equal(loaded["history_displacement"].values, history.displacement)
    np.testing.assert_array_equal(loaded["node_time"].values, problem.nodes)
    np.testing.assert_array_equal(loaded["interval_contact_count"].values, problem.contact_count)
    assert json.loads(loaded.attrs["metrics_json"]) == json.loads(json.dumps(response.metrics_json()))
    assert loaded.attrs["kv"] == response.metrics["kv"]
    assert loaded.attrs["valid"] == 1 and loaded.attrs["face_width_m"] == 0.025


def test_save_is_atomic_a_failed_write_keeps_the_previous_file(tmp_path, monkeypatch):
    import xarray as xr

    response = orbit_response(square_wave(), samples=8)
    target = response.save(tmp_path / "response.nc")
    before = target.read_bytes()

    def broken(self, path, *args, **kwargs):
        with open(path, "wb") as handle:
            handle.write(b"half a file")
        raise OSError("disk full")

    monkeypatch.setattr(xr.Dataset, "to_netcdf", broken)
    with pytest.raises(OSError, match="disk full"):
        orbit_response(square_wave(0.5), samples=8).save(target)
    assert target.read_bytes() == before
    assert sorted(os.listdir(tmp_path)) == ["response.nc"]


def test_plots_return_figures():
    import matplotlib.pyplot as plt

    problem = square_wave()
    response = orbit_response(problem, samples=8)
    other = response_from_transient(problem, transient_from_rest(problem, periods=3, steps_per_interval=16))
    figures = [response.plot_displacement(other), response.plot_phase(), response.plot_velocity(periods=2),
               response.plot_loads(other), response.plot_spectrum("system_load")]
    for figure in figures:
        assert figure.axes
        plt.close(figure)
