"""The gearbox as resolved, frozen inputs: gear pair, oil, housing, bearings, seals, capacities and the internal
heat-transfer coefficients, plus the operating point. Everything in SI (temperatures in °C).

Each shaft (with its bearings) is its own node. Each gear body conducts to its own shaft through the solid between
its root circle and its bore: a cylindrical wall, G = 2π·k·b/ln(r_f/r_bore) (Fourier's law in a hollow cylinder,
Incropera et al., Fundamentals of Heat and Mass Transfer, 6th ed., Eq. 3.27 for R_t,cond = ln(r2/r1)/(2πLk)); a
gear without a bore (cut on its shaft) conducts from its rim to its volume mean, G = 8π·k·b (the same book's
solid cylinder with uniform generation, §3.5.2: T_mean − T_s = q'/(8πk)). The contact resistance of the fit is
left out (it lowers G), and the node's mean temperature lies inside the annulus (that raises G): the formula is
an estimate, not a bound. The other internal coefficients (gear–oil, oil–housing, shafts–oil, shafts–housing
through the bearings) have no general correlation that this project could verify: they are inputs with stated
defaults of the usual order of magnitude for a dip-lubricated spur gearbox (gear–oil 100–1000 W/(m²K) where
dipped, oil–wall 50–300 W/(m²K); Changenet, Oviedo-Marlot & Velex 2006 fit theirs to measurements), given for
both shafts together and shared between them: the shafts–housing path in proportion to the bearings on each shaft
(it runs through the bearing seats; half each without bearings), the shafts–oil path and the shafts' mass half
each. They are the first thing to calibrate on a measured warm-up (docs/gearbox-temperature.md, "What would
validate it").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

from thermogear.errors import CaseError
from thermogear.friction.models import DEFAULT_LOSS_FRICTION_MODEL, FRICTION_MODELS, FrictionLaw
from thermogear.gearbox.bearing_loss import RollingBearing
from thermogear.gearbox.injection import OilJet
from thermogear.gearbox.mesh_loss import rigid_pinion_heat_share
from thermogear.gearbox.shaft_conduction import ShaftSpan, gear_shaft_paths
from thermogear.geometry import GearPair
from thermogear.helical.geometry import HelicalPair
from thermogear.lubricant import Lubricant


def _check_positive(key: str, value: float, allow_zero: bool = False) -> None:
    if (isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value)
            or not (value >= 0.0 if allow_zero else value > 0.0)):
        raise CaseError(key, value, ">= 0" if allow_zero else "> 0", "a size, mass, coefficient or conductance")


@dataclass(frozen=True)
class MountedBearing:
    """A rolling bearing on the pinion shaft (``on_wheel_shaft`` False) or the wheel shaft, carrying
    ``load_fraction`` of the tooth normal force as radial load (0.5 for a gear centred between two bearings; for a
    drivetrain bearing its static force per newton of tooth load); ``name`` the drivetrain bearing it is (None: a
    ``[[gearbox.bearings]]`` entry)."""

    bearing: RollingBearing
    on_wheel_shaft: bool
    load_fraction: float = 0.5
    name: str | None = None


@dataclass(frozen=True)
class LipSeal:
    """A radial lip seal on a shaft of diameter [mm]."""

    shaft_diameter_mm: float
    on_wheel_shaft: bool


@dataclass(frozen=True)
class OilConditioning:
    """A test rig's oil conditioning: a heater of up to ``heater`` [W] and a cooler of up to ``cooling`` [W] driven
    by a proportional thermostat of ``gain`` [W/K] on the sump temperature, holding it near ``setpoint_c`` [°C]:
    P = clip(gain·(set − T_oil), −cooling, heater) into the oil node [W]."""

    setpoint_c: float
    heater: float = 0.0
    cooling: float = 0.0
    gain: float = 200.0

    def __post_init__(self) -> None:
        _check_positive("conditioning.heater_w", self.heater, allow_zero=True)
        _check_positive("conditioning.cooling_w", self.cooling, allow_zero=True)
        _check_positive("conditioning.gain_w_per_k", self.gain)
        if not (math.isfinite(self.setpoint_c) and -40.0 <= self.setpoint_c <= 200.0):
            raise CaseError("conditioning.setpoint_c", self.setpoint_c, "[-40, 200] °C", "an oil temperature")

    def power(self, oil_c: float) -> float:
        """Heat into the oil [W] at the sump temperature ``oil_c`` [°C] (negative: cooling)."""
        return float(min(max(self.gain * (self.setpoint_c - oil_c), -self.cooling), self.heater)) + 0.0  # no -0.0


@dataclass(frozen=True)
class Housing:
    """Outer box of the housing (length, width, height [m]), its mass [kg], specific heat [J/(kg·K)], emissivity
    [–], linear expansion [1/K], air speed along the walls [m/s] (0: still air), the inner area wetted by the
    oil [m²] and whether the bottom face sheds heat (False: it stands on a foundation, taken as adiabatic)."""

    length: float
    width: float
    height: float
    mass: float
    specific_heat: float = 500.0  # grey cast iron [J/(kg·K)]
    emissivity: float = 0.9  # painted [–]
    expansion: float = 10.5e-6  # grey cast iron [1/K]
    air_speed: float = 0.0
    oil_wetted_area: float = 0.05
    bottom_cooled: bool = False

    def __post_init__(self) -> None:
        for key in ("length", "width", "height", "mass", "specific_heat", "oil_wetted_area"):
            _check_positive(f"housing.{key}", getattr(self, key))
        _check_positive("housing.air_speed", self.air_speed, allow_zero=True)
        if not 0.0 <= self.emissivity <= 1.0:
            raise CaseError("housing.emissivity", self.emissivity, "[0, 1]", "a grey-body emissivity")


@dataclass(frozen=True)
class GearboxDescription:
    """One gear stage in a dip-lubricated housing (see the module docstring for the internal coefficients): a
    spur pair, or a helical pair (``helical_pair``; ``gear_pair`` is then its transverse section).

    Masses [kg] of the pinion, wheel and of both shafts with their bearings (half each), oil volume [m³],
    immersion depths [m] of the wheel and pinion (0: above the oil), composite roughness R_a [m], the friction
    formula's lubricant factor X_L, the pinion's share of the tooth friction heat (None: Blok's partition
    averaged over the path, :attr:`heat_share`), the gear loss factor (None:
    Ohlendorf's H_V of the pair; give the mesh model's H_VL to use its load sharing), the cold normal backlash
    [m] (None: the AGMA 2002 minimum) and the assembly temperature [°C] at which it holds; ``oil_jet``: the
    into-mesh jet of injection lubrication (its impulse loss; the gears then usually dip nowhere: immersions 0).
    ``friction``: the mean friction law of the tooth loss (:data:`thermogear.friction.models.FRICTION_MODELS`,
    default Schlenk's), ``friction_constant`` its value for the ``"constant"`` law; ``lubricant_factor`` X_L of
    that law (None: the law's value for the oil's base oil). ``conditioning``: a test rig's thermostat-driven
    heater and cooler on the oil (:class:`OilConditioning`). ``helical_pair``: the helical pair whose transverse
    section ``gear_pair`` is (None: a spur pair); its helix enters the losses (:mod:`~thermogear.gearbox.losses`).
    """

    gear_pair: GearPair
    lubricant: Lubricant
    housing: Housing
    oil_volume: float
    pinion_mass: float
    wheel_mass: float
    shaft_mass: float
    wheel_immersion: float
    pinion_immersion: float = 0.0
    bearings: tuple[MountedBearing, ...] = ()
    seals: tuple[LipSeal, ...] = ()
    roughness: float = 0.5e-6
    lubricant_factor: float | None = None
    pinion_heat_share: float | None = None  # None: Blok's partition over the path (mesh_loss)
    loss_factor: float | None = None
    steel_specific_heat: float = 465.0  # [J/(kg·K)]
    oil_specific_heat: float = 2000.0  # [J/(kg·K)]
    gear_expansion: float = 11.5e-6  # [1/K]
    gear_oil_coefficient: float = 200.0  # [W/(m²·K)] over each gear's whole surface (assumed: calibrate)
    oil_housing_coefficient: float = 150.0  # [W/(m²·K)] over the wetted inner wall (assumed: calibrate)
    gear_shaft_conductance: float | None = None  # [W/K] each gear to its shaft (None: the hub formula)
    shaft_oil_conductance: float = 4.0  # [W/K] both shafts to the oil (assumed: calibrate)
    shaft_housing_conductance: float = 8.0  # [W/K] both shafts through the bearing seats (assumed: calibrate)
    steel_conductivity: float = 46.0  # k of the gears [W/(m·K)] (carbon steel; the material's)
    backlash: float | None = None
    assembly_c: float = 20.0
    oil_jet: OilJet | None = None  # injection lubrication: an into-mesh jet (None: dip lubrication only)
    friction: FrictionLaw = FRICTION_MODELS[DEFAULT_LOSS_FRICTION_MODEL]
    friction_constant: float | None = None
    conditioning: OilConditioning | None = None  # a rig's heater/cooler on the oil (None: none)
    pinion_shaft_spans: tuple[ShaftSpan, ...] = ()  # the pinion's shaft from its seat to each bearing (fins)
    wheel_shaft_spans: tuple[ShaftSpan, ...] = ()  # the wheel's likewise (() : seat and bearings one node)
    helical_pair: HelicalPair | None = None
    notes: tuple[str, ...] = field(default=(), compare=False)

    def __post_init__(self) -> None:
        for key in ("oil_volume", "pinion_mass", "wheel_mass", "shaft_mass", "steel_specific_heat",
                    "oil_specific_heat", "steel_conductivity"):
            _check_positive(key, getattr(self, key))
        if self.gear_shaft_conductance is not None:
            _check_positive("gear_shaft_conductance", self.gear_shaft_conductance, allow_zero=True)
        if self.lubricant_factor is not None:
            _check_positive("lubricant_factor", self.lubricant_factor)
        if self.friction_constant is not None:
            _check_positive("friction_constant", self.friction_constant)
        for key in ("wheel_immersion", "pinion_immersion", "roughness", "gear_expansion", "gear_oil_coefficient",
                    "oil_housing_coefficient", "shaft_oil_conductance", "shaft_housing_conductance"):
            _check_positive(key, getattr(self, key), allow_zero=True)
        if self.pinion_heat_share is not None and not 0.0 <= self.pinion_heat_share <= 1.0:
            raise CaseError("pinion_heat_share", self.pinion_heat_share, "[0, 1]", "a share of the friction heat")
        for key, depth, gear in (("wheel_immersion", self.wheel_immersion, self.gear_pair.wheel),
                                 ("pinion_immersion", self.pinion_immersion, self.gear_pair.pinion)):
            if depth > 2.0 * gear.tip_radius:
                raise CaseError(key, depth, f"[0, {2.0 * gear.tip_radius:.4g}] m", "at most the tip diameter")
        if self.helical_pair is not None and self.helical_pair.transverse != self.gear_pair:
            raise CaseError("helical_pair", "another pair's helix", "the helix of gear_pair (its transverse section)",
                            "the losses take the helix of the pair the network is built around")

    @property
    def helix_angle(self) -> float:
        """β on the reference cylinder [rad] (0: spur)."""
        return 0.0 if self.helical_pair is None else self.helical_pair.helix_angle

    @property
    def base_helix_angle(self) -> float:
        """β_b [rad] (0: spur)."""
        return 0.0 if self.helical_pair is None else self.helical_pair.base_helix_angle

    @property
    def total_contact_ratio(self) -> float:
        """ε_γ = ε_α + ε_β [–] (ε_α for a spur pair)."""
        return (self.gear_pair.contact_ratio if self.helical_pair is None
                else self.helical_pair.total_contact_ratio)

    def gear_surface(self, wheel: bool) -> float:
        """Outer surface of a gear body [m²]: two faces (tip circle less the bore) and the rim (tip cylinder)."""
        gear = self.gear_pair.wheel if wheel else self.gear_pair.pinion
        return (2.0 * math.pi * (gear.tip_radius**2 - gear.bore_radius**2)
                + 2.0 * math.pi * gear.tip_radius * gear.face_width)

    @property
    def friction_lubricant_factor(self) -> float:
        """X_L of the friction law [–]: the one given, else the law's for the oil's base oil."""
        return self.friction.lubricant_factor(self.lubricant.base_oil, self.lubricant_factor)

    @cached_property
    def heat_share(self) -> float:
        """The pinion's share of the tooth friction heat [–]: the one given, else Blok's partition averaged over
        the path (:func:`~thermogear.gearbox.mesh_loss.rigid_pinion_heat_share`)."""
        if self.pinion_heat_share is not None:
            return float(self.pinion_heat_share)
        return rigid_pinion_heat_share(self.gear_pair)

    def gear_body_conductance(self, wheel: bool) -> float:
        """Conductance of a gear body to its shaft [W/K]: the one given, else 2π·k·b/ln(r_f/r_bore), or 8π·k·b for
        a gear without a bore (module docstring)."""
        if self.gear_shaft_conductance is not None:
            return float(self.gear_shaft_conductance)
        gear = self.gear_pair.wheel if wheel else self.gear_pair.pinion
        conductivity, width = self.steel_conductivity, gear.face_width
        if gear.bore_radius <= 0.0:
            return 8.0 * math.pi * conductivity * width
        return 2.0 * math.pi * conductivity * width / math.log(gear.root_radius / gear.bore_radius)

    def shaft_paths(self, wheel: bool) -> tuple[float, float, float]:
        """(gear–its shaft's node, gear–oil, shaft node–oil) [W/K] through the gear's body and the stretches of
        shaft from its seat to its bearings (:func:`~thermogear.gearbox.shaft_conduction.gear_shaft_paths`: fins
        wetted at the gear–oil coefficient, the seat eliminated); (body, 0, 0) without spans."""
        spans = self.wheel_shaft_spans if wheel else self.pinion_shaft_spans
        return gear_shaft_paths(self.gear_body_conductance(wheel), spans, self.steel_conductivity,
                                self.gear_oil_coefficient)

    @property
    def shaft_housing_conductances(self) -> tuple[float, float]:
        """(pinion shaft, wheel shaft) to the housing [W/K]: the total in proportion to the bearings on each shaft
        (half each without bearings)."""
        on_wheel = sum(1 for mounted in self.bearings if mounted.on_wheel_shaft)
        count = len(self.bearings)
        wheel_share = 0.5 if count == 0 else on_wheel / count
        total = self.shaft_housing_conductance
        return ((1.0 - wheel_share) * total, wheel_share * total)

    @property
    def capacities(self) -> tuple[float, float, float, float, float, float]:
        """C = m·c of pinion, wheel, pinion shaft, wheel shaft (half the shafts' mass each), oil (ρ at 15 °C·V0),
        housing [J/K]."""
        oil_mass = float(self.lubricant.density(15.0)) * self.oil_volume
        steel = self.steel_specific_heat
        return (self.pinion_mass * steel, self.wheel_mass * steel, 0.5 * self.shaft_mass * steel,
                0.5 * self.shaft_mass * steel, oil_mass * self.oil_specific_heat,
                self.housing.mass * self.housing.specific_heat)


@dataclass(frozen=True)
class GearboxOperatingPoint:
    """Pinion speed [rpm], pinion torque [N·m] and ambient air temperature [°C]."""

    speed_rpm: float
    torque: float
    ambient_c: float = 20.0

    def __post_init__(self) -> None:
        _check_positive("operating.speed_rpm", self.speed_rpm)
        _check_positive("operating.torque_nm", self.torque, allow_zero=True)
        if not -60.0 <= self.ambient_c <= 80.0:
            raise CaseError("operating.ambient_c", self.ambient_c, "[-60, 80] °C", "air around a gearbox")

    @property
    def input_power(self) -> float:
        """T1·ω1 [W]."""
        return self.torque * self.speed_rpm * math.pi / 30.0
