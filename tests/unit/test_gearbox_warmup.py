"""The predicted warm-up coupled to the mesh (thermogear warmup CASE --model gearbox)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import thermogear.simulation  # noqa: F401  (registers the "gearbox" temperature model)
from thermogear.case import load_case
from thermogear.errors import CaseError
from thermogear.experiment.gearbox_warmup import gearbox_warmup, state_case
from thermogear.gearbox.backlash import backlash_change_estimate
from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point, predicted_steady_state
from thermogear.simulation import Simulation
from thermogear.temperature.source import temperature_field_from_case

CASE = Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"
pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


@pytest.fixture(scope="module")
def case():
    return load_case(CASE)


def steady(case):
    """The steady state the case's gearbox model predicts at its operating point."""
    return predicted_steady_state(gearbox_model_from_case(case), gearbox_operating_point(case.operating_point,
                                                                                         case.gearbox))


@pytest.fixture(scope="module")
def short(case):
    # 4 minutes, mesh every 60 s with its periodic response: 5 states
    return gearbox_warmup(case, duration_s=240.0, interval_s=60.0)


def test_states_follow_the_network(short):
    assert [state.time_s for state in short.states] == [0.0, 60.0, 120.0, 180.0, 240.0]
    assert short.history.energy_residual < 1e-5  # the integrator's rtol 1e-6 on the energy states
    pinion = short.history.node("pinion")
    assert np.all(np.diff(pinion) > 0.0)  # heats from the cold start
    stiffness = np.array([state.mesh_stiffness_mean for state in short.states])
    frequency = np.array([state.natural_frequency_hz for state in short.states])
    # E(T) falls with temperature (β_E < 0): stiffness and natural frequency fall while the gears heat
    assert np.all(np.diff(stiffness) < 0.0) and np.all(np.diff(frequency) < 0.0)
    assert all(state.kv is not None and state.kv >= 1.0 for state in short.states)
    smallest, at = short.smallest_backlash
    assert smallest == pytest.approx(float(np.min(short.history.backlash)), rel=1e-12) and at == 240.0


def test_state_case_at_the_steady_state_is_the_gearbox_case(case):
    # the warm-up's state case at the steady temperatures and the "gearbox" temperature model give the same mesh
    state = steady(case)
    at_state = Simulation(state_case(case, state.temperatures_c), "thermal")
    predicted = Simulation(case, "thermal")
    assert at_state.mesh_stiffness_mean == pytest.approx(predicted.mesh_stiffness_mean, rel=1e-9)
    assert temperature_field_from_case(at_state.case).wheel_base_c == pytest.approx(state.wheel_c, abs=1e-6)


def test_warm_up_ends_at_the_steady_state(case):
    long = gearbox_warmup(case, duration_s=6 * 3600.0, interval_s=3 * 3600.0, dynamics=False)
    # six hours is several of the slowest time constants (the housing's, about an hour here): within 0.5 K
    np.testing.assert_allclose(long.history.temperatures_c[:, -1], steady(case).temperatures_c,
                               atol=0.5)


def test_cold_start_below_the_reference_reports_backlash_and_the_cold_mesh(case):
    cold = gearbox_warmup(case, duration_s=60.0, interval_s=30.0, start_c=-30.0, dynamics=False)
    assert cold.cold_start.soak_c == -30.0
    # steel gears in a cast-iron housing (11.5e-6 vs 11.4e-6 /K): a 50 K soak changes the backlash by about
    # 2·sin α_w·a·Δλ·ΔT ≈ +0.35 μm (first order): the difference of a gear term and a housing term of about 38 μm
    # each; the exact geometry (involute, tooth thickness at the new operating pressure angle) differs from the
    # first-order estimate by under 1 % of those terms (0.4 μm)
    estimate = backlash_change_estimate(case.gear_pair, 11.5e-6, 11.4e-6, -50.0, -50.0)
    gear_term = abs(backlash_change_estimate(case.gear_pair, 11.5e-6, 0.0, -50.0, 0.0))
    assert cold.cold_start.change == pytest.approx(estimate, abs=0.01 * gear_term)
    # the thermo-elastic model evaluates the contracted pair (issue 28): stiffer by E(T) = E₂₀·[1 + β_E (T − 20)],
    # β_E = −3.33e-4 /K (carbon steel), against a start at the assembly temperature; the gears' contraction
    # (face width and size by λ·ΔT ≈ −0.06 %) and the housing's slightly smaller one change it by < 0.1 %, hence 0.2 %
    assembly = gearbox_warmup(case, duration_s=60.0, interval_s=60.0, start_c=20.0, dynamics=False)
    ratio = cold.states[0].mesh_stiffness_mean / assembly.states[0].mesh_stiffness_mean
    assert ratio == pytest.approx(1.0 + 3.33e-4 * 50.0, rel=2e-3)
    paper = gearbox_warmup(case.with_changes(**{"thermal.model": "luo2020"}), duration_s=60.0, interval_s=60.0,
                           start_c=-30.0, dynamics=False)
    # the paper's k_T describes heating only: no mesh below the assembly temperature, the model named
    assert paper.states[0].mesh_stiffness_mean is None and "luo2020" in paper.states[0].note


def test_aluminium_housing_at_minus_30_loses_backlash(case):
    aluminium = case.with_changes(**{"gearbox.housing.material": "aluminium"})
    cold = gearbox_warmup(aluminium, duration_s=60.0, interval_s=60.0, start_c=-30.0, dynamics=False)
    # Δj ≈ 2·sin α_w·a·(λ_h − λ_g)·ΔT = 2·0.36·91.5 mm·10e-6/K·(−50 K) ≈ −33 μm; the exact geometry within 1 % of
    # the housing term (72 μm) as above
    estimate = backlash_change_estimate(case.gear_pair, 11.5e-6, 21.5e-6, -50.0, -50.0)
    housing_term = abs(backlash_change_estimate(case.gear_pair, 0.0, 21.5e-6, 0.0, -50.0))
    assert estimate < -25e-6
    assert cold.cold_start.change == pytest.approx(estimate, abs=0.01 * housing_term)
    assert cold.cold_start.margin_to_jamming == pytest.approx(cold.cold_start.nominal + cold.cold_start.change)


@pytest.mark.parametrize("arguments, key", [
    (dict(duration_s=0.0), "--duration-s"), (dict(interval_s=7.0), "--interval-s"),
    (dict(start_c=-50.0), "--start-c"), (dict(interval_s=-1.0), "--interval-s"),
])
def test_bad_arguments(case, arguments, key):
    with pytest.raises(CaseError) as error:
        gearbox_warmup(case, **({"duration_s": 60.0, "interval_s": 30.0} | arguments))
    assert error.value.key == key


def test_cli_json_and_plot(tmp_path):
    from typer.testing import CliRunner

    from thermogear.cli.app import app
    import thermogear.cli.warmup  # noqa: F401

    figure = tmp_path / "warmup.png"
    result = CliRunner().invoke(app, ["warmup", str(CASE), "--model", "gearbox", "--duration-s", "120",
                                      "--interval-s", "60", "--no-dynamics", "--json", "--plot", str(figure)])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout[result.stdout.index("{"):])
    assert payload["model"] == "gearbox" and len(payload["states"]) == 3
    assert set(payload["history"]) >= {"pinion_c", "oil_c", "mesh_loss_w", "bearing_loss_w", "backlash_um"}
    assert figure.stat().st_size > 10_000
