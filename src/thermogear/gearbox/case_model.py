"""The gearbox of a case: its ``[gearbox]`` section resolved into a :class:`GearboxDescription`, the operating point,
and the predicted steady temperatures that ``[temperature].model = "gearbox"`` hands to every command.

What comes from where: the gear pair, its material (density, specific heat, expansion), roughness, cold backlash
(``gears.backlash_normal_um``) and assembly temperature (``temperature.reference_c``) from the case; the oil from
``[lubricant]`` (its X_L from the base oil); housing, oil volume and immersion, bearings, seals, ambient and the
internal coefficients from ``[gearbox]``. Gear masses are those of solid discs (tip circle less the bore, face
width) of the material's density.

Housing specific heats where the case gives none: grey cast iron 500, carbon steel 434, aluminium 903 J/(kg·K)
(room-temperature handbook values, e.g. Incropera et al., Fundamentals of Heat and Mass Transfer, Table A.1; the
cast-iron value is the description's default). A housing given by its cooled area A is a cube of side
√(A/5) (four walls and the top; √(A/6) with the bottom cooled). The oil-wetted inner area defaults to the floor
L·W plus the walls up to the oil level V/(L·W).
"""

from __future__ import annotations

import math
import weakref
from typing import TYPE_CHECKING, Any

from thermogear import warning_scope
from thermogear.case import cached_per_case
from thermogear.errors import CaseError
from thermogear.gearbox.bearing_entries import drivetrain_mounted_bearings, rolling_bearing
from thermogear.gearbox.shaft_conduction import drivetrain_shaft_spans
from thermogear.gearbox.injection import OilJet, jet_at_outlet
from thermogear.friction.models import friction_law
from thermogear.lubricant.methods import lubrication_method
from thermogear.gearbox.description import (GearboxDescription, GearboxOperatingPoint, Housing, LipSeal, MountedBearing,
                                            OilConditioning)
from thermogear.gearbox.input_checks import check_gearbox_inputs, housing_box, oil_floor_and_level
from thermogear.gearbox.network import NoSteadyStateError
from thermogear.temperature.limits import MATERIAL_MAXIMUM_C
from thermogear.thermoelastic.materials import HOUSING_EXPANSION_PER_K

if TYPE_CHECKING:
    from collections.abc import Callable

    from thermogear.case import Case
    from thermogear.geometry import GearPair
    from thermogear.helical.geometry import HelicalPair
    from thermogear.lubricant import Lubricant
    from thermogear.materials import Material
    from thermogear.schema import DrivetrainSection, GearsSection, TemperatureSection
    from thermogear.schema.gearbox import GearboxSection
    from thermogear.schema.housing import HousingSection
    from thermogear.gearbox.model import GearboxSteadyState, GearboxThermalModel
    from thermogear.operating import OperatingPoint

#: Specific heats of the housing materials [J/(kg·K)] (module docstring).
HOUSING_SPECIFIC_HEAT = {"cast_iron": 500.0, "steel": 434.0, "aluminium": 903.0}


def gearbox_section(section: "GearboxSection | None") -> "GearboxSection":
    """A case's ``[gearbox]`` section, refused (CaseError) where the case has none."""
    if section is None:
        raise CaseError("gearbox", None, "a [gearbox] section (housing, oil, bearings, seals)",
                        "the gearbox thermal model needs the gearbox around the gear pair")
    return section


def check_gearbox_section(gearbox_model: "GearboxThermalModel | None") -> None:
    """Load-time check of a ``[gearbox]`` section under any temperature model: the description builds.

    A load-time check (:data:`thermogear.composition.CASE_CHECKS`) whose work is done by asking for the piece
    ``gearbox_model`` (:mod:`thermogear.case.pieces`): resolving it builds the case's description (memoised: every
    later stage asks for this one), None for a case without ``[gearbox]``."""


