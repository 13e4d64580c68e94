"""The FE verification of one case (issue 7): bulk temperature of both gears, FE single-tooth compliance beside
the potential energy method, FE flank expansion beside Luo & Li Eqs. 8–12, X_te from elastic and thermo-elastic
runs, and a mesh-refinement study. :func:`stiffness_along_path` feeds Fig. 15 of the report.

X_te (the paper's procedure, §5.1: "obtained from the ratio of thermoelastic to elastic deformation and
averaged"): at each contact point the elastic run (external normal load F_n) gives the displacement u_e of the
meshing point K of each tooth and the thermo-elastic run (same load + bulk temperature rise) gives u_e + u_th.
With the paper's Eq. 21, δ_T − δ = X_te (Δ_t1 + Δ_t2)/F_n, the deformations read as the magnitudes of the
meshing-point displacements (the FE "total deformation" at the node of peak contact stress) give

    X_te(Γ) = Σ_i (|u_e,i + u_th,i| − |u_e,i|) / (Δ_t1 + Δ_t2)(Γ),      X_te = mean over the path,

with Δ_ti from Eqs. 8–12 and the FE temperature field. Also reported (``x_te_line_of_action``): the same with the
deformation taken along the line of action, −Σ_i u_th,i·n_i/(Δ_t1 + Δ_t2), which is negative: along the line of
action the heated flank moves *towards* the mate. docs/fem.md discusses why the two readings differ.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from thermogear.errors import ModelAssumptionWarning
from thermogear.fem.elasticity import plane_assumption
from thermogear.fem.tooth_elastic import (ToothDeflection, contact_point_geometry, own_roll_of, tooth_deflection,
                                          tooth_model)
from thermogear.fem.tooth_heat import ToothTemperature, tooth_temperature
from thermogear.schema.fem import FemSection

if TYPE_CHECKING:
    from thermogear.fem.inputs import FemInputs
    from thermogear.geometry import GearPair

GEARS = ("pinion", "wheel")

#: Uniform temperature rise of the expansion check [K].
UNIFORM_RISE = 50.0

#: Contact positions of the flank temperature table handed to the thermal chain.
FLANK_TABLE_POINTS = 41

#: Degree of the polynomial in Γ fitted to the FE flank temperature (as the paper fits its Fig. 3c).
FLANK_FIT_DEGREE = 6


def temperature_field_from_fem(pair: "GearPair", reference_c: float, temperatures: dict[str, ToothTemperature]):
    """TemperatureField (``source = "fem"``) from the two gears' FE temperatures of the gear pair ``pair``: the
    pinion flank table along the path fitted in Γ, the wheel flank as the pinion's plus its mean offset along the
    path (the field holds one constant offset), base-circle and bore means; ``reference_c`` the stress-free
    temperature [°C]."""
    from thermogear.temperature.source import TemperatureField  # noqa: PLC0415

    roll = pair.roll_grid(FLANK_TABLE_POINTS)
    gamma = np.asarray(pair.gamma(roll), dtype=float)
    pinion = temperatures["pinion"].flank_c(own_roll_of(pair, "pinion", roll))
    wheel = temperatures["wheel"].flank_c(own_roll_of(pair, "wheel", roll))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ModelAssumptionWarning)
        return TemperatureField.from_table(
            gamma, pinion, FLANK_FIT_DEGREE, pinion_base_c=temperatures["pinion"].base_c,
            pinion_bore_c=temperatures["pinion"].bore_c, wheel_base_c=temperatures["wheel"].base_c,
            wheel_bore_c=temperatures["wheel"].bore_c, reference_c=reference_c,
            wheel_flank_offset_c=float(np.mean(wheel - pinion)), source="fem")


@dataclass(frozen=True, eq=False)
class FemAnalysis:
    """Everything the FE verification computes for one case at one mesh refinement (SI, totals)."""

    inputs: "FemInputs"  # what the analysis read of the case
    settings: FemSection
    refinement: float
    roll: np.ndarray
    gamma: np.ndarray
    temperatures: dict
    temperature_field: object
    deflection: dict  # gear -> ToothDeflection (settings.plane)
    deflection_other_plane: dict
    thermal_displacement: dict  # gear -> (2, n) u_th at K [m] (bulk field, free gear)
    expansion_fe: dict  # gear -> Δ_t FE [m] (bulk field)
    expansion_analytical: dict  # gear -> Δ_t Eqs. 8–12 [m] (FE temperatures)
    uniform_expansion_fe: dict  # gear -> Δ_t FE for UNIFORM_RISE [m]
    uniform_expansion_analytical: dict  # gear -> Eqs. 8–12 for UNIFORM_RISE [m]
    timings: dict = field(default_factory=dict)
    checks: bool = True  # False: the other plane and the uniform-rise check were not run (their dicts are empty)

    # ------------------------------------------------------------------------------- derived quantities
    @property
    def gear_pair(self) -> "GearPair":
        return self.inputs.gear_pair

    @property
    def normal_load(self) -> float:
        return float(self.inputs.normal_load)

    @property
    def hertz(self) -> float:
        from thermogear.stiffness.potential_energy import hertz_compliance  # noqa: PLC0415

        material = self.inputs.material
        return hertz_compliance(material.youngs_modulus, material.poisson_ratio, self.gear_pair.face_width)

    @property
    def x_te_profile(self) -> np.ndarray:
        """X_te(Γ) by the magnitude reading (module docstring)."""
        load = self.normal_load / self.gear_pair.face_width
        excess = 0.0
        for gear in GEARS:
            elastic = self.deflection[gear].unit_displacement * load
            heated = elastic + self.thermal_displacement[gear]
            excess = excess + np.hypot(*heated) - np.hypot(*elastic)
        return excess / (self.expansion_analytical["pinion"] + self.expansion_analytical["wheel"])

    @property
    def x_te(self) -> float:
        return float(np.mean(self.x_te_profile))

    @property
    def x_te_line_of_action(self) -> float:
        total = self.expansion_fe["pinion"] + self.expansion_fe["wheel"]
        return float(np.mean(-total / (self.expansion_analytical["pinion"] + self.expansion_analytical["wheel"])))

    def thermal_result(self, x_te: float | None = None):
        """ThermalPairStiffness (Eqs. 13–23) with the FE tooth compliances, Eqs. 8–12 expansions of the FE field,
        the external normal load and the FE X_te."""
        from thermogear.luo2020.thermal.stiffness import thermal_pair_stiffness  # noqa: PLC0415

        half = 0.5 * self.hertz
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ModelAssumptionWarning)
            return thermal_pair_stiffness(self.deflection["pinion"].compliance + half,
                                          self.deflection["wheel"].compliance + half,
                                          self.expansion_analytical["pinion"], self.expansion_analytical["wheel"],
                                          np.full(self.roll.shape, self.normal_load),
                                          self.x_te if x_te is None else x_te)

    def flank_temperature_points(self) -> dict[str, float]:
        points = self.gear_pair.path_points
        return {name: float(self.temperatures["pinion"].flank_c(np.array([points[name]]))[0]) for name in "ACE"}

    def quantities(self) -> dict[str, np.ndarray]:
        """The reported quantities whose change under mesh refinement is checked (rises above the oil for
        temperatures)."""
        oil = self.temperatures["pinion"].oil_c
        flank = self.flank_temperature_points()
        return {
            "compliance_pinion": self.deflection["pinion"].compliance,
            "compliance_wheel": self.deflection["wheel"].compliance,
            "flank_rise": np.array([flank[name] - oil for name in "ACE"]),
            "base_rise": np.array([self.temperatures[g].base_c - oil for g in GEARS]),
            "bore_rise": np.array([self.temperatures[g].bore_c - oil for g in GEARS]),
            "expansion_fe": np.concatenate([self.expansion_fe[g] for g in GEARS]),
            "x_te": np.array([self.x_te]),
        }

    def summary(self) -> dict:
        """JSON-ready numbers (°C, %, μm, N/(mm·μm))."""
        if not self.checks:
            raise ValueError("this FE analysis ran without its checks (fem_analysis(..., checks=False)): the other "
                             "plane's compliances and the uniform-rise expansion check that the summary reports "
                             "were not computed")
        pair = self.gear_pair
        width = pair.face_width
        per_width = 1.0 / (width * 1e9)
        points = pair.path_points
        pinion, wheel = self.deflection["pinion"], self.deflection["wheel"]
        differences = np.concatenate([pinion.difference_percent, wheel.difference_percent])
        other = np.concatenate([self.deflection_other_plane[g].difference_percent for g in GEARS])
        uniform = np.concatenate([100.0 * (self.uniform_expansion_fe[g] / self.uniform_expansion_analytical[g] - 1.0)
                                  for g in GEARS])
        homogeneous = np.concatenate([
            100.0 * (self.uniform_expansion_fe[g] / (self.inputs.material.thermal_expansion * UNIFORM_RISE
                                                     * own_roll_of(pair, g, self.roll)) - 1.0)
            for g in GEARS])
        bulk = np.concatenate([100.0 * (self.expansion_fe[g] / self.expansion_analytical[g] - 1.0) for g in GEARS])
        result = self.thermal_result()
        drop = 100.0 * (1.0 - result.stiffness / result.elastic_stiffness)
        drop_at = {name: float(np.interp(points[name], self.roll, drop)) for name in "ACE"}
        temperatures = self.temperatures
        return {
            "case": self.inputs.name,
            "refinement": self.refinement,
            "plane": self.settings.plane,
            "elements": {g: self.deflection[g].elements for g in GEARS},
            "gamma": self.gamma.tolist(),
            "compliance_fe_vs_pem_percent": {
                "max_abs": float(np.max(np.abs(differences))), "mean_abs": float(np.mean(np.abs(differences))),
                "pinion": pinion.difference_percent.tolist(), "wheel": wheel.difference_percent.tolist(),
                "other_plane": {"plane": plane_assumption(self.settings.plane).other,
                                "max_abs": float(np.max(np.abs(other))), "mean_abs": float(np.mean(np.abs(other)))}},
            "tooth_stiffness_n_per_mm_um": {
                g: {"fe": (per_width / self.deflection[g].compliance).tolist(),
                    "pem": (per_width / self.deflection[g].pem).tolist()} for g in GEARS},
            "x_te": self.x_te,
            "x_te_profile": self.x_te_profile.tolist(),
            "x_te_line_of_action": self.x_te_line_of_action,
            "stiffness_drop_percent": drop_at,
            "flank_temperature_c": self.flank_temperature_points(),
            "base_temperature_c": {g: temperatures[g].base_c for g in GEARS},
            "bore_temperature_c": {g: temperatures[g].bore_c for g in GEARS},
            "oil_temperature_c": temperatures["pinion"].oil_c,
            "convection_w_per_m2_k": {g: temperatures[g].coefficients.as_dict() for g in GEARS},
            "mean_friction_coefficient": float(np.mean(temperatures["pinion"].heat_input.friction_coefficient)),
            "expansion_fe_vs_analytical_percent": {
                "max_abs": float(np.max(np.abs(uniform))), "mean_abs": float(np.mean(np.abs(uniform))),
                "uniform_rise_k": UNIFORM_RISE, "eq9_form": self.inputs.expansion_model,
                "vs_homogeneous_expansion_max_abs": float(np.max(np.abs(homogeneous))),
                "bulk_field_max_abs": float(np.max(np.abs(bulk)))},
            "expansion_um": {g: {"fe": (self.expansion_fe[g] * 1e6).tolist(),
                                 "eqs_8_12": (self.expansion_analytical[g] * 1e6).tolist()} for g in GEARS},
            "timings_s": dict(self.timings),
        }


def _expansion_analytical(pair, material, expansion_model: str, which: str, roll, field) -> np.ndarray:
    """Flank expansion of Luo & Li (2020) Eqs. 8–12 of the ``which`` gear of ``pair`` [m] in a temperature field."""
    from thermogear.luo2020.thermal.expansion import flank_expansion_along_line_of_action  # noqa: PLC0415

    gear = getattr(pair, which)
    gamma = pair.gamma(roll)
    flank = field.pinion_flank_c(gamma) if which == "pinion" else field.wheel_flank_c(gamma)
    base = field.pinion_base_c if which == "pinion" else field.wheel_base_c
    bore = field.pinion_bore_c if which == "pinion" else field.wheel_bore_c
    return flank_expansion_along_line_of_action(gear, own_roll_of(pair, which, roll), field.rise(flank),
                                                field.rise(base), field.rise(bore), material.thermal_expansion,
                                                expansion_model)


def fem_analysis(inputs: "FemInputs", refinement: float | None = None, settings: FemSection | None = None,
                 checks: bool = True) -> FemAnalysis:
    """Run the FE verification of a case (both gears) at one mesh refinement, from its resolved inputs
    (:func:`thermogear.fem.inputs.fem_inputs`; ``settings``: their ``[fem]`` section unless given).
    ``checks=False``: only what the FE pair stiffness needs (:meth:`FemAnalysis.thermal_result`, Fig. 15): the
    compliances in the other plane and the uniform-rise expansion check (two of the four elastic solves per gear,
    one of the two thermal ones) are left out, and :meth:`FemAnalysis.summary` refuses the analysis."""
    import time  # noqa: PLC0415

    from thermogear.luo2020.thermal.expansion import flank_expansion_along_line_of_action  # noqa: PLC0415

    settings = settings or inputs.settings
    refinement = settings.mesh_refinement if refinement is None else float(refinement)
    pair, material = inputs.gear_pair, inputs.material
    roll = pair.roll_grid(settings.contact_positions)
    gamma = np.asarray(pair.gamma(roll), dtype=float)
    timings = {}
    start = time.perf_counter()
    temperatures = {g: tooth_temperature(inputs, g, settings, refinement) for g in GEARS}
    field_ = temperature_field_from_fem(pair, inputs.reference_c, temperatures)
    timings["heat"] = time.perf_counter() - start
    other_plane = plane_assumption(settings.plane).other
    deflection, deflection_other, thermal, expansion_fe, expansion_an, uniform_fe, uniform_an = ({} for _ in range(7))
    start = time.perf_counter()
    for gear in GEARS:
        deflection[gear] = tooth_deflection(tooth_model(pair, material, gear, settings, refinement), roll,
                                            inputs.normal_load)
        if checks:
            deflection_other[gear] = tooth_deflection(
                tooth_model(pair, material, gear, settings, refinement, plane=other_plane), roll, inputs.normal_load)
    timings["elastic"] = time.perf_counter() - start
    start = time.perf_counter()
    reference = inputs.reference_c
    alpha = material.thermal_expansion
    for gear in GEARS:
        sector = tooth_model(pair, material, gear, settings, refinement, teeth=1)
        own = own_roll_of(pair, gear, roll)
        _, _, _, normal = contact_point_geometry(sector.gear, own)
        temperature = temperatures[gear]
        bulk = sector.thermal_displacement(lambda x, y, t=temperature: t.at(x, y) - reference, alpha)
        thermal[gear] = sector.point_displacement(bulk, own)
        expansion_fe[gear] = np.sum(thermal[gear] * normal, axis=0)
        expansion_an[gear] = _expansion_analytical(pair, material, inputs.expansion_model, gear, roll, field_)
        if not checks:
            continue
        uniform = sector.thermal_displacement(UNIFORM_RISE, alpha)
        uniform_fe[gear] = np.sum(sector.point_displacement(uniform, own) * normal, axis=0)
        uniform_an[gear] = flank_expansion_along_line_of_action(sector.gear, own, UNIFORM_RISE, UNIFORM_RISE,
                                                                UNIFORM_RISE, alpha, inputs.expansion_model)
    timings["thermoelastic"] = time.perf_counter() - start
    return FemAnalysis(inputs, settings, refinement, roll, gamma, temperatures, field_, deflection, deflection_other,
                       thermal, expansion_fe, expansion_an, uniform_fe, uniform_an, timings, checks)


def refinement_change_percent(coarse: FemAnalysis, fine: FemAnalysis) -> dict[str, float]:
    """Largest relative change [%] of each reported quantity from ``coarse`` to ``fine`` (and ``max``)."""
    changes = {}
    for name, value in coarse.quantities().items():
        other = fine.quantities()[name]
        changes[name] = float(np.max(np.abs(other - value) / np.maximum(np.abs(other), 1e-30)) * 100.0)
    changes["max"] = max(changes.values())
    return changes


# ------------------------------------------------------------------------------------------ cached entry
_CACHE: dict[tuple[str, float, bool], FemAnalysis] = {}


def _key(inputs: "FemInputs", refinement: float | None, checks: bool) -> tuple[str, float, bool]:
    value = inputs.settings.mesh_refinement if refinement is None else float(refinement)
    return inputs.document_key, value, checks


def cached_analysis(inputs: "FemInputs", refinement: float | None = None, checks: bool = True) -> FemAnalysis:
    """:func:`fem_analysis`, memoised per case document (the inputs' ``document_key``: they are resolved from it,
    so two resolutions of one case share an analysis), refinement and ``checks`` (the providers ask for it
    repeatedly); an analysis with its checks also answers a request without them."""
    key = _key(inputs, refinement, checks)
    complete = key[:2] + (True,)
    if complete in _CACHE:
        return _CACHE[complete]
    if key not in _CACHE:
        if len(_CACHE) > 16:
            _CACHE.clear()
        _CACHE[key] = fem_analysis(inputs, refinement, checks=checks)
    return _CACHE[key]


def stiffness_along_path(analysis: FemAnalysis) -> dict:
    """Fig. 15: FE elastic and thermo-elastic pair stiffness along the path [N/m, totals] and the driving tooth's
    single-tooth stiffness of an FE analysis: ``{gamma, elastic, thermal, driving_elastic, driving_thermal}``
    (arrays). The pair stiffness needs neither the other plane nor the check (``cached_analysis(inputs,
    checks=False)`` suffices).

    Elastic: 1/(δ1,FE + δ2,FE + δ_Hertz); thermal: Luo & Li Eqs. 21–23 with the FE compliances, the FE X_te and
    the Eqs. 8–12 expansions of the FE bulk temperature (external normal load)."""
    result = analysis.thermal_result()
    return {"gamma": analysis.gamma.copy(), "elastic": np.asarray(result.elastic_stiffness, dtype=float),
            "thermal": np.asarray(result.stiffness, dtype=float),
            "driving_elastic": 1.0 / np.asarray(result.elastic_pinion_compliance, dtype=float),
            "driving_thermal": np.asarray(result.pinion_stiffness, dtype=float)}


__all__ = ["FemAnalysis", "cached_analysis", "fem_analysis", "refinement_change_percent", "stiffness_along_path",
           "temperature_field_from_fem"]


