"""The cold gear pair of a ``[gears]`` section (the first stage, or a further stage of a train): the gears cut by
the section's rack, the centre distance, the sum of the profile shifts checked, and the geometry's refusals named by
the case file's keys (the geometry names its keys within ``[gears]``: ``pinion.bore_radius_mm`` is
``gears.pinion.bore_radius_mm`` in a case file)."""

from __future__ import annotations

import math

from thermogear.errors import CaseError
from thermogear.geometry import Gear, GearPair, involute
from thermogear.helical.geometry import LEFT_HAND, RIGHT_HAND, HelicalPair, transverse_pressure_angle
from thermogear.schema import GearSection, GearsSection

__all__ = ["check_profile_shift_sum", "gear_pair_of", "helical_pair_of", "HANDS"]

#: The ``[gears] hand`` names and the pinion's hand of :class:`~thermogear.helical.geometry.HelicalPair`.
HANDS = {"right": RIGHT_HAND, "left": LEFT_HAND}


def check_profile_shift_sum(gears) -> None:
    """Refuse profile shifts whose sum leaves no zero-backlash operating pressure angle.

    ISO 21771: inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2) (of a helical pair inv α_wt = inv α_t + 2 tan α_n
    (x_n1 + x_n2)/(z1 + z2), Eq. 42). The involute inv α = tan α − α is never negative,
    so x1 + x2 must exceed −inv α (z1 + z2)/(2 tan α); below that (e.g. z 12/27, α 15.9°, x −0.46/−0.11) the
    geometry has no solution (this used to surface as a ValueError of the inverse involute)."""
    angle = math.radians(gears.pressure_angle_deg)
    transverse = transverse_pressure_angle(angle, math.radians(gears.helix_angle_deg))  # α for a spur pair
    teeth = gears.pinion.teeth + gears.wheel.teeth
    shift_sum = gears.pinion.profile_shift + gears.wheel.profile_shift
    if float(involute(transverse)) + 2.0 * math.tan(angle) * shift_sum / teeth > 0.0:
        return
    minimum = -float(involute(transverse)) * teeth / (2.0 * math.tan(angle))
    raise CaseError("gears.pinion.profile_shift + gears.wheel.profile_shift", round(shift_sum, 6),
                    f"> {minimum:.4f} for z {gears.pinion.teeth}/{gears.wheel.teeth} at α = "
                    f"{gears.pressure_angle_deg:g}°",
                    "no operating pressure angle exists: inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2) (ISO 21771) "
                    "would be negative; raise the profile shifts")


def gear_pair_of(gears: GearsSection) -> GearPair:
    """The cold gear pair of a [gears] section (or a stage's gears): of a helical pair its transverse section
    (:func:`helical_pair_of`), of a spur pair (β = 0) the pair itself."""
    return helical_pair_of(gears).transverse


def helical_pair_of(gears: GearsSection) -> HelicalPair:
    """The cold pair of a [gears] section as a :class:`~thermogear.helical.geometry.HelicalPair`: the transverse
    section cut by the rack, module, pressure angle and profile shifts of the normal section (ISO 21771: m_t =
    m_n/cos β, tan α_t = tan α_n/cos β, and the normal lengths x_n m_n, h_aP* m_n, h_fP* m_n, ρ_fP* m_n kept, as
    :meth:`HelicalPair.create` builds them), with the section's per-gear widths, bores and tip diameters. β = 0
    gives the spur pair of the section bit for bit (every factor is then exactly 1)."""
    helix = math.radians(gears.helix_angle_deg)
    normal_angle = math.radians(gears.pressure_angle_deg)
    angle = transverse_pressure_angle(normal_angle, helix)
    cos_beta = math.cos(helix)
    module = gears.module_mm * 1e-3 / cos_beta

    def gear(section) -> Gear:
        width = section.face_width_mm if section.face_width_mm is not None else gears.face_width_mm
        return Gear(teeth=section.teeth, module=module, pressure_angle=angle,
                    face_width=width * 1e-3, profile_shift=section.profile_shift * cos_beta,
                    addendum_coefficient=gears.addendum_coefficient * cos_beta,
                    dedendum_coefficient=gears.dedendum_coefficient * cos_beta,
                    tool_tip_radius_coefficient=gears.tool_tip_radius_coefficient * cos_beta,
                    bore_radius=0.0 if section.bore_radius_mm is None else section.bore_radius_mm * 1e-3,
                    tip_radius=None if section.tip_diameter_mm is None else section.tip_diameter_mm * 0.5e-3)

    centre = None if gears.centre_distance_mm is None else gears.centre_distance_mm * 1e-3
    check_profile_shift_sum(gears)
    try:
        pair = GearPair.create(gear(gears.pinion), gear(gears.wheel), centre, tip_shortening=gears.tip_shortening)
    except CaseError as error:  # the geometry names its keys within [gears]: the case file's key is gears.<key>
        raise type(error)(_gears_key(error.key), error.value, error.allowed, error.reason) from None
    return HelicalPair(pair, helix, gears.module_mm * 1e-3, normal_angle,
                       (gears.pinion.profile_shift, gears.wheel.profile_shift), HANDS[gears.hand])


def _gears_key(key: str) -> str:
    """The case-file key of a key the geometry names within ``[gears]`` (``pinion.profile_shift`` →
    ``gears.pinion.profile_shift``); a derived quantity (``contact_ratio``) is named as such, within [gears]."""
    section, _, rest = key.partition(".")
    if section in GearsSection.model_fields or (section in ("pinion", "wheel") and rest in GearSection.model_fields):
        return f"gears.{key}"
    return f"gears ({key}, derived)"
