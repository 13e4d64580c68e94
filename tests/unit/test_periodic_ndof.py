"""The exact periodic state of an n-DOF linear time-periodic system: against the 1-DOF monodromy solver, against
solve_ivp run to steady state, and the Floquet multipliers of a constant system."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.modes.modal import damped_modes
from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, monodromy, periodic_response
from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.errors import ModelLimitError, ProblemError


def _chain(size: int, period: float, stiffness_levels=(1.3e8, 0.9e8), double_fraction=0.6) -> PiecewiseLinearSystem:
    """A chain of masses and springs to ground at both ends, one parametric spring (a square wave) between DOFs
    0 and 1 and Rayleigh damping C = aM + bK₀."""
    rng = np.random.default_rng(7)
    masses = rng.uniform(0.5, 2.0, size)
    springs = rng.uniform(0.5e8, 2e8, size + 1)
    stiffness = np.zeros((size, size))
    for i in range(size + 1):
        for a in (i - 1, i):
            if 0 <= a < size:
                stiffness[a, a] += springs[i]
        if 0 < i < size:
            stiffness[i - 1, i] -= springs[i]
            stiffness[i, i - 1] -= springs[i]
    mass = np.diag(masses)
    pattern = np.zeros((size, size))
    pattern[np.ix_([0, 1], [0, 1])] = [[1.0, -1.0], [-1.0, 1.0]]
    force_pattern = np.zeros(size)
    force_pattern[[0, 1]] = [1.0, -1.0]
    force = np.zeros(size)
    force[0], force[-1] = 500.0, -200.0
    return PiecewiseLinearSystem(
        mass=mass, stiffness=stiffness, damping=200.0 * mass + 2e-6 * stiffness, force=force,
        nodes=np.array([0.0, double_fraction * period, period]), stiffness_pattern=pattern,
        stiffness_factor=np.array(stiffness_levels), damping_pattern=pattern, damping_factor=np.array([200.0, 150.0]),
        force_pattern=force_pattern, force_factor=np.array([1e8 * 2e-6, 0.0]))


def test_one_dof_case_equals_the_existing_monodromy_solver():
    problem = MeshDynamicsProblem.square_wave(mass=0.35, mesh_period=1 / 3000, contact_ratio=1.6,
                                              single_stiffness=2.6e8, double_stiffness=4.1e8, single_damping=180.0,
                                              double_damping=230.0, force=3000.0)
    one = np.ones((1, 1))
    system = PiecewiseLinearSystem(mass=[[0.35]], stiffness=np.zeros((1, 1)), damping=np.zeros((1, 1)),
                                   force=[0.0], nodes=problem.nodes, stiffness_pattern=one,
                                   stiffness_factor=problem.stiffness, damping_pattern=one,
                                   damping_factor=problem.damping, force_pattern=[1.0],
                                   force_factor=problem.force_per_interval)
    response = periodic_response(system, samples_per_piece=32)
    orbit = periodic_steady_state(problem, samples_per_interval=32)
    scale = np.abs(orbit.displacement).max()
    # two exact solutions (closed-form 2×2 exponential vs scaled-and-squared expm): agree to rounding, 1e-9
    assert np.allclose(response.time, orbit.time, rtol=1e-12, atol=0)
    assert np.abs(response.displacement[:, 0] - orbit.displacement).max() < 1e-9 * scale
    assert np.abs(response.velocity[:, 0] - orbit.velocity).max() < 1e-9 * np.abs(orbit.velocity).max()
    assert np.sort(np.abs(response.multipliers)) == pytest.approx(np.sort(np.abs(orbit.multipliers)), rel=1e-9)


def test_constant_coefficients_give_multipliers_exp_lambda_t():
    period = 2e-4
    system = _chain(6, period, stiffness_levels=(1e8, 1e8))
    system = PiecewiseLinearSystem(**{**system.__dict__, "damping_factor": np.array([150.0, 150.0])})
    transition, _ = monodromy(system)
    stiffness, damping, _ = system.piece(0)
    modes = damped_modes(system.mass, damping, stiffness)
    expected = np.exp(np.concatenate([modes.eigenvalues, modes.eigenvalues.conj()]) * period)
    found = np.linalg.eigvals(transition)
    # match each e^{λT} to its nearest multiplier; both are exact to rounding (1e-10 of |μ| ≤ 1)
    for value in expected:
        assert np.abs(found - value).min() < 1e-10


@pytest.mark.slow
def test_thirty_dof_orbit_equals_solve_ivp_run_to_steady_state():
    from scipy.integrate import solve_ivp

    period = 1e-3
    system = _chain(30, period)
    response = periodic_response(system, samples_per_piece=8)
    n = system.size
    inverse = np.linalg.inv(system.mass)

    def field(piece):
        stiffness, damping, force = system.piece(piece)
        matrix = np.block([[np.zeros((n, n)), np.eye(n)], [-inverse @ stiffness, -inverse @ damping]])
        load = np.concatenate([np.zeros(n), inverse @ force])
        return lambda t, z: matrix @ z + load

    fields = [field(0), field(1)]
    state = np.zeros(2 * n)
    # every mode decays at least as e^{−at/2} (a = 200 1/s of the mass-proportional damping): 200 periods = 0.2 s
    # leave e^{−20} ≈ 2e-9 of the start-up transient, far below the 1e-6 compared
    for _ in range(200):
        for piece in (0, 1):
            start, stop = system.nodes[piece], system.nodes[piece + 1]
            state = solve_ivp(fields[piece], (start, stop), state, method="DOP853", rtol=1e-10,
                              atol=1e-17).y[:, -1]
    scale = np.abs(response.displacement).max()
    # the integration's end state against the orbit's z₀: 1e-6 relative (the criterion)
    assert np.abs(state[:n] - response.initial_state[:n]).max() < 1e-6 * scale
    assert response.spectral_radius < 1.0


def test_unstable_or_undamped_systems_are_refused():
    system = _chain(4, 1e-3)
    undamped = PiecewiseLinearSystem(**{**system.__dict__, "damping": np.zeros((4, 4)),
                                        "damping_factor": np.zeros(2)})
    with pytest.raises(ModelLimitError, match="modulus"):
        periodic_response(undamped)
    with pytest.raises(ProblemError, match="stiffness_factor"):
        PiecewiseLinearSystem(**{**system.__dict__, "stiffness_factor": np.ones(3)})


def _many_pieces(levels: int | None, pieces: int = 96) -> PiecewiseLinearSystem:
    """The chain over many pieces: k, c, g smooth along the period on pieces of three widths, each perturbed by a
    rounding unit or two as a mesh grid's are; or, when ``levels`` is 2, a square wave of two levels on 64 equal
    pieces of exactly 2⁻¹⁷ s (so that only two distinct pieces exist)."""
    base = _chain(12, 1 / 2500)
    if levels == 2:
        nodes = np.arange(65) * 2.0**-17
    else:
        widths = np.repeat([0.2, 0.5, 0.3], pieces // 3) / pieces
        widths = widths * (1.0 + np.random.default_rng(3).integers(-2, 3, widths.size) * 2.0**-52)
        nodes = np.concatenate([[0.0], np.cumsum(widths)]) / 2500
    phase = np.linspace(0.0, 2 * np.pi, nodes.size - 1, endpoint=False)
    wave = np.where(phase < 3.5, 1.0, -1.0) if levels == 2 else np.sin(phase) + 0.3 * np.cos(3 * phase)
    return PiecewiseLinearSystem(**{**base.__dict__, "nodes": nodes, "stiffness_factor": 1.1e8 + 3e7 * wave,
                                    "damping_factor": 170.0 + 30.0 * wave, "force_factor": 150.0 * wave})


def _reference_orbit(system: PiecewiseLinearSystem, samples: int) -> np.ndarray:
    """States at every sub-step from scipy's expm piece by piece, one Python step at a time."""
    from scipy.linalg import expm

    inverse = np.linalg.inv(system.mass)
    steps = [expm(system.augmented(j, inverse) * (system.nodes[j + 1] - system.nodes[j]) / samples)
             for j in range(system.nodes.size - 1)]
    total = np.eye(2 * system.size + 1)
    for step in steps:
        total = np.linalg.matrix_power(step, samples) @ total
    start = np.linalg.solve(np.eye(2 * system.size) - total[:-1, :-1], total[:-1, -1])
    states, state = [], np.append(start, 1.0)
    for step in steps:
        for _ in range(samples):
            states.append(state)
            state = step @ state
    states.append(state)
    return np.array(states)[:, :system.size]


