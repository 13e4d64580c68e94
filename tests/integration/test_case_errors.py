"""Bad cases fail at load time with one message naming key, value, allowed range and reason; the CLI exits 2
with that message on stderr and no traceback."""

from __future__ import annotations

import copy
import tomllib
import warnings

import pytest
import tomli_w

import inprocess_cli

from thermogear.case import case_from_document, load_case, parameter_set_path
from thermogear.errors import CaseError


def luo_document() -> dict:
    return tomllib.loads(parameter_set_path("luo2019").read_text(encoding="utf-8"))


def changed(edits: dict, removals: tuple[str, ...] = ()) -> dict:
    document = copy.deepcopy(luo_document())
    for dotted, value in edits.items():
        node = document
        *parents, last = dotted.split(".")
        for part in parents:
            node = node.setdefault(part, {})
        node[last] = value
    for dotted in removals:
        node = document
        *parents, last = dotted.split(".")
        for part in parents:
            node = node[part]
        del node[last]
    return document


# (id, edits, removals, expected key in the message, a word expected in the reason)
BAD_CASES = [
    ("contact ratio <= 1", {"gears.addendum_coefficient": 0.5, "gears.dedendum_coefficient": 0.8}, (),
     "contact_ratio", "contact ratio"),
    ("undercut", {"gears.pinion.teeth": 12, "gears.centre_distance_mm": 70.5}, (), "pinion.profile_shift",
     "undercut"),
    ("pointed tip", {"gears.pinion.teeth": 12, "gears.pinion.profile_shift": 1.2}, ("gears.centre_distance_mm",),
     "pinion.profile_shift", "point"),
    ("too thin tip", {"gears.pinion.teeth": 12, "gears.pinion.profile_shift": 0.8}, ("gears.centre_distance_mm",),
     "pinion.profile_shift", "thick"),
    ("root interference", {"gears.wheel.tip_diameter_mm": 112.6}, (), "wheel.tip_diameter_mm", "interference"),
    ("zero module", {"gears.module_mm": 0.0}, (), "gears.module_mm", "range"),
    ("negative face width", {"gears.face_width_mm": -5.0}, (), "gears.face_width_mm", "range"),
    ("bore beyond root", {"gears.pinion.bore_radius_mm": 37.0}, (), "pinion.bore_radius_mm", "bore"),
    ("unknown key", {"gears.modul_mm": 3.0}, (), "gears.modul_mm", "did you mean 'module_mm'"),
    ("wrong type", {"gears.pinion.teeth": "twenty-seven"}, (), "gears.pinion.teeth", "type"),
    ("metres in a mm key", {"gears.module_mm": 0.003}, (), "gears.module_mm", "metres"),
    ("power and torque", {"operating.torque_nm": 380.0}, (), "power_kw", "exactly one"),
    ("centre distance too small", {"gears.centre_distance_mm": 92.0}, (), "centre_distance_mm", "penetrate"),
    ("missing key", {}, ("gears.pinion.teeth",), "gears.pinion.teeth", "required"),
    ("unknown section", {"gearz": {"module_mm": 3}}, (), "gearz", "did you mean 'gears'"),
    # a key in the wrong section: the suggestion looks across sections (issue 24)
    ("key of another section", {"operating.pressure_angle_deg": 20.0}, (), "operating.pressure_angle_deg",
     "did you mean 'gears.pressure_angle_deg'"),
    ("gear key in the pair section", {"gears.teeth": 20}, (), "gears.teeth", "did you mean 'gears.pinion.teeth'"),
    ("misspelt key of another section", {"operating.preasure_angle_deg": 20.0}, (), "operating.preasure_angle_deg",
     "did you mean 'gears.pressure_angle_deg'"),
    ("bad choice", {"damping.rule": "average"}, (), "damping.rule", "choices"),
    ("poisson ratio", {"material.poisson_ratio": 0.5}, (), "material.poisson_ratio", "range"),
]


@pytest.mark.parametrize("edits, removals, key, reason", [case[1:] for case in BAD_CASES],
                         ids=[case[0] for case in BAD_CASES])
def test_bad_case_is_refused_with_key_value_range_and_reason(edits, removals, key, reason):
    with pytest.raises(CaseError) as caught:
        case_from_document(changed(edits, removals))
    message = str(caught.value)
    assert key in message
    assert reason.lower() in message.lower()
    assert "allowed" in message


def test_valid_document_loads_without_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        case = case_from_document(luo_document())
    assert case.gear_pair.contact_ratio == pytest.approx(1.658, abs=1e-3)


def test_unknown_parameter_set_suggests_the_closest():
    with pytest.raises(CaseError, match="did you mean 'luo2019'"):
        load_case("luo2091")


def test_invalid_toml_is_reported(tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text("[gears\nmodule_mm = 3\n", encoding="utf-8")
    with pytest.raises(CaseError, match="valid TOML"):
        load_case(path)


CLI_CASES = ["contact ratio <= 1", "undercut", "unknown key", "wrong type", "bore beyond root"]


@pytest.mark.parametrize("name", CLI_CASES)
def test_cli_exits_2_with_one_line_and_no_traceback(tmp_path, name):
    edits, removals, key, _ = next(case[1:] for case in BAD_CASES if case[0] == name)
    path = tmp_path / "bad.toml"
    path.write_text(tomli_w.dumps(changed(edits, removals)), encoding="utf-8")
    completed = inprocess_cli.run("check", str(path))  # an escaping exception (a traceback) fails the test
    assert completed.returncode == 2
    assert "Traceback" not in completed.stderr
    assert key in completed.stderr
    assert completed.stdout == ""


def test_cli_accepts_the_built_in_cases():
    for name in ("luo2019", "fzg_type_c"):
        completed = inprocess_cli.run("check", name, "--json")
        assert completed.returncode == 0, completed.stderr
        assert '"valid": true' in completed.stdout
