"""The gearbox's rolling bearings from a case: one SKF loss model per bearing entry, and, in a case with a
``[drivetrain]``, each drivetrain bearing with its loss data carrying the drivetrain's static bearing force.

Two ways, one per situation: without a drivetrain, ``[[gearbox.bearings]]`` (per shaft, ``count`` bearings each
carrying ``load_fraction`` of the tooth normal force); with one, each ``[[drivetrain.bearings]]`` table with a
``loss`` entry is one bearing of the loss model, on the shaft it sits on, and its radial load is the magnitude of
the radial force it carries in the drivetrain's static state (:func:`thermogear.drivetrain.static_state.
static_state`: K̄ q̄ = f̄ with the torque pair of the tooth normal load). The static state is linear in the load and
the mean deviation does not move the bearing forces of a single mesh (the mesh force is W whatever the deviation),
so each bearing's force per newton of tooth normal load is solved once per case and scales with the torque. The
mean mesh stiffness of that static state is ISO 6336-1's c_γα·b (the mesh stiffness does not enter the bearing
forces of shafts on two bearings, which are statically determinate: the lever rule).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from thermogear.errors import CaseError
from thermogear.gearbox.bearing_loss import NJ406_CONSTANTS, RollingBearing
from thermogear.gearbox.description import MountedBearing

if TYPE_CHECKING:
    from thermogear.geometry import GearPair
    from thermogear.helical.geometry import HelicalPair
    from thermogear.materials import Material
    from thermogear.schema import DrivetrainSection

__all__ = ["BEARING_CONSTANTS", "BEARING_TYPES", "drivetrain_bearing_loads", "drivetrain_mounted_bearings",
           "mounted_bearing_power", "rolling_bearing", "shaft_sides"]

#: Built-in bearing constants by designation (SKF model, catalogue units).
BEARING_CONSTANTS = {"NJ406": (RollingBearing.cylindrical_roller, NJ406_CONSTANTS)}


def _cylindrical_roller(sliding_constants, **constants) -> RollingBearing:
    """A cylindrical roller bearing of an entry's constants: its two sliding constants (S1, S2)."""
    return RollingBearing.cylindrical_roller(sliding_constants=tuple(sliding_constants), **constants)


def _deep_groove_ball(sliding_constants, **constants) -> RollingBearing:
    """A deep-groove ball bearing of an entry's constants: the first sliding constant S1 (no axial load)."""
    return RollingBearing.deep_groove_ball(sliding_constant=sliding_constants[0], **constants)


#: The bearing types of an entry's ``type`` by name, each ``factory(sliding_constants, **constants)``: the one place
#: the names are compared.
BEARING_TYPES = {"cylindrical_roller": _cylindrical_roller, "deep_groove_ball": _deep_groove_ball}


def rolling_bearing(entry) -> RollingBearing:
    """The SKF loss model of a bearing entry (a ``[[gearbox.bearings]]`` table or a drivetrain bearing's ``loss``):
    a built-in designation or the type with its size and constants."""
    if entry.designation is not None:
        factory, constants = BEARING_CONSTANTS[entry.designation]
        return factory(**constants)
    return BEARING_TYPES[entry.type](entry.sliding_constants, bore_mm=entry.bore_mm, outside_mm=entry.outside_mm,
                                     width_mm=entry.width_mm, rolling_constant=entry.rolling_constant,
                                     geometry_constant=entry.geometry_constant, drag_variable=entry.drag_variable or 0.0)


def mounted_bearing_power(mounted: MountedBearing, pinion_rpm: float, wheel_rpm: float, viscosity_mm2_s: float,
                          normal_force: float) -> float:
    """Power loss [W] of one mounted bearing at its shaft's speed, the oil's kinematic viscosity [mm²/s] at the
    bearing and the radial load ``load_fraction``·F_bn [N] (SKF model, :mod:`~thermogear.gearbox.bearing_loss`)."""
    speed = wheel_rpm if mounted.on_wheel_shaft else pinion_rpm
    return mounted.bearing.moments(speed, viscosity_mm2_s, mounted.load_fraction * normal_force).power


