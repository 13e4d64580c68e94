"""Power losses of the gearbox at node temperatures, each source on its own, and the efficiency.

Tooth friction P_VZP = P_in·μ_m·H_V (Niemann & Winter §21.6) with the description's mean friction law
(:mod:`thermogear.friction.models`: Schlenk's by default, the paper's DIN 3990-4 law, ISO/TR 13989-2 or a constant) at
the oil temperature, evaluated at the pitch point (sum of rolling speeds 2·v_t·sin α_w, relative radius of curvature at
C, unit load F_bt/b). A helical pair runs as its transverse section with its helix: H_V with Ohlendorf's 1/cos β_b, the
relative radius of curvature of the normal section ρ_t/cos β_b, the helical load factor K_Bγ(ε_γ) in the ISO/TR 13989
law (all three as in ISO/TR 13989 and checked against a KISSsoft printout of a helical pair, tests/validation), the
churning of its teeth with their helix (:mod:`~thermogear.gearbox.churning`); the unit load stays F_bt/b (the transverse
base tangential force, T1/r_b1, as the laws define it). Bearings by the SKF model at the viscosity of the oil at the
shaft node's temperature, radial load a fraction of the tooth normal force (for a drivetrain bearing its static force
per newton of tooth load, :mod:`~thermogear.gearbox.bearing_entries`); lip seals; churning of the dipped gears at the
oil temperature (:mod:`~thermogear.gearbox.churning`); the impulse loss of an into-mesh oil jet where the description
has one (injection lubrication, :mod:`~thermogear.gearbox.injection`). Heat goes to the nodes as: tooth friction to
pinion and wheel by the description's share (Blok's partition over the path unless given), each bearing and seal to the
node of the shaft it sits on (each bearing at the oil viscosity of its own shaft's temperature), churning and the jet's
impulse loss to the oil.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from thermogear.errors import ExtrapolationWarning
from thermogear.friction.models import PitchContact, helical_load_factor, normal_section_radius
from thermogear.gearbox.bearing_entries import mounted_bearing_power
from thermogear.gearbox.bearing_loss import seal_power_loss
from thermogear.gearbox.churning import DippedGear, churning_power_loss, churning_validity
from thermogear.gearbox.description import GearboxDescription, GearboxOperatingPoint
from thermogear.gearbox.injection import jet_impulse_power, jet_validity
from thermogear.gearbox.mesh_loss import mesh_power_loss, pair_gear_loss_factor

#: The nodes of the gearbox network, in this order: the two gear bodies, the two shafts with their bearings (each
#: shaft its own node), the oil sump and the housing.
NODES = ("pinion", "wheel", "pinion_shaft", "wheel_shaft", "oil", "housing")
PINION, WHEEL, PINION_SHAFT, WHEEL_SHAFT, OIL, HOUSING = range(len(NODES))


def node_temperature(node: int, array: str) -> property:
    """A property of a result holding one temperature per node of :data:`NODES` in its field ``array``: the
    temperature of ``node`` [°C]."""
    return property(lambda result: float(getattr(result, array)[node]),
                    doc=f"Temperature of the {NODES[node].replace('_', ' ')} [°C].")

REFERENCE_VISCOSITY = 0.01  # [Pa·s], where the friction coefficient is evaluated once (any value would do)


@dataclass(frozen=True)
class PowerLosses:
    """Losses by source [W] at one state, the mean friction coefficient and the input power [W]."""

    mesh: float
    bearings: float
    seals: float
    churning: float
    friction_coefficient: float
    input_power: float
    pinion_heat_share: float
    injection: float = 0.0  # impulse loss of the oil jet (injection lubrication) [W]
    wheel_shaft_heat: float = 0.0  # the part of bearings + seals on the wheel shaft [W] (the rest on the pinion's)

    @property
    def total(self) -> float:
        """Σ losses [W]."""
        return self.mesh + self.bearings + self.seals + self.churning + self.injection

    @property
    def efficiency(self) -> float:
        """η = 1 − P_loss/P_in [–] (0 input power: 0)."""
        return 1.0 - self.total / self.input_power if self.input_power > 0.0 else 0.0

    @property
    def node_sources(self) -> np.ndarray:
        """Heat into the nodes of :data:`NODES` [W]: pinion, wheel, pinion shaft, wheel shaft, oil, housing."""
        share = self.pinion_heat_share
        return np.array([share * self.mesh, (1.0 - share) * self.mesh,
                         self.bearings + self.seals - self.wheel_shaft_heat, self.wheel_shaft_heat,
                         self.churning + self.injection, 0.0])


def _dipped(description: GearboxDescription, wheel: bool) -> DippedGear | None:
    depth = description.wheel_immersion if wheel else description.pinion_immersion
    if depth <= 0.0:
        return None
    pair = description.gear_pair
    gear = pair.wheel if wheel else pair.pinion
    pitch_radius = pair.operating_pitch_radii[1 if wheel else 0]
    height = (gear.addendum_coefficient + gear.dedendum_coefficient) * gear.module
    return DippedGear(pitch_radius, gear.face_width, gear.module, gear.teeth, height, min(depth, 2 * pitch_radius),
                      description.oil_volume, gear.pressure_angle, description.helix_angle)


@dataclass(frozen=True, eq=False)
class LossModel:
    """The losses of one gearbox at one operating point, as functions of the node temperatures [°C]."""

    description: GearboxDescription
    operating: GearboxOperatingPoint

    def __post_init__(self) -> None:
        pair = self.description.gear_pair
        loss_factor = self.description.loss_factor
        object.__setattr__(self, "_loss_factor", pair_gear_loss_factor(pair, self.description.base_helix_angle)
                           if loss_factor is None else float(loss_factor))
        object.__setattr__(self, "_dipped", (_dipped(self.description, False), _dipped(self.description, True)))
        object.__setattr__(self, "_reference_friction", self._friction_at_viscosity(REFERENCE_VISCOSITY))
        object.__setattr__(self, "_heat_share", self.description.heat_share)
        for gear in self._dipped:
            message = None if gear is None else churning_validity(gear)
            if message:
                warnings.warn(message, ExtrapolationWarning, stacklevel=3)
        jet = self.description.oil_jet
        message = None if jet is None else jet_validity(jet, self.pitch_line_speed)
        if message:
            warnings.warn(message, ExtrapolationWarning, stacklevel=3)

    @property
    def pitch_line_speed(self) -> float:
        """v_t = ω1·r_w1 [m/s] (operating pitch circle)."""
        return self.operating.speed_rpm * math.pi / 30.0 * self.description.gear_pair.operating_pitch_radii[0]

    def _friction_at_viscosity(self, viscosity: float) -> float:
        pair, description = self.description.gear_pair, self.description
        if self.operating.torque == 0.0:
            return 0.0
        pitch = pair.path_points["C"]
        rolling_1, rolling_2 = pair.rolling_speeds(pitch, self.operating.speed_rpm)
        contact = PitchContact(self.normal_force / pair.face_width, description.roughness, viscosity,
                               float(rolling_1 + rolling_2),
                               normal_section_radius(float(pair.relative_radius_of_curvature(pitch)),
                                                     description.base_helix_angle),
                               description.friction_lubricant_factor,
                               helical_load_factor(description.total_contact_ratio), pair.pinion.pressure_angle)
        return description.friction.coefficient(contact, description.friction_constant)

    @property
    def loss_factor(self) -> float:
        """H_V used [–]."""
        return self._loss_factor

    @property
    def normal_force(self) -> float:
        """Tooth force along the transverse line of action F_bt = T1/r_b1 [N] (the normal force of a spur pair;
        a helical pair's is F_bt/cos β_b): the unit load's and the bearing loads' reference."""
        return self.operating.torque / self.description.gear_pair.pinion.base_radius

    def friction_coefficient(self, oil_c: float) -> float:
        """μ_m of the description's friction law at the pitch point with the oil's viscosity at ``oil_c`` [–]:
        every law is a power law μ ∝ η^e at a given load and speed (:attr:`FrictionLaw.viscosity_exponent`), so it
        is evaluated once at a reference viscosity (with its validity warnings) and scaled."""
        exponent = self.description.friction.viscosity_exponent
        if exponent == 0.0:
            return self._reference_friction
        viscosity = float(self.description.lubricant.dynamic_viscosity(oil_c, warn=False))
        return self._reference_friction * (viscosity / REFERENCE_VISCOSITY)**exponent

    def at(self, temperatures_c) -> PowerLosses:
        """Losses with the nodes of :data:`NODES` at ``temperatures_c`` [°C]."""
        temperatures = np.asarray(temperatures_c, dtype=float)
        oil_c = float(temperatures[OIL])
        description, operating = self.description, self.operating
        friction = self.friction_coefficient(oil_c)
        mesh = mesh_power_loss(operating.input_power, friction, self.loss_factor)
        pinion_rpm = operating.speed_rpm
        wheel_rpm = pinion_rpm / description.gear_pair.gear_ratio
        viscosity = {side: float(description.lubricant.kinematic_viscosity(
            float(temperatures[WHEEL_SHAFT if side else PINION_SHAFT]), warn=False)) * 1e6 for side in (False, True)}
        bearing_heat = [mounted_bearing_power(mounted, pinion_rpm, wheel_rpm, viscosity[mounted.on_wheel_shaft],
                                              self.normal_force) for mounted in description.bearings]
        seal_heat = [seal_power_loss(seal.shaft_diameter_mm, wheel_rpm if seal.on_wheel_shaft else pinion_rpm)
                     for seal in description.seals]
        bearings, seals = sum(bearing_heat), sum(seal_heat)
        wheel_side = (sum(heat for heat, mounted in zip(bearing_heat, description.bearings) if mounted.on_wheel_shaft)
                      + sum(heat for heat, seal in zip(seal_heat, description.seals) if seal.on_wheel_shaft))
        oil_viscosity = float(description.lubricant.kinematic_viscosity(oil_c, warn=False))
        density = float(description.lubricant.density(oil_c))
        churning = 0.0
        for gear, rpm in zip(self._dipped, (pinion_rpm, wheel_rpm)):
            if gear is not None:
                churning += churning_power_loss(gear, rpm * math.pi / 30.0, oil_viscosity, density)
        jet = description.oil_jet
        injection = 0.0 if jet is None else jet_impulse_power(jet, density, self.pitch_line_speed)
        return PowerLosses(mesh, float(bearings), float(seals), churning, friction, operating.input_power,
                           self._heat_share, injection, float(wheel_side))
