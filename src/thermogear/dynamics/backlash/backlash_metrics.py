"""Metrics of a backlash-model orbit: contact loss, back-side contact, mesh and pair forces, Kv, DTE statistics.

Definitions (those of every response, :mod:`thermogear.dynamics.results.period_metrics`, where they mean the same):

* mesh force F = Σ_s k_s⟨x − e_s⟩₊ − Σ_s k'_s⟨−x − j − e'_s⟩₊ [N] (back-flank contact counts negative);
  pair force of driving slot s: k_s⟨x − e_s⟩₊ [N]. With ``include_damping_force`` the damping force c_eff·ẋ is
  added to F and shared among the driving pairs in contact in proportion to their stiffness;
* Kv = max pair force / w0, w0 the time-mean static load (Luo & Li 2020 Eq. 29: Kv = 1 + Δw/w0 with
  Δw = max single-pair dynamic load − w0, as the linear ``compute_metrics``);
* ``contact_loss_fraction``: fraction of the orbit's time with no driving-flank pair in contact (exact, summed by
  the integrator over the pieces between switches); ``back_side_contact``: a back-flank pair touched;
* DTE mean, RMS about the mean and peak-to-peak of x over the orbit [m]; the DTE spectrum (one-sided harmonic
  amplitudes at j/(N·T), so the mesh harmonics are every N-th line of an N-period orbit).

The history holds the grid samples, every contact switch, every extremum of x and both one-sided limits at the
nodes; the forces are monotone in x between these points, so their maxima are exact.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.dynamics.backlash.backlash_periodic import BacklashHistory, BacklashOrbit
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.results.period_metrics import contact_time_metrics, dte_statistics, dynamic_factor
from thermogear.dynamics.results.spectra import harmonic_spectrum

__all__ = ["dte_spectrum", "history_forces", "orbit_metrics"]


def history_forces(problem: BacklashMeshProblem, history: BacklashHistory, include_damping_force: bool = False
                   ) -> tuple[np.ndarray, np.ndarray]:
    """Mesh force F [N] and (slots, samples) driving-pair forces [N] at every record of ``history``."""
    x, v, i = history.displacement, history.velocity, history.interval
    stiffness = problem.pair_stiffness[:, i]
    driving = stiffness * np.maximum(x[None, :] - problem.pair_deviation[:, i], 0.0)
    back = problem.back_pair_stiffness[:, i] * np.maximum(-x[None, :] - problem.backlash
                                                          - problem.back_pair_deviation[:, i], 0.0)
    total = driving.sum(axis=0) - back.sum(axis=0)
    if include_damping_force:
        damping = problem.damping[i].copy()
        if problem.damping_contact_only:
            present = np.maximum(np.sum(stiffness > 0.0, axis=0), 1)
            touching = history.driving_contacts + history.back_contacts
            damping = damping * np.minimum(1.0, touching / present)
        damping_force = damping * v
        total = total + damping_force
        active = stiffness * (x[None, :] > problem.pair_deviation[:, i])
        share = np.divide(active, active.sum(axis=0), out=np.zeros_like(active), where=active.sum(axis=0) > 0.0)
        driving = driving + share * damping_force[None, :]
    return total, driving


def dte_spectrum(orbit: BacklashOrbit, points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
    """Harmonic amplitudes of x over the orbit's N periods: (frequencies j/(N·T) [Hz], amplitudes [m])."""
    history = orbit.history
    return harmonic_spectrum(history.time, history.displacement, history.time[-1], points)


def orbit_metrics(orbit: BacklashOrbit, include_damping_force: bool = False, harmonics: int = 8) -> dict[str, Any]:
    """Metrics of an orbit (module docstring). A non-periodic response gets them over its recorded periods."""
    problem, history = orbit.problem, orbit.history
    total, pairs = history_forces(problem, history, include_damping_force)
    w0 = problem.static_load
    span = history.time[-1] - history.time[0]
    max_pair = float(np.max(pairs))
    frequencies, amplitudes = dte_spectrum(orbit)
    mesh_lines = amplitudes[::orbit.period_count][: harmonics + 1]
    return {
        "response": orbit.response,
        "period_count": int(orbit.period_count),
        "converged": bool(orbit.converged),
        "residual": float(orbit.residual),
        "largest_multiplier": float(orbit.largest_multiplier),
        "static_load": w0,
        **contact_time_metrics(history.free_flight_time, history.back_contact_time, history.switch_times.size,
                               span, history.periods,
                               history.back_contact_time > 0.0 or np.any(history.back_contacts > 0)),
        "max_mesh_force": float(np.max(total)),
        "min_mesh_force": float(np.min(total)),
        "max_pair_force": max_pair,
        "kv": dynamic_factor(max_pair, w0),
        "max_mesh_force_ratio": float(np.max(total)) / w0,
        **dte_statistics(history.time, history.displacement),
        "dte_mesh_harmonics": [float(a) for a in mesh_lines],
        "dte_spectrum_base_frequency": float(frequencies[1]) if frequencies.size > 1 else float("nan"),
    }
