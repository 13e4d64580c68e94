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

**Helical mesh** (the same class; the spur mesh is its β_b = 0, point-contact case). The flanks approach along the
tooth normal n of the helicoid, n = cos β_b u − σH sin β_b ẑ (:mod:`thermogear.helical.mesh_vector`, derived from
first principles: w_n = [n ; p₁ × n | −n ; −(p₂ × n)], p_i the arm from gear i's node to the operating pitch point,
r_wi = r_bi / cos α_wt from the axis). The element keeps the transverse quantities of the 1-DOF helical pair
(:mod:`thermogear.mesh.helical_state`): its ``stiffness`` is K_t along the transverse line of action, W the
transverse load, and its vector is w = w_n / cos β_b, so that K_t w wᵀ = K_n w_n w_nᵀ (K_n = K_t / cos²β_b), the
torsional entries stay s·r_bi (the torque pair s·r_bi·W is unchanged) and δ = wᵀq is the transverse transmission
error. The force W w on the DOFs holds the axial component W tan β_b = F_t tan β_w (F_t = W cos α_wt the
tangential force) and the tilting moments p_i × n; at β_b = 0 the axial and tilting entries vanish and w is the spur
vector above. Where on the face the stiffness acts (one point, or spread with a load centre and a tilting stiffness)
is the ``contact`` option (:mod:`thermogear.drivetrain.mesh_contact`). Both gear nodes sit at their gears'
mid-faces, in one transverse plane.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.elements import zero_matrix
from thermogear.drivetrain.mesh_contact import MESH_CONTACTS, FaceVariation, MeshContact
from thermogear.drivetrain.point_elements import NodeLocation
from thermogear.errors import CaseError
from thermogear.helical.mesh_vector import helical_mesh_vector

__all__ = ["GearMesh"]