def housing_expansion(housing: "HousingSection", gearbox: "GearboxSection | None") -> float:
    """Linear expansion of the housing [1/K]: ``[housing].thermal_expansion_per_k``, else the material of
    ``[housing]`` when it is given there, else that of ``[gearbox.housing]``."""
    if housing.thermal_expansion_per_k is not None:
        return float(housing.thermal_expansion_per_k)
    material = housing.material if "material" in housing.model_fields_set else gearbox_section(
        gearbox).housing.material
    return HOUSING_EXPANSION_PER_K[material]


def _housing(section: "GearboxSection", expansion: float) -> Housing:
    """The housing of a ``[gearbox]`` section (module docstring) with its linear expansion ``expansion`` [1/K]; the
    default wetted area is the inner floor plus the walls up to the oil level
    (:func:`~thermogear.gearbox.input_checks.oil_floor_and_level`; the floor of the footprint's proportions)."""
    housing = section.housing
    length, width, height = housing_box(section)
    wetted = housing.oil_wetted_area_m2
    if wetted is None:
        floor, level = oil_floor_and_level(section)
        scale = math.sqrt(floor / (length * width))
        wetted = floor + 2.0 * (length + width) * scale * level
    specific_heat = housing.specific_heat_j_per_kg_k or HOUSING_SPECIFIC_HEAT[housing.material]
    return Housing(length=length, width=width, height=height, mass=housing.mass_kg, specific_heat=specific_heat,
                   emissivity=housing.emissivity, expansion=expansion, air_speed=housing.air_speed_m_s,
                   oil_wetted_area=wetted, bottom_cooled=housing.bottom_cooled)


def _bearings(section) -> tuple[MountedBearing, ...]:
    mounted = []
    for entry in section.bearings:
        bearing = rolling_bearing(entry)
        fraction = 1.0 / entry.count if entry.load_fraction is None else entry.load_fraction
        mounted.extend(MountedBearing(bearing, entry.shaft == "wheel", fraction) for _ in range(entry.count))
    return tuple(mounted)


