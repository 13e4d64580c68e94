"""The ``thermal`` object of ``thermogear stiffness CASE --thermal --json`` and the Fig. 4 plot.

Plain floats only; stiffness per unit face width in N/(mm·μm) (the field's unit, = 1e9 N/m per m), compliance
per unit width in mm·μm/N, expansions in μm, loads in N (total) and N/mm.
"""

from __future__ import annotations

from dataclasses import dataclass
import numpy as np

from thermogear.luo2020.thermal.case_stiffness import PaperThermalModel
from thermogear.luo2020.thermal.stiffness import ThermalStiffness
from thermogear.mesh.model import MeshModel

#: Roll positions of the curves along the path (A to E inclusive) used for crossings, extremes and the plot.
CURVE_POINT_COUNT = 401

#: N/m per metre of face width → N/(mm·μm)
PER_WIDTH_STIFFNESS_TO_N_PER_MM_UM = 1e-9


@dataclass(frozen=True)
class ThermalCurves:
    """Thermal and elastic curves of one pair along the path, plus the same at the points A–E."""

    curve: ThermalStiffness  # on CURVE_POINT_COUNT rolls from A to E
    points: ThermalStiffness  # at A, B, C, D, E
    face_width: float  # of the pair [m] (the curves are totals over it)
    point_names: tuple[str, ...] = ("A", "B", "C", "D", "E")


def thermal_curves(model: PaperThermalModel, count: int = CURVE_POINT_COUNT, load_basis: str | None = None,
                   x_te: float | None = None) -> ThermalCurves:
    """Thermal stiffness of the paper's model of a pair on an even roll grid A–E and at the points A–E."""
    temperature = model.temperature
    pair = model.inputs.gear_pair
    if x_te is None:
        x_te, source = model.resolve_x_te(load_basis=load_basis, temperature=temperature)
    else:
        source = "given (argument)"
    curve = model.thermal_stiffness(pair.roll_grid(count), x_te=x_te, load_basis=load_basis, temperature=temperature)
    points = model.thermal_stiffness(np.array([pair.path_points[name] for name in "ABCDE"]), x_te=x_te,
                                     load_basis=load_basis, temperature=temperature)
    curve = _with_source(curve, source)
    points = _with_source(points, source)
    return ThermalCurves(curve, points, pair.face_width)


def _with_source(result: ThermalStiffness, source: str) -> ThermalStiffness:
    from dataclasses import replace  # noqa: PLC0415

    return replace(result, x_te_source=source)


def crossing_gammas(gamma, elastic, thermal) -> list[float]:
    """Γ where a thermal curve crosses its elastic curve (sign changes of thermal − elastic, located by linear
    interpolation between grid points). Touching without changing sign is not a crossing."""
    gamma = np.asarray(gamma, dtype=float)
    difference = np.asarray(thermal, dtype=float) - np.asarray(elastic, dtype=float)
    sign = np.sign(difference)
    crossings = []
    nonzero = np.flatnonzero(sign != 0)
    for left, right in zip(nonzero[:-1], nonzero[1:]):
        if sign[left] != sign[right]:
            if right == left + 1:
                weight = difference[left] / (difference[left] - difference[right])
                crossings.append(float(gamma[left] + weight * (gamma[right] - gamma[left])))
            else:  # exact zeros in between: the middle of the zero run
                crossings.append(float(0.5 * (gamma[left + 1] + gamma[right - 1])))
    return crossings


def _single_crossing(crossings: list[float]) -> float | None:
    """One crossing → its Γ; none → None; several → the first along the path (the count is reported too)."""
    return crossings[0] if crossings else None


