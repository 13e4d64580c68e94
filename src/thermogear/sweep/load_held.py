"""Which load a study holds from point to point — constant torque or constant power — said on every sweep output.

The mesh model of one case holds the load the case gives: a power is a torque P/ω1 that falls with speed (constant
power), a torque stays (constant torque; ``OperatingPoint.load_held``). A study over speed holds the torque instead:
a case that gives a power is run at the torque of that power at the case's own speed (``Study.fixed_changes``),
unless the study varies the load itself. Both are legitimate and give different Kv against speed, so the store's
attributes, the command's summary and JSON, the plot and the CSV export all name the one used (issue 24).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from thermogear.registry import registered

if TYPE_CHECKING:
    from thermogear.operating import OperatingPoint

__all__ = ["DEFAULT_HOLD", "HOLDS", "HeldLoad", "fixed_load_changes", "held_load", "study_load_held"]

_POWER, _TORQUE, _STAGE, _SPEED = ("operating.power_kw", "operating.torque_nm", "operating.fzg_load_stage",
                                   "operating.speed_rpm")


@dataclass(frozen=True)
class HeldLoad:
    """A load a speed sweep keeps from speed to speed: ``name`` (the ``--hold`` value) and whether it is the power
    (``power``: the torque P/ω1 falls with speed), else the pinion torque."""

    name: str
    power: bool


#: The loads a speed sweep can keep from speed to speed, by name (the first the default): the pinion torque or the
#: power. The one place the names are compared.
HOLDS: dict[str, HeldLoad] = {held.name: held for held in (HeldLoad("torque", power=False),
                                                           HeldLoad("power", power=True))}
#: The load a speed sweep keeps unless told (a study's description names any other).
DEFAULT_HOLD = next(iter(HOLDS))


def held_load(name: str) -> HeldLoad:
    """The held load called ``name``; a CaseError naming ``--hold`` for any other."""
    return registered(HOLDS, name, "--hold", "the load a speed sweep keeps from speed to speed")


def fixed_load_changes(given: dict[str, Any], point: "OperatingPoint", parameters,
                       hold: str = DEFAULT_HOLD) -> tuple[tuple[str, Any], ...]:
    """Changes applied to every point: the load a speed sweep keeps, of a case whose ``[operating]`` table gives
    ``given`` (the keys of its file) and makes the operating ``point``. ``hold = "torque"`` (default): a case whose
    load is a power is turned into the torque of that power at the case's speed; ``"power"``: a case whose load is
    a torque (or an FZG load stage) is turned into the power of that torque at the case's speed. Nothing changes
    where the study varies a load itself, or not the speed."""
    keys = {p.key for p in parameters}
    load_keys = {"operating.torque_nm", "operating.power_kw", "operating.fzg_load_stage"}
    if "operating.speed_rpm" not in keys or keys & load_keys:
        return ()
    power = held_load(hold).power
    if not power and given.get("power_kw") is not None:
        return (("operating.power_kw", None), ("operating.torque_nm", float(point.torque)))
    if power and given.get("power_kw") is None:
        power_kw = float(point.torque) * 2.0 * math.pi * float(point.speed_rpm) / 60.0 / 1000.0
        return (("operating.fzg_load_stage", None), ("operating.torque_nm", None), ("operating.power_kw", power_kw))
    return ()


def study_load_held(study) -> tuple[str, str]:
    """``(label, note)``: ``label`` is ``"constant torque"`` or ``"constant power"``, ``note`` says why.

    Follows what the points are computed with: the varied load key if any, else (speed varied) the torque of
    the case's load at its own speed, else the case's own load (one speed: either reading gives the same load)."""
    keys = {parameter.key for parameter in study.parameters}
    if _POWER in keys:
        return "constant power", "power_kw is varied: each point holds its power, the torque is P/ω1"
    if _TORQUE in keys:
        return "constant torque", "torque_nm is varied: each point holds its torque"
    if _STAGE in keys:
        return "constant torque", "fzg_load_stage is varied: each point holds the torque of its load stage"
    operating = study.case.operating_point
    torque = float(operating.torque_at(operating.speed_rpm))
    power_kw = torque * operating.speed_rpm * 3.141592653589793 / 30.0 / 1000.0
    if _SPEED in keys:
        if held_load(getattr(study, "hold", DEFAULT_HOLD)).power:
            return "constant power", (f"--hold power: every speed runs at the case's power at {operating.speed_rpm:g} "
                                      f"rpm, {power_kw:.4g} kW (the torque P/ω1 falls with speed)")
        if operating.constant_power:
            return "constant torque", (f"the case gives a power; the speed sweep holds its torque at "
                                       f"{operating.speed_rpm:g} rpm, {torque:.4g} N·m (--hold power keeps the "
                                       "power instead)")
        return "constant torque", f"the case's torque, {torque:.4g} N·m, at every speed (--hold power keeps the power)"
    if operating.constant_power:
        return "constant power", f"the case's power at its one speed {operating.speed_rpm:g} rpm ({torque:.4g} N·m)"
    return "constant torque", f"the case's torque, {torque:.4g} N·m"
