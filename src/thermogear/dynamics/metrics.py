"""Metrics of one steady period of the linear mesh dynamics (Kv of Luo & Li (2020) Eq. 29, loads, equilibria,
amplitudes, contact loss). The definitions are those of :mod:`thermogear.dynamics.response`."""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.dynamics.problem import MeshDynamicsProblem, region_name
from thermogear.errors import ModelLimitError


def _left_limit_index(interval: np.ndarray) -> np.ndarray:
    """Sample indices where the interval changes (nodes inside the record)."""
    return np.flatnonzero(interval[1:] != interval[:-1]) + 1


def sampled_load(stiffness: np.ndarray, damping: np.ndarray, offset: np.ndarray | None, interval: np.ndarray,
                 x: np.ndarray, v: np.ndarray, include_damping_force: bool) -> np.ndarray:
    """k·x (+ c·ẋ) − k·e with coefficients taken on ``interval`` (last axis = samples); ``offset`` k·e or None."""
    load = stiffness[..., interval] * x
    if offset is not None:
        load = load - offset[..., interval]
    if include_damping_force:
        load = load + damping[..., interval] * v
    return load


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
    detected = bool(minimum < 0.0)
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
    return {"detected": detected, "start_times": starts, "durations": durations,
            "total_duration": float(sum(durations)), "min_force": float(minimum),
            "min_force_ratio": float(minimum / static_load)}


def dynamic_factor(max_pair_load, static_load):
    """The dynamic load factor Kv = 1 + Δw/w0 = max pair load / w0 [-] (Luo & Li 2020 Eq. 29: Δw the largest
    single-pair dynamic load above the static load w0), of floats or arrays [N]: the one definition every response
    (1-DOF pair linear or backlash, drivetrain, sweep fast path) uses."""
    return max_pair_load / static_load


def compute_metrics(problem: MeshDynamicsProblem, time: np.ndarray, displacement: np.ndarray,
                    velocity: np.ndarray, interval: np.ndarray, multipliers: np.ndarray,
                    include_damping_force: bool = False) -> dict[str, Any]:
    """Metrics of one steady period (time from 0 to T, both ends sampled); see the module docstring."""
    x, v = displacement, velocity
    w0 = problem.static_load
    period = problem.period
    system_offset = None if problem.pair_offset is None else problem.system_offset
    system = _load_with_left_limits(problem.stiffness, problem.damping, system_offset, interval, x, v,
                                    include_damping_force)
    system_right = system[: x.size]
    max_system = float(np.max(system))
    metrics: dict[str, Any] = {"static_load": w0, "static_load_n_per_mm": w0 / problem.face_width / 1e3}

    pair = problem.pair_arrays()
    if pair is not None:
        pair_loads = _load_with_left_limits(pair[0], pair[1], problem.pair_offset, interval, x, v,
                                            include_damping_force)
        max_pair = float(np.max(pair_loads))
        basis = "pair_loads"
    else:
        single = problem.contact_count == 1
        if np.any(single):
            # one pair in contact carries the whole mesh force: there the pair load is the system load
            in_single = single[interval]
            nodes = _left_limit_index(interval)
            in_single_left = single[interval[nodes - 1]]
            mask = np.concatenate([in_single, in_single_left])
            max_pair = float(np.max(system[mask]))
            basis = "system_load_in_single_contact"
        else:
            max_pair = None
            basis = "unavailable: no pair stiffness and no single-contact interval"
    metrics["kv"] = None if max_pair is None else dynamic_factor(max_pair, w0)
    metrics["kv_basis"] = basis
    metrics["max_pair_load"] = max_pair
    metrics["max_pair_load_n_per_mm"] = None if max_pair is None else max_pair / problem.face_width / 1e3
    metrics["max_system_load"] = max_system
    metrics["max_system_load_n_per_mm"] = max_system / problem.face_width / 1e3
    metrics["max_system_load_ratio"] = max_system / w0

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

    mean_x = float(np.trapezoid(x, time) / period)
    metrics["dte_mean"] = mean_x
    metrics["dte_rms"] = float(np.sqrt(max(np.trapezoid((x - mean_x) ** 2, time) / period, 0.0)))
    metrics["dte_peak_to_peak"] = float(np.max(x) - np.min(x))
    metrics["max_velocity"] = float(np.max(np.abs(v)))
    metrics["natural_frequency_hz"] = problem.natural_frequency
    metrics["mesh_frequency_hz"] = problem.mesh_frequency
    metrics["frequency_ratio"] = problem.frequency_ratio
    moduli = np.sort(np.abs(np.asarray(multipliers)))[::-1]
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
