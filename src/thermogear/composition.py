"""Where the package is assembled: which module answers each pluggable name, declared once, as data.

Some models are chosen by a name in the case file but live in a layer above the code that asks for them: the
finite-element model is the ``"fem"`` source of the tooth temperatures and of X_te (asked for by
:mod:`thermogear.luo2020`), and the gearbox thermal network is the ``"gearbox"`` temperature model (its oil and
housing temperatures predicted when the case is loaded, :mod:`thermogear.case`) with a load-time check of the
``[gearbox]`` section. Registering them by importing their modules for the side effect made the result depend
on what had been imported before (a mesh model of an ``"fem"`` case failed unless ``thermogear.simulation`` had
been imported first).

Design choice: the low layers keep their registries (``register_*`` functions, for models added by a user at run
time, which take precedence), and on a miss look the name up in the tables below, importing the target when it is
first asked for. Their import stays a run-time lookup by name, as an entry point is, so the layers contract
(a low layer imports nothing above it) holds, and asking for a model never depends on import order. This module
imports nothing of thermogear, so every layer may read it; adding a built-in provider is one line here.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable

#: The derived pieces of a case a check or provider may ask for by name (:mod:`thermogear.case.pieces`): name →
#: (its resolver, the Case field it needs: None where that section is absent, or None where every case has it).
#: A resolver's own parameters are pieces too.
CASE_PIECES: dict[str, tuple[str, str | None]] = {
    "oil": ("thermogear.lubricant:lubricant_from_case", None),
    "gearbox_model": ("thermogear.gearbox.case_model:gearbox_model_from_case", "gearbox"),
    "fem_inputs": ("thermogear.fem.inputs:fem_inputs", None),
    "temperature_field": ("thermogear.temperature.source:temperature_field_from_case", None),
    "paper_thermal_memo": ("thermogear.luo2020.thermal.case_stiffness:paper_thermal_memo", None),
    "paper_thermal_model": ("thermogear.luo2020.thermal.case_stiffness:paper_thermal_model", None),
}

#: The pieces of a case that a plug-in its section names provides (:mod:`thermogear.case.pieces`): name → the chooser,
#: ``chooser(pieces) -> plug-in``, which picks the plug-in from the section's name; the plug-in is then called with
#: the pieces it names, and its answer is the piece.
CHOSEN_PIECES: dict[str, str] = {
    "provided_temperature_field": "thermogear.temperature.source:temperature_provider",
    "provided_x_te": "thermogear.luo2020.thermal.calibration:chosen_x_te_provider",
}

#: Every check and provider below receives the pieces of the case its parameters name
#: (:func:`thermogear.case.pieces.call_with_pieces`): ``provider(fem_inputs)``, ``check(damping, oil)``.

#: ``[temperature] model`` name → the provider of its tooth temperature field, ``provider(pieces) -> TemperatureField``.
TEMPERATURE_PROVIDERS: dict[str, str] = {
    "fem": "thermogear.fem.provider:fem_temperature_field",
    "gearbox": "thermogear.gearbox.provider:gearbox_temperature_field",
}

#: ``[thermal] x_te_source`` name → the provider of X_te, ``provider(pieces) -> float``.
X_TE_PROVIDERS: dict[str, str] = {
    "fem": "thermogear.fem.provider:fem_x_te",
}

#: ``[temperature] model`` name → the model that predicts the case's oil and housing temperatures at load time,
#: ``resolver(pieces) -> {Case field: value}`` (the parts of the case it predicts, which the loader writes).
TEMPERATURE_MODELS: dict[str, str] = {
    "gearbox": "thermogear.gearbox.case_model:predicted_temperatures",
}

#: ``[temperature] model`` name → the provider of the drivetrain's shaft and bearing-ring temperatures,
#: ``provider(pieces) -> thermogear.drivetrain.heat_source.DrivetrainHeat`` (none: the drivetrain's own default).
DRIVETRAIN_HEAT: dict[str, str] = {
    "gearbox": "thermogear.gearbox.drivetrain_coupling:network_drivetrain_heat",
}

#: Load-time checks every case passes (after the built-in ones), ``check(pieces) -> None``.
CASE_CHECKS: tuple[str, ...] = (
    "thermogear.gearbox.case_model:check_gearbox_section",
    "thermogear.mesh.table_file:check_mesh_table",
    "thermogear.mesh.model:check_damping_friction_law",
)


def resolve(target: str) -> Callable | None:
    """The callable a ``"package.module:attribute"`` target names, or None where that module or attribute is not
    installed (the caller says what is missing, in its own words)."""
    module_name, _, attribute = target.partition(":")
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as error:
        # only the provider's own module (or a package above it) being absent means "not installed"; a missing
        # import inside it is a defect of that module and must surface, not read as an absent model
        if error.name is None or not (module_name + ".").startswith(error.name + "."):
            raise
        return None
    found = getattr(module, attribute, None)
    return found if callable(found) else None


def builtin(table: dict[str, str], name: str) -> Callable | None:
    """The built-in callable registered under ``name`` in one of the tables above, or None."""
    target = table.get(name)
    return None if target is None else resolve(target)


__all__ = ["CASE_CHECKS", "CASE_PIECES", "DRIVETRAIN_HEAT", "TEMPERATURE_MODELS", "TEMPERATURE_PROVIDERS", "X_TE_PROVIDERS", "builtin", "resolve"]
