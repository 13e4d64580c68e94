"""`thermogear run CASE`: the dynamics of one case (elastic and/or thermal), as a table, JSON or a full report."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import typer

from thermogear.cli.app import app, console, error_console, print_json
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError
from thermogear.gearbox.case_model import describe_prediction
from thermogear.report.terminal import interruptible

if TYPE_CHECKING:
    from thermogear.dynamics.results.metric_results import LinearMetrics, NonlinearMetrics

_MODELS = {"elastic": ("elastic",), "thermal": ("thermal",), "both": ("elastic", "thermal")}


def model_json(response) -> dict:
    """The JSON object of one model (issue 5): loads per unit width, displacements in μm, stability, messages."""
    from thermogear.report.evaluate import model_messages

    from thermogear.dynamics.results.metric_results import typed_metrics
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
    multistart: int = typer.Option(0, "--multistart", min=0, help="backlash drivetrain: also search this many starts "
                                                                  "(rest, the linear solution, a grid) and list every "
                                                                  "stable orbit with its basin share"),
) -> None:
    """Run the dynamics of a case and report Kv, loads, transmission error per region, frequencies and stability.
    Contact loss and instability are said in words (when, how long, how deep)."""
    from thermogear.case import load_case
    from thermogear.cli.check import shown_warnings
    from thermogear.cli.console import print_notes, step_progress
    from thermogear.cli.run_drivetrain import print_drivetrain
    from thermogear.dynamics.problems.solution_methods import solution_method
    from thermogear.orchestrator import Orchestrator
    from thermogear.report.drivetrain_section import drivetrain_json
    from thermogear.report.evaluate import model_messages
    from thermogear.report.evaluate import DYNAMIC_FACTORS_NOTE
    from thermogear.report.terminal import print_messages, print_summary

    if model not in _MODELS:
        raise CaseError("--model", model, "elastic | thermal | both", "unknown model")
    if method is not None:
        solution_method(method, key="--method")  # a CaseError for an unknown one
    if out is not None:
        from thermogear.ownership import check_output_folder
        from thermogear.report.writer import OutputFolder

        check_output_folder(out, "--out")  # before any work: a name the system can hold, writable
        OutputFolder(out, force=force).check()  # an existing folder: --force, and thermogear's own
    if csv is not None:
        from thermogear.cli.export import check_csv_target

        check_csv_target(csv, force, "--csv")
    case = load_case(case_name)
    method = method or case.dynamics.method
    if multistart:
        from thermogear.cli.run_multistart import check_multistart

        check_multistart(case.drivetrain, case.dynamics, multistart, method, out)  # before any work
    if plot is not None:
        from thermogear.cli.run_drivetrain import check_picture_folder

        plot = check_picture_folder(plot, case.drivetrain, force)  # before any work
    models = _MODELS[model]
    orchestrator = Orchestrator(case, models, method)
    with shown_warnings() as shown:  # every warning printed on stderr, for --json's "messages" (issue 36)
        orchestrator.preflight(quiet=False)  # the checks `check` makes, before any output is written
        if out is not None:
            from thermogear.report.build import build_report, report_steps

            steps = report_steps(case.citation, drivetrain=case.drivetrain is not None)
            with interruptible(out), step_progress(steps, quiet or as_json, error_console) as advance:
                outcome = build_report(case, out, force=force, method=method, paper=False, progress=advance)
            results = outcome.evaluation.run_results(models)
        else:
            steps = [f"{name} model" for name in models]
            if case.drivetrain is not None:
                steps += [f"drivetrain, {name} model" for name in models]
            steps += [f"multi-start search, {name} model" for name in models] if multistart else []
            with step_progress(steps, quiet or as_json, error_console) as advance:
                results = orchestrator.run(progress=advance)
                if multistart:
                    from thermogear.cli.run_multistart import multistart_json

                    orbits = multistart_json(orchestrator.built_drivetrain, models, multistart,
                                             progress=lambda name: advance(f"multi-start search, {name} model"))
    responses = {name: pair.response for name, pair in results.pair.items()}
    messages = [text for name, response in responses.items() for text in model_messages(response, name)]
    drivetrain = drivetrain_json(results.drivetrain, results.drivetrain_not_computed)
    if plot is not None:  # the pictures of the CaseDrivetrain the results came from
        from thermogear.cli.run_drivetrain import write_pictures

        built = outcome.evaluation.drivetrain_built if out is not None else orchestrator.built_drivetrain
        pictures = write_pictures(plot, drivetrain, built)
        if not as_json:
            console.print(f"drivetrain pictures written to {plot}: {', '.join(pictures)}", highlight=False)
    if csv is not None:
        from thermogear.cli.export import responses_csv

        responses_csv(csv, responses, case_name=case.name, case_source=str(case.source),
                      load_held=case.operating_point.load_held)
    predicted = None if results.temperatures is None else describe_prediction(results.temperatures)
    if as_json:
        payload = {"case": case.name, "method": method, "load_held": case.operating_point.load_held,
                   "models": {name: {**model_json(response), "messages": model_messages(response, name),
                                     "mesh_stiffness_step_ratio": results.pair[name].mesh_stiffness_step_ratio}
                              for name, response in responses.items()}}
        payload["notes"] = list(case.notes)
        if results.thermoelastic is not None:
            payload["thermoelastic"] = results.thermoelastic
        if results.not_computed:
            payload["not_computed"] = dict(results.not_computed)
        if drivetrain is not None:
            payload["drivetrain"] = drivetrain
            if multistart:
                payload["drivetrain"]["multistart"] = orbits
        if predicted:
            payload["temperatures"] = predicted
        if out is not None:
            payload["report"] = str(outcome.report)
        if plot is not None:
            payload["plots"] = [str(plot / name) for name in pictures]
        payload["headline"] = headline_json(results)
        payload["dynamic_factors"] = DYNAMIC_FACTORS_NOTE
        print_messages(messages, error_console)
        payload["messages"] = messages + [f"warning: {text}" for text in _distinct(shown, results.warnings)]
        print_json(payload)
        return
    if out is not None:
        if quiet:  # scripts: no summary, but what the model must say (contact loss, instability) still goes out
            print_messages(messages, error_console)
        else:
            print_summary(outcome, console)
            console.print(_load_held_line(case.operating_point))
            print_notes(case.notes, console)
        for name, reason in results.not_computed.items():
            error_console.print(f"{name} model not computed: {reason}", highlight=False)
        return
    _print_table(case.name, results.pair, console, results.thermoelastic,
                 pair_label=" (1-DOF pair)" if results.drivetrain is not None else "")
    print_notes([DYNAMIC_FACTORS_NOTE], console)
    print_drivetrain(results.drivetrain, console, results.drivetrain_not_computed)
    if multistart:
        from thermogear.cli.run_multistart import print_multistart

        print_multistart(orbits, console)
    if results.drivetrain is not None:
        console.print(headline_line(results), highlight=False)
    console.print(_load_held_line(case.operating_point))
    print_notes(case.notes, console)
    if predicted:
        console.print(predicted, highlight=False)
    print_messages(messages, console)
    for name, reason in results.not_computed.items():  # as the report says it (run --out)
        error_console.print(f"{name} model not computed: {reason}", highlight=False)


def _distinct(*groups) -> list[str]:
    """The warning texts of ``groups`` without their category prefix, each cause once, in order."""
    from thermogear.cli.console import warning_text
    from thermogear.warning_causes import warning_cause

    seen, texts = set(), []
    for group in groups:
        for item in group:
            text = warning_text(item)
            if warning_cause(text) not in seen:
                seen.add(warning_cause(text))
                texts.append(text)
    return texts


def headline_json(results) -> dict:
    """The headline dynamic factor per model: the drivetrain's where the case has one (the structure the case
    describes), with the 1-DOF pair's beside it (issue 36)."""
    from thermogear.serialization import json_ready

    headline = {}
    for name in results.pair:
        kv, system = results.headline_kv(name)
        headline[name] = {"kv": kv, "system": system, "pair_kv": results.pair[name].kv}
    return json_ready(headline, non_finite="null")


