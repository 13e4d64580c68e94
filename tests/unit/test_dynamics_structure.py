"""Problems as matrices: the 1-DOF mesh is the 1×1 case of a mesh inside a structure of n degrees of freedom.

M q̈ + (C₀ + c_j·w wᵀ) q̇ + (K₀ + k_j·w wᵀ) q = f₀ + g_j·w. The checks are reductions with closed forms: a 1×1
structure with a scaled mesh vector and a symmetric two-body structure both reduce exactly to a 1-DOF mesh, which
the closed-form 2×2 kernels solve; and the 1-DOF problem handed to the matrix solver (periodic_ndof) gives the
closed-form orbit. Units as in test_dynamics_periodic: 1 kg, 100 Hz, 100 N.
"""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics import MeshDynamicsProblem, floquet_multipliers, periodic_steady_state
from thermogear.dynamics.backlash.backlash_periodic import periodic_response as backlash_periodic_response
from thermogear.dynamics.periodic_orbits.periodic import evaluate_orbit, periodic_initial_state
from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
from thermogear.dynamics.periodic_orbits.periodic_structure import piecewise_system
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.transients.backlash_reference import reference_backlash_solve_ivp
from thermogear.dynamics.transients.reference import reference_solve_ivp
from thermogear.dynamics.transients.transient import transient_from_rest
from thermogear.errors import ProblemError

MASS = 1.0  # [kg]
OMEGA = 2.0 * np.pi * 100.0  # [rad/s]
STIFFNESS = MASS * OMEGA**2  # [N/m]
FORCE = 100.0  # [N]
SAMPLES = 16
# expm (scaling and squaring, Al-Mohy & Higham 2009) and the closed form are each exact to rounding (~1e-15 per
# step); over 2 intervals × 16 sub-steps and the (I − M)⁻¹ solve (condition ~1/(1 − |μ|) ≈ 10 here) the two
# orbits agree to ~1e-12 relative; 1e-9 leaves room and still fails on any wrong term (they are O(1) wrong).
RTOL = 1e-9


def mesh(mass=MASS, force=FORCE, stiffness_scale=1.0, damping_scale=1.0, **structure) -> MeshDynamicsProblem:
    """Square-wave-like two-interval mesh (double then single contact), mesh frequency 0.3 × 100 Hz."""
    period = 1.0 / 30.0
    return MeshDynamicsProblem(mass=mass, nodes=[0.0, 0.6 * period, period],
                               stiffness=stiffness_scale * STIFFNESS * np.array([1.5, 1.0]),
                               damping=damping_scale * 2.0 * 0.05 * MASS * OMEGA * np.array([1.5, 1.0]),
                               force=force, contact_count=[2, 1], **structure)


def test_a_1x1_mass_matrix_with_unit_mesh_vector_is_the_scalar_mesh():
    problem = mesh(mass=[[MASS]], mesh_vector=[1.0])
    assert problem.structure.is_scalar_mesh and problem.degrees_of_freedom == 1
    assert problem.mass == MASS and isinstance(problem.mass, float)
    assert np.array_equal(periodic_steady_state(problem).displacement, periodic_steady_state(mesh()).displacement)


def test_the_matrix_solver_gives_the_closed_form_orbit_of_the_1dof_mesh():
    """The same representation feeds periodic_ndof: the 1-DOF problem as pieces M, K₀ + k_j w wᵀ, …"""
    problem = mesh()
    closed = periodic_steady_state(problem, samples_per_interval=SAMPLES)
    matrix = periodic_response(piecewise_system(problem), samples_per_piece=SAMPLES)
    assert np.allclose(matrix.time, closed.time, rtol=1e-14, atol=0.0)
    assert np.allclose(matrix.displacement[:, 0], closed.displacement, rtol=RTOL, atol=0.0)
    assert np.allclose(matrix.velocity[:, 0], closed.velocity, rtol=RTOL, atol=RTOL * np.abs(closed.velocity).max())


