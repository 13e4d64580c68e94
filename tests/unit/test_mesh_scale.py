"""Issue 38: a user's k(τ) as a mesh state (arrays and a table file through run and sweep), pieces grouped within a
tolerance (the effect bounded), the exact routes for large systems (reached coordinates, runs of equal pieces), and
the drivetrain's automatic cut-off with its error estimate."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from drivetrain_builders import geared_pair

from thermogear.errors import CaseError

PHASE = np.arange(40) / 40
STIFFNESS = np.where(PHASE < 0.55, 3.1e8, 2.0e8) * (1.0 + 0.05 * np.sin(2.0 * np.pi * PHASE))
DAMPING = np.full(PHASE.size, 800.0)


def _square_wave(speed_rpm: float, intervals: int, noise: float = 0.0, seed: int = 3):
    """Two levels on equal intervals (2.6e8 N/m over the first 60 %, 1.6e8 N/m after), optionally scattered."""
    from thermogear.mesh.state import mesh_state_from_arrays

    phase = np.arange(intervals) / intervals
    stiffness = np.where(phase < 0.6 - 1e-12, 2.6e8, 1.6e8)
    damping = np.full(intervals, 1200.0)
    if noise:
        generator = np.random.default_rng(seed)
        stiffness = stiffness * (1.0 + noise * generator.uniform(-1.0, 1.0, intervals))
        damping = damping * (1.0 + noise * generator.uniform(-1.0, 1.0, intervals))
    return mesh_state_from_arrays(phase, stiffness, damping=damping, speed_rpm=speed_rpm, pinion_teeth=20,
                                  normal_load=3000.0, mass=1.0, backlash=1e-4)


# ------------------------------------------------------------------------------------------- mesh state from arrays
def test_arrays_give_the_state_every_solver_takes():
    from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
    from thermogear.mesh.state import mesh_state_from_arrays

    j1, j2, r1, r2 = 4e-3, 9e-3, 0.0381, 0.0493
    state = mesh_state_from_arrays(PHASE, STIFFNESS, damping=DAMPING, deviation=np.full(PHASE.size, 2e-6),
                                   speed_rpm=1500.0, pinion_teeth=20, normal_load=3000.0, inertias=(j1, j2),
                                   base_radii=(r1, r2), backlash=1e-4)
    assert state.mass == pytest.approx(j1 * j2 / (j1 * r2**2 + j2 * r1**2), rel=1e-15)
    assert state.period == pytest.approx(60.0 / (20 * 1500.0), rel=1e-15)
    np.testing.assert_array_equal(state.mesh_stiffness, STIFFNESS)
    problem = state.problem()
    np.testing.assert_allclose(problem.force_per_interval, 3000.0 + STIFFNESS * 2e-6, rtol=1e-15)
    orbit = periodic_steady_state(problem, 4)
    # the static part: the mean deflection lies between the static deflections of the two levels, plus e
    assert (3000.0 / STIFFNESS.max() + 2e-6 < orbit.displacement.mean() < 3000.0 / STIFFNESS.min() + 2e-6)
    assert state.backlash_problem().backlash == 1e-4


@pytest.mark.parametrize("changes, key", [
    ({"phase": PHASE[::-1]}, "phase"), ({"stiffness": -STIFFNESS}, "stiffness"),
    ({"damping": DAMPING[:3]}, "damping"), ({"mass": None}, "mass"), ({"pinion_teeth": None}, "period"),
    ({"stiffness": np.where(PHASE > 0.5, np.nan, STIFFNESS)}, "stiffness")])
def test_bad_arrays_are_refused_by_name(changes, key):
    from thermogear.mesh.state import mesh_state_from_arrays

    arguments = {"phase": PHASE, "stiffness": STIFFNESS, "damping": DAMPING, "speed_rpm": 1500.0,
                 "pinion_teeth": 20, "normal_load": 3000.0, "mass": 1.0} | changes
    with pytest.raises(CaseError) as error:
        mesh_state_from_arrays(**arguments)
    assert error.value.key == key


def _table_case(folder: Path, rows: list[str], header: str = "phase [-],stiffness [N/m],damping [N*s/m]") -> Path:
    from thermogear.case import parameter_set_path

    text = parameter_set_path("luo2019").read_text(encoding="utf-8")
    text = text.replace("points_per_period = 1024", "points_per_period = 1024\nmesh_table = \"k.csv\"")
    (folder / "k.csv").write_text("\n".join([header, *rows]) + "\n", encoding="utf-8")
    path = folder / "case.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _rows(stiffness_unit_factor: float = 1.0) -> list[str]:
    return [f"{float(p)!r},{float(k) / stiffness_unit_factor!r},{float(c)!r}"
            for p, k, c in zip(PHASE, STIFFNESS, DAMPING)]


@pytest.mark.parametrize("rows, header, reason", [
    (["0.0,2e8,800", "0.5,-1e8,800"], None, "positive stiffness"),
    (["0.0,2e8,800", "0.5,2e8,800", "0.4,2e8,800"], None, "does not increase"),
    (["0.1,2e8,800"], None, "first phase"),
    (["0.0,2e8,800", "1.0,2e8,800"], None, "last phase"),
    (["0.0,2e8,800"], "phase [-],stiffness,damping [N*s/m]", "units must be named"),
    (["0.0,2e8,800"], "phase [-],stiffness [kN],damping [N*s/m]", "stiffness in [kN]"),
    (["0.0,abc,800"], None, "row 2")])
def test_a_bad_table_is_refused_when_the_case_loads(tmp_path, rows, header, reason):
    from thermogear.case import load_case

    path = _table_case(tmp_path, rows, *([header] if header else []))
    with pytest.raises(CaseError) as error:
        load_case(path)
    assert error.value.key == "dynamics.mesh_table" and error.value.value == "k.csv"
    assert reason in str(error.value)


def _python_metrics(case, speed_rpm: float) -> dict:
    """The same k(τ) built in Python at the case's operating point, solved as run solves it."""
    from thermogear.dynamics.solvers import PeriodicSolver
    from thermogear.mesh.model import MeshModel
    from thermogear.mesh.state import mesh_state_from_arrays

    model = MeshModel(case, "elastic")
    state = mesh_state_from_arrays(PHASE, STIFFNESS, damping=DAMPING, speed_rpm=speed_rpm,
                                   normal_load=model.normal_load(speed_rpm), mass=case.equivalent_mass,
                                   period=model.mesh_period(speed_rpm), face_width=model.face_width)
    solver = PeriodicSolver(case.dynamics.samples_per_interval)
    return solver.solve(state.problem(), include_damping_force=case.dynamics.include_damping_force).metrics


