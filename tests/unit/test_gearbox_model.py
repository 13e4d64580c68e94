"""The gearbox thermal model on the illustrative FZG-type gearbox: energy balance, warm-up to the steady state,
capacity scaling, limits, runaway, losses following the temperatures and backlash over a warm-up and a cold start."""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np
import pytest

from thermogear.errors import CaseError
from thermogear.gearbox.backlash import (backlash_allowance, backlash_at_temperatures, backlash_change_estimate,
                                         cold_start_backlash)
from thermogear.gearbox.description import GearboxOperatingPoint, Housing
from thermogear.gearbox.fzg_example import fzg_type_c_pair, illustrative_fzg_gearbox
from thermogear.gearbox.losses import NODES
from thermogear.gearbox.model import GearboxThermalModel
from thermogear.gearbox.network import NoSteadyStateError

LOAD_STAGE_6 = GearboxOperatingPoint(speed_rpm=2175.0, torque=135.3, ambient_c=20.0)


@pytest.fixture(autouse=True)
def quiet_extrapolation():
    # the built-in oil's viscosity fit covers 40–100 °C; warm-ups from 20 °C leave it on purpose (tested below)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


@pytest.fixture(scope="module")
def model() -> GearboxThermalModel:
    return GearboxThermalModel(illustrative_fzg_gearbox())


def test_steady_state_energy_balance(model):
    # the brief's bound: heat shed by the housing equals the sum of the losses to 1e-9 relative
    steady = model.steady_state(LOAD_STAGE_6)
    assert steady.energy_residual < 1e-9
    assert steady.heat_out == pytest.approx(steady.losses.total, rel=1e-9)
    # heat flows outwards: gears hottest, then shafts and oil, housing coolest, all above the air
    assert steady.pinion_c > steady.pinion_shaft_c > steady.housing_c > LOAD_STAGE_6.ambient_c
    assert steady.wheel_c > steady.wheel_shaft_c > steady.housing_c
    assert steady.wheel_c > steady.oil_c > steady.housing_c


def test_losses_reported_per_source_and_efficiency(model):
    steady = model.steady_state(LOAD_STAGE_6)
    losses = steady.losses
    assert losses.total == pytest.approx(losses.mesh + losses.bearings + losses.seals + losses.churning, rel=1e-15)
    assert losses.efficiency == pytest.approx(1.0 - losses.total / (135.3 * 2175.0 * math.pi / 30.0), rel=1e-12)
    assert np.sum(losses.node_sources) == pytest.approx(losses.total, rel=1e-14)
    assert min(losses.mesh, losses.bearings, losses.seals, losses.churning) > 0.0


def test_losses_follow_the_oil_temperature(model):
    # thinner oil: less churning and bearing drag, more tooth friction (the friction law's μ ∝ η^e, e < 0)
    losses = model.losses(LOAD_STAGE_6)
    cold, warm = losses.at(np.full(len(NODES), 40.0)), losses.at(np.full(len(NODES), 90.0))
    assert warm.churning < cold.churning
    assert warm.friction_coefficient > cold.friction_coefficient
    viscosity_ratio = (model.description.lubricant.dynamic_viscosity(90.0, warn=False)
                       / model.description.lubricant.dynamic_viscosity(40.0, warn=False))
    exponent = model.description.friction.viscosity_exponent
    assert exponent == -0.05  # Schlenk's law, the loss model's default
    assert warm.friction_coefficient / cold.friction_coefficient == pytest.approx(viscosity_ratio**exponent,
                                                                                  rel=1e-12)


def test_warm_up_ends_at_the_steady_state(model):
    # 20 slowest time constants (e^-20 of the initial 60 K gap ≈ 1e-7 K): the history ends on the steady state
    steady = model.steady_state(LOAD_STAGE_6)
    duration = 20.0 * float(np.max(steady.time_constants))
    history = model.warm_up(LOAD_STAGE_6, duration, points=41)
    assert history.temperatures_c[:, -1] == pytest.approx(steady.temperatures_c, abs=1e-3)
    # ∫P dt = ΔΣCT + ∫Q_out dt: the energy integrals are states and implicit Runge–Kutta keeps linear invariants,
    # so this holds to rounding and checks the assembly (symmetric exchange, the boundary flux), not the accuracy
    assert history.energy_residual < 1e-9
    assert history.backlash[-1] == pytest.approx(steady.backlash, abs=1e-9)


