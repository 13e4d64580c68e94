"""Figures of the dynamic response in the layout of Luo & Li (2020) Figs. 9–12.

Each function takes a :class:`~thermogear.dynamics.response.DynamicResponse` and optionally a second one to
overlay (elastic vs thermal), draws on ``ax`` or a new figure, and returns the figure. A response that holds a
transient history is drawn over the whole run (start-up from rest, as in the paper), or over its last
``periods`` periods; a periodic orbit is repeated ``periods`` times (default 3). Time in ms, x in μm, ẋ in
mm/s, loads per unit face width in N/mm.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["MODEL_STYLES", "plot_displacement", "plot_loads", "plot_phase", "plot_spectrum", "plot_velocity"]

#: Line style of the first and the second response of a plot (elastic and thermal in the report): every dynamic
#: plot, linear or nonlinear, and the report's start-up panels use the same two.
MODEL_STYLES = ({"color": "tab:blue", "linestyle": "-"}, {"color": "tab:red", "linestyle": "--"})


def _axes(ax: Any):
    import matplotlib.pyplot as plt

    if ax is None:
        figure, ax = plt.subplots(figsize=(7.0, 4.0), constrained_layout=True)
        return figure, ax
    return ax.figure, ax


def _finished(figure, ax, xlabel: str, ylabel: str, legend_columns: int = 1):
    """The figure with its axis labels, legend (in ``legend_columns`` columns) and grid: how the figures over time
    and the phase portrait end."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize="small", ncol=legend_columns)
    ax.grid(True, alpha=0.3)
    return figure


