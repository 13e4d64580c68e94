"""The helical mesh vector derived from the flank normal: the spur element at β = 0, no strain from the pair's
six rigid motions, the force ratios of a helical mesh, and the torsional projection."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.drivetrain.mesh_element import GearMesh
from thermogear.drivetrain.point_elements import NodeLocation
from thermogear.helical.geometry import HelicalPair
from thermogear.helical.mesh_vector import helical_mesh_vector, tooth_normal

PAIR = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(15.0), 25e-3)
RADII = PAIR.transverse.operating_pitch_radii
ALPHA_WT = PAIR.transverse.operating_pressure_angle


def _rigid_motions(centre_distance: float, phi: float) -> list[np.ndarray]:
    """The six rigid motions of the pair as one body (gear 1's node at the origin, gear 2's at a·e_c)."""
    offset = centre_distance * np.array([math.cos(phi), math.sin(phi), 0.0])
    motions = []
    for index in range(3):  # translations
        t = np.zeros(3)
        t[index] = 1.0
        motions.append(np.concatenate([t, np.zeros(3), t, np.zeros(3)]))
    for index in range(3):  # rotations about the axes through gear 1's node: gear 2's node moves by ω × offset
        omega = np.zeros(3)
        omega[index] = 1.0
        motions.append(np.concatenate([np.zeros(3), omega, np.cross(omega, offset), omega]))
    return motions


@pytest.mark.parametrize("phi, sense, flank, hand, offsets", [
    (0.0, 1, None, 1, (0.0, 0.0)), (0.7, -1, None, 1, (0.0, 0.0)), (2.1, 1, -1, -1, (4e-3, -2e-3)),
    (-1.2, -1, 1, 1, (-6e-3, 9e-3))])
def test_the_pairs_rigid_motions_do_not_strain_the_mesh(phi, sense, flank, hand, offsets):
    """Both gears are read at the same contact point, the nodes lying where that point is (gear 2's node at
    a·e_c + (z_1 − z_2)ẑ from gear 1's)."""
    w = helical_mesh_vector(RADII, ALPHA_WT, PAIR.base_helix_angle, phi, sense, flank, hand, offsets)
    centre_distance = RADII[0] + RADII[1]
    for motion in _rigid_motions(centre_distance, phi):
        # gear 2's node sits (z_1 − z_2) along the axis from the plane of gear 1's: a rotation about x or y moves it
        shift = np.array([0.0, 0.0, offsets[0] - offsets[1]])
        motion = motion.copy()
        motion[6:9] += np.cross(motion[3:6], shift)
        assert abs(w @ motion) < 1e-15


@pytest.mark.parametrize("phi, sense", [(0.0, 1), (0.7, -1), (3.0, 1)])
def test_a_zero_helix_is_the_spur_element(phi, sense):
    spur = GearMesh("mesh", NodeLocation("a", 0.0), NodeLocation("b", 0.0), RADII[0] * math.cos(ALPHA_WT),
                    RADII[1] * math.cos(ALPHA_WT), ALPHA_WT, 1e8, centre_line_angle=phi, rotation_sense=sense)
    np.testing.assert_allclose(helical_mesh_vector(RADII, ALPHA_WT, 0.0, phi, sense), spur.vector(), atol=1e-16)


def test_the_force_splits_radial_tangential_axial_as_tan_alpha_one_tan_beta():
    """At the zero-backlash centre distance α_wt = α_t and β_w = β: F_r : F_t : F_a = tan α_t : 1 : tan β."""
    normal = tooth_normal(ALPHA_WT, PAIR.base_helix_angle)  # φ_c = 0: e_c = x, e_t = y
    radial, tangential, axial = normal
    assert radial / tangential == pytest.approx(math.tan(PAIR.transverse_pressure_angle), rel=1e-13)
    assert abs(axial) / tangential == pytest.approx(math.tan(PAIR.helix_angle), rel=1e-13)
    assert np.linalg.norm(normal) == pytest.approx(1.0, rel=1e-15)


@pytest.mark.parametrize("sense, flank, hand, thrust", [(1, None, 1, -1.0), (1, None, -1, 1.0), (-1, None, 1, 1.0),
                                                        (1, -1, 1, 1.0)])
def test_the_axial_thrust_on_gear_2_follows_hand_rotation_and_flank(sense, flank, hand, thrust):
    """n_z = −σH sin β_b: a right-hand driver turning counter-clockwise on its drive flanks pushes gear 2 to −z
    (and takes +z itself); the other hand, the other sense or the coast flank turn it over."""
    normal = tooth_normal(ALPHA_WT, PAIR.base_helix_angle, 0.0, sense, flank, hand)
    assert math.copysign(1.0, normal[2]) == thrust
    assert abs(normal[2]) == pytest.approx(math.sin(PAIR.base_helix_angle), rel=1e-14)


def test_the_torsional_entries_project_the_transverse_stiffness():
    """θ entries s r_b cos β_b: K_n w_θ² = K_t r_b² with K_n = K_t/cos²β_b (the 1-DOF pair keeps K_t and r_b)."""
    w = helical_mesh_vector(RADII, ALPHA_WT, PAIR.base_helix_angle)
    base = (PAIR.transverse.pinion.base_radius, PAIR.transverse.wheel.base_radius)
    cos_b = math.cos(PAIR.base_helix_angle)
    assert w[5] == pytest.approx(base[0] * cos_b, rel=1e-13) and w[11] == pytest.approx(base[1] * cos_b, rel=1e-13)