def test_time_constants_scale_with_the_capacities():
    # every mass and the oil volume doubled: every τ doubles (conductances unchanged)
    base = illustrative_fzg_gearbox()
    heavy = dataclasses.replace(base, pinion_mass=2 * base.pinion_mass, wheel_mass=2 * base.wheel_mass,
                                shaft_mass=2 * base.shaft_mass, oil_volume=2 * base.oil_volume,
                                housing=dataclasses.replace(base.housing, mass=2 * base.housing.mass))
    light_steady = GearboxThermalModel(base).steady_state(LOAD_STAGE_6)
    heavy_steady = GearboxThermalModel(heavy).steady_state(LOAD_STAGE_6)
    # doubling the oil volume also changes the churning loss (V0 enters C_m), so the steady temperatures and
    # conductances differ slightly: compare τ with the outer conductance at the same housing temperature
    network = GearboxThermalModel(heavy).network(LOAD_STAGE_6)
    light_network = GearboxThermalModel(base).network(LOAD_STAGE_6)
    assert network.time_constants(light_steady.temperatures_c) == pytest.approx(
        2.0 * light_network.time_constants(light_steady.temperatures_c), rel=1e-10)
    assert heavy_steady.energy_residual < 1e-9


def test_infinite_internal_conductances_give_one_temperature():
    # every internal coefficient huge: gears, shafts, oil and housing at one temperature (to P/G ≈ 1e-3 K)
    description = illustrative_fzg_gearbox(gear_oil_coefficient=1e7, oil_housing_coefficient=1e7,
                                           gear_shaft_conductance=1e6, shaft_oil_conductance=1e6,
                                           shaft_housing_conductance=1e6)
    steady = GearboxThermalModel(description).steady_state(LOAD_STAGE_6)
    assert np.ptp(steady.temperatures_c) < 5e-3


def test_adiabatic_gears_have_no_steady_state():
    # gears joined to nothing: their friction heat has no way out
    description = illustrative_fzg_gearbox(gear_oil_coefficient=0.0, gear_shaft_conductance=0.0)
    with pytest.raises(NoSteadyStateError):
        GearboxThermalModel(description).steady_state(LOAD_STAGE_6)


def test_runaway_is_reported_when_cooling_is_too_weak():
    # a tiny housing in still air cannot shed the tooth friction, which grows as the oil thins (μ ∝ η^-0.25)
    base = illustrative_fzg_gearbox()
    tiny = dataclasses.replace(base.housing, length=0.05, width=0.05, height=0.05, air_speed=0.0, emissivity=0.05)
    with pytest.raises(NoSteadyStateError):
        GearboxThermalModel(dataclasses.replace(base, housing=tiny)).steady_state(
            GearboxOperatingPoint(2175.0, 265.1, 20.0))


def test_cold_start_at_minus_forty_and_bad_inputs(model):
    history = model.warm_up(LOAD_STAGE_6, 600.0, points=11, initial_c=-40.0)
    assert np.all(np.isfinite(history.temperatures_c))
    assert np.all(np.diff(history.node("oil")) > 0.0)  # a cold box only warms
    assert history.churning_loss[0] > history.churning_loss[-1]  # cold oil churns harder
    with pytest.raises(CaseError, match="warm_up.initial_c"):
        model.warm_up(LOAD_STAGE_6, 600.0, initial_c=-50.0)
    with pytest.raises(CaseError, match="operating.speed_rpm"):
        GearboxOperatingPoint(0.0, 100.0)
    with pytest.raises(CaseError, match="node"):
        history.node("gear")


def test_viscosity_extrapolation_is_announced(model):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        model.warm_up(LOAD_STAGE_6, 60.0, points=3)
    assert any("viscosity fit" in str(warning.message) for warning in caught)


