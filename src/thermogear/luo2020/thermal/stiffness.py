"""Meshing thermal stiffness of a tooth pair and of single teeth (Luo & Li 2020 Eqs. 13–23).

Pure functions (one equation each) and :class:`ThermalStiffness`; a case's k_T is assembled in
:mod:`thermogear.luo2020.thermal.case_stiffness`.

Units: thermogear works in totals over the face width b (stiffness N/m, compliance m/N, load N); the paper
writes everything per unit face width. Every relation here is homogeneous in b: with k = b·k′ and F_n = b·F_n′,
the ratio of Eq. 18, k_T/k_e = F_n/(F_n + X_te·k_e·(Δ_t1 + Δ_t2)) is the same in either convention (the
expansions Δ_t do not scale with b), so the percentage changes compare directly with the paper's.

Load basis (F_n of Eqs. 13–18): ``"external"`` — the external normal load w = T1/r_b1 for every pair; or
``"pair_share"`` — the part of w this pair carries, w·k_e,pair/Σk_e of the pairs in contact (elastic load
sharing). See docs/thermal.md for why ``"external"`` is the luo2019 default.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from operator import attrgetter
from typing import Any

import numpy as np

from thermogear.errors import CaseError, ModelAssumptionWarning, ModelLimitError
from thermogear.geometry.mesh_cycle import load_share_at

#: Tolerance on roll distances when deciding that a neighbouring pair is inside [A, E] [m].
CONTACT_TOLERANCE = 1e-12


# ------------------------------------------------------------------------------------------ pure functions
def check_x_te(x_te) -> None:
    """X_te must be finite and ≥ 0 (a thermo-elastic load that opposes the restrained expansion)."""
    value = np.asarray(x_te, dtype=float)
    if not np.all(np.isfinite(value)) or np.any(value < 0.0):
        raise CaseError("thermal.x_te", value.tolist(), ">= 0 and finite",
                        "X_te scales the thermo-elastic coupling load p_te = X_te·p_t (Luo & Li Eq. 14); a negative "
                        "factor would make the hot mesh stiffer than the restrained expansion allows")


def _check_load(normal_load) -> np.ndarray:
    load = np.asarray(normal_load, dtype=float)
    if not np.all(np.isfinite(load)) or np.any(load <= 0.0):
        raise CaseError("normal_load", load.tolist() if load.ndim else float(load), "> 0",
                        "the thermal stiffness s_T = F_n/Δ_te (Eq. 7) needs a positive normal load")
    return load


def equivalent_thermal_load(elastic_stiffness, expansion_1, expansion_2):
    """Equivalent thermal load of fully restrained expansion p_t = k_e (Δ_t1 + Δ_t2) [N] (Luo & Li Eq. 13)."""
    return np.asarray(elastic_stiffness) * (np.asarray(expansion_1) + np.asarray(expansion_2))


def thermal_stiffness_of_pair(normal_load, elastic_stiffness, expansion_sum, x_te):
    """Pair thermal stiffness k_T = F_n k_e / (F_n + X_te k_e (Δ_t1 + Δ_t2)) [N/m] (Luo & Li Eq. 17).

    ``normal_load`` F_n [N], ``elastic_stiffness`` k_e [N/m], ``expansion_sum`` Δ_t1 + Δ_t2 [m], ``x_te`` [–].
    """
    check_x_te(x_te)
    load = _check_load(normal_load)
    stiffness = np.asarray(elastic_stiffness, dtype=float)
    # Same as F k/(F + X k ΣΔ), written so that X_te = 0 returns k_e bit for bit.
    return stiffness / (1.0 + x_te * stiffness * np.asarray(expansion_sum, dtype=float) / load)


def thermal_stiffness_of_tooth(normal_load, tooth_stiffness, elastic_stiffness, expansion_sum, own_expansion, x_te):
    """Single-tooth thermal stiffness k_Ti = F_n k_ei / (F_n + (1 + X_te) k_e (Δ_t1 + Δ_t2) − k_ei Δ_ti) [N/m]
    (Luo & Li Eq. 16). ``tooth_stiffness`` k_ei [N/m] includes this tooth's share of the Hertz compliance so that
    1/k_e = 1/k_e1 + 1/k_e2 (docs/derivations.md: only then is Eq. 17 the series sum of Eq. 16)."""
    check_x_te(x_te)
    load = _check_load(normal_load)
    tooth = np.asarray(tooth_stiffness, dtype=float)
    return tooth / (1.0 + ((1.0 + x_te) * np.asarray(elastic_stiffness) * np.asarray(expansion_sum)
                           - tooth * np.asarray(own_expansion)) / load)


@dataclass(frozen=True)
class ThermalPairStiffness:
    """Compliances of a pair and its two teeth with heat (Luo & Li Eqs. 20–23), all [m/N] (totals)."""

    elastic_compliance: np.ndarray  # δ = δ1 + δ2
    elastic_pinion_compliance: np.ndarray  # δ1 (incl. half the Hertz compliance)
    elastic_wheel_compliance: np.ndarray  # δ2
    compliance: np.ndarray  # δ_T = δ + X_te δ_Tp (Eq. 21)
    pinion_compliance: np.ndarray  # δ_T1 (Eq. 23)
    wheel_compliance: np.ndarray  # δ_T2 (Eq. 23)
    expansion_compliance: np.ndarray  # δ_Tp = (Δ_t1 + Δ_t2)/F_n (Eq. 20)
    equivalent_thermal_load: np.ndarray  # p_t (Eq. 13) [N]

    @property
    def stiffness(self) -> np.ndarray:
        """k_T = 1/δ_T [N/m] (Eq. 22)."""
        return 1.0 / self.compliance

    @property
    def elastic_stiffness(self) -> np.ndarray:
        """k_e = 1/δ [N/m]."""
        return 1.0 / self.elastic_compliance

    @property
    def pinion_stiffness(self) -> np.ndarray:
        """k_T1 = 1/δ_T1 [N/m] (Eq. 23); infinite where δ_T1 = 0."""
        with np.errstate(divide="ignore"):
            return 1.0 / self.pinion_compliance

    @property
    def wheel_stiffness(self) -> np.ndarray:
        """k_T2 = 1/δ_T2 [N/m] (Eq. 23)."""
        with np.errstate(divide="ignore"):
            return 1.0 / self.wheel_compliance

    def __getitem__(self, name: str) -> np.ndarray:
        """Dictionary-style access by the paper's symbols: k_T, k_T1, k_T2, δ_T, δ_T1, δ_T2, δ_Tp."""
        symbols = {"k_T": "stiffness", "k_T1": "pinion_stiffness", "k_T2": "wheel_stiffness",
                   "δ_T": "compliance", "δ_T1": "pinion_compliance", "δ_T2": "wheel_compliance",
                   "δ_Tp": "expansion_compliance", "p_t": "equivalent_thermal_load"}
        return getattr(self, symbols.get(name, name))


