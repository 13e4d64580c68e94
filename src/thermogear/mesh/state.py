"""The state of one mesh period at one operating point: what the dynamics solvers take from the mesh model."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.problem import MeshDynamicsProblem
from thermogear.errors import CaseError
from thermogear.mesh_cycle import MeshCycle, MeshGrid


@dataclass(frozen=True, eq=False)
class MeshState:
    """One mesh period of a model at a pinion speed and normal load, on the mesh-cycle grid (totals over the face).

    ``pair_stiffness``, ``pair_damping`` [N/m, N·s/m] and ``pair_deviation`` [m] are (slots, n) on the grid
    intervals, 0 where a pair slot is out of contact; ``mesh_damping`` c(τ) (n,) under the case's rule;
    ``normal_load`` w [N]; ``mass`` me [kg]; ``backlash`` the normal backlash [m] or None. ``pair_engaged``
    (slots, n): the pairs that carry load under the static load (on the path, and where they have deviations, the
    static approach beyond them); ``static_transmission_error`` (n,) the loaded static transmission error [m]
    where the pairs have deviations (None otherwise: it is then w/k(τ)).
    """

    model: str
    speed_rpm: float
    normal_load: float
    mass: float
    grid: MeshGrid
    pair_stiffness: np.ndarray
    pair_damping: np.ndarray
    mesh_damping: np.ndarray
    pair_deviation: np.ndarray
    pair_engaged: np.ndarray
    static_transmission_error: np.ndarray | None
    backlash: float | None
    face_width: float
    mesh_frequency_hz: float

    @property
    def period(self) -> float:
        """Mesh period T_m [s]."""
        return float(self.grid.nodes[-1])

    @property
    def mesh_stiffness(self) -> np.ndarray:
        """k(τ) [N/m] (n,): the pairs that carry load, in parallel."""
        return MeshCycle.total(self.pair_stiffness, self.pair_engaged)

    @property
    def mean_mesh_stiffness(self) -> float:
        """Time mean of k(τ) over one period [N/m]."""
        return float(self.grid.time_average(self.mesh_stiffness))

    @property
    def damping_ratio(self) -> float:
        """Mean damping ratio ζ = c̄ / (2·sqrt(k̄·me)) [–] of the period: time means of c(τ) and k(τ) (the viscous
        damping ratio of the mean oscillator, Den Hartog 1956 §2.6)."""
        stiffness = self.mean_mesh_stiffness
        if not stiffness > 0.0:
            return float("nan")
        return float(self.grid.time_average(self.mesh_damping)) / (2.0 * float(np.sqrt(stiffness * self.mass)))

    @property
    def excitation(self) -> np.ndarray:
        """Σ_i k_i·e_i (n,) [N] over the pairs that carry load: the force the unloaded deviations add to the static
        load in me·ẍ + c·ẋ + Σ k_i·(x − e_i) = w."""
        return MeshCycle.total(self.pair_stiffness * self.pair_deviation, self.pair_engaged)

    def problem(self) -> MeshDynamicsProblem:
        """The linear mesh-dynamics problem me·ẍ + c(τ)ẋ + k(τ)(x − e(τ)) = w over this period (the pairs that
        carry the static load; where the dynamic response would unload one, the nonlinear model is the one)."""
        excitation = self.excitation
        force = self.normal_load + excitation if np.any(excitation) else self.normal_load
        engaged = np.where(self.pair_engaged, self.pair_stiffness, 0.0)
        deviation = np.where(self.pair_engaged, self.pair_deviation, 0.0) if np.any(excitation) else None
        return MeshDynamicsProblem(mass=self.mass, nodes=self.grid.nodes, stiffness=self.mesh_stiffness,
                                   damping=self.mesh_damping, force=force, contact_count=self.pair_engaged.sum(axis=0),
                                   pair_stiffness=engaged, face_width=self.face_width, pair_deviation=deviation)

    def backlash_problem(self, damping_in_flight: str = "always") -> BacklashMeshProblem:
        """The nonlinear mesh-dynamics problem over this period: every pair on the path acts only while it touches,
        k_i⟨x − e_i⟩₊ on the driving flanks and −k_i⟨−x − j − e_i⟩₊ across the normal backlash j on the back flanks.

        The back flanks of the same teeth are taken with the driving flanks' stiffness and deviation at the same
        mesh position (symmetric teeth whose two lines of action carry the same mesh-stiffness cycle; the phase
        between the two cycles is neglected, which matters only where the teeth strike the back flanks).
        """
        if self.backlash is None:
            raise CaseError("dynamics.mesh", "nonlinear", "'linear', or a case whose backlash is known",
                            "the nonlinear mesh needs the normal backlash")
        stiffness = np.where(self.grid.in_contact, self.pair_stiffness, 0.0)
        deviation = np.where(self.grid.in_contact, self.pair_deviation, 0.0)
        return BacklashMeshProblem(mass=self.mass, nodes=self.grid.nodes, pair_stiffness=stiffness,
                                   pair_deviation=deviation, back_pair_stiffness=stiffness,
                                   back_pair_deviation=deviation, backlash=self.backlash, damping=self.mesh_damping,
                                   force=self.normal_load, damping_mode=damping_in_flight, face_width=self.face_width)


__all__ = ["MeshState"]
