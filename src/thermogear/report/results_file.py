"""The report's data files: ``results.nc`` (every curve, netCDF through xarray/h5netcdf) and ``summary.json``.

``results.nc`` has the case curves in its root group and one group per dynamic response
(``elastic_steady``, ``thermal_steady``, ``elastic_transient``, ``thermal_transient``); its attributes carry the
thermogear version, the case name and the case file's TOML text. ``summary.json`` holds the headline (predictions
within / outside / not computed, known gaps with causes), the table (one row per number of the paper for the
paper's case) with ``table_counts`` per kind, the metrics per model, the messages, the timings and the references.
"""

from __future__ import annotations

import json
from datetime import datetime, timezone
from pathlib import Path
from typing import Any

import numpy as np

from thermogear.serialization import json_ready

__all__ = ["case_toml_text", "curves_dataset", "curves_parts", "write_results_netcdf", "summary_document",
           "write_summary_json", "RESPONSE_GROUPS"]

#: netCDF group of each dynamic response: (evaluation attribute, model) → group name
RESPONSE_GROUPS = {("responses", "elastic"): "elastic_steady", ("responses", "thermal"): "thermal_steady",
                   ("transients", "elastic"): "elastic_transient", ("transients", "thermal"): "thermal_transient"}


def case_toml_text(source: str, document: dict) -> str:
    """A case file's text from the case's ``source`` (the built-in parameter set's name or the user's file), else
    its ``document`` re-serialised."""
    path = Path(str(source))
    if path.suffix == ".toml" and path.is_file():
        return path.read_text(encoding="utf-8")
    from thermogear.case import parameter_set_names, parameter_set_path

    if str(source) in parameter_set_names():
        return parameter_set_path(str(source)).read_text(encoding="utf-8")
    import tomli_w

    return tomli_w.dumps(document)


def curves_dataset(evaluation):
    """xarray Dataset of the curves along the path and over the mesh cycle (root group of results.nc)."""
    import xarray as xr

    data, coords, attrs = curves_parts(evaluation)
    return xr.Dataset(data_vars=data, coords=coords, attrs=attrs)


def curves_parts(evaluation) -> tuple[dict, dict, dict]:
    """(data variables, coordinates, attributes) of :func:`curves_dataset`, ``name → (dims, values, attrs)``."""
    from thermogear import __version__

    case = evaluation.case
    pair = case.gear_pair
    data: dict[str, Any] = {}
    coords: dict[str, Any] = {}
    if evaluation.thermal_curves is not None:
        curve = evaluation.thermal_curves.curve
        coords["gamma"] = ("gamma", np.asarray(curve.gamma), {"long_name": "contact position Γ", "units": "1"})
        coords["roll"] = ("gamma", np.asarray(curve.roll), {"long_name": "roll distance from T1", "units": "m"})
        data["elastic_pair_stiffness"] = ("gamma", np.asarray(curve.elastic_stiffness), {"units": "N/m"})
        data["thermal_pair_stiffness"] = ("gamma", np.asarray(curve.stiffness), {"units": "N/m"})
        data["elastic_pinion_compliance"] = ("gamma", np.asarray(curve.result.elastic_pinion_compliance),
                                             {"units": "m/N"})
        data["thermal_pinion_compliance"] = ("gamma", np.asarray(curve.pinion_compliance), {"units": "m/N"})
        data["elastic_wheel_compliance"] = ("gamma", np.asarray(curve.result.elastic_wheel_compliance),
                                            {"units": "m/N"})
        data["thermal_wheel_compliance"] = ("gamma", np.asarray(curve.wheel_compliance), {"units": "m/N"})
        data["expansion_pinion"] = ("gamma", np.asarray(curve.expansion_pinion), {"units": "m"})
        data["expansion_wheel"] = ("gamma", np.asarray(curve.expansion_wheel), {"units": "m"})
    if evaluation.temperature_field is not None and "gamma" in coords:
        gamma = coords["gamma"][1]
        data["pinion_flank_temperature_c"] = ("gamma", np.asarray(evaluation.temperature_field.pinion_flank_c(gamma)),
                                              {"units": "degC"})
        data["wheel_flank_temperature_c"] = ("gamma", np.asarray(evaluation.temperature_field.wheel_flank_c(gamma)),
                                             {"units": "degC"})
    if evaluation.damping is not None:
        summary = evaluation.damping
        coords["damping_gamma"] = ("damping_gamma", np.asarray(summary.path["elastic"].gamma), {"units": "1"})
        for model in ("elastic", "thermal"):
            data[f"{model}_pair_damping"] = ("damping_gamma", np.asarray(summary.path[model].damping),
                                             {"units": "N s/m"})
            data[f"{model}_friction_coefficient"] = ("damping_gamma",
                                                     np.asarray(summary.path[model].friction_coefficient), {"units": "1"})
    for model, simulation in evaluation.simulations.items():
        if f"{model} model" in evaluation.problems:
            continue  # a model that failed has no cycle curves
        grid, pair_stiffness, mesh_damping = simulation.grid, simulation.pair_stiffness, simulation.mesh_damping
        coords[f"{model}_cycle_time"] = (f"{model}_cycle_time", np.asarray(grid.midpoints), {"units": "s"})
        data[f"{model}_cycle_pair_stiffness"] = ((f"{model}_slot", f"{model}_cycle_time"), np.asarray(pair_stiffness),
                                                {"units": "N/m"})
        data[f"{model}_cycle_mesh_stiffness"] = (f"{model}_cycle_time", np.asarray(simulation.mesh_stiffness),
                                                {"units": "N/m"})
        data[f"{model}_cycle_mesh_damping"] = (f"{model}_cycle_time", np.asarray(mesh_damping), {"units": "N s/m"})
        data[f"{model}_cycle_contact_count"] = (f"{model}_cycle_time", np.asarray(grid.contact_count, dtype=np.int64))
    attrs = {"title": f"thermogear report data: {case.title or case.name}", "thermogear_version": __version__,
             "case_name": case.name, "case_source": str(case.source), "case_toml": case_toml_text(case.source, case.document),
             "face_width_m": pair.face_width, "equivalent_mass_kg": case.equivalent_mass,
             "static_normal_load_n": case.normal_load,
             "groups": json.dumps({name: f"{model} model, {'steady state' if kind == 'responses' else 'from rest'}"
                                   for (kind, model), name in RESPONSE_GROUPS.items()})}
    return data, coords, attrs


