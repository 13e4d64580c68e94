"""Example 6 — through the primary resonance with the nonlinear mesh: contact loss, jumps and hysteresis.

    python examples/06_nonlinear_resonance.py [OUTPUT_FOLDER]

The FZG type C pair (the default nonlinear mesh: teeth may separate and strike the back flanks across the
backlash) is swept in pinion speed from 2000 to 30 000 rpm, once upward and once downward, each speed starting
from its neighbour's orbit. Near the primary resonance (mesh frequency = natural frequency, ≈ 21 900 rpm for
f_n ≈ 5.85 kHz and z1 = 16) the teeth lose contact; the lost contact softens the mesh, so the resonance bends to
lower speeds and two stable responses coexist over a band: the up sweep stays on the low branch and jumps up, the
down sweep stays on the high branch and jumps down at a lower speed (Kahraman & Singh 1990). The linear model
gives one response per speed and cannot show either branch.
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
from thermogear.simulation import Simulation  # noqa: E402
from thermogear.sweep import Study  # noqa: E402
from thermogear.sweep.branch_plots import plot_branches  # noqa: E402
from thermogear.sweep.branches import branch_study, hysteresis_bands  # noqa: E402


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    case = load_case("fzg_type_c")
    study = Study.define(case, {"speed_rpm": "2000:30000:141"}, model="elastic")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        data = branch_study(study, "both")
    bands = hysteresis_bands(data)["elastic"]
    speed = data["speed_rpm"].values
    natural = Simulation(case, "elastic").natural_frequency_hz  # sqrt(mean k / me)/2π of the elastic mesh [Hz]
    primary = 60.0 * natural / case.gear_pair.pinion.teeth

    # --- checks
    up = data.sel(direction="up", model="elastic")
    down = data.sel(direction="down", model="elastic")
    assert set(np.asarray(data["response"].values).ravel().astype(str)) <= {"periodic", "subharmonic",
                                                                             "non-periodic"}
    assert np.all(np.isfinite(data["kv"].values))
    # two branches over a band below the primary resonance (the backlash softens the mesh)
    assert bands["differ"] and bands["band_rpm"][1] < primary
    # on that band the down sweep rides the high branch: larger DTE and contact lost for part of the period
    inside = (speed >= bands["band_rpm"][0]) & (speed <= bands["band_rpm"][1])
    assert np.all(down["dte_peak_to_peak"].values[inside] > up["dte_peak_to_peak"].values[inside])
    assert np.all(down["contact_loss_fraction"].values[inside] > 0.0)
    # the down sweep falls off the high branch at the lower end of the band
    falls = [jump for jump in bands["down_sweep_jumps"] if jump["amplitude"] == "falls"]
    assert falls and abs(falls[0]["speed_rpm"] - bands["band_rpm"][0]) < 2 * (speed[1] - speed[0])

    # --- figure
    figure = plot_branches(data)
    path = out / "example_06_nonlinear_resonance.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    print(f"branches differ over {bands['band_rpm'][0]:.0f}–{bands['band_rpm'][1]:.0f} rpm (primary resonance "
          f"of the linear mesh {primary:.0f} rpm); figure: {path}")
    return {"bands": bands, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
