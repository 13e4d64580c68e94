"""`thermogear --version` and `thermogear schema` as a readable table (issue 24, "what users expect")."""

from __future__ import annotations

import json
import subprocess

import pytest

import inprocess_cli

import thermogear
from thermogear.schema import CaseFile
from thermogear.schema.reference import case_file_sections


def thermogear_command(*arguments: str) -> subprocess.CompletedProcess:
    return inprocess_cli.run(*arguments)


def test_version_prints_the_package_version():
    result = thermogear_command("--version")
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == f"thermogear {thermogear.__version__}"


def test_schema_prints_a_table_with_every_key_by_default():
    result = thermogear_command("schema")
    assert result.returncode == 0, result.stderr
    assert not result.stdout.lstrip().startswith("{")  # not the JSON schema
    lines = result.stdout.splitlines()
    for section in case_file_sections():
        assert any(line.startswith(f"[{section.name}]") for line in lines), section.name
        for key in section.keys:
            assert any(line.split()[:1] == [key.key] for line in lines), f"{section.name}.{key.key}"
    # a row reads key, unit, type, allowed range, default, meaning
    module_row = next(line.split(None, 1)[1] for line in lines if line.split()[:1] == ["module_mm"])
    assert module_row.split()[:2] == ["mm", "number"]
    assert "≥ 0.1, ≤ 100" in module_row and "required" in module_row and "module m" in module_row
    speed_row = next(line for line in lines if line.split()[:1] == ["speed_rpm"])
    assert " rpm " in speed_row and "> 0, ≤ 200000" in speed_row


def test_schema_json_is_the_case_file_json_schema():
    result = thermogear_command("schema", "--json")
    assert result.returncode == 0, result.stderr
    assert json.loads(result.stdout) == json.loads(json.dumps(CaseFile.model_json_schema()))


def test_schema_of_one_section_and_a_mistyped_section():
    result = thermogear_command("schema", "gears")
    assert result.returncode == 0, result.stderr
    titles = [line.split(":")[0] for line in result.stdout.splitlines() if line.startswith("[")]
    assert titles == ["[gears] (required)", "[gears.pinion] (required)", "[gears.wheel] (required)"]
    wrong = thermogear_command("schema", "operatin")
    assert wrong.returncode == 2
    assert "section = 'operatin'" in wrong.stderr and "did you mean 'operating'?" in wrong.stderr


@pytest.mark.parametrize("section, key, unit, default", [
    ("gears", "module_mm", "mm", None),
    ("gears", "pressure_angle_deg", "°", "20.0"),
    ("gears.pinion", "thermal_expansion_per_k", "1/K", None),  # its description ends "default [material]"
    ("material", "thermal_conductivity_w_per_m_k", "W/(m K)", "46.0"),
    ("temperature", "bulk_c", "°C", None),
    ("temperature", "model", "", '"uniform"'),
    ("fem", "oil_fraction", "–", "0.1"),  # a number with no unit is a ratio
])
def test_schema_rows_give_unit_and_default(section, key, unit, default):
    rows = {(item.section, item.key): item for part in case_file_sections() for item in part.keys}
    row = rows[(section, key)]
    assert (row.unit, row.default) == (unit, default)
    assert f"[{unit}]" not in row.meaning  # the unit has its own column
