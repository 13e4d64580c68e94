"""Evaluation of many operating points: the fast batch path and the one-Simulation-per-point path.

Fast path (a fixed geometry, load and temperature input; many speeds)
--------------------------------------------------------------------
Over one mesh period the pair positions in roll distance do not depend on the speed: with a fixed interval count
the mesh-cycle grid in roll is the same for every speed and only the times scale, T ∝ 1/n1. So for one
"group" (every case parameter fixed except the speed) the per-pair stiffness k(roll) — elastic k_e or thermal
k_T — and the mesh stiffness are computed once, and for the speeds of the group:

* the damping of Eqs. 27–28, c = 4·μ·k/(π·ω_m), scales as c ∝ μ/ω_m ∝ v_Σ^(−1/4)/n1 ∝ n1^(−5/4) (μ ∝ v_Σ^(−1/4),
  v_Σ ∝ n1, ω_m ∝ n1; load share, viscosity and radius of curvature do not depend on the speed);
* the equation me·ẍ + c·ẋ + k·x = w on the nodes t_s = t_ref/r (r = n1/n1,ref) is, in the reference time
  t_ref = r·t, the equation (me·r²)·x'' + (c·r)·x' + k·x = w on the reference nodes: the periodic solver runs all
  speeds of a group on one node grid (:func:`~thermogear.dynamics.periodic.periodic_steady_state_batch`);
* the metrics are computed by a compiled kernel that samples the exact orbit exactly as
  :func:`~thermogear.dynamics.response.compute_metrics` does (the same samples per interval, one-sided limits at
  the nodes), so the fast path gives the numbers of one :class:`~thermogear.simulation.Simulation` per point to
  rounding (tested to 1e-9 relative).

The stiffness tables (PEM quadrature) are cached per gear pair and material by ``stiffness.table``, so groups
that share a geometry (load or temperature sweeps) reuse them; groups of another geometry (module, face width,
profile shift) compute their own once.

Slow path
---------
:func:`evaluate_point` runs ``Simulation(case, model).run("periodic")`` for one point: the reference the fast path
is tested against, and the path for temperature inputs that depend on the speed (``temperature.model = "fem"``).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Any

import numba
import numpy as np

from thermogear.dynamics.periodic import _transition, periodic_steady_state_batch
from thermogear.errors import ModelLimitError

__all__ = ["MODEL_VARIABLES", "POINT_VARIABLES", "GroupTables", "empty_block_result", "evaluate_block",
           "evaluate_point", "evaluate_speeds", "group_tables"]

#: Per-model result variables: name → (units, long name).
MODEL_VARIABLES: dict[str, tuple[str, str]] = {
    "kv": ("1", "dynamic load factor Kv = max pair dynamic load / static load (Luo & Li Eq. 29)"),
    "max_pair_load": ("N", "largest single-pair dynamic load over the period"),
    "max_system_load_ratio": ("1", "largest system dynamic load / static load"),
    "dte_mean": ("m", "mean dynamic transmission error"),
    "dte_rms": ("m", "RMS of the dynamic transmission error about its mean"),
    "dte_peak_to_peak": ("m", "peak-to-peak dynamic transmission error"),
    "max_velocity": ("m/s", "largest |dx/dt| over the period"),
    "natural_frequency_hz": ("Hz", "natural frequency sqrt(mean k / me) / 2 pi"),
    "mean_mesh_stiffness": ("N/m", "time-mean mesh stiffness over one period"),
    "floquet_multiplier_max": ("1", "largest Floquet multiplier modulus (>= 1: parametric instability)"),
    "stable": ("1", "1 where a periodic steady state exists (all Floquet multipliers inside the unit circle)"),
    "contact_loss": ("1", "1 where the mesh force turns negative (the teeth would separate; linear model invalid)"),
}
#: Per-point result variables (the same for every model).
POINT_VARIABLES: dict[str, tuple[str, str]] = {
    "mesh_frequency_hz": ("Hz", "mesh frequency z1 n1 / 60"),
    "static_load": ("N", "static normal load w (total over the face width)"),
}
#: Speed exponent of the friction damping of Eqs. 27–28 (c ∝ n1^(−5/4)).
DAMPING_SPEED_EXPONENT = -1.25


# ------------------------------------------------------------------------------------------- tables
@dataclass(frozen=True)
class GroupTables:
    """Everything of one case and model that does not depend on the speed, on the reference node grid."""

    model: str
    speed_rpm: float  # reference speed of the nodes and the damping [rpm]
    mass: float  # me [kg]
    force: float  # w [N]
    nodes: np.ndarray  # (n+1,) [s] at the reference speed
    stiffness: np.ndarray  # (n,) k [N/m]
    damping: np.ndarray  # (n,) c [N·s/m] at the reference speed
    pair_stiffness: np.ndarray  # (slots, n) [N/m]
    include_damping_force: bool
    samples_per_interval: int  # orbit samples per interval for the metrics: the case's, as in Simulation.run
    natural_frequency_hz: float
    mean_mesh_stiffness: float
    pinion_teeth: int


def group_tables(case, model: str, points_per_period: int | None = None) -> GroupTables:
    """Speed-independent tables of a case and model, taken from a :class:`Simulation` at the case's speed."""
    from thermogear.simulation import Simulation

    simulation = Simulation(case, model, points_per_period)
    problem = simulation.problem
    return GroupTables(model=model, speed_rpm=float(simulation.speed_rpm), mass=float(problem.mass),
                       force=float(np.mean(problem.force_per_interval)),
                       nodes=np.ascontiguousarray(problem.nodes), stiffness=np.ascontiguousarray(problem.stiffness),
                       damping=np.ascontiguousarray(problem.damping),
                       pair_stiffness=np.ascontiguousarray(problem.pair_stiffness),
                       include_damping_force=bool(case.dynamics.include_damping_force),
                       samples_per_interval=int(case.dynamics.samples_per_interval),
                       natural_frequency_hz=float(problem.natural_frequency),
                       mean_mesh_stiffness=float(problem.mean_stiffness),
                       pinion_teeth=int(case.gear_pair.pinion.teeth))


