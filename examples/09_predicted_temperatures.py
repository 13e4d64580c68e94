"""Example 8 — temperatures predicted, not typed: a case with a [gearbox] section and temperature.model = "gearbox".

    python examples/09_predicted_temperatures.py [OUTPUT_FOLDER]

The FZG type C gears of the built-in case ``fzg_type_c`` at 1400 rpm and 138 N·m, in an assumed dip-lubricated
gearbox given as a ``[gearbox]`` section (the same assumed housing, oil, bearings and seals as example 7). Loading
the case solves the gearbox's steady state, so the dynamics sees the predicted gear, oil and housing
temperatures; the warm-up from 20 °C re-evaluates the mesh every minute (stiffness, natural frequency, Kv).
"""

from __future__ import annotations

import sys
import tempfile
import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear.case import case_from_document, parameter_set_path  # noqa: E402
from thermogear.experiment.gearbox_warmup import gearbox_warmup  # noqa: E402
from thermogear.gearbox.case_model import (gearbox_model_from_case, gearbox_operating_point,  # noqa: E402
                                           predicted_steady_state)
from thermogear.simulation import Simulation  # noqa: E402  (also registers the "gearbox" temperature model)

# the [gearbox] section of the built-in FZG test gearbox (every housing value an assumption there:
# src/thermogear/parameter_sets/fzg_test_gearbox.toml, docs/gearbox-temperature.md)
GEARBOX = tomllib.loads(parameter_set_path("fzg_test_gearbox").read_text(encoding="utf-8"))["gearbox"]


def gearbox_case():
    document = tomllib.loads(parameter_set_path("fzg_type_c").read_text(encoding="utf-8"))
    document["case"]["name"] = "fzg_type_c_in_a_gearbox"
    document["operating"] = {"speed_rpm": 1400.0, "torque_nm": 138.0}
    document["temperature"] = {"model": "gearbox", "reference_c": 20.0}
    del document["lubricant"]["operating_temperature_c"]  # predicted now
    document["gearbox"] = GEARBOX
    return case_from_document(document)


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    case = gearbox_case()
    state = predicted_steady_state(gearbox_model_from_case(case),
                                   gearbox_operating_point(case.operating_point, case.gearbox))
    simulation = Simulation(case, "thermal")
    response = simulation.run(method="periodic")
    warm_up = gearbox_warmup(case, duration_s=1200.0, interval_s=60.0)

    # --- checks
    assert state.energy_residual < 1e-9  # heat shed = losses at the steady state
    assert abs(case.lubricant.operating_temperature_c - state.oil_c) < 1e-5  # the dynamics sees the predicted oil
    assert state.pinion_c > state.oil_c > state.housing_c > 20.0
    stiffness = np.array([item.mesh_stiffness_mean for item in warm_up.states])
    kv = np.array([item.kv for item in warm_up.states])
    assert np.all(np.diff(stiffness) < 0.0)  # E(T) falls as the gears heat
    # 20 minutes is not yet the steady state: the gears are still colder, so stiffer, than at the steady state
    assert warm_up.history.node("pinion")[-1] < state.pinion_c
    assert stiffness[-1] > simulation.mesh_stiffness_mean and kv[-1] > response.metrics["kv"]

    # --- figure
    figure = warm_up.plot()
    path = out / "example_09_predicted_temperatures.png"
    figure.savefig(path, dpi=100)
    plt.close(figure)
    print(f"steady: pinion {state.pinion_c:.1f}, wheel {state.wheel_c:.1f}, oil {state.oil_c:.1f}, housing "
          f"{state.housing_c:.1f} °C from {state.losses.total:.0f} W; Kv at steady state "
          f"{response.metrics['kv']:.3f}; warm-up Kv {kv[0]:.3f} → {kv[-1]:.3f}; smallest backlash "
          f"{warm_up.smallest_backlash[0] * 1e6:.1f} μm; figure: {path}")
    return {"state": state, "warm_up": warm_up, "kv": float(response.metrics["kv"]), "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
