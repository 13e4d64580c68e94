"""Benchmark: two commits of thermogear measured against each other in the same run (issue 33).

Run: python benchmarks/bench_commits.py [--old REF] [--new REF] [--repeats N] [--quick]
Prints a table and writes benchmarks/results/bench_commits.json.

The old commit (default ``fe2cd59``, where issue 33's refactor started) is checked out into a temporary
``git worktree`` (detached, removed afterwards; the tree you work in is not touched); the new one is the tree this
script sits in, as it is on disk (uncommitted edits included), or ``--new REF`` checked out the same way. Nothing is
installed: every measurement runs in a child process with ``PYTHONPATH=<tree>/src`` (the child checks that it
imported that tree's ``thermogear``), BLAS and OpenMP on one thread, and the two trees' children alternate
(old, new, then new, old, ...) so that a slow spell of the machine hits both. Each child warms up (numba's cache,
the stiffness tables) before it times; every figure is the median over the repeats of each child's own median.
A first, untimed round lets each tree write its numba cache.

Figures (what the project's benchmarks measured at fe2cd59, each through the tree's own public API or CLI):

1. the 1-DOF periodic solve (``periodic_initial_state`` on ``Simulation(luo2019, "thermal").problem``, as
   bench_dynamics.py's first figure) in μs;
2. the whole 1-DOF periodic operating point (``Simulation(case, "thermal").run("periodic")``: mesh state,
   problem, orbit, metrics; bench_dynamics.py's second figure) in ms;
3. the sweep fast path through the command line (``python -m thermogear sweep luo2019 --vary torque_nm=200:400:T
   --vary speed_rpm=1000:10000:1000 --scheduler serial --out X --json``; the command's own ``seconds``, as
   bench_sweep_cli.py's first figure) in points/s, target >= 10 000;
4. the nonlinear (backlash) continuation up and down over 1000 speeds of luo2019 at a 100 μm backlash
   (``follow_branch``, as bench_nonlinear.py's third figure) in s;
5. the 1000-speed sweep of bench_drivetrain.py's reduced two-shaft drivetrain (60 DOF) on luo2019's thermal mesh
   state per speed (``drivetrain_speed_sweep`` with ``MeshModel.state`` per speed, cut-off 20 kHz, timed on a
   sample of speeds and scaled to 1000, as bench_drivetrain.py's fifth figure) in s.

Where a call differs between the trees, each figure lists the variants it knows, in order; a child uses the first
its tree has, and the table and the JSON say which call each tree used (a new API gets a new variant here).
``--quick`` shrinks every measurement (a smoke test of the script, not the figures).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"
DEFAULT_OLD = "fe2cd59"  # issue 33's start commit
TOLERANCE = 1.10  # "within 10 %": new at most 1.1 times slower than old
ONE_THREAD = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
              "NUMEXPR_NUM_THREADS": "1", "VECLIB_MAXIMUM_THREADS": "1"}


# ------------------------------------------------------------------------------------------ child-side measurements
# Each measurement runs inside a child process whose thermogear is one tree's. It returns
# {"call": <which API it used>, "value": <median>, "cpu": <median CPU>, ...}; times are per call in the unit named
# by FIGURES below.

def _median_times(function, repeat: int) -> tuple[float, float]:
    """Median wall and CPU seconds of ``repeat`` calls."""
    walls, cpus = [], []
    for _ in range(repeat):
        wall, cpu = time.perf_counter(), time.process_time()
        function()
        cpus.append(time.process_time() - cpu)
        walls.append(time.perf_counter() - wall)
    return statistics.median(walls), statistics.median(cpus)


def _luo2019_thermal_problem():
    from thermogear.case import load_case
    from thermogear.simulation import Simulation

    case = load_case("luo2019")
    return case, Simulation(case, "thermal").problem


#: The package whose modules sat flat before issue 33's split (spelled so that a rewrite of the moved paths leaves
#: the old tree's names alone).
_FLAT = "thermogear." + "dynamics."


def _imported(name: str, *modules: str):
    """``name`` from the first of ``modules`` this tree has (a module that moved between the trees: issue 33 split
    thermogear.dynamics into subpackages)."""
    import importlib

    for module in modules:
        try:
            return getattr(importlib.import_module(module), name)
        except ImportError:
            continue
    raise ImportError(f"{name} in none of {modules}")


def measure_periodic_solve(quick: bool) -> dict:
    periodic_initial_state = _imported("periodic_initial_state", "thermogear.dynamics.periodic_orbits.periodic",
                                       _FLAT + "periodic")

    _, problem = _luo2019_thermal_problem()
    for _ in range(20):
        periodic_initial_state(problem)  # numba's cache, the caches of the problem
    wall, cpu = _median_times(lambda: periodic_initial_state(problem), 200 if quick else 2000)
    return {"call": "thermogear.dynamics.periodic_orbits.periodic.periodic_initial_state("
                    "Simulation(case, 'thermal').problem)",
            "value": wall * 1e6, "cpu": cpu * 1e6}


def measure_operating_point(quick: bool) -> dict:
    from thermogear.case import load_case
    from thermogear.simulation import Simulation

    case = load_case("luo2019")

    def point():
        return Simulation(case, "thermal").run("periodic")

    point()
    point()  # the stiffness-table cache and every numba kernel warm, as any second point of a study
    wall, cpu = _median_times(point, 5 if quick else 30)
    return {"call": "thermogear.simulation.Simulation(case, 'thermal').run('periodic')",
            "value": wall * 1e3, "cpu": cpu * 1e3}


def _backlash_problems(count: int):
    """luo2019 elastic at 13 000 rpm with a 100 μm backlash, its time axis rescaled to ``count`` speeds from 4000 to
    16000 rpm (bench_nonlinear.py's continuation)."""
    import numpy as np

    from thermogear.case import load_case
    from thermogear.simulation import Simulation

    BacklashMeshProblem = _imported("BacklashMeshProblem", "thermogear.dynamics.problems.backlash_problem",
                                    _FLAT + "backlash_problem")

    speed_rpm, backlash = 13000.0, 100e-6
    case = load_case("luo2019").with_changes(**{"operating.speed_rpm": speed_rpm})
    problem = BacklashMeshProblem.from_linear(Simulation(case, "elastic").problem, backlash=backlash)
    speeds = np.linspace(4000.0, 16000.0, count)
    return speeds, [problem.with_changes(nodes=problem.nodes * (speed_rpm / speed)) for speed in speeds]


def measure_continuation(quick: bool) -> dict:
    follow_branch = _imported("follow_branch", "thermogear.dynamics.backlash.backlash_continuation",
                              _FLAT + "backlash_continuation")

    count = 200 if quick else 1000
    warm_speeds, warm_problems = _backlash_problems(8)
    follow_branch(warm_problems, "up", warm_speeds)  # numba's cache
    follow_branch(warm_problems, "down", warm_speeds)
    speeds, problems = _backlash_problems(count)

    def both_ways():
        follow_branch(problems, "up", speeds)
        follow_branch(problems, "down", speeds)

    wall, cpu = _median_times(both_ways, 1)
    return {"call": "thermogear.dynamics.backlash.backlash_continuation.follow_branch(problems, 'up'/'down', speeds) "
                    "on "
                    "BacklashMeshProblem.from_linear(Simulation(case, 'elastic').problem, backlash)",
            "value": wall * 1000 / count, "cpu": cpu * 1000 / count, "speeds_timed": count}


def measure_drivetrain_sweep(quick: bool) -> dict:
    import numpy as np

    from bench_drivetrain import _drivetrain  # its two-shaft drivetrain, built with this tree's public classes

    from thermogear.case import load_case
    from thermogear.drivetrain.response import drivetrain_speed_sweep
    from thermogear.mesh.model import MeshModel

    assembled = _drivetrain(elements=3).assemble()
    model = MeshModel(load_case("luo2019"), "thermal")
    sample = 8 if quick else 40
    speeds = np.linspace(500.0, 6000.0, sample)

    def sweep(chosen):
        drivetrain_speed_sweep(assembled, [model.state(speed_rpm=speed) for speed in chosen], samples_per_piece=1,
                               cutoff_hz=2e4)

    sweep(speeds[:2] + 1.0)  # numba's cache and the stiffness tables, on speeds the timed sweep does not use
    wall, cpu = _median_times(lambda: sweep(speeds), 1)
    return {"call": "thermogear.drivetrain.response.drivetrain_speed_sweep(assembled, [MeshModel(case, 'thermal')"
                    ".state(speed_rpm=s) ...], samples_per_piece=1, cutoff_hz=2e4)",
            "value": wall * 1000 / sample, "cpu": cpu * 1000 / sample, "speeds_timed": sample,
            "degrees_of_freedom": int(assembled.size)}


# name: (label, unit, higher is better, measurement variants tried in order, or None for the command line)
FIGURES = {
    "periodic_solve": ("1-DOF periodic solve, luo2019 thermal (periodic_initial_state)", "μs", False,
                       (measure_periodic_solve,)),
    "operating_point": ("1-DOF periodic operating point, luo2019 thermal (Simulation -> metrics)", "ms", False,
                        (measure_operating_point,)),
    "sweep_cli": ("sweep fast path through the CLI, serial (target >= 10 000 points/s)", "points/s", True, None),
    "continuation": ("nonlinear continuation up + down, 1000 speeds, luo2019 100 μm backlash", "s", False,
                     (measure_continuation,)),
    "drivetrain_sweep": ("1000-speed drivetrain sweep, reduced two-shaft drivetrain, luo2019 thermal", "s", False,
                         (measure_drivetrain_sweep,)),
}


def child(name: str, tree: str, quick: bool) -> None:
    """Run one figure's measurement in this process and print its JSON (the child side)."""
    import warnings

    warnings.simplefilter("ignore")
    import thermogear

    source = Path(thermogear.__file__).resolve()
    if Path(tree).resolve() / "src" not in source.parents:
        raise SystemExit(f"imported {source}, not the tree {tree}: PYTHONPATH does not reach it")
    failures = []
    for variant in FIGURES[name][3]:
        try:
            result = variant(quick)
        except (ImportError, AttributeError, TypeError) as error:  # this tree has another API: try the next call
            failures.append(f"{variant.__name__}: {type(error).__name__}: {error}")
            continue
        result["variants_not_available"] = failures
        print(json.dumps(result))
        return
    raise SystemExit("no measurement variant runs on this tree:\n" + "\n".join(failures))


# ------------------------------------------------------------------------------------------ parent side
def _environment(tree: Path) -> dict:
    environment = {**os.environ, **ONE_THREAD, "PYTHONPATH": str(tree / "src")}
    environment.pop("PYTHONHOME", None)
    return environment


def _children_cpu() -> float:
    try:
        import resource
    except ImportError:  # not on Windows
        return math.nan
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_child(name: str, tree: Path, quick: bool) -> dict:
    """One measurement of one figure in a fresh process on ``tree``."""
    if FIGURES[name][3] is None:
        return run_sweep_cli(tree, quick)
    command = [sys.executable, str(Path(__file__).resolve()), "--child", name, "--tree", str(tree),
               *(["--quick"] if quick else [])]
    completed = subprocess.run(command, capture_output=True, text=True, cwd=tree, env=_environment(tree))
    if completed.returncode != 0:
        raise RuntimeError(f"{name} on {tree} failed ({completed.returncode}):\n{completed.stderr[-3000:]}")
    return json.loads(completed.stdout.strip().splitlines()[-1])


def run_sweep_cli(tree: Path, quick: bool, torques: int | None = None, speeds: int = 1000) -> dict:
    """The sweep command of ``tree`` on a speed x torque grid of luo2019, serial; the command's own seconds."""
    torques = torques or (10 if quick else 100)
    with tempfile.TemporaryDirectory(prefix="bench_commits_sweep_") as folder:
        command = [sys.executable, "-m", "thermogear", "sweep", "luo2019", "--vary", f"torque_nm=200:400:{torques}",
                   "--vary", f"speed_rpm=1000:10000:{speeds}", "--out", str(Path(folder) / "study.zarr"), "--json",
                   "--scheduler", "serial"]
        before = _children_cpu()
        completed = subprocess.run(command, capture_output=True, text=True, cwd=folder, env=_environment(tree))
        cpu = _children_cpu() - before
    if completed.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} on {tree} failed ({completed.returncode}):\n"
                           f"{completed.stderr[-3000:]}")
    summary = json.loads(completed.stdout[completed.stdout.index("{"):])
    points, seconds = int(summary["points"]), float(summary["seconds"])
    return {"call": "python -m thermogear sweep luo2019 --vary torque_nm=... --vary speed_rpm=... --scheduler serial "
                    "--out X.zarr --json (the command's own 'seconds')",
            "value": points / seconds, "cpu": points / cpu, "points": points, "seconds": seconds,
            "variants_not_available": []}


