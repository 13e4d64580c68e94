"""Keys of a case that have no effect under the models it chooses.

A case file may hold keys of a model it does not run: the paper's thermal stiffness (``thermal.model =
"luo2020"``, Luo & Li 2020 Eqs. 13–23) reads X_te and how it is found; the thermo-elastic model (the default) reads
none of them. Such keys are accepted (a case may carry the paper's settings to show that model beside the
default, as ``thermogear stiffness --thermal`` does when X_te is complete), but a key that no output reads is named
at load time, with the model that would read it, as one :class:`~thermogear.errors.IneffectiveKeyWarning`.

Rules (each from what the code reads, not from a case's name):

* keys that another thermal model declares its own
  (:attr:`~thermogear.choices.thermal_models.ThermalModelRules.own_keys`) have no effect under the case's ``thermal.model``; the paper's keys (:data:`LUO2020_KEYS`), of a model that
  reads X_te, are excepted when they make a complete X_te (given with ``x_te``, calibrated with
  ``calibration_drop_percent``, or from the FE model): only then is the paper's model computed beside the default;
* ``dynamics.mesh = "linear"``: ``dynamics.damping_in_flight`` (teeth in flight through the backlash) has no effect,
  since the linear mesh keeps every pair in contact.
"""

from __future__ import annotations

import warnings

from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import IneffectiveKeyWarning
from thermogear.choices.thermal_models import LUO2020_RULES, THERMAL_MODEL_RULES, thermal_model_rules, x_te_source

__all__ = ["LUO2020_KEYS", "keys_without_effect", "luo2020_complete", "warn_keys_without_effect"]

#: [thermal] keys read only by the paper's thermal stiffness (its rules' own keys).
LUO2020_KEYS = LUO2020_RULES.own_keys


def luo2020_complete(thermal) -> bool:
    """True when the [thermal] section defines X_te completely (the paper's model can be computed from it)."""
    source = x_te_source(thermal.x_te_source)
    if source.given:
        return thermal.x_te is not None
    if source.calibrated:
        return thermal.x_te is None and thermal.calibration_drop_percent is not None
    return True  # a provider (the FE model) computes it


def keys_without_effect(thermal, dynamics) -> list[tuple[list[str], str]]:
    """``[(keys, reason)]`` of a case's ``[thermal]`` and ``[dynamics]`` sections: the keys the case sets that no
    output reads under its models (module docstring)."""
    found = []
    chosen = thermal_model_rules(thermal.model)
    for other in THERMAL_MODEL_RULES.values():
        keys = [f"thermal.{key}" for key in other.own_keys
                if key in thermal.model_fields_set and key not in chosen.own_keys]
        if other is chosen or not keys or (other.reads_x_te and luo2020_complete(thermal)):
            continue
        found.append((keys, f"keys of thermal.model = '{other.name}', not of thermal.model = '{chosen.name}', and "
                            "they do not define X_te completely (x_te, or x_te_source = 'calibrated' with "
                            "calibration_drop_percent, or 'fem'), so nothing reads them; remove them, or complete "
                            f"them and set thermal.model = '{other.name}' to run that model"
                      if other.reads_x_te else
                      f"keys of thermal.model = '{other.name}', not of thermal.model = '{chosen.name}', so nothing "
                      f"reads them; remove them, or set thermal.model = '{other.name}'"))
    if not mesh_law(dynamics.mesh).backlash and "damping_in_flight" in dynamics.model_fields_set:
        found.append((["dynamics.damping_in_flight"], "the linear mesh keeps every pair in contact, so the teeth "
                                                      "never fly; it acts with dynamics.mesh = 'nonlinear'"))
    return found


def warn_keys_without_effect(thermal, dynamics) -> None:
    """One IneffectiveKeyWarning per rule that finds keys in a case's ``[thermal]`` and ``[dynamics]`` sections
    (module docstring)."""
    for keys, reason in keys_without_effect(thermal, dynamics):
        warnings.warn(f"{', '.join(keys)}: no effect under this case's model — {reason}", IneffectiveKeyWarning,
                      stacklevel=3)
