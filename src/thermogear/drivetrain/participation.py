"""Which modes carry a bearing's force at a mesh harmonic: the modal terms of the bearing force per unit mesh force.

A mesh excitation enters the drivetrain as a force F along the mesh vector w (the transmission-error excitation
k·e·w, or the varying part of the mesh force). At a frequency ω the force on the housing of a bearing b (stiffness
K_b at its node's translations) is, on the undamped modes φ_i (M-normalised, φ_iᵀMφ_i = 1) with modal damping
ζ_i = φ_iᵀCφ_i / (2ω_i),

    F_b(ω) / F = Σ_i K_b φ_i,b (φ_iᵀ w) / (ω_i² − ω² + 2iζ_iω_iω)

(the modal superposition of a receptance, e.g. Ewins, Modal Testing, 2nd ed., Research Studies Press 2000, §2.3;
the modal damping drops the coupling of C between modes, a ranking approximation only). The size of each term,
√(|X_i|² + |Y_i|²) in the radial plane, ranks the modes "behind" that bearing force. It ranks; it is not the
response, which the exact periodic solution gives (:mod:`thermogear.drivetrain.response`).
"""

from __future__ import annotations

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.modes import DrivetrainModes
from thermogear.errors import CaseError

__all__ = ["bearing_force_modal_terms", "bearing_force_terms"]


def bearing_force_terms(assembled: AssembledDrivetrain, modes: DrivetrainModes, bearing: str,
                        frequency_hz: float, mesh: int = 0) -> np.ndarray:
    """The radial size √(|X_i|² + |Y_i|²) [N/N] of each mode's term in the force of ``bearing`` on its housing per
    unit mesh force at ``frequency_hz`` [Hz] (module docstring); ``modes`` undamped (M-normalised real shapes)."""
    return np.hypot(*np.abs(bearing_force_modal_terms(assembled, modes, bearing, frequency_hz, mesh)))


def bearing_force_modal_terms(assembled: AssembledDrivetrain, modes: DrivetrainModes, bearing: str,
                              frequency_hz: float, mesh: int = 0) -> np.ndarray:
    """The complex terms (x, y; modes) [N/N] of the modal sum of the module docstring: their sum over every mode is
    the bearing's force per unit mesh force (exactly, where the damping is modal)."""
    found = [item for item in assembled.drivetrain.bearings if item.name == bearing]
    if not found:
        raise CaseError("bearing", bearing, f"one of {[b.name for b in assembled.drivetrain.bearings]}",
                        "bearing forces by name")
    if np.iscomplexobj(modes.shapes):
        raise CaseError("modes", "damped modes", "undamped modes (drivetrain_modes without damped or speed)",
                        "the modal terms use M-normalised real shapes")
    item = found[0]
    dofs = assembled.translation_dofs(item.location)
    shapes = modes.shapes
    omega = modes.angular_frequencies
    damping = np.einsum("ij,ij->j", shapes, assembled.damping(0.0) @ shapes)
    zeta = damping / (2.0 * omega)
    forcing = assembled.mesh_vectors[mesh] @ shapes
    excitation = 2.0 * np.pi * frequency_hz
    denominator = omega ** 2 - excitation ** 2 + 2j * zeta * omega * excitation
    forces = item.stiffness_matrix()[:2, :3] @ shapes[dofs]  # (x, y) force per unit modal coordinate
    return forces * forcing / denominator
