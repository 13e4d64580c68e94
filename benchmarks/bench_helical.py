"""Benchmark: the mesh stiffness of a helical pair over one mesh period (the slice model integrated exactly over the face, normal
section) against the spur pair's (the mesh model's primitives: one pair-stiffness table, the pairs in contact
summed), both cold (the PEM tables computed) and warm (the tables cached), in the same run.

Run: python benchmarks/bench_helical.py [POINTS]
Writes benchmarks/results/bench_helical.json. The issue's target: helical ≤ 10× the spur cost.
"""

from __future__ import annotations

import json
import math
import platform
import sys
import warnings
from pathlib import Path

import numpy as np

from thermogear.helical.geometry import HelicalPair
from thermogear.helical.slices import helical_mesh_stiffness
from thermogear.materials import Material
from thermogear.mesh_cycle import MeshCycle
from thermogear.stiffness import table
from thermogear.stiffness.table import pair_stiffness_at
from timing import wall_times

STEEL = Material()


def spur_period(pair, points: int) -> np.ndarray:
    grid = MeshCycle(pair, 1000.0).grid(points)
    per_pair = np.zeros(grid.roll.shape)
    end = pair.path_points["E"]
    per_pair[grid.in_contact] = pair_stiffness_at(pair, STEEL, np.minimum(grid.roll[grid.in_contact], end))
    return MeshCycle.total(per_pair, grid.in_contact)


def helical_period(helical, points: int) -> np.ndarray:
    phase = np.linspace(0.0, helical.transverse_base_pitch, points, endpoint=False)
    return helical_mesh_stiffness(helical, STEEL, phase).stiffness


def cold(function):
    def run():
        table._table_with_warnings.cache_clear()
        table._spline_set.cache_clear()
        function()
    return run


def main(points: int = 1024) -> dict:
    warnings.simplefilter("ignore")
    spur = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), 0.0, 25e-3, bore_radii=(15e-3, 20e-3)).transverse
    helical = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(15.0), 25e-3,
                                 bore_radii=(15e-3, 20e-3))
    rows = {}
    for label, wrap in (("cold", cold), ("warm", lambda function: function)):
        spur_times = wall_times(wrap(lambda: spur_period(spur, points)), 5)
        helical_times = wall_times(wrap(lambda: helical_period(helical, points)), 5)
        rows[label] = {"spur_s": float(np.min(spur_times)), "helical_s": float(np.min(helical_times)),
                       "ratio": float(np.min(helical_times) / np.min(spur_times))}
        print(f"{label}: spur {rows[label]['spur_s'] * 1e3:.2f} ms, helical (face integral) "
              f"{rows[label]['helical_s'] * 1e3:.2f} ms, ratio {rows[label]['ratio']:.2f}")
    result = {"points_per_period": points, "rows": rows, "python": sys.version.split()[0],
              "machine": platform.machine()}
    out = Path(__file__).parent / "results" / "bench_helical.json"
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1024)
