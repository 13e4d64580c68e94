"""One heated system (issue 35): the gearbox network's temperatures set the drivetrain's shafts and bearing rings,
each bearing is described once (stiffness and loss), its clearance follows its ring temperatures, and every
operating point gets its own steady temperatures."""

from __future__ import annotations

import copy
import math
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

from thermogear.case import case_from_document
from thermogear.drivetrain.bearing_clearance import (BEARING_STEEL_EXPANSION_PER_K,
                                                     estimated_outer_raceway_diameter, operating_clearance,
                                                     radial_clearance_change)
from thermogear.errors import CaseError
from thermogear.gearbox.case_model import gearbox_model_from_case

DATA = Path(__file__).resolve().parents[1] / "data" / "gearbox"
COUPLED = DATA / "fzg_gearbox_drivetrain.toml"


def _document() -> dict:
    return tomllib.loads(COUPLED.read_text(encoding="utf-8"))


def _load(document: dict):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_from_document(document, source=str(COUPLED))


@pytest.fixture(scope="module")
def coupled():
    return _load(_document())


# --- clearance with the ring temperatures (differential expansion) ---------------------------------------------

@pytest.mark.parametrize("temperature_c", [-30.0, 20.0, 95.0, 180.0])
def test_equal_ring_temperatures_leave_the_clearance_unchanged(temperature_c):
    clearance = operating_clearance(25e-6, 0.075, temperature_c, temperature_c)
    assert clearance.operating == 25e-6 and not clearance.taken_up


def test_a_hotter_inner_ring_reduces_the_clearance_by_the_analytic_amount():
    # IKO Eq. (29): the radial internal clearance falls by λ·E·Δt; the play ± c is half of it
    raceway, difference = 0.075, 15.0
    clearance = operating_clearance(30e-6, raceway, 80.0 + difference, 80.0)
    expected = 30e-6 - 0.5 * BEARING_STEEL_EXPANSION_PER_K * raceway * difference
    assert clearance.operating == pytest.approx(expected, rel=1e-14)
    assert radial_clearance_change(raceway, 60.0, 75.0) == pytest.approx(
        +BEARING_STEEL_EXPANSION_PER_K * raceway * 15.0, rel=1e-14)  # a hotter outer ring opens it


def test_a_clearance_taken_up_is_zero_and_said():
    clearance = operating_clearance(2e-6, 0.075, 120.0, 60.0)  # ½·12.5e-6·0.075·60 = 28 μm > 2 μm
    assert clearance.operating == 0.0 and clearance.taken_up


def test_the_raceway_estimate_of_the_nj406():
    assert estimated_outer_raceway_diameter(30.0, 90.0) == 75.0


# --- each bearing described once ---------------------------------------------------------------------------------

def test_a_bearing_described_once_gives_its_stiffness_and_its_loss_at_the_static_force(coupled):
    from thermogear.drivetrain.case_layout import drivetrain_from_section
    from thermogear.drivetrain.static_state import static_state
    from thermogear.gearbox.bearing_entries import rolling_bearing
    from thermogear.gearbox.drivetrain_coupling import coupled_parts, operating_point_temperatures

    parts = coupled_parts(gearbox_model_from_case(coupled), coupled.gearbox, coupled.drivetrain)
    point = operating_point_temperatures(parts, 1400.0, 138.0)
    pair = coupled.gear_pair
    normal_force = 138.0 / pair.pinion.base_radius
    # the drivetrain's own static state at this load (another mesh stiffness: the bearings' forces do not need it)
    drivetrain = drivetrain_from_section(coupled.drivetrain, pair, coupled.material, 3.1e8)
    forces = static_state(drivetrain.assemble(), normal_force).bearing_forces
    oil = parts.model.description.lubricant
    total = 0.0
    for bearing in coupled.drivetrain.bearings:
        assert bearing.stiffness_x_n_per_m == 5.4e8  # the same table gives the stiffness
        radial = float(np.hypot(*forces[bearing.name][:2]))
        on_pinion = bearing.shaft == "pinion shaft"
        speed = 1400.0 if on_pinion else 1400.0 / pair.gear_ratio
        # each bearing at the oil's viscosity at its own shaft's node
        shaft_c = point.state.pinion_shaft_c if on_pinion else point.state.wheel_shaft_c
        viscosity = float(oil.kinematic_viscosity(shaft_c, warn=False)) * 1e6
        expected = rolling_bearing(bearing.loss).moments(speed, viscosity, radial).power
        assert point.bearing_losses[bearing.name] == pytest.approx(expected, rel=1e-9)
        assert point.heat.bearings[bearing.name].radial_load == pytest.approx(radial, rel=1e-9)
        total += expected
    # and the network's bearing loss is the sum of those bearings' (no other bearing in the case)
    assert point.state.losses.bearings == pytest.approx(total, rel=1e-9)


