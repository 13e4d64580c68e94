"""Example 9 — what heat moves in the drivetrain: cold and hot modes of the paper's pair on its shafts, each shift
attributed to its cause, and the interference (Campbell) diagram.

    python examples/10_drivetrain_heat.py [OUTPUT_FOLDER]

The drivetrain of example 8 (luo2019 pair on two 150 mm shafts, two bearings each) is built twice. Cold: the
elastic mesh model (E at 20 °C, the pair as built). Hot: the predictive thermo-elastic mesh (``[thermal] model =
"thermoelastic"``): E(T) of the teeth at their bulk temperature, the grown pair at the centre distance the cast-iron
housing has moved, hence another operating pressure angle and base radii and the hot mean mesh stiffness; the shafts
take E(T) with the gears' β_E at the same bulk temperature (an assumption: the shafts run as warm as the gear
bodies; an upper bound). Masses, inertias and bearing stiffnesses are held. Each mode's shift is split by the
first-order modal strain-energy sensitivity into the shafts' E(T), the mesh stiffness and the mesh geometry, and
compared with the exact re-solved shift. The interference diagram shows the hot modes against pinion speed with
the mesh harmonics; the crossings of modes with a large mesh share are the tooth-critical speeds.
"""

from __future__ import annotations

import importlib.util
import sys
import tempfile
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear import load_case  # noqa: E402
from thermogear.drivetrain.campbell import campbell_diagram  # noqa: E402
from thermogear.drivetrain.heat import WarmState, thermal_mode_shifts, warm_drivetrain  # noqa: E402
from thermogear.mesh.model import MeshModel  # noqa: E402

MODES = 12


def _example_8():
    path = Path(__file__).resolve().parent / "08_drivetrain.py"
    spec = importlib.util.spec_from_file_location("thermogear_example_08_for_09", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case("luo2019")
        cold_model = MeshModel(case, "elastic")
        hot_model = MeshModel(case.with_changes(**{"thermal.model": "thermoelastic"}), "thermal")
        cold_stiffness = cold_model.state().mean_mesh_stiffness
        hot_stiffness = hot_model.state().mean_mesh_stiffness
    thermoelastic = hot_model.thermoelastic_mesh
    bulk_c = float(np.mean(thermoelastic.tooth_c))
    beta = thermoelastic.gears[0].modulus_coefficient_per_k
    cold = _example_8().build_drivetrain(cold_model, cold_stiffness)
    hot_pair = hot_model.gear_pair
    warm = WarmState({shaft.name: bulk_c for shaft in cold.shafts}, beta, mesh_stiffness=hot_stiffness,
                     base_radius_1=hot_pair.pinion.base_radius, base_radius_2=hot_pair.wheel.base_radius,
                     operating_pressure_angle=hot_pair.operating_pressure_angle)
    hot = warm_drivetrain(cold, warm)
    shifts = thermal_mode_shifts(cold, hot, count=MODES)
    causes = {"shafts E(T)": shifts.contributions["pinion shaft"] + shifts.contributions["wheel shaft"],
              "mesh stiffness": shifts.contributions["mesh stiffness"],
              "mesh geometry": shifts.contributions["mesh geometry"]}
    teeth = case.gear_pair.pinion.teeth
    hot_assembled = hot.assemble()
    speeds = np.linspace(200.0, 14000.0, 15)
    diagram = campbell_diagram(hot_assembled, speeds, teeth, harmonics=(1, 2, 3), mode_count=MODES)

    # --- checks
    # the attributions add up to the exact shift to first order: the shifts are ~1 %, so the remainder is ~1e-4
    assert np.abs(shifts.first_order - shifts.exact).max() < 3e-4, shifts.first_order - shifts.exact
    # nothing but the causes listed moved (bearings are held)
    assert all(np.abs(value).max() == 0.0 for name, value in shifts.contributions.items() if "bearing" in name)
    mesh_mode = int(np.argmax(diagram.mesh_shares[0]))
    # every mode softens: E falls with temperature in the shafts and the teeth
    assert np.all(shifts.exact < 0.0)
    assert shifts.dominant_cause(mesh_mode) in ("mesh stiffness", "pinion shaft", "wheel shaft")
    critical = diagram.tooth_critical(0.3)
    assert critical, "the mesh mode is met by a mesh harmonic inside the speed range"
    for crossing in critical:  # each lies on its harmonic line (Brent to 1e-9 of the range)
        assert abs(crossing.frequency_hz / (crossing.harmonic * teeth * crossing.speed_rpm / 60.0) - 1.0) < 1e-6

    # --- figure
    figure, (left, right) = plt.subplots(1, 2, figsize=(11.0, 4.8), constrained_layout=True)
    index = np.arange(MODES)
    bottom_positive, bottom_negative = np.zeros(MODES), np.zeros(MODES)
    for (name, values), colour in zip(causes.items(), ("tab:blue", "tab:orange", "tab:green")):
        percent = 100.0 * values
        base = np.where(percent >= 0.0, bottom_positive, bottom_negative)
        left.bar(index, percent, bottom=base, color=colour, label=name)
        bottom_positive += np.clip(percent, 0.0, None)
        bottom_negative += np.clip(percent, None, 0.0)
    left.plot(index, 100.0 * shifts.exact, "k_", ms=14, mew=2, label="exact (re-solved)")
    left.set_xticks(index, [f"{f:.0f}" for f in shifts.cold_hz], rotation=60, fontsize=7)
    left.set_xlabel("cold mode [Hz]")
    left.set_ylabel("frequency shift cold → hot [%]")
    left.set_title(f"luo2019 drivetrain, gears and shafts at {bulk_c:.0f} °C", fontsize=10)
    left.legend(fontsize=8)
    diagram.plot_campbell(right)
    right.set_title("hot drivetrain: interference diagram", fontsize=10)
    path = out / "example_10_drivetrain_heat.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    for i in range(MODES):
        print(f"{shifts.cold_hz[i]:7.0f} Hz {shifts.labels[i]:22s} exact {100 * shifts.exact[i]:+.3f} % "
              f"first order {100 * shifts.first_order[i]:+.3f} % (shafts {100 * causes['shafts E(T)'][i]:+.3f}, "
              f"mesh k {100 * causes['mesh stiffness'][i]:+.3f}, geometry {100 * causes['mesh geometry'][i]:+.4f})")
    for crossing in critical:
        print(f"tooth-critical: {crossing.harmonic}× mesh meets {crossing.frequency_hz:.0f} Hz ({crossing.label}, "
              f"mesh share {crossing.mesh_share:.2f}) at {crossing.speed_rpm:.0f} rpm")
    return {"shifts": shifts, "diagram": diagram, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
