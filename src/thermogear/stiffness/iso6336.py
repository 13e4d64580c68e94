"""ISO 6336-1 Method B single stiffness c′ and mesh stiffness c_γα of spur gears — a cross-check of the PEM.

Formulas: ISO 6336-1 clause 9 ([S] python-gearbox ``iso.py``, GEARpie ``DIN3990.py``); ISO 6336-1:2006 §9.
Inside SI: stiffness per unit face width in N/m per m of face width (N/m²). 1 N/(mm·μm) = 1e9 N/m².
"""

from __future__ import annotations

import math
import warnings

from thermogear.errors import ExtrapolationWarning
from thermogear.geometry import GearPair
from thermogear.materials import Material
from thermogear.operating import OperatingPoint

#: 1 N/(mm·μm) in N/m² (SI per-unit-width stiffness).
N_PER_MM_UM = 1e9

#: Coefficients C1…C9 of the theoretical single-stiffness flexibility q′ [mm·μm/N] (ISO 6336-1, Table 9).
Q_PRIME_COEFFICIENTS = (0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182)

#: Reference modulus of ISO's c′ (steel/steel) [Pa].
REFERENCE_MODULUS = 206e9

#: Solid-disc (theoretical → real) correction C_M (ISO 6336-1 §9.3.3).
SOLID_DISC_FACTOR = 0.8


def iso6336_flexibility(teeth_1: float, teeth_2: float, shift_1: float, shift_2: float) -> float:
    """Minimum flexibility q′ of a tooth pair [m²/N] (ISO 6336-1 Eq. for q′, spur: z_n = z).

    q′ = C1 + C2/z1 + C3/z2 + C4 x1 + C5 x1/z1 + C6 x2 + C7 x2/z2 + C8 x1² + C9 x2²  [mm·μm/N].
    """
    c1, c2, c3, c4, c5, c6, c7, c8, c9 = Q_PRIME_COEFFICIENTS
    q = (c1 + c2 / teeth_1 + c3 / teeth_2 + c4 * shift_1 + c5 * shift_1 / teeth_1 + c6 * shift_2
         + c7 * shift_2 / teeth_2 + c8 * shift_1**2 + c9 * shift_2**2)
    return q / N_PER_MM_UM


def basic_rack_factor(rack_dedendum_coefficient: float, pressure_angle: float) -> float:
    """C_B = [1 + 0.5(1.2 − h_fP/m)]·[1 − 0.02(20° − α_P)] (ISO 6336-1 §9.3.4; α in degrees) [–]."""
    return ((1.0 + 0.5 * (1.2 - rack_dedendum_coefficient))
            * (1.0 - 0.02 * (20.0 - math.degrees(pressure_angle))))


def iso6336_single_stiffness(teeth_1: int, teeth_2: int, shift_1: float, shift_2: float,
                             youngs_modulus_1: float, youngs_modulus_2: float | None = None,
                             rack_dedendum_coefficient: float = 1.25, pressure_angle: float = math.radians(20.0),
                             line_load: float | None = None, rim_factor: float = 1.0,
                             helix_angle: float = 0.0, warn: bool = True,
                             virtual_teeth: tuple[float, float] | None = None) -> float:
    """Single stiffness c′ per unit face width [N/m²] (ISO 6336-1:2006 Method B, §9.3; ISO 6336-1 clause 9).

    c′ = (1/q′)·C_M·C_R·C_B·cos β·(E_r/206 GPa), E_r = 2E1E2/(E1 + E2); C_M = 0.8 (solid discs), C_R the rim
    factor (1 for solid blanks), C_B the basic rack factor. With ``line_load`` F_t·K_A/b [N/m] below 100 N/mm,
    c′ is reduced by (F_t K_A/b / 100 N/mm)^0.25. Warns where the q′ fit is extrapolated (x1 < x2 or
    x1 + x2 outside [−0.5, 2]).
    """
    if warn and (shift_1 < shift_2 - 1e-12 or not -0.5 <= shift_1 + shift_2 <= 2.0):
        warnings.warn(f"ISO 6336-1 q′ fit extrapolated: x1 = {shift_1}, x2 = {shift_2} (fitted for x1 ≥ x2 and "
                      "−0.5 ≤ x1 + x2 ≤ 2)", ExtrapolationWarning, stacklevel=2)
    e_2 = youngs_modulus_1 if youngs_modulus_2 is None else youngs_modulus_2
    reduced_modulus = 2.0 * youngs_modulus_1 * e_2 / (youngs_modulus_1 + e_2)
    if virtual_teeth is None:  # z_n ≈ z/cos³β; a helical pair gives the exact z/(cos²β_b cos β) (ISO 21771)
        virtual_teeth = (teeth_1 / (math.cos(helix_angle) ** 3), teeth_2 / (math.cos(helix_angle) ** 3))
    teeth_n1, teeth_n2 = virtual_teeth
    theoretical = 1.0 / iso6336_flexibility(teeth_n1, teeth_n2, shift_1, shift_2)
    stiffness = (theoretical * SOLID_DISC_FACTOR * rim_factor
                 * basic_rack_factor(rack_dedendum_coefficient, pressure_angle)
                 * math.cos(helix_angle) * reduced_modulus / REFERENCE_MODULUS)
    if line_load is not None and line_load < 100e3:
        stiffness *= (line_load / 100e3) ** 0.25
    return stiffness


def iso6336_mesh_stiffness(single_stiffness: float, contact_ratio: float) -> float:
    """Mean mesh stiffness c_γα = c′(0.75 ε_α + 0.25) per unit face width [N/m²] (ISO 6336-1 §9.3.1).

    For ε_α < 1.2 the value is multiplied by 0.9 as in python-gearbox (ISO 6336-1 clause 9) [R: the reduction
    "up to about 10 %" for low contact ratios is recalled from the standard, not confirmed].
    """
    value = single_stiffness * (0.75 * contact_ratio + 0.25)
    return 0.9 * value if contact_ratio < 1.2 else value


def iso6336_stiffness(gear_pair: GearPair, material: Material,
                      operating_point: OperatingPoint | None = None, application_factor: float = 1.0) -> dict:
    """c′ and c_γα of a gear pair [N/m per m of face width] (ISO 6336-1 Method B), solid blanks (C_R = 1).

    The line load F_t K_A / b uses F_t = T1 / r1 on the pinion's reference circle; without an operating point
    no load correction is made. Returns dict(c_prime=…, c_gamma_alpha=…, line_load=…).
    """
    pinion, wheel = gear_pair.pinion, gear_pair.wheel
    line_load = None
    if operating_point is not None:
        tangential_force = operating_point.torque / pinion.reference_radius
        line_load = tangential_force * application_factor / gear_pair.face_width
    c_prime = iso6336_single_stiffness(pinion.teeth, wheel.teeth, pinion.profile_shift, wheel.profile_shift,
                                       material.youngs_modulus, material.youngs_modulus,
                                       pinion.dedendum_coefficient, pinion.pressure_angle, line_load)
    return {"c_prime": c_prime,
            "c_gamma_alpha": iso6336_mesh_stiffness(c_prime, gear_pair.contact_ratio),
            "line_load": line_load}
