"""Steady temperatures, losses and backlash over speed × torque (thermogear.gearbox.sweep, `thermogear gearbox`)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
from thermogear.gearbox.model import GearboxThermalModel
from thermogear.gearbox.sweep import steady_sweep

CASE = Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"
pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


@pytest.fixture(scope="module")
def model():
    return GearboxThermalModel(illustrative_fzg_gearbox())


@pytest.fixture(scope="module")
def grid(model):
    return steady_sweep(model, [400.0, 1400.0, 4000.0], [50.0, 138.0, 300.0])


def test_each_point_is_the_steady_state(model, grid):
    state = model.steady_state(GearboxOperatingPoint(1400.0, 138.0, 20.0))
    np.testing.assert_allclose(grid.temperatures_c[:, 1, 1], state.temperatures_c, rtol=1e-12)
    assert grid.mesh_loss[1, 1] == pytest.approx(state.losses.mesh, rel=1e-12)
    assert grid.backlash[1, 1] == pytest.approx(state.backlash, rel=1e-12)


def test_hotter_and_tighter_with_speed_and_torque(grid):
    oil, backlash = grid.node("oil"), grid.backlash
    valid = ~grid.runaway
    for i in range(3):
        row = oil[i][valid[i]]
        assert np.all(np.diff(row) > 0.0)  # more torque, more tooth friction, hotter
        assert np.all(np.diff(backlash[i][valid[i]]) < 0.0)  # hot gears in a cooler housing: less backlash
    assert np.all(np.diff(oil[:, 0]) > 0.0)


def test_runaway_is_masked_never_a_number():
    # a 0.1 m box in still air: its stable branch at 2175 rpm ends near 129 N·m (continuation in torque), so 300 N·m
    # has no stable steady state and 50 N·m has one (hot, flagged, a result)
    import dataclasses

    base = illustrative_fzg_gearbox()
    tiny = dataclasses.replace(base.housing, length=0.1, width=0.1, height=0.1, air_speed=0.0, emissivity=0.05)
    grid = steady_sweep(GearboxThermalModel(dataclasses.replace(base, housing=tiny)), [2175.0], [50.0, 300.0])
    assert grid.runaway.tolist() == [[False, True]]
    assert grid.node("pinion")[0, 1] is np.ma.masked
    assert 100.0 < float(grid.fold_torque[0, 1]) < 300.0
    payload = grid.as_dict()
    assert payload["oil_c"][0][1] is None and payload["runaway"][0][1] is True
    assert "oil_above_usable" in payload["flags"][0][0] and payload["valid"][0] == [False, False]
    assert not any(value != value for row in payload["oil_c"] for value in row if value is not None)  # no NaN


def test_cli_gearbox_json():
    from typer.testing import CliRunner

    import thermogear.cli.gearbox  # noqa: F401
    from thermogear.cli.app import app

    result = CliRunner().invoke(app, ["gearbox", str(CASE), "--speeds", "400,1400", "--torques", "138", "--json"])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout[result.stdout.index("{"):])
    assert payload["speeds_rpm"] == [400.0, 1400.0] and len(payload["oil_c"]) == 2
    assert payload["oil_c"][0][0] < payload["oil_c"][1][0]


def test_study_of_a_gearbox_case_predicts_at_every_point():
    # a linear-mesh study over speed and torque: the fast path may not reuse one mesh period across speeds or loads
    # (the predicted temperatures follow both), so the batch and the per-point evaluations agree exactly
    from thermogear.case import load_case
    import thermogear.simulation  # noqa: F401  (registers the "gearbox" temperature model)
    from thermogear.mesh.model import MeshModel
    from thermogear.sweep.batch import evaluate_block
    from thermogear.sweep.study import Study

    # the paper's k_T (luo2020) runs on the fast path where it may: with one mesh period reused across speeds the
    # thermal Kv at 1400 rpm, 100 N·m would be 1.088 instead of the per-point 1.003
    case = load_case(CASE).with_changes(**{"dynamics.mesh": "linear", "thermal.model": "luo2020"})
    assert MeshModel(case, "thermal").damping_scaling is None
    study = Study.define(case, {"speed_rpm": "400,1400", "torque_nm": "100,138"}, model="both")
    block = study.blocks()[0]
    batch, _ = evaluate_block(study, block, "batch")
    single, _ = evaluate_block(study, block, "simulation")
    np.testing.assert_allclose(batch["kv"], single["kv"], rtol=1e-12)
    # and each point saw its own predicted temperatures: the natural frequency falls as the gears get hotter with
    # speed, and no two points share one
    frequency = batch["natural_frequency_hz"][1]  # the thermal model
    assert frequency[1, 1] < frequency[0, 1] and frequency[1, 0] < frequency[0, 0]
    assert np.unique(frequency).size == frequency.size


def test_thermal_mesh_of_a_gearbox_case_is_refused_at_another_operating_point():
    # its temperatures are the steady state at its own speed and load: the branch study of the nonlinear mesh,
    # which asks one case's mesh model at every speed, is refused instead of mixing two operating points
    from thermogear.case import load_case
    import thermogear.simulation  # noqa: F401
    from thermogear.errors import CaseError
    from thermogear.mesh.model import MeshModel

    case = load_case(CASE)
    thermal, elastic = MeshModel(case, "thermal"), MeshModel(case, "elastic")
    assert thermal.state().speed_rpm == 1400.0  # its own point
    with pytest.raises(CaseError) as error:
        thermal.state(speed_rpm=900.0)
    assert error.value.key == "operating.speed_rpm"
    assert elastic.state(speed_rpm=900.0).speed_rpm == 900.0  # the elastic model reads no temperature
