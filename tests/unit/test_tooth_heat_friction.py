"""The FE heat input takes its friction from the mesh model (one computation of μ for the damping and the heat).

The friction heat of the tooth model (Luo & Li Eq. 27, DIN 3990-4 μ with the pair's elastic load share, the oil
at the operating temperature) is read from :meth:`MeshModel.pair_damping_at`. The check below evaluates the
formula by hand from the same inputs (viscosity at the operating oil temperature, the pair's unit load, the sum of
rolling speeds, the relative radius of curvature, X_L) and asks for equality to 1e-12 relative: the two are the same
arithmetic on the same numbers, so only rounding order may differ.
"""

from __future__ import annotations

import dataclasses
import warnings

import numpy as np
import pytest

from thermogear import load_case
from thermogear.fem.inputs import fem_inputs
from thermogear.fem.tooth_heat import FlankHeatInput, angular_speed, flank_heat_input
from thermogear.friction import mean_friction_coefficient
from thermogear.lubricant import lubricant_from_case
from thermogear.mesh.model import MeshModel


@pytest.fixture(scope="module", params=["luo2019", "fzg_type_c"])
def case(request):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(request.param)


def test_heat_input_friction_is_the_din_formula_at_the_operating_oil_temperature(case):
    mesh = fem_inputs(case).friction
    heat = flank_heat_input(mesh, "pinion", case.fem)
    pair = mesh.gear_pair
    roll = np.sort(pair.roll_grid(201))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        contact = mesh.pair_damping_at(roll)
        oil = lubricant_from_case(case)
        viscosity = float(oil.dynamic_viscosity(case.lubricant.operating_temperature_c, warn=False))
    rolling_1, rolling_2 = pair.rolling_speeds(roll, case.operating_point.speed_rpm)
    factor = case.damping.lubricant_factor or oil.lubricant_factor
    expected = mean_friction_coefficient(contact.unit_load, case.roughness_ra, viscosity, rolling_1 + rolling_2,
                                         pair.relative_radius_of_curvature(roll), factor, check_limits=False)
    np.testing.assert_allclose(heat.friction_coefficient, expected, rtol=1e-12)
    # the damping's oil is at the reference temperature, the heat's at the operating one: μ differs between them
    assert case.lubricant.reference_temperature_c != case.lubricant.operating_temperature_c
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        damping_mu = MeshModel(case, "elastic").pair_damping_at(roll).friction_coefficient
    assert not np.allclose(damping_mu, heat.friction_coefficient, rtol=1e-3)


def test_the_heat_input_is_built_whole_and_stays_frozen(case):
    heat = flank_heat_input(fem_inputs(case).friction, "wheel", case.fem)
    assert heat.base_radius == case.gear_pair.wheel.base_radius
    with pytest.raises(dataclasses.FrozenInstanceError):
        heat.base_radius = 0.0
    assert {field.name for field in dataclasses.fields(FlankHeatInput)} >= {"base_radius", "flux"}


def test_the_wheel_turns_slower_by_the_gear_ratio(case):
    pair, speed = case.gear_pair, case.operating_point.speed_rpm
    assert angular_speed(pair, speed, "pinion") == pytest.approx(speed * np.pi / 30.0, rel=1e-15)
    assert angular_speed(pair, speed, "wheel") * pair.gear_ratio == pytest.approx(speed * np.pi / 30.0, rel=1e-15)
