"""What every mesh-dynamics problem over one mesh period derives from its nodes, mass, load and stiffness."""

from __future__ import annotations

from operator import attrgetter

import numpy as np

__all__ = ["MeshPeriod"]


class MeshPeriod:
    """Derived quantities of a problem over one mesh period (mixin of the linear and the backlash problem).

    The problem provides ``nodes`` (n+1,) [s], ``structure`` (its mass matrix and mesh vector), ``_force_array``
    (n,) [N], ``damping`` (n,) [N·s/m] and ``mesh_stiffness`` (n,) [N/m], the stiffness with every pair present in
    contact.
    """

    # the structure's, :class:`~thermogear.dynamics.problems.structure.MeshStructure`
    degrees_of_freedom = property(attrgetter("structure.degrees_of_freedom"),
                                  doc="Number of degrees of freedom n of the structure (1 for the 1-DOF mesh).")
    mesh_mass = property(attrgetter("structure.mesh_mass"), doc="Equivalent mass of the mesh deflection [kg]: me "
                         "for the 1-DOF mesh, 1/(wᵀM⁻¹w) in a structure.")

    @property
    def interval_count(self) -> int:
        """Number of intervals n."""
        return int(self.nodes.size - 1)

    @property
    def durations(self) -> np.ndarray:
        """(n,) interval lengths [s]."""
        return np.diff(self.nodes)

    @property
    def period(self) -> float:
        """Mesh period T [s]."""
        return float(self.nodes[-1])

    @property
    def mesh_frequency(self) -> float:
        """Mesh frequency f_m = 1/T [Hz]."""
        return 1.0 / self.period

    @property
    def force_per_interval(self) -> np.ndarray:
        """(n,) static load w on each interval [N]."""
        return self._force_array

    def time_mean(self, values) -> float:
        """Time mean over the period of a quantity constant on each interval."""
        return float(np.dot(np.asarray(values, dtype=float), self.durations) / self.period)

    @property
    def mean_stiffness(self) -> float:
        """Time-mean mesh stiffness over one period [N/m]."""
        return self.time_mean(self.mesh_stiffness)

    @property
    def mean_decay_rate(self) -> float:
        """Time-mean decay rate of free vibrations c̄/(2·me) [1/s]: the exponent σ of e^(−σt) of the mean viscous
        oscillator (Den Hartog 1956 §2.6), with c̄ the time mean of the mesh damping over the period and me the mesh
        mass. The problem provides ``damping`` (n,) [N·s/m]."""
        return self.time_mean(self.damping) / (2.0 * self.mesh_mass)

    @property
    def natural_frequency(self) -> float:
        """Natural frequency f_n = sqrt(mean k / me) / 2π [Hz] (from the time-mean stiffness; me is the mesh mass, so
        in a structure this is the mesh mode on rigid surroundings, a scale for the frequency ratio)."""
        return float(np.sqrt(self.mean_stiffness / self.mesh_mass) / (2.0 * np.pi))

    @property
    def frequency_ratio(self) -> float:
        """Frequency ratio λ = f_m / f_n [-] (Luo & Li's 0.153)."""
        return self.mesh_frequency / self.natural_frequency
