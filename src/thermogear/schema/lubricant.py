"""Case-file section [lubricant]: a built-in oil by name or one defined by its viscosity points."""

from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from pydantic import Field, model_validator

from thermogear.errors import CaseError, closest_key
from thermogear.lubricants import oil_records  # the data package: reads oils.toml, imports nothing of the model
from thermogear.schema.base import Section
from thermogear.schema.temperature import ABSOLUTE_ZERO_C, Celsius

#: Lowest kinematic viscosity of the Walther form of ASTM D341 without its low-viscosity correction [mm²/s].
WALTHER_MINIMUM_CST = 2.0


def check_viscosity_points(points_c_cst, key: str = "lubricant.viscosity_points") -> tuple[np.ndarray, np.ndarray]:
    """Check viscosity points [[temperature °C, kinematic viscosity mm²/s], ...] for the ASTM D341 (Walther) law:
    two or more finite points, above absolute zero, distinct temperatures, viscosities >= 2 mm²/s, viscosity
    falling as the temperature rises. Returns (temperatures, viscosities) sorted by temperature; raises CaseError
    naming ``key``. Used by the case schema (load time) and by :func:`thermogear.lubricant.walther_constants`."""
    try:
        points = np.asarray(points_c_cst, dtype=float)
    except (TypeError, ValueError):
        raise CaseError(key, points_c_cst, "[[temperature °C, viscosity mm²/s], ...]",
                        "each point is a (temperature, kinematic viscosity) pair of numbers") from None
    if points.size == 0:
        points = points.reshape(0, 2)
    if points.ndim != 2 or points.shape[1] != 2:
        raise CaseError(key, points_c_cst, "[[temperature °C, viscosity mm²/s], ...]",
                        "each point is a (temperature, kinematic viscosity) pair")
    if len(points) < 2:
        raise CaseError(key, points_c_cst, "two or more points",
                        "a viscosity–temperature law needs at least two points to fix its two constants")
    if not np.all(np.isfinite(points)):
        raise CaseError(key, points_c_cst, "finite numbers", "a point is not a number")
    order = np.argsort(points[:, 0])
    temperature_c, viscosity = points[order, 0], points[order, 1]
    if np.any(temperature_c <= ABSOLUTE_ZERO_C):
        raise CaseError(key, points_c_cst, "temperatures above -273.15 °C", "below absolute zero")
    if np.any(np.diff(temperature_c) == 0.0):
        raise CaseError(key, points_c_cst, "distinct temperatures", "two points share a temperature")
    if np.any(viscosity < WALTHER_MINIMUM_CST):
        raise CaseError(key, points_c_cst, "viscosities >= 2 mm²/s",
                        "the Walther form of ASTM D341 without its low-viscosity correction holds above 2 mm²/s")
    if np.any(np.diff(viscosity) >= 0.0):
        raise CaseError(key, points_c_cst, "viscosity decreasing as temperature rises",
                        "an oil thins when heated; check the order of temperature and viscosity in each point")
    return temperature_c, viscosity


class LubricantSection(Section):
    """The oil. Either ``name`` of a built-in oil, or ``viscosity_points`` (and density) of your own."""

    name: str | None = Field(None, description="built-in oil (see `thermogear oils`) or a label for your own")
    viscosity_points: list[tuple[float, float]] | None = Field(
        None, description="[[temperature °C, kinematic viscosity mm²/s], ...], two or more, for ASTM D341")
    density_kg_m3: Annotated[float, Field(ge=500.0, le=2000.0, description="density at density_reference_c")] | None = None
    density_reference_c: Celsius = Field(15.0, description="temperature of density_kg_m3 [°C]")
    density_coefficient_per_k: Annotated[float, Field(ge=-2e-3, le=0.0,
                                                      description="relative density change per K [1/K]")] | None = None
    base_oil: Literal["mineral", "pao", "pag_insoluble", "pag_soluble", "ester", "traction"] | None = Field(
        None, description="base oil type, sets the lubricant factor X_L of the friction formula")
    specific_heat_j_per_kg_k: Annotated[float, Field(gt=0.0, le=10000.0, description="oil specific heat "
                                                     "[J/(kg K)], for the FE convection correlations")] | None = None
    thermal_conductivity_w_per_m_k: Annotated[float, Field(gt=0.0, le=5.0, description="oil thermal conductivity "
                                                           "[W/(m K)], for the FE convection correlations")] | None = None
    reference_temperature_c: Celsius = Field(30.0, description="oil temperature of the 'elastic' model [°C]")
    operating_temperature_c: Celsius = Field(60.0, description="oil (sump or injection) temperature of the "
                                                               "thermal model [°C]")

    @model_validator(mode="after")
    def _name_or_points(self):
        if self.name is None and self.viscosity_points is None:
            raise ValueError("name / viscosity_points: give a built-in oil name or at least two viscosity points")
        if self.viscosity_points is not None:
            check_viscosity_points(self.viscosity_points)
        else:
            names = list(oil_records())
            if self.name not in names:
                suggestion = closest_key(self.name, names)
                hint = f" (did you mean '{suggestion}'?)" if suggestion else ""
                raise CaseError("lubricant.name", self.name, "a built-in oil (see `thermogear oils`) or "
                                "viscosity_points", f"no such built-in oil{hint}")
        return self
