"""Tooth temperature field of the thermal model, built from a ``[temperature]`` section and checked.

This module holds what needs nothing but the section and the gear pair's path of contact: the
:class:`TemperatureField` component, the flank-table checks, the polynomial fit (Luo & Li 2020 §2.1.5) and the
range checks of :func:`check_temperatures`. It imports no case machinery, so the case loader runs these checks
at load time (``thermogear check`` refuses what ``run`` would refuse); :mod:`thermogear.temperature.source` wires
it to a :class:`~thermogear.case.Case` (and to the finite-element provider) and re-exports it.

Temperatures are °C here; the expansion uses the rises above ``reference_c`` (Luo & Li Eq. 10 holds for rises
above the stress-free state, which the paper does not say). How cold the gears may be depends on the thermal
model (:class:`TemperatureLimits`): the thermo-elastic model evaluates contraction below the assembly temperature
(a cold start), the paper's k_T does not.
"""

from __future__ import annotations

import csv
import math
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from thermogear.temperature.kinds import temperature_source
from thermogear.errors import CaseError, ExtrapolationWarning, ModelAssumptionWarning, shown_value
from thermogear.text_files import is_existing_file, read_user_text

#: Highest tooth temperature the material data cover [°C] (room-temperature E, ν and a constant expansion
#: coefficient; gear steels are tempered at about 150–200 °C and soften above). The one definition is
#: :data:`thermogear.temperature.limits.MATERIAL_MAXIMUM_C`.
from thermogear.temperature.limits import MATERIAL_MAXIMUM_C  # noqa: E402

#: Lowest tooth temperature the thermo-elastic model evaluates [°C]: the coldest start the housing range allows
#: (schema.housing.HOUSING_TEMPERATURE_RANGE_C). Below the assembly temperature the gears contract uniformly by
#: λ·ΔT (ΔT < 0) and E(T) rises along the chord of Roark's table (fitted on 21–204 °C, so taken 61 K below its
#: data at −40 °C, a third of its span: an extrapolation; ASME B31.3 Table C-6, the table's source, also lists E
#: below room temperature, not yet compared here). Colder, the constants are not a description of the gear.
MATERIAL_MINIMUM_C = -40.0

#: Highest temperature of the usual viscosity data of a gear oil (ISO 3448 data sheets give 40 and 100 °C);
#: used when the case names a built-in oil whose own range is not known to this module [°C].
DEFAULT_LUBRICANT_DATA_MAXIMUM_C = 100.0

#: A fitted flank curve may leave the range of its table by this much before the fit is reported as
#: oscillating (Runge): the larger of 0.5 K and 10 % of the table's spread [K].
FIT_OVERSHOOT_ABSOLUTE_K = 0.5
FIT_OVERSHOOT_RELATIVE = 0.10

#: Relative tolerance on Γ when checking that a table spans the path of contact [–].
GAMMA_SPAN_TOLERANCE = 1e-9


