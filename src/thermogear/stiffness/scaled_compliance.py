"""Tooth compliance of a uniformly grown gear from one Chebyshev interpolant per gear shape.

Every length of a gear grown by a uniform strain ε (module, face width, bore; :func:`thermogear.thermoelastic.
operating.scaled_gear`) is the cold one × (1 + ε), while its angles (α, α2, θ_f) and radius ratios (r_f/r_b,
r_f/r_int) are unchanged. Each potential-energy compliance of a tooth at load angle α1 is a dimensionless integral
over E·L (Tian 2004, Eqs. for 1/k_b, 1/k_s, 1/k_a; Sainsot et al. 2004 for 1/k_f, whose u_f/S_f is a ratio of
lengths), so the product

    c(α1) = E·L·δ_tooth(α1)   [–]

is one function per gear *shape* (teeth, pressure angle, shift, rack coefficients, bore-to-module ratio) and
Poisson ratio: the same for the cold gear and for every warm state of a warm-up. The warm states differ only in
where the path of contact lies (which α1 each roll distance has, through the centre distance) and in E·L.

:func:`tooth_compliance_interpolant` builds c(α1) once per shape as a Chebyshev interpolant through
:func:`thermogear.stiffness.potential_energy.tooth_compliance` (the direct PEM quadrature) and accepts it only when
it agrees with the direct computation to :data:`INTERPOLANT_TOLERANCE` (relative) at check points between its
nodes. :func:`pair_stiffness_at` and :func:`tooth_compliance_at` then answer exactly as their namesakes of
:mod:`thermogear.stiffness.table` (a 401-point table along the pair's own path, cubic-spline interpolated), with
the table's values taken from the interpolants instead of the quadrature: the same results to the interpolant's
error, at a fraction of the cost for a pair that is a new cache key (every warm state of a warm-up).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.interpolate import CubicSpline

from thermogear import warning_scope
from thermogear.geometry import Gear, GearPair
from thermogear.materials import Material
from thermogear.stiffness.fillet_foundation import check_sainsot_range, root_half_angle, root_to_bore_ratio
from thermogear.stiffness.potential_energy import hertz_compliance, tooth_compliance
from thermogear.stiffness.table import ROLL_TOLERANCE, TABLE_POINT_COUNT

#: Largest accepted relative error of an interpolant against the direct quadrature [–], checked at build on
#: points between the Chebyshev nodes (where an interpolant's error is largest). c(α1) is analytic on the range
#: (the integrands of potential_energy.involute_integrals and the Sainsot polynomial are smooth for α1 > −α2), so
#: the Chebyshev error falls geometrically with the degree; 1e-11 leaves two decades under the 1e-9 the warm-up's
#: results are held to.
INTERPOLANT_TOLERANCE = 1e-11

#: Chebyshev degrees tried in turn; the first that meets the tolerance is kept.
DEGREES = (24, 40, 64, 96)

#: Check points between nodes in the acceptance test of an interpolant.
CHECK_POINT_COUNT = 97

#: The load-angle range of an interpolant is the range a path asks for, widened to multiples of this step [rad]
#: plus one step each side, so that the small shifts of the path during a warm-up (mrad) reuse one interpolant.
ANGLE_STEP = 0.02

#: Significant digits of the bore-to-module ratio in the shape key (grown gears give the same ratio to rounding).
SHAPE_DIGITS = 12


@dataclass(frozen=True, eq=False)
class ToothComplianceInterpolant:
    """c(α1) = E·L·δ_tooth(α1) [–] of one gear shape on load angles [low, high] [rad] (module docstring)."""

    low: float
    high: float
    series: np.polynomial.Chebyshev
    largest_error: float  # largest relative error found at the check points [–]

    def covers(self, load_angle: np.ndarray) -> bool:
        return bool(load_angle.size == 0 or (np.min(load_angle) >= self.low and np.max(load_angle) <= self.high))

    def __call__(self, load_angle) -> np.ndarray:
        return self.series(np.asarray(load_angle, dtype=float))


def _shape_key(gear: Gear) -> tuple:
    """What the dimensionless compliance of a gear depends on (module docstring); lengths as ratios to the module."""
    bore = float(f"{gear.bore_radius / gear.module:.{SHAPE_DIGITS}g}")
    return (gear.teeth, gear.pressure_angle, gear.profile_shift, gear.dedendum_coefficient,
            gear.tool_tip_radius_coefficient, bore)


def _unit_gear(key: tuple) -> Gear:
    teeth, pressure_angle, shift, dedendum, tool_tip, bore = key
    return Gear(teeth=teeth, module=1.0, pressure_angle=pressure_angle, face_width=1.0, profile_shift=shift,
                dedendum_coefficient=dedendum, tool_tip_radius_coefficient=tool_tip, bore_radius=bore)


@lru_cache(maxsize=32)
def _interpolant(key: tuple, poisson_ratio: float, low: float, high: float) -> ToothComplianceInterpolant | None:
    gear = _unit_gear(key)
    material = Material(youngs_modulus=1.0, poisson_ratio=poisson_ratio, density=1.0, thermal_expansion=0.0)

    def direct(load_angle):
        return tooth_compliance(gear, load_angle, material, 1.0, warn=False).total

    # check points: the midpoints between Chebyshev points of the highest degree tried, and the ends
    checks = 0.5 * (low + high) + 0.5 * (high - low) * np.cos(np.linspace(0.0, math.pi, CHECK_POINT_COUNT))
    try:
        reference = direct(checks)
    except ValueError:  # the margin of the range reaches past the tooth (a short or pointed tooth): the caller
        return None  # evaluates the quadrature at its own load angles, which lie on the tooth
    for degree in DEGREES:
        series = np.polynomial.Chebyshev.interpolate(direct, degree, domain=[low, high])
        error = float(np.max(np.abs(series(checks) / reference - 1.0)))
        if error <= INTERPOLANT_TOLERANCE:
            return ToothComplianceInterpolant(low, high, series, error)
    return None


def tooth_compliance_interpolant(gear: Gear, material: Material, load_angle) -> ToothComplianceInterpolant | None:
    """The interpolant of c(α1) for ``gear``'s shape covering ``load_angle`` [rad], cached per shape and range;
    None where no degree of :data:`DEGREES` meets :data:`INTERPOLANT_TOLERANCE` (callers then use the quadrature)."""
    load_angle = np.asarray(load_angle, dtype=float)
    low = (math.floor(float(np.min(load_angle)) / ANGLE_STEP) - 1) * ANGLE_STEP
    high = (math.ceil(float(np.max(load_angle)) / ANGLE_STEP) + 1) * ANGLE_STEP
    # below α1 = −α2 the contact would lie under the base circle: keep the range inside the tooth
    floor = -gear.half_tooth_angle_at_base + 0.5 * ANGLE_STEP
    if low < floor:  # (the floor itself, a stable cache key, unless the path reaches below it)
        low = min(floor, float(np.min(load_angle)))
    return _interpolant(_shape_key(gear), float(material.poisson_ratio), low, high)


def _tooth_totals(gear: Gear, load_angle: np.ndarray, material: Material, width: float, key: str) -> np.ndarray:
    """δ_tooth at ``load_angle`` [m/N] over the face width ``width``: from the interpolant, else the quadrature."""
    interpolant = tooth_compliance_interpolant(gear, material, load_angle)
    if interpolant is None or not interpolant.covers(load_angle):
        return tooth_compliance(gear, load_angle, material, width, key, warn=False).total
    return interpolant(load_angle) / (material.youngs_modulus * width)


@lru_cache(maxsize=16)
def _table(gear_pair: GearPair, material: Material) -> tuple[dict[str, np.ndarray], tuple]:
    """The table's roll grid and values (δ1, δ2 with half the Hertz compliance each, k_e) and the warnings the
    quadrature would give (the Sainsot fit's range)."""
    roll = gear_pair.roll_grid(TABLE_POINT_COUNT)
    width = gear_pair.face_width
    with warning_scope.recorded() as caught:
        for gear, key in ((gear_pair.pinion, "pinion"), (gear_pair.wheel, "wheel")):
            check_sainsot_range(root_to_bore_ratio(gear.root_radius, gear.bore_radius, key),
                                root_half_angle(gear.teeth, gear.pressure_angle, gear.dedendum_coefficient,
                                                gear.tool_tip_radius_coefficient), key)
    hertz = hertz_compliance(material.youngs_modulus, material.poisson_ratio, width)
    pinion = _tooth_totals(gear_pair.pinion, gear_pair.pinion_load_angle(roll), material, width, "pinion")
    wheel = _tooth_totals(gear_pair.wheel, gear_pair.wheel_load_angle(roll), material, width, "wheel")
    # the sums of PairCompliance (pinion_total, wheel_total, stiffness) of the table
    values = {"roll": roll, "pinion": pinion + 0.5 * hertz, "wheel": wheel + 0.5 * hertz,
              "stiffness": 1.0 / (pinion + wheel + hertz)}
    return values, warning_scope.kept(caught)


@lru_cache(maxsize=48)
def _spline(gear_pair: GearPair, material: Material, name: str) -> CubicSpline:
    values = _table(gear_pair, material)[0]
    return CubicSpline(values["roll"], values[name])  # the table's interpolation (stiffness.table)


def _checked_roll(gear_pair: GearPair, material: Material, roll) -> np.ndarray:
    warning_scope.raise_again(_table(gear_pair, material)[1])
    roll = np.asarray(roll, dtype=float)
    start, end = gear_pair.path_points["A"], gear_pair.path_points["E"]
    if roll.size and (np.min(roll) < start - ROLL_TOLERANCE or np.max(roll) > end + ROLL_TOLERANCE):
        raise ValueError(f"roll distance outside the path of contact [{start * 1e3:.4f}, {end * 1e3:.4f}] mm")
    return np.clip(roll, start, end)


def pair_stiffness_at(gear_pair: GearPair, material: Material, roll) -> np.ndarray:
    """Pair stiffness [N/m] as :func:`thermogear.stiffness.table.pair_stiffness_at`, the table from the
    interpolants (module docstring)."""
    roll = _checked_roll(gear_pair, material, roll)
    return _spline(gear_pair, material, "stiffness")(roll)


def tooth_compliance_at(gear_pair: GearPair, material: Material, roll) -> tuple[np.ndarray, np.ndarray]:
    """(δ1, δ2) [m/N] as :func:`thermogear.stiffness.table.tooth_compliance_at`, the table from the interpolants."""
    roll = _checked_roll(gear_pair, material, roll)
    return _spline(gear_pair, material, "pinion")(roll), _spline(gear_pair, material, "wheel")(roll)


def clear_cache() -> None:
    """Drop the cached interpolants and tables (tests, memory)."""
    _interpolant.cache_clear()
    _table.cache_clear()
    _spline.cache_clear()


__all__ = ["ToothComplianceInterpolant", "clear_cache", "pair_stiffness_at", "tooth_compliance_at",
           "tooth_compliance_interpolant"]
