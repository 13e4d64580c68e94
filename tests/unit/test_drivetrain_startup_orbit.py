"""What a start-up reaches on the backlash drivetrain: where two stable orbits coexist, the one a start from rest
settles on is reported (and the other described); the multi-start search lists both with their basin shares."""

from __future__ import annotations

import numpy as np
import pytest
from drivetrain_builders import geared_pair
from test_drivetrain_backlash_sweep import _state

from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
from thermogear.drivetrain.response import drivetrain_backlash_system
from thermogear.dynamics.backlash.backlash_ndof import backlash_periodic_orbit
from thermogear.dynamics.backlash.backlash_orbits_ndof import stable_orbits_ndof
from thermogear.dynamics.backlash.backlash_trajectory import backlash_trajectory

SPEED_RPM = 1450.0  # in the softening resonance's band where the no-impact and an impacting orbit coexist


def _rotor():
    # the two-shaft test rotor on steel shafts and 2e8 N/m bearings, two elements per shaft: 36 DOF
    return geared_pair(pinion_inertia=(1.0, 4e-3, 2e-3), wheel_inertia=(1.5, 9e-3, 4.5e-3), bearing_damping=1e3,
                       material_damping=1e-6, elements=2).assemble()


@pytest.fixture(scope="module")
def coexisting():
    assembled = _rotor()
    state = _state(SPEED_RPM)
    response = drivetrain_backlash_response(assembled, state, substeps=32, samples_per_piece=8,
                                            startup_periods=60)
    return assembled, state, response


def test_the_orbit_a_start_up_reaches_is_reported_with_the_other(coexisting):
    assembled, state, response = coexisting
    assert response.converged and response.stable and assembled.size == 36
    startup = response.metrics["startup"]
    assert startup["reached_from"] == "rest" and startup["branch"] == "high"
    (other,) = startup["coexisting"]
    assert other["reached_from"] == "the linear solution" and other["branch"] == "low" and other["stable"]
    # the two orbits differ by far more than the solver's resolution: the start-up's strikes the back flanks and
    # loses contact over an eighth of the period (measured 0.126, Kv 3.48), the other never separates (Kv 1.75)
    assert response.contact_loss_fraction > 0.05 and response.back_contact_fraction > 0.1
    assert other["contact_loss_fraction"] == 0.0 and other["back_contact_fraction"] == 0.0
    assert response.kv > 1.5 * other["kv"]
    assert response.metrics["dte_peak_to_peak"] * 1e6 > other["dte_peak_to_peak_um"]
    assert any("coexist" in note for note in response.notes)


def test_the_reported_orbit_is_where_the_motion_from_rest_goes(coexisting):
    # an independent path: 150 mesh periods of the exact flow from rest (no shooting) end on the reported orbit;
    # its distance to the orbit falls as |μ|^N (largest multiplier 0.907 here: 4e-7 after 150 periods): 1e-5
    assembled, state, response = coexisting
    system, _ = drivetrain_backlash_system(assembled, state)
    motion = backlash_trajectory(system, np.zeros(2 * system.linear.size), 150, 1, 32)
    end = motion.end_state
    orbit = np.array(response.metrics["initial_state"])
    assert np.abs(end - orbit).max() < 1e-5 * np.abs(orbit).max()


def test_without_a_start_up_the_linear_solution_s_orbit_is_shot(coexisting):
    # the shooting alone (as before: no start from rest) finds the low orbit, the one the report used to give
    assembled, state, _ = coexisting
    response = drivetrain_backlash_response(assembled, state, substeps=32, samples_per_piece=8)
    assert response.converged and response.contact_loss_fraction == 0.0 and "startup" not in response.metrics


@pytest.mark.slow
def test_multi_start_search_lists_both_orbits_with_their_basin_shares(coexisting):
    assembled, state, response = coexisting
    system, _ = drivetrain_backlash_system(assembled, state)
    census = stable_orbits_ndof(system, starts=4, run_in_periods=30, substeps=32)
    period = state.period
    fractions = sorted(item.orbit.free_flight_time / period for item in census.orbits)
    assert len(census.orbits) == 2 and fractions[0] == 0.0 and fractions[1] > 0.05
    assert sum(item.start_count for item in census.orbits) + np.sum(census.outcome < 0) == 4
    assert sum(item.basin_share for item in census.orbits) <= 1.0
    # the start from rest (the first start) is on the high orbit, the linear periodic state (the second) on the low
    high = max(census.orbits, key=lambda item: item.orbit.free_flight_time)
    assert high.from_rest and census.outcome[0] == census.orbits.index(high)
    reference = backlash_periodic_orbit(system, None, 32)
    low = min(census.orbits, key=lambda item: item.orbit.free_flight_time)
    assert np.abs(low.orbit.initial_state - reference.initial_state).max() < 1e-6 * np.abs(
        reference.initial_state).max()


@pytest.mark.parametrize("backlash", [True, False])
def test_motion_from_rest_on_the_modal_cut_off(backlash):
    # `run --method transient` solves on the section's cut-off, as the periodic orbit: with a cut-off above every
    # mode the basis spans every DOF and the motion from rest equals the one on every DOF to rounding (1e-9 of the
    # DTE's scale); with a low cut-off (2 kHz: the low modes and the static corrections) it stays within the
    # reduction's error, 1e-2 of the DTE's scale
    from thermogear.drivetrain.transient_response import drivetrain_transient

    assembled = _rotor()
    state = _state(1000.0)  # far below the band of contact loss
    full = drivetrain_transient(assembled, state, 6, backlash=backlash, samples_per_piece=4, substeps=8)
    scale = np.abs(full.transmission_error).max()
    nodes = state.grid.nodes  # the 4 samples of each of the 3 pieces of 6 periods
    grid = ((nodes[:-1, None] + np.diff(nodes)[:, None] * np.arange(4) / 4).ravel()[None, :]
            + state.period * np.arange(6)[:, None]).ravel()
    for cutoff, tolerance in ((1e7, 1e-9), (2e3, 1e-2)):
        cut = drivetrain_transient(assembled, state, 6, backlash=backlash, samples_per_piece=4, substeps=8,
                                   cutoff_hz=cutoff)
        for time in grid:  # the grid's samples (extrema and switch instants may move by rounding)
            mine = np.flatnonzero(np.abs(cut.time - time) <= 1e-12 * state.period)
            theirs = np.flatnonzero(np.abs(full.time - time) <= 1e-12 * state.period)
            assert mine.size and theirs.size
            assert abs(cut.transmission_error[mine[-1]] - full.transmission_error[theirs[-1]]) < tolerance * scale