# ------------------------------------------------------------------------------------------------ component
@dataclass(frozen=True)
class TemperatureField:
    """Tooth temperatures of the pair [°C].

    The flank temperature at contact position Γ is ``flank_coefficients`` (a NumPy ``Polynomial`` in Γ on
    ``fit_domain``) for the pinion, the same plus ``wheel_flank_offset_c`` for the wheel. ``fit_range`` is the
    Γ range of the data the curve was fitted to (``None`` for a uniform field, valid everywhere).
    """

    reference_c: float
    pinion_base_c: float
    pinion_bore_c: float
    wheel_base_c: float
    wheel_bore_c: float
    flank_coefficients: tuple[float, ...]
    fit_domain: tuple[float, float] = (-1.0, 1.0)
    fit_range: tuple[float, float] | None = None
    fit_degree: int = 0
    wheel_flank_offset_c: float = 0.0
    source: str = "uniform"
    table_gamma: tuple[float, ...] = ()
    table_flank_c: tuple[float, ...] = ()

    # ------------------------------------------------------------------------------------ constructors
    @classmethod
    def uniform(cls, bulk_c: float, reference_c: float = 20.0) -> "TemperatureField":
        """The whole of both gears at ``bulk_c``."""
        return cls(reference_c=reference_c, pinion_base_c=bulk_c, pinion_bore_c=bulk_c, wheel_base_c=bulk_c,
                   wheel_bore_c=bulk_c, flank_coefficients=(float(bulk_c),), source="uniform")

    @classmethod
    def from_table(cls, gamma, flank_c, fit_degree: int, *, pinion_base_c: float, pinion_bore_c: float,
                   wheel_base_c: float, wheel_bore_c: float, reference_c: float = 20.0,
                   wheel_flank_offset_c: float = 0.0, source: str = "tabulated") -> "TemperatureField":
        """Fit a degree-``fit_degree`` polynomial in Γ to a flank temperature table (least squares; the paper's
        treatment of Fig. 3c). Raises CaseError for a table that cannot carry the fit."""
        gamma, flank_c = check_flank_table(gamma, flank_c, fit_degree)
        polynomial = fit_flank_polynomial(gamma, flank_c, fit_degree)
        return cls(reference_c=reference_c, pinion_base_c=pinion_base_c, pinion_bore_c=pinion_bore_c,
                   wheel_base_c=wheel_base_c, wheel_bore_c=wheel_bore_c,
                   flank_coefficients=tuple(float(c) for c in polynomial.coef),
                   fit_domain=(float(polynomial.domain[0]), float(polynomial.domain[1])),
                   fit_range=(float(gamma[0]), float(gamma[-1])), fit_degree=int(fit_degree),
                   wheel_flank_offset_c=wheel_flank_offset_c, source=source,
                   table_gamma=tuple(float(g) for g in gamma), table_flank_c=tuple(float(t) for t in flank_c))

    # ----------------------------------------------------------------------------------------- values
    @property
    def flank_polynomial(self) -> np.polynomial.Polynomial:
        """The fitted pinion flank temperature T(Γ) [°C]."""
        return np.polynomial.Polynomial(self.flank_coefficients, domain=self.fit_domain)

    def pinion_flank_c(self, gamma) -> np.ndarray:
        """Pinion flank temperature at contact position Γ [°C]. Warns (ExtrapolationWarning) outside the fitted
        range."""
        gamma = np.asarray(gamma, dtype=float)
        self._warn_outside(gamma)
        return np.asarray(self.flank_polynomial(gamma), dtype=float)

    def wheel_flank_c(self, gamma) -> np.ndarray:
        """Wheel flank temperature at contact position Γ [°C] (pinion curve + ``wheel_flank_offset_c``)."""
        return self.pinion_flank_c(gamma) + self.wheel_flank_offset_c

    def rise(self, temperature_c):
        """Temperature rise above the stress-free reference [K]."""
        return np.asarray(temperature_c, dtype=float) - self.reference_c

    def describe(self) -> dict:
        """Plain summary for result files and JSON."""
        return {"source": self.source, "reference_c": self.reference_c, "fit_degree": self.fit_degree,
                "fit_range_gamma": None if self.fit_range is None else list(self.fit_range),
                "pinion_base_c": self.pinion_base_c, "pinion_bore_c": self.pinion_bore_c,
                "wheel_base_c": self.wheel_base_c, "wheel_bore_c": self.wheel_bore_c,
                "wheel_flank_offset_c": self.wheel_flank_offset_c}

    def _warn_outside(self, gamma: np.ndarray) -> None:
        if self.fit_range is None or gamma.size == 0:
            return
        low, high = self.fit_range
        slack = GAMMA_SPAN_TOLERANCE * max(1.0, abs(low), abs(high))
        if np.min(gamma) < low - slack or np.max(gamma) > high + slack:
            warnings.warn(f"flank temperature asked at Γ in [{np.min(gamma):.4g}, {np.max(gamma):.4g}], outside "
                          f"the table it was fitted to [{low:.4g}, {high:.4g}]: the degree-{self.fit_degree} "
                          "polynomial is extrapolated", ExtrapolationWarning, stacklevel=3)


