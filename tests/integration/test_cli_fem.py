"""`thermogear fem`: JSON keys, plots, and the "fem" providers driving the thermal chain end to end."""

from __future__ import annotations

import json

import numpy as np
import pytest

import inprocess_cli

KEYS = ("compliance_fe_vs_pem_percent", "x_te", "flank_temperature_c", "base_temperature_c", "bore_temperature_c",
        "expansion_fe_vs_analytical_percent", "refinement_change_percent")


@pytest.fixture(scope="module")
def run_json(tmp_path_factory):
    folder = tmp_path_factory.mktemp("plots")
    result = inprocess_cli.run("fem", "luo2019", "--json", "--plot", str(folder))
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
    result = inprocess_cli.run("fem", "no_such_case")
    assert result.returncode == 2


def test_fem_temperature_and_x_te_drive_the_chain():
    import thermogear.fem.provider  # noqa: F401
    from thermogear.case import load_case
    from thermogear.fem.inputs import fem_inputs
    from thermogear.fem.verification import cached_analysis
    from thermogear.simulation import Simulation
    from thermogear.case.pieces import call_with_pieces
    from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model

    case = load_case("luo2019").with_changes(**{
        "temperature": {"model": "fem", "reference_c": 20.0},
        "thermal": {"model": "luo2020", "x_te_source": "fem", "load_basis": "external"}})
    points = case.gear_pair.path_points
    result = call_with_pieces(paper_thermal_model, case).thermal_stiffness(np.array([points[name] for name in "ACE"]))
    analysis = cached_analysis(fem_inputs(case))
    assert result.x_te == pytest.approx(analysis.x_te)
    assert result.temperature.source == "fem"
    assert np.all(result.drop_percent > 0)
    simulation = Simulation(case, "thermal").run()
    assert simulation is not None


def test_a_user_pair_is_told_what_x_te_and_the_drop_mean():
    # `fem` on a user's pair printed X_te and a drop of tens of per cent without a word: now it says what they are,
    # how much E(T) can explain, and that the paper's model is not predictive for this pair (from the case's
    # content: its X_te is not calibrated); the paper's case, which calibrates X_te, is told the calibration instead
    from pathlib import Path

    user = Path(__file__).resolve().parents[1] / "data" / "user_pair.toml"
    result = inprocess_cli.run("fem", str(user), "--no-refinement")
    assert result.returncode == 0, result.stderr
    notes = [line for line in result.stdout.splitlines() if line.startswith("note: ")]
    assert len(notes) == 3, notes
    assert "Eqs. 17–18" in notes[0] and "no unique definition" in notes[0]
    import re

    # |β_E| 3.37e-4 /K × the FE flank rise ≈ 59 K ≈ 2.0 %; 0.1 % allows the FE temperature to move by 3 K
    limit = float(re.search(r"at most ([0-9.]+) %", notes[1]).group(1))
    assert limit == pytest.approx(2.0, abs=0.1)
    assert "not predictive for this pair" in notes[2]


def test_the_calibrated_paper_case_is_told_its_calibration(run_json):
    data, _ = run_json
    notes = data["interpretation"]["notes"]
    assert any("calibrates X_te" in text and "by construction" in text for text in notes)
    assert not any("not predictive" in text for text in notes)
    # E(T) explains at most |β_E|·ΔT of the drop; the paper's 14.52 % drop is several times that
    assert 0.0 < data["interpretation"]["youngs_modulus_change_limit_percent"] < 5.0


def test_a_cold_case_is_told_there_is_no_x_te_to_verify(tmp_path):
    """Oil at −30 °C, assembled at 20 °C: the FE teeth contract; the paper's X_te (heating only) is not read as a
    bad thermal.x_te (issue 28) but refused once, naming the model it belongs to."""
    from thermogear.case import parameter_set_path

    text = parameter_set_path("fzg_type_c").read_text(encoding="utf-8")
    assert "operating_temperature_c = 60.0" in text
    path = tmp_path / "cold.toml"
    path.write_text(text.replace("operating_temperature_c = 60.0", "operating_temperature_c = -30.0"),
                    encoding="utf-8")
    result = inprocess_cli.run("fem", str(path), "--no-refinement", "--json")
    assert result.returncode == 2, (result.stdout[-300:], result.stderr)
    message = " ".join(result.stderr.split())
    assert "no X_te to verify" in message and "thermal.model = 'luo2020'" in message and "Traceback" not in message
