"""The helical mesh vector: how the twelve motions of two gears (x, y, z, α, β, θ of each node; global angles, all
rotations about the fixed +x, +y, +z) approach the flanks along the tooth normal.

Derivation (first principles, no source code followed). Gear i's material point at the contact P moves by
Δ_i = t_i + ω_i × p_i, with t_i, ω_i its node's translation and small rotation and p_i = P − O_i the arm from its
node. The flanks approach along the tooth normal n (the direction of the force on gear 2):

    δ = n·(Δ_1 − Δ_2) = n·t_1 + ω_1·(p_1 × n) − n·t_2 − ω_2·(p_2 × n) = wᵀq,
    w = [ n ; p_1 × n | −n ; −(p_2 × n) ]                         (n·(ω × p) = ω·(p × n))

The normal of an involute helicoid at a contact point lies in the plane of action (spanned by the line of action
u and the axis ẑ) and is square to the contact line, which is inclined at the base helix angle β_b to the axis,
l̂ = σH sin β_b u + cos β_b ẑ; hence

    n = cos β_b u − σH sin β_b ẑ,   u = sin α_wt e_c + s cos α_wt e_t,

e_c the unit vector from gear 1's centre to gear 2's, e_t = ẑ × e_c, s = +1 when gear 1 turns counter-clockwise
about +z, σ = s on the drive flanks (−s on the coast flanks), H = +1 for a right-hand gear 1 (its transverse
section at axial position z turned by +z tan β/r about +z). P is the operating pitch point, r_w1 from gear 1's
axis, at axial offsets z_1, z_2 from the gear nodes: p_1 = r_w1 e_c + z_1 ẑ, p_2 = −r_w2 e_c + z_2 ẑ.

Properties (tested): with β_b = 0 and z_i = 0 it is the spur element's w of
:mod:`thermogear.drivetrain.mesh_element`; the six rigid motions of the pair (both gears moving as one body) leave
δ = 0, because both gears are read at the same point P; the torsional entries are s r_bi cos β_b, so on rigid
supports the torsional stiffness is K_n r_b² cos²β_b = K_t r_b²; the force F n on gear 2 splits into radial,
tangential and axial parts in the ratios tan α_wt : 1 : tan β_w (tan β_w = tan β_b / cos α_wt, the helix angle
on the operating pitch cylinder), tan α_t : 1 : tan β at the reference centre distance.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["helical_mesh_vector", "tooth_normal"]


def tooth_normal(operating_pressure_angle: float, base_helix_angle: float, centre_line_angle: float = 0.0,
                 rotation_sense: int = 1, flank: int | None = None, hand: int = 1) -> np.ndarray:
    """n (3,): the unit normal of the flanks at the contact, the direction of the tooth force on gear 2
    (module docstring); ``flank`` σ defaults to the drive flanks (σ = s)."""
    sigma = rotation_sense if flank is None else flank
    phi = centre_line_angle
    centre = np.array([math.cos(phi), math.sin(phi), 0.0])
    tangent = np.array([-math.sin(phi), math.cos(phi), 0.0])
    line = math.sin(operating_pressure_angle) * centre + rotation_sense * math.cos(operating_pressure_angle) * tangent
    return math.cos(base_helix_angle) * line - sigma * hand * math.sin(base_helix_angle) * np.array([0.0, 0.0, 1.0])


def helical_mesh_vector(operating_pitch_radii: tuple[float, float], operating_pressure_angle: float,
                        base_helix_angle: float, centre_line_angle: float = 0.0, rotation_sense: int = 1,
                        flank: int | None = None, hand: int = 1,
                        axial_offsets: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """w (12,) on (gear-1 node x, y, z, α, β, θ | gear-2 node ...): δ = wᵀq [m per SI DOF] (module docstring).
    ``operating_pitch_radii`` r_w1, r_w2 [m]; ``axial_offsets`` z_1, z_2 [m] of the contact from the nodes."""
    normal = tooth_normal(operating_pressure_angle, base_helix_angle, centre_line_angle, rotation_sense, flank, hand)
    phi = centre_line_angle
    centre = np.array([math.cos(phi), math.sin(phi), 0.0])
    axis = np.array([0.0, 0.0, 1.0])
    arm_1 = operating_pitch_radii[0] * centre + axial_offsets[0] * axis
    arm_2 = -operating_pitch_radii[1] * centre + axial_offsets[1] * axis
    return np.concatenate([normal, np.cross(arm_1, normal), -normal, -np.cross(arm_2, normal)])