# ------------------------------------------------------------------------------------------------ functions
def check_flank_table(gamma, flank_c, fit_degree: int, key: str = "temperature") -> tuple[np.ndarray, np.ndarray]:
    """Validate a flank temperature table (Γ [–], T [°C]): equal lengths, finite, Γ strictly increasing, enough
    points for the fit degree. Returns the arrays; raises CaseError naming the key."""
    gamma = np.asarray(gamma, dtype=float)
    flank_c = np.asarray(flank_c, dtype=float)
    if gamma.ndim != 1 or flank_c.ndim != 1 or gamma.size != flank_c.size:
        raise CaseError(f"{key}.flank_c", np.atleast_1d(flank_c).tolist(), f"{gamma.size} values, one per gamma",
                        "the flank temperature table needs one temperature per contact position")
    if gamma.size < 2:
        raise CaseError(f"{key}.gamma", gamma.tolist(), "two or more positions",
                        "a flank temperature curve needs at least two points")
    for name, values in (("gamma", gamma), ("flank_c", flank_c)):
        if not np.all(np.isfinite(values)):
            raise CaseError(f"{key}.{name}", values.tolist(), "finite numbers", "the table holds NaN or inf")
    steps = np.diff(gamma)
    if np.any(steps == 0.0):
        duplicate = float(gamma[1:][steps == 0.0][0])
        raise CaseError(f"{key}.gamma", gamma.tolist(), "strictly increasing, no repeats",
                        f"Γ = {duplicate} appears twice: a flank temperature table is a function of Γ")
    if np.any(steps < 0.0):
        index = int(np.argmax(steps < 0.0))
        raise CaseError(f"{key}.gamma", gamma.tolist(), "strictly increasing",
                        f"Γ decreases from {gamma[index]} to {gamma[index + 1]}: sort the table along the path")
    if not 0 <= fit_degree <= gamma.size - 1:
        raise CaseError(f"{key}.fit_degree", fit_degree, f"0 to {gamma.size - 1} (points − 1)",
                        f"a degree-{fit_degree} polynomial needs at least {fit_degree + 1} table points; the "
                        f"table has {gamma.size}")
    return gamma, flank_c


@dataclass(frozen=True)
class TemperatureLimits:
    """Range of gear temperatures a thermal model can evaluate: ``lowest_c`` [°C] (``None``: the stress-free
    reference temperature itself) up to :data:`MATERIAL_MAXIMUM_C`; ``model`` names it in a refusal and
    ``reason`` says why it stops there."""

    model: str
    lowest_c: float | None
    reason: str


#: The thermo-elastic model (thermal.model = 'thermoelastic'): uniform expansion or contraction of gears and
#: housing by λ·(T − reference), E(T), backlash and jamming hold on either side of the assembly temperature.
THERMOELASTIC_LIMITS = TemperatureLimits(
    "thermal.model = 'thermoelastic'", MATERIAL_MINIMUM_C,
    f"below {MATERIAL_MINIMUM_C:g} °C the material data (E(T) of Roark's table, a constant expansion coefficient) "
    "are extrapolated too far to describe the gear")

#: The paper's k_T (thermal.model = 'luo2020'): Luo & Li Eq. 13 turns a rise into the load p_t = k_e (Δ_t1 + Δ_t2)
#: of fully restrained expansion, which the teeth carry in compression; a contraction (Δ_t < 0) would make it a
#: tensile load that meshing teeth cannot carry, and Eq. 17 would return a mesh stiffer than the cold one.
LUO2020_LIMITS = TemperatureLimits(
    "thermal.model = 'luo2020'", None,
    "the paper's thermal stiffness (Luo & Li Eqs. 13–17) describes the restrained expansion of heated teeth; a "
    "contraction would make its thermal load p_t = k_e (Δ_t1 + Δ_t2) tensile, which meshing teeth cannot carry "
    "(use thermal.model = 'thermoelastic' for a cold start, or lower temperature.reference_c if the gears were "
    "assembled colder)")

def fit_flank_polynomial(gamma, flank_c, fit_degree: int) -> np.polynomial.Polynomial:
    """Least-squares polynomial T(Γ) of the given degree (Luo & Li 2020 §2.1.5: "fitted by a high-order
    polynomial"), on a scaled domain for conditioning. Raises CaseError if the fit is rank deficient."""
    # full=True returns the rank instead of warning (NumPy raises RankWarning when rank != degree + 1): no
    # process-wide warning filter is needed, so the fit is safe in a study's worker threads
    polynomial, (_, rank, _, _) = np.polynomial.Polynomial.fit(np.asarray(gamma, float), np.asarray(flank_c, float),
                                                               int(fit_degree), full=True)
    if rank != int(fit_degree) + 1:
        raise CaseError("temperature.fit_degree", fit_degree, "a lower degree",
                        "the table's positions cannot determine a polynomial of this degree (rank "
                        "deficient least-squares fit)")
    return polynomial


