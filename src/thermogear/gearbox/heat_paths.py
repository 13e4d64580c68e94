"""Conductances of the gearbox network [W/K]: the internal paths (constant, from the description's coefficients)
and the housing's outer surface to the ambient (natural and forced convection and radiation, following the
housing and ambient temperatures).

Outer surface: four vertical walls of the housing's height H (Churchill–Chu on H, combined with forced flow along
the length when air moves: h = (h_N³ + h_F³)^(1/3)), the top face (horizontal plate, length A/P; hot face up when
the housing is warmer than the air), the bottom face only when the description says it is cooled, and radiation
of every cooled face to surroundings at the air temperature. Air properties at the film temperature.
"""

from __future__ import annotations

import numpy as np

from thermogear.gearbox.convection import (air_properties, churchill_chu_vertical, combined_nusselt,
                                           flat_plate_forced, horizontal_plate, radiation_coefficient)
from thermogear.gearbox.description import GearboxDescription, Housing
from thermogear.gearbox.losses import HOUSING, NODES, OIL, PINION, PINION_SHAFT, WHEEL, WHEEL_SHAFT


def housing_outer_conductance(housing: Housing, housing_c: float, ambient_c: float) -> float:
    """g = Σ h·A of the outer surface [W/K] at the housing and air temperatures [°C] (module docstring)."""
    air = air_properties(0.5 * (housing_c + ambient_c))
    difference = housing_c - ambient_c
    length, width, height = housing.length, housing.width, housing.height
    natural_wall = churchill_chu_vertical(air.rayleigh(difference, height), air.prandtl) * air.conductivity / height
    forced_wall = flat_plate_forced(housing.air_speed * length / air.kinematic_viscosity,
                                    air.prandtl) * air.conductivity / length
    wall = combined_nusselt(natural_wall, forced_wall)  # same combination rule applied to h
    plate_area = length * width
    plate_length = plate_area / (2.0 * (length + width))
    plate_rayleigh = air.rayleigh(difference, plate_length)
    top = horizontal_plate(plate_rayleigh, difference >= 0.0) * air.conductivity / plate_length
    bottom = horizontal_plate(plate_rayleigh, difference < 0.0) * air.conductivity / plate_length
    radiation = radiation_coefficient(housing.emissivity, housing_c, ambient_c)
    wall_area = 2.0 * (length + width) * height
    conductance = (wall + radiation) * wall_area + (top + radiation) * plate_area
    if housing.bottom_cooled:
        conductance += (bottom + radiation) * plate_area
    return float(conductance)


def internal_conductances(description: GearboxDescription) -> np.ndarray:
    """Symmetric G [W/K] between the nodes of :data:`~thermogear.gearbox.losses.NODES` (constant): each gear to the
    oil and to its own shaft (through its body and, where the description has them, the stretches of shaft to its
    bearings as fins, :meth:`GearboxDescription.shaft_paths`), each shaft to the oil (half the shafts' path each,
    plus its fins' surfaces) and to the housing (through its bearings,
    :attr:`GearboxDescription.shaft_housing_conductances`), the oil to the housing."""
    matrix = np.zeros((len(NODES), len(NODES)))
    pinion_housing, wheel_housing = description.shaft_housing_conductances
    shaft_oil = 0.5 * description.shaft_oil_conductance
    pinion_shaft, pinion_oil, pinion_shaft_oil = description.shaft_paths(False)
    wheel_shaft, wheel_oil, wheel_shaft_oil = description.shaft_paths(True)
    links = ((PINION, OIL, description.gear_oil_coefficient * description.gear_surface(False) + pinion_oil),
             (WHEEL, OIL, description.gear_oil_coefficient * description.gear_surface(True) + wheel_oil),
             (PINION, PINION_SHAFT, pinion_shaft), (WHEEL, WHEEL_SHAFT, wheel_shaft),
             (PINION_SHAFT, OIL, shaft_oil + pinion_shaft_oil), (WHEEL_SHAFT, OIL, shaft_oil + wheel_shaft_oil),
             (PINION_SHAFT, HOUSING, pinion_housing), (WHEEL_SHAFT, HOUSING, wheel_housing),
             (OIL, HOUSING, description.oil_housing_coefficient * description.housing.oil_wetted_area))
    for first, second, value in links:
        matrix[first, second] = matrix[second, first] = value
    return matrix
