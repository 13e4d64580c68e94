"""Case-file section [temperature]: where the tooth temperatures come from."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from thermogear.schema.base import Section
from thermogear.temperature.limits import MATERIAL_MAXIMUM_C

#: Absolute zero [°C]: no temperature of a case may reach it.
ABSOLUTE_ZERO_C = -273.15
#: Lowest temperature any case temperature may have [°C]: below the coldest start gearboxes are specified for
#: (the housing range starts at −40 °C) with margin. Colder, mineral and synthetic gear oils are past their pour
#: point (an ASTM D341 line fitted at 40 and 100 °C says nothing there) and the room-temperature material data no
#: longer hold; −273 °C passed as an assembly temperature before (issue 25). An assumption of this project.
CASE_MINIMUM_C = -60.0
#: Highest temperature any case temperature may have [°C]: the one limit of the material data
#: (:data:`thermogear.temperature.limits.MATERIAL_MAXIMUM_C`; room-temperature constants, gear steels temper at
#: 150–200 °C).
CASE_MAXIMUM_C = MATERIAL_MAXIMUM_C

#: Largest temperature difference across the face [K]: measured helical gears differ by a few to some 20 K
#: between inlet and outlet side; 100 K keeps every tooth within the material data's range (an assumption).
FACE_GRADIENT_LIMIT_K = 100.0

#: A temperature of a case [°C]: a finite number from CASE_MINIMUM_C to CASE_MAXIMUM_C.
Celsius = Annotated[float, Field(ge=CASE_MINIMUM_C, le=CASE_MAXIMUM_C, allow_inf_nan=False)]


class TemperatureSection(Section):
    """Tooth temperature input of the thermal model (°C). ``model`` picks the source:

    - ``"uniform"``: one bulk temperature for the whole gear body (``bulk_c``);
    - ``"tabulated"``: flank temperature along Γ (``gamma`` and ``flank_c``, or ``csv``) fitted by a polynomial
      of ``fit_degree``, with base-circle and bore temperatures per gear;
    - ``"fem"``: the finite-element bulk-temperature model computes everything;
    - ``"gearbox"``: the gearbox thermal model (``[gearbox]`` section) predicts the gear, oil and housing
      temperatures at the operating point (steady state of its network).
    """

    model: Literal["uniform", "tabulated", "fem", "gearbox"] = "uniform"
    reference_c: Celsius = Field(20.0, description="stress-free (assembly) temperature [°C]")
    bulk_c: Celsius | None = Field(None, description="uniform bulk temperature [°C]")
    gamma: list[Annotated[float, Field(allow_inf_nan=False)]] | None = Field(
        None, description="contact positions Γ of the flank table [–]")
    flank_c: list[Celsius] | None = Field(None, description="flank temperatures at gamma [°C]")
    csv: str | None = Field(None, description="CSV file with columns gamma, flank_c (relative to the case file)")
    fit_degree: Annotated[int, Field(ge=0, le=12)] = 4
    pinion_base_c: Celsius | None = Field(None, description="pinion base-circle temperature [°C]")
    pinion_bore_c: Celsius | None = Field(None, description="pinion bore temperature [°C]")
    wheel_base_c: Celsius | None = Field(None, description="wheel base-circle temperature [°C]")
    wheel_bore_c: Celsius | None = Field(None, description="wheel bore temperature [°C]")
    wheel_flank_offset_c: Annotated[float, Field(ge=-CASE_MAXIMUM_C, le=CASE_MAXIMUM_C, allow_inf_nan=False)] = Field(
        0.0, description="wheel flank temperature minus the pinion's [°C]")
    face_gradient_k: Annotated[float, Field(ge=-FACE_GRADIENT_LIMIT_K, le=FACE_GRADIENT_LIMIT_K,
                                            allow_inf_nan=False)] = Field(0.0, description=(
        "temperature across the face of a helical pair [K]: the end face where the contact lines leave the mesh "
        "(the oil's outlet side) minus the one where they enter, a linear variation about the bulk temperatures, "
        "the same for both gears; it distorts the lead (docs/helical.md). Helical pairs under thermal.model = "
        "'thermoelastic' only; 0: none"))
