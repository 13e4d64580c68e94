"""The thermo-elastic mesh of a case: one frozen component the mesh model plugs in (docs/thermal.md).

``ThermoelasticMesh.from_case(case)`` (memoised per case) resolves the temperatures, expands gears and housing,
builds the hot gear pair, Young's modulus of each gear at its tooth temperature, the backlash hot and cold, the
jamming temperature and the unloaded deviations; it then answers per tooth pair along the roll distance on the hot
geometry (stiffness, deviation) and, for a normal load, the loaded static transmission error over one mesh period.
At zero rise (everything at 20 °C, the reference) it is the elastic model bit for bit.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from thermogear.temperature.kinds import temperature_source
from thermogear.case import cached_per_case
from thermogear.geometry import GearPair
from thermogear.materials import Material
from thermogear.geometry.mesh_cycle import MeshCycle, MeshGrid
from thermogear.operating import OperatingPoint
from thermogear.stiffness import scaled_compliance
from thermogear.stiffness import table as stiffness_table
from thermogear.stiffness.table import pair_stiffness_at
from thermogear.temperature.source import TemperatureField
from thermogear.thermoelastic.deviations import (base_pitch_deviation, equivalent_bulk_rise, flank_distortion,
                                                 tip_relief)
from thermogear.thermoelastic.inputs import (GearInputs, HousingInputs, backlash_allowance, check_not_jammed,
                                             gear_inputs, housing_inputs)
from thermogear.thermoelastic.load_sharing import LoadedTransmissionError, loaded_transmission_error
from thermogear.thermoelastic.materials import youngs_modulus_at
from thermogear.thermoelastic.operating import BacklashAllowance, backlash_at, jamming_rise, operating_gear_pair

#: Contact positions Γ of the thermal flank-distortion table (A to E inclusive); linear interpolation between them
#: is exact to < 1e-4 of the distortion for the smooth (polynomial) flank fields of thermogear.
DISTORTION_POINT_COUNT = 401

#: Intervals of one mesh period for the period statistics (min/mean/max stiffness, STE) [–].
PERIOD_INTERVAL_COUNT = 512

#: Plausibility bounds: jamming closer than this above the operating bulk temperature is flagged [K]; a hot
#: contact ratio below this is flagged [–]; the stiffness change may exceed what E(T) and the change of contact
#: ratio explain by this much before it is flagged [–] (the PEM table interpolation is good to 1e-6).
JAMMING_MARGIN_K = 20.0
CONTACT_RATIO_MINIMUM = 1.05
STIFFNESS_EXPLAINED_SLACK = 0.005


@dataclass(frozen=True, eq=False)
class ThermoelasticMesh:
    """The gear mesh of a case at its operating temperatures (SI units; temperatures in °C)."""

    cold_gear_pair: GearPair  # at the reference temperature
    gear_pair: GearPair  # at temperature: gears by their bulk rise, centre distance by the housing's
    material: Material  # the case's material, E at 20 °C
    reference_c: float
    housing_c: float
    bulk_c: tuple[float, float]  # equivalent bulk temperature of pinion and wheel [°C]
    tooth_c: tuple[float, float]  # tooth temperature of E(T) [°C]
    strains: tuple[float, float, float]  # pinion, wheel, housing [–]
    youngs_modulus: tuple[float, float]  # E at the tooth temperatures [Pa]
    youngs_modulus_cold: tuple[float, float]  # E at the reference temperature [Pa]
    gears: tuple[GearInputs, GearInputs]
    housing: HousingInputs
    allowance: BacklashAllowance
    backlash_normal: float  # at temperature [m]
    backlash_normal_cold: float  # at the reference temperature [m]
    jamming_bulk_temperature_c: float | None
    distortion_gamma: np.ndarray  # Γ of the distortion table (cold pair)
    distortion: np.ndarray  # thermal flank distortion of a pair at distortion_gamma [m], + = material missing
    operating_point: OperatingPoint  # the case's speed and load (the one place they are held)
    temperature_source: str

    @property
    def speed_rpm(self) -> float:
        """Pinion speed of the operating point [rpm]."""
        return self.operating_point.speed_rpm

    @property
    def normal_load(self) -> float:
        """Static normal load of the operating point on the pair as built, w = T1/r_b1 [N] (total)."""
        return self.operating_point.normal_load(self.cold_gear_pair.pinion.base_radius)

    # ---------------------------------------------------------------------------------------- construction
    @staticmethod
    @cached_per_case
    def from_case(temperature_field: "TemperatureField", gear_pair: "GearPair", gears_input, material_input,
                  material: "Material", housing, lubricant, operating_point: "OperatingPoint") -> "ThermoelasticMesh":
        """The component of a case, built once per case (raises CaseError when the gears jam) from these pieces of
        it: its temperature field, gear pair, sections and operating point. Called with the case
        (``ThermoelasticMesh.from_case(case)``, memoised per case, :func:`thermogear.case.cached_per_case`)."""
        return thermoelastic_mesh(temperature_field, gear_pair, gears_input, material_input, material, housing,
                                  lubricant, operating_point)

    # ------------------------------------------------------------------------------------------- stiffness
    @property
    def modulus_ratios(self) -> tuple[float, float]:
        """E(T)/E(20 °C) of pinion and wheel [–]."""
        return (self.youngs_modulus[0] / self.material.youngs_modulus,
                self.youngs_modulus[1] / self.material.youngs_modulus)

    def pair_stiffness_at(self, roll) -> np.ndarray:
        """Pair stiffness [N/m, total over the face width] at roll distances on the hot path [A', E'].

        Every PEM compliance of a tooth (bending, shear, axial, fillet, its half of Hertz) is ∝ 1/E, so each
        tooth's compliance from the cached table of the hot pair is divided by its own E ratio. With equal ratios
        this is the ratio times the cached pair stiffness (bit for bit the elastic one at ratio 1).
        """
        ratio_pinion, ratio_wheel = self.modulus_ratios
        # a grown pair: its table from one interpolant per gear shape (the same values to < 1e-11)
        source = scaled_compliance if self.gear_pair is not self.cold_gear_pair else stiffness_table
        if ratio_pinion == ratio_wheel:
            return ratio_pinion * source.pair_stiffness_at(self.gear_pair, self.material, roll)
        pinion, wheel = source.tooth_compliance_at(self.gear_pair, self.material, roll)
        return 1.0 / (pinion / ratio_pinion + wheel / ratio_wheel)

    def elastic_pair_stiffness_at(self, roll) -> np.ndarray:
        """The elastic model's pair stiffness [N/m] (cold pair, E at 20 °C) at roll distances on the cold path."""
        return pair_stiffness_at(self.cold_gear_pair, self.material, roll)

    # ------------------------------------------------------------------------------------------ deviations
    def deviation_parts_at(self, roll) -> dict[str, np.ndarray]:
        """The parts of the unloaded deviation [m] at roll distances on the hot path: ``tip_relief`` (both gears),
        ``base_pitch`` and ``thermal_distortion``; positive = material missing."""
        roll = np.asarray(roll, dtype=float)
        pair = self.gear_pair
        pinion, wheel = self.gears
        pinion_strain, wheel_strain, _ = self.strains
        points = pair.path_points
        relief = tip_relief(roll, points["E"], pinion.tip_relief, pinion.tip_relief_length * (1 + pinion_strain),
                            pinion.tip_relief_shape)
        wheel_roll = pair.line_of_action_length - roll
        relief = relief + tip_relief(wheel_roll, pair.line_of_action_length - points["A"], wheel.tip_relief,
                                     wheel.tip_relief_length * (1 + wheel_strain), wheel.tip_relief_shape)
        # p_b2'/p_b1' = (1 + ε2)/(1 + ε1): written with the strains so that equal strains give exactly 0
        pitch = base_pitch_deviation(roll, points["C"], 1.0 + pinion_strain, 1.0 + wheel_strain)
        distortion = np.interp(pair.gamma(roll), self.distortion_gamma, self.distortion)
        return {"tip_relief": relief, "base_pitch": pitch, "thermal_distortion": distortion}

    def pair_deviation_at(self, roll) -> np.ndarray:
        """Unloaded deviation e(roll) of a tooth pair [m] on the hot path, positive = material missing."""
        parts = self.deviation_parts_at(roll)
        return parts["tip_relief"] + parts["base_pitch"] + parts["thermal_distortion"]

    # --------------------------------------------------------------------------------- one mesh period
    def mesh_grid(self, count: int = PERIOD_INTERVAL_COUNT, cold: bool = False) -> MeshGrid:
        """Pair slots over one mesh period of the hot (or cold) pair at the case's speed."""
        pair = self.cold_gear_pair if cold else self.gear_pair
        return MeshCycle(pair, self.speed_rpm).grid(count)

    def mesh_stiffness(self, count: int = PERIOD_INTERVAL_COUNT, cold: bool = False) -> tuple[MeshGrid, np.ndarray]:
        """(grid, k(τ)): the unloaded mesh stiffness over one period [N/m], pairs on the path in parallel; thermal
        (hot pair, E(T)) or ``cold`` (the elastic model)."""
        grid = self.mesh_grid(count, cold)
        stiffness = self._per_pair(grid, self.elastic_pair_stiffness_at if cold else self.pair_stiffness_at)
        return grid, MeshCycle.total(stiffness, grid.in_contact)

    def loaded_transmission_error(self, normal_load: float | None = None, count: int = PERIOD_INTERVAL_COUNT,
                                  cold: bool = False) -> tuple[MeshGrid, LoadedTransmissionError]:
        """Loaded static transmission error and load share over one mesh period at ``normal_load`` [N] (default:
        the case's). ``cold``: the elastic model's pair with the same tip reliefs and no thermal deviation."""
        grid, stiffness, deviation = self.period_pairs(count, cold)
        load = self.normal_load if normal_load is None else float(normal_load)
        return grid, loaded_transmission_error(stiffness, deviation, load, grid.in_contact)

    def period_pairs(self, count: int = PERIOD_INTERVAL_COUNT,
                     cold: bool = False) -> tuple[MeshGrid, np.ndarray, np.ndarray]:
        """(grid, k_i(τ) [N/m], e_i(τ) [m]) of every pair slot over one mesh period (0 for slots off the path):
        what the dynamics' me·ẍ + c·ẋ + Σ k_i (x − e_i) = w needs, on the hot (or ``cold``) pair."""
        grid = self.mesh_grid(count, cold)
        if cold:
            return (grid, self._per_pair(grid, self.elastic_pair_stiffness_at),
                    self._per_pair(grid, self.cold_pair_deviation_at))
        return grid, self._per_pair(grid, self.pair_stiffness_at), self._per_pair(grid, self.pair_deviation_at)

    def cold_pair_deviation_at(self, roll) -> np.ndarray:
        """The elastic model's unloaded deviation of a pair [m] at roll distances on the cold path: the tip
        reliefs alone (no thermal part), positive = material missing."""
        pair = self.cold_gear_pair
        pinion, wheel = self.gears
        points = pair.path_points
        return (tip_relief(roll, points["E"], pinion.tip_relief, pinion.tip_relief_length, pinion.tip_relief_shape)
                + tip_relief(pair.line_of_action_length - np.asarray(roll, dtype=float),
                             pair.line_of_action_length - points["A"], wheel.tip_relief, wheel.tip_relief_length,
                             wheel.tip_relief_shape))

    @staticmethod
    def _per_pair(grid: MeshGrid, evaluate) -> np.ndarray:
        values = np.zeros_like(grid.roll)
        values[grid.in_contact] = evaluate(grid.roll[grid.in_contact])
        return values

    # ------------------------------------------------------------------------------------------- checks
    @cached_property
    def plausibility(self) -> tuple[str, ...]:
        """Findings that make the thermal result doubtful, in words (empty when nothing is flagged); computed once."""
        flags = []
        hot_grid, hot = self.mesh_stiffness()
        cold_grid, cold = self.mesh_stiffness(cold=True)
        change = float(hot_grid.time_average(hot) / cold_grid.time_average(cold)) - 1.0
        modulus = 0.5 * sum(self.modulus_ratios) - 1.0
        width = self.gear_pair.face_width / self.cold_gear_pair.face_width - 1.0
        contact = self.gear_pair.contact_ratio / self.cold_gear_pair.contact_ratio - 1.0
        if abs(change - modulus - width) > 2.0 * abs(contact) + STIFFNESS_EXPLAINED_SLACK:
            flags.append(f"the mean mesh stiffness changes by {100 * change:+.2f} %, more than E(T) "
                         f"({100 * modulus:+.2f} %) and the change of contact ratio ({100 * contact:+.2f} %) explain")
        jamming = self.jamming_bulk_temperature_c
        if jamming is not None and jamming - max(self.bulk_c) < JAMMING_MARGIN_K:
            flags.append(f"the backlash closes at a bulk temperature of {jamming:.1f} °C, less than "
                         f"{JAMMING_MARGIN_K:g} K above the operating {max(self.bulk_c):.1f} °C")
        if self.gear_pair.contact_ratio < CONTACT_RATIO_MINIMUM:
            flags.append(f"the contact ratio at temperature is {self.gear_pair.contact_ratio:.3f}, close to 1")
        return tuple(flags)


