"""What each friction law (``friction_model`` of ``[gearbox]`` and ``[damping]``) takes from the case, declared once
by name for both the case's checks and the laws (issue 33: no law chosen by comparing its name):

* ``takes_coefficient``: the law is a coefficient the case gives (``friction_coefficient``, then required), else it
  computes μ from the contact and the key would have no effect;
* ``takes_lubricant_factor``: the law has a lubricant factor X_L (``lubricant_factor``, default the law's value for
  the base oil), else the key would have no effect.

The laws themselves live in :data:`thermogear.friction.models.FRICTION_MODELS`, which reads the lubricant (and so the
case) and therefore sits above the schema; this module imports nothing of thermogear, so the schema's checks read it
without crossing the layers, and a test holds its names equal to the registry's and each fact equal to what the law
does. A new law is one entry here and one there.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["FRICTION_INPUTS", "FrictionInputs"]


@dataclass(frozen=True)
class FrictionInputs:
    """The case keys a friction law ``name`` reads besides its name (module docstring)."""

    name: str
    takes_coefficient: bool
    takes_lubricant_factor: bool


#: What every friction law takes, by name, in the order of :data:`thermogear.friction.models.FRICTION_MODELS`.
FRICTION_INPUTS: dict[str, FrictionInputs] = {inputs.name: inputs for inputs in (
    FrictionInputs("paper", takes_coefficient=False, takes_lubricant_factor=True),
    FrictionInputs("iso_tr_13989_2", takes_coefficient=False, takes_lubricant_factor=True),
    FrictionInputs("schlenk", takes_coefficient=False, takes_lubricant_factor=True),
    FrictionInputs("constant", takes_coefficient=True, takes_lubricant_factor=False),
)}
