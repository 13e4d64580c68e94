"""Benchmark: the gearbox thermal network (issue 28) — a steady state and a 20-minute warm-up — against baselines
measured in the same run.

Run: python benchmarks/bench_gearbox_thermal.py
Prints a table and writes benchmarks/results/bench_gearbox_thermal.json.

The illustrative FZG-type gearbox (thermogear.gearbox.fzg_example) at load stage 6 (2175 rpm, 135.3 N·m, air
20 °C):

- steady: the nonlinear steady state (losses and housing conductance following the temperatures; scipy root);
  baseline: one linear solve of the same network with conductances and losses frozen at the ambient temperature;
- warm-up: 20 minutes from the ambient temperature, 121 output times (Radau), with the losses and backlash at
  every output time; baseline: the same integration with conductances and losses frozen (the linear network).

- coupled warm-up: the same 20 minutes with the mesh re-evaluated every 10 s (121 states: thermal mesh model,
  mean stiffness, natural frequency and the periodic steady response at each), the FZG-type case file
  tests/data/gearbox/fzg_gearbox.toml at 1400 rpm, 138 N·m (thermogear.experiment.gearbox_warmup); baseline: one
  state (the mesh and periodic response at one temperature), so the ratio is the cost in states;
- coupled warm-up, old path against new, interleaved in the same run (wall and CPU time): the old path builds the
  401-point compliance table of every warm gear pair by the PEM quadrature (every warm pair is a new cache key)
  and solves every state afresh with Simulation.run (checks, periodic solve from the linear solution, coexistence
  search from rest); the new one takes the table's values from one Chebyshev interpolant per gear shape
  (thermogear.stiffness.scaled_compliance, the same values to < 1e-11) and starts each state's periodic solve from
  the previous state's orbit (gearbox_warmup(warm_start=True), the same Kv to < 1e-9); "tables only" is the new
  tables with the old solves, to attribute the gain.

Targets (issue 28): a steady state ≤ 50 ms; a 20-minute warm-up coupled to the mesh ≤ 2 s.
"""

from __future__ import annotations

import json
import os
import platform
import sys
import time
import warnings
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results"
STEADY_TARGET_S = 0.050
WARM_UP_TARGET_S = 2.0


def _interleaved(functions: dict, repeat: int) -> dict:
    """Median wall and CPU (user + sys of this process) seconds of each function, the calls interleaved."""
    wall = {name: [] for name in functions}
    cpu = {name: [] for name in functions}
    for _ in range(repeat):
        for name, function in functions.items():
            start_wall, start_cpu = time.perf_counter(), time.process_time()
            function()
            wall[name].append(time.perf_counter() - start_wall)
            cpu[name].append(time.process_time() - start_cpu)
    return {name: (float(np.median(wall[name])), float(np.median(cpu[name]))) for name in functions}


def _median_time(function, repeat: int) -> float:
    values = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        values.append(time.perf_counter() - start)
    return float(np.median(values))


