"""Fillet-foundation (gear body) compliance of a spur gear tooth after Sainsot, Velex & Duverger (2004).

P. Sainsot, P. Velex, O. Duverger, "Contribution of gear body to tooth deflections — a new bidimensional
analytical formula", J. Mech. Des. 126 (2004) 748–752. Coefficients and formula: Sainsot et al. (2004).

The root half angle θ_f of a rack-cut gear is derived here from the rack geometry (see
:func:`root_half_angle`); the x = 0 formula is often quoted with the gear's addendum coefficient in it,
which drops the clearance term (see docs/stiffness.md).

Validity range and the solid-gear limit (docs/stiffness.md, "Small bores and solid gears"). Sainsot et al. fitted
L*, M*, P*, Q* to finite-element results of gear bodies clamped at the bore r_int, for h_f = r_f/r_int in
[1.4, 7] and θ_f in [0.01, 0.12] (SAINSOT_INPUT_RANGES). Evaluated as it stands, the fit's compliance grows as
h_f² without bound, so a small bore drove the mesh stiffness to zero (luo2019: bore 10 mm → 15.2, 1 mm → 0.23,
0.01 mm → 3e-9 N/(mm·μm)). That growth is the torsional wind-up of the gear body between its rigidly clamped
bore and the rim: for an annulus under a torque the rim turns by T/(4πGb)·(1/r_int² − 1/r_f²), i.e. the rim
displacement grows as h_f² − 1, the form of the fit's B h_f² + E h_f terms. It measures the clamp, not the tooth
foundation, and diverges for a clamp shrinking to a point, which no gear has: a solid or small-bore gear takes
its torque from a shaft over a seat whose radius the case does not describe. thermogear therefore evaluates the
fit with the inner boundary at no less than a nominal seat radius of 0.3 r_f (NOMINAL_SEAT_RATIO, the solid-gear
inner boundary the finite-element tooth model already uses, docs/fem.md), i.e. at h_f = min(r_f/r_int, 1/0.3):
the two stiffness models of the project then see the same gear body, the stiffness is continuous in the bore and
constant below 0.3 r_f, so it converges as the bore shrinks to nothing and a solid gear (no bore) has a value.
The built-in cases (h_f 2.08 to 3.28) are unchanged. A bore between r_f/7 and 0.3 r_f is inside the fit's data
but treated as the seat: reported as a ModelAssumptionWarning; a bore outside the fit's data (h_f > 7, a solid
gear, or h_f < 1.4, a thin rim, evaluated at 1.4) as an ExtrapolationWarning. θ_f is not limited: its terms stay
finite (A/θ_f², D/θ_f fall as θ_f grows) and a θ_f outside its range is only reported.
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning, ModelAssumptionWarning

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

#: Input ranges of the fit, h_f = r_f/r_int ∈ [1.4, 7] and θ_f ∈ [0.01, 0.12] rad, as checked (commented out) in
#: ROSS's gear_element.py ``_gear_body_polynominal`` (``not 1.4 <= h <= 7``, ``not 0.01 <= theta_f <= 0.12``;
#: re-read for issue 15). The paper itself could not be opened to confirm them (docs/stiffness.md). For a
#: standard 20° tooth (h_a* 1, h_f* 1.25, ρ* 0.38, no shift) θ_f ≤ 0.12 rad means at least about 26 teeth
#: (θ_f = 0.1435 at z = 21, 0.1255 at z = 24, 0.1205 at z = 25): ordinary pinions lie just outside this range,
#: while L*, M*, P*, Q* stay within the fit's data there, which the message then says.
SAINSOT_INPUT_RANGES: dict[str, tuple[float, float]] = {"h_f": (1.4, 7.0), "theta_f": (0.01, 0.12)}


#: The words every Sainsot extrapolation message starts with, and what to do about it.
SAINSOT_WARNING = "Sainsot fillet-foundation fit extrapolated"
SAINSOT_ADVICE = ("the gear-body part of the tooth compliance is less certain there: where the stiffness matters, "
                  "compare it with the finite-element tooth model (`thermogear fem CASE`, FE vs PEM tooth compliance)")

#: Nominal radius of the torque-carrying seat of a solid or small-bore gear as a share of its root radius [–]:
#: the solid-gear inner boundary of the finite-element tooth model (thermogear.fem.tooth_mesh, docs/fem.md).
NOMINAL_SEAT_RATIO = 0.3


def evaluated_root_to_bore_ratio(root_to_bore):
    """h_f at which the Sainsot fit is evaluated [–]: the gear's h_f = r_f/r_int limited to
    [1.4, 1/NOMINAL_SEAT_RATIO]. A solid gear (h_f = ∞) and any bore below the nominal seat 0.3 r_f are evaluated
    at the seat, a rim thinner than the fit's data at h_f = 1.4 (module docstring)."""
    low = SAINSOT_INPUT_RANGES["h_f"][0]
    return np.clip(np.asarray(root_to_bore, dtype=float), low, 1.0 / NOMINAL_SEAT_RATIO)


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
    circle) and S_f = 2 r_f θ_f. ``load_angle`` α1 [rad] may be an array. ``root_to_bore_ratio`` h_f = r_f/r_int
    [–] may be ``inf`` (a solid gear): L*, M*, P*, Q* are evaluated at :func:`evaluated_root_to_bore_ratio` (h_f
    limited to [1.4, 1/0.3], module docstring).
    """
    root_to_bore_ratio = evaluated_root_to_bore_ratio(root_to_bore_ratio)
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
    """h_f = r_f / r_int [–] of the gear as built: ``inf`` for a solid gear (no bore, r_int = 0); the fit is
    evaluated at :func:`evaluated_root_to_bore_ratio` of it. Refuses a negative or non-finite bore radius."""
    if not (math.isfinite(bore_radius) and bore_radius >= 0.0):
        raise CaseError(f"gears.{key}.bore_radius_mm", bore_radius * 1e3, ">= 0 (0 or omitted: a solid gear)",
                        "a bore radius is a length")
    if bore_radius == 0.0:
        return math.inf
    return root_radius / bore_radius


def check_sainsot_range(root_to_bore: float, root_half_angle_rad: float, key: str = "gear",
                        warn: bool = True) -> list[str]:
    """Messages for each input or output of the Sainsot fit outside its range; with ``warn`` each is also
    issued as an ExtrapolationWarning. A bore inside the fit's data but below the nominal seat (evaluated at the
    seat) is reported too, as a ModelAssumptionWarning. The outputs are checked at the h_f the fit is evaluated
    at."""
    messages = []
    assumptions = []
    low, high = SAINSOT_INPUT_RANGES["h_f"]
    evaluated = float(evaluated_root_to_bore_ratio(root_to_bore))
    built = ("a solid gear (no bore), h_f = ∞" if math.isinf(root_to_bore)
             else f"h_f = r_f/r_int = {root_to_bore:.3f}")
    if not low <= root_to_bore <= high:
        treatment = ("the fit's thinnest rim" if root_to_bore < low
                     else f"the nominal seat r_int = {NOMINAL_SEAT_RATIO:g} r_f")
        messages.append(f"{key}: {built} outside the fitted range [{low}, {high}]; evaluated at h_f = "
                        f"{evaluated:.3g} ({treatment}, docs/stiffness.md)")
    elif root_to_bore > evaluated:
        assumptions.append(f"{key}: bore below the nominal seat radius {NOMINAL_SEAT_RATIO:g} r_f ({built}): the "
                           f"Sainsot body compliance is evaluated at the seat, h_f = {evaluated:.3g} "
                           "(docs/stiffness.md)")
    low, high = SAINSOT_INPUT_RANGES["theta_f"]
    if not low <= root_half_angle_rad <= high:
        messages.append(f"{key}: θ_f = {root_half_angle_rad:.4f} rad outside the fitted range [{low}, {high}]")
    outputs_inside = True
    for name, (low, high) in SAINSOT_OUTPUT_RANGES.items():
        value = float(sainsot_coefficient(name, evaluated, root_half_angle_rad))
        if not low <= value <= high:
            outputs_inside = False
            messages.append(f"{key}: {name}* = {value:.4f} outside the range of Sainsot's data [{low}, {high}]")
    if messages and outputs_inside:  # only an input outside: the coefficients stay within what the fit was made on
        messages = [f"{text} (the coefficients L*, M*, P*, Q* stay within the fit's data: a mild extrapolation)"
                    for text in messages]
    messages = [f"{SAINSOT_WARNING} — {text}; {SAINSOT_ADVICE}" for text in messages]
    # One wording for every command (stiffness, run, sweeps) and one place the warning comes from: warnings are
    # attributed to the single call in potential_energy.tooth_compliance (stacklevel 2), so Python's default filter
    # shows each gear's message once however many stiffness tables a call builds.
    for message in messages if warn else ():
        warnings.warn(message, ExtrapolationWarning, stacklevel=2)
    for message in assumptions if warn else ():
        warnings.warn(message, ModelAssumptionWarning, stacklevel=2)
    return messages + assumptions


def gear_sainsot_messages(gear, key: str = "gear") -> list[str]:
    """Extrapolation messages of the Sainsot fit for one gear (no warning issued)."""
    h_f = root_to_bore_ratio(gear.root_radius, gear.bore_radius, key)
    theta_f = root_half_angle(gear.teeth, gear.pressure_angle, gear.dedendum_coefficient,
                              gear.tool_tip_radius_coefficient)
    return check_sainsot_range(h_f, theta_f, key, warn=False)
