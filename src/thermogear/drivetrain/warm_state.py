"""The warm state of a case's drivetrain: each shaft's temperature and where it came from, and each bearing's play at
its ring temperatures, as the hot drivetrain of :mod:`thermogear.drivetrain.case_model` takes them and as ``run``
reports them (the ``warm_state`` record: per shaft the temperature and its source; per bearing, where a temperature
model gives its rings, their temperatures, the play as mounted and hot, the static radial load and the loss).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from thermogear.drivetrain.assembly import Drivetrain
from thermogear.drivetrain.heat_source import DrivetrainHeat

__all__ = ["operating_clearances", "shaft_temperatures", "with_clearances"]


def shaft_temperatures(section, tooth_c: float, heat: DrivetrainHeat | None,
                       thermoelastic: bool) -> tuple[dict[str, float], dict[str, Any], str | None]:
    """Each shaft's temperature in the warm state [°C], the warm-state record for the output (each shaft's
    temperature and where it came from) and a note on the shafts whose temperature was not given: the shaft's own
    ``temperature_c``, else the temperature model's prediction (``heat``), else the gears' mean tooth temperature
    ``tooth_c`` (thermo-elastic model, an upper bound) or, under the paper's model, ``tooth_c`` = the case's bulk
    temperature (else 20 °C)."""
    defaulted = [shaft.name for shaft in section.shafts if shaft.temperature_c is None]
    names = ", ".join(defaulted)
    if heat is not None:
        source, note = heat.source, f"drivetrain: {names} at {heat.source}"
    elif thermoelastic:
        source = "the gears' mean tooth temperature (an upper bound)"
        note = (f"drivetrain: {names} taken at the gears' mean tooth temperature {tooth_c:.1f} °C in the warm state "
                "(give drivetrain.shafts.temperature_c to change it)")
    else:
        source = "the case's bulk temperature, else 20 °C"
        note = (f"drivetrain: {names} taken at {tooth_c:g} °C in the warm state (the case's bulk temperature, else "
                "20 °C) with carbon steel's β_E; under the paper's thermal model the mesh keeps its cold geometry, "
                "only its stiffness changes")
    temperatures, shafts = {}, {}
    for shaft in section.shafts:
        if shaft.temperature_c is not None:
            value, given = float(shaft.temperature_c), "given (drivetrain.shafts.temperature_c)"
        else:
            value, given = (heat.shaft_temperature_c[shaft.name] if heat is not None else tooth_c), source
        temperatures[shaft.name] = value
        shafts[shaft.name] = {"temperature_c": float(value), "source": given}
    record: dict[str, Any] = {"shafts": shafts, "bearings": {}}
    if heat is not None:
        record["network_c"] = dict(heat.nodes_c)
        record["source"] = heat.source
    return temperatures, record, note if defaulted else None


def operating_clearances(section, heat: DrivetrainHeat | None, warm_state: dict[str, Any],
                          notes: list[str]) -> dict[str, float]:
    """Each bearing's play ± c [m] at its ring temperatures where the temperature model gives them and the
    bearing's size is known (:mod:`~thermogear.drivetrain.bearing_clearance`); recorded in ``warm_state``."""
    if heat is None:
        return {}
    clearances = {}
    for bearing in section.bearings:
        rings = heat.bearings.get(bearing.name)
        mounted = bearing.radial_clearance_um * 1e-6
        operating = heat.clearance(bearing.name, mounted)
        entry: dict[str, Any] = {"inner_ring_c": None if rings is None else float(rings.inner_c),
                                 "outer_ring_c": None if rings is None else float(rings.outer_c),
                                 "mounted_clearance_um": bearing.radial_clearance_um,
                                 "static_radial_load_n": None if rings is None else rings.radial_load,
                                 "loss_w": None if rings is None else rings.loss}
        if operating is None:
            entry.update(operating_clearance_um=bearing.radial_clearance_um, clearance_source="held (the bearing's "
                         "size is not given: no loss data)")
        else:
            clearances[bearing.name] = operating.operating
            entry.update(operating_clearance_um=operating.operating * 1e6, clearance_source="ring temperatures "
                         "(differential expansion)", taken_up=operating.taken_up)
            if operating.taken_up:
                notes.append(f"drivetrain: the clearance of {bearing.name} ({bearing.radial_clearance_um:g} μm) is "
                             f"taken up by its hotter inner ring ({operating.inner_c:.1f} °C against "
                             f"{operating.outer_c:.1f} °C): no play in the hot drivetrain (a preload is not modelled)")
        warm_state["bearings"][bearing.name] = entry
    return clearances


def with_clearances(drivetrain: Drivetrain, clearances: dict[str, float]) -> Drivetrain:
    """The drivetrain with the bearings named in ``clearances`` given that play ± c [m]."""
    if not clearances:
        return drivetrain
    return replace(drivetrain, bearings=tuple(replace(bearing, radial_clearance=clearances[bearing.name])
                                              if bearing.name in clearances else bearing
                                              for bearing in drivetrain.bearings))