def main(repeat: int = 21) -> dict:
    from thermogear.gearbox.description import GearboxOperatingPoint
    from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
    from thermogear.gearbox.model import GearboxThermalModel
    from thermogear.gearbox.network import ThermalNetwork, integrate_transient, solve_steady_state

    warnings.simplefilter("ignore")
    model = GearboxThermalModel(illustrative_fzg_gearbox())
    operating = GearboxOperatingPoint(2175.0, 135.3, 20.0)
    network = model.network(operating)
    ambient = np.full(network.size, 20.0)
    internal, boundary = network.exchange(ambient)
    sources = network.sources(ambient, 0.0)
    frozen = ThermalNetwork(network.capacities, lambda t: (internal, boundary), lambda t, time: sources,
                            lambda time: 20.0)
    times = np.linspace(0.0, 1200.0, 121)

    def linear_steady():
        return solve_steady_state(frozen, ambient)

    def steady():
        return model.steady_state(operating)

    def linear_warm_up():
        return integrate_transient(frozen, ambient, times)

    def warm_up():
        return model.warm_up(operating, 1200.0, points=121)

    from thermogear.case import load_case
    from thermogear.experiment.gearbox_warmup import gearbox_warmup, state_case
    from thermogear.simulation import Simulation

    case = load_case(Path(__file__).resolve().parents[1] / "tests" / "data" / "gearbox" / "fzg_gearbox.toml")

    def coupled_warm_up(warm_start: bool = True):
        return gearbox_warmup(case, duration_s=1200.0, interval_s=10.0, warm_start=warm_start)

    def one_state():
        simulation = Simulation(state_case(case, np.array([60.0, 55.0, 50.0, 45.0, 35.0])), "thermal")
        simulation.mesh_stiffness_mean
        return simulation.run(method="periodic")

    for function in (linear_steady, steady, linear_warm_up, warm_up, one_state):
        function()  # imports and caches
    linear_steady_s = _median_time(linear_steady, repeat)
    steady_s = _median_time(steady, repeat)
    linear_warm_up_s = _median_time(linear_warm_up, max(5, repeat // 4))
    warm_up_s = _median_time(warm_up, max(5, repeat // 4))
    one_state_s = _median_time(one_state, 5)

    import thermogear.thermoelastic.mesh as thermoelastic_mesh
    from thermogear.stiffness import scaled_compliance
    from thermogear.stiffness import table as stiffness_table

    def with_source(source, warm_start: bool):
        def run():
            thermoelastic_mesh.scaled_compliance = source  # the warm tables from this module
            stiffness_table.clear_cache()
            scaled_compliance.clear_cache()
            try:
                return coupled_warm_up(warm_start)
            finally:
                thermoelastic_mesh.scaled_compliance = scaled_compliance
        return run

    paths = _interleaved({"old": with_source(stiffness_table, False), "tables only": with_source(scaled_compliance,
                                                                                                 False),
                          "new": with_source(scaled_compliance, True)}, 3)
    (old_wall, old_cpu), (coupled_s, coupled_cpu) = paths["old"], paths["new"]
    tables_wall, tables_cpu = paths["tables only"]
    state, history = steady(), warm_up()
    figures = [
        {"name": "steady state (nonlinear) vs frozen-linear solve", "value": steady_s, "baseline": linear_steady_s,
         "ratio": steady_s / linear_steady_s, "unit": "s"},
        {"name": "20-min warm-up (nonlinear) vs frozen-linear warm-up", "value": warm_up_s,
         "baseline": linear_warm_up_s, "ratio": warm_up_s / linear_warm_up_s, "unit": "s"},
        {"name": "steady state vs 50 ms target", "value": steady_s, "baseline": STEADY_TARGET_S,
         "ratio": steady_s / STEADY_TARGET_S, "unit": "s"},
        {"name": "20-min warm-up (thermal only) vs 2 s target", "value": warm_up_s, "baseline": WARM_UP_TARGET_S,
         "ratio": warm_up_s / WARM_UP_TARGET_S, "unit": "s"},
        {"name": "coupled 20-min warm-up (121 mesh states) vs one state", "value": coupled_s,
         "baseline": one_state_s, "ratio": coupled_s / one_state_s, "unit": "s"},
        {"name": "coupled 20-min warm-up vs 2 s target", "value": coupled_s, "baseline": WARM_UP_TARGET_S,
         "ratio": coupled_s / WARM_UP_TARGET_S, "unit": "s"},
        {"name": "coupled warm-up, new vs old path (wall)", "value": coupled_s, "baseline": old_wall,
         "ratio": coupled_s / old_wall, "unit": "s"},
        {"name": "coupled warm-up, new vs old path (CPU)", "value": coupled_cpu, "baseline": old_cpu,
         "ratio": coupled_cpu / old_cpu, "unit": "s"},
        {"name": "coupled warm-up, new tables only vs old (CPU)", "value": tables_cpu, "baseline": old_cpu,
         "ratio": tables_cpu / old_cpu, "unit": "s"},
        {"name": "coupled warm-up (CPU) vs 2 s target", "value": coupled_cpu, "baseline": WARM_UP_TARGET_S,
         "ratio": coupled_cpu / WARM_UP_TARGET_S, "unit": "s"},
    ]
    result = {
        "benchmark": "bench_gearbox_thermal", "figures": figures,
        "steady_temperatures_c": [round(float(value), 2) for value in state.temperatures_c],
        "steady_losses_w": {"mesh": state.losses.mesh, "bearings": state.losses.bearings, "seals": state.losses.seals,
                            "churning": state.losses.churning},
        "warm_up_end_temperatures_c": [round(float(value), 2) for value in history.temperatures_c[:, -1]],
        "load_average_1_5_15_min": [round(value, 2) for value in os.getloadavg()],
        "python": sys.version.split()[0], "numpy": np.__version__, "machine": platform.machine(),
        "processor": platform.processor(),
    }
    print(f"{'figure':<56}{'value':>12}{'baseline':>12}{'ratio':>9}")
    for figure in figures:
        print(f"{figure['name']:<56}{figure['value'] * 1e3:>10.2f}ms{figure['baseline'] * 1e3:>10.2f}ms"
              f"{figure['ratio']:>9.2f}")
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / "bench_gearbox_thermal.json"
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main()
