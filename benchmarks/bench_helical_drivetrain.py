"""Benchmark: the drivetrain's modes and periodic response with a helical mesh (β = 15°, spread contact) against the
same drivetrain with the spur mesh (β = 0, point contact), in the same run, on one BLAS thread.

The drivetrain is docs/drivetrain.md's two-shaft rotor (~130 DOF); both meshes are fed the same kind of mesh state
(the helical one the slice model's K_t, the spur one the spur pair's k(τ) — the helical state at β = 0) over the
same number of intervals, solved on the modes up to 30 kHz plus the static corrections. Interleaved repeats; the
median of each is compared, in wall and in CPU time (the machine may be loaded). The issue's target: helical within
1.5× of the spur one.

A third case, "spur element, helical state", feeds the helical K_t(τ) to the spur element (β = 0, point contact):
helical over it is the cost of the element alone (mesh vector and tilting terms); it over spur is the cost of the
helical mesh state (a K_t that varies on every interval, where the spur k(τ) repeats few distinct values whose
exponentials the solver takes once).

Run: python benchmarks/bench_helical_drivetrain.py [--quick]
Writes benchmarks/results/bench_helical_drivetrain.json.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import json  # noqa: E402
import math  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from thermogear.drivetrain import (Bearing, CrossSection, Drivetrain, GearMesh, Material, NodeLocation,  # noqa: E402
                                   RigidDisk, Shaft, ShaftSegment)
from thermogear.drivetrain.mesh_contact import MESH_CONTACTS  # noqa: E402
from thermogear.drivetrain.modes import drivetrain_modes  # noqa: E402
from thermogear.drivetrain.response import drivetrain_periodic_response  # noqa: E402
from thermogear.helical.geometry import HelicalPair  # noqa: E402
from thermogear.materials import Material as GearMaterial  # noqa: E402
from thermogear.mesh.helical_state import helical_mesh_state  # noqa: E402

STEEL = Material(youngs_modulus=206e9, density=7850.0, poisson_ratio=0.3)


def case(helix_deg: float, contact: str, points: int):
    """(assembled drivetrain, mesh state) of the two-shaft rotor with a 27/35 pair of helix ``helix_deg``."""
    helical = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(helix_deg), 20e-3,
                                 bore_radii=(18e-3, 25e-3))
    transverse = helical.transverse
    pinion_at, wheel_at = NodeLocation("pinion shaft", 0.125), NodeLocation("wheel shaft", 0.150)
    shafts = (Shaft("pinion shaft", (ShaftSegment(0.25, CrossSection(0.036), STEEL),), 0.0125, material_damping=1e-8),
              Shaft("wheel shaft", (ShaftSegment(0.30, CrossSection(0.05), STEEL),), 0.0125, material_damping=1e-8))
    gears = (RigidDisk.annulus("pinion", pinion_at, 7850.0, 0.02, 2 * transverse.operating_pitch_radii[0], 0.036),
             RigidDisk.annulus("wheel", wheel_at, 7850.0, 0.02, 2 * transverse.operating_pitch_radii[1], 0.05))
    damped = dict(damping_x=2500.0, damping_y=2500.0, damping_z=1250.0)
    bearings = (Bearing("pA", NodeLocation("pinion shaft", 0.0), 2e8, 2.5e8, stiffness_z=1e8, **damped),
                Bearing("pB", NodeLocation("pinion shaft", 0.25), 2e8, 2.5e8, **damped),
                Bearing("wA", NodeLocation("wheel shaft", 0.0), 3e8, 3e8, stiffness_z=1e8, **damped),
                Bearing("wB", NodeLocation("wheel shaft", 0.30), 3e8, 3e8, **damped))
    state = helical_mesh_state(helical, GearMaterial(), 1500.0, 150.0, (gears[0].polar_inertia,
                                                                      gears[1].polar_inertia), points, 0.05)
    mesh = GearMesh("mesh", pinion_at, wheel_at, transverse.pinion.base_radius, transverse.wheel.base_radius,
                    transverse.operating_pressure_angle, state.mean_mesh_stiffness, float(state.mesh_damping.mean()),
                    base_helix_angle=helical.base_helix_angle, contact=MESH_CONTACTS[contact],
                    face_width=helical.face_width)
    return Drivetrain(shafts, gears, bearings, meshes=(mesh,)).assemble(), state


def main(quick: bool = False) -> dict:
    points, repeat = (128, 3) if quick else (512, 7)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cases = {"spur": case(0.0, "point", points), "helical": case(15.0, "spread", points)}
        cases["spur element, helical state"] = (case(0.0, "point", points)[0], cases["helical"][1])
    kinds = ("modes", "periodic")
    timings = {name: {f"{kind} {clock}": [] for kind in kinds for clock in ("wall", "cpu")} for name in cases}
    for _ in range(repeat):  # interleaved
        for name, (assembled, state) in cases.items():
            for kind, run in (("modes", lambda: drivetrain_modes(assembled, count=12)),
                              ("periodic", lambda: drivetrain_periodic_response(assembled, state, cutoff_hz=30e3))):
                wall, cpu = time.perf_counter(), time.process_time()
                run()
                timings[name][f"{kind} wall"].append(time.perf_counter() - wall)
                timings[name][f"{kind} cpu"].append(time.process_time() - cpu)
    medians = {name: {key: float(np.median(values)) for key, values in items.items()}
               for name, items in timings.items()}
    ratios = {f"{over}/{under}": {key: medians[over][key] / medians[under][key] for key in medians[under]}
              for over, under in (("helical", "spur"), ("helical", "spur element, helical state"),
                                  ("spur element, helical state", "spur"))}
    result = {"dofs": cases["spur"][0].size, "intervals": points, "repeat": repeat, "median_s": medians,
              "ratios": ratios, "target_helical_over_spur": 1.5, "python": sys.version.split()[0],
              "machine": platform.machine()}
    print(f"{result['dofs']} DOF, {points} intervals, median of {repeat} (ms, wall / CPU)")
    for name in cases:
        print(f"{name:>30}: " + "  ".join(f"{kind} {1e3 * medians[name][kind + ' wall']:7.1f} / "
                                           f"{1e3 * medians[name][kind + ' cpu']:7.1f}" for kind in kinds))
    for label, values in ratios.items():
        print(f"{label:>45}: " + "  ".join(f"{key} {value:.2f}" for key, value in values.items()))
    out = Path(__file__).resolve().parent / "results" / "bench_helical_drivetrain.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(result, indent=2), encoding="utf-8")
    return result


if __name__ == "__main__":
    main("--quick" in sys.argv)
