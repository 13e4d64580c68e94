"""`thermogear sweep CASE --vary speed_rpm=a:b:n` on a case with a ``[drivetrain]``, into a zarr store: with the
linear mesh the per-speed path of :mod:`thermogear.sweep.drivetrain_speeds` (the study's fast path batches the 1-DOF
pair only); with the backlash mesh the orbit followed up and down in speed (:mod:`thermogear.sweep.
drivetrain_branches`, summary and figure in :mod:`thermogear.cli.sweep_drivetrain_branches`)."""

from __future__ import annotations

import time
from pathlib import Path

from thermogear.errors import CaseError

__all__ = ["drivetrain_models", "run_drivetrain_sweep"]

_MODELS = {"elastic": ("elastic",), "thermal": ("thermal",), "both": ("elastic", "thermal")}


def drivetrain_models(model: str) -> tuple[str, ...]:
    """The mesh models of ``--model`` (elastic | thermal | both)."""
    if model not in _MODELS:
        raise CaseError("--model", model, "elastic | thermal | both", "unknown model")
    return _MODELS[model]


def _speeds(definition) -> "object":
    """The speeds of a sweep definition (``["speed_rpm=a:b:n"]`` or ``{"speed_rpm": ...}``); anything else is
    refused: the drivetrain sweep varies the pinion speed only."""
    from thermogear.schema.values import parse_values

    items = dict(definition) if isinstance(definition, dict) else dict(
        item.split("=", 1) if "=" in item else (item, None) for item in definition)
    names = sorted(items)
    if names != ["speed_rpm"] or items["speed_rpm"] is None:
        raise CaseError("--vary", ", ".join(names), "speed_rpm=VALUES only, for a case with a [drivetrain]",
                        "the drivetrain sweep varies the pinion speed (Kv, DTE and bearing forces per speed); sweep "
                        "other keys on the pair by removing the [drivetrain] section")
    return parse_values(items["speed_rpm"], "speed_rpm")


def run_drivetrain_sweep(built, origin, models: tuple[str, ...], definition, out: Path, overwrite: bool,
                         resume: bool, plot: Path | None, progress: bool, as_json: bool, workers: int | None, console,
                         error_console, direction: str | None = None) -> dict:
    """Run the speed sweep of ``built`` (a :class:`~thermogear.drivetrain.case_model.CaseDrivetrain` holding
    ``models``; ``origin`` its case's :class:`~thermogear.sweep.drivetrain_speeds.SweepOrigin`) into ``out`` and
    print its summary (table or JSON): the backlash orbit up and down in speed where the case's mesh is nonlinear,
    the linear per-speed path otherwise."""
    from thermogear.cli.app import print_json
    from thermogear.cli.console import point_progress
    from thermogear.sweep.branches import write_branch_store
    from thermogear.sweep.drivetrain_speeds import drivetrain_speed_sweep, plot_drivetrain_sweep

    nonlinear = built.backlash_mesh
    if resume:
        raise CaseError("--resume", True, "absent for a drivetrain case", "the drivetrain sweep is written whole "
                        "at its end (a backlash branch also needs every speed before it in its direction); run it "
                        "again")
    if direction is not None and not nonlinear:
        raise CaseError("--direction", direction, "only with [dynamics] mesh = \"nonlinear\"",
                        "the linear mesh has one steady solution per speed: there is no branch to follow")
    speeds = _speeds(definition)
    if (out.exists() or out.is_symlink()) and not overwrite:
        raise CaseError("out", str(out), "a path that does not exist yet (or --overwrite)",
                        "the result store exists; overwrite it explicitly")
    if nonlinear:
        from thermogear.cli.sweep_drivetrain_branches import run_drivetrain_branches

        return run_drivetrain_branches(built, origin, models, speeds, out, overwrite, plot, progress, as_json, console,
                                       direction or "both", workers)
    start = time.perf_counter()
    with point_progress("drivetrain sweep", total=int(speeds.size), unit="speeds",
                        enabled=progress and not as_json) as advance:
        sweep = drivetrain_speed_sweep(built, origin, speeds, models, workers=workers, progress=advance)
    write_branch_store(sweep.dataset, out, overwrite=overwrite)
    figure_path = None
    if plot is not None:
        from thermogear.cli.sweep_drivetrain_branches import save_figure

        figure_path = save_figure(plot_drivetrain_sweep(sweep), plot, out)
    data = sweep.dataset
    summary = {"out": str(out), "path": "drivetrain per-speed path (modal reduction shared per task; linear mesh)",
               "models": list(models), "points": int(speeds.size), "seconds": time.perf_counter() - start,
               "valid_points": {m: int(data["valid"].sel(model=m).sum()) for m in models},
               "kv_max": {m: _finite_max(data["kv"].sel(model=m).where(data["valid"].sel(model=m)).values)
                          for m in models},
               "resonances": sweep.resonances, "plot": figure_path}
    if as_json:
        print_json(summary)
    else:
        console.print(f"drivetrain sweep of {origin.name}: {speeds.size} speeds × {len(models)} model(s) in "
                      f"{summary['seconds']:.1f} s on the per-speed path (modal reduction, linear mesh) → {out}",
                      highlight=False)
        for m in models:
            console.print(f"  {m}: {summary['valid_points'][m]} valid points, Kv max {summary['kv_max'][m]}; "
                          "mesh harmonics meet modes in range (* mesh-dominated): " + ("; ".join(
                              f"{r['harmonic']}× mesh meets {r['mode_hz']:.0f} Hz {r['label']}"
                              f"{' *' if r['mesh_dominated'] else ''} at {r['speed_rpm']:.0f} rpm"
                              for r in sweep.resonances[m]) or "none"), highlight=False)
        if figure_path:
            console.print(f"  plot: {figure_path}", highlight=False)
    return summary


def _finite_max(values) -> float | None:
    import numpy as np

    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    return round(float(finite.max()), 6) if finite.size else None
