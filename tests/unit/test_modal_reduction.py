"""Modal reduction with static correction: exact when every mode is kept, exact in the static limit of every piece,
and converging on the full solution as the cut-off rises; the Newmark reference converges on the exact orbit as h²."""

from __future__ import annotations

import numpy as np
import pytest
from drivetrain_builders import geared_pair
from test_drivetrain_response import _mesh_state

from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_periodic_system
from thermogear.dynamics.modes.modal_reduction import modal_basis
from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
from thermogear.dynamics.transients.newmark import newmark_steady_state
from thermogear.errors import CaseError, ProblemError


@pytest.fixture(scope="module")
def flexible():
    assembled = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=3).assemble()
    return assembled, _mesh_state(0.5, speed_rpm=3000.0)


def _error(response, reference) -> float:
    return float(np.abs(response.transmission_error - reference.transmission_error).max()
                 / np.abs(reference.transmission_error).max())


def test_every_mode_kept_equals_the_full_system(flexible):
    assembled, state = flexible
    full = drivetrain_periodic_response(assembled, state, samples_per_piece=4)
    reduced = drivetrain_periodic_response(assembled, state, samples_per_piece=4, cutoff_hz=1e9)
    # same solution in another basis (the unexcited invariant subspace dropped): rounding of the eigenvectors and
    # of two different exponentials, 1e-9 of the largest DTE
    assert _error(reduced, full) < 1e-9
    for name, force in full.bearing_forces.items():
        assert np.abs(reduced.bearing_forces[name] - force).max() < 1e-9 * np.abs(force).max()


def test_static_corrections_make_every_piece_statically_exact(flexible):
    # no mode kept at all: the basis is the static corrections alone, and still K_j⁻¹f_j of every piece is in its
    # span (Sherman–Morrison), so the Galerkin static solution equals the full one to rounding
    assembled, state = flexible
    system, _ = drivetrain_periodic_system(assembled, state)
    basis = modal_basis(system, cutoff=1e-3)
    assert basis.mode_count == 0 and basis.size >= 1
    reduced = basis.reduce(system)
    for piece in range(system.nodes.size - 1):
        stiffness, _, force = system.piece(piece)
        stiffness_r, _, force_r = reduced.piece(piece)
        exact = np.linalg.solve(stiffness, force)
        approximate = basis.expand(np.linalg.solve(stiffness_r, force_r))
        assert np.abs(approximate - exact).max() < 1e-9 * np.abs(exact).max()


def test_error_falls_as_the_cutoff_rises(flexible):
    assembled, state = flexible
    full = drivetrain_periodic_response(assembled, state, samples_per_piece=2)
    errors = [_error(drivetrain_periodic_response(assembled, state, samples_per_piece=2, cutoff_hz=cutoff), full)
              for cutoff in (5e3, 2e4, 8e4)]
    # a mode above the cut-off responds quasi-statically; the error of dropping its dynamics falls like
    # (f_excitation/f_mode)² — measured here (5e3, 2e4, 8e4 Hz) 1.8e-3, 2.0e-6, 4.6e-12 (all excited modes kept at
    # 8e4) — so each step must gain > 10×
    assert errors[0] > 10 * errors[1] > 100 * errors[2]
    assert errors[1] < 1e-3


def test_bad_cutoff_is_named():
    assembled = geared_pair(elements=2).assemble()
    with pytest.raises(CaseError, match="cutoff_hz"):
        drivetrain_periodic_response(assembled, _mesh_state(0.5), cutoff_hz=-1.0)
    system, _ = drivetrain_periodic_system(assembled, _mesh_state(0.5))
    with pytest.raises(ProblemError, match="cutoff"):
        modal_basis(system, float("nan"))


def test_newmark_converges_on_the_exact_orbit_as_h_squared(flexible):
    assembled, state = flexible
    system, _ = drivetrain_periodic_system(assembled, state)
    basis = modal_basis(system, 2 * np.pi * 2e4)
    reduced = basis.reduce(system)
    exact = periodic_response(reduced, 8)
    errors = []
    for steps in (8, 16):
        orbit = newmark_steady_state(reduced, steps_per_piece=steps, tolerance=1e-10)
        reference = exact.displacement if steps == 8 else periodic_response(reduced, 16).displacement
        errors.append(np.abs(orbit.displacement - reference).max() / np.abs(reference).max())
    # second order: halving h divides the error by ~4 (3 to 5 allows the pre-asymptotic range)
    assert 3.0 < errors[0] / errors[1] < 5.0
