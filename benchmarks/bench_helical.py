"""Benchmark: the mesh stiffness of a helical pair over one mesh period against the spur pair's, in the same run.

Three figures, each a ratio helical / spur (the issue's target: helical ≤ 10× the spur cost):

1. the library functions: the slice model integrated exactly over the face (normal section) against the spur
   pair's primitives (one pair-stiffness table, the pairs in contact summed), cold (the PEM tables computed) and
   warm (the tables cached);
2. through the mesh model the commands use: ``MeshModel(case, model).state(...)`` of the built-in helical set
   ``fzg_h501`` (its thermal model carries the lead distortion of a 10 K face gradient, so its period is the face
   load solved at every mesh position) against the same case cut straight (β = 0, no face gradient), for both
   models; cold = a new mesh model with every stiffness table dropped, warm = the same mesh model at another speed
   and load on each call (what a sweep or a run's second state asks);
3. a 20-point linear speed sweep of both models (``Study`` → ``run_study``, serial, into a zarr store) of the same
   two cases, ``dynamics.mesh = "linear"``;
4. the drivetrain (the issue's target: helical within 1.5× of spur): the periodic response of the two-shaft rotor of
   docs/drivetrain.md (tests/data/two_shaft_drivetrain.toml, 256 points per period, every DOF) with its pair cut at
   β = 15° and the spread contact whose moments vary over the period (three patterns: a rank-2 update per mesh)
   against the same rotor with the spur pair, thermal model, states and assembly prepared, the two alternating;
   and the helical one with the moments held at their means (one pattern) for reference; and the point contact (the
   default ``helical_contact``: a constant normal stiffness at mid-face) of the helical pair against the spur pair's;
   each also on the modes to 20 kHz (``cutoff_hz``, what a case's ``response_cutoff_hz`` does).

Run: python benchmarks/bench_helical.py [--quick] [--drivetrain] (``--drivetrain``: figure 4 only)
Writes benchmarks/results/bench_helical.json (``--drivetrain``: bench_helical_two_shaft.json;
bench_helical_drivetrain.json is the other script's, benchmarks/bench_helical_drivetrain.py).
"""

from __future__ import annotations

import json
import math
import platform
import shutil
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from thermogear.helical.geometry import HelicalPair
from thermogear.helical.slices import helical_mesh_stiffness
from thermogear.materials import Material
from thermogear.mesh import helical_model
from thermogear.geometry.mesh_cycle import MeshCycle
from thermogear.stiffness import scaled_compliance, table
from thermogear.stiffness.table import pair_stiffness_at
from timing import wall_times

STEEL = Material()
RESULTS = Path(__file__).resolve().parent / "results"


def spur_period(pair, points: int) -> np.ndarray:
    grid = MeshCycle(pair, 1000.0).grid(points)
    per_pair = np.zeros(grid.roll.shape)
    end = pair.path_points["E"]
    per_pair[grid.in_contact] = pair_stiffness_at(pair, STEEL, np.minimum(grid.roll[grid.in_contact], end))
    return MeshCycle.total(per_pair, grid.in_contact)


def helical_period(helical, points: int) -> np.ndarray:
    phase = np.linspace(0.0, helical.transverse_base_pitch, points, endpoint=False)
    return helical_mesh_stiffness(helical, STEEL, phase).stiffness


def drop_tables() -> None:
    """Every cached stiffness table and interpolant (the cold start of a new pair)."""
    table.clear_cache()
    scaled_compliance.clear_cache()
    helical_model.clear_cache()


def cold(function):
    def run():
        drop_tables()
        function()
    return run


def _ratio_row(spur_times, helical_times) -> dict:
    spur, helical = float(np.min(spur_times)), float(np.min(helical_times))
    return {"spur_s": spur, "helical_s": helical, "ratio": helical / spur}


def library_functions(points: int, repeat: int) -> dict:
    spur = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), 0.0, 25e-3, bore_radii=(15e-3, 20e-3)).transverse
    helical = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(15.0), 25e-3,
                                 bore_radii=(15e-3, 20e-3))
    rows = {}
    for label, wrap in (("cold", cold), ("warm", lambda function: function)):
        rows[label] = _ratio_row(wall_times(wrap(lambda: spur_period(spur, points)), repeat),
                                 wall_times(wrap(lambda: helical_period(helical, points)), repeat))
        print(f"library functions, {label}: spur {rows[label]['spur_s'] * 1e3:.2f} ms, helical (face integral) "
              f"{rows[label]['helical_s'] * 1e3:.2f} ms, ratio {rows[label]['ratio']:.2f}")
    return rows


