"""Several meshes on one structure (issue 33): the common period from the tooth counts, the pieces of a train, the
solver's mesh term as a sum over meshes, and the built-in two-stage reducer checked three ways — its modes against an
independent eigen-solution of the same matrices, its periodic response against scipy's solve_ivp integrated to steady
state, and the limit where the second stage's mesh is made rigid. Plus the train's topology refused at load (issue 36).
"""

from __future__ import annotations

import copy
import math
import tomllib
import warnings
from dataclasses import dataclass, replace
from fractions import Fraction
from functools import lru_cache
from pathlib import Path

import numpy as np
import pytest

from thermogear.case import case_from_document, load_case
from thermogear.drivetrain import Drivetrain, NodeLocation
from thermogear.drivetrain.case_model import case_drivetrain
from thermogear.drivetrain.elements import StructureElement, zero_matrix
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_periodic_system
from thermogear.drivetrain.train import MeshTrain, common_period_repeats, train_grid
from thermogear.dynamics.modes.modal_reduction import modal_basis
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, monodromy, periodic_response
from thermogear.errors import CaseError

TWO_SHAFTS = Path(__file__).resolve().parents[1] / "data" / "two_shaft_drivetrain.toml"


# ----------------------------------------------------------------------------------------------- the common period
@pytest.mark.parametrize("teeth, repeats", [
    # two stages z1/z2 → z3/z4: ν = z3/z2, T = (z2/g)·T_1 = (z3/g)·T_2 with g = gcd(z2, z3) (hand values)
    (((19, 47), (21, 53)), (47, 21)),   # g = 1: one turn of the intermediate shaft
    (((16, 24), (16, 24)), (3, 2)),     # the built-in reducer: g = 8
    (((20, 40), (20, 50)), (2, 1)),     # g = 20
])
def test_the_common_period_holds_whole_mesh_periods_of_every_stage(teeth, repeats):
    (z1, z2), (z3, _) = teeth
    assert common_period_repeats([Fraction(1), Fraction(z3, z2)]) == repeats
    g = math.gcd(z2, z3)
    assert repeats == (z2 // g, z3 // g)


def test_the_pieces_of_a_train_are_the_union_of_each_mesh_breakpoints_with_its_phase():
    first = np.array([0.0, 0.4, 1.0])            # a mesh of period 1 s, breakpoint at τ = 0.4
    second = np.array([0.0, 0.75, 1.5])          # period 1.5 s (T = 2·1 = ... no: repeats (3, 2) give T = 3 s)
    grid = train_grid([first, second], (3, 2), (0.0, 0.25))
    assert grid.period == pytest.approx(3.0)
    # first mesh: 0, 0.4, 1, 1.4, 2, 2.4; second (phase ¼ cycle): (k + ½ − ¼)·1.5 and (k − ¼)·1.5 mod 3
    expected = sorted({0.0, 0.4, 1.0, 1.4, 2.0, 2.4, 0.375, 1.875, 1.125, 2.625, 3.0})
    np.testing.assert_allclose(grid.nodes, expected, atol=1e-12)
    middles = 0.5 * (grid.nodes[:-1] + grid.nodes[1:])
    np.testing.assert_array_equal(grid.pieces[:, 0], (np.mod(middles, 1.0) >= 0.4).astype(int))
    np.testing.assert_array_equal(grid.pieces[:, 1], (np.mod(middles / 1.5 + 0.25, 1.0) >= 0.5).astype(int))


def test_repeats_that_do_not_belong_to_the_periods_are_refused():
    with pytest.raises(CaseError, match="common period"):
        train_grid([np.array([0.0, 1.0]), np.array([0.0, 1.0])], (3, 2), (0.0, 0.0))


# --------------------------------------------------------------------------------- the solver's sum over meshes
def _random_system(patterns: int, seed: int = 3) -> PiecewiseLinearSystem:
    rng = np.random.default_rng(seed)
    n, pieces = 4, 6
    mass = np.diag(rng.uniform(1.0, 2.0, n))
    base = rng.normal(size=(n, n))
    stiffness = base @ base.T + n * np.eye(n)
    vectors = rng.normal(size=(patterns, n))
    outer = np.einsum("mi,mj->mij", vectors, vectors)
    return PiecewiseLinearSystem(mass=mass, stiffness=stiffness, damping=0.1 * np.eye(n), force=rng.normal(size=n),
                                 nodes=np.linspace(0.0, 1.0, pieces + 1), stiffness_pattern=outer,
                                 stiffness_factor=rng.uniform(0.5, 1.5, (pieces, patterns)), damping_pattern=outer,
                                 damping_factor=rng.uniform(0.0, 0.1, (pieces, patterns)), force_pattern=vectors,
                                 force_factor=rng.normal(size=(pieces, patterns)))


def test_a_second_pattern_with_zero_factors_changes_nothing():
    two = _random_system(2)
    factors = {name: np.column_stack([getattr(two, name)[:, 0], np.zeros(6)])
               for name in ("stiffness_factor", "damping_factor", "force_factor")}
    padded = replace(two, **factors)
    single = replace(two, stiffness_pattern=two.stiffness_pattern[0], damping_pattern=two.damping_pattern[0],
                     force_pattern=two.force_pattern[0], **{name: getattr(two, name)[:, 0] for name in factors})
    for one, other in zip(monodromy(padded), monodromy(single)):
        np.testing.assert_allclose(one, other, rtol=1e-12, atol=1e-14)


def test_each_piece_of_a_train_is_the_sum_over_its_meshes():
    system = _random_system(3)
    for index in range(6):
        stiffness, damping, force = system.piece(index)
        expected_k = system.stiffness + np.einsum("m,mij->ij", system.stiffness_factor[index], system.stiffness_pattern)
        expected_f = system.force + system.force_factor[index] @ system.force_pattern
        np.testing.assert_allclose(stiffness, expected_k, rtol=1e-14)
        np.testing.assert_allclose(force, expected_f, rtol=1e-14)
    # the exact periodic state solves the pieces: one period of the flow from z0 returns to z0
    response = periodic_response(system, 2)
    transition, image = monodromy(system)
    np.testing.assert_allclose(transition @ response.initial_state + image, response.initial_state, atol=1e-12)


# ----------------------------------------------------------------------------------------- the two-stage reducer
def _reducer_document(cutoff_hz: float = 3000.0, damping_s: float | None = 2e-5) -> dict:
    """The built-in reducer on coarse shaft elements, its lowest modes and the fewest mesh-grid points: small enough
    for an independent integration. ``damping_s``: shaft material damping, raised so that an integration from rest
    reaches the steady state in a few common periods (the periodic solver needs no such help)."""
    document = copy.deepcopy(load_case("fzg_type_c_two_stage").document)
    document["drivetrain"]["response_cutoff_hz"] = cutoff_hz
    document["drivetrain"]["maximum_element_length_mm"] = 50.0
    document["dynamics"]["points_per_period"] = 64
    if damping_s is not None:
        for shaft in document["drivetrain"]["shafts"]:
            shaft["material_damping_s"] = damping_s
    return document


@lru_cache(maxsize=None)
def _reducer(cutoff_hz: float = 3000.0, damping_s: float | None = 2e-5):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_drivetrain(case_from_document(_reducer_document(cutoff_hz, damping_s)), ("elastic",))


def test_the_built_in_reducer_is_a_train_of_two_type_c_pairs_with_every_assumption_stated():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case("fzg_type_c_two_stage")
    assert [stage.name for stage in case.stages] == ["stage 2"]
    assert (case.stages[0].gear_pair.pinion.teeth, case.stages[0].gear_pair.wheel.teeth) == (16, 24)
    text = " ".join(case.assumptions)
    for words in ("intermediate shaft 200 mm", "mesh phase 0", "lossless", "common period"):
        assert words in text
    built = _reducer()
    assert built.train_repeats == (3, 2) and built.stage_speeds == pytest.approx((16 / 24,))
    senses = [mesh.rotation_sense for mesh in built.drivetrains["elastic"].meshes]
    assert senses == [1, -1]  # the intermediate shaft turns the other way


def test_the_reducer_modes_equal_an_independent_eigen_solution_of_the_same_matrices():
    from scipy.linalg import eig

    assembled = _reducer().assembled("elastic")
    modes = drivetrain_modes(assembled, count=15)
    values = eig(assembled.stiffness(), assembled.mass, right=False)
    frequencies = np.sort(np.sqrt(np.abs(values.real)))
    # one rigid rotation of the whole train (free at both ends): the only value near zero
    assert frequencies[0] < 1e-3 * frequencies[1] and frequencies[1] > 1.0
    elastic = frequencies[1:16]
    np.testing.assert_allclose(modes.angular_frequencies, elastic, rtol=1e-8)
    # both meshes carry strain energy in the modes: the train's meshes are in the stiffness the modes see
    every = drivetrain_modes(assembled)
    assert every.mesh_share("mesh").max() > 0.1 and every.mesh_share("stage 2").max() > 0.1


def _integrated_to_steady_state(system: PiecewiseLinearSystem, periods: int, samples: np.ndarray) -> np.ndarray:
    """z(t) at ``samples`` (times in the last of ``periods`` periods) of the same piecewise system, integrated from
    rest by scipy's solve_ivp (DOP853) piece by piece — no exponential, no monodromy."""
    from scipy.integrate import solve_ivp

    n = system.size
    inverse = np.linalg.inv(system.mass)
    state = np.zeros(2 * n)
    recorded = []
    for repeat in range(periods):
        for index in range(system.nodes.size - 1):
            stiffness, damping, force = system.piece(index)
            matrix = np.block([[np.zeros((n, n)), np.eye(n)], [-inverse @ stiffness, -inverse @ damping]])
            load = np.concatenate([np.zeros(n), inverse @ force])
            start, stop = system.nodes[index], system.nodes[index + 1]
            wanted = samples[(samples >= start) & (samples < stop)] if repeat == periods - 1 else np.array([])
            solution = solve_ivp(lambda _, z: matrix @ z + load, (start, stop), state, method="DOP853", rtol=1e-11,
                                 atol=1e-16, t_eval=np.append(wanted, stop))
            if wanted.size:
                recorded.append(solution.y[:, :-1].T)
            state = solution.y[:, -1]
    return np.vstack(recorded)


@pytest.mark.slow
def test_the_reducer_periodic_response_equals_solve_ivp_integrated_to_steady_state():
    built = _reducer()
    assembled = built.assembled("elastic")
    train = built.mesh_states("elastic")
    assert isinstance(train, MeshTrain) and train.repeats == (3, 2)
    system, _ = drivetrain_periodic_system(assembled, train)
    reduced = modal_basis(system, 2.0 * math.pi * 3000.0).reduce(system)
    exact = periodic_response(reduced, 1)
    radius = exact.spectral_radius
    periods = math.ceil(math.log(1e-10) / math.log(radius))  # the start-up decays below 1e-10 of itself
    assert periods <= 25, radius
    samples = reduced.nodes[:-1]
    integrated = _integrated_to_steady_state(reduced, periods, samples)
    n = reduced.size
    for mesh in range(2):  # each mesh's deflection δ_m = w_mᵀq (w_m in the reduced coordinates)
        vector = reduced.force_pattern[mesh]
        expected = exact.displacement[:-1] @ vector
        found = integrated[:, :n] @ vector
        # 1e-6 of the deflection: the integrator's rtol 1e-11 and a start-up decayed to 1e-10 leave far less
        np.testing.assert_allclose(found, expected, rtol=0.0, atol=1e-6 * np.abs(expected).max())
        assert np.ptp(expected) > 1e-3 * np.abs(expected).max()  # a real dynamic part, not only the static one


@pytest.mark.slow
def test_a_rigid_second_mesh_leaves_the_first_stage_alone_on_a_structure_where_the_second_is_locked():
    """The limit of one stage made rigid: with the second mesh's k(τ) scaled up, the first stage's response tends to
    that of the first mesh alone (the single-mesh solver) on the same structure with the second mesh as a constant
    spring of that stiffness — a locked mesh, here one new element class (the element interface)."""

    @dataclass(frozen=True)
    class LockedMesh:
        """A mesh of constant stiffness k [N/m] along its mesh vector w: k·w wᵀ on its two nodes."""

        name: str
        gear_1: NodeLocation
        gear_2: NodeLocation
        vector_12: np.ndarray
        stiffness: float

        locations = property(lambda self: (self.gear_1, self.gear_2))
        spin_shaft = property(lambda self: self.gear_1.shaft)
        energy_group = property(lambda self: self.name)

        def stiffness_matrix(self):
            return self.stiffness * np.outer(self.vector_12, self.vector_12)

        def mass_matrix(self):
            return zero_matrix(2)

        damping_matrix = gyroscopic_matrix = mass_matrix

        def dead_zones(self):
            return ()

        def mesh_vector(self):
            return None

    built = _reducer(damping_s=None)
    assembled = built.assembled("elastic")
    train = built.mesh_states("elastic", points_per_period=64)
    drivetrain = built.drivetrains["elastic"]
    second = drivetrain.meshes[1]
    errors = []
    for scale in (1e2, 1e4):
        stiff = replace(train.states[1], pair_stiffness=train.states[1].pair_stiffness * scale)
        response = drivetrain_periodic_response(assembled, replace(train, states=(train.states[0], stiff)),
                                                samples_per_piece=1)
        locked = LockedMesh("locked stage 2", second.gear_1, second.gear_2, second.vector(),
                            float(stiff.mean_mesh_stiffness))
        assert isinstance(locked, StructureElement)
        alone = Drivetrain(drivetrain.shafts, drivetrain.disks, drivetrain.bearings, drivetrain.couplings,
                           drivetrain.meshes[:1], drivetrain.torsional_supports, further_elements=(locked,))
        reference = drivetrain_periodic_response(alone.assemble(), train.states[0], samples_per_piece=1)
        # the train spans 3 mesh periods of the first stage: its last one at the first mesh's own nodes
        period = train.states[0].period * 3
        wanted = 2.0 * period / 3.0 + reference.time
        index = np.searchsorted(response.time, wanted - 1e-9 * period)
        np.testing.assert_allclose(response.time[index], wanted, rtol=0.0, atol=1e-9 * period)
        delta = response.meshes["mesh"].transmission_error[index]
        errors.append(np.abs(delta - reference.transmission_error).max() / np.ptp(reference.transmission_error))
    # the second mesh's variation acts through its tiny deflection: the difference falls as the mesh stiffens
    assert errors[1] < 1e-3 and errors[1] < 0.1 * errors[0], errors


def test_a_coupling_that_contradicts_the_meshes_is_refused_by_the_drivetrain_too():
    from thermogear.drivetrain import Coupling

    drivetrain = _reducer().drivetrains["elastic"]
    jam = Coupling("jam", NodeLocation("input shaft", 0.0), NodeLocation("output shaft", 0.0), 1e4)
    with pytest.raises(CaseError, match="conflicting speed ratios"):
        replace(drivetrain, couplings=(jam,)).speed_ratios()


# ------------------------------------------------------------------------------------- topology refused at load
def _two_shafts() -> dict:
    return tomllib.loads(TWO_SHAFTS.read_text(encoding="utf-8"))


def _load(document: dict):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_from_document(document, source=str(TWO_SHAFTS))


def _with_loose_shaft(section):
    section["shafts"].append({"name": "loose shaft", "segments": [{"length_mm": 100.0, "outer_diameter_mm": 30.0}]})
    for position in (0.0, 100.0):
        section["bearings"].append({"name": f"loose bearing {position:g}", "shaft": "loose shaft",
                                    "position_mm": position, "stiffness_x_n_per_m": 1e8, "stiffness_y_n_per_m": 1e8})


def _with_coupling_between_meshing_shafts(section):
    section["couplings"] = [{"name": "short circuit", "shaft_1": "pinion shaft", "position_1_mm": 0.0,
                             "shaft_2": "wheel shaft", "position_2_mm": 0.0,
                             "torsional_stiffness_n_m_per_rad": 1e4}]


def _with_zero_bearing(section):
    section["bearings"][1]["stiffness_x_n_per_m"] = 0.0
    section["bearings"][1]["stiffness_y_n_per_m"] = 0.0


def _with_x_only_bearing(section):
    section["bearings"][1]["stiffness_y_n_per_m"] = 0.0


def _with_huge_disk(section):
    section["disks"] = [{"name": "flywheel", "shaft": "wheel shaft", "position_mm": 300.0, "mass_kg": 1e5,
                         "polar_inertia_kg_m2": 1e6}]


@pytest.mark.parametrize("change, key, words", [
    (_with_loose_shaft, "drivetrain.shafts", "joined to nothing"),
    (_with_coupling_between_meshing_shafts, "drivetrain.couplings 'short circuit'", "conflicting speed ratios"),
    (_with_zero_bearing, "drivetrain.bearings 'pinion bearing B'.stiffness_x_n_per_m", "holds nothing"),
    (_with_x_only_bearing, "drivetrain.bearings (shaft 'pinion shaft') stiffness_y_n_per_m", ">= 2 bearings stiff"),
    (_with_huge_disk, "drivetrain.disks 'flywheel'.polar_inertia_kg_m2", "hold that end at speed"),
])
def test_a_drivetrain_that_cannot_turn_or_hold_is_refused_at_load_naming_key_value_range_reason(change, key, words):
    document = _two_shafts()
    change(document["drivetrain"])
    with pytest.raises(CaseError) as caught:
        _load(document)
    text = str(caught.value)
    assert key in text and words in text, text


def _reducer_with(change) -> dict:
    document = copy.deepcopy(load_case("fzg_type_c_two_stage").document)
    change(document)
    return document


@pytest.mark.parametrize("change, key, words", [
    (lambda d: d["drivetrain"]["stages"][0].update(pinion={"shaft": "output shaft", "position_mm": 50.0}),
     "drivetrain.stages 'stage 2'.wheel.shaft", "other than the stage's pinion's"),
    (lambda d: d["drivetrain"]["stages"][0].update(mesh_phase=1.0), "mesh_phase", "< 1"),
    (lambda d: d["drivetrain"]["stages"][0].update(pinion={"shaft": "output shaft", "position_mm": 50.0},
                                                   wheel={"shaft": "intermediate shaft", "position_mm": 150.0}),
     "drivetrain.stages 'stage 2'.pinion.shaft", "a shaft the train already drives"),
    (lambda d: d["drivetrain"]["stages"][0].update(name="mesh"), "drivetrain names", "unique names"),
])
def test_a_wrong_stage_is_refused_at_load(change, key, words):
    with pytest.raises(CaseError) as caught:
        _load(_reducer_with(change))
    text = str(caught.value)
    assert key in text and words in text, text


# ------------------------------------------------------------------- the 1-DOF pair: the degenerate drivetrain
@pytest.mark.parametrize("name", ["luo2019", "fzg_type_c"])
def test_the_rigid_pair_as_a_drivetrain_equals_the_compiled_one_degree_of_freedom_solver(name):
    """Two rigid gears on rigid supports through the drivetrain's route (M, w, torque pair, rigid rotation removed,
    the n-DOF exact periodic solver) give the 1-DOF pair's orbit from its compiled closed-form kernels."""
    from thermogear.drivetrain.rigid_pair import rigid_pair_system
    from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
    from thermogear.mesh.model import MeshModel

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case(name)
        state = MeshModel(case, "elastic").state(points_per_period=64)
    rigid = case.gear_pair.rigid_pair(case.material.density, case.inertias)  # the structure the 1-DOF pair is
    assert rigid.mesh_mass == state.mass  # the scalar problem's m_e is the structure's, exactly
    w = rigid.mesh_vector()
    assert 1.0 / (w @ np.linalg.solve(rigid.mass_matrix(), w)) == pytest.approx(state.mass, rel=1e-14)
    assert rigid.mesh_structure().is_scalar_mesh  # the compiled route
    problem = state.problem()
    system, reduction = rigid_pair_system(rigid, problem, state.normal_load)
    general = periodic_response(system, 4)
    delta = reduction.expand(general.displacement.T).T @ rigid.mesh_vector()
    compiled = periodic_steady_state(problem, samples_per_interval=4)
    np.testing.assert_allclose(delta, compiled.displacement, rtol=0.0, atol=1e-9 * np.abs(compiled.displacement).max())
    np.testing.assert_allclose(np.sort(np.abs(general.multipliers)), np.sort(np.abs(compiled.multipliers)),
                               rtol=1e-8)