@pytest.mark.slow
def test_a_table_in_a_case_runs_and_sweeps_as_the_same_arrays_in_python(tmp_path):
    import xarray as xr
    from typer.testing import CliRunner

    import thermogear.cli.run  # noqa: F401
    import thermogear.cli.sweep  # noqa: F401
    from thermogear.case import load_case
    from thermogear.cli.app import app

    # the stiffness in N/um: the table's units are converted on reading
    path = _table_case(tmp_path, _rows(1e6), "phase [-],stiffness [N/um],damping [N*s/m]")
    case = load_case(path)
    result = CliRunner().invoke(app, ["run", str(path), "--json", "--model", "elastic"])
    assert result.exit_code == 0, result.output
    models = json.loads(result.stdout[result.stdout.index("{"):])["models"]
    expected = _python_metrics(case, case.operating_point.speed_rpm)
    assert models["elastic"]["kv"] == pytest.approx(expected["kv"], rel=1e-12)
    assert models["elastic"]["dte_peak_to_peak_um"] == pytest.approx(expected["dte_peak_to_peak"] * 1e6, rel=1e-12)
    store = tmp_path / "study.zarr"
    result = CliRunner().invoke(app, ["sweep", str(path), "--vary", "speed_rpm=1500,3000", "--out", str(store),
                                      "--model", "elastic", "--scheduler", "serial"])
    assert result.exit_code == 0, result.output
    data = xr.open_zarr(store)
    kv = np.asarray(data["kv"]).ravel()
    for speed, value in zip((1500.0, 3000.0), kv):
        assert value == pytest.approx(_python_metrics(case, speed)["kv"], rel=1e-12)


# ------------------------------------------------------------------------------------------- pieces within a tolerance
def test_grouping_is_exact_at_zero_and_merges_only_within_the_tolerance():
    from thermogear.dynamics.linear_algebra.piece_groups import group_rows

    rows = np.array([[1.0, 2.0], [1.0, 2.0 + 1e-12], [1.0, 3.0], [1.0, 2.0]])
    distinct, where = group_rows(rows, 0.0)
    assert distinct.shape[0] == 3 and where[0] == where[3] != where[1]
    distinct, where = group_rows(rows, 1e-9)
    assert distinct.shape[0] == 2 and where[0] == where[1] == where[3] != where[2]
    np.testing.assert_allclose(distinct[where], rows, rtol=0.0, atol=1e-9 * 3.0)
    # a chain of small steps is cut where it spans more than the tolerance: no drift through a group
    chain = np.column_stack([np.ones(50), 1.0 + np.arange(50) * 0.4e-9])
    distinct, where = group_rows(chain, 1e-9)
    assert np.abs(distinct[where] - chain).max() <= 1e-9 * chain.max()


