"""Heat in the drivetrain: a warm state of the shafts and the mesh, and each mode's frequency shift from cold to hot
attributed to the element that causes it.

What heat changes here: the shafts' Young's and shear moduli, E(T) = E(20 °C)·[1 + β_E (T − 20 °C)] with the same
β_E as the gears' material (the linear fit of :mod:`thermogear.thermoelastic.materials`; ν held, so G scales with
E); the mesh stiffness (the hot mesh state's mean: E(T) of the teeth and the hot path of contact); and the mesh
geometry — base radii and operating pressure angle of the hot pair, whose centre distance the housing's growth has
moved (the thermo-elastic mesh of :mod:`thermogear.thermoelastic.mesh`). Not changed (a stated limitation): the
masses and inertias (a gear's polar inertia grows by 2ε ≈ 1.6e-3 at 70 K, about a tenth of the E(T) effect on
frequency) and the bearings' stiffness.

Attribution by first-order perturbation of K φ = ω² M φ with M-normalised shapes (Rayleigh; e.g. Géradin &
Rixen, Mechanical Vibrations, 3rd ed. 2015, §2.8 on eigenvalue sensitivity): with the mass unchanged,

    δ(ω_i²) = φ_iᵀ δK φ_i = Σ_j φ_iᵀ δK_j φ_i,   so   δ(ω_i²)/ω_i² = Σ_j e_ij·(φ_iᵀ δK_j φ_i / φ_iᵀ K_j φ_i),

e_ij the modal strain-energy share of element j; for an element whose stiffness only scales, K_j → (1 + δk_j/k_j)K_j
(a shaft's E(T), the mesh stiffness), the bracket is δk_j/k_j and δ(ω²)/ω² = Σ_j e_ij·δk_j/k_j. The frequency
shift follows as δf/f = ½·δ(ω²)/ω². The mesh's change is split into its stiffness part (k_h − k_c)·w_c w_cᵀ and its
geometry part k_h·(w_h w_hᵀ − w_c w_cᵀ). The attributions add up to the exact re-solved shift to first order in
the changes (a test checks that the remainder falls as their square). Modes are paired cold–hot by rank; a pair of
equal frequencies (x/y twins of a round shaft) shares its attribution only as a sum.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from thermogear.drivetrain.assembly import Drivetrain
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.errors import CaseError
from thermogear.thermoelastic.materials import MODULUS_REFERENCE_C, youngs_modulus_at

__all__ = ["WarmState", "ModeShifts", "warm_drivetrain", "thermal_mode_shifts"]


@dataclass(frozen=True)
class WarmState:
    """What heat changes: ``shaft_temperature_c`` shaft name → uniform temperature [°C] (others stay at 20 °C);
    ``modulus_coefficient_per_k`` β_E [1/K]; the hot mesh's ``mesh_stiffness`` [N/m], ``base_radius_1``,
    ``base_radius_2`` [m] and ``operating_pressure_angle`` [rad] (None keeps the cold value)."""

    shaft_temperature_c: Mapping[str, float]
    modulus_coefficient_per_k: float
    mesh_stiffness: float | None = None
    base_radius_1: float | None = None
    base_radius_2: float | None = None
    operating_pressure_angle: float | None = None

    def __post_init__(self) -> None:
        if not -1e-3 <= float(self.modulus_coefficient_per_k) <= 0.0:
            raise CaseError("modulus_coefficient_per_k", self.modulus_coefficient_per_k, "[-1e-3, 0] 1/K",
                            "β_E of E(T) = E(20 °C)·[1 + β_E (T − 20 °C)]")
        for name, temperature in self.shaft_temperature_c.items():
            if not -50.0 <= float(temperature) <= 200.0:
                raise CaseError(f"shaft_temperature_c.{name}", temperature, "[-50, 200] °C",
                                "the range of the E(T) fit")


def warm_drivetrain(drivetrain: Drivetrain, warm: WarmState) -> Drivetrain:
    """The drivetrain in the warm state (shaft moduli at temperature; the first mesh with the hot stiffness and
    geometry)."""
    names = {shaft.name for shaft in drivetrain.shafts}
    unknown = sorted(set(warm.shaft_temperature_c) - names)
    if unknown:
        raise CaseError("shaft_temperature_c", unknown, f"shaft names among {sorted(names)}", "a shaft by name")
    shafts = []
    for shaft in drivetrain.shafts:
        temperature = warm.shaft_temperature_c.get(shaft.name, MODULUS_REFERENCE_C)
        ratio = youngs_modulus_at(1.0, warm.modulus_coefficient_per_k, temperature)
        segments = []
        for segment in shaft.segments:
            material = segment.material
            hot = replace(material, youngs_modulus=material.youngs_modulus * ratio,
                          shear_modulus=None if material.shear_modulus is None else material.shear_modulus * ratio)
            segments.append(replace(segment, material=hot))
        shafts.append(replace(shaft, segments=tuple(segments)))
    meshes = list(drivetrain.meshes)
    if meshes:
        changes = {key: getattr(warm, key) for key in ("base_radius_1", "base_radius_2", "operating_pressure_angle")
                   if getattr(warm, key) is not None}
        if warm.mesh_stiffness is not None:
            changes["stiffness"] = warm.mesh_stiffness
        meshes[0] = replace(meshes[0], **changes)
    return replace(drivetrain, shafts=tuple(shafts), meshes=tuple(meshes))


@dataclass(frozen=True, eq=False)
class ModeShifts:
    """Per mode (lowest first): ``cold_hz``, ``hot_hz`` [Hz], ``labels`` (cold), ``exact`` δf/f = f_h/f_c − 1 [-],
    and ``contributions`` cause → first-order δf/f [-] (each shaft's E(T) by shaft name, each other element by name,
    the mesh as "<mesh> stiffness" and "<mesh> geometry")."""

    cold_hz: np.ndarray
    hot_hz: np.ndarray
    labels: tuple[str, ...]
    exact: np.ndarray
    contributions: dict[str, np.ndarray]

    @property
    def first_order(self) -> np.ndarray:
        """Σ of the contributions: the first-order δf/f [-]."""
        return sum(self.contributions.values(), np.zeros_like(self.exact))

    def dominant_cause(self, mode: int) -> str:
        """The cause with the largest |contribution| to one mode's shift."""
        return max(self.contributions, key=lambda name: abs(self.contributions[name][mode]))