def _series(response: Any, periods: int | None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(time, x, ẋ, interval) to draw: the history (or its last ``periods``) or the orbit repeated."""
    history = response.history
    if history is not None:
        if periods is None or periods >= history.periods:
            return history.time, history.displacement, history.velocity, history.interval
        stride = history.samples_per_period
        start = history.time.size - 1 - periods * stride
        return (history.time[start:], history.displacement[start:], history.velocity[start:],
                history.interval[start:])
    count = 3 if periods is None else max(1, int(periods))
    body = slice(0, -1)
    period = response.problem.period
    time = np.concatenate([response.time[body] + q * period for q in range(count)] + [[count * period]])
    x = np.concatenate([np.tile(response.displacement[body], count), response.displacement[-1:]])
    v = np.concatenate([np.tile(response.velocity[body], count), response.velocity[-1:]])
    interval = np.concatenate([np.tile(response.interval[body], count), response.interval[-1:]])
    return time, x, v, interval


def _with_jumps(time: np.ndarray, interval: np.ndarray, right: np.ndarray, left: np.ndarray
                ) -> tuple[np.ndarray, np.ndarray]:
    """Insert the left limit before every node sample so that jumps draw as vertical lines."""
    nodes = np.flatnonzero(interval[1:] != interval[:-1]) + 1
    order = np.concatenate([np.arange(time.size), nodes - 0.5])
    values = np.concatenate([right, left[..., nodes]], axis=-1)
    times = np.concatenate([time, time[nodes]])
    sort = np.argsort(order, kind="stable")
    return times[sort], values[..., sort]


def _label(response: Any, fallback: str) -> str:
    return response.label or fallback


def _responses(response: Any, other: Any) -> list[Any]:
    return [response] if other is None else [response, other]


def plot_displacement(response: Any, other: Any = None, ax: Any = None, periods: int | None = None):
    """Fig. 9: x(τ) [μm] against time [ms] with the static transmission error (dotted)."""
    figure, ax = _axes(ax)
    for number, item in enumerate(_responses(response, other)):
        style = MODEL_STYLES[number % 2]
        time, x, _, interval = _series(item, periods)
        ax.plot(time * 1e3, x * 1e6, label=_label(item, item.method), **style)
        static = item.problem.static_transmission_error
        t_static, static_values = _with_jumps(time, interval, static[interval],
                                              static[np.concatenate([[interval[0]], interval[:-1]])])
        ax.plot(t_static * 1e3, static_values * 1e6, color=style["color"], linestyle=":", linewidth=1.0,
                label=f"{_label(item, item.method)}: static TE")
    return _finished(figure, ax, "time [ms]", "transmission error x [μm]")


def plot_phase(response: Any, other: Any = None, ax: Any = None, periods: int | None = None):
    """Fig. 10: phase portrait ẋ [mm/s] against x [μm]; the steady orbit drawn bold."""
    figure, ax = _axes(ax)
    for number, item in enumerate(_responses(response, other)):
        style = MODEL_STYLES[number % 2]
        if item.history is not None:
            _, x, v, _ = _series(item, periods)
            ax.plot(x * 1e6, v * 1e3, linewidth=0.6, alpha=0.6, color=style["color"],
                    label=f"{_label(item, item.method)}: transient")
        ax.plot(item.displacement * 1e6, item.velocity * 1e3, linewidth=2.0, color=style["color"],
                linestyle=style["linestyle"], label=f"{_label(item, item.method)}: steady orbit")
        static = item.problem.static_transmission_error
        ax.plot(static * 1e6, np.zeros_like(static), "o", color=style["color"], markersize=5)
    return _finished(figure, ax, "transmission error x [μm]", "velocity ẋ [mm/s]")


def plot_velocity(response: Any, other: Any = None, ax: Any = None, periods: int | None = None):
    """Fig. 11: ẋ(τ) [mm/s] against time [ms]."""
    figure, ax = _axes(ax)
    for number, item in enumerate(_responses(response, other)):
        time, _, v, _ = _series(item, periods)
        ax.plot(time * 1e3, v * 1e3, label=_label(item, item.method), **MODEL_STYLES[number % 2])
    return _finished(figure, ax, "time [ms]", "velocity ẋ [mm/s]")


def plot_loads(response: Any, other: Any = None, ax: Any = None, periods: int | None = None):
    """Fig. 12: system and pair dynamic loads per unit face width [N/mm], with the static load (dotted)."""
    figure, ax = _axes(ax)
    for number, item in enumerate(_responses(response, other)):
        style = MODEL_STYLES[number % 2]
        problem = item.problem
        scale = 1.0 / problem.face_width / 1e3
        time, x, v, interval = _series(item, periods)
        previous = np.concatenate([[interval[0]], interval[:-1]])
        damping_on = item.include_damping_force

        def load(k: np.ndarray, c: np.ndarray, which: np.ndarray, damping_on: bool = damping_on) -> np.ndarray:
            values = k[..., which] * x
            return values + c[..., which] * v if damping_on else values

        name = _label(item, item.method)
        t_sys, system = _with_jumps(time, interval, load(problem.stiffness, problem.damping, interval),
                                    load(problem.stiffness, problem.damping, previous))
        ax.plot(t_sys * 1e3, system * scale, linewidth=1.6, label=f"{name}: system", **style)
        pair = problem.pair_arrays()
        if pair is not None:
            t_pair, pairs = _with_jumps(time, interval, load(pair[0], pair[1], interval),
                                        load(pair[0], pair[1], previous))
            for slot in range(pairs.shape[0]):
                ax.plot(t_pair * 1e3, pairs[slot] * scale, linewidth=0.9, alpha=0.8, color=style["color"],
                        linestyle=(0, (3, 1 + slot)), label=f"{name}: pair {slot}")
        ax.axhline(problem.static_load * scale, color=style["color"], linestyle=":", linewidth=1.0)
    return _finished(figure, ax, "time [ms]", "dynamic load per face width [N/mm]", legend_columns=2)


def plot_spectrum(response: Any, quantity: str = "displacement", ax: Any = None, harmonics: int = 20):
    """Harmonic amplitudes (orders of the mesh frequency 1 … ``harmonics``) of ``quantity``."""
    figure, ax = _axes(ax)
    frequencies, amplitudes = response.spectrum(quantity)
    amplitudes = np.atleast_2d(amplitudes)
    orders = np.arange(1, min(harmonics, frequencies.size - 1) + 1)
    width = 0.8 / amplitudes.shape[0]
    scale, unit = {"displacement": (1e6, "μm"), "velocity": (1e3, "mm/s")}.get(quantity, (1e-3, "kN"))
    for row in range(amplitudes.shape[0]):
        ax.bar(orders + row * width, amplitudes[row, orders] * scale, width=width,
               label=quantity if amplitudes.shape[0] == 1 else f"pair {row}")
    ax.set_xlabel("harmonic of the mesh frequency")
    ax.set_ylabel(f"amplitude [{unit}]")
    ax.legend(fontsize="small")
    return figure