# ------------------------------------------------------------------------------------------- kernel
_METRIC_COUNT = 8  # max pair load, max system load, min system load, mean x, rms x, max x, min x, max |v|


@numba.njit(cache=True)
def _orbit_metrics(mass: float, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray, force: float,
                   pair_stiffness: np.ndarray, x0: float, v0: float, samples: int, damping_force: bool,
                   out: np.ndarray) -> None:
    """Metrics of the exact periodic orbit from (x0, v0), sampled like ``compute_metrics`` (``samples`` equal
    sub-steps per interval plus the end of the period; loads right-continuous at the samples plus the left
    limits at the interior nodes). Without the damping force the extreme loads of an interval are k·max x and
    k·min x (k ≥ 0), so only the extremes of x per interval are tracked."""
    n = stiffness.size
    slots = pair_stiffness.shape[0]
    reference = x0
    period = nodes[n] - nodes[0]
    first_sum = 0.0
    second_sum = 0.0
    max_pair = -np.inf
    max_system = -np.inf
    min_system = np.inf
    max_x = -np.inf
    min_x = np.inf
    max_v = 0.0
    x_start = x0
    v_start = v0
    for i in range(n):
        k = stiffness[i]
        c = damping[i]
        length = nodes[i + 1] - nodes[i]
        step = length / samples
        equilibrium = force / k
        p00, p01, p10, p11 = _transition(k, c, mass, step)
        x = x_start
        v = v_start
        top = x
        bottom = x
        fastest = abs(v)
        shifted = x - reference
        inner_first = 0.5 * shifted
        inner_second = 0.5 * shifted * shifted
        if damping_force:
            for j in range(samples):
                if j > 0:
                    dx = x - equilibrium
                    x, v = p00 * dx + p01 * v + equilibrium, p10 * dx + p11 * v
                    shifted = x - reference
                    inner_first += shifted
                    inner_second += shifted * shifted
                    top = max(top, x)
                    bottom = min(bottom, x)
                    fastest = max(fastest, abs(v))
                load = k * x + c * v
                max_system = max(max_system, load)
                min_system = min(min_system, load)
                for s in range(slots):
                    share = pair_stiffness[s, i] / k
                    max_pair = max(max_pair, pair_stiffness[s, i] * x + share * c * v)
            if i > 0:  # left limit at node i: coefficients of interval i − 1
                kp = stiffness[i - 1]
                cp = damping[i - 1]
                load = kp * x_start + cp * v_start
                max_system = max(max_system, load)
                min_system = min(min_system, load)
                for s in range(slots):
                    share = pair_stiffness[s, i - 1] / kp
                    max_pair = max(max_pair, pair_stiffness[s, i - 1] * x_start + share * cp * v_start)
        else:
            for j in range(1, samples):
                dx = x - equilibrium
                x, v = p00 * dx + p01 * v + equilibrium, p10 * dx + p11 * v
                shifted = x - reference
                inner_first += shifted
                inner_second += shifted * shifted
                top = max(top, x)
                bottom = min(bottom, x)
                fastest = max(fastest, abs(v))
        # end of the interval (start of the next): the exact transition over the whole interval
        q00, q01, q10, q11 = _transition(k, c, mass, length)
        dx = x_start - equilibrium
        x_end = q00 * dx + q01 * v_start + equilibrium
        v_end = q10 * dx + q11 * v_start
        shifted = x_end - reference
        inner_first += 0.5 * shifted
        inner_second += 0.5 * shifted * shifted
        first_sum += step * inner_first
        second_sum += step * inner_second
        if not damping_force:
            peak = max(top, bottom)
            low = min(top, bottom)
            max_system = max(max_system, k * top)
            min_system = min(min_system, k * bottom)
            for s in range(slots):
                max_pair = max(max_pair, pair_stiffness[s, i] * top)
            if i > 0:
                max_system = max(max_system, stiffness[i - 1] * x_start)
                min_system = min(min_system, stiffness[i - 1] * x_start)
                for s in range(slots):
                    max_pair = max(max_pair, pair_stiffness[s, i - 1] * x_start)
            max_x = max(max_x, peak)
            min_x = min(min_x, low)
        else:
            max_x = max(max_x, top)
            min_x = min(min_x, bottom)
        max_v = max(max_v, fastest)
        x_start = x_end
        v_start = v_end
    # the last sample, τ = T, belongs to the last interval
    k = stiffness[n - 1]
    c = damping[n - 1]
    load = k * x_start + (c * v_start if damping_force else 0.0)
    max_system = max(max_system, load)
    min_system = min(min_system, load)
    for s in range(slots):
        extra = pair_stiffness[s, n - 1] / k * c * v_start if damping_force else 0.0
        max_pair = max(max_pair, pair_stiffness[s, n - 1] * x_start + extra)
    max_x = max(max_x, x_start)
    min_x = min(min_x, x_start)
    max_v = max(max_v, abs(v_start))
    mean_shift = first_sum / period
    variance = max(second_sum / period - mean_shift * mean_shift, 0.0)
    out[0] = max_pair
    out[1] = max_system
    out[2] = min_system
    out[3] = reference + mean_shift
    out[4] = math.sqrt(variance)
    out[5] = max_x
    out[6] = min_x
    out[7] = max_v


