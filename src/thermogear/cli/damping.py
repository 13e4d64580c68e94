"""`thermogear damping` (friction damping of a case, Luo & Li Eqs. 26–28) and `thermogear oils` (built-in oils)."""

from __future__ import annotations

import warnings
from pathlib import Path

import typer
from rich.table import Table

from thermogear.case import load_case
from thermogear.cli.app import app, console, error_console, print_json
from thermogear.cli.console import print_warning
from thermogear.summaries.damping_plots import plot_damping
from thermogear.summaries.damping import damping_summary
from thermogear.lubricant import builtin_lubricant, builtin_lubricant_names
from thermogear.mesh.model import MeshModel
from thermogear.mesh.model_names import MODELS
from thermogear.warning_causes import distinct_warnings


@app.command()
def damping(case: str = typer.Argument(..., metavar="CASE",
                                    help="built-in parameter set (see `thermogear cases`) or a .toml file"),
            as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
            plot: Path | None = typer.Option(None, "--plot", help="write the figure (Figs. 7–8) to this file"),
            rule: str | None = typer.Option(None, "--rule", help="mesh rule 'paper' or 'parallel' "
                                                                   "(default: the case's [damping] rule)"),
            points: int = typer.Option(720, "--points", min=16, max=100000, help="intervals per mesh period")) -> None:
    """Equivalent viscous damping of tooth friction: elastic (oil at the reference temperature) and thermal
    (oil at the local flank temperature), per pair along the path and over the mesh cycle."""
    from thermogear.ownership import check_figure_file

    if plot is not None:
        check_figure_file(plot)  # before any work
    loaded = load_case(case)
    if rule is not None:
        loaded = loaded.with_changes(**{"damping.rule": rule})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        summary = damping_summary({model: MeshModel(loaded, model) for model in MODELS}, loaded.damping,
                                  loaded.name, count=points)
    messages = distinct_warnings(str(w.message) for w in caught)  # once per cause
    payload = summary.to_dict()
    reference = _paper_means(loaded.citation)
    if reference is not None:
        payload["paper_n_s_per_m"] = reference
    payload["warnings"] = messages
    if plot is not None:
        figure = plot_damping(summary, paper=reference)
        figure.savefig(plot, dpi=150)
        payload["plot"] = str(plot)
    if as_json:
        print_json(payload)
        return
    for message in messages:
        print_warning(message, error_console)
    table = Table(title=f"Friction damping of {summary.case_name} (rule '{summary.rule}', Eq. 28 stiffness "
                        f"'{summary.stiffness}')")
    table.add_column("quantity")
    table.add_column("elastic", justify="right")
    table.add_column("thermal", justify="right")
    table.add_column("ratio", justify="right")
    if reference:
        table.add_column("paper (el. / th.)", justify="right")
    mu = payload["friction_coefficient_pitch"]
    row = ["friction coefficient at C", f"{mu['elastic']:.4f}", f"{mu['thermal']:.4f}",
           f"{mu['thermal'] / mu['elastic']:.3f}"]
    table.add_row(*(row + [""] if reference else row))
    for region in ("single", "double"):
        means = payload["damping_n_s_per_m"]
        row = [f"mean damping, {region}-pair region [N·s/m]", f"{means['elastic'][region]:.4g}",
               f"{means['thermal'][region]:.4g}", f"{payload['thermal_over_elastic'][region]:.3f}"]
        if reference:
            row.append(f"{reference['elastic'][region]:.3g} / {reference['thermal'][region]:.3g}")
        table.add_row(*row)
    viscosity, temperature = payload["viscosity_mpa_s"], payload["temperature_c"]
    row = ["oil temperature [°C] / viscosity [mPa·s]",
           f"{temperature['oil_reference']:.1f} / {viscosity['oil_reference']:.1f}",
           f"{temperature['flank_mean']:.1f} / {viscosity['flank_mean']:.1f} (flank mean)", ""]
    table.add_row(*(row + [""] if reference else row))
    console.print(table)
    if plot is not None:
        console.print(f"figure written to {plot}")


def _paper_means(citation: str | None) -> dict | None:
    """The paper's mean dampings {model: {region: N·s/m}} for a parameter set of the paper (its ``citation``, from
    the paper table), else None."""
    from thermogear.luo2020.report.table import paper_reference

    reference = paper_reference(citation)
    return None if reference is None else reference.mean_damping_n_s_per_m


@app.command()
def oils(as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout")) -> None:
    """List the built-in oils with their viscosities, density, base oil and source."""
    rows = []
    for name in builtin_lubricant_names():
        oil = builtin_lubricant(name)
        rows.append({"name": name, "title": oil.title, "base_oil": oil.base_oil,
                     "viscosity_points_c_mm2_s": [list(point) for point in oil.viscosity_points],
                     "density_kg_m3": oil.density_reference, "density_reference_c": oil.density_reference_c,
                     "density_coefficient_per_k": oil.density_coefficient,
                     "lubricant_factor": oil.lubricant_factor, "source": oil.source})
    if as_json:
        print_json({"oils": rows})
        return
    table = Table(title="Built-in oils (select with [lubricant] name = ...)")
    for column in ("name", "base oil", "ν 40 °C [mm²/s]", "ν 100 °C [mm²/s]", "ρ 15 °C [kg/m³]", "X_L"):
        table.add_column(column, justify="left" if column in ("name", "base oil") else "right")
    for row in rows:
        points = dict(row["viscosity_points_c_mm2_s"])
        table.add_row(row["name"], row["base_oil"], f"{points.get(40.0, float('nan')):g}",
                      f"{points.get(100.0, float('nan')):g}", f"{row['density_kg_m3']:g}", f"{row['lubricant_factor']:g}")
    console.print(table)
    console.print("Sources: `thermogear oils --json`. The ISO VG grades are generic oils; use your oil's data sheet "
                  "(viscosity_points) for real work.")
