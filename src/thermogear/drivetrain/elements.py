"""The one interface of a drivetrain's structure elements, and the shaft element placed on its two nodes.

Every element — a shaft element, a rigid disk, a bearing, a coupling, a torsional support, a gear mesh — sits on
one or more shaft nodes (``locations``, 6 DOF each: x, y, z, α, β, θ) and gives, on those nodes' DOFs:

- ``mass_matrix()``, ``stiffness_matrix()``, ``damping_matrix()`` [SI] and ``gyroscopic_matrix()`` per unit spin
  speed of its shaft (``spin_shaft``; multiplied by that shaft's speed ratio × Ω in the assembly, Friswell, Penny,
  Garvey & Lees, Dynamics of Rotating Machines, CUP 2010, Eq. 5.88: M q̈ + (C + ΩG) q̇ + K q = f);
- ``dead_zones()``: its state-dependent law where it has one, as dead zones on its local DOFs
  (:class:`~thermogear.dynamics.backlash.backlash_ndof.DeadZone`: a bearing's radial clearance, one per direction x, y);
- ``mesh_vector()``: the vector w of a time-varying (mesh) stiffness k(τ)·w wᵀ on its DOFs, None for a constant
  element; a mesh's stiffness, damping, excitation and backlash come from its mesh state, so its constant matrices
  hold only what no state changes (a helical spread contact's tilting stiffness and damping) and its dead zone (the backlash) is built with the state's width;
- ``energy_group``: the name under which its strain energy is reported (a shaft's elements share the shaft's
  name; None for an element without stiffness).

:meth:`~thermogear.drivetrain.assembly.Drivetrain.assemble` is one loop over the elements; a new element is one
class with these members (:class:`StructureElement`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, runtime_checkable

import numpy as np

from thermogear.drivetrain.shaft_element import ShaftElement

if TYPE_CHECKING:
    from thermogear.dynamics.backlash.backlash_ndof import DeadZone

__all__ = ["PlacedShaftElement", "StructureElement", "zero_matrix"]


@runtime_checkable
class StructureElement(Protocol):
    """What the assembly asks of an element (module docstring)."""

    @property
    def locations(self) -> tuple:
        """The nodes it sits on, in the order of its matrices' DOF blocks."""

    @property
    def spin_shaft(self) -> str:
        """The shaft whose spin speed multiplies its gyroscopic matrix."""

    @property
    def energy_group(self) -> str | None:
        """The name its strain energy is reported under (None: no stiffness)."""

    def mass_matrix(self) -> np.ndarray:
        """(6m, 6m) mass on its m nodes [SI]."""

    def stiffness_matrix(self) -> np.ndarray:
        """(6m, 6m) constant stiffness [SI]."""

    def damping_matrix(self) -> np.ndarray:
        """(6m, 6m) constant damping [SI]."""

    def gyroscopic_matrix(self) -> np.ndarray:
        """(6m, 6m) skew gyroscopic matrix per unit spin speed [SI]."""

    def dead_zones(self) -> tuple[DeadZone, ...]:
        """Its dead zones on its local DOFs (vectors of length 6m); () where it is linear."""

    def mesh_vector(self) -> np.ndarray | None:
        """w (6m,) of a time-varying stiffness k(τ)·w wᵀ, or None."""


def zero_matrix(nodes: int = 1) -> np.ndarray:
    """The (6m, 6m) zero matrix of an element on m nodes."""
    return np.zeros((6 * nodes, 6 * nodes))


@dataclass(frozen=True)
class PlacedShaftElement:
    """A Timoshenko :class:`~thermogear.drivetrain.shaft_element.ShaftElement` between two consecutive nodes of its
    shaft, with the shaft's stiffness-proportional material damping β [s] (C = β·K)."""

    shaft: str
    first: object  # NodeLocation (point_elements), not imported: point_elements imports this module
    second: object
    element: ShaftElement
    material_damping: float = 0.0

    @property
    def locations(self) -> tuple:
        """Its two nodes."""
        return (self.first, self.second)

    @property
    def spin_shaft(self) -> str:
        """Its shaft."""
        return self.shaft

    @property
    def energy_group(self) -> str:
        """The shaft's name: a shaft's strain energy is reported whole."""
        return self.shaft

    def mass_matrix(self) -> np.ndarray:
        """12×12 consistent mass."""
        return self.element.mass()

    def stiffness_matrix(self) -> np.ndarray:
        """12×12 stiffness."""
        return self.element.stiffness()

    def damping_matrix(self) -> np.ndarray:
        """β·K (12×12)."""
        return self.material_damping * self.element.stiffness()

    def gyroscopic_matrix(self) -> np.ndarray:
        """12×12 gyroscopic per unit spin."""
        return self.element.gyroscopic()

    def dead_zones(self) -> tuple:
        """None: the shaft is linear."""
        return ()

    def mesh_vector(self) -> None:
        """None: constant stiffness."""
        return None
