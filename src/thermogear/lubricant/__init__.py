"""Lubricant properties: kinematic viscosity (ASTM D341 / Walther), density and dynamic viscosity versus temperature.

Functions (layer 1) take and return SI values, temperatures in °C; kelvin and centistokes appear only inside the
Walther law. :class:`Lubricant` (layer 2) holds one oil; :func:`builtin_lubricant` reads the library
``thermogear/lubricants/oils.toml`` and :func:`lubricant_from_case` builds the oil a case selects.

Sources: ASTM D341 (Walther equation, two-point form), density law and per-base-oil
coefficients of the GEARpie lubricant library (C.M.C.G. Fernandes), lubricant factor X_L of DIN 3990-4 /
ISO/TR 13989-1 (recalled, not checked against the standard's text).
"""

from __future__ import annotations

import threading
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning, ModelAssumptionWarning, closest_key

if TYPE_CHECKING:  # pragma: no cover
    from thermogear.schema.lubricant import LubricantSection

#: Constant of the Walther double logarithm, ν + 0.7 with ν in mm²/s (ASTM D341, valid for ν ≥ 2 mm²/s).
WALTHER_OFFSET_CST = 0.7
#: Absolute zero offset [K].
KELVIN = 273.15

#: Lubricant factor X_L of the DIN 3990-4 / ISO/TR 13989-1 mean friction coefficient per base oil
#: (ISO/TR 13989-1, recalled [R]; the standard's entry for esters is "phosphate ester").
LUBRICANT_FACTORS = {"mineral": 1.0, "pao": 0.8, "pag_insoluble": 0.7, "pag_soluble": 0.6, "ester": 1.3,
                     "traction": 1.5}
#: Density at 15 °C [kg/m³] and its relative temperature coefficient [1/K] per base oil (GEARpie
#: LUBRICANT_LIBRARY.py, base-oil entries M, P, E, G; PAG values for both PAG kinds; traction fluids assumed
#: like PAO). Used only when a user-defined oil gives no density.
BASE_OIL_DENSITY = {"mineral": (902.0, -5.8e-4), "pao": (859.0, -5.5e-4), "ester": (915.0, -8.1e-4),
                    "pag_insoluble": (1059.0, -7.1e-4), "pag_soluble": (1059.0, -7.1e-4),
                    "traction": (859.0, -5.5e-4)}


# ---------------------------------------------------------------------------------------------- functions
def walther_constants(points_c_cst: Sequence[Sequence[float]], key: str = "lubricant.viscosity_points"
                      ) -> tuple[float, float]:
    """Constants (A, B) of log10 log10(ν + 0.7) = A − B·log10 T through viscosity points (ASTM D341).

    Two points give the exact fit (ASTM D341); more points a least-squares fit of the straight line in
    Walther coordinates. ``points_c_cst`` is [[temperature °C, ν mm²/s], ...].

    Raises CaseError (naming ``key``) for fewer than two points, repeated temperatures, viscosities below the
    law's range, or a viscosity that does not fall as the temperature rises.
    """
    from thermogear.schema.lubricant import check_viscosity_points  # noqa: PLC0415  (the schema: pydantic)

    temperature_c, viscosity = check_viscosity_points(points_c_cst, key)
    x = np.log10(temperature_c + KELVIN)
    y = np.log10(np.log10(viscosity + WALTHER_OFFSET_CST))
    slope, intercept = np.polyfit(x, y, 1)
    return float(intercept), float(-slope)


def walther_kinematic_viscosity(temperature_c, walther_a: float, walther_b: float):
    """Kinematic viscosity ν(T) [m²/s] from the ASTM D341 constants (A, B) (T in °C, ν in mm²/s inside).

    ν = 10^(10^(A − B·log10 T)) − 0.7  [mm²/s],  T in K.
    """
    temperature_k = np.asarray(temperature_c, dtype=float) + KELVIN
    if np.any(temperature_k <= 0.0):
        raise CaseError("temperature_c", temperature_c, "> -273.15 °C", "below absolute zero")
    viscosity_cst = 10.0 ** (10.0 ** (walther_a - walther_b * np.log10(temperature_k))) - WALTHER_OFFSET_CST
    return viscosity_cst * 1e-6


def linear_density(temperature_c, density_reference: float, reference_c: float, coefficient: float):
    """Density ρ(T) = ρ_ref·[1 + α_T·(T − T_ref)] [kg/m³] (the density law of the GEARpie lubricant library)."""
    return density_reference * (1.0 + coefficient * (np.asarray(temperature_c, dtype=float) - reference_c))


