"""`thermogear gearbox CASE`: steady temperatures, losses and backlash of the case's [gearbox], at its operating
point or over a grid of speeds × torques."""

from __future__ import annotations

from pathlib import Path

import typer
from rich.table import Table

from thermogear.cli.app import app, console, error_console, print_json
from thermogear.errors import CaseError


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
            workers: int | None = typer.Option(None, "--workers", min=1, help="threads that solve the points "
                                                                              "(default 1)")) -> None:
    """Steady temperatures, power losses by source, efficiency and backlash of the case's gearbox, at its
    operating point or over speeds × torques. With --out, the grid is also written as a zarr store."""
    if out is None:
        if overwrite:
            raise CaseError("--overwrite", True, "only with --out", "there is no store to replace")
        _steady_table(case, speeds, torques, as_json, workers)
        return
    from thermogear.ownership import check_output_folder, exclusive_writer  # noqa: PLC0415
    from thermogear.sweep.steady_store import check_steady_store_target, write_steady_store  # noqa: PLC0415

    check_output_folder(out, "--out")  # the output path before any work
    with exclusive_writer(out):  # one writer per store: a second command writing it is refused at once
        check_steady_store_target(out, overwrite)
        loaded, result = _steady_table(case, speeds, torques, as_json, workers)
        target = write_steady_store(result, loaded.name, loaded.source, loaded.document, out, overwrite=overwrite)
    error_console.print(f"wrote {result.runaway.size} points to {target}", highlight=False)


def _steady_table(case_name: str, speeds: str | None, torques: str | None, as_json: bool, workers: int | None):
    """Solve the grid and print it (a table, or JSON); returns the loaded case and the SteadySweep."""
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point  # noqa: PLC0415
    from thermogear.gearbox.sweep import steady_sweep  # noqa: PLC0415
    from thermogear.schema.values import parse_values  # noqa: PLC0415
    import numpy as np  # noqa: PLC0415

    from thermogear.gearbox.case_model import load_gearbox_case  # noqa: PLC0415

    loaded = load_gearbox_case(case_name)
    operating = gearbox_operating_point(loaded.operating_point, loaded.gearbox)
    speed_values = [operating.speed_rpm] if speeds is None else parse_values(speeds, "--speeds")
    torque_values = [operating.torque] if torques is None else parse_values(torques, "--torques")
    result = steady_sweep(gearbox_model_from_case(loaded), speed_values, torque_values, operating.ambient_c,
                          workers=workers)
    if as_json:
        print_json({"case": loaded.name, **result.as_dict()})
        return loaded, result
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
    from thermogear.temperature_limits import FLAG_MEANINGS  # noqa: PLC0415

    for flag, meaning in FLAG_MEANINGS.items():
        marked = result.flagged(flag)
        if marked.any():
            points = ", ".join(f"{result.speeds_rpm[i]:g} rpm/{result.torques[j]:g} N·m"
                               for i, j in zip(*np.nonzero(marked)))
            console.print(f"flag {flag}: {meaning} at {points}", highlight=False)
    return loaded, result