def gearbox_description(gearbox: "GearboxSection | None", pair: "GearPair", material: "Material",
                        oil: "Lubricant", temperature: "TemperatureSection", housing: "HousingSection",
                        gears_input: "GearsSection | None", drivetrain: "DrivetrainSection | None",
                        roughness_ra: float, helical_pair: "HelicalPair | None" = None) -> GearboxDescription:
    """The :class:`GearboxDescription` (module docstring) of a ``[gearbox]`` section around the cold ``pair`` of
    ``material``, lubricated by ``oil``, with the case's ``[temperature]`` (its assembly temperature), ``[housing]``,
    ``[gears]`` (backlash), ``[drivetrain]`` (bearings with loss data), composite roughness Ra [m] and, for a
    helical pair, the ``helical_pair`` whose transverse section ``pair`` is: the pieces
    :func:`gearbox_model_from_case` resolves a case into."""
    section = gearbox_section(gearbox)
    check_gearbox_inputs(section, pair, temperature)

    def disc_mass(gear) -> float:
        return material.density * math.pi * (gear.tip_radius**2 - gear.bore_radius**2) * gear.face_width

    lubrication = lubrication_method(section.oil.lubrication)
    default_immersion = pair.operating_pitch_radii[1] if lubrication.wheel_dipped else 0.0
    wheel_immersion = (default_immersion if section.oil.wheel_immersion_mm is None
                       else section.oil.wheel_immersion_mm * 1e-3)
    jet = OilJet(section.oil.injection_flow_l_min / 60000.0, section.oil.jet_speed_m_s,
                 at_outlet=jet_at_outlet(section.oil.jet_position)) if lubrication.oil_jet else None
    for key, depth, gear in (("wheel_immersion_mm", wheel_immersion, pair.wheel),
                             ("pinion_immersion_mm", section.oil.pinion_immersion_mm * 1e-3, pair.pinion)):
        if depth > 2.0 * gear.tip_radius:
            raise CaseError(f"gearbox.oil.{key}", round(depth * 1e3, 6), f"<= the tip diameter "
                            f"{2e3 * gear.tip_radius:.4g} mm", "a gear cannot dip deeper than it is tall")
    backlash_um = None if gears_input is None else gears_input.backlash_normal_um
    law = friction_law(section.friction_model)
    law.lubricant_factor(oil.base_oil, section.lubricant_factor)  # refuses a base oil the law has no X_L for
    pinion_spans, wheel_spans = drivetrain_shaft_spans(drivetrain)
    conditioning = None if section.conditioning is None else OilConditioning(
        section.conditioning.setpoint_c, section.conditioning.heater_w, section.conditioning.cooling_w,
        section.conditioning.gain_w_per_k)
    return GearboxDescription(
        gear_pair=pair, lubricant=oil, housing=_housing(section, housing_expansion(housing, section)),
        oil_volume=section.oil.volume_l * 1e-3,
        pinion_mass=disc_mass(pair.pinion), wheel_mass=disc_mass(pair.wheel), shaft_mass=section.shaft_mass_kg,
        wheel_immersion=wheel_immersion, pinion_immersion=section.oil.pinion_immersion_mm * 1e-3,
        bearings=_bearings(section) + drivetrain_mounted_bearings(drivetrain, pair, material, helical_pair),
        seals=tuple(LipSeal(seal.diameter_mm, seal.shaft == "wheel") for seal in section.seals),
        roughness=roughness_ra, lubricant_factor=section.lubricant_factor, friction=law,
        friction_constant=section.friction_coefficient, conditioning=conditioning,
        pinion_heat_share=section.pinion_heat_share, steel_specific_heat=material.specific_heat,
        steel_conductivity=material.thermal_conductivity,
        oil_specific_heat=section.oil.specific_heat_j_per_kg_k, gear_expansion=material.thermal_expansion,
        gear_oil_coefficient=section.internal.gear_oil_w_per_m2_k,
        oil_housing_coefficient=section.internal.oil_housing_w_per_m2_k,
        gear_shaft_conductance=section.internal.gear_shaft_w_per_k,
        shaft_oil_conductance=section.internal.shaft_oil_w_per_k,
        shaft_housing_conductance=section.internal.shaft_housing_w_per_k,
        backlash=None if backlash_um is None else backlash_um * 1e-6, assembly_c=temperature.reference_c,
        oil_jet=jet, pinion_shaft_spans=pinion_spans, wheel_shaft_spans=wheel_spans, helical_pair=helical_pair)


def gearbox_operating_point(operating: "OperatingPoint", gearbox: "GearboxSection | None",
                            speed_rpm: float | None = None, torque: float | None = None) -> GearboxOperatingPoint:
    """The pinion speed [rpm] and torque [N·m] of a case's operating point ``operating`` (or the ones given) with the
    ambient temperature of its ``[gearbox]`` section."""
    speed = operating.speed_rpm if speed_rpm is None else float(speed_rpm)
    load = operating.torque_at(speed) if torque is None else float(torque)
    return GearboxOperatingPoint(speed, load, gearbox_section(gearbox).ambient_c)


@cached_per_case
def gearbox_model_from_case(gearbox: "GearboxSection | None", gear_pair: "GearPair", material: "Material",
                            oil: "Lubricant", temperature: "TemperatureSection", housing: "HousingSection",
                            gears_input: "GearsSection | None", drivetrain: "DrivetrainSection | None",
                            roughness_ra: float, helical_pair: "HelicalPair | None"):
    """The :class:`~thermogear.gearbox.model.GearboxThermalModel` of a case with a ``[gearbox]`` section, its
    ``description`` the :class:`GearboxDescription` of these pieces of the case (:func:`gearbox_description`).
    Called with the case (``gearbox_model_from_case(case)``), memoised per case
    (:func:`thermogear.case.cached_per_case`)."""
    from thermogear.gearbox.model import GearboxThermalModel  # noqa: PLC0415

    return GearboxThermalModel(gearbox_description(gearbox, gear_pair, material, oil, temperature, housing,
                                                   gears_input, drivetrain, roughness_ra, helical_pair))