def cases():
    from thermogear.case import load_case

    helical = load_case("fzg_h501")
    straight = helical.with_changes(**{"gears.helix_angle_deg": 0.0, "temperature.face_gradient_k": 0.0})
    return helical, straight


def _interleaved(spur_run, helical_run, repeat: int) -> dict:
    """Minimum wall and CPU seconds of ``repeat`` calls of each, the two alternating (on a shared machine the load
    changes within seconds: alternating exposes both to the same)."""
    times = {"spur": [], "helical": []}
    for _ in range(repeat):
        for label, run in (("spur", spur_run), ("helical", helical_run)):
            wall, cpu = time.perf_counter(), time.process_time()
            run()
            times[label].append((time.perf_counter() - wall, time.process_time() - cpu))
    best = {label: np.min(np.array(values), axis=0) for label, values in times.items()}
    return {"spur_s": float(best["spur"][0]), "helical_s": float(best["helical"][0]),
            "ratio": float(best["helical"][0] / best["spur"][0]),
            "spur_cpu_s": float(best["spur"][1]), "helical_cpu_s": float(best["helical"][1]),
            "cpu_ratio": float(best["helical"][1] / best["spur"][1])}


def mesh_model_states(repeat: int) -> dict:
    """Figure 2: MeshModel.state of fzg_h501 against the case cut straight, both models, cold and warm (the two
    cases alternating, wall and CPU time)."""
    from thermogear.mesh.model import MeshModel

    helical_case, straight_case = cases()
    operating = [(1500.0 + 250.0 * index, 3000.0 + 200.0 * index) for index in range(repeat)]
    rows = {}
    for model in ("elastic", "thermal"):
        def cold_state(case):
            def run():
                drop_tables()
                MeshModel(case, model).state()
            return run

        def warm_states(case):
            mesh = MeshModel(case, model)
            mesh.state()
            calls = iter(operating)
            return lambda: mesh.state(*next(calls))

        for label, make in (("cold", cold_state), ("warm", warm_states)):
            make(straight_case)(), make(helical_case)()  # imports, first compilations
            rows[f"{model}, {label}"] = row = _interleaved(make(straight_case), make(helical_case), repeat)
            print(f"MeshModel.state, {model}, {label}: straight {row['spur_s'] * 1e3:.2f} ms, fzg_h501 "
                  f"{row['helical_s'] * 1e3:.2f} ms, ratio {row['ratio']:.2f} (CPU {row['spur_cpu_s'] * 1e3:.2f} "
                  f"ms, {row['helical_cpu_s'] * 1e3:.2f} ms, ratio {row['cpu_ratio']:.2f})")
    return rows


def linear_sweeps(points: int) -> dict:
    """Figure 3: a linear speed sweep of both models of both cases, serial, into a zarr store."""
    from thermogear.sweep import Study, run_study

    folder = Path(tempfile.mkdtemp(prefix="bench_helical_"))
    seconds = {}
    try:  # a first small study of another case imports and compiles what every study uses
        from thermogear.case import load_case

        warm_up = Study.define(load_case("luo2019").with_changes(**{"dynamics.mesh": "linear"}),
                               ["speed_rpm=1000,2000"], model="both")
        run_study(warm_up, folder / "warm_up.zarr", scheduler="serial", progress=False)
        for label, case in zip(("helical", "spur"), cases()):
            linear = case.with_changes(**{"dynamics.mesh": "linear"})
            study = Study.define(linear, [f"speed_rpm=1000:4000:{points}"], model="both")
            drop_tables()
            start = time.perf_counter()
            run = run_study(study, folder / f"{label}.zarr", scheduler="serial", progress=False)
            seconds[label] = time.perf_counter() - start
            kv = run.read("kv")
            if not np.all(np.isfinite(kv)):
                raise RuntimeError(f"the {label} sweep has points without a result: {kv}")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    row = {"points": points, "models": 2, "spur_s": seconds["spur"], "helical_s": seconds["helical"],
           "ratio": seconds["helical"] / seconds["spur"]}
    print(f"linear sweep, {points} speeds × 2 models (cold tables): straight {row['spur_s']:.2f} s, fzg_h501 "
          f"{row['helical_s']:.2f} s, ratio {row['ratio']:.2f}")
    return row


