"""Tables of a drivetrain's results as plain JSON-ready numbers, for the sweeps and the pictures: each is the typed
builder of :mod:`thermogear.drivetrain.results` (one implementation per quantity) written by its ``as_json``."""

from __future__ import annotations

from typing import Any

from thermogear.drivetrain.assembly import Drivetrain
from thermogear.drivetrain.heat import ModeShifts
from thermogear.drivetrain.modes import DrivetrainModes
from thermogear.drivetrain.response import DrivetrainResponse
from thermogear.drivetrain.results import (MESH_COUPLED_SHARE, MESH_DOMINATED_SHARE, ModeRow, bearing_forces_of,
                                           heat_rows, mode_rows, resonances_of, stage_results)

__all__ = ["MESH_COUPLED_SHARE", "MESH_DOMINATED_SHARE", "SPECTRUM_POINTS", "bearing_force_summary", "heat_table",
           "mode_table", "resonance_speeds", "stage_summary"]

#: Uniform samples per period for the bearing-force harmonics (the first mesh harmonics need far fewer).
SPECTRUM_POINTS = 256


def mode_table(modes: DrivetrainModes, drivetrain: Drivetrain) -> list[dict[str, Any]]:
    """One dict per mode (:func:`~thermogear.drivetrain.results.mode_rows` as JSON): frequency [Hz], label, mesh
    share, the shares grouped and per element, whether the mesh dominates it; for a train each mesh's share."""
    return [row.as_json() for row in mode_rows(modes, drivetrain)]


def bearing_force_summary(response: DrivetrainResponse, harmonics: int) -> dict[str, dict[str, Any]]:
    """Per bearing, :func:`~thermogear.drivetrain.results.bearing_forces_of` as JSON (mean radial force, RMS of the
    dynamic radial force, radial amplitudes of the mesh harmonics, of every mesh for a train, with their
    frequencies)."""
    return {name: force.as_json() for name, force in bearing_forces_of(response, harmonics, SPECTRUM_POINTS).items()}


def resonance_speeds(rows: list[dict[str, Any]], teeth: int, harmonics: int,
                     stages: tuple[tuple[str, float], ...] = ()) -> list[dict[str, Any]]:
    """Pinion speeds [rpm] at which mesh harmonics meet a mode of ``rows`` (:func:`mode_table`) with a mesh share
    above :data:`MESH_COUPLED_SHARE` (:func:`~thermogear.drivetrain.results.resonances_of`, as JSON)."""
    typed = tuple(ModeRow(**row) for row in rows)
    return [item.as_json() for item in resonances_of(typed, teeth, harmonics, stages)]


def stage_summary(response: DrivetrainResponse) -> dict[str, dict[str, Any]]:
    """Per mesh of a train: Kv, DTE RMS and peak-to-peak [μm], the largest mesh force [N] and the mesh frequency
    [Hz] over the common period (:func:`~thermogear.drivetrain.results.stage_results` as JSON)."""
    return {name: stage.as_json() for name, stage in stage_results(response).items()}


def heat_table(shifts: ModeShifts, drivetrain: Drivetrain) -> list[dict[str, Any]]:
    """Per mode: cold and hot frequency [Hz], the exact shift and its first-order sum [%], and the causes [%]
    (:func:`~thermogear.drivetrain.results.heat_rows` as JSON)."""
    return [row.as_json() for row in heat_rows(shifts, drivetrain)]
