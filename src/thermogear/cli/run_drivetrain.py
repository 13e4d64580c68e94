"""`thermogear run` on a case with a ``[drivetrain]``: the drivetrain's modes (labels, energy shares, cold and hot,
what heat moved), its Kv and DTE, and the dynamic force of each bearing on the housing, as tables or JSON."""

from __future__ import annotations

from pathlib import Path
from typing import Any

__all__ = ["check_picture_folder", "drivetrain_outputs", "print_drivetrain", "write_pictures"]


def drivetrain_outputs(build, models: tuple[str, ...], outcome=None, responses=None, transient: bool = False,
                       progress=None) -> dict[str, Any] | None:
    """The drivetrain results (None without a ``[drivetrain]``: ``build`` None, else the function that builds the
    case's CaseDrivetrain, :func:`~thermogear.drivetrain.case_model.drivetrain_builder`): those the report computed
    when there is one (``outcome``), computed here otherwise (``transient``: the last period of the motion from
    rest; ``progress`` called before each model). Where the drivetrain's mesh was linear and the pair's own
    ``responses`` find the teeth separating, a note says that the drivetrain's numbers assume permanent contact."""
    if build is None:
        return None
    if outcome is not None and getattr(outcome.evaluation, "drivetrain", None) is not None:
        data = outcome.evaluation.drivetrain
    else:
        from thermogear.report.drivetrain_section import drivetrain_report_data

        data = drivetrain_report_data(build, models, transient, progress)
    separated = [name for name, response in (responses or {}).items()
                 if response.metrics.get("contact_loss", {}).get("detected")]
    if separated and "notes" in data and not data.get("backlash_mesh"):
        data = {**data, "notes": [*data["notes"], f"drivetrain: the pair's {' and '.join(separated)} model finds "
                                  "the teeth separating; the drivetrain's numbers assume permanent contact (linear "
                                  "mesh) and overstate the mesh force there"]}
    return data


def _number(value, pattern: str = "{:.1f}") -> str:
    return "not found" if value is None else pattern.format(value)


def print_drivetrain(data: dict[str, Any] | None, console) -> None:
    """Print the drivetrain tables: modes (with the cold → hot shift and its main cause), response, bearings."""
    if data is None:
        return
    if "not_computed" in data:
        console.print(f"drivetrain not computed: {data['not_computed']}", highlight=False)
        return
    from rich.table import Table

    models = data["models"]
    first = next(iter(models.values()))
    heat = data.get("heat")
    table = Table(title=f"drivetrain modes ({data['degrees_of_freedom']} DOF; shares of the modal strain energy; "
                        "other: couplings and motor supports)", header_style="bold")
    for column in ("mode", "label", *(f"{name} [Hz]" for name in models), "mesh", "bearings", "shafts", "other"):
        table.add_column(column, justify="left" if column == "label" else "right")
    if heat:
        table.add_column("cold→hot [%]", justify="right")
        table.add_column("main cause")
    for index, mode in enumerate(first["modes"]):
        shares = mode["energy_shares"]
        cells = [str(index + 1), mode["label"] + (" *" if mode["mesh_dominated"] else ""),
                 *(_number(model["modes"][index]["frequency_hz"]) for model in models.values()),
                 *(f"{shares.get(key, 0.0):.3f}" for key in ("mesh", "bearings", "shafts")),
                 f"{sum(v for k, v in shares.items() if k not in ('mesh', 'bearings', 'shafts')):.3f}"]
        if heat:
            cells += [f"{heat[index]['shift_percent']:+.3f}", heat[index]["dominant_cause"]]
        table.add_row(*cells)
    console.print(table)
    console.print("* mesh-dominated (mesh share > 0.1). Mesh harmonics meet modes with a mesh share above 0.01 at: "
                  + ("; ".join(f"{r['harmonic']}× mesh at {r['speed_rpm']:.0f} rpm ({r['mode_hz']:.0f} Hz "
                               f"{r['label']}{' *' if r['mesh_dominated'] else ''}, {name})"
                               for name, model in models.items() for r in model["resonances"]) or "none"),
                  highlight=False)
    response = Table(title=f"drivetrain response (mesh {data['mesh']}; {data['solved_on']})", header_style="bold")
    for column in ("quantity", *models, "unit"):
        response.add_column(column, justify="left" if column in ("quantity", "unit") else "right")
    rows = [("Kv", "kv", "{:.4f}", "–"), ("DTE RMS", "dte_rms_um", "{:.3f}", "μm"),
            ("DTE peak-to-peak", "dte_peak_to_peak_um", "{:.3f}", "μm")]
    if not data.get("transient"):
        rows.append(("largest |Floquet multiplier|", "largest_floquet_multiplier_abs", "{:.4f}", "–"))
    for label, key, pattern, unit in rows:
        response.add_row(label, *(_number(model[key], pattern) for model in models.values()), unit)
    for stage in first.get("stages", {}):  # a train: each mesh over the common period
        response.add_section()
        for label, key, pattern, unit in (("Kv", "kv", "{:.4f}", "–"), ("DTE RMS", "dte_rms_um", "{:.3f}", "μm"),
                                          ("DTE peak-to-peak", "dte_peak_to_peak_um", "{:.3f}", "μm"),
                                          ("largest mesh force", "max_mesh_force_n", "{:.1f}", "N")):
            response.add_row(f"{stage}: {label}", *(_number(model["stages"][stage][key], pattern)
                                                    for model in models.values()), unit)
    if data.get("backlash_mesh"):
        response.add_row("time without contact", *(_number(_percent(model["contact_loss_fraction"]), "{:.2f}")
                                                   for model in models.values()), "%")
        response.add_row("back flanks struck", *(_yes_no(model["back_side_contact"]) for model in models.values()),
                         "")
    if data.get("backlash_mesh") and not data.get("transient"):
        response.add_row("periodic orbit found (stable)", *(_found(model) for model in models.values()), "")
    for bearing in first["bearing_forces"]:
        forces = {name: model["bearing_forces"][bearing] for name, model in models.items()}
        response.add_section()
        response.add_row(f"{bearing}: mean radial", *(_number(f["mean_radial_n"]) for f in forces.values()), "N")
        response.add_row(f"{bearing}: dynamic RMS", *(_number(f["dynamic_rms_n"]) for f in forces.values()), "N")
        for j, frequency in enumerate(next(iter(forces.values()))["harmonic_hz"]):
            line = f"mesh harmonic {frequency:.0f} Hz" if "stages" in first else f"{j + 1}× mesh ({frequency:.0f} Hz)"
            response.add_row(f"{bearing}: {line}",
                             *(_number(f["harmonic_amplitude_n"][j], "{:.2f}") for f in forces.values()), "N")
    console.print(response)
    _print_warm_state(data.get("warm_state"), console)
    for name, model in models.items():
        if model.get("failure"):
            console.print(f"drivetrain, {name} model: no periodic orbit — {model['failure']}", highlight=False)
    for note in data.get("notes", []):
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


