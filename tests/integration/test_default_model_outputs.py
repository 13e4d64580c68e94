"""What a user's own pair under the default model says in every output: the defaults it took (notes), the keys
that have no effect, the load held, the damping ratios no gear mesh has (issue 24)."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest

import inprocess_cli

from thermogear.case import load_case

DATA = Path(__file__).resolve().parents[1] / "data"
MINIMAL = DATA / "minimal_pair.toml"  # no [lubricant], [temperature] or [thermal] section
USER_PAIR = DATA / "user_pair.toml"


def _cli(*args: str) -> subprocess.CompletedProcess:
    return inprocess_cli.run(*args)


def test_a_case_without_temperature_has_the_gears_at_the_oil_temperature():
    # was refused: "temperature.bulk_c = None: … model = 'uniform' needs bulk_c", even by `stiffness`
    case = load_case(str(MINIMAL))
    assert case.temperature.bulk_c == case.lubricant.operating_temperature_c == 60.0
    (note,) = case.notes
    assert "oil's operating temperature, 60 °C" in note and "bulk_c" in note
    assert load_case(str(USER_PAIR)).notes == ()  # a case that gives its temperature gets no note


@pytest.mark.parametrize("command", ["check", "stiffness", "run"])
def test_every_command_says_the_default_temperature(command):
    table = _cli(command, str(MINIMAL))
    assert table.returncode == 0, table.stderr
    assert "note: temperature: no bulk temperature given" in table.stdout
    result = _cli(command, str(MINIMAL), "--json")
    assert result.returncode == 0, result.stderr
    (note,) = json.loads(result.stdout)["notes"]
    assert "oil's operating temperature" in note


def _with(tmp_path, text: str) -> Path:
    path = tmp_path / "case.toml"
    path.write_text(USER_PAIR.read_text(encoding="utf-8") + text, encoding="utf-8")
    return path


def test_keys_of_another_model_are_named_once_by_check(tmp_path):
    # `x_te_source = "given"` without x_te under the default model passed check silently, and `stiffness --thermal`
    # then failed on it
    case = _with(tmp_path, '\n[thermal]\nx_te_source = "given"\nload_basis = "pair_share"\n'
                           '\n[dynamics]\nmesh = "linear"\ndamping_in_flight = "in_contact"\n')
    result = _cli("check", str(case))
    assert result.returncode == 0, result.stderr
    lines = [line for line in result.stderr.splitlines() if line.startswith("warning: ")]
    thermal = [line for line in lines if "thermal.x_te_source, thermal.load_basis: no effect" in line]
    flight = [line for line in lines if "dynamics.damping_in_flight: no effect" in line]
    assert len(thermal) == 1 and "thermal.model = 'luo2020'" in thermal[0]
    assert len(flight) == 1 and "dynamics.mesh = 'nonlinear'" in flight[0]
    stiffness = _cli("stiffness", str(case), "--thermal", "--json")
    assert stiffness.returncode == 0, stiffness.stderr
    assert "luo2020" not in json.loads(stiffness.stdout)["thermal"]  # incomplete: the paper's model is not beside


@pytest.mark.parametrize("name", ["luo2019", "fzg_type_c"])
def test_keys_read_by_some_output_are_not_named(name):
    # luo2019 runs the paper's model; fzg_type_c gives a complete X_te that `stiffness --thermal` shows beside
    import warnings

    from thermogear.errors import IneffectiveKeyWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        load_case(name)
    assert not [item for item in caught if issubclass(item.category, IneffectiveKeyWarning)]


def test_run_names_the_load_held_and_flags_damping_no_mesh_has(tmp_path):
    # the mesh model holds the power of a case that gives power_kw, the torque otherwise (a sweep over speed holds
    # the torque): every output of run says which, in the same words ("load held: constant torque|power")
    result = _cli("run", str(USER_PAIR), "--json")
    assert result.returncode == 0, result.stderr
    payload = json.loads(result.stdout)
    assert payload["load_held"] == "constant torque"
    # Eq. 28's friction damping grows as 1/speed: at 1500 rpm this pair's mean ζ is far above measured gear meshes
    # (0.03–0.17); the result is kept and the ratio is flagged in words, per model
    for name, model in payload["models"].items():
        assert model["damping_ratio"] > 0.34 and model["kv"] > 1.0, name
        assert any("damping ratio ζ" in text and "is above 0.34" in text for text in model["messages"]), name
    power = _with(tmp_path, "").read_text(encoding="utf-8").replace("torque_nm = 100.0", "power_kw = 15.0")
    (tmp_path / "power.toml").write_text(power, encoding="utf-8")
    table = _cli("run", str(tmp_path / "power.toml"), "--model", "elastic")
    assert table.returncode == 0, table.stderr
    assert "load held: constant power" in table.stdout and "damping ratio ζ (mean)" in table.stdout


def test_damping_ratio_is_that_of_the_mean_oscillator_and_flagged_only_above_the_limit():
    import warnings

    import numpy as np

    from thermogear.mesh.plausibility import DAMPING_RATIO_LIMIT, damping_ratio_flags
    from thermogear.simulation import Simulation

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        slow = Simulation(load_case("fzg_type_c").with_changes(**{"operating.speed_rpm": 900.0}), "elastic").state
        paper = Simulation(load_case("luo2019"), "thermal").state
    # identity: ζ = mean c / (2 sqrt(mean k · me)), time means over the grid intervals
    durations = np.diff(slow.grid.nodes)
    mean_c = float(np.dot(slow.mesh_damping, durations) / durations.sum())
    mean_k = float(np.dot(slow.mesh_stiffness, durations) / durations.sum())
    assert slow.damping_ratio == pytest.approx(mean_c / (2.0 * np.sqrt(mean_k * slow.mass)), rel=1e-12)
    # the FZG case at 900 rpm (ζ ≈ 0.7 elastic) is flagged; the paper's own thermal damping (≈ 0.30) is not
    assert slow.damping_ratio > DAMPING_RATIO_LIMIT and len(damping_ratio_flags(slow)) == 1
    assert 0.25 < paper.damping_ratio < DAMPING_RATIO_LIMIT and damping_ratio_flags(paper) == ()


def test_the_sainsot_warning_has_one_wording_once_per_call_with_advice():
    # z = 21: θ_f = 0.1435 rad is outside the fit's recorded input range [0.01, 0.12] (≥ about 26 teeth for a
    # standard tooth) while L*, M*, P*, Q* stay in its data: said once, in one wording, with what to do
    import warnings

    from thermogear.simulation import Simulation

    case = load_case(str(USER_PAIR))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("default")  # Python's own filter: each cause once per place
        for model in ("elastic", "thermal"):
            Simulation(case, model).run()
    sainsot = [str(item.message) for item in caught if "Sainsot" in str(item.message)]
    assert len(sainsot) == 1, sainsot  # was 4 (two tables per model, raised again from two caches)
    (text,) = sainsot
    assert "pinion: θ_f = 0.1435 rad" in text and "mild extrapolation" in text and "thermogear fem" in text
    lines = []
    for command in ("stiffness", "run"):
        result = _cli(command, str(USER_PAIR))
        assert result.returncode == 0, result.stderr
        found = [line for line in result.stderr.splitlines() if "Sainsot" in line]
        assert len(found) == 1, (command, found)
        lines += found
    assert lines[0] == lines[1] == f"warning: {text}"
