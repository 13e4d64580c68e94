"""Metrics of one steady period of the linear mesh dynamics (Kv of Luo & Li (2020) Eq. 29, loads, equilibria,
amplitudes, contact loss). The definitions are those of :mod:`thermogear.dynamics.response`; the metrics every
response shares (loads and Kv, DTE statistics, contact loss, frequencies) are defined once in
:mod:`thermogear.dynamics.results.period_metrics`."""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.dynamics.results.period_metrics import (contact_loss_summary, dte_statistics, dynamic_factor,
                                                frequency_metrics, load_metrics, multiplier_moduli,
                                                pair_load_maximum)
from thermogear.dynamics.problems.problem import MeshDynamicsProblem, region_name
from thermogear.dynamics.results.metric_formulas import mesh_load
from thermogear.errors import ModelLimitError


def _left_limit_index(interval: np.ndarray) -> np.ndarray:
    """Sample indices where the interval changes (nodes inside the record)."""
    return np.flatnonzero(interval[1:] != interval[:-1]) + 1


def sampled_load(stiffness: np.ndarray, damping: np.ndarray, offset: np.ndarray | None, interval: np.ndarray,
                 x: np.ndarray, v: np.ndarray, include_damping_force: bool) -> np.ndarray:
    """k·x (+ c·ẋ) − k·e with coefficients taken on ``interval`` (last axis = samples); ``offset`` k·e or None
    (:func:`~thermogear.dynamics.results.metric_formulas.mesh_load`, the compiled sweep kernel's formula)."""
    if include_damping_force:
        return mesh_load(stiffness[..., interval], x, damping[..., interval], v,
                         0.0 if offset is None else offset[..., interval])
    return mesh_load(stiffness[..., interval], x, 0.0, 0.0, 0.0 if offset is None else offset[..., interval])


def _load_with_left_limits(stiffness: np.ndarray, damping: np.ndarray, offset: np.ndarray | None,
                           interval: np.ndarray, x: np.ndarray, v: np.ndarray, include_damping_force: bool
                           ) -> np.ndarray:
    """Loads at the samples followed by the left limits at the interior nodes (for maxima and minima)."""
    right = sampled_load(stiffness, damping, offset, interval, x, v, include_damping_force)
    nodes = _left_limit_index(interval)
    left = sampled_load(stiffness, damping, offset, interval[nodes - 1], x[nodes], v[nodes], include_damping_force)
    return np.concatenate([right, left], axis=-1)


def _contact_loss(time: np.ndarray, force: np.ndarray, minimum: float, static_load: float) -> dict[str, Any]:
    """Runs of negative mesh force: start times [s], durations [s], the minimum force [N]."""
    negative = force < 0.0
    starts: list[float] = []
    durations: list[float] = []
    if np.any(negative):
        edges = np.diff(np.concatenate([[0], negative.astype(np.int8), [0]]))
        first = np.flatnonzero(edges == 1)
        last = np.flatnonzero(edges == -1) - 1
        for a, b in zip(first, last, strict=True):
            # the crossing lies between a sample and its neighbour: linear interpolation of the force
            t_start = time[a]
            if a > 0 and force[a - 1] > 0.0:
                t_start = time[a - 1] + (time[a] - time[a - 1]) * force[a - 1] / (force[a - 1] - force[a])
            t_end = time[b]
            if b + 1 < time.size and force[b + 1] > 0.0:
                t_end = time[b] + (time[b + 1] - time[b]) * force[b] / (force[b] - force[b + 1])
            starts.append(float(t_start))
            durations.append(float(t_end - t_start))
    return contact_loss_summary(minimum < 0.0, starts, durations, sum(durations), minimum, static_load)


def compute_metrics(problem: MeshDynamicsProblem, time: np.ndarray, displacement: np.ndarray,
                    velocity: np.ndarray, interval: np.ndarray, multipliers: np.ndarray,
                    include_damping_force: bool = False) -> dict[str, Any]:
    """Metrics of one steady period (time from 0 to T, both ends sampled); see the module docstring."""
    x, v = displacement, velocity
    w0 = problem.static_load
    system_offset = None if problem.pair_offset is None else problem.system_offset
    system = _load_with_left_limits(problem.stiffness, problem.damping, system_offset, interval, x, v,
                                    include_damping_force)
    system_right = system[: x.size]
    pair = problem.pair_arrays()
    if pair is not None:
        pair_loads = _load_with_left_limits(pair[0], pair[1], problem.pair_offset, interval, x, v,
                                            include_damping_force)
        single_loads = None
    else:
        pair_loads = single_loads = None
        single = problem.contact_count == 1
        if np.any(single):
            # one pair in contact carries the whole mesh force: there the pair load is the system load
            in_single = single[interval]
            nodes = _left_limit_index(interval)
            in_single_left = single[interval[nodes - 1]]
            single_loads = system[np.concatenate([in_single, in_single_left])]
    max_pair, basis = pair_load_maximum(pair_loads, single_loads)
    metrics = load_metrics(w0, problem.face_width, max_pair, basis, float(np.max(system)))

    static_te = problem.static_transmission_error
    durations = problem.durations
    equilibrium: dict[str, float] = {}
    amplitude: dict[str, float] = {}
    deviation: dict[str, float] = {}
    region_of_sample = problem.contact_count[interval]
    nodes = _left_limit_index(interval)
    for count in problem.regions:
        name = region_name(count)
        in_region = problem.contact_count == count
        level = float(np.dot(static_te[in_region], durations[in_region]) / durations[in_region].sum())
        mask = region_of_sample == count
        mask[nodes] |= problem.contact_count[interval[nodes - 1]] == count  # right end of a region interval
        equilibrium[name] = level
        amplitude[name] = float(np.max(x[mask]) - level)
        deviation[name] = float(np.max(np.abs(x[mask] - level)))
    metrics["equilibrium_per_region"] = equilibrium
    metrics["amplitude_per_region"] = amplitude
    metrics["deviation_per_region"] = deviation

    metrics.update(dte_statistics(time, x, problem.period))  # time from 0 to T: over the mesh period T
    metrics["max_velocity"] = float(np.max(np.abs(v)))
    metrics.update(frequency_metrics(problem))
    moduli = multiplier_moduli(multipliers)
    metrics["floquet_multipliers_abs"] = [float(m) for m in moduli]
    # undamped: det M = 1, so |μ|max >= 1 in exact arithmetic even where rounding puts it a hair below 1
    metrics["stable"] = bool(moduli[0] < 1.0 and np.any(problem.damping > 0.0))
    loss = _contact_loss(time, system_right, float(np.min(system)), w0)
    metrics["contact_loss"] = loss
    metrics["valid"] = bool(metrics["stable"] and not loss["detected"])
    _check_finite(metrics)
    return metrics


def _check_finite(value: Any, key: str = "metrics") -> None:
    if isinstance(value, dict):
        for name, item in value.items():
            _check_finite(item, f"{key}.{name}")
    elif isinstance(value, list | tuple):
        for item in value:
            _check_finite(item, key)
    elif isinstance(value, float) and not np.isfinite(value):
        raise ModelLimitError(f"{key} is not finite ({value}); the model is out of its numerical range")


__all__ = ["compute_metrics", "dynamic_factor", "sampled_load"]
