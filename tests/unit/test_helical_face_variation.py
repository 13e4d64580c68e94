"""The spread contact's moments over the mesh period in the drivetrain (thermogear.drivetrain.mesh_contact, "The
variation over the period"): the three patterns are the slices' own sum Σk_j w(z_j)w(z_j)ᵀ and their gaps' force
Σk_je_j w(z_j) exactly; with the moments held at their means the route is today's spread route; the modes at the
period mean are unchanged; through the case, a mirror image of the pair (the other hand turning the other way) mirrors
the bearing forces and moments, a face temperature gradient moves the bearing load towards the hot end and a uniform
temperature leaves it where the mean moments put it."""

from __future__ import annotations

import copy
import math
import tomllib
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from drivetrain_builders import geared_pair
from thermogear.drivetrain.mesh_contact import FaceVariation, face_variation, mesh_contact
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_periodic_system
from thermogear.drivetrain.static_state import mesh_torque_forces
from thermogear.errors import CaseError
from thermogear.mesh.state import mesh_state_from_arrays

ROOT = Path(__file__).resolve().parents[2]
BASE_HELIX = math.radians(14.0)
PIECES = 24
RATIO = 2e-5  # c(τ)/k(τ) [s]: a slice's damping proportional to its stiffness, as the helical mesh state's


def _drivetrain(sense: int = 1, hand: int = 1, tilting: float = 0.0):
    """The small geared pair of drivetrain_builders at β_b = 14°, the spread contact, bearings that resist tilt."""
    drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2, rotation_sense=sense)
    mesh = replace(drivetrain.meshes[0], base_helix_angle=BASE_HELIX, hand=hand, contact=mesh_contact("spread"),
                   face_width=0.02, damping=0.0)
    bearings = tuple(replace(bearing, tilting_stiffness=tilting) for bearing in drivetrain.bearings)
    return replace(drivetrain, meshes=(mesh,), bearings=bearings)


def _slices():
    """A hand-made face: 5 slices across b = 20 mm, each with its own stiffness history (a contact line crossing
    it) and gap (a helix slope deviation plus a crowning), over PIECES equal intervals."""
    z = np.linspace(-0.008, 0.008, 5)
    phase = (np.arange(PIECES) + 0.5) / PIECES
    stiffness = 6e7 * (1.0 + 0.4 * np.cos(2.0 * np.pi * (phase[:, None] + 0.17 * np.arange(5)[None, :]))) \
        * (1.0 + 0.1 * z[None, :] / 0.008)
    gap = 2e-6 * z / 0.008 + 1e-6 * (z / 0.008) ** 2
    return z, stiffness, np.broadcast_to(gap, stiffness.shape)


def _face():
    """(z, stiffness, gap of _slices, the spread mesh with their variation and z̄, ρ their stiffness-weighted period
    means, the drivetrain with it assembled, the same with a point contact: its structure without the mesh)."""
    z, stiffness, gap = _slices()
    k0 = stiffness.sum(axis=1)
    variation = face_variation(k0, stiffness @ z, stiffness @ z**2, np.sum(stiffness * gap * z, axis=1), 1)
    drivetrain = _drivetrain()
    mesh = replace(drivetrain.meshes[0], stiffness=float(np.mean(k0)), damping=RATIO * float(np.mean(k0)),
                   load_centre=variation.mean_load_centre, load_gyration=variation.mean_gyration,
                   face_variation=variation)
    structure = replace(drivetrain, meshes=(replace(mesh, contact=mesh_contact("point")),)).assemble()
    return z, stiffness, gap, mesh, replace(drivetrain, meshes=(mesh,)).assemble(), structure


def _state(stiffness: np.ndarray, excitation: np.ndarray | None = None, load: float = 2e3):
    deviation = None if excitation is None else excitation / stiffness
    return mesh_state_from_arrays(np.arange(stiffness.size) / stiffness.size, stiffness, damping=RATIO * stiffness,
                                  deviation=deviation, speed_rpm=3000.0, normal_load=load, mass=0.5, pinion_teeth=27)


