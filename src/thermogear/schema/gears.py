"""Case-file sections [gears], [gears.pinion], [gears.wheel], [material] and [operating]."""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, model_validator

from thermogear.errors import CaseError
from thermogear.geometry import MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH
from thermogear.schema.base import Section


#: Smallest face width [mm]: the smallest module the schema takes (0.1 mm); a thinner gear is no gear the
#: tooth models describe (1e-9 mm passed and gave a static line load of 4·10¹² N/mm, issue 25).
MINIMUM_FACE_WIDTH_MM = 0.1


class GearSection(Section):
    """One gear of the pair. Lengths in millimetres as the key names say."""

    teeth: Annotated[int, Field(ge=5, le=1000, description="number of teeth z [–]")]
    profile_shift: Annotated[float, Field(ge=-1.0, le=1.5, description="profile shift coefficient x [–]; of a "
                                                                      "helical pair the normal x_n")] = 0.0
    face_width_mm: Annotated[float, Field(ge=MINIMUM_FACE_WIDTH_MM, le=2000.0,
                                          description="face width b [mm]")] | None = None
    bore_radius_mm: Annotated[float, Field(ge=0.0, le=5000.0, allow_inf_nan=False, description=(
        "bore (hub) radius r_n [mm]; omitted or 0: a solid gear (the fillet foundation then takes a nominal seat "
        "of 0.3 r_f, docs/stiffness.md)"))] | None = None
    tip_diameter_mm: Annotated[float, Field(gt=0.0, le=20000.0,
                                            description="tip diameter d_a [mm]; default from the geometry")] | None = None
    inertia_kg_m2: Annotated[float, Field(gt=0.0, allow_inf_nan=False,
                                          description="polar moment of inertia [kg m²]; default: solid "
                                                      "disc of the pitch radius with the bore")] | None = None
    # thermo-elastic mesh model (docs/thermal.md): per-gear material at temperature and profile modification
    thermal_expansion_per_k: Annotated[float, Field(ge=0.0, le=1e-4, description="this gear's linear expansion "
                                                    "coefficient [1/K]; default [material]")] | None = None
    youngs_modulus_temperature_coefficient_per_k: Annotated[float, Field(
        ge=-1e-3, le=0.0, description="β_E of E(T) = E(20 °C)·[1 + β_E (T − 20 °C)] for this gear [1/K]; "
                                      "default [material]")] | None = None
    tip_relief_um: Annotated[float, Field(ge=0.0, le=1000.0, description="tip relief amount at the tip, along "
                                                                         "the line of action [μm]")] = 0.0
    tip_relief_length_mm: Annotated[float, Field(gt=0.0, le=1000.0, description="tip relief length: roll "
                                                 "distance along the line of action from the tip [mm]")] | None = None
    tip_relief_shape: Literal["linear", "parabolic"] = Field("linear", description="tip relief shape")

    @model_validator(mode="after")
    def _relief_complete(self):
        if self.tip_relief_um > 0.0 and self.tip_relief_length_mm is None:
            raise ValueError("tip_relief_length_mm: a tip relief needs its length (roll distance from the tip, mm)")
        return self


