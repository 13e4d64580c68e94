"""`thermogear fem`: JSON keys, plots, and the "fem" providers driving the thermal chain end to end."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

KEYS = ("compliance_fe_vs_pem_percent", "x_te", "flank_temperature_c", "base_temperature_c", "bore_temperature_c",
        "expansion_fe_vs_analytical_percent", "refinement_change_percent")


@pytest.fixture(scope="module")
def run_json(tmp_path_factory):
    folder = tmp_path_factory.mktemp("plots")
    result = subprocess.run([sys.executable, "-m", "thermogear", "fem", "luo2019", "--json", "--plot", str(folder)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout), folder


def test_json_has_the_issue_keys(run_json):
    data, _ = run_json
    for key in KEYS:
        assert key in data
    assert set(data["flank_temperature_c"]) == {"A", "C", "E"}
    assert {"max_abs", "mean_abs"} <= set(data["compliance_fe_vs_pem_percent"])
    assert data["refinement_change_percent"] < 2.0


def test_plots_are_written(run_json):
    _, folder = run_json
    names = {path.name for path in folder.iterdir()}
    assert {"fig3b_temperature_field.png", "fig3c_flank_temperature.png", "fig15_stiffness_along_path.png"} <= names


def test_bad_case_exits_2():
    result = subprocess.run([sys.executable, "-m", "thermogear", "fem", "no_such_case"], capture_output=True, text=True)
    assert result.returncode == 2


def test_fem_temperature_and_x_te_drive_the_chain():
    import thermogear.fem.provider  # noqa: F401
    from thermogear.case import load_case
    from thermogear.fem.verification import cached_analysis
    from thermogear.simulation import Simulation
    from thermogear.thermal.case_stiffness import thermal_stiffness

    case = load_case("luo2019").with_changes(**{
        "temperature": {"model": "fem", "reference_c": 20.0},
        "thermal": {"model": "luo2020", "x_te_source": "fem", "load_basis": "external"}})
    points = case.gear_pair.path_points
    result = thermal_stiffness(case, np.array([points[name] for name in "ACE"]))
    analysis = cached_analysis(case)
    assert result.x_te == pytest.approx(analysis.x_te)
    assert result.temperature.source == "fem"
    assert np.all(result.drop_percent > 0)
    simulation = Simulation(case, "thermal").run()
    assert simulation is not None