#: Steady states already solved, per thermal model (by identity: the model is built once per case and compares by
#: identity) and per operating point (a frozen value: speed, torque, ambient), with the warnings their solution
#: raised. Weakly keyed, so the entries go with the model (and so with the case that built it).
_STEADY_STATES: "weakref.WeakKeyDictionary[GearboxThermalModel, dict]" = weakref.WeakKeyDictionary()


def predicted_steady_state(model: "GearboxThermalModel", operating: GearboxOperatingPoint) -> "GearboxSteadyState":
    """The steady state of the gearbox ``model`` at ``operating`` (raises NoSteadyStateError on runaway), solved once
    per model and operating point: the case's temperature model, its temperature provider and the commands' note
    all ask for it. The warnings of the first solution are raised again on every later call."""
    states = _STEADY_STATES.setdefault(model, {})
    entry = states.get(operating)
    if entry is None:
        with warning_scope.recorded() as caught:
            state = model.steady_state(operating)
        entry = states[operating] = (state, warning_scope.kept(caught))
    warning_scope.raise_again(entry[1])  # the memo never swallows a warning the second time
    return entry[0]


def describe_prediction(state: "GearboxSteadyState") -> str:
    """One line: the predicted temperatures and the losses that made them (rounded to 0.1 K and 0.1 W)."""
    losses = state.losses
    return (f"temperatures predicted by the gearbox thermal model (steady state): pinion {state.pinion_c:.1f} °C, "
            f"wheel {state.wheel_c:.1f} °C, oil {state.oil_c:.1f} °C, housing {state.housing_c:.1f} °C, from "
            f"losses {losses.total:.1f} W (mesh {losses.mesh:.1f}, bearings {losses.bearings:.1f}, seals "
            f"{losses.seals:.1f}, churning {losses.churning:.1f}"
            + (f", oil jet {losses.injection:.1f}" if losses.injection else "") + " W)")


class PredictedTemperatureError(CaseError):
    """The gearbox network's stable steady state at the case's operating point lies above the material data: the
    mesh cannot be evaluated there, so commands that evaluate it (``check``, ``run``, ``sweep``) refuse the case.
    It carries what it reports: the key, value, allowed range and reason of a CaseError, and ``state`` the steady
    state, flags included (None where the network has no stable steady state there: thermal runaway). The commands
    that report the network itself (``gearbox``, ``warmup --model gearbox``) go on with the case before its
    temperatures were predicted (``load_case(..., predict_temperatures=False)``, :func:`load_gearbox_case`)."""

    def __init__(self, state: "GearboxSteadyState | None", key: str, value, allowed: str, reason: str) -> None:
        super().__init__(key, value, allowed, reason)
        self.state = state


def _no_steady_state(given: dict, operating: GearboxOperatingPoint, error: "NoSteadyStateError") -> tuple:
    """(key, value, allowed, reason) of the load-time error of a ``temperature.model = "gearbox"`` case whose network
    has no stable steady state at its operating point: the load key the case file ``given`` as its ``[operating]``
    and the fold torque where the stable branch ends (thermal runaway), else the temperature model."""
    fold = getattr(error, "fold_torque", None)
    reason = f"{error} (`thermogear gearbox CASE` reports the network itself)"
    if fold is None:
        return ("temperature.model", "gearbox", "a gearbox network with a stable steady state at the operating point",
                reason)
    name = next((name for name in ("torque_nm", "power_kw", "fzg_load_stage") if name in given), "torque_nm")
    return (f"operating.{name}", given.get(name),
            f"a pinion torque below the fold near {fold:.1f} N·m at {operating.speed_rpm:g} rpm", reason)


