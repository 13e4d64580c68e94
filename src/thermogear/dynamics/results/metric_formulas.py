"""The formulas of the period metrics, each written once as a plain function of numbers (or NumPy arrays) that the
Python metrics call and the compiled sweep kernel compiles with numba
(:mod:`thermogear.dynamics.periodic_orbits.periodic_batch_metrics`), so the fast path and the single-point solver
share one definition (issue 33: each metric defined once; a test holds their results equal):

* :func:`mesh_load` — the mesh (or pair) load k·x − k·e + c·ẋ [N] of the linear mesh (Luo & Li 2020 Eq. 28 with the
  damping force, or k·x without it);
* :func:`mean_and_rms` — the time mean of the transmission error and its RMS about the mean, from the time integrals
  of x − s and (x − s)² over the record, s any shift (the kernel walks the orbit once about its start, the
  Python path integrates about the trapezoidal mean, where the first integral is zero);
* :func:`peak_to_peak` — the largest minus the smallest transmission error [m].

The dynamic factor Kv = max pair load / w0 is :func:`thermogear.dynamics.results.period_metrics.dynamic_factor`.
Nothing here imports numba: a function compiled by the kernel stays a plain function for every other caller.
"""

from __future__ import annotations

import math

__all__ = ["mean_and_rms", "mesh_load", "peak_to_peak"]


def mesh_load(stiffness, displacement, damping, velocity, offset=0.0):
    """The load k·x − k·e + c·ẋ [N] of a spring ``stiffness`` k [N/m] and dashpot ``damping`` c [N·s/m] at the
    ``displacement`` x [m] and ``velocity`` ẋ [m/s]; ``offset`` k·e [N] the load of a deviation e (0: none). Without
    the damping force pass c = 0 (then the load is k·x − k·e exactly)."""
    return stiffness * displacement - offset + damping * velocity


def mean_and_rms(shift, first_moment, second_moment, span):
    """(the time mean [m], the RMS about it [m]) of a signal x(t) over ``span`` T [s] from its integrals
    ``first_moment`` ∫(x − s) dt [m·s] and ``second_moment`` ∫(x − s)² dt [m²·s] about a ``shift`` s [m]:
    mean = s + ∫(x − s)dt/T, RMS = √(∫(x − s)²dt/T − (∫(x − s)dt/T)²) (the variance's shift theorem; the rounding
    that makes it a hair negative for a constant signal read as 0)."""
    mean_shift = first_moment / span
    variance = max(second_moment / span - mean_shift * mean_shift, 0.0)
    return shift + mean_shift, math.sqrt(variance)


def peak_to_peak(largest, smallest):
    """The peak-to-peak value [unit of the signal] of a signal whose extremes are ``largest`` and ``smallest``."""
    return largest - smallest
