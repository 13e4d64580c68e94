"""BacklashMeshProblem: input checks (ProblemError naming key, value, allowed range, reason) and its constructors."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics import MeshDynamicsProblem
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.errors import ProblemError

STIFFNESS = 1e8  # [N/m]
FORCE = 1e3  # [N]; static deflection w/k = 10 μm


def make(**changes):
    n = 4
    values = {"mass": 1.0, "nodes": np.linspace(0.0, 1e-3, n + 1), "pair_stiffness": np.full((2, n), STIFFNESS / 2),
              "pair_deviation": np.zeros((2, n)), "back_pair_stiffness": np.full((2, n), STIFFNESS / 2),
              "back_pair_deviation": np.zeros((2, n)), "backlash": 1e-5, "damping": np.full(n, 100.0),
              "force": FORCE}
    values.update(changes)
    return BacklashMeshProblem(**values)


def test_valid_problem_and_derived_values():
    problem = make()
    assert problem.slot_count == 2 and problem.interval_count == 4
    assert problem.displacement_scale == pytest.approx(FORCE / STIFFNESS, rel=1e-15)
    assert problem.damping_mode == "always"
    linear = problem.linear_problem()
    np.testing.assert_allclose(linear.stiffness, STIFFNESS, rtol=1e-15)


@pytest.mark.parametrize("backlash", [0.0, -1e-6, np.nan, np.inf])
def test_backlash_not_positive_is_a_jammed_mesh(backlash):
    with pytest.raises(ProblemError, match="backlash") as error:
        make(backlash=backlash)
    assert error.value.quantity == "backlash"


def test_deviations_that_close_the_backlash_are_refused():
    # e + e' = −2e-5 m closes a backlash of 1e-5 m: the pair would touch both flanks at once
    with pytest.raises(ProblemError, match="jammed"):
        make(pair_deviation=np.full((2, 4), -1e-5), back_pair_deviation=np.full((2, 4), -1e-5))
    make(pair_deviation=np.full((2, 4), -1e-5), back_pair_deviation=np.full((2, 4), 1e-5))  # pitch-type: fine


@pytest.mark.parametrize("key, value", [
    ("pair_deviation", np.zeros((3, 4))),
    ("back_pair_stiffness", np.zeros((2, 5))),
    ("damping", np.zeros(3)),
    ("force", np.ones(2)),
])
def test_shape_mismatch(key, value):
    with pytest.raises(ProblemError) as error:
        make(**{key: value})
    assert error.value.quantity == key and "shape" in error.value.allowed


@pytest.mark.parametrize("key, value", [
    ("pair_stiffness", np.full((2, 4), np.nan)),
    ("pair_stiffness", np.full((2, 4), -1.0)),
    ("pair_stiffness", np.zeros((2, 4))),
    ("damping", np.full(4, -1.0)),
    ("force", 0.0),
    ("mass", 0.0),
    ("nodes", np.array([0.0, 1e-3, 1e-3, 2e-3, 3e-3])),
    ("damping_mode", "sometimes"),
])
def test_bad_values(key, value):
    with pytest.raises(ProblemError) as error:
        make(**{key: value})
    assert error.value.quantity == key


def test_from_linear_defaults_the_back_flank_to_the_driving_flank():
    linear = MeshDynamicsProblem.square_wave(mass=1.0, mesh_period=1e-3, contact_ratio=1.6, single_stiffness=1e8,
                                             double_stiffness=1.6e8, single_damping=200.0, double_damping=250.0,
                                             force=FORCE)
    problem = BacklashMeshProblem.from_linear(linear, backlash=2e-5, pair_deviation=1e-6)
    np.testing.assert_array_equal(problem.pair_stiffness, linear.pair_stiffness)
    np.testing.assert_array_equal(problem.back_pair_stiffness, linear.pair_stiffness)
    np.testing.assert_array_equal(problem.back_pair_deviation, np.full((2, 2), 1e-6))
    np.testing.assert_array_equal(problem.damping, linear.damping)
    with pytest.raises(ProblemError, match="pair_deviation"):
        BacklashMeshProblem.from_linear(linear, backlash=2e-5, pair_deviation=np.zeros(3))
