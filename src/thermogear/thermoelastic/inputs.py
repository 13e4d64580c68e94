"""The thermo-elastic inputs of a case, resolved to numbers with their defaults, and their load-time checks.

Pure functions of the validated case-file sections and the cold gear pair (no Case import, so
:func:`thermogear.case.case_from_document` can call :func:`check_thermoelastic_inputs` while it builds a case).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.temperature.kinds import temperature_source
from thermogear.errors import CaseError, JammingError
from thermogear.geometry import GearPair
from thermogear.temperature.field import MATERIAL_MAXIMUM_C, MATERIAL_MINIMUM_C  # the material data's range [°C]
from thermogear.choices.thermal_models import thermal_model_rules
from thermogear.thermoelastic.materials import HOUSING_EXPANSION_PER_K, MODULUS_TEMPERATURE_COEFFICIENTS_PER_K
from thermogear.thermoelastic.operating import (BacklashAllowance, agma_minimum_backlash, backlash_at, jamming_rise,
                                                normal_backlash)

GEAR_NAMES = ("pinion", "wheel")


@dataclass(frozen=True)
class GearInputs:
    """Material at temperature and profile modification of one gear (SI)."""

    expansion_per_k: float  # λ [1/K]
    modulus_coefficient_per_k: float  # β_E [1/K]
    modulus_source: str
    tip_relief: float  # amount at the tip [m]
    tip_relief_length: float  # roll length from the tip [m] (0 without relief)
    tip_relief_shape: str


@dataclass(frozen=True)
class HousingInputs:
    expansion_per_k: float  # [1/K]
    temperature_c: float  # [°C]
    source: str


def gear_inputs(gears_section, material_section, name: str) -> GearInputs:
    """Resolve one gear's inputs: per-gear keys, else [material], else the material-class default of β_E."""
    section = getattr(gears_section, name)
    expansion = section.thermal_expansion_per_k
    if expansion is None:
        expansion = material_section.thermal_expansion_per_k
    coefficient = section.youngs_modulus_temperature_coefficient_per_k
    source = f"gears.{name}.youngs_modulus_temperature_coefficient_per_k"
    if coefficient is None:
        coefficient = material_section.youngs_modulus_temperature_coefficient_per_k
        source = "material.youngs_modulus_temperature_coefficient_per_k"
    if coefficient is None:
        coefficient = MODULUS_TEMPERATURE_COEFFICIENTS_PER_K[material_section.material_class]
        source = (f"default for {material_section.material_class.replace('_', ' ')}: chord of Roark's E(T) table, "
                  "21–204 °C")
    length = 0.0 if section.tip_relief_length_mm is None else section.tip_relief_length_mm * 1e-3
    return GearInputs(expansion, coefficient, source, section.tip_relief_um * 1e-6,
                      length if section.tip_relief_um > 0.0 else 0.0, section.tip_relief_shape)


def housing_inputs(housing_section, lubricant_section) -> HousingInputs:
    """Housing expansion coefficient (given, else its material's) and temperature (given, else the oil's)."""
    expansion = housing_section.thermal_expansion_per_k
    source = "housing.thermal_expansion_per_k"
    if expansion is None:
        expansion = HOUSING_EXPANSION_PER_K[housing_section.material]
        source = f"{housing_section.material.replace('_', ' ')} housing"
    temperature = housing_section.temperature_c
    if temperature is None:
        temperature = lubricant_section.operating_temperature_c
        source += ", at the oil temperature"
    return HousingInputs(expansion, temperature, source)


def backlash_allowance(pair: GearPair, gears_section) -> BacklashAllowance:
    """Cold normal backlash: the case's ``gears.backlash_normal_um``, else the AGMA 2002-B88 minimum (or the
    centre distance's own backlash where that is larger). Raises CaseError for a given backlash below what the
    centre distance alone gives."""
    geometric = normal_backlash(pair)
    given = gears_section.backlash_normal_um
    if given is not None:
        nominal = given * 1e-6
        if nominal < geometric - 1e-12:
            raise CaseError("gears.backlash_normal_um", given, f">= {geometric * 1e6:.2f} μm",
                            "the centre distance alone gives more backlash than this with unthinned teeth")
        return BacklashAllowance(nominal, geometric, "case")
    default = agma_minimum_backlash(pair.centre_distance, pair.module)
    if default < geometric:
        return BacklashAllowance(geometric, geometric, "the centre distance's (larger than the AGMA minimum)")
    return BacklashAllowance(default, geometric, "AGMA 2002-B88 minimum 0.06 + 0.0005·a + 0.03·m mm")


