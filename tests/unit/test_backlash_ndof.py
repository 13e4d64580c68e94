"""Shooting for periodic orbits with backlash on n-DOF matrices: the 1-DOF case against the existing backlash
solver, and an n-DOF orbit that never loses contact against the linear periodic state."""

from __future__ import annotations

import numpy as np
import pytest
from backlash_textbook import FORCE, textbook_problem

from thermogear.dynamics.backlash.backlash_ndof import (BACK_CONTACT, FREE_FLIGHT, BacklashSystem, backlash_flow_ndof,
                                               backlash_periodic_orbit, odd_crossings)
from thermogear.dynamics.backlash.backlash_periodic import periodic_response as one_dof_backlash_response
from thermogear.dynamics.backlash.backlash_trajectory import backlash_trajectory
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, periodic_response
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


def _textbook_system(deviation: float = 0.3, backlash: float = 1.0) -> BacklashSystem:
    """The textbook oscillator near resonance (0.9, ζ = 0.08) as an n-DOF system of one coordinate."""
    from test_backlash_branch_ndof import _as_matrices

    return _as_matrices(textbook_problem(0.9, 0.08, deviation=deviation, backlash=backlash, n=8))


def test_parity_rule_flags_an_odd_crossing():
    assert odd_crossings({("mesh", 0): 2, ("mesh", 1): 4, ("zone", 0, 1): 2}) == []
    assert odd_crossings({("mesh", 0): 1, ("zone", 1, -1): 3, ("zone", 1, 1): 2}) == [("mesh", 0), ("zone", 1, -1)]
    # a closed orbit with contact loss and back-flank impacts crosses both of the mesh's boundaries twice
    system = _textbook_system(0.5, 0.1)
    orbit = backlash_periodic_orbit(system, substeps=8)
    _, _, info = backlash_flow_ndof(system, orbit.initial_state, substeps=8)
    assert orbit.converged and orbit.failure == "" and orbit.switches == 4
    assert info["crossings"] == {("mesh", 0): 2, ("mesh", 1): 2} and odd_crossings(info["crossings"]) == []
    # a motion that is no orbit: released at rest in the middle of the gap it lands on the driving flanks, bounces
    # and ends the period on the back flanks: g = −b crossed once, which the rule reports (a path that does not
    # close may cross a boundary an odd number of times; only a closed one may not)
    start = np.array([system.deviation[0] - 0.5 * system.backlash, 0.0])
    end, _, info = backlash_flow_ndof(system, start, substeps=8)
    assert system.region(np.append(end, 1.0), 0) == BACK_CONTACT
    assert odd_crossings(info["crossings"]) == [("mesh", 1)]


def test_trajectory_samples_are_the_flow_s_exact_states():
    # every grid sample that falls on a recorded segment end (the sub-steps are multiples of the grid here) is the
    # same product of exponentials: 1e-12 of the motion's scale (measured ~1e-16)
    system = _textbook_system(0.5, 0.1)
    orbit = backlash_periodic_orbit(system, substeps=8)
    trajectory = backlash_trajectory(system, orbit.initial_state, periods=2, samples_per_piece=4, substeps=8)
    period = system.linear.period
    for index in range(2):
        _, _, info = backlash_flow_ndof(system, orbit.initial_state if index == 0 else trajectory_start, substeps=8,
                                        record=True)
        trajectory_start = info["states"][-1]
        scale = np.abs(np.array(info["states"])).max()
        matched = 0
        for time, state in zip(info["time"], info["states"]):
            rows = np.flatnonzero(np.abs(trajectory.time - (time + index * period)) < 1e-13 * period)
            for row in rows:
                assert np.abs(trajectory.state[row] - state).max() < 1e-12 * scale
                matched += 1
        assert matched >= 8 * 4  # the grid (and every switch, on both sides)
    # both sides of every switch: 4 switches a period, each sampled twice with the region before and after
    assert trajectory.switches == 8 and trajectory.free_flight_time == pytest.approx(2 * orbit.free_flight_time)
    twice = np.flatnonzero(trajectory.time[1:] == trajectory.time[:-1])
    assert np.count_nonzero(trajectory.region[twice] != trajectory.region[twice + 1]) == 8
    free = trajectory.region == FREE_FLIGHT
    gap = trajectory.displacement[:, 0] - system.deviation[trajectory.piece]
    assert np.all((gap[free] <= 1e-12 * scale) & (gap[free] >= -system.backlash - 1e-12 * scale))
    assert np.all(np.diff(trajectory.time) >= 0.0) and trajectory.time[-1] == pytest.approx(2 * period, rel=1e-12)
    assert np.abs(trajectory.end_state - trajectory.state[-1]).max() < 1e-12 * scale


@pytest.mark.parametrize("odd_below, substeps, converged", [(8, 8, True), (10**6, 64, False)])
def test_an_odd_crossing_count_refines_the_substeps_or_fails(monkeypatch, odd_below, substeps, converged):
    # the flow made to report one extra crossing of g = 0 below ``odd_below`` sub-steps: the guard shoots again
    # with 8 (and finds the orbit, even again) or, still odd at 64, says not converged and why
    import thermogear.dynamics.backlash.backlash_ndof as module

    flow = module.backlash_flow_ndof

    def missing_one(system, state, steps=16, **options):
        end, matrix, info = flow(system, state, steps, **options)
        if steps < odd_below:
            info["crossings"][("mesh", 0)] = info["crossings"].get(("mesh", 0), 0) + 1
        return end, matrix, info

    monkeypatch.setattr(module, "backlash_flow_ndof", missing_one)
    orbit = module.backlash_periodic_orbit(_textbook_system(0.5, 0.1), substeps=4)
    assert orbit.substeps == substeps and orbit.converged == converged
    assert (orbit.failure == "") == converged
    if not converged:
        assert "odd number of times" in orbit.failure and "('mesh', 0)" in orbit.failure and not orbit.stable


def test_the_start_up_check_takes_the_motion_prepared_on_the_orbit_s_pass(monkeypatch):
    # the switch-free orbit's solve (chunked route) prepares the start-up check's motion when asked: the check then
    # runs no pass of its own and decides as with its own pass (the motion from rest stays in driving contact)
    import thermogear.dynamics.backlash.backlash_orbits_ndof as orbits
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic
    from thermogear.dynamics.backlash.backlash_ndof import STARTUP_MOTION, WATCH_STARTUP

    linear = _chain()
    system = BacklashSystem(linear, linear.force_pattern, np.zeros(2), backlash=1e-5)
    monkeypatch.setattr(periodic, "LEAN_ROUTE_BYTES", 0)
    own = orbits.startup_orbit(system, backlash_periodic_orbit(system, substeps=8), 5, 8)
    cache = {WATCH_STARTUP: True}
    orbit = backlash_periodic_orbit(system, substeps=8, cache=cache)
    assert (STARTUP_MOTION, 8) in cache
    monkeypatch.setattr(orbits, "motion_projections", lambda *arguments: pytest.fail("a pass of its own"))
    shared = orbits.startup_orbit(system, orbit, 5, 8, cache=cache)
    assert own.same and not own.left_contact_state
    assert shared.same and not shared.left_contact_state
