"""`thermogear stiffness CASE`: elastic mesh stiffness (potential energy method) and the ISO 6336-1 cross-check."""

from __future__ import annotations

import importlib
import os
import tempfile
import warnings
from pathlib import Path

import numpy as np
import typer
from rich.table import Table

from thermogear.case import Case, load_case
from thermogear.cli.app import app, console, error_console, print_json
from thermogear.cli.console import print_warning
from thermogear.cli.tables import dict_tables
from thermogear.errors import ExtrapolationWarning, ThermogearError
from thermogear.ownership import check_figure_file
from thermogear.mesh.model import MeshModel
from thermogear.stiffness.fillet_foundation import gear_sainsot_messages
from thermogear.stiffness.iso6336 import N_PER_MM_UM, iso6336_stiffness
from thermogear.stiffness.table import pair_compliance_table, pair_stiffness_at, tooth_compliance_at

POINTS = ("A", "B", "C", "D", "E")
MESH_GRID_COUNT = 2048
PLOT_SUFFIXES = (".png", ".svg", ".pdf")


def stiffness_summary(case: Case) -> tuple[dict, list[str]]:
    """The JSON summary of the elastic stiffness of a case (per-unit-width values in N/(mm·μm)) and the
    extrapolation warnings raised while computing it."""
    pair, material = case.gear_pair, case.material
    width = pair.face_width
    per_width = 1.0 / (width * N_PER_MM_UM)  # N/m total → N/(mm·μm)
    messages = (gear_sainsot_messages(pair.pinion, "pinion") + gear_sainsot_messages(pair.wheel, "wheel"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ExtrapolationWarning)
        points = pair.path_points
        rolls = np.array([points[name] for name in POINTS])
        pair_k = pair_stiffness_at(pair, material, rolls)
        delta_1, delta_2 = tooth_compliance_at(pair, material, rolls)
        table = pair_compliance_table(pair, material)
        state = MeshModel(case, "elastic").state(points_per_period=MESH_GRID_COUNT)
        grid, mesh_k = state.grid, state.mesh_stiffness
        iso = iso6336_stiffness(pair, material, case.operating_point)
    messages += [str(w.message) for w in caught
                 if issubclass(w.category, ExtrapolationWarning) and "Sainsot" not in str(w.message)]
    gamma = pair.gamma(rolls)
    mean = float(grid.time_average(mesh_k))
    summary = {
        "case": case.name,
        "contact_ratio": pair.contact_ratio,
        "centre_distance_mm": pair.centre_distance * 1e3,
        "operating_pressure_angle_deg": float(np.degrees(pair.operating_pressure_angle)),
        "face_width_mm": width * 1e3,
        "base_pitch_mm": pair.base_pitch * 1e3,
        "mesh_period_s": state.period,
        "path_mm": {name: float(points[name] * 1e3) for name in POINTS},
        "gamma": {name: float(value) for name, value in zip(POINTS, gamma)},
        "pair_stiffness_n_per_mm_um": {name: float(k * per_width) for name, k in zip(POINTS, pair_k)},
        "tooth_stiffness_n_per_mm_um": {
            "pinion": {name: float(per_width / (d - 0.5 * table.hertz)) for name, d in zip(POINTS, delta_1)},
            "wheel": {name: float(per_width / (d - 0.5 * table.hertz)) for name, d in zip(POINTS, delta_2)},
            "hertz": float(per_width / table.hertz),
        },
        "mesh_stiffness_n_per_mm_um": {"min": float(mesh_k.min() * per_width), "mean": mean * per_width,
                                       "max": float(mesh_k.max() * per_width)},
        "mesh_stiffness_total_n_per_m": {"min": float(mesh_k.min()), "mean": mean, "max": float(mesh_k.max())},
        "iso6336": {"c_prime_n_per_mm_um": iso["c_prime"] / N_PER_MM_UM,
                    "c_gamma_alpha_n_per_mm_um": iso["c_gamma_alpha"] / N_PER_MM_UM},
        "pem_mean_over_iso_c_gamma_alpha": mean * per_width / (iso["c_gamma_alpha"] / N_PER_MM_UM),
        "method": "potential energy method (Hertz, bending, shear, axial, Sainsot fillet foundation); "
                  "pairs in parallel; ISO 6336-1 Method B cross-check",
        "warnings": messages,
    }
    return summary, messages


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


def plot_stiffness(case: Case, ax=None):
    """Figure: pair and single-tooth stiffness along Γ, and the mesh stiffness over one period (per mm of face
    width). ``ax``: an array of three axes, or None for a new figure. Returns the figure."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    pair, material = case.gear_pair, case.material
    per_width = 1.0 / (pair.face_width * N_PER_MM_UM)
    table = pair_compliance_table(pair, material)
    gamma = pair.gamma(table.roll)
    if ax is None:
        figure, ax = plt.subplots(1, 3, figsize=(15, 4.2), constrained_layout=True)
    else:
        figure = ax[0].figure
    ax[0].plot(gamma, table.stiffness * per_width, color="k")
    for name, roll in pair.path_points.items():
        ax[0].axvline(pair.gamma(roll), color="0.8", lw=0.8)
        ax[0].annotate(name, (pair.gamma(roll), ax[0].get_ylim()[0]), textcoords="offset points", xytext=(2, 4))
    ax[0].set(xlabel="Γ", ylabel="pair stiffness [N/(mm·μm)]", title="Tooth pair along the path of contact")
    ax[1].plot(gamma, per_width / table.pinion.total, label="pinion tooth")
    ax[1].plot(gamma, per_width / table.wheel.total, label="wheel tooth")
    ax[1].axhline(per_width / table.hertz, color="0.5", ls="--", label="Hertz")
    ax[1].set(xlabel="Γ", ylabel="stiffness [N/(mm·μm)]", title="Single-tooth stiffness", yscale="log")
    ax[1].legend()
    state = MeshModel(case, "elastic").state(points_per_period=MESH_GRID_COUNT)
    grid, per_pair, total = state.grid, state.pair_stiffness, state.mesh_stiffness
    period = grid.nodes[-1]
    ax[2].plot(grid.midpoints / period, total * per_width, color="k", label="mesh")
    for slot in range(per_pair.shape[0]):
        values = np.where(grid.in_contact[slot], per_pair[slot] * per_width, np.nan)
        ax[2].plot(grid.midpoints / period, values, lw=0.8, label=f"pair {slot}")
    ax[2].set(xlabel="τ / T_m", ylabel="stiffness [N/(mm·μm)]", title="Mesh stiffness over one period")
    ax[2].legend()
    figure.suptitle(f"{case.name}: elastic mesh stiffness (potential energy method)")
    return figure


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
    console.print(f"Hertz contact stiffness {teeth['hertz']:.1f} N/(mm·μm)")
    console.print(f"Mesh stiffness over one period: min {mesh['min']:.3f}, mean {mesh['mean']:.3f}, "
                  f"max {mesh['max']:.3f} N/(mm·μm)")
    console.print(f"ISO 6336-1 Method B: c′ = {iso['c_prime_n_per_mm_um']:.3f}, "
                  f"c_γα = {iso['c_gamma_alpha_n_per_mm_um']:.3f} N/(mm·μm); PEM mean / c_γα = "
                  f"{summary['pem_mean_over_iso_c_gamma_alpha']:.3f}")


@app.command()
def stiffness(
    case: str = typer.Argument(..., metavar="CASE",
                               help="built-in parameter set (see `thermogear cases`) or a .toml case file"),
    as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
    plot: Path | None = typer.Option(None, "--plot", help="write a figure (.png, .svg or .pdf)"),
    thermal: bool = typer.Option(False, "--thermal", help="add the thermal stiffness (thermogear.thermal)"),
) -> None:
    """Elastic mesh stiffness along the path of contact and over one mesh period (per mm of face width)."""
    if plot is not None:
        check_figure_file(plot)  # before any work: suffix, not a folder, writable folder (issue 15)
    loaded = load_case(case)
    thermal_module = importlib.import_module("thermogear.summaries.thermoelastic") if thermal else None  # both models
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)  # collected into the summary instead
        summary, _ = stiffness_summary(loaded)
    for message in summary["warnings"]:
        print_warning(message, error_console)
    if thermal_module is not None:
        summary["thermal"] = thermal_module.thermal_stiffness_summary(loaded)
    if plot is not None:
        if thermal_module is not None:
            thermal_module.plot_thermal_stiffness(loaded, plot)
        else:
            import matplotlib.pyplot as plt

            figure = plot_stiffness(loaded)
            try:
                _atomic_figure(figure, plot)
            finally:
                plt.close(figure)
        summary["plot"] = str(plot)
    if as_json:
        print_json(summary)
        return
    _print_table(summary)
    if thermal_module is not None:
        for table in dict_tables(f"Thermal mesh (model {summary['thermal']['model']})", summary["thermal"]):
            console.print(table)
    if plot is not None:
        console.print(f"figure written to {plot}")
