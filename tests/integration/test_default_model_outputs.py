"""What a user's own pair under the default model says in every output: the defaults it took (notes), the keys
that have no effect, the load held, the damping ratios no gear mesh has (issue 24)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from thermogear.case import load_case

DATA = Path(__file__).resolve().parents[1] / "data"
MINIMAL = DATA / "minimal_pair.toml"  # no [lubricant], [temperature] or [thermal] section
USER_PAIR = DATA / "user_pair.toml"


def _cli(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "thermogear", *args], capture_output=True, text=True, timeout=300)


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
