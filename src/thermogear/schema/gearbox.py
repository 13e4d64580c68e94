"""Case-file section [gearbox]: the housing, oil, bearings and seals around the gear pair, for the gearbox thermal
model (``[temperature].model = "gearbox"`` and ``thermogear warmup --model gearbox``). Optional: a case without it
is as before.

```toml
[gearbox]
ambient_c = 20.0                  # air around the housing [°C]

[gearbox.housing]
material = "cast_iron"            # cast_iron | steel | aluminium: specific heat and expansion
length_mm = 450.0                 # outer box (or outer_area_m2 for a cube of that cooled area)
width_mm = 300.0
height_mm = 400.0
mass_kg = 40.0
emissivity = 0.9                  # painted
air_speed_m_s = 1.0               # along the walls (0: still air)

[gearbox.oil]
lubrication = "dip"               # dip | injection (then injection_flow_l_min and jet_speed_m_s)
volume_l = 1.25
wheel_immersion_mm = 40.0         # default: the wheel dipped to its centre (injection: 0)

[[gearbox.bearings]]
shaft = "pinion"                  # pinion | wheel
designation = "NJ406"             # built-in constants, or type + the SKF constants
count = 2

[[gearbox.seals]]
shaft = "pinion"
diameter_mm = 30.0
```
The defaults of the internal heat-transfer coefficients are the gearbox model's (``[gearbox.internal]``); every
one is an assumption to calibrate on a measured warm-up (docs/gearbox-temperature.md).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from thermogear.errors import CaseError
from thermogear.schema.base import Section
from thermogear.lubricant.methods import lubrication_method
from thermogear.schema.friction_inputs import check_friction_inputs
from thermogear.schema.bearing_loss import SkfBearingData

#: Ambient air temperatures the correlations (air properties, radiation) are used for [°C].
AMBIENT_RANGE_C = (-60.0, 80.0)

Positive = Annotated[float, Field(gt=0.0, allow_inf_nan=False)]


class GearboxHousingSection(Section):
    """The housing's outside: size, mass, material, surface and the air around it."""

    material: Literal["cast_iron", "steel", "aluminium"] = Field(
        "cast_iron", description="housing material: specific heat (and expansion unless [housing] gives one)")
    length_mm: Annotated[float, Field(gt=10.0, le=10000.0, allow_inf_nan=False)] | None = Field(
        None, description="outer length [mm]")
    width_mm: Annotated[float, Field(gt=10.0, le=10000.0, allow_inf_nan=False)] | None = Field(
        None, description="outer width [mm]")
    height_mm: Annotated[float, Field(gt=10.0, le=10000.0, allow_inf_nan=False)] | None = Field(
        None, description="outer height [mm]")
    outer_area_m2: Annotated[float, Field(gt=0.0, le=500.0, allow_inf_nan=False)] | None = Field(
        None, description="cooled outer area [m²], instead of the three dimensions (taken as a cube)")
    mass_kg: Annotated[float, Field(gt=0.0, le=1e5, allow_inf_nan=False)] = Field(description="housing mass [kg]")
    specific_heat_j_per_kg_k: Annotated[float, Field(ge=100.0, le=2000.0, allow_inf_nan=False)] | None = Field(
        None, description="specific heat [J/(kg K)]; default from the material")
    emissivity: Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False)] = Field(
        0.9, description="grey-body emissivity of the outer surface [–] (0.9 painted)")
    air_speed_m_s: Annotated[float, Field(ge=0.0, le=50.0, allow_inf_nan=False)] = Field(
        0.0, description="air speed along the walls [m/s] (0: natural convection only)")
    oil_wetted_area_m2: Annotated[float, Field(gt=0.0, le=100.0, allow_inf_nan=False)] | None = Field(
        None, description="inner wall area wetted by the oil [m²]; default the floor plus the walls up to the "
                          "oil level")
    bottom_cooled: bool = Field(False, description="the bottom face sheds heat (False: it stands on a foundation)")

    @model_validator(mode="after")
    def _dimensions_or_area(self):
        given = [self.length_mm, self.width_mm, self.height_mm]
        if self.outer_area_m2 is not None and any(value is not None for value in given):
            raise CaseError("gearbox.housing.outer_area_m2", self.outer_area_m2,
                            "either outer_area_m2 or length_mm/width_mm/height_mm", "the housing size is given twice")
        if self.outer_area_m2 is None and any(value is None for value in given):
            missing = ("length_mm", "width_mm", "height_mm")[[value is None for value in given].index(True)]
            raise CaseError(f"gearbox.housing.{missing}", None, "a size in mm (or outer_area_m2 instead)",
                            "the housing's outer dimensions set its cooled area")
        return self


