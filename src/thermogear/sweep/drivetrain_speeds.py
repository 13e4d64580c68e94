"""The figure of a drivetrain's speed study (linear mesh): Kv and the bearing forces per speed, mesh-dominated
resonances marked. The study itself (each speed's exact periodic response on the modal reduction of the drivetrain,
the speeds of one task sharing the rigid-body reduction and the modal basis) is
:mod:`thermogear.sweep.drivetrain_study`, run by ``thermogear sweep`` and ``thermogear.sweep(case, ...)``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["plot_drivetrain_sweep"]


def plot_drivetrain_sweep(sweep):
    """Kv and the largest first-harmonic bearing force against speed, invalid points left out, the mesh-dominated
    resonances (harmonic j meets a mode) as dashed lines; ``sweep``: a drivetrain study's ``dataset`` (one group:
    dims model × speed_rpm [× bearing × harmonic]) and ``resonances`` (model → crossings), as
    :func:`~thermogear.sweep.drivetrain_run.run_drivetrain_study` returns them. Returns the figure."""
    import matplotlib.pyplot as plt

    data = sweep.dataset
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8.0, 6.0), sharex=True, constrained_layout=True)
    for index, model in enumerate(data["model"].values):
        valid = data["valid"].values[index]
        speeds = data["speed_rpm"].values
        kv = np.where(valid, data["kv"].values[index], np.nan)
        first = np.where(valid, np.nanmax(data["bearing_harmonic_amplitude_n"].values[index, :, :, 0], axis=1),
                         np.nan)
        style = "-" if index == 0 else "--"
        top.plot(speeds, kv, style, label=str(model))
        bottom.plot(speeds, first, style, label=str(model))
        for resonance in sweep.resonances.get(str(model), []) if index == 0 else ():  # cold modes (hot: table)
            dominated = resonance["mesh_dominated"]
            for axis in (top, bottom):
                axis.axvline(resonance["speed_rpm"], color="0.3" if dominated else "0.7",
                             linestyle="--" if dominated else ":", linewidth=1.0)
            top.annotate(f"{resonance['harmonic']}× {resonance['mode_hz']:.0f} Hz", (resonance["speed_rpm"], 1.0),
                         xycoords=("data", "axes fraction"), fontsize=7, rotation=90, va="top", ha="right",
                         color="0.2" if dominated else "0.5")
    top.set_ylabel("Kv [-]")
    bottom.set_ylabel("largest bearing force, 1× mesh [N]")
    bottom.set_xlabel("pinion speed [rpm]")
    top.legend(fontsize=8)
    top.set_title(f"{data.attrs['case']}: drivetrain speed sweep ({data.attrs['load_held']}); mesh harmonic meets a "
                  f"mode: dashed mesh-dominated, dotted mesh-coupled ({data['model'].values[0]} modes)", fontsize=9)
    if not np.any(data["valid"].values):
        top.text(0.5, 0.5, "no valid point", transform=top.transAxes, ha="center")
    return figure
