"""The textbook single-mesh backlash oscillator of the backlash tests (Kahraman & Singh 1990 type).

me = 1 kg, mean stiffness k0 = 1e8 N/m (ω_n = 1e4 rad/s), w = 1e3 N (static deflection x_st = 10 μm), stiffness
k0·(1 + ε·cos 2πτ/T) and a transmission-error excitation e(τ) = a·x_st·sin 2πτ/T on the driving flank, e' = −e on
the back flank (a pitch-type error shifts both flanks together, so the local clearance stays j), all piecewise
constant on ``n`` equal intervals. The mesh frequency ratio Ω = ω_m/ω_n plays the speed.
"""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem

MASS, K0, FORCE = 1.0, 1e8, 1e3
X_STATIC = FORCE / K0


def textbook_problem(ratio, zeta, eps=0.1, deviation=0.1, backlash=1.0, n=32, mode="always"
                     ) -> BacklashMeshProblem:
    """``ratio`` = mesh over natural circular frequency; ``deviation``, ``backlash`` in static deflections;
    ``zeta`` the damping ratio."""
    period = 2.0 * np.pi / (ratio * np.sqrt(K0 / MASS))
    tau = (np.arange(n) + 0.5) / n
    stiffness = K0 * (1.0 + eps * np.cos(2.0 * np.pi * tau))
    error = deviation * X_STATIC * np.sin(2.0 * np.pi * tau)
    return BacklashMeshProblem(mass=MASS, nodes=np.linspace(0.0, period, n + 1), pair_stiffness=stiffness[None],
                               pair_deviation=error[None], back_pair_stiffness=stiffness[None],
                               back_pair_deviation=-error[None], backlash=backlash * X_STATIC,
                               damping=np.full(n, 2.0 * zeta * np.sqrt(K0 * MASS)), force=FORCE, damping_mode=mode)
