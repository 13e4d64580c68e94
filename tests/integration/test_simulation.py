"""Simulation wiring: the elastic and thermal models share one pipeline; the three solvers agree on the steady
orbit of the real luo2019 problem; the transient from rest converges to the periodic orbit."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
from thermogear.dynamics.transients.reference import reference_solve_ivp
from thermogear.dynamics.transients.transient import transient_from_rest
from thermogear.errors import CaseError
from thermogear.simulation import Simulation, compare

# luo2019's 30 °C reference oil lies 10 K below SCH632's data (40-100 °C): the warning is expected here
pytestmark = pytest.mark.filterwarnings("ignore::thermogear.errors.ExtrapolationWarning")


@pytest.fixture(scope="module")
def problem(luo2019):
    return Simulation(luo2019, "thermal", points_per_period=256).problem


def relative_difference(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def test_periodic_orbit_matches_solve_ivp_started_on_it(problem):
    orbit = periodic_steady_state(problem, samples_per_interval=4)
    x0, v0 = orbit.initial_state
    reference = reference_solve_ivp(problem, periods=1, rtol=1e-12, samples_per_interval=4, x0=x0, v0=v0)
    assert relative_difference(reference.displacement, orbit.displacement) < 1e-6
    assert relative_difference(reference.velocity, orbit.velocity) < 1e-6


def test_solve_ivp_from_rest_converges_to_the_periodic_orbit(problem):
    # the largest Floquet multiplier is ~7e-6 per period (thermal damping), so 6 periods leave < 1e-12 of the start
    orbit = periodic_steady_state(problem, samples_per_interval=4)
    history = reference_solve_ivp(problem, periods=6, rtol=1e-12, samples_per_interval=4)
    _, x, v, _ = history.last_period()
    assert relative_difference(x, orbit.displacement) < 1e-6
    assert relative_difference(v, orbit.velocity) < 1e-6


def test_rk4_transient_from_rest_converges_to_the_periodic_orbit(problem):
    orbit = periodic_steady_state(problem, samples_per_interval=8)
    history = transient_from_rest(problem, periods=8, steps_per_interval=8)
    _, x, v, _ = history.last_period()
    # RK4 global error ~ (omega_n h)^4 with omega_n h ~ 0.03 here: well below 1e-6 of the orbit
    assert relative_difference(x, orbit.displacement) < 1e-6
    assert history.convergence()[-1] < 1e-6 < history.convergence()[0]


def test_thermal_model_without_coupling_has_the_elastic_stiffness(luo2019):
    uncoupled = luo2019.with_changes(**{"thermal.x_te_source": "given", "thermal.x_te": 0.0})
    elastic = Simulation(uncoupled, "elastic", points_per_period=128)
    thermal = Simulation(uncoupled, "thermal", points_per_period=128)
    assert np.array_equal(elastic.grid.nodes, thermal.grid.nodes)
    np.testing.assert_allclose(thermal.pair_stiffness, elastic.pair_stiffness, rtol=1e-9)
    # damping still differs: the thermal model reads the viscosity at the flank temperature (hotter, thinner)
    assert np.all(thermal.mesh_damping > elastic.mesh_damping)


def test_compare_runs_both_models_and_heat_lowers_the_mesh_stiffness(luo2019):
    responses = compare(Simulation(luo2019, points_per_period=256))
    assert set(responses) == {"elastic", "thermal"}
    assert responses["thermal"].metrics["natural_frequency_hz"] < responses["elastic"].metrics["natural_frequency_hz"]
    for response in responses.values():
        assert response.valid
        assert np.all(np.isfinite(response.displacement))


def test_periodic_and_transient_methods_give_the_same_metrics(luo2019):
    simulation = Simulation(luo2019, "elastic", points_per_period=256)
    periodic = simulation.run("periodic").metrics
    transient = simulation.run("transient").metrics
    assert transient["kv"] == pytest.approx(periodic["kv"], rel=1e-4)
    assert transient["max_system_load_ratio"] == pytest.approx(periodic["max_system_load_ratio"], rel=1e-4)


def test_unknown_model_is_refused(luo2019):
    with pytest.raises(CaseError, match="model"):
        Simulation(luo2019, "plastic")


def test_responses_are_labelled_with_their_model(luo2019):
    # plots and result files name the curves by model (elastic / thermal), not by solver
    for model in ("elastic", "thermal"):
        response = Simulation(luo2019, model, points_per_period=128).run("periodic")
        assert response.label == model
        assert response.to_xarray().attrs["label"] == model
