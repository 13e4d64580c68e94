"""`thermogear sweep CASE --vary speed_rpm=a:b:n [--vary KEY=...]` on a case with a ``[drivetrain]``: the study of
:mod:`thermogear.sweep.drivetrain_run` (linear mesh: each speed's periodic response; backlash mesh: the orbit
followed up and down in speed) into a zarr store, its summary (table or JSON) and its figure."""

from __future__ import annotations

import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np

from thermogear.dynamics.problems.continuation_directions import study_directions
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError

__all__ = ["drivetrain_models", "run_drivetrain_sweep"]

_MODELS = {"elastic": ("elastic",), "thermal": ("thermal",), "both": ("elastic", "thermal")}


def drivetrain_models(model: str) -> tuple[str, ...]:
    """The mesh models of ``--model`` (elastic | thermal | both)."""
    if model not in _MODELS:
        raise CaseError("--model", model, "elastic | thermal | both", "unknown model")
    return _MODELS[model]


def _first_group(run) -> SimpleNamespace:
    """What the figures draw: the first combination of the parameters other than the speed."""
    data = run.dataset
    extra = [name for name in data.dims if name not in ("model", "direction", "speed_rpm", "bearing", "harmonic",
                                                        "state")]
    shown = data.isel({name: 0 for name in extra}) if extra else data
    hysteresis = next(iter(run.hysteresis.values()), {}) if run.hysteresis else {}
    return SimpleNamespace(dataset=shown, resonances=run.resonances, hysteresis=hysteresis)


def run_drivetrain_sweep(study, out: Path, direction: str | None, options: dict, plot: Path | None,
                         as_json: bool, console, progress_bar) -> dict:
    """Run the drivetrain study ``study`` into ``out`` (``options``: scheduler, workers, resume, overwrite,
    chunk_points) and print its summary; returns it."""
    from thermogear.cli.app import print_json
    from thermogear.cli.sweep_drivetrain_branches import drivetrain_branch_summary, print_branch_summary, save_figure
    from thermogear.sweep.drivetrain_run import run_drivetrain_study

    backlash = mesh_law(study.case.dynamics.mesh).backlash
    if direction is not None and not backlash:
        raise CaseError("--direction", direction, "only with [dynamics] mesh = \"nonlinear\"",
                        "the linear mesh has one steady solution per speed: there is no branch to follow")
    directions = study_directions(direction)
    start = time.perf_counter()
    run = run_drivetrain_study(study, out, directions, progress=progress_bar, **options)
    data = run.dataset
    shown = _first_group(run)
    figure_path = None
    if plot is not None:
        if backlash:
            from thermogear.sweep.drivetrain_branch_plots import plot_drivetrain_branches as draw
        else:
            from thermogear.sweep.drivetrain_speeds import plot_drivetrain_sweep as draw
        figure_path = save_figure(draw(shown), plot, run.path)
    summary = {"out": str(run.path), "path": ("drivetrain backlash branches (orbit followed in speed, modal "
                                              f"reduction up to {data.attrs['response_cutoff_hz']:g} Hz)" if backlash
                                              else "drivetrain per-speed path (modal reduction shared per task; "
                                              "linear mesh)"),
               "mesh": "nonlinear" if backlash else "linear", "models": list(study.models),
               "dims": {name: int(size) for name, size in zip(study.dims, study.shape)}, "points": study.size,
               "load_held": data.attrs["load"], "load_held_note": data.attrs["load_note"],
               "temperatures": data.attrs["temperatures"], "tasks_computed": run.computed, "tasks_kept": run.kept,
               "seconds": time.perf_counter() - start, "resonances": run.resonances, "plot": figure_path}
    if backlash:
        summary.update({"directions": list(directions), **drivetrain_branch_summary(data),
                        "hysteresis": (run.hysteresis["all"] if list(run.hysteresis) == ["all"]
                                       else run.hysteresis)})
    else:
        summary["valid_points"] = {m: int(data["valid"].sel(model=m).sum()) for m in study.models}
        summary["kv_max"] = {m: _finite_max(data["kv"].sel(model=m).where(data["valid"].sel(model=m)).values)
                             for m in study.models}
    if as_json:
        print_json(summary)
        return summary
    console.print(f"drivetrain {'backlash ' if backlash else ''}sweep of {study.case.name}: "
                  f"{' × '.join(f'{n} {k}' for k, n in summary['dims'].items())} × {len(study.models)} model(s) in "
                  f"{summary['seconds']:.1f} s → {run.path} ({run.computed} tasks computed, {run.kept} kept)",
                  highlight=False)
    console.print(f"  load held: {summary['load_held']} ({summary['load_held_note']}); temperatures: "
                  f"{summary['temperatures']}", highlight=False)
    if backlash:
        print_branch_summary(summary, run.hysteresis, console)
    else:
        for m in study.models:
            console.print(f"  {m}: {summary['valid_points'][m]} valid points, Kv max {summary['kv_max'][m]}; "
                          "mesh harmonics meet modes in range (* mesh-dominated): " + ("; ".join(
                              f"{r['harmonic']}× mesh meets {r['mode_hz']:.0f} Hz {r['label']}"
                              f"{' *' if r['mesh_dominated'] else ''} at {r['speed_rpm']:.0f} rpm"
                              for r in run.resonances[m]) or "none"), highlight=False)
    if figure_path:
        console.print(f"  plot: {figure_path}" + (" (the first combination of the other parameters)"
                                                 if len(study.parameters) > 1 else ""), highlight=False)
    return summary


def _finite_max(values) -> float | None:
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    return round(float(finite.max()), 6) if finite.size else None
