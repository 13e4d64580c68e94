"""Example 5 — the thermal effect on a pair in an aluminium housing (the thermo-elastic model).

    python examples/05_aluminium_housing.py [OUTPUT_FOLDER]

``[thermal] model = "thermoelastic"`` (the default; docs/thermal.md) predicts what heat does to a pair without a
fitted factor: the teeth soften with E(T), the gears grow with their bulk temperature and the bearings move
apart with the housing. The housing material decides whether the backlash opens or closes when the gears run at
90 °C: aluminium (21.5e-6 1/K) grows faster than the steel gears (11.5e-6 1/K), cast iron (11.4e-6 1/K) slower,
and a housing that stays cooler than the gears closes the backlash further. The figure shows the normal
backlash against the housing temperature for both housings, the gears at 90 °C.
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
from thermogear.thermoelastic.mesh import ThermoelasticMesh  # noqa: E402

CASE_FILE = """\
[case]
name = "hot_pair_aluminium_housing"
title = "20/41 pair, module 4 mm, gears at 90 °C in an aluminium housing at 60 °C"
assumptions = [
  "Bores 12 mm (pinion) and 20 mm (wheel).",
  "Gear bodies at a uniform 90 °C, housing at 60 °C (no measured temperatures).",
  "Cold backlash from the AGMA 2002-B88 minimum (the case gives none).",
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
bulk_c = 90.0

[thermal]
model = "thermoelastic"

[housing]
material = "aluminium"
temperature_c = 60.0
"""

HOUSINGS = {"aluminium": 21.5e-6, "cast_iron": 11.4e-6}  # expansion coefficients the model uses [1/K]


def backlash_by_hand(cold_backlash: float, centre_distance: float, operating_angle: float, gear_strain: float,
                     housing_strain: float) -> float:
    """Normal backlash of the hot pair to first order in the strains [m]: gears scaled by ε_g at a centre
    distance grown by ε_h, Δj_bn = ε_g·j_bn + 2·a·sin α_w·(ε_h − ε_g) (∂j_bn/∂a = 2 sin α_w, docs/thermal.md)."""
    return cold_backlash * (1.0 + gear_strain) + 2.0 * centre_distance * math.sin(operating_angle) * (
        housing_strain - gear_strain)


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    case_path = out / "hot_pair.toml"
    case_path.write_text(CASE_FILE, encoding="utf-8")
    base = load_case(case_path)
    reference_c = 20.0  # stress-free temperature (the [temperature] reference_c default)
    gear_strain = 11.5e-6 * (90.0 - reference_c)  # [material] thermal_expansion_per_k default

    results = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # extrapolation warnings of the fits are listed by `thermogear check`
        for material, coefficient in HOUSINGS.items():
            case = base.with_changes(**{"housing.material": material})
            mesh = ThermoelasticMesh.from_case(case)
            cold = mesh.cold_gear_pair
            expected = backlash_by_hand(mesh.backlash_normal_cold, cold.centre_distance,
                                        cold.operating_pressure_angle, gear_strain, coefficient * (60.0 - reference_c))
            responses = compare(Simulation(case))
            results[material] = {"mesh": mesh, "expected_backlash": expected,
                                 "natural_hz": {m: r.metrics["natural_frequency_hz"] for m, r in responses.items()}}
        sweep = {material: [] for material in HOUSINGS}
        housing_c = np.linspace(20.0, 90.0, 8)
        for material in HOUSINGS:
            for temperature in housing_c:
                changed = base.with_changes(**{"housing.material": material, "housing.temperature_c": temperature})
                sweep[material].append(ThermoelasticMesh.from_case(changed).backlash_normal * 1e6)

    # --- checks
    aluminium, cast_iron = results["aluminium"], results["cast_iron"]
    for material, found in results.items():
        # the model's backlash equals the first-order hand formula to 0.1 μm (second-order terms ~ε²·a ≈ 0.1 nm)
        assert abs(found["mesh"].backlash_normal - found["expected_backlash"]) < 0.1e-6, material
        # heat softens the mesh: E(T) and the longer centre distance lower the natural frequency
        assert found["natural_hz"]["thermal"] < found["natural_hz"]["elastic"], material
    assert aluminium["mesh"].backlash_normal > aluminium["mesh"].backlash_normal_cold  # aluminium opens it
    assert cast_iron["mesh"].backlash_normal < cast_iron["mesh"].backlash_normal_cold  # cast iron closes it
    # the aluminium housing moves the bearings apart: shorter path of contact, lower contact ratio and frequency
    assert aluminium["mesh"].gear_pair.contact_ratio < cast_iron["mesh"].gear_pair.contact_ratio
    assert aluminium["natural_hz"]["thermal"] < cast_iron["natural_hz"]["thermal"]
    # backlash rises linearly with the housing temperature at slope 2·a·sin α_w·λ_h (1 %)
    for material, coefficient in HOUSINGS.items():
        slope = np.polyfit(housing_c, sweep[material], 1)[0] * 1e-6
        cold = results[material]["mesh"].cold_gear_pair
        expected_slope = 2.0 * cold.centre_distance * math.sin(cold.operating_pressure_angle) * coefficient
        assert abs(slope / expected_slope - 1.0) < 0.01, (material, slope, expected_slope)

    # --- figure
    figure, ax = plt.subplots(figsize=(7.5, 4.0), constrained_layout=True)
    colors = {"aluminium": "tab:orange", "cast_iron": "tab:gray"}
    for material in HOUSINGS:
        ax.plot(housing_c, sweep[material], "o-", color=colors[material],
                label=f"{material.replace('_', ' ')} housing (λ = {HOUSINGS[material] * 1e6:.1f}e-6 1/K)")
    ax.axhline(aluminium["mesh"].backlash_normal_cold * 1e6, color="0.3", ls=":", lw=1.0,
               label="cold backlash (20 °C, AGMA minimum)")
    ax.set_xlabel("housing temperature [°C] (gears at 90 °C)")
    ax.set_ylabel("normal backlash j_bn [μm]")
    ax.set_title("Thermo-elastic model: backlash of a 20/41 pair, module 4 mm", fontsize=10)
    figure.legend(loc="outside lower center", ncol=2, fontsize=8)
    path = out / "example_05_aluminium_housing.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    print("backlash cold → hot: " + "; ".join(
        f"{m} {r['mesh'].backlash_normal_cold * 1e6:.1f} → {r['mesh'].backlash_normal * 1e6:.1f} μm, f_n "
        f"{r['natural_hz']['elastic']:.0f} → {r['natural_hz']['thermal']:.0f} Hz" for m, r in results.items())
        + f"; figure: {path}")
    return {"results": results, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
