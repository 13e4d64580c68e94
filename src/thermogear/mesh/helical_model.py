"""A case's helical pair under a mesh model: its stiffness along the face, the load along the face with the
deviations the model gives (profile deviations of the transverse section, the thermal lead distortion of a
temperature gradient across the face), and the one mesh period the 1-DOF solvers take.

The 1-DOF pair is the torsional projection along the transverse line of action (:mod:`thermogear.mesh.helical_state`):
the transmission error δ = r_b1θ₁ + r_b2θ₂ against F_bt = T₁/r_b1 and the stiffness K_t of the slice model
(:mod:`thermogear.helical.slices`). The model's transverse section is the one the spur machinery gives for the
same case (:attr:`MeshModel.gear_pair`): at temperature for the thermo-elastic model (gears grown by their bulk
rise, centre distance by the housing's), as built otherwise. What the model changes and how it enters here:

- E(T): every compliance of the slice model is ∝ 1/E, so K_t is scaled by the pair's modulus ratio; with different
  ratios of pinion and wheel the series mean 2/(1/r₁ + 1/r₂) is taken (exact for equal ratios; for the tooth
  temperatures of one case the ratios differ by well under 1 %, and the error is second order in that difference);
- the profile deviations of a tooth pair along the transverse path (tip reliefs, base-pitch mismatch, thermal
  profile distortion) become the gap of every slice at its path position;
- the lead distortion of ``[temperature] face_gradient_k`` (g = outlet minus inlet side, linear across the face):
  ΔT(z) = g (1/2 − z/b) for both gears, z from the end face where a tooth pair's contact line leaves the mesh
  last — the slice at z = b reaches the start of the path A first, so a tooth's contact sweeps from z = b to z = 0
  and the oil is driven out at z = 0 (the outlet side). Its gap is
  :func:`~thermogear.helical.face_load.thermal_lead_deviation`.
With deviations, each mesh position is solved with compression-only slices (Σ k_i⟨δ − e_i⟩₊ = F_bt,
:func:`~thermogear.helical.face_load.slice_loads`), and the period takes the stiffness of the slices that carry load
and the deviation e(φ) = δ(φ) − F_bt/K(φ) that reproduces the loaded static transmission error. Without deviations
K_t is the exact face integral and e = 0.

Friction damping: Luo & Li (2020) Eq. 28 gives each contact c = 4μk/(πω_m), so the mesh damping is ∝ the stiffness
at the contacts' mean μ; the helical mesh takes c(τ) = K_t(τ)·c̄/k̄ with c̄/k̄ the time means of the model's
transverse section (the spur pair of the same transverse geometry, oil and load per width). A stated
approximation: a helical contact line spans the path, so μ is averaged along it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
import numpy as np

from thermogear.helical.face_load import FaceLoad, slice_loads, thermal_lead_deviation
from thermogear.helical.geometry import HelicalPair
from thermogear.helical.slices import DEFAULT_SLICES, contact_stiffness, helical_mesh_stiffness
from thermogear.mesh.state import MeshState, mesh_state_from_arrays

#: ``mesh_model`` below is a :class:`thermogear.mesh.model.MeshModel` (not imported: it imports this module).
MeshModel = object

__all__ = ["HelicalMeshPeriod", "helical_mesh_period", "helical_model_state", "operating_helical_pair",
           "face_temperature_rise"]


@dataclass(frozen=True)
class HelicalMeshPeriod:
    """One mesh period of a case's helical pair under a model, at mesh phases φ [m] along the transverse path.

    ``stiffness`` K_t [N/m] of the slices that carry load; ``approach`` δ the loaded static transmission error [m];
    ``face`` the load along the face (None where there are no deviations: the load is then spread as the stiffness
    is); ``stiffness_scale`` the E(T) factor applied."""

    helical: HelicalPair
    phase: np.ndarray
    load: float  # F_bt [N]
    stiffness: np.ndarray
    approach: np.ndarray
    face: FaceLoad | None
    stiffness_scale: float

    @property
    def deviation(self) -> np.ndarray:
        """e(φ) = δ(φ) − F_bt/K(φ) [m]: the unloaded deviation of the mesh whose linear response to F_bt is the
        loaded static transmission error (0 without deviations)."""
        if self.face is None:
            return np.zeros(self.phase.shape)
        return self.approach - self.load / self.stiffness


def operating_helical_pair(mesh_model: MeshModel) -> HelicalPair:
    """The case's helical pair with the model's transverse section (at temperature for the thermo-elastic model)."""
    return replace(mesh_model.case.helical_pair, transverse=mesh_model.gear_pair)


def _stiffness_scale(mesh_model: MeshModel) -> float:
    """E(T)/E(20 °C) of the pair (module docstring): 1 for a model without E(T)."""
    mesh = mesh_model.thermoelastic_mesh
    if mesh is None or not mesh_model.thermal:
        return 1.0
    pinion, wheel = mesh.modulus_ratios
    return pinion if pinion == wheel else 2.0 / (1.0 / pinion + 1.0 / wheel)


def face_temperature_rise(mesh_model: MeshModel, z: np.ndarray) -> np.ndarray:
    """ΔT(z) = g (1/2 − z/b) [K] of ``[temperature] face_gradient_k`` g under a thermal model, 0 otherwise."""
    gradient = float(getattr(mesh_model.case.temperature, "face_gradient_k", 0.0))
    if gradient == 0.0 or not mesh_model.thermal:
        return np.zeros(np.shape(z))
    return gradient * (0.5 - np.asarray(z, dtype=float) / mesh_model.case.helical_pair.face_width)


def _lead_gap(mesh_model: MeshModel, helical: HelicalPair, z: np.ndarray) -> np.ndarray:
    rise = face_temperature_rise(mesh_model, z)
    if not np.any(rise):
        return np.zeros(z.shape)
    mesh = mesh_model.thermoelastic_mesh
    transverse = helical.transverse
    return thermal_lead_deviation(rise, rise, transverse.operating_pitch_radii, transverse.operating_pressure_angle,
                                  (mesh.gears[0].expansion_per_k, mesh.gears[1].expansion_per_k))


def helical_mesh_period(mesh_model: MeshModel, load: float, points: int, slices: int = DEFAULT_SLICES,
                        always_face: bool = False, deviations: bool = True) -> HelicalMeshPeriod:
    """The period of ``mesh_model``'s case at F_bt = ``load`` [N] on ``points`` intervals (each at its midpoint;
    module docstring). ``always_face`` solves the load along the face even without deviations (for the report);
    ``deviations=False`` leaves the model's deviations out (the stiffness of the flanks as they are)."""
    if not deviations:
        helical = operating_helical_pair(mesh_model)
        scale = _stiffness_scale(mesh_model)
        phase = (np.arange(points) + 0.5) / points * helical.transverse.base_pitch
        total = scale * helical_mesh_stiffness(helical, mesh_model.case.material, phase).stiffness
        return HelicalMeshPeriod(helical, phase, load, total, load / total, None, scale)
    helical = operating_helical_pair(mesh_model)
    transverse = helical.transverse
    scale = _stiffness_scale(mesh_model)
    material = mesh_model.case.material
    phase = (np.arange(points) + 0.5) / points * transverse.base_pitch
    z, stiffness = contact_stiffness(helical, material, phase, slices)
    stiffness = scale * stiffness
    lead = _lead_gap(mesh_model, helical, z)
    entries_along_path = _slice_positions(helical, phase, z)
    points_on_path = transverse.path_points
    inside = stiffness > 0.0
    profile = np.zeros(stiffness.shape)
    if inside.any():
        roll = np.clip(points_on_path["A"] + entries_along_path[inside], points_on_path["A"], points_on_path["E"])
        profile[inside] = mesh_model.pair_deviation_at(roll)
    gap = profile + lead
    if not np.any(gap) and not always_face:
        total = scale * helical_mesh_stiffness(helical, material, phase).stiffness
        return HelicalMeshPeriod(helical, phase, load, total, load / total, None, scale)
    approach = np.empty(points)
    engaged = np.empty(points)
    line_load = np.empty((points, z.size))
    width = helical.face_width / z.size
    for index in range(points):
        approach[index], carried = slice_loads(stiffness[index], gap[index], load)
        engaged[index] = float(np.sum(np.where(carried > 0.0, stiffness[index].ravel(), 0.0)))
        line_load[index] = carried.reshape(stiffness.shape[1:]).sum(axis=0) / width
    face = FaceLoad(z, phase, line_load, approach)
    return HelicalMeshPeriod(helical, phase, load, engaged, approach, face, scale)


