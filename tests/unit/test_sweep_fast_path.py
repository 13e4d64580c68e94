"""The sweep's fast path gives the numbers of one Simulation per point, for every sweepable key and both models.

Both paths ask the same mesh model and evaluate the same exact periodic orbit at the same samples; the fast path
reuses one mesh period per group and scales it in time, load and damping. Only rounding separates them, so 1e-9
relative on every stored variable is a wide margin (measured: below 1e-13). The grids cover what the issue named:
speed × power (the load changes with the speed), speed × torque, oil temperature, flank-temperature offset,
module, face width and X_te.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.sweep.batch import evaluate_block
from thermogear.sweep.inert import inert_parameters
from thermogear.sweep.study import Study

from sweep_paths import assert_fast_path_equals_simulation

GRIDS = {
    "speed x power": ["power_kw=40,80", "speed_rpm=1000:4000:4"],
    "speed x torque": ["torque_nm=250,400", "speed_rpm=1000:9000:3"],
    "oil temperature": ["oil_reference_temperature_c=30,50", "speed_rpm=1500,6000"],
    "flank-temperature offset": ["flank_temperature_offset_c=-10,0,10", "speed_rpm=1500,6000"],
    "module": ["module_mm=2.5,3", "speed_rpm=1500,6000"],
    "face width": ["face_width_mm=20,30", "speed_rpm=1500,6000"],
    "X_te": ["x_te=0.1,0.4", "speed_rpm=1500,6000"],
}


@pytest.fixture(scope="module")
def luo():
    return load_case("luo2019")


@pytest.mark.parametrize("name", list(GRIDS))
def test_fast_path_equals_one_simulation_per_point(luo, name):
    case = luo.with_changes(**{"gears.centre_distance_mm": None}) if name == "module" else luo
    study = Study.define(case, GRIDS[name], model="both", chunk_points=64)
    assert_fast_path_equals_simulation(study, name)


def test_power_sweep_keeps_the_power_so_the_load_falls_with_the_speed(luo):
    # the defect of the old fast path: a power of 80 kW gave the load of 2000 rpm at every speed
    study = Study.define(luo, ["power_kw=80", "speed_rpm=1000:4000:4"], model="elastic")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fast, _ = evaluate_block(study, study.blocks()[0], "batch")
    load = fast["static_load"].ravel()
    expected = 80e3 / (np.array([1000.0, 2000.0, 3000.0, 4000.0]) * np.pi / 30) / luo.gear_pair.pinion.base_radius
    np.testing.assert_allclose(load, expected, rtol=1e-12)


def test_an_axis_that_changes_nothing_is_named(luo):
    # luo2019's thermal model takes tabulated flank temperatures and its elastic model the oil's reference
    # temperature: the operating oil temperature enters neither, so sweeping it is flagged
    study = Study.define(luo, ["oil_temperature_c=40,70", "torque_nm=250,300", "speed_rpm=1500,3000"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the paper's 30 °C reference oil is below the oil's fitted range
        assert inert_parameters(study) == ["oil_temperature_c"]


def test_the_sweep_command_warns_about_an_inert_axis(tmp_path):
    import subprocess
    import sys

    result = subprocess.run([sys.executable, "-m", "thermogear", "sweep", "luo2019", "--vary", "oil_temperature_c=40,70",
                             "--vary", "speed_rpm=1000,2000", "--scheduler", "serial", "--out",
                             str(tmp_path / "s.zarr"), "--json"], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "warning: sweep axis 'oil_temperature_c' changes nothing" in result.stderr
