"""What the paper's thermal stiffness of a case needs besides the elastic compliances, resolved once from the case:
the gear pair and material, the expansion model of the flank expansions Δ_t1, Δ_t2 (Luo & Li (2020) Eqs. 8–12),
and the normal load F_n of Eqs. 13–18 (the external load, or the pair's share of it)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.registry import registered
from thermogear.geometry import GearPair
from thermogear.materials import Material
from thermogear.stiffness.table import pair_stiffness_at
from thermogear.luo2020.thermal.expansion import pair_flank_expansion
from thermogear.luo2020.thermal.stiffness import pair_share_normal_load
from thermogear.temperature.source import TemperatureField


@dataclass(frozen=True, eq=False)
class PaperThermalInputs:
    """The inputs of the paper's k_T of one case: its gear pair and material, ``[thermal] expansion_model`` and
    ``load_basis``, and the external normal load of its operating point [N] (total over the face width)."""

    gear_pair: GearPair
    material: Material
    expansion_model: str
    load_basis: str
    normal_load: float

    def expansion(self, roll, temperature: TemperatureField):
        """(Δ_t1, Δ_t2) [m] of the pair at roll distances T1K [m] in a temperature field (Eqs. 8–12)."""
        pair = self.gear_pair
        gamma = pair.gamma(roll)
        return pair_flank_expansion(
            pair, roll, temperature.rise(temperature.pinion_flank_c(gamma)),
            temperature.rise(temperature.wheel_flank_c(gamma)), self.material.thermal_expansion,
            temperature.rise(temperature.pinion_base_c), temperature.rise(temperature.pinion_bore_c),
            temperature.rise(temperature.wheel_base_c), temperature.rise(temperature.wheel_bore_c),
            self.expansion_model)

    def normal_load_at(self, roll, load_basis: str | None = None, external_load: float | None = None) -> np.ndarray:
        """F_n of Eqs. 13–18 at roll distances [m] [N]: the external normal load ``external_load`` (default: the
        case's operating point) for every pair (``"external"``) or the pair's elastic share of it
        (``"pair_share"``)."""
        basis = self.load_basis if load_basis is None else load_basis
        roll = np.atleast_1d(np.asarray(roll, dtype=float))
        external = self.normal_load if external_load is None else float(external_load)
        if not load_basis_of(basis).pair_share:
            return np.full(roll.shape, external)
        pair = self.gear_pair
        points = pair.path_points
        return pair_share_normal_load(external, roll, lambda other: pair_stiffness_at(pair, self.material, other),
                                      points["A"], points["E"], pair.base_pitch)


@dataclass(frozen=True)
class LoadBasis:
    """The load F_n of Eqs. 13–18 (``[thermal] load_basis``): ``name``, and whether each pair takes its elastic
    share of the external load (``pair_share``; else every pair the whole external load, the paper's reading, so
    k_T depends on the load alone and is tabulated per load)."""

    name: str
    pair_share: bool


#: The load bases by name: the one place the names are compared.
LOAD_BASES: dict[str, LoadBasis] = {basis.name: basis for basis in (
    LoadBasis("external", pair_share=False), LoadBasis("pair_share", pair_share=True))}


def load_basis_of(name: str) -> LoadBasis:
    """The load basis called ``name``; a CaseError naming ``thermal.load_basis`` for any other."""
    return registered(LOAD_BASES, name, "thermal.load_basis", "unknown load basis", "'external' or 'pair_share'")


__all__ = ["LOAD_BASES", "LoadBasis", "PaperThermalInputs", "load_basis_of"]
