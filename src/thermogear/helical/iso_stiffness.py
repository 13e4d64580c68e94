"""ISO 6336-1 Method B stiffness of a helical pair: single stiffness c′ (virtual spur teeth of the normal section,
×cos β), mesh stiffness c_γα = c′(0.75 ε_α + 0.25) for the dynamic and transverse factors and c_γβ = 0.85 c_γα for
the face load factors (ISO 6336-1:2006 §9.3), the cross-check of the slice model's mean."""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.helical.geometry import HelicalPair
from thermogear.materials import Material
from thermogear.stiffness.iso6336 import iso6336_mesh_stiffness, iso6336_single_stiffness

__all__ = ["HelicalIsoStiffness", "helical_iso_stiffness", "FACE_STIFFNESS_SHARE"]

#: c_γβ / c_γα (ISO 6336-1:2006 §9.3.2, the mesh stiffness of the face load factors K_Hβ, K_Fβ).
FACE_STIFFNESS_SHARE = 0.85


@dataclass(frozen=True)
class HelicalIsoStiffness:
    """Per unit face width [N/m per m]."""

    single: float  # c′
    mesh: float  # c_γα
    face: float  # c_γβ


def helical_iso_stiffness(helical: HelicalPair, material: Material) -> HelicalIsoStiffness:
    """c′, c_γα, c_γβ of a solid-blank steel pair (C_R = 1) with the case's basic rack (ISO 6336-1 Method B)."""
    pinion, wheel = helical.transverse.pinion, helical.transverse.wheel
    single = iso6336_single_stiffness(
        pinion.teeth, wheel.teeth, *helical.normal_profile_shifts, material.youngs_modulus,
        rack_dedendum_coefficient=pinion.dedendum_coefficient / math.cos(helical.helix_angle),
        pressure_angle=helical.normal_pressure_angle, helix_angle=helical.helix_angle, warn=False,
        virtual_teeth=helical.virtual_teeth)
    mesh = iso6336_mesh_stiffness(single, helical.transverse_contact_ratio)
    return HelicalIsoStiffness(single, mesh, FACE_STIFFNESS_SHARE * mesh)
