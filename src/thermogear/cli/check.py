"""`thermogear check CASE`: validate a case file and show the geometry it describes."""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from contextlib import contextmanager

import typer
from rich.table import Table

from thermogear.case import load_case
from thermogear.cli.app import app, console, print_json
from thermogear.cli.console import print_notes, warning_text


@app.command()
def check(case: str = typer.Argument(..., metavar="CASE",
                                  help="built-in parameter set name or path to a .toml case file"),
          as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout")) -> None:
    """Validate a case and print its gear-pair geometry (exit status 2 with one clear message if it is invalid)."""
    from thermogear.load_capacity import load_flags
    from thermogear.orchestrator import Orchestrator

    with shown_warnings() as shown:  # printed on stderr as they come, and listed in the JSON
        loaded = load_case(case)
        # what run builds before it solves (the hot backlash of the whole temperature field)
        Orchestrator(loaded).preflight()
        _check_study_table(case, loaded.document.get("sweep"))
    pair = loaded.gear_pair
    payload = {
        "case": loaded.name,
        "valid": True,
        "centre_distance_mm": pair.centre_distance * 1e3,
        "operating_pressure_angle_deg": math.degrees(pair.operating_pressure_angle),
        "contact_ratio": pair.contact_ratio,
        "tip_diameter_mm": {"pinion": 2e3 * pair.pinion.tip_radius, "wheel": 2e3 * pair.wheel.tip_radius},
        "root_diameter_mm": {"pinion": 2e3 * pair.pinion.root_radius, "wheel": 2e3 * pair.wheel.root_radius},
        "base_diameter_mm": {"pinion": 2e3 * pair.pinion.base_radius, "wheel": 2e3 * pair.wheel.base_radius},
        "path_mm": {key: value * 1e3 for key, value in pair.path_points.items()},
        "normal_load_n": loaded.normal_load,
        "pinion_torque_nm": loaded.operating_point.torque,
        "mesh_frequency_hz": pair.mesh_frequency(loaded.operating_point.speed_rpm),
        # a load no steel tooth carries is computed by run, and labelled there and here
        "load_checks": list(load_flags(pair, loaded.material, loaded.operating_point.torque)),
    }
    if loaded.helical_pair is not None:  # the pair above is its transverse section
        from thermogear.helical.summary import helical_geometry_summary

        payload["helical"] = helical_geometry_summary(loaded.helical_pair)
    payload["notes"] = list(loaded.notes)
    payload["model_checks"] = model_choice_flags(loaded.thermal.model, loaded.dynamics.mesh)
    payload["warnings"] = list(dict.fromkeys(shown))  # keys without effect, extrapolated fits, … (once each)
    if as_json:
        print_json(payload)
        return
    table = Table(title=f"{loaded.name}: {loaded.title}")
    table.add_column("quantity")
    table.add_column("value", justify="right")
    table.add_row("centre distance [mm]", f"{payload['centre_distance_mm']:.4f}")
    table.add_row("operating pressure angle [°]", f"{payload['operating_pressure_angle_deg']:.4f}")
    table.add_row("contact ratio ε_α [–]", f"{pair.contact_ratio:.4f}")
    for gear in ("pinion", "wheel"):
        table.add_row(f"{gear} d_a / d_b / d_f [mm]",
                      f"{payload['tip_diameter_mm'][gear]:.3f} / {payload['base_diameter_mm'][gear]:.3f} / "
                      f"{payload['root_diameter_mm'][gear]:.3f}")
    table.add_row("path A/B/C/D/E from T1 [mm]", " / ".join(f"{v:.3f}" for v in payload["path_mm"].values()))
    if "helical" in payload:
        add_helical_rows(table, payload["helical"])
    table.add_row("normal load F_bt [N]", f"{loaded.normal_load:.1f}")
    table.add_row("mesh frequency [Hz]", f"{payload['mesh_frequency_hz']:.2f}")
    console.print(table)
    print_notes(loaded.notes, console)
    for flag in payload["load_checks"] + payload["model_checks"]:
        console.print(f"check — {flag}", highlight=False)
    console.print("case is valid", style="green")


def add_helical_rows(table: Table, helical: dict) -> None:
    """The helical geometry's rows (:func:`thermogear.helical.summary.helical_geometry_summary`)."""
    lengths = helical["contact_line_length_mm"]
    for label, text in (
            ("helix angle β / base helix angle β_b [°]",
             f"{helical['helix_angle_deg']:.4f} / {helical['base_helix_angle_deg']:.4f}"),
            ("hand (pinion; the wheel has the other)", helical["hand"]),
            ("module m_n / m_t [mm]", f"{helical['normal_module_mm']:.4f} / {helical['transverse_module_mm']:.4f}"),
            ("pressure angle α_n / α_t [°]",
             f"{helical['normal_pressure_angle_deg']:.4f} / {helical['transverse_pressure_angle_deg']:.4f}"),
            ("contact ratios ε_α / ε_β / ε_γ [–]", f"{helical['transverse_contact_ratio']:.4f} / "
                                                  f"{helical['overlap_ratio']:.4f} / {helical['total_contact_ratio']:.4f}"),
            ("axial pitch p_x [mm]", f"{helical['axial_pitch_mm']:.3f}"),
            ("contact-line length mean / min / max [mm]",
             f"{lengths['mean']:.3f} / {lengths['min']:.3f} / {lengths['max']:.3f}")):
        table.add_row(label, text)


@contextmanager
def shown_warnings() -> Iterator[list[str]]:
    """The warnings shown in the block, as the command line prints them (``warnings.showwarning`` is wrapped, so
    Python's filters still decide what shows and each is still printed on stderr)."""
    shown: list[str] = []
    previous = warnings.showwarning

    def keep(message, category, filename, lineno, file=None, line=None) -> None:
        shown.append(warning_text(str(message)))
        previous(message, category, filename, lineno, file, line)

    warnings.showwarning = keep
    try:
        yield shown
    finally:
        warnings.showwarning = previous


def model_choice_flags(thermal_model: str, mesh: str) -> list[str]:
    """What ``run`` flags on every result of this choice of models (``[thermal] model`` and ``[dynamics] mesh``), said
    by ``check`` before any solving (check = run): the paper's secant k_T used as the contact stiffness of the
    nonlinear mesh."""
    from thermogear.mesh.pair_models import PAIR_MODELS, pair_model_name  # noqa: PLC0415

    pair_model = PAIR_MODELS.get(pair_model_name("thermal", thermal_model))
    return [] if pair_model is None else pair_model.choice_flags(mesh)


def _check_study_table(case: str, sweep_table) -> None:
    """A [sweep] table (``sweep_table``, the case file's, None where it has none) is defined as ``thermogear sweep``
    defines it (names resolved, every value's case checked), so a table ``check`` accepts is one ``sweep`` runs."""
    if sweep_table is None:
        return
    from thermogear.sweep.study import Study, load_study_case

    study_case, section = load_study_case(case)
    if section is not None and section.vary:
        Study.define(study_case, dict(section.vary), model=section.model, chunk_points=section.chunk_points)