def headline_line(results) -> str:
    """One line: the drivetrain's Kv per model (the headline) with the 1-DOF pair's beside it, labelled."""
    parts = []
    for name in results.pair:
        kv, system = results.headline_kv(name)
        pair = results.pair[name].kv
        parts.append(f"{name} Kv {_shown(kv)} ({system}; 1-DOF pair on rigid supports {_shown(pair)})")
    return "headline: " + "; ".join(parts)


def _load_held_line(operating_point) -> str:
    """``load held: constant torque|power`` with where it comes from (the same words as the sweep's)."""
    held = operating_point.load_held
    source = "the case gives power_kw" if operating_point.constant_power else "the case gives the torque"
    return f"load held: {held} ({source})"


def _print_table(case_name: str, responses, console, thermoelastic: dict | None = None, pair_label: str = "") -> None:
    from rich.table import Table

    table = Table(title=f"{case_name}: dynamics ({', '.join(responses)})", header_style="bold")
    table.add_column("quantity")
    for name in responses:
        table.add_column(name, justify="right")
    table.add_column("unit")
    data = {name: {**model_json(pair.response), "mesh_stiffness_step_ratio": pair.mesh_stiffness_step_ratio}
            for name, pair in responses.items()}
    rows = [(f"Kv (Eq. 29){pair_label}", "kv", "–"), ("max pair load", "max_pair_load_n_per_mm", "N/mm"),
            ("max system load / static", "max_system_load_ratio", "–"),
            ("mesh stiffness step (after / before)", "mesh_stiffness_step_ratio", "–"),
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
    if any(mesh_law(d["mesh"]).backlash for d in data.values()):
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
    from thermogear.luo2020.report.table import format_value

    return "not found" if value is None else format_value(scale * value)
