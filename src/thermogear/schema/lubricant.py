"""Case-file section [lubricant]: a built-in oil by name or one defined by its viscosity points."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from thermogear.schema.base import Section


class LubricantSection(Section):
    """The oil. Either ``name`` of a built-in oil, or ``viscosity_points`` (and density) of your own."""

    name: str | None = Field(None, description="built-in oil (see `thermogear oils`) or a label for your own")
    viscosity_points: list[tuple[float, float]] | None = Field(
        None, description="[[temperature °C, kinematic viscosity mm²/s], ...], two or more, for ASTM D341")
    density_kg_m3: Annotated[float, Field(ge=500.0, le=2000.0, description="density at density_reference_c")] | None = None
    density_reference_c: float = Field(15.0, description="temperature of density_kg_m3 [°C]")
    density_coefficient_per_k: Annotated[float, Field(ge=-2e-3, le=0.0,
                                                      description="relative density change per K [1/K]")] | None = None
    base_oil: Literal["mineral", "pao", "pag_insoluble", "pag_soluble", "ester", "traction"] | None = Field(
        None, description="base oil type, sets the lubricant factor X_L of the friction formula")
    specific_heat_j_per_kg_k: Annotated[float, Field(gt=0.0, le=10000.0, description="oil specific heat "
                                                     "[J/(kg K)], for the FE convection correlations")] | None = None
    thermal_conductivity_w_per_m_k: Annotated[float, Field(gt=0.0, le=5.0, description="oil thermal conductivity "
                                                           "[W/(m K)], for the FE convection correlations")] | None = None
    reference_temperature_c: float = Field(30.0, description="oil temperature of the 'elastic' model [°C]")
    operating_temperature_c: float = Field(60.0, description="oil (sump or injection) temperature of the "
                                                             "thermal model [°C]")

    @model_validator(mode="after")
    def _name_or_points(self):
        if self.name is None and self.viscosity_points is None:
            raise ValueError("name / viscosity_points: give a built-in oil name or at least two viscosity points")
        return self
