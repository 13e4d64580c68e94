"""The report section of a case with a ``[drivetrain]``: modes cold and hot with their labels and energy shares, what
heat moved per mode, the drivetrain's Kv and DTE, and the dynamic force of every bearing on its housing."""

from __future__ import annotations

import html
import math
from typing import Any

__all__ = ["drivetrain_json", "drivetrain_section"]


def drivetrain_json(results, reason: str | None = None) -> dict[str, Any] | None:
    """The drivetrain's results (:class:`~thermogear.drivetrain.results.DrivetrainResults`) as the JSON-ready
    object of ``run --json`` and ``summary.json``; ``{"not_computed": reason}`` where they could not be computed
    (``reason``); None for a case without a ``[drivetrain]``."""
    if results is None:
        return None if reason is None else {"not_computed": reason}
    from thermogear.serialization import json_ready

    return json_ready(results.as_json(), non_finite="null")


def _number(value, pattern: str = "{:.1f}") -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "not found"
    return pattern.format(value)


def _cells(values: list[str], header: bool = False) -> str:
    tag = "th" if header else "td"
    return "<tr>" + "".join(f"<{tag}{'' if header or i == 0 else ' class=num'}>{html.escape(v)}</{tag}>"
                            for i, v in enumerate(values)) + "</tr>"


def _other_share(shares) -> float:
    return sum(value for key, value in shares.items() if key not in ("mesh", "bearings", "shafts"))


def _modes_table(results) -> str:
    models = results.models
    first = next(iter(models.values()))
    heat = results.heat
    header = ["mode", "label"] + [f"{name} [Hz]" for name in models] + ["mesh", "bearings", "shafts", "other"]
    if heat:
        header += ["shift cold→hot [%]", "main cause"]
    rows = [_cells(header, header=True)]
    for index, mode in enumerate(first.modes):
        shares = mode.energy_shares
        cells = [str(index + 1), mode.label + (" (mesh-dominated)" if mode.mesh_dominated else "")]
        cells += [_number(model.modes[index].frequency_hz) for model in models.values()]
        cells += [f"{shares.get(key, 0.0):.3f}" for key in ("mesh", "bearings", "shafts")]
        cells += [f"{_other_share(shares):.3f}"]
        if heat:
            cells += [f"{100.0 * heat[index].shift:+.3f}", heat[index].dominant_cause]
        rows.append(_cells(cells))
    return "<table>" + "".join(rows) + "</table>" + _mesh_modes_text(results)


def _mesh_modes_text(results) -> str:
    """The mesh-dominated modes above the listed ones (issue 36), and how to tabulate them."""
    count = len(next(iter(results.models.values())).modes)
    above = {name: model.mesh_modes for name, model in results.models.items() if model.mesh_modes}
    if not above:
        return ""
    listed = "; ".join(f"{name}: " + ", ".join(f"{row.frequency_hz:.0f} Hz {row.label} (mesh share "
                                               f"{row.mesh_share:.2f})" for row in rows)
                       for name, rows in above.items())
    return (f"<p>Mesh-dominated modes above the {count} listed, up to the response cut-off: "
            f"{html.escape(listed)}. Raise <code>drivetrain.mode_count</code> to tabulate every mode up to them.</p>")


def _bearings_table(results) -> str:
    models = results.models
    first = next(iter(models.values()))
    harmonics = len(next(iter(first.bearing_forces.values())).harmonic_amplitude_n)
    header = (["bearing", "model", "mean radial [N]", "dynamic RMS [N]", "mean axial [N]", "tilting moment [N·m]"]
              + [f"{j}× mesh [N]" for j in range(1, harmonics + 1)])
    rows = [_cells(header, header=True)]
    for bearing in first.bearing_forces:
        for name, model in models.items():
            force = model.bearing_forces[bearing]
            rows.append(_cells([bearing, name, _number(force.mean_radial_n), _number(force.dynamic_rms_n),
                                _number(force.mean_axial_n), _number(force.mean_tilting_moment_n_m)]
                               + [_number(a, "{:.2f}") for a in force.harmonic_amplitude_n]))
    return "<table>" + "".join(rows) + "</table>"


def _orbit_found(model) -> str:
    if not getattr(model, "converged", False):
        return "NO"
    return "yes" if model.stable else "yes (unstable)"


def _extent(results) -> str:
    """On what the response was solved: every DOF, or the modes up to the cut-off plus the static corrections."""
    return results.solved_on + ("" if results.transient else " plus the static corrections")


