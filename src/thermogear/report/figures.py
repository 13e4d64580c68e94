"""The report's figures, named after the figures of Luo & Li (2020): 3c, 4, 6, 7, 8, 9, 10, 11, 12 (and 15).

:func:`report_figures` draws every figure it can from an :class:`~thermogear.report.evaluate.Evaluation` and
returns ``{name: figure}`` plus ``{name: reason}`` for those it cannot draw. Where the library has a plotting
function (thermal curves, dynamic response) it is used; this module only lays the panels out.
"""

from __future__ import annotations

from functools import partial
from typing import Any, Callable

import numpy as np

from thermogear.drivetrain.pictures import PICTURES as DRIVETRAIN_PICTURES
from thermogear.report.helical_section import draw_helical, helical_figure_absent

__all__ = ["FE_FIGURES", "FIG6_SPAN_MS", "FIGURES", "SHARED_FIGURES", "report_figures", "save_figure",
           "write_figures"]

#: Time span of the right panel of Fig. 6 [ms] (the paper's 0–5 ms).
FIG6_SPAN_MS = 5.0

#: Figure name → caption.
FIGURES: dict[str, str] = {
    "fig3c": "Fig. 3(c) — flank temperature of the driving tooth along the path of contact Γ (temperature input).",
    "fig4": "Fig. 4 — elastic and thermal stiffness and compliance along Γ: pair and single teeth (the paper's "
            "model); under the thermo-elastic model: unloaded deviation along Γ, loaded static transmission error "
            "and load share over one mesh period, elastic (dashed) and thermal (solid).",
    "fig6": "Fig. 6 — per-pair and total mesh stiffness per width over one mesh cycle (left) and over 0–5 ms "
            "(right).",
    "fig7": "Fig. 7 — friction damping with oil at the reference temperature (elastic model, c_e).",
    "fig8": "Fig. 8 — friction damping with oil at the flank temperature (thermal model, c_r).",
    "fig9": "Fig. 9 — dynamic transmission error: start-up from rest (left) and two steady-state mesh periods "
            "(right), elastic and thermal, with the static transmission error (dotted).",
    "fig10": "Fig. 10 — phase portrait ẋ against x from rest, elastic and thermal.",
    "fig11": "Fig. 11 — velocity ẋ: start-up from rest (left) and two steady-state mesh periods (right), elastic "
             "and thermal.",
    "fig12": "Fig. 12 — dynamic pair and system loads per unit face width in the steady state (three periods).",
    "fig15": "Fig. 15 — FE verification of the elastic and thermal stiffness along Γ.",
    "helical": "Helical pair — contact lines on the plane of action, mean line load across the face cold and hot "
               "with the temperature across it, mesh stiffness K_t per width and loaded static TE over one period.",
    **DRIVETRAIN_PICTURES,
}

_COLORS = {"elastic": "tab:blue", "thermal": "tab:red"}


def _pyplot():
    import matplotlib.pyplot as plt

    return plt


def _stairs(ax, values, edges, **style):
    """A piecewise-constant curve (``values`` between ``edges``) drawn as one line with vertical jumps: the shape
    of :meth:`~matplotlib.axes.Axes.stairs` without a patch, whose data limits matplotlib updates segment by
    segment in Python (seconds for the 0–5 ms panel of Fig. 6)."""
    edges, values = np.asarray(edges), np.asarray(values)
    return ax.plot(np.repeat(edges, 2)[1:-1], np.repeat(values, 2), **style)


def _mark_points(ax, pair) -> None:
    """Vertical lines at A–E with their letters above the axes; letters closer than 6 % of the path to the
    previous one go one row higher, so that B and C (or C and D) never overlap on a short single-contact zone."""
    points = sorted(((float(pair.gamma(roll)), name) for name, roll in pair.path_points.items()))
    span = max(points[-1][0] - points[0][0], 1e-12)
    level, previous = 0, None
    for gamma, name in points:
        level = level + 1 if previous is not None and gamma - previous < 0.06 * span and level < 2 else 0
        previous = gamma
        ax.axvline(gamma, color="0.8", lw=0.7, zorder=0)
        ax.annotate(name, (gamma, 1.0), xycoords=("data", "axes fraction"), xytext=(0, 2 + 9 * level),
                    textcoords="offset points", ha="center", va="bottom", fontsize=8)
    if ax.get_title():
        ax.set_title(ax.get_title(), pad=14 + 9 * 2)  # above the letters, whatever their rows


