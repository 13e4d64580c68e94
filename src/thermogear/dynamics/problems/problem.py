"""The mesh-cycle equation of motion as data: me·ẍ + c(τ)·ẋ + k(τ)·x = w over one mesh period.

Luo & Li (2020) Eqs. (5)–(6). The coefficients are piecewise constant on the intervals
between ``nodes`` (the region transitions A..E of the mesh cycle are nodes). Everything is a total over the
face width (kg, N/m, N·s/m, N); the face width is kept only for per-width views of loads in metrics.

This module holds inputs and checks them; it has no solver logic (layer 2 of design.md).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermogear.dynamics.problems.mesh_period import MeshPeriod
from thermogear.dynamics.problems.structure import MeshStructure, checked_structure
from thermogear.errors import ProblemError

__all__ = ["STRUCTURE_FIELDS", "MeshDynamicsProblem", "MeshProblemBase", "region_name"]

_REGION_NAMES = {0: "no_contact", 1: "single", 2: "double", 3: "triple", 4: "quadruple"}


#: The structure's inputs of a mesh problem (:class:`MeshProblemBase`), by name.
STRUCTURE_FIELDS = ("mesh_vector", "structural_stiffness", "structural_damping", "structural_force")


def region_name(contact_count: int) -> str:
    """Name of a contact region from the number of tooth pairs in contact (1 → "single", 2 → "double")."""
    return _REGION_NAMES.get(int(contact_count), f"{int(contact_count)}_pairs")


def checked_array(name: str, value: object, shape: tuple[int, ...],
                  reason: str = "one value per interval between consecutive nodes") -> np.ndarray:
    """A read-only, contiguous float copy of a solver input of the given shape (a 1-D array is taken as one row
    where one row is asked for); ProblemError naming the quantity otherwise, or where it is not finite."""
    array = np.array(value, dtype=float, copy=True)
    if array.ndim == 1 and len(shape) == 2 and shape[0] == 1:
        array = array[None, :]
    if array.shape != shape:
        raise ProblemError(name, f"array of shape {array.shape}", f"shape {shape}", reason)
    if not np.all(np.isfinite(array)):
        raise ProblemError(name, f"{int(np.sum(~np.isfinite(array)))} non-finite values", "finite numbers",
                           "a NaN or infinite coefficient has no physical meaning")
    array = np.ascontiguousarray(array)
    array.setflags(write=False)
    return array



def checked_nodes(value: object) -> np.ndarray:
    """Read-only interval boundaries of one mesh period [s]: 1-D, finite, from 0, strictly increasing."""
    nodes = np.array(value, dtype=float, copy=True)
    if nodes.ndim != 1 or nodes.size < 2:
        raise ProblemError("nodes", f"array of shape {nodes.shape}", "1-D, at least 2 values",
                           "the nodes bound the intervals of one mesh period")
    if not np.all(np.isfinite(nodes)):
        raise ProblemError("nodes", "non-finite values", "finite times [s]", "a node time must be a number")
    if nodes[0] != 0.0:
        raise ProblemError("nodes[0]", float(nodes[0]), "0", "the mesh period starts at τ = 0")
    if np.any(np.diff(nodes) <= 0.0):
        raise ProblemError("nodes", "not strictly increasing", "strictly increasing times",
                           "each interval must have a positive length")
    nodes.setflags(write=False)
    return nodes


@dataclass(frozen=True)
class MeshProblemBase(MeshPeriod):
    """What the linear and the backlash mesh problem share: the structure's inputs and the input checks.

    The structure's inputs (keyword-only: a subclass's own fields come first in its ``__init__``) are w, K₀, C₀
    and f₀ of :class:`~.structure.MeshStructure`; ``structure`` holds them checked. A subclass has ``mass``
    (scalar or a mass matrix), ``nodes``, ``damping``, ``force`` and ``face_width``; each check below stores the
    checked, read-only value in place of the input.
    """

    mesh_vector: np.ndarray | None = field(default=None, kw_only=True)
    structural_stiffness: np.ndarray | None = field(default=None, kw_only=True)
    structural_damping: np.ndarray | None = field(default=None, kw_only=True)
    structural_force: np.ndarray | None = field(default=None, kw_only=True)
    structure: MeshStructure = field(init=False, repr=False, compare=False)
    _force_array: np.ndarray = field(init=False, repr=False, compare=False)

    def structure_fields(self) -> dict[str, object]:
        """The structure's inputs (mesh vector, structural matrices and loads) as keyword arguments."""
        return {name: getattr(self, name) for name in STRUCTURE_FIELDS}

    def _check_frame(self) -> int:
        """Check and store the structure (:func:`~.structure.checked_structure`), the mass (a float for the 1-DOF
        mesh) and the nodes; return the number of intervals n."""
        structure = checked_structure(self.mass, self.mesh_vector, self.structural_stiffness,
                                      self.structural_damping, self.structural_force)
        object.__setattr__(self, "structure", structure)
        object.__setattr__(self, "mass", float(structure.mass[0, 0]) if structure.is_scalar_mesh else structure.mass)
        nodes = checked_nodes(self.nodes)
        object.__setattr__(self, "nodes", nodes)
        return nodes.size - 1

    def _check_damping(self, n: int) -> None:
        """``damping`` (n,) [N·s/m], >= 0 on every interval."""
        damping = checked_array("damping", self.damping, (n,), "one damping value per interval")
        if np.any(damping < 0.0):
            raise ProblemError("damping", float(damping.min()), ">= 0 N·s/m", "negative damping injects energy")
        object.__setattr__(self, "damping", damping)

    def _check_force(self, n: int, positive: bool) -> None:
        """``force`` kept a float where it is one (a constant load) or checked as (n,) [N]; its per-interval values
        stored read-only as ``_force_array``; every value > 0 where ``positive``."""
        force_value = np.array(self.force, dtype=float)
        if force_value.ndim == 0:
            force_array = np.full(n, float(force_value))
            object.__setattr__(self, "force", float(force_value))
        else:
            force_array = checked_array("force", force_value, (n,), "one load per interval")
            object.__setattr__(self, "force", force_array)
        if not np.all(np.isfinite(force_array)):
            raise ProblemError("force", self.force, "finite [N]", "the static load must be a number")
        if positive and np.any(force_array <= 0.0):
            raise ProblemError("force", float(force_array.min()), "> 0 N",
                               "the mesh is modelled under a positive transmitted load")
        force_array.setflags(write=False)
        object.__setattr__(self, "_force_array", force_array)

    def _check_face_width(self) -> None:
        """``face_width`` b [m], finite and > 0."""
        face_width = float(self.face_width)
        if not np.isfinite(face_width) or face_width <= 0.0:
            raise ProblemError("face_width", self.face_width, "> 0 m", "used to express loads per unit face width")
        object.__setattr__(self, "face_width", face_width)