def test_a_scaled_mesh_vector_reduces_to_the_1dof_mesh():
    """M = [4me], w = [2]: with δ = 2q, 4me·q̈ + 4c·q̇ + 4k·q = 2g is me·δ̈ + c·δ̇ + k·δ = g; mesh mass me."""
    scaled = mesh(mass=[[4.0 * MASS]], mesh_vector=[2.0])
    assert not scaled.structure.is_scalar_mesh  # solved by the matrix path, checked against the 2×2 one
    assert scaled.mesh_mass == pytest.approx(MASS, rel=1e-15)
    orbit = periodic_steady_state(scaled, samples_per_interval=SAMPLES)
    reference = periodic_steady_state(mesh(), samples_per_interval=SAMPLES)
    assert np.allclose(orbit.displacement, reference.displacement, rtol=RTOL, atol=0.0)
    assert np.allclose(orbit.coordinates[:, 0], reference.displacement / 2.0, rtol=RTOL, atol=0.0)
    assert np.allclose(np.sort(np.abs(floquet_multipliers(scaled))), np.sort(np.abs(floquet_multipliers(mesh()))),
                       rtol=RTOL, atol=0.0)


def test_two_symmetric_bodies_reduce_to_the_1dof_mesh():
    """Two bodies of mass m, each on a support (k_g, c_g), meshing along w = [1, −1]: the mesh load g·w drives the
    antisymmetric motion q₁ = −q₂ = δ/2 only, and row 1 gives (m/2)·δ̈ + (c + c_g/2)·δ̇ + (k + k_g/2)·δ = g."""
    body, support_k, support_c = 2.0 * MASS, 0.4 * STIFFNESS, 2.0 * 0.05 * MASS * OMEGA
    structure = mesh(mass=np.diag([body, body]), mesh_vector=[1.0, -1.0],
                     structural_stiffness=np.diag([support_k, support_k]),
                     structural_damping=np.diag([support_c, support_c]))
    assert structure.degrees_of_freedom == 2
    orbit = periodic_steady_state(structure, samples_per_interval=SAMPLES)
    base = mesh()
    equivalent = MeshDynamicsProblem(mass=body / 2.0, nodes=base.nodes,
                                     stiffness=base.stiffness + support_k / 2.0,
                                     damping=base.damping + support_c / 2.0, force=FORCE,
                                     contact_count=base.contact_count)
    reference = periodic_steady_state(equivalent, samples_per_interval=SAMPLES)
    assert np.allclose(orbit.displacement, reference.displacement, rtol=RTOL, atol=0.0)
    assert np.allclose(orbit.coordinates[:, 0], -orbit.coordinates[:, 1], rtol=RTOL, atol=0.0)
    assert orbit.interval.tolist() == reference.interval.tolist()


@pytest.mark.parametrize("changes, key", [
    ({"mass": np.diag([1.0, 1.0])}, "mesh_vector"),
    ({"mass": [[1.0, 0.5], [0.0, 1.0]], "mesh_vector": [1.0, -1.0]}, "mass"),
    ({"mass": np.diag([1.0, -1.0]), "mesh_vector": [1.0, -1.0]}, "mass"),
    ({"mass": np.eye(2), "mesh_vector": [0.0, 0.0]}, "mesh_vector"),
    ({"mass": np.eye(2), "mesh_vector": [1.0, -1.0], "structural_stiffness": np.eye(3)}, "structural_stiffness"),
    ({"mass": np.eye(2), "mesh_vector": [1.0, -1.0], "structural_force": [np.nan, 0.0]}, "structural_force"),
    ({"mass": -1.0}, "mass"),
])
def test_bad_structures_are_refused_naming_the_input(changes, key):
    with pytest.raises(ProblemError, match=key):
        mesh(**changes)


