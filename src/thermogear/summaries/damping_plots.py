"""Luo & Li (2020) Figs. 7–8: friction damping per pair along Γ and c(τ) over a few mesh periods."""

from __future__ import annotations

import numpy as np

from thermogear.friction.damping import MODELS, damping_rule
from thermogear.summaries.damping import DampingSummary


def plot_damping(summary: DampingSummary, periods: int = 3, axes=None, paper: dict | None = None):
    """Luo & Li Figs. 7–8: per-pair damping along Γ and mesh damping c(τ) over a few mesh periods, elastic
    and thermal. ``paper``: the paper's mean dampings {model: {region: N·s/m}} (dotted lines under the paper's
    mesh rule; the caller passes them for a parameter set of the paper). Returns the matplotlib figure."""
    import matplotlib.pyplot as plt

    if axes is None:
        figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    else:
        figure = axes[0].figure
    show_paper = paper is not None and damping_rule(summary.rule).published  # the paper's means are of its rule
    styles = {"elastic": dict(color="tab:blue", label="elastic c_e (oil at reference temperature)"),
              "thermal": dict(color="tab:red", label="thermal c_r (oil at flank temperature)")}
    for model in MODELS:
        axes[0].plot(summary.path[model].gamma, summary.path[model].damping, **styles[model])
    axes[0].set_xlabel("contact position Γ [–]")
    axes[0].set_ylabel("damping of one tooth pair [N·s/m]")
    axes[0].set_title("per pair along the path")
    for model in MODELS:
        grid = summary.grids[model]
        period = grid.nodes[-1]
        times = np.concatenate([grid.nodes[:-1] + j * period for j in range(periods)] + [[periods * period]])
        values = np.tile(summary.mesh[model], periods)
        axes[1].stairs(values, times * 1e3, baseline=None, color=styles[model]["color"], label=model)
        if show_paper:
            for region in ("single", "double"):
                axes[1].axhline(paper[model][region], color=styles[model]["color"], lw=0.8, ls=":")
    axes[1].set_xlabel("time τ [ms]")
    axes[1].set_ylabel("mesh damping c(τ) [N·s/m]")
    title = f"mesh cycle, rule '{summary.rule}'"
    if show_paper:
        title += " (dotted: paper's means)"
    axes[1].set_title(title)
    axes[0].legend(loc="best", fontsize=8)
    axes[1].legend(loc="best", fontsize=8)
    figure.suptitle(f"Friction damping (Luo & Li Eqs. 26–28), case {summary.case_name}")
    return figure


__all__ = ["plot_damping"]