def case_key_of(source: str, key: str) -> str:
    """The case-file key a temperature of a field from ``source`` (its model's name first) came from, never a key
    the user did not write: ``temperature.flank_c`` was named for a gearbox case (issue 36)."""
    kind = temperature_source(source.split()[0])
    if kind.tabulated:
        return "temperature.csv" if source.endswith("(csv)") and key.endswith(".flank_c") else key
    return "temperature.bulk_c" if kind.uniform else f"temperature.model = '{kind.name}'"


def check_temperatures(field: TemperatureField, gamma_start: float, gamma_end: float,
                       lubricant_maximum_c: float | None = None, count: int = 401, *,
                       limits: TemperatureLimits = THERMOELASTIC_LIMITS) -> None:
    """Check a temperature field over the path of contact [Γ_A, Γ_E] for the thermal model of ``limits``:

    - a tabulated flank curve must span the path (no silent extrapolation);
    - every temperature (table, fitted curve on the path, base circles, bores) must be at or above
      ``limits.lowest_c`` (the reference temperature where that is None) and at most MATERIAL_MAXIMUM_C;
    - a fit that overshoots its table (polynomial wiggle) is reported (ModelAssumptionWarning);
    - a flank temperature above ``lubricant_maximum_c`` is reported (ExtrapolationWarning: the oil's viscosity
      law is used beyond its data by the damping model).
    """
    if field.fit_range is not None:
        low, high = field.fit_range
        slack = GAMMA_SPAN_TOLERANCE * max(1.0, abs(gamma_start), abs(gamma_end))
        if low > gamma_start + slack or high < gamma_end - slack:
            raise CaseError("temperature.gamma", [low, high], f"covering the path of contact "
                            f"[{gamma_start:.4f}, {gamma_end:.4f}]",
                            "the flank temperature table does not span the path of contact; the fitted polynomial "
                            "would be extrapolated (extend the table)")
    path_gamma = np.linspace(gamma_start, gamma_end, count)
    flank = np.asarray(field.flank_polynomial(path_gamma), dtype=float)
    wheel_flank = flank + field.wheel_flank_offset_c
    values = {  # key: (what, lowest, highest)
        "temperature.flank_c": ("the fitted pinion flank temperature on the path", float(flank.min()),
                                float(flank.max())),
        "temperature.wheel_flank_offset_c": ("the wheel flank temperature on the path", float(wheel_flank.min()),
                                             float(wheel_flank.max())),
        "temperature.pinion_base_c": ("the pinion base-circle temperature",) + (field.pinion_base_c,) * 2,
        "temperature.pinion_bore_c": ("the pinion bore temperature",) + (field.pinion_bore_c,) * 2,
        "temperature.wheel_base_c": ("the wheel base-circle temperature",) + (field.wheel_base_c,) * 2,
        "temperature.wheel_bore_c": ("the wheel bore temperature",) + (field.wheel_bore_c,) * 2,
    }
    if field.table_flank_c:
        values["temperature.flank_c"] = ("the flank temperature (table and fit)",
                                         min(min(field.table_flank_c), float(flank.min())),
                                         max(max(field.table_flank_c), float(flank.max())))
    floor = field.reference_c if limits.lowest_c is None else limits.lowest_c
    floor_text = (f">= reference_c = {field.reference_c:g} °C" if limits.lowest_c is None else f">= {floor:g} °C")
    for key, (name, lowest, highest) in values.items():
        key = case_key_of(field.source, key)
        if not (math.isfinite(lowest) and math.isfinite(highest)):
            raise CaseError(key, lowest, "finite", "a temperature is NaN or infinite")
        if lowest < floor:
            below = ("below the stress-free reference temperature" if limits.lowest_c is None else
                     f"below what {limits.model} evaluates")
            raise CaseError(key, round(lowest, 4), f"{floor_text} under {limits.model}",
                            f"{name} is {below}: {limits.reason}")
        if highest > MATERIAL_MAXIMUM_C:
            raise CaseError(key, round(highest, 4), f"<= {MATERIAL_MAXIMUM_C} °C",
                            f"{name} is above what the material data cover (room-temperature E, ν and a constant "
                            "expansion coefficient; gear steels temper at 150–200 °C)")
    if field.fit_range is not None and field.table_flank_c:
        table_low, table_high = min(field.table_flank_c), max(field.table_flank_c)
        allowed = max(FIT_OVERSHOOT_ABSOLUTE_K, FIT_OVERSHOOT_RELATIVE * (table_high - table_low))
        overshoot = max(table_low - float(flank.min()), float(flank.max()) - table_high)
        if overshoot > allowed:
            warnings.warn(f"the degree-{field.fit_degree} flank temperature fit leaves the range of its table by "
                          f"{overshoot:.2f} K on the path of contact (polynomial wiggle); a lower "
                          "temperature.fit_degree follows the data more faithfully", ModelAssumptionWarning,
                          stacklevel=2)
    if lubricant_maximum_c is not None:
        hottest = float(flank.max() + max(field.wheel_flank_offset_c, 0.0))
        if hottest > lubricant_maximum_c:
            warnings.warn(f"flank temperature up to {hottest:.1f} °C is above the lubricant's viscosity data "
                          f"(up to {lubricant_maximum_c:.1f} °C): the viscosity law is extrapolated there",
                          ExtrapolationWarning, stacklevel=2)