# --------------------------------------------------------------------------------------------- building
def thermoelastic_mesh(field: TemperatureField, pair: GearPair, gears_section, material_section, material: Material,
                       housing_section, lubricant_section, operating_point: OperatingPoint) -> ThermoelasticMesh:
    """The thermo-elastic mesh of a gear pair (as built) of ``material``, with the expansion and E(T) inputs of the
    ``[gears]`` and ``[material]`` sections, in the temperature field ``field``, inside the housing of the
    ``[housing]`` section (its temperature defaulting from the ``[lubricant]`` section), at an operating point
    (raises CaseError when the gears jam)."""
    inputs = tuple(gear_inputs(gears_section, material_section, name) for name in ("pinion", "wheel"))
    housing = housing_inputs(housing_section, lubricant_section)
    reference = field.reference_c
    bulk_rise = (equivalent_bulk_rise(pair.pinion, inputs[0].expansion_per_k, field.pinion_base_c - reference,
                                      field.pinion_bore_c - reference),
                 equivalent_bulk_rise(pair.wheel, inputs[1].expansion_per_k, field.wheel_base_c - reference,
                                      field.wheel_bore_c - reference))
    bulk_c = (reference + bulk_rise[0], reference + bulk_rise[1])
    strains = (inputs[0].expansion_per_k * bulk_rise[0], inputs[1].expansion_per_k * bulk_rise[1],
               housing.expansion_per_k * (housing.temperature_c - reference))
    allowance = backlash_allowance(pair, gears_section)
    hot_backlash = check_not_jammed(pair, allowance, inputs[0], inputs[1], housing, reference, bulk_c,
                                    "temperature.bulk_c" if temperature_source(field.source).uniform else "temperature")
    rise = jamming_rise(pair, allowance, inputs[0].expansion_per_k, inputs[1].expansion_per_k, strains[2])
    tooth_c = _tooth_temperatures(field, pair)
    modulus = material.youngs_modulus
    gamma, distortion = _distortion_table(field, pair, inputs, bulk_rise)
    return ThermoelasticMesh(
        cold_gear_pair=pair, gear_pair=operating_gear_pair(pair, *strains), material=material,
        reference_c=reference, housing_c=housing.temperature_c, bulk_c=bulk_c, tooth_c=tooth_c, strains=strains,
        youngs_modulus=tuple(youngs_modulus_at(modulus, g.modulus_coefficient_per_k, t)
                             for g, t in zip(inputs, tooth_c)),
        youngs_modulus_cold=tuple(youngs_modulus_at(modulus, g.modulus_coefficient_per_k, reference)
                                  for g in inputs),
        gears=inputs, housing=housing, allowance=allowance, backlash_normal=hot_backlash,
        backlash_normal_cold=backlash_at(pair, allowance, 0.0, 0.0, 0.0),
        jamming_bulk_temperature_c=None if rise is None else reference + rise,
        distortion_gamma=gamma, distortion=distortion, operating_point=operating_point,
        temperature_source=field.source)


