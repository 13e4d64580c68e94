"""Compiled metrics of exact periodic orbits for the sweep's fast path.

The kernel samples the exact periodic orbit of me·ẍ + c·ẋ + k·x = w (closed-form transitions of
:mod:`thermogear.dynamics.periodic`) exactly as :func:`thermogear.dynamics.response.compute_metrics` does (the
same samples per interval, one-sided limits at the nodes), so the fast path gives the numbers of one
``Simulation`` per point to rounding.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from thermogear.dynamics.periodic import _transition

METRIC_COUNT = 8  # max pair load, max system load, min system load, mean x, rms x, max x, min x, max |v|


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
def metrics_batch(mass: np.ndarray, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                  force: np.ndarray, pair_stiffness: np.ndarray, x0: np.ndarray, v0: np.ndarray, samples: int,
                  damping_force: bool) -> np.ndarray:
    """Metrics (m, METRIC_COUNT) of m periodic orbits sharing nodes and stiffness: mass (m,), damping (m, n),
    force (m,), initial states (m,); NaN rows where x0 is NaN (unstable points)."""
    count = mass.size
    out = np.full((count, METRIC_COUNT), np.nan)
    for j in range(count):
        if not np.isfinite(x0[j]):
            continue
        _orbit_metrics(mass[j], nodes, stiffness, damping[j], force[j], pair_stiffness, x0[j], v0[j], samples,
                       damping_force, out[j])
    return out


__all__ = ["METRIC_COUNT", "metrics_batch"]
