"""The paper's meshing thermal stiffness k_T of a case (Luo & Li (2020) Eqs. 8–23): elastic compliances from the
cached PEM table, flank expansions of the case's temperature field, X_te given / calibrated / from a provider,
and the normal load of Eqs. 13–18 as an argument.

With the external load basis k_T is a smooth function of the roll distance for a given load: it is tabulated
once per case and load on the PEM table's roll grid and interpolated by a cubic spline, like k_e, so every
operating point and sweep at that load reuses it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from thermogear import warning_scope
from thermogear.case import cached_per_case
from thermogear.stiffness.potential_energy import pair_compliance
from thermogear.stiffness.table import pair_compliance_table, tooth_compliance_at
from thermogear.luo2020.calibration import resolve_x_te
from thermogear.luo2020.case_inputs import PaperThermalInputs
from thermogear.luo2020.stiffness import (CONTACT_TOLERANCE, ThermalStiffness, check_x_te, thermal_pair_stiffness)
from thermogear.temperature_source import TemperatureField, temperature_field_from_case

if TYPE_CHECKING:
    from thermogear.case import Case

#: Splines kept per case (one per distinct normal load) before the oldest is dropped.
_SPLINES_PER_CASE = 64


def thermal_stiffness(case: "Case", roll, x_te: float | None = None, load_basis: str | None = None,
                      temperature: TemperatureField | None = None, normal_load: float | None = None
                      ) -> ThermalStiffness:
    """Thermal stiffness of a case's tooth pair at roll distances T1K [m] (Luo & Li Eqs. 8–23).

    X_te is resolved from the case (given / calibrated / provider) unless ``x_te`` is passed; ``load_basis``
    overrides ``[thermal].load_basis``; ``normal_load`` [N] the external load (default: the case's).
    """
    roll = np.atleast_1d(np.asarray(roll, dtype=float))
    basis = case.thermal.load_basis if load_basis is None else load_basis
    temperature = temperature_field_from_case(case) if temperature is None else temperature
    if x_te is None:
        x_te, source = resolve_x_te(case, load_basis=basis, temperature=temperature)
    else:
        check_x_te(x_te)
        source = "given (argument)"
    elastic = pair_compliance(case.gear_pair, case.material, roll)
    inputs = PaperThermalInputs.from_case(case)
    expansion_pinion, expansion_wheel = inputs.expansion(roll, temperature)
    load = inputs.normal_load_at(roll, basis, external_load=normal_load)
    return ThermalStiffness(roll=roll, gamma=np.asarray(case.gear_pair.gamma(roll)), elastic=elastic,
                            expansion_pinion=np.asarray(expansion_pinion), expansion_wheel=np.asarray(expansion_wheel),
                            x_te=float(x_te), x_te_source=source, load_basis=basis, normal_load=load,
                            temperature=temperature)


def thermal_pair_stiffness_at(case: "Case", roll, x_te: float | None = None, normal_load: float | None = None
                              ) -> np.ndarray:
    """k_T [N/m] (total over the face width) of one tooth pair at roll distances T1K [m] under the external normal
    load ``normal_load`` [N] (default: the case's): what the dynamics use, summed over the pairs in contact.
    Zero outside the path [A, E]. Tabulated per case and load with the case's own X_te and the external load
    basis; evaluated directly otherwise."""
    roll = np.asarray(roll, dtype=float)
    points = case.gear_pair.path_points
    inside = (roll >= points["A"] - CONTACT_TOLERANCE) & (roll <= points["E"] + CONTACT_TOLERANCE)
    result = np.zeros(roll.shape)
    load = case.normal_load if normal_load is None else float(normal_load)
    if np.any(inside):
        inner = np.clip(roll[inside], points["A"], points["E"])
        if x_te is None and case.thermal.load_basis == "external":
            result[inside] = _spline(case, load)(inner)
        else:
            result[inside] = _thermal_pair_stiffness_direct(case, inner, x_te, load)
    return result if result.ndim else float(result)


def _thermal_pair_stiffness_direct(case: "Case", roll: np.ndarray, x_te: float | None, normal_load: float
                                   ) -> np.ndarray:
    """k_T [N/m] at roll distances on [A, E] from Eqs. 8–23 directly (elastic compliances from the PEM table)."""
    temperature = temperature_field_from_case(case)
    if x_te is None:
        x_te, _ = resolve_x_te(case, normal_load=normal_load)
    check_x_te(x_te)
    pinion, wheel = tooth_compliance_at(case.gear_pair, case.material, roll)
    inputs = PaperThermalInputs.from_case(case)
    expansion_pinion, expansion_wheel = inputs.expansion(roll, temperature)
    load = inputs.normal_load_at(roll, external_load=normal_load)
    return thermal_pair_stiffness(pinion, wheel, expansion_pinion, expansion_wheel, load, x_te).stiffness


@cached_per_case
def _splines_of_case(case: "Case") -> dict:
    return {}


def _spline(case: "Case", normal_load: float):
    """Cubic spline of k_T over the PEM table's roll grid (401 points from A to E), once per case and load."""
    from scipy.interpolate import CubicSpline  # noqa: PLC0415  (scipy only where a spline is built)

    splines = _splines_of_case(case)
    entry = splines.get(normal_load)
    if entry is None:
        with warning_scope.recorded() as caught:
            roll = np.asarray(pair_compliance_table(case.gear_pair, case.material).roll)
            spline = CubicSpline(roll, _thermal_pair_stiffness_direct(case, roll, None, normal_load))
        if len(splines) >= _SPLINES_PER_CASE:
            splines.pop(next(iter(splines)))
        entry = splines[normal_load] = (spline, warning_scope.kept(caught))
    warning_scope.raise_again(entry[1])  # the cache never swallows a warning the second time
    return entry[0]


__all__ = ["thermal_pair_stiffness_at", "thermal_stiffness"]
