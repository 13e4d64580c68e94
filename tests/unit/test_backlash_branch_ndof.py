"""Speed continuation of the n-DOF backlash orbit: on a 1-DOF system it jumps where the existing 1-DOF continuation
(``thermogear.dynamics.backlash.backlash_continuation``) jumps, up and down, and follows the same orbits."""

from __future__ import annotations

import numpy as np
import pytest
from backlash_textbook import FORCE, X_STATIC, textbook_problem

from thermogear.dynamics.backlash.backlash_branch_ndof import follow_backlash_branch
from thermogear.dynamics.backlash.backlash_continuation import follow_branch
from thermogear.dynamics.backlash.backlash_ndof import BacklashSystem
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.errors import ProblemError

RATIOS = np.round(np.arange(0.80, 1.1001, 0.01), 6)


def _as_matrices(problem) -> BacklashSystem:
    stiffness, error, one = problem.pair_stiffness[0], problem.pair_deviation[0], np.ones((1, 1))
    linear = PiecewiseLinearSystem(mass=one, stiffness=np.zeros((1, 1)), damping=np.zeros((1, 1)), force=[FORCE],
                                   nodes=problem.nodes, stiffness_pattern=one, stiffness_factor=stiffness,
                                   damping_pattern=one, damping_factor=problem.damping, force_pattern=[1.0],
                                   force_factor=stiffness * error)
    return BacklashSystem(linear, [1.0], error, problem.backlash)


@pytest.mark.slow
def test_jumps_equal_the_one_dof_continuation():
    problems = [textbook_problem(ratio, 0.03, n=8) for ratio in RATIOS]
    systems = [_as_matrices(problem) for problem in problems]
    for direction in ("up", "down"):
        reference = follow_branch(problems, direction, RATIOS)
        branch = follow_backlash_branch(systems, direction, RATIOS)
        assert np.all(branch.converged) and np.all(branch.stable)
        jump = branch.jumps()
        swing = reference["dte_peak_to_peak"]
        step = 1 if direction == "up" else -1
        expected = [i for i in range(RATIOS.size)[::step][:-1]
                    if abs(swing[i + step] - swing[i]) > 0.2 * max(swing[i], swing[i + step])]
        # the same grid interval: the jump is located to the grid spacing (0.01 of Ω), as in the 1-DOF sweep
        assert list(jump) == expected and len(expected) == 1
        # the same orbits everywhere (same attractor picked on both sides of the jump): Newton tolerance 1e-10 of
        # the state, and the exact flows agree to 1e-8 (the existing 1-DOF solver test): 1e-6 of x_st
        np.testing.assert_allclose(branch.initial_state[:, 0], reference.initial_state[:, 0], rtol=0,
                                   atol=1e-6 * X_STATIC)
        # the swing: the 1-DOF metric finds the exact extrema, the n-DOF branch samples 8 substeps per piece
        # (64 per period): a sampled extremum of a harmonic is low by at most 1 − cos(π/64) = 1.2e-3
        assert np.all(branch.peak_to_peak <= swing * (1 + 1e-9))
        np.testing.assert_allclose(branch.peak_to_peak, swing, rtol=2.5e-3)


def test_bad_direction_is_named():
    with pytest.raises(ProblemError, match="direction"):
        follow_backlash_branch([_as_matrices(textbook_problem(1.0, 0.03, n=8))], "sideways")


@pytest.mark.parametrize(("count", "parameter", "key"), [(0, None, "systems"), (2, [1.0, 2.0, 3.0], "parameter")])
def test_both_continuations_refuse_the_same_inputs(count, parameter, key):
    # issue 33: the 1-DOF continuation (over problems) and the n-DOF one (over systems) check their inputs with one
    # function; an empty sequence and a label count other than the item count are refused by both, naming the key
    problem = textbook_problem(1.0, 0.03, n=8)
    with pytest.raises(ProblemError, match=key):
        follow_backlash_branch([_as_matrices(problem)] * count, "up", parameter)
    with pytest.raises(ProblemError, match=key.replace("systems", "problems")):
        follow_branch([problem] * count, "up", parameter)
