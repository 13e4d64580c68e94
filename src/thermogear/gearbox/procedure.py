"""A rig's test procedure on the gearbox network: load stages run one after the other, each for a fixed time from a
set start temperature, with the rig's oil conditioning (heater, cooler, thermostat) if it has one.

The FZG scuffing test (ISO 14635-1, method A/8,3/90; ASTM D5182 §10) runs load stages of 15 min (21 700 pinion
revolutions at 1450 rpm of the motor) at a pinion speed of about 2170 rpm; from load stage 4 on each stage starts
with the oil at 90–93 °C, brought there by the test gearbox's heater and cooling coil, and the heater stays on
(its thermostat on the sump); the temperature at the end of each stage is recorded. :func:`run_load_stages` runs
that: every node of the network starts a stage at ``start_c`` (an assumption: the gearbox conditioned to the start
temperature between stages; the standard prescribes only the oil's), then the warm-up of ``duration_s`` follows
with the conditioning given.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from thermogear.errors import CaseError
from thermogear.gearbox.description import GearboxOperatingPoint, OilConditioning
from thermogear.gearbox.losses import NODES, OIL, PINION, node_temperature

#: Duration of an FZG load stage [s] (ISO 14635-1, ASTM D5182 §10.2: 15 min).
FZG_STAGE_DURATION_S = 900.0
#: Start oil temperature of an FZG A/8,3/90 load stage [°C] (ASTM D5182 §10.4: 90–93 °C; the lower end).
FZG_START_C = 90.0


@dataclass(frozen=True)
class StageResult:
    """One load stage: its name, torque [N·m], the temperatures [°C] at its end (one per node of
    :data:`~thermogear.gearbox.losses.NODES`), the losses [W] and the conditioning power [W] there, the plausibility flags at the end and the
    energy residual of the integration (relative)."""

    name: str
    torque: float
    end_c: np.ndarray
    total_loss: float
    conditioning: float
    flags: tuple[str, ...]
    energy_residual: float

    oil_c = node_temperature(OIL, "end_c")
    pinion_c = node_temperature(PINION, "end_c")

    def node_c(self, name: str) -> float:
        """The end temperature of one node [°C] (a name of :data:`~thermogear.gearbox.losses.NODES`)."""
        return float(self.end_c[NODES.index(name)])


def run_load_stages(model, speed_rpm: float, stages: dict[str, float], ambient_c: float = 20.0,
                    duration_s: float = FZG_STAGE_DURATION_S, start_c: float = FZG_START_C,
                    conditioning: OilConditioning | None = None, points: int = 31) -> tuple[StageResult, ...]:
    """Run ``stages`` (name → pinion torque [N·m]) one by one on a
    :class:`~thermogear.gearbox.model.GearboxThermalModel` (module docstring): each stage from every node at
    ``start_c`` [°C] for ``duration_s`` [s] at ``speed_rpm``, with ``conditioning`` (None: the model's own)."""
    if not stages:
        raise CaseError("stages", stages, "at least one load stage", "a procedure runs load stages")
    if conditioning is not None:
        from thermogear.gearbox.model import GearboxThermalModel  # noqa: PLC0415

        model = GearboxThermalModel(replace(model.description, conditioning=conditioning))
    results = []
    for name, torque in stages.items():
        operating = GearboxOperatingPoint(float(speed_rpm), float(torque), float(ambient_c))
        history = model.warm_up(operating, duration_s, points=points, initial_c=start_c)
        end = history.temperatures_c[:, -1].copy()
        results.append(StageResult(str(name), float(torque), end, float(history.total_loss[-1]),
                                   float(history.conditioning[-1]), model.flags(end), history.energy_residual))
    return tuple(results)


def fzg_load_stages(first: int = 5, last: int = 12) -> dict[str, float]:
    """The FZG load stages K``first``..K``last`` with their pinion torques [N·m] (thermogear.fzg)."""
    from thermogear.fzg import FZG_LOAD_STAGE_TORQUE_NM  # noqa: PLC0415

    if not (first in FZG_LOAD_STAGE_TORQUE_NM and last in FZG_LOAD_STAGE_TORQUE_NM and first <= last):
        raise CaseError("stages", (first, last), f"{min(FZG_LOAD_STAGE_TORQUE_NM)}..{max(FZG_LOAD_STAGE_TORQUE_NM)}, "
                        "first <= last", "the FZG load stages")
    return {f"K{stage}": FZG_LOAD_STAGE_TORQUE_NM[stage] for stage in range(first, last + 1)}


__all__ = ["FZG_START_C", "FZG_STAGE_DURATION_S", "StageResult", "fzg_load_stages", "run_load_stages"]