@pytest.mark.parametrize("levels, samples", [(None, 1), (None, 3), (2, 1)])
def test_many_pieces_equal_a_piece_by_piece_reference(levels, samples):
    # smooth k(τ): 96 distinct pieces of rank-1 variation take the rank-update exponentials; the square wave's 64
    # pieces are two distinct ones, each exponential taken once (full Taylor route). Both are exact: what is left is
    # rounding in the ~100 products and in scipy's expm (6e-15 of the orbit measured), so 1e-10 of the orbit's size
    system = _many_pieces(levels)
    response = periodic_response(system, samples_per_piece=samples)
    reference = _reference_orbit(system, samples)
    scale = np.abs(reference).max()
    assert response.displacement.shape == reference.shape
    assert np.abs(response.displacement - reference).max() < 1e-10 * scale


@pytest.mark.parametrize("levels, samples", [(None, 1), (None, 3), (2, 2)])
def test_chunked_route_equals_the_piece_by_piece_reference(monkeypatch, levels, samples):
    # the route of large systems (issue 36: a 1024-piece, 83-coordinate drivetrain held 1.3 GB in the block route's
    # stacks) forced on the small chain, in chunks of 10 pieces so that several chunks and a partial last one occur:
    # the whole pieces' transitions formed directly (not as powers of the sub-steps) and the states stepped one
    # sub-step at a time are exact as the block route, so the same 1e-10 of the orbit's size as above
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic

    system = _many_pieces(levels)
    monkeypatch.setattr(periodic, "LEAN_ROUTE_BYTES", 0)
    monkeypatch.setattr(periodic, "CHUNK_BYTES", 10 * 8 * (2 * system.size + 1) ** 2)
    chunked = periodic_response(system, samples_per_piece=samples)
    reference = _reference_orbit(system, samples)
    scale = np.abs(reference).max()
    assert np.abs(chunked.displacement - reference).max() < 1e-10 * scale
    monkeypatch.setattr(periodic, "LEAN_ROUTE_BYTES", 2**62)
    blocks = periodic_response(system, samples_per_piece=samples)
    assert np.allclose(np.abs(chunked.multipliers), np.abs(blocks.multipliers), rtol=1e-9, atol=1e-14)


