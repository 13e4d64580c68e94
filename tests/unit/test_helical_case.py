"""A helical pair through the case file and the commands (issue 37): the keys resolve into the ISO 21771 geometry,
β = 0 is today's spur pair to the bit (objects and the commands' JSON), the load-time refusals, and the known
properties of the thermo-elastic helical mesh (a face gradient moves the load to the hot side)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from thermogear.case import load_case, parameter_set_path
from thermogear.cli.app import app
from thermogear.errors import CaseError
from thermogear.helical.geometry import HelicalPair
from thermogear.mesh.model import MeshModel
from thermogear.summaries.helical import helical_face_summary


def _with_gears_keys(name: str, keys: str, folder) -> str:
    """The built-in set ``name`` as a case file with ``keys`` added at the top of its [gears] table."""
    text = parameter_set_path(name).read_text(encoding="utf-8")
    assert "\n[gears]\n" in text
    path = folder / f"{name}_keys.toml"
    path.write_text(text.replace("\n[gears]\n", f"\n[gears]\n{keys}\n", 1), encoding="utf-8")
    return str(path)


def _json(arguments: list[str]) -> dict:
    result = CliRunner().invoke(app, arguments)
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def _without_source(payload):
    """The payload without what names the case's file (the only thing a copy of a set may change); the warnings as
    a set (in one process the second run takes the cached stiffness table, whose warnings come again in another
    order)."""
    if isinstance(payload, dict):
        return {key: sorted(value) if key == "messages" else _without_source(value)
                for key, value in payload.items() if key not in ("source", "case_file")}
    if isinstance(payload, list):
        return [_without_source(value) for value in payload]
    return payload


def _assert_close(left, right, path="") -> None:
    if isinstance(left, dict):
        assert left.keys() == right.keys(), path
        for key in left:
            _assert_close(left[key], right[key], f"{path}.{key}")
    elif isinstance(left, list):
        assert len(left) == len(right), path
        for index, (a, b) in enumerate(zip(left, right)):
            _assert_close(a, b, f"{path}[{index}]")
    elif isinstance(left, float) and isinstance(right, float):
        assert left == pytest.approx(right, rel=1e-9, abs=1e-300) or (math.isnan(left) and math.isnan(right)), path
    else:
        assert left == right, path


# ------------------------------------------------------------------------------------------------ β = 0 is spur
@pytest.mark.parametrize("name", ["luo2019", "fzg_type_c"])
def test_zero_helix_angle_and_a_hand_give_the_spur_objects(name, tmp_path):
    spur = load_case(name)
    zero = load_case(_with_gears_keys(name, 'helix_angle_deg = 0.0\nhand = "left"', tmp_path))
    assert zero.helical_pair is None and spur.helical_pair is None
    assert zero.gear_pair == spur.gear_pair  # every field of both gears and the pair, exactly
    elastic, elastic_zero = MeshModel(spur, "elastic").state(), MeshModel(zero, "elastic").state()
    assert np.array_equal(elastic.mesh_stiffness, elastic_zero.mesh_stiffness)


@pytest.mark.slow
@pytest.mark.parametrize("command", [["stiffness", "--json"], ["run", "--json"]], ids=["stiffness", "run"])
@pytest.mark.parametrize("name", ["luo2019", "fzg_type_c"])
def test_zero_helix_angle_reproduces_the_spur_json(name, command, tmp_path):
    """Issue 37: β = 0 reproduces every spur number of run --json and stiffness --json to 1e-9."""
    spur = _json([command[0], name, *command[1:]])
    zero = _json([command[0], _with_gears_keys(name, 'helix_angle_deg = 0.0\nhand = "left"', tmp_path),
                  *command[1:]])
    _assert_close(_without_source(spur), _without_source(zero))


# ------------------------------------------------------------------------------------------------ geometry
def test_the_case_keys_give_the_iso_21771_pair():
    """fzg_h501: the case's helical pair is HelicalPair.create of the same normal-section data (the library's
    geometry, tested against ISO 21771's formulas in test_helical_geometry), with the rig's centre distance."""
    case = load_case("fzg_h501")
    expected = HelicalPair.create(20, 30, 3.5e-3, math.radians(20.0), math.radians(15.0), 23e-3,
                                  (0.1809, 0.0891), bore_radii=(15e-3, 15e-3))
    helical = case.helical_pair
    assert helical == expected
    assert case.gear_pair is helical.transverse
    # a = 91.5003 mm: the FZG rig's 91.5 mm (ISO 14635-1) to the tabulated shifts' rounding
    assert helical.transverse.centre_distance == pytest.approx(91.5e-3, abs=1e-6)
    assert helical.overlap_ratio == pytest.approx(23.0 * math.sin(math.radians(15.0)) / (math.pi * 3.5), rel=1e-12)


def test_check_shows_the_helical_geometry():
    payload = _json(["check", "fzg_h501", "--json"])
    helical = payload["helical"]
    assert helical["helix_angle_deg"] == pytest.approx(15.0)
    assert helical["hand"] == "right"
    assert helical["transverse_module_mm"] == pytest.approx(3.5 / math.cos(math.radians(15.0)), rel=1e-12)
    assert helical["total_contact_ratio"] == pytest.approx(helical["transverse_contact_ratio"]
                                                            + helical["overlap_ratio"], rel=1e-12)
    lengths = helical["contact_line_length_mm"]
    assert lengths["min"] < lengths["mean"] < lengths["max"]
    assert "helical" not in _json(["check", "luo2019", "--json"])


# ------------------------------------------------------------------------------------------------ refusals
def test_the_paper_model_refuses_a_helical_pair(tmp_path):
    path = _with_gears_keys("luo2019", "helix_angle_deg = 15.0", tmp_path)
    with pytest.raises(CaseError) as error:
        load_case(path)
    assert error.value.key == "thermal.model" and "spur-only" in str(error.value)


def test_a_face_gradient_needs_a_helical_pair(tmp_path):
    text = parameter_set_path("fzg_type_c").read_text(encoding="utf-8").replace(
        "bulk_c = 70.0", "bulk_c = 70.0\nface_gradient_k = 5.0")
    path = tmp_path / "spur_gradient.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(CaseError) as error:
        load_case(str(path))
    assert error.value.key == "temperature.face_gradient_k"


@pytest.mark.parametrize("keys, key", [("helix_angle_deg = 46.0", "gears.helix_angle_deg"),
                                       ('hand = "up"', "gears.hand")])
def test_bad_helix_keys_are_refused_with_their_key(keys, key, tmp_path):
    with pytest.raises(CaseError) as error:
        load_case(_with_gears_keys("fzg_type_c", keys, tmp_path))
    assert error.value.key == key


# ------------------------------------------------------------------------------------------------ thermo-elastic
def test_a_face_gradient_moves_the_load_to_the_hot_side():
    """Issue 37: a uniform temperature leaves the load symmetric about mid-face; a gradient moves it to the hot
    (outlet, z = 0) side, the more the larger the gradient."""
    case = load_case("fzg_h501")
    centres = {}
    for gradient in (0.0, 10.0, 20.0):
        changed = case.with_changes(**{"temperature.face_gradient_k": gradient})
        face = helical_face_summary(MeshModel(changed, "thermal"), points=64)
        centres[gradient] = face["load_centre_mm"]
        if gradient == 0.0:  # symmetric: the mean line load mirrors about mid-face; 64 mesh positions sample
            # where the lines' ends cross each slice, a ripple of about ±1 % from slice to slice
            load = np.asarray(face["mean_line_load_n_per_mm"])
            assert np.allclose(load, load[::-1], rtol=0.02), load
    assert centres[0.0] == pytest.approx(11.5, abs=1e-2)  # b/2
    assert centres[20.0] < centres[10.0] < centres[0.0]


def test_the_thermal_stiffness_of_a_helical_pair_follows_e_of_t():
    """Without deviations the hot K_t is the slice model of the hot transverse pair scaled by E(T): its mean
    drops by about the E ratio (the hot geometry changes the contact ratio by < 1 %)."""
    case = load_case("fzg_h501").with_changes(**{"temperature.face_gradient_k": 0.0})
    elastic = MeshModel(case, "elastic").state(points_per_period=128, damping=False)
    thermal_model = MeshModel(case, "thermal")
    thermal = thermal_model.state(points_per_period=128, damping=False)
    ratio = np.mean(thermal_model.thermoelastic_mesh.modulus_ratios)
    assert thermal.mean_mesh_stiffness / elastic.mean_mesh_stiffness == pytest.approx(ratio, rel=0.01)


# ------------------------------------------------------------------------------------------------ commands
def test_stiffness_of_a_helical_pair_is_the_slice_model_beside_iso():
    """stiffness --json: K_t over the cycle from the slice model, the ISO values of the helical pair (not its
    transverse section's). FZG H501 with its 15 mm bores: the slice mean is within 5 % of ISO 6336-1's c_γα
    (docs/helical.md: the normal-section slices follow ISO's helix trend, +2 % at 15° on a 27/35 pair; ISO's
    Method B is itself an empirical fit of that order)."""
    from thermogear.helical.iso_stiffness import helical_iso_stiffness
    from thermogear.stiffness.iso6336 import N_PER_MM_UM

    payload = _json(["stiffness", "fzg_h501", "--json"])
    helical = payload["helical"]
    mesh = helical["mesh_stiffness_n_per_mm_um"]
    assert mesh["min"] < mesh["mean"] < mesh["max"]
    assert helical["ripple"] == pytest.approx((mesh["max"] - mesh["min"]) / mesh["mean"], rel=1e-9)
    case = load_case("fzg_h501")
    iso = helical_iso_stiffness(case.helical_pair, case.material)
    assert payload["iso6336"]["c_gamma_alpha_n_per_mm_um"] == pytest.approx(iso.mesh / N_PER_MM_UM, rel=1e-12)
    assert helical["slice_mean_over_iso_c_gamma_alpha"] == pytest.approx(1.0, abs=0.05)


def test_the_report_draws_and_tables_the_helical_pair():
    import matplotlib.pyplot as plt

    from thermogear.orchestrator import Orchestrator
    from thermogear.report.helical_section import helical_figure, helical_section

    summary = Orchestrator(load_case("fzg_h501"), ("elastic", "thermal")).thermoelastic()
    helical = summary["helical"]
    assert helical["hot"]["face_load_factor"] > helical["cold"]["face_load_factor"]
    page = helical_section(summary)
    assert "Helical pair" in page and "face load factor" in page
    figure = helical_figure(helical)
    assert len(figure.axes) == 5  # four panels and the temperature's twin axis
    plt.close(figure)
    assert helical_section(Orchestrator(load_case("fzg_type_c"), ("elastic", "thermal")).thermoelastic()) == ""


def test_a_linear_sweep_of_a_helical_pair_equals_one_simulation_per_point():
    """sweep takes a helical case: its batch path (one mesh period reused and scaled where the model allows) gives
    what one Simulation per point gives (1e-9), and the case's own point is run's."""
    from sweep_paths import assert_fast_path_equals_simulation

    from thermogear.sweep.study import Study

    case = load_case("fzg_h501").with_changes(**{"dynamics.mesh": "linear", "dynamics.points_per_period": 256})
    study = Study.define(case, ["speed_rpm=2175,3000", "torque_nm=135.3"], model="both", chunk_points=64)
    fast = assert_fast_path_equals_simulation(study)
    assert np.all(np.isfinite(np.asarray(fast["kv"], float))) and np.all(np.asarray(fast["kv"], float) > 1.0)


def test_the_commands_built_on_spur_teeth_say_so_or_use_the_transverse_section():
    """damping: the friction damping of the helical pair's transverse section (finite in both regions); fem: the
    plane-strain spur tooth refuses a helical pair with the key."""
    from thermogear.fem.inputs import fem_inputs

    payload = _json(["damping", "fzg_h501", "--json"])
    means = payload["damping_n_s_per_m"]
    assert all(math.isfinite(value) and value > 0.0 for model in means.values() for value in model.values())
    with pytest.raises(CaseError) as error:
        fem_inputs(load_case("fzg_h501"))
    assert error.value.key == "gears.helix_angle_deg"
