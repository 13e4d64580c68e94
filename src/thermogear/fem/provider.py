"""Registers the finite-element model as the ``"fem"`` source of the tooth temperature field
(``[temperature].model = "fem"``) and of X_te (``[thermal].x_te_source = "fem"``) on import.

The thermal chain looks providers up by name; importing this module (the ``thermogear`` CLI does) plugs them in.
Both answers come from one memoised :func:`thermogear.fem.verification.cached_analysis` per case.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from thermogear.thermal.calibration import register_x_te_provider
from thermogear.thermal.temperature import register_temperature_provider

if TYPE_CHECKING:
    from thermogear.case import Case
    from thermogear.thermal.temperature import TemperatureField


def fem_temperature_field(case: "Case") -> "TemperatureField":
    """The FE bulk temperature of both gears as a TemperatureField (flank along Γ, base circle, bore)."""
    from thermogear.fem.verification import cached_analysis  # noqa: PLC0415

    return cached_analysis(case).temperature_field


def fem_x_te(case: "Case") -> float:
    """X_te from the FE elastic and thermo-elastic runs, averaged along the path (verification module)."""
    from thermogear.fem.verification import cached_analysis  # noqa: PLC0415

    return cached_analysis(case).x_te


register_temperature_provider("fem", fem_temperature_field)
register_x_te_provider("fem", fem_x_te)

__all__ = ["fem_temperature_field", "fem_x_te"]
