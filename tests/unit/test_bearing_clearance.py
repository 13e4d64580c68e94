"""A bearing's radial clearance as dead zones (``DeadZone``) in the n-DOF backlash solver: zero clearance is the
linear bearing, a clearance wider than the motion is no bearing, and an orbit with impacts is checked against an
independent solve_ivp integration of the force law; the drivetrain's ``Bearing(radial_clearance=…)`` feeds it."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from test_backlash_ndof import _chain

from thermogear.drivetrain import Bearing, NodeLocation
from thermogear.dynamics.backlash.backlash_ndof import (BacklashSystem, DeadZone, backlash_flow_ndof,
                                                        backlash_periodic_orbit)
from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
from thermogear.errors import CaseError, ProblemError

SUPPORT, SUPPORT_DAMPING, DOF = 1e8, 400.0, 5


def _with_support(linear, stiffness: float = SUPPORT, damping: float = SUPPORT_DAMPING, push: float = 0.0):
    """The chain with a further spring and dashpot from its last DOF to ground (the bearing in contact) and a
    static force ``push`` [N] on that DOF."""
    unit = np.zeros(linear.size)
    unit[DOF] = 1.0
    pattern = np.outer(unit, unit)
    return replace(linear, stiffness=linear.stiffness + stiffness * pattern,
                   damping=linear.damping + damping * pattern, force=linear.force + push * unit), unit


def _system(clearance: float, push: float = 0.0) -> BacklashSystem:
    linear, unit = _with_support(_chain(), push=push)
    zone = DeadZone(unit, SUPPORT, SUPPORT_DAMPING, clearance)
    return BacklashSystem(linear, linear.force_pattern, np.zeros(2), backlash=1e-5, dead_zones=(zone,))


def test_zero_clearance_is_the_linear_bearing():
    # δ = 0: the force law k·u is the same on both sides, so the orbit is the linear one although u changes sign
    # (the switches at u = 0 only split segments: the located switch times leave ~1e-13 of a piece, so 1e-9)
    system = _system(0.0)
    orbit = backlash_periodic_orbit(system, substeps=8)
    reference = periodic_response(system.linear, 1)
    _, _, info = backlash_flow_ndof(system, orbit.initial_state, substeps=8)
    assert orbit.converged and orbit.switches == 0 and info["zone_switches"] >= 2
    scale = np.abs(reference.initial_state).max()
    assert np.abs(orbit.initial_state - reference.initial_state).max() < 1e-9 * scale


def test_clearance_wider_than_the_motion_is_no_bearing():
    system = _system(1.0)  # 1 m: no DOF moves that far
    orbit = backlash_periodic_orbit(system, substeps=8)
    free, _ = _with_support(_chain(), stiffness=0.0, damping=0.0)
    reference = periodic_response(free, 1)
    _, _, info = backlash_flow_ndof(system, orbit.initial_state, substeps=8)
    assert orbit.converged and info["zone_switches"] == 0
    # the same linear flow (without the bearing) from two exact solvers: 1e-9
    scale = np.abs(reference.initial_state).max()
    assert np.abs(orbit.initial_state - reference.initial_state).max() < 1e-9 * scale
    assert np.sort(np.abs(orbit.multipliers)) == pytest.approx(np.sort(np.abs(reference.multipliers)), rel=1e-9)


def _reference_period(system: BacklashSystem, state: np.ndarray, zone: DeadZone) -> np.ndarray:
    """One period of the force law integrated by solve_ivp (DOP853), restarted at every node and at every contact
    switch located by its event finder: independent of the exponentials and of the region bookkeeping."""
    from scipy.integrate import solve_ivp

    linear = system.linear
    n = linear.size
    inverse = np.linalg.inv(linear.mass)
    pattern = np.outer(zone.vector, zone.vector)
    z = np.array(state, dtype=float)
    for piece in range(linear.nodes.size - 1):
        stiffness, damping, force = linear.piece(piece)
        stiffness, damping = stiffness - zone.stiffness * pattern, damping - zone.damping * pattern

        def field(t, y, k=stiffness, c=damping, f=force):
            u, rate = zone.vector @ y[:n], zone.vector @ y[n:]
            contact = np.sign(u) * max(abs(u) - zone.clearance, 0.0)
            active = abs(u) > zone.clearance
            load = f - k @ y[:n] - c @ y[n:] - zone.vector * (zone.stiffness * contact + active * zone.damping * rate)
            return np.concatenate([y[n:], inverse @ load])

        events = [lambda t, y, b=b: zone.vector @ y[:n] - b for b in (zone.clearance, -zone.clearance)]
        t, stop = linear.nodes[piece], linear.nodes[piece + 1]
        while t < stop:
            result = solve_ivp(field, (t, stop), z, method="DOP853", rtol=1e-12, atol=1e-15, events=events)
            z, t = result.y[:, -1], result.t[-1]
            if result.status == 1:  # a switch: step just past it so that the event does not fire again at once
                nudge = solve_ivp(field, (t, min(t + 1e-9 * (stop - t), stop)), z, method="DOP853", rtol=1e-12,
                                  atol=1e-15)
                z, t = nudge.y[:, -1], nudge.t[-1]
    return z


def test_orbit_with_impacts_against_an_independent_integrator():
    linear, unit = _with_support(_chain())
    motion = periodic_response(linear, 64).displacement[:, DOF]
    clearance = 0.5 * np.abs(motion).max()  # the support loses and regains contact on both sides
    system = _system(clearance)
    orbit = backlash_periodic_orbit(system, substeps=16)
    _, _, info = backlash_flow_ndof(system, orbit.initial_state, substeps=16)
    assert orbit.converged and info["zone_switches"] >= 2
    end = _reference_period(system, orbit.initial_state, system.dead_zones[0])
    # the independent integration returns to the orbit's start: its tolerance (1e-12) and the located switches
    # leave ~1e-9 of the state; 1e-6 of each half of it (displacement, velocity)
    n = linear.size
    for part in (slice(0, n), slice(n, 2 * n)):
        assert np.abs(end[part] - orbit.initial_state[part]).max() < 1e-6 * np.abs(orbit.initial_state[part]).max()
    # the monodromy, with the saltation matrices of the dashpot's switches, against central differences of the
    # independent integration (steps 1e-6 of each half's size: their error is ~1e-12/1e-6 = 1e-6 from the
    # integrator, measured 3.5e-6 in all; leaving the saltation out is 2.7e-2 off): 1e-4 of the largest entry
    _, monodromy, _ = backlash_flow_ndof(system, orbit.initial_state, substeps=16)
    differences = np.zeros((2 * n, 2 * n))
    for column in range(2 * n):
        half = orbit.initial_state[:n] if column < n else orbit.initial_state[n:]
        step = np.zeros(2 * n)
        step[column] = 1e-6 * np.abs(half).max()
        differences[:, column] = (_reference_period(system, orbit.initial_state + step, system.dead_zones[0])
                                  - _reference_period(system, orbit.initial_state - step, system.dead_zones[0])
                                  ) / (2 * step[column])
    assert np.abs(monodromy - differences).max() < 1e-4 * np.abs(differences).max()


def test_bearing_clearance_key():
    bearing = Bearing("A", NodeLocation("shaft", 0.0), 1e8, 1e8, radial_clearance=20e-6)
    assert bearing.radial_clearance == 20e-6 and Bearing("B", NodeLocation("shaft", 0.0), 1e8, 1e8).radial_clearance == 0.0
    with pytest.raises(CaseError, match="radial_clearance"):
        Bearing("A", NodeLocation("shaft", 0.0), 1e8, 1e8, radial_clearance=-1e-6)
    with pytest.raises(CaseError, match="radial_clearance"):
        Bearing("A", NodeLocation("shaft", 0.0), 1e8, 1e8, stiffness_xy=1e7, radial_clearance=1e-6)
    with pytest.raises(ProblemError, match="dead_zone"):
        DeadZone(np.ones(3), 1e8, 0.0, -1.0)


def test_drivetrain_bearing_clearance_feeds_the_backlash_solver():
    # the pinion shaft's bearings with a clearance of 1e-12 m against static deflections of 2.4 and 6.6 μm: each
    # gives a dead zone in x and one in y, the shaft stays in contact on one side (no zone switch), and the orbit is
    # the linear bearing's shifted by δ (measured 8.7e-11 of the state; 3.9e-8 at δ = 1e-9 m, in proportion): 1e-8
    from drivetrain_builders import geared_pair
    from test_drivetrain_response import _mesh_state

    from thermogear.drivetrain.response import drivetrain_backlash_system

    drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2)
    state = replace(_mesh_state(0.5, speed_rpm=600.0), backlash=50e-6)
    loose = replace(drivetrain, bearings=tuple(replace(bearing, radial_clearance=1e-12)
                                               if bearing.location.shaft == "pinion shaft" else bearing
                                               for bearing in drivetrain.bearings))
    linear, _ = drivetrain_backlash_system(drivetrain.assemble(), state)
    system, _ = drivetrain_backlash_system(loose.assemble(), state)
    assert linear.dead_zones == () and len(system.dead_zones) == 4
    orbit = backlash_periodic_orbit(system, substeps=4)
    reference = backlash_periodic_orbit(linear, substeps=4)
    _, _, info = backlash_flow_ndof(system, orbit.initial_state, substeps=4)
    assert orbit.converged and info["zone_switches"] == 0
    scale = np.abs(reference.initial_state).max()
    assert np.abs(orbit.initial_state - reference.initial_state).max() < 1e-8 * scale