def default_bulk_temperature(section, lubricant) -> tuple[object, tuple[str, ...]]:
    """The ``[temperature]`` section with its default made physical, and the note that says so.

    A case that gives no tooth temperature (no ``[temperature]`` section, or ``model = "uniform"`` without
    ``bulk_c``) has its gears at the oil's operating temperature (``lubricant.operating_temperature_c``): gear
    bodies and oil in thermal equilibrium, no frictional heating of the teeth above the oil. The bulk temperature of
    a running pair lies at or above its oil temperature, so this is its lower bound. Returns ``(section, notes)``;
    the section unchanged and no note when the case gives a temperature."""
    if not temperature_source(section.model).uniform or section.bulk_c is not None:
        return section, ()
    oil = lubricant.operating_temperature_c
    note = (f"temperature: no bulk temperature given ([temperature] bulk_c): the gears are taken at the oil's "
            f"operating temperature, {oil:g} °C (lubricant.operating_temperature_c) — gears and oil in equilibrium, "
            "no frictional heating of the teeth above the oil (a lower bound); give [temperature] bulk_c for hotter "
            "gears")
    return section.model_copy(update={"bulk_c": float(oil)}), (note,)


def temperature_field_from_section(section, directory: Path | None = None) -> TemperatureField:
    """The TemperatureField of a ``uniform`` or ``tabulated`` ``[temperature]`` section (CSV paths relative to
    ``directory``). Raises CaseError for bad input."""
    if temperature_source(section.model).uniform:
        return _uniform_field(section)
    if temperature_source(section.model).tabulated:
        return _tabulated_field(section, directory)
    raise CaseError("temperature.model", section.model, "uniform | tabulated here",
                    "this model's field comes from its provider (see thermogear.temperature.source)")


def _uniform_field(section) -> TemperatureField:
    if section.bulk_c is None:
        raise CaseError("temperature.bulk_c", None, "a temperature in °C", "model = 'uniform' needs bulk_c")
    table_only = {"gamma", "flank_c", "csv", "fit_degree", "pinion_base_c", "pinion_bore_c", "wheel_base_c",
                  "wheel_bore_c", "wheel_flank_offset_c"} & section.model_fields_set
    if table_only:
        name = sorted(table_only)[0]
        raise CaseError(f"temperature.{name}", getattr(section, name), "absent with model = 'uniform'",
                        "a uniform field has one bulk temperature; use model = 'tabulated' for flank, base and "
                        "bore temperatures")
    return TemperatureField.uniform(section.bulk_c, section.reference_c)