def thermal_mode_shifts(cold: Drivetrain, hot: Drivetrain, count: int = 12) -> ModeShifts:
    """Cold and hot modes (undamped, mean mesh stiffness of each mesh element) and the attribution of each mode's
    shift (module docstring). ``cold`` and ``hot`` must be the same drivetrain in two states
    (:func:`warm_drivetrain`)."""
    cold_assembled, hot_assembled = cold.assemble(), hot.assemble()
    if (cold_assembled.size != hot_assembled.size or np.abs(cold_assembled.mass - hot_assembled.mass).max()
            > 1e-12 * np.abs(cold_assembled.mass).max()):  # rounding of E/G in the Timoshenko mass terms only
        raise CaseError("hot", "another layout or other masses", "the cold drivetrain with changed stiffnesses",
                        "the attribution compares one drivetrain in two states")
    cold_modes = drivetrain_modes(cold_assembled, count=count)
    hot_modes = drivetrain_modes(hot_assembled, count=count)
    shapes = cold_modes.shapes
    omega_squared = cold_modes.angular_frequencies**2

    def relative(change: np.ndarray) -> np.ndarray:  # ½ φᵀδKφ/ω²
        return 0.5 * np.einsum("ij,ik,kj->j", shapes, change, shapes) / omega_squared

    contributions = {name: relative(hot_assembled.stiffness_groups[name] - matrix)
                     for name, matrix in cold_assembled.stiffness_groups.items()}
    for mesh_cold, mesh_hot, w_cold, w_hot in zip(cold.meshes, hot.meshes, cold_assembled.mesh_vectors,
                                                  hot_assembled.mesh_vectors):
        contributions[f"{mesh_cold.name} stiffness"] = relative((mesh_hot.stiffness - mesh_cold.stiffness)
                                                                * np.outer(w_cold, w_cold))
        contributions[f"{mesh_cold.name} geometry"] = relative(mesh_hot.stiffness * (np.outer(w_hot, w_hot)
                                                                                      - np.outer(w_cold, w_cold)))
    exact = hot_modes.frequencies_hz / cold_modes.frequencies_hz - 1.0
    return ModeShifts(cold_modes.frequencies_hz, hot_modes.frequencies_hz, cold_modes.labels, exact, contributions)
