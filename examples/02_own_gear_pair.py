"""Example 2 — your own gear pair from scratch: write a case file, load it, run both models, check the numbers.

    python examples/02_own_gear_pair.py [OUTPUT_FOLDER]

The case file below is all a user writes (units in the key names; every key is in docs/case-file-reference.md).
thermogear checks it when it loads, then computes the elastic and the thermal mesh over one mesh period and the
exact periodic steady state of both. The figure shows the mesh stiffness per width and the dynamic transmission
error over two mesh periods.
"""

from __future__ import annotations

import math
import sys
import tempfile
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear import load_case  # noqa: E402
from thermogear.simulation import Simulation, compare  # noqa: E402

CASE_FILE = """\
[case]
name = "my_pair"
title = "20/41 spur pair, module 4 mm, 40 kW at 3000 rpm"
assumptions = [
  "Bores 12 mm (pinion) and 20 mm (wheel).",
  "Gear bodies at a uniform 85 °C (no measured flank temperatures).",
  "X_te = 0.217, the value calibrated for Luo & Li's pair, transferred: an assumption, not a measurement.",
]

[gears]
module_mm = 4.0
face_width_mm = 30.0

[gears.pinion]
teeth = 20
bore_radius_mm = 12.0

[gears.wheel]
teeth = 41
bore_radius_mm = 20.0

[operating]
speed_rpm = 3000.0
power_kw = 40.0

[lubricant]
name = "iso_vg_100_mineral"
operating_temperature_c = 70.0

[temperature]
model = "uniform"
bulk_c = 85.0

[thermal]
model = "luo2020"
x_te = 0.217
"""


def contact_ratio_by_hand(module: float, teeth1: int, teeth2: int, pressure_angle_deg: float) -> float:
    """ε_α = (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a sin α) / (π m cos α) for unshifted standard gears at the
    standard centre distance (ISO 21771; h_a* = 1)."""
    alpha = math.radians(pressure_angle_deg)
    r1, r2 = module * teeth1 / 2, module * teeth2 / 2
    ra1, ra2 = r1 + module, r2 + module
    rb1, rb2 = r1 * math.cos(alpha), r2 * math.cos(alpha)
    path = math.sqrt(ra1**2 - rb1**2) + math.sqrt(ra2**2 - rb2**2) - (r1 + r2) * math.sin(alpha)
    return path / (math.pi * module * math.cos(alpha))


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    case_path = out / "my_pair.toml"
    case_path.write_text(CASE_FILE, encoding="utf-8")
    case = load_case(case_path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        responses = compare(Simulation(case))  # both models at the case's operating point
        simulations = {model: Simulation(case, model) for model in ("elastic", "thermal")}
        stiffness = {model: simulation.mesh_stiffness for model, simulation in simulations.items()}
    pair = case.gear_pair

    # --- checks
    # geometry: the contact ratio equals the hand formula of ISO 21771 (exact up to rounding)
    assert math.isclose(pair.contact_ratio, contact_ratio_by_hand(4.0, 20, 41, 20.0), rel_tol=1e-9)
    for model, response in responses.items():
        metrics = response.metrics
        assert metrics["stable"] and not metrics["contact_loss"]["detected"], model
        # the period mean of the elastic mesh force k·x equals the static load (no mean acceleration); 1 %:
        # the orbit is sampled at 4 points per interval and integrated by the trapezoidal rule
        load = response.system_load()
        mean = float(np.trapezoid(load, response.time) / response.problem.period)
        assert abs(mean / response.problem.static_load - 1.0) < 0.01, (model, mean)
        assert metrics["kv"] >= 1.0, model
    # heat with X_te > 0 softens the mesh: lower natural frequency, larger static transmission error
    elastic, thermal = responses["elastic"].metrics, responses["thermal"].metrics
    assert thermal["natural_frequency_hz"] < elastic["natural_frequency_hz"]
    assert thermal["dte_mean"] > elastic["dte_mean"]

    # --- figure
    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 3.6), constrained_layout=True)
    colors = {"elastic": "tab:blue", "thermal": "tab:red"}
    for model, simulation in simulations.items():
        grid = simulation.grid
        period = responses[model].problem.period
        left.step(np.asarray(grid.midpoints) / period, stiffness[model] / pair.face_width * 1e-9, where="mid",
                  color=colors[model], label=model)
        response = responses[model]
        time = np.concatenate([response.time, response.time[1:] + period]) / period
        dte = np.concatenate([response.displacement, response.displacement[1:]]) * 1e6
        right.plot(time, dte, color=colors[model], label=model)
    left.set_xlabel("time / mesh period [–]")
    left.set_ylabel("mesh stiffness per width [N/(mm·μm)]")
    right.set_xlabel("time / mesh period [–]")
    right.set_ylabel("dynamic transmission error [μm]")
    left.set_title(f"{case.title}", fontsize=9)
    right.set_title("steady state, two periods", fontsize=9)
    figure.legend(*left.get_legend_handles_labels(), loc="outside lower center", ncol=2, fontsize=8)
    path = out / "example_02_own_pair.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    print(f"ε = {pair.contact_ratio:.4f}; Kv elastic {elastic['kv']:.3f}, thermal {thermal['kv']:.3f}; "
          f"f_n {elastic['natural_frequency_hz']:.0f} → {thermal['natural_frequency_hz']:.0f} Hz; figure: {path}")
    return {"case_file": case_path, "elastic": elastic, "thermal": thermal, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
