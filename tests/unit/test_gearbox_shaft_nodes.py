"""Each shaft its own node in the gearbox network: the gear-body conduction formula, each bearing's loss at its own
shaft's temperature and into its own shaft's node, a symmetric gearbox giving equal shafts, and the two shafts of
the FZG test gearbox differing with the energy balance kept."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from thermogear.gearbox.bearing_entries import mounted_bearing_power
from thermogear.gearbox.description import GearboxOperatingPoint, MountedBearing
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
from thermogear.gearbox.heat_paths import internal_conductances
from thermogear.gearbox.losses import NODES, OIL, PINION_SHAFT, WHEEL_SHAFT
from thermogear.gearbox.mesh_loss import rigid_pinion_heat_share
from thermogear.gearbox.model import GearboxThermalModel
from thermogear.geometry import Gear, GearPair

LOAD_STAGE_6 = GearboxOperatingPoint(speed_rpm=2175.0, torque=135.3, ambient_c=20.0)


# the built-in oils' viscosity fits cover 40–100 °C; these checks leave them on purpose
pytestmark = pytest.mark.filterwarnings("ignore")


def test_gear_body_conductance_is_the_hollow_cylinder_formula():
    # hand calculation: G = 2π k b / ln(r_f / r_bore) (Incropera Eq. 3.27), b 14 mm, k 46 W/(m K), bore 15 mm
    description = illustrative_fzg_gearbox()
    for wheel in (False, True):
        gear = description.gear_pair.wheel if wheel else description.gear_pair.pinion
        expected = 2.0 * math.pi * 46.0 * 0.014 / math.log(gear.root_radius / 0.015)
        assert description.gear_body_conductance(wheel) == pytest.approx(expected, rel=1e-14)
    # FZG C: pinion root radius 31.4 mm, wheel 49.0 mm (x = 0.18/0.17, h_f* = 1.25) → 5.5 and 3.4 W/K
    assert description.gear_body_conductance(False) == pytest.approx(5.53, abs=0.01)
    assert description.gear_body_conductance(True) == pytest.approx(3.41, abs=0.01)
    # a given conductance replaces the formula; a gear without a bore conducts 8π k b (solid cylinder, §3.5.2)
    assert dataclasses.replace(description, gear_shaft_conductance=2.5).gear_body_conductance(True) == 2.5
    pair = description.gear_pair
    solid = dataclasses.replace(description, gear_pair=GearPair.create(
        dataclasses.replace(pair.pinion, bore_radius=0.0), pair.wheel, pair.centre_distance))
    assert solid.gear_body_conductance(False) == pytest.approx(8.0 * math.pi * 46.0 * 0.014, rel=1e-14)


def test_each_shaft_is_joined_to_its_own_gear_and_bearings():
    description = illustrative_fzg_gearbox()
    matrix = internal_conductances(description)
    assert matrix.shape == (len(NODES), len(NODES)) and np.array_equal(matrix, matrix.T)
    pinion, wheel = NODES.index("pinion"), NODES.index("wheel")
    housing = NODES.index("housing")
    assert matrix[pinion, WHEEL_SHAFT] == 0.0 and matrix[wheel, PINION_SHAFT] == 0.0
    assert matrix[PINION_SHAFT, WHEEL_SHAFT] == 0.0
    # the totals of the shared paths are kept: shafts–oil (less the surfaces of the stretches of shaft between gear
    # and bearings, which the set's drivetrain gives: thermogear.gearbox.shaft_conduction) and shafts–housing add up
    # to the description's
    for shaft, wheel_side in ((PINION_SHAFT, False), (WHEEL_SHAFT, True)):
        assert matrix[shaft, OIL] == pytest.approx(0.5 * description.shaft_oil_conductance
                                                   + description.shaft_paths(wheel_side)[2], rel=1e-14)
    lumped = internal_conductances(dataclasses.replace(description, pinion_shaft_spans=(), wheel_shaft_spans=()))
    assert lumped[PINION_SHAFT, OIL] + lumped[WHEEL_SHAFT, OIL] == pytest.approx(description.shaft_oil_conductance)
    assert matrix[PINION_SHAFT, housing] + matrix[WHEEL_SHAFT, housing] == pytest.approx(
        description.shaft_housing_conductance)
    # three of four bearings on the wheel shaft: three quarters of the bearing-seat path there
    bearings = description.bearings
    skewed = dataclasses.replace(description, bearings=tuple(
        dataclasses.replace(item, on_wheel_shaft=index > 0) for index, item in enumerate(bearings)))
    assert skewed.shaft_housing_conductances == pytest.approx((0.25 * 8.0, 0.75 * 8.0))


def test_each_bearing_loss_at_its_own_shaft_temperature_and_into_its_own_node():
    description = illustrative_fzg_gearbox()
    losses = GearboxThermalModel(description).losses(LOAD_STAGE_6)
    temperatures = np.full(len(NODES), 70.0)
    temperatures[PINION_SHAFT], temperatures[WHEEL_SHAFT] = 50.0, 95.0
    state = losses.at(temperatures)
    wheel_rpm = LOAD_STAGE_6.speed_rpm / description.gear_pair.gear_ratio

    def viscosity(celsius):
        return float(description.lubricant.kinematic_viscosity(celsius, warn=False)) * 1e6

    by_side = {False: 0.0, True: 0.0}
    for mounted in description.bearings:
        by_side[mounted.on_wheel_shaft] += mounted_bearing_power(
            mounted, LOAD_STAGE_6.speed_rpm, wheel_rpm, viscosity(95.0 if mounted.on_wheel_shaft else 50.0),
            losses.normal_force)
    seal_side = {False: 0.0, True: 0.0}
    from thermogear.gearbox.bearing_loss import seal_power_loss  # noqa: PLC0415

    for seal in description.seals:
        seal_side[seal.on_wheel_shaft] += seal_power_loss(seal.shaft_diameter_mm,
                                                          wheel_rpm if seal.on_wheel_shaft else 2175.0)
    sources = state.node_sources
    assert sources[PINION_SHAFT] == pytest.approx(by_side[False] + seal_side[False], rel=1e-13)
    assert sources[WHEEL_SHAFT] == pytest.approx(by_side[True] + seal_side[True], rel=1e-13)
    assert np.sum(sources) == pytest.approx(state.total, rel=1e-14)
    # the thinner oil at the hotter wheel shaft: its bearings lose less than at the pinion shaft's 50 °C
    cold = losses.at(np.full(len(NODES), 50.0)).node_sources
    assert sources[WHEEL_SHAFT] < cold[WHEEL_SHAFT] and sources[PINION_SHAFT] == pytest.approx(cold[PINION_SHAFT],
                                                                                               rel=1e-13)


def test_a_symmetric_gearbox_has_equal_shafts():
    # reduction: equal gears (u = 1), the friction heat shared half and half, the same bearings and seals on both
    # shafts at the same speed and load: the two gears and the two shafts settle at the same temperatures
    base = illustrative_fzg_gearbox()
    gear = Gear(20, 4.5e-3, math.radians(20.0), 14e-3, 0.0, bore_radius=15e-3)
    pair = GearPair.create(gear, gear, 90e-3)
    bearings = tuple(MountedBearing(base.bearings[0].bearing, wheel, 0.5) for wheel in (False, False, True, True))
    description = dataclasses.replace(base, gear_pair=pair, bearings=bearings, pinion_heat_share=0.5,
                                      wheel_immersion=0.0, pinion_immersion=0.0, pinion_mass=base.wheel_mass)
    steady = GearboxThermalModel(description).steady_state(LOAD_STAGE_6)
    assert steady.energy_balance_w < 1e-9
    assert steady.pinion_shaft_c == pytest.approx(steady.wheel_shaft_c, abs=1e-8)
    assert steady.pinion_c == pytest.approx(steady.wheel_c, abs=1e-8)


@pytest.mark.parametrize("torque", [94.1, 302.0])
def test_the_fzg_gearbox_shafts_differ_and_balance(torque):
    # the pinion shaft turns 1.5 times faster and carries the hotter gear: it runs hotter than the wheel shaft;
    # the network's energy balance holds to 1e-9 W
    steady = GearboxThermalModel(illustrative_fzg_gearbox()).steady_state(
        GearboxOperatingPoint(2175.0, torque, 20.0))
    assert steady.energy_balance_w < 1e-9
    assert steady.pinion_shaft_c > steady.wheel_shaft_c + 3.0
    assert steady.pinion_c > steady.pinion_shaft_c and steady.wheel_c > steady.wheel_shaft_c


# --- the pinion's share of the friction heat: Blok's partition over the path -------------------------------------

def test_blok_share_of_a_symmetric_pair_is_one_half():
    # equal gears without shift: the path is symmetric about C and the rolling speeds swap, so β1 = 1/2 exactly
    gear = Gear(20, 4.5e-3, math.radians(20.0), 14e-3, 0.0, bore_radius=15e-3)
    assert rigid_pinion_heat_share(GearPair.create(gear, gear, 90e-3)) == pytest.approx(0.5, abs=1e-12)


def test_blok_share_of_the_fzg_pair_by_quadrature():
    # an independent quadrature of β1 = ∫F_n v_g β ds / ∫F_n v_g ds with scipy's adaptive rule on each stretch
    from scipy.integrate import quad  # noqa: PLC0415

    pair = illustrative_fzg_gearbox().gear_pair
    points = pair.path_points

    def integrand(roll, pinion):
        v1, v2 = (float(np.asarray(value).item()) for value in pair.rolling_speeds(np.array([roll]), 1.0))
        load = 1.0 if points["B"] <= roll <= points["D"] else 0.5
        weight = load * abs(v1 - v2)
        return weight * math.sqrt(v1) / (math.sqrt(v1) + math.sqrt(v2)) if pinion else weight

    stretches = (("A", "B"), ("B", "C"), ("C", "D"), ("D", "E"))
    heat = sum(quad(integrand, points[a], points[b], args=(False,), epsabs=0, epsrel=1e-12)[0] for a, b in stretches)
    pinion = sum(quad(integrand, points[a], points[b], args=(True,), epsabs=0, epsrel=1e-12)[0] for a, b in stretches)
    share = rigid_pinion_heat_share(pair)
    assert share == pytest.approx(pinion / heat, abs=1e-8)
    assert share == pytest.approx(0.4928, abs=1e-4)  # a little below one half for FZG C (z 16/24)
    assert illustrative_fzg_gearbox().heat_share == share
    assert illustrative_fzg_gearbox(pinion_heat_share=0.6).heat_share == 0.6
