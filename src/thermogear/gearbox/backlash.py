"""Normal backlash of the gear pair with the gears and the housing at their own temperatures.

The exact operating geometry is thermogear's thermo-elastic one (:mod:`thermogear.thermoelastic.operating`: each
gear scaled by its strain λ_g·ΔT, the centre distance by the housing's λ_h·ΔT_h). To first order it is

    Δj_bn = 2·sin α_w·a·(λ_h·ΔT_h − λ_g·ΔT_g)                                             [m]

(∂j_bn/∂a = 2 sin α_w for the centre distance; a gear grown by ε closes the backlash by 2 sin α_w·ε·a shared
between the two gears in proportion to their radii) — :func:`backlash_change_estimate`, used only as a check.
The margin to jamming is the backlash itself: zero means the flanks touch on both sides.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.geometry import GearPair
from thermogear.thermoelastic.operating import (BacklashAllowance, agma_minimum_backlash, backlash_at,
                                                normal_backlash)


def backlash_allowance(pair: GearPair, nominal: float | None = None) -> BacklashAllowance:
    """The cold backlash of the pair [m]: ``nominal`` or the AGMA 2002-B88 minimum, with the pair's own geometric
    backlash at its centre distance."""
    value = agma_minimum_backlash(pair.centre_distance, pair.module) if nominal is None else float(nominal)
    return BacklashAllowance(value, normal_backlash(pair), "given" if nominal is not None else "AGMA 2002-B88")


def backlash_at_temperatures(pair: GearPair, allowance: BacklashAllowance, gear_expansion: float,
                             housing_expansion: float, pinion_c, wheel_c, housing_c, assembly_c: float) -> float:
    """Normal backlash [m] with pinion, wheel and housing at their temperatures [°C] (exact operating geometry)."""
    return backlash_at(pair, allowance, gear_expansion * (pinion_c - assembly_c),
                       gear_expansion * (wheel_c - assembly_c), housing_expansion * (housing_c - assembly_c))


def backlash_change_estimate(pair: GearPair, gear_expansion: float, housing_expansion: float, gear_rise: float,
                             housing_rise: float) -> float:
    """Δj_bn = 2·sin α_w·a·(λ_h·ΔT_h − λ_g·ΔT_g) [m] (module docstring; both gears at the same rise)."""
    return (2.0 * math.sin(pair.operating_pressure_angle) * pair.centre_distance
            * (housing_expansion * housing_rise - gear_expansion * gear_rise))


@dataclass(frozen=True)
class ColdStart:
    """Backlash [m] of a gearbox soaked at one temperature [°C] and its nominal (assembly) value [m]."""

    soak_c: float
    backlash: float
    nominal: float

    @property
    def change(self) -> float:
        """j_bn(soak) − j_bn(assembly) [m]."""
        return self.backlash - self.nominal

    @property
    def margin_to_jamming(self) -> float:
        """What is left before the flanks touch on both sides: the backlash itself [m]."""
        return self.backlash

    @property
    def jammed(self) -> bool:
        return self.backlash <= 0.0


def cold_start_backlash(pair: GearPair, allowance: BacklashAllowance, gear_expansion: float,
                        housing_expansion: float, soak_c: float, assembly_c: float) -> ColdStart:
    """Backlash with everything at ``soak_c`` (e.g. −30 °C: steel gears in an aluminium housing lose backlash)."""
    value = backlash_at_temperatures(pair, allowance, gear_expansion, housing_expansion, soak_c, soak_c, soak_c,
                                     assembly_c)
    nominal = backlash_at_temperatures(pair, allowance, gear_expansion, housing_expansion, assembly_c,
                                       assembly_c, assembly_c, assembly_c)
    return ColdStart(soak_c, value, nominal)
