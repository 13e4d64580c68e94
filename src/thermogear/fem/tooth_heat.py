"""Bulk temperature of one gear's tooth (docs/fem.md): steady 2-D conduction in a one-tooth sector from the
bore to the tip, time-averaged friction heat on the meshing flank, convection elsewhere, end faces as a sink.

Model (all assumptions stated in docs/fem.md):
- domain: one tooth sector (angular width 2π/z), cut faces adiabatic (cyclic symmetry);
- meshing (right) flank: q̄ = γ β μ F′ v_s/(2π ρ) over the path A–E (:func:`heat.mean_flank_heat_flux`), μ from
  the DIN 3990-4 formula (Luo & Li Eq. 27) with the pair's elastic load share and the oil viscosity at the
  operating oil temperature, β Blok's partition; plus convection h_m;
- other flank, fillets and root: h_n; tip: h_t; end faces: sink 2 h_e / b in 2-D; bore adiabatic or h_bore;
- ambient: the operating oil temperature ``[lubricant].operating_temperature_c``.
Coefficients not given in ``[fem]`` come from the correlations of docs/fem.md, unverified with oil–air mist
properties (:func:`convection_coefficients`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import skfem
from matplotlib.path import Path as PolygonPath

from thermogear import warning_scope
from thermogear.errors import ExtrapolationWarning
from thermogear.fem.heat import (RobinBoundary, blok_heat_partition, mean_flank_heat_flux, mist_properties,
                                 rotating_disc_coefficient, solve_steady_conduction, tooth_surface_coefficient)
from thermogear.fem.sampling import probe_matrix
from thermogear.fem.tooth_mesh import ToothMesh, nominal_bore_radius, tooth_mesh
from thermogear.schema.fem import FemSection

if TYPE_CHECKING:
    from thermogear.fem.inputs import FemInputs
    from thermogear.lubricant import Lubricant
    from thermogear.schema.lubricant import LubricantSection

#: Oil properties used by the correlations when the case does not give them (typical mineral/PAO gear oil).
DEFAULT_OIL_CONDUCTIVITY = 0.14  # [W/(m K)] (Luo & Li Table 1)
DEFAULT_OIL_SPECIFIC_HEAT = 2000.0  # [J/(kg K)] (Luo & Li Table 1)

#: Distance by which probe points on a flank are moved into the tooth [m] (the polygon's chords lie inside the
#: convex involute by < 1 μm at the default spacing).
INWARD_OFFSET = 2e-6


@dataclass(frozen=True)
class BoreCondition:
    """The thermal condition at the bore (``[fem] bore``): ``convective`` (a heat-transfer coefficient, given or the
    end face's) or adiabatic (no flux)."""

    name: str
    convective: bool


#: The bore conditions by name: the one place the names are compared.
BORE_CONDITIONS: dict[str, BoreCondition] = {condition.name: condition for condition in (
    BoreCondition("adiabatic", convective=False), BoreCondition("convective", convective=True))}


def gear_of(gear_pair, which: str):
    """The ``which`` gear (``"pinion"`` or ``"wheel"``) of a gear pair."""
    if which not in ("pinion", "wheel"):
        raise ValueError(f"gear must be 'pinion' or 'wheel', not {which!r}")
    return getattr(gear_pair, which)


def angular_speed(gear_pair, speed_rpm: float, which: str) -> float:
    """ω of the gear [rad/s] at the pinion speed ``speed_rpm`` [rpm]."""
    omega = speed_rpm * math.pi / 30.0
    return omega if which == "pinion" else omega / gear_pair.gear_ratio


@dataclass(frozen=True)
class ConvectionCoefficients:
    """Convection coefficients [W/(m² K)] and where each comes from."""

    meshing_flank: float
    passive_flank: float
    tip: float
    end_face: float
    bore: float
    sources: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        return {"meshing_flank": self.meshing_flank, "passive_flank": self.passive_flank, "tip": self.tip,
                "end_face": self.end_face, "bore": self.bore, "sources": dict(self.sources)}


def convection_coefficients(gear_pair, oil: "Lubricant", section: "LubricantSection", settings: FemSection,
                            which: str, speed_rpm: float) -> ConvectionCoefficients:
    """Convection coefficients of one gear: the ``[fem]`` values where given, else the correlations of
    docs/fem.md evaluated with oil–air mist properties (oil fraction ``[fem].oil_fraction``) at the operating
    oil temperature: flanks and tip h = 0.228 Re^0.731 Pr^(1/3) k/L (L = tooth depth, r = reference radius), end
    faces the laminar rotating disc h = 0.308 k (m + 2)^0.5 Pr^0.5 (ω/ν)^0.5 with m = 2; a convective bore without
    a value takes the end-face coefficient. ``which`` gear of ``gear_pair``; ``oil`` the lubricant of the
    ``[lubricant]`` section ``section``; ``settings`` the ``[fem]`` section; ``speed_rpm``: the pinion speed
    [rpm]."""
    gear = gear_of(gear_pair, which)
    temperature = section.operating_temperature_c
    mist = mist_properties(settings.oil_fraction,
                           section.thermal_conductivity_w_per_m_k or DEFAULT_OIL_CONDUCTIVITY,
                           float(oil.density(temperature)),
                           section.specific_heat_j_per_kg_k or DEFAULT_OIL_SPECIFIC_HEAT,
                           float(oil.dynamic_viscosity(temperature, warn=False)))
    omega = angular_speed(gear_pair, float(speed_rpm), which)
    depth = gear.tip_radius - gear.root_radius
    surface = tooth_surface_coefficient(mist["k"], mist["prandtl"], omega, gear.reference_radius, depth, mist["nu"])
    end_face = rotating_disc_coefficient(mist["k"], mist["prandtl"], omega, mist["nu"])
    values, sources = {}, {}
    for name, correlation, label in (("meshing_flank", surface, "tooth-surface correlation"),
                                     ("passive_flank", surface, "tooth-surface correlation"),
                                     ("tip", surface, "tooth-surface correlation"),
                                     ("end_face", end_face, "rotating-disc correlation")):
        given = getattr(settings, f"{name}_h_w_per_m2_k")
        values[name] = float(correlation if given is None else given)
        sources[name] = label if given is None else "given"
    if BORE_CONDITIONS[settings.bore].convective:
        given = settings.bore_h_w_per_m2_k
        values["bore"] = values["end_face"] if given is None else float(given)
        sources["bore"] = "end-face coefficient" if given is None else "given"
    else:
        values["bore"] = 0.0
        sources["bore"] = "adiabatic"
    return ConvectionCoefficients(**values, sources=sources)


@dataclass(frozen=True)
class FlankHeatInput:
    """Time-averaged friction heat flux on one gear's flank at its own roll distances ρ (from its base-circle
    tangency point, increasing outwards) [m] → q̄ [W/m²]; zero outside the path of contact."""

    roll: np.ndarray
    flux: np.ndarray
    friction_coefficient: np.ndarray
    heat_share: np.ndarray
    base_radius: float  # of the gear [m]: the flank point at (x, y) has ρ = sqrt(x² + y² − r_b²)

    def __call__(self, x, y):
        return np.interp(np.sqrt(np.maximum(x**2 + y**2 - self.base_radius**2, 0.0)), self.roll, self.flux,
                         left=0.0, right=0.0)


def flank_heat_input(mesh, which: str, settings: FemSection, count: int = 201) -> FlankHeatInput:
    """q̄ along the flank of ``which`` gear (module docstring). μ, the pair's load share and unit load come from the
    mesh model's friction damping (:meth:`~thermogear.mesh.model.MeshModel.pair_damping_at`) of ``mesh`` (the
    ``friction`` model of :func:`thermogear.fem.inputs.fem_inputs`: the oil at the operating temperature); the speed
    is the mesh model's; ``settings`` the case's ``[fem]`` section."""
    pair = mesh.gear_pair
    roll = pair.roll_grid(count)
    speed = mesh.speed_rpm
    with warning_scope.ignored(ExtrapolationWarning):  # the damping model reports the friction limits
        contact = mesh.pair_damping_at(roll)
    friction = np.asarray(contact.friction_coefficient, dtype=float)
    rolling_1, rolling_2 = pair.rolling_speeds(roll, speed)
    pinion_share = (blok_heat_partition(rolling_1, rolling_2) if settings.pinion_heat_share is None
                    else np.full(roll.shape, settings.pinion_heat_share))
    sliding = pair.sliding_speed(roll, speed)
    if which == "pinion":
        own_roll, share = roll, pinion_share
    else:
        own_roll, share = pair.line_of_action_length - roll, 1.0 - pinion_share
    flux = mean_flank_heat_flux(share, friction, contact.unit_load, sliding, own_roll,
                                settings.heat_conversion_factor)
    order = np.argsort(own_roll)
    return FlankHeatInput(own_roll[order], np.asarray(flux)[order], friction[order], np.asarray(share)[order],
                          base_radius=gear_of(pair, which).base_radius)


@dataclass(frozen=True, eq=False)
class ToothTemperature:
    """Steady bulk temperature of one gear's tooth sector [°C] (P2 field on ``mesh``)."""

    which: str
    mesh: ToothMesh
    basis: skfem.CellBasis
    values: np.ndarray  # [°C] at the dofs
    coefficients: ConvectionCoefficients
    heat_input: FlankHeatInput
    oil_c: float

    @property
    def gear(self):
        return self.mesh.gear

    def at(self, x, y) -> np.ndarray:
        """Temperature [°C] at points (x, y) [m] of the tooth frame; points in other teeth are rotated into the
        sector (the field repeats tooth by tooth)."""
        x = np.asarray(x, dtype=float)
        y = np.asarray(y, dtype=float)
        pitch = 2.0 * math.pi / self.gear.teeth
        angle = np.arctan2(x, y)
        wrapped = (angle + 0.5 * pitch) % pitch - 0.5 * pitch
        radius = np.hypot(x, y)
        points = np.vstack([(radius * np.sin(wrapped)).ravel(), (radius * np.cos(wrapped)).ravel()])
        return (probe_matrix(self.basis, points) @ self.values).reshape(x.shape)

    def flank_c(self, own_roll) -> np.ndarray:
        """Temperature [°C] of the meshing flank at the gear's own roll distances ρ [m]."""
        own_roll = np.asarray(own_roll, dtype=float)
        radius = np.hypot(self.gear.base_radius, own_roll)
        angle = np.asarray(self.gear.half_angle_at(radius)) - INWARD_OFFSET / radius
        return self.at(radius * np.sin(angle), radius * np.cos(angle))

    def circle_mean_c(self, radius: float, count: int = 61) -> float:
        """Mean temperature [°C] over the part of the circle of ``radius`` inside the sector."""
        pitch = math.pi / self.gear.teeth
        angle = np.linspace(-pitch, pitch, count)
        points = np.column_stack([radius * np.sin(angle), radius * np.cos(angle)])
        inside = PolygonPath(self.mesh.outline.points).contains_points(points, radius=-INWARD_OFFSET)
        inside |= PolygonPath(self.mesh.outline.points).contains_points(points, radius=INWARD_OFFSET)
        chosen = points[inside]
        return float(np.mean(self.at(chosen[:, 0], chosen[:, 1])))

    @property
    def base_c(self) -> float:
        """Mean temperature on the base circle [°C] (t_b of Luo & Li Eq. 10)."""
        return self.circle_mean_c(self.gear.base_radius)

    @property
    def bore_c(self) -> float:
        """Mean temperature at the bore [°C] (t_n of Eq. 10)."""
        return self.circle_mean_c(self.mesh.outline.bore_radius * (1.0 + 1e-6))

    @property
    def vertex_values(self) -> np.ndarray:
        """Temperature at the mesh vertices [°C] (for plots)."""
        return self.values[self.basis.nodal_dofs[0]]


def tooth_temperature(inputs: "FemInputs", which: str = "pinion", settings: FemSection | None = None,
                      refinement: float | None = None) -> ToothTemperature:
    """Solve the steady bulk temperature of one gear's tooth (module docstring) from a case's resolved FE inputs
    (``settings``: their ``[fem]`` section unless given)."""
    settings = settings or inputs.settings
    refinement = settings.mesh_refinement if refinement is None else refinement
    gear = gear_of(inputs.gear_pair, which)
    mesh = tooth_mesh(gear, nominal_bore_radius(gear), teeth=1, refinement=refinement)
    friction = inputs.friction  # one mesh model: the speed and the friction heat of the operating point
    coefficients = convection_coefficients(inputs.gear_pair, inputs.oil, inputs.lubricant, settings, which,
                                           friction.speed_rpm)
    heat = flank_heat_input(friction, which, settings)
    oil_c = float(inputs.lubricant.operating_temperature_c)
    facets = mesh.facets
    boundaries = [RobinBoundary(facets("active_flank"), h=coefficients.meshing_flank, ambient=oil_c, flux=heat),
                  RobinBoundary(facets("passive_flank", "fillet", "root"), h=coefficients.passive_flank,
                                ambient=oil_c),
                  RobinBoundary(facets("tip"), h=coefficients.tip, ambient=oil_c)]
    if coefficients.bore > 0.0:
        boundaries.append(RobinBoundary(facets("bore"), h=coefficients.bore, ambient=oil_c))
    sink = 2.0 * coefficients.end_face / gear.face_width
    basis, values = solve_steady_conduction(mesh.mesh, inputs.material.thermal_conductivity, boundaries, sink=sink,
                                            ambient=oil_c)
    return ToothTemperature(which, mesh, basis, values, coefficients, heat, oil_c)


__all__ = ["ConvectionCoefficients", "FlankHeatInput", "ToothTemperature", "angular_speed", "convection_coefficients",
           "flank_heat_input", "tooth_temperature"]
