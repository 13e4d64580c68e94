"""The nonsmooth (backlash, contact-loss) mesh equation of motion as data.

Per tooth-pair slot s, on each interval of the mesh period (coefficients piecewise constant between ``nodes``):

    me·ẍ + c_eff·ẋ + Σ_s k_s·⟨x − e_s⟩₊ − Σ_s k'_s·⟨−x − j − e'_s⟩₊ = w,      ⟨u⟩₊ = max(u, 0)

x is the dynamic transmission error along the line of action [m] (positive = approach of the driving flanks),
e_s the unloaded deviation of pair s on the driving flank [m] (positive = material missing: the pair engages
later), j the normal backlash [m] and k'_s, e'_s the stiffness and deviation of the back (coast) flank pair.
The dead-zone force law is that of Kahraman & Singh (1990), "Non-linear dynamics of a spur gear pair",
J. Sound Vib. 142(1):49–75, written here per tooth pair with the time-varying pair stiffness of the linear model.

Damping (``damping_mode``):

* ``"always"`` (default): c acts on ẋ at all times, also in free flight, as in Kahraman & Singh (1990). The oil
  squeezed out of the closing gap and the bearings and shafts that carry the gear bodies keep dissipating energy
  while the flanks are apart; the lumped c of a torsional model stands for all of them, not only for the contact.
  How large the in-flight share is, is not known in general; "always" is the usual modelling choice and keeps the
  vector field continuous (no saltation at a contact switch).
* ``"in_contact"``: c is scaled by the fraction of the pairs present on the interval that are in contact (driving
  or back flank), so it vanishes in free flight; the vector field then jumps at every contact switch.

This module holds inputs and checks them; it has no solver logic.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.problems.damping_modes import DAMPING_MODES
from thermogear.dynamics.problems.problem import STRUCTURE_FIELDS, MeshDynamicsProblem, MeshProblemBase, checked_array
from thermogear.errors import ProblemError

__all__ = ["DAMPING_MODES", "BacklashMeshProblem"]


@dataclass(frozen=True)
class BacklashMeshProblem(MeshProblemBase):
    """Torsional mesh model with contact loss and back-side contact over one mesh period.

    Parameters
    ----------
    mass:
        Equivalent mass me [kg]; or the (n, n) mass matrix M of a structure that holds the mesh (then x is the mesh
        deflection wᵀq, see :mod:`~.structure`; the 1-DOF solvers here refuse it).
    nodes:
        (n+1,) interval boundaries [s], ``nodes[0] = 0``, ``nodes[-1] = T`` (mesh period), strictly increasing.
    pair_stiffness:
        (slots, n) driving-flank stiffness k_s of each tooth-pair slot [N/m], >= 0 (0 = pair not in mesh).
    pair_deviation:
        (slots, n) unloaded deviation e_s of the driving flank [m] (positive = engages later).
    back_pair_stiffness, back_pair_deviation:
        (slots, n) the same for the back flank, k'_s [N/m] and e'_s [m].
    backlash:
        Normal backlash j [m], > 0 (j <= 0 is a jammed mesh, refused).
    damping:
        (n,) mesh damping c on each interval [N·s/m], >= 0.
    force:
        Static load w [N], scalar or (n,), > 0.
    damping_mode:
        ``"always"`` or ``"in_contact"`` (module docstring).
    face_width:
        Face width b [m], only for per-width views of loads.
    mesh_vector, structural_stiffness, structural_damping, structural_force:
        With a mass matrix: w, K₀, C₀, f₀ of :class:`~.structure.MeshStructure`, as in :class:`MeshDynamicsProblem`.
    """

    mass: float
    nodes: np.ndarray
    pair_stiffness: np.ndarray
    pair_deviation: np.ndarray
    back_pair_stiffness: np.ndarray
    back_pair_deviation: np.ndarray
    backlash: float
    damping: np.ndarray
    force: float | np.ndarray
    damping_mode: str = "always"
    face_width: float = 1.0

    def __post_init__(self) -> None:
        n = self._check_frame()
        stiffness = np.atleast_2d(np.array(self.pair_stiffness, dtype=float))
        shape = (stiffness.shape[0], n)
        per_pair = "one row per tooth-pair slot, one column per interval between nodes"
        stiffness = checked_array("pair_stiffness", stiffness, shape, per_pair)
        back_stiffness = checked_array("back_pair_stiffness", self.back_pair_stiffness, shape, per_pair)
        for name, array in (("pair_stiffness", stiffness), ("back_pair_stiffness", back_stiffness)):
            if np.any(array < 0.0):
                raise ProblemError(name, float(array.min()), ">= 0 N/m", "0 marks a pair out of mesh")
        if not np.any(stiffness > 0.0):
            raise ProblemError("pair_stiffness", "all zero", "some pair with k > 0",
                            "without any tooth pair the mesh transmits no load")
        object.__setattr__(self, "pair_stiffness", stiffness)
        object.__setattr__(self, "back_pair_stiffness", back_stiffness)
        object.__setattr__(self, "pair_deviation", checked_array("pair_deviation", self.pair_deviation, shape, per_pair))
        object.__setattr__(self, "back_pair_deviation",
                           checked_array("back_pair_deviation", self.back_pair_deviation, shape, per_pair))
        backlash = float(self.backlash)
        if not np.isfinite(backlash) or backlash <= 0.0:
            raise ProblemError("backlash", self.backlash, "> 0 m, finite",
                            "zero or negative backlash is a jammed mesh: both flanks would be loaded at once")
        object.__setattr__(self, "backlash", backlash)
        # the local clearance of slot s between the driving contact (x > e_s) and the back contact (x < −j − e'_s)
        clearance = backlash + self.pair_deviation + self.back_pair_deviation
        both = (stiffness > 0.0) & (back_stiffness > 0.0)
        if np.any(both & (clearance <= 0.0)):
            worst = float(np.min(np.where(both, clearance, np.inf)))
            raise ProblemError("backlash", backlash, f"> −(e_s + e'_s) for every pair (local clearance {worst:.3g} m)",
                            "a pair whose deviations close the backlash would touch both flanks at once (jammed); "
                            "a pitch-type error shifts the flanks together (e' = −e), thinning adds to both")
        self._check_damping(n)
        self._check_force(n, positive=True)
        if self.damping_mode not in DAMPING_MODES:
            raise ProblemError("damping_mode", self.damping_mode, " | ".join(DAMPING_MODES),
                            "damping acts always (default) or only in proportion to the pairs in contact")
        self._check_face_width()

    # ---------------------------------------------------------------- derived quantities
    @property
    def damping_contact_only(self) -> bool:
        """True where the damping acts only in proportion to the pairs in contact (its ``damping_mode``, resolved
        by :data:`~thermogear.dynamics.problems.damping_modes.DAMPING_MODES`)."""
        return DAMPING_MODES[self.damping_mode].contact_only

    @property
    def slot_count(self) -> int:
        """Number of tooth-pair slots."""
        return int(self.pair_stiffness.shape[0])

    @property
    def static_load(self) -> float:
        """Time-mean static load w0 [N] (the denominator of Kv, as in the linear metrics)."""
        return self.time_mean(self._force_array)

    @property
    def mesh_stiffness(self) -> np.ndarray:
        """(n,) driving-flank stiffness with every present pair in contact, Σ_s k_s [N/m]."""
        return self.pair_stiffness.sum(axis=0)

    @property
    def displacement_scale(self) -> float:
        """Largest static deflection w/Σk [m]: the scale of x for tolerances."""
        stiffness = self.mesh_stiffness
        present = stiffness > 0.0
        return float(np.max(self._force_array[present] / stiffness[present]))

    @property
    def velocity_scale(self) -> float:
        """displacement_scale times the largest natural angular frequency [m/s]."""
        return self.displacement_scale * float(np.sqrt(np.max(self.mesh_stiffness) / self.mesh_mass))

    def linear_problem(self) -> MeshDynamicsProblem | None:
        """The linear model with every present driving pair in contact (deviations folded into the load).

        Σ_s k_s·(x − e_s) = w  ⇔  (Σ_s k_s)·x = w + Σ_s k_s·e_s, so the linear problem has stiffness Σ_s k_s and
        load w + Σ_s k_s e_s. None when an interval has no pair or the folded load is not positive.
        """
        stiffness = self.mesh_stiffness
        if np.any(stiffness <= 0.0):
            return None
        load = self._force_array + np.sum(self.pair_stiffness * self.pair_deviation, axis=0)
        if np.any(load <= 0.0):
            return None
        contact = np.maximum(np.sum(self.pair_stiffness > 0.0, axis=0), 1)
        return MeshDynamicsProblem(mass=self.mass, nodes=self.nodes, stiffness=stiffness, damping=self.damping,
                                   force=load, contact_count=contact, pair_stiffness=self.pair_stiffness,
                                   face_width=self.face_width, **self.structure_fields())

    def with_changes(self, **changes: object) -> BacklashMeshProblem:
        """A copy with some fields replaced (checked again)."""
        values = {name: getattr(self, name) for name in
                  ("mass", "nodes", "pair_stiffness", "pair_deviation", "back_pair_stiffness", "back_pair_deviation",
                   "backlash", "damping", "force", "damping_mode", "face_width") + STRUCTURE_FIELDS}
        unknown = set(changes) - set(values)
        if unknown:
            raise ProblemError("with_changes", sorted(unknown), ", ".join(values), "unknown field")
        values.update(changes)
        return BacklashMeshProblem(**values)

    # ---------------------------------------------------------------- constructors
    @classmethod
    def from_linear(cls, problem: MeshDynamicsProblem, backlash: float, pair_deviation: object = 0.0,
                    back_pair_stiffness: object | None = None, back_pair_deviation: object | None = None,
                    damping_mode: str = "always") -> BacklashMeshProblem:
        """Build from a linear :class:`MeshDynamicsProblem` plus deviations and backlash.

        The pair stiffness is the problem's ``pair_stiffness`` (one slot carrying the whole ``stiffness`` when it
        has none). ``pair_deviation`` [m] is broadcast to (slots, n); the back flank defaults to the driving-flank
        stiffness and deviation (a symmetric tooth pair).
        """
        pair_stiffness = (problem.pair_stiffness if problem.pair_stiffness is not None
                          else problem.stiffness[None, :])
        shape = pair_stiffness.shape
        try:
            deviation = np.broadcast_to(np.asarray(pair_deviation, dtype=float), shape)
        except ValueError:
            raise ProblemError("pair_deviation", f"shape {np.shape(pair_deviation)}", f"broadcastable to {shape}",
                            "one deviation per tooth-pair slot and interval") from None
        back_k = pair_stiffness if back_pair_stiffness is None else back_pair_stiffness
        back_e = deviation if back_pair_deviation is None else back_pair_deviation
        return cls(mass=problem.mass, nodes=problem.nodes, pair_stiffness=pair_stiffness, pair_deviation=deviation,
                   back_pair_stiffness=back_k, back_pair_deviation=back_e, backlash=backlash,
                   damping=problem.damping, force=problem.force, damping_mode=damping_mode,
                   face_width=problem.face_width,
                   **problem.structure_fields())
