"""Held-out fuzz of drivetrain and gearbox cases (issue 36): seeded random cases within the schema's ranges, each
run through `thermogear check` and `thermogear run` (drivetrain) or `thermogear gearbox` (gearbox) in a child
process with a timeout. Counted: tracebacks (any "Traceback" on stderr or an exit status other than 0 and 2),
hangs (past the timeout), and check ≠ run (check accepts a case the command then refuses, or refuses a drivetrain
case `run` computes; a gearbox too hot for the mesh is refused by check, for `run`, and reported by `gearbox` with
its flags, by design).

Run: python benchmarks/fuzz_drivetrain_gearbox.py [--cases N] [--seed S] [--timeout SECONDS] [--shard K/N]
Prints one line per case and writes benchmarks/results/fuzz_drivetrain_gearbox.json (the cases that failed are
kept as TOML under benchmarks/results/fuzz_failures/). ``--shard K/N`` judges only the cases whose number is K
modulo N (every case is still drawn, so the set is the same) and writes ``…_shardKofN.json``: N shards started side
by side on a many-core machine cover the set; ``--combine`` then sums the shard files of the same seed and count.

The generator (:func:`drivetrain_case`, :func:`gearbox_case`) starts from tests/data/user_drivetrain.toml and
tests/data/gearbox/fzg_gearbox.toml and draws, from one ``numpy.random.Generator``: gear size and ratio, face
width, speed and torque, shaft segments and diameters, bearing count, positions, stiffness, damping and radial
clearance, a disk, the gears' positions, the mesh law, the mesh grid and the response cut-off (drivetrain); speed,
torque, ambient, housing size and mass, oil volume (gearbox). Values lie inside the schema's ranges but are not
all physical: a case may rightly be refused; what may not happen is a traceback, a hang, or check ≠ run.
"""

from __future__ import annotations

import copy
import json
import os
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
RESULTS = Path(__file__).resolve().parent / "results"
DRIVETRAIN_BASE = ROOT / "tests" / "data" / "user_drivetrain.toml"
GEARBOX_BASE = ROOT / "tests" / "data" / "gearbox" / "fzg_gearbox.toml"


def _round(value: float, digits: int = 4) -> float:
    return float(f"{value:.{digits}g}")


def drivetrain_case(rng: np.random.Generator) -> dict:
    """One random drivetrain case document (module docstring)."""
    document = tomllib.loads(DRIVETRAIN_BASE.read_text(encoding="utf-8"))
    module = _round(rng.uniform(1.5, 5.0), 2)
    pinion = int(rng.integers(14, 31))
    wheel = int(round(pinion * rng.uniform(1.0, 4.0)))
    document["case"]["name"] = "fuzzed_drivetrain"
    document["gears"] = {"module_mm": module, "face_width_mm": _round(module * rng.uniform(4.0, 14.0), 3),
                         "pinion": {"teeth": pinion}, "wheel": {"teeth": wheel}}
    if pinion < 17 and rng.random() < 0.7:  # mostly the shift that avoids undercut (DIN 3960: x >= (17 − z)/17)
        document["gears"]["pinion"]["profile_shift"] = _round((17 - pinion) / 17 + 0.05, 3)
    document["operating"] = {"speed_rpm": _round(rng.uniform(300.0, 12000.0), 4),
                             "torque_nm": _round(rng.uniform(5.0, 400.0), 3)}
    document["dynamics"] = {"mesh": str(rng.choice(["nonlinear", "linear"])),
                            "points_per_period": int(rng.choice([64, 128, 256, 512]))}
    section = document["drivetrain"]
    section["response_cutoff_hz"] = _round(rng.uniform(5e3, 6e4), 3)
    section["maximum_element_length_mm"] = _round(rng.uniform(20.0, 120.0), 3)
    shafts, bearings, disks = [], [], []
    for name, gear in (("motor shaft", "pinion"), ("output shaft", "wheel")):
        teeth = pinion if gear == "pinion" else wheel
        root_radius = 0.5 * module * teeth - 1.25 * module
        diameter = _round(min(2.0 * root_radius * rng.uniform(0.3, 0.8), 80.0), 3)
        document["gears"][gear]["bore_radius_mm"] = _round(diameter / 2.0, 4)
        segments = [{"length_mm": _round(rng.uniform(60.0, 250.0), 3), "outer_diameter_mm": diameter}]
        if rng.random() < 0.4:
            segments.append({"length_mm": _round(rng.uniform(40.0, 150.0), 3),
                             "outer_diameter_mm": _round(diameter * rng.uniform(0.7, 1.4), 3)})
        length = sum(segment["length_mm"] for segment in segments)
        shafts.append({"name": name, "material_damping_s": _round(10 ** rng.uniform(-9.0, -6.0), 3),
                       "segments": segments})
        section[gear] = {"shaft": name, "position_mm": _round(length * rng.uniform(0.1, 0.9), 4)}
        positions = [0.0, length] + ([_round(length * rng.uniform(0.2, 0.8), 4)] if rng.random() < 0.3 else [])
        for number, position in enumerate(positions):
            stiffness = _round(10 ** rng.uniform(7.0, 9.5), 3)
            bearing = {"name": f"{name} bearing {number + 1}", "shaft": name, "position_mm": position,
                       "stiffness_x_n_per_m": stiffness, "stiffness_y_n_per_m": stiffness,
                       "damping_x_n_s_per_m": _round(rng.uniform(0.0, 5000.0), 3),
                       "damping_y_n_s_per_m": _round(rng.uniform(0.0, 5000.0), 3)}
            if number == 0:
                bearing["stiffness_z_n_per_m"] = _round(stiffness * rng.uniform(0.1, 1.0), 3)
                bearing["damping_z_n_s_per_m"] = _round(rng.uniform(0.0, 3000.0), 3)
            if rng.random() < 0.2:
                bearing["radial_clearance_um"] = _round(rng.uniform(0.0, 60.0), 3)
            bearings.append(bearing)
        if gear == "pinion" and rng.random() < 0.6:
            mass = _round(rng.uniform(0.5, 20.0), 3)
            disks.append({"name": "rotor", "shaft": name, "position_mm": _round(length * rng.uniform(0.0, 1.0), 4),
                          "mass_kg": mass, "polar_inertia_kg_m2": _round(mass * rng.uniform(2e-4, 3e-3), 3),
                          "diametral_inertia_kg_m2": _round(mass * rng.uniform(2e-4, 3e-3), 3)})
    section["shafts"], section["bearings"], section["disks"] = shafts, bearings, disks
    return document


