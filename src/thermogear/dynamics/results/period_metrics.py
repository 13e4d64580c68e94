"""The metrics every periodic response reports, each defined once and used by every solver's metrics: the linear
period (:func:`thermogear.dynamics.results.metrics.compute_metrics`, 1-DOF or in a structure), the 1-DOF backlash orbit
(:func:`thermogear.dynamics.backlash.backlash_metrics.orbit_metrics`) and the drivetrain's period with backlash
(:func:`thermogear.drivetrain.sampled_period.sampled_metrics`).

* loads: the static load w0 [N]; Kv = max pair load / w0 (Luo & Li 2020 Eq. 29, :func:`dynamic_factor`) and the
  basis it was read on; the largest mesh (system) load; each also per unit face width [N/mm];
* DTE statistics of the transmission error x(t) over the record: time mean and RMS about it (trapezoidal rule,
  :func:`~thermogear.dynamics.results.spectra.time_mean_and_rms`), peak-to-peak (the formulas in
  :mod:`thermogear.dynamics.results.metric_formulas`, which the compiled sweep kernel compiles);
* contact times: the fractions of the record without driving-flank contact and on the back flanks, the switches
  per mesh period;
* the mesh and natural frequencies of the problem and the moduli of the Floquet multipliers, largest first.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.dynamics.results.metric_formulas import peak_to_peak
from thermogear.dynamics.results.spectra import time_mean_and_rms

__all__ = ["KV_ON_PAIR_LOADS", "KV_ON_SINGLE_CONTACT", "KV_UNAVAILABLE", "contact_loss_summary", "contact_time_metrics", "dte_statistics",
           "dynamic_factor", "frequency_metrics", "load_metrics", "multiplier_moduli",
           "pair_load_maximum"]

#: The bases Kv is read on (``metrics["kv_basis"]``): the pair loads where the pair stiffness is known, else the
#: mesh load in single contact (one pair carries it all), else none.
KV_ON_PAIR_LOADS = "pair_loads"
KV_ON_SINGLE_CONTACT = "system_load_in_single_contact"
KV_UNAVAILABLE = "unavailable: no pair stiffness and no single-contact interval"


def dynamic_factor(max_pair_load, static_load):
    """The dynamic load factor Kv = 1 + Δw/w0 = max pair load / w0 [-] (Luo & Li 2020 Eq. 29: Δw the largest
    single-pair dynamic load above the static load w0), of floats or arrays [N]: the one definition every response
    (1-DOF pair linear or backlash, drivetrain, sweep fast path) uses."""
    return max_pair_load / static_load


def load_metrics(static_load: float, face_width: float, max_pair: float | None, basis: str,
                 max_system: float) -> dict[str, Any]:
    """The load metrics of a period: w0 [N], Kv on ``basis`` (None without a pair load), the largest pair and mesh
    loads [N], each also per unit face width b [m] in N/mm, and the largest mesh load over w0."""
    return {"static_load": static_load, "static_load_n_per_mm": static_load / face_width / 1e3,
            "kv": None if max_pair is None else dynamic_factor(max_pair, static_load), "kv_basis": basis,
            "max_pair_load": max_pair,
            "max_pair_load_n_per_mm": None if max_pair is None else max_pair / face_width / 1e3,
            "max_system_load": max_system, "max_system_load_n_per_mm": max_system / face_width / 1e3,
            "max_system_load_ratio": max_system / static_load}


def pair_load_maximum(pair_loads: np.ndarray | None, single_contact_loads: np.ndarray | None
                      ) -> tuple[float | None, str]:
    """(the largest pair load [N] Kv is read from, its basis): over the ``pair_loads`` where the pair stiffness is
    known, else over the mesh loads in single contact (one pair carries the whole mesh load), else (None, why)."""
    if pair_loads is not None:
        return float(np.max(pair_loads)), KV_ON_PAIR_LOADS
    if single_contact_loads is not None:
        return float(np.max(single_contact_loads)), KV_ON_SINGLE_CONTACT
    return None, KV_UNAVAILABLE


def dte_statistics(time: np.ndarray, displacement: np.ndarray, span: float | None = None) -> dict[str, float]:
    """``dte_mean``, ``dte_rms`` (about the mean) and ``dte_peak_to_peak`` [m] of the transmission error sampled at
    increasing ``time`` [s]; the mean and RMS over ``span`` [s], the record's unless given
    (:func:`~thermogear.dynamics.results.spectra.time_mean_and_rms`)."""
    mean, rms = time_mean_and_rms(time, displacement, span)
    return {"dte_mean": mean, "dte_rms": rms,
            "dte_peak_to_peak": float(peak_to_peak(np.max(displacement), np.min(displacement)))}


def frequency_metrics(problem) -> dict[str, float]:
    """The problem's natural and mesh frequencies [Hz] and their ratio λ = f_m / f_n [-]
    (:class:`~thermogear.dynamics.problems.mesh_period.MeshPeriod`)."""
    return {"natural_frequency_hz": problem.natural_frequency, "mesh_frequency_hz": problem.mesh_frequency,
            "frequency_ratio": problem.frequency_ratio}


def multiplier_moduli(multipliers) -> np.ndarray:
    """|μ| of the Floquet multipliers, largest first."""
    return np.sort(np.abs(np.asarray(multipliers)))[::-1]


def contact_loss_summary(detected: bool, start_times: list[float], durations: list[float], total_duration: float,
                         min_force: float, static_load: float) -> dict[str, Any]:
    """The contact loss of a period (``metrics["contact_loss"]``): whether it was ``detected``, the ``start_times``
    [s] and ``durations`` [s] of its runs, their ``total_duration`` per mesh period [s], the smallest mesh force [N]
    and its ratio to the static load w0 [N]."""
    return {"detected": bool(detected), "start_times": start_times, "durations": durations,
            "total_duration": float(total_duration), "min_force": float(min_force),
            "min_force_ratio": float(min_force / static_load)}


def contact_time_metrics(free_flight_time: float, back_contact_time: float, switches: int, span: float,
                         periods: int, back_side_contact: bool) -> dict[str, Any]:
    """The contact times of a record ``span`` [s] long over ``periods`` mesh periods: the fractions of it without
    driving-flank contact (``contact_loss_fraction``) and on the back flanks, whether a back flank touched, and the
    contact switches per mesh period."""
    return {"contact_loss_fraction": float(free_flight_time / span), "back_side_contact": bool(back_side_contact),
            "back_contact_fraction": float(back_contact_time / span),
            "switches_per_period": float(switches / periods)}
