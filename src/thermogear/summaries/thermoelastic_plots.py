"""Figures of the thermo-elastic mesh: unloaded deviation along the path, loaded static transmission error and
load share over one mesh period, elastic and thermal. matplotlib is imported when a plot is asked for."""

from __future__ import annotations

import warnings

import numpy as np

from thermogear.errors import ExtrapolationWarning
from thermogear.thermoelastic.mesh import ThermoelasticMesh


def plot_thermoelastic(component: ThermoelasticMesh, ax=None, title: str = ""):
    """Three panels: (a) deviation e(Γ) of a pair [μm] by part, (b) loaded static TE δ(τ) [μm], (c) load share of
    each pair slot [–]; elastic (cold pair, tip reliefs only) dashed, thermal solid. ``ax``: three axes or None.
    Returns the figure."""
    import matplotlib.pyplot as plt  # noqa: PLC0415

    if ax is None:
        figure, ax = plt.subplots(1, 3, figsize=(15, 4.2), constrained_layout=True)
    else:
        figure = ax[0].figure
    hot = component.gear_pair
    roll = hot.roll_grid(401)
    gamma = hot.gamma(roll)
    parts = component.deviation_parts_at(roll)
    ax[0].plot(gamma, sum(parts.values()) * 1e6, color="k", label="total (thermal)")
    for name, values in parts.items():
        ax[0].plot(gamma, values * 1e6, lw=0.8, label=name.replace("_", " "))
    cold = component.cold_gear_pair
    ax[0].plot(cold.gamma(cold.roll_grid(401)), component.cold_pair_deviation_at(cold.roll_grid(401)) * 1e6,
               color="0.5", ls="--", label="elastic (relief only)")
    ax[0].set(xlabel="Γ", ylabel="deviation [μm] (+ = material missing)", title="Unloaded deviation of a pair")
    ax[0].legend(fontsize=8)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        results = {"thermal": component.loaded_transmission_error(),
                   "elastic": component.loaded_transmission_error(cold=True)}
    for label, style, color in (("thermal", "-", "k"), ("elastic", "--", "0.5")):
        grid, result = results[label]
        phase = grid.midpoints / grid.nodes[-1]
        ax[1].plot(phase, result.approach * 1e6, ls=style, color=color, label=label)
        for slot in range(result.load_share.shape[0]):
            share = np.where(grid.in_contact[slot], result.load_share[slot], np.nan)
            ax[2].plot(phase, share, ls=style, lw=0.9, label=f"{label} pair {slot}")
    ax[1].set(xlabel="τ / T_m", ylabel="loaded static TE δ [μm]", title="Loaded static transmission error")
    ax[1].legend()
    ax[2].set(xlabel="τ / T_m", ylabel="load share [–]", title="Load share of the pair slots", ylim=(-0.02, 1.02))
    ax[2].legend(fontsize=8)
    figure.suptitle(f"{title}: thermo-elastic mesh at {max(component.bulk_c):.1f} °C (housing "
                    f"{component.housing_c:.1f} °C)".lstrip(": "))
    return figure
