"""Plots of a study: responses against speed (elastic and thermal on one axes), resonance orders, 2-D maps.

A resonance of the mesh (parametrically excited by k(τ) at the mesh frequency f_m = z1·n1/60) is expected where a
harmonic of the mesh frequency meets the natural frequency, j·f_m = f_n, i.e. at the pinion speed
n_j = 60·f_n/(z1·j) (order j = 1 main resonance, j = 2, 3 … super-harmonic ones). The speed plots mark these
speeds for each model (the thermal model's are lower: k_T < k_e lowers f_n) and label the peaks found.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.sweep.plot_layout import label_speeds, mark_invalid, scale_to_valid

__all__ = ["QUANTITY_LABELS", "find_resonance", "linear_model_valid", "plot_map", "plot_speed_response",
           "resonance_peaks", "resonance_speeds", "unstable_bands"]

#: Axis labels and display scale of the plotted quantities.
QUANTITY_LABELS: dict[str, tuple[str, float]] = {
    "kv": ("Kv [–]", 1.0),
    "dte_rms": ("RMS DTE [μm]", 1e6),
    "dte_peak_to_peak": ("peak-to-peak DTE [μm]", 1e6),
    "max_system_load_ratio": ("max dynamic load / static load [–]", 1.0),
    "max_pair_load": ("max pair dynamic load [N]", 1.0),
    "dte_mean": ("mean DTE [μm]", 1e6),
    "max_velocity": ("max |dx/dt| [m/s]", 1.0),
    "floquet_multiplier_max": ("largest Floquet multiplier [–]", 1.0),
}
_MODEL_STYLE = {"elastic": {"color": "tab:blue", "linestyle": "-"},
                "thermal": {"color": "tab:red", "linestyle": "--"}}
SPEED = "speed_rpm"


def _select(dataset, select: dict[str, Any] | None, keep: tuple[str, ...]):
    """Pick one value of every dimension other than ``keep`` and ``model`` (given, or the first one)."""
    chosen: dict[str, Any] = dict(select or {})
    for dim in dataset.dims:
        if dim not in keep and dim not in ("model", "chunk") and dim not in chosen:
            chosen[dim] = dataset[dim].values[0]
    picked = dataset.sel(chosen) if chosen else dataset
    return picked, chosen


def linear_model_valid(dataset):
    """Per model and point: True where the linear mesh model holds (a stable periodic steady state and no contact
    loss, gears not jammed). ``dataset``: a study's Dataset, or a mapping of its ``stable``, ``contact_loss`` and
    ``jammed`` NumPy arrays.
    Elsewhere Kv and the other responses are those of teeth that would separate or of an unstable solution (Kv of
    several hundred), not of the gear pair: summaries leave them out and plots mark them."""
    valid = (dataset["stable"] == 1) & (dataset["contact_loss"] == 0)
    if "jammed" in dataset:  # stores written before the flag existed have none
        valid = valid & (dataset["jammed"] == 0)
    return valid


def _pinion_teeth(dataset) -> float:
    ratio = dataset["mesh_frequency_hz"] / dataset[SPEED] * 60.0
    return float(np.nanmedian(np.asarray(ratio)))


def resonance_speeds(dataset, model: str, orders=(1, 2, 3), select: dict[str, Any] | None = None) -> dict[int, float]:
    """Pinion speeds n_j = 60·f_n/(z1·j) [rpm] where order j of the mesh frequency meets f_n (per model)."""
    picked, _ = _select(dataset, select, keep=(SPEED,))
    natural = float(np.nanmedian(picked["natural_frequency_hz"].sel(model=model)))
    teeth = _pinion_teeth(picked)
    return {int(j): 60.0 * natural / (teeth * j) for j in orders}


def resonance_peaks(dataset, model: str, quantity: str = "kv", select: dict[str, Any] | None = None,
                    prominence: float = 0.05) -> list[dict[str, float]]:
    """Local maxima of ``quantity`` against speed for one model: speed, value, and the nearest order j of the
    mesh frequency (f_n/f_m) with the relative distance of the peak from that order's predicted speed."""
    from scipy.signal import find_peaks

    picked, _ = _select(dataset, select, keep=(SPEED,))
    curve = picked[quantity].sel(model=model)
    values = np.asarray(curve, dtype=float)
    speeds = np.asarray(picked[SPEED], dtype=float)
    finite = np.where(np.isfinite(values), values, np.nanmin(values))
    span = float(np.nanmax(values) - np.nanmin(values)) or 1.0
    indices, _ = find_peaks(finite, prominence=prominence * span)
    predicted = resonance_speeds(dataset, model, orders=range(1, 11), select=select)
    natural = float(np.nanmedian(picked["natural_frequency_hz"].sel(model=model)))
    peaks = []
    for index in indices:
        mesh = float(picked["mesh_frequency_hz"].values[index])
        order = max(int(round(natural / mesh)), 1)
        expected = predicted.get(order, 60.0 * natural / (_pinion_teeth(picked) * order))
        peaks.append({"speed_rpm": float(speeds[index]), "value": float(values[index]), "order": order,
                      "predicted_speed_rpm": expected,
                      "relative_offset": float(speeds[index] / expected - 1.0)})
    return peaks