def thermal_pair_stiffness(elastic_compliance_1, elastic_compliance_2, expansion_1, expansion_2, normal_load,
                           x_te, elastic_compliance=None) -> ThermalPairStiffness:
    """Pair and single-tooth thermal compliance (Luo & Li 2020 Eqs. 13–23), in compliance form:

        δ = δ1 + δ2,  δ_Tp = (Δ_t1 + Δ_t2)/F_n,  δ_Tpi = Δ_ti/F_n                          (Eq. 20, 23)
        δ_T = δ + X_te δ_Tp  ⇔  k_T = F_n k_e/(F_n + X_te k_e (Δ_t1 + Δ_t2))                 (Eqs. 21–22 = 17)
        δ_Ti = δ_i + (δ_i/δ)(1 + X_te) δ_Tp − δ_Tpi  ⇔  Eq. 16;  δ_T1 + δ_T2 = δ_T

    ``elastic_compliance_1/2`` δ1, δ2 [m/N] (each tooth with half the Hertz compliance, δ1 + δ2 = 1/k_e);
    ``expansion_1/2`` Δ_t1, Δ_t2 [m] (positive = interference); ``normal_load`` F_n [N]; ``x_te`` [–].
    ``elastic_compliance``: the pair's δ as computed by the elastic model, if at hand (equal to δ1 + δ2 up to
    rounding; passing it makes X_te = 0 return that model's k_e bit for bit). Arrays broadcast. Warns (ModelAssumptionWarning) where a single-tooth compliance is ≤ 0 (the expansion of
    that flank exceeds its elastic share: Eq. 23 then has no physical single-tooth meaning).
    """
    check_x_te(x_te)
    load = _check_load(normal_load)
    pinion = np.asarray(elastic_compliance_1, dtype=float)
    wheel = np.asarray(elastic_compliance_2, dtype=float)
    if np.any(~np.isfinite(pinion) | ~np.isfinite(wheel)) or np.any(pinion <= 0.0) or np.any(wheel <= 0.0):
        raise CaseError("elastic_compliance", None, "> 0 and finite", "tooth compliances must be positive")
    expansion_1 = np.asarray(expansion_1, dtype=float)
    expansion_2 = np.asarray(expansion_2, dtype=float)
    total = pinion + wheel if elastic_compliance is None else np.asarray(elastic_compliance, dtype=float)
    if elastic_compliance is not None and not np.allclose(total, pinion + wheel, rtol=1e-12, atol=0.0):
        raise ValueError("thermal_pair_stiffness: elastic_compliance differs from δ1 + δ2")
    expansion_compliance = (expansion_1 + expansion_2) / load
    compliance = total + x_te * expansion_compliance
    if np.any(compliance <= 0.0):
        raise ModelLimitError("thermal pair compliance δ_T = δ + X_te·δ_Tp ≤ 0: the flanks contract (Δ_t1 + Δ_t2 < 0) "
                              "more than the elastic compliance allows; the model needs heating above the reference")
    pinion_thermal = pinion + (pinion / total) * (1.0 + x_te) * expansion_compliance - expansion_1 / load
    wheel_thermal = wheel + (wheel / total) * (1.0 + x_te) * expansion_compliance - expansion_2 / load
    if np.any(pinion_thermal <= 0.0) or np.any(wheel_thermal <= 0.0):
        warnings.warn("a single-tooth thermal compliance δ_Ti (Luo & Li Eq. 23) is ≤ 0 somewhere: that flank's "
                      "expansion exceeds its elastic deflection share; k_Ti there is not a physical stiffness",
                      ModelAssumptionWarning, stacklevel=2)
    return ThermalPairStiffness(
        elastic_compliance=total, elastic_pinion_compliance=pinion * np.ones_like(total),
        elastic_wheel_compliance=wheel * np.ones_like(total), compliance=compliance,
        pinion_compliance=pinion_thermal, wheel_compliance=wheel_thermal,
        expansion_compliance=expansion_compliance,
        equivalent_thermal_load=equivalent_thermal_load(1.0 / total, expansion_1, expansion_2))


