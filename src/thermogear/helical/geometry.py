"""Helical gear pair geometry (ISO 21771:2007, basic rack ISO 53): normal and transverse module and pressure angle,
base helix angle, pitches, contact ratios ε_α, ε_β, ε_γ and the virtual spur gears of the normal section.

A helical gear's transverse section is an involute spur gear of the transverse module m_t = m_n/cos β and pressure
angle tan α_t = tan α_n/cos β (ISO 21771 §4.3). The normal profile shift x_n·m_n, the rack addendum h_aP*·m_n and
dedendum h_fP*·m_n are lengths of the normal section that the transverse section keeps: in units of m_t they are
x_n cos β, h_aP* cos β and h_fP* cos β. With them the zero-backlash operating pressure angle of the transverse
section, inv α_wt = inv α_t + 2 tan α_t (x_t1 + x_t2)/(z1 + z2), is ISO 21771's inv α_wt = inv α_t + 2 tan α_n
(x_n1 + x_n2)/(z1 + z2) (tan α_t·cos β = tan α_n). The rack's tip radius ρ_fP*·m_n is kept as a length too
(ρ_fP* cos β in units of m_t): an approximation, since the normal section's circle is an ellipse in the transverse
one; it only moves where the generated involute starts (the form circle), not the working flank.

Base helix: sin β_b = sin β cos α_n; the contact lines on the plane of action are inclined at β_b to the axis and
one face width b spans g_β = b tan β_b of the path (overlap ratio ε_β = g_β/p_bt = b sin β/(π m_n)).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from thermogear.errors import CaseError
from thermogear.geometry import Gear, GearPair
from thermogear.geometry.involute import operating_pressure_angle_from_shifts

__all__ = ["HelicalPair", "RIGHT_HAND", "LEFT_HAND", "transverse_pressure_angle", "base_helix_angle"]

RIGHT_HAND = 1
LEFT_HAND = -1
#: Largest helix angle [rad] the slice model is used for: above about 45° the transverse slices no longer
#: describe the tooth (double-helical and high-helix designs stay below 40°; ISO 6336-1 treats β ≤ 45°).
MAXIMUM_HELIX_ANGLE = math.radians(45.0)


def zero_backlash_centre_distance(pinion: Gear, wheel: Gear) -> float:
    """a = a_0 cos α / cos α_w, inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2) [m] (ISO 21771 Eq. 41, 42)."""
    angle = operating_pressure_angle_from_shifts(pinion.teeth, wheel.teeth, pinion.profile_shift,
                                                 wheel.profile_shift, pinion.pressure_angle)
    return pinion.module * (pinion.teeth + wheel.teeth) / 2.0 * math.cos(pinion.pressure_angle) / math.cos(angle)


def transverse_pressure_angle(normal_pressure_angle: float, helix_angle: float) -> float:
    """α_t from tan α_t = tan α_n / cos β [rad] (ISO 21771 Eq. 6); exactly α_n for β = 0."""
    if helix_angle == 0.0:
        return normal_pressure_angle
    return math.atan(math.tan(normal_pressure_angle) / math.cos(helix_angle))


def base_helix_angle(helix_angle: float, normal_pressure_angle: float) -> float:
    """β_b from sin β_b = sin β cos α_n [rad] (ISO 21771 Eq. 11, ⇔ tan β_b = tan β cos α_t)."""
    return math.asin(math.sin(helix_angle) * math.cos(normal_pressure_angle))


@dataclass(frozen=True)
class HelicalPair:
    """An external helical pair: its transverse section (a spur :class:`~thermogear.geometry.GearPair` in
    transverse quantities, face width b) and its helix. Build it with :meth:`create`.

    ``pinion_hand``: +1 right-hand pinion (the wheel of an external pair has the other hand), −1 left-hand."""

    transverse: GearPair
    helix_angle: float  # β on the reference cylinder [rad]
    normal_module: float  # m_n [m]
    normal_pressure_angle: float  # α_n [rad]
    normal_profile_shifts: tuple[float, float]  # x_n1, x_n2 [–]
    pinion_hand: int = RIGHT_HAND

    @classmethod
    def create(cls, pinion_teeth: int, wheel_teeth: int, normal_module: float, normal_pressure_angle: float,
               helix_angle: float, face_width: float, profile_shifts: tuple[float, float] = (0.0, 0.0),
               addendum_coefficient: float = 1.0, dedendum_coefficient: float = 1.25,
               tool_tip_radius_coefficient: float = 0.38, bore_radii: tuple[float, float] = (0.0, 0.0),
               centre_distance: float | None = None, tip_shortening: bool = True,
               pinion_hand: int = RIGHT_HAND) -> "HelicalPair":
        """The pair from its normal-section data (SI: m, rad); ``centre_distance`` None gives zero backlash."""
        if not (math.isfinite(helix_angle) and 0.0 <= helix_angle <= MAXIMUM_HELIX_ANGLE):
            raise CaseError("gears.helix_angle_deg", math.degrees(helix_angle), "[0, 45]°",
                            "helical gears of the slice model (β = 0 is the spur pair)")
        if pinion_hand not in (RIGHT_HAND, LEFT_HAND):
            raise CaseError("gears.pinion.hand", pinion_hand, "+1 (right) or -1 (left)", "the hand of the helix")
        cos_beta = math.cos(helix_angle)
        transverse_module = normal_module / cos_beta
        alpha_t = transverse_pressure_angle(normal_pressure_angle, helix_angle)

        def gear(teeth: int, shift: float, bore: float) -> Gear:
            return Gear(teeth=teeth, module=transverse_module, pressure_angle=alpha_t, face_width=face_width,
                        profile_shift=shift * cos_beta, addendum_coefficient=addendum_coefficient * cos_beta,
                        dedendum_coefficient=dedendum_coefficient * cos_beta,
                        tool_tip_radius_coefficient=tool_tip_radius_coefficient * cos_beta, bore_radius=bore)

        pair = GearPair.create(gear(pinion_teeth, profile_shifts[0], bore_radii[0]),
                               gear(wheel_teeth, profile_shifts[1], bore_radii[1]), centre_distance,
                               tip_shortening=tip_shortening)
        return cls(pair, float(helix_angle), float(normal_module), float(normal_pressure_angle),
                   (float(profile_shifts[0]), float(profile_shifts[1])), pinion_hand)

    # ------------------------------------------------------------------------------------------------ helix
    @property
    def face_width(self) -> float:
        """b [m]."""
        return self.transverse.face_width

    @property
    def transverse_module(self) -> float:
        """m_t = m_n / cos β [m]."""
        return self.transverse.module

    @property
    def transverse_pressure_angle(self) -> float:
        """α_t [rad]."""
        return self.transverse.pinion.pressure_angle

    @property
    def base_helix_angle(self) -> float:
        """β_b [rad] (sin β_b = sin β cos α_n)."""
        return base_helix_angle(self.helix_angle, self.normal_pressure_angle)

    @property
    def operating_helix_angle(self) -> float:
        """β_w on the operating pitch cylinder: tan β_w = tan β·r_w1/r_1 [rad] (the helix angle on any diameter
        d_y: tan β_y = tan β·d_y/d, ISO 21771 Eq. 12)."""
        pinion = self.transverse.pinion
        return math.atan(math.tan(self.helix_angle) * self.transverse.operating_pitch_radii[0]
                         / pinion.reference_radius)

    @property
    def transverse_base_pitch(self) -> float:
        """p_bt = π m_t cos α_t [m]."""
        return self.transverse.base_pitch

    @property
    def normal_base_pitch(self) -> float:
        """p_bn = π m_n cos α_n = p_bt cos β_b [m]."""
        return math.pi * self.normal_module * math.cos(self.normal_pressure_angle)

    @property
    def axial_pitch(self) -> float:
        """p_x = π m_n / sin β [m] (infinite for a spur pair)."""
        return math.inf if self.helix_angle == 0.0 else math.pi * self.normal_module / math.sin(self.helix_angle)

    @property
    def face_advance(self) -> float:
        """g_β = b tan β_b [m]: how far along the transverse path one contact line reaches across the face."""
        return self.face_width * math.tan(self.base_helix_angle)

    @property
    def transverse_contact_ratio(self) -> float:
        """ε_α = g_α / p_bt [–] of the transverse section."""
        return self.transverse.contact_ratio

    @property
    def overlap_ratio(self) -> float:
        """ε_β = b sin β / (π m_n) = g_β / p_bt [–] (ISO 21771 Eq. 64)."""
        return self.face_width * math.sin(self.helix_angle) / (math.pi * self.normal_module)

    @property
    def total_contact_ratio(self) -> float:
        """ε_γ = ε_α + ε_β [–]."""
        return self.transverse_contact_ratio + self.overlap_ratio

    @property
    def virtual_teeth(self) -> tuple[float, float]:
        """z_n = z / (cos²β_b cos β) [–]: the teeth of the normal section's virtual spur gears (ISO 21771 Eq. 75,
        ISO 6336-1 Eq. for z_n)."""
        factor = math.cos(self.base_helix_angle) ** 2 * math.cos(self.helix_angle)
        return self.transverse.pinion.teeth / factor, self.transverse.wheel.teeth / factor

    def virtual_spur_pair(self) -> GearPair:
        """The normal section as a spur pair (ISO 6336-1's virtual spur gears): z_n, m_n, α_n, x_n and the case's
        rack, at zero backlash, b/cos β_b wide (a contact line's length across the face), each bore scaled with its
        reference radius (the same rim ratio), its centre distance opened by as much as the pair's own beyond zero
        backlash (a radial length, the same in both sections). The slice model maps a contact by its fraction of the path A…E, so
        this pair gives the shape and level of the per-length stiffness along the path, not positions."""
        if self.helix_angle == 0.0:
            return self.transverse
        pinion, wheel = self.transverse.pinion, self.transverse.wheel
        z_n1, z_n2 = self.virtual_teeth
        cos_beta = math.cos(self.helix_angle)

        def gear(source: Gear, teeth: float, shift: float) -> Gear:
            scale = teeth * self.normal_module / (2.0 * source.reference_radius)
            return replace(source, teeth=teeth, module=self.normal_module, pressure_angle=self.normal_pressure_angle,
                           face_width=self.face_width / math.cos(self.base_helix_angle), profile_shift=shift,
                           addendum_coefficient=source.addendum_coefficient / cos_beta,
                           dedendum_coefficient=source.dedendum_coefficient / cos_beta,
                           tool_tip_radius_coefficient=source.tool_tip_radius_coefficient / cos_beta,
                           bore_radius=source.bore_radius * scale, tip_radius=None)

        virtual = (gear(pinion, z_n1, self.normal_profile_shifts[0]), gear(wheel, z_n2, self.normal_profile_shifts[1]))
        # a pair closed below zero backlash (a hot pair whose backlash is its teeth's thinning allowance, which the
        # virtual gears do not carry) meshes at the virtual pair's zero backlash
        opened = max(self.transverse.centre_distance - zero_backlash_centre_distance(pinion, wheel), 0.0)
        return GearPair.create(*virtual, zero_backlash_centre_distance(*virtual) + opened)

    def axial_force_ratio(self) -> float:
        """F_a / F_bt = tan β_b [–]: the axial component of the tooth normal force per unit of its component along
        the transverse line of action (n = cos β_b u ∓ sin β_b ẑ)."""
        return math.tan(self.base_helix_angle)