@dataclass(frozen=True)
class MeshDynamicsProblem(MeshProblemBase):
    """Linear time-periodic model of a gear mesh over one mesh period (Luo & Li Eqs. 5–6), alone or in a structure.

    The 1-DOF mesh me·ẍ + c(τ)·ẋ + k(τ)·x = w(τ) by default; with a mass matrix the mesh sits in a structure of n
    degrees of freedom, M q̈ + (C₀ + c(τ)·w wᵀ) q̇ + (K₀ + k(τ)·w wᵀ) q = f₀ + g(τ)·w (:mod:`~.structure`), where
    ``stiffness``, ``damping`` and ``force`` are the mesh's per-interval k, c and g and the displacement of the
    orbit is the mesh deflection wᵀq. The 1-DOF mesh is the 1×1 case, solved by the closed-form 2×2 kernels.

    Parameters
    ----------
    mass:
        Equivalent mass me [kg] (total over the face width), Eq. (5); or the (n, n) mass matrix M of a structure.
    nodes:
        (n+1,) interval boundaries [s], ``nodes[0] = 0``, ``nodes[-1] = T`` (the mesh period), strictly increasing.
    stiffness:
        (n,) mesh stiffness k on each interval [N/m], > 0.
    damping:
        (n,) mesh damping c on each interval [N·s/m], >= 0.
    force:
        Static normal load w [N]; scalar or (n,) per interval.
    contact_count:
        (n,) number of tooth pairs in contact on each interval (defines the regions: 1 single, 2 double).
    pair_stiffness, pair_damping:
        Optional (slots, n) stiffness [N/m] and damping [N·s/m] of each tooth pair slot (0 where out of contact).
        ``pair_stiffness`` must sum over slots to ``stiffness``. Without ``pair_damping`` the damping is shared
        in proportion to the pair stiffness when a pair load including the damping force is asked for.
    face_width:
        Face width b [m], only for per-width views of loads (N/mm) in metrics.
    pair_deviation:
        Optional (slots, n) unloaded deviation e_i of each pair [m] (positive: material missing). The equation is
        then me·ẍ + c·ẋ + Σ k_i·(x − e_i) = w, i.e. ``force`` = w + Σ k_i·e_i per interval, and a pair's load is
        k_i·(x − e_i); the static load w0 is ``force`` less that excitation.
    mesh_vector, structural_stiffness, structural_damping, structural_force:
        With a mass matrix: w (n,), K₀ and C₀ (n, n), f₀ (n,) of :class:`~.structure.MeshStructure` (defaults:
        K₀ = C₀ = 0, f₀ = 0; w is required for n > 1). ``structure`` holds them checked (also in the 1-DOF case).
    """

    mass: float
    nodes: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    force: float | np.ndarray
    contact_count: np.ndarray
    pair_stiffness: np.ndarray | None = None
    pair_damping: np.ndarray | None = None
    face_width: float = 1.0
    pair_deviation: np.ndarray | None = None

    def __post_init__(self) -> None:
        n = self._check_frame()
        stiffness = checked_array("stiffness", self.stiffness, (n,))
        if np.any(stiffness <= 0.0):
            raise ProblemError("stiffness", float(stiffness.min()), "> 0 N/m on every interval",
                            "the linear mesh model needs at least one pair in contact; zero stiffness is contact "
                            "loss, which this linear model does not represent")
        self._check_damping(n)
        self._check_force(n, positive=self.structure.is_scalar_mesh)
        contact = np.array(self.contact_count, copy=True)
        if contact.shape != (n,):
            raise ProblemError("contact_count", f"array of shape {contact.shape}", f"shape ({n},)",
                            "one pair count per interval")
        if not np.all(np.isfinite(contact.astype(float))) or np.any(contact != np.round(contact)) or np.any(contact < 1):
            raise ProblemError("contact_count", contact.tolist()[:8], "integers >= 1",
                            "the number of tooth pairs in contact on each interval")
        contact = contact.astype(np.int64)
        contact.setflags(write=False)
        object.__setattr__(self, "stiffness", stiffness)
        object.__setattr__(self, "contact_count", contact)
        if self.pair_stiffness is not None:
            pair_k = np.atleast_2d(np.array(self.pair_stiffness, dtype=float))
            pair_k = checked_array("pair_stiffness", pair_k, (pair_k.shape[0], n))
            if np.any(pair_k < 0.0):
                raise ProblemError("pair_stiffness", float(pair_k.min()), ">= 0 N/m", "0 marks a pair out of contact")
            total = pair_k.sum(axis=0)
            if not np.allclose(total, stiffness, rtol=1e-6, atol=0.0):
                worst = float(np.max(np.abs(total - stiffness) / stiffness))
                raise ProblemError("pair_stiffness", f"sum over pairs off by {worst:.3g} (relative)",
                                "sum over pairs equal to stiffness (rtol 1e-6)",
                                "pairs in contact act in parallel, so their stiffnesses add up to the mesh stiffness")
            object.__setattr__(self, "pair_stiffness", pair_k)
        if self.pair_damping is not None:
            if self.pair_stiffness is None:
                raise ProblemError("pair_damping", "given", "only together with pair_stiffness",
                                "pair loads need the pair stiffness")
            pair_c = np.atleast_2d(np.array(self.pair_damping, dtype=float))
            pair_c = checked_array("pair_damping", pair_c, self.pair_stiffness.shape)
            if np.any(pair_c < 0.0):
                raise ProblemError("pair_damping", float(pair_c.min()), ">= 0 N·s/m", "negative damping injects energy")
            object.__setattr__(self, "pair_damping", pair_c)
        if self.pair_deviation is not None:
            if self.pair_stiffness is None:
                raise ProblemError("pair_deviation", "given", "only together with pair_stiffness",
                                   "a deviation acts through its pair's stiffness")
            deviation = checked_array("pair_deviation", np.atleast_2d(np.array(self.pair_deviation, dtype=float)),
                                        self.pair_stiffness.shape)
            object.__setattr__(self, "pair_deviation", deviation)
        self._check_face_width()

    # ---------------------------------------------------------------- derived quantities
    @property
    def mesh_stiffness(self) -> np.ndarray:
        """(n,) mesh stiffness k on each interval [N/m] (the ``stiffness`` field)."""
        return self.stiffness

    @property
    def pair_offset(self) -> np.ndarray | None:
        """(slots, n) k_i·e_i [N]: what a pair's deviation takes off its load k_i·x; None without deviations."""
        if self.pair_deviation is None:
            return None
        return self.pair_stiffness * self.pair_deviation

    @property
    def system_offset(self) -> np.ndarray:
        """(n,) Σ k_i·e_i [N] (zeros without deviations): the mesh force is k·x + c·ẋ − Σ k_i·e_i."""
        offset = self.pair_offset
        return np.zeros(self.interval_count) if offset is None else offset.sum(axis=0)

    @property
    def static_load(self) -> float:
        """Time-mean static load w0 [N] (equals ``force`` for a constant load without deviations)."""
        return self.time_mean(self._force_array - self.system_offset)

    @property
    def static_transmission_error(self) -> np.ndarray:
        """(n,) static transmission error w/k on each interval [m] (the equilibria of the dynamic response).

        Only for the 1-DOF mesh: in a structure the equilibrium of the mesh deflection depends on K₀ and f₀."""
        if not self.structure.is_scalar_mesh:
            raise ProblemError("mass", "a mass matrix", "the 1-DOF mesh (scalar mass)",
                               "the static transmission error w/k is that of the 1-DOF mesh; solve the structure's "
                               "equilibrium instead")
        return self._force_array / self.stiffness

    @property
    def regions(self) -> tuple[int, ...]:
        """Distinct contact counts present, ascending."""
        return tuple(int(c) for c in np.unique(self.contact_count))

    def pair_arrays(self) -> tuple[np.ndarray, np.ndarray] | None:
        """(slots, n) pair stiffness and pair damping; damping shared in proportion to stiffness when not given."""
        if self.pair_stiffness is None:
            return None
        if self.pair_damping is not None:
            return self.pair_stiffness, self.pair_damping
        share = self.pair_stiffness / self.stiffness[None, :]
        return self.pair_stiffness, share * self.damping[None, :]

    # ---------------------------------------------------------------- constructors
    @classmethod
    def square_wave(cls, *, mass: float, mesh_period: float, contact_ratio: float, single_stiffness: float,
                    double_stiffness: float, single_damping: float, double_damping: float, force: float,
                    face_width: float = 1.0) -> MeshDynamicsProblem:
        """Two-level (square-wave) mesh stiffness of a spur pair with 1 < contact ratio < 2.

        One mesh period starts when a pair enters contact at A: double contact for (ε − 1)·T (A→B), single
        contact for (2 − ε)·T (B→D). Two pair slots: slot 0 is the pair that entered at A (half the double
        stiffness, then the whole single stiffness), slot 1 the pair that leaves at E (half the double stiffness,
        then out of contact). Meant for tests, benchmarks and quick studies; the gear chain builds its own.
        """
        if not 1.0 < contact_ratio < 2.0:
            raise ProblemError("contact_ratio", contact_ratio, "(1, 2)",
                            "the square wave alternates one double- and one single-contact region")
        t_double = (contact_ratio - 1.0) * mesh_period
        nodes = np.array([0.0, t_double, mesh_period])
        stiffness = np.array([double_stiffness, single_stiffness])
        damping = np.array([double_damping, single_damping])
        pair_stiffness = np.array([[0.5 * double_stiffness, single_stiffness], [0.5 * double_stiffness, 0.0]])
        pair_damping = np.array([[0.5 * double_damping, single_damping], [0.5 * double_damping, 0.0]])
        return cls(mass=mass, nodes=nodes, stiffness=stiffness, damping=damping, force=force,
                   contact_count=np.array([2, 1]), pair_stiffness=pair_stiffness, pair_damping=pair_damping,
                   face_width=face_width)
