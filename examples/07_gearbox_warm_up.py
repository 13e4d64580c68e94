"""Example 7 — how hot a gearbox gets: losses, steady state and a 20-minute warm-up with the backlash.

    python examples/07_gearbox_warm_up.py [OUTPUT_FOLDER]

The FZG type C gears in an illustrative, dip-lubricated housing (thermogear.gearbox.fzg_example: the gears are
the standard's, the housing, bearings and internal heat-transfer coefficients are assumptions listed in the
description's notes) at load stage 6, 2175 rpm, air at 20 °C. The thermal network gives the losses by source,
the steady temperatures of pinion, wheel, each shaft, oil and housing, and the warm-up from the ambient temperature
with a cast-iron and with an aluminium housing: the gears heat in minutes, the housing in tens of minutes, so
with aluminium (which grows faster than the steel gears) the backlash first closes and then reopens.
"""

from __future__ import annotations

import dataclasses
import sys
import tempfile
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # a script that only writes files: no window
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from thermogear.gearbox.description import GearboxOperatingPoint  # noqa: E402
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox  # noqa: E402
from thermogear.gearbox.mesh_loss import pair_gear_loss_factor  # noqa: E402
from thermogear.gearbox.model import GearboxThermalModel  # noqa: E402

POINT = GearboxOperatingPoint(speed_rpm=2175.0, torque=135.3, ambient_c=20.0)  # FZG load stage 6
DURATION_S = 1200.0


def main(out: Path) -> dict:
    out.mkdir(parents=True, exist_ok=True)
    cast_iron = illustrative_fzg_gearbox()
    aluminium = dataclasses.replace(cast_iron, housing=dataclasses.replace(
        cast_iron.housing, expansion=23e-6, specific_heat=900.0, mass=15.0))
    models = {"cast iron": GearboxThermalModel(cast_iron), "aluminium": GearboxThermalModel(aluminium)}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the oil's viscosity fit (40–100 °C) is extrapolated below 40 °C
        steady = {name: model.steady_state(POINT) for name, model in models.items()}
        histories = {name: model.warm_up(POINT, DURATION_S, points=121) for name, model in models.items()}
        long_aluminium = models["aluminium"].warm_up(POINT, 4 * 3600.0, points=241)

    # --- checks
    for name, state in steady.items():
        assert state.energy_residual < 1e-9, name  # heat shed = losses at steady state
        assert state.pinion_c > state.oil_c > state.housing_c > POINT.ambient_c, name
        history = histories[name]
        assert np.all(np.diff(history.node("oil")) > 0.0), name  # the oil only warms
        assert np.all(history.temperatures_c[:, -1] < state.temperatures_c), name  # not there after 20 min
    # the tooth loss uses Ohlendorf's H_V of the pair
    assert abs(models["cast iron"].losses(POINT).loss_factor - pair_gear_loss_factor(cast_iron.gear_pair)) < 1e-15
    # aluminium: the smallest backlash lies inside the warm-up, not at the steady state
    smallest, when = long_aluminium.smallest_backlash
    assert 0.0 < when < long_aluminium.times[-1] and smallest < long_aluminium.backlash[-1]

    # --- figure
    figure, axes = plt.subplots(1, 3, figsize=(12.0, 3.8), constrained_layout=True)
    minutes = histories["cast iron"].times / 60.0
    for node, color in zip(("pinion", "wheel", "pinion_shaft", "wheel_shaft", "oil", "housing"),
                           ("tab:red", "tab:orange", "tab:purple", "tab:pink", "tab:blue", "tab:gray")):
        axes[0].plot(minutes, histories["cast iron"].node(node), color=color, label=node.replace("_", " "))
    axes[0].set(xlabel="time [min]", ylabel="temperature [°C]", title="warm-up, cast-iron housing")
    axes[0].legend(fontsize=8)
    history = histories["cast iron"]
    for values, label in ((history.mesh_loss, "tooth friction"), (history.bearing_loss, "bearings"),
                          (history.seal_loss, "seals"), (history.churning_loss, "churning")):
        axes[1].plot(minutes, values, label=label)
    axes[1].set(xlabel="time [min]", ylabel="power loss [W]", title="losses by source")
    axes[1].legend(fontsize=8)
    for name, color in (("cast iron", "tab:gray"), ("aluminium", "tab:orange")):
        axes[2].plot(minutes, histories[name].backlash * 1e6, color=color, label=f"{name} housing")
    axes[2].set(xlabel="time [min]", ylabel="normal backlash [μm]", title="backlash")
    axes[2].legend(fontsize=8)
    figure.suptitle("FZG type C gears in an illustrative housing, 135.3 N·m at 2175 rpm, air 20 °C", fontsize=10)
    path = out / "example_07_gearbox_warm_up.png"
    figure.savefig(path, dpi=110)
    plt.close(figure)
    state = steady["cast iron"]
    print(f"steady (cast iron): pinion {state.pinion_c:.1f}, wheel {state.wheel_c:.1f}, oil {state.oil_c:.1f}, "
          f"housing {state.housing_c:.1f} °C; losses {state.losses.total:.0f} W, efficiency "
          f"{state.losses.efficiency * 100:.2f} %; aluminium smallest backlash {smallest * 1e6:.1f} μm after "
          f"{when / 60:.0f} min; figure: {path}")
    return {"steady": steady, "histories": histories, "figure": path}


if __name__ == "__main__":
    # without a folder argument the output goes to the temporary directory, never into the folder the script is
    # run from (a checkout's root would gain an untracked folder)
    default = Path(tempfile.gettempdir()) / "thermogear-examples" / Path(__file__).stem
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else default)