def test_an_overhung_gear_loads_its_bearings_by_the_lever_rule():
    from thermogear.gearbox.bearing_entries import drivetrain_bearing_loads

    document = _document()
    document["drivetrain"]["pinion"]["position_mm"] = 75.0  # 3/4 of the span: bearings carry W/4 and 3W/4
    case = _load(document)
    loads = drivetrain_bearing_loads(case.drivetrain, case.gear_pair, case.material)
    assert loads["pinion bearing A"] == pytest.approx(0.25, rel=1e-6)
    assert loads["pinion bearing B"] == pytest.approx(0.75, rel=1e-6)


def test_gearbox_bearings_beside_a_drivetrain_are_refused_with_the_drivetrain_bearings_named():
    document = _document()
    document["gearbox"]["bearings"] = [{"shaft": "pinion", "designation": "NJ406", "count": 2}]
    with pytest.raises(CaseError) as raised:
        _load(document)
    message = str(raised.value)
    assert "gearbox.bearings (shaft = 'pinion')" in message and "pinion bearing A" in message
    assert "described once" in message


_CONSTANTS = {"type": "cylindrical_roller", "bore_mm": 30.0, "outside_mm": 90.0, "width_mm": 23.0,
              "rolling_constant": 1e-6, "sliding_constants": [0.16, 0.0015], "geometry_constant": 5.1}


@pytest.mark.parametrize("loss, key, words", [
    ({"designation": "NJ406", "bore_mm": 30.0}, "loss.bore_mm", "absent with a designation"),
    ({key: value for key, value in _CONSTANTS.items() if key != "width_mm"}, "loss.width_mm", "a value"),
    ({**_CONSTANTS, "outer_raceway_diameter_mm": 95.0}, "loss.outer_raceway_diameter_mm", "between bore_mm"),
])
def test_bad_loss_data_is_refused_naming_the_bearing(loss, key, words):
    document = _document()
    document["drivetrain"]["bearings"][1]["loss"] = loss
    with pytest.raises(CaseError) as raised:
        _load(document)
    assert f"drivetrain.bearings 'pinion bearing B'.{key}" in str(raised.value) and words in str(raised.value)


def test_the_skf_constants_give_the_designations_loss(coupled):
    from thermogear.gearbox.bearing_entries import drivetrain_mounted_bearings

    document = _document()
    document["drivetrain"]["bearings"][1]["loss"] = {**_CONSTANTS, "drag_variable": 1.49e-4}
    case = _load(document)
    by_constants = {item.name: item.bearing
                    for item in drivetrain_mounted_bearings(case.drivetrain, case.gear_pair, case.material)}
    by_designation = {item.name: item.bearing
                      for item in drivetrain_mounted_bearings(coupled.drivetrain, coupled.gear_pair, coupled.material)}
    assert by_constants["pinion bearing B"] == by_designation["pinion bearing B"]


def test_the_old_gearbox_bearings_stay_for_a_gearbox_without_drivetrain():

    document = _document()
    del document["drivetrain"]
    document["gearbox"]["bearings"] = [{"shaft": "pinion", "designation": "NJ406", "count": 2},
                                       {"shaft": "wheel", "designation": "NJ406", "count": 2}]
    mounted = gearbox_model_from_case(_load(document)).description.bearings
    assert [item.load_fraction for item in mounted] == [0.5] * 4 and all(item.name is None for item in mounted)


# --- the coupled steady state ------------------------------------------------------------------------------------

def test_the_coupled_steady_state_balances_to_a_nano_watt(coupled):
    from thermogear.gearbox.drivetrain_coupling import coupled_parts, operating_point_temperatures

    parts = coupled_parts(gearbox_model_from_case(coupled), coupled.gearbox, coupled.drivetrain)
    state = operating_point_temperatures(parts, 1400.0, 138.0).state
    total = state.losses.total
    assert total > 100.0 and state.losses.bearings > 0.0
    assert abs(total - state.heat_out) < 1e-9  # W


def test_each_operating_point_has_its_own_temperatures(coupled):
    from thermogear.gearbox.drivetrain_coupling import coupled_parts, operating_point_temperatures

    parts = coupled_parts(gearbox_model_from_case(coupled), coupled.gearbox, coupled.drivetrain)
    slow = operating_point_temperatures(parts, 700.0, 138.0)
    fast = operating_point_temperatures(parts, 2100.0, 138.0)
    assert fast.state.pinion_shaft_c > slow.state.pinion_shaft_c + 1.0
    assert fast.state.wheel_shaft_c > slow.state.wheel_shaft_c + 1.0
    assert fast.heat.shaft_temperature_c["pinion shaft"] == fast.state.pinion_shaft_c
    assert fast.heat.shaft_temperature_c["wheel shaft"] == fast.state.wheel_shaft_c
    assert "2100 rpm" in fast.heat.source


