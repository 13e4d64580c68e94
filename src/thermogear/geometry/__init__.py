"""Involute geometry of an external spur gear pair.

Roll distances are measured along the line of action from T1, the point where it touches the pinion's base
circle (ISO 21771). Point lettering A–E is ISO 6336 usage: A start of contact (wheel tip), B lowest point of
single contact on the pinion, C pitch point, D highest point of single contact, E end of contact (pinion tip).

Sources: ISO 21771 (gear geometry), Luo & Li (2020) Eqs. 8, 24, 25; the involute relations themselves are in
:mod:`thermogear.geometry.involute`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from thermogear.errors import CaseError

# Smallest tooth thickness at the tip, in modules, below which a tip is refused as too thin. Common design
# practice (e.g. Niemann/Winter, ISO 21771 commentary) asks for at least 0.2·m for through-hardened gears.
MINIMUM_TIP_THICKNESS_MODULES = 0.2
#: Largest normal backlash as a share of the base pitch [–], whatever makes it (a thinning of the teeth given as
#: ``gears.backlash_normal_um``, or a centre distance above the zero-backlash one). The tooth models use the
#: unthinned tooth: 0.1 p_b of thinning changes a tooth's bending stiffness (∝ thickness³) by about 30 %; usual
#: backlashes (AGMA 2002 / ISO/TR 10064-2 tables, 0.02 to 0.1 m) are a few hundredths of p_b.
MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH = 0.1


from thermogear.dynamics.problems.rigid_pair import RigidPair  # noqa: E402
from thermogear.geometry.involute import (disc_polar_inertia, gamma_from_roll,  # noqa: E402,F401
                                          half_tooth_angle, involute, inverse_involute,
                                          operating_pressure_angle_from_shifts, reference_tooth_thickness,
                                          roll_from_gamma, tooth_thickness_at_radius)


# --------------------------------------------------------------------------------------------- components
@dataclass(frozen=True)
class Gear:
    """One external spur gear cut by a standard basic rack (ISO 53 type, with tool tip radius).

    Lengths in metres, angles in radians. ``tip_radius`` is resolved by :class:`GearPair` (tip shortening)
    unless the user gives it.
    """

    teeth: int
    module: float  # [m]
    pressure_angle: float  # [rad]
    face_width: float  # [m]
    profile_shift: float = 0.0  # [–]
    addendum_coefficient: float = 1.0  # h_a* [–]
    dedendum_coefficient: float = 1.25  # h_f* = rack addendum [–]
    tool_tip_radius_coefficient: float = 0.38  # ρ_fP* [–]
    bore_radius: float = 0.0  # [m]
    tip_radius: float | None = None  # [m], None: from the pair (with tip shortening)

    @property
    def reference_radius(self) -> float:
        """r = m z / 2 [m]."""
        return self.module * self.teeth / 2.0

    @property
    def base_radius(self) -> float:
        """r_b = r cos α [m]."""
        return self.reference_radius * math.cos(self.pressure_angle)

    @property
    def root_radius(self) -> float:
        """r_f = r − (h_f* − x) m [m]."""
        return self.reference_radius - (self.dedendum_coefficient - self.profile_shift) * self.module

    @property
    def reference_thickness(self) -> float:
        """Circular tooth thickness on the reference circle [m]."""
        return reference_tooth_thickness(self.module, self.pressure_angle, self.profile_shift)

    @property
    def half_tooth_angle_at_base(self) -> float:
        """α2 = π/(2z) + inv α + 2x tan α / z: half tooth angle on the base circle [rad] (Tian (2004))."""
        return (math.pi / (2.0 * self.teeth) + involute(self.pressure_angle)
                + 2.0 * self.profile_shift * math.tan(self.pressure_angle) / self.teeth)

    @property
    def form_roll_distance(self) -> float:
        """Roll distance on this gear's base tangent where the generated involute starts [m].

        The straight flank of the generating rack ends ρ_fP*(1 − sin α)·m below its addendum line; the involute
        it generates starts at roll distance r sin α − (h_f* − ρ_fP*(1 − sin α) − x)·m / sin α. Negative means
        undercut.
        """
        limit_height = (self.dedendum_coefficient
                        - self.tool_tip_radius_coefficient * (1.0 - math.sin(self.pressure_angle))
                        - self.profile_shift) * self.module
        return self.reference_radius * math.sin(self.pressure_angle) - limit_height / math.sin(self.pressure_angle)

    @property
    def form_radius(self) -> float:
        """Radius where the usable involute begins (form circle) [m]."""
        return math.hypot(self.base_radius, max(self.form_roll_distance, 0.0))

    def thickness_at(self, radius):
        """Circular tooth thickness at radius ≥ r_b [m]."""
        return tooth_thickness_at_radius(radius, self.reference_radius, self.reference_thickness,
                                         self.pressure_angle, self.base_radius)

    def half_angle_at(self, radius):
        """Half angular tooth thickness φ_k at radius ≥ r_b [rad] (Luo & Li Eq. 8)."""
        return half_tooth_angle(radius, self.reference_radius, self.reference_thickness, self.pressure_angle,
                                self.base_radius)


@dataclass(frozen=True)
class GearPair:
    """An external spur gear pair: pinion (driving, 1) and wheel (driven, 2) at a centre distance.

    Build it with :meth:`GearPair.create`, which resolves the centre distance from the profile shifts when none
    is given and the tip radii with tip shortening, and checks the geometry.
    """

    pinion: Gear
    wheel: Gear
    centre_distance: float  # [m]
    names: tuple[str, str] = field(default=("pinion", "wheel"), compare=False)

    # ------------------------------------------------------------------------------------- construction
    @classmethod
    def create(cls, pinion: Gear, wheel: Gear, centre_distance: float | None = None,
               tip_shortening: bool = True, check: bool = True) -> "GearPair":
        """Resolve centre distance and tip radii, then check the geometry (raises CaseError)."""
        for key, gear in (("pinion", pinion), ("wheel", wheel)):
            _check_gear_inputs(key, gear)
        if not math.isclose(pinion.module, wheel.module) or not math.isclose(pinion.pressure_angle,
                                                                             wheel.pressure_angle):
            raise CaseError("wheel.module", wheel.module, f"equal to the pinion's ({pinion.module})",
                            "a pair must be cut by the same rack")
        reference_distance = pinion.module * (pinion.teeth + wheel.teeth) / 2.0
        alpha_w_shift = operating_pressure_angle_from_shifts(pinion.teeth, wheel.teeth, pinion.profile_shift,
                                                             wheel.profile_shift, pinion.pressure_angle)
        shift_distance = reference_distance * math.cos(pinion.pressure_angle) / math.cos(alpha_w_shift)
        if centre_distance is None:
            centre_distance = shift_distance
        elif centre_distance < shift_distance * (1.0 - 1e-6):
            raise CaseError("centre_distance_mm", round(centre_distance * 1e3, 6),
                            f">= {shift_distance * 1e3:.4f} mm",
                            "the profile shifts give a zero-backlash centre distance larger than this: the teeth "
                            "would have to penetrate each other")
        base_radii = reference_distance * math.cos(pinion.pressure_angle)
        if centre_distance > base_radii:
            opened = 2.0 * base_radii * (float(involute(math.acos(base_radii / centre_distance)))
                                         - float(involute(alpha_w_shift)))
            base_pitch = math.pi * pinion.module * math.cos(pinion.pressure_angle)
            if opened > MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH * base_pitch:
                needed = ((float(involute(math.acos(base_radii / centre_distance))) - float(involute(
                    pinion.pressure_angle))) * (pinion.teeth + wheel.teeth) / (2.0 * math.tan(pinion.pressure_angle)))
                raise CaseError("centre_distance_mm", round(centre_distance * 1e3, 6),
                                f"<= {_widest_centre_distance(reference_distance, pinion, alpha_w_shift) * 1e3:.4f}"
                                f" mm with these profile shifts (a normal backlash of at most a tenth of the base "
                                f"pitch, {MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH * base_pitch * 1e6:.0f} μm)",
                                f"{(centre_distance - shift_distance) * 1e3:.3f} mm above the zero-backlash centre "
                                f"distance {shift_distance * 1e3:.4f} mm the unthinned teeth leave a normal backlash "
                                f"of {opened * 1e6:.0f} μm: no designed pair runs so (backlash tables of ISO/TR "
                                f"10064-2 and AGMA 2002 stay within a few hundredths of the base pitch) and the "
                                f"contact ratio falls; a pair meant for this centre distance has profile shifts "
                                f"x1 + x2 = {needed:.4f} (ISO 21771: inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2))")
        shortening = (pinion.profile_shift + wheel.profile_shift
                      - (centre_distance - reference_distance) / pinion.module)
        shortening = max(shortening, 0.0) if tip_shortening else 0.0

        def resolved(gear: Gear) -> Gear:
            if gear.tip_radius is not None:
                return gear
            tip = gear.reference_radius + (gear.addendum_coefficient + gear.profile_shift - shortening) * gear.module
            return replace(gear, tip_radius=tip)

        pair = cls(resolved(pinion), resolved(wheel), centre_distance)
        if check:
            pair.check()
        return pair

    # ---------------------------------------------------------------------------------------- geometry
    @property
    def module(self) -> float:
        return self.pinion.module

    @property
    def face_width(self) -> float:
        """Common (contact) face width: the smaller of the two [m]."""
        return min(self.pinion.face_width, self.wheel.face_width)

    @property
    def gear_ratio(self) -> float:
        """u = z2 / z1 [–]."""
        return self.wheel.teeth / self.pinion.teeth

    @cached_property
    def operating_pressure_angle(self) -> float:
        """α_w from cos α_w = a0 cos α / a [rad]."""
        reference_distance = self.module * (self.pinion.teeth + self.wheel.teeth) / 2.0
        return math.acos(reference_distance * math.cos(self.pinion.pressure_angle) / self.centre_distance)

    @property
    def operating_pitch_radii(self) -> tuple[float, float]:
        """Operating pitch radii r_w = r_b / cos α_w [m]."""
        cos_w = math.cos(self.operating_pressure_angle)
        return self.pinion.base_radius / cos_w, self.wheel.base_radius / cos_w

    @property
    def base_pitch(self) -> float:
        """p_b = π m cos α [m]."""
        return math.pi * self.module * math.cos(self.pinion.pressure_angle)

    @property
    def line_of_action_length(self) -> float:
        """T1T2 = a sin α_w: distance between the base-circle tangency points [m]."""
        return self.centre_distance * math.sin(self.operating_pressure_angle)

    @cached_property
    def path_points(self) -> dict[str, float]:
        """Roll distances of A, B, C, D, E from T1 [m] (ISO 21771; ISO 6336-1 points of contact)."""
        start = self.line_of_action_length - math.sqrt(self.wheel.tip_radius**2 - self.wheel.base_radius**2)
        end = math.sqrt(self.pinion.tip_radius**2 - self.pinion.base_radius**2)
        pitch = self.pinion.base_radius * math.tan(self.operating_pressure_angle)
        return {"A": start, "B": end - self.base_pitch, "C": pitch, "D": start + self.base_pitch, "E": end}

    @property
    def path_length(self) -> float:
        """Length of the path of contact g_α = T1E − T1A [m]."""
        return self.path_points["E"] - self.path_points["A"]

    @property
    def contact_ratio(self) -> float:
        """Transverse contact ratio ε_α = g_α / p_b [–]."""
        return self.path_length / self.base_pitch

    def gamma(self, roll):
        """Γ of roll distance(s) (Eq. 24) [–]."""
        return gamma_from_roll(roll, self.path_points["C"])

    def roll(self, gamma):
        """Roll distance(s) of Γ [m]."""
        return roll_from_gamma(gamma, self.path_points["C"])

    def roll_grid(self, count: int) -> np.ndarray:
        """Evenly spaced roll distances from A to E inclusive [m]."""
        return np.linspace(self.path_points["A"], self.path_points["E"], count)

    def contact_radii(self, roll):
        """Radii of the contact point on pinion and wheel (r_K1, r_K2) [m]."""
        roll = np.asarray(roll, dtype=float)
        return (np.hypot(self.pinion.base_radius, roll),
                np.hypot(self.wheel.base_radius, self.line_of_action_length - roll))

    def radii_of_curvature(self, roll):
        """Flank radii of curvature (ρ1, ρ2) at the contact point [m]."""
        roll = np.asarray(roll, dtype=float)
        return roll, self.line_of_action_length - roll

    def relative_radius_of_curvature(self, roll):
        """R = ρ1 ρ2 / (ρ1 + ρ2) [m]."""
        rho_1, rho_2 = self.radii_of_curvature(roll)
        return rho_1 * rho_2 / (rho_1 + rho_2)

    def rolling_speeds(self, roll, pinion_speed_rpm: float):
        """Rolling (tangential surface) speeds v1 = ω1 ρ1, v2 = ω2 ρ2 [m/s]."""
        omega_1 = pinion_speed_rpm * math.pi / 30.0
        omega_2 = omega_1 / self.gear_ratio
        rho_1, rho_2 = self.radii_of_curvature(roll)
        return omega_1 * rho_1, omega_2 * rho_2

    def sliding_speed(self, roll, pinion_speed_rpm: float):
        """Sliding speed |v1 − v2| [m/s]."""
        v_1, v_2 = self.rolling_speeds(roll, pinion_speed_rpm)
        return np.abs(v_1 - v_2)

    def mesh_period(self, pinion_speed_rpm: float) -> float:
        """T_m = 60 / (z1 n1) [s]."""
        return 60.0 / (self.pinion.teeth * pinion_speed_rpm)

    def mesh_frequency(self, pinion_speed_rpm: float) -> float:
        """f_m = z1 n1 / 60 [Hz]."""
        return self.pinion.teeth * pinion_speed_rpm / 60.0

    def roll_at_time(self, time, pinion_speed_rpm: float):
        """Roll distance of the pair that enters at A at τ = 0 (Eq. 25): T1A + r_b1 ω1 τ [m]."""
        omega_1 = pinion_speed_rpm * math.pi / 30.0
        return self.path_points["A"] + self.pinion.base_radius * omega_1 * np.asarray(time, dtype=float)

    def time_at_roll(self, roll, pinion_speed_rpm: float):
        """Time since the pair entered at A [s] (inverse of :meth:`roll_at_time`)."""
        omega_1 = pinion_speed_rpm * math.pi / 30.0
        return (np.asarray(roll, dtype=float) - self.path_points["A"]) / (self.pinion.base_radius * omega_1)

    def pinion_load_angle(self, roll):
        """Load angle ω_k = α1 = tan α_K − α2 of the pinion at the contact point [rad] (Tian (2004); Sainsot et al. (2004))."""
        return np.asarray(roll, dtype=float) / self.pinion.base_radius - self.pinion.half_tooth_angle_at_base

    def wheel_load_angle(self, roll):
        """Load angle of the wheel tooth at the contact point [rad]."""
        wheel_roll = self.line_of_action_length - np.asarray(roll, dtype=float)
        return wheel_roll / self.wheel.base_radius - self.wheel.half_tooth_angle_at_base

    def rigid_pair(self, density: float, inertias: tuple[float, float] | None = None) -> RigidPair:
        """The pair as two rigid gears on rigid supports (:class:`~thermogear.dynamics.problems.rigid_pair.
        RigidPair`, the 1-DOF pair's structure): the given polar inertias [kg·m²] or those of solid discs of the
        operating pitch radius with the bores, over each gear's face width, and the base radii."""
        if inertias is None:
            pitch_1, pitch_2 = self.operating_pitch_radii
            inertias = (disc_polar_inertia(density, pitch_1, self.pinion.bore_radius, self.pinion.face_width),
                        disc_polar_inertia(density, pitch_2, self.wheel.bore_radius, self.wheel.face_width))
        return RigidPair(inertias[0], inertias[1], self.pinion.base_radius, self.wheel.base_radius)

    def equivalent_mass(self, density: float, inertias: tuple[float, float] | None = None) -> float:
        """Equivalent mass me of Eq. 5 [kg]: the mesh mass of :meth:`rigid_pair`."""
        return self.rigid_pair(density, inertias).mesh_mass

    # -------------------------------------------------------------------------------------------- checks
    def check(self) -> None:
        """Refuse geometries the model cannot handle (raises CaseError naming key, value, range, reason)."""
        for key, gear in (("pinion", self.pinion), ("wheel", self.wheel)):
            if gear.form_roll_distance < 0.0:
                limit = (gear.dedendum_coefficient
                         - gear.tool_tip_radius_coefficient * (1 - math.sin(gear.pressure_angle))
                         - gear.teeth * math.sin(gear.pressure_angle) ** 2 / 2.0)
                raise CaseError(f"{key}.profile_shift", gear.profile_shift, f">= {limit:.4f}",
                                f"the rack undercuts the root of this {gear.teeth}-tooth {key} (the involute "
                                "would start below the base circle)")
            if gear.bore_radius >= gear.root_radius:
                raise CaseError(f"{key}.bore_radius_mm", gear.bore_radius * 1e3,
                                f"< root radius {gear.root_radius * 1e3:.3f} mm",
                                "the bore would cut through the tooth roots")
            tip = gear.tip_radius
            if tip <= gear.base_radius:
                raise CaseError(f"{key}.tip_diameter_mm", 2e3 * tip, f"> base diameter {2e3 * gear.base_radius:.3f} mm",
                                "the tooth would have no involute flank")
            tip_thickness = float(gear.thickness_at(tip))
            if tip_thickness <= 0.0:
                raise CaseError(f"{key}.profile_shift", gear.profile_shift, "smaller, or a smaller tip diameter (pointed tip)",
                                f"the tooth comes to a point below its tip circle (tip thickness "
                                f"{tip_thickness * 1e3:.3f} mm)")
            if tip_thickness < MINIMUM_TIP_THICKNESS_MODULES * gear.module:
                raise CaseError(f"{key}.profile_shift", gear.profile_shift, "smaller, or a smaller tip diameter (thicker tip)",
                                f"the tip is {tip_thickness * 1e3:.3f} mm thick, less than "
                                f"{MINIMUM_TIP_THICKNESS_MODULES}·m = "
                                f"{MINIMUM_TIP_THICKNESS_MODULES * gear.module * 1e3:.3f} mm")
        points = self.path_points
        if points["A"] < self.pinion.form_roll_distance:
            raise CaseError("wheel.tip_diameter_mm", 2e3 * self.wheel.tip_radius,
                            "a smaller wheel tip or a larger pinion profile shift",
                            f"the wheel tip meets the pinion below its usable involute (start of contact at "
                            f"{points['A'] * 1e3:.3f} mm from T1, form point at "
                            f"{self.pinion.form_roll_distance * 1e3:.3f} mm): interference at the pinion root")
        if self.line_of_action_length - points["E"] < self.wheel.form_roll_distance:
            raise CaseError("pinion.tip_diameter_mm", 2e3 * self.pinion.tip_radius,
                            "a smaller pinion tip or a larger wheel profile shift",
                            "the pinion tip meets the wheel below its usable involute: interference at the "
                            "wheel root")
        if self.contact_ratio <= 1.0:
            raise CaseError("contact_ratio", round(self.contact_ratio, 4), "> 1",
                            "with a contact ratio of 1 or less the mesh loses contact between tooth pairs; "
                            "raise the addendum, lower the pressure angle or use more teeth")


def _widest_centre_distance(reference_distance: float, pinion: Gear, alpha_w_shift: float) -> float:
    """Centre distance [m] at which the unthinned teeth leave a normal backlash of
    :data:`MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH` base pitches: j_bn = 2(r_b1 + r_b2)(inv α_w − inv α_w0) solved for
    α_w (ISO 21771), a = (r_b1 + r_b2)/cos α_w."""
    base_radii = reference_distance * math.cos(pinion.pressure_angle)
    base_pitch = math.pi * pinion.module * math.cos(pinion.pressure_angle)
    target = float(involute(alpha_w_shift)) + MAXIMUM_BACKLASH_SHARE_OF_BASE_PITCH * base_pitch / (2.0 * base_radii)
    return base_radii / math.cos(float(inverse_involute(target)))


def _check_gear_inputs(key: str, gear: Gear) -> None:
    """Sizes and coefficients that are never valid, whatever the mate."""
    if gear.teeth < 5:
        raise CaseError(f"{key}.teeth", gear.teeth, ">= 5", "an involute gear needs at least a few teeth")
    for name, value in (("module_mm", gear.module), ("face_width_mm", gear.face_width)):
        if not value > 0.0:
            raise CaseError(f"{key}.{name}" if name == "face_width_mm" else name, value * 1e3, "> 0",
                            "a size must be positive")
    if not 0.0 < gear.pressure_angle < math.radians(45):
        raise CaseError("pressure_angle_deg", math.degrees(gear.pressure_angle), "(0, 45)",
                        "outside the range of involute spur gears")
    if gear.bore_radius < 0.0:
        raise CaseError(f"{key}.bore_radius_mm", gear.bore_radius * 1e3, ">= 0", "a radius cannot be negative")
    if not 0.0 < gear.addendum_coefficient <= 2.0:
        raise CaseError("addendum_coefficient", gear.addendum_coefficient, "(0, 2]", "not a spur gear addendum")
    if not gear.addendum_coefficient < gear.dedendum_coefficient <= 2.5:
        raise CaseError("dedendum_coefficient", gear.dedendum_coefficient,
                        f"({gear.addendum_coefficient}, 2.5]", "the root must clear the mating tip")
    if not 0.0 <= gear.tool_tip_radius_coefficient <= 0.6:
        raise CaseError("tool_tip_radius_coefficient", gear.tool_tip_radius_coefficient, "[0, 0.6]",
                        "beyond the radius that fits the rack tip")