def shaft_sides(section) -> dict[str, bool]:
    """Drivetrain shaft name → True where it turns with the wheel, False with the pinion (joined by couplings);
    shafts joined to neither are left out."""
    sides = {section.pinion.shaft: False, section.wheel.shaft: True}
    changed = True
    while changed:
        changed = False
        for coupling in section.couplings:
            for first, second in ((coupling.shaft_1, coupling.shaft_2), (coupling.shaft_2, coupling.shaft_1)):
                if first in sides and second not in sides:
                    sides[second] = sides[first]
                    changed = True
    return sides


def drivetrain_bearing_loads(section: "DrivetrainSection", pair: "GearPair", material: "Material",
                             helical_pair: "HelicalPair | None" = None) -> dict[str, float]:
    """Radial force of each bearing of the ``[drivetrain]`` ``section`` per newton of tooth normal load [N/N] in the
    static state (module docstring), the gears being the cold ``pair`` of ``material`` (the transverse section of
    ``helical_pair`` where one is given: its mesh then carries the helix, whose axial force tilts the shafts and
    loads the bearings radially too): |(F_x, F_y)| of the bearing's force on the housing at W = 1 N, W the
    mesh's load of torque r_b·W (F_bt of a helical pair)."""
    from thermogear.drivetrain.case_layout import drivetrain_from_section  # noqa: PLC0415
    from thermogear.drivetrain.static_state import static_state  # noqa: PLC0415
    from thermogear.stiffness.iso6336 import iso6336_mesh_stiffness, iso6336_single_stiffness  # noqa: PLC0415

    pinion, wheel = pair.pinion, pair.wheel
    single = iso6336_single_stiffness(pinion.teeth, wheel.teeth, pinion.profile_shift, wheel.profile_shift,
                                      material.youngs_modulus, material.youngs_modulus, pinion.dedendum_coefficient,
                                      pinion.pressure_angle, warn=False)
    stiffness = iso6336_mesh_stiffness(single, pair.contact_ratio) * pair.face_width
    helices = () if helical_pair is None else ((helical_pair.base_helix_angle, helical_pair.pinion_hand),)
    drivetrain = drivetrain_from_section(section, pair, material, stiffness, helices=helices)
    forces = static_state(drivetrain.assemble(), 1.0).bearing_forces
    return {name: float(np.hypot(force[0], force[1])) for name, force in forces.items()}


def drivetrain_mounted_bearings(section: "DrivetrainSection | None", pair: "GearPair", material: "Material",
                                helical_pair: "HelicalPair | None" = None) -> tuple[MountedBearing, ...]:
    """The bearings of the ``[drivetrain]`` ``section`` with loss data as bearings of the loss model (module
    docstring), by name, under the cold ``pair`` of ``material``; () for no section (None) or no loss data on its
    bearings."""
    if section is None or not any(bearing.loss is not None for bearing in section.bearings):
        return ()
    sides = shaft_sides(section)
    loads = drivetrain_bearing_loads(section, pair, material, helical_pair)
    mounted = []
    for bearing in section.bearings:
        if bearing.loss is None:
            continue
        if bearing.shaft not in sides:
            raise CaseError(f"drivetrain.bearings '{bearing.name}'.loss", bearing.shaft,
                            "a bearing on a shaft joined to the pinion's or the wheel's (by couplings)",
                            "its loss needs its shaft's speed, which only the gears and couplings give")
        load = loads[bearing.name]
        if not math.isfinite(load):
            raise CaseError(f"drivetrain.bearings '{bearing.name}'", load, "a finite static force",
                            "the static state of the drivetrain gives the bearing's radial load")
        mounted.append(MountedBearing(rolling_bearing(bearing.loss), sides[bearing.shaft], load, bearing.name))
    return tuple(mounted)