class GearboxOilSection(Section):
    """The oil sump: volume, how deep the gears dip, how the mesh is lubricated."""

    lubrication: Literal["dip", "injection"] = Field(
        "dip", description="dip (splash) lubrication: churning of the dipped gears; injection: an into-mesh oil jet "
                           "(its impulse loss), the gears above the oil unless immersions are given")
    volume_l: Annotated[float, Field(gt=0.0, le=10000.0, allow_inf_nan=False)] = Field(
        description="oil volume [L]")
    wheel_immersion_mm: Annotated[float, Field(ge=0.0, le=5000.0, allow_inf_nan=False)] | None = Field(
        None, description="depth the wheel dips into the oil [mm]; default its operating pitch radius (dip) or 0 "
                          "(injection)")
    injection_flow_l_min: Annotated[float, Field(gt=0.0, le=1000.0, allow_inf_nan=False)] | None = Field(
        None, description="oil flow of the into-mesh jet [L/min] (injection only)")
    jet_speed_m_s: Annotated[float, Field(gt=0.0, le=200.0, allow_inf_nan=False)] | None = Field(
        None, description="speed of the oil jet [m/s] (injection only; an inlet jet at most the pitch-line speed "
                          "for its impulse loss)")
    jet_position: Literal["inlet", "outlet"] = Field(
        "inlet", description="injection only: the jet aimed into the mesh inlet, with the teeth (inlet), or at the "
                             "mesh outlet, against them (outlet)")
    pinion_immersion_mm: Annotated[float, Field(ge=0.0, le=5000.0, allow_inf_nan=False)] = Field(
        0.0, description="depth the pinion dips into the oil [mm] (0: above the oil)")
    level_mm: Annotated[float, Field(gt=0.0, le=10000.0, allow_inf_nan=False)] | None = Field(
        None, description="oil level above the housing floor [mm]; default the volume over the outer footprint "
                          "(length × width). Given, it sets the inner floor area volume/level")
    specific_heat_j_per_kg_k: Annotated[float, Field(ge=1000.0, le=4000.0, allow_inf_nan=False)] = Field(
        2000.0, description="oil specific heat [J/(kg K)]")

    @model_validator(mode="after")
    def _jet_with_injection(self):
        jet = {"injection_flow_l_min": self.injection_flow_l_min, "jet_speed_m_s": self.jet_speed_m_s}
        if lubrication_method(self.lubrication).oil_jet:
            for key, value in jet.items():
                if value is None:
                    raise CaseError(f"gearbox.oil.{key}", None, "a number > 0",
                                    "injection lubrication needs the jet's flow and speed for its impulse loss")
        else:
            if "jet_position" in self.model_fields_set:
                jet["jet_position"] = self.jet_position
            for key, value in jet.items():
                if value is not None:
                    raise CaseError(f"gearbox.oil.{key}", value, 'only with lubrication = "injection"',
                                    "dip lubrication has no oil jet")
        return self


class GearboxBearingSection(SkfBearingData):
    """Rolling bearings of one shaft: a built-in designation or the SKF model's constants (catalogue units)."""

    shaft: Literal["pinion", "wheel"]
    count: Annotated[int, Field(ge=1, le=8)] = Field(2, description="bearings of this kind on the shaft")
    load_fraction: Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False)] | None = Field(
        None, description="share of the tooth normal force each bearing carries; default 1/count")

    @model_validator(mode="after")
    def _designation_or_constants(self):
        constants = ("type", "bore_mm", "outside_mm", "width_mm", "rolling_constant", "sliding_constants",
                     "geometry_constant")
        if self.designation is not None:
            given = [name for name in constants if getattr(self, name) is not None]
            if given:
                raise CaseError(f"gearbox.bearings.{given[0]}", getattr(self, given[0]),
                                "absent with a designation", "the designation sets the bearing's constants")
            return self
        for name in constants:
            if getattr(self, name) is None:
                raise CaseError(f"gearbox.bearings.{name}", None, "a value (or designation = 'NJ406')",
                                "the SKF model of the bearing's frictional moment needs it")
        if self.outside_mm <= self.bore_mm:
            raise CaseError("gearbox.bearings.outside_mm", self.outside_mm, f"> bore_mm = {self.bore_mm}",
                            "the outside diameter is larger than the bore")
        return self


class GearboxSealSection(Section):
    """A radial lip seal on a shaft."""

    shaft: Literal["pinion", "wheel"]
    diameter_mm: Annotated[float, Field(gt=0.0, le=2000.0, allow_inf_nan=False)] = Field(
        description="shaft diameter under the seal [mm]")


class GearboxInternalSection(Section):
    """Internal heat-transfer coefficients and conductances: the defaults are the model's stated assumptions of
    the usual order for a dip-lubricated spur gearbox (calibrate them on a measured warm-up)."""

    gear_oil_w_per_m2_k: Annotated[float, Field(ge=0.0, le=1e5, allow_inf_nan=False)] = Field(
        200.0, description="gear surface to oil [W/(m² K)]")
    oil_housing_w_per_m2_k: Annotated[float, Field(ge=0.0, le=1e5, allow_inf_nan=False)] = Field(
        150.0, description="oil to the wetted inner wall [W/(m² K)]")
    gear_shaft_w_per_k: Annotated[float, Field(ge=0.0, le=1e5, allow_inf_nan=False)] | None = Field(
        None, description="each gear to its own shaft's node [W/K]; default conduction through the gear body from "
                          "its root circle to its bore, 2π k b/ln(r_f/r_bore)")
    shaft_oil_w_per_k: Annotated[float, Field(ge=0.0, le=1e5, allow_inf_nan=False)] = Field(
        4.0, description="both shafts and their bearings to the oil [W/K], half each (with a [drivetrain], the stretches "
                         "of shaft from each gear to its bearings add their own surfaces as fins: then the bearings' "
                         "and the rest of the shafts')")
    shaft_housing_w_per_k: Annotated[float, Field(ge=0.0, le=1e5, allow_inf_nan=False)] = Field(
        8.0, description="both shafts to the housing through the bearing seats [W/K], shared in proportion to the "
                         "bearings on each shaft")


