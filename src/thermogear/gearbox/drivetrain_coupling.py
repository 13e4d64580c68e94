"""One heated system: the gearbox thermal network sets the temperatures of the drivetrain it holds.

With ``[gearbox]``, ``[drivetrain]`` and ``[temperature].model = "gearbox"``, the network's steady state at an
operating point gives

* each drivetrain shaft its temperature: the network's node of the shaft it turns with — the pinion's shaft node for
  the pinion's shaft and the shafts coupled to it, the wheel's for the wheel's side (each shaft of the network is its
  own node, with its own bearings' losses and its own gear's conduction) —, which sets the shaft's E(T) and its free
  thermal growth in the hot drivetrain (:mod:`thermogear.drivetrain.heat`) instead of the gears' mean tooth
  temperature, an upper bound; a shaft with its own ``temperature_c`` keeps it (a shaft outside the housing); a shaft
  joined to neither side takes the mean of the two shaft nodes;
* each bearing its ring temperatures: the inner ring at its shaft's node, the outer ring at the housing seat's (the
  housing node), from which its operating clearance follows (:mod:`thermogear.drivetrain.bearing_clearance`).

The bearings' losses in that network come from the same bearings (:mod:`thermogear.gearbox.bearing_entries`: the
drivetrain bearing's loss data, loaded by its static force), so the two halves describe one gearbox.

:func:`operating_point_temperatures` is the per-operating-point function: the resolved parts of a case
(:func:`coupled_parts` of the case's gearbox model and sections, built once) and a pinion speed [rpm] and torque
[N·m] give that point's own steady temperatures (every command and every study point computes its own, never the
case's point reused).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from thermogear.drivetrain.bearing_clearance import estimated_outer_raceway_diameter
from thermogear.drivetrain.heat_source import BearingRings, DrivetrainHeat
from thermogear.errors import CaseError
from thermogear.gearbox.bearing_entries import mounted_bearing_power, rolling_bearing, shaft_sides
from thermogear.gearbox.case_model import gearbox_operating_point, gearbox_section, predicted_steady_state
from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.losses import NODES

if TYPE_CHECKING:
    from thermogear.operating import OperatingPoint
    from thermogear.schema import DrivetrainSection, GearboxSection
    from thermogear.gearbox.model import GearboxSteadyState, GearboxThermalModel

__all__ = ["CoupledThermalParts", "OperatingTemperatures", "coupled_parts", "network_drivetrain_heat",
           "operating_point_temperatures"]

_MM = 1e-3


@dataclass(frozen=True, eq=False)
class CoupledThermalParts:
    """What a case resolves once for its coupled temperatures: the gearbox ``model`` (whose bearings are the
    drivetrain's), the ``ambient_c`` [°C], the drivetrain's ``shafts`` name → True where it turns with the wheel,
    False with the pinion, None with neither, ``raceways`` bearing name → outer raceway diameter [m] (None: size
    unknown, clearance held) and ``bearing_shafts`` bearing name → the shaft it sits on."""

    model: "GearboxThermalModel"
    ambient_c: float
    shafts: dict[str, bool | None]
    raceways: dict[str, float | None]
    bearing_shafts: dict[str, str]


@dataclass(frozen=True, eq=False)
class OperatingTemperatures:
    """The steady temperatures of one operating point: the network's ``state`` (nodes, losses, energy balance), the
    drivetrain's ``heat`` (shafts and bearing rings) and each drivetrain bearing's loss [W] by name."""

    speed_rpm: float
    torque: float
    state: "GearboxSteadyState"
    heat: DrivetrainHeat
    bearing_losses: dict[str, float]


def _raceway(section) -> float | None:
    """Outer raceway diameter [m] of a drivetrain bearing from its loss data (given, else estimated from d, D)."""
    loss = section.loss
    if loss is None:
        return None
    if loss.outer_raceway_diameter_mm is not None:
        return loss.outer_raceway_diameter_mm * _MM
    bearing = rolling_bearing(loss)
    return estimated_outer_raceway_diameter(bearing.bore_mm, bearing.outside_mm) * _MM


def coupled_parts(model: "GearboxThermalModel", gearbox: "GearboxSection | None",
                  section: "DrivetrainSection | None") -> CoupledThermalParts:
    """The :class:`CoupledThermalParts` of a case with ``[gearbox]`` and ``[drivetrain]``: its gearbox ``model``
    (:func:`~thermogear.gearbox.case_model.gearbox_model_from_case`, memoised per case), its ``[gearbox]`` section
    (the ambient) and its ``[drivetrain]`` ``section`` (the shafts' sides and bearings)."""
    if section is None:
        raise CaseError("drivetrain", None, "a [drivetrain] section", "the network's temperatures set a drivetrain")
    sides = shaft_sides(section)
    return CoupledThermalParts(model, gearbox_section(gearbox).ambient_c,
                               {shaft.name: sides.get(shaft.name) for shaft in section.shafts},
                               {bearing.name: _raceway(bearing) for bearing in section.bearings},
                               {bearing.name: bearing.shaft for bearing in section.bearings})


def operating_point_temperatures(parts: CoupledThermalParts, speed_rpm: float,
                                 torque: float) -> OperatingTemperatures:
    """The steady temperatures of the coupled system at a pinion speed [rpm] and torque [N·m] (module docstring):
    the network solved at that point (once per model and point, :func:`~thermogear.gearbox.case_model.
    predicted_steady_state`; raises NoSteadyStateError where it has none), each shaft at its side's shaft node,
    each bearing's inner ring at its shaft's and outer ring at the housing node, and each drivetrain bearing's
    loss (at the oil viscosity of its shaft node, as in the network)."""
    operating = GearboxOperatingPoint(float(speed_rpm), float(torque), parts.ambient_c)
    state = predicted_steady_state(parts.model, operating)
    side_c = {False: state.pinion_shaft_c, True: state.wheel_shaft_c,
              None: 0.5 * (state.pinion_shaft_c + state.wheel_shaft_c)}
    shaft_c = {name: side_c[side] for name, side in parts.shafts.items()}
    housing_c = state.housing_c
    description = parts.model.description
    normal_force = parts.model.losses(operating).normal_force
    wheel_rpm = operating.speed_rpm / description.gear_pair.gear_ratio
    mounted = {item.name: item for item in description.bearings if item.name is not None}
    bearing_losses = {name: mounted_bearing_power(item, operating.speed_rpm, wheel_rpm, float(
        description.lubricant.kinematic_viscosity(side_c[item.on_wheel_shaft], warn=False)) * 1e6, normal_force)
        for name, item in mounted.items()}
    rings = {name: BearingRings(shaft_c[parts.bearing_shafts[name]], housing_c, raceway,
                                None if name not in mounted else mounted[name].load_fraction * normal_force,
                                bearing_losses.get(name)) for name, raceway in parts.raceways.items()}
    source = (f"gearbox thermal network, each shaft at its shaft node (steady state at {operating.speed_rpm:g} "
              f"rpm, {operating.torque:g} N·m)")
    heat = DrivetrainHeat(shaft_c, rings, source, dict(zip(NODES, (float(value) for value in state.temperatures_c))))
    return OperatingTemperatures(operating.speed_rpm, operating.torque, state, heat, bearing_losses)


def network_drivetrain_heat(gearbox_model: "GearboxThermalModel | None", gearbox: "GearboxSection | None",
                            drivetrain: "DrivetrainSection | None", operating_point: "OperatingPoint") -> DrivetrainHeat:
    """The drivetrain's temperatures at the case's own operating point: the steady state of the case's network
    ``gearbox_model`` (the ``"gearbox"`` provider of :data:`thermogear.composition.DRIVETRAIN_HEAT`, which receives
    these pieces of the case, :mod:`thermogear.case.pieces`)."""
    operating = gearbox_operating_point(operating_point, gearbox)
    parts = coupled_parts(gearbox_model, gearbox, drivetrain)
    return operating_point_temperatures(parts, operating.speed_rpm, operating.torque).heat
