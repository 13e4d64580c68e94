"""Compiled periodic steady states and orbit metrics of many operating points at once (the fast path of sweeps).

One fused kernel per group of points that share the node grid and the stiffness k(τ): for a tile of points it
builds the monodromy matrix (periodic initial state, Floquet multipliers) and then walks the exact periodic orbit,
sampling it exactly as :func:`thermogear.dynamics.response.compute_metrics` does (``samples`` equal sub-steps per
interval plus the end of the period, loads right-continuous at the samples plus the left limits at the interior
nodes), so the fast path gives the numbers of the single-point solver and its metrics to rounding.

Transition over one sub-step h of an interval (me·ẍ + c·ẋ + k·x = w, constant coefficients; the closed form of
:mod:`thermogear.dynamics.linear_algebra.transition_2x2`, after Cayley–Hamilton for a 2×2 matrix exponential, e.g. Moler
& Van Loan, SIAM Review 45 (2003), method 17):

    Φ(h) = e^{−σh}·[C·I + S·(A + σI)],   σ = c/(2me),   u = (σ² − k/me)·h²,
    C = Σ u^j/(2j)!  (= cos √−u, cosh √u),   S = h·Σ u^j/(2j+1)!.

For |u| ≤ 1/4 and σh ≤ 1/8 (every interval of a usual mesh period: h is 1/(samples·intervals) of it) the series
to u⁷ and e^{−x} to x¹¹ are exact to rounding (first omitted terms < 1e-18 relative), so the kernel needs no
transcendental function and the loop over points is vectorised; outside that range it takes the closed form
(``transition_2x2``). The transition over a whole interval is Φ(h)^samples (the same orbit: the state at the
end of the interval is the one after the last sub-step), so one transition per interval serves the monodromy and
the walk.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from thermogear.dynamics.linear_algebra.transition_2x2 import multiplier_moduli_2x2, periodic_state_2x2, transition_2x2
from thermogear.dynamics.results.metric_formulas import mean_and_rms, mesh_load

__all__ = ["METRIC_COUNT", "periodic_metrics_batch"]

METRIC_COUNT = 8  # max pair load, max system load, min system load, mean x, rms x, max x, min x, max |v|
TILE = 64  # points walked together: their state arrays stay in the L1 cache
_SERIES_U = 0.25  # |u| = |σ² − k/me|·h² up to which the series of C and S are exact to rounding
_SERIES_DECAY = 0.125  # σh up to which the series of e^{−σh} is exact to rounding

# 1/(2j)!, 1/(2j+1)! for j = 1..7 and 1/j for j = 2..11 (Horner forms below)
_C1, _C2, _C3, _C4 = 1.0 / 2.0, 1.0 / 24.0, 1.0 / 720.0, 1.0 / 40320.0
_C5, _C6, _C7 = 1.0 / 3628800.0, 1.0 / 479001600.0, 1.0 / 87178291200.0
_S1, _S2, _S3, _S4 = 1.0 / 6.0, 1.0 / 120.0, 1.0 / 5040.0, 1.0 / 362880.0
_S5, _S6, _S7 = 1.0 / 39916800.0, 1.0 / 6227020800.0, 1.0 / 1307674368000.0

# The metrics' formulas, defined once in thermogear.dynamics.results.metric_formulas (the Python path calls them as
# they are), compiled here: the mesh load k·x + c·ẋ and the mean and RMS of the transmission error from its moments.
# (numba's cache keys on this file: after editing those formulas, clear this module's __pycache__ *.nbi/*.nbc.)
_mesh_load = numba.njit(cache=True, error_model="numpy")(mesh_load)
_mean_and_rms = numba.njit(cache=True, error_model="numpy")(mean_and_rms)


@numba.njit(cache=True, error_model="numpy")
def _step_transitions(stiffness: float, damping_reference: float, mass: np.ndarray, factor: np.ndarray,
                      step: float, p00: np.ndarray, p01: np.ndarray, p10: np.ndarray, p11: np.ndarray) -> None:
    """Φ(step) of every point of a tile (damping c = damping_reference·factor[j], mass me = mass[j])."""
    count = mass.size
    outside = 0
    for j in range(count):
        c = damping_reference * factor[j]
        a = stiffness / mass[j]
        sigma = 0.5 * c / mass[j]
        u = (sigma * sigma - a) * step * step
        x = sigma * step
        cosine = 1.0 + u * (_C1 + u * (_C2 + u * (_C3 + u * (_C4 + u * (_C5 + u * (_C6 + u * _C7))))))
        sine = step * (1.0 + u * (_S1 + u * (_S2 + u * (_S3 + u * (_S4 + u * (_S5 + u * (_S6 + u * _S7)))))))
        decay = 1.0 - x * (1.0 - x * 0.5 * (1.0 - x * (1.0 / 3.0) * (1.0 - x * 0.25 * (1.0 - x * 0.2 * (
            1.0 - x * (1.0 / 6.0) * (1.0 - x * (1.0 / 7.0) * (1.0 - x * 0.125 * (1.0 - x * (1.0 / 9.0) * (
                1.0 - x * 0.1 * (1.0 - x * (1.0 / 11.0)))))))))))
        p00[j] = decay * (cosine + sigma * sine)
        p01[j] = decay * sine
        p10[j] = -decay * a * sine
        p11[j] = decay * (cosine - sigma * sine)
        outside += (abs(u) > _SERIES_U) | (x > _SERIES_DECAY)
    if outside:
        for j in range(count):
            c = damping_reference * factor[j]
            sigma = 0.5 * c / mass[j]
            u = (sigma * sigma - stiffness / mass[j]) * step * step
            if abs(u) > _SERIES_U or sigma * step > _SERIES_DECAY or not math.isfinite(u):
                p00[j], p01[j], p10[j], p11[j] = transition_2x2(stiffness, c, mass[j], step)


@numba.njit(cache=True, error_model="numpy")
def _multiply(a00, a01, a10, a11, b00, b01, b10, b11) -> None:
    """b ← a·b for every point of a tile (2×2 matrices stored entry by entry)."""
    for j in range(a00.size):
        n00 = a00[j] * b00[j] + a01[j] * b10[j]
        n01 = a00[j] * b01[j] + a01[j] * b11[j]
        n10 = a10[j] * b00[j] + a11[j] * b10[j]
        n11 = a10[j] * b01[j] + a11[j] * b11[j]
        b00[j], b01[j], b10[j], b11[j] = n00, n01, n10, n11


@numba.njit(cache=True, error_model="numpy")
def _square(p00, p01, p10, p11) -> None:
    """p ← p·p for every point of a tile."""
    for j in range(p00.size):
        a00, a01, a10, a11 = p00[j], p01[j], p10[j], p11[j]
        p00[j] = a00 * a00 + a01 * a10
        p01[j] = a00 * a01 + a01 * a11
        p10[j] = a10 * a00 + a11 * a10
        p11[j] = a10 * a01 + a11 * a11


@numba.njit(cache=True, error_model="numpy")
def _monodromy(mass, nodes, stiffness, damping, factor, force, samples, work, stored):
    """Monodromy (m00, m01, m10, m11 in work[12:16]) and image (bx, bv in work[16:18]) of y = 0 after one period,
    per point of a tile, and whether any interval of a point has c ≠ 0."""
    count = mass.size
    p00, p01, p10, p11, q00, q01, q10, q11 = work[0], work[1], work[2], work[3], work[4], work[5], work[6], work[7]
    m00, m01, m10, m11, bx, bv = work[12], work[13], work[14], work[15], work[16], work[17]
    damped = np.zeros(count, dtype=np.bool_)
    for j in range(count):
        m00[j], m01[j], m10[j], m11[j], bx[j], bv[j] = 1.0, 0.0, 0.0, 1.0, 0.0, 0.0
    squarings = 0
    while (1 << squarings) < samples:
        squarings += 1
    by_squaring = (1 << squarings) == samples
    for i in range(stiffness.size):
        step = (nodes[i + 1] - nodes[i]) / samples
        _step_transitions(stiffness[i], damping[i], mass, factor, step, p00, p01, p10, p11)
        kept = stored[i]
        for j in range(count):  # the walk reuses Φ(step)
            kept[0, j], kept[1, j], kept[2, j], kept[3, j] = p00[j], p01[j], p10[j], p11[j]
        # whole interval: Q = Φ(step)^samples
        if by_squaring:
            for _ in range(squarings):
                _square(p00, p01, p10, p11)
            q00, q01, q10, q11 = p00, p01, p10, p11
        else:
            q00, q01, q10, q11 = work[4], work[5], work[6], work[7]
            for j in range(count):
                q00[j], q01[j], q10[j], q11[j] = p00[j], p01[j], p10[j], p11[j]
            for _ in range(samples - 1):
                _multiply(p00, p01, p10, p11, q00, q01, q10, q11)
        k = stiffness[i]
        c = damping[i]
        for j in range(count):
            damped[j] |= c * factor[j] != 0.0
            equilibrium = force[j] / k
            dx = bx[j] - equilibrium
            a00, a01, a10, a11 = q00[j], q01[j], q10[j], q11[j]
            bx[j], bv[j] = a00 * dx + a01 * bv[j] + equilibrium, a10 * dx + a11 * bv[j]
            n00 = a00 * m00[j] + a01 * m10[j]
            n01 = a00 * m01[j] + a01 * m11[j]
            n10 = a10 * m00[j] + a11 * m10[j]
            n11 = a10 * m01[j] + a11 * m11[j]
            m00[j], m01[j], m10[j], m11[j] = n00, n01, n10, n11
    return damped


@numba.njit(cache=True, error_model="numpy")
def _walk_displacement(nodes, stiffness, force, pair_high, pair_low, x0, v0, samples, work, stored,
                       out) -> None:
    """:func:`_walk` without the damping force, one pass over the points per sub-step: the loads are k·x and
    k_p·x, so an interval's extreme loads are those at its extreme x (k > 0, k_p >= 0), and the largest pair
    load max_p k_p·x is pair_high·x for x >= 0 and pair_low·x for x < 0 (the largest and smallest k_p of the
    interval: the same products, so the same numbers)."""
    count = x0.size
    n = stiffness.size
    x, v, xs, eq = work[4], work[5], work[6], work[7]
    top, bottom, fastest, in1, in2, first, second = work[8], work[9], work[10], work[11], work[12], work[13], \
        work[14]
    max_pair, max_system, min_system = work[15], work[16], work[17]
    for j in range(count):
        x[j], v[j] = x0[j], v0[j]
        first[j], second[j] = 0.0, 0.0
        max_pair[j], max_system[j], min_system[j] = -np.inf, -np.inf, np.inf
        top[j], bottom[j], fastest[j] = -np.inf, np.inf, 0.0
    for i in range(n):
        k = stiffness[i]
        step = (nodes[i + 1] - nodes[i]) / samples
        p00, p01, p10, p11 = stored[i, 0], stored[i, 1], stored[i, 2], stored[i, 3]
        kp = stiffness[i - 1] if i > 0 else 0.0
        high = pair_high[i - 1] if i > 0 else 0.0
        low = pair_low[i - 1] if i > 0 else 0.0
        left = i > 0
        for j in range(count):  # the interval's first sample (its start), the left limit at node i, a sub-step
            start = x[j]
            xs[j] = start
            if left:
                load = _mesh_load(kp, start, 0.0, 0.0)
                max_system[j] = max(max_system[j], load)
                min_system[j] = min(min_system[j], load)
                max_pair[j] = max(max_pair[j], _mesh_load(high if start >= 0.0 else low, start, 0.0, 0.0))
            top[j] = max(top[j], start)
            bottom[j] = min(bottom[j], start)
            fastest[j] = max(fastest[j], abs(v[j]))
            shifted = start - x0[j]
            equilibrium = force[j] / k
            eq[j] = equilibrium
            dx = start - equilibrium
            x[j], v[j] = p00[j] * dx + p01[j] * v[j] + equilibrium, p10[j] * dx + p11[j] * v[j]
            in1[j] = 0.5 * shifted
            in2[j] = 0.5 * shifted * shifted
        for _ in range(1, samples):  # the interior samples, each followed by a sub-step
            for j in range(count):
                here = x[j]
                top[j] = max(top[j], here)
                bottom[j] = min(bottom[j], here)
                fastest[j] = max(fastest[j], abs(v[j]))
                shifted = here - x0[j]
                in1[j] += shifted
                in2[j] += shifted * shifted
                dx = here - eq[j]
                x[j], v[j] = p00[j] * dx + p01[j] * v[j] + eq[j], p10[j] * dx + p11[j] * v[j]
        high = pair_high[i]
        low = pair_low[i]
        for j in range(count):  # the end of the interval: half weight; the interval's extreme loads
            shifted = x[j] - x0[j]
            first[j] += step * (in1[j] + 0.5 * shifted)
            second[j] += step * (in2[j] + 0.5 * shifted * shifted)
            upper = top[j]
            lower = bottom[j]
            max_system[j] = max(max_system[j], _mesh_load(k, upper, 0.0, 0.0))
            min_system[j] = min(min_system[j], _mesh_load(k, lower, 0.0, 0.0))
            max_pair[j] = max(max_pair[j], _mesh_load(high if upper >= 0.0 else low, upper, 0.0, 0.0))
            # the running extremes of x over the period continue from the interval's
            work[18, j] = max(work[18, j], upper) if i > 0 else upper
            work[19, j] = min(work[19, j], lower) if i > 0 else lower
            top[j] = -np.inf
            bottom[j] = np.inf
    # the last sample, τ = T, belongs to the last interval
    k = stiffness[n - 1]
    period = nodes[n] - nodes[0]
    high = pair_high[n - 1]
    low = pair_low[n - 1]
    for j in range(count):
        end = x[j]
        out[j, 0] = max(max_pair[j], _mesh_load(high if end >= 0.0 else low, end, 0.0, 0.0))
        out[j, 1] = max(max_system[j], _mesh_load(k, end, 0.0, 0.0))
        out[j, 2] = min(min_system[j], _mesh_load(k, end, 0.0, 0.0))
        out[j, 3], out[j, 4] = _mean_and_rms(x0[j], first[j], second[j], period)
        out[j, 5] = max(work[18, j], end)
        out[j, 6] = min(work[19, j], end)
        out[j, 7] = max(fastest[j], abs(v[j]))


@numba.njit(cache=True, error_model="numpy")
def _walk(mass, nodes, stiffness, damping, factor, force, pair_stiffness, x0, v0, samples, damping_force,
          work, out):
    """Metrics of the exact periodic orbits from (x0, v0) of a tile of points into ``out`` (count, METRIC_COUNT);
    see ``thermogear.dynamics.results.metrics`` for the definitions (trapezoidal mean and RMS, maxima over the samples
    and the left limits at the nodes; loads k·x + c·ẋ with the damping force, else k·x). The general walk: the
    loads at every sample (:func:`_walk_displacement` is the faster one without the damping force)."""
    count = mass.size
    n = stiffness.size
    slots = pair_stiffness.shape[0]
    weight = 1.0 if damping_force else 0.0
    p00, p01, p10, p11, x, v, xs, vs = work[0], work[1], work[2], work[3], work[4], work[5], work[6], work[7]
    top, bottom, fastest, in1, in2, first, second, eq = work[8], work[9], work[10], work[11], work[12], \
        work[13], work[14], work[15]
    max_pair, max_system, min_system, max_x, min_x, max_v = work[16], work[17], work[18], work[19], work[20], \
        work[21]
    for j in range(count):
        x[j], v[j] = x0[j], v0[j]
        first[j], second[j] = 0.0, 0.0
        max_pair[j], max_system[j], min_system[j] = -np.inf, -np.inf, np.inf
        max_x[j], min_x[j], max_v[j] = -np.inf, np.inf, 0.0
    for i in range(n):
        k = stiffness[i]
        step = (nodes[i + 1] - nodes[i]) / samples
        _step_transitions(k, damping[i], mass, factor, step, p00, p01, p10, p11)
        for j in range(count):
            xs[j], vs[j] = x[j], v[j]
            eq[j] = force[j] / k
            top[j], bottom[j], fastest[j] = x[j], x[j], abs(v[j])
            shifted = x[j] - x0[j]
            in1[j] = 0.5 * shifted
            in2[j] = 0.5 * shifted * shifted
        for sub in range(samples):
            for j in range(count):  # loads at the sample of this sub-step (right-continuous)
                load = _mesh_load(k, x[j], weight * damping[i] * factor[j], v[j])
                max_system[j] = max(max_system[j], load)
                min_system[j] = min(min_system[j], load)
            for s in range(slots):
                pk = pair_stiffness[s, i]
                share = pk / k
                for j in range(count):
                    max_pair[j] = max(max_pair[j], _mesh_load(pk, x[j], weight * share * (damping[i] * factor[j]),
                                                              v[j]))
            last = sub == samples - 1
            for j in range(count):
                dx = x[j] - eq[j]
                x[j], v[j] = p00[j] * dx + p01[j] * v[j] + eq[j], p10[j] * dx + p11[j] * v[j]
                shifted = x[j] - x0[j]
                if last:  # the end of the interval: half weight, and the next interval's first sample
                    in1[j] += 0.5 * shifted
                    in2[j] += 0.5 * shifted * shifted
                else:
                    in1[j] += shifted
                    in2[j] += shifted * shifted
                    top[j] = max(top[j], x[j])
                    bottom[j] = min(bottom[j], x[j])
                    fastest[j] = max(fastest[j], abs(v[j]))
        for j in range(count):
            first[j] += step * in1[j]
            second[j] += step * in2[j]
            max_x[j] = max(max_x[j], top[j])
            min_x[j] = min(min_x[j], bottom[j])
            max_v[j] = max(max_v[j], fastest[j])
        if i > 0:  # left limit at node i: coefficients of interval i − 1
            kp = stiffness[i - 1]
            for j in range(count):
                load = _mesh_load(kp, xs[j], weight * damping[i - 1] * factor[j], vs[j])
                max_system[j] = max(max_system[j], load)
                min_system[j] = min(min_system[j], load)
            for s in range(slots):
                pk = pair_stiffness[s, i - 1]
                share = pk / kp
                for j in range(count):
                    max_pair[j] = max(max_pair[j], _mesh_load(pk, xs[j], weight * share * (damping[i - 1] * factor[j]),
                                                              vs[j]))
    # the last sample, τ = T, belongs to the last interval
    k = stiffness[n - 1]
    period = nodes[n] - nodes[0]
    for j in range(count):
        c = damping[n - 1] * factor[j] if damping_force else 0.0
        load = _mesh_load(k, x[j], c, v[j])
        max_system[j] = max(max_system[j], load)
        min_system[j] = min(min_system[j], load)
        for s in range(slots):
            max_pair[j] = max(max_pair[j], _mesh_load(pair_stiffness[s, n - 1], x[j], pair_stiffness[s, n - 1] / k * c,
                                                      v[j]))
        max_x[j] = max(max_x[j], x[j])
        min_x[j] = min(min_x[j], x[j])
        max_v[j] = max(max_v[j], abs(v[j]))
        out[j, 0] = max_pair[j]
        out[j, 1] = max_system[j]
        out[j, 2] = min_system[j]
        out[j, 3], out[j, 4] = _mean_and_rms(x0[j], first[j], second[j], period)
        out[j, 5] = max_x[j]
        out[j, 6] = min_x[j]
        out[j, 7] = max_v[j]


@numba.njit(cache=True, error_model="numpy", nogil=True)
def periodic_metrics_batch(mass: np.ndarray, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                           factor: np.ndarray, force: np.ndarray, pair_stiffness: np.ndarray, samples: int,
                           damping_force: bool) -> tuple[np.ndarray, np.ndarray]:
    """Floquet multiplier moduli (m, 2) (larger first) and orbit metrics (m, METRIC_COUNT) of m points that share
    the nodes (n+1,) [s] and the stiffness (n,) [N/m]: mass (m,) [kg], damping damping[i]·factor[j] [N·s/m],
    force (m,) [N], pair stiffness (slots, n) [N/m]. Unstable points (a modulus >= 1, or c = 0 on every interval:
    det M = 1, Liouville's formula) get NaN metrics, as ``periodic_steady_state_batch`` gives them NaN states."""
    total = mass.size
    slots, n = pair_stiffness.shape
    pair_high = np.zeros(n)
    pair_low = np.zeros(n)
    for i in range(n):
        if slots:
            pair_high[i] = pair_low[i] = pair_stiffness[0, i]
        for s in range(1, slots):
            pair_high[i] = max(pair_high[i], pair_stiffness[s, i])
            pair_low[i] = min(pair_low[i], pair_stiffness[s, i])
    moduli = np.empty((total, 2))
    full_work = np.empty((22, TILE))  # per-point state of a tile
    full_stored = np.empty((n, 4, TILE))  # Φ(step) of every interval of a tile, for the walk
    out = np.full((total, METRIC_COUNT), np.nan)
    for start in range(0, total, TILE):
        stop = min(start + TILE, total)
        count = stop - start
        if count == TILE:  # full tiles share one set of buffers (allocated once: large blocks cost page faults)
            work, stored = full_work, full_stored
        else:
            work, stored = np.empty((22, count)), np.empty((n, 4, count))
        tile_mass = np.ascontiguousarray(mass[start:stop])
        tile_factor = np.ascontiguousarray(factor[start:stop])
        tile_force = np.ascontiguousarray(force[start:stop])
        damped = _monodromy(tile_mass, nodes, stiffness, damping, tile_factor, tile_force, samples, work, stored)
        x0 = np.zeros(count)
        v0 = np.zeros(count)  # unstable points are walked harmlessly from 0 and reported as NaN
        stable = 0
        for j in range(count):
            first, second = multiplier_moduli_2x2(work[12, j], work[13, j], work[14, j], work[15, j])
            if not damped[j]:
                first = max(first, 1.0)  # |μ1·μ2| = det M = 1 exactly: |μ|max >= 1 whatever rounding gives
            moduli[start + j, 0] = first
            moduli[start + j, 1] = second
            if first < 1.0:
                x0[j], v0[j] = periodic_state_2x2(work[12, j], work[13, j], work[14, j], work[15, j], work[16, j],
                                               work[17, j])
                stable += 1
        if stable == 0:
            continue
        metrics = np.empty((count, METRIC_COUNT))
        if damping_force or slots == 0:
            _walk(tile_mass, nodes, stiffness, damping, tile_factor, tile_force, pair_stiffness, x0, v0, samples,
                  damping_force, work, metrics)
        else:
            _walk_displacement(nodes, stiffness, tile_force, pair_high, pair_low, x0, v0, samples, work, stored,
                               metrics)
        for j in range(count):
            if moduli[start + j, 0] < 1.0:
                out[start + j, :] = metrics[j, :]
    return moduli, out
