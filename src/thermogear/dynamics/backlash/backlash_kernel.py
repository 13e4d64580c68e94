"""Exact event-driven integrator of the piecewise-linear backlash mesh model (numba), with its variational matrix.

Within one interval of the mesh period and one contact set (which driving and back-flank pairs touch) the
equation of :mod:`thermogear.dynamics.problems.backlash_problem` is linear with constant coefficients,

    me·ẍ + c·ẋ + K·x = G,   K = Σ_active k,   G = w + Σ_active-driving k_s·e_s − Σ_active-back k'_s·(j + e'_s),

so y = [x, ẋ] follows in closed form: y(t) = Φ(t)·(y0 − [G/K, 0]) + [G/K, 0] for K > 0 with the 2×2 transition
matrix Φ = expm(A t) of :func:`thermogear.dynamics.linear_algebra.transition_2x2.transition_2x2` (under-, critically and
over-damped); for K = 0 (free flight through the backlash) Φ = [[1, (1 − e^{−βt})/β], [0, e^{−βt}]], β = c/me, and the
constant force adds [a·(βt + expm1(−βt))/β², a·(1 − e^{−βt})/β], a = G/me (Taylor series for small βt, a·t²/2 at c = 0).

Contact switches. The set is constant while x stays strictly between the nearest threshold below (L) and above
(U) among the e_s and −j − e'_s of the pairs present. Each interval is advanced in scan steps no longer than
``scan_fraction`` (default 1/16) of the natural period 2π·sqrt(me/K) of the active set (no limit in free flight).
In such a step ẋ has at most one zero: for K > 0 the zeros of ẋ = e^{−σt}(A cos ω_d t + B sin ω_d t) are π/ω_d
≥ T_n/2 apart (ω_d <= ω_n), over-damped and free-flight velocities have at most one zero at all. So x is
monotone on [0, t_e] and [t_e, h] around the located extremum t_e, and a threshold crossing, including a double
crossing that leaves and re-enters within one step, shows as a sign change of x − level on one of these two
monotone pieces. The crossing is then found by safeguarded Newton (bisection fallback) on the closed form to
machine precision, x is set to the threshold and the new set is chosen from the sign of ẋ (of ẍ when ẋ = 0).

Variational matrix. The monodromy ∂y(T)/∂y0 is the time-ordered product of the Φ of every piece and of the
saltation matrices S = I + (f⁺ − f⁻)·nᵀ/(nᵀ·f⁻) at the switches, n = [1, 0] (the switching surface x = level).
The spring force is continuous at a switch, so f⁺ − f⁻ = [0, −(c⁺ − c⁻)·ẋ/me] and S = [[1, 0], [−(c⁺ − c⁻)/me, 1]]:
S = I in damping mode "always" (continuous field); in mode "in_contact" S carries the jump of c. Node crossings
are time events with a continuous state: no saltation.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from thermogear.dynamics.linear_algebra.transition_2x2 import transition_2x2

__all__ = ["integrate_periods"]

_MAX_SWITCHES_PER_INTERVAL = 10_000  # beyond this the motion is chattering or Zeno: reported, never looped on


@numba.njit(cache=True)
def _advance(stiffness: float, damping: float, load: float, mass: float, x0: float, v0: float, t: float
             ) -> tuple[float, float, float, float, float, float]:
    """State at local time t from (x0, v0) under me·ẍ + c·ẋ + K·x = G, and Φ(t) (4 entries)."""
    p00, p01, p10, p11 = transition_2x2(stiffness, damping, mass, t)
    if stiffness > 0.0:
        equilibrium = load / stiffness
        dx = x0 - equilibrium
        return p00 * dx + p01 * v0 + equilibrium, p10 * dx + p11 * v0, p00, p01, p10, p11
    acceleration = load / mass
    beta = damping / mass
    bt = beta * t
    if abs(bt) < 1e-4:
        second = t * t * (0.5 - bt / 6.0 + bt * bt / 24.0)
    else:
        second = (bt + math.expm1(-bt)) / (beta * beta)
    return (p00 * x0 + p01 * v0 + acceleration * second, p10 * x0 + p11 * v0 + acceleration * p01,
            p00, p01, p10, p11)


@numba.njit(cache=True)
def _root(stiffness: float, damping: float, load: float, mass: float, x0: float, v0: float, ta: float, tb: float,
          level: float, velocity_root: bool) -> float:
    """Local time in [ta, tb] where x(t) = level (or ẋ(t) = 0), given a sign change on the bracket."""
    xa, va, _, _, _, _ = _advance(stiffness, damping, load, mass, x0, v0, ta)
    fa = va if velocity_root else xa - level
    t = 0.5 * (ta + tb)
    for _ in range(200):
        x, v, _, _, _, _ = _advance(stiffness, damping, load, mass, x0, v0, t)
        if velocity_root:
            f = v
            slope = (load - damping * v - stiffness * x) / mass
        else:
            f = x - level
            slope = v
        if f == 0.0:
            return t
        if (f > 0.0) == (fa > 0.0):
            ta, fa = t, f
        else:
            tb = t
        if tb - ta <= 4.0 * 2.220446049250313e-16 * max(abs(tb), 1e-300):
            return tb
        candidate = t - f / slope if slope != 0.0 else 0.5 * (ta + tb)
        if not (ta < candidate < tb) or not math.isfinite(candidate):
            candidate = 0.5 * (ta + tb)
        if abs(candidate - t) <= 2.220446049250313e-16 * abs(t):
            return candidate
        t = candidate
    return t


@numba.njit(cache=True)
def _spring_force(i: int, x: float, pair_k: np.ndarray, pair_e: np.ndarray, back_k: np.ndarray,
                  back_e: np.ndarray, backlash: float) -> float:
    """Σ k_s⟨x − e_s⟩₊ − Σ k'_s⟨−x − j − e'_s⟩₊ [N] on interval i."""
    total = 0.0
    for s in range(pair_k.shape[0]):
        total += pair_k[s, i] * max(x - pair_e[s, i], 0.0) - back_k[s, i] * max(-x - backlash - back_e[s, i], 0.0)
    return total


@numba.njit(cache=True)
def _region(i: int, x: float, direction: float, pair_k: np.ndarray, pair_e: np.ndarray, back_k: np.ndarray,
            back_e: np.ndarray, backlash: float, damping: float, force: float, mode: int
            ) -> tuple[float, float, float, float, float, int, int]:
    """Contact set at x on interval i: K, G, c_eff, lower and upper thresholds, driving and back contact counts.

    A threshold equal to x counts as crossed in the direction of motion (``direction`` = sign of ẋ or ẍ).
    """
    stiffness = 0.0
    load = force
    lower = -np.inf
    upper = np.inf
    driving = 0
    back = 0
    present = 0
    for s in range(pair_k.shape[0]):
        k = pair_k[s, i]
        if k > 0.0:
            present += 1
            level = pair_e[s, i]
            if level < x or (level == x and direction > 0.0):
                stiffness += k
                load += k * level
                driving += 1
                lower = max(lower, level)
            else:
                upper = min(upper, level)
        k = back_k[s, i]
        if k > 0.0:
            level = -backlash - back_e[s, i]
            if level > x or (level == x and direction < 0.0):
                stiffness += k
                load += k * level
                back += 1
                upper = min(upper, level)
            else:
                lower = max(lower, level)
    if mode == 0:
        effective = damping
    elif present > 0:
        effective = damping * min(1.0, (driving + back) / present)
    else:
        effective = 0.0
    return stiffness, load, effective, lower, upper, driving, back


@numba.njit(cache=True)
def _direction(i: int, x: float, v: float, pair_k: np.ndarray, pair_e: np.ndarray, back_k: np.ndarray,
               back_e: np.ndarray, backlash: float, force: float) -> float:
    """Sign of the motion: ẋ, or ẍ = (w − spring force)/me where ẋ = 0 (c·ẋ vanishes there)."""
    if v != 0.0:
        return v
    return force - _spring_force(i, x, pair_k, pair_e, back_k, back_e, backlash)


@numba.njit(cache=True)
def _crossing(x_start: float, x_end: float, lower: float, upper: float) -> int:
    """+1 / −1 when a monotone piece from x_start to x_end crosses the upper / lower threshold, else 0."""
    if x_start < upper <= x_end:
        return 1
    if x_start > lower >= x_end:
        return -1
    return 0


@numba.njit(cache=True, nogil=True)  # releases the GIL: branch studies run their groups on threads
def integrate_periods(mass, nodes, pair_k, pair_e, back_k, back_e, backlash, damping, force, mode, x0, v0,
                      periods, scan_fraction, record, samples, out_time, out_x, out_v, out_driving, out_back,
                      out_interval, out_kind):
    """Integrate ``periods`` mesh periods from (x0, v0) at τ = 0.

    Returns (x, v, m00, m01, m10, m11, free_time, back_time, switches, records, status): the final state, the
    monodromy ∂y_end/∂y0 (row-major), the time without driving-flank contact and with back-flank contact [s], the
    number of contact switches, the number of records written and a status (0 ok, 1 record arrays full, 2 non-finite
    state or chattering). With ``record`` the samples are written to the out_* arrays: ``samples`` equal sub-steps
    per interval (kind 0), contact switches (kind 1, the state after the switch), extrema of x (kind 2, ẋ = 0) and
    each interval's end with that interval's coefficients (kind 3, the left limit at the node).
    """
    n = nodes.size - 1
    period = nodes[n]
    m00, m01, m10, m11 = 1.0, 0.0, 0.0, 1.0
    x, v = x0, v0
    free_time = 0.0
    back_time = 0.0
    switches = 0
    count = 0
    capacity = out_time.size
    status = 0
    for q in range(periods):
        offset = q * period
        for i in range(n):
            t = nodes[i]
            t_end = nodes[i + 1]
            direction = _direction(i, x, v, pair_k, pair_e, back_k, back_e, backlash, force[i])
            stiffness, load, c, lower, upper, driving, back = _region(i, x, direction, pair_k, pair_e, back_k,
                                                                      back_e, backlash, damping[i], force[i], mode)
            sample = 0
            local_switches = 0
            sample_step = (t_end - t) / samples if record else 0.0
            while True:
                remaining = t_end - t
                h = remaining
                if stiffness > 0.0:
                    h = min(h, scan_fraction * 2.0 * np.pi * np.sqrt(mass / stiffness))
                reaches_end = h >= remaining
                x1, v1, p00, p01, p10, p11 = _advance(stiffness, c, load, mass, x, v, h)
                side = 0
                t_cross = h
                t_extremum = -1.0
                if (v > 0.0 and v1 < 0.0) or (v < 0.0 and v1 > 0.0):
                    t_extremum = _root(stiffness, c, load, mass, x, v, 0.0, h, 0.0, True)
                    xe, _, _, _, _, _ = _advance(stiffness, c, load, mass, x, v, t_extremum)
                    side = _crossing(x, xe, lower, upper)
                    if side != 0:
                        t_cross = _root(stiffness, c, load, mass, x, v, 0.0, t_extremum,
                                        upper if side > 0 else lower, False)
                    else:
                        side = _crossing(xe, x1, lower, upper)
                        if side != 0:
                            t_cross = _root(stiffness, c, load, mass, x, v, t_extremum, h,
                                            upper if side > 0 else lower, False)
                else:
                    side = _crossing(x, x1, lower, upper)
                    if side != 0:
                        t_cross = _root(stiffness, c, load, mass, x, v, 0.0, h, upper if side > 0 else lower, False)
                if side != 0:
                    x1, v1, p00, p01, p10, p11 = _advance(stiffness, c, load, mass, x, v, t_cross)
                    x1 = upper if side > 0 else lower
                if record:
                    while sample < samples and nodes[i] + sample * sample_step - t < t_cross:
                        local = nodes[i] + sample * sample_step - t
                        if count < capacity:
                            xs, vs, _, _, _, _ = _advance(stiffness, c, load, mass, x, v, local)
                            out_time[count] = offset + nodes[i] + sample * sample_step
                            out_x[count], out_v[count] = xs, vs
                            out_driving[count], out_back[count] = driving, back
                            out_interval[count], out_kind[count] = i, 0
                        count += 1
                        sample += 1
                    if 0.0 <= t_extremum < t_cross:
                        if count < capacity:
                            xs, vs, _, _, _, _ = _advance(stiffness, c, load, mass, x, v, t_extremum)
                            out_time[count] = offset + t + t_extremum
                            out_x[count], out_v[count] = xs, 0.0
                            out_driving[count], out_back[count] = driving, back
                            out_interval[count], out_kind[count] = i, 2
                        count += 1
                if driving == 0:
                    free_time += t_cross
                if back > 0:
                    back_time += t_cross
                n00 = p00 * m00 + p01 * m10
                n01 = p00 * m01 + p01 * m11
                m10 = p10 * m00 + p11 * m10
                m11 = p10 * m01 + p11 * m11
                m00, m01 = n00, n01
                x, v = x1, v1
                if not (math.isfinite(x) and math.isfinite(v)):
                    return x, v, m00, m01, m10, m11, free_time, back_time, switches, count, 2
                if side == 0:
                    if reaches_end:
                        break
                    t += h
                    continue
                t += t_cross
                switches += 1
                local_switches += 1
                if local_switches > _MAX_SWITCHES_PER_INTERVAL:
                    return x, v, m00, m01, m10, m11, free_time, back_time, switches, count, 2
                direction = _direction(i, x, v, pair_k, pair_e, back_k, back_e, backlash, force[i])
                c_before = c
                stiffness, load, c, lower, upper, driving, back = _region(i, x, direction, pair_k, pair_e, back_k,
                                                                          back_e, backlash, damping[i], force[i],
                                                                          mode)
                # saltation S = I + (f⁺ − f⁻)nᵀ/(nᵀf⁻) = [[1, 0], [−Δc/me, 1]] (module docstring)
                jump = -(c - c_before) / mass
                m10 += jump * m00
                m11 += jump * m01
                if record:
                    if count < capacity:
                        out_time[count] = offset + t
                        out_x[count], out_v[count] = x, v
                        out_driving[count], out_back[count] = driving, back
                        out_interval[count], out_kind[count] = i, 1
                    count += 1
            if record:
                if count < capacity:
                    out_time[count] = offset + t_end
                    out_x[count], out_v[count] = x, v
                    out_driving[count], out_back[count] = driving, back
                    out_interval[count], out_kind[count] = i, 3
                count += 1
    if count > capacity:
        status = 1
    return x, v, m00, m01, m10, m11, free_time, back_time, switches, count, status
