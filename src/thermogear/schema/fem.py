"""Case-file section [fem]: settings of the finite-element tooth model (mesh, heat and elasticity).

Every convection coefficient left out is computed from the correlations of docs/fem.md (stated there as
recalled [R]; see docs/fem.md for the values they give); a number given here replaces the correlation for that
boundary.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, field_validator

from thermogear.schema.base import Section

Coefficient = Annotated[float, Field(ge=0.0, le=1e6)] | None


class FemSection(Section):
    """Finite-element tooth model settings (defaults: the documented assumptions of docs/fem.md)."""

    mesh_refinement: Annotated[float, Field(gt=0.2, le=6.0, description="divides every element size [–]")] = 1.0
    plane: Literal["stress", "strain"] = Field("stress", description="2-D elasticity assumption (the potential "
                                               "energy method uses E, i.e. plane stress)")
    sector_teeth: Annotated[int, Field(ge=0, le=9, description="elasticity model: 0 = the whole gear (bore "
                                       "clamped); an odd number = a sector of that many teeth, cut faces free")] = 0
    contact_positions: Annotated[int, Field(ge=3, le=61, description="FE load positions from A to E")] = 11
    bore: Literal["adiabatic", "convective"] = Field("adiabatic", description="thermal condition at the bore")
    bore_h_w_per_m2_k: Coefficient = Field(None, description="bore convection coefficient (bore = 'convective')")
    meshing_flank_h_w_per_m2_k: Coefficient = Field(None, description="convection on the meshing flank")
    passive_flank_h_w_per_m2_k: Coefficient = Field(None, description="convection on the non-meshing flank, "
                                                    "fillet and root")
    tip_h_w_per_m2_k: Coefficient = Field(None, description="convection on the tip")
    end_face_h_w_per_m2_k: Coefficient = Field(None, description="convection on the end faces (2-D sink term)")
    oil_fraction: Annotated[float, Field(ge=0.0, le=1.0, description="oil volume fraction of the oil–air mist "
                                         "in the convection correlations")] = 0.1
    heat_conversion_factor: Annotated[float, Field(gt=0.0, le=1.0, description="share of the friction work "
                                                   "that becomes heat")] = 0.95
    pinion_heat_share: Annotated[float, Field(ge=0.0, le=1.0, description="heat partition to the pinion; "
                                              "default: Blok's partition at each contact point")] | None = None

    @field_validator("sector_teeth")
    @classmethod
    def _odd(cls, value: int) -> int:
        if value != 0 and value % 2 == 0:
            raise ValueError("the loaded tooth sits in the middle of the sector, so the number must be odd (or 0 for the whole gear)")
        return value