def fig3c(evaluation):
    plt = _pyplot()
    case, field = evaluation.case, evaluation.temperature_field
    pair = case.gear_pair
    figure, ax = plt.subplots(figsize=(6.5, 3.8), constrained_layout=True)
    gamma = np.asarray(pair.gamma(pair.roll_grid(201)), float)
    ax.plot(gamma, field.pinion_flank_c(gamma), color="tab:red", label="driving flank (fit used by the model)")
    ax.plot(gamma, field.wheel_flank_c(gamma), color="tab:orange", ls="--", label="driven flank")
    table = case.temperature
    if getattr(table, "gamma", None) is not None and getattr(table, "flank_c", None) is not None:
        ax.plot(table.gamma, table.flank_c, "ko", ms=4, label="tabulated input")
    _mark_points(ax, pair)
    ax.set_xlabel("contact position Γ [–]")
    ax.set_ylabel("flank temperature [°C]")
    ax.legend(fontsize=8, loc="best")
    return figure


def fig4(evaluation):
    if evaluation.thermal_curves is None:  # the thermo-elastic model: deviation, loaded STE and load share
        from thermogear.summaries.thermoelastic_plots import plot_thermoelastic
        from thermogear.thermoelastic.mesh import ThermoelasticMesh

        return plot_thermoelastic(ThermoelasticMesh.from_case(evaluation.case))
    try:
        from thermogear.summaries.thermal_plots import plot_thermal_curves
    except ImportError:
        plot_thermal_curves = None
    if plot_thermal_curves is not None:
        return plot_thermal_curves(evaluation.thermal_curves, evaluation.case.name)
    plt = _pyplot()  # fallback: the pair curves only
    curve = evaluation.thermal_curves.curve
    width = evaluation.case.gear_pair.face_width
    figure, ax = plt.subplots(figsize=(6.5, 3.8), constrained_layout=True)
    ax.plot(curve.gamma, curve.elastic_stiffness / width * 1e-9, color=_COLORS["elastic"], label="k_e")
    ax.plot(curve.gamma, curve.stiffness / width * 1e-9, color=_COLORS["thermal"], label="k_T")
    ax.set_xlabel("contact position Γ [–]")
    ax.set_ylabel("pair stiffness [N/(mm·μm)]")
    ax.legend()
    return figure


def fig6(evaluation):
    plt = _pyplot()
    simulation = evaluation.simulations["thermal"]
    elastic = evaluation.simulations.get("elastic")
    grid = simulation.grid
    width = evaluation.case.gear_pair.face_width
    scale = 1.0 / width * 1e-9  # N/m total → N/(mm·μm) per width
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.0), constrained_layout=True)
    nodes_ms = grid.nodes * 1e3
    for slot, values in enumerate(simulation.pair_stiffness):
        _stairs(left, values * scale, nodes_ms, lw=1.0, label=f"k_T pair {slot + 1}")
    _stairs(left, simulation.mesh_stiffness * scale, nodes_ms, color="k", lw=1.6, label="k_T total")
    if elastic is not None:
        _stairs(left, elastic.mesh_stiffness * scale, elastic.grid.nodes * 1e3, color="0.5", ls="--", lw=1.0,
                    label="k_e total")
    left.set_xlabel("time τ in one mesh period [ms]")
    left.set_ylabel("stiffness per width [N/(mm·μm)]")
    left.set_title("one mesh cycle")
    left.legend(fontsize=8)
    period = grid.nodes[-1]
    count = int(np.ceil(FIG6_SPAN_MS * 1e-3 / period))
    times = np.concatenate([grid.nodes[:-1] + j * period for j in range(count)] + [[count * period]]) * 1e3
    values = np.tile(simulation.mesh_stiffness * scale, count)
    _stairs(right, values, times, color="k", label="k_T total")
    if elastic is not None:
        elastic_nodes = elastic.grid.nodes
        elastic_times = np.concatenate([elastic_nodes[:-1] + j * elastic_nodes[-1] for j in range(count)]
                                       + [[count * elastic_nodes[-1]]]) * 1e3
        _stairs(right, np.tile(elastic.mesh_stiffness * scale, count), elastic_times, color="0.5",
                     ls="--", label="k_e total")
    right.set_xlim(0.0, FIG6_SPAN_MS)
    right.set_xlabel("time τ [ms]")
    right.set_title(f"0–{FIG6_SPAN_MS:g} ms")
    right.legend(fontsize=8)
    return figure


