"""`stiffness --thermal` as tables with units, whatever keys its JSON gains (issue 15, part B)."""

from __future__ import annotations

import io
import json
import re

import pytest
from rich.console import Console

import inprocess_cli

from thermogear.cli.tables import dict_tables, format_value, split_unit


def render(data: dict) -> str:
    console = Console(file=io.StringIO(), width=200, markup=False, emoji=False, highlight=False)
    for item in dict_tables("Thermal stiffness", data):
        console.print(item)
    return console.file.getvalue()


@pytest.mark.parametrize(("key", "label", "unit"), [
    ("flank_temperature_c", "flank temperature", "°C"),
    ("thermal_stiffness_n_per_mm_um", "thermal stiffness", "N/(mm·μm)"),
    ("normal_load_n_per_mm", "normal load", "N/mm"),
    ("expansion_pinion_um", "expansion pinion", "μm"),
    ("stiffness_drop_percent_range", "stiffness drop range", "%"),
    ("x_te", "X_te", None),
    ("youngs_modulus_gpa", "Young's modulus", "GPa"),
    ("backlash_normal_um", "normal backlash", "μm"),
    ("load_basis", "load basis", None),
])
def test_units_come_from_the_key(key, label, unit):
    assert split_unit(key) == (label, unit)


def test_values_are_short():
    assert format_value(14.52000000000001) == "14.52"
    assert format_value(0.21662311627157446) == "0.21662"
    assert format_value(True) == "yes" and format_value(None) == "—"
    assert format_value([-0.6, 0.55]) == "-0.6, 0.55" and format_value([]) == "none"
    # a long list of numbers would widen the table: summarised
    assert format_value([0.1 * i for i in range(21)]) == "21 values, 0 to 2"


def test_nested_summary_gives_rows_and_a_matrix():
    data = {"x_te": 0.21662311627157446,
            "stiffness_drop_percent": {"A": 10.447797676446003, "C": 14.52000000000001},
            "points": {"A": {"flank_temperature_c": 80.57687607782132, "gamma": -0.5391880507140497},
                       "C": {"flank_temperature_c": 77.06897948160419, "gamma": 0.0}},
            "new_key_mpa_s": 1.23456789,
            "x_te_source": "calibrated: X_te=0.21662 gives 14.52 % drop at C [external basis]"}
    text = render(data)
    assert not re.search(r"\d\.\d{7,}", text)  # no 16-digit floats
    assert "stiffness drop, A" in text and "10.448" in text and "%" in text
    assert re.search(r"flank temperature\s*│\s*80\.577\s*│\s*77\.069\s*│\s*°C", text)  # one column per point
    assert "mPa·s" in text  # a key nobody told the table about
    assert "X_te source: calibrated: X_te=0.21662 gives 14.52 % drop at C [external basis]" in text


def test_stiffness_thermal_prints_tables_not_dicts():
    result = inprocess_cli.run("stiffness", "luo2019", "--thermal")
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert "{'" not in text and "':" not in text  # no Python dict reprs
    assert not re.search(r"\d\.\d{9,}", text)
    assert "N/(mm·μm)" in text and "°C" in text and "μm" in text
    # every number of the JSON's thermal block has a row: the drop at C to 5 digits
    data = json.loads(inprocess_cli.run("stiffness", "luo2019", "--thermal", "--json").stdout)
    assert format_value(data["thermal"]["stiffness_drop_percent"]["C"]) in text


def test_lists_of_sentences_are_lines_and_every_number_has_a_unit(tmp_path):
    # a plausibility flag (a sentence) in a list used to be printed as a Python list in a cell, widening the table
    # past 200 characters; "youngs modulus gpa" had an empty unit column
    case = tmp_path / "tight.toml"
    from pathlib import Path

    source = Path(__file__).resolve().parents[1] / "data" / "user_pair.toml"
    case.write_text(source.read_text(encoding="utf-8").replace("module_mm = 3.0", "module_mm = 3.0\n"
                                                                "backlash_normal_um = 20.0"), encoding="utf-8")
    result = inprocess_cli.run("stiffness", str(case), "--thermal")
    assert result.returncode == 0, result.stderr
    text = result.stdout
    table = [line for line in text.splitlines() if line[:1] in "┏┃┡│└"]
    assert table and max(len(line) for line in table) < 120
    assert "plausibility: the backlash closes at a bulk temperature" in text  # a line of its own
    assert re.search(r"Young's modulus, pinion\s*│\s*[0-9.]+\s*│\s*GPa", text)
    assert "youngs" not in text and "['" not in text
    for line in table:  # every number has a unit or – (dimensionless)
        cells = [cell.strip() for cell in line.strip("│").split("│")]
        if len(cells) == 3 and re.fullmatch(r"-?[0-9.]+(e[-+]?[0-9]+)?", cells[1]):
            assert cells[2], line