def load_gearbox_case(name_or_path) -> "Case":
    """A case loaded for the commands that report the gearbox network itself (``gearbox``, ``warmup --model
    gearbox``): as :func:`thermogear.case.load_case`, except that a ``temperature.model = "gearbox"`` case whose
    predicted steady state lies above the material data is returned before that prediction (the network's result
    is reported with its flags there, not refused)."""
    from thermogear.case import load_case  # noqa: PLC0415

    try:
        return load_case(name_or_path)
    except PredictedTemperatureError:
        return load_case(name_or_path, predict_temperatures=False)


def predicted_temperatures(gearbox: "GearboxSection | None", housing: "HousingSection",
                           lubricant: "LubricantSection", operating_point: "OperatingPoint",
                           gearbox_model_of: "Callable[[], GearboxThermalModel]", document: dict,
                           assumptions: tuple[str, ...]) -> dict[str, Any]:
    """What the case's parts are under ``temperature.model = "gearbox"``, as every command sees them: the predicted
    oil temperature as ``lubricant.operating_temperature_c`` (viscosity, damping), the housing node's as
    ``housing.temperature_c`` (centre distance, backlash) and the prediction added to the ``assumptions``; the
    loader writes them into the case. The gear temperatures come from the ``"gearbox"`` temperature provider
    (:mod:`thermogear.gearbox.provider`). The ``"gearbox"`` temperature model's resolver
    (:data:`thermogear.composition.TEMPERATURE_MODELS`): its parameters name the pieces of the case it reads
    (``document``: the case file as loaded, for the load key a refusal names)."""
    gearbox_section(gearbox)
    if housing.temperature_c is not None:
        raise CaseError("housing.temperature_c", housing.temperature_c, "absent with temperature.model = "
                        "'gearbox'", "the gearbox model predicts the housing temperature")
    if "operating_temperature_c" in lubricant.model_fields_set:
        raise CaseError("lubricant.operating_temperature_c", lubricant.operating_temperature_c,
                        "absent with temperature.model = 'gearbox'", "the gearbox model predicts the oil temperature")
    operating = gearbox_operating_point(operating_point, gearbox)
    try:
        state = predicted_steady_state(gearbox_model_of(), operating)  # its network, once the sections are checked
    except NoSteadyStateError as error:  # a case the commands cannot evaluate: refused at load, naming the key
        raise PredictedTemperatureError(None, *_no_steady_state(document.get("operating", {}), operating,
                                                                error)) from error
    hottest = max(state.pinion_c, state.wheel_c, state.oil_c, state.housing_c)
    if hottest > MATERIAL_MAXIMUM_C:
        raise PredictedTemperatureError(state, "temperature.model", "gearbox",
                        f"predicted temperatures <= {MATERIAL_MAXIMUM_C:g} °C",
                        f"the gearbox network's stable steady state at {operating.speed_rpm:g} rpm, "
                        f"{operating.torque:g} N·m has pinion {state.pinion_c:.1f} °C, wheel {state.wheel_c:.1f} °C, "
                        f"oil {state.oil_c:.1f} °C, housing {state.housing_c:.1f} °C ({state.flag_text}): above the "
                        f"{MATERIAL_MAXIMUM_C:g} °C the material data cover, so the mesh cannot be evaluated there "
                        "(`thermogear gearbox CASE` reports the steady state itself)")
    housing_update = {"temperature_c": round(state.housing_c, 6)}
    if "material" not in housing.model_fields_set:
        housing_update["material"] = gearbox_section(gearbox).housing.material
    return {"lubricant": lubricant.model_copy(update={"operating_temperature_c": round(state.oil_c, 6)}),
            "housing": housing.model_copy(update=housing_update),
            "assumptions": assumptions + (describe_prediction(state),)}
