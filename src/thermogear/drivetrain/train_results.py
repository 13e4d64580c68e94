"""A train's results beside those of one mesh (:mod:`thermogear.drivetrain.results`): the spectrum lines of every
mesh's harmonics over the common period, and each mesh's Kv, DTE and force over it."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

import numpy as np

__all__ = ["StageResult", "harmonic_orders", "stage_results"]


def harmonic_orders(response, harmonics: int) -> list[int]:
    """The spectrum lines (multiples of 1/T) of the mesh harmonics 1…``harmonics`` of every mesh: 1…harmonics for
    one mesh; for a train, j·L_m of each mesh m (L_m its periods in the common period T), in ascending order."""
    meshes = getattr(response, "meshes", None) or {}
    repeats = {max(1, round(response.period / item.mesh_period)) for item in meshes.values()} or {1}
    return sorted({j * repeat for repeat in repeats for j in range(1, harmonics + 1)})


@dataclass(frozen=True)
class StageResult:
    """One mesh of a train over the common period: Kv [-], DTE RMS and peak-to-peak [m], the largest mesh force
    [N] and the mesh frequency [Hz]."""

    kv: float
    dte_rms: float
    dte_peak_to_peak: float
    max_mesh_force_n: float
    mesh_frequency_hz: float
    contact_loss_fraction: float | None = None  # the backlash mesh: the mesh's own time off and on its back flanks
    back_contact_fraction: float | None = None

    def as_json(self) -> dict[str, Any]:
        contact = {} if self.contact_loss_fraction is None else {
            "contact_loss_fraction": self.contact_loss_fraction, "back_contact_fraction": self.back_contact_fraction}
        return {"kv": self.kv, "dte_rms_um": self.dte_rms * 1e6, "dte_peak_to_peak_um": self.dte_peak_to_peak * 1e6,
                "max_mesh_force_n": self.max_mesh_force_n, "mesh_frequency_hz": self.mesh_frequency_hz, **contact}


def stage_results(response) -> Mapping[str, StageResult]:
    """Per mesh of a train's response (``response.meshes``: periodic, backlash orbit or last period from rest):
    its :class:`StageResult` (with the backlash mesh, its own contact loss)."""
    return MappingProxyType({name: StageResult(item.metrics["kv"], item.metrics["dte_rms"],
                                               item.metrics["dte_peak_to_peak"], float(np.max(item.mesh_force)),
                                               1.0 / item.mesh_period, item.metrics.get("contact_loss_fraction"),
                                               item.metrics.get("back_contact_fraction"))
                             for name, item in response.meshes.items()})
