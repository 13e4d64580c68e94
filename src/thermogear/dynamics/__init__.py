"""Mesh dynamics that know nothing of gears: me·ẍ + c(τ)·ẋ + k(τ)·x = w over one mesh period.

* :class:`MeshDynamicsProblem` — the equation as data (piecewise-constant coefficients on a node grid).
* :func:`periodic_steady_state` — exact periodic orbit by the monodromy matrix (Floquet multipliers reported);
  :func:`periodic_steady_state_batch` and :func:`~thermogear.dynamics.periodic_batch_metrics.periodic_metrics_batch`
  (states and orbit metrics of many points at once) for sweeps, on the same closed-form kernels.
* :func:`transient_from_rest` — numba RK4 from rest, steps aligned to the nodes.
* :func:`reference_solve_ivp` — SciPy reference (tests, benchmarks).
* :class:`DynamicResponse` — x(τ), ẋ(τ), loads, metrics (Kv, Eq. 29), spectra, plots, netCDF.
"""

from __future__ import annotations

from thermogear.dynamics.periodic import PeriodicOrbit, evaluate_orbit, floquet_multipliers, periodic_steady_state
from thermogear.dynamics.periodic_batch import periodic_steady_state_batch
from thermogear.dynamics.problem import MeshDynamicsProblem, region_name
from thermogear.dynamics.reference import reference_solve_ivp
from thermogear.dynamics.response import (DynamicResponse, compute_metrics, response_from_orbit,
                                          response_from_transient)
from thermogear.dynamics.transient import (TransientHistory, largest_safe_step, transient_from_rest,
                                           transient_python)

__all__ = ["DynamicResponse", "MeshDynamicsProblem", "compute_metrics", "response_from_orbit",
           "response_from_transient", "PeriodicOrbit", "TransientHistory", "evaluate_orbit", "floquet_multipliers",
           "largest_safe_step", "periodic_steady_state", "periodic_steady_state_batch", "reference_solve_ivp",
           "region_name", "transient_from_rest", "transient_python"]
