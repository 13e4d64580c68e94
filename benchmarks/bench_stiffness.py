"""Benchmark: the full PEM stiffness table of one case, vectorised Gauss–Legendre vs per-point scipy quad.

Run: python benchmarks/bench_stiffness.py [CASE] [COUNT]
Prints a table and writes benchmarks/results/bench_stiffness.json. Both implementations are timed in the same
run; the baseline integrates the same integrands (Tian 2004; Chaari et al. 2009) with scipy.integrate.quad point by point.
"""

from __future__ import annotations

import json
import math
import platform
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from scipy.integrate import quad

from thermogear.case import load_case
from thermogear.stiffness.fillet_foundation import fillet_foundation_compliance, root_half_angle
from thermogear.stiffness.potential_energy import (hertz_compliance, involute_end_angle, pair_compliance,
                                                   root_segment_integrals)


def quad_tooth_compliance(gear, alpha_1: float, material, width: float) -> float:
    """Straightforward per-point implementation: scipy quad on the involute integrands (same closed forms)."""
    alpha_2 = gear.half_tooth_angle_at_base
    end = involute_end_angle(alpha_2, gear.base_radius, gear.root_radius)
    cos_1 = math.cos(alpha_1)

    def bending(a):
        arm = alpha_2 - a
        return 1.5 * (1 + cos_1 * (arm * math.sin(a) - math.cos(a))) ** 2 * arm * math.cos(a) / (
            math.sin(a) + arm * math.cos(a)) ** 3

    def normal(a):
        arm = alpha_2 - a
        return arm * math.cos(a) / (math.sin(a) + arm * math.cos(a))

    b = quad(bending, -alpha_1, end)[0]
    n = quad(normal, -alpha_1, end)[0]
    rb, rn = root_segment_integrals(np.array([alpha_1]), alpha_2, gear.base_radius, gear.root_radius)
    b, n = b + rb[0], n + rn[0]
    e, nu = material.youngs_modulus, material.poisson_ratio
    theta_f = root_half_angle(gear.teeth, gear.pressure_angle, gear.dedendum_coefficient,
                              gear.tool_tip_radius_coefficient)
    fillet = fillet_foundation_compliance(alpha_1, gear.base_radius, gear.root_radius,
                                          gear.root_radius / gear.bore_radius, theta_f, e, width)
    return (b + 1.2 * (1 + nu) * cos_1**2 * n + 0.5 * math.sin(alpha_1) ** 2 * n) / (e * width) + float(fillet)


def quad_pair_stiffness(pair, material, roll) -> np.ndarray:
    width = pair.face_width
    hertz = hertz_compliance(material.youngs_modulus, material.poisson_ratio, width)
    out = np.empty(roll.size)
    for i, r in enumerate(roll):
        out[i] = 1.0 / (quad_tooth_compliance(pair.pinion, float(pair.pinion_load_angle(r)), material, width)
                        + quad_tooth_compliance(pair.wheel, float(pair.wheel_load_angle(r)), material, width)
                        + hertz)
    return out


def best_of(function, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times), float(np.median(times))


def main(case_name: str = "luo2019", count: int = 401) -> dict:
    case = load_case(case_name)
    pair, material = case.gear_pair, case.material
    roll = pair.roll_grid(count)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        vectorised = lambda: pair_compliance(pair, material, roll).stiffness  # noqa: E731
        vectorised()  # warm-up
        fast_best, fast_median = best_of(vectorised, 50)
        baseline = lambda: quad_pair_stiffness(pair, material, roll)  # noqa: E731
        slow_best, slow_median = best_of(baseline, 3)
        difference = float(np.max(np.abs(vectorised() / baseline() - 1.0)))
    result = {
        "benchmark": "bench_stiffness", "case": case_name, "contact_positions": count,
        "vectorised_gauss_legendre_s": {"best": fast_best, "median": fast_median},
        "per_point_scipy_quad_s": {"best": slow_best, "median": slow_median},
        "speed_ratio_median": slow_median / fast_median,
        "max_relative_difference": difference,
        "target_s": 0.050, "meets_target": fast_median < 0.050,
        "python": sys.version.split()[0], "numpy": np.__version__, "machine": platform.machine(),
        "processor": platform.processor(),
    }
    print(f"{'implementation':32s} {'best [ms]':>10s} {'median [ms]':>12s}")
    print(f"{'vectorised Gauss-Legendre':32s} {fast_best * 1e3:10.3f} {fast_median * 1e3:12.3f}")
    print(f"{'per-point scipy quad':32s} {slow_best * 1e3:10.1f} {slow_median * 1e3:12.1f}")
    print(f"ratio (median) {result['speed_ratio_median']:.0f}x, max relative difference {difference:.1e}, "
          f"{count} contact positions, case {case_name}")
    out = Path(__file__).parent / "results" / "bench_stiffness.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main(*(sys.argv[1:2] or ["luo2019"]), *([int(sys.argv[2])] if len(sys.argv) > 2 else []))