def _damping_figure(evaluation, model: str):
    plt = _pyplot()
    from thermogear.luo2020.report.table import paper_reference

    summary = evaluation.damping
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.0), constrained_layout=True)
    path = summary.path[model]
    left.plot(path.gamma, path.damping, color=_COLORS[model])
    left.set_xlabel("contact position Γ [–]")
    left.set_ylabel("damping of one tooth pair [N·s/m]")
    left.set_title("per pair along the path")
    _mark_points(left, evaluation.case.gear_pair)
    grid = summary.grids[model]  # each model's own mesh grid (the thermoelastic one is the hot pair's)
    period = grid.nodes[-1]
    periods = 3
    times = np.concatenate([grid.nodes[:-1] + j * period for j in range(periods)] + [[periods * period]]) * 1e3
    _stairs(right, np.tile(summary.mesh[model], periods), times, color=_COLORS[model],
                 label=f"c(τ), rule '{summary.rule}'")
    means = summary.region_means[model]
    for region, style in (("single", "-."), ("double", ":")):
        if np.isfinite(means.get(region, np.nan)):
            right.axhline(means[region], color=_COLORS[model], ls=style, lw=0.8,
                          label=f"thermogear mean, {region}: {means[region]:.3g}")
    reference = paper_reference(evaluation.case.citation)  # None unless the case is a parameter set of the paper
    if reference is not None:
        paper = reference.mean_damping_n_s_per_m[model]
        for region, style in (("single", "-."), ("double", ":")):
            right.axhline(paper[region], color="k", ls=style, lw=0.8,
                          label=f"paper mean, {region}: {paper[region]:.3g}")
    right.set_xlabel("time τ [ms]")
    right.set_ylabel("mesh damping [N·s/m]")
    right.set_title("mesh cycle")
    right.legend(fontsize=7, loc="best")
    return figure


def fig7(evaluation):
    return _damping_figure(evaluation, "elastic")


def fig8(evaluation):
    return _damping_figure(evaluation, "thermal")


def _pair(evaluation, source: str):
    responses = getattr(evaluation, source)
    elastic, thermal = responses.get("elastic"), responses.get("thermal")
    first = elastic if elastic is not None else thermal
    other = thermal if elastic is not None else None
    return first, other


#: Axis label and scale of the start-up panels (the units of Luo & Li Figs. 9 and 11 and of the steady panels).
_START_UP_AXES = {"displacement": ("transmission error x [μm]", 1e6), "velocity": ("velocity ẋ [mm/s]", 1e3)}


def _start_up(ax, evaluation, quantity: str, periods: int = 6) -> None:
    """The first ``periods`` mesh periods from rest (the transient), x [μm] or ẋ [mm/s] against time [ms], in the
    colours and line styles of the steady panel beside it (elastic first, as :func:`_pair` orders them)."""
    label, scale = _START_UP_AXES[quantity]
    models = [model for model in ("elastic", "thermal") if evaluation.transients.get(model) is not None]
    for number, model in enumerate(models):
        response = evaluation.transients[model]
        history = response.history
        count = int(np.searchsorted(history.time, periods * response.problem.period, side="right"))
        ax.plot(history.time[:count] * 1e3, getattr(history, quantity)[:count] * scale,
                label=f"{model}, from rest", **_model_style(number))
    ax.set_xlabel("time [ms]")
    ax.set_ylabel(label)
    ax.set_title(f"start-up from rest (first {periods} mesh periods)", fontsize=9)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)


