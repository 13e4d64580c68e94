"""A train of several meshes under the backlash mesh (issue 33): every mesh its own dead zone (its own backlash,
deviation and stiffness factor on the pieces of the common period).

Checked: (1) where no mesh separates, the backlash orbit is the linear train response (also when Newton has to find
it from a perturbed start); (3) a case where both meshes separate, against an independent brute-force integration
of the same piecewise-linear system (scipy's solve_ivp, no exponential, no monodromy, no switch location).
"""

from __future__ import annotations

import copy
import math
import warnings
from functools import lru_cache

import numpy as np
import pytest

from thermogear.case import case_from_document, load_case
from thermogear.drivetrain.backlash_response import reduced_backlash_system
from thermogear.drivetrain.case_model import case_drivetrain
from thermogear.drivetrain.response import drivetrain_backlash_system
from thermogear.dynamics.backlash.backlash_ndof import (BacklashSystem, MeshZone, backlash_flow_ndof,
                                               backlash_periodic_orbit)
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, periodic_response
from thermogear.errors import ProblemError


def _nonlinear_reducer_document(load_stage: int | None = None, speed_rpm: float | None = None) -> dict:
    """The built-in two-stage reducer with the backlash mesh, on coarse shaft elements and 64 grid points per mesh
    period (small enough to solve in a test)."""
    document = copy.deepcopy(load_case("fzg_type_c_two_stage").document)
    document["dynamics"]["mesh"] = "nonlinear"
    document["dynamics"]["points_per_period"] = 64
    document["drivetrain"]["maximum_element_length_mm"] = 50.0
    if load_stage is not None:
        document["operating"]["fzg_load_stage"] = load_stage
    if speed_rpm is not None:
        document["operating"]["speed_rpm"] = speed_rpm
    return document


@lru_cache(maxsize=None)
def _reducer_system(cutoff_hz: float = 3000.0):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        built = case_drivetrain(case_from_document(_nonlinear_reducer_document()), ("elastic",))
    train = built.mesh_states("elastic")
    system, _ = drivetrain_backlash_system(built.assembled("elastic"), train)
    return train, reduced_backlash_system(system, cutoff_hz)[0]


def test_every_mesh_of_the_train_is_its_own_dead_zone():
    train, system = _reducer_system()
    assert system.linear.pattern_count == 2
    meshes = [zone for zone in system.dead_zones if isinstance(zone, MeshZone)]
    assert [zone.column for zone in meshes] == [1]
    assert meshes[0].backlash == train.states[1].backlash and system.backlash == train.states[0].backlash
    # each mesh's deviation is its own excitation over its own stiffness on the common period's pieces
    np.testing.assert_allclose(meshes[0].deviation * system.linear.stiffness_factor[:, 1],
                               system.linear.force_factor[:, 1], rtol=1e-12)


def test_a_train_whose_meshes_never_separate_has_the_linear_train_response_as_its_backlash_orbit():
    """(1) The reducer at its rated load stays on the driving flanks of both meshes: the backlash orbit is the linear
    periodic response of the same system. Also shot by Newton from a start 0.1 % off, through the flows of the
    backlash system (the switch search on every piece of both meshes), it returns there."""
    _, system = _reducer_system()
    linear = periodic_response(system.linear, 16)
    scale = np.abs(linear.initial_state).max()
    orbit = backlash_periodic_orbit(system, substeps=16, tolerance=1e-10)
    assert orbit.converged and orbit.switches == 0 and orbit.free_flight_time == 0.0
    np.testing.assert_allclose(orbit.initial_state, linear.initial_state, rtol=0.0, atol=1e-9 * scale)
    shot = backlash_periodic_orbit(system, initial_state=linear.initial_state * 1.001, substeps=16, tolerance=1e-12)
    assert shot.converged and shot.iterations >= 1
    np.testing.assert_allclose(shot.initial_state, linear.initial_state, rtol=0.0, atol=1e-9 * scale)
    np.testing.assert_allclose(np.sort(np.abs(shot.multipliers)), np.sort(np.abs(linear.multipliers)),
                               rtol=0.0, atol=1e-9)
    end, _, info = backlash_flow_ndof(system, orbit.initial_state, 16, monodromy=False)
    assert info["zone_switches"] == 0 and not info["crossings"]


