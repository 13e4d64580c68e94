"""The figure of a drivetrain backlash sweep: Kv and the DTE peak-to-peak against speed, the up and the down branch
of each model, the jumps marked where each branch leaves its orbit."""

from __future__ import annotations

import numpy as np

__all__ = ["plot_drivetrain_branches"]

_STYLES = {"up": ("-", "^"), "down": ("--", "v")}


def plot_drivetrain_branches(sweep):
    """Kv (top) and DTE peak-to-peak [μm] (bottom) of the valid points against the pinion speed [rpm], one curve
    per model and direction (up: solid, ▲; down: dashed, ▼), each direction's jumps as a vertical line (dotted
    for the up sweep, dash-dotted for the down sweep) and the bands where the branches differ shaded. Returns the
    figure."""
    import matplotlib.pyplot as plt

    data = sweep.dataset
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8.0, 6.0), sharex=True, constrained_layout=True)
    speeds = data["speed_rpm"].values
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for index, model in enumerate(data["model"].values):
        colour = colours[index % len(colours)]
        for direction in data["direction"].values:
            part = data.sel(model=model, direction=direction)
            valid = part["valid"].values
            line, marker = _STYLES[str(direction)]
            for axis, name in ((top, "kv"), (bottom, "dte_peak_to_peak_um")):
                axis.plot(speeds, np.where(valid, part[name].values, np.nan), line, marker=marker, markersize=3,
                          color=colour, label=f"{model}, {direction}")
        band = sweep.hysteresis.get(str(model), {})
        for low, high in band.get("bands_rpm", []):
            for axis in (top, bottom):
                axis.axvspan(low, high, color=colour, alpha=0.08, linewidth=0)
        for direction, style in (("up", ":"), ("down", "-.")):
            for jump in band.get(f"{direction}_sweep_jumps", []):
                for axis in (top, bottom):
                    axis.axvline(jump["speed_rpm"], color=colour, linestyle=style, linewidth=1.0)
    top.set_ylabel("Kv [-]")
    bottom.set_ylabel("DTE peak-to-peak [μm]")
    bottom.set_xlabel("pinion speed [rpm]")
    top.legend(fontsize=8)
    top.set_title(f"{data.attrs['case']}: drivetrain with backlash, orbit followed up and down in speed "
                  f"({data.attrs['load_held']})\njumps: dotted up sweep, dash-dotted down sweep; shaded: the "
                  "branches differ", fontsize=9)
    if not np.any(data["valid"].values):
        top.text(0.5, 0.5, "no valid point", transform=top.transAxes, ha="center")
    return figure