@numba.njit(cache=True)
def _metrics_batch(mass: np.ndarray, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                   damping_factor: np.ndarray, force: float, pair_stiffness: np.ndarray, x0: np.ndarray,
                   v0: np.ndarray, samples: int, damping_force: bool) -> np.ndarray:
    count = mass.size
    out = np.full((count, _METRIC_COUNT), np.nan)
    scaled = np.empty_like(damping)
    for j in range(count):
        if not np.isfinite(x0[j]):
            continue
        for i in range(damping.size):
            scaled[i] = damping[i] * damping_factor[j]
        _orbit_metrics(mass[j], nodes, stiffness, scaled, force, pair_stiffness, x0[j], v0[j], samples,
                       damping_force, out[j])
    return out


def evaluate_speeds(tables: GroupTables, speeds_rpm, samples: int | None = None) -> dict[str, np.ndarray]:
    """Metrics of one group at many speeds [rpm] (the fast path); arrays of the shape of ``speeds_rpm``.

    Unstable points (a Floquet multiplier modulus >= 1) get NaN metrics and ``stable`` 0.
    """
    speeds = np.atleast_1d(np.asarray(speeds_rpm, dtype=float))
    ratio = speeds / tables.speed_rpm
    mass = tables.mass * ratio**2
    # damping at speed n1 is c_ref·r^(−5/4); in the reference time it is multiplied by r
    factor = ratio ** (DAMPING_SPEED_EXPONENT + 1.0)
    damping = tables.damping[None, :] * factor[:, None]
    x0, v0, moduli = periodic_steady_state_batch(mass, tables.nodes, np.broadcast_to(tables.stiffness,
                                                 damping.shape), damping, tables.force)
    values = _metrics_batch(np.ascontiguousarray(mass), tables.nodes, tables.stiffness, tables.damping,
                            np.ascontiguousarray(factor), tables.force, tables.pair_stiffness, x0, v0,
                            int(tables.samples_per_interval if samples is None else samples),
                            tables.include_damping_force)
    stable = moduli[:, 0] < 1.0
    w0 = tables.force
    with np.errstate(invalid="ignore"):
        contact_loss = np.where(stable, values[:, 2] < 0.0, False)
    return {
        "kv": values[:, 0] / w0,
        "max_pair_load": values[:, 0],
        "max_system_load_ratio": values[:, 1] / w0,
        "dte_mean": values[:, 3],
        "dte_rms": values[:, 4],
        "dte_peak_to_peak": values[:, 5] - values[:, 6],
        "max_velocity": values[:, 7] * ratio,
        "natural_frequency_hz": np.full(speeds.shape, tables.natural_frequency_hz),
        "mean_mesh_stiffness": np.full(speeds.shape, tables.mean_mesh_stiffness),
        "floquet_multiplier_max": moduli[:, 0].copy(),
        "stable": stable.astype(np.int8),
        "contact_loss": contact_loss.astype(np.int8),
        "mesh_frequency_hz": tables.pinion_teeth * speeds / 60.0,
        "static_load": np.full(speeds.shape, w0),
    }


