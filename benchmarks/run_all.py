"""Run every benchmark and print one table of the project's speed figures (ratios against same-run baselines).

Run: python benchmarks/run_all.py [--collect-only] [--only NAME ...] [extra args passed to every benchmark]

Each ``benchmarks/bench_*.py`` is run as its own process (so one benchmark's caches and compilation do not help
another) and writes ``benchmarks/results/<name>.json``. This script then reads every result file and writes
``benchmarks/results/summary.json`` and ``benchmarks/results/summary.md`` (the table the README shows).

A result file contributes rows from its ``"figures"`` list (``name``, ``value``, ``baseline``, ``ratio``,
``unit``) when it has one; otherwise every top-level number whose key names a ratio or a rate
(``*ratio*``, ``*speedup*``, ``*per_second*``) becomes a row.
"""

from __future__ import annotations

import json
import platform
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"
_KEY_WORDS = ("ratio", "speedup", "per_second")


def run_benchmarks(only: list[str] | None = None, extra: list[str] | None = None) -> dict[str, dict]:
    """Run each bench_*.py; returns {name: {"returncode", "seconds"}}."""
    status = {}
    for script in sorted(HERE.glob("bench_*.py")):
        name = script.stem
        if only and name not in only and name.removeprefix("bench_") not in only:
            continue
        print(f"running {name} ...", flush=True)
        start = time.perf_counter()
        completed = subprocess.run([sys.executable, str(script), *(extra or [])], cwd=HERE.parent)
        status[name] = {"returncode": completed.returncode, "seconds": time.perf_counter() - start}
        if completed.returncode != 0:
            print(f"  {name} failed (exit {completed.returncode})", flush=True)
    return status


def _rows_of(name: str, result: dict) -> list[dict]:
    rows = []
    for figure in result.get("figures", []) or []:
        rows.append({"benchmark": name, "figure": str(figure.get("name", "")), "value": figure.get("value"),
                     "baseline": figure.get("baseline"), "ratio": figure.get("ratio"),
                     "unit": figure.get("unit", "")})
    if rows:
        return rows
    for key, value in result.items():
        if isinstance(value, (int, float)) and not isinstance(value, bool) and any(w in key for w in _KEY_WORDS):
            rows.append({"benchmark": name, "figure": key, "value": None, "baseline": None,
                         "ratio": float(value) if "ratio" in key or "speedup" in key else None,
                         "unit": "" if "ratio" in key or "speedup" in key else "per second",
                         **({"value": float(value)} if "per_second" in key else {})})
    return rows


def collect() -> dict:
    """Read every results/bench_*.json into one summary."""
    rows, sources = [], {}
    for path in sorted(RESULTS.glob("bench_*.json")):
        name = path.stem
        try:
            result = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, json.JSONDecodeError) as error:
            sources[name] = f"unreadable: {error}"
            continue
        sources[name] = str(path.relative_to(HERE.parent))
        rows.extend(_rows_of(name, result))
    return {"rows": rows, "sources": sources, "python": platform.python_version(), "machine": platform.machine()}


def _number(value, digits: int = 4) -> str:
    if value is None:
        return "–"
    return f"{value:.{digits}g}"


def markdown(summary: dict) -> str:
    lines = ["| benchmark | figure | value | baseline | ratio | unit |", "|---|---|---:|---:|---:|---|"]
    for row in summary["rows"]:
        lines.append(f"| {row['benchmark'].removeprefix('bench_')} | {row['figure']} | {_number(row['value'])} | "
                     f"{_number(row['baseline'])} | {_number(row['ratio'], 3)} | {row['unit']} |")
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    collect_only = "--collect-only" in argv
    only, extra, rest = [], [], [a for a in argv if a != "--collect-only"]
    while rest:
        item = rest.pop(0)
        if item == "--only" and rest:
            only.append(rest.pop(0))
        else:
            extra.append(item)
    status = {} if collect_only else run_benchmarks(only or None, extra)
    summary = collect()
    summary["runs"] = status
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "summary.json").write_text(json.dumps(summary, indent=2) + "\n", encoding="utf-8")
    table = markdown(summary)
    (RESULTS / "summary.md").write_text(table, encoding="utf-8")
    print()
    print(table)
    return 1 if any(s["returncode"] != 0 for s in status.values()) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
