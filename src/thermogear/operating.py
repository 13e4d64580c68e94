"""Operating point: speed and load of the pinion."""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class OperatingPoint:
    """Pinion speed and torque. The pinion drives.

    ``constant_power``: the load was given as a power, so at another speed the torque is P/ω1 (a speed sweep of
    such a case keeps the power, not the torque); otherwise the torque stays as given.
    """

    speed_rpm: float  # n1 [rpm]
    torque: float  # T1 [N m]
    constant_power: bool = False

    @classmethod
    def from_power(cls, speed_rpm: float, power: float) -> "OperatingPoint":
        """From transmitted power P [W]: T1 = P / ω1."""
        return cls(speed_rpm, power / cls.angular_speed_of(speed_rpm), constant_power=True)

    def torque_at(self, speed_rpm: float) -> float:
        """Pinion torque T1 [N m] at a pinion speed [rpm]: the given torque, or the given power over ω1."""
        if self.constant_power and speed_rpm != self.speed_rpm:
            return self.power / self.angular_speed_of(speed_rpm)
        return self.torque

    def torques_at(self, speeds_rpm):
        """:meth:`torque_at` at many pinion speeds [rpm] at once (an array of T1 [N m], each element equal to
        ``torque_at`` at that speed: the same operations in the same order)."""
        import numpy as np

        speeds = np.asarray(speeds_rpm, dtype=float)
        if not self.constant_power:
            return np.full(speeds.shape, float(self.torque))
        with np.errstate(divide="ignore"):
            return np.where(speeds != self.speed_rpm, self.power / self.angular_speed_of(speeds), self.torque)

    @property
    def load_held(self) -> str:
        """Which load the mesh model keeps when the speed changes: ``"constant power"`` (the load was given as a
        power: T1 = P/ω1) or ``"constant torque"``; every output of ``thermogear run`` names it ("load held: …")."""
        return "constant power" if self.constant_power else "constant torque"

    @staticmethod
    def angular_speed_of(speed_rpm: float) -> float:
        return speed_rpm * math.pi / 30.0

    @property
    def angular_speed(self) -> float:
        """ω1 [rad/s]."""
        return self.angular_speed_of(self.speed_rpm)

    @property
    def power(self) -> float:
        """P = T1 ω1 [W]."""
        return self.torque * self.angular_speed

    def normal_load(self, pinion_base_radius: float) -> float:
        """Normal (line-of-action) load F_n = F_bt = T1 / r_b1 [N], total over the face width."""
        return self.torque / pinion_base_radius