# ------------------------------------------------------------------------------------------- slow path
def evaluate_point(case, model: str, points_per_period: int | None = None) -> dict[str, float]:
    """Metrics of one point from ``Simulation(case, model).run("periodic")`` (the reference path)."""
    from thermogear.dynamics.periodic import floquet_multipliers
    from thermogear.simulation import Simulation

    simulation = Simulation(case, model, points_per_period)
    problem = simulation.problem
    result = {name: math.nan for name in MODEL_VARIABLES}
    result.update(natural_frequency_hz=problem.natural_frequency, mean_mesh_stiffness=problem.mean_stiffness,
                  mesh_frequency_hz=problem.mesh_frequency, static_load=problem.static_load, contact_loss=0)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            metrics = simulation.run("periodic").metrics
    except ModelLimitError:
        result["floquet_multiplier_max"] = float(np.max(np.abs(floquet_multipliers(problem))))
        result["stable"] = 0
        return result
    result.update(kv=metrics["kv"], max_pair_load=metrics["max_pair_load"],
                  max_system_load_ratio=metrics["max_system_load_ratio"], dte_mean=metrics["dte_mean"],
                  dte_rms=metrics["dte_rms"], dte_peak_to_peak=metrics["dte_peak_to_peak"],
                  max_velocity=metrics["max_velocity"], floquet_multiplier_max=metrics["floquet_multipliers_abs"][0],
                  stable=int(metrics["stable"]), contact_loss=int(metrics["contact_loss"]["detected"]))
    return result


# ------------------------------------------------------------------------------------------- blocks
def empty_block_result(models: tuple[str, ...], shape: tuple[int, ...]) -> dict[str, np.ndarray]:
    """Arrays of a block: per-model variables (models, *shape), per-point variables (*shape)."""
    result: dict[str, np.ndarray] = {}
    for name in MODEL_VARIABLES:
        dtype = np.int8 if name in ("stable", "contact_loss") else float
        result[name] = np.full((len(models), *shape), 0 if dtype is np.int8 else np.nan, dtype=dtype)
    for name in POINT_VARIABLES:
        result[name] = np.full(shape, np.nan)
    return result


def _speed_dependent_input(case) -> bool:
    """True when a case's stiffness input depends on the speed, so the fast path cannot reuse it."""
    return case.temperature.model == "fem" or case.thermal.x_te_source == "fem"


def evaluate_block(study, block, method: str = "batch") -> tuple[dict[str, np.ndarray], list[str]]:
    """Result arrays of one block of a study and the distinct warning messages raised while computing it.

    ``method``: ``"batch"`` (groups of points that differ only in speed run through the fast path) or
    ``"simulation"`` (one Simulation per point and model).
    """
    shape = block.shape
    result = empty_block_result(study.models, shape)
    points = study.block_values(block)
    dims = study.dims
    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    messages: list[str] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        groups: dict[tuple, list[int]] = {}
        for flat, values in enumerate(points):
            key = tuple(v for a, v in enumerate(values) if a != speed_axis) if speed_axis is not None else (flat,)
            groups.setdefault(key, []).append(flat)
        for members in groups.values():
            first = points[members[0]]
            group_case = study.case_at(first)
            use_batch = method == "batch" and not _speed_dependent_input(group_case)
            indices = np.unravel_index(np.array(members), shape)
            if use_batch:
                speeds = np.array([points[m][speed_axis] if speed_axis is not None
                                   else group_case.operating_point.speed_rpm for m in members], dtype=float)
                for model_index, model in enumerate(study.models):
                    values = evaluate_speeds(group_tables(group_case, model), speeds)
                    _store(result, values, model_index, indices)
            else:
                for member, position in zip(members, zip(*indices)):
                    point_case = group_case if member == members[0] else study.case_at(points[member])
                    for model_index, model in enumerate(study.models):
                        values = {k: np.array([v]) for k, v in evaluate_point(point_case, model).items()}
                        _store(result, values, model_index, tuple(np.array([p]) for p in position))
    for item in caught:
        text = f"{item.category.__name__}: {item.message}"
        if text not in messages:
            messages.append(text)
    del dims
    return result, messages


def _store(result: dict[str, np.ndarray], values: dict[str, Any], model_index: int, indices) -> None:
    for name in MODEL_VARIABLES:
        result[name][(model_index, *indices)] = values[name]
    for name in POINT_VARIABLES:
        result[name][indices] = values[name]