def test_motion_projections_from_the_orbit_stay_on_it(monkeypatch):
    # the motion from the periodic state is the orbit itself, period after period: the functionals watched by the
    # chunked pass (chunks of 7 pieces) equal the orbit's own sampled displacement at every sub-step of 3 periods
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic
    from thermogear.dynamics.periodic_orbits.periodic_motion import motion_projections

    system = _many_pieces(None)
    samples = 2
    monkeypatch.setattr(periodic, "CHUNK_BYTES", 7 * 8 * (2 * system.size + 1) ** 2)
    orbit = periodic_response(system, samples_per_piece=samples)
    rows = np.zeros((2, 2 * system.size))
    rows[0, 0], rows[1, system.size - 1] = 1.0, 1.0
    values = motion_projections(system, orbit.initial_state, 3, samples, rows)
    expected = orbit.displacement[:-1][:, [0, system.size - 1]]
    scale = np.abs(expected).max()
    assert values.shape == (3 * expected.shape[0] + 1, 2)
    for period in range(3):
        block = values[period * expected.shape[0]:(period + 1) * expected.shape[0]]
        assert np.abs(block - expected).max() < 1e-10 * scale


def test_motion_prepared_on_the_orbits_pass_equals_its_own_pass(monkeypatch):
    # the start-up check's motion prepared on the periodic solve's pass of sub-step exponentials (its observer, on
    # the chunked route) is the motion of motion_projections' own pass bit for bit (the same chunks, the same
    # transitions in the same order); on a route that forms no chunks the projector is fed nothing and says so
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic
    from thermogear.dynamics.periodic_orbits.periodic_motion import MotionProjector, motion_projections

    system = _many_pieces(None)
    samples = 2
    monkeypatch.setattr(periodic, "LEAN_ROUTE_BYTES", 0)
    monkeypatch.setattr(periodic, "CHUNK_BYTES", 7 * 8 * (2 * system.size + 1) ** 2)
    rows = np.zeros((2, 2 * system.size))
    rows[0, 0], rows[1, system.size + 3] = 1.0, 1.0
    projector = MotionProjector(system, samples, rows)
    observed = periodic_response(system, samples_per_piece=samples, observer=projector.add)
    assert projector.complete
    rest = np.zeros(2 * system.size)
    assert np.array_equal(projector.projections(rest, 4), motion_projections(system, rest, 4, samples, rows))
    monkeypatch.setattr(periodic, "LEAN_ROUTE_BYTES", 2**62)
    unfed = MotionProjector(system, samples, rows)
    plain = periodic_response(system, samples_per_piece=samples, observer=unfed.add)
    assert not unfed.complete
    with pytest.raises(ProblemError, match="pieces"):
        unfed.projections(rest, 1)
    assert np.allclose(plain.displacement, observed.displacement, rtol=0.0, atol=1e-9 * np.abs(plain.displacement).max())
