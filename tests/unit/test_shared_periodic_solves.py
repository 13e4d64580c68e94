"""Issue 36: one periodic solve per reduced system. The linear response of a drivetrain and the backlash solver's
switch-free orbit (every contact closed) solve the same reduced system; `run` solves it once, the sharing decided
by equality of the arrays (a system that differs in one bit is solved afresh), and every number stays the same."""

from __future__ import annotations

import tomllib
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from test_backlash_ndof import _chain

from thermogear.case import case_from_document
from thermogear.drivetrain.case_model import SAMPLES_PER_PIECE, case_drivetrain
from thermogear.drivetrain.response import drivetrain_periodic_response
from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
from thermogear.dynamics.periodic_orbits.periodic_solves import PeriodicSolves, same_system

USER_DRIVETRAIN = Path(__file__).resolve().parents[1] / "data" / "user_drivetrain.toml"


def test_a_system_equal_bit_for_bit_is_solved_once_and_one_bit_off_afresh():
    system = _chain()
    solves = PeriodicSolves()
    first = solves.response(system, 4)
    copied = replace(system, mass=system.mass.copy())  # equal arrays, another object
    assert same_system(system, copied) and solves.response(copied, 4) is first
    assert solves.response(system, 8) is not first  # other samples: another solve
    nudged = replace(system, stiffness_factor=np.nextafter(system.stiffness_factor, np.inf))
    assert not same_system(system, nudged)
    again = solves.response(nudged, 4)
    assert again is not first and solves.find(nudged, 4) is again
    fresh = periodic_response(system, 4)
    assert np.array_equal(first.displacement, fresh.displacement)
    assert np.array_equal(first.multipliers, fresh.multipliers)
    assert len(solves) == solves.capacity == 2  # the oldest dropped: a sweep keeps its last few


@pytest.fixture(scope="module")
def user_drivetrain():
    document = tomllib.loads(USER_DRIVETRAIN.read_text(encoding="utf-8"))
    # 512 pieces: the backlash solver's 2048 sub-steps per period are then the linear response's 4 samples per piece
    # (backlash_substeps), so that both solve the same system at the same samples
    document["dynamics"]["points_per_period"] = 512
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_drivetrain(case_from_document(document, source=str(USER_DRIVETRAIN)), ("elastic",))


def test_the_linear_response_takes_the_backlash_solvers_switch_free_solve(user_drivetrain, monkeypatch):
    built = user_drivetrain
    backlash = built.backlash_response("elastic")
    assert backlash.converged and backlash.contact_loss_fraction == 0.0  # switch-free: the linear orbit
    kept = built._solves  # the case drivetrain's kept solves
    assert len(kept) == 1
    import thermogear.drivetrain.response as response_module
    import thermogear.dynamics.periodic_orbits.periodic_solves as solves_module

    for module in (response_module, solves_module):
        monkeypatch.setattr(module, "periodic_response", lambda *arguments, **keywords: pytest.fail(
            "the same reduced system solved twice"))
    shared = built.response("elastic")
    assert len(kept) == 1
    monkeypatch.undo()
    own = drivetrain_periodic_response(built.assembled("elastic"), built.mesh_states("elastic"), SAMPLES_PER_PIECE,
                                       built.section.response_cutoff_hz)
    # the same solve: equal up to the rounding of BLAS, whose thread count (one in the backlash solver, as many as
    # it likes here) changes the order of the sums (measured 1e-14 of the DTE peak-to-peak; 1e-12 is far below any
    # number the response reports)
    scale = np.ptp(own.transmission_error)
    assert np.abs(shared.transmission_error - own.transmission_error).max() < 1e-12 * scale
    assert shared.metrics["kv"] == pytest.approx(own.metrics["kv"], rel=1e-12)
    assert np.abs(shared.multipliers - own.multipliers).max() < 1e-12
    # the backlash orbit (no switch) is that orbit: the same Kv to the shooting's resolution
    assert backlash.kv == pytest.approx(own.kv, rel=1e-8)


@pytest.mark.parametrize("parted", [True, False])
def test_the_chunked_solve_with_and_without_the_exponentials_parts(monkeypatch, parted):
    # the chunked route keeps each sub-step as the parts of its rank-update exponential and multiplies the whole
    # pieces through theirs; where the parts are refused (here: the rank route forced off, as for patterns of high
    # rank) it forms the matrices, the sub-steps in a second pass. Both exact: 1e-10 of the orbit's size against the
    # piece-by-piece reference (as test_periodic_ndof's chunked route), and the start-up projector fed either way
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic
    from test_periodic_ndof import _many_pieces, _reference_orbit

    from thermogear.dynamics.periodic_orbits.periodic_motion import MotionProjector, motion_projections

    system = _many_pieces(None)
    monkeypatch.setattr(periodic, "LEAN_ROUTE_BYTES", 0)
    monkeypatch.setattr(periodic, "CHUNK_BYTES", 10 * 8 * (2 * system.size + 1) ** 2)
    if not parted:
        monkeypatch.setattr(periodic, "_RANK_ROUTE_RATIO", 10**9)
    rows, where = periodic.grouped_pieces(system, 2)
    first_wholes, first_steps = next(periodic.chunked_transitions(system, rows, where, 2, dense_steps=False))[1:]
    assert (first_steps is not None) == parted
    # parted, the whole pieces chain in the modal coordinates of the period's mean piece (its guard passes here)
    assert (getattr(first_wholes, "modal", None) is not None) == parted
    projector = MotionProjector(system, 2, np.eye(2 * system.size)[:1])
    response = periodic_response(system, samples_per_piece=2, observer=projector.add)
    reference = _reference_orbit(system, 2)
    assert np.abs(response.displacement - reference).max() < 1e-10 * np.abs(reference).max()
    assert projector.complete
    rest = np.zeros(2 * system.size)
    assert np.array_equal(projector.projections(rest, 3), motion_projections(system, rest, 3, 2,
                                                                             np.eye(2 * system.size)[:1]))
