"""The finite-element model as the ``"fem"`` source of the tooth temperature field (``[temperature].model =
"fem"``) and of X_te (``[thermal].x_te_source = "fem"``).

The thermal chain finds these two functions by name (:mod:`thermogear.composition`); importing this module
registers nothing. Both answers come from one memoised :func:`thermogear.fem.verification.cached_analysis` per case
document. Each asks for the piece ``fem_inputs`` of the case (:mod:`thermogear.case.pieces`): the FE inputs its one
resolver, :func:`thermogear.fem.inputs.fem_inputs`, makes of the case.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from thermogear.fem.inputs import FemInputs
    from thermogear.temperature.source import TemperatureField


def fem_temperature_field(fem_inputs: "FemInputs") -> "TemperatureField":
    """The FE bulk temperature of both gears as a TemperatureField (flank along Γ, base circle, bore)."""
    from thermogear.fem.verification import cached_analysis  # noqa: PLC0415

    return cached_analysis(fem_inputs).temperature_field


def fem_x_te(fem_inputs: "FemInputs") -> float:
    """X_te from the FE elastic and thermo-elastic runs, averaged along the path (verification module)."""
    from thermogear.fem.verification import cached_analysis  # noqa: PLC0415

    return cached_analysis(fem_inputs).x_te


__all__ = ["fem_temperature_field", "fem_x_te"]
