"""The spur-gear mesh element along the line of action, coupling the transverse and torsional motion of two gears.

After Kahraman, Ozguven, Houser & Zakrajsek, "Dynamic analysis of geared rotors by finite elements", J. Mech. Des.
114 (1992) 507–514, and Lin & Parker, J. Vib. Acoust. 121 (1999) 316–321, written here in global angles (every θ is
a rotation about the same +z axis). Let e_c = (cos φ_c, sin φ_c) point from the centre of gear 1 to that of gear 2,
e_t = ẑ × e_c, s = +1 when gear 1 drives turning counter-clockwise about +z (−1 clockwise) and α_w the operating
pressure angle. The line of action (direction of the tooth force on gear 2) is u = sin α_w·e_c + s·cos α_w·e_t; the
tangency point of gear 1 moves by r_b1θ₁u when gear 1 turns, that of gear 2 by −r_b2θ₂u, so the approach of the
flanks along u is

    δ = u·(r₁ − r₂) + s·(r_b1θ₁ + r_b2θ₂) = wᵀq,   w = [u_x, u_y, 0, 0, 0, s·r_b1 | −u_x, −u_y, 0, 0, 0, s·r_b2].

The mesh adds k(τ)·w wᵀ to the stiffness, c(τ)·w wᵀ to the damping and (k e + c ė)·w to the forces (e: unloaded
deviation, positive where material is missing). The tooth force F = k(δ − e) + c(δ̇ − ė) pushes gear 2 along +u and
gear 1 along −u; a driving torque s·r_b1·W on gear 1 and a load torque s·r_b2·W on gear 2 are in equilibrium with F = W.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.elements import zero_matrix
from thermogear.drivetrain.point_elements import NodeLocation
from thermogear.errors import CaseError

__all__ = ["GearMesh"]


@dataclass(frozen=True)
class GearMesh:
    """A spur mesh between gear 1 (the driver) and gear 2 on two shaft nodes.

    ``base_radius_1``, ``base_radius_2`` [m]; ``operating_pressure_angle`` α_w [rad]; ``centre_line_angle`` φ_c
    [rad] of the line from gear 1's centre to gear 2's, from +x towards +y; ``rotation_sense`` s = +1 when gear 1
    turns counter-clockwise about +z, −1 clockwise. ``stiffness`` is the mean (or a given constant) mesh stiffness
    [N/m] used by the modal analysis and the static state; ``damping`` [N·s/m] likewise.
    """

    name: str
    gear_1: NodeLocation
    gear_2: NodeLocation
    base_radius_1: float
    base_radius_2: float
    operating_pressure_angle: float
    stiffness: float
    damping: float = 0.0
    centre_line_angle: float = 0.0
    rotation_sense: int = 1

    def __post_init__(self) -> None:
        for key in ("base_radius_1", "base_radius_2", "stiffness"):
            value = float(getattr(self, key))
            if not math.isfinite(value) or value <= 0.0:
                raise CaseError(f"{self.name}.{key}", getattr(self, key), "> 0, finite", "[m] or [N/m] of the mesh")
        if not math.isfinite(float(self.damping)) or self.damping < 0.0:
            raise CaseError(f"{self.name}.damping", self.damping, ">= 0 N·s/m", "negative damping injects energy")
        if not 0.0 < float(self.operating_pressure_angle) < math.pi / 2.0:
            raise CaseError(f"{self.name}.operating_pressure_angle", self.operating_pressure_angle,
                            "(0, π/2) rad", "the line of action is inclined to the centre line")
        if self.rotation_sense not in (1, -1):
            raise CaseError(f"{self.name}.rotation_sense", self.rotation_sense, "+1 or −1",
                            "+1: gear 1 turns counter-clockwise about +z")
        if self.gear_1.shaft == self.gear_2.shaft:
            raise CaseError(f"{self.name}.gear_2", self.gear_2.shaft, "a shaft other than gear 1's",
                            "a mesh joins two shafts")

    @property
    def line_of_action(self) -> np.ndarray:
        """Unit vector u (2,) of the tooth force on gear 2 in the x–y plane."""
        alpha, phi = self.operating_pressure_angle, self.centre_line_angle
        centre = np.array([math.cos(phi), math.sin(phi)])
        tangent = np.array([-math.sin(phi), math.cos(phi)])
        return math.sin(alpha) * centre + self.rotation_sense * math.cos(alpha) * tangent

    def vector(self) -> np.ndarray:
        """w (12,) on (gear-1 node DOFs, gear-2 node DOFs): δ = wᵀq [m per SI DOF]."""
        u = self.line_of_action
        s = self.rotation_sense
        return np.array([u[0], u[1], 0.0, 0.0, 0.0, s * self.base_radius_1,
                         -u[0], -u[1], 0.0, 0.0, 0.0, s * self.base_radius_2])

    def torques(self, normal_load: float) -> tuple[float, float]:
        """Driving torque on gear 1 and load torque on gear 2 [N·m], global sense, in equilibrium with W [N]."""
        s = self.rotation_sense
        return s * self.base_radius_1 * normal_load, s * self.base_radius_2 * normal_load

    # the element interface (thermogear.drivetrain.elements): the mesh's stiffness, damping, excitation and backlash
    # are its mesh state's, acting through w; its constant matrices are zero
    @property
    def locations(self) -> tuple[NodeLocation, ...]:
        """Gear 1's node, gear 2's node."""
        return (self.gear_1, self.gear_2)

    @property
    def spin_shaft(self) -> str:
        """Gear 1's shaft (the mesh has no gyroscopic matrix)."""
        return self.gear_1.shaft

    @property
    def energy_group(self) -> str:
        """Its name (its strain energy k̄(wᵀφ)² is reported from its mean stiffness)."""
        return self.name

    def mass_matrix(self) -> np.ndarray:
        """12×12 zero (the gear bodies are disks)."""
        return zero_matrix(2)

    stiffness_matrix = damping_matrix = gyroscopic_matrix = mass_matrix

    def dead_zones(self) -> tuple:
        """None here: the backlash is a dead zone of width given by the mesh state, built with it."""
        return ()

    def mesh_vector(self) -> np.ndarray:
        """w (12,), :meth:`vector`."""
        return self.vector()

    @property
    def speed_ratio(self) -> float:
        """Angular speed of gear 2 over that of gear 1, signed in the global sense: −r_b1/r_b2 (external pair)."""
        return -self.base_radius_1 / self.base_radius_2