def _percent(value):
    return None if value is None else 100.0 * value


def _yes_no(value) -> str:
    return "not found" if value is None else "yes" if value else "no"


def _found(model: dict[str, Any]) -> str:
    """'yes' for a converged stable orbit, 'yes (unstable)', or 'NO' where none was found."""
    if not model.get("converged"):
        return "NO"
    return "yes" if model.get("stable") else "yes (unstable)"


def check_picture_folder(folder: Path, case, force: bool) -> Path:
    """``run --plot FOLDER``, checked before any work: the case has a [drivetrain] (the pictures are of it), the
    folder can be written, and no picture file of the same name is there unless ``force`` (thermogear replaces only
    what it wrote: the files it would replace are its own names, and --force says to replace them)."""
    from thermogear.drivetrain.pictures import PICTURES
    from thermogear.errors import CaseError
    from thermogear.ownership import check_output_folder

    if case.drivetrain is None:
        raise CaseError("--plot", str(folder), "a case with a [drivetrain] section",
                        "the pictures are of the drivetrain (layout, modes, Campbell, bearing forces); the pair's "
                        "own figures are in the report: run --out FOLDER")
    target = check_output_folder(folder, "--plot")
    existing = [f"{name}.png" for name in PICTURES if (target / f"{name}.png").exists()]
    if existing and not force:
        raise CaseError("--plot", str(folder), "a folder without thermogear's picture files, or --force",
                        f"{', '.join(existing)} would be replaced")
    return target


def write_pictures(folder: Path, build, data: dict[str, Any] | None, built=None) -> list[str]:
    """Draw the drivetrain's pictures (:mod:`thermogear.drivetrain.pictures`) of the results ``data`` that ``run``
    reports, from ``built`` (the report's CaseDrivetrain) or ``build()``; write each as ``<name>.png`` into
    ``folder`` (each file written beside and renamed, so none is left half-written). Returns the file names."""
    import os

    import matplotlib.pyplot as plt

    from thermogear.drivetrain.pictures import drivetrain_pictures
    from thermogear.errors import CaseError

    if data is not None and "not_computed" in data:
        raise CaseError("--plot", str(folder), "a drivetrain whose results were computed",
                        f"no pictures: {data['not_computed']}")
    figures = drivetrain_pictures(built if built is not None else build(), data)
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
