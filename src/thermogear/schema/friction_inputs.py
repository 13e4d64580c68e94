"""The keys of a case section that chooses a friction law (``[gearbox]``, ``[damping]``) checked together."""

from __future__ import annotations

from thermogear.errors import CaseError
from thermogear.choices.friction import FRICTION_INPUTS
from thermogear.registry import registered


def check_friction_inputs(section: str, model: str, coefficient: float | None,
                          lubricant_factor: float | None) -> None:
    """The keys of a section that chooses a friction law (``[gearbox]``, ``[damping]``) checked together, as the law
    declares them (:data:`thermogear.choices.friction.FRICTION_INPUTS`): ``friction_coefficient`` exactly with a law
    that takes a given coefficient (the ``"constant"`` law), no ``lubricant_factor`` with a law that has none
    (CaseError naming ``section.key``)."""
    inputs = registered(FRICTION_INPUTS, model, f"{section}.friction_model", "not a friction law")
    if inputs.takes_coefficient and coefficient is None:
        raise CaseError(f"{section}.friction_coefficient", None, "a value in (0, 0.3]",
                        f"friction_model = {model!r} needs the coefficient")
    if not inputs.takes_coefficient and coefficient is not None:
        taking = " or ".join(repr(name) for name, law in FRICTION_INPUTS.items() if law.takes_coefficient)
        raise CaseError(f"{section}.friction_coefficient", coefficient, f"only with friction_model = {taking}",
                        f"friction_model = {model!r} computes the coefficient: the key would have no effect")
    if not inputs.takes_lubricant_factor and lubricant_factor is not None:
        raise CaseError(f"{section}.lubricant_factor", lubricant_factor, f"absent with friction_model = {model!r}",
                        f"friction_model = {model!r} has no lubricant factor: the key would have no effect")


__all__ = ["check_friction_inputs"]
