"""What the paper's thermal stiffness of a case needs besides the elastic compliances: the flank expansions
Δ_t1, Δ_t2 of the case's temperature field (Luo & Li (2020) Eqs. 8–12) and the normal load F_n of Eqs. 13–18
(the external load, or the pair's share of it)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from thermogear.errors import CaseError
from thermogear.stiffness.table import pair_stiffness_at
from thermogear.thermal.expansion import pair_flank_expansion
from thermogear.thermal.stiffness import pair_share_normal_load
from thermogear.thermal.temperature import TemperatureField, temperature_field_from_case

if TYPE_CHECKING:
    from thermogear.case import Case


def expansion_for_case(case: "Case", roll, temperature: TemperatureField | None = None):
    """(Δ_t1, Δ_t2) [m] of a case's pair at roll distances T1K [m] from its temperature field (Eqs. 8–12)."""
    temperature = temperature_field_from_case(case) if temperature is None else temperature
    pair = case.gear_pair
    gamma = pair.gamma(roll)
    return pair_flank_expansion(
        pair, roll, temperature.rise(temperature.pinion_flank_c(gamma)),
        temperature.rise(temperature.wheel_flank_c(gamma)), case.material.thermal_expansion,
        temperature.rise(temperature.pinion_base_c), temperature.rise(temperature.pinion_bore_c),
        temperature.rise(temperature.wheel_base_c), temperature.rise(temperature.wheel_bore_c),
        case.thermal.expansion_model)


def normal_load_for_case(case: "Case", roll, load_basis: str | None = None, external_load: float | None = None
                         ) -> np.ndarray:
    """F_n of Eqs. 13–18 at roll distances [m] [N]: the external normal load ``external_load`` (default: the
    case's operating point) for every pair (``"external"``) or the pair's elastic share of it (``"pair_share"``)."""
    basis = case.thermal.load_basis if load_basis is None else load_basis
    roll = np.atleast_1d(np.asarray(roll, dtype=float))
    external = case.normal_load if external_load is None else float(external_load)
    if basis == "external":
        return np.full(roll.shape, external)
    if basis != "pair_share":
        raise CaseError("thermal.load_basis", basis, "'external' or 'pair_share'", "unknown load basis")
    pair = case.gear_pair
    points = pair.path_points
    return pair_share_normal_load(external, roll, lambda other: pair_stiffness_at(pair, case.material, other),
                                  points["A"], points["E"], pair.base_pitch)


__all__ = ["expansion_for_case", "normal_load_for_case"]
