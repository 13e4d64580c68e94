"""The mesh model: one reader of the case, speed and load as arguments, deviations in the linear problem."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel
from thermogear.simulation import Simulation


@pytest.fixture(scope="module")
def luo():
    return load_case("luo2019")


@pytest.fixture(scope="module")
def relieved(luo):
    # the paper's pair with a 15 μm linear tip relief on both gears over 2 mm of roll length
    relief = {"tip_relief_um": 15.0, "tip_relief_length_mm": 2.0}
    return luo.with_changes(**{f"gears.{gear}.{key}": value for gear in ("pinion", "wheel")
                               for key, value in relief.items()})


def test_the_load_of_a_power_falls_with_the_speed_and_a_torque_stays(luo):
    mesh = MeshModel(luo, "elastic")
    radius = luo.gear_pair.pinion.base_radius
    assert mesh.normal_load() == luo.normal_load  # the case's own point, exactly
    assert mesh.normal_load(4000.0) == pytest.approx(80e3 / (4000.0 * math.pi / 30) / radius, rel=1e-14)
    torque = MeshModel(luo.with_changes(**{"operating.power_kw": None, "operating.torque_nm": 300.0}), "elastic")
    assert torque.normal_load(4000.0) == pytest.approx(300.0 / radius, rel=1e-15)


def test_state_at_another_speed_equals_the_case_at_that_speed(luo):
    # speed and load are arguments: asking the luo2019 mesh model at 5000 rpm gives what the case at 5000 rpm gives
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for model in ("elastic", "thermal"):
            asked = MeshModel(luo, model).state(speed_rpm=5000.0)
            built = MeshModel(luo.with_changes(**{"operating.speed_rpm": 5000.0}), model).state()
            assert asked.normal_load == pytest.approx(built.normal_load, rel=1e-14)
            np.testing.assert_allclose(asked.mesh_stiffness, built.mesh_stiffness, rtol=1e-12)
            np.testing.assert_allclose(asked.mesh_damping, built.mesh_damping, rtol=1e-12)


def test_a_pair_without_deviations_has_none_and_the_linear_problem_is_the_papers(luo):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the paper's 30 °C reference oil is below the oil's fitted range
        state = MeshModel(luo, "elastic").state()
    assert not np.any(state.pair_deviation)
    assert state.static_transmission_error is None
    problem = state.problem()
    assert problem.pair_deviation is None
    assert problem.static_load == pytest.approx(luo.normal_load, rel=1e-14)  # a time mean: rounding only


def test_tip_relief_enters_the_linear_problem_as_a_deviation(relieved):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        state = MeshModel(relieved, "elastic").state()
    assert np.max(state.pair_deviation) > 0.0
    problem = state.problem()
    # the static load stays w; the deviations add Σ k_i e_i to the force of me·ẍ + c·ẋ + Σ k_i (x − e_i) = w
    assert problem.static_load == pytest.approx(relieved.normal_load, rel=1e-12)
    # at the static equilibrium x = (w + Σ k_i e_i)/Σ k_i the engaged pairs carry w between them, none pulls
    equilibrium = problem.static_transmission_error
    pair_loads = problem.pair_stiffness * (equilibrium[None, :] - problem.pair_deviation)
    engaged = problem.pair_stiffness > 0.0
    np.testing.assert_allclose(pair_loads.sum(axis=0), relieved.normal_load, rtol=1e-10)
    assert np.all(pair_loads[engaged] >= -1e-9 * relieved.normal_load)
    # the loaded static transmission error of the mesh model is that equilibrium
    np.testing.assert_allclose(state.static_transmission_error, equilibrium, rtol=1e-10)


def test_pair_loads_of_the_response_subtract_the_deviation(relieved):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        response = Simulation(relieved, "elastic").run()
    problem = response.problem
    pair = response.pair_loads()
    # pair loads sum to the system load (no damping force in the paper's dynamic load)
    np.testing.assert_allclose(pair.sum(axis=0), response.system_load(), rtol=1e-9, atol=1e-6)
    orbit = periodic_steady_state(problem, 4)
    expected = problem.pair_stiffness[:, orbit.interval] * (orbit.displacement - problem.pair_deviation[:, orbit.interval])
    np.testing.assert_allclose(pair, expected, rtol=1e-9, atol=1e-6)


def test_unknown_model_is_refused(luo):
    with pytest.raises(CaseError, match="model"):
        MeshModel(luo, "plastic")
