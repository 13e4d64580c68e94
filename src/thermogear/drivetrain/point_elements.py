"""Rigid disks, bearings and couplings: the lumped elements that sit at shaft nodes (6 DOF: x, y, z, α, β, θ).

Rigid disk: mass matrix diag(m, m, m, I_d, I_d, I_p) and gyroscopic block G[α, β] = +I_p, G[β, α] = −I_p per unit
spin speed, from the angular momentum of a disk spinning about a tilted axis (Friswell, Penny, Garvey & Lees,
Dynamics of Rotating Machines, CUP 2010, §5.3: I_d α̈ + I_pΩβ̇ = M_x, I_d β̈ − I_pΩα̇ = M_y). Annulus of bore d_i,
outer diameter d_o and width b: m = ρπb(d_o² − d_i²)/4, I_p = m(d_o² + d_i²)/8, I_d = I_p/2 + m b²/12.
Bearing: linear springs and dashpots from a node to ground on x, y (and z); coupling: springs and dashpots between
two nodes, [[K, −K], [−K, K]] (Friswell et al. 2010 §5.5).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from typing import TYPE_CHECKING

import numpy as np

from thermogear.drivetrain.elements import zero_matrix
from thermogear.errors import CaseError

if TYPE_CHECKING:
    from thermogear.dynamics.backlash.backlash_ndof import DeadZone

__all__ = ["NodeLocation", "OneNodeElement", "RigidDisk", "Bearing", "Coupling", "TorsionalSupport"]


class OneNodeElement:
    """The members of the element interface (:mod:`thermogear.drivetrain.elements`) shared by the elements that
    sit on one node (``location``): no mass, stiffness, damping, gyroscopic matrix, dead zone or mesh vector unless
    the element gives its own."""

    @property
    def locations(self) -> tuple[NodeLocation, ...]:
        """Its node."""
        return (self.location,)

    @property
    def spin_shaft(self) -> str:
        """The shaft it sits on."""
        return self.location.shaft

    @property
    def energy_group(self) -> str | None:
        """Its own name."""
        return self.name

    def mass_matrix(self) -> np.ndarray:
        """6×6 zero mass."""
        return zero_matrix()

    def stiffness_matrix(self) -> np.ndarray:
        """6×6 zero stiffness."""
        return zero_matrix()

    def damping_matrix(self) -> np.ndarray:
        """6×6 zero damping."""
        return zero_matrix()

    def gyroscopic_matrix(self) -> np.ndarray:
        """6×6 zero gyroscopic matrix."""
        return zero_matrix()

    def dead_zones(self) -> tuple:
        """None: linear."""
        return ()

    def mesh_vector(self) -> None:
        """None: constant stiffness."""
        return None


def _non_negative(key: str, value: float) -> float:
    number = float(value)
    if not math.isfinite(number) or number < 0.0:
        raise CaseError(key, value, ">= 0, finite", "stiffness, damping, mass and inertia cannot be negative")
    return number


@dataclass(frozen=True)
class NodeLocation:
    """A point on a shaft: the shaft's name and the axial position [m] from the shaft's first end."""

    shaft: str
    position: float

    def __post_init__(self) -> None:
        position = float(self.position)
        if not math.isfinite(position) or position < 0.0:
            raise CaseError(f"{self.shaft}.position", self.position, ">= 0 m from the shaft's first end",
                            "positions are measured along the shaft")


@dataclass(frozen=True)
class RigidDisk(OneNodeElement):
    """A rigid body on a shaft node: mass [kg], polar and diametral moments of inertia [kg·m²]."""

    name: str
    location: NodeLocation
    mass: float
    polar_inertia: float
    diametral_inertia: float

    def __post_init__(self) -> None:
        for key in ("mass", "polar_inertia", "diametral_inertia"):
            _non_negative(f"{self.name}.{key}", getattr(self, key))

    @classmethod
    def annulus(cls, name: str, location: NodeLocation, density: float, width: float, outer_diameter: float,
                inner_diameter: float = 0.0) -> RigidDisk:
        """A uniform annulus [kg/m³, m] (Friswell et al. 2010 App. 1). For a gear body take the pitch
        diameter as the outer diameter and the face width as the width (the teeth fill about half the tooth zone)."""
        if not 0.0 <= inner_diameter < outer_diameter or width <= 0.0 or density <= 0.0:
            raise CaseError(f"{name}.outer_diameter", outer_diameter,
                            f"> inner diameter {inner_diameter} m, with width and density > 0",
                            "an annulus needs a positive radial thickness, width and density")
        mass = density * math.pi * width * (outer_diameter**2 - inner_diameter**2) / 4.0
        polar = mass * (outer_diameter**2 + inner_diameter**2) / 8.0
        return cls(name, location, mass, polar, polar / 2.0 + mass * width**2 / 12.0)

    def mass_matrix(self) -> np.ndarray:
        """6×6 mass matrix on the node's DOFs."""
        m = self.mass
        return np.diag([m, m, m, self.diametral_inertia, self.diametral_inertia, self.polar_inertia])

    def gyroscopic(self) -> np.ndarray:
        """6×6 skew gyroscopic matrix per unit spin speed."""
        matrix = np.zeros((6, 6))
        matrix[3, 4] = self.polar_inertia
        matrix[4, 3] = -self.polar_inertia
        return matrix

    gyroscopic_matrix = gyroscopic

    @property
    def energy_group(self) -> None:
        """None: a rigid body stores no strain energy."""
        return None


