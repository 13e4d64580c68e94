"""Rolling-bearing and seal power losses.

Bearings: the SKF model of the frictional moment (SKF General Catalogue 6000 EN (2005), "The SKF model for
calculating the frictional moment", pp. 88–103; SKF Rolling Bearings catalogue 2016 pp. 97–106), in the
catalogue's units — moments N·mm, speeds r/min, viscosity mm²/s, diameters mm, loads N:

    M = φ_ish·φ_rs·M_rr + M_sl + M_seal + M_drag
    M_rr = G_rr·(ν·n)^0.6                          rolling
    M_sl = G_sl·μ_sl,  μ_sl = φ_bl·μ_bl + (1 − φ_bl)·μ_EHL,  φ_bl = 1/exp(2.6e-8·(n·ν)^1.4·d_m)   sliding
    φ_ish = 1/(1 + 1.84e-9·(n·d_m)^1.28·ν^0.64)    inlet shear heating
    φ_rs = 1/exp(K_rs·ν·n·(d + D)·√(K_Z/(2(D − d))))   kinematic replenishment/starvation
    cylindrical roller: G_rr = R1·d_m^2.41·F_r^0.31,  G_sl = S1·d_m^0.9·F_a + S2·d_m·F_r,
                        M_drag = 10·V_M·K_roll·B·d_m⁴·n²,  K_roll = K_L·K_Z·(d + D)/(D − d)·1e-12
    deep-groove ball (F_a = 0): G_rr = R1·d_m^1.96·F_r^0.54,  G_sl = S1·d_m^−0.26·F_r^(5/3),
                        M_drag = V_M·K_ball·d_m⁵·n²,  K_ball = K_Z·(d + D)/(D − d)·1e-12

The G_rr, G_sl and μ_sl forms were read in the catalogue; the reduction factors φ_ish, φ_rs, the drag formulas,
K_rs (3e-8 oil bath, 6e-8 grease or oil–air) and the drag variable V_M (a catalogue diagram against the oil level)
were not re-read here: they are inputs of each bearing, documented as such in docs/gearbox-temperature.md.
Validity (catalogue): constant speed below the speed ratings, no misalignment beyond the limits, radial load
above the minimum load.

Seals: radial lip seal P = 7.69e-6·d_sh²·n [W] (d_sh mm, n r/min), the form quoted from ISO/TR 14179-2:2001 by
the Technical University of Munich's open powertrain design code (not read in the standard: unverified).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.errors import CaseError

#: Boundary-lubrication sliding friction coefficient μ_bl of the SKF model ("generally ≈ 0.15").
BOUNDARY_SLIDING_FRICTION = 0.15


def _positive(key: str, value: float, allow_zero: bool = False) -> float:
    value = float(value)
    if not math.isfinite(value) or value < 0.0 or (value == 0.0 and not allow_zero):
        raise CaseError(key, value, ">= 0" if allow_zero else "> 0", "a bearing size, load, speed or viscosity")
    return value


def inlet_shear_heating_factor(speed_rpm, mean_diameter_mm, viscosity_mm2_s):
    """φ_ish = 1/(1 + 1.84e-9·(n·d_m)^1.28·ν^0.64) [–] (SKF 6000 EN p. 97)."""
    return 1.0 / (1.0 + 1.84e-9 * (speed_rpm * mean_diameter_mm)**1.28 * viscosity_mm2_s**0.64)


def replenishment_factor(speed_rpm, viscosity_mm2_s, bore_mm, outside_mm, replenishment_constant,
                         geometry_constant):
    """φ_rs = 1/exp(K_rs·ν·n·(d + D)·√(K_Z/(2(D − d)))) [–] (SKF 6000 EN p. 98)."""
    exponent = (replenishment_constant * viscosity_mm2_s * speed_rpm * (bore_mm + outside_mm)
                * math.sqrt(geometry_constant / (2.0 * (outside_mm - bore_mm))))
    return math.exp(-exponent)


def sliding_friction_coefficient(speed_rpm, viscosity_mm2_s, mean_diameter_mm, boundary, full_film):
    """μ_sl = φ_bl·μ_bl + (1 − φ_bl)·μ_EHL, φ_bl = exp(−2.6e-8·(n·ν)^1.4·d_m) [–] (SKF 2016 p. 105)."""
    weight = math.exp(-2.6e-8 * (speed_rpm * viscosity_mm2_s)**1.4 * mean_diameter_mm)
    return weight * boundary + (1.0 - weight) * full_film


@dataclass(frozen=True)
class BearingMoments:
    """The SKF frictional moment by source [N·m] and the power it dissipates [W]."""

    rolling: float  # φ_ish·φ_rs·M_rr
    sliding: float  # M_sl
    seal: float  # M_seal (given)
    drag: float  # M_drag
    speed_rpm: float

    @property
    def total(self) -> float:
        """M [N·m]."""
        return self.rolling + self.sliding + self.seal + self.drag

    @property
    def power(self) -> float:
        """P = M·ω [W]."""
        return self.total * self.speed_rpm * math.pi / 30.0


@dataclass(frozen=True)
class RollingBearing:
    """Constants of one rolling bearing for the SKF model (catalogue units: mm, N, r/min, mm²/s).

    ``rolling_exponents`` (a, b) and ``sliding_*`` give G_rr = R1·d_m^a·F_r^b and the G_sl form of the bearing
    type; use :meth:`cylindrical_roller` or :meth:`deep_groove_ball`. ``full_film_friction`` μ_EHL: 0.02
    cylindrical roller, 0.05 other bearings in mineral oil (SKF 2016 p. 105). ``drag_variable`` V_M from the
    catalogue's diagram for the oil level (0 above the oil); ``seal_moment`` [N·mm].
    """

    bore_mm: float
    outside_mm: float
    width_mm: float
    rolling_constant: float  # R1
    rolling_exponents: tuple[float, float]  # (exponent of d_m, exponent of F_r)
    sliding_constants: tuple[float, float]  # (S1, S2)
    roller: bool  # drag formula: roller (True) or ball
    geometry_constant: float  # K_Z
    replenishment_constant: float = 3e-8  # K_rs: 3e-8 oil bath/jet, 6e-8 grease/oil-air
    drag_variable: float = 0.0  # V_M
    roller_drag_constant: float = 0.65  # K_L (roller bearings only)
    boundary_friction: float = BOUNDARY_SLIDING_FRICTION
    full_film_friction: float = 0.02
    seal_moment: float = 0.0  # [N·mm]

    def __post_init__(self) -> None:
        _positive("bearing.bore_mm", self.bore_mm)
        if not self.outside_mm > self.bore_mm:
            raise CaseError("bearing.outside_mm", self.outside_mm, f"> bore {self.bore_mm} mm", "D > d")
        _positive("bearing.width_mm", self.width_mm)
        for key in ("rolling_constant", "geometry_constant", "boundary_friction", "full_film_friction"):
            _positive(f"bearing.{key}", getattr(self, key))
        for key in ("replenishment_constant", "drag_variable", "seal_moment"):
            _positive(f"bearing.{key}", getattr(self, key), allow_zero=True)

    @classmethod
    def cylindrical_roller(cls, bore_mm, outside_mm, width_mm, rolling_constant, sliding_constants,
                           geometry_constant, **others) -> "RollingBearing":
        """A cylindrical roller bearing: G_rr = R1·d_m^2.41·F_r^0.31, G_sl = S1·d_m^0.9·F_a + S2·d_m·F_r."""
        return cls(bore_mm, outside_mm, width_mm, rolling_constant, (2.41, 0.31), sliding_constants, True,
                   geometry_constant, **others)

    @classmethod
    def deep_groove_ball(cls, bore_mm, outside_mm, width_mm, rolling_constant, sliding_constant, geometry_constant,
                         **others) -> "RollingBearing":
        """A deep-groove ball bearing without axial load: G_rr = R1·d_m^1.96·F_r^0.54, G_sl = S1·d_m^−0.26·F_r^(5/3)."""
        others.setdefault("full_film_friction", 0.05)
        return cls(bore_mm, outside_mm, width_mm, rolling_constant, (1.96, 0.54), (sliding_constant, 0.0), False,
                   geometry_constant, **others)

    @property
    def mean_diameter_mm(self) -> float:
        """d_m = (d + D)/2 [mm]."""
        return 0.5 * (self.bore_mm + self.outside_mm)

    def sliding_variable(self, radial_load: float, axial_load: float = 0.0) -> float:
        """G_sl of the bearing type [catalogue units]."""
        first, second = self.sliding_constants
        d_m = self.mean_diameter_mm
        if self.roller:
            return first * d_m**0.9 * axial_load + second * d_m * radial_load
        if axial_load != 0.0:
            raise CaseError("bearing.axial_load", axial_load, "0 N for this deep-groove ball form",
                            "the F_a > 0 form of G_sl is not implemented")
        return first * d_m**-0.26 * radial_load**(5.0 / 3.0)

    def drag_moment(self, speed_rpm: float) -> float:
        """M_drag [N·mm] (module docstring)."""
        d, outside, d_m = self.bore_mm, self.outside_mm, self.mean_diameter_mm
        shape = self.geometry_constant * (d + outside) / (outside - d) * 1e-12
        if self.roller:
            return 10.0 * self.drag_variable * self.roller_drag_constant * shape * self.width_mm * d_m**4 * speed_rpm**2
        return self.drag_variable * shape * d_m**5 * speed_rpm**2

    def moments(self, speed_rpm: float, viscosity_mm2_s: float, radial_load: float,
                axial_load: float = 0.0) -> BearingMoments:
        """The frictional moment by source at a speed [r/min], the operating viscosity ν [mm²/s] (the oil at
        the bearing's temperature) and loads [N]; results in N·m."""
        speed = _positive("speed_rpm", speed_rpm, allow_zero=True)
        viscosity = _positive("viscosity_mm2_s", viscosity_mm2_s)
        radial = _positive("bearing.radial_load", radial_load, allow_zero=True)
        _positive("bearing.axial_load", axial_load, allow_zero=True)
        d_m = self.mean_diameter_mm
        exponent_d, exponent_f = self.rolling_exponents
        rolling = self.rolling_constant * d_m**exponent_d * radial**exponent_f * (viscosity * speed)**0.6
        rolling *= inlet_shear_heating_factor(speed, d_m, viscosity) * replenishment_factor(
            speed, viscosity, self.bore_mm, self.outside_mm, self.replenishment_constant, self.geometry_constant)
        friction = sliding_friction_coefficient(speed, viscosity, d_m, self.boundary_friction,
                                                self.full_film_friction)
        sliding = self.sliding_variable(radial, axial_load) * friction
        return BearingMoments(rolling * 1e-3, sliding * 1e-3, self.seal_moment * 1e-3,
                              self.drag_moment(speed) * 1e-3, speed)


def seal_power_loss(shaft_diameter_mm: float, speed_rpm: float) -> float:
    """Radial lip seal loss P = 7.69e-6·d_sh²·n [W] (ISO/TR 14179-2 as quoted; module docstring, unverified)."""
    return 7.69e-6 * _positive("seal.shaft_diameter_mm", shaft_diameter_mm)**2 * _positive(
        "speed_rpm", speed_rpm, allow_zero=True)


#: NJ 406 cylindrical roller bearing (d 30, D 90, B 23 mm): R1, S1, S2, K_Z, K_L from SKF's tables for the NJ 4
#: series as used for the FZG rig's bearings by Fernandes, Marques, Martins & Seabra (2015), "Gearbox power loss.
#: Part I: losses in rolling bearings", Tribology International; V_M 1.49e-4 read from SKF's diagram at their oil
#: level (not re-read here).
NJ406_CONSTANTS = dict(bore_mm=30.0, outside_mm=90.0, width_mm=23.0, rolling_constant=1.00e-6,
                       sliding_constants=(0.16, 0.0015), geometry_constant=5.1, roller_drag_constant=0.65,
                       replenishment_constant=3e-8, drag_variable=1.49e-4)
