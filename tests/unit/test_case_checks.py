"""Every check ``run`` would make is made when the case is loaded (issue 15, "one set of checks").

Each bad case under tests/data/bad_cases/ differs from ``valid_reference.toml`` by one defect and names, on its
first line (``# expect: KEY``), the key the refusal must name. Loading it must raise one CaseError naming that key,
before anything is computed.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from thermogear.case import load_case, register_case_check
from thermogear.errors import CaseError
from thermogear.schema.temperature import CASE_MAXIMUM_C
from thermogear.temperature.field import MATERIAL_MAXIMUM_C

BAD_CASES = Path(__file__).parents[1] / "data" / "bad_cases"


def _expected_key(path: Path) -> str:
    first = path.read_bytes().split(b"\n", 1)[0].decode("ascii")
    assert first.startswith("# expect: "), path
    return first.removeprefix("# expect: ").strip()


BAD = sorted(p for p in BAD_CASES.glob("*.toml") if _expected_key(p) != "valid")


def test_the_reference_of_the_bad_cases_is_valid():
    case = load_case(BAD_CASES / "valid_reference.toml")
    assert case.gear_pair.pinion.teeth == 27


@pytest.mark.parametrize("path", BAD, ids=lambda p: p.stem)
def test_bad_case_is_refused_at_load_naming_its_key(path):
    with pytest.raises(CaseError) as caught:
        load_case(path)
    assert _expected_key(path) in caught.value.key, (caught.value.key, str(caught.value))


def test_misspelt_section_suggests_the_closest_one():
    with pytest.raises(CaseError, match=r"unknown section \[gear\] \(did you mean 'gears'\?\)"):
        load_case(BAD_CASES / "misspelt_section.toml")


def test_infinite_reference_is_blamed_on_reference_not_bulk():
    with pytest.raises(CaseError) as caught:
        load_case(BAD_CASES / "reference_infinite.toml")
    assert caught.value.key == "temperature.reference_c"


def test_no_operating_pressure_angle_names_both_shifts():
    with pytest.raises(CaseError) as caught:
        load_case(BAD_CASES / "no_operating_pressure_angle.toml")
    assert "gears.pinion.profile_shift" in caught.value.key and "gears.wheel.profile_shift" in caught.value.key


def test_shift_sum_limit_is_the_involute_zero():
    # the limit x1 + x2 > -inv(α)(z1 + z2)/(2 tan α): just above it loads, just below it is refused
    import math

    from thermogear.case import case_from_document
    from thermogear.geometry import involute

    document = __import__("tomllib").loads((BAD_CASES / "valid_reference.toml").read_text())
    document["gears"].pop("centre_distance_mm")
    document["gears"]["pressure_angle_deg"] = 15.9
    document["gears"]["pinion"]["teeth"], document["gears"]["wheel"]["teeth"] = 12, 27
    angle = math.radians(15.9)
    limit = -float(involute(angle)) * 39 / (2 * math.tan(angle))
    document["gears"]["wheel"]["profile_shift"] = 0.0
    document["gears"]["pinion"]["profile_shift"] = limit - 0.01
    with pytest.raises(CaseError, match="profile_shift"):
        case_from_document(document)
    document["gears"]["pinion"]["profile_shift"] = limit + 0.3
    try:
        case_from_document(document)
    except CaseError as error:  # other checks may refuse this odd pair, but never for the shift sum
        assert "profile_shift +" not in error.key


def test_schema_temperature_limit_is_the_material_limit():
    assert CASE_MAXIMUM_C == MATERIAL_MAXIMUM_C


def test_sweep_refuses_an_oil_temperature_below_absolute_zero(luo2019):
    from thermogear.sweep.study import Study

    with pytest.raises(CaseError, match="oil_temperature_c"):
        Study.define(luo2019, ["oil_temperature_c=-300,30"])


def test_registered_checks_run_at_load(tmp_path):
    from thermogear import case as case_module

    calls = []

    def refuse_small_pinions(case):
        calls.append(case.name)
        if case.gear_pair.pinion.teeth < 30:
            raise CaseError("gears.pinion.teeth", case.gear_pair.pinion.teeth, ">= 30", "a site rule")

    register_case_check(refuse_small_pinions)
    try:
        with pytest.raises(CaseError, match="a site rule"):
            load_case(BAD_CASES / "valid_reference.toml")
    finally:
        case_module._CASE_CHECKS.remove(refuse_small_pinions)
    assert calls == ["bad"]
    load_case(BAD_CASES / "valid_reference.toml")  # removed again
