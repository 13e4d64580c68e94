"""Tables of a drivetrain's results, as plain numbers: the modes with their strain-energy shares, the bearing forces
and their mesh-harmonic lines, the speeds where mesh harmonics meet modes, each stage of a train, and what heat moved
per mode (the numbers ``run``, the report and the sweeps show)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from thermogear.drivetrain.assembly import Drivetrain
from thermogear.drivetrain.case_layout import MESH_NAME
from thermogear.drivetrain.heat import ModeShifts
from thermogear.drivetrain.modes import DrivetrainModes
from thermogear.drivetrain.response import DrivetrainResponse

__all__ = ["MESH_COUPLED_SHARE", "MESH_DOMINATED_SHARE", "SPECTRUM_POINTS", "bearing_force_summary", "heat_table",
           "mode_table", "resonance_speeds", "stage_summary"]

#: A mode is "mesh-dominated" when the mesh holds more than this share of its strain energy: a threshold chosen
#: here (Velex & Berthe 1989 rank modes by this share; no source fixes a value). Kept low so that no mode the mesh
#: excites noticeably is left unmarked.
MESH_DOMINATED_SHARE = 0.1
#: Modes with a smaller mesh share still respond to the mesh where a harmonic meets them: lateral modes of a few
#: per cent mesh share carry the largest bearing forces (the FZG rig set: 3–4 % share, bearing-force peaks 4×
#: the torsional mode's). Their crossings are listed too, marked not mesh-dominated. A threshold chosen here.
MESH_COUPLED_SHARE = 0.01

#: Uniform samples per period for the bearing-force harmonics (the first mesh harmonics need far fewer).
SPECTRUM_POINTS = 256


def _group(name: str, drivetrain: Drivetrain) -> str:
    if any(mesh.name == name for mesh in drivetrain.meshes):
        return "mesh"
    for kind, items in (("bearings", drivetrain.bearings), ("couplings", drivetrain.couplings),
                        ("supports", drivetrain.torsional_supports), ("shafts", drivetrain.shafts)):
        if any(item.name == name for item in items):
            return kind
    return "other"


def mode_table(modes: DrivetrainModes, drivetrain: Drivetrain) -> list[dict[str, Any]]:
    """One dict per mode: frequency [Hz], label, mesh share, the shares grouped (mesh, bearings, shafts, couplings,
    supports) and per element, and whether the mesh dominates it (share > :data:`MESH_DOMINATED_SHARE`)."""
    rows = []
    meshes = [mesh.name for mesh in drivetrain.meshes]
    for index, frequency in enumerate(modes.frequencies_hz):
        shares = {name: float(values[index]) for name, values in modes.strain_energy_shares.items()}
        grouped: dict[str, float] = {}
        for name, value in shares.items():
            kind = _group(name, drivetrain)
            grouped[kind] = grouped.get(kind, 0.0) + value
        mesh_share = shares.get(MESH_NAME, 0.0) if len(meshes) == 1 else grouped.get("mesh", 0.0)
        row = {"frequency_hz": float(frequency), "label": modes.labels[index], "mesh_share": mesh_share,
               "energy_shares": grouped, "element_shares": shares, "mesh_dominated": mesh_share > MESH_DOMINATED_SHARE}
        if len(meshes) > 1:  # a train: the share of each mesh, and the one that holds most
            row["mesh_shares"] = {name: shares.get(name, 0.0) for name in meshes}
            row["dominant_mesh"] = max(meshes, key=lambda name: shares.get(name, 0.0))
        rows.append(row)
    return rows


def bearing_force_summary(response: DrivetrainResponse, harmonics: int) -> dict[str, dict[str, Any]]:
    """Per bearing: the mean radial force [N], the RMS of the dynamic radial force |F − F̄| over the period [N]
    (trapezoidal rule on the solver's samples, a jump being a segment of zero width) and the radial amplitude
    √(X_j² + Y_j²) of mesh harmonics j = 1…``harmonics`` [N] with their frequencies [Hz]."""
    summary = {}
    time = response.time
    orders = _harmonic_orders(response, harmonics)
    points = max(SPECTRUM_POINTS, 4 * orders[-1])
    for name, force in response.bearing_forces.items():
        radial = force[:, :2]
        mean = np.trapezoid(radial, time, axis=0) / (time[-1] - time[0])
        dynamic = np.sum((radial - mean) ** 2, axis=1)
        rms = math.sqrt(float(np.trapezoid(dynamic, time)) / (time[-1] - time[0]))
        frequencies, amplitudes = response.bearing_spectrum(name, points=points)
        radial_amplitudes = np.hypot(amplitudes[0], amplitudes[1])
        summary[name] = {"mean_radial_n": float(np.hypot(*mean)), "dynamic_rms_n": rms,
                         "harmonic_hz": [float(frequencies[order]) for order in orders],
                         "harmonic_amplitude_n": [float(radial_amplitudes[order]) for order in orders]}
    return summary


def _harmonic_orders(response, harmonics: int) -> list[int]:
    """The spectrum lines (multiples of 1/T) of the mesh harmonics 1…``harmonics`` of every mesh: 1…harmonics for
    one mesh; for a train, j·L_m of each mesh m (L_m its periods in the common period T), in ascending order."""
    meshes = getattr(response, "meshes", None) or {}
    repeats = {max(1, round(response.period / item.mesh_period)) for item in meshes.values()} or {1}
    return sorted({j * repeat for repeat in repeats for j in range(1, harmonics + 1)})


def resonance_speeds(rows: list[dict[str, Any]], teeth: int, harmonics: int,
                     stages: tuple[tuple[str, float], ...] = ()) -> list[dict[str, Any]]:
    """Pinion speeds [rpm] at which mesh harmonic j meets a mode with a mesh share above
    :data:`MESH_COUPLED_SHARE`: n = 60·f/(j·z1), each marked ``mesh_dominated`` or not (the modes at standstill;
    the Campbell diagram, :mod:`thermogear.drivetrain.campbell`, follows their gyroscopic shift). A train's further
    ``stages`` (mesh name, teeth per input revolution z_p·n_p/n_1): the first pinion's speeds where their mesh
    harmonics meet such a mode, each row naming its ``mesh``."""
    found = [{"speed_rpm": 60.0 * row["frequency_hz"] / (j * teeth), "harmonic": j, "mode_hz": row["frequency_hz"],
              "label": row["label"], "mesh_share": row["mesh_share"], "mesh_dominated": row["mesh_dominated"]}
             for row in rows if row["mesh_share"] > MESH_COUPLED_SHARE for j in range(1, harmonics + 1)]
    if stages:
        for item in found:
            item["mesh"] = MESH_NAME
        found += [{"speed_rpm": 60.0 * row["frequency_hz"] / (j * per_turn), "harmonic": j,
                   "mode_hz": row["frequency_hz"], "label": row["label"], "mesh_share": row["mesh_share"],
                   "mesh_dominated": row["mesh_dominated"], "mesh": name}
                  for name, per_turn in stages for row in rows if row["mesh_share"] > MESH_COUPLED_SHARE
                  for j in range(1, harmonics + 1)]
    return found


def stage_summary(response: DrivetrainResponse) -> dict[str, dict[str, Any]]:
    """Per mesh of a train: Kv, DTE RMS and peak-to-peak [μm], the largest mesh force [N] and the mesh frequency
    [Hz] over the common period."""
    return {name: {"kv": item.metrics["kv"], "dte_rms_um": item.metrics["dte_rms"] * 1e6,
                   "dte_peak_to_peak_um": item.metrics["dte_peak_to_peak"] * 1e6,
                   "max_mesh_force_n": float(np.max(item.mesh_force)), "mesh_frequency_hz": 1.0 / item.mesh_period}
            for name, item in response.meshes.items()}


def heat_table(shifts: ModeShifts, drivetrain: Drivetrain) -> list[dict[str, Any]]:
    """Per mode: cold and hot frequency [Hz], the exact shift and its first-order sum [%], and the causes [%]
    (each shaft's E(T), the mesh stiffness, the mesh geometry; causes that moved nothing are left out)."""
    shafts = {shaft.name for shaft in drivetrain.shafts}
    names = {name: (f"{name} E(T)" if name in shafts else name) for name in shifts.contributions}
    moving = [name for name, values in shifts.contributions.items() if np.any(values != 0.0)]
    return [{"cold_hz": float(shifts.cold_hz[i]), "hot_hz": float(shifts.hot_hz[i]), "label": shifts.labels[i],
             "shift_percent": 100.0 * float(shifts.exact[i]), "first_order_percent": 100.0 * float(
                 shifts.first_order[i]),
             "causes_percent": {names[name]: 100.0 * float(shifts.contributions[name][i]) for name in moving},
             "dominant_cause": names[shifts.dominant_cause(i)]} for i in range(shifts.exact.size)]