def test_the_1dof_only_quantities_and_solvers_refuse_a_structure():
    structure = mesh(mass=np.eye(2), mesh_vector=[1.0, -1.0], structural_stiffness=np.eye(2) * STIFFNESS)
    with pytest.raises(ProblemError, match="mass"):
        _ = structure.static_transmission_error
    for solve in (periodic_initial_state, lambda p: evaluate_orbit(p, (0.0, 0.0), np.zeros(1)),
                  lambda p: transient_from_rest(p, 1), lambda p: reference_solve_ivp(p, 1)):
        with pytest.raises(ProblemError, match="1-DOF mesh"):
            solve(structure)
    backlash = BacklashMeshProblem.from_linear(structure, backlash=1e-4)
    assert backlash.degrees_of_freedom == 2 and np.array_equal(backlash.structure.mesh_vector, [1.0, -1.0])
    for solve in (backlash_periodic_response, lambda p: reference_backlash_solve_ivp(p, 1)):
        with pytest.raises(ProblemError, match="1-DOF mesh"):
            solve(backlash)


def test_the_backlash_problem_carries_its_structure_to_the_linear_problem():
    structure = mesh(mass=np.eye(2), mesh_vector=[1.0, -1.0], structural_stiffness=np.eye(2) * STIFFNESS)
    backlash = BacklashMeshProblem.from_linear(structure, backlash=1e-4)
    linear = backlash.linear_problem()
    assert np.array_equal(linear.structure.stiffness, structure.structure.stiffness)
    assert np.array_equal(linear.mass, structure.mass)
    scalar = BacklashMeshProblem.from_linear(mesh(), backlash=1e-4)
    assert scalar.structure.is_scalar_mesh and scalar.mass == MASS


def test_the_drivetrain_system_is_a_mesh_problem_in_a_structure():
    """The drivetrain hands periodic_ndof M, K₀, C₀ (with the skew gyroscopic term), f₀, w wᵀ and w with the mesh's
    k_j, c_j, g_j: the same problem type holds it, gives back the very same pieces, and its orbit is wᵀq."""
    from drivetrain_builders import geared_pair

    from thermogear.drivetrain.response import drivetrain_periodic_system
    from thermogear.mesh.state import MeshState
    from thermogear.geometry.mesh_cycle import MeshGrid

    period = 60.0 / (20 * 1500.0)
    nodes = np.array([0.0, 0.6 * period, period])
    in_contact = np.array([[True, True], [True, False]])
    pair_stiffness = np.array([[1.0e7, 2.0e7], [1.0e7, 0.0]])
    pair_damping = np.array([[500.0, 1000.0], [500.0, 0.0]])
    grid = MeshGrid(nodes=nodes, midpoints=0.5 * (nodes[1:] + nodes[:-1]), roll=np.zeros((2, 2)),
                    in_contact=in_contact, contact_count=in_contact.sum(axis=0))
    state = MeshState(model="test", speed_rpm=1500.0, normal_load=3000.0, mass=1.0, grid=grid,
                      pair_stiffness=pair_stiffness, pair_damping=pair_damping, mesh_damping=pair_damping.sum(axis=0),
                      pair_deviation=np.zeros((2, 2)), pair_engaged=in_contact, static_transmission_error=None,
                      backlash=None, face_width=0.02, mesh_frequency_hz=1.0 / period)
    system, _ = drivetrain_periodic_system(geared_pair(bearing_damping=1e3, material_damping=1e-5).assemble(), state)
    problem = MeshDynamicsProblem(mass=system.mass, mesh_vector=system.force_pattern,
                                  structural_stiffness=system.stiffness, structural_damping=system.damping,
                                  structural_force=system.force, nodes=system.nodes, stiffness=system.stiffness_factor,
                                  damping=system.damping_factor, force=system.force_factor,
                                  contact_count=grid.contact_count)
    assert problem.degrees_of_freedom == system.size > 1
    again = piecewise_system(problem)
    for name in ("mass", "stiffness", "damping", "force", "nodes", "stiffness_pattern", "stiffness_factor",
                 "damping_pattern", "damping_factor", "force_pattern", "force_factor"):
        assert np.array_equal(getattr(again, name), getattr(system, name)), name
