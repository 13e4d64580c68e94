"""The report section of a case with a ``[drivetrain]``: modes cold and hot with their labels and energy shares, what
heat moved per mode, the drivetrain's Kv and DTE, and the dynamic force of every bearing on its housing."""

from __future__ import annotations

import html
import math
from collections.abc import Callable
from typing import Any

__all__ = ["drivetrain_report_data", "drivetrain_section"]


def drivetrain_report_data(build: Callable[[], Any] | None, models: tuple[str, ...] = ("elastic", "thermal"),
                           transient: bool = False, progress=None, series: dict | None = None
                           ) -> dict[str, Any] | None:
    """The drivetrain results as JSON-ready numbers (:func:`~thermogear.drivetrain.case_model.drivetrain_results`
    of the CaseDrivetrain that ``build()`` returns; None for a case without ``[drivetrain]``, ``build`` None);
    where they cannot be computed, ``{"not_computed": reason}`` (the rest of the report stands). ``series``: filled
    per model with the response's arrays for results.nc."""
    if build is None:
        return None
    from thermogear.drivetrain.case_model import drivetrain_results
    from thermogear.errors import CaseError, ModelLimitError
    from thermogear.serialization import json_ready

    try:
        return json_ready(drivetrain_results(build(), models, transient, progress, series), non_finite="null")
    except ModelLimitError as error:  # most often a mode nothing damps: say where damping comes from
        return {"not_computed": f"{error} (every mode needs damping: give the shafts material_damping_s and the "
                                "bearings damping in x, y and, where they locate the shaft, z)"}
    except CaseError as error:
        return {"not_computed": str(error)}


def _number(value, pattern: str = "{:.1f}") -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "not found"
    return pattern.format(value)


def _cells(values: list[str], header: bool = False) -> str:
    tag = "th" if header else "td"
    return "<tr>" + "".join(f"<{tag}{'' if header or i == 0 else ' class=num'}>{html.escape(v)}</{tag}>"
                            for i, v in enumerate(values)) + "</tr>"


def _modes_table(data: dict[str, Any]) -> str:
    models = data["models"]
    first = next(iter(models.values()))
    heat = data.get("heat")
    header = ["mode", "label"] + [f"{name} [Hz]" for name in models] + ["mesh", "bearings", "shafts", "other"]
    if heat:
        header += ["shift cold→hot [%]", "main cause"]
    rows = [_cells(header, header=True)]
    for index, mode in enumerate(first["modes"]):
        shares = mode["energy_shares"]
        other = sum(value for key, value in shares.items() if key not in ("mesh", "bearings", "shafts"))
        cells = [str(index + 1), mode["label"] + (" (mesh-dominated)" if mode["mesh_dominated"] else "")]
        cells += [_number(model["modes"][index]["frequency_hz"]) for model in models.values()]
        cells += [f"{shares.get(key, 0.0):.3f}" for key in ("mesh", "bearings", "shafts")] + [f"{other:.3f}"]
        if heat:
            cells += [f"{heat[index]['shift_percent']:+.3f}", heat[index]["dominant_cause"]]
        rows.append(_cells(cells))
    return "<table>" + "".join(rows) + "</table>"


def _bearings_table(data: dict[str, Any]) -> str:
    models = data["models"]
    first = next(iter(models.values()))
    harmonics = len(next(iter(first["bearing_forces"].values()))["harmonic_amplitude_n"])
    header = ["bearing", "model", "mean radial [N]", "dynamic RMS [N]"] + [f"{j}× mesh [N]"
                                                                           for j in range(1, harmonics + 1)]
    rows = [_cells(header, header=True)]
    for bearing in first["bearing_forces"]:
        for name, model in models.items():
            force = model["bearing_forces"][bearing]
            rows.append(_cells([bearing, name, _number(force["mean_radial_n"]), _number(force["dynamic_rms_n"])]
                               + [_number(a, "{:.2f}") for a in force["harmonic_amplitude_n"]]))
    return "<table>" + "".join(rows) + "</table>"


def _orbit_found(model: dict[str, Any]) -> str:
    if not model.get("converged"):
        return "NO"
    return "yes" if model.get("stable") else "yes (unstable)"


