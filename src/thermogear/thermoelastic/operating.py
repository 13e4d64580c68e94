"""Operating geometry at temperature: expanded gears in an expanded housing, normal backlash and jamming.

A free gear heated uniformly by ΔT is the same gear scaled by (1 + ε), ε = λ·ΔT: every radius, thickness and the
base pitch grow by (1 + ε) and every angle stays — the gear cut with module m·(1 + ε) (:func:`scaled_gear`). The
bearings sit in the housing, so the centre distance grows with the housing: a' = a·(1 + ε_h). The hot pair's
operating pressure angle follows from cos α_w' = (r_b1' + r_b2')/a' (:class:`OperatingGearPair`).

Normal backlash (along the line of action) of a pair at centre distance a with base thicknesses s_b1, s_b2 and
base pitch p_b — derived in docs/thermal.md from the transverse backlash on the operating pitch circles,
j_t = p_w − s_w1 − s_w2 with s_w = 2 r_w (ψ_b − inv α_w), p_w = p_b / cos α_w, j_bn = j_t cos α_w:

    j_bn = p_b − s_b1 − s_b2 + 2·a·cos α_w·inv α_w          (= 0 at the tight-mesh centre distance)

so ∂j_bn/∂a = 2 sin α_w (the familiar j_n = 2·Δa·sin α_w).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property

from thermogear.geometry import Gear, GearPair, involute

#: AGMA 2002-B88 minimum recommended normal backlash j_bn,min = 0.06 + 0.0005·a + 0.03·m [mm] (a, m in mm), as
#: quoted by the geargen.xyz backlash resource; the default when a case gives no backlash.
AGMA_MINIMUM_BACKLASH_TERMS_MM = (0.06, 0.0005, 0.03)


@dataclass(frozen=True)
class OperatingGearPair(GearPair):
    """A gear pair whose two gears may have grown by different strains (different modules).

    :class:`GearPair` takes the operating pressure angle from the common module; here it comes from the base radii
    themselves, cos α_w = (r_b1 + r_b2)/a, which holds for any two involutes. The base pitch along the line of
    action is the pinion's (the contact points of successive pairs are one pinion base pitch apart); the wheel's
    different pitch enters as the base-pitch deviation (:mod:`thermogear.thermoelastic.deviations`).
    """

    @cached_property
    def operating_pressure_angle(self) -> float:
        """α_w from cos α_w = (r_b1 + r_b2)/a [rad]."""
        return math.acos((self.pinion.base_radius + self.wheel.base_radius) / self.centre_distance)


def scaled_gear(gear: Gear, strain: float) -> Gear:
    """The gear grown by a uniform strain ε (module, face width, bore and tip radius × (1 + ε)) [m]."""
    factor = 1.0 + strain
    return replace(gear, module=gear.module * factor, face_width=gear.face_width * factor,
                   bore_radius=gear.bore_radius * factor,
                   tip_radius=None if gear.tip_radius is None else gear.tip_radius * factor)


def operating_gear_pair(pair: GearPair, pinion_strain: float, wheel_strain: float,
                        housing_strain: float) -> GearPair:
    """The pair at temperature: each gear scaled by its bulk strain, the centre distance by the housing's.

    Returns ``pair`` itself when all three strains are zero (the cold pair, bit for bit). The geometry checks of
    :meth:`GearPair.check` are not repeated: the scaled pair is the cold one to first order, and jamming is
    checked on the backlash (:func:`normal_backlash`).
    """
    if pinion_strain == 0.0 and wheel_strain == 0.0 and housing_strain == 0.0:
        return pair
    return OperatingGearPair(scaled_gear(pair.pinion, pinion_strain), scaled_gear(pair.wheel, wheel_strain),
                             pair.centre_distance * (1.0 + housing_strain), pair.names)


def base_thickness(gear: Gear) -> float:
    """Circular tooth thickness on the base circle s_b = 2 r_b ψ_b [m], ψ_b the half tooth angle on the base
    circle (ISO 21771: ψ_b = π/(2z) + inv α + 2x tan α / z)."""
    return 2.0 * gear.base_radius * gear.half_tooth_angle_at_base


def normal_backlash(pair: GearPair, thinning_pinion: float = 0.0, thinning_wheel: float = 0.0) -> float:
    """Normal backlash j_bn = p_b − s_b1 − s_b2 + 2 a cos α_w inv α_w [m] (module docstring, docs/thermal.md).

    ``thinning_*``: reduction of each gear's base tooth thickness by its tooth-thickness allowance [m]. With
    different base pitches (gears at different strains) p_b is their mean: the backlash averaged over the teeth.
    """
    pitch = math.pi * (pair.pinion.base_radius / pair.pinion.teeth + pair.wheel.base_radius / pair.wheel.teeth)
    sum_base_radii = pair.pinion.base_radius + pair.wheel.base_radius
    angle = math.acos(sum_base_radii / pair.centre_distance)
    return float(pitch - (base_thickness(pair.pinion) - thinning_pinion)
                 - (base_thickness(pair.wheel) - thinning_wheel) + 2.0 * sum_base_radii * float(involute(angle)))


def agma_minimum_backlash(centre_distance: float, module: float) -> float:
    """Minimum recommended normal backlash of ANSI/AGMA 2002-B88, 0.06 + 0.0005·a + 0.03·m [mm], in m."""
    constant, per_distance, per_module = AGMA_MINIMUM_BACKLASH_TERMS_MM
    return 1e-3 * (constant + per_distance * centre_distance * 1e3 + per_module * module * 1e3)


@dataclass(frozen=True)
class BacklashAllowance:
    """How the cold normal backlash is made: the geometric part of the centre distance and the tooth-thickness
    allowance (split equally between the gears, each scaled with its gear at temperature) [m]."""

    nominal: float  # j_bn at the reference temperature [m]
    geometric: float  # j_bn of the unthinned teeth at the case's centre distance [m]
    source: str  # "case" or the default's name

    @property
    def thinning_per_gear(self) -> float:
        """Base tooth-thickness allowance of each gear [m]."""
        return 0.5 * (self.nominal - self.geometric)


def backlash_at(pair: GearPair, allowance: BacklashAllowance, pinion_strain: float, wheel_strain: float,
                housing_strain: float) -> float:
    """Normal backlash [m] with the gears and the housing at the given strains (the thinning scales with its
    gear)."""
    hot = operating_gear_pair(pair, pinion_strain, wheel_strain, housing_strain)
    thinning = allowance.thinning_per_gear
    return normal_backlash(hot, thinning * (1.0 + pinion_strain), thinning * (1.0 + wheel_strain))


def jamming_rise(pair: GearPair, allowance: BacklashAllowance, pinion_expansion: float, wheel_expansion: float,
                 housing_strain: float, rise_limit: float = 5000.0) -> float | None:
    """Common bulk rise ΔT [K] of both gears at which the normal backlash closes, the housing held at its strain.

    j_bn(ΔT) is smooth and almost linear (its curvature is of order ε²), so a secant iteration from 0 and 100 K
    converges to machine precision in a few steps. None when the backlash does not close below ``rise_limit``
    (e.g. gears that do not expand).
    """
    def backlash(rise: float) -> float:
        return backlash_at(pair, allowance, pinion_expansion * rise, wheel_expansion * rise, housing_strain)

    low, high = 0.0, 100.0
    value_low, value_high = backlash(low), backlash(high)
    for _ in range(30):
        if value_high == value_low:
            return None
        root = high - value_high * (high - low) / (value_high - value_low)
        if not math.isfinite(root) or abs(root) > rise_limit:
            return None
        low, value_low = high, value_high
        high, value_high = root, backlash(root)
        if abs(high - low) < 1e-9:
            break
    return float(high)
