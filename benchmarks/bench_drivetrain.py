"""Benchmark: drivetrain modes and the exact periodic response of a geared drivetrain, against baselines in the
same run, on one BLAS thread.

Run: python benchmarks/bench_drivetrain.py [--quick]
Prints a table and writes benchmarks/results/bench_drivetrain.json.

Figures:

1. modes of a ~100-DOF geared two-shaft drivetrain (``drivetrain_modes``: rigid-mode reduction, symmetric
   eigenproblem, labels, strain-energy shares) in ms, against the bare ``scipy.linalg.eigh(K, M)`` of the same full
   matrices (ratio: times slower than the bare solve).
2. the exact periodic response of a ~50-DOF drivetrain to a square-wave mesh period (3 pieces; monodromy by
   augmented expm, 8 samples per piece, bearing forces, metrics) in ms per speed, against ``solve_ivp`` (DOP853,
   restarted at every node) run from rest on the same reduced system for as many periods as it needs to agree with
   the periodic state to 1e-6 relative (the count is measured).
   The Newmark average-acceleration reference (``dynamics/transients/newmark.py``, 64 steps per piece) run from rest to
   a steady state (period ends agreeing to 1e-6) on the same system is a second baseline; its distance to the exact
   orbit is printed.
3. the same drivetrain fed by the luo2019 thermal mesh state (1024 grid intervals, as many pieces, 1024 distinct
   stiffnesses: the thermal k(τ) varies along the path): ms per speed on every DOF, and reduced to the excited modes
   below 20 kHz plus the static corrections (``cutoff_hz``; its DTE difference from the full solution is printed),
   each against the same solution with the full Taylor exponential of every piece (the route before the rank-1
   update exponentials, ``old_route``), interleaved, wall and CPU time; and against the 1-DOF periodic solver.
4. a square-wave mesh (two stiffness levels) on 1024 equal intervals, reduced: ms per speed with the exponentials
   of the distinct pieces and the products of repeated blocks taken once, against figure 3's reduced luo2019 state
   (1024 distinct pieces) on the same grid size, interleaved.
5. a sweep of the reduced solver over pinion speeds, each with its own thermal mesh state (``MeshModel.state``,
   included): seconds for 1000 speeds (timed on ``SWEEP_SAMPLE`` speeds and scaled), ``drivetrain_speed_sweep``
   (rigid-body reduction and modal basis shared) against one ``drivetrain_periodic_response`` per speed on
   ``old_route`` (as before), interleaved, wall and CPU; and against the 1-DOF sweep.

The machine these numbers come from may be loaded: CPU time (user + sys of this process) is printed beside wall.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core, as the targets; oversubscribed BLAS threads cost 100×

import json  # noqa: E402
import math  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

import contextlib  # noqa: E402

import numpy as np  # noqa: E402
from timing import wall_times  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
TOLERANCE = 1e-6
CUTOFF_HZ = 2e4
SWEEP_SAMPLE = 40


@contextlib.contextmanager
def old_route():
    """Every piece's exponential by the full Taylor polynomial, as before the rank-update exponentials (the
    dispatch threshold raised past any piece count)."""
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic_ndof

    saved = periodic_ndof._RANK_ROUTE_PIECES
    periodic_ndof._RANK_ROUTE_PIECES = sys.maxsize
    try:
        yield
    finally:
        periodic_ndof._RANK_ROUTE_PIECES = saved


def _old(function):
    def run():
        with old_route():
            return function()
    return run


def interleaved(new, old, repeat: int) -> dict:
    """Median wall and CPU seconds of ``new`` and ``old`` called alternately ``repeat`` times each."""
    times = {"new": [], "old": []}
    for _ in range(repeat):
        for name, function in (("new", new), ("old", old)):
            wall, cpu = time.perf_counter(), time.process_time()
            function()
            times[name].append((time.perf_counter() - wall, time.process_time() - cpu))
    return {name: np.median(np.array(values), axis=0) for name, values in times.items()}


def _figure(name: str, timed: dict, unit_scale: float, unit: str) -> dict:
    new_wall, new_cpu = timed["new"] * unit_scale
    old_wall, old_cpu = timed["old"] * unit_scale
    return {"name": name, "value": float(new_wall), "baseline": float(old_wall), "unit": unit,
            "ratio": float(old_wall / new_wall), "cpu": float(new_cpu), "baseline_cpu": float(old_cpu),
            "cpu_ratio": float(old_cpu / new_cpu)}



def _drivetrain(elements: int, pinion_radius: float = 0.0381, wheel_radius: float = 0.0493):
    """Two 0.2 m steel shafts (d = 40 mm), gear at mid-span, two bearings each (2e8 N/m, 2 kN·s/m)."""
    from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation, RigidDisk,
                                       Shaft, ShaftSegment)

    steel = Material(youngs_modulus=206e9, density=7850.0, poisson_ratio=0.3)
    shafts = tuple(Shaft(name, (ShaftSegment(0.2, CrossSection(0.04), steel),), 0.2 / elements * (1 + 1e-12),
                         material_damping=1e-6) for name in ("pinion shaft", "wheel shaft"))
    pinion, wheel = NodeLocation("pinion shaft", 0.1), NodeLocation("wheel shaft", 0.1)
    disks = (RigidDisk.annulus("pinion", pinion, 7850.0, 0.02, 2 * pinion_radius / math.cos(math.radians(20)), 0.04),
             RigidDisk.annulus("wheel", wheel, 7850.0, 0.02, 2 * wheel_radius / math.cos(math.radians(20)), 0.04))
    bearings = tuple(Bearing(f"{s} {e}", NodeLocation(s, z), 2e8, 2e8, 1e9, 2e3, 2e3, 2e3)
                     for s in ("pinion shaft", "wheel shaft") for e, z in (("A", 0.0), ("B", 0.2)))
    mesh = GearMesh("mesh", pinion, wheel, pinion_radius, wheel_radius, math.radians(20.0), 2.2e8)
    return Drivetrain(shafts, disks, bearings, meshes=(mesh,))


def _square_wave_state(speed_rpm: float, intervals: int = 3):
    """A two-pair square-wave mesh period (contact ratio 1.6 on 3 pieces; on ``intervals`` equal intervals the
    second pair is in contact over the first 60 %), as a mesh model would hand it over."""
    from thermogear.mesh.state import MeshState
    from thermogear.geometry.mesh_cycle import MeshGrid

    period = 60.0 / (20 * speed_rpm)
    if intervals == 3:
        nodes = np.array([0.0, 0.3 * period, 0.6 * period, period])
        in_contact = np.array([[True, True, True], [True, True, False]])
        stiffness = np.array([[1.9e8, 2.1e8, 2.7e8], [2.0e8, 1.8e8, 0.0]])
        damping = np.array([[900.0, 1000.0, 1500.0], [1000.0, 900.0, 0.0]])
    else:
        nodes = np.linspace(0.0, period, intervals + 1)
        double = 0.5 * (nodes[1:] + nodes[:-1]) < 0.6 * period
        in_contact = np.array([np.ones(intervals, dtype=bool), double])
        stiffness = np.where(in_contact, 2.0e8, 0.0) + np.where(double, 0.0, 0.7e8) * in_contact[0]
        damping = np.where(in_contact, 1000.0, 0.0)
    grid = MeshGrid(nodes=nodes, midpoints=0.5 * (nodes[1:] + nodes[:-1]), roll=np.zeros(in_contact.shape),
                    in_contact=in_contact, contact_count=in_contact.sum(axis=0))
    return MeshState(model="square wave", speed_rpm=speed_rpm, normal_load=3000.0, mass=1.0, grid=grid,
                     pair_stiffness=stiffness, pair_damping=damping, mesh_damping=damping.sum(axis=0),
                     pair_deviation=np.zeros(in_contact.shape), pair_engaged=in_contact,
                     static_transmission_error=None, backlash=None, face_width=0.02, mesh_frequency_hz=1.0 / period)


def _solve_ivp_periods(system, initial_state, limit: int = 2000) -> tuple[int, float]:
    """Periods of solve_ivp from rest until the state at a period's end matches the periodic state to TOLERANCE,
    and the seconds it took."""
    from scipy.integrate import solve_ivp

    n = system.size
    inverse = np.linalg.inv(system.mass)
    fields = []
    for piece in range(system.nodes.size - 1):
        stiffness, damping, force = system.piece(piece)
        matrix = np.block([[np.zeros((n, n)), np.eye(n)], [-inverse @ stiffness, -inverse @ damping]])
        load = np.concatenate([np.zeros(n), inverse @ force])
        fields.append(lambda t, z, a=matrix, b=load: a @ z + b)
    scale = np.abs(initial_state[:n]).max()
    state = np.zeros(2 * n)
    start = time.perf_counter()
    for period in range(1, limit + 1):
        for piece, field in enumerate(fields):
            state = solve_ivp(field, (system.nodes[piece], system.nodes[piece + 1]), state, method="DOP853",
                              rtol=1e-10, atol=1e-12 * scale).y[:, -1]
        if np.abs(state[:n] - initial_state[:n]).max() < TOLERANCE * scale:
            return period, time.perf_counter() - start
    raise RuntimeError(f"solve_ivp did not reach the periodic state to {TOLERANCE} in {limit} periods")


def main(quick: bool = False) -> dict:
    warnings.simplefilter("ignore")
    from scipy.linalg import eigh

    from thermogear.drivetrain.modes import drivetrain_modes
    from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_periodic_system
    from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
    from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response

    figures = []
    # ---------------------------------------------------------------- 1. modes of ~100 DOF
    large = _drivetrain(elements=8).assemble()
    drivetrain_modes(large)
    modes_s = wall_times(lambda: drivetrain_modes(large), 5 if quick else 30)
    stiffness = large.stiffness()
    bare_s = wall_times(lambda: eigh(stiffness, large.mass), 5 if quick else 30)
    modes_ms, bare_ms = float(np.median(modes_s)) * 1e3, float(np.median(bare_s)) * 1e3
    figures.append({"name": f"drivetrain modes, {large.size} DOF (labels, energy shares) vs bare eigh",
                    "value": modes_ms, "baseline": bare_ms, "unit": "ms", "ratio": modes_ms / bare_ms})

    # ---------------------------------------------------------------- 2. periodic response of ~50 DOF
    small = _drivetrain(elements=3).assemble()
    state = _square_wave_state(3000.0)
    drivetrain_periodic_response(small, state)
    response_s = wall_times(lambda: drivetrain_periodic_response(small, state), 5 if quick else 30)
    system, _ = drivetrain_periodic_system(small, state)
    orbit = periodic_response(system, 1)
    periods, ivp_s = _solve_ivp_periods(system, orbit.initial_state)
    response_ms = float(np.median(response_s)) * 1e3
    figures.append({"name": f"exact periodic response, {small.size} DOF, 3 pieces, per speed vs solve_ivp from "
                            f"rest to 1e-6 ({periods} periods)",
                    "value": response_ms, "baseline": ivp_s * 1e3, "unit": "ms per speed",
                    "ratio": ivp_s * 1e3 / response_ms})
    from thermogear.dynamics.transients.newmark import newmark_steady_state

    start = time.perf_counter()
    newmark = newmark_steady_state(system, steps_per_piece=64, tolerance=TOLERANCE)
    newmark_s = time.perf_counter() - start
    exact = periodic_response(system, 64).displacement
    distance = float(np.abs(newmark.displacement - exact).max() / np.abs(exact).max())
    figures.append({"name": f"exact periodic response, {small.size} DOF, 3 pieces, per speed vs Newmark (64 steps "
                            f"per piece, {newmark.periods} periods to 1e-6, {distance:.1e} from the exact orbit)",
                    "value": response_ms, "baseline": newmark_s * 1e3, "unit": "ms per speed",
                    "ratio": newmark_s * 1e3 / response_ms})

    # ---------------------------------------------------------------- 3. the luo2019 mesh state as pieces
    from thermogear.case import load_case
    from thermogear.mesh.model import MeshModel

    real_state = MeshModel(load_case("luo2019"), "thermal").state()
    full_run = lambda: drivetrain_periodic_response(small, real_state, samples_per_piece=1)  # noqa: E731
    full_timed = interleaved(full_run, _old(full_run), 1 if quick else 3)
    one_dof_s = wall_times(lambda: periodic_steady_state(real_state.problem(), samples_per_interval=1), 5)
    pieces = real_state.grid.nodes.size - 1
    figures.append(_figure(f"exact periodic response, {small.size} DOF, luo2019 state ({pieces} pieces) vs every "
                           "piece's full exponential", full_timed, 1e3, "ms per speed"))
    real_ms, one_dof_ms = full_timed["new"][0] * 1e3, float(np.median(one_dof_s)) * 1e3
    figures.append({"name": f"exact periodic response, {small.size} DOF, luo2019 state vs the 1-DOF periodic solver",
                    "value": real_ms, "baseline": one_dof_ms, "unit": "ms per speed", "ratio": real_ms / one_dof_ms})
    full_real = full_run()
    reduced_run = lambda: drivetrain_periodic_response(small, real_state, samples_per_piece=1,  # noqa: E731
                                                       cutoff_hz=CUTOFF_HZ)
    reduced = reduced_run()
    difference = float(np.abs(reduced.transmission_error - full_real.transmission_error).max()
                       / np.abs(full_real.transmission_error).max())
    with old_route():
        old_reduced = reduced_run()
    routes = float(np.abs(reduced.transmission_error - old_reduced.transmission_error).max()
                   / np.abs(old_reduced.transmission_error).max())
    reduced_timed = interleaved(reduced_run, _old(reduced_run), 3 if quick else 15)
    figures.append(_figure(f"reduced periodic response (modes < {CUTOFF_HZ:.0f} Hz + static corrections, DTE "
                           f"{difference:.1e} from the full one; routes differ by {routes:.1e}), luo2019 state, vs "
                           "every piece's full exponential", reduced_timed, 1e3, "ms per speed"))

    # ---------------------------------------------------------------- 4. a square wave on 1024 intervals
    square = _square_wave_state(3000.0, intervals=1024)
    square_run = lambda: drivetrain_periodic_response(small, square, samples_per_piece=1,  # noqa: E731
                                                      cutoff_hz=CUTOFF_HZ)
    square_timed = interleaved(square_run, reduced_run, 3 if quick else 15)
    distinct = len({(w, k) for w, k in zip(np.diff(square.grid.nodes), square.problem().stiffness)})
    figures.append(_figure(f"reduced periodic response, square-wave mesh on 1024 intervals ({distinct} distinct "
                           "pieces: each exponential and each repeated block product taken once), vs the luo2019 "
                           "state's 1024 distinct pieces", square_timed, 1e3, "ms per speed"))

    # ---------------------------------------------------------------- 5. a 1000-speed sweep
    from thermogear.drivetrain.response import drivetrain_speed_sweep

    model = MeshModel(load_case("luo2019"), "thermal")
    sweep_speeds = np.linspace(500.0, 6000.0, 4 if quick else SWEEP_SAMPLE)

    def sweep() -> None:
        drivetrain_speed_sweep(small, [model.state(speed_rpm=speed) for speed in sweep_speeds], samples_per_piece=1,
                               cutoff_hz=CUTOFF_HZ)

    def sweep_per_speed() -> None:
        for speed in sweep_speeds:
            drivetrain_periodic_response(small, model.state(speed_rpm=speed), samples_per_piece=1,
                                         cutoff_hz=CUTOFF_HZ)

    def sweep_one_dof() -> None:
        for speed in sweep_speeds:
            periodic_steady_state(model.state(speed_rpm=speed).problem(), samples_per_interval=1)

    sweep_timed = interleaved(sweep, _old(sweep_per_speed), 1 if quick else 2)
    figures.append(_figure(f"1000-speed sweep, reduced {small.size}-DOF drivetrain, thermal state per speed (timed on "
                           f"{sweep_speeds.size}), shared basis vs one call per speed on every piece's exponential",
                           sweep_timed, 1000 / sweep_speeds.size, "s"))
    per_speed = sweep_timed["new"][0] / sweep_speeds.size
    per_speed_one_dof = float(wall_times(sweep_one_dof, 1)[0]) / sweep_speeds.size
    figures.append({"name": f"1000-speed sweep, reduced {small.size}-DOF drivetrain vs the 1-DOF sweep",
                    "value": 1000 * per_speed, "baseline": 1000 * per_speed_one_dof, "unit": "s",
                    "ratio": per_speed / per_speed_one_dof})

    result = {"figures": figures, "python": platform.python_version(), "machine": platform.machine(),
              "quick": quick}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_drivetrain.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    for figure in figures:
        cpu = (f"; CPU {figure['cpu']:.3g} vs {figure['baseline_cpu']:.3g}, ratio {figure['cpu_ratio']:.3g}"
               if "cpu" in figure else "")
        print(f"{figure['name']}: {figure['value']:.3g} {figure['unit']} (baseline {figure['baseline']:.3g}, "
              f"ratio {figure['ratio']:.3g}{cpu})")
    return result


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
