"""`thermogear sweep CASE --vary NAME=VALUES ... --out study.zarr`: a parameter study on Dask."""

from __future__ import annotations

import time
from pathlib import Path

import typer

from thermogear.cli.app import app, console, error_console, print_json
from thermogear.cli.console import print_warning
from thermogear.cli.sweep_summary import load_held_summary, print_sweep_summary, response_summary
from thermogear.dynamics.problems.continuation_directions import (DEFAULT_STUDY_DIRECTION, STUDY_DIRECTIONS,
                                                                   study_directions)
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError
from thermogear.sweep.evaluation_methods import is_batched
from thermogear.sweep.executor import check_scheduler_address
from thermogear.sweep.schedulers import Placement, PROCESSES, check_dashboard, scheduler_help
from thermogear.sweep.schedulers import scheduler as scheduler_named


@app.command()
def sweep(
    case: str = typer.Argument(..., metavar="CASE", help="built-in parameter set name or path to a .toml case file"),
    vary: list[str] = typer.Option(None, "--vary", help="NAME=VALUES, VALUES 'a:b:n', 'v1,v2,...' or one number; "
                                   "NAME an alias (speed_rpm, torque_nm, oil_temperature_c, x_te, module_mm, ...) "
                                   "or a dotted case key; repeat for a grid (the case's [sweep] table otherwise)"),
    out: Path = typer.Option(..., "--out", help="zarr store of the results (a directory, e.g. study.zarr)"),
    model: str = typer.Option(None, "--model", help="elastic | thermal | both (default: both, or [sweep].model)"),
    scheduler: str = typer.Option(None, "--scheduler", help=f"{scheduler_help()}, or a dask.distributed "
                                  "scheduler address (tcp://host:port); default: threads on the fast path and for "
                                  "branches, a local Dask cluster of processes otherwise (drivetrain studies)"),
    workers: int = typer.Option(None, "--workers", min=1, help="threads or processes of the local scheduler "
                                "(default: cores)"),
    dashboard: str = typer.Option(None, "--dashboard", help="serve the local cluster's Dask dashboard at this "
                                  "address, e.g. :8787 (default: no dashboard, no port opened)"),
    resume: bool = typer.Option(False, "--resume", help="continue an interrupted study stored at --out"),
    overwrite: bool = typer.Option(False, "--overwrite", help="replace an existing store at --out"),
    chunk_points: int = typer.Option(None, "--chunk-points", min=1, help="grid points per task and stored chunk"),
    method: str = typer.Option("batch", "--method", help="batch (fast path) | simulation (one Simulation per "
                               "point, the reference)"),
    plot: Path = typer.Option(None, "--plot", help="write the speed-response plot (PNG/SVG/PDF) here"),
    progress: bool = typer.Option(True, "--progress/--no-progress", help="progress bar on stderr"),
    as_json: bool = typer.Option(False, "--json", help="one JSON summary on stdout"),
    direction: str = typer.Option(None, "--direction", help="nonlinear mesh: follow the solution branch in speed "
                                  f"{' | '.join(STUDY_DIRECTIONS)} (default {DEFAULT_STUDY_DIRECTION}); the store gets "
                                  "a direction dimension"),
    multistart: int = typer.Option(0, "--multistart", min=0, help="nonlinear mesh: at every point also search "
                                   "the state plane from N starts and list every stable orbit found with its basin "
                                   "share (about 0.1 s per start, point and model; default 0: branches only)"),
    hold: str = typer.Option(None, "--hold", help="the load a speed sweep keeps from speed to speed: torque "
                             "(default) | power; stated in the store, the summary, the JSON and the plot"),
    kind: str = typer.Option(None, "--kind", help="the kind of study when the case's own is not meant: warmup (the "
                             "gearbox warm-up at every point of the grid; a case with a [gearbox])"),
    duration_s: float = typer.Option(None, "--duration-s", help="--kind warmup: each warm-up's duration [s] "
                                     "(default 1200)"),
    interval_s: float = typer.Option(None, "--interval-s", help="--kind warmup: time between mesh "
                                     "re-evaluations [s] (default 10)"),
    start_c: float = typer.Option(None, "--start-c", help="--kind warmup: every node's start temperature [°C] "
                                  "(default: each point's ambient)"),
) -> None:
    """Run a parameter study of a case (grid over speed, load, temperatures, geometry) into a zarr store.

    Every kind of study runs on one Dask executor into one resumable store: a linear-mesh pair's independent points,
    a nonlinear-mesh pair's branches up and down in speed (each orbit from its neighbour's), a drivetrain case's
    speeds (linear or backlash mesh) over any other keys, and, named with --kind warmup, a gearbox case's warm-up at
    every point; a speed sweep holds the torque (--hold power: the power)."""
    from thermogear.sweep import Study, load_study_case, run_study
    from thermogear.sweep.load_held import DEFAULT_HOLD
    from thermogear.sweep.store import study_description

    from thermogear.orchestrator import Orchestrator
    from thermogear.ownership import check_figure_file, check_output_folder, exclusive_writer

    check_output_folder(out, "--out")  # every output path before any work
    if plot is not None:
        check_figure_file(plot)
    with exclusive_writer(out):  # one writer per store: a second sweep into it is refused at once
        _refuse_foreign_entries(out, overwrite)
        loaded, section = load_study_case(case)
        check_scheduler_address(scheduler)
        stored = study_description(out) if resume else None
        if vary:
            definition: dict | list = list(vary)
        elif section is not None and section.vary:
            definition = dict(section.vary)
        elif stored is not None:
            definition = {p["name"]: list(p["values"]) for p in stored["parameters"]}
        else:
            raise CaseError("vary", None, "--vary NAME=VALUES (repeatable) or a [sweep] table in the case file",
                            "a sweep needs something to vary")
        chosen_model = model or (section.model if section is not None else None)
        chunks = chunk_points or (section.chunk_points if section is not None else None)
        if stored is not None:
            chosen_model = chosen_model or ("both" if len(stored["models"]) == 2 else stored["models"][0])
            chunks = chunks or stored["chunk_points"]
        from thermogear.case.pieces import call_with_pieces
        from thermogear.sweep.api import StudySubject, study_kind

        chosen = study_kind(call_with_pieces(StudySubject.of, loaded), method, kind)
        study = Study.define(loaded, definition, model=chosen_model or chosen.default_model, chunk_points=chunks,
                             hold=hold or (stored or {}).get("hold", DEFAULT_HOLD))
        warmup = None
        if (duration_s, interval_s, start_c) != (None, None, None):
            from thermogear.sweep.warmup_study import WarmupSettings

            warmup = WarmupSettings(1200.0 if duration_s is None else duration_s,
                                    10.0 if interval_s is None else interval_s, start_c)
        elif (stored or {}).get("warmup"):  # --resume of a warm-up family: its settings as stored
            from thermogear.sweep.warmup_study import WarmupSettings

            warmup = WarmupSettings(**stored["warmup"])
        if not chosen.by_case:  # a kind named on the command line, through the registry
            from thermogear.cli.sweep_named import run_named_sweep

            if plot is not None or dashboard is not None:
                raise CaseError("--plot" if plot is not None else "--dashboard", str(plot or dashboard),
                                f"absent with --kind {kind}", "this kind of study draws no speed plot and runs on the "
                                "executor without a dashboard")
            run_named_sweep(chosen, study, out, {
                "scheduler": scheduler, "workers": workers, "resume": resume, "overwrite": overwrite,
                "chunk_points": chunk_points or (stored or {}).get("chunk_points"), "method": method,
                "direction": direction, "multistart": multistart, "warmup": warmup}, _progress_bar if progress and not as_json else None, as_json)
            return
        if warmup is not None:
            raise CaseError("--duration-s/--interval-s/--start-c", warmup.describe(), "only with --kind warmup",
                            f"the case's {chosen.name} study runs no warm-up")
        if loaded.drivetrain is not None:  # the drivetrain's studies: linear or backlash mesh, any grid
            _run_drivetrain(study, out, direction, multistart, method, scheduler, workers, dashboard, resume,
                            overwrite, chunk_points or (stored or {}).get("speeds_per_task"), plot,
                            progress and not as_json, as_json)
            return
        # the case itself passes what check and run check; a study solves periodic steady states only
        Orchestrator(loaded, tuple(study.models), "periodic").preflight()
        study_directions(direction)  # an unknown direction is refused before anything is computed
        _warn_inert_axes(study)
        if mesh_law(loaded.dynamics.mesh).backlash and is_batched(method):
            from thermogear.cli.sweep_branches import run_branch_sweep

            run_branch_sweep(study, out, direction or "both", overwrite, resume, plot, progress, as_json,
                             scheduler=scheduler, workers=workers, multistart=multistart,
                             chunk_points=chunk_points, dashboard=dashboard)
            return
        if multistart:
            raise CaseError("--multistart", multistart, "only with [dynamics] mesh = \"nonlinear\"",
                            "the linear mesh has one periodic steady state per point (or none): there is no other "
                            "orbit to search for")
        if direction is not None:
            raise CaseError("--direction", direction, "only with [dynamics] mesh = \"nonlinear\"",
                            "the linear mesh has one steady solution per point: there is no branch to follow")
        start = time.perf_counter()
        existed = out.exists() or out.is_symlink()
        try:
            run = run_study(study, out, scheduler=scheduler, resume=resume, overwrite=overwrite, workers=workers,
                            method=method, dashboard=dashboard,
                            progress=_progress_bar if progress and not as_json else None)
        except (OSError, TimeoutError) as error:  # the scheduler went away, or the disk refused a write
            _remove_empty_store(out, existed)
            named = scheduler_named(scheduler)  # None: the disk (the serial loop reaches no scheduler either)
            serial = named.placement is Placement.CALLING_THREAD
            raise CaseError("--out" if serial else "--scheduler", str(out) if serial else scheduler,
                            "a reachable scheduler and a writable --out",
                            f"the study could not run: {error}") from None
        elapsed = time.perf_counter() - start
        figure_path = None
        if plot is not None and "speed_rpm" not in study.dims:
            print_warning(f"no plot written to {plot}: the plot draws the responses against speed, and this study "
                          "does not vary speed_rpm (add --vary speed_rpm=..., or draw a map with "
                          "thermogear.sweep.plots.plot_map)", error_console)
        if plot is not None and "speed_rpm" in study.dims:
            from thermogear.cli.sweep_drivetrain_branches import save_figure
            from thermogear.sweep.plots import plot_speed_response

            # the path was checked before the study; the disk may still refuse
            figure_path = save_figure(plot_speed_response(run.dataset), plot, out)
        summary = {
            "out": str(out),
            "dims": {name: int(size) for name, size in zip(study.dims, study.shape)},
            "models": list(study.models),
            "points": study.size,
            **load_held_summary(study),
            "chunks": len(study.blocks()),
            "chunks_computed": run.computed,
            "chunks_kept": run.skipped,
            "seconds": elapsed,
            **response_summary(run, study.models),
            "plot": figure_path,
            "warnings": run.messages,
        }
        if as_json:
            for message in run.messages:
                print_warning(message, error_console)
            print_json(summary)
            return
        print_sweep_summary(summary, console, error_console)