def test_a_scattered_table_gives_the_clean_result_within_the_bound():
    from thermogear.drivetrain.response import drivetrain_periodic_system
    from thermogear.dynamics.linear_algebra.piece_groups import grouping_bound
    from thermogear.dynamics.periodic_orbits.periodic_ndof import _piece_steps, periodic_response

    assembled = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2).assemble()
    mesh = assembled.mesh_vectors
    for noise, tolerance in ((3e-13, 1e-9), (2e-5, 1e-4)):
        clean_system, reduction = drivetrain_periodic_system(assembled, _square_wave(3000.0, 200))
        noisy_system, _ = drivetrain_periodic_system(assembled, _square_wave(3000.0, 200, noise))
        assert _piece_steps(noisy_system, 1, tolerance)[0].shape[0] == 2  # two levels: two exponentials
        assert _piece_steps(noisy_system, 1, 0.0)[0].shape[0] == 200
        w = reduction.project_vector(mesh[0])
        clean = periodic_response(clean_system, 2, 0.0)
        noisy = periodic_response(noisy_system, 2, tolerance)
        delta, rate = clean.displacement @ w, clean.velocity @ w
        change = np.abs(noisy.displacement @ w - delta).max() / np.abs(delta).max()
        # the dynamic amplification of the mesh mode, 1/(2ζ), from the time means of c and k and the mesh mass
        problem = _square_wave(3000.0, 200).problem()
        mass = 1.0 / (w @ np.linalg.solve(clean_system.mass, w))
        zeta = problem.time_mean(problem.damping) / (2.0 * math.sqrt(problem.mean_stiffness * mass))
        bound = grouping_bound(tolerance + noise, np.diff(clean_system.nodes), clean_system.stiffness_factor,
                               clean_system.damping_factor, clean_system.force_factor, delta, rate, 0.5 / zeta)
        assert change <= bound
        if noise > 1e-6:  # the scatter itself moves the result measurably: the bound is not vacuous
            assert change > 1e-3 * bound


def test_the_run_route_and_the_reached_coordinates_are_exact():
    from thermogear.drivetrain.response import drivetrain_periodic_system
    from thermogear.dynamics.periodic_orbits import periodic_ndof
    from thermogear.dynamics.periodic_orbits.periodic_runs import by_runs, reached_coordinates

    assembled = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=2).assemble()
    system, _ = drivetrain_periodic_system(assembled, _square_wave(3000.0, 40))
    reached = reached_coordinates(system)
    assert 0 < reached.sum() < system.size  # the axial DOFs are never loaded by a spur mesh
    on_reached = periodic_ndof.periodic_response(system, 4, 0.0)  # runs of equal pieces, reached coordinates
    distinct, where = periodic_ndof._piece_steps(system, 4, 0.0)
    blocks = periodic_ndof._by_blocks(system, distinct, where, 4)  # every coordinate, blocks of pieces
    starts = np.flatnonzero(np.diff(where, prepend=-1))
    runs = periodic_ndof.PeriodicResponse(*by_runs(system, distinct, where, starts, 4))  # every coordinate, runs
    scale = np.abs(blocks.displacement).max()
    for other in (runs, on_reached):
        assert np.abs(other.displacement - blocks.displacement).max() <= 1e-10 * scale
        np.testing.assert_allclose(np.sort(np.abs(other.multipliers)), np.sort(np.abs(blocks.multipliers)),
                                   atol=1e-10)


# ------------------------------------------------------------------------------------------- cut-off and its estimate
def test_automatic_cutoff_and_its_error_estimate():
    from thermogear.drivetrain.cutoff import cutoff_for_harmonics, drivetrain_cutoff_sweep
    from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_speed_sweep

    assembled = geared_pair(bearing_damping=2e3, material_damping=1e-6, elements=4).assemble()
    states = [_square_wave(speed, 5) for speed in (2000.0, 3000.0)]
    assert cutoff_for_harmonics(1000.0, 5) == 20_000.0
    swept = drivetrain_cutoff_sweep(assembled, states, harmonics=2, factor=2.0)
    cutoff = swept[0].error.cutoff_hz
    assert cutoff == pytest.approx(4.0 * states[-1].mesh_frequency_hz)
    shared = drivetrain_speed_sweep(assembled, states, 8, cutoff)  # the same cut-off, matrices projected per speed
    for result, other, state in zip(swept, shared, states):
        scale = np.ptp(other.transmission_error)
        assert np.abs(result.response.transmission_error - other.transmission_error).max() <= 1e-9 * scale
        full = drivetrain_periodic_response(assembled, state)
        error = np.abs(result.response.transmission_error - full.transmission_error).max() / scale
        # the estimate has the size of the true error (within a factor 3 either way) and is not rounding
        assert error / 3.0 <= result.error.transmission_error <= 3.0 * error and error > 1e-8
