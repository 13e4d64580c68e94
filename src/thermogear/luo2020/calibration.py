"""The thermal-load correction factor X_te (Luo & Li 2020 Eq. 14): given, calibrated, or from the FE model.

The paper obtains X_te from a finite-element thermo-elastic analysis and does not report it. ``"calibrated"``
solves Eq. 18 for the X_te that gives a target stiffness drop at a chosen point of the path. Eq. 18 is linear in
X_te, so the solution is closed form:

    k_T/k_e = F_n/(F_n + X_te k_e ΣΔ_t) = 1 − d   ⇒   X_te = (1/(1 − d) − 1)·F_n/(k_e ΣΔ_t)

It is a calibration to a published number and is always reported as such (the source label says so).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from thermogear.case import cached_per_case
from thermogear.composition import X_TE_PROVIDERS, builtin
from thermogear.errors import CaseError, ThermogearError
from thermogear.stiffness.potential_energy import pair_compliance
from thermogear.luo2020.case_inputs import PaperThermalInputs
from thermogear.luo2020.stiffness import check_x_te
from thermogear.temperature_source import TemperatureField, temperature_field_from_case

if TYPE_CHECKING:
    from thermogear.case import Case

XteProvider = Callable[["Case"], float]
_PROVIDERS: dict[str, XteProvider] = {}


def register_x_te_provider(name: str, provider: XteProvider) -> None:
    """Plug in an X_te source selectable as ``[thermal].x_te_source = name`` (the FE thermo-elastic analysis
    registers ``"fem"``). The provider takes the Case and returns X_te ≥ 0."""
    if not callable(provider):
        raise TypeError("provider must be callable: provider(case) -> float")
    _PROVIDERS[name] = provider


def x_te_for_drop(drop_percent, normal_load, elastic_stiffness, expansion_sum):
    """X_te [–] that gives a stiffness drop (k_e − k_T)/k_e = ``drop_percent``/100 (Luo & Li Eq. 18 solved for
    X_te). ``normal_load`` F_n [N], ``elastic_stiffness`` k_e [N/m], ``expansion_sum`` Δ_t1 + Δ_t2 [m]."""
    drop = np.asarray(drop_percent, dtype=float) / 100.0
    if np.any(drop <= 0.0) or np.any(drop >= 1.0):
        raise CaseError("thermal.calibration_drop_percent", float(np.max(drop_percent)), "(0, 100)",
                        "a stiffness drop is a fraction of the elastic stiffness")
    expansion_sum = np.asarray(expansion_sum, dtype=float)
    if np.any(expansion_sum <= 0.0):
        raise CaseError("temperature", float(np.min(expansion_sum)), "temperatures that expand the flanks "
                        "(Δ_t1 + Δ_t2 > 0 at the calibration point)",
                        "with no thermal interference at the calibration point no X_te can produce a stiffness drop")
    return (1.0 / (1.0 - drop) - 1.0) * np.asarray(normal_load) / (np.asarray(elastic_stiffness) * expansion_sum)


@dataclass(frozen=True)
class Calibration:
    """An X_te calibration: the value, where and to what it was fitted."""

    x_te: float
    point: str
    gamma: float
    drop_percent: float
    load_basis: str

    @property
    def label(self) -> str:
        return (f"calibrated: X_te={self.x_te:.5g} gives {self.drop_percent:g} % drop at {self.point} "
                f"(Γ={self.gamma:.4f}, F_n basis '{self.load_basis}')")


def calibrate_x_te(case: "Case", drop_percent: float | None = None, point: str | None = None,
                   load_basis: str | None = None, temperature: TemperatureField | None = None,
                   normal_load: float | None = None) -> Calibration:
    """Solve for the X_te that gives ``drop_percent`` at path point ``point`` (A–E) for a case under the external
    normal load ``normal_load`` [N] (defaults from ``[thermal]`` and the case's operating point)."""
    section = case.thermal
    drop_percent = section.calibration_drop_percent if drop_percent is None else drop_percent
    if drop_percent is None:
        raise CaseError("thermal.calibration_drop_percent", None, "(0, 100)",
                        "x_te_source = 'calibrated' needs the target stiffness drop")
    point = section.calibration_point if point is None else point
    points = case.gear_pair.path_points
    if point not in points:
        raise CaseError("thermal.calibration_point", point, "one of A, B, C, D, E", "unknown path point")
    basis = section.load_basis if load_basis is None else load_basis
    roll = np.array([points[point]])
    elastic = pair_compliance(case.gear_pair, case.material, roll)
    stiffness = np.asarray(elastic.stiffness, dtype=float)
    inputs = PaperThermalInputs.from_case(case)
    temperature = temperature_field_from_case(case) if temperature is None else temperature
    expansion_pinion, expansion_wheel = inputs.expansion(roll, temperature)
    load = inputs.normal_load_at(roll, basis, external_load=normal_load)
    x_te = float(np.ravel(x_te_for_drop(drop_percent, load, stiffness, expansion_pinion + expansion_wheel))[0])
    return Calibration(x_te=x_te, point=point, gamma=float(case.gear_pair.gamma(points[point])),
                       drop_percent=float(drop_percent), load_basis=basis)


def resolve_x_te(case: "Case", load_basis: str | None = None, temperature: TemperatureField | None = None,
                 normal_load: float | None = None) -> tuple[float, str]:
    """(X_te, source label) from ``[thermal]``: ``"given"``, ``"calibrated: X_te=… gives … % drop at …"`` or
    ``"fem"``. Raises CaseError for missing or contradictory keys, ThermogearError when the FE model is absent.
    A calibration is solved at ``normal_load`` [N] (default: the case's), so a case asked for another load keeps
    its calibration target, exactly as the same case file at that load would. With the case's own settings (no
    option given) the answer is computed once per case."""
    if load_basis is None and temperature is None and (normal_load is None or normal_load == case.normal_load):
        return _resolve_x_te_of_case(case)
    return _resolve_x_te(case, load_basis, temperature, normal_load)


@cached_per_case
def _resolve_x_te_of_case(case: "Case") -> tuple[float, str]:
    return _resolve_x_te(case, None, None, None)


def _resolve_x_te(case: "Case", load_basis: str | None, temperature: TemperatureField | None,
                  normal_load: float | None) -> tuple[float, str]:
    section = case.thermal
    if section.x_te_source == "given":
        if section.x_te is None:
            raise CaseError("thermal.x_te", None, ">= 0", "x_te_source = 'given' needs thermal.x_te")
        check_x_te(section.x_te)
        return float(section.x_te), "given"
    if section.x_te_source == "calibrated":
        if section.x_te is not None:
            raise CaseError("thermal.x_te", section.x_te, "absent with x_te_source = 'calibrated'",
                            "X_te is either given or calibrated; remove one of them")
        temperature = temperature_field_from_case(case) if temperature is None else temperature
        calibration = calibrate_x_te(case, load_basis=load_basis, temperature=temperature, normal_load=normal_load)
        check_x_te(calibration.x_te)
        return calibration.x_te, calibration.label
    provider = _PROVIDERS.get(section.x_te_source) or builtin(X_TE_PROVIDERS, section.x_te_source)
    if provider is None:
        raise ThermogearError(f"thermal.x_te_source = '{section.x_te_source}': the finite-element thermo-elastic "
                              "analysis is not registered (its module is not installed); use "
                              "'given' or 'calibrated'")
    value = float(provider(case))
    check_x_te(value)
    return value, section.x_te_source
