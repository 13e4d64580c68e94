"""No-load churning loss of a gear dipping in an oil bath (Changenet–Velex type correlation).

    T_ch = ½·ρ·ω²·R³·S_m·C_m ,   P_ch = T_ch·ω                                            [N·m], [W]
    C_m = K·(h/D)^a·(V0/D³)^c·Re^(−d)·Fr^(−f)·(b/D)^k,   Re = ω·R·b/ν,  Fr = ω²·R/g,  Υ = ω²·(R·b·m)^(1/3)

R pitch radius, D = 2R, b face width, m module, h immersion depth, V0 oil volume, ν kinematic viscosity (SI).
The form is Changenet & Velex (2007), J. Mech. Des. 129(1):128 "A model for the prediction of churning losses in
geared transmissions — preliminary results", extended to four flow regimes by Changenet, Leprince, Ville & Velex
(2011), J. Mech. Des. 133(12):121009 "A note on flow regimes and churning loss modeling". PROVENANCE: the papers
were not read for this module; the regime table below (constants, the Reynolds number ω·R·b/ν, Υ without g, the
linear interpolation in Υ between 750 and 1250) is that of a third-party implementation and is shipped as an
unverified correlation. Its own consistency is checked: C_m is continuous at Re = 4000 because
1.366·4000^−0.21 = 0.2395 ≈ 0.239 and 20.797·4000^−0.21 = 3.645 ≈ 3.644 (to 0.3 ‰).

Wetted area (geometry, Changenet & Velex 2007): θ = arccos(1 − 2h/D) the half angle of the immersed arc;
S_m = R²(2θ − sin 2θ) (both faces) + 2·R·θ·b (immersed rim; the third-party code has R·θ·b, half the arc) +
2·z·θ·h_t·b/(π·cos α·cos β) (tooth flanks, as in that code). Validity: the rigs of the papers (spur and helical gears
of about 100–250 mm diameter, dip lubrication; h/D up to about 0.5); warn outside 0.1 ≤ h/D ≤ 0.5 or for an
immersion below the root (not implemented as a warning here: :func:`churning_validity` says so).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from thermogear.errors import CaseError

GRAVITY = 9.80665  # [m/s²]

#: (K, a, c, d, f, k) of the four regimes: low/high Re × low/high Υ (see the module docstring's provenance).
REGIME_CONSTANTS = {
    (False, False): (1.366, 0.45, 0.1, 0.21, 0.6, 0.21),
    (True, False): (0.239, 0.45, 0.1, 0.0, 0.6, 0.21),
    (False, True): (20.797, 0.1, -0.35, 0.21, 0.88, 0.85),
    (True, True): (3.644, 0.1, -0.35, 0.0, 0.88, 0.85),
}
CRITICAL_REYNOLDS = 4000.0
LOW_SPEED_PARAMETER = 750.0  # Υ below: low-speed regime
HIGH_SPEED_PARAMETER = 1250.0  # Υ above: high-speed regime


@dataclass(frozen=True)
class DippedGear:
    """A gear dipping in the oil bath: pitch radius, face width, module [m], teeth, tooth height [m],
    immersion depth h [m] (0: above the oil), oil volume V0 [m³], pressure and helix angle [rad]."""

    pitch_radius: float
    face_width: float
    module: float
    teeth: int
    tooth_height: float
    immersion_depth: float
    oil_volume: float
    pressure_angle: float = math.radians(20.0)
    helix_angle: float = 0.0

    def __post_init__(self) -> None:
        for key in ("pitch_radius", "face_width", "module", "tooth_height", "oil_volume"):
            value = getattr(self, key)
            if not (math.isfinite(value) and value > 0.0):
                raise CaseError(f"churning.{key}", value, "> 0", "a size of the dipped gear or of the bath")
        if not (0.0 <= self.immersion_depth <= 2.0 * self.pitch_radius):
            raise CaseError("churning.immersion_depth", self.immersion_depth,
                            f"[0, {2.0 * self.pitch_radius:.4g}] m", "from above the oil to fully submerged")

    @property
    def immersed_half_angle(self) -> float:
        """θ = arccos(1 − 2h/D) [rad]."""
        return math.acos(1.0 - self.immersion_depth / self.pitch_radius)

    @property
    def wetted_area(self) -> float:
        """S_m [m²] (module docstring)."""
        theta, radius, width = self.immersed_half_angle, self.pitch_radius, self.face_width
        faces = radius**2 * (2.0 * theta - math.sin(2.0 * theta))
        rim = 2.0 * radius * theta * width
        flanks = (2.0 * self.teeth * theta * self.tooth_height * width
                  / (math.pi * math.cos(self.pressure_angle) * math.cos(self.helix_angle)))
        return faces + rim + flanks


def _coefficient(constants, immersion_ratio, volume_ratio, reynolds, froude, width_ratio) -> float:
    factor, a, c, d, f, k = constants
    return (factor * immersion_ratio**a * volume_ratio**c * reynolds**(-d) * froude**(-f) * width_ratio**k)


def churning_coefficient(gear: DippedGear, speed_rad_s: float, kinematic_viscosity: float) -> float:
    """Dimensionless churning torque C_m [–] (module docstring): the regime from Re and Υ, linear in Υ between
    the low- and high-speed regimes for 750 ≤ Υ ≤ 1250."""
    if not (speed_rad_s > 0.0 and kinematic_viscosity > 0.0):
        raise CaseError("churning.speed", speed_rad_s, "> 0 with viscosity > 0", "C_m needs motion and a fluid")
    if gear.immersion_depth == 0.0:
        return 0.0
    diameter = 2.0 * gear.pitch_radius
    reynolds = speed_rad_s * gear.pitch_radius * gear.face_width / kinematic_viscosity
    froude = speed_rad_s**2 * gear.pitch_radius / GRAVITY
    parameter = speed_rad_s**2 * (gear.pitch_radius * gear.face_width * gear.module)**(1.0 / 3.0)
    turbulent = reynolds > CRITICAL_REYNOLDS
    ratios = (gear.immersion_depth / diameter, gear.oil_volume / diameter**3, reynolds, froude,
              gear.face_width / diameter)
    low = _coefficient(REGIME_CONSTANTS[(turbulent, False)], *ratios)
    high = _coefficient(REGIME_CONSTANTS[(turbulent, True)], *ratios)
    weight = min(max((parameter - LOW_SPEED_PARAMETER) / (HIGH_SPEED_PARAMETER - LOW_SPEED_PARAMETER), 0.0), 1.0)
    return (1.0 - weight) * low + weight * high


def churning_power_loss(gear: DippedGear, speed_rad_s: float, kinematic_viscosity: float, density: float) -> float:
    """P_ch = ½·ρ·ω³·R³·S_m·C_m [W] at gear speed ω [rad/s], oil ν [m²/s] and ρ [kg/m³]."""
    if gear.immersion_depth == 0.0:
        return 0.0
    if not density > 0.0:
        raise CaseError("lubricant.density", density, "> 0 kg/m³", "the oil has mass")
    coefficient = churning_coefficient(gear, speed_rad_s, kinematic_viscosity)
    return 0.5 * density * speed_rad_s**3 * gear.pitch_radius**3 * gear.wetted_area * coefficient


def churning_validity(gear: DippedGear) -> str | None:
    """A sentence when the immersion is outside 0.1 ≤ h/D ≤ 0.5 (the papers' rig range), else None."""
    ratio = gear.immersion_depth / (2.0 * gear.pitch_radius)
    if gear.immersion_depth > 0.0 and not 0.1 <= ratio <= 0.5:
        return f"churning: immersion h/D = {ratio:.3g} outside the correlation's tested 0.1–0.5"
    return None
