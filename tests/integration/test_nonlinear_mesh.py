"""The nonlinear mesh wired to gear cases: the linear limit, through resonance, up and down sweeps, the CLI."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest

import inprocess_cli

from thermogear.case import load_case
from thermogear.simulation import Simulation
from thermogear.sweep.branches import branch_study, hysteresis_bands
from thermogear.sweep.study import Study


@pytest.fixture(scope="module")
def nonlinear_luo():
    return load_case("luo2019").with_changes(**{"dynamics.mesh": "nonlinear"})


def _quiet(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args, **kwargs)


@pytest.mark.parametrize("model", ["elastic", "thermal"])
def test_without_contact_loss_the_nonlinear_result_is_the_linear_one(nonlinear_luo, model):
    # luo2019 at 2000 rpm keeps every pair in contact: the backlash model is then the linear model exactly, so
    # Kv and the DTE agree to 1e-6 (the tolerance). The nonlinear history holds the exact extrema of x; the
    # linear orbit is sampled, 4 points per interval by default (1.6e-6 short of the true peak-to-peak here), so
    # the linear reference is sampled 64 times per interval (sampling error ~ (1/64)² smaller)
    fine = load_case("luo2019").with_changes(**{"dynamics.samples_per_interval": 64})
    linear = _quiet(Simulation(fine, model).run).metrics
    nonlinear = _quiet(Simulation(nonlinear_luo, model).run).metrics
    assert nonlinear["contact_loss_fraction"] == 0.0 and not nonlinear["back_side_contact"]
    for name in ("kv", "dte_peak_to_peak", "dte_rms", "dte_mean"):
        assert nonlinear[name] == pytest.approx(linear[name], rel=1e-6), name
    assert nonlinear["response"] == "periodic"


def test_near_resonance_the_teeth_separate_and_the_loads_stay_finite(nonlinear_luo):
    # at 13 000 rpm the linear model has no steady state (Floquet multiplier > 1); the backlash model does
    case = nonlinear_luo.with_changes(**{"operating.speed_rpm": 13000.0})
    metrics = _quiet(Simulation(case, "elastic").run).metrics
    assert 0.0 < metrics["contact_loss_fraction"] < 1.0
    assert np.isfinite(metrics["kv"]) and metrics["kv"] > 1.0
    assert metrics["min_mesh_force"] >= -1e-9 * metrics["static_load"] or metrics["back_side_contact"]


def test_speed_sweep_through_the_primary_resonance_shows_hysteresis(nonlinear_luo):
    # luo2019's mesh frequency meets its natural frequency near 13 400 rpm (f_n ≈ 6 kHz, z1 = 27); the backlash
    # softens the mesh, so the down sweep stays on the high-amplitude branch below where the up sweep jumps
    study = Study.define(nonlinear_luo, ["speed_rpm=7000:16000:91"], model="elastic")
    dataset = _quiet(branch_study, study, "both")
    kinds = set(np.asarray(dataset["response"].values).ravel().astype(str))
    assert kinds <= {"periodic", "subharmonic", "non-periodic"}  # no point refused as 'unstable' or failed
    for name in ("kv", "dte_peak_to_peak"):
        assert np.all(np.isfinite(dataset[name].values)), name
    loss = dataset["contact_loss_fraction"].sel(direction="up", model="elastic").values
    speeds = dataset["speed_rpm"].values
    assert np.any(loss[(speeds > 10000) & (speeds < 14500)] > 0.0)  # contact lost near the peak
    bands = hysteresis_bands(dataset)["elastic"]
    assert bands["differ"] and bands["band_rpm"][1] - bands["band_rpm"][0] > 0.0
    assert any(item["amplitude"] == "rises" for item in bands["up_sweep_jumps"])


def _cli(*arguments):
    return inprocess_cli.run(*arguments)


def test_sweep_cli_writes_both_directions_and_refuses_a_bad_one(tmp_path, nonlinear_luo):
    out = tmp_path / "branches.zarr"
    result = _cli("sweep", "fzg_type_c", "--vary", "speed_rpm=2000:24000:12", "--model", "elastic",
                  "--out", str(out), "--json", "--no-progress")
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["mesh"] == "nonlinear" and summary["directions"] == ["up", "down"]
    import xarray as xr

    stored = xr.open_zarr(out)
    assert stored["kv"].dims[:2] == ("direction", "model")
    bad = _cli("sweep", "fzg_type_c", "--vary", "speed_rpm=2000,3000", "--out", str(tmp_path / "x.zarr"),
               "--direction", "sideways")
    assert bad.returncode == 2 and "--direction" in bad.stderr and "Traceback" not in bad.stderr
    linear = _cli("sweep", "luo2019", "--vary", "speed_rpm=2000,3000", "--out", str(tmp_path / "y.zarr"),
                  "--direction", "up")
    assert linear.returncode == 2 and "nonlinear" in linear.stderr


def test_run_json_names_the_branch_and_the_contact_state():
    result = _cli("run", "fzg_type_c", "--json", "--model", "elastic")
    assert result.returncode == 0, result.stderr
    model = json.loads(result.stdout)["models"]["elastic"]
    assert model["mesh"] == "nonlinear" and model["response"] == "periodic"
    assert model["branch"] in ("unique", "low", "high") and model["contact_loss_fraction"] == 0.0
    assert model["back_side_contact"] is False


def test_start_up_from_rest_settles_on_the_orbit_the_shooting_finds(nonlinear_luo):
    # Luo & Li start the gears from rest; the same exact integrator run for 400 mesh periods from x = ẋ = 0 must end
    # on the periodic orbit found by shooting (contact loss included): peak-to-peak of the last period within 1e-6
    case = nonlinear_luo.with_changes(**{"operating.speed_rpm": 13000.0, "dynamics.transient_periods": 400})
    simulation = Simulation(case, "elastic")
    start_up = _quiet(simulation.run, "transient")
    orbit = _quiet(simulation.run)
    history = start_up.history
    last = history.time >= history.time[-1] - simulation.state.period
    assert np.ptp(history.displacement[last]) == pytest.approx(orbit.metrics["dte_peak_to_peak"], rel=1e-6)
    assert start_up.metrics["contact_loss_fraction"] > 0.0


@pytest.mark.parametrize("speed_rpm", [2000.0, 13000.0])
def test_a_transient_is_read_like_a_steady_response(nonlinear_luo, speed_rpm):
    # `run --method transient` on the nonlinear mesh used to fail (KeyError 'response'): the transient from rest now
    # carries the metrics of its last mesh period under the names of the steady response. After 400 periods it has
    # settled on the orbit the shooting finds (with contact loss at 13 000 rpm), so Kv, the DTE and the per-region
    # levels agree to 1e-6 (the settling tolerance is 1e-6 of the static deflection; both use the exact integrator)
    case = nonlinear_luo.with_changes(**{"operating.speed_rpm": speed_rpm, "dynamics.transient_periods": 400})
    simulation = Simulation(case, "elastic")
    transient = _quiet(simulation.run, "transient").metrics
    orbit = _quiet(simulation.run).metrics
    assert transient["response"] == "periodic" and transient["valid"] and transient["branch"] == "from rest"
    assert transient["transient_last_period_change"] <= 1e-6
    for name in ("kv", "dte_peak_to_peak", "max_system_load_ratio", "contact_loss_fraction"):
        assert transient[name] == pytest.approx(orbit[name], rel=1e-6, abs=1e-9), name
    assert transient["equilibrium_per_region"] == pytest.approx(orbit["equilibrium_per_region"], rel=1e-9)


def test_an_unsettled_transient_says_so(nonlinear_luo):
    # two mesh periods from rest are far from settled (the damping ratio is a few per cent: e-folding over tens of
    # natural periods): the response is "not settled", not valid, and the words say what to do
    from thermogear.report.evaluate import model_messages

    case = nonlinear_luo.with_changes(**{"dynamics.transient_periods": 2})
    response = _quiet(Simulation(case, "elastic").run, "transient")
    assert response.metrics["response"] == "not settled" and not response.valid
    assert any("transient_periods" in text for text in model_messages(response, "elastic"))


def test_the_papers_secant_stiffness_in_the_nonlinear_mesh_is_flagged(nonlinear_luo):
    # luo2019 runs the paper's k_T (a secant stiffness at the static load, Eq. 18): as the contact stiffness of the
    # nonlinear mesh it is flagged with the reason, and with the separation where the teeth fly (13 000 rpm)
    quiet = _quiet(Simulation(nonlinear_luo, "thermal").run)
    (flag,) = [text for text in quiet.flags if "secant stiffness at the static" in text]
    assert "near the static load" in flag and "thermal.model = 'thermoelastic'" in flag
    flying = _quiet(Simulation(nonlinear_luo.with_changes(**{"operating.speed_rpm": 13000.0}), "thermal").run)
    (flag,) = [text for text in flying.flags if "secant stiffness at the static" in text]
    assert f"{100 * flying.metrics['contact_loss_fraction']:.1f} % of the period" in flag
    # the thermo-elastic model and the linear mesh are not flagged
    assert not [text for text in _quiet(Simulation(nonlinear_luo, "elastic").run).flags if "secant stiffness at the static" in text]
    linear = _quiet(Simulation(load_case("luo2019"), "thermal").run)
    assert not [text for text in linear.flags if "secant stiffness at the static" in text]