def _separating_train(seed: int = 5) -> BacklashSystem:
    """A 3-DOF structure with two meshes whose deviations swing wider than their static deflections: both separate
    during each period (free flight, no back contact with these backlashes)."""
    rng = np.random.default_rng(seed)
    n, pieces = 3, 8
    mass = np.diag([1.0, 1.5, 2.0])
    base = rng.normal(size=(n, n))
    stiffness = 0.3 * (base @ base.T) + np.eye(n)
    vectors = np.array([[1.0, -1.0, 0.0], [0.0, 1.0, -1.0]])
    outer = np.einsum("mi,mj->mij", vectors, vectors)
    stiffness_factor = np.column_stack([np.where(np.arange(pieces) % 2, 10.0, 14.0),
                                        np.where(np.arange(pieces) % 4 < 2, 8.0, 12.0)])
    deviation = np.column_stack([0.12 * np.cos(2 * np.pi * (np.arange(pieces) + 0.5) / pieces),
                                 0.10 * np.sin(2 * np.pi * (np.arange(pieces) + 0.5) / pieces)])
    load = vectors.T @ np.array([0.6, 0.5])  # static normal loads of the two meshes
    linear = PiecewiseLinearSystem(mass=mass, stiffness=stiffness, damping=0.05 * np.eye(n), force=load,
                                   nodes=np.linspace(0.0, 2.0, pieces + 1), stiffness_pattern=outer,
                                   stiffness_factor=stiffness_factor, damping_pattern=outer,
                                   damping_factor=np.full((pieces, 2), 1.0), force_pattern=vectors,
                                   force_factor=stiffness_factor * deviation)
    return BacklashSystem(linear, vectors[0], deviation[:, 0], 0.5,
                          (MeshZone(vectors[1], 1, deviation[:, 1], 0.4),))


def _brute_force_period(system: BacklashSystem, state: np.ndarray) -> np.ndarray:
    """One period of the piecewise-linear system with every mesh's dead zone, integrated by solve_ivp (DOP853) piece
    by piece: M q̈ = f₀ − K₀q − C₀q̇ − Σ_m (k_mj·φ_m(g_m) + c_mj·ġ_m)·w_m, g_m = w_mᵀq − e_mj, φ_m the dead zone
    of width b_m — written out here, independent of the solver's contact states, exponentials and switch search."""
    from scipy.integrate import solve_ivp

    linear = system.linear
    n = linear.size
    inverse = np.linalg.inv(linear.mass)
    meshes = [(system.mesh_vector, 0, system.deviation, system.backlash)] + [
        (zone.vector, zone.column, zone.deviation, zone.backlash) for zone in system.dead_zones]

    def field(piece):
        def rate(_, z):
            q, v = z[:n], z[n:]
            force = linear.force - linear.stiffness @ q - linear.damping @ v
            for vector, column, deviation, backlash in meshes:
                gap = vector @ q - deviation[piece]
                bent = gap if gap > 0.0 else (gap + backlash if gap < -backlash else 0.0)
                force -= (linear.stiffness_factor[piece, column] * bent
                          + linear.damping_factor[piece, column] * (vector @ v)) * vector
            return np.concatenate([v, inverse @ force])
        return rate

    z = np.array(state, dtype=float)
    for piece in range(linear.nodes.size - 1):
        solution = solve_ivp(field(piece), (linear.nodes[piece], linear.nodes[piece + 1]), z, method="DOP853",
                             rtol=1e-12, atol=1e-14)
        z = solution.y[:, -1]
    return z


def test_a_separating_train_orbit_is_a_fixed_point_of_a_brute_force_integration():
    """(3) Both meshes leave contact once per period; the orbit's start, integrated over one period by solve_ivp with
    the dead zones written out, comes back to itself. Tolerance 1e-8 of the state: DOP853 at rtol 1e-12 loses
    accuracy only at the kinks of the force (continuous, its derivative jumps at a switch; a few per period), where
    its step control shrinks the steps — measured about 1e-10 here, against the orbit's own residual of 1e-12; an
    orbit off by a misplaced switch (a sub-step of 1/16 piece) would be off by ~1e-2."""
    system = _separating_train()
    orbit = backlash_periodic_orbit(system, substeps=16, tolerance=1e-12)
    assert orbit.converged and orbit.stable, orbit.failure
    _, _, info = backlash_flow_ndof(system, orbit.initial_state, orbit.substeps, monodromy=False)
    assert orbit.switches >= 2 and orbit.free_flight_time > 0.0  # the first mesh separates
    assert info["crossings"].get(("zone", 0, 1), 0) >= 2  # and so does the second (leaves its driving flanks)
    end = _brute_force_period(system, orbit.initial_state)
    scale = np.abs(orbit.initial_state).max()
    np.testing.assert_allclose(end, orbit.initial_state, rtol=0.0, atol=1e-8 * scale)
    # and the linear orbit of the same system is no fixed point of the brute-force flow (the check can fail)
    linear = periodic_response(system.linear, 16).initial_state
    assert np.abs(_brute_force_period(system, linear) - linear).max() > 1e-3 * scale


