"""check = run (issue 25): one set of checks, run by every command. Each bad case ``check`` refuses is refused
by every command with the same one message naming its key (no traceback, nothing computed first); a case
``check`` accepts runs; a [sweep] table ``check`` accepts is one ``sweep`` accepts and the reverse."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest
import tomli_w

from thermogear.case import parameter_set_path

from inprocess_cli import invoke

BAD_CASES = Path(__file__).parents[1] / "data" / "bad_cases"


def _expected_key(path: Path) -> str:
    return path.read_bytes().split(b"\n", 1)[0].decode("ascii").removeprefix("# expect: ").strip()


def _commands(case: str, tmp_path: Path) -> list[list[str]]:
    return [["stiffness", case], ["stiffness", case, "--thermal"], ["damping", case], ["run", case, "--json"],
            ["sweep", case, "--vary", "speed_rpm=1000,2000", "--out", str(tmp_path / "study.zarr")]]


def _error_line(stderr: str) -> str:
    lines = [line for line in stderr.splitlines() if line.startswith("error:")]
    assert len(lines) == 1, stderr
    return lines[0]


@pytest.mark.parametrize("path", [p for p in sorted(BAD_CASES.glob("*.toml")) if _expected_key(p) != "valid"],
                         ids=lambda p: p.stem)
def test_every_command_refuses_what_check_refuses_with_the_same_message(path, tmp_path):
    code, out, err = invoke("check", str(path))
    assert code == 2 and out == "", err
    message = _error_line(err)
    assert _expected_key(path) in message
    for command in _commands(str(path), tmp_path):
        code, out, err = invoke(*command)
        assert code == 2, (command, err)
        assert _error_line(err) == message, command
    assert not (tmp_path / "study.zarr").exists()  # nothing written for a refused case


def _case_file(tmp_path: Path, base: str, edits: dict, name: str = "case.toml") -> Path:
    document = tomllib.loads(parameter_set_path(base).read_text(encoding="utf-8"))
    for dotted, value in edits.items():
        node = document
        *parents, last = dotted.split(".")
        for part in parents:
            node = node.setdefault(part, {})
        node[last] = value
    path = tmp_path / name
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


#: The FZG type C pair (m 4.5, z 16/24) with 40 μm backlash assembled at 21 °C, base circles at 21 °C, bores at
#: 200 °C, housing at 20 °C: the base-circle check passed while run jammed ("−9.1 μm at 87.2 °C").
HOT_BORE = {"gears.backlash_normal_um": 40.0,
            "temperature": {"model": "tabulated", "reference_c": 21.0, "gamma": [-1.5, 0.0, 1.5],
                            "flank_c": [21.0, 21.0, 21.0], "fit_degree": 2, "pinion_base_c": 21.0,
                            "wheel_base_c": 21.0, "pinion_bore_c": 200.0, "wheel_bore_c": 200.0},
            "housing.temperature_c": 20.0}


def test_check_tests_jamming_with_the_temperature_field_run_uses(tmp_path):
    path = _case_file(tmp_path, "fzg_type_c", HOT_BORE)
    code, _, err = invoke("check", str(path))
    assert code == 2
    message = _error_line(err)
    assert "jam" in message and "-9.1 μm" in message
    for command in (["run", str(path)], ["stiffness", str(path), "--thermal"],
                    ["sweep", str(path), "--vary", "speed_rpm=1000,2000", "--out", str(tmp_path / "s.zarr")]):
        code, _, err = invoke(*command)
        assert code == 2 and _error_line(err) == message


def test_a_case_check_accepts_runs_with_every_command(tmp_path):
    edits = {**HOT_BORE, "housing.temperature_c": 90.0}  # the same case with a warm housing: the backlash opens
    path = _case_file(tmp_path, "fzg_type_c", edits)
    assert invoke("check", str(path))[0] == 0
    for command in (["stiffness", str(path), "--thermal"], ["run", str(path), "--json"]):
        code, out, err = invoke(*command)
        assert code == 0, (command, err)


@pytest.mark.parametrize("vary, key", [
    ({"speed_rpm": "0:1000:10"}, "vary.speed_rpm"),
    ({"speed_rpm": "-100:100:5"}, "vary.speed_rpm"),
    ({"sped_rpm": [1000.0, 2000.0]}, "sped_rpm"),
    ({"module_mm": [0.0001, 3.0]}, "vary.module_mm"),
])
def test_sweep_tables_check_accepts_are_the_tables_sweep_accepts(vary, key, tmp_path):
    path = _case_file(tmp_path, "luo2019", {"sweep": {"model": "elastic", "vary": vary}})
    code, _, err = invoke("check", str(path))
    assert code == 2
    message = _error_line(err)
    assert key in message
    code, _, err = invoke("sweep", str(path), "--out", str(tmp_path / "study.zarr"))
    assert code == 2 and _error_line(err) == message


def test_check_labels_a_load_no_steel_tooth_carries_and_keeps_the_case(tmp_path):
    # 10⁷ N·m on m 0.5, b 5 mm: DTE 5.4 m called valid before; now computed and labelled
    path = tmp_path / "heavy.toml"
    path.write_text('[case]\nname = "heavy"\n[gears]\nmodule_mm = 0.5\nface_width_mm = 5.0\n[gears.pinion]\n'
                    'teeth = 20\n[gears.wheel]\nteeth = 40\n[operating]\nspeed_rpm = 1000.0\ntorque_nm = 1e7\n'
                    '[temperature]\nbulk_c = 60.0\n', encoding="utf-8")
    code, out, err = invoke("check", str(path), "--json")
    assert code == 0, err
    checks = " ".join(json.loads(out)["load_checks"])
    assert "contact stress" in checks and "root stress" in checks and "deflection" in checks
