"""The ``"gearbox"`` source of the tooth temperature field (``[temperature].model = "gearbox"``): each gear at its
predicted steady bulk temperature (the network's pinion and wheel nodes), uniform over the gear body.

Found by name where the package is assembled (:mod:`thermogear.composition`, beside the finite-element provider),
with the load-time check of a ``[gearbox]`` section; importing this module registers nothing. :func:`register`
remains for callers that plug it in explicitly (it changes nothing the composition does not already give).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from thermogear.gearbox.case_model import gearbox_operating_point, gearbox_section, predicted_steady_state
from thermogear.temperature.field import TemperatureField

if TYPE_CHECKING:
    from thermogear.gearbox.model import GearboxThermalModel
    from thermogear.operating import OperatingPoint
    from thermogear.schema.gearbox import GearboxSection
    from thermogear.schema.temperature import TemperatureSection

#: The name of this source in ``[temperature].model``.
MODEL_NAME = "gearbox"


def gearbox_temperature_field(gearbox_model: "GearboxThermalModel | None", gearbox: "GearboxSection | None",
                              operating_point: "OperatingPoint", temperature: "TemperatureSection") -> TemperatureField:
    """Pinion flank, base circle and bore at the pinion node's temperature, the wheel's at the wheel node's
    (``wheel_flank_offset_c`` = wheel − pinion) [°C], stress-free at ``temperature.reference_c``: the steady state
    of the case's network ``gearbox_model`` at its ``operating_point`` in the ambient of its ``[gearbox]``.

    A temperature provider (:data:`thermogear.composition.TEMPERATURE_PROVIDERS`): it receives these pieces of the
    case (:mod:`thermogear.case.pieces`)."""
    gearbox_section(gearbox)  # a case without [gearbox] is refused, naming the section
    state = predicted_steady_state(gearbox_model, gearbox_operating_point(operating_point, gearbox))
    pinion, wheel = round(state.pinion_c, 6), round(state.wheel_c, 6)
    losses = state.losses
    source = (f"gearbox (predicted steady state: oil {state.oil_c:.1f} °C, housing {state.housing_c:.1f} °C; "
              f"losses mesh {losses.mesh:.1f} W, bearings {losses.bearings:.1f} W, seals {losses.seals:.1f} W, "
              f"churning {losses.churning:.1f} W)")
    return TemperatureField(reference_c=temperature.reference_c, pinion_base_c=pinion, pinion_bore_c=pinion,
                            wheel_base_c=wheel, wheel_bore_c=wheel, flank_coefficients=(pinion,),
                            wheel_flank_offset_c=wheel - pinion, source=source)

