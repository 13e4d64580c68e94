"""`thermogear run` on a case with a ``[drivetrain]``: the drivetrain's modes (labels, energy shares, cold and hot,
what heat moved), its Kv and DTE, and the dynamic force of each bearing on the housing, as tables or JSON."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["check_picture_folder", "print_drivetrain", "write_pictures"]


def _number(value, pattern: str = "{:.1f}") -> str:
    return "not found" if value is None else pattern.format(value)


def print_drivetrain(results, console, reason: str | None = None) -> None:
    """Print the drivetrain tables of :class:`~thermogear.drivetrain.results.DrivetrainResults`: modes (with the
    cold → hot shift and its main cause), response, bearings; ``reason`` where they could not be computed."""
    if results is None:
        if reason is not None:
            console.print(f"drivetrain not computed: {reason}", highlight=False)
        return
    from rich.table import Table

    models = results.models
    first = next(iter(models.values()))
    heat = results.heat
    table = Table(title=f"drivetrain modes ({results.degrees_of_freedom} DOF; shares of the modal strain energy; "
                        "other: couplings and motor supports)", header_style="bold")
    for column in ("mode", "label", *(f"{name} [Hz]" for name in models), "mesh", "bearings", "shafts", "other"):
        table.add_column(column, justify="left" if column == "label" else "right")
    if heat:
        table.add_column("cold→hot [%]", justify="right")
        table.add_column("main cause")
    for index, mode in enumerate(first.modes):
        shares = mode.energy_shares
        cells = [str(index + 1), mode.label + (" *" if mode.mesh_dominated else ""),
                 *(_number(model.modes[index].frequency_hz) for model in models.values()),
                 *(f"{shares.get(key, 0.0):.3f}" for key in ("mesh", "bearings", "shafts")),
                 f"{sum(v for k, v in shares.items() if k not in ('mesh', 'bearings', 'shafts')):.3f}"]
        if heat:
            cells += [f"{100.0 * heat[index].shift:+.3f}", heat[index].dominant_cause]
        table.add_row(*cells)
    console.print(table)
    for name, model in models.items():  # issue 36: the mesh mode is listed even above the tabulated ones
        if model.mesh_modes:
            console.print(f"{name}: mesh-dominated modes above the {len(model.modes)} listed, up to the response "
                          "cut-off: " + ", ".join(
                              f"{row.frequency_hz:.0f} Hz {row.label} (mesh share {row.mesh_share:.2f})"
                              for row in model.mesh_modes) + " (raise drivetrain.mode_count to tabulate them)",
                          highlight=False)
    console.print("* mesh-dominated (mesh share > 0.1). Mesh harmonics meet modes with a mesh share above 0.01 at: "
                  + ("; ".join(f"{r.harmonic}× mesh at {r.speed_rpm:.0f} rpm ({r.mode_hz:.0f} Hz "
                               f"{r.label}{' *' if r.mesh_dominated else ''}, {name})"
                               for name, model in models.items() for r in model.resonances) or "none"),
                  highlight=False)
    response = Table(title=f"drivetrain response (mesh {results.mesh}; {results.solved_on})", header_style="bold")
    for column in ("quantity", *models, "unit"):
        response.add_column(column, justify="left" if column in ("quantity", "unit") else "right")
    rows = [("Kv", lambda m: m.kv, "{:.4f}", "–"), ("DTE RMS", lambda m: _micro(m.dte_rms), "{:.3f}", "μm"),
            ("DTE peak-to-peak", lambda m: _micro(m.dte_peak_to_peak), "{:.3f}", "μm")]
    if not results.transient:
        rows.append(("largest |Floquet multiplier|", lambda m: m.largest_floquet_multiplier_abs, "{:.4f}", "–"))
    for label, value, pattern, unit in rows:
        response.add_row(label, *(_number(value(model), pattern) for model in models.values()), unit)
    stages = next((model.stages for model in models.values() if model.stages), None) or {}
    for stage in stages:  # a train: each mesh over the common period (none where a model's orbit was not found)
        response.add_section()
        lines = [("Kv", lambda s: s.kv, "{:.4f}", "–"), ("DTE RMS", lambda s: _micro(s.dte_rms), "{:.3f}", "μm"),
                 ("DTE peak-to-peak", lambda s: _micro(s.dte_peak_to_peak), "{:.3f}", "μm"),
                 ("largest mesh force", lambda s: s.max_mesh_force_n, "{:.1f}", "N")]
        if results.backlash_mesh:  # each mesh's own dead zone
            lines.append(("time without contact", lambda s: _percent(s.contact_loss_fraction), "{:.2f}", "%"))
        for label, value, pattern, unit in lines:
            response.add_row(f"{stage}: {label}", *(_number(value(model.stages[stage]) if model.stages else None,
                                                            pattern) for model in models.values()), unit)
    if results.backlash_mesh:
        response.add_row("time without contact", *(_number(_percent(model.contact_loss_fraction), "{:.2f}")
                                                   for model in models.values()), "%")
        response.add_row("back flanks struck", *(_yes_no(model.back_side_contact) for model in models.values()), "")
    if results.backlash_mesh and not results.transient:
        response.add_row("periodic orbit found (stable)", *(_found(model) for model in models.values()), "")
    for bearing in first.bearing_forces:
        forces = {name: model.bearing_forces[bearing] for name, model in models.items()}
        response.add_section()
        response.add_row(f"{bearing}: mean radial", *(_number(f.mean_radial_n) for f in forces.values()), "N")
        response.add_row(f"{bearing}: dynamic RMS", *(_number(f.dynamic_rms_n) for f in forces.values()), "N")
        response.add_row(f"{bearing}: mean axial", *(_number(f.mean_axial_n) for f in forces.values()), "N")
        response.add_row(f"{bearing}: mean tilting moment",
                         *(_number(f.mean_tilting_moment_n_m) for f in forces.values()), "N·m")
        for j, frequency in enumerate(next(iter(forces.values())).harmonic_hz):
            line = f"mesh harmonic {frequency:.0f} Hz" if first.stages else f"{j + 1}× mesh ({frequency:.0f} Hz)"
            response.add_row(f"{bearing}: {line}",
                             *(_number(f.harmonic_amplitude_n[j], "{:.2f}") for f in forces.values()), "N")
    console.print(response)
    for name, model in models.items():  # issue 38: the cut-off's own error, stated with every response
        if model.cutoff_error is not None:
            console.print(f"drivetrain, {name} model, response solved on the {model.cutoff_error.describe()}",
                          highlight=False)
    _print_warm_state(results.warm_state, console)
    for name, model in models.items():
        if getattr(model, "failure", ""):
            console.print(f"drivetrain, {name} model: no periodic orbit — {model.failure}", highlight=False)
    for note in results.notes:
        console.print(f"note: {note}", highlight=False)


def _print_warm_state(warm: dict[str, Any] | None, console) -> None:
    """The hot drivetrain's shaft temperatures with where they came from and, where a temperature model gives its
    bearings' rings, their temperatures, operating clearance, static load and loss."""
    if not warm or not warm.get("shafts"):
        return
    from rich.table import Table

    shafts = Table(title="drivetrain warm state: shaft temperatures (E(T) and thermal growth)", header_style="bold")
    for column in ("shaft", "temperature [°C]", "from"):
        shafts.add_column(column, justify="right" if column.startswith("temperature") else "left")
    for name, shaft in warm["shafts"].items():
        shafts.add_row(name, f"{shaft['temperature_c']:.1f}", shaft["source"])
    console.print(shafts)
    if not warm.get("bearings"):
        return
    bearings = Table(title="drivetrain warm state: bearings (inner ring at the shaft, outer ring at the housing)",
                     header_style="bold")
    for column in ("bearing", "inner ring [°C]", "outer ring [°C]", "clearance mounted → hot [μm]",
                   "static radial load [N]", "loss [W]"):
        bearings.add_column(column, justify="left" if column == "bearing" else "right")
    for name, bearing in warm["bearings"].items():
        bearings.add_row(name, _number(bearing["inner_ring_c"]), _number(bearing["outer_ring_c"]),
                         f"{bearing['mounted_clearance_um']:.2f} → {bearing['operating_clearance_um']:.2f}",
                         "–" if bearing["static_radial_load_n"] is None else f"{bearing['static_radial_load_n']:.1f}",
                         "–" if bearing["loss_w"] is None else f"{bearing['loss_w']:.2f}")
    console.print(bearings)


