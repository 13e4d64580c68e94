"""Element matrices of the drivetrain: symmetry, skew gyroscopic matrices, rigid-body null spaces, the
Euler–Bernoulli limit, shear coefficients, disks and the mesh vector."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.drivetrain import (Bearing, Coupling, CrossSection, GearMesh, Material, NodeLocation, RigidDisk,
                                   ShaftElement, cowper_shear_coefficient, hutchinson_shear_coefficient)
from thermogear.errors import CaseError

STEEL = Material(youngs_modulus=211e9, density=7810.0, shear_modulus=81.2e9)


def _element(length=0.1, outer=0.05, inner=0.02, **options) -> ShaftElement:
    return ShaftElement(length, CrossSection(outer, inner), STEEL, **options)


def _rigid_motions(length: float) -> np.ndarray:
    """The six rigid motions of a two-node element (columns): x, y, z, rotation about x (y = −α z), about y
    (x = +β z), torsion."""
    motions = np.zeros((12, 6))
    for node, z in ((0, 0.0), (1, length)):
        base = 6 * node
        for kind in (0, 1, 2, 5):
            motions[base + kind, kind] = 1.0
        motions[base + 3, 3], motions[base + 1, 3] = 1.0, -z
        motions[base + 4, 4], motions[base + 0, 4] = 1.0, z
    return motions


@pytest.mark.parametrize("length", [0.01, 0.1, 1.0])
def test_shaft_element_symmetry_skew_and_definiteness(length):
    element = _element(length)
    stiffness, mass, gyroscopic = element.stiffness(), element.mass(), element.gyroscopic()
    # rounding of O(1e12) entries: relative 1e-12 of the largest entry
    assert np.allclose(stiffness, stiffness.T, rtol=0, atol=1e-12 * np.abs(stiffness).max())
    assert np.allclose(mass, mass.T, rtol=0, atol=1e-14 * np.abs(mass).max())
    assert np.allclose(gyroscopic, -gyroscopic.T, rtol=0, atol=1e-14 * np.abs(gyroscopic).max())
    assert np.abs(gyroscopic).max() > 0.0
    assert np.linalg.eigvalsh(mass).min() > 0.0
    eigenvalues = np.linalg.eigvalsh(stiffness)
    assert eigenvalues.min() > -1e-10 * eigenvalues.max()


@pytest.mark.parametrize("shear", [True, False])
def test_shaft_element_rigid_body_null_space(shear):
    element = _element(0.3, shear_deformation=shear)
    stiffness = element.stiffness()
    residual = np.abs(stiffness @ _rigid_motions(0.3)).max()
    assert residual < 1e-12 * np.abs(stiffness).max()
    # exactly six zero eigenvalues: the rest are elastic (relative 1e-9 separates them by many orders)
    eigenvalues = np.linalg.eigvalsh(stiffness)
    assert np.sum(eigenvalues < 1e-9 * eigenvalues.max()) == 6


def test_euler_bernoulli_limit_equals_the_classical_element():
    # φ = 0: the cubic Hermite element, K = EI/L³[12, 6L, …] and M = ρAL/420[156, 22L, 54, −13L, …]
    element = _element(0.2, shear_deformation=False, rotary_inertia=False)
    L, ei = 0.2, STEEL.youngs_modulus * element.section.second_moment
    rho_a = STEEL.density * element.section.area
    hermite_k = ei / L**3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L**2, -6 * L, 2 * L**2],
                                      [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L**2, -6 * L, 4 * L**2]])
    hermite_m = rho_a * L / 420 * np.array([[156, 22 * L, 54, -13 * L], [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                                            [54, 13 * L, 156, -22 * L], [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    x_plane = np.array([0, 4, 6, 10])
    assert np.allclose(element.stiffness()[np.ix_(x_plane, x_plane)], hermite_k, rtol=1e-13, atol=0)
    assert np.allclose(element.mass()[np.ix_(x_plane, x_plane)], hermite_m, rtol=1e-13, atol=1e-18)
    # and the Timoshenko element tends to it as the shear stiffness grows (φ ∝ 1/G → 0; κ given, since ν from
    # E/(2G) − 1 would be unphysical here)
    stiff = ShaftElement(0.2, element.section, Material(211e9, 7810.0, shear_modulus=81.2e9 * 1e8),
                         shear_coefficient=0.9, rotary_inertia=False)
    assert stiff.shear_parameter < 1e-8
    assert np.allclose(stiff.stiffness()[np.ix_(x_plane, x_plane)], hermite_k, rtol=1e-7, atol=0)


def test_planes_mirror_each_other_through_the_slope_signs():
    # y–z plane = x–z plane with the rotation signs flipped (dy/dz = −α, dx/dz = +β)
    element = _element(0.15)
    x_plane, y_plane = np.array([0, 4, 6, 10]), np.array([1, 3, 7, 9])
    signs = np.diag([1.0, -1.0, 1.0, -1.0])
    for matrix in (element.stiffness(), element.mass()):
        assert np.allclose(matrix[np.ix_(y_plane, y_plane)], signs @ matrix[np.ix_(x_plane, x_plane)] @ signs,
                           rtol=1e-14, atol=0)


@pytest.mark.parametrize("ratio, cowper, hutchinson", [(0.0, 0.8864, 0.9252)])
def test_shear_coefficients_of_a_solid_circle(ratio, cowper, hutchinson):
    # Cowper (1966): 6(1+ν)/(7+6ν); Hutchinson (2001), as quoted by Stephen (2001): 6(1+ν)²/(7+12ν+4ν²); 4 digits
    assert cowper_shear_coefficient(0.3, ratio) == pytest.approx(cowper, abs=5e-5)
    assert hutchinson_shear_coefficient(0.3, ratio) == pytest.approx(hutchinson, abs=5e-5)


def test_shear_parameter_of_a_hollow_element():
    # φ = 12EI/(κGAL²) with Cowper's hollow κ: L = 0.5 m, d = 0.10/0.05 m, E = 211 GPa, G = 81.2 GPa gives the value
    # ROSS's ShaftElement documents (0.1571268472906404); 1e-9 relative: the formula, not library digits
    element = ShaftElement(0.5, CrossSection(0.10, 0.05), STEEL)
    assert element.shear_parameter == pytest.approx(0.1571268472906404, rel=1e-9)


def test_annulus_disk_and_its_limits():
    location = NodeLocation("s", 0.0)
    disk = RigidDisk.annulus("d", location, 7810.0, 0.07, 0.28, 0.05)
    mass = 7810.0 * math.pi * 0.07 * (0.28**2 - 0.05**2) / 4
    assert disk.mass == pytest.approx(mass, rel=1e-14)
    assert disk.polar_inertia == pytest.approx(mass * (0.28**2 + 0.05**2) / 8, rel=1e-14)
    solid = RigidDisk.annulus("d", location, 7810.0, 1e-6, 0.2)
    assert solid.polar_inertia == pytest.approx(solid.mass * 0.2**2 / 8, rel=1e-14)
    assert solid.diametral_inertia == pytest.approx(solid.polar_inertia / 2, rel=1e-9)  # thin disk: I_d → I_p/2
    gyroscopic = disk.gyroscopic()
    assert gyroscopic[3, 4] == disk.polar_inertia and gyroscopic[4, 3] == -disk.polar_inertia
    with pytest.raises(CaseError, match="outer_diameter"):
        RigidDisk.annulus("d", location, 7810.0, 0.07, 0.04, 0.05)


def test_bearing_and_coupling_matrices():
    bearing = Bearing("b", NodeLocation("s", 0.0), 1e8, 2e8, 3e7, damping_x=10.0)
    assert np.array_equal(np.diag(bearing.stiffness_matrix()), [1e8, 2e8, 3e7, 0, 0, 0])
    coupling = Coupling("c", NodeLocation("a", 0.0), NodeLocation("b", 0.0), 5e4, 2.0)
    stiffness = coupling.stiffness_matrix()
    assert stiffness[5, 5] == 5e4 and stiffness[5, 11] == -5e4
    assert np.allclose(stiffness @ np.ones(12), 0.0)  # a common motion of both nodes strains nothing
    with pytest.raises(CaseError, match="stiffness_x"):
        Bearing("b", NodeLocation("s", 0.0), -1.0, 1.0)


def _mesh(alpha=math.radians(20.0), phi=0.0, sense=1) -> GearMesh:
    return GearMesh("m", NodeLocation("a", 0.0), NodeLocation("b", 0.0), 0.04, 0.06, alpha, 1e8,
                    centre_line_angle=phi, rotation_sense=sense)


def test_mesh_vector_geometry():
    alpha = math.radians(20.0)
    w = _mesh(alpha).vector()
    # φ_c = 0, s = +1: u = (sin α, cos α); torsion r_b1, r_b2 in the same (global) sense
    assert np.allclose(w, [math.sin(alpha), math.cos(alpha), 0, 0, 0, 0.04,
                           -math.sin(alpha), -math.cos(alpha), 0, 0, 0, 0.06], rtol=1e-15, atol=1e-17)
    assert np.linalg.matrix_rank(np.outer(w, w)) == 1
    # the other turning sense mirrors u about the centre line and flips the torsional entries
    mirrored = _mesh(alpha, sense=-1).vector()
    assert np.allclose(mirrored[[0, 1, 5, 11]], [math.sin(alpha), -math.cos(alpha), -0.04, -0.06])
    # a centre line at 90°: u rotated by 90°
    rotated = _mesh(alpha, phi=math.pi / 2).line_of_action
    assert np.allclose(rotated, [-math.cos(alpha), math.sin(alpha)], atol=1e-15)


def test_mesh_torques_do_no_work_on_the_rigid_rotation():
    # rigid rotation (θ₁, θ₂) ∝ (r_b2, −r_b1) leaves δ unchanged; the torque pair does no work on it
    mesh = _mesh(sense=-1)
    first, second = mesh.torques(1000.0)
    assert first * 0.06 + second * -0.04 == pytest.approx(0.0, abs=1e-12)
    w = mesh.vector()
    assert w[5] * 0.06 + w[11] * -0.04 == pytest.approx(0.0, abs=1e-17)
    assert mesh.speed_ratio == pytest.approx(-0.04 / 0.06)


def test_bad_inputs_name_the_key():
    with pytest.raises(CaseError, match="operating_pressure_angle"):
        _mesh(alpha=2.0)
    with pytest.raises(CaseError, match="inner_diameter"):
        CrossSection(0.05, 0.06)
    with pytest.raises(CaseError, match="shear_modulus"):
        Material(211e9, 7810.0)
