"""The keys of a case section that chooses a friction law (``[gearbox]``, ``[damping]``) checked together."""

from __future__ import annotations

from thermogear.errors import CaseError

def check_friction_inputs(section: str, model: str, coefficient: float | None,
                          lubricant_factor: float | None) -> None:
    """The keys of a section that chooses a friction law (``[gearbox]``, ``[damping]``) checked together:
    ``friction_coefficient`` exactly with the ``"constant"`` law, no ``lubricant_factor`` with it (CaseError naming
    ``section.key``)."""
    if model == "constant" and coefficient is None:
        raise CaseError(f"{section}.friction_coefficient", None, "a value in (0, 0.3]",
                        "friction_model = 'constant' needs the coefficient")
    if model != "constant" and coefficient is not None:
        raise CaseError(f"{section}.friction_coefficient", coefficient, "only with friction_model = 'constant'",
                        f"friction_model = {model!r} computes the coefficient: the key would have no effect")
    if model == "constant" and lubricant_factor is not None:
        raise CaseError(f"{section}.lubricant_factor", lubricant_factor, "absent with friction_model = 'constant'",
                        "a constant coefficient has no lubricant factor: the key would have no effect")


__all__ = ["check_friction_inputs"]