def _tabulated_field(section, directory: Path | None) -> TemperatureField:
    if section.bulk_c is not None:
        raise CaseError("temperature.bulk_c", section.bulk_c, "absent with model = 'tabulated'",
                        "the tabulated model takes flank, base-circle and bore temperatures")
    if section.csv is not None:
        if section.gamma is not None or section.flank_c is not None:
            raise CaseError("temperature.csv", section.csv, "either csv or gamma/flank_c",
                            "the flank temperature table is given twice")
        gamma, flank_c = read_flank_table_csv(section.csv, directory)
    else:
        if section.gamma is None or section.flank_c is None:
            raise CaseError("temperature.gamma", section.gamma, "gamma and flank_c lists, or csv",
                            "model = 'tabulated' needs a flank temperature table")
        gamma, flank_c = section.gamma, section.flank_c
    if section.pinion_base_c is None or section.pinion_bore_c is None:
        name = "pinion_base_c" if section.pinion_base_c is None else "pinion_bore_c"
        raise CaseError(f"temperature.{name}", None, "a temperature in °C",
                        "both thermal models (thermoelastic and luo2020) size each gear by its base-circle expansion "
                        "(the annulus of Luo & Li Eq. 10), which needs the base-circle and bore temperatures")
    wheel = {}
    for part in ("base", "bore"):
        value = getattr(section, f"wheel_{part}_c")
        if value is None:
            value = getattr(section, f"pinion_{part}_c")
            warnings.warn(f"temperature.wheel_{part}_c not given: the wheel's {part} temperature is taken equal to "
                          f"the pinion's ({value} °C)", ModelAssumptionWarning, stacklevel=3)
        wheel[part] = value
    return TemperatureField.from_table(
        gamma, flank_c, section.fit_degree, pinion_base_c=section.pinion_base_c,
        pinion_bore_c=section.pinion_bore_c, wheel_base_c=wheel["base"], wheel_bore_c=wheel["bore"],
        reference_c=section.reference_c, wheel_flank_offset_c=section.wheel_flank_offset_c,
        source="tabulated (csv)" if section.csv is not None else "tabulated")


def read_flank_table_csv(name: str, directory: Path | None = None) -> tuple[list[float], list[float]]:
    """Read a flank temperature table from a CSV file with a header row naming the columns ``gamma`` and
    ``flank_c`` (other columns ignored). Relative paths are taken from the case file's folder."""
    path = Path(name)
    if not path.is_absolute() and directory is not None:
        path = directory / path
    if not is_existing_file(path):
        raise CaseError("temperature.csv", name, "an existing CSV file (relative to the case file)",
                        f"no such file ({shown_value(str(path))})")
    text = read_user_text(path, "temperature.csv", name, "CSV")
    lines = [row for row in text.splitlines() if row.strip() and not row.lstrip().startswith("#")]
    reader = csv.DictReader(lines)
    columns = [c.strip() for c in (reader.fieldnames or [])]
    if "gamma" not in columns or "flank_c" not in columns:
        raise CaseError("temperature.csv", name, "a header with columns gamma, flank_c",
                        f"the first line names no gamma and flank_c columns ({len(columns)} columns); the file's "
                        "content is not shown")
    gamma, flank_c = [], []
    for line, row in enumerate(reader, start=2):
        row = {key.strip(): value for key, value in row.items() if key is not None}
        try:
            gamma.append(float(row["gamma"]))
            flank_c.append(float(row["flank_c"]))
        except (TypeError, ValueError):
            raise CaseError("temperature.csv", name, "numbers in the gamma and flank_c columns",
                            f"row {line} has no number in gamma or flank_c") from None
    return gamma, flank_c


__all__ = ["DEFAULT_LUBRICANT_DATA_MAXIMUM_C", "FIT_OVERSHOOT_ABSOLUTE_K", "FIT_OVERSHOOT_RELATIVE", "GAMMA_SPAN_TOLERANCE",
           "LUO2020_LIMITS", "MATERIAL_MAXIMUM_C", "MATERIAL_MINIMUM_C", "THERMOELASTIC_LIMITS",
           "TemperatureField", "TemperatureLimits", "check_flank_table", "check_temperatures",
           "fit_flank_polynomial", "read_flank_table_csv", "temperature_field_from_section"]
