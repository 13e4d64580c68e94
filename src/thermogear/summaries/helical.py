"""A case's helical pair as the commands show it (``stiffness``, ``run``, the report): its geometry, K_t over the
mesh cycle from the slice model beside ISO 6336-1's c′, c_γα and c_γβ, and the load along the face cold (the
elastic model) and hot (the thermo-elastic model with its lead distortion). Numbers only; the figures are in
:mod:`thermogear.report.helical_section`."""

from __future__ import annotations

import math

import numpy as np

from thermogear.helical.contact_lines import contact_line_segments, total_contact_length
from thermogear.helical.iso_stiffness import helical_iso_stiffness
from thermogear.helical.summary import helical_geometry_summary
from thermogear.mesh.helical_model import face_temperature_rise, helical_mesh_period
from thermogear.mesh.model import MeshModel
from thermogear.stiffness.iso6336 import N_PER_MM_UM

__all__ = ["helical_stiffness_summary", "helical_face_summary", "helical_thermoelastic_summary",
           "pair_thermoelastic_summary", "HELICAL_CYCLE_POINTS"]

#: Mesh positions over one period for the stiffness and face-load curves the commands show [–] (the interval
#: midpoints; K_t is continuous, so the mean converges at second order).
HELICAL_CYCLE_POINTS = 256


def helical_stiffness_summary(mesh: MeshModel, points: int = HELICAL_CYCLE_POINTS) -> dict:
    """K_t of ``mesh``'s helical pair over one period (no deviations: the exact face integral at the model's
    temperature), its mean, extremes and ripple, K_n = K_t/cos²β_b, and ISO 6336-1 Method B (c′, c_γα, c_γβ of
    the pair as built) with the ratio mean/c_γα — per unit face width in N/(mm·μm), the curve in N/m total."""
    helical = mesh.case.helical_pair
    period = helical_mesh_period(mesh, mesh.normal_load(), points, deviations=False)
    stiffness = period.stiffness
    per_width = 1.0 / (helical.face_width * N_PER_MM_UM)
    iso = helical_iso_stiffness(helical, mesh.case.material)
    mean = float(np.mean(stiffness))
    transverse = period.helical.transverse
    return {
        "geometry": helical_geometry_summary(helical),
        "model": mesh.model,
        "section": "normal",
        "phase_mm": (period.phase * 1e3).tolist(),
        "mesh_stiffness_total_n_per_m": stiffness.tolist(),
        "contact_line_length_mm": (total_contact_length(period.phase, transverse.path_length, helical.face_width,
                                                        helical.base_helix_angle, transverse.base_pitch)
                                   * 1e3).tolist(),
        "mesh_stiffness_n_per_mm_um": {"min": float(stiffness.min()) * per_width, "mean": mean * per_width,
                                       "max": float(stiffness.max()) * per_width},
        "ripple": float(np.ptp(stiffness)) / mean,
        "normal_mesh_stiffness_mean_n_per_mm_um": mean * per_width / math.cos(helical.base_helix_angle) ** 2,
        "iso6336": {"c_prime_n_per_mm_um": iso.single / N_PER_MM_UM,
                    "c_gamma_alpha_n_per_mm_um": iso.mesh / N_PER_MM_UM,
                    "c_gamma_beta_n_per_mm_um": iso.face / N_PER_MM_UM},
        "slice_mean_over_iso_c_gamma_alpha": mean * per_width / (iso.mesh / N_PER_MM_UM),
        "method": "thin uncoupled slices across the face (Velex & Maatar 1996), each the potential-energy "
                  "stiffness of ISO 6336-1's virtual spur pair of the normal section, integrated exactly over "
                  "the face; ISO 6336-1 Method B cross-check with the virtual teeth z_n",
    }


