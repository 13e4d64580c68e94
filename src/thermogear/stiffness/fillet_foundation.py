"""Fillet-foundation (gear body) compliance of a spur gear tooth after Sainsot, Velex & Duverger (2004).

P. Sainsot, P. Velex, O. Duverger, "Contribution of gear body to tooth deflections — a new bidimensional
analytical formula", J. Mech. Des. 126 (2004) 748–752. Coefficients and formula: Sainsot et al. (2004).

The root half angle θ_f of a rack-cut gear is derived here from the rack geometry (see
:func:`root_half_angle`); the x = 0 formula is often quoted with the gear's addendum coefficient in it,
which drops the clearance term (see docs/stiffness.md).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning

#: Sainsot et al. (2004) polynomial coefficients (A, B, C, D, E, F) of X*(h_f, θ_f) for X* ∈ {L*, M*, P*, Q*}
#: (Sainsot et al. (2004)).
SAINSOT_COEFFICIENTS: dict[str, tuple[float, float, float, float, float, float]] = {
    "L": (-5.574e-5, -1.9986e-3, -2.3015e-4, 4.7702e-3, 0.0271, 6.8045),
    "M": (60.111e-5, 28.100e-3, -83.431e-4, -9.9256e-3, 0.1624, 0.9086),
    "P": (-50.952e-5, 185.50e-3, 0.0538e-4, 53.300e-3, 0.2895, 0.9236),
    "Q": (-6.2042e-5, 9.0889e-3, -4.0964e-4, 7.8297e-3, -0.1472, 0.6904),
}

#: Ranges of the fitted outputs L*, M*, P*, Q* over Sainsot's data [S: ROSS gear_element.py, Sainsot et al. (2004)].
SAINSOT_OUTPUT_RANGES: dict[str, tuple[float, float]] = {
    "L": (6.82, 6.94), "M": (1.08, 3.29), "P": (2.56, 13.47), "Q": (0.141, 0.62),
}

#: Input ranges of the fit, h_f = r_f/r_int ∈ [1.4, 7] and θ_f ∈ [0.01, 0.12] rad. [R]: read from a commented-out
#: check in ROSS (gear_element.py, ``_gear_body_polynominal``); the original paper was not opened.
SAINSOT_INPUT_RANGES: dict[str, tuple[float, float]] = {"h_f": (1.4, 7.0), "theta_f": (0.01, 0.12)}


def sainsot_coefficient(name: str, root_to_bore_ratio, root_half_angle):
    """X*(h_f, θ_f) = A/θ_f² + B h_f² + C h_f/θ_f + D/θ_f + E h_f + F  [–]  (Sainsot et al. 2004).

    ``name`` is one of "L", "M", "P", "Q"; h_f = r_f / r_int [–], θ_f [rad].
    """
    a, b, c, d, e, f = SAINSOT_COEFFICIENTS[name]
    h_f = np.asarray(root_to_bore_ratio, dtype=float)
    theta_f = np.asarray(root_half_angle, dtype=float)
    return a / theta_f**2 + b * h_f**2 + c * h_f / theta_f + d / theta_f + e * h_f + f


def root_half_angle(teeth: int, pressure_angle: float, tool_addendum_coefficient: float,
                    tool_tip_radius_coefficient: float) -> float:
    """Half angle θ_f subtended at the gear centre by the tooth's footprint on the root circle [rad].

    Derived for this package from the generating rack (the fillet-foundation formula needs it; Sainsot et al. 2004 define
    S_f = 2 r_f θ_f as the tooth root length): the fillet meets the root circle where the rack-tip corner
    radius ρ = ρ* m touches the rack tip line. That point lies
    w = m[π/4 − h_fP* tan α − ρ*(1 − sin α)/cos α] from the middle of the rack tooth, and rolling the rack on the
    reference circle (radius mz/2) turns a lateral offset w into the gear angle 2w/(mz). The tooth footprint is
    the angular pitch less the space bottom: θ_f = π/z − 2w/(mz), i.e.

        θ_f = [π/2 + 2 h_fP* tan α + 2ρ*(1 − sin α)/cos α] / z.

    The profile shift x moves the rack radially only, so θ_f does not depend on x (x enters through r_f).
    This equals the textbook form [π/2 + 2 tan α (h* − ρ*) + 2ρ*/cos α]/z with h* the rack (tool) addendum h_fP*
    (1.25 for ISO 53), not the gear addendum. A tool whose corner radius leaves no flat tip (w < 0) gives the
    full-round limit θ_f = π/z.
    """
    flat_half_width = (math.pi / 4.0 - tool_addendum_coefficient * math.tan(pressure_angle)
                       - tool_tip_radius_coefficient * (1.0 - math.sin(pressure_angle)) / math.cos(pressure_angle))
    return math.pi / teeth - 2.0 * max(flat_half_width, 0.0) / teeth


def fillet_foundation_compliance(load_angle, base_radius: float, root_radius: float, root_to_bore_ratio: float,
                                 root_half_angle_rad: float, youngs_modulus: float, face_width: float):
    """Fillet-foundation compliance 1/k_f [m/N] (Sainsot et al. 2004).

    1/k_f = cos²α1/(E L) · {L*(u_f/S_f)² + M*(u_f/S_f) + P*(1 + Q* tan²α1)}, with
    u_f = r_b / cos α1 − r_f (where the line of action crosses the tooth centreline, measured from the root
    circle) and S_f = 2 r_f θ_f. ``load_angle`` α1 [rad] may be an array.
    """
    alpha_1 = np.asarray(load_angle, dtype=float)
    cos_1 = np.cos(alpha_1)
    u_over_s = (base_radius / cos_1 - root_radius) / (2.0 * root_radius * root_half_angle_rad)
    l_star = sainsot_coefficient("L", root_to_bore_ratio, root_half_angle_rad)
    m_star = sainsot_coefficient("M", root_to_bore_ratio, root_half_angle_rad)
    p_star = sainsot_coefficient("P", root_to_bore_ratio, root_half_angle_rad)
    q_star = sainsot_coefficient("Q", root_to_bore_ratio, root_half_angle_rad)
    return cos_1**2 / (youngs_modulus * face_width) * (
        l_star * u_over_s**2 + m_star * u_over_s + p_star * (1.0 + q_star * np.tan(alpha_1) ** 2))


def root_to_bore_ratio(root_radius: float, bore_radius: float, key: str = "gear") -> float:
    """h_f = r_f / r_int [–]; refuses a solid gear (r_int = 0), for which the fit has no meaning."""
    if not bore_radius > 0.0:
        raise CaseError(f"gears.{key}.bore_radius_mm", bore_radius * 1e3, "> 0",
                        "the Sainsot fillet-foundation model needs the radius of the gear body's inner boundary "
                        "(h_f = r_f / r_int); give the bore or shaft-seat radius")
    return root_radius / bore_radius


def check_sainsot_range(root_to_bore: float, root_half_angle_rad: float, key: str = "gear",
                        warn: bool = True) -> list[str]:
    """Messages for each input or output of the Sainsot fit outside its range; with ``warn`` each is also
    issued as an ExtrapolationWarning."""
    messages = []
    low, high = SAINSOT_INPUT_RANGES["h_f"]
    if not low <= root_to_bore <= high:
        messages.append(f"{key}: h_f = r_f/r_int = {root_to_bore:.3f} outside the fitted range [{low}, {high}]")
    low, high = SAINSOT_INPUT_RANGES["theta_f"]
    if not low <= root_half_angle_rad <= high:
        messages.append(f"{key}: θ_f = {root_half_angle_rad:.4f} rad outside the fitted range [{low}, {high}]")
    for name, (low, high) in SAINSOT_OUTPUT_RANGES.items():
        value = float(sainsot_coefficient(name, root_to_bore, root_half_angle_rad))
        if not low <= value <= high:
            messages.append(f"{key}: {name}* = {value:.4f} outside the range of Sainsot's data [{low}, {high}]")
    for message in messages if warn else ():
        warnings.warn(f"Sainsot fillet-foundation fit extrapolated — {message}", ExtrapolationWarning,
                      stacklevel=3)
    return messages


def gear_sainsot_messages(gear, key: str = "gear") -> list[str]:
    """Extrapolation messages of the Sainsot fit for one gear (no warning issued)."""
    h_f = root_to_bore_ratio(gear.root_radius, gear.bore_radius, key)
    theta_f = root_half_angle(gear.teeth, gear.pressure_angle, gear.dedendum_coefficient,
                              gear.tool_tip_radius_coefficient)
    return check_sainsot_range(h_f, theta_f, key, warn=False)