def gearbox_case(rng: np.random.Generator) -> dict:
    """One random gearbox case document (module docstring)."""
    document = tomllib.loads(GEARBOX_BASE.read_text(encoding="utf-8"))
    document["case"]["name"] = "fuzzed_gearbox"
    document["operating"] = {"speed_rpm": _round(rng.uniform(100.0, 6000.0), 4),
                             "torque_nm": _round(rng.uniform(5.0, 400.0), 3)}
    document["gearbox"]["ambient_c"] = _round(rng.uniform(-20.0, 45.0), 3)
    housing = document["gearbox"]["housing"]
    scale = rng.uniform(0.5, 2.0)
    for key in ("length_mm", "width_mm", "height_mm"):
        housing[key] = _round(housing[key] * scale * rng.uniform(0.8, 1.25), 4)
    housing["mass_kg"] = _round(housing["mass_kg"] * scale**2 * rng.uniform(0.5, 2.0), 3)
    oil = document["gearbox"].get("oil")
    if isinstance(oil, dict) and "volume_l" in oil:
        oil["volume_l"] = _round(oil["volume_l"] * rng.uniform(0.3, 3.0), 3)
    return document


def _command(arguments: list[str], timeout: float) -> dict:
    environment = {**os.environ, "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
    start = time.perf_counter()
    try:
        result = subprocess.run([sys.executable, "-m", "thermogear", *arguments], capture_output=True, text=True,
                                timeout=timeout, env=environment)
    except subprocess.TimeoutExpired:
        return {"status": None, "hang": True, "traceback": False, "seconds": timeout, "stderr": ""}
    return {"status": result.returncode, "hang": False, "seconds": time.perf_counter() - start,
            "traceback": "Traceback" in result.stderr or result.returncode not in (0, 2),
            "stderr": result.stderr[-600:]}


def judge(kind: str, path: Path, timeout: float) -> dict:
    """check and the kind's command on one case file: the module docstring's counts."""
    check = _command(["check", str(path)], timeout)
    command = ["run", str(path), "--json", "-q"] if kind == "drivetrain" else ["gearbox", str(path), "--json"]
    ran = _command(command, timeout)
    at_load = ran["status"] == 2 and ("error" in ran["stderr"].lower())
    # `check` answers for `run` (the mesh dynamics); a gearbox whose steady state is too hot for the mesh is refused
    # by check and `run` but reported by `gearbox` with its flags, by design (the refusal names that command), so
    # for a gearbox case only a refusal by `gearbox` of a case check accepts is a disagreement
    disagree = (check["status"] == 0 and at_load) or (
        kind == "drivetrain" and check["status"] == 2 and ran["status"] == 0)
    return {"check": check, "command": ran, "traceback": check["traceback"] or ran["traceback"],
            "hang": check["hang"] or ran["hang"], "check_differs": bool(disagree)}


def main(cases: int, seed: int, timeout: float, shard: tuple[int, int] = (0, 1)) -> dict:
    import tomli_w

    import tempfile

    rng = np.random.default_rng(seed)
    work = Path(tempfile.mkdtemp(prefix="thermogear-fuzz-"))
    failures = RESULTS / "fuzz_failures"
    rows = []
    for number in range(cases):
        kind = "drivetrain" if number % 2 == 0 else "gearbox"
        document = drivetrain_case(rng) if kind == "drivetrain" else gearbox_case(rng)
        if number % shard[1] != shard[0]:
            continue
        path = work / f"case_{number:03d}.toml"
        path.write_text(tomli_w.dumps(document), encoding="utf-8")
        verdict = judge(kind, path, timeout)
        bad = verdict["traceback"] or verdict["hang"] or verdict["check_differs"]
        if bad:
            failures.mkdir(exist_ok=True)
            (failures / path.name).write_text(path.read_text(encoding="utf-8"), encoding="utf-8")
        rows.append({"case": number, "kind": kind, **{key: verdict[key] for key in (
            "traceback", "hang", "check_differs")}, "check_status": verdict["check"]["status"],
            "command_status": verdict["command"]["status"], "command_seconds": verdict["command"]["seconds"],
            "stderr_tail": verdict["command"]["stderr"][-300:] if bad else ""})
        print(f"{number:3d} {kind:10s} check {verdict['check']['status']} command {verdict['command']['status']} "
              f"{verdict['command']['seconds']:6.1f} s{'  FAILED' if bad else ''}", flush=True)
    return _summary(seed, cases, timeout, rows)


def _summary(seed: int, cases: int, timeout: float, rows: list[dict]) -> dict:
    summary = {"seed": seed, "cases": cases, "judged": len(rows), "timeout_s": timeout,
               "tracebacks": sum(row["traceback"] for row in rows), "hangs": sum(row["hang"] for row in rows),
               "check_differs": sum(row["check_differs"] for row in rows),
               "longest_command_s": max((row["command_seconds"] for row in rows), default=0.0), "rows": rows}
    print(f"{len(rows)} of {cases} cases: {summary['tracebacks']} tracebacks, {summary['hangs']} hangs, "
          f"{summary['check_differs']} check ≠ run")
    return summary


def combine(seed: int, cases: int) -> dict:
    """The summary of every shard file of this seed and count, as one run of the whole set would give it."""
    shards = [json.loads(path.read_text(encoding="utf-8"))
              for path in sorted(RESULTS.glob("fuzz_drivetrain_gearbox_shard*.json"))]
    shards = [shard for shard in shards if shard["seed"] == seed and shard["cases"] == cases]
    rows = sorted((row for shard in shards for row in shard["rows"]), key=lambda row: row["case"])
    if [row["case"] for row in rows] != list(range(cases)):
        raise SystemExit(f"the shard files of seed {seed} cover {len(rows)} of the {cases} cases")
    return _summary(seed, cases, max(shard["timeout_s"] for shard in shards), rows)


if __name__ == "__main__":
    def _option(name: str, default: float) -> float:
        return float(sys.argv[sys.argv.index(name) + 1]) if name in sys.argv else default

    cases, seed = int(_option("--cases", 100)), int(_option("--seed", 36))
    if "--combine" in sys.argv:
        result, name = combine(seed, cases), "fuzz_drivetrain_gearbox.json"
    elif "--shard" in sys.argv:
        part, count = (int(value) for value in sys.argv[sys.argv.index("--shard") + 1].split("/"))
        result = main(cases, seed, _option("--timeout", 300.0), (part, count))
        name = f"fuzz_drivetrain_gearbox_shard{part}of{count}.json"
    else:
        result, name = main(cases, seed, _option("--timeout", 300.0)), "fuzz_drivetrain_gearbox.json"
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / name).write_text(json.dumps(result, indent=2), encoding="utf-8")
