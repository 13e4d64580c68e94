"""Modes of an assembled drivetrain, labelled: torsional / lateral (which shaft) / axial by kinetic energy, and
the share of modal strain energy in each mesh, bearing, shaft, coupling and support (Velex & Berthe 1989: modes with
a large mesh share are the tooth-critical ones)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.dynamics.modes.modal import (damped_modes, kinetic_energy_fractions, strain_energy_shares,
                                       undamped_modes)
from thermogear.dynamics.modes.rigid_body import rigid_body_reduction

__all__ = ["DrivetrainModes", "drivetrain_modes", "mode_labels"]

_MOTIONS = {"torsional": ("theta",), "lateral": ("x", "y", "alpha", "beta"), "axial": ("z",)}


@dataclass(frozen=True, eq=False)
class DrivetrainModes:
    """Elastic modes, lowest first: natural frequencies ω_n [rad/s], damping ratios ζ [-] (0 when undamped),
    shapes (DOFs, modes) on the full DOFs, a label per mode, kinetic-energy fractions per motion (torsional,
    lateral, axial) and per shaft, and strain-energy shares per named element (meshes included)."""

    angular_frequencies: np.ndarray
    damping_ratios: np.ndarray
    shapes: np.ndarray
    labels: tuple[str, ...]
    kinetic_fractions: dict[str, np.ndarray]
    shaft_fractions: dict[str, np.ndarray]
    strain_energy_shares: dict[str, np.ndarray]
    rigid_mode_count: int

    @property
    def frequencies_hz(self) -> np.ndarray:
        """f = ω_n/2π [Hz]."""
        return self.angular_frequencies / (2.0 * np.pi)

    def mesh_share(self, mesh: str) -> np.ndarray:
        """Share of the modal strain energy stored in one mesh [-] per mode."""
        return self.strain_energy_shares[mesh]


def _label(motion: dict[str, float], by_shaft: dict[tuple[str, str], float]) -> str:
    """"torsional", or the dominant motion and the shaft that carries most of its kinetic energy."""
    kind = max(motion, key=motion.get)
    if kind == "torsional":
        return "torsional"
    shafts = {shaft: value for (motion_kind, shaft), value in by_shaft.items() if motion_kind == kind}
    return f"{kind} {max(shafts, key=shafts.get)}"


def drivetrain_modes(assembled: AssembledDrivetrain, speed: float = 0.0, mesh_stiffness: np.ndarray | None = None,
                     damped: bool = False, count: int | None = None,
                     max_frequency_hz: float | None = None) -> DrivetrainModes:
    """Modes at reference speed Ω [rad/s] and mean (or given constant) mesh stiffness [N/m].

    Undamped and non-spinning by default (symmetric eigenproblem); ``damped`` or a speed > 0 takes the state-space
    eigenproblem with the structural and mesh damping and the gyroscopic matrix. Rigid-body modes (free torsion,
    unlocated axial motion) are removed by projecting on their mass-orthogonal complement.
    """
    stiffness = assembled.stiffness(mesh_stiffness)
    damping = assembled.damping(speed)
    reduction = rigid_body_reduction(assembled.mass, assembled.connection_stiffness(mesh_stiffness),
                                     assembled.rigid_candidates())
    mass_q, stiffness_q = reduction.project(assembled.mass), reduction.project(stiffness)
    if damped or speed != 0.0:
        modes = damped_modes(mass_q, reduction.project(damping), stiffness_q)
        frequencies, ratios, shapes = modes.natural_frequencies, modes.damping_ratios, modes.shapes
    else:
        modes = undamped_modes(mass_q, stiffness_q)
        frequencies, shapes = modes.angular_frequencies, modes.shapes
        ratios = np.zeros_like(frequencies)
    if count is not None:
        frequencies, ratios, shapes = frequencies[:count], ratios[:count], shapes[:, :count]
    if max_frequency_hz is not None:  # the modes up to a frequency [Hz] (the shares are computed for these only)
        kept = int(np.count_nonzero(frequencies / (2.0 * np.pi) <= max_frequency_hz))
        frequencies, ratios, shapes = frequencies[:kept], ratios[:kept], shapes[:, :kept]
    full = reduction.expand(shapes)
    kinetic, by_shaft = _kinetic_fractions(assembled, full)
    per_shaft = {name: sum(by_shaft[(kind, name)] for kind in _MOTIONS) for name in assembled.node_offsets}
    groups = dict(assembled.stiffness_groups)
    groups.update(assembled.mesh_stiffness_groups(mesh_stiffness))
    shares = strain_energy_shares(full, groups)
    return DrivetrainModes(frequencies, ratios, full, _labels(kinetic, by_shaft, frequencies.size), kinetic,
                           per_shaft, shares, reduction.rigid_modes.shape[1])


def _kinetic_fractions(assembled: AssembledDrivetrain, shapes: np.ndarray) -> tuple[dict, dict]:
    """Kinetic-energy fractions of each motion, and of each motion per shaft, of the shapes (DOFs, modes)."""
    masks = {kind: assembled.dof_mask(names) for kind, names in _MOTIONS.items()}
    kinetic = kinetic_energy_fractions(shapes, assembled.mass, masks)
    by_shaft = kinetic_energy_fractions(shapes, assembled.mass, {
        (kind, name): assembled.dof_mask(names, name) for kind, names in _MOTIONS.items()
        for name in assembled.node_offsets})
    return kinetic, by_shaft


def _labels(kinetic: dict, by_shaft: dict, count: int) -> tuple[str, ...]:
    return tuple(_label({kind: kinetic[kind][i] for kind in kinetic},
                        {key: value[i] for key, value in by_shaft.items()}) for i in range(count))


def mode_labels(assembled: AssembledDrivetrain, shapes: np.ndarray) -> tuple[str, ...]:
    """The label of each shape (DOFs, modes), real or complex, as :func:`drivetrain_modes` gives it."""
    kinetic, by_shaft = _kinetic_fractions(assembled, shapes)
    return _labels(kinetic, by_shaft, shapes.shape[1])
