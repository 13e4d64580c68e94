"""The nonlinear-mesh branch study of `thermogear sweep`: continuation in speed, up and down, one store."""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from thermogear.cli.app import console, error_console, print_json
from thermogear.cli.console import print_warning
from thermogear.cli.sweep_summary import load_held_line, load_held_summary
from thermogear.errors import CaseError
from thermogear.sweep.schedulers import PROCESSES, check_dashboard
from thermogear.sweep.schedulers import scheduler as scheduler_named
from thermogear.warning_causes import distinct_warnings


def branch_summary(dataset, models) -> dict:
    """Per model and direction: the largest Kv over the points whose orbit was found, how many points lost
    contact, struck the back flanks or were not periodic, and the hysteresis between the branches."""
    from thermogear.sweep.hysteresis import hysteresis_bands  # noqa: PLC0415

    result: dict = {"kv_max": {}, "contact_loss_points": {}, "back_side_contact_points": {},
                    "not_periodic_points": {}, "failed_points": {}, "jammed_points": {}}
    for model in models:
        for direction in dataset["direction"].values:
            key = f"{model}/{direction}"
            part = dataset.sel(model=model, direction=direction)
            found = np.asarray(part["converged"].values, dtype=float) == 1.0
            kv = np.asarray(part["kv"].values, dtype=float)
            result["kv_max"][key] = float(np.nanmax(kv[found])) if np.any(found) else None
            result["contact_loss_points"][key] = int((np.asarray(part["contact_loss_fraction"].values) > 0).sum())
            result["back_side_contact_points"][key] = int((np.asarray(part["back_side_contact"].values) == 1).sum())
            kinds = np.asarray(part["response"].values).astype(str)
            result["not_periodic_points"][key] = int(np.isin(kinds, ("subharmonic", "non-periodic")).sum())
            result["failed_points"][key] = int((kinds == "failed").sum())
            result["jammed_points"][key] = int((kinds == "jammed").sum())
    result["hysteresis"] = hysteresis_bands(dataset)
    return result


def run_branch_sweep(study, out: Path, direction: str, overwrite: bool, resume: bool, plot: Path | None,
                     progress: bool, as_json: bool, scheduler: str | None = None, workers: int | None = None,
                     multistart: int = 0, chunk_points: int | None = None, dashboard: str | None = None) -> None:
    """Compute, store, plot and summarise a nonlinear-mesh study (``thermogear sweep`` of such a case)."""
    import warnings  # noqa: PLC0415

    from thermogear.cli.console import point_progress  # noqa: PLC0415
    from thermogear.sweep.branches import branch_study  # noqa: PLC0415

    if plot is not None:
        from thermogear.ownership import check_figure_file  # noqa: PLC0415

        check_figure_file(plot)
    if chunk_points is not None:
        raise CaseError("--chunk-points", chunk_points, "absent with the nonlinear mesh",
                        "a branch study's task is one point of one branch (each speed followed from its neighbour's "
                        "orbit), written and resumed point by point")
    if dashboard is not None:  # the local choice with a dashboard: the Dask cluster, which serves it
        scheduler = scheduler_named(scheduler, default=PROCESSES)
        check_dashboard(scheduler, dashboard)
    start = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        dataset = branch_study(study, direction, workers=workers, multistart=multistart, scheduler=scheduler, out=out,
                               resume=resume, overwrite=overwrite,
                               progress=lambda total, completed: point_progress(
                                   "branches", total=total, completed=completed, unit="points",
                                   enabled=progress and not as_json))
    from thermogear.ownership import resolve_output  # noqa: PLC0415

    target = resolve_output(out)
    elapsed = time.perf_counter() - start
    figure_path = None
    if plot is not None and "speed_rpm" not in study.dims:
        print_warning(f"no plot written to {plot}: the plot draws the responses against speed, and this study does "
                      "not vary speed_rpm (add --vary speed_rpm=...)", error_console)
    if plot is not None and "speed_rpm" in study.dims:
        from thermogear.cli.sweep_drivetrain_branches import save_figure  # noqa: PLC0415
        from thermogear.sweep.branch_plots import plot_branches  # noqa: PLC0415

        # the path was checked before the study; the disk may still refuse
        figure_path = save_figure(plot_branches(dataset), plot, target)
    messages = distinct_warnings(str(item.message) for item in caught)
    summary = {"out": str(target), "mesh": "nonlinear", "directions": list(dataset["direction"].values),
               "dims": {name: int(size) for name, size in zip(study.dims, study.shape)},
               "models": list(study.models), "points": study.size, **load_held_summary(study), "seconds": elapsed,
               **branch_summary(dataset, study.models), "plot": figure_path, "warnings": messages}
    if multistart:
        summary["multistart"] = {"starts": multistart, "points": orbit_listing(dataset)}
    if as_json:
        for message in messages:
            print_warning(message, error_console)
        print_json(summary)
        return
    for message in messages:
        print_warning(message, error_console)
    console.print(f"branch study written to {summary['out']}: {summary['points']} points × "
                  f"{len(summary['models'])} model(s) × {len(summary['directions'])} direction(s) in "
                  f"{elapsed:.1f} s (nonlinear mesh)")
    console.print(load_held_line(summary), highlight=False)
    for key, value in summary["kv_max"].items():
        console.print(f"  {key}: max Kv {value if value is None else f'{value:.4g}'}, contact loss at "
                      f"{summary['contact_loss_points'][key]} points, back-flank impacts at "
                      f"{summary['back_side_contact_points'][key]}, not periodic at "
                      f"{summary['not_periodic_points'][key]}, no orbit found at {summary['failed_points'][key]}"
                      + (f", jammed (backlash closed, no result) at {summary['jammed_points'][key]}"
                         if summary["jammed_points"][key] else ""))
    for model, band in summary["hysteresis"].items():
        if band.get("differ"):
            jumps = "; ".join(f"{way} sweep jumps " + ", ".join(f"{'up' if item['amplitude'] == 'rises' else 'down'} at "
                                                              f"{item['speed_rpm']:.0f} rpm" for item in items)
                              for way in ("up", "down") if (items := band.get(f"{way}_sweep_jumps")))
            spans = ", ".join(f"{low:.0f}–{high:.0f}" for low, high in band["bands_rpm"])
            console.print(f"  {model}: up and down branches differ over {spans} rpm (hysteresis)"
                          f"{'; ' + jumps if jumps else ''}")
    if multistart:
        _print_orbits(summary["multistart"], console)
    if figure_path:
        console.print(f"plot: {figure_path}")