def test_a_mesh_zone_whose_column_is_missing_is_refused():
    system = _separating_train()
    with pytest.raises(ProblemError, match="MeshZone"):
        BacklashSystem(system.linear, system.mesh_vector, system.deviation, system.backlash, ())
    with pytest.raises(ProblemError, match="backlash"):
        MeshZone(system.mesh_vector, 1, system.deviation, 0.0)


def test_a_single_mesh_backlash_system_is_unchanged_by_the_train_path():
    """The single mesh keeps its own form (one pattern, no MeshZone): the orbit of a one-mesh system equals the one
    solved with the train's multi-pattern form holding a second mesh that never touches (zero stiffness)."""
    system = _separating_train()
    linear = system.linear
    single = PiecewiseLinearSystem(
        mass=linear.mass, stiffness=linear.stiffness, damping=linear.damping, force=linear.force, nodes=linear.nodes,
        stiffness_pattern=linear.stiffness_pattern[0], stiffness_factor=linear.stiffness_factor[:, 0],
        damping_pattern=linear.damping_pattern[0], damping_factor=linear.damping_factor[:, 0],
        force_pattern=linear.force_pattern[0], force_factor=linear.force_factor[:, 0])
    one = backlash_periodic_orbit(BacklashSystem(single, system.mesh_vector, system.deviation, system.backlash),
                                  substeps=16, tolerance=1e-12)
    silent = PiecewiseLinearSystem(
        mass=linear.mass, stiffness=linear.stiffness, damping=linear.damping, force=linear.force, nodes=linear.nodes,
        stiffness_pattern=linear.stiffness_pattern, stiffness_factor=linear.stiffness_factor * [1.0, 0.0],
        damping_pattern=linear.damping_pattern, damping_factor=linear.damping_factor * [1.0, 0.0],
        force_pattern=linear.force_pattern, force_factor=linear.force_factor * [1.0, 0.0])
    zone = MeshZone(linear.force_pattern[1], 1, system.dead_zones[0].deviation, 0.4)
    two = backlash_periodic_orbit(BacklashSystem(silent, system.mesh_vector, system.deviation, system.backlash,
                                                 (zone,)), substeps=16, tolerance=1e-12)
    assert one.converged and two.converged and one.free_flight_time > 0.0
    np.testing.assert_allclose(two.initial_state, one.initial_state, rtol=0.0,
                               atol=1e-10 * np.abs(one.initial_state).max())


# ------------------------------------------------------------------------------- the train's drivetrain responses
def _damped_reducer_document(**changes) -> dict:
    """The coarse nonlinear reducer with shaft damping raised (β = 2e-5 s, as the linear train's solve_ivp check) so
    that a motion from rest settles within a few common periods, 3 kHz cut-off."""
    document = _nonlinear_reducer_document(**changes)
    document["drivetrain"]["response_cutoff_hz"] = 3000.0
    for shaft in document["drivetrain"]["shafts"]:
        shaft["material_damping_s"] = 2e-5
    return document


@lru_cache(maxsize=None)
def _damped_reducer():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return case_drivetrain(case_from_document(_damped_reducer_document()), ("elastic",))