def test_backlash_formula_cases():
    # FZG C, steel gears 20 K above a steel housing: Δj = −2·sin α_w·a·λ·20 = −16.07 μm (first order); the exact
    # operating geometry agrees to 0.5 % (second-order terms and the unequal gear radii)
    pair = fzg_type_c_pair()
    allowance = backlash_allowance(pair)
    exact = backlash_at_temperatures(pair, allowance, 11.5e-6, 11.5e-6, 40.0, 40.0, 20.0, 20.0) - allowance.nominal
    estimate = backlash_change_estimate(pair, 11.5e-6, 11.5e-6, 20.0, 0.0)
    assert estimate == pytest.approx(-16.07e-6, abs=0.01e-6)
    assert exact == pytest.approx(estimate, rel=5e-3)


def test_cold_start_in_an_aluminium_housing():
    # steel gears (11.5e-6) in aluminium (23e-6), assembled at 20 °C, soaked at −30 °C: −40.2 μm (first order
    # 2·sin α_w·a·(23 − 11.5)e-6·(−50)); the margin left is the AGMA minimum 240.75 μm less that
    pair = fzg_type_c_pair()
    allowance = backlash_allowance(pair)
    cold = cold_start_backlash(pair, allowance, 11.5e-6, 23e-6, -30.0, 20.0)
    assert cold.change == pytest.approx(backlash_change_estimate(pair, 11.5e-6, 23e-6, -50.0, -50.0), rel=5e-3)
    assert cold.change == pytest.approx(-40.2e-6, abs=0.2e-6)
    assert cold.nominal == pytest.approx(240.75e-6, rel=1e-9)
    assert not cold.jammed


def test_smallest_backlash_during_a_warm_up_comes_before_the_steady_state():
    # aluminium housing: the gears heat in minutes, the housing in ~40 min, so the backlash first closes (gears
    # expand) and then reopens as the housing (λ_h = 2 λ_g) catches up: the minimum is inside the warm-up
    base = illustrative_fzg_gearbox()
    aluminium = dataclasses.replace(base.housing, expansion=23e-6, specific_heat=900.0, mass=15.0)
    model = GearboxThermalModel(dataclasses.replace(base, housing=aluminium))
    history = model.warm_up(LOAD_STAGE_6, 4 * 3600.0, points=241)
    smallest, when = history.smallest_backlash
    assert 0.0 < when < history.times[-1]
    assert smallest < history.backlash[-1] and smallest < history.backlash[0]


@pytest.mark.parametrize("changes, key", [
    ({"oil_volume": 0.0}, "oil_volume"),
    ({"pinion_mass": -1.0}, "pinion_mass"),
    ({"wheel_mass": True}, "wheel_mass"),  # a boolean is not a number
    ({"gear_oil_coefficient": float("nan")}, "gear_oil_coefficient"),
    ({"pinion_heat_share": 1.5}, "pinion_heat_share"),
    ({"wheel_immersion": 1.0}, "wheel_immersion"),
])
def test_description_refuses_bad_inputs_by_name(changes, key):
    with pytest.raises(CaseError, match=key):
        illustrative_fzg_gearbox(**changes)


@pytest.mark.parametrize("changes, key", [
    ({"length": 0.0}, "housing.length"), ({"emissivity": 1.5}, "housing.emissivity"),
    ({"air_speed": -1.0}, "housing.air_speed")])
def test_housing_refuses_bad_inputs_by_name(changes, key):
    fields = dict(length=0.4, width=0.3, height=0.3, mass=30.0)
    fields.update(changes)
    with pytest.raises(CaseError, match=key):
        Housing(**fields)


def test_the_steady_state_and_the_warm_up_as_tables_and_datasets(model):
    # issue 33: every result typed with to_dataframe() and to_dataset(), holding the same numbers
    steady = model.steady_state(LOAD_STAGE_6)
    frame, dataset = steady.to_dataframe(), steady.to_dataset()
    assert frame.loc["oil", "temperature_c"] == steady.oil_c and frame.attrs["heat_out_w"] == steady.heat_out
    assert float(dataset["temperature"].sel(node="pinion")) == steady.pinion_c
    assert float(dataset["loss"].sum()) == pytest.approx(steady.losses.total, rel=1e-14)
    history = model.warm_up(LOAD_STAGE_6, 600.0, points=7)
    table, series = history.to_dataframe(), history.to_dataset()
    assert list(table.index) == list(history.times) and np.array_equal(table["oil_c"], history.node("oil"))
    assert np.array_equal(series["backlash"].values, history.backlash)
    assert series["temperature"].dims == ("node", "time")