def _extent(data: dict[str, Any]) -> str:
    """On what the response was solved: every DOF, or the modes up to the cut-off plus the static corrections."""
    solved_on = data.get("solved_on", f"modes up to {data['response_cutoff_hz']:.0f} Hz")
    return solved_on + ("" if solved_on == "every DOF" else " plus the static corrections")


def drivetrain_section(data: dict[str, Any] | None) -> str:
    """HTML of the drivetrain results (empty for a case without a drivetrain)."""
    if not data:
        return ""
    if "not_computed" in data:
        return ("<h2 id='drivetrain'>The pair in its drivetrain</h2><div class='warn'>Not computed: "
                f"{html.escape(data['not_computed'])}</div>")
    models = data["models"]
    backlash = bool(data.get("backlash_mesh"))
    header = ["model", "Kv", "DTE RMS [μm]", "DTE peak-to-peak [μm]", "largest |Floquet multiplier|"]
    if backlash:
        header += ["time without contact [%]", "back flanks struck", "periodic orbit found"]
    rows = []
    for name, m in models.items():
        cells = [name, _number(m["kv"], "{:.4f}"), _number(m["dte_rms_um"], "{:.3f}"),
                 _number(m["dte_peak_to_peak_um"], "{:.3f}"), _number(m["largest_floquet_multiplier_abs"], "{:.4f}")]
        if backlash:
            fraction = m.get("contact_loss_fraction")
            struck = m.get("back_side_contact")
            cells += [_number(None if fraction is None else 100.0 * fraction, "{:.2f}"),
                      "not found" if struck is None else "yes" if struck else "no",
                      "—" if data.get("transient") else _orbit_found(m)]
        rows.append(_cells(cells))
    for name, m in models.items():  # a train: each mesh over the common period
        for stage, values in m.get("stages", {}).items():
            rows.append(_cells([f"{name}, {stage}", _number(values["kv"], "{:.4f}"),
                                _number(values["dte_rms_um"], "{:.3f}"), _number(values["dte_peak_to_peak_um"], "{:.3f}"),
                                "—"] + ["—"] * (3 if backlash else 0)))
    response = "".join(rows)
    failures = "".join(f"<p class='small'>{html.escape(name)} model: no periodic orbit — "
                       f"{html.escape(m['failure'])}</p>" for name, m in models.items() if m.get("failure"))
    resonances = sorted({(round(r["speed_rpm"]), r["harmonic"], round(r["mode_hz"]), r["label"],
                          " (mesh-dominated)" if r["mesh_dominated"] else "", name)
                         for name, m in models.items() for r in m["resonances"]})
    resonance_text = "; ".join(f"{h}× mesh meets {f} Hz {label}{dominated} at {n} rpm ({name})"
                               for n, h, f, label, dominated, name in resonances) or "none"
    notes = "".join(f"<p class='small'>{html.escape(note)}</p>" for note in data.get("notes", []))
    return ("<h2 id='drivetrain'>The pair in its drivetrain</h2>"
            f"<p>{data['degrees_of_freedom']} degrees of freedom (Timoshenko shafts, gear bodies, bearings, "
            f"couplings, the mesh along the line of action); the response is solved exactly "
            f"({html.escape(_extent(data))}), with the mesh {html.escape(data['mesh'])}. Cold: the elastic mesh model, shafts at 20 °C; hot: the case's thermal "
            "model, shafts' E(T), hot mesh stiffness and geometry. Energy shares are of the modal strain energy "
            "(mesh-dominated: mesh share above 0.1).</p>"
            + _modes_table(data)
            + "<table>" + _cells(header, header=True) + response + "</table>" + failures
            + f"<p>Mesh harmonics meet modes with a mesh share above 0.01 at: {html.escape(resonance_text)}.</p>"
            + "<h3>Dynamic bearing forces on the housing</h3>"
            "<p>Radial force of each bearing over one mesh period: its mean, the RMS of its dynamic part and the "
            "amplitude √(X_j² + Y_j²) of the first mesh harmonics — what an accelerometer on the housing "
            "sees. The forces in time (x, y, z over one mesh period, with the DTE and the mesh force) and their "
            "mesh harmonics per direction are in <code>results.nc</code>, group <code>drivetrain_&lt;model&gt;</code>"
            " (the transient's are not stored).</p>"
            + _bearings_table(data) + notes)
