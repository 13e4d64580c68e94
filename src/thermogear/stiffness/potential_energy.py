"""Elastic compliance of spur gear teeth by the potential energy method (PEM).

Yang & Lin (1987): Hertz, bending, axial compression; Tian (2004): shear; Sainsot et al. (2004): fillet
foundation; two-case root treatment after Ma et al. (2015). Formulas, symbols and derivations: Yang & Lin (1987), Tian 2004; Chaari et al. 2009.

All compliances are in m/N for a face width L [m] (pass L = 1 for per-unit-width values). The load angle α1 of
Chaari et al. (2009) is the angle between the contact force and the normal to the tooth centreline.

The integrals over the involute are evaluated with fixed Gauss–Legendre nodes mapped onto [−α1, α_end] for all
contact positions at once (one (positions × nodes) array); the straight root segment below the base circle has
closed forms (Tian 2004; Chaari et al. 2009).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from thermogear.geometry import Gear, GearPair
from thermogear.materials import Material
from thermogear.stiffness.fillet_foundation import (check_sainsot_range, fillet_foundation_compliance,
                                                    root_half_angle, root_to_bore_ratio)

#: Gauss–Legendre nodes per involute integral. The integrands are smooth (analytic) on the interval; 24 nodes
#: agree with adaptive quadrature to ~1e-13 relative (tests/unit/test_potential_energy.py).
GAUSS_NODE_COUNT = 24

#: Shear form factor of a rectangular section (Tian 2004).
SHEAR_FORM_FACTOR = 1.2


@lru_cache(maxsize=8)
def _gauss_legendre(count: int) -> tuple[np.ndarray, np.ndarray]:
    nodes, weights = np.polynomial.legendre.leggauss(count)
    nodes.setflags(write=False)
    weights.setflags(write=False)
    return nodes, weights


# ------------------------------------------------------------------------------------------------- functions
def hertz_compliance(youngs_modulus: float, poisson_ratio: float, face_width: float) -> float:
    """Hertzian contact compliance 1/k_h = 4(1 − ν²)/(π E L) [m/N] (Yang & Sun 1985).

    Load-independent (linearised line contact) and the same for every contact position.
    """
    return 4.0 * (1.0 - poisson_ratio**2) / (math.pi * youngs_modulus * face_width)


def involute_end_angle(half_tooth_angle_base: float, base_radius: float, root_radius: float) -> float:
    """Upper limit α_end of the involute integrals [rad] (Tian 2004; Chaari et al. 2009).

    α2 when the root circle lies below the base circle (the involute runs down to r_b); otherwise
    α5 = α2 − sqrt((r_f/r_b)² − 1), where the involute r(α) = r_b·sqrt(1 + (α2 − α)²) meets the root circle.
    """
    if root_radius < base_radius:
        return half_tooth_angle_base
    return half_tooth_angle_base - math.sqrt((root_radius / base_radius) ** 2 - 1.0)


def involute_integrals(load_angle, half_tooth_angle_base: float, end_angle: float,
                       node_count: int = GAUSS_NODE_COUNT) -> tuple[np.ndarray, np.ndarray]:
    """Dimensionless PEM integrals over the involute part of the tooth, α ∈ [−α1, α_end] (Tian 2004; Chaari et al. 2009).

    Returns (I_b, I_n) with
        I_b = ∫ 3{1 + cos α1[(α2 − α) sin α − cos α]}² (α2 − α) cos α / (2[sin α + (α2 − α) cos α]³) dα
        I_n = ∫ (α2 − α) cos α / [sin α + (α2 − α) cos α] dα,
    so that 1/k_b = I_b/(E L), 1/k_s = 1.2(1 + ν) cos²α1 I_n/(E L), 1/k_a = sin²α1 I_n/(2 E L).
    Vectorised over ``load_angle`` α1 [rad] with ``node_count`` fixed Gauss–Legendre nodes.
    """
    alpha_1 = np.asarray(load_angle, dtype=float)
    nodes, weights = _gauss_legendre(node_count)
    low = -alpha_1[..., None]
    half_span = 0.5 * (end_angle - low)
    alpha = low + half_span * (nodes + 1.0)
    arm = half_tooth_angle_base - alpha  # α2 − α
    cos_a = np.cos(alpha)
    sin_a = np.sin(alpha)
    thickness = sin_a + arm * cos_a  # h(α)/r_b
    jacobian = arm * cos_a  # −dx/(r_b dα)
    moment = 1.0 + np.cos(alpha_1)[..., None] * (arm * sin_a - cos_a)  # (r_b − x cos α1)/r_b
    bending = 1.5 * moment**2 * jacobian / thickness**3
    normal = jacobian / thickness
    scale = half_span[..., 0]
    return scale * (bending @ weights), scale * (normal @ weights)


def root_segment_integrals(load_angle, half_tooth_angle_base: float, base_radius: float,
                           root_radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Closed-form PEM integrals of the straight segment between root and base circle (Tian 2004; Chaari et al. 2009) [–].

    Zero when r_f ≥ r_b. Otherwise the tooth between r_f and r_b is a straight segment of half-thickness
    r_b sin α2, α3 = arcsin(r_b sin α2 / r_f), and
        ΔI_b = [(1 − (r_f/r_b) cos α1 cos α3)³ − (1 − cos α1 cos α2)³] / (2 cos α1 sin³α2)
        ΔI_n = (cos α2 − (r_f/r_b) cos α3) / sin α2
    (the same normalisation as :func:`involute_integrals`).
    """
    alpha_1 = np.asarray(load_angle, dtype=float)
    if root_radius >= base_radius:
        zero = np.zeros_like(alpha_1)
        return zero, zero
    alpha_2 = half_tooth_angle_base
    ratio = root_radius / base_radius
    alpha_3 = math.asin(min(math.sin(alpha_2) / ratio, 1.0))
    cos_1 = np.cos(alpha_1)
    bending = ((1.0 - ratio * cos_1 * math.cos(alpha_3)) ** 3 - (1.0 - cos_1 * math.cos(alpha_2)) ** 3) / (
        2.0 * cos_1 * math.sin(alpha_2) ** 3)
    normal = np.full_like(alpha_1, (math.cos(alpha_2) - ratio * math.cos(alpha_3)) / math.sin(alpha_2))
    return bending, normal