def check_tip_relief(pair: GearPair, name: str, inputs: GearInputs) -> None:
    """Refuse a relief longer than the path of contact or deeper than half the tip's thickness."""
    if inputs.tip_relief == 0.0:
        return
    if inputs.tip_relief_length > pair.path_length * (1.0 + 1e-12):
        raise CaseError(f"gears.{name}.tip_relief_length_mm", inputs.tip_relief_length * 1e3,
                        f"<= path of contact {pair.path_length * 1e3:.3f} mm",
                        "the relief would start below the first point of contact: no part of the flank would "
                        "carry load as an involute")
    gear = getattr(pair, name)
    tip_angle = math.acos(gear.base_radius / gear.tip_radius)
    limit = 0.5 * float(gear.thickness_at(gear.tip_radius)) * math.cos(tip_angle)
    if inputs.tip_relief > limit:
        raise CaseError(f"gears.{name}.tip_relief_um", inputs.tip_relief * 1e6, f"<= {limit * 1e6:.1f} μm",
                        "deeper than half the tip thickness (normal to the flank): the relieved flank would cross "
                        "the tooth centreline")


def bulk_temperatures_c(temperature_section) -> tuple[float, float] | None:
    """Gear body temperatures the case gives directly (uniform: the bulk; tabulated: the base circles), None when
    a model computes them (FE)."""
    if temperature_source(temperature_section.model).uniform and temperature_section.bulk_c is not None:
        return temperature_section.bulk_c, temperature_section.bulk_c
    if temperature_source(temperature_section.model).tabulated and temperature_section.pinion_base_c is not None:
        wheel = temperature_section.wheel_base_c
        return temperature_section.pinion_base_c, temperature_section.pinion_base_c if wheel is None else wheel
    return None


def check_not_jammed(pair: GearPair, allowance: BacklashAllowance, pinion: GearInputs, wheel: GearInputs,
                     housing: HousingInputs, reference_c: float, bulk_c: tuple[float, float],
                     key: str = "temperature.bulk_c") -> float:
    """The hot normal backlash [m]; raises JammingError (a CaseError) when it is closed at the operating
    temperatures."""
    housing_strain = housing.expansion_per_k * (housing.temperature_c - reference_c)
    hot = backlash_at(pair, allowance, pinion.expansion_per_k * (bulk_c[0] - reference_c),
                      wheel.expansion_per_k * (bulk_c[1] - reference_c), housing_strain)
    if hot <= 0.0:
        rise = jamming_rise(pair, allowance, pinion.expansion_per_k, wheel.expansion_per_k, housing_strain)
        at = "" if rise is None else f" (it closes at a bulk temperature of {reference_c + rise:.1f} °C)"
        raise JammingError(key, round(max(bulk_c), 4), "a temperature at which the backlash stays open",
                           f"the gears jam: the normal backlash is {hot * 1e6:.1f} μm at {bulk_c[0]:g}/{bulk_c[1]:g} "
                           f"°C with the housing at {housing.temperature_c:g} °C{at}; give more backlash "
                           "(gears.backlash_normal_um) or a warmer housing")
    return hot


def check_thermoelastic_inputs(pair: GearPair, document) -> None:
    """Load-time checks of a validated case file (:class:`thermogear.schema.CaseFile`) against its cold pair:
    tip reliefs, backlash, gear temperatures within the material data and, for the thermo-elastic model,
    no jamming at the operating temperatures the case gives (hot or, below the assembly temperature, cold). Raises CaseError."""
    inputs = {name: gear_inputs(document.gears, document.material, name) for name in GEAR_NAMES}
    for name in GEAR_NAMES:
        check_tip_relief(pair, name, inputs[name])
    allowance = backlash_allowance(pair, document.gears)
    if not thermal_model_rules(document.thermal.model).expands_geometry:
        return
    bulk = bulk_temperatures_c(document.temperature)
    if bulk is None:
        return
    key = ("temperature.bulk_c" if temperature_source(document.temperature.model).uniform
           else "temperature.pinion_base_c")
    if max(bulk) > MATERIAL_MAXIMUM_C:
        raise CaseError(key, max(bulk), f"<= {MATERIAL_MAXIMUM_C} °C",
                        "above what the material data cover (E(T) fitted on 21–204 °C; gear steels temper at "
                        "150–200 °C)")
    if min(bulk) < MATERIAL_MINIMUM_C:
        raise CaseError(key, min(bulk), f">= {MATERIAL_MINIMUM_C} °C under thermal.model = 'thermoelastic'",
                        "below what the material data cover (E(T) fitted on 21–204 °C, taken down to the coldest "
                        "start the housing range allows)")
    housing = housing_inputs(document.housing, document.lubricant)
    check_not_jammed(pair, allowance, inputs["pinion"], inputs["wheel"], housing, document.temperature.reference_c,
                     bulk, key)
