"""Heat in the drivetrain: a warm state of the shafts and the mesh, and each mode's frequency shift from cold to hot
attributed to the element that causes it.

What heat changes here: the shafts' Young's and shear moduli, E(T) = E(20 °C)·[1 + β_E (T − 20 °C)] with the same
β_E as the gears' material (the linear fit of :mod:`thermogear.thermoelastic.materials`; ν held, so G scales with
E); the mesh stiffness (the hot mesh state's mean: E(T) of the teeth and the hot path of contact); and the mesh
geometry — base radii and operating pressure angle of the hot pair, whose centre distance the housing's growth has
moved (the thermo-elastic mesh of :mod:`thermogear.thermoelastic.mesh`); and, with an expansion coefficient λ, the
free thermal expansion of each shaft and the gear bodies and disks on it, ε = λ(T − 20 °C): every axial position
on the shaft (segment lengths, and so the gear, bearing and coupling seats: the bearings' inner rings ride on the
shaft, the floating bearing takes up the axial growth), its diameters grow by (1 + ε), its density falls by
(1 + ε)⁻³ (mass conserved) and the disks' inertias grow by (1 + ε)². The housing's growth moves the bearing centres
apart laterally, which is the centre distance of the hot pair above. Not changed (a stated limitation): the
bearings' stiffness and the masses.

Attribution by first-order perturbation of K φ = ω² M φ with M-normalised shapes (Rayleigh; e.g. Géradin &
Rixen, Mechanical Vibrations, 3rd ed. 2015, §2.8 on eigenvalue sensitivity): with the mass unchanged,

    δ(ω_i²) = φ_iᵀ δK φ_i = Σ_j φ_iᵀ δK_j φ_i,   so   δ(ω_i²)/ω_i² = Σ_j e_ij·(φ_iᵀ δK_j φ_i / φ_iᵀ K_j φ_i),

e_ij the modal strain-energy share of element j; for an element whose stiffness only scales, K_j → (1 + δk_j/k_j)K_j
(a shaft's E(T), the mesh stiffness), the bracket is δk_j/k_j and δ(ω²)/ω² = Σ_j e_ij·δk_j/k_j. The frequency
shift follows as δf/f = ½·δ(ω²)/ω². The mesh's change is split into its stiffness part (k_h − k_c)·w_c w_cᵀ and its
geometry part k_h·(w_h w_hᵀ − w_c w_cᵀ). The attributions add up to the exact re-solved shift to first order in
the changes (a test checks that the remainder falls as their square). The expansion's share, "thermal expansion", is the
re-solved shift from the drivetrain with hot moduli to the hot one (modes paired by rank). Its first-order
perturbation φᵀ(δK − ω²δM)φ would be exact to first order too, but here the first-order changes of K and M largely
cancel (a similarity scaling seen in translations and rotations), leaving a second-order remainder of about 24ε²
(measured: 5 % of the share at ε = 1e-3), so the share is re-solved. Modes are paired cold–hot by rank; a pair of
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

__all__ = ["WarmState", "ModeShifts", "expanded_drivetrain", "warm_drivetrain", "thermal_mode_shifts"]


@dataclass(frozen=True)
class WarmState:
    """What heat changes: ``shaft_temperature_c`` shaft name → uniform temperature [°C] (others stay at 20 °C);
    ``modulus_coefficient_per_k`` β_E [1/K]; the hot mesh's ``mesh_stiffness`` [N/m], ``base_radius_1``,
    ``base_radius_2`` [m] and ``operating_pressure_angle`` [rad] (None keeps the cold value);
    ``expansion_coefficient_per_k`` λ [1/K] of the shafts and the disks on them (0: no expansion);
    ``stage_mesh_stiffness`` the hot mean stiffness [N/m] of a train's further meshes, in order."""

    shaft_temperature_c: Mapping[str, float]
    modulus_coefficient_per_k: float
    mesh_stiffness: float | None = None
    base_radius_1: float | None = None
    base_radius_2: float | None = None
    operating_pressure_angle: float | None = None
    expansion_coefficient_per_k: float = 0.0
    stage_mesh_stiffness: tuple[float, ...] = ()

    def __post_init__(self) -> None:
        if not 0.0 <= float(self.expansion_coefficient_per_k) <= 5e-5:
            raise CaseError("expansion_coefficient_per_k", self.expansion_coefficient_per_k, "[0, 5e-5] 1/K",
                            "λ of a metal shaft (steel about 1.2e-5)")
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
        for index, stiffness in enumerate(warm.stage_mesh_stiffness, start=1):
            meshes[index] = replace(meshes[index], stiffness=stiffness)
    warm_moduli = replace(drivetrain, shafts=tuple(shafts), meshes=tuple(meshes))
    strains = {shaft.name: warm.expansion_coefficient_per_k
               * (warm.shaft_temperature_c.get(shaft.name, MODULUS_REFERENCE_C) - MODULUS_REFERENCE_C)
               for shaft in drivetrain.shafts}
    return expanded_drivetrain(warm_moduli, strains) if any(strains.values()) else warm_moduli


