"""The paper's meshing thermal stiffness k_T of a case (Luo & Li (2020) Eqs. 8–23): elastic compliances from the
cached PEM table, flank expansions of the case's temperature field, X_te given / calibrated / from a provider,
and the normal load of Eqs. 13–18 as an argument.

:func:`paper_thermal_model` resolves a case into a :class:`PaperThermalModel`: the small inputs (gear pair,
material, ``[thermal]`` section, operating load), the temperature field and the X_te provider. The model answers
everything else without the case. With the external load basis k_T is a smooth function of the roll distance for a
given load: it is tabulated once per case and load on the PEM table's roll grid and interpolated by a cubic spline,
like k_e, so every operating point and sweep at that load reuses it. What is computed once per case (the splines,
the case's own X_te) lives in a memo kept per case that holds no reference to the case, so a case is freed with
its memo when nothing else holds it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from thermogear import warning_scope
from thermogear.case import cached_per_case
from thermogear.stiffness.potential_energy import pair_compliance
from thermogear.stiffness.table import pair_compliance_table, tooth_compliance_at
from thermogear.luo2020.thermal.calibration import Calibration, calibrate, section_x_te
from thermogear.luo2020.thermal.case_inputs import PaperThermalInputs, load_basis_of
from thermogear.luo2020.thermal.stiffness import (CONTACT_TOLERANCE, ThermalStiffness, check_x_te, thermal_pair_stiffness)
from thermogear.temperature.source import TemperatureField

if TYPE_CHECKING:
    from thermogear.geometry import GearPair
    from thermogear.materials import Material
    from thermogear.schema.thermal import ThermalSection

#: Splines kept per case (one per distinct normal load) before the oldest is dropped.
SPLINES_PER_CASE = 64


@dataclass(frozen=True, eq=False)
class PaperThermalModel:
    """The paper's k_T of one case, resolved: its inputs, its ``[thermal]`` section, its temperature field (asked
    for when first needed, ``field_of()``), its X_te provider (``provided_x_te()``, asked only for a provider
    source such as ``"fem"``) and ``memo``, what is computed once per case (splines by load, the own X_te)."""

    inputs: PaperThermalInputs
    section: "ThermalSection"
    field_of: Callable[[], TemperatureField]
    provided_x_te: Callable[[], float]
    memo: dict = field(default_factory=dict, repr=False)  # "splines": {load: (spline, warnings)}, "own_x_te"

    @property
    def temperature(self) -> TemperatureField:
        return self.field_of()

    # ---------------------------------------------------------------------------------------------- X_te
    def calibrate_x_te(self, drop_percent: float | None = None, point: str | None = None,
                       load_basis: str | None = None, temperature: TemperatureField | None = None,
                       normal_load: float | None = None) -> Calibration:
        """The X_te that gives ``drop_percent`` at path point ``point`` (A–E) under the external normal load
        ``normal_load`` [N] (defaults from ``[thermal]`` and the operating point; :func:`calibrate`)."""
        return calibrate(self.inputs, self.section, self.temperature if temperature is None else temperature,
                         drop_percent, point, load_basis, normal_load)

    def resolve_x_te(self, load_basis: str | None = None, temperature: TemperatureField | None = None,
                     normal_load: float | None = None) -> tuple[float, str]:
        """(X_te, source label) from ``[thermal]`` (:func:`~thermogear.luo2020.thermal.calibration.section_x_te`). A
        calibration is solved at ``normal_load`` [N] (default: the operating point's), so a case asked for another
        load keeps its calibration target, exactly as the same case file at that load would. With the model's own
        settings (no option given) the answer is computed once."""
        if load_basis is None and temperature is None and (normal_load is None
                                                           or normal_load == self.inputs.normal_load):
            entry = self.memo.get("own_x_te")
            if entry is None:
                with warning_scope.recorded() as caught:
                    value = section_x_te(self.section, self.inputs, self.field_of, self.provided_x_te)
                entry = self.memo["own_x_te"] = (value, warning_scope.kept(caught))
            warning_scope.raise_again(entry[1])  # the cache never swallows a warning the second time
            return entry[0]
        field_of = self.field_of if temperature is None else (lambda: temperature)
        return section_x_te(self.section, self.inputs, field_of, self.provided_x_te, load_basis, normal_load)

    # ------------------------------------------------------------------------------------------ stiffness
    def thermal_stiffness(self, roll, x_te: float | None = None, load_basis: str | None = None,
                          temperature: TemperatureField | None = None, normal_load: float | None = None
                          ) -> ThermalStiffness:
        """Thermal stiffness of the tooth pair at roll distances T1K [m] (Luo & Li Eqs. 8–23).

        X_te is resolved from ``[thermal]`` (given / calibrated / provider) unless ``x_te`` is passed;
        ``load_basis`` overrides ``[thermal].load_basis``; ``normal_load`` [N] the external load (default: the
        operating point's)."""
        roll = np.atleast_1d(np.asarray(roll, dtype=float))
        basis = self.section.load_basis if load_basis is None else load_basis
        temperature = self.temperature if temperature is None else temperature
        if x_te is None:
            x_te, source = self.resolve_x_te(load_basis=basis, temperature=temperature)
        else:
            check_x_te(x_te)
            source = "given (argument)"
        pair = self.inputs.gear_pair
        elastic = pair_compliance(pair, self.inputs.material, roll)
        expansion_pinion, expansion_wheel = self.inputs.expansion(roll, temperature)
        load = self.inputs.normal_load_at(roll, basis, external_load=normal_load)
        return ThermalStiffness(roll=roll, gamma=np.asarray(pair.gamma(roll)), elastic=elastic,
                                expansion_pinion=np.asarray(expansion_pinion),
                                expansion_wheel=np.asarray(expansion_wheel), x_te=float(x_te), x_te_source=source,
                                load_basis=basis, normal_load=load, temperature=temperature)

    def pair_stiffness_at(self, roll, x_te: float | None = None, normal_load: float | None = None) -> np.ndarray:
        """k_T [N/m] (total over the face width) of one tooth pair at roll distances T1K [m] under the external
        normal load ``normal_load`` [N] (default: the operating point's): what the dynamics use, summed over the
        pairs in contact. Zero outside the path [A, E]. Tabulated per load with the model's own X_te and the
        external load basis; evaluated directly otherwise."""
        roll = np.asarray(roll, dtype=float)
        points = self.inputs.gear_pair.path_points
        inside = (roll >= points["A"] - CONTACT_TOLERANCE) & (roll <= points["E"] + CONTACT_TOLERANCE)
        result = np.zeros(roll.shape)
        load = self.inputs.normal_load if normal_load is None else float(normal_load)
        if np.any(inside):
            inner = np.clip(roll[inside], points["A"], points["E"])
            if x_te is None and not load_basis_of(self.section.load_basis).pair_share:
                result[inside] = self.spline(load)(inner)
            else:
                result[inside] = self.pair_stiffness_direct(inner, x_te, load)
        return result if result.ndim else float(result)

    def pair_stiffness_direct(self, roll: np.ndarray, x_te: float | None, normal_load: float) -> np.ndarray:
        """k_T [N/m] at roll distances on [A, E] from Eqs. 8–23 directly (elastic compliances from the PEM
        table)."""
        temperature = self.temperature
        if x_te is None:
            x_te, _ = self.resolve_x_te(normal_load=normal_load)
        check_x_te(x_te)
        pinion, wheel = tooth_compliance_at(self.inputs.gear_pair, self.inputs.material, roll)
        expansion_pinion, expansion_wheel = self.inputs.expansion(roll, temperature)
        load = self.inputs.normal_load_at(roll, external_load=normal_load)
        return thermal_pair_stiffness(pinion, wheel, expansion_pinion, expansion_wheel, load, x_te).stiffness

    def spline(self, normal_load: float):
        """Cubic spline of k_T over the PEM table's roll grid (401 points from A to E), once per load."""
        from scipy.interpolate import CubicSpline  # noqa: PLC0415  (scipy only where a spline is built)

        splines = self.memo.setdefault("splines", {})
        entry = splines.get(normal_load)
        if entry is None:
            with warning_scope.recorded() as caught:
                roll = np.asarray(pair_compliance_table(self.inputs.gear_pair, self.inputs.material).roll)
                spline = CubicSpline(roll, self.pair_stiffness_direct(roll, None, normal_load))
            if len(splines) >= SPLINES_PER_CASE:
                splines.pop(next(iter(splines)))
            entry = splines[normal_load] = (spline, warning_scope.kept(caught))
        warning_scope.raise_again(entry[1])  # the cache never swallows a warning the second time
        return entry[0]


# ------------------------------------------------------------------------------------ the case's resolver
@cached_per_case
def paper_thermal_memo() -> dict:
    """The memo of a case's model (splines by load, the case's own X_te): one per case, dropped with the case
    (:func:`thermogear.case.cached_per_case`, the piece ``paper_thermal_memo``). Per case, deliberately: what the
    memo holds depends on the temperature field and the X_te provider, which are functions of the whole case (a
    provider such as the FE model reads more than the ``[thermal]`` section), so no smaller key determines it."""
    return {}


def paper_thermal_model(gear_pair: "GearPair", material: "Material", thermal: "ThermalSection", normal_load: float,
                        temperature_field_of: Callable[[], TemperatureField], provided_x_te_of: Callable[[], float],
                        paper_thermal_memo: dict) -> PaperThermalModel:
    """The paper's k_T model of a case, from the pieces it reads (:mod:`thermogear.case.pieces`; called with the
    case as ``call_with_pieces(paper_thermal_model, case)``): the gear pair, material, ``[thermal]`` section and
    normal load [N], the temperature field and the provider's X_te, each asked for when first needed, and the
    case's memo of what is computed once per case (a model is cheap to build, its memo is shared)."""
    inputs = PaperThermalInputs(gear_pair=gear_pair, material=material, expansion_model=thermal.expansion_model,
                                load_basis=thermal.load_basis, normal_load=normal_load)
    return PaperThermalModel(inputs=inputs, section=thermal, field_of=temperature_field_of,
                             provided_x_te=provided_x_te_of, memo=paper_thermal_memo)


__all__ = ["PaperThermalModel", "paper_thermal_memo", "paper_thermal_model"]
