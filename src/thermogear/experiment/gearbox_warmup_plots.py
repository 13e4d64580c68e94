"""Figure of a predicted gearbox warm-up: temperatures, losses by source, backlash, mean mesh stiffness, natural
frequency and Kv against time (six panels sharing the time axis)."""

from __future__ import annotations

import numpy as np

from thermogear.gearbox.losses import NODES


def plot_gearbox_warmup(result):
    """The six panels of a :class:`~thermogear.experiment.gearbox_warmup.GearboxWarmupResult`; returns the
    figure."""
    import matplotlib.pyplot as plt  # noqa: PLC0415

    history = result.history
    minutes = history.times / 60.0
    figure, axes = plt.subplots(3, 2, figsize=(10, 8.5), sharex=True, layout="constrained")
    ax = axes[0, 0]
    for name in NODES:
        ax.plot(minutes, history.node(name), label=name.replace("_", " "))
    ax.axhline(result.ambient_c, color="0.5", lw=0.8, ls=":", label="ambient")
    ax.set_ylabel("temperature [°C]")
    ax.legend(fontsize=7, ncol=2)
    ax = axes[0, 1]
    for values, label in ((history.mesh_loss, "tooth friction"), (history.bearing_loss, "bearings"),
                          (history.seal_loss, "seals"), (history.churning_loss, "churning"),
                          (history.total_loss, "total")):
        ax.plot(minutes, values, label=label, lw=1.6 if label == "total" else 1.0)
    ax.set_ylabel("power loss [W]")
    ax.legend(fontsize=7)
    ax = axes[1, 0]
    ax.plot(minutes, history.backlash * 1e6, color="C3")
    smallest, at = result.smallest_backlash
    ax.plot(at / 60.0, smallest * 1e6, "v", color="C3", label=f"smallest {smallest * 1e6:.1f} μm")
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_ylabel("normal backlash [μm]")
    ax.legend(fontsize=7)
    evaluated = [state for state in result.states if state.mesh_stiffness_mean is not None]
    state_minutes = np.array([state.time_s for state in evaluated]) / 60.0
    panels = ((axes[1, 1], [state.mesh_stiffness_mean * 1e-6 for state in evaluated],
               "mean mesh stiffness [N/μm]"),
              (axes[2, 0], [state.natural_frequency_hz for state in evaluated], "natural frequency [Hz]"),
              (axes[2, 1], [np.nan if state.kv is None else state.kv for state in evaluated], "Kv [–]"))
    for ax, values, label in panels:
        ax.plot(state_minutes, values, ".-", ms=3)
        ax.set_ylabel(label)
    for ax in axes[2]:
        ax.set_xlabel("time [min]")
    figure.suptitle(f"{result.case_name}: predicted warm-up at {result.speed_rpm:g} rpm, {result.torque:g} N·m "
                    f"(start {result.start_c:g} °C, ambient {result.ambient_c:g} °C)", fontsize=10)
    return figure
