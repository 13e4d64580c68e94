"""A rig's oil conditioning (heater, cooler, thermostat) in the gearbox network, the FZG load-stage procedure and the
warm-up at temperatures above the material data (never a traceback)."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from thermogear.errors import CaseError
from thermogear.gearbox.description import GearboxOperatingPoint, OilConditioning
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
from thermogear.gearbox.model import GearboxThermalModel
from thermogear.gearbox.procedure import fzg_load_stages, run_load_stages

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")
POINT = GearboxOperatingPoint(2175.0, 302.0, 20.0)  # K9


def test_thermostat_power_law():
    heater = OilConditioning(90.0, heater=1000.0, cooling=300.0, gain=200.0)
    assert heater.power(80.0) == 1000.0  # 10 K below: 2000 W asked, the heater's 1000 W
    assert heater.power(88.0) == pytest.approx(400.0)  # in the proportional band
    assert heater.power(95.0) == -300.0  # the cooler's full power
    assert OilConditioning(90.0, heater=500.0).power(120.0) == 0.0  # no cooler: nothing, and not -0.0
    assert str(OilConditioning(90.0, heater=500.0).power(120.0)) == "0.0"
    with pytest.raises(CaseError, match="conditioning.setpoint_c"):
        OilConditioning(250.0, heater=1.0)


def test_a_strong_thermostat_holds_the_oil_and_the_energy_balances():
    base = illustrative_fzg_gearbox()
    held = GearboxThermalModel(dataclasses.replace(base, conditioning=OilConditioning(90.0, 3000.0, 3000.0, 3000.0)))
    state = held.steady_state(POINT)
    # P_oil,cond = 3000·(90 − T_oil): the oil within ΣP/gain of the set point
    assert abs(state.oil_c - 90.0) < state.losses.total / 3000.0
    assert state.energy_balance_w < 1e-9  # ΣP includes the conditioning (negative: the cooler takes heat out)
    free = GearboxThermalModel(base).steady_state(POINT)
    assert free.oil_c > 100.0 > state.oil_c


def test_warm_up_with_a_heater_keeps_the_energy_identity():
    model = GearboxThermalModel(dataclasses.replace(illustrative_fzg_gearbox(),
                                                    conditioning=OilConditioning(90.0, heater=1000.0)))
    history = model.warm_up(GearboxOperatingPoint(2175.0, 94.1, 20.0), 900.0, points=31, initial_c=20.0)
    assert history.conditioning[0] == 1000.0  # cold oil: the heater at full power
    assert np.all(history.conditioning >= 0.0) and np.all(history.conditioning <= 1000.0)
    assert history.energy_residual < 1e-5  # ∫ΣP dt = ΔΣCT + ∫Q_out dt, to about the integrator's rtol


def test_fzg_stages_each_from_the_start_temperature():
    stages = fzg_load_stages(5, 7)
    assert list(stages) == ["K5", "K6", "K7"] and stages["K6"] == 135.3
    results = run_load_stages(GearboxThermalModel(illustrative_fzg_gearbox()), 2175.0, stages, duration_s=900.0,
                              conditioning=OilConditioning(90.0, heater=1000.0))
    assert [result.name for result in results] == ["K5", "K6", "K7"]
    assert results[0].oil_c < results[1].oil_c < results[2].oil_c
    # a single warm-up of K7 from 90 °C gives the same end: each stage starts afresh, not from the last one's end
    conditioned = GearboxThermalModel(dataclasses.replace(illustrative_fzg_gearbox(),
                                                          conditioning=OilConditioning(90.0, heater=1000.0)))
    alone = conditioned.warm_up(GearboxOperatingPoint(2175.0, 183.35, 20.0), 900.0, points=31, initial_c=90.0)
    np.testing.assert_allclose(results[2].end_c, alone.temperatures_c[:, -1], rtol=1e-12)
    with pytest.raises(CaseError, match="stages"):
        fzg_load_stages(12, 5)


def test_warmup_above_the_material_data_reports_instead_of_failing(tmp_path):
    # the paper's law at 4500 rpm for two hours heats the pinion to ~337 °C: the states above 200 °C keep their
    # temperatures and losses, "mesh not evaluated", and every flag is listed (a pydantic traceback before)
    from thermogear.case import load_case
    from thermogear.experiment.gearbox_warmup import gearbox_warmup

    case = load_case("fzg_test_gearbox").with_changes(**{"gearbox.friction_model": "paper",
                                                         "operating.fzg_load_stage": None,
                                                         "operating.torque_nm": 138.0})
    result = gearbox_warmup(case, duration_s=7200.0, interval_s=2400.0, dynamics=False, speed_rpm=4500.0)
    hottest = float(np.max(result.history.node("pinion")))
    assert hottest > 300.0
    skipped = [state for state in result.states if state.mesh_stiffness_mean is None]
    assert skipped and all("mesh not evaluated" in state.note for state in skipped)
    assert {"oil_above_usable", "steel_above_tempering", "above_material_data"} <= set(result.flags_raised)
    payload = json.loads(json.dumps(result.as_dict()))
    assert payload["flags_raised"]["above_material_data"]["first_time_s"] > 0.0


def test_cli_stages_json():
    from typer.testing import CliRunner

    import thermogear.cli.warmup  # noqa: F401
    from thermogear.cli.app import app

    result = CliRunner().invoke(app, ["warmup", "fzg_test_gearbox", "--model", "gearbox", "--stages", "5:6",
                                      "--duration-s", "900", "--oil-setpoint-c", "90", "--heater-w", "1000",
                                      "--json"])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout[result.stdout.index("{"):])
    assert [stage["stage"] for stage in payload["stages"]] == ["K5", "K6"] and payload["start_c"] == 90.0
    assert payload["stages"][0]["conditioning_w"] >= 0.0


def test_one_limit_for_every_command_on_a_hot_gearbox_case(tmp_path):
    # the paper's law at K7: the stable steady state has a 279.9 °C pinion (218.3 °C before the stretches of shaft between
    # gears and bearings were fins, 237 °C while both shafts shared one node).
    # `check`/`run` refuse it (the mesh cannot be evaluated above the material data) with the state in the message;
    # `gearbox` reports it with its flags
    from typer.testing import CliRunner

    import thermogear.cli.check  # noqa: F401
    import thermogear.cli.gearbox  # noqa: F401
    from thermogear.case import load_case
    from thermogear.cli.app import app
    from thermogear.gearbox.case_model import PredictedTemperatureError, load_gearbox_case

    changes = {"gearbox.friction_model": "paper", "operating.fzg_load_stage": 7}
    with pytest.raises(PredictedTemperatureError) as caught:
        load_case("fzg_test_gearbox").with_changes(**changes)
    assert caught.value.key == "temperature.model" and "above_material_data" in caught.value.state.flags
    assert "pinion 279.9 °C" in str(caught.value) and "<= 200 °C" in str(caught.value)
    # the case before the prediction, for the commands that report the network itself
    unresolved = load_case("fzg_test_gearbox").with_changes(predict_temperatures=False, **changes)
    assert unresolved.gearbox.friction_model == "paper" and unresolved.housing.temperature_c is None
    from thermogear.case import parameter_set_path

    text = parameter_set_path("fzg_test_gearbox").read_text(encoding="utf-8")
    path = tmp_path / "hot.toml"
    path.write_text(text.replace('friction_model = "schlenk"', 'friction_model = "paper"')
                    .replace("fzg_load_stage = 6", "fzg_load_stage = 7"), encoding="utf-8")
    assert load_gearbox_case(str(path)).name == "fzg_test_gearbox"  # the network's case, before the prediction
    result = CliRunner().invoke(app, ["check", str(path)])
    assert isinstance(result.exception, PredictedTemperatureError)
    result = CliRunner().invoke(app, ["gearbox", str(path), "--json"])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout[result.stdout.index("{"):])
    assert payload["pinion_c"][0][0] == pytest.approx(279.9, abs=0.1) and payload["valid"] == [[False]]
    assert "above_material_data" in payload["flags"][0][0]
