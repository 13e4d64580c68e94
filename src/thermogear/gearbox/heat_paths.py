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
    """Symmetric G [W/K] between pinion, wheel, shafts, oil, housing (constant)."""
    matrix = np.zeros((5, 5))
    links = ((0, 3, description.gear_oil_coefficient * description.gear_surface(False)),
             (1, 3, description.gear_oil_coefficient * description.gear_surface(True)),
             (0, 2, description.gear_shaft_conductance), (1, 2, description.gear_shaft_conductance),
             (2, 3, description.shaft_oil_conductance), (2, 4, description.shaft_housing_conductance),
             (3, 4, description.oil_housing_coefficient * description.housing.oil_wetted_area))
    for first, second, value in links:
        matrix[first, second] = matrix[second, first] = value
    return matrix