def _run_drivetrain(study, out: Path, direction, multistart: int, method: str, scheduler, workers, dashboard,
                    resume: bool, overwrite: bool, chunk_points, plot, progress: bool, as_json: bool) -> None:
    """The study of a case with a [drivetrain] (every option acts, or is refused with the reason)."""
    from thermogear.cli.sweep_drivetrain import run_drivetrain_sweep

    if multistart:
        raise CaseError("--multistart", multistart, "0 for a case with a [drivetrain]",
                        "the drivetrain study follows the orbit in speed; the state-plane search is the pair's")
    if not is_batched(method):
        raise CaseError("--method", method, "batch (the default) for a case with a [drivetrain]",
                        "the drivetrain study solves each speed's periodic orbit on its modal reduction; there is "
                        "no one-Simulation-per-point reference for a drivetrain")
    backlash = mesh_law(study.case.dynamics.mesh).backlash
    if chunk_points is not None and backlash:
        raise CaseError("--chunk-points", chunk_points, "absent with the backlash mesh",
                        "each point of a branch is its own task (it starts from its neighbour's orbit), so a "
                        "branch is written and resumed point by point")
    kind = scheduler_named(scheduler, default=PROCESSES)
    check_dashboard(kind, dashboard)
    options = {"scheduler": kind, "workers": workers, "resume": resume, "overwrite": overwrite,
               "chunk_points": chunk_points, "dashboard": dashboard}
    run_drivetrain_sweep(study, out, direction, options, plot, as_json, console,
                         _progress_bar if progress else None)


