"""Case-file section [thermal]: the thermo-elastic coupling of Luo & Li Eqs. 13–23."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from thermogear.schema.base import Section
from thermogear.choices.thermal_models import THERMAL_MODEL_RULES


class ThermalSection(Section):
    """Thermal mesh stiffness settings.

    ``x_te_source``: ``"given"`` uses ``x_te``; ``"calibrated"`` solves for the X_te that gives
    ``calibration_drop_percent`` at ``calibration_point`` (reported as a calibration); ``"fem"`` takes it from the
    finite-element thermoelastic analysis. ``load_basis``: F_n of Eqs. 13–18 is the external normal load
    (``"external"``) or the pair's share (``"pair_share"``).
    """

    # the names of the thermal models' rules, the first the default: a model added there is a valid value here
    model: Literal[tuple(THERMAL_MODEL_RULES)] = Field(  # type: ignore[valid-type]
        next(iter(THERMAL_MODEL_RULES)), description="'thermoelastic': E(T), expansion of gears and housing, backlash, flank "
                                     "deviations (no fitted factor; docs/thermal.md); 'luo2020': the paper's k_T "
                                     "with X_te (Luo & Li 2020 Eqs. 13–23), kept to reproduce the paper")
    x_te: Annotated[float, Field(ge=0.0, le=100.0, description="thermal-load correction factor X_te [–]")] | None = None
    x_te_source: Literal["given", "calibrated", "fem"] = "given"
    calibration_drop_percent: Annotated[float, Field(gt=0.0, lt=100.0)] | None = None
    calibration_point: Literal["A", "B", "C", "D", "E"] = "C"
    load_basis: Literal["external", "pair_share"] = "external"
    expansion_model: Literal["paper", "consistent"] = Field(
        "consistent", description="form of Luo & Li Eq. 9: 'paper' as printed (counts the circumferential growth "
                                  "twice), 'consistent' (homogeneous expansion for a uniform rise; FE-verified)")