def orbit_listing(dataset) -> list[dict]:
    """Per point and model of a multi-start study: its parameter values, and every stable orbit found (period
    count, DTE peak-to-peak [μm], Kv, back-flank contact, basin share), the largest basin share first."""
    listing = []
    count = dataset["stable_orbit_count"]
    for index in np.ndindex(*count.shape):
        if not np.isfinite(count.values[index]):
            continue  # jammed: no orbit
        point = {dim: (str(count[dim].values[i]) if dim == "model" else float(count[dim].values[i]))
                 for dim, i in zip(count.dims, index)}
        orbits = []
        for number in range(int(count.values[index])):
            where = (*index, number)
            orbits.append({
                "period_count": int(dataset["orbit_period_count"].values[where]),
                "dte_peak_to_peak_um": round(float(dataset["orbit_dte_peak_to_peak"].values[where]) * 1e6, 2),
                "kv": round(float(dataset["orbit_kv"].values[where]), 4),
                "back_side_contact": bool(dataset["orbit_back_contact_fraction"].values[where] > 0.0),
                "basin_share": round(float(dataset["orbit_basin_share"].values[where]), 4)})
        listing.append({**point, "orbits": orbits,
                        "unsettled_start_share": round(float(dataset["unsettled_start_share"].values[index]), 4)})
    return listing


def _print_orbits(search: dict, console, limit: int = 40) -> None:
    """One line per point: every stable orbit found from the starts (the rest of a long study in the store)."""
    console.print(f"stable orbits found from {search['starts']} starts per point (more may exist; the store holds "
                  "them all):")
    for point in search["points"][:limit]:
        where = ", ".join(f"{key} {value:g}" for key, value in point.items()
                          if key not in ("model", "orbits", "unsettled_start_share"))
        orbits = "; ".join(f"{item['dte_peak_to_peak_um']:.1f} μm p-p, {item['period_count']} period"
                           f"{'s' if item['period_count'] > 1 else ''}"
                           f"{', both flanks' if item['back_side_contact'] else ''}, Kv {item['kv']:.3g}, "
                           f"{100 * item['basin_share']:.0f} % of starts" for item in point["orbits"])
        unsettled = (f" ({100 * point['unsettled_start_share']:.0f} % of starts settled on none)"
                     if point["unsettled_start_share"] else "")
        console.print(f"  {point['model']} at {where}: {len(point['orbits'])} stable orbit"
                      f"{'s' if len(point['orbits']) != 1 else ''}: {orbits}{unsettled}")
    if len(search["points"]) > limit:
        console.print(f"  … {len(search['points']) - limit} more points in the store")