def _model_style(number: int) -> dict:
    from thermogear.dynamics.results.plots import MODEL_STYLES  # noqa: PLC0415

    return MODEL_STYLES[number % 2]


def _steady_and_start_up(evaluation, quantity: str):
    plt = _pyplot()
    figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4.0), constrained_layout=True,
                                         gridspec_kw={"width_ratios": (1, 1.3)})
    _start_up(left, evaluation, quantity)
    first, other = _pair(evaluation, "responses")
    draw = first.plot_displacement if quantity == "displacement" else first.plot_velocity
    draw(other=other, ax=right, periods=2)
    right.set_title("steady state, two mesh periods", fontsize=9)
    return figure


def fig9(evaluation):
    return _steady_and_start_up(evaluation, "displacement")


def fig10(evaluation):
    first, other = _pair(evaluation, "transients")
    return first.plot_phase(other=other)


def fig11(evaluation):
    return _steady_and_start_up(evaluation, "velocity")


def fig12(evaluation):
    first, other = _pair(evaluation, "responses")
    return first.plot_loads(other=other, periods=3)


def fig15(evaluation):
    plt = _pyplot()
    result = evaluation.fem
    width = evaluation.case.gear_pair.face_width
    figure, ax = plt.subplots(figsize=(6.5, 3.8), constrained_layout=True)
    ax.plot(result["gamma"], np.asarray(result["elastic"]) / width * 1e-9, "o-", color=_COLORS["elastic"],
            label="FE elastic")
    ax.plot(result["gamma"], np.asarray(result["thermal"]) / width * 1e-9, "s-", color=_COLORS["thermal"],
            label="FE thermo-elastic")
    curves = evaluation.thermal_curves
    if curves is not None:
        ax.plot(curves.curve.gamma, curves.curve.elastic_stiffness / width * 1e-9, color=_COLORS["elastic"], ls=":",
                label="analytical k_e")
        ax.plot(curves.curve.gamma, curves.curve.stiffness / width * 1e-9, color=_COLORS["thermal"], ls=":",
                label="analytical k_T")
    ax.set_xlabel("contact position Γ [–]")
    ax.set_ylabel("pair stiffness [N/(mm·μm)]")
    ax.legend(fontsize=8)
    return figure


def _drivetrain_picture(name: str, evaluation):
    """One of the drivetrain's pictures (:mod:`thermogear.drivetrain.pictures`), from the drivetrain the report's
    results came from."""
    from thermogear.drivetrain.pictures import drivetrain_pictures

    return drivetrain_pictures(evaluation.drivetrain_built, evaluation.drivetrain.as_json(), (name,))[name]


_DRAW: dict[str, tuple[Callable[[Any], Any], tuple[str, ...]]] = {
    "fig3c": (fig3c, ("thermal stiffness",)),
    "fig4": (fig4, ("thermal stiffness",)),
    "fig6": (fig6, ("thermal model",)),
    "fig7": (fig7, ("damping",)),
    "fig8": (fig8, ("damping",)),
    "fig9": (fig9, ("start-up transients", "elastic model", "thermal model")),
    "fig10": (fig10, ("start-up transients",)),
    "fig11": (fig11, ("start-up transients", "elastic model", "thermal model")),
    "fig12": (fig12, ("elastic model", "thermal model")),
    "fig15": (fig15, ("FE verification",)),
    "helical": (draw_helical, ("thermal stiffness", "thermal model")),
    **{name: (partial(_drivetrain_picture, name), ()) for name in DRIVETRAIN_PICTURES},
}