class GearboxConditioningSection(Section):
    """Oil conditioning of a test rig: a heater and a cooler driven by a thermostat on the sump temperature.

    The conditioning power into the oil is P = clip(gain·(set − T_oil), −cooling_w, heater_w) [W]: full heating
    below the set point by more than heater_w/gain, full cooling above it by more than cooling_w/gain, in
    proportion between (a proportional thermostat; the band keeps the network's equations smooth)."""

    setpoint_c: Annotated[float, Field(ge=-40.0, le=200.0, allow_inf_nan=False)] = Field(
        description="oil temperature the thermostat holds [°C]")
    heater_w: Annotated[float, Field(ge=0.0, le=1e6, allow_inf_nan=False)] = Field(
        0.0, description="largest heating power into the oil [W]")
    cooling_w: Annotated[float, Field(ge=0.0, le=1e6, allow_inf_nan=False)] = Field(
        0.0, description="largest cooling power taken from the oil [W]")
    gain_w_per_k: Annotated[float, Field(gt=0.0, le=1e6, allow_inf_nan=False)] = Field(
        200.0, description="thermostat gain [W/K]: the power per kelvin off the set point (proportional band "
                           "= power/gain)")

    @model_validator(mode="after")
    def _some_power(self):
        if self.heater_w == 0.0 and self.cooling_w == 0.0:
            raise CaseError("gearbox.conditioning.heater_w", 0.0, "> 0 (or cooling_w > 0)",
                            "a conditioning without heater or cooler has no effect")
        return self


class GearboxSection(Section):
    """The gearbox around the gear pair, for the gearbox thermal model (``[temperature].model = "gearbox"``,
    ``thermogear warmup --model gearbox``, ``thermogear gearbox``): optional."""

    ambient_c: Annotated[float, Field(ge=AMBIENT_RANGE_C[0], le=AMBIENT_RANGE_C[1], allow_inf_nan=False)] = Field(
        20.0, description="ambient air temperature [°C]")
    housing: GearboxHousingSection
    oil: GearboxOilSection
    bearings: list[GearboxBearingSection] = Field(
        default_factory=list, description="[[gearbox.bearings]] tables: shaft (pinion | wheel), count, and a "
                                          "designation (NJ406) or type, bore_mm, outside_mm, width_mm and the SKF "
                                          "constants rolling_constant, sliding_constants, geometry_constant, "
                                          "drag_variable; load_fraction")
    seals: list[GearboxSealSection] = Field(
        default_factory=list, description="[[gearbox.seals]] tables: shaft (pinion | wheel), diameter_mm (radial "
                                          "lip seals)")
    internal: GearboxInternalSection = GearboxInternalSection()
    shaft_mass_kg: Annotated[float, Field(gt=0.0, le=1e5, allow_inf_nan=False)] = Field(
        4.0, description="mass of both shafts with their bearings [kg], half each")
    pinion_heat_share: Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False)] | None = Field(
        None, description="pinion's share of the tooth friction heat [–]; default Blok's partition (equal flash "
                          "temperatures) averaged over the path with the friction power")
    friction_model: Literal["schlenk", "paper", "iso_tr_13989_2", "constant"] = Field(
        "schlenk", description="mean friction law of the tooth loss: schlenk (Schlenk 1994 with the X_L of "
                               "Fernandes et al. 2015: FZG power-loss work, the default), paper (DIN 3990-4 as "
                               "Luo & Li Eq. 27, the paper's damping law), iso_tr_13989_2 (the integral-temperature "
                               "method's), constant")
    friction_coefficient: Annotated[float, Field(gt=0.0, le=0.3, allow_inf_nan=False)] | None = Field(
        None, description="the mean friction coefficient [–] of friction_model = 'constant' (only there)")
    lubricant_factor: Annotated[float, Field(gt=0.0, le=3.0, allow_inf_nan=False)] | None = Field(
        None, description="X_L of the friction law [–]; default the law's value for the oil's base oil")
    conditioning: GearboxConditioningSection | None = Field(
        None, description="oil conditioning of a test rig (heater, cooler, thermostat set point) for warm-ups")

    @model_validator(mode="after")
    def _friction_inputs(self):
        check_friction_inputs("gearbox", self.friction_model, self.friction_coefficient, self.lubricant_factor)
        return self
