"""Involute relations of spur gears, one function each (ISO 21771; Luo & Li (2020) Eqs. 5, 8, 24), vectorised
where a radius or a position is an argument. The components of :mod:`thermogear.geometry` call them."""

from __future__ import annotations

import math

import numpy as np


def involute(angle):
    """Involute function inv α = tan α − α [rad]."""
    return np.tan(angle) - angle


def inverse_involute(value, tolerance: float = 1e-14):
    """Angle α [rad] with inv α = value, by Newton's method (vectorised).

    tan α − α is convex and increasing on [0, π/2), and both (3v)^(1/3) and arctan(v + π/2) bound the root from
    above, so Newton's method started at the smaller of the two converges monotonically.
    """
    value = np.asarray(value, dtype=float)
    if np.any(value < 0):
        raise ValueError("inverse_involute: the involute function is non-negative")
    angle = np.minimum(np.cbrt(3.0 * value), np.arctan(value + np.pi / 2.0))
    for _ in range(50):
        step = (np.tan(angle) - angle - value) / np.tan(angle) ** 2
        step = np.where(angle > 0, step, 0.0)
        angle = angle - step
        if np.all(np.abs(step) < tolerance):
            break
    return angle if angle.ndim else float(angle)


def reference_tooth_thickness(module: float, pressure_angle: float, profile_shift: float) -> float:
    """Circular tooth thickness on the reference circle s = m(π/2 + 2x·tan α) [m] (ISO 21771)."""
    return module * (math.pi / 2.0 + 2.0 * profile_shift * math.tan(pressure_angle))


def half_tooth_angle(radius, reference_radius: float, reference_thickness: float, pressure_angle: float,
                     base_radius: float):
    """Half angular tooth thickness φ_k at radius r_k [rad] (Luo & Li Eq. 8, with s the reference thickness).

    φ_k = s/(2r) + inv α − inv α_k,  cos α_k = r_b / r_k.
    """
    radius = np.asarray(radius, dtype=float)
    local_pressure_angle = np.arccos(np.clip(base_radius / radius, -1.0, 1.0))
    return (reference_thickness / (2.0 * reference_radius) + involute(pressure_angle)
            - involute(local_pressure_angle))


def tooth_thickness_at_radius(radius, reference_radius: float, reference_thickness: float,
                              pressure_angle: float, base_radius: float):
    """Circular tooth thickness s_k = 2 r_k φ_k at radius r_k ≥ r_b [m] (ISO 21771)."""
    radius = np.asarray(radius, dtype=float)
    return 2.0 * radius * half_tooth_angle(radius, reference_radius, reference_thickness, pressure_angle,
                                           base_radius)


def operating_pressure_angle_from_shifts(teeth_1: int, teeth_2: int, shift_1: float, shift_2: float,
                                         pressure_angle: float) -> float:
    """Operating pressure angle α_w of zero-backlash mesh: inv α_w = inv α + 2 tan α (x1+x2)/(z1+z2) [rad]."""
    return inverse_involute(involute(pressure_angle)
                            + 2.0 * math.tan(pressure_angle) * (shift_1 + shift_2) / (teeth_1 + teeth_2))


def gamma_from_roll(roll, pitch_point_roll: float):
    """Dimensionless contact position Γ = (T1K − T1C)/T1C (Luo & Li Eq. 24) [–]."""
    return (np.asarray(roll, dtype=float) - pitch_point_roll) / pitch_point_roll


def roll_from_gamma(gamma, pitch_point_roll: float):
    """Roll distance T1K [m] of a contact position Γ (inverse of Eq. 24)."""
    return pitch_point_roll * (1.0 + np.asarray(gamma, dtype=float))


def disc_polar_inertia(density: float, outer_radius: float, bore_radius: float, width: float) -> float:
    """Polar moment of inertia of a solid disc with a bore, J = ρπb(R⁴ − r⁴)/2 [kg·m²]."""
    return density * math.pi * width * (outer_radius**4 - bore_radius**4) / 2.0


__all__ = ["involute", "inverse_involute", "reference_tooth_thickness", "half_tooth_angle", "tooth_thickness_at_radius", "operating_pressure_angle_from_shifts", "gamma_from_roll", "roll_from_gamma", "disc_polar_inertia"]