def _micro(value):
    return None if value is None else value * 1e6


def _percent(value):
    return None if value is None else 100.0 * value


def _yes_no(value) -> str:
    return "not found" if value is None else "yes" if value else "no"


def _found(model) -> str:
    """'yes' for a converged stable orbit, 'yes (unstable)', or 'NO' where none was found."""
    if not getattr(model, "converged", False):
        return "NO"
    return "yes" if model.stable else "yes (unstable)"


def check_picture_folder(folder: Path, drivetrain, force: bool) -> Path:
    """``run --plot FOLDER``, checked before any work: the case has a [drivetrain] (``drivetrain``, the section or
    None; the pictures are of it), the
    folder can be written, and no picture file of the same name is there unless ``force`` (thermogear replaces only
    what it wrote: the files it would replace are its own names, and --force says to replace them)."""
    from thermogear.drivetrain.pictures import PICTURES
    from thermogear.errors import CaseError
    from thermogear.ownership import check_output_folder

    if drivetrain is None:
        raise CaseError("--plot", str(folder), "a case with a [drivetrain] section",
                        "the pictures are of the drivetrain (layout, modes, Campbell, bearing forces); the pair's "
                        "own figures are in the report: run --out FOLDER")
    target = check_output_folder(folder, "--plot")
    existing = [f"{name}.png" for name in PICTURES if (target / f"{name}.png").exists()]
    if existing and not force:
        raise CaseError("--plot", str(folder), "a folder without thermogear's picture files, or --force",
                        f"{', '.join(existing)} would be replaced")
    return target


def write_pictures(folder: Path, data: dict[str, Any] | None, built) -> list[str]:
    """Draw the drivetrain's pictures (:mod:`thermogear.drivetrain.pictures`) of the results ``data`` that ``run``
    reports (their JSON), from ``built``, the CaseDrivetrain they came from
    (:attr:`~thermogear.orchestrator.Orchestrator.built_drivetrain`); write each as ``<name>.png`` into ``folder``
    (each file written beside and renamed, so none is left half-written). Returns the file names."""
    import os

    import matplotlib.pyplot as plt

    from thermogear.drivetrain.pictures import drivetrain_pictures
    from thermogear.errors import CaseError

    if data is None or "not_computed" in data or built is None:
        reason = (data or {}).get("not_computed", "the drivetrain was not built")
        raise CaseError("--plot", str(folder), "a drivetrain whose results were computed", f"no pictures: {reason}")
    figures = drivetrain_pictures(built, data)
    folder.mkdir(parents=True, exist_ok=True)
    written = []
    for name, figure in figures.items():
        target = folder / f"{name}.png"
        partial = folder / f".{name}.partial.png"
        figure.savefig(partial, dpi=150)
        plt.close(figure)
        os.replace(partial, target)
        written.append(target.name)
    return written