def thermal_stiffness_summary(model: PaperThermalModel, elastic: MeshModel, thermal: MeshModel) -> dict:
    """The ``thermal`` JSON object (plain floats) of the paper's model of a pair: X_te and its source, drops at the
    path points, single-tooth compliance changes at tips and roots, the crossings of single-tooth curves,
    per-width values at A–E, the extremes of the curves, the temperature input, and the mesh stiffness over one
    cycle of the ``elastic`` and ``thermal`` mesh models of the same case."""
    curves = thermal_curves(model)
    curve, points = curves.curve, curves.points
    width = curves.face_width
    names = curves.point_names
    drop = dict(zip(names, (float(v) for v in points.drop_percent)))
    pinion_change = points.pinion_compliance_change_percent
    wheel_change = points.wheel_compliance_change_percent
    # Driving (pinion) flank: contact starts at its root (A) and ends at its tip (E); the driven flank the reverse.
    compliance_change = {"driving_tip": float(pinion_change[4]), "driving_root": float(pinion_change[0]),
                         "driven_tip": float(wheel_change[0]), "driven_root": float(wheel_change[4])}
    gamma = curve.gamma
    driving = crossing_gammas(gamma, curve.result.elastic_pinion_compliance, curve.pinion_compliance)
    driven = crossing_gammas(gamma, curve.result.elastic_wheel_compliance, curve.wheel_compliance)
    temperature = points.temperature

    def per_width_stiffness(values) -> np.ndarray:
        return np.asarray(values) / width * PER_WIDTH_STIFFNESS_TO_N_PER_MM_UM

    at_points = {}
    for index, name in enumerate(names):
        at_points[name] = {
            "gamma": float(points.gamma[index]),
            "flank_temperature_c": float(temperature.pinion_flank_c(points.gamma[index])),
            "elastic_stiffness_n_per_mm_um": float(per_width_stiffness(points.elastic_stiffness[index])),
            "thermal_stiffness_n_per_mm_um": float(per_width_stiffness(points.stiffness[index])),
            "expansion_pinion_um": float(points.expansion_pinion[index] * 1e6),
            "expansion_wheel_um": float(points.expansion_wheel[index] * 1e6),
            "normal_load_n": float(points.normal_load[index]),
            "normal_load_n_per_mm": float(points.normal_load[index] / (width * 1e3)),
            "driving_compliance_change_percent": float(pinion_change[index]),
            "driven_compliance_change_percent": float(wheel_change[index]),
        }
    summary = {
        "x_te": float(points.x_te),
        "x_te_source": points.x_te_source,
        "load_basis": points.load_basis,
        "stiffness_drop_percent": drop,
        "single_tooth_compliance_change_percent": compliance_change,
        "single_tooth_crossing_gamma": {"driving": _single_crossing(driving), "driven": _single_crossing(driven)},
        "single_tooth_crossing_count": {"driving": len(driving), "driven": len(driven)},
        "stiffness_drop_percent_range": {"min": float(curve.drop_percent.min()),
                                         "max": float(curve.drop_percent.max())},
        "thermal_below_elastic_everywhere": bool(np.all(curve.stiffness < curve.elastic_stiffness)),
        "points": at_points,
        "temperature": temperature.describe(),
        "units": {"stiffness": "N/(mm·μm) per unit face width", "expansion": "μm along the line of action, "
                  "positive = interference", "normal_load_n": "N total over the face width"},
    }
    summary["mesh_stiffness_n_per_mm_um"] = _mesh_stiffness_summary({"elastic": elastic, "thermal": thermal}, width)
    return summary


def _mesh_stiffness_summary(meshes: dict[str, MeshModel], width: float) -> dict | None:
    """Min/mean/max over one mesh cycle of the mesh stiffness (pairs in parallel) of each mesh model at its
    operating point, per unit face width ``width`` [m]."""
    scale = PER_WIDTH_STIFFNESS_TO_N_PER_MM_UM / width
    result = {}
    for name, mesh in meshes.items():
        values = mesh.state(damping=False).mesh_stiffness
        result[name] = {"min": float(values.min() * scale), "mean": float(values.mean() * scale),
                        "max": float(values.max() * scale)}
    return result
