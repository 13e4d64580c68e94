"""Example 11 — a drivetrain from the case file: the built-in FZG test gearbox cold and hot, and a speed sweep of its
bearing forces.

    python examples/11_drivetrain_case.py [OUTPUT_FOLDER]

The built-in set ``fzg_rig_type_c`` is the FZG type C pair on two 30 mm shafts with two NJ 406 bearings each, all
in its ``[drivetrain]`` section (every dimension sourced or stated as an assumption in the set). The script loads it
like any case, builds the drivetrain cold (elastic mesh model) and hot (the case's thermo-elastic model: E(T) of
shafts and teeth, hot mesh stiffness and geometry), prints the modes with their labels, energy shares and what heat
moved, and sweeps the pinion speed to show the force each bearing puts on the housing — what an accelerometer there
sees — with the speeds where mesh harmonics meet the modes the mesh excites. The same numbers come from
``thermogear run fzg_rig_type_c`` and ``thermogear sweep fzg_rig_type_c --vary speed_rpm=...``.
"""

from __future__ import annotations

import sys
import tempfile
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear import load_case  # noqa: E402
from thermogear.drivetrain.case_model import case_drivetrain, heat_table, mode_table  # noqa: E402
from thermogear.sweep import Study  # noqa: E402
from thermogear.sweep.drivetrain_run import run_drivetrain_study  # noqa: E402

SPEEDS = np.linspace(1000.0, 14000.0, 53)  # pinion speeds [rpm]: 250 rpm steps, through the lateral resonances


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case("fzg_rig_type_c")
        built = case_drivetrain(case)
        cold = mode_table(built.modes("elastic"), built.drivetrains["elastic"])
        heat = heat_table(built.heat_shifts(), built.drivetrains["elastic"])
        # the speed study `thermogear sweep` runs, here in this process, into a store in the output folder, with the
        # linear mesh (permanent contact: each speed's one periodic response; the set's own backlash mesh would
        # follow the orbit up and down in speed)
        linear = case.with_changes(**{"dynamics.mesh": "linear"})
        study = Study.define(linear, {"speed_rpm": SPEEDS.tolist()}, model="both")
        sweep = run_drivetrain_study(study, out / "speeds.zarr", scheduler="serial",
                                     overwrite=(out / "speeds.zarr").exists())
    data = sweep.dataset
    first = data["bearing_harmonic_amplitude_n"].sel(harmonic=1).max("bearing")  # largest bearing, 1× mesh
    teeth = case.gear_pair.pinion.teeth

    # --- checks
    assert bool(data["valid"].all())  # every speed has a stable periodic response
    # every mode's strain energy is shared out completely, and heat softens every mode
    assert all(abs(sum(row["energy_shares"].values()) - 1.0) < 1e-9 for row in cold)
    assert all(row["shift_percent"] < 0.0 for row in heat)
    torsional = max(cold, key=lambda row: row["mesh_share"])
    assert torsional["label"] == "torsional" and torsional["mesh_share"] > 0.5
    # the bearing force's first mesh harmonic peaks where that harmonic meets a lateral mode the mesh couples to
    # (mesh share of a few per cent): within one step of the sweep (250 rpm) of a listed crossing
    peak = float(SPEEDS[int(np.argmax(first.sel(model="elastic").values))])
    crossings = [r["speed_rpm"] for r in sweep.resonances["elastic"] if r["harmonic"] == 1]
    assert min(abs(peak - speed) for speed in crossings) <= 250.0, (peak, crossings)
    # Kv peaks where the third mesh harmonic meets the torsional mesh mode
    kv_peak = float(SPEEDS[int(np.argmax(data["kv"].sel(model="elastic").values))])
    assert abs(kv_peak - 60.0 * torsional["frequency_hz"] / (3 * teeth)) <= 250.0, kv_peak

    # --- figure
    figure, (left, right) = plt.subplots(1, 2, figsize=(11.0, 4.5), constrained_layout=True)
    for model, style in (("elastic", "-"), ("thermal", "--")):
        left.plot(SPEEDS, first.sel(model=model), style, label=f"{model} ({'cold' if model == 'elastic' else 'hot'})")
    for resonance in sweep.resonances["elastic"]:
        if resonance["harmonic"] == 1 or resonance["mesh_dominated"]:
            left.axvline(resonance["speed_rpm"], color="0.3" if resonance["mesh_dominated"] else "0.7",
                         linestyle="--" if resonance["mesh_dominated"] else ":", linewidth=1.0)
    left.set_xlabel("pinion speed [rpm]")
    left.set_ylabel("largest bearing force, 1× mesh [N]")
    left.set_title("FZG test gearbox: bearing force on the housing\n(dotted: 1× mesh meets a lateral mode; dashed: "
                   "a harmonic meets the mesh mode)", fontsize=9)
    left.legend(fontsize=8)
    index = np.arange(len(heat))
    right.bar(index, [row["shift_percent"] for row in heat], color="tab:blue")
    right.set_xticks(index, [f"{row['cold_hz']:.0f}\n{row['label'].split()[0]}" for row in heat], fontsize=6)
    right.set_ylabel("frequency shift cold → hot [%]")
    right.set_title("what heat moved: every mode softens (shafts' and teeth's E(T))", fontsize=9)
    path = out / "example_11_drivetrain_case.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    for row, shift in zip(cold, heat):
        print(f"{row['frequency_hz']:8.1f} Hz {row['label']:22s} mesh {row['mesh_share']:.3f} "
              f"hot {shift['shift_percent']:+.3f} % ({shift['dominant_cause']})")
    print(f"bearing force 1× mesh peaks at {peak:.0f} rpm ({first.sel(model='elastic').max().item():.0f} N); Kv peaks "
          f"at {kv_peak:.0f} rpm ({data['kv'].sel(model='elastic').max().item():.3f}); figure: {path}")
    return {"modes": cold, "heat": heat, "sweep": sweep, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
