"""`thermogear sweep` of a drivetrain case with the backlash mesh: the orbit followed up and down in speed
(:mod:`thermogear.sweep.drivetrain_branches`) into a zarr store, its summary (jumps, largest Kv per direction) as
a table or JSON, and its figure."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from thermogear.errors import CaseError

__all__ = ["drivetrain_branch_summary", "run_drivetrain_branches", "save_figure"]


def drivetrain_branch_summary(dataset) -> dict:
    """Per "model/direction": the counts of valid, unstable, missing (not computed), run-in, contact-loss and
    back-flank points; the largest Kv and its speed."""
    from thermogear.sweep.drivetrain_branches import largest_kv

    counts: dict = {name: {} for name in ("valid_points", "unstable_points", "missing_points", "run_in_points",
                                          "contact_loss_points", "back_side_contact_points")}
    for model in dataset["model"].values:
        for direction in dataset["direction"].values:
            key = f"{model}/{direction}"
            part = dataset.sel(model=model, direction=direction)
            status = np.asarray(part["status"].values).astype(str)
            counts["valid_points"][key] = int(part["valid"].values.sum())
            counts["unstable_points"][key] = int((status == "unstable").sum())
            counts["missing_points"][key] = int(np.char.startswith(status, "not computed").sum())
            counts["run_in_points"][key] = int(part["run_in"].values.sum())
            counts["contact_loss_points"][key] = int((np.nan_to_num(part["contact_loss_fraction"].values) > 0).sum())
            counts["back_side_contact_points"][key] = int((np.nan_to_num(part["back_side_contact"].values) == 1).sum())
    return {**counts, "kv_max": largest_kv(dataset)}


def save_figure(figure, plot: Path, store: Path) -> str:
    """Write a sweep's ``figure`` to ``plot`` and close it; the path written. A disk that refuses is a CaseError
    that says the study itself is complete in ``store``."""
    import matplotlib.pyplot as plt

    try:
        figure.savefig(plot, dpi=120)
    except OSError as error:
        raise CaseError("--plot", str(plot), "a writable figure file", f"the study is complete in {store}, but "
                        f"its figure could not be written: {error.strerror or error}") from None
    finally:
        plt.close(figure)
    return str(plot)


def run_drivetrain_branches(built, origin, models: tuple[str, ...], speeds: np.ndarray, out: Path, overwrite: bool,
                            plot: Path | None, progress: bool, as_json: bool, console, direction: str,
                            workers: int | None = None) -> dict:
    """Compute, store, plot and summarise the backlash sweep of ``built`` (``direction`` up | down | both; each
    model and direction a task for one of ``workers`` processes, default the cores)."""
    from thermogear.cli.app import print_json
    from thermogear.cli.console import point_progress
    from thermogear.sweep.branches import write_branch_store
    from thermogear.sweep.drivetrain_branches import DIRECTIONS, drivetrain_branch_sweep

    if direction not in ("up", "down", "both"):
        raise CaseError("--direction", direction, "up | down | both",
                        "the orbit is followed from the lowest speed up, from the highest down, or both")
    directions = DIRECTIONS if direction == "both" else (direction,)
    start, cpu = time.perf_counter(), time.process_time()
    total = int(np.unique(speeds).size) * len(models) * len(directions)
    with point_progress("drivetrain branches", total=total, unit="points",
                        enabled=progress and not as_json) as advance:
        sweep = drivetrain_branch_sweep(built, origin, speeds, models, directions, progress=advance,
                                        workers=workers)
    target = write_branch_store(sweep.dataset, out, overwrite=overwrite)
    figure_path = None
    if plot is not None:
        from thermogear.sweep.drivetrain_branch_plots import plot_drivetrain_branches

        figure_path = save_figure(plot_drivetrain_branches(sweep), plot, target)
    data = sweep.dataset
    summary = {"out": str(target), "path": "drivetrain backlash branches (orbit followed in speed, modal reduction "
               f"up to {data.attrs['response_cutoff_hz']:g} Hz)", "mesh": "nonlinear", "models": list(models),
               "directions": list(directions), "points": int(data["speed_rpm"].size),
               "seconds": time.perf_counter() - start, "cpu_seconds_this_process": time.process_time() - cpu,
               **drivetrain_branch_summary(data), "hysteresis": sweep.hysteresis, "resonances": sweep.resonances,
               "plot": figure_path}
    if as_json:
        print_json(summary)
        return summary
    console.print(f"drivetrain backlash sweep of {data.attrs['case']}: {summary['points']} speeds × {len(models)} "
                  f"model(s) × {len(directions)} direction(s) in {summary['seconds']:.1f} s → {target}",
                  highlight=False)
    for key, largest in summary["kv_max"].items():
        where = "no valid point" if largest is None else (f"max Kv {largest['kv']:.4g} at "
                                                          f"{largest['speed_rpm']:.0f} rpm")
        console.print(f"  {key}: {where}; {summary['valid_points'][key]} valid, {summary['unstable_points'][key]} "
                      f"unstable, {summary['missing_points'][key]} not computed (in the store with the reason), "
                      f"{summary['run_in_points'][key]} run in after losing the branch; teeth separating at "
                      f"{summary['contact_loss_points'][key]}, back flanks struck at "
                      f"{summary['back_side_contact_points'][key]} of the speeds", highlight=False)
    for model, band in sweep.hysteresis.items():
        if not band.get("differ"):
            console.print(f"  {model}: up and down branches coincide (no jump in the range)", highlight=False)
            continue
        spans = ", ".join(f"{low:.0f}–{high:.0f}" for low, high in band["bands_rpm"])
        jumps = "; ".join(f"{way} sweep jumps " + ", ".join(
            f"{'up' if item['amplitude'] == 'rises' else 'down'} near {item['speed_rpm']:.0f} rpm" for item in items)
            for way in ("up", "down") if (items := band.get(f"{way}_sweep_jumps")))
        console.print(f"  {model}: up and down branches differ over {spans} rpm (hysteresis)"
                      f"{'; ' + jumps if jumps else ''}", highlight=False)
    if figure_path:
        console.print(f"  plot: {figure_path}", highlight=False)
    return summary
