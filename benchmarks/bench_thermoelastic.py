"""Benchmark: the thermo-elastic mesh component of one operating point, against the elastic path in the same run.

Run: python benchmarks/bench_thermoelastic.py
Prints a table and writes benchmarks/results/bench_thermoelastic.json.

One operating point (after warm-up: the component of the case is built and its PEM tables cached, as in a loop
over speeds or loads), at 1024 intervals per mesh period:

- elastic: the mesh grid of the cold pair and the pair stiffness of the slots in contact (``pair_stiffness_at``);
- thermoelastic: the same on the hot pair with E(T) (``ThermoelasticMesh.pair_stiffness_at``), plus the unloaded
  deviation of every slot and the loaded static transmission error and load share (exact piecewise-linear root).

Also timed: building the component of a new case (temperature field, hot pair, backlash and jamming, distortion
table; the PEM table of the hot pair), the one-off cost per case. Target (issue #13): ≤ 1 ms per operating point.
"""

from __future__ import annotations

import json
import platform
import sys
import time
import warnings
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results"
INTERVALS = 1024
TARGET_S = 1e-3


def _median_time(function, repeat: int) -> float:
    values = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        values.append(time.perf_counter() - start)
    return float(np.median(values))


def main(case_name: str = "fzg_type_c", repeat: int = 200) -> dict:
    from thermogear.case import load_case
    from thermogear.geometry.mesh_cycle import MeshCycle
    from thermogear.stiffness.table import pair_stiffness_at
    from thermogear.thermoelastic.load_sharing import loaded_transmission_error
    from thermogear.thermoelastic.mesh import ThermoelasticMesh

    warnings.simplefilter("ignore")
    case = load_case(case_name)
    component = ThermoelasticMesh.from_case(case)
    speed = case.operating_point.speed_rpm

    def elastic():
        grid = MeshCycle(case.gear_pair, speed).grid(INTERVALS)
        values = np.zeros_like(grid.roll)
        values[grid.in_contact] = pair_stiffness_at(case.gear_pair, case.material, grid.roll[grid.in_contact])
        return MeshCycle.total(values, grid.in_contact)

    def thermoelastic():
        grid, stiffness, deviation = component.period_pairs(INTERVALS)
        total = MeshCycle.total(stiffness, grid.in_contact)
        return total, loaded_transmission_error(stiffness, deviation, component.normal_load, grid.in_contact)

    for function in (elastic, thermoelastic):
        function()  # warm-up: tables and splines cached
    elastic_s = _median_time(elastic, repeat)
    thermal_s = _median_time(thermoelastic, repeat)

    def build_new():
        fresh = load_case(case_name)  # a new case: its component and the hot pair's PEM table are built again
        from thermogear.stiffness.table import clear_cache

        clear_cache()
        ThermoelasticMesh.from_case(fresh).mesh_stiffness(INTERVALS)

    build_s = _median_time(build_new, 5)
    result = {
        "benchmark": "bench_thermoelastic", "case": case_name, "intervals_per_period": INTERVALS,
        "elastic_operating_point_s": elastic_s, "thermoelastic_operating_point_s": thermal_s,
        "ratio_thermoelastic_over_elastic": thermal_s / elastic_s,
        "build_component_new_case_s": build_s,
        "target_s": TARGET_S, "meets_target": thermal_s <= TARGET_S,
        "python": sys.version.split()[0], "numpy": np.__version__, "machine": platform.machine(),
        "processor": platform.processor(),
    }
    print(f"{'path':<42}{'median':>12}")
    print(f"{'elastic (grid + pair stiffness)':<42}{elastic_s * 1e3:>10.3f} ms")
    print(f"{'thermoelastic (k, deviation, loaded STE)':<42}{thermal_s * 1e3:>10.3f} ms")
    print(f"{'ratio':<42}{thermal_s / elastic_s:>12.2f}")
    print(f"{'build component of a new case (cold)':<42}{build_s * 1e3:>10.3f} ms")
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / "bench_thermoelastic.json"
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main()