@dataclass(frozen=True)
class GearMesh:
    """A spur or helical mesh between gear 1 (the driver) and gear 2 on two shaft nodes.

    ``base_radius_1``, ``base_radius_2`` [m]; ``operating_pressure_angle`` α_w [rad]; ``centre_line_angle`` φ_c
    [rad] of the line from gear 1's centre to gear 2's, from +x towards +y; ``rotation_sense`` s = +1 when gear 1
    turns counter-clockwise about +z, −1 clockwise. ``stiffness`` is the mean (or a given constant) mesh stiffness
    [N/m] used by the modal analysis and the static state; ``damping`` [N·s/m] likewise.

    Helical (module docstring): ``base_helix_angle`` β_b [rad] (0: spur), ``hand`` H of gear 1 (+1 right, −1
    left), ``contact`` a :class:`~thermogear.drivetrain.mesh_contact.MeshContact` (default the point at mid-face),
    ``face_width`` b [m] (the spread contact's default ρ = b/√12), ``load_centre`` z̄ [m] from mid-face along +z
    and ``load_gyration`` ρ [m] of the spread contact (None: b/√12, the uniform face). ``stiffness`` and
    ``damping`` are then transverse, K_t and c_t. ``face_variation``: the spread contact's moments over the mesh
    period (:class:`~thermogear.drivetrain.mesh_contact.FaceVariation`; None: held at their means), taken by the
    periodic solvers as two more patterns of the mesh (:meth:`face_factors`).
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
    base_helix_angle: float = 0.0
    hand: int = 1
    contact: MeshContact = MESH_CONTACTS["point"]
    face_width: float = 0.0
    load_centre: float = 0.0
    load_gyration: float | None = None
    face_variation: FaceVariation | None = None

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
        if not 0.0 <= float(self.base_helix_angle) < math.pi / 2.0:
            raise CaseError(f"{self.name}.base_helix_angle", self.base_helix_angle, "[0, π/2) rad",
                            "0 is a spur mesh; the hand gives the helix's sense")
        if self.hand not in (1, -1):
            raise CaseError(f"{self.name}.hand", self.hand, "+1 (right) or −1 (left)", "the hand of gear 1's helix")
        if not isinstance(self.contact, MeshContact):
            raise CaseError(f"{self.name}.contact", self.contact, f"one of MESH_CONTACTS: {', '.join(MESH_CONTACTS)}",
                            "where the mesh stiffness acts on the face (thermogear.drivetrain.mesh_contact)")
        for key in ("face_width", "load_centre") + (("load_gyration",) if self.load_gyration is not None else ()):
            value = float(getattr(self, key))
            if not math.isfinite(value) or (key != "load_centre" and value < 0.0):
                raise CaseError(f"{self.name}.{key}", getattr(self, key), ">= 0 m, finite" if key != "load_centre"
                                else "finite [m]", "the contact's extent across the face")
        if self.face_variation is not None and not isinstance(self.face_variation, FaceVariation):
            raise CaseError(f"{self.name}.face_variation", type(self.face_variation).__name__,
                            "a FaceVariation or None", "the moments of the spread contact over the mesh period")
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

    def vector_at(self, axial_position: float) -> np.ndarray:
        """w (12,) of a contact at ``axial_position`` [m] from mid-face along +z, transverse scaling w_n / cos β_b
        (module docstring): δ = wᵀq [m per SI DOF]."""
        cosine = math.cos(self.operating_pressure_angle)
        radii = (self.base_radius_1 / cosine, self.base_radius_2 / cosine)
        w = helical_mesh_vector(radii, self.operating_pressure_angle, self.base_helix_angle, self.centre_line_angle,
                                self.rotation_sense, None, self.hand, (axial_position, axial_position))
        return w / math.cos(self.base_helix_angle)

    def vector(self) -> np.ndarray:
        """w (12,) on (gear-1 node DOFs, gear-2 node DOFs) at the contact's load centre: δ = wᵀq [m per SI DOF]
        (the spur vector [u, 0, 0, 0, s·r_b1 | −u, 0, 0, 0, s·r_b2] at β_b = 0)."""
        return self.vector_at(self.contact.moments(self)[0])

    def tilt_vector(self) -> np.ndarray:
        """w_z = ∂w/∂z (12,): the relative tilt of the gears that strains a contact in proportion to its axial
        position (:mod:`thermogear.drivetrain.mesh_contact`) [1/rad per SI DOF]."""
        return self.vector_at(1.0) - self.vector_at(0.0)

    def tilting_matrix(self, value: float) -> np.ndarray:
        """value·ρ²·w_z w_zᵀ (12×12): the spread of ``value`` (a stiffness or damping) about the load centre."""
        gyration = self.contact.moments(self)[1]
        if gyration == 0.0:
            return zero_matrix(2)
        tilt = self.tilt_vector()
        return value * gyration**2 * np.outer(tilt, tilt)

    def varies(self) -> bool:
        """Whether the periodic solvers take this mesh's moments over the period (a :class:`FaceVariation` with a
        contact that takes one): three stiffness patterns instead of one (:meth:`face_factors`)."""
        return self.face_variation is not None and self.contact.varies

    def face_factors(self, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                     excitation: np.ndarray) -> np.ndarray:
        """(5, N): the factors per interval of the patterns w w_zᵀ + w_z wᵀ (stiffness k₁′, damping c₁′), w_z w_zᵀ
        beyond its constant k̄ρ² (k₂′ − k̄ρ², c₂′ − c̄ρ²) and the force along w_z (the gaps' moment about the load
        centre), from the state's ``stiffness`` k(τ) [N/m], ``damping`` c(τ) [N·s/m] and ``excitation`` Σk_je_j [N]
        on the intervals of ``nodes`` (:mod:`thermogear.drivetrain.mesh_contact`, "The variation over the period")."""
        first, second, gap = self.face_variation.on(nodes)
        centre, gyration = self.contact.moments(self)
        tilt = gyration**2 + second - 2.0 * centre * first
        return np.array([stiffness * first, damping * first, stiffness * tilt - self.stiffness * gyration**2,
                         damping * tilt - self.damping * gyration**2, stiffness * gap - centre * excitation])

    def torques(self, normal_load: float) -> tuple[float, float]:
        """Driving torque on gear 1 and load torque on gear 2 [N·m], global sense, in equilibrium with W [N]."""
        s = self.rotation_sense
        return s * self.base_radius_1 * normal_load, s * self.base_radius_2 * normal_load

    # the element interface (thermogear.drivetrain.elements): the mesh's stiffness, damping, excitation and backlash
    # are its mesh state's, acting through w; its constant matrices hold only a spread contact's tilting terms
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

    gyroscopic_matrix = mass_matrix

    def stiffness_matrix(self) -> np.ndarray:
        """12×12 constant part: the spread contact's tilting stiffness k̄ρ² w_z w_zᵀ (zero for a point contact);
        the k(τ) w wᵀ part is the mesh state's."""
        return self.tilting_matrix(self.stiffness)

    def damping_matrix(self) -> np.ndarray:
        """12×12 constant part: c̄ρ² w_z w_zᵀ (zero for a point contact)."""
        return self.tilting_matrix(self.damping)

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
