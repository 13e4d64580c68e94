"""`thermogear fem CASE`: the finite-element verification (bulk temperature, FE vs PEM compliance, flank expansion
vs Eqs. 8–12, X_te from FE runs, mesh refinement study)."""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

import typer
from rich.table import Table

from thermogear.case import load_case
from thermogear.cli.app import app, console, print_json
from thermogear.cli.console import step_progress
from thermogear.errors import CaseError


def fem_summary(case_name: str, refine: bool = True, progress=None) -> tuple[dict, object]:
    """(JSON summary, FemAnalysis) of a case; with ``refine`` the study at twice the refinement is added.
    ``progress(step_name)`` is called as each step starts (see :data:`FEM_STEPS`)."""
    from thermogear.fem.inputs import fem_inputs  # noqa: PLC0415
    from thermogear.fem.interpretation import fem_interpretation  # noqa: PLC0415
    from thermogear.fem.verification import cached_analysis, fem_analysis, refinement_change_percent  # noqa: PLC0415
    from thermogear.luo2020.report.table import paper_reference  # noqa: PLC0415

    advance = progress or (lambda name: None)
    start = time.perf_counter()
    case = load_case(case_name)
    advance(FEM_STEPS[0])
    inputs = fem_inputs(case)
    analysis = cached_analysis(inputs)
    _check_heated(analysis.temperature_field)
    summary = analysis.summary()
    if refine:
        advance(FEM_STEPS[1])
        fine = fem_analysis(inputs, 2.0 * analysis.refinement)
        changes = refinement_change_percent(analysis, fine)
        summary["refinement_change_percent"] = changes["max"]
        summary["refinement_change_by_quantity_percent"] = changes
        summary["refinement_compared"] = [analysis.refinement, fine.refinement]
    summary["interpretation"] = fem_interpretation(case.temperature.reference_c, case.thermal, summary)
    summary["wall_time_s"] = time.perf_counter() - start
    reference = paper_reference(case.citation)
    if reference is not None:  # a parameter set of the paper: its numbers beside the case's
        summary["paper"] = {"flank_temperature_c": list(reference.flank_temperature_c),
                            "stiffness_drop_percent": dict(reference.stiffness_drop_percent)}
    return summary, analysis


def _check_heated(field) -> None:
    """Refuse FE tooth temperatures below the assembly temperature: the verification reads the paper's X_te
    (thermal.model = 'luo2020', Luo & Li Eqs. 13–17), which describes the restrained expansion of heated teeth; a
    contracted tooth gives it no meaning (it came out negative and was refused as a bad thermal.x_te)."""
    flank = [*field.table_flank_c, *(value + field.wheel_flank_offset_c for value in field.table_flank_c)]
    lowest = min(*flank, field.pinion_base_c, field.pinion_bore_c, field.wheel_base_c, field.wheel_bore_c)
    if lowest < field.reference_c:
        raise CaseError("temperature.reference_c", field.reference_c, f"<= {lowest:.1f} °C, the coldest FE tooth "
                        "temperature", "thermogear fem verifies the paper's thermal chain (X_te of thermal.model = "
                        "'luo2020', Luo & Li Eqs. 13–17), which describes heated teeth expanding from their assembly; "
                        "these teeth (oil at lubricant.operating_temperature_c) are colder than it, so there is no "
                        "X_te to verify (stiffness --thermal and run evaluate the cold pair with the thermo-elastic "
                        "model)")


#: The steps of `thermogear fem` as its progress display names them (the refinement study takes most of the time).
FEM_STEPS = ("FE analysis: heat, elastic and thermo-elastic tooth models",
             "refinement study at twice the mesh density", "figures")


def _save(figure, path: Path) -> None:
    handle, temporary = tempfile.mkstemp(suffix=path.suffix, dir=path.parent)
    os.close(handle)
    try:
        figure.savefig(temporary, dpi=120)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


