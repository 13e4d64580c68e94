"""Tooth temperature input of the thermal model: flank temperature along the path of contact, base-circle and
bore temperatures of each gear, and the stress-free reference (assembly) temperature.

Three sources, chosen in the case file (``[temperature].model``):

- ``"uniform"``: one bulk temperature for the whole gear body (flank, base circle and bore);
- ``"tabulated"``: flank temperatures at contact positions Γ (in the case or a CSV file), fitted by a polynomial
  in Γ of ``fit_degree`` as Luo & Li (2020) do for their Fig. 3(c), with base-circle and bore temperatures per gear;
- ``"fem"``: the finite-element bulk-temperature model (docs/fem.md). It plugs in through
  :func:`register_temperature_provider` or is found by name in :mod:`thermogear.composition`; where neither
  gives it, asking for it is an error.

Temperatures are °C here; the expansion uses the rises above ``reference_c`` (Timoshenko & Goodier 1951: Eq. 10 holds for
rises above the stress-free state, which the paper does not say).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from thermogear.temperature.kinds import temperature_source
from thermogear import warning_scope
from thermogear.case import cached_per_case
from thermogear.composition import TEMPERATURE_PROVIDERS, builtin
from thermogear.errors import ModelAssumptionWarning, ThermogearError
from thermogear.choices.thermal_models import thermal_model_rules
# The field, its checks and the fit need no case machinery: they live in thermogear.temperature.field so that the
# case loader can run them at load time; re-exported here, where the rest of the thermal model looks for them.
from thermogear.temperature.field import (DEFAULT_LUBRICANT_DATA_MAXIMUM_C, FIT_OVERSHOOT_ABSOLUTE_K,  # noqa: F401
                                          FIT_OVERSHOOT_RELATIVE, GAMMA_SPAN_TOLERANCE, MATERIAL_MAXIMUM_C,
                                          MATERIAL_MINIMUM_C, TemperatureLimits,
                                          TemperatureField, check_flank_table, check_temperatures,
                                          fit_flank_polynomial, read_flank_table_csv,
                                          temperature_field_from_section)

if TYPE_CHECKING:
    from pathlib import Path

    from thermogear.geometry import GearPair
    from thermogear.lubricant import Lubricant
    from thermogear.schema.lubricant import LubricantSection
    from thermogear.schema.temperature import TemperatureSection
    from thermogear.schema.thermal import ThermalSection

# ------------------------------------------------------------------------------------------- case wiring
TemperatureProvider = Callable[..., TemperatureField]  # its parameters name pieces (thermogear.case.pieces)
_PROVIDERS: dict[str, TemperatureProvider] = {}


def register_temperature_provider(name: str, provider: TemperatureProvider) -> None:
    """Plug in a temperature source selectable as ``[temperature].model = name`` (the finite-element bulk
    temperature model registers ``"fem"``). The provider receives the pieces of the case its parameters name
    (:mod:`thermogear.case.pieces`; ``provider(case)``: the whole case) and returns a TemperatureField."""
    if not callable(provider):
        raise TypeError("provider must be callable: provider(case) -> TemperatureField")
    _PROVIDERS[name] = provider


def temperature_provider(temperature: "TemperatureSection") -> TemperatureProvider:
    """The provider of the tooth temperatures a ``[temperature]`` section's model names (registered, else built in:
    :data:`thermogear.composition.TEMPERATURE_PROVIDERS`); ThermogearError where none is installed. The chooser of
    the piece ``provided_temperature_field`` (:data:`thermogear.composition.CHOSEN_PIECES`)."""
    provider = _PROVIDERS.get(temperature.model) or builtin(TEMPERATURE_PROVIDERS, temperature.model)
    if provider is None:
        raise ThermogearError(f"temperature.model = '{temperature.model}': the finite-element bulk-temperature "
                              "model is not registered (its module is not installed); use "
                              "'uniform' or 'tabulated'")
    return provider


@cached_per_case
def temperature_field_from_case(temperature: "TemperatureSection", gear_pair: "GearPair", directory: "Path | None",
                                lubricant: "LubricantSection", thermal: "ThermalSection",
                                provided_temperature_field_of: Callable[[], TemperatureField],
                                oil_of: Callable[[], "Lubricant"]) -> TemperatureField:
    """Build and check the TemperatureField of a case: its ``[temperature]`` section as given (files relative to
    the case's ``directory``), else the field its model's provider gives (asked for only then). Raises CaseError
    for bad input and ThermogearError when the ``fem`` model is asked for but not available. Called with the case
    (``temperature_field_from_case(case)``), memoised per case (:func:`thermogear.case.cached_per_case`)."""
    section = temperature
    points = gear_pair.path_points
    gamma_start, gamma_end = (float(gear_pair.gamma(points["A"])), float(gear_pair.gamma(points["E"])))
    if temperature_source(section.model).given:
        field = temperature_field_from_section(section, directory)
    else:
        field = provided_temperature_field_of()  # the provider, with the pieces it names (thermogear.case.pieces)
    # the highest temperature of the lubricant's viscosity data [°C]: the case's viscosity points, else the fitted
    # range of the case's oil (a built-in oil's data)
    data_maximum_c = _viscosity_data_maximum_c(lubricant.viscosity_points)
    if data_maximum_c is None:
        with warning_scope.ignored(ModelAssumptionWarning):  # the lubricant model reports its own assumptions
            data_maximum_c = float(oil_of().fitted_range_c[1])
    check_temperatures(field, gamma_start, gamma_end, data_maximum_c,
                       limits=thermal_model_rules(thermal.model).temperature_limits)
    return field


def _viscosity_data_maximum_c(points) -> float | None:
    """Highest temperature of a case's own viscosity points [(°C, mm²/s)] [°C], None where it gives none."""
    return float(max(temperature for temperature, _ in points)) if points else None
