"""The finite-element model as the ``"fem"`` source of the tooth temperature field (``[temperature].model =
"fem"``) and of X_te (``[thermal].x_te_source = "fem"``).

The thermal chain finds these two functions by name (:mod:`thermogear.composition`); importing this module
registers nothing. Both answers come from one memoised :func:`thermogear.fem.verification.cached_analysis` per case
document. They keep the whole case: the providers' protocol (``provider(case)``, shared with the gearbox thermal
model's) hands them one, and each resolves it into the FE inputs (:func:`thermogear.fem.inputs.fem_inputs`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from thermogear.case import Case
    from thermogear.temperature_source import TemperatureField


def fem_temperature_field(case: "Case") -> "TemperatureField":
    """The FE bulk temperature of both gears as a TemperatureField (flank along Γ, base circle, bore)."""
    from thermogear.fem.inputs import fem_inputs  # noqa: PLC0415
    from thermogear.fem.verification import cached_analysis  # noqa: PLC0415

    return cached_analysis(fem_inputs(case)).temperature_field


def fem_x_te(case: "Case") -> float:
    """X_te from the FE elastic and thermo-elastic runs, averaged along the path (verification module)."""
    from thermogear.fem.inputs import fem_inputs  # noqa: PLC0415
    from thermogear.fem.verification import cached_analysis  # noqa: PLC0415

    return cached_analysis(fem_inputs(case)).x_te


__all__ = ["fem_temperature_field", "fem_x_te"]
