"""Every gearbox input checked with the others at load (thermogear.gearbox.input_checks): each refusal names the key,
the value, the allowed range and why, through the load-time checks every command runs (``check`` = ``run``)."""

from __future__ import annotations

import copy
from pathlib import Path
import warnings

import pytest

from thermogear.case import case_from_document, load_case
from thermogear.errors import CaseError, ModelAssumptionWarning

pytestmark = pytest.mark.filterwarnings("ignore::thermogear.errors.ExtrapolationWarning")


@pytest.fixture(scope="module")
def document():
    return copy.deepcopy(load_case("fzg_test_gearbox").document)


def loaded(document, **changes):
    """The document with dotted keys replaced (None deletes), loaded."""
    changed = copy.deepcopy(document)
    for dotted, value in changes.items():
        node = changed
        *parents, last = dotted.split(".")
        for part in parents:
            node = node.setdefault(part, {})
        if value is None:
            node.pop(last, None)
        else:
            node[last] = value
    return case_from_document(changed)


def refusal(document, **changes) -> CaseError:
    with pytest.raises(CaseError) as caught:
        loaded(document, **changes)
    return caught.value


def test_the_built_in_set_passes(document):
    loaded(document)


def test_default_immersion_deeper_than_the_oil_stands(document):
    # 0.6 L over the 0.45 × 0.30 m footprint stands 4.4 mm deep; the default wheel immersion (its centre) is 54.9 mm
    error = refusal(document, **{"gearbox.oil.volume_l": 0.6, "gearbox.oil.level_mm": None})
    text = str(error)
    assert error.key == "gearbox.oil.wheel_immersion_mm" and "54.9" in text and "4.444 mm" in text
    assert "the default: the wheel dipped to its centre" in text and "level_mm" in text


def test_given_immersion_against_the_given_level(document):
    error = refusal(document, **{"gearbox.oil.wheel_immersion_mm": 70.0})
    assert error.key == "gearbox.oil.wheel_immersion_mm" and "<= 60 mm" in str(error)
    error = refusal(document, **{"gearbox.oil.pinion_immersion_mm": 61.0})
    assert error.key == "gearbox.oil.pinion_immersion_mm"


def test_level_needs_a_floor_that_fits(document):
    # 10 L at 60 mm needs 0.167 m² of floor, more than the 0.135 m² footprint
    error = refusal(document, **{"gearbox.oil.volume_l": 10.0})
    assert error.key == "gearbox.oil.level_mm" and "0.135" in str(error)
    error = refusal(document, **{"gearbox.oil.level_mm": 450.0})
    assert error.key == "gearbox.oil.level_mm" and "housing height" in str(error)


def test_oil_volume_against_the_housing_also_with_a_wetted_area(document):
    # 10 000 L in a 54 L box, the wetted area given: refused on the volume
    error = refusal(document, **{"gearbox.oil.volume_l": 10000.0})
    assert error.key == "gearbox.oil.volume_l" and "54" in str(error)


def test_wetted_area_larger_than_the_housing(document):
    error = refusal(document, **{"gearbox.housing.oil_wetted_area_m2": 5.0})
    assert error.key == "gearbox.housing.oil_wetted_area_m2" and "0.87 m²" in str(error)


def test_bearing_load_fractions():
    # the load fractions of [[gearbox.bearings]], in a case without a drivetrain (with one, each bearing's load is
    # its static force in the drivetrain and the table is refused)
    document = copy.deepcopy(load_case(Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml").document)
    bearings = copy.deepcopy(document["gearbox"]["bearings"])
    bearings[0]["load_fraction"] = 1.0  # 2 × 1.0 on the pinion shaft: 2 > 1
    error = refusal(document, **{"gearbox.bearings": bearings})
    assert error.key == "gearbox.bearings.load_fraction" and "= 2" in str(error) and "statics" in str(error)
    bearings[0]["load_fraction"] = 0.25  # 2 × 0.25: half the tooth force carried by nothing
    with pytest.warns(ModelAssumptionWarning, match="pinion shaft's bearings carry 0.5"):
        loaded(document, **{"gearbox.bearings": bearings})


@pytest.mark.parametrize("key, value", [("temperature.bulk_c", 70.0), ("temperature.pinion_base_c", 60.0)])
def test_temperature_keys_without_effect_under_the_gearbox_model(document, key, value):
    error = refusal(document, **{key: value})
    assert error.key == key and "no effect" in str(error)


def test_friction_keys_checked_together(document):
    error = refusal(document, **{"gearbox.friction_coefficient": 0.05})
    assert error.key == "gearbox.friction_coefficient" and "no effect" in str(error)
    error = refusal(document, **{"gearbox.friction_model": "constant"})
    assert error.key == "gearbox.friction_coefficient"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = loaded(document, **{"gearbox.friction_model": "constant", "gearbox.friction_coefficient": 0.05})
    from thermogear.gearbox.case_model import gearbox_model_from_case

    assert gearbox_model_from_case(case).description.friction.name == "constant"
    error = refusal(document, **{"gearbox.friction_model": "stribeck"})
    assert error.key == "gearbox.friction_model"


def test_check_refuses_what_run_would(tmp_path):
    # the same refusal through `thermogear check`: one set of load-time checks for every command
    from typer.testing import CliRunner

    import thermogear.cli.check  # noqa: F401
    from thermogear.case import parameter_set_path
    from thermogear.cli.app import app

    text = parameter_set_path("fzg_test_gearbox").read_text(encoding="utf-8")
    assert "volume_l = 1.25\nlevel_mm = 60.0\n" in text
    path = tmp_path / "shallow.toml"
    path.write_text(text.replace("volume_l = 1.25\nlevel_mm = 60.0\n", "volume_l = 0.6\n"), encoding="utf-8")
    result = CliRunner().invoke(app, ["check", str(path)])
    assert result.exit_code != 0 and isinstance(result.exception, CaseError)
    assert result.exception.key == "gearbox.oil.wheel_immersion_mm"
    assert "a gear cannot dip deeper" in str(result.exception)
