"""Random spur pairs through stiffness and both meshes (issue 25's check: no NaN called valid, every
non-periodic point labelled, no traceback).

Run: nice -n 10 python benchmarks/random_pairs.py --count 10000 [--seed 0] [--time-limit 1200] [--log pairs.jsonl]

Each pair is a case document drawn over the schema's ranges (module, teeth, face width, profile shift, speed,
torque or power, backlash, oil, bulk, housing and reference temperatures, the thermal model). It goes through what
the commands use: the case is loaded (a ``CaseError`` there is a refusal, counted), ``preflight`` (what ``check``
runs; a refusal there is counted too), the stiffness summary of ``thermogear stiffness``, then the elastic and the
thermal model of ``thermogear run`` with the linear and with the nonlinear mesh, and the JSON object ``run --json``
prints. A defect is anything else: an exception that is not a ``CaseError`` before solving, a ``CaseError`` after
``check`` accepted the case (check ≠ run; a ``ModelLimitError`` such as a parametric instability of the linear
mesh is the clean error ``run`` prints and is counted as a label, not a defect), a non-finite number in a result called valid, a result whose response
is not periodic and which is not labelled so, or a JSON object that cannot be written. The summary counts refusals
by key and defects by class; ``--log`` keeps one line per pair (the document and the outcome) to replay a defect.
The tests run a small derandomised draw of the same function (tests/integration/test_reliability_random_pairs.py).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
import traceback
import warnings
from collections import Counter

import numpy as np

#: Built-in oils of different grades and base oils (``thermogear oils``).
OILS = ("iso_vg_46_mineral", "iso_vg_100_mineral", "iso_vg_220_mineral", "iso_vg_68_pao", "sch632")

#: Probability that a parameter is drawn over the whole schema range rather than over the usual design range.
WIDE = 0.2


def _log_uniform(rng, low: float, high: float) -> float:
    return float(math.exp(rng.uniform(math.log(low), math.log(high))))


def _pick(rng, usual, wide):
    """A value from ``usual()`` or, with probability WIDE, from ``wide()`` (the schema's whole range)."""
    return wide() if rng.random() < WIDE else usual()


def set_wide(probability: float) -> None:
    """Draw each parameter over the schema's whole range with this probability (default 0.2)."""
    global WIDE
    WIDE = float(probability)


def draw_document(rng: np.random.Generator, index: int = 0) -> dict:
    """One random case document: usual spur-gear designs mixed with values anywhere in the schema's ranges."""
    module = _pick(rng, lambda: _log_uniform(rng, 0.5, 12.0), lambda: _log_uniform(rng, 0.1, 100.0))
    pinion = int(_pick(rng, lambda: rng.integers(14, 60), lambda: rng.integers(5, 1001)))
    wheel = int(_pick(rng, lambda: rng.integers(14, 120), lambda: rng.integers(5, 1001)))
    face = _pick(rng, lambda: module * rng.uniform(4.0, 20.0), lambda: _log_uniform(rng, 0.1, 2000.0))
    shifts = [_pick(rng, lambda: rng.uniform(-0.4, 0.8), lambda: rng.uniform(-1.0, 1.5)) for _ in range(2)]
    gears = {"module_mm": round(module, 4), "face_width_mm": round(face, 3),
             "pinion": {"teeth": pinion, "profile_shift": round(shifts[0], 3)},
             "wheel": {"teeth": wheel, "profile_shift": round(shifts[1], 3)}}
    if rng.random() < 0.6:  # else the AGMA default backlash
        base_pitch_um = math.pi * module * math.cos(math.radians(20.0)) * 1e3
        gears["backlash_normal_um"] = round(_pick(rng, lambda: base_pitch_um * rng.uniform(0.0, 0.05),
                                                  lambda: rng.uniform(0.0, 20000.0)), 2)
    speed = _pick(rng, lambda: _log_uniform(rng, 100.0, 20000.0), lambda: _log_uniform(rng, 1e-3, 200000.0))
    operating: dict = {"speed_rpm": round(speed, 3)}
    if rng.random() < 0.5:
        # a torque scaled with the pair's size (module² · teeth · width ~ the tooth's load capacity) or anywhere
        usual = lambda: module ** 2 * pinion * face * 1e-3 * _log_uniform(rng, 0.5, 50.0)  # noqa: E731
        operating["torque_nm"] = float(f"{_pick(rng, usual, lambda: _log_uniform(rng, 1e-6, 1e7)):.4g}")
    else:
        operating["power_kw"] = float(f"{_pick(rng, lambda: _log_uniform(rng, 0.1, 500.0), lambda: _log_uniform(rng, 1e-9, 1e5)):.4g}")
    oil = round(_pick(rng, lambda: rng.uniform(20.0, 120.0), lambda: rng.uniform(-60.0, 200.0)), 1)
    document = {"case": {"name": f"random{index}"}, "gears": gears, "operating": operating,
                "lubricant": {"name": str(rng.choice(OILS)), "operating_temperature_c": oil}}
    if rng.random() < 0.7:  # else no [temperature]: the gears at the oil temperature
        document["temperature"] = {"bulk_c": round(_pick(rng, lambda: oil + rng.uniform(0.0, 60.0),
                                                         lambda: rng.uniform(-60.0, 200.0)), 1)}
        if rng.random() < 0.2:
            document["temperature"]["reference_c"] = round(rng.uniform(-60.0, 200.0), 1)
    if rng.random() < 0.5:
        document["housing"] = {"temperature_c": round(_pick(rng, lambda: oil - rng.uniform(0.0, 30.0),
                                                            lambda: rng.uniform(-40.0, 200.0)), 1)}
    if rng.random() < 0.1:
        document["thermal"] = {"model": "luo2020", "x_te": round(rng.uniform(0.0, 5.0), 3)}
    return document


def _non_finite(value, path: str = "") -> list[str]:
    """The paths of the non-finite floats inside a nested metrics dict / list / array."""
    if isinstance(value, dict):
        return [p for key, item in value.items() for p in _non_finite(item, f"{path}.{key}")]
    if isinstance(value, (list, tuple)):
        return [p for i, item in enumerate(value) for p in _non_finite(item, f"{path}[{i}]")]
    if isinstance(value, np.ndarray) and value.dtype.kind == "f":
        return [path] if not np.all(np.isfinite(value)) else []
    if isinstance(value, (float, np.floating)) and not math.isfinite(value):
        return [path]
    return []


#: Metrics a valid result must give as finite numbers (the rest may be absent for a mesh that has no such value).
VALID_METRICS = ("kv", "dte_peak_to_peak", "dte_rms", "max_mesh_force", "max_pair_load_n_per_mm",
                 "max_system_load_n_per_mm", "static_load_n_per_mm", "natural_frequency_hz", "mesh_frequency_hz",
                 "floquet_multipliers_abs", "largest_multiplier", "damping_ratio")


#: Responses that are a steady orbit (a subharmonic repeats after N mesh periods and says so in ``response``).
STEADY = ("periodic", "subharmonic")


def _model_defects(response) -> list[str]:
    """The defect classes of one model's response (empty: a clean result, valid or labelled)."""
    from thermogear.cli.run import model_json, response_status
    from thermogear.dynamics.results.metric_results import typed_metrics

    metrics = response.metrics
    kind = metrics.get("response", "periodic")
    defects = []
    if metrics["valid"]:
        bad = [key for key in VALID_METRICS if key in metrics and _non_finite(metrics[key])]
        if bad:
            defects.append("NaN called valid: " + ", ".join(bad))
        if kind not in STEADY:
            defects.append(f"'{kind}' response called valid")
    elif response_status(typed_metrics(metrics)) == "valid":
        defects.append("invalid point with status valid")
    try:
        payload = model_json(response)
        json.dumps(payload, allow_nan=False)
    except (ValueError, TypeError) as error:
        defects.append(f"run --json fails: {type(error).__name__}")
        return defects
    if payload["response"] != kind or (kind not in STEADY and payload["status"] == "valid"):
        defects.append(f"'{kind}' response not labelled in run --json")
    return defects


def check_pair(document: dict, method: str = "periodic") -> dict:
    """Run one case document through load, check, stiffness and both meshes under both models.

    ``method``: "periodic" (the steady state) or "transient" (the motion from rest, as ``run --method transient``).
    Returns ``{"outcome": "refused" | "computed" | "defect", "stage": …, "key"/"defects": …, "seconds": …}``."""
    from thermogear.case import case_from_document
    from thermogear.errors import CaseError, ModelLimitError
    from thermogear.evaluation import uses_paper_thermal_stiffness
    from thermogear.mesh.model import MeshModel
    from thermogear.orchestrator import Orchestrator
    from thermogear.serialization import json_ready
    from thermogear.simulation import MODELS, Simulation
    from thermogear.summaries.stiffness import stiffness_summary
    from thermogear.summaries.thermoelastic import thermoelastic_summary

    start = time.perf_counter()
    stage = "load"
    result: dict = {"outcome": "computed", "defects": [], "labels": Counter()}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # warnings are outputs of the commands, not defects here
            cases = {}
            for mesh in ("linear", "nonlinear"):
                stage = "load"
                variant = json.loads(json.dumps(document))
                variant.setdefault("dynamics", {})["mesh"] = mesh
                cases[mesh] = case = case_from_document(variant, source="<random>")
                stage = "check"
                Orchestrator(case, method=method).preflight()  # as run --method does
            stage = "stiffness"
            linear = cases["linear"]
            summary, _ = stiffness_summary(MeshModel(linear, "elastic"), linear.material, linear.operating_point,
                                           linear.name)
            bad = _non_finite({k: v for k, v in summary.items() if k != "warnings"})
            if bad:
                result["defects"].append("stiffness summary non-finite: " + ", ".join(bad[:3]))
            thermal = MeshModel(linear, "thermal")
            if not uses_paper_thermal_stiffness(thermal):
                stage = "thermo-elastic summary"  # run's rows: backlash cold/hot, jamming, E(T), loaded STE
                summary = thermoelastic_summary(thermal.thermoelastic_mesh, thermal.thermal_model, thermal.temperature)
                json.dumps(json_ready(summary, non_finite="null"), allow_nan=False)
            for mesh, case in cases.items():
                for model in MODELS:
                    stage = f"{mesh} {model}"
                    try:
                        response = Simulation(case, model).run(method)
                    except ModelLimitError:  # a clean "error: …" of `run` (e.g. parametric instability)
                        result["labels"][f"{mesh} model limit"] += 1
                        continue
                    label = "valid" if response.metrics["valid"] else response.metrics.get("response", "not valid")
                    result["labels"][f"{mesh} {label}"] += 1
                    result["defects"] += [f"{stage}: {defect}" for defect in _model_defects(response)]
    except CaseError as error:
        if stage in ("load", "check"):
            result.update(outcome="refused", stage=stage, key=error.key)
        else:
            result["defects"].append(f"{stage}: CaseError after check accepted ({error.key})")
            result["message"] = str(error)[:300]
    except Exception as error:  # noqa: BLE001  (every other exception is the defect this script counts)
        result["defects"].append(f"{stage}: {type(error).__name__}")
        result["message"] = "".join(traceback.format_exception_only(error)).strip()[:300]
        result["traceback"] = traceback.format_exc()[-1500:]
    if result["defects"]:
        result["outcome"] = "defect"
    result["stage"] = result.get("stage", stage)
    result["labels"] = dict(result["labels"])
    result["seconds"] = round(time.perf_counter() - start, 3)
    return result


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=10000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--time-limit", type=float, default=math.inf, help="stop after this many seconds")
    parser.add_argument("--log", default=None, help="JSON lines: one document and outcome per pair")
    parser.add_argument("--wide", type=float, default=WIDE, help="probability of a draw over the whole schema range")
    parser.add_argument("--transient-every", type=int, default=10,
                        help="every N-th pair runs the motion from rest (run --method transient) instead")
    arguments = parser.parse_args(argv)
    set_wide(arguments.wide)
    rng = np.random.default_rng(arguments.seed)
    log = open(arguments.log, "w", encoding="utf-8") if arguments.log else None
    outcomes, refusals, defects, labels = Counter(), Counter(), Counter(), Counter()
    start = time.perf_counter()
    cpu = time.process_time()
    done = 0
    for index in range(arguments.count):
        if time.perf_counter() - start > arguments.time_limit:
            break
        document = draw_document(rng, index)
        every = arguments.transient_every
        result = check_pair(document, "transient" if every and index % every == every - 1 else "periodic")
        done += 1
        outcomes[result["outcome"]] += 1
        labels.update(result["labels"])
        if result["outcome"] == "refused":
            refusals[f"{result['stage']}: {result['key']}"] += 1
        for defect in result["defects"]:
            defects[defect] += 1
        if log is not None:
            log.write(json.dumps({"index": index, "document": document, **result}) + "\n")
            log.flush()
        if done % 100 == 0:
            print(f"{done} pairs, {time.perf_counter() - start:.0f} s: {dict(outcomes)}", file=sys.stderr, flush=True)
    if log is not None:
        log.close()
    report = {"pairs": done, "seed": arguments.seed, "wide": WIDE, "transient_every": arguments.transient_every, "wall_s": round(time.perf_counter() - start, 1),
              "cpu_s": round(time.process_time() - cpu, 1), "outcomes": dict(outcomes),
              "refusals": dict(refusals.most_common()), "defects": dict(defects.most_common()),
              "labels": dict(labels.most_common())}
    print(json.dumps(report, indent=1))
    return 1 if defects else 0


if __name__ == "__main__":
    sys.exit(main())
