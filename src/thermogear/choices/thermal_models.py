"""What each ``[thermal] model`` asks of a case's input, as data of the model, resolved from its name once.

The case is validated below the mesh layer (where the pair models live), so the input rules of a thermal model
cannot be read from its pair model class at load time. They live here, one frozen :class:`ThermalModelRules` per
model, and the pair model of the same name refers to the same object
(:attr:`thermogear.mesh.pair_models.PairModelBase.rules`). Code that validates or reads a case asks
:func:`thermal_model_rules` for the rules of the case's model and reads their fields; no code outside this module
and the pair-model registry compares a model's name.

Adding a thermal model that a case file can choose takes one :class:`ThermalModelRules` line in
:data:`THERMAL_MODEL_RULES` (the ``[thermal] model`` schema accepts exactly its names) and one pair-model class with
its line in :data:`thermogear.mesh.pair_models.PAIR_MODELS`. This module imports no case machinery.
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.errors import CaseError
from thermogear.temperature.field import LUO2020_LIMITS, THERMOELASTIC_LIMITS, TemperatureLimits


@dataclass(frozen=True)
class ThermalModelRules:
    """The input rules of one thermal model.

    ``name``: its ``[thermal] model`` value. ``temperature_limits``: the gear temperatures it can evaluate (checked
    when the case is loaded). ``reads_x_te``: True where its stiffness rests on the paper's thermal-load factor X_te
    (Luo & Li (2020) Eqs. 13–23), so X_te must be given or calibrated. ``expands_geometry``: True where it expands
    gears and housing with temperature, so backlash and jamming at the operating temperatures are checked at load.
    ``own_keys``: ``[thermal]`` keys that only this model reads (a case of another model that sets them is told
    they have no effect). ``spur_only``: True where the model is defined for spur pairs only (a helical case is
    refused at load).
    """

    name: str
    temperature_limits: TemperatureLimits
    reads_x_te: bool = False
    expands_geometry: bool = False
    own_keys: tuple[str, ...] = ()
    spur_only: bool = False


#: The predictive thermo-elastic model: E(T), expansion of gears and housing, backlash and flank deviations.
THERMOELASTIC_RULES = ThermalModelRules("thermoelastic", THERMOELASTIC_LIMITS, expands_geometry=True)

#: The paper's secant k_T with X_te (Luo & Li (2020) Eqs. 13–23): X_te and how it is found are its own keys.
LUO2020_RULES = ThermalModelRules(
    "luo2020", LUO2020_LIMITS, reads_x_te=True,
    own_keys=("x_te", "x_te_source", "calibration_drop_percent", "calibration_point", "load_basis",
              "expansion_model"), spur_only=True)

#: The rules per ``[thermal] model`` name; the first is the schema's default. One line per model.
THERMAL_MODEL_RULES: dict[str, ThermalModelRules] = {
    THERMOELASTIC_RULES.name: THERMOELASTIC_RULES,
    LUO2020_RULES.name: LUO2020_RULES,
}


def thermal_model_rules(name: str) -> ThermalModelRules:
    """The rules of the thermal model called ``name``: the one place such a name is resolved for the input checks."""
    try:
        return THERMAL_MODEL_RULES[name]
    except KeyError:
        raise CaseError("thermal.model", name, " | ".join(THERMAL_MODEL_RULES), "no thermal model of this name") from None


@dataclass(frozen=True)
class XTeSource:
    """Where the X_te of a model that reads it comes from (``[thermal] x_te_source``): ``given`` — the case's
    ``thermal.x_te``; ``calibrated`` — solved for the X_te that gives ``thermal.calibration_drop_percent`` at
    ``thermal.calibration_point``; neither — computed by the provider of that name
    (:data:`thermogear.composition.X_TE_PROVIDERS`, the finite-element analysis for ``"fem"``)."""

    name: str
    given: bool = False
    calibrated: bool = False

    @property
    def provided(self) -> bool:
        """Whether a model's provider computes X_te (neither given nor calibrated)."""
        return not (self.given or self.calibrated)


#: The sources of X_te per ``[thermal] x_te_source`` name (the schema's values, in its order): the one place the
#: names are compared.
X_TE_SOURCES: dict[str, XTeSource] = {source.name: source for source in (
    XTeSource("given", given=True), XTeSource("calibrated", calibrated=True), XTeSource("fem"))}


def x_te_source(name: str) -> XTeSource:
    """The X_te source called ``name`` (``[thermal] x_te_source``)."""
    try:
        return X_TE_SOURCES[name]
    except KeyError:
        raise CaseError("thermal.x_te_source", name, " | ".join(X_TE_SOURCES),
                        "no source of X_te of this name") from None


__all__ = ["LUO2020_RULES", "THERMAL_MODEL_RULES", "THERMOELASTIC_RULES", "ThermalModelRules", "X_TE_SOURCES",
           "XTeSource", "thermal_model_rules", "x_te_source"]
