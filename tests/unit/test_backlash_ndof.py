"""Shooting for periodic orbits with backlash on n-DOF matrices: the 1-DOF case against the existing backlash
solver, and an n-DOF orbit that never loses contact against the linear periodic state."""

from __future__ import annotations

import numpy as np
import pytest
from backlash_textbook import FORCE, textbook_problem

from thermogear.dynamics.backlash_ndof import BacklashSystem, backlash_flow_ndof, backlash_periodic_orbit
from thermogear.dynamics.backlash_periodic import periodic_response as one_dof_backlash_response
from thermogear.dynamics.periodic_ndof import PiecewiseLinearSystem, periodic_response
from thermogear.errors import ProblemError


@pytest.mark.slow
@pytest.mark.parametrize("deviation, backlash", [(0.3, 1.0), (0.5, 0.1)])
def test_one_dof_case_equals_the_existing_backlash_solver(deviation, backlash):
    # the textbook oscillator near resonance: contact loss (and, with the small backlash, back-flank impacts)
    problem = textbook_problem(0.9, 0.08, deviation=deviation, backlash=backlash, n=8)
    reference = one_dof_backlash_response(problem)
    stiffness, error, one = problem.pair_stiffness[0], problem.pair_deviation[0], np.ones((1, 1))
    linear = PiecewiseLinearSystem(mass=one, stiffness=np.zeros((1, 1)), damping=np.zeros((1, 1)), force=[FORCE],
                                   nodes=problem.nodes, stiffness_pattern=one, stiffness_factor=stiffness,
                                   damping_pattern=one, damping_factor=problem.damping, force_pattern=[1.0],
                                   force_factor=stiffness * error)
    orbit = backlash_periodic_orbit(BacklashSystem(linear, [1.0], error, problem.backlash), substeps=8)
    assert reference.response == "periodic" and orbit.converged and orbit.stable
    assert orbit.free_flight_time > 0.0
    assert (orbit.back_contact_time > 0.0) == (backlash < 0.5)
    # two exact solutions of the same piecewise-linear flow (closed form vs expm, both switch times located to
    # ~1e-13 of a piece): 1e-8 relative leaves a wide margin
    assert orbit.initial_state == pytest.approx(np.array(reference.initial_state), rel=1e-8)
    assert np.sort(np.abs(orbit.multipliers)) == pytest.approx(np.sort(np.abs(reference.multipliers)), rel=1e-8)


def _chain(size: int = 6) -> PiecewiseLinearSystem:
    """Masses on springs to ground with a parametric mesh spring between DOFs 0 and 1 loaded in compression."""
    rng = np.random.default_rng(3)
    stiffness = np.diag(rng.uniform(1e8, 2e8, size)) * 2
    for i in range(size - 1):
        stiffness[i, i + 1] = stiffness[i + 1, i] = -1e8
    mass = np.diag(rng.uniform(0.5, 1.5, size))
    w = np.zeros(size)
    w[[0, 1]] = [1.0, -1.0]
    force = np.zeros(size)
    force[[0, 1]] = [2000.0, -2000.0]
    return PiecewiseLinearSystem(mass=mass, stiffness=stiffness, damping=100.0 * mass + 1e-6 * stiffness,
                                 force=force, nodes=[0.0, 4e-4, 1e-3], stiffness_pattern=np.outer(w, w),
                                 stiffness_factor=[3e8, 2e8], damping_pattern=np.outer(w, w),
                                 damping_factor=[300.0, 200.0], force_pattern=w, force_factor=[0.0, 0.0])


def test_orbit_in_permanent_contact_is_the_linear_one():
    # a large static load keeps the mesh in driving contact: the backlash orbit is the linear periodic state
    linear = _chain()
    system = BacklashSystem(linear, linear.force_pattern, np.zeros(2), backlash=1e-5)
    orbit = backlash_periodic_orbit(system, substeps=8)
    reference = periodic_response(linear, 1)
    assert orbit.converged and orbit.switches == 0 and orbit.free_flight_time == 0.0
    scale = np.abs(reference.initial_state).max()
    assert np.abs(orbit.initial_state - reference.initial_state).max() < 1e-9 * scale
    # and the flow's monodromy is the linear one (no switch, so no saltation)
    _, monodromy, _ = backlash_flow_ndof(system, reference.initial_state, substeps=8)
    assert np.sort(np.abs(np.linalg.eigvals(monodromy))) == pytest.approx(np.sort(np.abs(reference.multipliers)),
                                                                          rel=1e-9)


def test_bad_backlash_is_refused():
    with pytest.raises(ProblemError, match="backlash"):
        BacklashSystem(_chain(), _chain().force_pattern, np.zeros(2), backlash=0.0)