def _git(repository: Path, *arguments: str) -> str:
    completed = subprocess.run(["git", "-C", str(repository), *arguments], capture_output=True, text=True)
    if completed.returncode != 0:
        raise SystemExit(f"git {' '.join(arguments)} in {repository} failed: {completed.stderr.strip()}")
    return completed.stdout.strip()


def check_tree(tree: Path) -> str:
    """The thermogear a child on ``tree`` imports must be that tree's (else PYTHONPATH did not reach it and both
    sides would time the installed package)."""
    completed = subprocess.run([sys.executable, "-c", "import thermogear; print(thermogear.__file__)"],
                               capture_output=True, text=True, cwd=tree, env=_environment(tree))
    if completed.returncode != 0:
        raise SystemExit(f"thermogear does not import from {tree / 'src'}:\n{completed.stderr[-2000:]}")
    source = Path(completed.stdout.strip().splitlines()[-1]).resolve()
    if (tree / "src").resolve() not in source.parents:
        raise SystemExit(f"a child on {tree} imported {source}, not {tree / 'src'}")
    return str(source)


class Worktrees:
    """Temporary detached git worktrees of the given commits, removed on exit."""

    def __init__(self, repository: Path):
        self.repository = repository
        self.folder = Path(tempfile.mkdtemp(prefix="bench_commits_"))
        self.trees: list[Path] = []

    def add(self, reference: str) -> Path:
        tree = self.folder / f"tree{len(self.trees)}"
        _git(self.repository, "worktree", "add", "--detach", "--quiet", str(tree), reference)
        self.trees.append(tree)
        return tree

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        for tree in self.trees:
            subprocess.run(["git", "-C", str(self.repository), "worktree", "remove", "--force", str(tree)],
                           capture_output=True, text=True)
        subprocess.run(["git", "-C", str(self.repository), "worktree", "prune"], capture_output=True, text=True)
        shutil.rmtree(self.folder, ignore_errors=True)


