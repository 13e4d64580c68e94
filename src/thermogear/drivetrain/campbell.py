"""Interference (Campbell) diagram of a geared drivetrain: the modal frequencies against the pinion speed, which the
gyroscopic terms make move, with the mesh-harmonic lines f = j·z₁·n/60 and their crossings.

A crossing of harmonic j with mode i is a speed where the mesh excitation meets that mode; the modes that store a
large share of their strain energy in the mesh are the tooth-critical ones, whose crossings are the critical speeds
of the gear (Velex & Berthe, "Dynamic tooth loads on geared train", Proc. ASME Int. Power Transmission and Gearing
Conf., Chicago 1989, pp. 447–454). Each crossing is found by Brent's method on h(n) = f_i(n) − j·z₁·n/60 with the
modes re-solved at each trial speed; f_i is the i-th natural frequency |λ|/2π of the damped, spinning system in
ascending order (modes are followed by their rank, so two modes that cross each other swap names there).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.errors import CaseError

__all__ = ["Crossing", "CampbellDiagram", "campbell_diagram"]


@dataclass(frozen=True)
class Crossing:
    """Harmonic ``harmonic`` j of the mesh frequency meets mode ``mode`` (rank, lowest 0) at ``speed_rpm`` [rpm]
    and ``frequency_hz`` [Hz]; the mode's ``mesh_share`` of strain energy there [-] and its ``label``."""

    harmonic: int
    mode: int
    speed_rpm: float
    frequency_hz: float
    mesh_share: float
    label: str


@dataclass(frozen=True, eq=False)
class CampbellDiagram:
    """``speeds_rpm`` (S,) of the pinion; ``frequencies_hz`` (S, modes) natural frequencies; ``mesh_shares``
    (S, modes) [-]; ``labels`` per mode at the lowest speed; ``teeth`` z₁ of the pinion; ``harmonics``; the
    ``crossings`` found."""

    speeds_rpm: np.ndarray
    frequencies_hz: np.ndarray
    mesh_shares: np.ndarray
    labels: tuple[str, ...]
    teeth: int
    harmonics: tuple[int, ...]
    crossings: tuple[Crossing, ...]

    def tooth_critical(self, minimum_share: float = 0.1) -> tuple[Crossing, ...]:
        """The crossings whose mode stores at least ``minimum_share`` of its strain energy in the mesh."""
        return tuple(crossing for crossing in self.crossings if crossing.mesh_share >= minimum_share)

    def plot_campbell(self, ax=None):
        """Draw the diagram (modes as lines, darker with a larger mesh share; harmonics dashed; crossings of
        modes with a mesh share ≥ 0.1 marked) on ``ax`` or a new axes; returns the figure."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(7.5, 5.0), constrained_layout=True)
        for mode in range(self.frequencies_hz.shape[1]):
            share = float(self.mesh_shares[:, mode].max())
            ax.plot(self.speeds_rpm, self.frequencies_hz[:, mode], color=plt.cm.viridis_r(0.15 + 0.85 * share),
                    lw=0.8 + 2.0 * share, label=f"{self.labels[mode]}, mesh {share:.2f}" if share >= 0.05 else None)
        for harmonic in self.harmonics:
            ax.plot(self.speeds_rpm, harmonic * self.teeth * self.speeds_rpm / 60.0, "k--", lw=0.8)
            ax.annotate(f"{harmonic}×mesh", (self.speeds_rpm[-1], harmonic * self.teeth * self.speeds_rpm[-1] / 60),
                        fontsize=7, ha="right", va="bottom")
        critical = self.tooth_critical()
        ax.plot([c.speed_rpm for c in critical], [c.frequency_hz for c in critical], "ro", ms=5,
                label="tooth-critical crossings")
        ax.set_xlabel("pinion speed [rpm]")
        ax.set_ylabel("frequency [Hz]")
        ax.set_ylim(0.0, 1.05 * float(self.frequencies_hz.max()))
        ax.legend(fontsize=7, loc="upper left")
        return ax.figure


def campbell_diagram(assembled: AssembledDrivetrain, speeds_rpm: np.ndarray, teeth: int,
                     harmonics: tuple[int, ...] = (1, 2, 3), mode_count: int = 12,
                     mesh_stiffness: float | None = None) -> CampbellDiagram:
    """Modes at each pinion speed [rpm] (mean mesh stiffness of the mesh element, or ``mesh_stiffness`` [N/m]),
    the lowest ``mode_count``, and every crossing of the harmonics j·z₁·n/60 with them inside the speed range."""
    from scipy.optimize import brentq

    speeds = np.asarray(speeds_rpm, dtype=float)
    if speeds.ndim != 1 or speeds.size < 2 or np.any(np.diff(speeds) <= 0) or speeds[0] < 0:
        raise CaseError("speeds_rpm", speeds_rpm, "increasing speeds >= 0 rpm, at least two", "the speed axis")
    if int(teeth) != teeth or teeth < 1:
        raise CaseError("teeth", teeth, "an integer >= 1", "the pinion's tooth count z₁")
    if not harmonics or any(int(j) != j or j < 1 for j in harmonics):
        raise CaseError("harmonics", harmonics, "integers >= 1", "mesh harmonics j of j·z₁·n/60")
    stiffness = None if mesh_stiffness is None else np.array([mesh_stiffness])
    mesh_name = assembled.drivetrain.meshes[0].name

    @lru_cache(maxsize=None)
    def modes_at(speed: float):
        modes = drivetrain_modes(assembled, speed=speed * math.pi / 30.0, mesh_stiffness=stiffness, damped=True,
                                 count=mode_count)
        return modes.frequencies_hz, modes.mesh_share(mesh_name), modes.labels

    table = [modes_at(float(speed)) for speed in speeds]
    count = min(len(row[0]) for row in table)
    frequencies = np.array([row[0][:count] for row in table])
    shares = np.array([row[1][:count] for row in table])
    crossings = []
    for harmonic in harmonics:
        for mode in range(count):
            def gap(speed: float, mode: int = mode, harmonic: int = harmonic) -> float:
                return float(modes_at(float(speed))[0][mode] - harmonic * teeth * speed / 60.0)

            values = frequencies[:, mode] - harmonic * teeth * speeds / 60.0
            for index in np.flatnonzero(np.sign(values[:-1]) * np.sign(values[1:]) <= 0):
                if values[index] == 0.0 and index > 0:
                    continue  # a root on a grid speed is found from the interval on its left
                root = float(brentq(gap, speeds[index], speeds[index + 1], xtol=1e-9 * speeds[-1], rtol=1e-12))
                found_frequencies, found_shares, found_labels = modes_at(root)
                crossings.append(Crossing(int(harmonic), mode, root, float(found_frequencies[mode]),
                                          float(found_shares[mode]), found_labels[mode]))
    crossings.sort(key=lambda crossing: crossing.speed_rpm)
    return CampbellDiagram(speeds, frequencies, shares, tuple(table[0][2][:count]), int(teeth),
                           tuple(int(j) for j in harmonics), tuple(crossings))
