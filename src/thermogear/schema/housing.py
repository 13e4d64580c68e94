"""Case-file section [housing]: what sets the centre distance at temperature (the thermo-elastic mesh model).

```toml
[housing]
material = "cast_iron"          # steel | cast_iron | aluminium (sets the expansion coefficient)
thermal_expansion_per_k = 11e-6 # optional: overrides the material's coefficient [1/K]
temperature_c = 45.0            # optional: housing temperature [°C]; default the oil temperature
```
The coefficients of the named materials and their sources: :mod:`thermogear.thermoelastic.materials`.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from thermogear.schema.base import Section

#: Range of linear expansion coefficients of the metals gear housings are made of [1/K]: from titanium alloys
#: (≈ 8.6e-6) to magnesium alloys (≈ 26e-6) (ASM room-temperature tables). Outside it no metal housing matches.
HOUSING_EXPANSION_RANGE_PER_K = (8.0e-6, 27.0e-6)

#: Housing temperatures the linear expansion law is used for [°C]: the usual gearbox range (cold start to the
#: tempering limit of the gear steels, which the gear temperatures also respect).
HOUSING_TEMPERATURE_RANGE_C = (-40.0, 200.0)


class HousingSection(Section):
    """The housing that holds the bearings: its material (or expansion coefficient) and temperature."""

    material: Literal["steel", "cast_iron", "aluminium"] = Field(
        "cast_iron", description="housing material; sets the expansion coefficient unless one is given")
    thermal_expansion_per_k: Annotated[float, Field(
        ge=HOUSING_EXPANSION_RANGE_PER_K[0], le=HOUSING_EXPANSION_RANGE_PER_K[1],
        description="linear expansion coefficient of the housing [1/K] (metals: 8e-6 … 27e-6)")] | None = None
    temperature_c: Annotated[float, Field(
        ge=HOUSING_TEMPERATURE_RANGE_C[0], le=HOUSING_TEMPERATURE_RANGE_C[1],
        description="housing temperature [°C]; default: the oil (operating) temperature")] | None = None