@dataclass(frozen=True)
class Bearing(OneNodeElement):
    """A linear bearing from a shaft node to rigid ground: stiffness [N/m] and damping [N·s/m] in x, y and z.

    ``stiffness_xy``/``damping_xy`` are cross-coupling terms (k_xy = k_yx; non-symmetric bearings are out of scope).
    ``stiffness_z`` > 0 locates the shaft axially (otherwise the shaft has an axial rigid-body mode).
    ``radial_clearance`` δ [m] (default 0: linear): the shaft moves freely within ±δ of the bearing centre in x and
    in y, each on its own, and meets the bearing's stiffness and damping beyond (a dead zone per direction, the
    piecewise-linear form of a radial clearance: a square gap rather than a circle). The modes and the linear periodic
    response use the bearing in contact; the backlash solver (``drivetrain_backlash_system``) takes the clearance.
    ``tilting_stiffness`` [N·m/rad] resists the shaft's tilts α and β at the bearing (a wide or paired bearing; 0, the
    default, is a bearing that lets the shaft tilt freely); its moment on the housing is :meth:`housing_moment`.
    """

    name: str
    location: NodeLocation
    stiffness_x: float
    stiffness_y: float
    stiffness_z: float = 0.0
    damping_x: float = 0.0
    damping_y: float = 0.0
    damping_z: float = 0.0
    stiffness_xy: float = 0.0
    damping_xy: float = 0.0
    radial_clearance: float = 0.0
    tilting_stiffness: float = 0.0

    def __post_init__(self) -> None:
        for key in ("stiffness_x", "stiffness_y", "stiffness_z", "damping_x", "damping_y", "damping_z",
                    "radial_clearance", "tilting_stiffness"):
            _non_negative(f"{self.name}.{key}", getattr(self, key))
        if self.radial_clearance > 0.0 and (self.stiffness_xy != 0.0 or self.damping_xy != 0.0):
            raise CaseError(f"{self.name}.radial_clearance", self.radial_clearance, "0 with cross-coupling terms",
                            "a dead zone per direction cannot carry the x–y coupling of a bearing in contact")

    def stiffness_matrix(self) -> np.ndarray:
        """6×6 stiffness on the node's DOFs (ground is rigid)."""
        matrix = np.zeros((6, 6))
        matrix[:3, :3] = [[self.stiffness_x, self.stiffness_xy, 0.0], [self.stiffness_xy, self.stiffness_y, 0.0],
                          [0.0, 0.0, self.stiffness_z]]
        matrix[3, 3] = matrix[4, 4] = self.tilting_stiffness
        return matrix

    def housing_moment(self, tilts: np.ndarray) -> np.ndarray:
        """Moment on the housing (S, 2) [N·m] about x and y from the node's tilts α, β (S, 2) [rad]."""
        return self.tilting_stiffness * np.asarray(tilts, dtype=float)

    def damping_matrix(self) -> np.ndarray:
        """6×6 damping on the node's DOFs."""
        matrix = np.zeros((6, 6))
        matrix[:3, :3] = [[self.damping_x, self.damping_xy, 0.0], [self.damping_xy, self.damping_y, 0.0],
                          [0.0, 0.0, self.damping_z]]
        return matrix

    def dead_zones(self) -> tuple[DeadZone, ...]:
        """The radial clearance δ as one dead zone in x and one in y on the node's DOFs (none without a
        clearance): the bearing's spring and dashpot of that direction act beyond ±δ."""
        from thermogear.dynamics.backlash.backlash_ndof import DeadZone

        if self.radial_clearance <= 0.0:
            return ()
        return tuple(DeadZone(np.eye(6)[axis], stiffness, damping, self.radial_clearance)
                     for axis, stiffness, damping in ((0, self.stiffness_x, self.damping_x),
                                                      (1, self.stiffness_y, self.damping_y)))

    def housing_force(self, displacement: np.ndarray, velocity: np.ndarray, clearance: bool = True) -> np.ndarray:
        """Force on the housing (S, 3) [N] in x, y, z from the node's translations and their rates (S, 3) [m, m/s]:
        K·u + C·u̇, each direction x, y of a clearance taken by its dead zone's law (zero for |u| <= δ, k(u ∓ δ) +
        c·u̇ beyond; ``clearance`` False: in contact throughout, as the linear system solves it). The one place
        the bearing's law is read."""
        u, rate = np.array(displacement, dtype=float), np.array(velocity, dtype=float)
        if clearance:  # no x–y coupling with a clearance (refused at construction)
            for axis, zone in enumerate(self.dead_zones()):
                u[:, axis], rate[:, axis] = zone.engaged(u[:, axis], rate[:, axis])
        return u @ self.stiffness_matrix()[:3, :3].T + rate @ self.damping_matrix()[:3, :3].T