def test_the_three_patterns_are_the_slices_own_sum_and_their_gaps_force():
    """On every piece the periodic system's stiffness is K₀ + Σ_j k_j w(z_j)w(z_j)ᵀ, its damping C₀ + Σ_j c_j w w ᵀ
    and its force T + Σ_j k_je_j w(z_j), the slice sum written out (first principles), for a mesh whose z̄ and ρ are
    the slices' stiffness-weighted period means."""
    z, stiffness, gap, mesh, assembled, structure = _face()
    k0 = stiffness.sum(axis=1)
    state = _state(k0, np.sum(stiffness * gap, axis=1))
    system, reduction = drivetrain_periodic_system(assembled, state)
    assert system.pattern_count == 3
    for piece in (0, 7, 19):
        w = np.array([mesh.vector_at(position) for position in z])  # (slices, 12)
        local = np.einsum("j,ja,jb->ab", stiffness[piece], w, w)
        dofs = np.concatenate([np.arange(6 * node, 6 * node + 6) for node in (
            assembled.dof(mesh.gear_1, "x") // 6, assembled.dof(mesh.gear_2, "x") // 6)])
        expected_k = structure.structure_stiffness.copy()
        expected_k[np.ix_(dofs, dofs)] += local
        expected_c = structure.structure_damping + (3000.0 * math.pi / 30.0) * structure.gyroscopic
        expected_c[np.ix_(dofs, dofs)] += RATIO * local
        expected_f = mesh_torque_forces(structure, 2e3)
        expected_f[dofs] += np.einsum("j,ja->a", stiffness[piece] * gap[piece], w)
        matrices = system.piece(piece)
        for got, expected in zip(matrices, (reduction.project(expected_k), reduction.project(expected_c),
                                            reduction.project_vector(expected_f))):
            np.testing.assert_allclose(got, expected, rtol=0.0, atol=1e-10 * np.abs(expected).max())


def test_the_backlash_contact_states_take_the_whole_face():
    """The backlash system of the same face: on the back flanks every slice's gap grows by the backlash b, the force
    T + Σ_j k_j(e_j − b) w(z_j) with the driving flanks' stiffness; in free flight the face's varying part leaves with
    the mesh (what stays is the mean tilting stiffness k̄ρ² w_zw_zᵀ of the constant matrices, as before)."""
    from thermogear.drivetrain.response import drivetrain_backlash_system
    from thermogear.dynamics.backlash.backlash_pieces import contact_state_system
    from thermogear.dynamics.backlash.backlash_system import BACK_CONTACT, DRIVING_CONTACT, FREE_FLIGHT

    z, stiffness, gap, mesh, assembled, structure = _face()
    k0 = stiffness.sum(axis=1)
    backlash = 40e-6
    system, reduction = drivetrain_backlash_system(assembled, replace(_state(k0, np.sum(stiffness * gap, axis=1)),
                                                                      backlash=backlash))
    assert system.pattern_meshes == (0, 0, 0)
    dofs = np.concatenate([np.arange(6 * node, 6 * node + 6) for node in (
        assembled.dof(mesh.gear_1, "x") // 6, assembled.dof(mesh.gear_2, "x") // 6)])
    w = np.array([mesh.vector_at(position) for position in z])
    for piece in (3, 15):
        back = contact_state_system(system, (BACK_CONTACT, ())).piece(piece)
        drive = contact_state_system(system, (DRIVING_CONTACT, ())).piece(piece)
        free = contact_state_system(system, (FREE_FLIGHT, ())).piece(piece)
        expected_f = mesh_torque_forces(structure, 2e3)
        expected_f[dofs] += np.einsum("j,ja->a", stiffness[piece] * (gap[piece] - backlash), w)
        np.testing.assert_allclose(back[2], reduction.project_vector(expected_f), rtol=0.0,
                                   atol=1e-10 * np.abs(expected_f).max())
        np.testing.assert_array_equal(back[0], drive[0])
        expected_k = structure.structure_stiffness.copy()
        expected_k[np.ix_(dofs, dofs)] += mesh.tilting_matrix(mesh.stiffness)
        np.testing.assert_allclose(free[0], reduction.project(expected_k), rtol=0.0,
                                   atol=1e-10 * np.abs(expected_k).max())
        np.testing.assert_allclose(free[2], reduction.project_vector(mesh_torque_forces(structure, 2e3)), rtol=0.0,
                                   atol=1e-10 * np.abs(expected_f).max())


def test_moments_held_at_their_means_give_todays_spread_route():
    """f₁ = 0, k(τ)(ρ² + f₂) = k̄ρ² and no gap moment: the three-pattern route (two patterns of zero factor) is the
    one-pattern spread route with the constant tilting term, response for response."""
    drivetrain = _drivetrain()
    stiffness = 3e8 * (1.0 + 0.12 * np.cos(2.0 * np.pi * (np.arange(PIECES) + 0.5) / PIECES))
    mean = float(np.mean(stiffness))
    mesh = replace(drivetrain.meshes[0], stiffness=mean, damping=RATIO * mean)
    gyration = mesh.contact.moments(mesh)[1]
    held = FaceVariation(np.zeros(PIECES), gyration**2 * (mean / stiffness - 1.0), np.zeros(PIECES))
    today = replace(drivetrain, meshes=(mesh,)).assemble()
    varied = replace(drivetrain, meshes=(replace(mesh, face_variation=held),)).assemble()
    state = _state(stiffness)
    ours, theirs = drivetrain_periodic_response(varied, state), drivetrain_periodic_response(today, state)
    np.testing.assert_allclose(ours.transmission_error, theirs.transmission_error, rtol=0.0,
                               atol=1e-9 * np.abs(theirs.transmission_error).max())
    for name, force in theirs.bearing_forces.items():
        np.testing.assert_allclose(ours.bearing_forces[name], force, rtol=0.0, atol=1e-9 * np.abs(force).max())
    np.testing.assert_allclose(drivetrain_modes(varied).frequencies_hz, drivetrain_modes(today).frequencies_hz,
                               rtol=1e-12)


def test_a_variation_of_the_wrong_shape_is_refused():
    with pytest.raises(CaseError, match="face_variation"):
        FaceVariation(np.zeros(3), np.zeros(4), np.zeros(3))
    with pytest.raises(CaseError, match="sense"):
        face_variation(np.ones(3), np.zeros(3), np.zeros(3), np.zeros(3), 0)


def _case_responses(hand: str, rotation: str, gradients: tuple[float, ...]) -> dict:
    """The thermal model's periodic response of the two-shaft rotor of docs/drivetrain.md cut at β = 15° with the
    spread contact, bearings with a tilting stiffness, coarse settings, per face gradient [K] (and the same with the
    variation taken out, key None)."""
    from thermogear.case import case_from_document
    from thermogear.drivetrain.case_model import case_drivetrain

    base = tomllib.loads((ROOT / "tests" / "data" / "two_shaft_drivetrain.toml").read_text(encoding="utf-8"))
    base["gears"].update(helix_angle_deg=15.0, hand=hand)
    base["dynamics"].update(points_per_period=64)
    base["drivetrain"].update(helical_contact="spread", maximum_element_length_mm=125.0, pinion_rotation=rotation)
    for bearing in base["drivetrain"]["bearings"]:
        bearing["tilting_stiffness_n_m_per_rad"] = 2e5
    responses = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for gradient in gradients:
            document = copy.deepcopy(base)
            document["temperature"]["face_gradient_k"] = gradient
            built = case_drivetrain(case_from_document(document))
            drivetrain, state = built.drivetrains["thermal"], built.mesh_states("thermal")
            responses[gradient] = drivetrain_periodic_response(drivetrain.assemble(), state)
            if gradient == 0.0:
                plain = replace(drivetrain, meshes=(replace(drivetrain.meshes[0], face_variation=None),))
                responses[None] = drivetrain_periodic_response(plain.assemble(), state)
    return responses


@pytest.fixture(scope="module")
def case_responses() -> dict:
    return {("right", "counter-clockwise"): _case_responses("right", "counter-clockwise", (0.0, 20.0)),
            ("left", "clockwise"): _case_responses("left", "clockwise", (20.0,))}


def _means(response) -> dict:
    return {name: (response.bearing_forces[name].mean(axis=0), response.bearing_moments[name].mean(axis=0))
            for name in response.bearing_forces}


def test_a_mirror_image_pair_mirrors_the_bearing_forces_and_moments(case_responses):
    """The left-hand pair turning clockwise is the right-hand pair turning counter-clockwise seen in the mirror
    y → −y (centre line along +x): forces (x, −y, z), moments (−M_x, M_y), with the face gradient on. Axial positions
    are kept (sH is the same), so the mapping ζ = sH(z_s − b/2) is what this checks; a mapping by the hand alone
    would mirror the load centre's swing and the gradient's moment to the other end of the face."""
    right = _means(case_responses[("right", "counter-clockwise")][20.0])
    left = _means(case_responses[("left", "clockwise")][20.0])
    for name, (force, moment) in right.items():
        np.testing.assert_allclose(left[name][0], force * np.array([1.0, -1.0, 1.0]), rtol=0.0,
                                   atol=1e-6 * np.abs(force).max())
        np.testing.assert_allclose(left[name][1], moment * np.array([-1.0, 1.0]), rtol=0.0,
                                   atol=1e-6 * np.abs(moment).max())


def test_a_face_gradient_moves_the_bearing_load_to_the_hot_end_and_a_uniform_temperature_does_not(case_responses):
    """The hot end (z_s = 0, where the oil leaves the mesh) lies at ζ = −sH·b/2 = −b/2 for the right-hand pinion
    turning counter-clockwise: towards bearing A (z = 0) on both shafts. Against the uniform temperature, the mean
    radial force of bearing A grows and that of bearing B falls on each shaft. With a uniform temperature the
    variation adds no static moment: the mean bearing forces are those of the mean moments alone (2.3e-7 m of mean
    load-centre shift measured, against 0.03 b = 6e-4 m per 10 K of gradient)."""
    responses = case_responses[("right", "counter-clockwise")]
    hot, uniform, plain = (_means(responses[key]) for key in (20.0, 0.0, None))

    def radial(means, name):
        return float(np.hypot(*means[name][0][:2]))

    for shaft in ("pinion", "wheel"):
        near = radial(hot, f"{shaft} bearing A") - radial(uniform, f"{shaft} bearing A")
        far = radial(hot, f"{shaft} bearing B") - radial(uniform, f"{shaft} bearing B")
        assert near > 0.0 > far
        change = max(abs(near), abs(far))
        for end in ("A", "B"):
            name = f"{shaft} bearing {end}"
            assert abs(radial(uniform, name) - radial(plain, name)) < 0.05 * change


def test_the_variation_of_a_pair_without_deviations_swings_about_mid_face():
    """pair_face_variation (the Python route): the period means are the uniform face's (z̄ = 0 to 1e-3 b, ρ = b/√12
    to 1e-3), the load centre swings across mid-face, no gap moment, and the other sense sH mirrors the odd moment."""
    from thermogear.helical.geometry import HelicalPair
    from thermogear.materials import Material as GearMaterial
    from thermogear.drivetrain.mesh_contact import pair_face_variation

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        helical = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(15.0), 20e-3,
                                     bore_radii=(18e-3, 25e-3))
        right, mirrored = (pair_face_variation(helical, GearMaterial(), 32, sense) for sense in (1, -1))
    width = helical.face_width
    assert abs(right.mean_load_centre) < 1e-3 * width
    assert right.mean_gyration == pytest.approx(width / math.sqrt(12.0), rel=1e-3)
    assert right.first.max() > 0.02 * width and right.first.min() < -0.02 * width
    assert np.all(right.gap_moment == 0.0)
    np.testing.assert_allclose(mirrored.first, -right.first, rtol=0.0, atol=1e-15 * width)
    np.testing.assert_array_equal(mirrored.second, right.second)
