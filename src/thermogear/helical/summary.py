"""The geometry of a helical pair as numbers for the commands (``check``, ``stiffness``, ``run``, the report):
ISO 21771 quantities and the contact lines' length over the mesh cycle, in the units the case file uses."""

from __future__ import annotations

import math

from thermogear.helical.contact_lines import contact_length_extremes
from thermogear.helical.geometry import RIGHT_HAND, HelicalPair

__all__ = ["helical_geometry_summary"]


def helical_geometry_summary(helical: HelicalPair) -> dict:
    """β, β_b, the pinion's hand, m_n/m_t [mm], α_n/α_t [°], ε_α, ε_β, ε_γ, the axial pitch p_x [mm] and the total
    contact-line length (mean, min, max over the mesh cycle [mm], closed form of
    :func:`~thermogear.helical.contact_lines.contact_length_extremes`)."""
    mean, low, high = contact_length_extremes(helical.transverse_contact_ratio, helical.overlap_ratio,
                                              helical.face_width, helical.base_helix_angle)
    return {
        "helix_angle_deg": math.degrees(helical.helix_angle),
        "base_helix_angle_deg": math.degrees(helical.base_helix_angle),
        "hand": "right" if helical.pinion_hand == RIGHT_HAND else "left",
        "normal_module_mm": helical.normal_module * 1e3,
        "transverse_module_mm": helical.transverse_module * 1e3,
        "normal_pressure_angle_deg": math.degrees(helical.normal_pressure_angle),
        "transverse_pressure_angle_deg": math.degrees(helical.transverse_pressure_angle),
        "transverse_contact_ratio": helical.transverse_contact_ratio,
        "overlap_ratio": helical.overlap_ratio,
        "total_contact_ratio": helical.total_contact_ratio,
        "axial_pitch_mm": helical.axial_pitch * 1e3,
        "contact_line_length_mm": {"mean": mean * 1e3, "min": low * 1e3, "max": high * 1e3},
    }