def check_fitted_range(temperature_c, fitted_range_c: tuple[float, float], what: str, stacklevel: int = 3
                       ) -> None:
    """Warn (ExtrapolationWarning) when temperatures leave a fit's range, saying by how much."""
    temperature = np.asarray(temperature_c, dtype=float)
    if temperature.size == 0:
        return
    low, high = fitted_range_c
    below = low - float(np.min(temperature))
    above = float(np.max(temperature)) - high
    if below > 0.0 or above > 0.0:
        parts = []
        if below > 0.0:
            parts.append(f"{below:.1f} K below")
        if above > 0.0:
            parts.append(f"{above:.1f} K above")
        shown = (f"{float(np.min(temperature)):.1f} °C" if np.ptp(temperature) == 0.0 else
                 f"{float(np.min(temperature)):.1f}–{float(np.max(temperature)):.1f} °C")
        warnings.warn(f"{what}: temperature {shown} is {' and '.join(parts)} the fitted range {low:g}–{high:g} °C; the ASTM D341 line is "
                      "extrapolated", ExtrapolationWarning, stacklevel=stacklevel)


# --------------------------------------------------------------------------------------------- component
@dataclass(frozen=True)
class Lubricant:
    """One oil: the ASTM D341 constants of its kinematic viscosity, its density law and base oil.

    ``walther_a``, ``walther_b``: log10 log10(ν[mm²/s] + 0.7) = A − B·log10 T[K].
    ``density_reference`` [kg/m³] at ``density_reference_c`` [°C], relative change ``density_coefficient``
    [1/K]. ``fitted_range_c``: span of the viscosity points [°C]; outside it the law warns.
    """

    name: str
    source: str
    walther_a: float
    walther_b: float
    density_reference: float  # [kg/m³]
    density_reference_c: float  # [°C]
    density_coefficient: float  # [1/K]
    base_oil: str
    fitted_range_c: tuple[float, float]
    title: str = ""
    viscosity_points: tuple[tuple[float, float], ...] = ()  # [(°C, mm²/s), ...] as given

    @classmethod
    def from_points(cls, name: str, points_c_cst: Sequence[Sequence[float]], density: float | None = None,
                    density_reference_c: float = 15.0, density_coefficient: float | None = None,
                    base_oil: str = "mineral", source: str = "user-defined", title: str = "",
                    key: str = "lubricant.viscosity_points") -> "Lubricant":
        """An oil from two or more (temperature °C, ν mm²/s) points; density [kg/m³] at density_reference_c.

        Missing density or coefficient: the base oil's typical value (``BASE_OIL_DENSITY``).
        """
        if base_oil not in LUBRICANT_FACTORS:
            raise CaseError("lubricant.base_oil", base_oil, ", ".join(LUBRICANT_FACTORS), "unknown base oil")
        walther_a, walther_b = walther_constants(points_c_cst, key)
        typical_density, typical_coefficient = BASE_OIL_DENSITY[base_oil]
        density = typical_density if density is None else float(density)
        coefficient = typical_coefficient if density_coefficient is None else float(density_coefficient)
        if not density > 0.0:
            raise CaseError("lubricant.density_kg_m3", density, "> 0", "a density must be positive")
        if coefficient > 0.0:
            raise CaseError("lubricant.density_coefficient_per_k", coefficient, "<= 0",
                            "an oil expands (gets lighter) when heated")
        temperatures = [float(point[0]) for point in points_c_cst]
        return cls(name=name, source=source, walther_a=walther_a, walther_b=walther_b,
                   density_reference=density, density_reference_c=float(density_reference_c),
                   density_coefficient=coefficient, base_oil=base_oil,
                   fitted_range_c=(min(temperatures), max(temperatures)), title=title,
                   viscosity_points=tuple((float(t), float(v)) for t, v in points_c_cst))

    def kinematic_viscosity(self, temperature_c, warn: bool = True):
        """ν(T) [m²/s] (ASTM D341). Warns when T leaves the fitted range."""
        if warn:
            check_fitted_range(temperature_c, self.fitted_range_c, f"viscosity of oil '{self.name}'")
        return walther_kinematic_viscosity(temperature_c, self.walther_a, self.walther_b)

    def density(self, temperature_c):
        """ρ(T) [kg/m³] (linear law about the reference temperature)."""
        return linear_density(temperature_c, self.density_reference, self.density_reference_c,
                              self.density_coefficient)

    def dynamic_viscosity(self, temperature_c, warn: bool = True):
        """η(T) = ν(T)·ρ(T) [Pa·s]."""
        if warn:
            check_fitted_range(temperature_c, self.fitted_range_c, f"viscosity of oil '{self.name}'")
        return self.kinematic_viscosity(temperature_c, warn=False) * self.density(temperature_c)

    @property
    def lubricant_factor(self) -> float:
        """X_L of the DIN 3990-4 / ISO/TR 13989-1 friction formula for this base oil (ISO/TR 13989-1, [R])."""
        return LUBRICANT_FACTORS[self.base_oil]

    def viscosity_index_points(self) -> dict[str, float]:
        """ν at 40 and 100 °C [mm²/s] (the usual data-sheet pair), for display."""
        return {"40": float(self.kinematic_viscosity(40.0, warn=False) * 1e6),
                "100": float(self.kinematic_viscosity(100.0, warn=False) * 1e6)}