def unstable_bands(dataset, model: str, select: dict[str, Any] | None = None) -> list[tuple[float, float]]:
    """Speed ranges [rpm] (first and last swept speed) where the model has no stable periodic steady state
    (parametric instability: a Floquet multiplier of modulus >= 1)."""
    picked, _ = _select(dataset, select, keep=(SPEED,))
    unstable = np.asarray(picked["stable"].sel(model=model)) == 0
    speeds = np.asarray(picked[SPEED], dtype=float)
    bands, start = [], None
    for index, flag in enumerate(unstable):
        if flag and start is None:
            start = index
        if start is not None and (not flag or index == unstable.size - 1):
            stop = index if flag else index - 1
            bands.append((float(speeds[start]), float(speeds[stop])))
            start = None
    return bands


def find_resonance(dataset, model: str, order: int = 1, quantity: str = "kv",
                   select: dict[str, Any] | None = None) -> dict[str, Any]:
    """The resonance of one mesh-frequency order in a speed sweep, beside its prediction n_j = 60·f_n/(z1·j).

    Where the response is parametrically unstable near the prediction (lightly damped mesh: the instability
    tongue around j·f_m = f_n), the resonance is the centre of that unstable band; otherwise the largest value
    of ``quantity`` within ±25 % of the prediction.
    """
    predicted = resonance_speeds(dataset, model, (order,), select=select)[order]
    bands = [b for b in unstable_bands(dataset, model, select) if b[0] <= 1.25 * predicted and b[1] >= 0.75 * predicted]
    if bands:
        band = min(bands, key=lambda b: abs(0.5 * (b[0] + b[1]) - predicted))
        found, kind = 0.5 * (band[0] + band[1]), "unstable band"
    else:
        picked, _ = _select(dataset, select, keep=(SPEED,))
        speeds = np.asarray(picked[SPEED], dtype=float)
        values = np.asarray(picked[quantity].sel(model=model), dtype=float)
        window = (speeds >= 0.75 * predicted) & (speeds <= 1.25 * predicted) & np.isfinite(values)
        if not np.any(window):
            raise ValueError(f"no swept speed within 25 % of the predicted resonance {predicted:.1f} rpm")
        index = np.flatnonzero(window)[np.argmax(values[window])]
        found, kind, band = float(speeds[index]), f"maximum of {quantity}", None
    return {"model": model, "order": order, "predicted_speed_rpm": predicted, "speed_rpm": found, "kind": kind,
            "band_rpm": band, "relative_offset": found / predicted - 1.0}