def _tooth_temperatures(field: TemperatureField, pair: GearPair) -> tuple[float, float]:
    """Tooth temperature of each gear for E(T) [°C]: the mean of its flank temperature over the path and its
    base-circle temperature (a uniform field: the bulk temperature, exactly)."""
    if temperature_source(field.source).uniform:
        return field.pinion_base_c, field.wheel_base_c
    gamma = pair.gamma(pair.roll_grid(DISTORTION_POINT_COUNT))
    pinion_flank = float(np.mean(field.pinion_flank_c(gamma)))
    wheel_flank = float(np.mean(field.wheel_flank_c(gamma)))
    return 0.5 * (pinion_flank + field.pinion_base_c), 0.5 * (wheel_flank + field.wheel_base_c)


def _distortion_table(field: TemperatureField, pair: GearPair, inputs, bulk_rise) -> tuple[np.ndarray, np.ndarray]:
    """Thermal flank distortion of a pair on Γ from A to E of the cold pair [m], + = material missing.

    A uniform field has none: its consistent Eqs. 8–12 are the homogeneous expansion, which the geometry already
    holds (tests/unit/test_thermoelastic_deviations.py checks the formula gives 0 to rounding); it is set to 0
    exactly so that a uniform field adds no rounding noise (and zero rise is the elastic model bit for bit).
    """
    roll = pair.roll_grid(DISTORTION_POINT_COUNT)
    gamma = np.asarray(pair.gamma(roll), dtype=float)
    if temperature_source(field.source).uniform:
        zero = np.zeros_like(gamma)
        gamma.setflags(write=False)
        zero.setflags(write=False)
        return gamma, zero
    reference = field.reference_c
    pinion = flank_distortion(pair.pinion, roll, field.pinion_flank_c(gamma) - reference,
                              field.pinion_base_c - reference, field.pinion_bore_c - reference,
                              inputs[0].expansion_per_k, bulk_rise[0])
    wheel = flank_distortion(pair.wheel, pair.line_of_action_length - roll, field.wheel_flank_c(gamma) - reference,
                             field.wheel_base_c - reference, field.wheel_bore_c - reference,
                             inputs[1].expansion_per_k, bulk_rise[1])
    distortion = -(pinion + wheel)
    gamma.setflags(write=False)
    distortion.setflags(write=False)
    return gamma, distortion