def pair_share_normal_load(external_load, roll, stiffness_at, path_start, path_end, base_pitch):
    """Normal load F_n [N] of the pair at roll distance ``roll`` [m] when the pairs in contact share the external
    load ``external_load`` [N] in proportion to their elastic stiffness (pairs in parallel, equal deflection):
    F_n = w·k_e(roll)/Σ_j k_e(roll + j·p_b), over the pairs j with roll + j·p_b in [A, E]
    (:func:`thermogear.geometry.mesh_cycle.load_share_at`). ``stiffness_at(roll) -> k_e`` [N/m] along the path."""
    share, _ = load_share_at(roll, stiffness_at, path_start, path_end, base_pitch)
    return external_load * share


# --------------------------------------------------------------------------------------------- component
@dataclass(frozen=True)
class ThermalStiffness:
    """Thermal stiffness of one tooth pair along its path (totals over the face width).

    ``elastic`` is the elastic PairCompliance at ``roll``; ``expansion_pinion/wheel`` Δ_t1, Δ_t2 [m];
    ``normal_load`` F_n used in Eqs. 13–18 per position [N] (``load_basis``); ``x_te`` with ``x_te_source``.
    """

    roll: np.ndarray  # [m] from T1
    gamma: np.ndarray  # [–]
    elastic: Any  # PairCompliance
    expansion_pinion: np.ndarray  # Δ_t1 [m]
    expansion_wheel: np.ndarray  # Δ_t2 [m]
    x_te: float
    x_te_source: str
    load_basis: str
    normal_load: np.ndarray  # [N]
    temperature: Any = None  # TemperatureField the expansions came from
    result: ThermalPairStiffness = field(init=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "result", thermal_pair_stiffness(
            self.elastic.pinion_total, self.elastic.wheel_total, self.expansion_pinion, self.expansion_wheel,
            self.normal_load, self.x_te, elastic_compliance=self.elastic.total))

    # the thermal pair stiffness of Eqs. 21–23 computed in __post_init__
    stiffness = property(attrgetter("result.stiffness"), doc="k_T [N/m] (Eq. 22).")
    compliance = property(attrgetter("result.compliance"), doc="δ_T [m/N] (Eq. 21).")
    pinion_compliance = property(attrgetter("result.pinion_compliance"), doc="δ_T1 of the driving tooth [m/N] (Eq. 23).")
    wheel_compliance = property(attrgetter("result.wheel_compliance"), doc="δ_T2 of the driven tooth [m/N] (Eq. 23).")
    elastic_stiffness = property(attrgetter("result.elastic_stiffness"), doc="k_e [N/m].")
    elastic_compliance = property(attrgetter("result.elastic_compliance"), doc="δ = δ1 + δ2 [m/N].")

    @property
    def drop_percent(self) -> np.ndarray:
        """Stiffness drop (k_e − k_T)/k_e·100 [%] (positive = softer with heat)."""
        return 100.0 * (1.0 - self.stiffness / self.elastic_stiffness)

    @property
    def pinion_compliance_change_percent(self) -> np.ndarray:
        """(δ_T1 − δ1)/δ1·100 [%]."""
        return 100.0 * (self.pinion_compliance / self.result.elastic_pinion_compliance - 1.0)

    @property
    def wheel_compliance_change_percent(self) -> np.ndarray:
        """(δ_T2 − δ2)/δ2·100 [%]."""
        return 100.0 * (self.wheel_compliance / self.result.elastic_wheel_compliance - 1.0)
