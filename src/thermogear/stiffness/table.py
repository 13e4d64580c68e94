"""Cached pair-compliance tables along the path of contact, and interpolation from them.

The PEM quadrature runs once per (gear pair, material) and grid size; sweeps that change only speed or load
reuse the table (design.md, performance). Inputs are frozen, hashable dataclasses, so ``functools.lru_cache``
keys on them directly. Cached arrays are read-only.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from scipy.interpolate import CubicSpline

from thermogear import warning_scope
from thermogear.geometry import GearPair
from thermogear.materials import Material
from thermogear.stiffness.potential_energy import PairCompliance, ToothCompliance, pair_compliance

#: Default number of roll positions of a table, A to E inclusive.
TABLE_POINT_COUNT = 401

#: Rolls this far outside [A, E] [m] are still accepted (rounding of the callers' time → roll mapping).
ROLL_TOLERANCE = 1e-9


def _read_only(compliance: PairCompliance) -> PairCompliance:
    arrays = [compliance.roll]
    for tooth in (compliance.pinion, compliance.wheel):
        arrays += [tooth.bending, tooth.shear, tooth.axial, tooth.fillet]
    for array in arrays:
        array.setflags(write=False)
    return compliance


@lru_cache(maxsize=64)
def _table_with_warnings(gear_pair: GearPair, material: Material, count: int) -> tuple[PairCompliance, tuple]:
    with warning_scope.recorded() as caught:
        table = _read_only(pair_compliance(gear_pair, material, gear_pair.roll_grid(count)))
    return table, warning_scope.kept(caught)


def pair_compliance_table(gear_pair: GearPair, material: Material, count: int = TABLE_POINT_COUNT) -> PairCompliance:
    """Pair compliance on ``count`` evenly spaced roll distances from A to E (inclusive), totals over the
    face width [m/N]. Cached; the arrays are read-only. The warnings of the first computation (e.g. the
    fillet-foundation fit extrapolated) are raised again on every call, so the cache never swallows them."""
    if count < 4:
        raise ValueError("pair_compliance_table: count must be at least 4")
    table, recorded = _table_with_warnings(gear_pair, material, count)
    warning_scope.raise_again(recorded)
    return table


@lru_cache(maxsize=64)
def _spline_set(gear_pair: GearPair, material: Material) -> tuple[dict[str, CubicSpline], tuple]:
    table, recorded = _table_with_warnings(gear_pair, material, TABLE_POINT_COUNT)
    return {"stiffness": CubicSpline(table.roll, table.stiffness),
            "pinion": CubicSpline(table.roll, table.pinion_total),
            "wheel": CubicSpline(table.roll, table.wheel_total)}, recorded


def _splines(gear_pair: GearPair, material: Material) -> dict[str, CubicSpline]:
    """The cached splines of a pair's table; re-raises the warnings of the table's computation."""
    splines, recorded = _spline_set(gear_pair, material)
    warning_scope.raise_again(recorded)
    return splines


def _checked_roll(gear_pair: GearPair, roll) -> np.ndarray:
    roll = np.asarray(roll, dtype=float)
    start, end = gear_pair.path_points["A"], gear_pair.path_points["E"]
    if roll.size and (np.min(roll) < start - ROLL_TOLERANCE or np.max(roll) > end + ROLL_TOLERANCE):
        raise ValueError(f"roll distance outside the path of contact [{start * 1e3:.4f}, {end * 1e3:.4f}] mm "
                         f"(got {np.min(roll) * 1e3:.4f} … {np.max(roll) * 1e3:.4f} mm); mask pairs out of "
                         "contact before asking for their stiffness")
    return np.clip(roll, start, end)


def pair_stiffness_at(gear_pair: GearPair, material: Material, roll) -> np.ndarray:
    """Pair stiffness k_e [N/m] (total over the face width) at roll distances on [A, E], by cubic
    interpolation of the cached table (error < 1e-6 relative with 401 points). Raises ValueError outside."""
    return _splines(gear_pair, material)["stiffness"](_checked_roll(gear_pair, roll))


@lru_cache(maxsize=64)
def _stiffness_antiderivative(gear_pair: GearPair, material: Material):
    return _spline_set(gear_pair, material)[0]["stiffness"].antiderivative()


def pair_stiffness_integral(gear_pair: GearPair, material: Material, start, end) -> np.ndarray:
    """∫ k_e(s) ds [N] over [start, end] ∩ [A, E] (roll distances [m]; k_e the total over the face width), exact
    for the interpolating cubic of :func:`pair_stiffness_at` (its antiderivative, cached with the table)."""
    low, high = gear_pair.path_points["A"], gear_pair.path_points["E"]
    start = np.clip(np.asarray(start, dtype=float), low, high)
    end = np.clip(np.asarray(end, dtype=float), low, high)
    _splines(gear_pair, material)  # the table's warnings, raised again
    primitive = _stiffness_antiderivative(gear_pair, material)
    return np.where(end > start, primitive(end) - primitive(start), 0.0)


def tooth_compliance_at(gear_pair: GearPair, material: Material, roll) -> tuple[np.ndarray, np.ndarray]:
    """(δ1, δ2) [m/N]: each tooth's compliance including half the Hertz compliance (δ1 + δ2 = 1/k_e),
    interpolated from the cached table at roll distances on [A, E]."""
    roll = _checked_roll(gear_pair, roll)
    splines = _splines(gear_pair, material)
    return splines["pinion"](roll), splines["wheel"](roll)


def clear_cache() -> None:
    """Drop every cached table (tests, memory)."""
    _table_with_warnings.cache_clear()
    _spline_set.cache_clear()
    _stiffness_antiderivative.cache_clear()


__all__ = ["TABLE_POINT_COUNT", "PairCompliance", "ToothCompliance", "clear_cache", "pair_compliance_table",
           "pair_stiffness_at", "pair_stiffness_integral", "tooth_compliance_at"]