def write_results_netcdf(evaluation, path: Path) -> list[str]:
    """Write results.nc (root: curves; one group per response; for a drivetrain case ``drivetrain_<model>``: DTE,
    mesh force and bearing forces over one mesh period, the bearings' mesh harmonics). Returns the group names written. Written with
    h5netcdf directly (:mod:`thermogear.report.netcdf_file`); xarray reads it as before."""
    from thermogear.report.netcdf_file import write_groups

    groups = {}
    for (kind, model), group in RESPONSE_GROUPS.items():
        response = getattr(evaluation, kind).get(model)
        if response is not None:
            groups[group] = response.dataset_parts()
    for model, parts in getattr(evaluation, "drivetrain_series", {}).items():  # [drivetrain] cases (issue 27)
        groups[f"drivetrain_{model}"] = parts
    return write_groups(path, curves_parts(evaluation), groups)


def summary_document(evaluation, verdicts, results, messages, figures, missing_figures, citations) -> dict:
    """The content of summary.json."""
    from thermogear import __version__

    case = evaluation.case
    from thermogear.report.html import fe_versus_analytical
    from thermogear.luo2020.report.table import known_gaps, table_counts

    table = [verdict.as_dict() for verdict in verdicts]
    counts = table_counts(verdicts) if verdicts else {}
    gaps = [{"key": v.row.key, "kind": v.row.kind, "quantity": v.row.quantity, "status": v.status,
             "cause": v.row.gap or v.reason} for v in known_gaps(verdicts)]
    return json_ready({
        "thermogear_version": __version__,
        "generated": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        "case": {"name": case.name, "title": case.title, "source": str(case.source), "citation": case.citation,
                 "assumptions": list(case.assumptions), "notes": list(case.notes),
                 "load_held": case.operating_point.load_held},
        "paper": "Luo & Li (2020), doi:10.1016/j.engfailanal.2020.104724" if verdicts else None,
        "table": table,
        "headline": ({"predictions": counts["prediction"], "qualitative": counts["qualitative"],
                      "known_gaps": gaps,
                      "note": "input and calibration rows are transcription and calibration checks and are not "
                              "counted here"} if verdicts else None),
        "table_counts": counts,
        "fig15_fe_versus_analytical": fe_versus_analytical(evaluation),
        "thermoelastic_beside_paper": evaluation.thermoelastic,
        "results": results,
        "models": {model: response.metrics_json() for model, response in evaluation.responses.items()},
        "messages": messages,
        "warnings": list(evaluation.warnings),
        "not_computed_stages": dict(evaluation.problems),
        "figures": {"drawn": sorted(figures), "missing": missing_figures},
        "timings_s": dict(evaluation.timings),
        "timings_background_s": dict(evaluation.background_timings),
        "references": [{"key": ref.key, "text": ref.formatted()} for ref in citations],
    }, non_finite="null")


def write_summary_json(document: dict, path: Path) -> None:
    path.write_text(json.dumps(document, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
