"""Issue 36: the cut-off's error estimate without a second periodic solve (thermogear.dynamics.modes.truncation_error,
drivetrain.cutoff.cutoff_error_estimate) against the true error, the response on every DOF.

The factor. The estimate is the modes above the cut-off driven by the cut-off solution's own loads, less what the
static-correction columns carry, plus one step of the error's own feedback. What it leaves out is the rest of that
feedback (measured: the step itself moves it by 1-10 %), the damping's diagonal taken as each mode's own in that
step, and the sampling of the solution. Measured on the cases below it lies at 0.81-1.12x the true error (DTE and
bearing forces). We assert 1.5x either way: tight enough to catch the estimate's known failure mode, leaving out
the damping coupling, which made it 2.5x too low on fzg_rig_type_c's DTE; and loose enough for the terms it leaves
out. An estimate below the true error by more than 1.5x fails.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.drivetrain.case_model import SAMPLES_PER_PIECE, case_drivetrain
from thermogear.drivetrain.cutoff import cutoff_error_estimate, cutoff_for_harmonics
from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_periodic_system

FACTOR = 1.5  # module docstring
ROTOR = Path(__file__).resolve().parents[2] / "benchmarks" / "large_rotor.py"


def _true_errors(response, every) -> tuple[float, float]:
    """(DTE error / DTE peak-to-peak, bearing-force error / largest bearing-force peak-to-peak) against every DOF."""
    dte = np.abs(response.transmission_error - every.transmission_error).max() / np.ptp(every.transmission_error)
    force = (max(np.abs(response.bearing_forces[name] - every.bearing_forces[name]).max()
                 for name in every.bearing_forces)
             / max(np.ptp(every.bearing_forces[name], axis=0).max() for name in every.bearing_forces))
    return float(dte), float(force)


def _assert_estimate_within_factor(assembled, state, cutoff: float, samples: int):
    response = drivetrain_periodic_response(assembled, state, samples, cutoff)
    estimate = cutoff_error_estimate(assembled, state, response, cutoff)
    every = drivetrain_periodic_response(assembled, state, samples)
    for estimated, true in zip((estimate.transmission_error, estimate.bearing_force),
                               _true_errors(response, every)):
        assert true > 1e-7  # a real truncation error, far above rounding
        assert true / FACTOR <= estimated <= FACTOR * true
    return estimate


def test_the_estimate_is_the_true_error_of_a_time_invariant_system_with_modal_damping(script_module):
    """Identity: constant mesh stiffness and damping and a damping diagonal in the modes leave nothing out but the
    sampling: the estimate is the error of the cut-off solution (1 %)."""
    from thermogear.dynamics.modes.modal_reduction import mean_modes, modal_basis
    from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
    from thermogear.dynamics.modes.truncation_error import truncation_error

    rotor = script_module(ROTOR)
    assembled = rotor.rotor(12).assemble()
    system, _ = drivetrain_periodic_system(assembled, rotor.square_wave(3000.0, 16))
    cutoff = 2.0 * math.pi * 8000.0
    modes = mean_modes(system, cutoff)
    modal = modes.shapes.T @ system.damping @ modes.shapes
    mass_shapes = system.mass @ modes.shapes
    pieces = system.nodes.size - 1
    phase = np.arange(pieces) / pieces
    system = dataclasses.replace(  # C₀ diagonal in the modes; k, c constant; harmonics 1 and 5 of the force on the mesh
        system, damping=mass_shapes @ np.diag(np.diag(modal)) @ mass_shapes.T,
        stiffness_factor=np.full(pieces, system.stiffness_factor.mean()),
        damping_factor=np.full(pieces, system.damping_factor.mean()),
        force_factor=300.0 * np.sin(2.0 * np.pi * phase) + 200.0 * np.cos(10.0 * np.pi * phase))
    samples = 32
    basis = modal_basis(system, cutoff, modes=modes)
    cut = periodic_response(basis.reduce(system), samples)
    exact = periodic_response(system, samples)
    displacement = cut.displacement @ basis.basis.T
    error = truncation_error(system, basis, modes, cut.time, displacement, cut.velocity @ basis.basis.T)
    vector = system.force_pattern
    estimated, _ = error.observed(vector)
    true = np.interp(error.time, exact.time, (exact.displacement - displacement) @ vector)
    assert 0 < modes.dropped.sum() < system.size and np.abs(true).max() > 1e-4 * np.ptp(displacement @ vector)
    # measured 0.3 %: what is left is the sampling (the Hermite reading of 512 samples and the transform)
    assert np.abs(estimated[:, 0] - true).max() <= 0.01 * np.abs(true).max()


def test_the_default_estimate_of_run_has_the_size_of_the_true_error_on_the_rig():
    built = case_drivetrain(load_case("fzg_rig_type_c"), ("elastic",))
    cutoff = built.section.response_cutoff_hz
    assembled = built.assembled("elastic")
    state = built.mesh_states("elastic", points_per_period=64)  # every DOF costs ~N pieces: few here
    # measured 0.92x (DTE) and 0.81x (bearing forces) of the true 1.06e-3 and 3.9e-2
    estimate = _assert_estimate_within_factor(assembled, state, cutoff, SAMPLES_PER_PIECE)
    assert estimate.coordinates < estimate.check_coordinates <= assembled.size
    assert estimate.check_cutoff_hz > cutoff and "modes above it" in estimate.describe()
    assert estimate.as_json()["estimated_from"] == estimate.estimated_from
    on_case = built.cutoff_error("elastic")  # run's route: the case's own grid, the default estimate
    checked = built.cutoff_error("elastic", second_solve=True)  # the exact two-solve check, still callable
    assert checked.check_cutoff_hz == 2.0 * cutoff and "difference" in checked.estimated_from
    for new, old in ((on_case.transmission_error, checked.transmission_error),
                     (on_case.bearing_force, checked.bearing_force)):
        # both have the size of the true error: the estimate lies within 1.5x of it (FACTOR) and the two-solve check
        # read 1.2-1.36x of it, so they differ by at most about 2x; 3x leaves room for neither drifting further
        assert old / 3.0 <= new <= 3.0 * old


@pytest.mark.slow
@pytest.mark.parametrize("path", ["tests/data/two_shaft_drivetrain.toml", "tests/data/user_drivetrain.toml"])
def test_the_estimate_has_the_size_of_the_true_error_on_the_test_drivetrains(path):
    """Measured at 128 intervals (DTE / bearing forces): the two-shaft fixture 1.12x / 1.00x, the user's drivetrain
    1.11x / 0.96x."""
    built = case_drivetrain(load_case(path), ("elastic",))
    _assert_estimate_within_factor(built.assembled("elastic"), built.mesh_states("elastic", points_per_period=128),
                                   built.section.response_cutoff_hz, SAMPLES_PER_PIECE)


@pytest.mark.slow
@pytest.mark.parametrize("speed", [3000.0, 6000.0])
def test_the_estimate_has_the_size_of_the_true_error_on_the_492_dof_rotor(script_module, speed):
    """The benchmarks' 492-DOF rotor on a square-wave mesh (two pieces): measured 1.01x / 1.00x at 3000 rpm and
    0.96x / 1.00x at 6000 rpm."""
    rotor = script_module(ROTOR)
    state = rotor.square_wave(speed)
    _assert_estimate_within_factor(rotor.rotor(40).assemble(), state, cutoff_for_harmonics(state.mesh_frequency_hz),
                                   256)
