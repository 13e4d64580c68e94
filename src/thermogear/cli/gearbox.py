"""`thermogear gearbox CASE`: steady temperatures, losses and backlash of the case's [gearbox], at its operating
point or over a grid of speeds × torques."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.table import Table

from thermogear.cli.app import app, console, error_console, print_json
from thermogear.errors import CaseError
from thermogear.sweep.schedulers import scheduler_help


@app.command()
def gearbox(case: str = typer.Argument(..., metavar="CASE", help="built-in parameter set or a .toml file with a "
                                                                  "[gearbox] section"),
            speeds: str | None = typer.Option(None, "--speeds", help="pinion speeds [rpm]: 'a:b:n' or 'v1,v2,...' "
                                                                     "(default the case's)"),
            torques: str | None = typer.Option(None, "--torques", help="pinion torques [N·m]: 'a:b:n' or "
                                                                       "'v1,v2,...' (default the case's)"),
            as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
            out: Path | None = typer.Option(None, "--out", help="also write the grid to this zarr store (like "
                                                                "`thermogear sweep`; `thermogear export` reads it)"),
            overwrite: bool = typer.Option(False, "--overwrite", help="replace an existing store at --out that "
                                                                      "thermogear wrote"),
            workers: int | None = typer.Option(None, "--workers", min=1, help="local worker processes that solve "
                                                                              "the points (default: serial)"),
            scheduler: str | None = typer.Option(None, "--scheduler", help=f"{scheduler_help()}, or a "
                                                 "dask.distributed scheduler address (default: serial, processes "
                                                 "with --workers)"),
            resume: bool = typer.Option(False, "--resume", help="continue an interrupted grid stored at --out"),
            chunk_points: int | None = typer.Option(None, "--chunk-points", min=1, help="points per task and stored "
                                                    "chunk (default 50)"),
            progress: bool = typer.Option(True, "--progress/--no-progress", help="progress bar on stderr")) -> None:
    """Steady temperatures, power losses by source, efficiency and backlash of the case's gearbox, at its
    operating point or over speeds × torques, on the study executor (serial, worker processes or a Dask
    scheduler). With --out, the grid is also written as a zarr store, block by block (--resume continues it)."""
    from thermogear.sweep.executor import check_scheduler_address  # noqa: PLC0415

    if out is None:
        for name, given in (("--overwrite", overwrite), ("--resume", resume)):
            if given:
                raise CaseError(name, True, "only with --out", "there is no store to replace or continue")
    if resume and overwrite:
        raise CaseError("--resume", True, "either --resume or --overwrite", "--resume keeps the finished blocks, "
                        "--overwrite replaces them")
    check_scheduler_address(scheduler)
    options = {"scheduler": _scheduler(scheduler, workers), "workers": workers, "chunk_points": chunk_points,
               "progress": progress and not as_json}
    if out is None:
        _steady_table(case, speeds, torques, as_json, options)
        return
    from thermogear.ownership import check_output_folder, exclusive_writer  # noqa: PLC0415
    from thermogear.sweep.steady_store import check_steady_store_target  # noqa: PLC0415

    check_output_folder(out, "--out")  # the output path before any work
    with exclusive_writer(out):  # one writer per store: a second command writing it is refused at once
        if not resume:
            check_steady_store_target(out, overwrite)
        _, run = _steady_table(case, speeds, torques, as_json, {**options, "out": out, "resume": resume,
                                                               "overwrite": overwrite})
    error_console.print(f"wrote {run.result.runaway.size} points to {run.path} ({run.computed} blocks computed, "
                        f"{run.kept} kept)", highlight=False)


def _scheduler(named: str | None, workers: int | None):
    """The grid's scheduler: the one named, else local worker processes where --workers is given, else serial."""
    from thermogear.sweep.schedulers import PROCESSES, SERIAL, scheduler  # noqa: PLC0415

    return scheduler(named, default=PROCESSES if workers is not None else SERIAL)


def _steady_table(case_name: str, speeds: str | None, torques: str | None, as_json: bool, options: dict):
    """Solve the grid and print it (a table, or JSON); returns the loaded case and the finished
    :class:`~thermogear.sweep.gearbox_grid.GridRun`."""
    from thermogear.cli.console import point_progress, print_warning  # noqa: PLC0415
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point  # noqa: PLC0415
    from thermogear.schema.values import parse_values  # noqa: PLC0415
    import numpy as np  # noqa: PLC0415

    from thermogear.sweep.gearbox_grid import run_gearbox_grid  # noqa: PLC0415

    from thermogear.gearbox.case_model import load_gearbox_case  # noqa: PLC0415

    loaded = load_gearbox_case(case_name)
    operating = gearbox_operating_point(loaded.operating_point, loaded.gearbox)
    speed_values = [operating.speed_rpm] if speeds is None else parse_values(speeds, "--speeds")
    torque_values = [operating.torque] if torques is None else parse_values(torques, "--torques")
    shown = options.pop("progress")
    with point_progress("gearbox grid", total=len(speed_values) * len(torque_values), unit="points",
                        enabled=shown) as advance:
        run = run_gearbox_grid(gearbox_model_from_case(loaded), speed_values, torque_values, operating.ambient_c,
                               progress=advance, case=loaded, **options)
    for message in run.messages:
        print_warning(message, error_console)
    result = run.result
    if as_json:
        print_json({"case": loaded.name, **result.as_dict()})
        return loaded, run
    table = Table(title=f"steady state of the gearbox of {loaded.name} (ambient {operating.ambient_c:g} °C)")
    for name in ("n [rpm]", "T [N·m]", "pinion [°C]", "wheel [°C]", "oil [°C]", "housing [°C]", "mesh [W]",
                 "bearings [W]", "seals [W]", "churning/jet [W]", "η [%]", "j_bn [μm]"):
        table.add_column(name, justify="right")
    # the no-load gear loss: churning of the dipped gears, plus the oil jet's impulse loss (injection)
    no_load = result.churning_loss if result.injection_loss is None else result.churning_loss + result.injection_loss
    for i, speed in enumerate(result.speeds_rpm):
        for j, torque in enumerate(result.torques):
            if result.runaway[i, j]:
                fold = None if result.fold_torque is None else result.fold_torque[i, j]
                where = "" if fold is None or fold is np.ma.masked else f" above {float(fold):.4g} N·m"
                table.add_row(f"{speed:g}", f"{torque:g}", *(["—"] * 9), f"no stable steady state{where} (runaway)")
                continue
            table.add_row(f"{speed:g}", f"{torque:g}",
                          *(f"{result.node(name)[i, j]:.1f}" for name in ("pinion", "wheel", "oil", "housing")),
                          f"{result.mesh_loss[i, j]:.1f}", f"{result.bearing_loss[i, j]:.1f}",
                          f"{result.seal_loss[i, j]:.1f}", f"{no_load[i, j]:.1f}",
                          f"{result.efficiency[i, j] * 100:.2f}", f"{result.backlash[i, j] * 1e6:.1f}")
    console.print(table)
    from thermogear.temperature.limits import FLAG_MEANINGS  # noqa: PLC0415

    for flag, meaning in FLAG_MEANINGS.items():
        marked = result.flagged(flag)
        if marked.any():
            points = ", ".join(f"{result.speeds_rpm[i]:g} rpm/{result.torques[j]:g} N·m"
                               for i, j in zip(*np.nonzero(marked)))
            console.print(f"flag {flag}: {meaning} at {points}", highlight=False)
    return loaded, run