# ------------------------------------------------------------------------------------------------ components
@dataclass(frozen=True, eq=False)
class ToothCompliance:
    """Compliances of one tooth at a set of contact positions [m/N], arrays of one shape."""

    bending: np.ndarray
    shear: np.ndarray
    axial: np.ndarray
    fillet: np.ndarray

    @property
    def total(self) -> np.ndarray:
        """δ_tooth = 1/k_b + 1/k_s + 1/k_a + 1/k_f [m/N]."""
        return self.bending + self.shear + self.axial + self.fillet


def tooth_compliance(gear: Gear, load_angle, material: Material, face_width: float,
                     key: str = "gear", node_count: int = GAUSS_NODE_COUNT,
                     warn: bool = True) -> ToothCompliance:
    """Bending, shear, axial and fillet-foundation compliance of one tooth [m/N] (Tian 2004; Sainsot et al. 2004).

    ``load_angle`` α1 [rad] (scalar or array; see :meth:`GearPair.pinion_load_angle`); ``face_width`` L [m];
    ``key`` ("pinion"/"wheel") names the gear in errors and warnings. Handles the root circle below the base
    circle (straight root segment) and above it (involute integrated down to the root circle), and profile
    shift (through α2, r_f and r_a). Warns (ExtrapolationWarning) where the Sainsot fit is extrapolated.
    """
    alpha_1 = np.asarray(load_angle, dtype=float)
    if not (face_width > 0.0 and material.youngs_modulus > 0.0):
        raise ValueError("tooth_compliance: face width and Young's modulus must be positive")
    alpha_2 = gear.half_tooth_angle_at_base
    base_radius = gear.base_radius
    root_radius = gear.root_radius
    end_angle = involute_end_angle(alpha_2, base_radius, root_radius)
    bending_i, normal_i = involute_integrals(alpha_1, alpha_2, end_angle, node_count)
    bending_r, normal_r = root_segment_integrals(alpha_1, alpha_2, base_radius, root_radius)
    stiffness_scale = material.youngs_modulus * face_width
    bending = (bending_i + bending_r) / stiffness_scale
    normal = (normal_i + normal_r) / stiffness_scale
    shear = SHEAR_FORM_FACTOR * (1.0 + material.poisson_ratio) * np.cos(alpha_1) ** 2 * normal
    axial = 0.5 * np.sin(alpha_1) ** 2 * normal
    h_f = root_to_bore_ratio(root_radius, gear.bore_radius, key)
    theta_f = root_half_angle(gear.teeth, gear.pressure_angle, gear.dedendum_coefficient,
                              gear.tool_tip_radius_coefficient)
    if warn:
        check_sainsot_range(h_f, theta_f, key)
    fillet = fillet_foundation_compliance(alpha_1, base_radius, root_radius, h_f, theta_f,
                                          material.youngs_modulus, face_width)
    compliance = ToothCompliance(bending, shear, axial, fillet)
    total = compliance.total
    if not np.all(np.isfinite(total)) or np.any(total <= 0.0):
        raise ValueError(f"tooth_compliance ({key}): non-finite or non-positive compliance; check the geometry "
                         "(load angles outside the tooth?)")
    return compliance


