"""The figures `thermogear sweep` prints and puts in its JSON: counted over the points where the linear model
holds.

A point with contact loss (the teeth would separate) or parametric instability has a Kv of the linear model that
is no load factor of the gear pair (Kv of several hundred): the maxima leave those points out and say how many
were left out (:func:`thermogear.sweep.plots.linear_model_valid`).
"""

from __future__ import annotations

import json
import math

from rich.console import Console
from rich.text import Text

from thermogear.cli.console import print_warning

__all__ = ["load_held_line", "load_held_summary", "print_sweep_summary", "response_summary"]


def load_held_summary(study) -> dict:
    """``{"load_held": "constant torque" | "constant power", "load_held_note": why}`` of a study (its store's
    ``load`` and ``load_note`` attributes say the same)."""
    from thermogear.sweep.load_held import study_load_held  # noqa: PLC0415

    load, note = study_load_held(study)
    return {"load_held": load, "load_held_note": note}


def load_held_line(summary: dict) -> str:
    """``load held: constant torque (why)``, the words of ``run``'s line."""
    return f"load held: {summary['load_held']} ({summary['load_held_note']})"


def response_summary(run, models) -> dict:
    """Counts of unstable, contact-loss and jammed points and, per model, the largest Kv over the valid points
    (None when none is valid) beside the largest over every point. ``run``: a finished study
    (:class:`thermogear.sweep.StudyRun`), read as NumPy arrays, so the command imports no xarray for its summary."""
    import numpy as np  # noqa: PLC0415

    from thermogear.sweep.plots import linear_model_valid  # noqa: PLC0415

    arrays = {name: run.read(name) for name in ("kv", "stable", "contact_loss", "jammed")}  # (model, *parameters)
    valid = linear_model_valid(arrays)
    jammed = arrays["jammed"] == 1
    kv_max, kv_max_all, valid_points = {}, {}, {}
    for index, model in enumerate(models):
        kv = np.asarray(arrays["kv"][index], dtype=float)
        holds = valid[index] & np.isfinite(kv)
        valid_points[model] = int(holds.sum())
        kv_max[model] = float(kv[holds].max()) if holds.any() else None
        finite = kv[np.isfinite(kv)]
        kv_max_all[model] = float(finite.max()) if finite.size else None
    return {
        "unstable_points": int(((arrays["stable"] == 0) & ~jammed).sum()),
        "jammed_points": int(jammed.sum()),
        "contact_loss_points": int((arrays["contact_loss"] == 1).sum()),
        "valid_points": valid_points,
        "kv_max": kv_max,
        "kv_max_note": "largest Kv over the points where the linear model holds (stable, no contact loss); "
                       "kv_max_all_points includes the others",
        "kv_max_all_points": kv_max_all,
    }


def _number(value: float | None) -> str:
    return "—" if value is None or not math.isfinite(value) else f"{value:.4g}"


def print_sweep_summary(summary: dict, console: Console, error_console: Console) -> None:
    """The summary of a finished study: where it went, its size, the largest Kv over valid points, what was left
    out, the plot, and the warnings once per cause."""
    for message in summary.get("warnings", []):
        print_warning(message, error_console)
    console.print(Text.assemble(("study written", "green"), f" to {summary['out']}: {summary['points']} points × "
                                f"{len(summary['models'])} model(s) in {summary['chunks']} chunks "
                                f"({summary['chunks_computed']} computed, {summary['chunks_kept']} kept) in "
                                f"{summary['seconds']:.1f} s"))
    points = summary["points"]
    console.print(load_held_line(summary), highlight=False)
    console.print("dims: " + json.dumps(summary["dims"]) + "; max Kv where the linear model holds: "
                  + ", ".join(f"{m} {_number(v)} ({summary['valid_points'][m]}/{points} points)"
                              for m, v in summary["kv_max"].items()))
    left_out = []
    if summary["contact_loss_points"]:
        left_out.append(f"{summary['contact_loss_points']} with contact loss")
    if summary["unstable_points"]:
        left_out.append(f"{summary['unstable_points']} parametrically unstable (NaN metrics, stable = 0)")
    if summary.get("jammed_points"):
        left_out.append(f"{summary['jammed_points']} jammed (the thermal expansion closes the backlash: no result, "
                        "jammed = 1)")
    if left_out:
        console.print(Text("left out of the maxima (model × point): " + ", ".join(left_out) + "; max Kv over every "
                           "point: " + ", ".join(f"{m} {_number(v)}" for m, v in summary["kv_max_all_points"].items()),
                           style="yellow"))
    if summary.get("plot"):
        console.print(f"plot: {summary['plot']}")
