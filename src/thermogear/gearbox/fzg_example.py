"""An illustrative FZG-type gearbox for examples, tests and benchmarks: FZG type C gears (ISO 14635-1) in a dip
lubricated housing. The gears are the standard's; everything about the housing, the masses of shafts and
housing, the bearing arrangement and the internal heat-transfer coefficients is ASSUMED (listed in ``notes``): it
is a plausible gearbox of that size, not a model of the FZG rig calibrated on measurements.
"""

from __future__ import annotations

import math

from thermogear.gearbox.bearing_loss import NJ406_CONSTANTS, RollingBearing
from thermogear.gearbox.description import GearboxDescription, Housing, LipSeal, MountedBearing
from thermogear.geometry import Gear, GearPair
from thermogear.lubricant import builtin_lubricant

STEEL_DENSITY = 7850.0  # [kg/m³]


def fzg_type_c_pair() -> GearPair:
    """FZG type C: m 4.5 mm, z 16/24, x 0.1817/0.1715, b 14 mm, a 91.5 mm, α 20° (ISO 14635-1), tips with the
    ISO 21771 tip shortening; bores 15 mm (30 mm shafts)."""
    pinion = Gear(16, 4.5e-3, math.radians(20.0), 14e-3, 0.1817, bore_radius=15e-3)
    wheel = Gear(24, 4.5e-3, math.radians(20.0), 14e-3, 0.1715, bore_radius=15e-3)
    return GearPair.create(pinion, wheel, 91.5e-3)


def illustrative_fzg_gearbox(**changes) -> GearboxDescription:
    """The illustrative gearbox (module docstring); keyword arguments replace description fields."""
    pair = fzg_type_c_pair()

    def disc_mass(gear: Gear) -> float:
        return STEEL_DENSITY * math.pi * (gear.tip_radius**2 - gear.bore_radius**2) * gear.face_width

    bearing = RollingBearing.cylindrical_roller(**NJ406_CONSTANTS)
    fields = dict(
        gear_pair=pair, lubricant=builtin_lubricant("iso_vg_100_mineral"),
        housing=Housing(length=0.45, width=0.30, height=0.40, mass=40.0, air_speed=1.0, oil_wetted_area=0.10),
        oil_volume=1.25e-3, pinion_mass=disc_mass(pair.pinion), wheel_mass=disc_mass(pair.wheel), shaft_mass=4.0,
        wheel_immersion=pair.operating_pitch_radii[1],
        bearings=tuple(MountedBearing(bearing, on_wheel) for on_wheel in (False, False, True, True)),
        seals=(LipSeal(30.0, False), LipSeal(30.0, True)), roughness=0.355e-6,
        notes=("housing 0.45 × 0.30 × 0.40 m, 40 kg grey cast iron, painted (ε 0.9), standing on a foundation "
               "(bottom adiabatic), air at 1 m/s along the walls (the rig's motor fan): assumed",
               "oil 1.25 L ISO VG 100 mineral (the rig's volume), wheel dipped to its centre (h = its operating pitch "
               "radius): assumed level",
               "four NJ 406 bearings (each half the tooth normal force), two 30 mm lip seals: assumed arrangement",
               "shafts with bearings 4 kg steel; internal coefficients the description's defaults: assumed"),
    )
    fields.update(changes)
    return GearboxDescription(**fields)
