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
