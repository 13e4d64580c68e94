"""The friction law of the friction damping as a choice (``[damping] friction_model``, the loss model's registry):
the default is the paper's law, number for number; another law gives, point by point along the path, its own μ
and c = 4μk/(πω); the speed and load scaling follows the law's exponent; bad inputs are refused at load."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.friction.damping import friction_damping, friction_damping_exponents, friction_pair_damping
from thermogear.errors import CaseError
from thermogear.friction import mean_friction_coefficient
from thermogear.friction.models import FRICTION_MODELS, SCHLENK_LUBRICANT_FACTORS, PitchContact, friction_law
from thermogear.lubricant import lubricant_from_case
from thermogear.mesh.model import MeshModel


# the built-in oils' viscosity fits cover 40–100 °C; these checks leave them on purpose
pytestmark = pytest.mark.filterwarnings("ignore")


def _arrays():
    shares = np.array([0.2, 0.5, 1.0, 0.5])
    speeds = np.array([4.0, 5.0, 6.0, 7.0])
    radii = np.array([5e-3, 7e-3, 9e-3, 11e-3])
    viscosity = np.array([0.02, 0.021, 0.022, 0.023])
    return shares, speeds, radii, viscosity


def test_the_default_is_the_papers_law_bit_for_bit():
    shares, speeds, radii, viscosity = _arrays()
    stiffness = np.full(4, 3e8)
    default = friction_pair_damping(stiffness, shares, 4e5, 0.4e-6, viscosity, speeds, radii, 1.0, 2000.0)
    paper = friction_pair_damping(stiffness, shares, 4e5, 0.4e-6, viscosity, speeds, radii, 1.0, 2000.0,
                                  FRICTION_MODELS["paper"])
    direct = mean_friction_coefficient(shares * 4e5, 0.4e-6, viscosity, speeds, radii, 1.0, check_limits=False)
    for result in (default, paper):
        assert np.array_equal(result[0], direct)
        assert np.array_equal(result[1], friction_damping(stiffness, direct, 2000.0))


@pytest.mark.parametrize("name", ["schlenk", "iso_tr_13989_2"])
def test_another_law_gives_its_own_friction_and_damping_point_by_point(name):
    shares, speeds, radii, viscosity = _arrays()
    stiffness = np.array([1e8, 2e8, 3e8, 2e8])
    law = friction_law(name)
    friction, damping, unit_load = friction_pair_damping(stiffness, shares, 4e5, 0.4e-6, viscosity, speeds, radii,
                                                         0.846, 2000.0, law)
    for index in range(4):
        expected = law.coefficient(PitchContact(float(unit_load[index]), 0.4e-6, float(viscosity[index]),
                                                float(speeds[index]), float(radii[index]), 0.846), warn=False)
        assert friction[index] == pytest.approx(expected, rel=1e-13)
        assert damping[index] == pytest.approx(4.0 * expected * stiffness[index] / (math.pi * 2000.0), rel=1e-13)


def test_a_constant_friction_gives_a_damping_proportional_to_the_stiffness():
    shares, speeds, radii, viscosity = _arrays()
    stiffness = np.array([1e8, 2e8, 3e8, 2e8])
    friction, damping, _ = friction_pair_damping(stiffness, shares, 4e5, 0.4e-6, viscosity, speeds, radii, 1.0,
                                                 2000.0, FRICTION_MODELS["constant"], 0.05)
    assert np.array_equal(friction, np.full(4, 0.05))
    assert damping == pytest.approx(4.0 * 0.05 * stiffness / (math.pi * 2000.0), rel=1e-15)


@pytest.mark.parametrize("name, speed, load", [("paper", -1.25, 0.25), ("schlenk", -1.2, 0.2),
                                               ("iso_tr_13989_2", -1.2, 0.2), ("constant", -1.0, 0.0)])
def test_the_damping_scaling_follows_the_law(name, speed, load):
    assert friction_damping_exponents(FRICTION_MODELS[name]) == pytest.approx((speed, load), abs=1e-15)


@pytest.fixture(scope="module")
def luo():
    return load_case("luo2019")


def test_the_case_key_chooses_the_law_of_the_mesh_model(luo):
    # luo2019 gives X_L = 1 in [damping]; Schlenk's law with its own X_L (the PAO of the set: 0.666) needs the key
    # removed
    document_changes = {"damping.friction_model": "schlenk", "damping.lubricant_factor": None}
    schlenk_case = luo.with_changes(**document_changes)
    paper, schlenk = MeshModel(luo, "elastic"), MeshModel(schlenk_case, "elastic")
    assert paper.damping_friction_law.name == "paper" and schlenk.damping_friction_law.name == "schlenk"
    points = luo.gear_pair.path_points
    roll = np.linspace(points["A"], points["E"], 9)
    ours, theirs = schlenk.pair_damping_at(roll), paper.pair_damping_at(roll)
    # the same pair stiffness and load share, the other law's μ: the dampings stand in the ratio of the μ
    assert np.array_equal(ours.pair_stiffness, theirs.pair_stiffness)
    assert ours.damping == pytest.approx(theirs.damping * ours.friction_coefficient / theirs.friction_coefficient,
                                         rel=1e-12)
    for index in (0, 4, 8):
        expected = friction_law("schlenk").coefficient(PitchContact(
            float(ours.unit_load[index]), luo.roughness_ra, float(ours.viscosity[index]),
            float(np.sum(luo.gear_pair.rolling_speeds(roll[index], luo.operating_point.speed_rpm))),
            float(luo.gear_pair.relative_radius_of_curvature(roll[index])),
            SCHLENK_LUBRICANT_FACTORS[lubricant_from_case(luo).base_oil]),
            warn=False)
        assert ours.friction_coefficient[index] == pytest.approx(expected, rel=1e-12)
    assert schlenk.damping_scaling[0] == pytest.approx(-1.2) and paper.damping_scaling[0] == pytest.approx(-1.25)


def test_a_constant_damping_law_needs_its_coefficient_and_nothing_else(luo):
    with pytest.raises(CaseError) as caught:
        luo.with_changes(**{"damping.friction_model": "constant", "damping.lubricant_factor": None})
    assert caught.value.key == "damping.friction_coefficient"
    with pytest.raises(CaseError) as caught:
        luo.with_changes(**{"damping.friction_coefficient": 0.05})
    assert caught.value.key == "damping.friction_coefficient"
    constant = luo.with_changes(**{"damping.friction_model": "constant", "damping.friction_coefficient": 0.05,
                                   "damping.lubricant_factor": None})
    points = luo.gear_pair.path_points
    state = MeshModel(constant, "elastic").pair_damping_at(np.array([points["A"], points["E"]]))
    assert np.array_equal(state.friction_coefficient, [0.05, 0.05])


def test_a_law_without_a_lubricant_factor_for_the_oil_is_refused_at_load(luo):
    # Schlenk's law has no published X_L for traction fluids: refused at load, naming the damping's key
    with pytest.raises(CaseError) as caught:
        luo.with_changes(**{"damping.friction_model": "schlenk", "damping.lubricant_factor": None,
                            "lubricant.base_oil": "traction"})
    assert caught.value.key == "damping.lubricant_factor"