def drivetrain_responses(repeat: int) -> dict:
    """Figure 4: ``drivetrain_periodic_response`` of the two-shaft rotor, helical against spur with the same contact:
    the spread contact (the helical one with its moments varying, and held at their means) and the point contact
    (the default ``helical_contact``), each on every DOF and on the modes to 20 kHz, all runs alternating."""
    import tomllib
    from dataclasses import replace

    from thermogear.case import case_from_document
    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.drivetrain.response import drivetrain_periodic_response

    root = Path(__file__).resolve().parents[1]
    document = tomllib.loads((root / "tests" / "data" / "two_shaft_drivetrain.toml").read_text(encoding="utf-8"))
    prepared = {}
    for contact in ("spread", "point"):
        for label, helix in (("spur", 0.0), ("helical", 15.0)):
            document["gears"].update(helix_angle_deg=helix, hand="right")
            document["drivetrain"]["helical_contact"] = contact
            built = case_drivetrain(case_from_document(document))
            drivetrain, state = built.drivetrains["thermal"], built.mesh_states("thermal")
            name = label if contact == "spread" else f"{label}, point contact"
            prepared[name] = (drivetrain.assemble(), state)
            if helix and contact == "spread":
                assert drivetrain.meshes[0].varies()
                held = replace(drivetrain, meshes=(replace(drivetrain.meshes[0], face_variation=None),))
                prepared["helical, moments at their means"] = (held.assemble(), state)
    runs = {label: (lambda item=item: drivetrain_periodic_response(*item)) for label, item in prepared.items()}
    runs.update({f"{label}, modes to 20 kHz": (lambda item=item: drivetrain_periodic_response(*item, cutoff_hz=2e4))
                 for label, item in prepared.items()})
    for run in runs.values():  # imports, first compilations
        run()
    times = {label: [] for label in runs}
    for _ in range(repeat):  # all alternating: each repeat exposes every run to the same load
        for label, run in runs.items():
            wall, cpu = time.perf_counter(), time.process_time()
            run()
            times[label].append((time.perf_counter() - wall, time.process_time() - cpu))
    best = {label: np.min(np.array(values), axis=0) for label, values in times.items()}
    rows = {}
    pairs = [("helical", "spur"), ("helical, moments at their means", "spur"),
             ("helical, point contact", "spur, point contact")]
    for label, spur in pairs + [(f"{label}, modes to 20 kHz", f"{spur}, modes to 20 kHz") for label, spur in pairs]:
        rows[label] = row = {"spur_s": float(best[spur][0]), "helical_s": float(best[label][0]),
                             "ratio": float(best[label][0] / best[spur][0]),
                             "spur_cpu_s": float(best[spur][1]), "helical_cpu_s": float(best[label][1]),
                             "cpu_ratio": float(best[label][1] / best[spur][1])}
        print(f"drivetrain periodic response, two-shaft rotor (256 pieces), {label}: spur "
              f"{row['spur_s'] * 1e3:.0f} ms, helical {row['helical_s'] * 1e3:.0f} ms, ratio {row['ratio']:.2f} "
              f"(CPU ratio {row['cpu_ratio']:.2f})")
    return rows


def main(quick: bool = False, drivetrain_only: bool = False) -> dict:
    if drivetrain_only:
        warnings.simplefilter("ignore")
        result = {"drivetrain_response": drivetrain_responses(3 if quick else 7),
                  "python": sys.version.split()[0], "machine": platform.machine()}
        RESULTS.mkdir(exist_ok=True)
        (RESULTS / "bench_helical_two_shaft.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
        return result
    warnings.simplefilter("ignore")
    result = {"points_per_period": 1024,
              "library_functions": library_functions(1024, 3 if quick else 5),
              "mesh_model_state": mesh_model_states(5 if quick else 15),
              "linear_sweep": linear_sweeps(20),
              "python": sys.version.split()[0], "machine": platform.machine()}
    result["rows"] = result["library_functions"]  # the earlier name of figure 1
    figures = [(f"helical/spur mesh stiffness, library functions, {label}", row)
               for label, row in result["library_functions"].items()]
    figures += [(f"helical/spur MeshModel.state (fzg_h501 / cut straight), {label}", row)
                for label, row in result["mesh_model_state"].items()]
    figures.append(("helical/spur linear sweep, 20 speeds x 2 models (fzg_h501 / cut straight)",
                    result["linear_sweep"]))
    result["drivetrain_response"] = drivetrain_responses(3 if quick else 7)
    figures += [(f"helical/spur drivetrain periodic response, two-shaft rotor, {label}", row)
                for label, row in result["drivetrain_response"].items()]
    result["figures"] = [{"name": name, "value": row["helical_s"], "baseline": row["spur_s"],
                          "ratio": row["ratio"], "unit": "s",
                          **({"cpu_ratio": row["cpu_ratio"]} if "cpu_ratio" in row else {})} for name, row in figures]
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_helical.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main("--quick" in sys.argv[1:], "--drivetrain" in sys.argv[1:])