def expanded_drivetrain(drivetrain: Drivetrain, strains: Mapping[str, float]) -> Drivetrain:
    """The drivetrain with each shaft (by name) grown freely by its thermal strain ε [-] (module docstring):
    lengths, seat positions, diameters and the element-length limit × (1 + ε), density × (1 + ε)⁻³, the inertias of
    the disks on it × (1 + ε)²; the element layout and the masses are unchanged."""
    def grown(location):
        return replace(location, position=location.position * (1.0 + strains.get(location.shaft, 0.0)))

    shafts = []
    for shaft in drivetrain.shafts:
        scale = 1.0 + strains.get(shaft.name, 0.0)
        segments = tuple(replace(segment, length=segment.length * scale,
                                 section=replace(segment.section, outer_diameter=segment.section.outer_diameter * scale,
                                                 inner_diameter=segment.section.inner_diameter * scale),
                                 material=replace(segment.material, density=segment.material.density / scale**3))
                         for segment in shaft.segments)
        shafts.append(replace(shaft, segments=segments, maximum_element_length=shaft.maximum_element_length * scale))
    disks = tuple(replace(disk, location=grown(disk.location),
                          polar_inertia=disk.polar_inertia * (1.0 + strains.get(disk.location.shaft, 0.0))**2,
                          diametral_inertia=disk.diametral_inertia * (1.0 + strains.get(disk.location.shaft, 0.0))**2)
                  for disk in drivetrain.disks)
    return replace(drivetrain, shafts=tuple(shafts), disks=disks,
                   bearings=tuple(replace(item, location=grown(item.location)) for item in drivetrain.bearings),
                   couplings=tuple(replace(item, first=grown(item.first), second=grown(item.second))
                                   for item in drivetrain.couplings),
                   meshes=tuple(replace(item, gear_1=grown(item.gear_1), gear_2=grown(item.gear_2))
                                for item in drivetrain.meshes),
                   torsional_supports=tuple(replace(item, location=grown(item.location))
                                            for item in drivetrain.torsional_supports))


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


def thermal_mode_shifts(cold: Drivetrain, hot: Drivetrain, count: int = 12,
                        expansion_from: Drivetrain | None = None) -> ModeShifts:
    """Cold and hot modes (undamped, mean mesh stiffness of each mesh element) and the attribution of each mode's
    shift (module docstring). ``cold`` and ``hot`` must be the same drivetrain in two states
    (:func:`warm_drivetrain`); where the hot one has expanded, ``expansion_from`` is it before the expansion (the
    warm state with λ = 0): the moduli and the mesh are attributed between it and ``cold``, the expansion between
    it and ``hot``."""
    reference = hot if expansion_from is None else expansion_from
    cold_assembled, hot_assembled = cold.assemble(), hot.assemble()
    reference_assembled = hot_assembled if expansion_from is None else reference.assemble()
    if (cold_assembled.size != hot_assembled.size or reference_assembled.size != cold_assembled.size
            or np.abs(cold_assembled.mass - reference_assembled.mass).max()
            > 1e-12 * np.abs(cold_assembled.mass).max()):  # rounding of E/G in the Timoshenko mass terms only
        raise CaseError("hot", "another layout or other masses", "the cold drivetrain with changed stiffnesses "
                        "(an expanded one with expansion_from, its state before the expansion)",
                        "the attribution compares one drivetrain in two states")
    cold_modes = drivetrain_modes(cold_assembled, count=count)
    hot_modes = drivetrain_modes(hot_assembled, count=count)
    shapes = cold_modes.shapes
    omega_squared = cold_modes.angular_frequencies**2

    def relative(change: np.ndarray) -> np.ndarray:  # ½ φᵀδKφ/ω²
        return 0.5 * np.einsum("ij,ik,kj->j", shapes, change, shapes) / omega_squared

    contributions = {name: relative(reference_assembled.stiffness_groups[name] - matrix)
                     for name, matrix in cold_assembled.stiffness_groups.items()}
    for mesh_cold, mesh_hot, w_cold, w_hot in zip(cold.meshes, reference.meshes, cold_assembled.mesh_vectors,
                                                  reference_assembled.mesh_vectors):
        contributions[f"{mesh_cold.name} stiffness"] = relative((mesh_hot.stiffness - mesh_cold.stiffness)
                                                                * np.outer(w_cold, w_cold))
        contributions[f"{mesh_cold.name} geometry"] = relative(mesh_hot.stiffness * (np.outer(w_hot, w_hot)
                                                                                      - np.outer(w_cold, w_cold)))
    if expansion_from is not None:  # re-solved, not by perturbation (module docstring)
        expanded_hz = drivetrain_modes(reference_assembled, count=count).frequencies_hz
        contributions["thermal expansion"] = hot_modes.frequencies_hz / expanded_hz - 1.0
    exact = hot_modes.frequencies_hz / cold_modes.frequencies_hz - 1.0
    return ModeShifts(cold_modes.frequencies_hz, hot_modes.frequencies_hz, cold_modes.labels, exact, contributions)
