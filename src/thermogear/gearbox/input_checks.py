"""Load-time checks of a ``[gearbox]`` section's inputs against each other and against the gear pair: each refusal
names the key, its value, the range it must lie in and why (CaseError); keys without effect are refused too.

* **Oil level and immersion.** The oil stands ``level`` = V/A_floor above the floor: ``[gearbox.oil] level_mm``
  where given (its floor V/level must fit in the housing's footprint), else V over the outer footprint
  length × width (the model's own assumption, the one the default wetted area uses). A gear cannot dip deeper than
  the oil stands (its lowest point is at least on the floor): each immersion must be at most the level.
* **Oil volume against the housing**, whether or not the wetted area is given: the oil fits in the box
  (V < length × width × height; with ``outer_area_m2`` the model's cube).
* **Wetted area** at most the housing's whole inner surface (its outer surface is an upper bound).
* **Bearing load fractions**: the network puts each gear between the bearings of its shaft, whose radial
  reactions then sum to the tooth force (statics of a beam on two supports): per shaft, Σ count·load_fraction must
  not exceed 1 (an overhung gear, whose reactions sum to more, is outside what the model describes); a sum below 1
  is warned about (part of the tooth force carried by nothing the model knows).
* **Keys without effect** under ``temperature.model = "gearbox"``: the given-temperature keys of ``[temperature]``
  (``bulk_c``, the flank table and the base/bore temperatures) are refused, the network predicts them.
"""

from __future__ import annotations

import math
import warnings
from typing import TYPE_CHECKING

from thermogear.errors import CaseError, ModelAssumptionWarning
from thermogear.lubricant.methods import lubrication_method
from thermogear.temperature.kinds import temperature_source

if TYPE_CHECKING:
    from thermogear.geometry import GearPair
    from thermogear.schema.gearbox import GearboxSection
    from thermogear.schema.temperature import TemperatureSection

#: ``[temperature]`` keys that give temperatures: without effect when the gearbox model predicts them.
GIVEN_TEMPERATURE_KEYS = ("bulk_c", "gamma", "flank_c", "csv", "pinion_base_c", "pinion_bore_c", "wheel_base_c",
                          "wheel_bore_c", "wheel_flank_offset_c")


def housing_box(section: "GearboxSection") -> tuple[float, float, float]:
    """Outer length, width, height of the housing [m] (a cube of the cooled area where only the area is given:
    side √(A/5), √(A/6) with the bottom cooled)."""
    housing = section.housing
    if housing.outer_area_m2 is not None:
        side = math.sqrt(housing.outer_area_m2 / (6.0 if housing.bottom_cooled else 5.0))
        return side, side, side
    return housing.length_mm * 1e-3, housing.width_mm * 1e-3, housing.height_mm * 1e-3


def oil_floor_and_level(section: "GearboxSection") -> tuple[float, float]:
    """(inner floor area [m²], oil level [m]) the model uses (module docstring)."""
    length, width, _ = housing_box(section)
    volume = section.oil.volume_l * 1e-3
    if section.oil.level_mm is not None:
        level = section.oil.level_mm * 1e-3
        return volume / level, level
    return length * width, volume / (length * width)


def check_gearbox_inputs(section: "GearboxSection", pair: "GearPair", temperature: "TemperatureSection") -> None:
    """Refuse inputs of a ``[gearbox]`` section that contradict each other (module docstring)."""
    length, width, height = housing_box(section)
    volume_l = section.oil.volume_l
    box_l = length * width * height * 1e3
    if volume_l >= box_l:
        raise CaseError("gearbox.oil.volume_l", volume_l, f"< {box_l:.4g} L (the housing's volume)",
                        "the oil would fill the housing")
    floor, level = oil_floor_and_level(section)
    if section.oil.level_mm is not None:
        if floor > length * width * (1.0 + 1e-12):
            raise CaseError("gearbox.oil.level_mm", section.oil.level_mm,
                            f">= {volume_l * 1e-3 / (length * width) * 1e3:.4g} mm",
                            f"{volume_l:g} L at that level needs a floor of {floor:.4g} m², more than the housing's "
                            f"footprint {length * width:.4g} m²")
        if level >= height:
            raise CaseError("gearbox.oil.level_mm", section.oil.level_mm, f"< the housing height {height * 1e3:.4g} mm",
                            "the oil would fill the housing")
    dipped = lubrication_method(section.oil.lubrication).wheel_dipped
    wheel_depth = (pair.operating_pitch_radii[1] if dipped else 0.0) \
        if section.oil.wheel_immersion_mm is None else section.oil.wheel_immersion_mm * 1e-3
    level_text = (f"the oil level {level * 1e3:.4g} mm ({volume_l:g} L over a floor of {floor:.4g} m²"
                  + ("" if section.oil.level_mm is not None else ": the housing's footprint; give "
                     "gearbox.oil.level_mm where the inner floor is smaller") + ")")
    for key, depth, given in (("wheel_immersion_mm", wheel_depth, section.oil.wheel_immersion_mm),
                              ("pinion_immersion_mm", section.oil.pinion_immersion_mm * 1e-3, True)):
        if depth > level * (1.0 + 1e-9):
            shown = round(depth * 1e3, 4)
            default = "" if given is not None else " (the default: the wheel dipped to its centre)"
            raise CaseError(f"gearbox.oil.{key}", shown, f"<= {level * 1e3:.4g} mm, {level_text}",
                            f"a gear cannot dip deeper than the oil stands{default}")
    wetted = section.housing.oil_wetted_area_m2
    inner_surface = 2.0 * (length * width + length * height + width * height)
    if wetted is not None and wetted > inner_surface:
        raise CaseError("gearbox.housing.oil_wetted_area_m2", wetted, f"<= {inner_surface:.4g} m² (the housing's "
                        "whole surface)", "the oil cannot wet more than the housing's inside")
    for shaft in ("pinion", "wheel"):
        entries = [entry for entry in section.bearings if entry.shaft == shaft]
        total = sum(entry.count * (1.0 / entry.count if entry.load_fraction is None else entry.load_fraction)
                    for entry in entries)
        if total > 1.0 + 1e-9:
            raise CaseError("gearbox.bearings.load_fraction", round(total, 6),
                            f"a sum of count × load_fraction <= 1 over the {shaft} shaft's bearings",
                            "the gear sits between its shaft's bearings, whose radial reactions sum to the tooth force "
                            "(statics); more would create load")
        if entries and total < 1.0 - 1e-9:
            warnings.warn(f"gearbox.bearings: the {shaft} shaft's bearings carry {total:.3g} of the tooth force "
                          "(count × load_fraction); the rest is carried by nothing the model knows",
                          ModelAssumptionWarning, stacklevel=3)
    if temperature_source(temperature.model).predicted_at_load:  # the gearbox network (or a registered model)
        for key in GIVEN_TEMPERATURE_KEYS:
            if key in temperature.model_fields_set:
                raise CaseError(f"temperature.{key}", getattr(temperature, key), "absent with temperature.model = "
                                f"'{temperature.model}'", "the temperature model predicts the gear temperatures: the "
                                "key would have no effect")


__all__ = ["GIVEN_TEMPERATURE_KEYS", "check_gearbox_inputs", "housing_box", "oil_floor_and_level"]