def compare(old_tree: Path, new_tree: Path, names: list[str], repeats: int, quick: bool) -> dict:
    """Every figure measured ``repeats`` times in each tree, the trees alternating; {name: {"old": [...], ...}}."""
    runs = {name: {"old": [], "new": []} for name in names}
    trees = {"old": old_tree, "new": new_tree}
    for name in names:  # an untimed round: each tree writes its numba cache and warms the OS file cache
        for side in ("old", "new"):
            print(f"  warm-up {name} ({side}) ...", flush=True)
            run_child(name, trees[side], quick)
    for repeat in range(repeats):
        order = ("old", "new") if repeat % 2 == 0 else ("new", "old")
        for name in names:
            for side in order:
                result = run_child(name, trees[side], quick)
                runs[name][side].append(result)
                print(f"  repeat {repeat + 1}/{repeats} {name:17s} {side}: {result['value']:.4g} "
                      f"{FIGURES[name][1]}", flush=True)
    return runs


def summarise(runs: dict, labels: dict) -> list[dict]:
    figures = []
    for name, sides in runs.items():
        label, unit, higher_is_better, _ = FIGURES[name]
        old = statistics.median(run["value"] for run in sides["old"])
        new = statistics.median(run["value"] for run in sides["new"])
        old_cpu = statistics.median(run["cpu"] for run in sides["old"])
        new_cpu = statistics.median(run["cpu"] for run in sides["new"])
        slowdown = old / new if higher_is_better else new / old  # > 1: the new tree is slower
        cpu_slowdown = old_cpu / new_cpu if higher_is_better else new_cpu / old_cpu
        calls = {side: sorted({run["call"] for run in sides[side]}) for side in ("old", "new")}
        figure = {"name": label, "value": new, "baseline": old, "ratio": new / old, "unit": unit,
                  "slowdown": slowdown, "within_10_percent": bool(slowdown <= TOLERANCE),
                  "cpu": new_cpu, "baseline_cpu": old_cpu, "cpu_slowdown": cpu_slowdown,
                  "old_values": [run["value"] for run in sides["old"]],
                  "new_values": [run["value"] for run in sides["new"]],
                  "same_call": calls["old"] == calls["new"], "old_call": calls["old"], "new_call": calls["new"],
                  "baseline_from": labels["old"], "value_from": labels["new"]}
        if name == "sweep_cli":
            figure["new_meets_10000_points_per_second"] = bool(new >= 1e4)
            figure["old_meets_10000_points_per_second"] = bool(old >= 1e4)
        figures.append(figure)
    return figures


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description="Two commits of thermogear against each other in the same run "
                                     "(writes benchmarks/results/bench_commits.json).")
    parser.add_argument("--old", default=DEFAULT_OLD, help=f"the baseline commit (default {DEFAULT_OLD})")
    parser.add_argument("--new", default=None, help="the commit to judge (default: this tree as it is on disk)")
    parser.add_argument("--repeats", type=int, default=5, help="child processes per tree and figure (default 5)")
    parser.add_argument("--quick", action="store_true", help="small measurements: a smoke test, not the figures")
    parser.add_argument("--only", action="append", choices=sorted(FIGURES), help="measure only this figure")
    parser.add_argument("--child", choices=sorted(FIGURES), help=argparse.SUPPRESS)
    parser.add_argument("--tree", help=argparse.SUPPRESS)
    arguments, _ = parser.parse_known_args(argv)  # run_all.py passes its extra arguments to every benchmark
    if arguments.child:
        child(arguments.child, arguments.tree, arguments.quick)
        return 0
    if arguments.repeats < 1:
        parser.error("--repeats must be at least 1")
    repository = Path(_git(HERE, "rev-parse", "--show-toplevel"))
    names = arguments.only or list(FIGURES)
    with Worktrees(repository) as worktrees:
        old_tree = worktrees.add(arguments.old)
        new_tree = worktrees.add(arguments.new) if arguments.new else repository
        labels = {"old": f"{arguments.old} ({_git(old_tree, 'rev-parse', '--short', 'HEAD')})",
                  "new": (f"{arguments.new} ({_git(new_tree, 'rev-parse', '--short', 'HEAD')})" if arguments.new
                          else f"working tree at {_git(repository, 'rev-parse', '--short', 'HEAD')}"
                               + (" with uncommitted changes" if _git(repository, "status", "--porcelain",
                                                                      "--untracked-files=no") else ""))}
        for side, tree in (("old", old_tree), ("new", new_tree)):
            print(f"{side}: {labels[side]}, imports {check_tree(tree)}", flush=True)
        start = time.perf_counter()
        runs = compare(old_tree, new_tree, names, arguments.repeats, arguments.quick)
        elapsed = time.perf_counter() - start
    figures = summarise(runs, labels)
    result = {"benchmark": "bench_commits", "old": labels["old"], "new": labels["new"], "repeats": arguments.repeats,
              "quick": arguments.quick, "tolerance": "new at most 10 % slower than old (slowdown <= 1.10)",
              "threads": ONE_THREAD, "seconds": elapsed, "figures": figures,
              "runs": {name: sides for name, sides in runs.items()},
              "load_average_at_end": os.getloadavg() if hasattr(os, "getloadavg") else None,
              "cores": os.cpu_count(), "python": platform.python_version(), "machine": platform.machine()}
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "bench_commits.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    print(f"\nold = {labels['old']}, new = {labels['new']}; median of {arguments.repeats} child processes per tree"
          f"{' (--quick: not the figures)' if arguments.quick else ''}")
    print("slower: new time / old time (for points/s, old / new); CPU: the same in CPU time of the child process")
    print(f"{'figure':76s} {'unit':>8s} {'old':>10s} {'new':>10s} {'new/old':>8s} {'slower':>7s} {'CPU':>6s}  "
          "within 10 %?")
    for figure in figures:
        print(f"{figure['name'][:76]:76s} {figure['unit']:>8s} {figure['baseline']:10.4g} {figure['value']:10.4g} "
              f"{figure['ratio']:8.3f} {figure['slowdown']:7.3f} {figure['cpu_slowdown']:6.3f}  "
              f"{'yes' if figure['within_10_percent'] else 'NO'}")
        if not figure["same_call"]:
            print(f"    the trees differ in API: old {figure['old_call']}, new {figure['new_call']}")
    for figure in figures:
        if "new_meets_10000_points_per_second" in figure:
            print(f"sweep fast path >= 10 000 points/s: new {figure['value']:,.0f} "
                  f"({'yes' if figure['new_meets_10000_points_per_second'] else 'NO'}), old {figure['baseline']:,.0f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
