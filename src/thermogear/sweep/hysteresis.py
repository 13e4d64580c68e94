"""Hysteresis of a nonlinear-mesh branch study: where the up and the down branches differ, and where they jump.

Near a resonance softened by contact loss a backlash oscillator has two stable responses over a band of speeds;
a run-up stays on one, a run-down on the other, and each jumps where its branch ends (Kahraman & Singh 1990,
J. Sound Vib. 142(1):49–75). The branches can coexist over several separate bands (a primary and a
super-harmonic resonance, say) with speeds between where they coincide: each band is reported on its own.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.dynamics.problems.continuation_directions import DIRECTIONS

__all__ = ["difference_bands", "hysteresis_bands"]


def difference_bands(speeds, up, down, tolerance: float = 0.02) -> list[list[float]]:
    """The speed bands [rpm] where the branches ``up`` and ``down`` (one value per speed, speeds ascending)
    differ by more than ``tolerance`` relative to the larger: each band runs from the first to the last speed of
    a run of neighbouring speeds that differ, so two bands separated by speeds where the branches coincide stay
    two. A speed where either branch has no value (NaN) ends a band."""
    speeds = np.asarray(speeds, dtype=float)
    up, down = np.asarray(up, dtype=float), np.asarray(down, dtype=float)
    with np.errstate(invalid="ignore"):
        differ = np.abs(up - down) > tolerance * np.maximum(np.abs(up), np.abs(down))
    bands = []
    edges = np.diff(np.concatenate(([0], differ.astype(np.int8), [0])))
    for first, stop in zip(np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)):
        bands.append([float(speeds[first]), float(speeds[stop - 1])])
    return bands


def hysteresis_bands(dataset, variable: str = "dte_peak_to_peak", tolerance: float = 0.02, jump: float = 0.5,
                     select: dict[str, Any] | None = None) -> dict[str, Any]:
    """Where the up and the down branch differ (the jump phenomenon), per model.

    ``bands_rpm``: every speed band [rpm] in which ``variable`` differs by more than ``tolerance`` (relative to
    the larger), in ascending order (:func:`difference_bands`); ``band_rpm``: the widest of them; ``differ``:
    whether there is any. Per sweep direction its jumps: the changes of ``variable`` between neighbouring speeds
    larger than ``jump`` (relative to the smaller), each with the speed midway between them, in the order the
    sweep meets them, and whether the amplitude rises or falls there (a smooth branch has none); a jump lies beside
    a speed where the branches differ, and a change as large where they coincide (both branches as steep between
    two grid speeds) is listed apart as ``{direction}_sweep_steep_changes``, never as a jump. ``select``:
    values of the other parameters of a grid (their first values by default). Empty without a speed axis or
    without both directions."""
    if "speed_rpm" not in dataset.dims or tuple(dataset["direction"].values) != tuple(DIRECTIONS):
        return {}
    result = {}
    speeds = np.asarray(dataset["speed_rpm"].values, dtype=float)
    for model in dataset["model"].values:
        selected = dataset[variable].sel(model=model)
        if select:
            selected = selected.sel(select)
        extra = [d for d in selected.dims if d not in ("direction", "speed_rpm")]
        if extra:  # one entry per study: the first value of any other parameter not selected
            selected = selected.isel({d: 0 for d in extra})
        branches = {d: np.asarray(selected.sel(direction=d).transpose("speed_rpm").values, dtype=float)
                    for d in ("up", "down")}
        bands = difference_bands(speeds, branches["up"], branches["down"], tolerance)
        with np.errstate(invalid="ignore"):
            differ = np.abs(branches["up"] - branches["down"]) > tolerance * np.maximum(np.abs(branches["up"]),
                                                                                         np.abs(branches["down"]))
        entry: dict[str, Any] = {"differ": bool(bands), "bands_rpm": bands}
        if bands:
            entry["band_rpm"] = max(bands, key=lambda band: band[1] - band[0])
        for way, values in branches.items():
            if not DIRECTIONS[way].ascending:  # the down sweep visits the speeds from the highest
                values, order, apart = values[::-1], speeds[::-1], differ[::-1]
            else:
                order, apart = speeds, differ
            smaller = np.maximum(np.minimum(np.abs(values[:-1]), np.abs(values[1:])), 1e-300)
            change = np.abs(np.diff(values)) / smaller
            steps = np.flatnonzero(np.nan_to_num(change) > jump)
            listed = [{"speed_rpm": float(0.5 * (order[i] + order[i + 1])),
                       "amplitude": "rises" if values[i + 1] > values[i] else "falls", "ratio": float(change[i] + 1.0)}
                      for i in steps]
            # a jump is where this branch leaves the other's: beside a speed where the two differ. Where both
            # change as steeply at the same speeds, the branches coincide: a steep slope between grid speeds
            jumping = [bool(apart[i] or apart[i + 1]) for i in steps]
            entry[f"{way}_sweep_jumps"] = [item for item, kept in zip(listed, jumping) if kept]
            entry[f"{way}_sweep_steep_changes"] = [item for item, kept in zip(listed, jumping) if not kept]
        result[str(model)] = entry
    return result
