"""The speed response of a nonlinear-mesh branch study: both models and both sweep directions on one figure, the
points without a converged orbit marked, contact loss and back-flank impacts shown, and the speeds where a
mesh-frequency order meets each model's natural frequency marked."""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.sweep.plot_layout import label_speeds, mark_invalid, scale_to_valid

__all__ = ["plot_branches"]

_MODEL_COLOR = {"elastic": "tab:blue", "thermal": "tab:red"}
_DIRECTION_STYLE = {"up": dict(ls="-", lw=1.6), "down": dict(ls="--", lw=1.4)}
_PANELS = (("dte_peak_to_peak", "DTE peak-to-peak [μm]", 1e6), ("kv", "Kv [–]", 1.0))


def _natural_speeds(part, model: str, orders) -> dict[int, float]:
    """n_j = 60·f_n/(z1·j) [rpm] of a model (f_n of the linear mesh with every pair in contact); none for a store
    written before f_n was kept."""
    if "natural_frequency_hz" not in part:
        return {}
    natural = np.asarray(part["natural_frequency_hz"].sel(model=model), dtype=float)
    ratio = np.asarray(part["mesh_frequency_hz"] / part["speed_rpm"] * 60.0, dtype=float)
    if not (np.isfinite(natural).any() and np.isfinite(ratio).any()):
        return {}
    f_n, teeth = float(np.nanmedian(natural)), float(np.nanmedian(ratio))
    return {int(j): 60.0 * f_n / (teeth * j) for j in orders}


def plot_branches(dataset, model: str | None = None, select: dict[str, Any] | None = None, axes=None,
                  orders=(1, 2)):
    """Two panels against the pinion speed [rpm]: the DTE peak-to-peak [μm] and Kv of the up (solid) and the down
    (dashed) branch of every model (``model``: one of them only), elastic blue, thermal red. Points where the
    teeth lose contact are dotted, back-flank impacts crossed; points without a converged orbit (non-periodic,
    failed) are left out of the curves and drawn pale (on the edge where beyond the axis, which is scaled to the
    converged points); jammed points are absent. Dotted vertical lines: the speeds where order j of the mesh
    frequency meets each model's natural frequency (j·f_m = f_n, the linear primary resonance at j = 1).
    ``select``: values of the other parameters of a grid (their first values otherwise). Returns the figure."""
    import matplotlib.pyplot as plt  # noqa: PLC0415

    models = [str(m) for m in dataset["model"].values] if model is None else [model]
    part = dataset.sel(model=models)
    extra = {d: 0 for d in part["kv"].dims if d not in ("direction", "model", "speed_rpm")}
    if select:
        part = part.sel(select)
        extra = {d: i for d, i in extra.items() if d not in select}
    part = part.isel(extra) if extra else part
    speeds = np.asarray(part["speed_rpm"].values, dtype=float)
    if axes is None:
        figure, axes = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    else:
        figure = axes[0].figure
    marks = []
    for name in models:
        color = _MODEL_COLOR.get(name, "tab:green")
        marks += [(speed, f"j={j} {name[0]}", color) for j, speed in _natural_speeds(part, name, orders).items()]
    for ax, (quantity, label, scale) in zip(axes, _PANELS):
        converged = np.asarray(part["converged"].transpose("direction", "model", "speed_rpm").values) == 1
        values_all = np.asarray(part[quantity].transpose("direction", "model", "speed_rpm").values) * scale
        limits = scale_to_valid(ax, values_all[converged])
        for d_index, direction in enumerate(part["direction"].values):
            style = _DIRECTION_STYLE[str(direction)]
            branch = part.sel(direction=direction)
            for m_index, name in enumerate(models):
                color = _MODEL_COLOR.get(name, "tab:green")
                values, good = values_all[d_index, m_index], converged[d_index, m_index]
                ax.plot(speeds, np.where(good, values, np.nan), color=color, label=f"{name}, speed {direction}",
                        **style)
                mark_invalid(ax, speeds[~good], values[~good], limits, color=color)
                row = branch.sel(model=name)
                loss = good & (np.asarray(row["contact_loss_fraction"].values) > 0)
                ax.plot(speeds[loss], values[loss], ".", ms=3, color=color)
                impact = good & (np.asarray(row["back_side_contact"].values) == 1)
                ax.plot(speeds[impact], values[impact], "x", ms=4, color=color)
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.set_xlim(speeds.min(), speeds.max())
    label_speeds(axes[0], marks)
    for speed, _, color in marks:
        if speeds.min() <= speed <= speeds.max():
            axes[1].axvline(speed, color=color, linewidth=0.7, alpha=0.6, linestyle=":")
    axes[1].set_xlabel("pinion speed [rpm]")
    axes[0].plot([], [], ".", color="0.3", label="contact loss")
    axes[0].plot([], [], "x", color="0.3", label="back-flank impacts")
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="lower center", ncol=3, fontsize=8, frameon=False,
                  title="dotted, j=…: j·f_m = f_n of the linear mesh (e elastic, t thermal); pale: no converged "
                        "orbit (▲: beyond the axis)", title_fontsize=7)
    chosen = {d: part[d].values.item() for d in extra}
    chosen.update(select or {})
    where = "; " + ", ".join(f"{k} = {v:g}" for k, v in chosen.items()) if chosen else ""
    figure.suptitle(f"{dataset.attrs.get('case', '')}: nonlinear mesh, branches up and down "
                    f"(load: {dataset.attrs.get('load', 'constant torque')}){where}", fontsize=10)
    figure.tight_layout(rect=(0, 0.1, 1, 1))
    return figure
