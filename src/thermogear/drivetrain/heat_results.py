"""What heat moved in each mode of the drivetrain, cold → hot, and by which cause, as frozen rows of the results
(:class:`HeatShift`, built once by :func:`heat_rows` from :class:`~thermogear.drivetrain.heat.ModeShifts`)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

__all__ = ["HeatShift", "heat_rows"]


@dataclass(frozen=True)
class HeatShift:
    """One mode cold → hot: frequencies [Hz], the exact shift and its first-order sum [-], each cause's share [-]
    (causes that moved nothing left out) and the largest cause."""

    cold_hz: float
    hot_hz: float
    label: str
    shift: float
    first_order: float
    causes: Mapping[str, float]
    dominant_cause: str

    def as_json(self) -> dict[str, Any]:
        return {"cold_hz": self.cold_hz, "hot_hz": self.hot_hz, "label": self.label,
                "shift_percent": 100.0 * self.shift, "first_order_percent": 100.0 * self.first_order,
                "causes_percent": {name: 100.0 * value for name, value in self.causes.items()},
                "dominant_cause": self.dominant_cause}


def heat_rows(shifts, drivetrain) -> tuple[HeatShift, ...]:
    """Per mode of :class:`~thermogear.drivetrain.heat.ModeShifts` (``drivetrain`` the cold one, to name each
    shaft's E(T) cause): the shift and its causes."""
    shafts = {shaft.name for shaft in drivetrain.shafts}
    names = {name: (f"{name} E(T)" if name in shafts else name) for name in shifts.contributions}
    moving = [name for name, values in shifts.contributions.items() if np.any(values != 0.0)]
    return tuple(HeatShift(float(shifts.cold_hz[i]), float(shifts.hot_hz[i]), shifts.labels[i],
                           float(shifts.exact[i]), float(shifts.first_order[i]),
                           MappingProxyType({names[name]: float(shifts.contributions[name][i]) for name in moving}),
                           names[shifts.dominant_cause(i)]) for i in range(shifts.exact.size))