def test_the_network_sets_the_drivetrain_shafts_and_the_run_output_says_so(coupled):
    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.case.pieces import call_with_pieces
    from thermogear.gearbox.drivetrain_coupling import network_drivetrain_heat
    from thermogear.mesh.model_names import ELASTIC, THERMAL
    from thermogear.thermoelastic.materials import youngs_modulus_at

    heat = call_with_pieces(network_drivetrain_heat, coupled)
    built = case_drivetrain(coupled)
    shafts_c = heat.nodes_c["pinion_shaft"]
    assert heat.nodes_c["pinion"] > shafts_c + 5.0  # the gears' mean tooth temperature would overstate it
    assert shafts_c > heat.nodes_c["wheel_shaft"] + 1.0  # each shaft its own node: the faster pinion's is hotter
    warm = built.warm_state
    for name, node in (("pinion shaft", "pinion_shaft"), ("wheel shaft", "wheel_shaft")):
        assert warm["shafts"][name]["temperature_c"] == heat.nodes_c[node]
        assert "gearbox thermal network" in warm["shafts"][name]["source"]
    beta = built.models[THERMAL].thermoelastic_mesh.gears[0].modulus_coefficient_per_k
    for index, node in enumerate(("pinion_shaft", "wheel_shaft")):
        cold = built.drivetrains[ELASTIC].shafts[index].segments[0].material.youngs_modulus
        hot = built.drivetrains[THERMAL].shafts[index].segments[0].material.youngs_modulus
        assert hot == pytest.approx(youngs_modulus_at(cold, beta, heat.nodes_c[node]), rel=1e-12)
    bearing = warm["bearings"]["pinion bearing A"]
    assert bearing["inner_ring_c"] == shafts_c and bearing["outer_ring_c"] == heat.nodes_c["housing"]
    assert bearing["loss_w"] > 0.0 and bearing["static_radial_load_n"] == pytest.approx(
        0.5 * 138.0 / coupled.gear_pair.pinion.base_radius, rel=1e-9)
    assert warm["bearings"]["wheel bearing A"]["inner_ring_c"] == heat.nodes_c["wheel_shaft"]


def test_the_backlash_drivetrain_takes_the_hot_clearance():
    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.case.pieces import call_with_pieces
    from thermogear.gearbox.drivetrain_coupling import network_drivetrain_heat
    from thermogear.mesh.model_names import ELASTIC, THERMAL

    document = copy.deepcopy(_document())
    document["dynamics"]["mesh"] = "nonlinear"
    for bearing in document["drivetrain"]["bearings"]:
        bearing["radial_clearance_um"] = 20.0
    case = _load(document)
    heat = call_with_pieces(network_drivetrain_heat, case)
    built = case_drivetrain(case)
    assert math.isclose(built.drivetrains[ELASTIC].bearings[0].radial_clearance, 20e-6)
    shafts = {bearing["name"]: bearing["shaft"] for bearing in document["drivetrain"]["bearings"]}
    for bearing in built.drivetrains[THERMAL].bearings:
        # each bearing's inner ring at its own shaft's node
        node = "pinion_shaft" if shafts[bearing.name] == "pinion shaft" else "wheel_shaft"
        difference = heat.nodes_c[node] - heat.nodes_c["housing"]
        expected = 20e-6 - 0.5 * BEARING_STEEL_EXPANSION_PER_K * 75e-3 * difference
        assert difference > 5.0 and bearing.radial_clearance == pytest.approx(expected, rel=1e-12)


def test_a_changed_operating_point_predicts_its_own_drivetrain_temperatures(coupled):
    from thermogear.case.pieces import call_with_pieces
    from thermogear.gearbox.drivetrain_coupling import (coupled_parts, network_drivetrain_heat,
                                                        operating_point_temperatures)

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        faster = coupled.with_changes(**{"operating.speed_rpm": 2100.0})
        heat = call_with_pieces(network_drivetrain_heat, faster)
    parts = coupled_parts(gearbox_model_from_case(coupled), coupled.gearbox, coupled.drivetrain)
    expected = operating_point_temperatures(parts, 2100.0, 138.0).heat
    assert heat.shaft_temperature_c == pytest.approx(expected.shaft_temperature_c, rel=1e-9)
    slower = call_with_pieces(network_drivetrain_heat, coupled)
    assert heat.shaft_temperature_c["wheel shaft"] > slower.shaft_temperature_c["wheel shaft"] + 1.0
