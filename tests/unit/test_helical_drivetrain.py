"""The helical mesh in the drivetrain: the spur element at β = 0, no strain from the assembled structure's rigid
motions, the axial bearing reactions of the thrust F_t tan β_w, an axial–torsional mode by hand, the spread contact's
tilting stiffness, and the periodic and backlash responses with a helical mesh state."""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import numpy as np
import pytest

from drivetrain_builders import geared_pair
from thermogear.drivetrain import Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation, RigidDisk, \
    Shaft, ShaftSegment
from thermogear.drivetrain.mesh_contact import MESH_CONTACTS, face_contact_moments, mesh_contact
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.drivetrain.response import drivetrain_periodic_response
from thermogear.drivetrain.static_state import static_state
from thermogear.errors import CaseError, ExtrapolationWarning, ModelAssumptionWarning
from thermogear.helical.geometry import HelicalPair
from thermogear.materials import Material as GearMaterial
from thermogear.mesh.helical_state import helical_mesh_state

HELIX = math.radians(15.0)
PRESSURE = math.radians(20.0)
BASE_HELIX = math.atan(math.tan(HELIX) * math.cos(math.atan(math.tan(PRESSURE) / math.cos(HELIX))))


def _helical(drivetrain: Drivetrain, base_helix: float = BASE_HELIX, hand: int = 1, contact: str = "point",
             face_width: float = 0.02) -> Drivetrain:
    mesh = replace(drivetrain.meshes[0], base_helix_angle=base_helix, hand=hand, contact=mesh_contact(contact),
                   face_width=face_width)
    return replace(drivetrain, meshes=(mesh,))


@pytest.mark.parametrize("phi, sense", [(0.0, 1), (0.7, -1), (3.0, 1)])
def test_a_zero_helix_is_the_spur_vector_written_out(phi, sense):
    """w = [u, 0, 0, 0, s r_b1 | −u, 0, 0, 0, s r_b2] (Kahraman et al. 1992), whatever the hand."""
    for hand in (1, -1):
        mesh = replace(geared_pair(centre_line_angle=phi, rotation_sense=sense).meshes[0], hand=hand)
        u = mesh.line_of_action
        spur = np.array([u[0], u[1], 0, 0, 0, sense * 0.0381, -u[0], -u[1], 0, 0, 0, sense * 0.0493])
        np.testing.assert_allclose(mesh.vector(), spur, rtol=0.0, atol=1e-16)


def test_a_zero_helix_gives_the_spur_drivetrains_modes_and_bearing_forces():
    spur = geared_pair().assemble()
    helical = _helical(geared_pair(), 0.0, -1).assemble()
    np.testing.assert_allclose(drivetrain_modes(helical).frequencies_hz, drivetrain_modes(spur).frequencies_hz,
                               rtol=1e-12)
    ours, theirs = static_state(helical, 1e3), static_state(spur, 1e3)
    for name, force in theirs.bearing_forces.items():
        np.testing.assert_allclose(ours.bearing_forces[name], force, rtol=0.0, atol=1e-9 * np.abs(force).max())
        assert np.all(ours.bearing_moments[name] == 0.0)


def _global_rigid_motions(assembled, mesh: GearMesh) -> list[np.ndarray]:
    """The six rigid motions of the whole structure: gear 1's shaft on the z axis, gear 2's at a·e_c, both shafts'
    positions measured from one transverse plane (the gears sit at the same position on their shafts)."""
    cosine = math.cos(mesh.operating_pressure_angle)
    distance = (mesh.base_radius_1 + mesh.base_radius_2) / cosine
    centres = {mesh.gear_1.shaft: np.zeros(2),
               mesh.gear_2.shaft: distance * np.array([math.cos(mesh.centre_line_angle),
                                                        math.sin(mesh.centre_line_angle)])}
    motions = []
    for kind in range(6):
        translation, rotation = np.zeros(3), np.zeros(3)
        (translation if kind < 3 else rotation)[kind % 3] = 1.0
        q = np.zeros(assembled.size)
        for shaft, offset in assembled.node_offsets.items():
            for node, z in enumerate(assembled.node_positions[shaft]):
                point = np.array([*centres[shaft], z])
                q[6 * (offset + node):6 * (offset + node) + 3] = translation + np.cross(rotation, point)
                q[6 * (offset + node) + 3:6 * (offset + node) + 6] = rotation
        motions.append(q)
    return motions