@dataclass(frozen=True)
class Coupling(OneNodeElement):
    """Springs and dashpots between two nodes (on different shafts, or a node and another on the same line).

    ``torsional_stiffness`` [N·m/rad] and ``torsional_damping`` [N·m·s/rad] act on θ; the optional
    ``lateral_stiffness`` [N/m] on x and y, ``angular_stiffness`` [N·m/rad] on α and β, ``axial_stiffness`` on z.
    """

    name: str
    first: NodeLocation
    second: NodeLocation
    torsional_stiffness: float
    torsional_damping: float = 0.0
    lateral_stiffness: float = 0.0
    angular_stiffness: float = 0.0
    axial_stiffness: float = 0.0

    def __post_init__(self) -> None:
        for key in ("torsional_stiffness", "torsional_damping", "lateral_stiffness", "angular_stiffness",
                    "axial_stiffness"):
            _non_negative(f"{self.name}.{key}", getattr(self, key))

    @staticmethod
    def _two_node(diagonal: np.ndarray) -> np.ndarray:
        block = np.diag(diagonal)
        return np.block([[block, -block], [-block, block]])

    def stiffness_matrix(self) -> np.ndarray:
        """12×12 stiffness on (first node DOFs, second node DOFs)."""
        k_l, k_a = self.lateral_stiffness, self.angular_stiffness
        return self._two_node(np.array([k_l, k_l, self.axial_stiffness, k_a, k_a, self.torsional_stiffness]))

    def damping_matrix(self) -> np.ndarray:
        """12×12 damping on (first node DOFs, second node DOFs)."""
        return self._two_node(np.array([0.0, 0.0, 0.0, 0.0, 0.0, self.torsional_damping]))

    @property
    def locations(self) -> tuple[NodeLocation, ...]:
        """Its two nodes."""
        return (self.first, self.second)

    @property
    def spin_shaft(self) -> str:
        """The first node's shaft (a coupling has no gyroscopic matrix)."""
        return self.first.shaft

    def mass_matrix(self) -> np.ndarray:
        """12×12 zero (its hubs are disks)."""
        return zero_matrix(2)

    def gyroscopic_matrix(self) -> np.ndarray:
        """12×12 zero."""
        return zero_matrix(2)


@dataclass(frozen=True)
class TorsionalSupport(OneNodeElement):
    """A torsional spring and dashpot from a node to ground: a motor held at speed by its speed controller
    (stiffness [N·m/rad] and damping [N·m·s/rad] from the drive's speed-loop gains). It removes the torsional
    rigid-body mode of the train physically, instead of reducing the equations on its complement."""

    name: str
    location: NodeLocation
    stiffness: float
    damping: float = 0.0

    def __post_init__(self) -> None:
        _non_negative(f"{self.name}.stiffness", self.stiffness)
        _non_negative(f"{self.name}.damping", self.damping)

    def stiffness_matrix(self) -> np.ndarray:
        """6×6: the torsional spring to ground on θ."""
        matrix = zero_matrix()
        matrix[5, 5] = self.stiffness
        return matrix

    def damping_matrix(self) -> np.ndarray:
        """6×6: the dashpot to ground on θ."""
        matrix = zero_matrix()
        matrix[5, 5] = self.damping
        return matrix
