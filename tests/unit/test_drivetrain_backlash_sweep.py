"""The drivetrain's backlash orbit continued in speed: on (nearly) rigid shafts and bearings it jumps where the 1-DOF
pair's continuation (``thermogear.dynamics.backlash.backlash_continuation``) jumps, sweeping up and down."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from drivetrain_builders import geared_pair
from test_drivetrain_response import J_1, J_2, R_B1, R_B2, _mesh_state

from thermogear.drivetrain import Material
from thermogear.drivetrain.backlash_sweep import drivetrain_backlash_branch
from thermogear.dynamics.backlash.backlash_continuation import follow_branch
from thermogear.errors import CaseError

MASS = J_1 * J_2 / (J_1 * R_B2**2 + J_2 * R_B1**2)
BACKLASH = 8.77e-5  # about the static deflection: contact is lost near resonance


def _state(speed_rpm: float):
    # the square-wave mesh with a quarter of its damping (ζ ≈ 0.03), no deviations (the drivetrain's whole-mesh
    # dead zone then equals the 1-DOF model's per-pair separation)
    state = _mesh_state(MASS, speed_rpm=speed_rpm)
    return replace(state, pair_damping=0.25 * state.pair_damping, mesh_damping=0.25 * state.mesh_damping,
                   backlash=BACKLASH)


def _rigid_pair():
    # shafts 1e4× steel, bearings 1e12 N/m: support modes ~100× above the mesh mode (material and bearing damping
    # keep them damped); the gear inertias of the 1-DOF pair
    stiff = Material(youngs_modulus=211e9 * 1e4, density=7810.0, poisson_ratio=0.3)
    return geared_pair(bearing_x=1e12, bearing_y=1e12, material=stiff, pinion_inertia=(1.0, 4e-3, 2e-3),
                       wheel_inertia=(1.5, 9e-3, 4.5e-3), bearing_damping=1e3, material_damping=1e-6, elements=2)


@pytest.mark.slow
def test_rigid_supports_jump_where_the_one_dof_pair_jumps():
    natural = math.sqrt(3.6e7 / MASS) / (2 * math.pi)  # mean mesh stiffness 3.6e7 N/m of the square wave
    speeds = np.linspace(0.7, 1.15, 19) * natural * 60.0 / 20.0
    states = [_state(speed) for speed in speeds]
    problems = [state.backlash_problem() for state in states]
    assembled = _rigid_pair().assemble()
    for direction in ("up", "down"):
        reference = follow_branch(problems, direction, speeds)
        # shooting to 1e-8: the 1e4 stiffness contrast leaves a rounding floor of the residual near 1e-9
        branch = drivetrain_backlash_branch(assembled, states, direction, tolerance=1e-8)
        swing = reference["dte_peak_to_peak"]
        step = 1 if direction == "up" else -1
        expected = [i for i in range(speeds.size)[::step][:-1]
                    if abs(swing[i + step] - swing[i]) > 0.2 * max(swing[i], swing[i + step])]
        assert np.all(branch.converged) and len(expected) >= 1
        # the same grid intervals (the jump located to the speed step, 2.5 % of the natural frequency)
        assert list(branch.jumps()) == expected
        # the swing: the supports' compliance (~1e-4 of the mesh's) and the sampling of the n-DOF orbit (8
        # substeps per piece: ≤ 1 − cos(π/24) = 8.6e-3 low for the fundamental) — 2 %
        np.testing.assert_allclose(branch.peak_to_peak, swing, rtol=2e-2)


def test_states_out_of_order_are_refused():
    with pytest.raises(CaseError, match="states"):
        drivetrain_backlash_branch(_rigid_pair().assemble(), [_state(2000.0), _state(1000.0)])
