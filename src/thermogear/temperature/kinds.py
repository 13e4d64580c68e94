"""The kinds of tooth temperature source, chosen once: ``[temperature] model`` resolved here into what the rest of
the package asks (does the case give the temperatures, is it one bulk temperature, a table along the path, computed
by a model, predicted when the case is loaded), never compared as a string.

* ``"uniform"``: one bulk temperature for the whole gear body, given in the case;
* ``"tabulated"``: flank temperatures along the path of contact with base-circle and bore temperatures, given;
* ``"fem"``: computed by the finite-element bulk-temperature model (its provider, :mod:`thermogear.composition`);
* ``"gearbox"``: predicted by the gearbox thermal network when the case is loaded.

A model registered at run time under another name predicts the temperatures at load time. This module imports nothing of thermogear, so every layer may
read it.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["TEMPERATURE_SOURCES", "TemperatureSourceKind", "temperature_source"]


@dataclass(frozen=True)
class TemperatureSourceKind:
    """What a ``[temperature] model`` is: ``given`` (the case's own numbers, read by
    :func:`thermogear.temperature.field.temperature_field_from_section`), ``uniform`` (one bulk temperature),
    ``tabulated`` (flank temperatures along the path), ``predicted_at_load`` (a model sets the case's temperatures
    when it is loaded), ``solved_per_state`` (each operating state runs a field solution: the FE model),
    ``takes_helical`` (a helical pair may use it: the given temperatures, and the gearbox network, whose losses take
    the helix; the FE model's heat input is the spur pair's)."""

    name: str
    given: bool
    takes_helical: bool
    uniform: bool = False
    tabulated: bool = False
    predicted_at_load: bool = False
    solved_per_state: bool = False

    @property
    def computed(self) -> bool:
        """Whether a model computes the temperatures (its provider), rather than the case giving them."""
        return not self.given


#: Every built-in temperature source by name: the one place the names are compared.
TEMPERATURE_SOURCES: dict[str, TemperatureSourceKind] = {kind.name: kind for kind in (
    TemperatureSourceKind("uniform", given=True, takes_helical=True, uniform=True),
    TemperatureSourceKind("tabulated", given=True, takes_helical=True, tabulated=True),
    TemperatureSourceKind("fem", given=False, takes_helical=False, solved_per_state=True),
    TemperatureSourceKind("gearbox", given=False, takes_helical=True, predicted_at_load=True),
)}


def temperature_source(name: str) -> TemperatureSourceKind:
    """The kind of the temperature source ``name``; a name outside :data:`TEMPERATURE_SOURCES` is a model
    registered at run time, which predicts the case's temperatures when it is loaded
    (:func:`thermogear.case.register_temperature_model`) and gives the field through its provider."""
    return TEMPERATURE_SOURCES.get(name) or TemperatureSourceKind(name, given=False, takes_helical=False,
                                                                      predicted_at_load=True)