@pytest.mark.parametrize("phi, sense, hand", [(0.0, 1, 1), (0.9, -1, -1), (-2.0, 1, -1)])
def test_rigid_motions_of_the_assembled_structure_do_not_strain_the_mesh(phi, sense, hand):
    drivetrain = _helical(geared_pair(centre_line_angle=phi, rotation_sense=sense), hand=hand, contact="spread")
    assembled = drivetrain.assemble()
    mesh = drivetrain.meshes[0]
    tilting = assembled.mesh_stiffness_groups()["mesh"]
    for motion in _global_rigid_motions(assembled, mesh):
        scale = np.abs(assembled.mesh_vectors[0]).max() * np.abs(motion).max()
        assert abs(assembled.mesh_vectors[0] @ motion) < 1e-14 * scale
        assert np.abs(tilting @ motion).max() < 1e-14 * mesh.stiffness * scale


@pytest.mark.parametrize("hand, sense", [(1, 1), (-1, 1), (1, -1)])
def test_the_static_axial_bearing_reactions_balance_the_thrust(hand, sense):
    """Σ F_z over a shaft's bearings = ∓W tan β_b = ∓F_t tan β_w (F_t = W cos α_wt); the radial ones balance the
    transverse force as for a spur pair; a bearing with a tilting stiffness reports K_tilt·(α, β)."""
    drivetrain = _helical(geared_pair(rotation_sense=sense), hand=hand)
    first = drivetrain.bearings[0]
    drivetrain = replace(drivetrain, bearings=(replace(first, tilting_stiffness=5e5), *drivetrain.bearings[1:]))
    assembled = drivetrain.assemble()
    load = 2e3
    state = static_state(assembled, load)
    tangential = load * math.cos(PRESSURE)
    thrust = tangential * math.tan(BASE_HELIX) / math.cos(PRESSURE)  # F_t tan β_w
    assert thrust == pytest.approx(load * math.tan(BASE_HELIX), rel=1e-14)
    axial = {shaft: sum(state.bearing_forces[b.name][2] for b in drivetrain.bearings if b.location.shaft == shaft)
             for shaft in ("pinion shaft", "wheel shaft")}
    # the force on gear 2 is W·n_z/cos β_b = −σH W tan β_b along z (σ = s on the drive flanks): its bearings take it
    assert axial["wheel shaft"] == pytest.approx(-sense * hand * thrust, rel=1e-9)
    assert axial["pinion shaft"] == pytest.approx(sense * hand * thrust, rel=1e-9)
    alpha_beta = state.displacement[[assembled.dof(first.location, "alpha"), assembled.dof(first.location, "beta")]]
    np.testing.assert_allclose(state.bearing_moments[first.name], 5e5 * alpha_beta, rtol=1e-15)
    assert np.abs(state.bearing_moments[first.name]).max() > 0.0


def _rigid_pair_on_axial_springs(axial_stiffness: float, mesh_stiffness: float) -> tuple[Drivetrain, float, float]:
    """Two very stiff, light shafts, each with a disk gear; radial bearings far stiffer than the mesh;
    the pinion shaft on an axial spring, the wheel shaft held axially far stiffer."""
    rigid = Material(youngs_modulus=211e9 * 1e4, density=1.0, poisson_ratio=0.3)
    shafts = tuple(Shaft(name, (ShaftSegment(0.1, CrossSection(0.05), rigid),), 0.05 * (1 + 1e-12))
                   for name in ("one", "two"))
    one, two = NodeLocation("one", 0.05), NodeLocation("two", 0.05)
    disks = (RigidDisk("pinion", one, 2.0, 2e-3, 1e-3), RigidDisk("wheel", two, 4.0, 6e-3, 3e-3))
    hard = 1e14
    bearings = tuple(Bearing(f"{shaft} {end}", NodeLocation(shaft, position), hard, hard,
                             (axial_stiffness if shaft == "one" else hard) if end == "A" else 0.0)
                     for shaft in ("one", "two") for end, position in (("A", 0.0), ("B", 0.1)))
    mesh = GearMesh("mesh", one, two, 0.0381, 0.0493, PRESSURE, mesh_stiffness, base_helix_angle=BASE_HELIX)
    return Drivetrain(shafts, disks, bearings, meshes=(mesh,)), 2.0, 2e-3 * 6e-3 / (2e-3 * 0.0493**2 + 6e-3 * 0.0381**2)