def helical_face_summary(mesh: MeshModel, points: int = HELICAL_CYCLE_POINTS) -> dict:
    """The load along the face of ``mesh``'s helical pair at the case's load over one period: the slice centres z
    [mm], the mean line load w̄(z) [N/mm], the face load factor max w̄/mean w̄, the peak factor, the load centre
    [mm from the outlet-side end face], the temperature rise ΔT(z) across the face [K] and the loaded static
    transmission error δ(φ) [μm] with its mean and peak-to-peak."""
    period = helical_mesh_period(mesh, mesh.normal_load(), points, deviations=True, always_face=True)
    face = period.face
    helical, transverse = period.helical, period.helical.transverse
    approach = period.approach * 1e6
    per_width = 1.0 / (period.helical.face_width * N_PER_MM_UM)
    return {
        "mesh_stiffness_n_per_mm_um": {"min": float(period.stiffness.min()) * per_width,
                                       "mean": float(np.mean(period.stiffness)) * per_width,
                                       "max": float(period.stiffness.max()) * per_width},
        "model": mesh.model,
        "z_mm": (face.z * 1e3).tolist(),
        "mean_line_load_n_per_mm": (face.mean_line_load * 1e-3).tolist(),
        "face_temperature_rise_k": face_temperature_rise(mesh, face.z).tolist(),
        "face_load_factor": face.face_load_factor,
        "peak_factor": face.peak_factor,
        "load_centre_mm": face.load_centre * 1e3,
        "phase_mm": (period.phase * 1e3).tolist(),
        "static_transmission_error_um": approach.tolist(),
        "static_transmission_error_mean_um": float(np.mean(approach)),
        "static_transmission_error_peak_to_peak_um": float(np.ptp(approach)),
        "mesh_stiffness_curve_n_per_mm_um": (period.stiffness * per_width).tolist(),
        "stiffness_scale": period.stiffness_scale,
        "zone_of_action_mm": {"path_length": transverse.path_length * 1e3, "face_width": helical.face_width * 1e3},
        "contact_lines_at_phase_0_mm": [[list(map(lambda value: value * 1e3, end)) for end in segment]
                                        for segment in contact_line_segments(
                                            0.0, transverse.path_length, helical.face_width,
                                            helical.base_helix_angle, transverse.base_pitch)],
        "contact_line_length_mm": (total_contact_length(period.phase, transverse.path_length, helical.face_width,
                                                        helical.base_helix_angle, transverse.base_pitch)
                                   * 1e3).tolist(),
    }


def helical_thermoelastic_summary(summary: dict, elastic: MeshModel, thermal: MeshModel,
                                  points: int = HELICAL_CYCLE_POINTS) -> dict:
    """The thermo-elastic summary (:func:`thermogear.summaries.thermoelastic.thermoelastic_summary`, built on the
    transverse section) of a helical pair: its mesh stiffness and loaded static transmission error are the slice
    model's, cold (``elastic``) and hot (``thermal``, with the lead distortion of the face gradient), and
    ``helical`` holds the geometry and the load along the face of both. The operating geometry, backlash (along
    the transverse line of action) and jamming stay the transverse section's."""
    cold, hot = helical_face_summary(elastic, points), helical_face_summary(thermal, points)
    change = hot["mesh_stiffness_n_per_mm_um"]["mean"] / cold["mesh_stiffness_n_per_mm_um"]["mean"] - 1.0
    elastic_part = {**summary["elastic"], "mesh_stiffness_n_per_mm_um": cold["mesh_stiffness_n_per_mm_um"],
                    "loaded_transmission_error_um": _transmission_error(cold)}
    return {**summary, "mesh_stiffness_n_per_mm_um": hot["mesh_stiffness_n_per_mm_um"],
            "mesh_stiffness_change_percent": 100.0 * change,
            "loaded_transmission_error_um": _transmission_error(hot), "elastic": elastic_part,
            "helical": {"geometry": helical_geometry_summary(thermal.case.helical_pair),
                        "face_gradient_k": float(thermal.case.temperature.face_gradient_k),
                        "cold": cold, "hot": hot}}


def _transmission_error(face: dict) -> dict:
    return {"mean": face["static_transmission_error_mean_um"],
            "peak_to_peak": face["static_transmission_error_peak_to_peak_um"]}


def pair_thermoelastic_summary(thermal: MeshModel) -> dict:
    """The thermo-elastic summary of a case's pair under its thermal mesh model ``thermal``, spur or helical (the
    one call ``run`` and the report make): :func:`~thermogear.summaries.thermoelastic.thermoelastic_summary`, and
    for a helical pair :func:`helical_thermoelastic_summary` on it."""
    from thermogear.summaries.thermoelastic import thermoelastic_summary  # noqa: PLC0415

    summary = thermoelastic_summary(thermal.thermoelastic_mesh, thermal.thermal_model, thermal.temperature)
    if thermal.case.helical_pair is None:
        return summary
    return helical_thermoelastic_summary(summary, MeshModel(thermal.case, "elastic"), thermal)