@pytest.mark.slow
def test_the_motion_of_the_train_from_rest_converges_onto_its_backlash_orbit():
    """(2) From rest the train's state approaches the periodic orbit as the largest Floquet multiplier's modulus to
    the power of the periods run: after N periods within 1e-6 of the state (ρ^N ≤ 1e-8 leaves room for the start's
    distance from the orbit, a few times the orbit's own size), and each stage's Kv of the last period equals the
    orbit's."""
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
    from thermogear.drivetrain.transient_response import drivetrain_transient

    built = _damped_reducer()
    assembled, train = built.assembled("elastic"), built.mesh_states("elastic")
    orbit = drivetrain_backlash_response(assembled, train, substeps=8, samples_per_piece=4, cutoff_hz=3000.0)
    assert orbit.converged and orbit.stable and set(orbit.meshes) == {"mesh", "stage 2"}
    radius = float(np.abs(orbit.multipliers).max())
    periods = math.ceil(math.log(1e-8) / math.log(radius))
    assert periods <= 40, radius
    motion = drivetrain_transient(assembled, train, periods, backlash=True, samples_per_piece=4, substeps=8,
                                  cutoff_hz=3000.0)
    start = np.array(orbit.metrics["initial_state"])
    np.testing.assert_allclose(motion.end_state, start, rtol=0.0, atol=1e-6 * np.abs(start).max())
    assert set(motion.meshes) == {"mesh", "stage 2"}
    for name in orbit.meshes:
        assert motion.meshes[name].metrics["kv"] == pytest.approx(orbit.meshes[name].metrics["kv"], rel=1e-6)
        assert motion.meshes[name].mesh_period == pytest.approx(orbit.meshes[name].mesh_period, rel=1e-12)
    # the first stage's mesh period is a third of the common period, the second's a half (z2/g = 3, z3/g = 2)
    assert orbit.period == pytest.approx(3 * orbit.meshes["mesh"].mesh_period, rel=1e-12)
    assert orbit.period == pytest.approx(2 * orbit.meshes["stage 2"].mesh_period, rel=1e-12)


@pytest.mark.slow
def test_run_json_of_the_two_stage_reducer_with_the_nonlinear_mesh_reports_each_stage(tmp_path):
    """(4) ``run --json`` on the (coarse) two-stage set with the backlash mesh: the orbit of both models found, each
    stage with its Kv and its own contact loss; at the rated load neither mesh separates, so each stage's Kv is that
    of the linear mesh's run of the same case (the backlash orbit is the linear one, test (1))."""
    import json

    import tomli_w
    from typer.testing import CliRunner

    from thermogear.cli.app import app

    results = {}
    for mesh in ("nonlinear", "linear"):
        document = _damped_reducer_document()
        document["dynamics"]["mesh"] = mesh
        path = tmp_path / f"reducer_{mesh}.toml"
        path.write_text(tomli_w.dumps(document))
        outcome = CliRunner().invoke(app, ["run", str(path), "--json"])
        assert outcome.exit_code == 0, outcome.output
        results[mesh] = json.loads(outcome.stdout[outcome.stdout.index("{"):])["drivetrain"]
    nonlinear, linear = results["nonlinear"], results["linear"]
    assert nonlinear["backlash_mesh"] and not linear["backlash_mesh"]
    for model, values in nonlinear["models"].items():
        assert values["converged"] and values["failure"] == ""
        assert set(values["stages"]) == {"mesh", "stage 2"}
        for name, stage in values["stages"].items():
            assert stage["contact_loss_fraction"] == 0.0 and stage["back_contact_fraction"] == 0.0
            # the orbits are equal (test 1); the Kv differ only by where each samples the maximum: the backlash
            # sampling adds every extremum of δ to the 4 samples per piece the linear response takes (a peak between
            # samples is missed by ~(ω·Δt)²/8 of the dynamic part: measured 3e-6 here), so the backlash value is
            # the larger and within 1e-4
            expected = linear["models"][model]["stages"][name]["kv"]
            assert expected * (1.0 - 1e-12) <= stage["kv"] <= expected * (1.0 + 1e-4)


@pytest.mark.slow
def test_the_backlash_speed_sweep_of_the_train_stores_each_stage(tmp_path):
    """The speed sweep of the (coarse) two-stage set with the backlash mesh: every branch point found, each stage's
    Kv stored, the first stage's equal to the point's Kv (the first mesh's)."""
    import tomli_w
    import xarray as xr
    from typer.testing import CliRunner

    from thermogear.cli.app import app

    path = tmp_path / "reducer.toml"
    path.write_text(tomli_w.dumps(_damped_reducer_document()))
    store = tmp_path / "sweep.zarr"
    outcome = CliRunner().invoke(app, ["sweep", str(path), "--vary", "speed_rpm=2000:2400:2", "--out", str(store),
                                       "--json"])
    assert outcome.exit_code == 0, outcome.output
    data = xr.open_zarr(store)
    assert list(data["mesh"].values) == ["mesh", "stage 2"]
    assert bool(data["valid"].all())
    stage = data["stage_kv"].values
    assert np.all(np.isfinite(stage)) and np.all(stage >= 1.0)
    np.testing.assert_array_equal(stage[..., 0], data["kv"].values)
