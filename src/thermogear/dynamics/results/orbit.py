"""The periodic orbit over one mesh period, as every periodic solver of a mesh problem returns it."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["PeriodicOrbit"]


@dataclass(frozen=True)
class PeriodicOrbit:
    """The periodic steady state over one mesh period.

    ``time`` [s] has ``samples_per_interval`` equal sub-steps per interval plus the end of the period T (where the
    state equals the initial state); ``interval`` gives the interval of each sample (right-continuous at nodes, the
    last sample belongs to the last interval). ``multipliers`` are the Floquet multipliers (complex), ``stable``
    is True when all lie inside the unit circle (always, for an orbit that was returned). For a mesh in a structure
    of n degrees of freedom ``displacement`` and ``velocity`` are those of the mesh deflection wᵀq and
    ``coordinates``, ``coordinate_velocities`` (samples, n) hold q and q̇ (None for the 1-DOF mesh).
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    multipliers: np.ndarray
    stable: bool
    initial_state: tuple[float, float]
    interval: np.ndarray
    method: str = "periodic"
    coordinates: np.ndarray | None = None
    coordinate_velocities: np.ndarray | None = None

    @property
    def multipliers_abs(self) -> np.ndarray:
        """Moduli of the Floquet multipliers, larger first."""
        return np.sort(np.abs(self.multipliers))[::-1]
