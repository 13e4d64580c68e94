"""Each bearing's force and moment on its housing over a mesh period, as the drivetrain's results report them: the
mean and dynamic radial force, the radial amplitudes of the mesh harmonics, the mean axial force (a helical mesh's
thrust) and the mean tilting moment (:class:`BearingForces`)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

from thermogear.drivetrain.train_results import harmonic_orders

__all__ = ["BearingForces", "bearing_forces_of", "unknown_bearing_forces"]


def _frozen_mapping(values: Mapping) -> Mapping:
    return MappingProxyType(dict(values))


@dataclass(frozen=True)
class BearingForces:
    """One bearing's force on its housing over a mesh period: mean radial force [N], RMS of the dynamic radial force
    |F − F̄| [N], and the radial amplitudes √(X_j² + Y_j²) [N] of mesh harmonics j = 1… at ``harmonic_hz`` [Hz]
    (None where the response was not found); the mean axial force F_z [N] (signed, along +z: a helical mesh's
    thrust) and the mean tilting moment √(M_x² + M_y²) [N·m] of its tilting stiffness (0 for a bearing without)."""

    mean_radial_n: float | None
    dynamic_rms_n: float | None
    harmonic_hz: tuple[float, ...]
    harmonic_amplitude_n: tuple[float | None, ...]
    mean_axial_n: float | None = None
    mean_tilting_moment_n_m: float | None = None

    def as_json(self) -> dict[str, Any]:
        return {"mean_radial_n": self.mean_radial_n, "dynamic_rms_n": self.dynamic_rms_n,
                "harmonic_hz": list(self.harmonic_hz), "harmonic_amplitude_n": list(self.harmonic_amplitude_n),
                "mean_axial_n": self.mean_axial_n, "mean_tilting_moment_n_m": self.mean_tilting_moment_n_m}


def bearing_forces_of(response, harmonics: int, spectrum_points: int) -> Mapping[str, BearingForces]:
    """Per bearing of a response (anything with ``time``, ``bearing_forces`` and ``bearing_spectrum``): the mean
    radial force, the RMS of the dynamic radial force (trapezoidal rule on the solver's samples, a jump being a
    segment of zero width) and the radial amplitudes of the first ``harmonics`` mesh harmonics (from at least
    ``spectrum_points`` uniform samples of the period); for a train, those of every mesh (:func:`harmonic_orders`)."""
    summary = {}
    time = response.time
    orders = harmonic_orders(response, harmonics)
    spectrum_points = max(spectrum_points, 4 * orders[-1])
    for name, force in response.bearing_forces.items():
        radial = force[:, :2]
        mean = np.trapezoid(radial, time, axis=0) / (time[-1] - time[0])
        axial = float(np.trapezoid(force[:, 2], time)) / (time[-1] - time[0])
        moment = getattr(response, "bearing_moments", {}).get(name)
        tilting = (None if moment is None
                   else float(np.hypot(*(np.trapezoid(moment, time, axis=0) / (time[-1] - time[0])))))
        dynamic = np.sum((radial - mean) ** 2, axis=1)
        rms = math.sqrt(float(np.trapezoid(dynamic, time)) / (time[-1] - time[0]))
        frequencies, amplitudes = response.bearing_spectrum(name, points=spectrum_points)
        radial_amplitudes = np.hypot(amplitudes[0], amplitudes[1])
        summary[name] = BearingForces(float(np.hypot(*mean)), rms, tuple(float(frequencies[j]) for j in orders),
                                      tuple(float(radial_amplitudes[j]) for j in orders), axial, tilting)
    return _frozen_mapping(summary)


def unknown_bearing_forces(names, period: float, harmonics: int) -> Mapping[str, BearingForces]:
    """Every bearing's forces unknown (no orbit found), at the mesh harmonics of ``period`` [s]."""
    frequency = 1.0 / period
    return _frozen_mapping({name: BearingForces(None, None, tuple(j * frequency for j in range(1, harmonics + 1)),
                                                (None,) * harmonics) for name in names})