# ------------------------------------------------------------------------------------------------ library
def builtin_lubricant_names() -> list[str]:
    """Names of the built-in oils (``thermogear oils``)."""
    from thermogear.lubricants import oil_records

    def order(name: str):
        parts = name.split("_")
        grade = next((int(part) for part in parts if part.isdigit()), 0)
        return (name.startswith("iso_vg_"), parts[-1], grade, name)

    return sorted(oil_records(), key=order)


def builtin_lubricant(name: str) -> Lubricant:
    """A built-in oil by name (``"sch632"``, ``"iso_vg_100_mineral"``, ...)."""
    from thermogear.lubricants import oil_records

    records = oil_records()
    if name not in records:
        suggestion = closest_key(name, records)
        hint = f" (did you mean '{suggestion}'?)" if suggestion else ""
        raise CaseError("lubricant.name", name, "a built-in oil (see `thermogear oils`) or viscosity_points",
                        f"no such built-in oil{hint}")
    record = records[name]
    return Lubricant.from_points(name, record["viscosity_points"], density=record["density_kg_m3"],
                                 density_reference_c=record["density_reference_c"],
                                 density_coefficient=record["density_coefficient_per_k"],
                                 base_oil=record["base_oil"], source=record["source"], title=record["title"],
                                 key=f"lubricants/oils.toml:{name}.viscosity_points")


def _lubricant_from_pieces(lubricant: "LubricantSection", source: str) -> Lubricant:
    """The oil a case selects (its ``[lubricant]`` section; ``source``: the case file or parameter set, named in the
    oil's source): a built-in one (optionally with the case's density or
    base oil), or its own ``viscosity_points``. Called with the case (``lubricant_from_case(case)``, memoised per
    case, :func:`thermogear.case.cached_per_case`)."""
    section = lubricant
    if section.viscosity_points is None:
        oil = builtin_lubricant(section.name)
        changes = {}
        if section.density_kg_m3 is not None:
            changes.update(density_reference=float(section.density_kg_m3),
                           density_reference_c=float(section.density_reference_c))
        if section.density_coefficient_per_k is not None:
            changes["density_coefficient"] = float(section.density_coefficient_per_k)
        if section.base_oil is not None:
            changes["base_oil"] = section.base_oil
        if changes:
            from dataclasses import replace

            oil = replace(oil, source=oil.source + " Case file overrides: " + ", ".join(sorted(changes)) + ".",
                          **changes)
        return oil
    if section.base_oil is None:
        warnings.warn("lubricant.base_oil not given: assumed 'mineral' (it sets the friction formula's lubricant "
                      "factor X_L and the default density)", ModelAssumptionWarning, stacklevel=2)
    return Lubricant.from_points(section.name or "custom", section.viscosity_points, density=section.density_kg_m3,
                                 density_reference_c=section.density_reference_c,
                                 density_coefficient=section.density_coefficient_per_k,
                                 base_oil=section.base_oil or "mineral",
                                 source=f"case file {source} [lubricant]")


_RESOLVER_LOCK = threading.Lock()


def __getattr__(name: str):
    """``lubricant_from_case`` (:func:`_lubricant_from_pieces` memoised per case by
    :func:`thermogear.case.cached_per_case`), made when first asked for: thermogear.case imports the case schema
    (pydantic), 0.5 s of CPU that a study's worker process, which only evaluates the oil it was sent in a model,
    need not pay."""
    if name != "lubricant_from_case":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    with _RESOLVER_LOCK:
        if name not in globals():
            from thermogear.case import cached_per_case  # noqa: PLC0415

            resolver = cached_per_case(_lubricant_from_pieces)
            resolver.__name__ = resolver.__qualname__ = name
            globals()[name] = resolver
    return globals()[name]


__all__ = ["BASE_OIL_DENSITY", "LUBRICANT_FACTORS", "Lubricant", "builtin_lubricant", "builtin_lubricant_names",
           "check_fitted_range", "linear_density", "lubricant_from_case", "walther_constants",
           "walther_kinematic_viscosity"]