@dataclass(frozen=True, eq=False)
class PairCompliance:
    """Compliance of one tooth pair at roll distances ``roll`` [m] from T1; totals over the face width."""

    roll: np.ndarray  # [m]
    pinion: ToothCompliance
    wheel: ToothCompliance
    hertz: float  # [m/N]

    @property
    def total(self) -> np.ndarray:
        """δ = δ_pinion + δ_wheel + δ_hertz [m/N] (docs/derivations.md)."""
        return self.pinion.total + self.wheel.total + self.hertz

    @property
    def stiffness(self) -> np.ndarray:
        """Pair stiffness k_e = 1/δ [N/m]."""
        return 1.0 / self.total

    @property
    def pinion_total(self) -> np.ndarray:
        """δ1: pinion tooth compliance plus half the Hertz compliance [m/N] (so δ1 + δ2 = δ; Luo & Li 2020, Eqs. 7–23)."""
        return self.pinion.total + 0.5 * self.hertz

    @property
    def wheel_total(self) -> np.ndarray:
        """δ2: wheel tooth compliance plus half the Hertz compliance [m/N]."""
        return self.wheel.total + 0.5 * self.hertz


def pair_compliance(gear_pair: GearPair, material: Material, roll, face_width: float | None = None,
                    node_count: int = GAUSS_NODE_COUNT, warn: bool = True) -> PairCompliance:
    """Pinion, wheel and Hertz compliance of one tooth pair in contact at roll distances ``roll`` [m].

    ``face_width`` [m] defaults to the pair's common face width (totals over the face width); pass 1 for
    per-unit-width values. The two teeth and the contact act in series (docs/derivations.md).
    """
    roll = np.asarray(roll, dtype=float)
    width = gear_pair.face_width if face_width is None else float(face_width)
    pinion = tooth_compliance(gear_pair.pinion, gear_pair.pinion_load_angle(roll), material, width, "pinion",
                              node_count, warn)
    wheel = tooth_compliance(gear_pair.wheel, gear_pair.wheel_load_angle(roll), material, width, "wheel",
                             node_count, warn)
    return PairCompliance(roll, pinion, wheel,
                          hertz_compliance(material.youngs_modulus, material.poisson_ratio, width))