def _slice_positions(helical: HelicalPair, phase: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Path position s [m] from A of each slice on each contact line, shape (phases, lines, slices)."""
    from thermogear.helical.contact_lines import line_entries

    transverse = helical.transverse
    entries = line_entries(phase, transverse.path_length, helical.face_advance, transverse.base_pitch)
    return entries[..., None] + z * math.tan(helical.base_helix_angle)


def helical_model_state(mesh_model: MeshModel, transverse_state: MeshState, speed: float, load: float,
                        points: int, damping: bool) -> MeshState:
    """The :class:`MeshState` of the case's helical pair (module docstring); ``transverse_state`` is the model's
    state of the transverse section at the same point, whose c̄/k̄ gives the friction damping."""
    period = helical_mesh_period(mesh_model, load, points)
    if damping and transverse_state.mean_mesh_stiffness > 0.0:
        ratio = float(transverse_state.grid.time_average(transverse_state.mesh_damping)) \
            / transverse_state.mean_mesh_stiffness
        mesh_damping = ratio * period.stiffness
    else:
        mesh_damping = np.zeros(points)
    deviation = period.deviation
    transverse = period.helical.transverse
    return mesh_state_from_arrays(np.arange(points) / points, period.stiffness, damping=mesh_damping,
                                  deviation=deviation if np.any(deviation) else None, speed_rpm=speed,
                                  normal_load=load, mass=transverse_state.mass, pinion_teeth=transverse.pinion.teeth,
                                  backlash=transverse_state.backlash, face_width=period.helical.face_width,
                                  model=transverse_state.model)