class GearsSection(Section):
    """The pair: common rack data, centre distance, and the two gears."""

    module_mm: Annotated[float, Field(ge=0.1, le=100.0, description="module m [mm]; of a helical pair the normal "
                                                                    "module m_n (ISO 21771)")]
    pressure_angle_deg: Annotated[float, Field(gt=0.0, lt=45.0, description="pressure angle α [°]; of a helical pair "
                                                                           "the normal pressure angle α_n")] = 20.0
    helix_angle_deg: Annotated[float, Field(ge=0.0, le=45.0, allow_inf_nan=False, description=(
        "helix angle β at the reference cylinder [°]; 0: a spur pair. With β > 0, module_mm, pressure_angle_deg and "
        "the profile shifts are the normal-section values (ISO 21771); the slice model covers β ≤ 45° "
        "(docs/helical.md)"))] = 0.0
    hand: Literal["right", "left"] = Field("right", description=(
        "hand of the pinion's helix (the wheel of an external pair has the other hand); sets the sense of the "
        "axial force. Accepted with helix_angle_deg = 0, where it has no effect"))
    face_width_mm: Annotated[float, Field(ge=MINIMUM_FACE_WIDTH_MM, le=2000.0,
                                          description="face width b of both gears [mm]")] | None = None
    addendum_coefficient: Annotated[float, Field(gt=0.0, le=2.0, description="h_a* [–]")] = 1.0
    dedendum_coefficient: Annotated[float, Field(gt=0.0, le=2.5, description="h_f* [–]")] = 1.25
    tool_tip_radius_coefficient: Annotated[float, Field(ge=0.0, le=0.6, description="rack tip radius ρ_fP* [–]")] = 0.38
    centre_distance_mm: Annotated[float, Field(gt=0.0, description="centre distance a [mm]; default: zero "
                                                                   "backlash from the profile shifts")] | None = None
    tip_shortening: bool = Field(True, description="shorten the tips to keep the standard clearance (ISO 21771)")
    roughness_ra_um: Annotated[float, Field(ge=0.0, le=50.0, description="composite arithmetic mean roughness "
                                                                        "Ra = (Ra1 + Ra2)/2 [μm]")] = 1.0
    backlash_normal_um: Annotated[float, Field(ge=0.0, le=20000.0, description="normal backlash at the reference "
                                               "temperature [μm]; default: AGMA 2002-B88 minimum")] | None = None
    pinion: GearSection
    wheel: GearSection

    @model_validator(mode="after")
    def _face_width_given(self):
        for name in ("pinion", "wheel"):
            if self.face_width_mm is None and getattr(self, name).face_width_mm is None:
                raise ValueError(f"face_width_mm: give gears.face_width_mm or gears.{name}.face_width_mm")
        return self

    @model_validator(mode="after")
    def _backlash_below_base_pitch(self):
        if self.backlash_normal_um is not None:
            base_pitch_um = math.pi * self.module_mm * math.cos(math.radians(self.pressure_angle_deg)) * 1e3
            limit_um = MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH * base_pitch_um
            if self.backlash_normal_um > limit_um:
                raise CaseError("gears.backlash_normal_um", self.backlash_normal_um,
                                f"<= {limit_um:.1f} μm (a tenth of the base pitch {base_pitch_um:.1f} μm)",
                                "the backlash thins the teeth and the tooth models use the unthinned tooth: "
                                "beyond a tenth of the base pitch each tooth loses about a tenth of its "
                                "thickness and its bending stiffness changes by about 30 %")
        return self


class MaterialSection(Section):
    """Gear material (both gears)."""

    youngs_modulus_gpa: Annotated[float, Field(ge=1.0, le=1000.0, description="Young's modulus E [GPa]")] = 206.0
    poisson_ratio: Annotated[float, Field(ge=0.0, lt=0.5, description="Poisson's ratio ν [–]")] = 0.3
    density_kg_m3: Annotated[float, Field(ge=500.0, le=25000.0, description="density ρ [kg/m³]")] = 7850.0
    specific_heat_j_per_kg_k: Annotated[float, Field(gt=0.0, le=5000.0, description="specific heat c [J/(kg K)]")] = 465.0
    thermal_conductivity_w_per_m_k: Annotated[float, Field(gt=0.0, le=500.0,
                                                           description="thermal conductivity [W/(m K)]")] = 46.0
    thermal_expansion_per_k: Annotated[float, Field(ge=0.0, le=1e-4,
                                                    description="linear thermal expansion coefficient [1/K]")] = 11.5e-6
    material_class: Literal["carbon_steel", "carbon_moly_steel", "nickel_steel"] = Field(
        "carbon_steel", description="steel class of the default temperature coefficient of E (Roark's table)")
    youngs_modulus_temperature_coefficient_per_k: Annotated[float, Field(
        ge=-1e-3, le=0.0, description="β_E of E(T) = E(20 °C)·[1 + β_E (T − 20 °C)] [1/K]; default from "
                                      "material_class")] | None = None


class OperatingSection(Section):
    """Operating point: pinion speed and either the power or the pinion torque."""

    speed_rpm: Annotated[float, Field(gt=0.0, le=200000.0, description="pinion speed n1 [rpm]")]
    power_kw: Annotated[float, Field(gt=0.0, le=1e5, description="transmitted power P [kW]")] | None = None
    torque_nm: Annotated[float, Field(gt=0.0, le=1e7, description="pinion torque T1 [N m]")] | None = None
    fzg_load_stage: Annotated[int, Field(ge=1, le=14, description="FZG load stage KS (pinion torque from the "
                                                                  "standard table)")] | None = None

    @model_validator(mode="after")
    def _one_load(self):
        given = [name for name in ("power_kw", "torque_nm", "fzg_load_stage") if getattr(self, name) is not None]
        if len(given) != 1:
            raise ValueError("power_kw: give exactly one of power_kw, torque_nm, fzg_load_stage "
                             f"(given: {', '.join(given) or 'none'})")
        return self
