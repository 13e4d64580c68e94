"""`thermogear run CASE`: the dynamics of one case (elastic and/or thermal), as a table, JSON or a full report."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import typer

from thermogear.cli.app import app, console, error_console, print_json
from thermogear.report.terminal import interruptible
from thermogear.errors import CaseError, ModelLimitError
from thermogear.gearbox.case_model import (describe_prediction, gearbox_model_from_case, gearbox_operating_point,
                                           predicted_steady_state)
from thermogear.mesh.model_names import THERMAL

if TYPE_CHECKING:
    from thermogear.dynamics.metric_results import LinearMetrics, NonlinearMetrics
    from thermogear.mesh.model import MeshModel

_MODELS = {"elastic": ("elastic",), "thermal": ("thermal",), "both": ("elastic", "thermal")}


def model_json(response) -> dict:
    """The JSON object of one model (issue 5): loads per unit width, displacements in μm, stability, messages."""
    from thermogear.report.evaluate import model_messages

    from thermogear.dynamics.metric_results import typed_metrics
    from thermogear.serialization import json_ready

    metrics = typed_metrics(response.metrics)
    regions = list(metrics.equilibrium_per_region)
    return json_ready({  # a number that could not be computed (no orbit, a region never reached) is null
        "status": response_status(metrics),
        "kv": metrics.kv,
        "max_pair_load_n_per_mm": metrics.max_pair_load_n_per_mm,
        "max_system_load_n_per_mm": metrics.max_system_load_n_per_mm,
        "max_system_load_ratio": metrics.max_system_load_ratio,
        "static_load_n_per_mm": metrics.static_load_n_per_mm,
        "equilibrium_um": {region: metrics.equilibrium_per_region[region] * 1e6 for region in regions},
        "amplitude_um": {region: metrics.amplitude_per_region[region] * 1e6 for region in regions},
        "natural_frequency_hz": metrics.natural_frequency_hz,
        "damping_ratio": response.metrics.get("damping_ratio"),  # added by the simulation (a gear quantity)
        "mesh_frequency_hz": metrics.mesh_frequency_hz,
        "frequency_ratio": metrics.frequency_ratio,
        "floquet_multipliers_abs": metrics.floquet_multipliers_abs,
        "stable": metrics.stable,
        "contact_loss": bool(metrics.contact_loss.detected),
        "valid": metrics.valid,
        "mesh": metrics.mesh,
        "contact_loss_fraction": metrics.contact_loss_fraction,
        "back_side_contact": metrics.back_side_contact,
        "response": metrics.response,
        "branch": metrics.branch,
        "coexisting_orbits": metrics.coexisting_orbits,
        "dte_peak_to_peak_um": metrics.dte_peak_to_peak * 1e6,
        "dte_rms_um": metrics.dte_rms * 1e6,
        "method": response.method,
        "messages": model_messages(response, response.label or ""),
    }, non_finite="null")


def response_status(metrics: LinearMetrics | NonlinearMetrics) -> str:
    """One word for what the model found: ``"valid"`` (a steady orbit, stable, inside the model's limits),
    ``"non-periodic"`` (no repeating orbit: the metrics describe the recorded periods) or ``"not valid"``."""
    if metrics.valid:
        return "valid"
    return "non-periodic" if metrics.response == "non-periodic" else "not valid"


@app.command()
def run(
    case_name: str = typer.Argument(..., metavar="CASE", help="built-in parameter set (thermogear cases) or a .toml"),
    model: str = typer.Option("both", "--model", help="elastic | thermal | both"),
    method: str = typer.Option(None, "--method", help="periodic | transient (default: the case's [dynamics])"),
    as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
    out: Path = typer.Option(None, "--out", help="write the full report (report.html, figures, results.nc, "
                                                 "summary.json) into this folder"),
    force: bool = typer.Option(False, "--force", help="replace an existing --out folder (and the picture files of "
                                                     "--plot)"),
    quiet: bool = typer.Option(False, "--quiet", "-q", help="no progress bar, and no summary with --out (for scripts)"),
    csv: Path = typer.Option(None, "--csv", help="also write the steady responses as CSV (a row per time sample and "
                                                 "model, units in the column names)"),
    plot: Path = typer.Option(None, "--plot", help="write the drivetrain's pictures (layout, mode shapes, Campbell "
                                                   "diagram, bearing-force spectra; PNG) into this folder"),
) -> None:
    """Run the dynamics of a case and report Kv, loads, transmission error per region, frequencies and stability.
    Contact loss and instability are said in words (when, how long, how deep)."""
    from thermogear.case import load_case
    from thermogear.preflight import preflight
    from thermogear.report.evaluate import model_messages
    from thermogear.cli.console import print_notes, step_progress
    from thermogear.report.terminal import print_messages, print_summary

    if model not in _MODELS:
        raise CaseError("--model", model, "elastic | thermal | both", "unknown model")
    if method is not None and method not in ("periodic", "transient"):
        raise CaseError("--method", method, "periodic | transient", "unknown solution method")
    if out is not None:
        from thermogear.ownership import check_output_folder
        from thermogear.report.writer import OutputFolder

        check_output_folder(out, "--out")  # before any work: a name the system can hold, writable
        OutputFolder(out, force=force).check()  # an existing folder: --force, and thermogear's own
    if csv is not None:
        from thermogear.cli.export import check_csv_target

        check_csv_target(csv, force, "--csv")
    case = load_case(case_name)
    if plot is not None:
        from thermogear.cli.run_drivetrain import check_picture_folder

        plot = check_picture_folder(plot, case, force)  # before any work
    method = method or case.dynamics.method
    models = _MODELS[model]
    preflight(case, models, quiet=False, method=method)  # the checks `check` makes, before any output is written
    if out is not None:
        from thermogear.report.build import build_report, report_steps

        steps = report_steps(case.citation)
        with interruptible(out), step_progress(steps, quiet or as_json, error_console) as advance:
            outcome = build_report(case, out, force=force, method=method, paper=False, progress=advance)
        responses = {name: outcome.evaluation.responses[name] for name in models
                     if name in outcome.evaluation.responses}
        failed = {name: outcome.evaluation.problems[f"{name} model"] for name in models
                  if f"{name} model" in outcome.evaluation.problems}
        thermoelastic = outcome.evaluation.thermoelastic_summary if THERMAL in models else None
    else:
        from thermogear.mesh.model import MeshModel
        from thermogear.simulation import Simulation, solver_for

        solver = solver_for(case.dynamics, method)  # the --method string, resolved once
        responses, failed, limit = {}, {}, None
        with step_progress([f"{name} model" for name in models], quiet or as_json, error_console) as advance:
            for name in models:
                advance(f"{name} model")
                try:
                    responses[name] = Simulation(case, name, solver=solver).run()
                except ModelLimitError as error:  # e.g. unstable: said, and the other model still computed
                    failed[name], limit = f"{type(error).__name__}: {error}", limit or error
        if not responses:
            raise limit
        thermoelastic = _thermoelastic_summary(MeshModel(case, THERMAL)) if THERMAL in models else None
    messages = [text for name, response in responses.items() for text in model_messages(response, name)]
    from thermogear.cli.run_drivetrain import drivetrain_outputs, print_drivetrain  # [drivetrain] (issue 27)
    from thermogear.drivetrain.case_model import drivetrain_builder

    build = drivetrain_builder(case, models)
    steps = [f"drivetrain, {name} model" for name in models] if build is not None and out is None else []
    with step_progress(steps, quiet or as_json or not steps, error_console) as advance:
        drivetrain = drivetrain_outputs(build, models, outcome if out is not None else None, responses,
                                        transient=method == "transient", progress=advance)
    if plot is not None:
        from thermogear.cli.run_drivetrain import write_pictures

        pictures = write_pictures(plot, build, drivetrain,
                                  getattr(outcome.evaluation, "drivetrain_built", None) if out is not None else None)
        if not as_json:
            console.print(f"drivetrain pictures written to {plot}: {', '.join(pictures)}", highlight=False)
    if csv is not None:
        from thermogear.cli.export import responses_csv

        responses_csv(csv, responses, case_name=case.name, case_source=str(case.source),
                      load_held=case.operating_point.load_held)
    predicted = None  # the gearbox model's prediction, said beside the outputs where it set the temperatures
    if case.temperature.model == "gearbox":
        predicted = describe_prediction(predicted_steady_state(
            gearbox_model_from_case(case), gearbox_operating_point(case.operating_point, case.gearbox)))
    if as_json:
        payload = {"case": case.name, "method": method, "load_held": case.operating_point.load_held,
                   "models": {name: {**model_json(response), "messages": model_messages(response, name)}
                              for name, response in responses.items()}}
        payload["notes"] = list(case.notes)
        if thermoelastic is not None:
            payload["thermoelastic"] = thermoelastic
        if failed:
            payload["not_computed"] = failed
        if drivetrain is not None:
            payload["drivetrain"] = drivetrain
        if predicted:
            payload["temperatures"] = predicted
        if out is not None:
            payload["report"] = str(outcome.report)
        if plot is not None:
            payload["plots"] = [str(plot / name) for name in pictures]
        print_messages(messages, error_console)
        print_json(payload)
        return
    if out is not None:
        if quiet:  # scripts: no summary, but what the model must say (contact loss, instability) still goes out
            print_messages(messages, error_console)
        else:
            print_summary(outcome, console)
            console.print(_load_held_line(case.operating_point))
            print_notes(case.notes, console)
        for name, reason in failed.items():
            error_console.print(f"{name} model not computed: {reason}", highlight=False)
        return
    _print_table(case.name, responses, console, thermoelastic)
    print_drivetrain(drivetrain, console)
    console.print(_load_held_line(case.operating_point))
    print_notes(case.notes, console)
    if predicted:
        console.print(predicted, highlight=False)
    print_messages(messages, console)
    for name, reason in failed.items():  # as the report says it (run --out)
        error_console.print(f"{name} model not computed: {reason}", highlight=False)


def _load_held_line(operating_point) -> str:
    """``load held: constant torque|power`` with where it comes from (the same words as the sweep's)."""
    held = operating_point.load_held
    source = "the case gives power_kw" if held == "constant power" else "the case gives the torque"
    return f"load held: {held} ({source})"


def _thermoelastic_summary(thermal: MeshModel) -> dict | None:
    """What the thermo-elastic model is for (operating geometry, backlash, jamming, E(T), loaded STE), where it is
    the case's thermal model (``thermal``, its thermal MeshModel, holds the component); None under the paper's model
    (its k_T has none of these)."""
    from thermogear.evaluation import uses_paper_thermal_stiffness

    if uses_paper_thermal_stiffness(thermal):
        return None
    from thermogear.summaries.thermoelastic import thermoelastic_summary

    return thermoelastic_summary(thermal.thermoelastic_mesh, thermal.thermal_model, thermal.temperature)


def _print_table(case_name: str, responses, console, thermoelastic: dict | None = None) -> None:
    from rich.table import Table

    table = Table(title=f"{case_name}: dynamics ({', '.join(responses)})", header_style="bold")
    table.add_column("quantity")
    for name in responses:
        table.add_column(name, justify="right")
    table.add_column("unit")
    data = {name: model_json(response) for name, response in responses.items()}
    rows = [("Kv (Eq. 29)", "kv", "–"), ("max pair load", "max_pair_load_n_per_mm", "N/mm"),
            ("max system load / static", "max_system_load_ratio", "–"),
            ("natural frequency", "natural_frequency_hz", "Hz"), ("frequency ratio λ", "frequency_ratio", "–"),
            ("damping ratio ζ (mean)", "damping_ratio", "–")]
    for label, key, unit in rows:
        table.add_row(label, *(_shown(d[key]) for d in data.values()), unit)
    regions = list(next(iter(data.values()))["equilibrium_um"])
    for region in regions:
        table.add_row(f"equilibrium, {region}", *(_shown(d["equilibrium_um"].get(region)) for d in data.values()),
                      "μm")
    for region in regions:
        table.add_row(f"amplitude, {region}", *(_shown(d["amplitude_um"].get(region)) for d in data.values()),
                      "μm")
    table.add_row("DTE peak-to-peak", *(_shown(d["dte_peak_to_peak_um"]) for d in data.values()), "μm")
    table.add_row("largest |Floquet multiplier|", *(_shown(d["floquet_multipliers_abs"][0]) for d in data.values()),
                  "–")
    if any(d["mesh"] == "nonlinear" for d in data.values()):
        table.add_row("time without contact", *(_shown(d["contact_loss_fraction"], 100.0)
                                                for d in data.values()), "%")
        table.add_row("back flanks struck", *("yes" if d["back_side_contact"] else "no" for d in data.values()), "")
        table.add_row("response (branch)", *(f"{d['response']} ({d['branch']})" for d in data.values()), "")
        table.add_row("steady orbit found", *("yes" if d["valid"] else "not found" if d["response"] == "non-periodic"
                                              else "NO" for d in data.values()), "")
    else:
        table.add_row("linear model valid", *("yes" if d["valid"] else "NO" for d in data.values()), "")
    if thermoelastic is not None:
        from thermogear.report.thermoelastic_rows import thermoelastic_rows

        table.add_section()
        for label, unit, elastic, thermal, _ in thermoelastic_rows(thermoelastic):
            cells = {"elastic": elastic, "thermal": thermal}
            table.add_row(label, *(_shown(cells[name]) if cells[name] is not None else "—" for name in responses),
                          unit)
    console.print(table)


def _shown(value, scale: float = 1.0) -> str:
    """A table cell: a number, or "not found" where the model gave none (JSON null)."""
    from thermogear.report.paper_table import format_value

    return "not found" if value is None else format_value(scale * value)
