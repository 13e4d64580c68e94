"""The paper's numbers live in the paper table only (thermogear.luo2020.report.rows).

A command or a figure that shows a number of Luo & Li (2020) takes it from the table
(``luo2020.report.table.paper_reference`` / ``row``); a copy elsewhere can drift from the table and from the
validation that checks it. The scan looks for the table's *distinctive* numbers — non-integers of three or more
significant digits and integers ≥ 100 that are not whole hundreds (the paper's Table 1 inputs, round numbers such
as 20 or 0.5, and the rig's Table 3 transcription, which the bundled CSV holds and the table checks, are left out:
they coincide with ordinary constants) — as numeric literals and inside strings other than docstrings (which
document, they do not show).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

import thermogear
from thermogear.luo2020.rig.data import STATED_TORQUE_NM
from thermogear.luo2020.report.table import PAPER_ROWS, row

SOURCE = Path(thermogear.__file__).parent

#: (path, value) found by the scan that are not copies of the paper's numbers, each with the reason.
ALLOWED = {
    ("stiffness/fillet_foundation.py", 6.82): "a coefficient of Sainsot et al. (2004)'s fillet-foundation fit",
    ("drivetrain/shaft_element.py", 77.0): "Hutchinson's shear coefficient of a hollow circular section",
    # the rig's stated torque is an input of the rig prediction (luo2020.rig sits at the experiment layer, below the
    # report's, and cannot import the table); the test below keeps it equal to the table's row
    ("luo2020/rig/data.py", 138.0): "the rig's stated torque, checked equal to row sec5.load_stage_torque",
}


def _distinctive(value: float) -> bool:
    value = abs(value)
    if value != round(value):
        return len(f"{value:.6g}".replace(".", "").lstrip("0")) >= 3
    return value >= 100 and value % 100 != 0


#: Rows whose numbers are scanned as float literals although not distinctive by the rule (the figure's
#: temperature band, which a command once hard-coded; as integers they are counts such as grid sizes).
ALSO_SCANNED = ("fig3.flank_temperature_min", "fig3.flank_temperature_max")


def paper_numbers() -> set[float]:
    return {abs(float(item.paper)) for item in PAPER_ROWS
            if not isinstance(item.paper, bool) and not item.key.startswith(("table1.", "table3."))
            and _distinctive(float(item.paper))}


def float_only_numbers() -> set[float]:
    return {abs(float(row(key).paper)) for key in ALSO_SCANNED}


def copies(root: Path = SOURCE) -> list[tuple[str, float]]:
    """(path, value) of every literal or shown text of a paper number outside the rows module."""
    numbers, floats = paper_numbers(), float_only_numbers()
    texts = sorted((f"{value:g}" for value in numbers), key=len, reverse=True)
    pattern = re.compile(r"(?<![\d.])(" + "|".join(re.escape(text) for text in texts) + r")(?!\d)")
    found = []
    for path in sorted(root.rglob("*.py")):
        name = str(path.relative_to(root))
        if name == "luo2020/report/rows.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        docstrings = {id(node.body[0].value) for node in ast.walk(tree)
                      if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef))
                      and node.body and isinstance(node.body[0], ast.Expr)
                      and isinstance(node.body[0].value, ast.Constant)}
        for node in ast.walk(tree):
            if not isinstance(node, ast.Constant) or isinstance(node.value, bool):
                continue
            if isinstance(node.value, (int, float)) and (
                    abs(float(node.value)) in numbers or (isinstance(node.value, float) and abs(node.value) in floats)):
                found.append((name, abs(float(node.value))))
            elif isinstance(node.value, str) and id(node) not in docstrings:
                found += [(name, float(match)) for match in pattern.findall(node.value)]
    return found


def test_no_paper_number_outside_the_table():
    assert [item for item in copies() if item not in ALLOWED] == []


def test_the_rig_torque_is_the_tables():
    assert STATED_TORQUE_NM == row("sec5.load_stage_torque").paper


def test_the_scan_finds_planted_copies(tmp_path):
    (tmp_path / "cli_fem.py").write_text('BAND = (77.0, 81.0)\nDROP = {"C": 14.52}\n'
                                         'TEXT = f"calibrated to the paper\'s 14.52 % drop"\n')
    (tmp_path / "other.py").write_text('"""Docstring: the paper\'s 14.52 % drop."""\nX = 14.521\nY = 0.5\n'
                                       'grid = roll_grid(81)\n')
    assert sorted(copies(tmp_path)) == [("cli_fem.py", 14.52), ("cli_fem.py", 14.52), ("cli_fem.py", 77.0),
                                        ("cli_fem.py", 81.0)]
