"""`thermogear stiffness CASE`: elastic mesh stiffness (potential energy method) and the ISO 6336-1 cross-check."""

from __future__ import annotations

import importlib
import os
import tempfile
import textwrap
import warnings
from pathlib import Path

import typer
from rich.table import Table

from thermogear.case import load_case
from thermogear.cli.app import app, console, error_console, print_json
from thermogear.cli.console import print_notes, print_warning
from thermogear.cli.tables import dict_tables
from thermogear.errors import ExtrapolationWarning, ThermogearError
from thermogear.mesh.model import MeshModel
from thermogear.ownership import check_figure_file
from thermogear.summaries.stiffness import POINTS, plot_stiffness, stiffness_summary


PLOT_SUFFIXES = (".png", ".svg", ".pdf")

#: Widest line of a sentence under the thermal table [characters]: texts wrap to the table's width, at most this
#: (an 80-column terminal still wraps them to its own width).
TEXT_WIDTH_MAXIMUM = 120


def _atomic_figure(figure, path: Path) -> None:
    """Save a matplotlib figure atomically (temporary file in the target folder, then os.replace)."""
    suffix = path.suffix.lower()
    if suffix not in PLOT_SUFFIXES:
        raise ThermogearError(f"--plot {path}: the file name must end in one of {', '.join(PLOT_SUFFIXES)}")
    folder = path.resolve().parent
    if not folder.is_dir():
        raise ThermogearError(f"--plot {path}: folder {folder} does not exist")
    handle, temporary = tempfile.mkstemp(suffix=suffix, dir=folder)
    os.close(handle)
    try:
        figure.savefig(temporary, format=suffix[1:], dpi=150)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def _print_table(summary: dict) -> None:
    console.print(f"{summary['case']}: contact ratio {summary['contact_ratio']:.4f}, centre distance "
                  f"{summary['centre_distance_mm']:.3f} mm, face width {summary['face_width_mm']:.2f} mm, "
                  f"mesh period {summary['mesh_period_s'] * 1e3:.4f} ms")
    table = Table(title="Tooth pair along the path of contact (stiffness per mm of face width)")
    for column in ("point", "roll T1K [mm]", "Γ", "pair [N/(mm·μm)]", "pinion tooth", "wheel tooth"):
        table.add_column(column, justify="right")
    teeth = summary["tooth_stiffness_n_per_mm_um"]
    for name in POINTS:
        table.add_row(name, f"{summary['path_mm'][name]:.3f}", f"{summary['gamma'][name]:+.3f}",
                      f"{summary['pair_stiffness_n_per_mm_um'][name]:.3f}", f"{teeth['pinion'][name]:.2f}",
                      f"{teeth['wheel'][name]:.2f}")
    console.print(table)
    mesh = summary["mesh_stiffness_n_per_mm_um"]
    iso = summary["iso6336"]
    if "helical" in summary:
        _print_helical(summary)
        return
    console.print(f"Hertz contact stiffness {teeth['hertz']:.1f} N/(mm·μm)")
    console.print(f"Mesh stiffness over one period: min {mesh['min']:.3f}, mean {mesh['mean']:.3f}, "
                  f"max {mesh['max']:.3f} N/(mm·μm)")
    console.print(f"ISO 6336-1 Method B: c′ = {iso['c_prime_n_per_mm_um']:.3f}, "
                  f"c_γα = {iso['c_gamma_alpha_n_per_mm_um']:.3f} N/(mm·μm); PEM mean / c_γα = "
                  f"{summary['pem_mean_over_iso_c_gamma_alpha']:.3f}")


def _print_helical(summary: dict) -> None:
    """The helical pair's lines: the table above is its transverse section's tooth pair."""
    from thermogear.cli.check import add_helical_rows  # noqa: PLC0415

    table = Table(title="Helical pair")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    add_helical_rows(table, summary["helical"]["geometry"])
    for key, label in (("helical", "elastic"), ("helical_thermal", "thermal")):
        if key not in summary:
            continue
        part = summary[key]
        mesh = part["mesh_stiffness_n_per_mm_um"]
        table.add_row(f"K_t min / mean / max, {label} [N/(mm·μm)]",
                      f"{mesh['min']:.3f} / {mesh['mean']:.3f} / {mesh['max']:.3f}")
        table.add_row(f"ripple (max − min)/mean, {label} [–]", f"{part['ripple']:.4f}")
    helical = summary["helical"]
    iso = helical["iso6336"]
    table.add_row("K_n = K_t/cos²β_b, mean [N/(mm·μm)]", f"{helical['normal_mesh_stiffness_mean_n_per_mm_um']:.3f}")
    table.add_row("ISO 6336-1 B: c′ / c_γα / c_γβ [N/(mm·μm)]",
                  f"{iso['c_prime_n_per_mm_um']:.3f} / {iso['c_gamma_alpha_n_per_mm_um']:.3f} / "
                  f"{iso['c_gamma_beta_n_per_mm_um']:.3f}")
    table.add_row("slice model mean / c_γα [–]", f"{helical['slice_mean_over_iso_c_gamma_alpha']:.3f}")
    console.print(table)
    console.print(f"method: {helical['method']}", highlight=False)