def drivetrain_section(results, reason: str | None = None) -> str:
    """HTML of the drivetrain results (:class:`~thermogear.drivetrain.results.DrivetrainResults`; empty for a case
    without a drivetrain, ``reason`` where they could not be computed)."""
    if results is None:
        if reason is None:
            return ""
        return ("<h2 id='drivetrain'>The pair in its drivetrain</h2><div class='warn'>Not computed: "
                f"{html.escape(reason)}</div>")
    models = results.models
    backlash = results.backlash_mesh
    header = ["model", "Kv", "DTE RMS [μm]", "DTE peak-to-peak [μm]", "largest |Floquet multiplier|"]
    if backlash:
        header += ["time without contact [%]", "back flanks struck", "periodic orbit found"]
    rows = []
    for name, m in models.items():
        cells = [name, _number(m.kv, "{:.4f}"), _number(_micro(m.dte_rms), "{:.3f}"),
                 _number(_micro(m.dte_peak_to_peak), "{:.3f}"), _number(m.largest_floquet_multiplier_abs, "{:.4f}")]
        if backlash:
            fraction, struck = m.contact_loss_fraction, m.back_side_contact
            cells += [_number(None if fraction is None else 100.0 * fraction, "{:.2f}"),
                      "not found" if struck is None else "yes" if struck else "no",
                      "—" if results.transient else _orbit_found(m)]
        rows.append(_cells(cells))
    for name, m in models.items():  # a train: each mesh over the common period
        for stage, values in (m.stages or {}).items():
            rows.append(_cells([f"{name}, {stage}", _number(values.kv, "{:.4f}"),
                                _number(_micro(values.dte_rms), "{:.3f}"),
                                _number(_micro(values.dte_peak_to_peak), "{:.3f}"), "—"]
                               + ["—"] * (3 if backlash else 0)))
    response = "".join(rows)
    failures = "".join(f"<p class='small'>{html.escape(name)} model: no periodic orbit — "
                       f"{html.escape(m.failure)}</p>" for name, m in models.items() if getattr(m, "failure", ""))
    resonances = sorted({(round(r.speed_rpm), r.harmonic, round(r.mode_hz), r.label,
                          " (mesh-dominated)" if r.mesh_dominated else "", name)
                         for name, m in models.items() for r in m.resonances})
    resonance_text = "; ".join(f"{h}× mesh meets {f} Hz {label}{dominated} at {n} rpm ({name})"
                               for n, h, f, label, dominated, name in resonances) or "none"
    notes = "".join(f"<p class='small'>{html.escape(note)}</p>" for note in results.notes)
    notes += "".join(f"<p class='small'>{html.escape(name)} model, response solved on the "
                     f"{html.escape(m.cutoff_error.describe())}</p>"
                     for name, m in models.items() if m.cutoff_error is not None)
    return ("<h2 id='drivetrain'>The pair in its drivetrain</h2>"
            f"<p>{results.degrees_of_freedom} degrees of freedom (Timoshenko shafts, gear bodies, bearings, "
            f"couplings, the mesh along the line of action); the response is solved exactly "
            f"({html.escape(_extent(results))}), with the mesh {html.escape(results.mesh)}. Cold: the elastic mesh "
            "model, shafts at 20 °C; hot: the case's thermal model, shafts' E(T), hot mesh stiffness and geometry. "
            "Energy shares are of the modal strain energy (mesh-dominated: mesh share above 0.1). The headline Kv "
            "above is the drivetrain's; the results table gives the 1-DOF pair's on rigid supports beside it.</p>"
            + _modes_table(results)
            + "<table>" + _cells(header, header=True) + response + "</table>" + failures
            + f"<p>Mesh harmonics meet modes with a mesh share above 0.01 at: {html.escape(resonance_text)}.</p>"
            + "<h3>Dynamic bearing forces on the housing</h3>"
            "<p>Radial force of each bearing over one mesh period: its mean, the RMS of its dynamic part and the "
            "amplitude √(X_j² + Y_j²) of the first mesh harmonics — what an accelerometer on the housing "
            "sees. The forces in time (x, y, z over one mesh period, with the DTE and the mesh force) and their "
            "mesh harmonics per direction are in <code>results.nc</code>, group <code>drivetrain_&lt;model&gt;</code>"
            " (the transient's are not stored).</p>"
            + _bearings_table(results) + notes)


def _micro(value: float | None) -> float | None:
    return None if value is None else value * 1e6