@app.command()
def fem(case: str = typer.Argument(..., metavar="CASE", help="built-in parameter set or case file"),
        json_output: bool = typer.Option(False, "--json", help="print the summary as JSON"),
        plot: Path | None = typer.Option(None, "--plot", help="folder for Figs. 3(b), 3(c), 15 (PNG)"),
        no_refinement: bool = typer.Option(False, "--no-refinement", help="skip the refinement study"),
        quiet: bool = typer.Option(False, "--quiet", "-q", help="no progress display (for scripts)")) -> None:
    """Finite-element verification: bulk temperature, FE vs PEM tooth compliance, flank expansion, X_te."""
    if plot is not None:
        from thermogear.ownership import check_output_folder

        check_output_folder(plot)  # before any work
    steps = [FEM_STEPS[0]] + ([] if no_refinement else [FEM_STEPS[1]]) + ([] if plot is None else [FEM_STEPS[2]])
    with step_progress(steps, quiet=quiet or json_output) as advance:
        summary, analysis = fem_summary(case, refine=not no_refinement, progress=advance)
        if plot is not None:
            advance(FEM_STEPS[2])
            _write_figures(plot, analysis, summary.get("paper"))
            summary["plots"] = str(plot)
    if json_output:
        print_json(summary)
        return
    _print_table(summary)


def _write_figures(plot: Path, analysis, paper: dict | None = None) -> None:
    """Figs. 3(b), 3(c), 15 and the FE vs PEM compliance into the folder ``plot``; ``paper``: the paper's numbers
    of the summary (Fig. 3(c) then shows the paper's flank-temperature range)."""
    from functools import partial  # noqa: PLC0415

    from thermogear.fem import plots  # noqa: PLC0415

    band = None if paper is None else tuple(paper["flank_temperature_c"])
    plot.mkdir(parents=True, exist_ok=True)
    for name, draw in (("fig3b_temperature_field.png", plots.plot_temperature_field),
                       ("fig3c_flank_temperature.png", partial(plots.plot_flank_temperature, paper_band=band)),
                       ("fig15_stiffness_along_path.png", plots.plot_stiffness_along_path),
                       ("fe_vs_pem_tooth_stiffness.png", plots.plot_compliance_comparison)):
        figure = draw(analysis)
        _save(figure, plot / name)


def _print_table(summary: dict) -> None:
    table = Table(title=f"FE verification — {summary['case']}")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    compliance = summary["compliance_fe_vs_pem_percent"]
    rows = [("FE vs PEM tooth compliance, max |Δ| [%]", f"{compliance['max_abs']:.2f}"),
            ("FE vs PEM tooth compliance, mean |Δ| [%]", f"{compliance['mean_abs']:.2f}"),
            ("X_te (FE, magnitude reading)", f"{summary['x_te']:.4g}"),
            ("X_te (line-of-action reading)", f"{summary['x_te_line_of_action']:.4g}")]
    rows += [(f"stiffness drop at {k} [%]", f"{v:.2f}") for k, v in summary["stiffness_drop_percent"].items()]
    rows += [(f"pinion flank temperature at {k} [°C]", f"{v:.2f}") for k, v in summary["flank_temperature_c"].items()]
    rows += [(f"{g} base / bore temperature [°C]",
              f"{summary['base_temperature_c'][g]:.2f} / {summary['bore_temperature_c'][g]:.2f}")
             for g in ("pinion", "wheel")]
    rows.append(("flank expansion FE vs Eqs. 8–12, uniform rise, max |Δ| [%]",
                 f"{summary['expansion_fe_vs_analytical_percent']['max_abs']:.2f}"))
    if "refinement_change_percent" in summary:
        rows.append(("largest change on refinement [%]", f"{summary['refinement_change_percent']:.2f}"))
    rows.append(("wall time (s)", f"{summary['wall_time_s']:.1f}"))
    for row in rows:
        table.add_row(*row)
    console.print(table)
    for note in summary["interpretation"]["notes"]:
        console.print(f"note: {note}", soft_wrap=True)