def report_figures(evaluation, names=None) -> tuple[dict[str, Any], dict[str, str]]:
    """Draw every figure (or those in ``names``): ``({name: matplotlib figure}, {name: reason it is missing})``."""
    figures, missing = {}, {}
    for name, (draw, stages) in _DRAW.items():
        if names is not None and name not in names:
            continue
        if name in DRIVETRAIN_PICTURES:
            if evaluation.drivetrain is None and "drivetrain" not in evaluation.problems:
                continue  # a case without [drivetrain]: nothing to draw, nothing missing
            if evaluation.drivetrain is None or evaluation.drivetrain_built is None:
                missing[name] = evaluation.problems.get("drivetrain") or "the drivetrain was not built"
                continue
        if name == "helical" and (absent := helical_figure_absent(evaluation)) is not None:
            missing.update({name: absent} if absent else {})  # "": a spur pair, nothing to draw, nothing missing
            continue
        if name == "fig15" and evaluation.fem is None:
            missing[name] = evaluation.problem("FE verification") or "the FE verification was not run"
            continue
        reason = evaluation.problem(*stages)
        if reason:
            missing[name] = reason
            continue
        try:
            figures[name] = draw(evaluation)
        except (KeyboardInterrupt, SystemExit):
            raise
        except Exception as error:  # noqa: BLE001 - a figure that cannot be drawn is reported with its reason
            missing[name] = f"{type(error).__name__}: {error}"
    return figures, missing


def legends_below(figure) -> None:
    """Gather the legends of every axes into one legend below the plots, so that no legend hides data (one entry
    per label). Also replaces legends placed at "best": matplotlib's search scans every data point."""
    handles, labels = [], []
    for ax in figure.axes:
        legend = ax.get_legend()
        if legend is None:
            continue
        for handle, label in zip(*ax.get_legend_handles_labels()):
            if label not in labels:
                handles.append(handle)
                labels.append(label)
        legend.remove()
    if not handles:
        return
    if figure.get_layout_engine() is None:
        figure.set_layout_engine("constrained")
    columns = min(len(labels), 4 if max(len(text) for text in labels) < 30 else 2)
    figure.legend(handles, labels, loc="outside lower center", ncol=columns, fontsize=8, frameon=False)


def save_figure(figure, folder, name: str) -> list[str]:
    """Write ``name.png`` (150 dpi) and ``name.svg`` into ``folder``; close the figure; return the file names."""
    import matplotlib.pyplot as plt

    legends_below(figure)
    files = []
    for suffix, options in ((".png", {"dpi": 150}), (".svg", {})):
        path = folder / f"{name}{suffix}"
        figure.savefig(path, **options)
        files.append(path.name)
        # the layout is done: the PNG's constrained layout placed every axes in figure coordinates, which do not
        # depend on the resolution, so the SVG keeps it (a second layout pass is a third of a figure's time)
        figure.set_layout_engine("none")
    plt.close(figure)
    return files


#: The figures the report's two processes share (each takes the next one not yet taken, see
#: :func:`thermogear.report.build.build_report`), slowest first: Fig. 4's four panels (~0.6 s CPU), the two-panel
#: figures (~0.3 s), the single panels last (~0.2 s). Whichever process is free takes the next, so the last ones
#: taken are short and both processes end close together, however busy each was before (longest job first).
SHARED_FIGURES = ("drivetrain_campbell", "drivetrain_modes", "fig4", "fig7", "fig8", "fig11", "fig6", "fig9", "fig10",
                  "helical", "drivetrain_layout", "drivetrain_bearing_spectra", "fig3c", "fig12")
#: The figures that need the FE verification: drawn last, once its child process has answered.
FE_FIGURES = ("fig15",)


def write_figures(evaluation, folder, names=None) -> dict[str, str]:
    """Draw the figures ``names`` (all: None) and save each as PNG and SVG into ``folder``; returns the missing
    ones with their reasons."""
    figures, missing = report_figures(evaluation, names)
    for name, figure in figures.items():
        save_figure(figure, folder, name)
    return missing
