"""Fig. 4 of Luo & Li (2020): elastic and thermal stiffness and compliance of a pair and of each tooth along Γ.

Per unit face width, as the paper plots them: stiffness in N/(mm·μm), compliance in mm·μm/N.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from thermogear.summaries.thermal import ThermalCurves

#: m/N total → mm·μm/N per unit face width (δ·b)
_COMPLIANCE_SCALE = 1e9


def plot_thermal_curves(curves: "ThermalCurves", name: str, axes=None):
    """Four panels: (a) k_e and k_T; (b) δ_e and δ_T; (c) driving tooth δ_e1 and δ_T1; (d) driven tooth δ_e2
    and δ_T2, along Γ with the points A–E marked; ``name`` (the case's) heads the title. ``axes``: four
    matplotlib axes, or None for a new figure. Returns the figure."""
    import matplotlib.pyplot as plt  # noqa: PLC0415

    curve, points = curves.curve, curves.points
    width = curves.face_width  # totals → per unit face width
    gamma = curve.gamma
    if axes is None:
        figure, grid = plt.subplots(2, 2, figsize=(10, 7), constrained_layout=True)
        axes = grid.ravel()
    else:
        figure = axes[0].figure
    stiffness_scale = 1e-9 / width
    compliance_scale = _COMPLIANCE_SCALE * width
    panels = [
        (axes[0], curve.elastic_stiffness * stiffness_scale, curve.stiffness * stiffness_scale,
         r"$k_e$", r"$k_T$", "pair stiffness [N/(mm·μm)]", "(a) meshing stiffness"),
        (axes[1], curve.elastic_compliance * compliance_scale, curve.compliance * compliance_scale,
         r"$\delta_e$", r"$\delta_T$", "pair compliance [mm·μm/N]", "(b) meshing compliance"),
        (axes[2], curve.result.elastic_pinion_compliance * compliance_scale,
         curve.pinion_compliance * compliance_scale, r"$\delta_{e1}$", r"$\delta_{T1}$",
         "tooth compliance [mm·μm/N]", "(c) driving tooth"),
        (axes[3], curve.result.elastic_wheel_compliance * compliance_scale,
         curve.wheel_compliance * compliance_scale, r"$\delta_{e2}$", r"$\delta_{T2}$",
         "tooth compliance [mm·μm/N]", "(d) driven tooth"),
    ]
    for ax, elastic, thermal, elastic_label, thermal_label, ylabel, title in panels:
        ax.plot(gamma, elastic, color="tab:blue", label=elastic_label + " (elastic)")
        ax.plot(gamma, thermal, color="tab:red", linestyle="--", label=thermal_label + " (thermal)")
        for name, value in zip(curves.point_names, points.gamma):
            ax.axvline(value, color="0.8", linewidth=0.8, zorder=0)
            ax.annotate(name, (value, 1.0), xycoords=("data", "axes fraction"), ha="center", va="bottom",
                        fontsize=8)
        ax.set_xlabel(r"contact position $\Gamma$")
        ax.set_ylabel(ylabel)
        ax.set_title(title, loc="left", fontsize=10, pad=14)
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    drop = points.drop_percent
    figure.suptitle(f"{name} thermal stiffness (Luo & Li Fig. 4): X_te = {curve.x_te:.4g} ({curve.load_basis} load), "
                    f"drop A {drop[0]:.2f} %, C {drop[2]:.2f} %, E {drop[4]:.2f} %", fontsize=10)
    return figure


def save_figure_atomically(figure, path) -> None:
    """Save a figure to ``path`` through a temporary file in the same folder and an atomic rename; the
    format follows the suffix (.png, .svg, .pdf). Closes the figure."""
    import matplotlib.pyplot as plt  # noqa: PLC0415

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(prefix=f".{path.stem}.", suffix=path.suffix or ".png", dir=path.parent)
    os.close(handle)
    try:
        figure.savefig(temporary, dpi=150)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise
    finally:
        plt.close(figure)