def plot_speed_response(dataset, quantities=("kv", "dte_rms", "dte_peak_to_peak", "max_system_load_ratio"),
                        select: dict[str, Any] | None = None, orders=(1, 2, 3), ax=None):
    """Quantities against pinion speed, elastic and thermal on the same axes, resonance orders marked.

    ``select`` fixes the other swept parameters (default: their first value). ``ax``: one axes per quantity (a
    sequence) or None for a new figure. Returns the figure.
    """
    import matplotlib.pyplot as plt

    if SPEED not in dataset.dims:
        raise ValueError("plot_speed_response needs a study that varies speed_rpm")
    picked, chosen = _select(dataset, select, keep=(SPEED,))
    quantities = tuple(quantities)
    if ax is None:
        figure, axes = plt.subplots(len(quantities), 1, sharex=True, figsize=(8.0, 2.4 * len(quantities) + 0.6),
                                    squeeze=False)
        axes = list(axes[:, 0])
    else:
        axes = list(np.atleast_1d(ax))
        figure = axes[0].figure
    speeds = np.asarray(picked[SPEED], dtype=float)
    valid = linear_model_valid(picked)
    marks = []
    for model in picked["model"].values:
        color = _MODEL_STYLE.get(str(model), {}).get("color", "grey")
        for order, speed in resonance_speeds(dataset, str(model), orders, select=chosen).items():
            marks.append((speed, f"j={order} {str(model)[0]}", color))
    for axis, quantity in zip(axes, quantities):
        label, scale = QUANTITY_LABELS.get(quantity, (quantity, 1.0))
        holds_values = []
        for model in picked["model"].values:
            values = np.asarray(picked[quantity].sel(model=model), dtype=float) * scale
            holds = np.asarray(valid.sel(model=model), dtype=bool)
            holds_values.append(values[holds])
        limits = scale_to_valid(axis, np.concatenate(holds_values) if holds_values else [])
        for model in picked["model"].values:
            style = _MODEL_STYLE.get(str(model), {})
            values = np.asarray(picked[quantity].sel(model=model), dtype=float) * scale
            holds = np.asarray(valid.sel(model=model), dtype=bool)
            axis.plot(speeds, np.where(holds, values, np.nan), label=str(model), **style)
            lost = ~holds & np.isfinite(values)
            if lost.any():  # contact loss: the linear model's number, greyed (on the edge beyond the valid range)
                mark_invalid(axis, speeds[lost], values[lost], limits,
                             label=f"{model}: contact loss (linear model invalid)", color=style.get("color", "grey"))
            for low, high in unstable_bands(dataset, str(model), select=chosen):
                axis.axvspan(low, high, color=style.get("color", "grey"), alpha=0.12, linewidth=0)
        axis.set_ylabel(label)
        axis.grid(True, alpha=0.3)
        axis.set_xlim(speeds.min(), speeds.max())
    label_speeds(axes[0], marks)
    for axis in axes[1:]:
        for speed, _, color in marks:
            if speeds.min() <= speed <= speeds.max():
                axis.axvline(speed, color=color, linewidth=0.7, alpha=0.6, linestyle=":")
    handles, labels = axes[0].get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    figure.legend(unique.values(), unique.keys(), loc="lower center", ncol=2, fontsize=8, frameon=False,
                  title="shaded: no stable periodic response (parametric instability); pale x: the linear model "
                        "does not hold (▲: beyond the axis)\ndotted, j=…: mesh-frequency order j meets the natural "
                        "frequency, j·f_m = f_n (e elastic, t thermal)",
                  title_fontsize=7)
    axes[-1].set_xlabel("pinion speed [rpm]")
    title = f"load: {dataset.attrs.get('load', 'constant torque')}"
    if chosen:
        title += "; " + ", ".join(f"{k} = {v:g}" if isinstance(v, (int, float, np.number)) else f"{k} = {v}"
                                  for k, v in chosen.items())
    figure.suptitle(title, fontsize=9)
    figure.tight_layout(rect=(0, 0.09, 1, 1))
    return figure


def plot_map(dataset, quantity: str = "kv", x: str | None = None, y: str | None = None, model: str = "thermal",
             select: dict[str, Any] | None = None, ax=None):
    """Map of ``quantity`` over two swept parameters (default: the first two dimensions) for one model."""
    import matplotlib.pyplot as plt

    dims = [d for d in dataset[quantity].dims if d != "model"]
    x = x or (SPEED if SPEED in dims else dims[-1])
    y = y or next(d for d in dims if d != x)
    picked, chosen = _select(dataset, select, keep=(x, y))
    # points where the linear model does not hold (contact loss, instability) are left blank
    values = picked[quantity].where(linear_model_valid(picked)).sel(model=model).transpose(y, x)
    label, scale = QUANTITY_LABELS.get(quantity, (quantity, 1.0))
    if ax is None:
        figure, ax = plt.subplots(figsize=(7.0, 4.5))
    else:
        figure = ax.figure
    mesh = ax.pcolormesh(np.asarray(picked[x]), np.asarray(picked[y]), np.asarray(values, dtype=float) * scale,
                         shading="nearest")
    figure.colorbar(mesh, ax=ax, label=label)
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    title = f"{quantity} ({model}; blank: contact loss or unstable)"
    if chosen:
        title += " — " + ", ".join(f"{k} = {v}" for k, v in chosen.items())
    ax.set_title(title, fontsize=9)
    figure.tight_layout()
    return figure