def test_the_axial_torsional_mode_of_a_rigid_pair_on_axial_springs():
    """Hand calculation: the transverse TE x = r_b1θ₁ + r_b2θ₂ (mass m_e = J₁J₂/(J₁r_b2² + J₂r_b1²)) and the pinion's
    axial motion z (mass m, spring k_z); δ = x − t z with t = tan β_b (w's z entry of gear 1 is n_z/cos β_b = −tan β_b
    for H = s = 1), so K = K_t[[1, −t], [−t, t²]] + diag(0, k_z) and
    m_e m ω⁴ − (K_t m + (K_t t² + k_z) m_e) ω² + K_t k_z = 0.
    Everything else is ~10⁶ times stiffer (bearings, shafts: the lateral modes lie near 340 kHz) and the shafts weigh
    1e-4 of the gears (density 1 kg/m³): that mass lowers the two modes by ~½·1e-4 (measured 5e-5 and 4e-5), hence
    2e-4."""
    axial, mesh_stiffness = 3e8, 4e8
    drivetrain, mass, equivalent = _rigid_pair_on_axial_springs(axial, mesh_stiffness)
    t = math.tan(BASE_HELIX)
    b = mesh_stiffness * mass + (mesh_stiffness * t**2 + axial) * equivalent
    c = mesh_stiffness * axial
    roots = np.sort([(b - s * math.sqrt(b * b - 4 * mass * equivalent * c)) / (2 * mass * equivalent)
                     for s in (1, -1)])
    expected = np.sqrt(roots) / (2 * math.pi)
    modes = drivetrain_modes(drivetrain.assemble(), count=2)
    np.testing.assert_allclose(modes.frequencies_hz, expected, rtol=2e-4)
    spur = drivetrain_modes(replace(drivetrain, meshes=(replace(drivetrain.meshes[0], base_helix_angle=0.0),))
                            .assemble(), count=2)
    # at β = 0 the two decouple: the torsional mode √(K_t/m_e) and the axial one √(k_z/m)
    np.testing.assert_allclose(np.sort(spur.frequencies_hz), np.sort([math.sqrt(mesh_stiffness / equivalent),
                                                                       math.sqrt(axial / mass)]) / (2 * math.pi),
                               rtol=2e-4)


def test_the_spread_contact_adds_the_tilting_stiffness_of_the_face():
    """k̄ρ² w_z w_zᵀ with ρ = b/√12 on top of the point contact's k̄ w wᵀ: every frequency rises or stays
    (a positive semi-definite addition) and some rise; the slice model's period-mean distribution is uniform across
    the face (z̄ = 0, ρ² = b²(1 − 1/N²)/12 for N midpoint slices)."""
    point = drivetrain_modes(_helical(geared_pair(), contact="point").assemble(), count=12).frequencies_hz
    spread = drivetrain_modes(_helical(geared_pair(), contact="spread").assemble(), count=12).frequencies_hz
    assert np.all(spread >= point * (1 - 1e-12)) and np.any(spread > point * (1 + 1e-4))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        warnings.simplefilter("ignore", ModelAssumptionWarning)
        helical = HelicalPair.create(27, 35, 3e-3, PRESSURE, HELIX, 25e-3, bore_radii=(15e-3, 20e-3))
        centre, gyration = face_contact_moments(helical, GearMaterial(), slices=50, points=64)
    assert abs(centre) < 1e-3 * helical.face_width
    assert gyration == pytest.approx(helical.face_width * math.sqrt((1 - 1 / 50**2) / 12), rel=2e-2)


def test_a_contact_option_outside_the_registry_is_refused():
    with pytest.raises(CaseError, match="helical_contact"):
        mesh_contact("line")
    with pytest.raises(CaseError, match="contact"):
        replace(geared_pair().meshes[0], contact="spread")
    assert set(MESH_CONTACTS) == {"point", "spread"}


def _helical_response_case():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        warnings.simplefilter("ignore", ModelAssumptionWarning)
        helical = HelicalPair.create(27, 35, 3e-3, PRESSURE, HELIX, 20e-3, bore_radii=(15e-3, 20e-3))
        base = (helical.transverse.pinion.base_radius, helical.transverse.wheel.base_radius)
        drivetrain = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2,
                                 pressure_angle=helical.transverse.operating_pressure_angle)
        mesh = replace(drivetrain.meshes[0], base_radius_1=base[0], base_radius_2=base[1],
                       base_helix_angle=helical.base_helix_angle, contact=mesh_contact("spread"),
                       face_width=helical.face_width)
        drivetrain = replace(drivetrain, meshes=(mesh,))
        state = helical_mesh_state(helical, GearMaterial(), 600.0, 150.0, (2e-3, 6e-3), 128, damping_ratio=0.05)
    return drivetrain.assemble(), replace(state, backlash=50e-6), helical