def _print_wrapped(renderables: list) -> None:
    """Tables as they are; the sentences after them (the assumptions) wrapped at word boundaries to the width of
    the widest table, at most TEXT_WIDTH_MAXIMUM (off a terminal the console would print each on one line)."""
    from rich.measure import Measurement  # noqa: PLC0415

    tables = [item for item in renderables if isinstance(item, Table)]
    widest = max((Measurement.get(console, console.options, table).maximum for table in tables), default=0)
    width = min(max(widest, 1), TEXT_WIDTH_MAXIMUM) if tables else TEXT_WIDTH_MAXIMUM
    width = min(width, console.width)
    for item in renderables:
        if isinstance(item, Table):
            console.print(item)
        else:  # at spaces, never inside a word or a number; no trailing blanks
            console.print(textwrap.fill(str(item), width, break_long_words=False, break_on_hyphens=False),
                          soft_wrap=True)


@app.command()
def stiffness(
    case: str = typer.Argument(..., metavar="CASE",
                               help="built-in parameter set (see `thermogear cases`) or a .toml case file"),
    as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
    plot: Path | None = typer.Option(None, "--plot", help="write a figure (.png, .svg or .pdf)"),
    thermal: bool = typer.Option(False, "--thermal", help="add the case's thermal mesh stiffness"),
) -> None:
    """Elastic mesh stiffness along the path of contact and over one mesh period (per mm of face width)."""
    if plot is not None:
        check_figure_file(plot)  # before any work: suffix, not a folder, writable folder (issue 15)
    loaded = load_case(case)
    thermal_module = importlib.import_module("thermogear.summaries.thermoelastic") if thermal else None  # both models
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)  # collected into the summary instead
        summary, _ = stiffness_summary(MeshModel(loaded, "elastic"), loaded.material, loaded.operating_point,
                                       loaded.name)
    for message in summary["warnings"]:
        print_warning(message, error_console)
    if thermal and loaded.helical_pair is not None:  # the helical pair's K_t under the case's thermal model
        from thermogear.summaries.helical import helical_stiffness_summary  # noqa: PLC0415

        summary["helical_thermal"] = helical_stiffness_summary(MeshModel(loaded, "thermal"))
        thermal_module = None
    if thermal_module is not None:
        from thermogear.case.pieces import call_with_pieces  # noqa: PLC0415
        from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model  # noqa: PLC0415
        from thermogear.thermoelastic.mesh import ThermoelasticMesh  # noqa: PLC0415

        thermal_models = thermal_module.ThermalModels(
            paper=call_with_pieces(paper_thermal_model, loaded), elastic=MeshModel(loaded, "elastic"),
            thermal=MeshModel(loaded, "thermal"), component_of=lambda: ThermoelasticMesh.from_case(loaded),
            name=loaded.name)
        summary["thermal"] = thermal_module.thermal_stiffness_summary(thermal_models)
    if plot is not None:
        if thermal_module is not None:
            thermal_module.plot_thermal_stiffness(thermal_models, plot)
        else:
            import matplotlib.pyplot as plt

            figure = plot_stiffness(MeshModel(loaded, "elastic"), loaded.material, loaded.name)
            try:
                _atomic_figure(figure, plot)
            finally:
                plt.close(figure)
        summary["plot"] = str(plot)
    summary["notes"] = list(loaded.notes)
    if as_json:
        print_json(summary)
        return
    _print_table(summary)
    if thermal_module is not None:
        _print_wrapped(dict_tables(f"Thermal mesh (model {summary['thermal']['model']})", summary["thermal"]))
    print_notes(loaded.notes, console)
    if plot is not None:
        console.print(f"figure written to {plot}")