def _refuse_foreign_entries(out: Path, overwrite: bool) -> None:
    """Before any work: an owned store that --overwrite would replace must hold nothing thermogear did not write
    (a user's notes.txt is never deleted; --resume keeps what is there, and refuses the same way in the rare case
    where it must recreate an unfinished store)."""
    from thermogear.ownership import is_owned, require_no_foreign_entries

    if overwrite and is_owned(out, "sweep-store"):
        require_no_foreign_entries(out)


def _warn_inert_axes(study) -> None:
    """Say, before computing, which swept parameters change nothing either model sees (identical columns)."""
    import warnings as _warnings

    from thermogear.sweep.inert import inert_parameters

    with _warnings.catch_warnings():
        _warnings.simplefilter("ignore")  # the model's own warnings come with the study's results
        inert = inert_parameters(study)
    for name in inert:
        print_warning(f"sweep axis '{name}' changes nothing that either model sees for this case (every value gives "
                      "the same mesh stiffness, damping, deviations, load and mass): its columns will be identical",
                      error_console)


def _progress_bar(total: int, completed: int):
    """The study's progress bar on stderr, counting grid points (shown on a terminal only)."""
    from thermogear.cli.console import point_progress

    return point_progress("sweep", total=total, completed=completed, unit="points")


def _remove_empty_store(out: Path, existed: bool) -> None:
    """After a failed run, remove the store this run created when it holds no finished block (never a path that
    existed before the run, and only a store carrying thermogear's marker)."""
    if existed:
        return
    import shutil

    import numpy as np
    import zarr

    from thermogear.ownership import is_owned, resolve_output

    target = resolve_output(out)
    if not is_owned(target, "sweep-store"):
        return
    try:
        done = int(np.sum(zarr.open_group(str(target), mode="r")["chunk_done"][:]))
    except (OSError, KeyError, ValueError, TypeError):
        done = 0
    if done == 0:
        shutil.rmtree(target, ignore_errors=True)