def test_the_periodic_response_of_a_helical_mesh_carries_the_thrust_to_the_bearings():
    """Over one period the mean mesh force is W (torque balance on the free rotation), so the wheel shaft's bearings
    carry W tan β_b axially on the mean; the trapezoidal means of the sampled orbit (8 samples per piece, 128 pieces)
    agree to 1e-3."""
    assembled, state, helical = _helical_response_case()
    response = drivetrain_periodic_response(assembled, state, samples_per_piece=8)
    assert np.all(np.abs(response.multipliers) < 1.0)
    period = response.time[-1] - response.time[0]
    axial = sum(np.trapezoid(force[:, 2], response.time) / period
                for name, force in response.bearing_forces.items() if name.startswith("wheel"))
    assert abs(axial) == pytest.approx(state.normal_load * math.tan(helical.base_helix_angle), rel=1e-3)
    from thermogear.drivetrain.results import bearing_forces_of

    summary = bearing_forces_of(response, 2, 256)  # the typed result (JSON, table) of each bearing
    assert sum(summary[name].mean_axial_n for name in summary if name.startswith("wheel")) == pytest.approx(axial,
                                                                                                           rel=1e-12)
    assert all(force.mean_tilting_moment_n_m == 0.0 for force in summary.values())  # no tilting stiffness here
    assert set(summary["wheel shaft bearing A"].as_json()) >= {"mean_axial_n", "mean_tilting_moment_n_m"}


@pytest.mark.slow
def test_the_backlash_response_of_a_helical_mesh_in_permanent_contact_is_the_linear_one():
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response

    assembled, state, _ = _helical_response_case()
    state = replace(state, normal_load=state.normal_load * 20.0)  # far from separating
    response = drivetrain_backlash_response(assembled, state, substeps=4, samples_per_piece=4)
    linear = drivetrain_periodic_response(assembled, state, samples_per_piece=4)
    assert response.converged and response.switches == 0
    rows = [int(np.flatnonzero(np.abs(response.time - t) <= 1e-12 * linear.period)[-1]) for t in linear.time]
    for name in linear.bearing_forces:
        theirs = linear.bearing_forces[name]
        assert np.abs(response.bearing_forces[name][rows] - theirs).max() < 1e-8 * np.abs(theirs).max()


def _helical_reducer():
    """The built-in two-stage reducer on coarse elements with helical stages (8° right-hand, then 6° left-hand; the
    zero-backlash centre distances of the transverse sections) and the spread contact."""
    import copy

    from thermogear.case import case_from_document, load_case
    from thermogear.drivetrain.case_model import case_drivetrain

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        document = copy.deepcopy(load_case("fzg_type_c_two_stage").document)
        section = document["drivetrain"]
        section.update(maximum_element_length_mm=50.0, response_cutoff_hz=3000.0, helical_contact="spread")
        document["dynamics"]["points_per_period"] = 64
        for shaft in section["shafts"]:
            shaft["material_damping_s"] = 2e-5
        for gears, helix, hand in ((document["gears"], 8.0, "right"), (section["stages"][0]["gears"], 6.0, "left")):
            gears.pop("centre_distance_mm", None)
            gears.update(helix_angle_deg=helix, hand=hand)
        case = case_from_document(document)
        return case, case_drivetrain(case, ("elastic",))


def test_a_helical_train_carries_each_stages_thrust_and_solves_its_periodic_response():
    """Each mesh takes its own stage's helix; statically the input shaft's bearings carry the first mesh's thrust
    W₁ tan β_b1, the output shaft's the second's, the intermediate shaft the difference, and the housing as a whole
    none (each mesh's axial forces are action and reaction); the train's periodic response is stable."""
    from thermogear.drivetrain.train import MeshTrain

    case, built = _helical_reducer()
    drivetrain = built.drivetrains["elastic"]
    first, second = drivetrain.meshes
    assert first.base_helix_angle == case.helical_pair.base_helix_angle and first.hand == 1
    assert second.hand == -1 and 0.0 < second.base_helix_angle < first.base_helix_angle
    assembled = drivetrain.assemble()
    load = 1e3
    # the intermediate shaft in equilibrium: W₁ r_b(wheel 1) = W₂ r_b(pinion 2)
    loads = np.array([load, load * first.base_radius_2 / second.base_radius_1])
    state = static_state(assembled, loads)
    axial = {}
    for bearing in drivetrain.bearings:
        axial[bearing.location.shaft] = axial.get(bearing.location.shaft, 0.0) + state.bearing_forces[bearing.name][2]
    thrusts = loads * np.tan([first.base_helix_angle, second.base_helix_angle])
    assert abs(axial["input shaft"]) == pytest.approx(thrusts[0], rel=1e-9)
    assert abs(axial["output shaft"]) == pytest.approx(thrusts[1], rel=1e-9)
    assert abs(sum(axial.values())) < 1e-9 * thrusts.max()
    train = built.mesh_states("elastic")
    assert isinstance(train, MeshTrain)
    response = drivetrain_periodic_response(assembled, train, cutoff_hz=3000.0)
    assert np.all(np.abs(response.multipliers) < 1.0) and set(response.meshes) == {"mesh", "stage 2"}
