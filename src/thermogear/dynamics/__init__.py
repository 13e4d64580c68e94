"""Mesh dynamics that know nothing of gears: me·ẍ + c(τ)·ẋ + k(τ)·x = w over one mesh period.

* :class:`MeshDynamicsProblem` — the equation as data (piecewise-constant coefficients on a node grid).
* :func:`periodic_steady_state` — exact periodic orbit by the monodromy matrix (Floquet multipliers reported);
  :func:`periodic_steady_state_batch` and
  :func:`~thermogear.dynamics.periodic_orbits.periodic_batch_metrics.periodic_metrics_batch` (states and orbit metrics
  of many points at once) for sweeps, on the same closed-form kernels.
* :func:`transient_from_rest` — numba RK4 from rest, steps aligned to the nodes.
* :func:`reference_solve_ivp` — SciPy reference (tests, benchmarks).
* :class:`DynamicResponse` — x(τ), ẋ(τ), loads, metrics (Kv, Eq. 29), spectra, plots, netCDF.
"""

from __future__ import annotations

#: Public name -> the module that defines it, imported when first asked for (PEP 562): importing one solver module
#: (e.g. the registry of solution methods the case schema reads) does not compile or load every kernel.
_PUBLIC = {"PeriodicOrbit": "periodic_orbits.periodic", "evaluate_orbit": "periodic_orbits.periodic",
           "floquet_multipliers": "periodic_orbits.periodic", "periodic_steady_state": "periodic_orbits.periodic",
           "periodic_steady_state_batch": "periodic_orbits.periodic_batch", "MeshDynamicsProblem": "problems.problem",
           "region_name": "problems.problem", "reference_solve_ivp": "transients.reference",
           "DynamicResponse": "response", "compute_metrics": "response", "response_from_orbit": "response",
           "response_from_transient": "response", "TransientHistory": "transients.transient",
           "largest_safe_step": "transients.transient", "transient_from_rest": "transients.transient",
           "transient_python": "transients.transient"}

__all__ = sorted(_PUBLIC)


def __getattr__(name: str):
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    import importlib

    return getattr(importlib.import_module(f"{__name__}.{_PUBLIC[name]}"), name)
