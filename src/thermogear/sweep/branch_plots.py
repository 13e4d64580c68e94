"""The speed response of a nonlinear-mesh branch study: both sweep directions, contact loss and back-flank impacts
marked, the linear natural frequency for reference."""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["plot_branches"]

_STYLE = {"up": dict(color="tab:blue", ls="-", label="speed up"),
          "down": dict(color="tab:red", ls="--", label="speed down")}


def plot_branches(dataset, model: str | None = None, select: dict[str, Any] | None = None, axes=None):
    """Two panels against the pinion speed [rpm]: the DTE peak-to-peak [μm] and Kv of the up and the down branch;
    points where the teeth lose contact are dotted, back-flank impacts crossed. ``model``: the dataset's first by
    default; ``select``: values of other parameters (their first value otherwise). Returns the figure."""
    import matplotlib.pyplot as plt  # noqa: PLC0415

    model = str(dataset["model"].values[0]) if model is None else model
    part = dataset.sel(model=model)
    extra = {d: 0 for d in part["kv"].dims if d not in ("direction", "speed_rpm")}
    part = part.isel(extra) if not select else part.sel(select)
    speeds = np.asarray(dataset["speed_rpm"].values, dtype=float)
    if axes is None:
        figure, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True, constrained_layout=True)
    else:
        figure = axes[0].figure
    for direction in part["direction"].values:
        branch = part.sel(direction=direction)
        style = _STYLE[str(direction)]
        for ax, quantity, scale in ((axes[0], "dte_peak_to_peak", 1e6), (axes[1], "kv", 1.0)):
            values = np.asarray(branch[quantity].values, dtype=float) * scale
            ax.plot(speeds, values, lw=1.5, **style)
            loss = np.asarray(branch["contact_loss_fraction"].values) > 0
            ax.plot(speeds[loss], values[loss], ".", ms=3, color=style["color"])
            impact = np.asarray(branch["back_side_contact"].values) == 1
            ax.plot(speeds[impact], values[impact], "x", ms=4, color=style["color"])
    axes[0].set_ylabel("DTE peak-to-peak [μm]")
    axes[1].set_ylabel("Kv [–]")
    axes[1].set_xlabel("pinion speed [rpm]")
    axes[0].plot([], [], ".", color="0.3", label="contact loss")
    axes[0].plot([], [], "x", color="0.3", label="back-flank impacts")
    axes[0].legend(fontsize="small", loc="upper right")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    figure.suptitle(f"{dataset.attrs.get('case', '')}: nonlinear mesh, {model} model — branches up and down")
    return figure
