"""The mesh state of a helical pair for the solvers: its stiffness along the transverse line of action over one
mesh period (the slice model integrated over the face, :func:`thermogear.helical.slices.helical_mesh_stiffness`),
as the piecewise-constant k(τ) every solver takes (:func:`~thermogear.mesh.state.mesh_state_from_arrays`).

The 1-DOF pair is the torsional projection along the transverse line of action: the transmission error
δ = r_b1θ₁ + r_b2θ₂ against the transverse force F_bt = T₁/r_b1, the mass m_e = J₁J₂/(J₁r_b2² + J₂r_b1²) of the
base radii and inertias, and the stiffness K_t (= K_n cos²β_b: a normal force F_n = F_bt/cos β_b on a normal
approach δ cos β_b). Each interval takes K_t at its midpoint (the helical K_t is continuous; the piecewise-constant
form converges at first order in the interval width, as the spur mesh model's own sampling does).
"""

from __future__ import annotations

import numpy as np

from thermogear.helical.geometry import HelicalPair
from thermogear.helical.slices import helical_mesh_stiffness
from thermogear.materials import Material
from thermogear.mesh.state import MeshState, mesh_state_from_arrays

__all__ = ["helical_mesh_state"]


def helical_mesh_state(helical: HelicalPair, material: Material, speed_rpm: float, torque: float,
                       inertias: tuple[float, float], points: int = 1024, damping_ratio: float = 0.0,
                       section: str = "normal") -> MeshState:
    """The :class:`MeshState` of ``helical`` at pinion ``speed_rpm`` [rpm] and torque [N·m] with the gears' polar
    inertias [kg·m²] over ``points`` intervals of one mesh period; ``damping_ratio`` ζ gives a constant mesh damping
    c = 2ζ√(k̄ m_e) (none by default)."""
    transverse = helical.transverse
    phase = np.arange(points) / points
    midpoints = (phase + 0.5 / points) * transverse.base_pitch
    stiffness = helical_mesh_stiffness(helical, material, midpoints, section=section).stiffness
    base_radii = (transverse.pinion.base_radius, transverse.wheel.base_radius)
    mass = inertias[0] * inertias[1] / (inertias[0] * base_radii[1] ** 2 + inertias[1] * base_radii[0] ** 2)
    damping = np.full(points, 2.0 * damping_ratio * np.sqrt(np.mean(stiffness) * mass))
    return mesh_state_from_arrays(phase, stiffness, damping=damping, speed_rpm=speed_rpm,
                                  pinion_teeth=transverse.pinion.teeth, normal_load=torque / base_radii[0],
                                  mass=mass, face_width=helical.face_width, model="helical")
