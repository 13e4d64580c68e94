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

from thermogear.composition import X_TE_PROVIDERS, builtin
from thermogear.errors import CaseError, ThermogearError
from thermogear.stiffness.potential_energy import pair_compliance
from thermogear.luo2020.thermal.case_inputs import PaperThermalInputs
from thermogear.luo2020.thermal.stiffness import check_x_te
from thermogear.temperature.source import TemperatureField
from thermogear.choices.thermal_models import x_te_source

if TYPE_CHECKING:
    from thermogear.case import Case
    from thermogear.schema.thermal import ThermalSection

XteProvider = Callable[..., float]  # its parameters name pieces of the case (thermogear.case.pieces)
_PROVIDERS: dict[str, XteProvider] = {}


def register_x_te_provider(name: str, provider: XteProvider) -> None:
    """Plug in an X_te source selectable as ``[thermal].x_te_source = name`` (the FE thermo-elastic analysis
    registers ``"fem"``). The provider receives the pieces of the case its parameters name
    (:mod:`thermogear.case.pieces`; ``provider(case)``: the whole case) and returns X_te ≥ 0."""
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


def calibrate(inputs: PaperThermalInputs, section: "ThermalSection", temperature: TemperatureField,
              drop_percent: float | None = None, point: str | None = None, load_basis: str | None = None,
              normal_load: float | None = None) -> Calibration:
    """Solve for the X_te that gives ``drop_percent`` at path point ``point`` (A–E) of the pair of ``inputs`` in the
    temperature field ``temperature`` under the external normal load ``normal_load`` [N] (defaults from the
    ``[thermal]`` section and the operating point of ``inputs``)."""
    drop_percent = section.calibration_drop_percent if drop_percent is None else drop_percent
    if drop_percent is None:
        raise CaseError("thermal.calibration_drop_percent", None, "(0, 100)",
                        "x_te_source = 'calibrated' needs the target stiffness drop")
    point = section.calibration_point if point is None else point
    pair = inputs.gear_pair
    points = pair.path_points
    if point not in points:
        raise CaseError("thermal.calibration_point", point, "one of A, B, C, D, E", "unknown path point")
    basis = section.load_basis if load_basis is None else load_basis
    roll = np.array([points[point]])
    elastic = pair_compliance(pair, inputs.material, roll)
    stiffness = np.asarray(elastic.stiffness, dtype=float)
    expansion_pinion, expansion_wheel = inputs.expansion(roll, temperature)
    load = inputs.normal_load_at(roll, basis, external_load=normal_load)
    x_te = float(np.ravel(x_te_for_drop(drop_percent, load, stiffness, expansion_pinion + expansion_wheel))[0])
    return Calibration(x_te=x_te, point=point, gamma=float(pair.gamma(points[point])),
                       drop_percent=float(drop_percent), load_basis=basis)


def x_te_provider(name: str) -> XteProvider:
    """The X_te provider registered (or built in) under ``name`` (``[thermal].x_te_source``); ThermogearError when
    none is (its module is not installed)."""
    provider = _PROVIDERS.get(name) or builtin(X_TE_PROVIDERS, name)
    if provider is None:
        raise ThermogearError(f"thermal.x_te_source = '{name}': the finite-element thermo-elastic "
                              "analysis is not registered (its module is not installed); use "
                              "'given' or 'calibrated'")
    return provider


def chosen_x_te_provider(thermal: "ThermalSection") -> XteProvider:
    """The X_te provider a ``[thermal]`` section's ``x_te_source`` names: the chooser of the piece ``provided_x_te``
    (:data:`thermogear.composition.CHOSEN_PIECES`)."""
    return x_te_provider(thermal.x_te_source)


def section_x_te(section: "ThermalSection", inputs: PaperThermalInputs, temperature: Callable[[], TemperatureField],
                 provided: Callable[[], float], load_basis: str | None = None,
                 normal_load: float | None = None) -> tuple[float, str]:
    """(X_te, source label) from a ``[thermal]`` section: ``"given"``, ``"calibrated: X_te=… gives … % drop at …"``
    (solved by :func:`calibrate` in the field ``temperature()`` at ``normal_load`` [N], default the operating
    point's) or the provider's value ``provided()``. Raises CaseError for missing or contradictory keys."""
    source = x_te_source(section.x_te_source)
    if source.given:
        if section.x_te is None:
            raise CaseError("thermal.x_te", None, ">= 0", "x_te_source = 'given' needs thermal.x_te")
        check_x_te(section.x_te)
        return float(section.x_te), "given"
    if source.calibrated:
        if section.x_te is not None:
            raise CaseError("thermal.x_te", section.x_te, "absent with x_te_source = 'calibrated'",
                            "X_te is either given or calibrated; remove one of them")
        calibration = calibrate(inputs, section, temperature(), load_basis=load_basis, normal_load=normal_load)
        check_x_te(calibration.x_te)
        return calibration.x_te, calibration.label
    value = float(provided())
    check_x_te(value)
    return value, section.x_te_source
