"""The multi-start orbit search of a nonlinear-mesh study: every stable orbit found at each point, with its basin
share, stored beside the branches (``thermogear sweep … --multistart N``).

Continuation in speed follows the branches its path meets; other stable orbits (double-sided impacts,
subharmonics) can coexist with them unseen. At every grid point and model, :func:`~thermogear.dynamics.
backlash_orbits.stable_orbits` runs N starts spread over the backlash and the velocities of impacts across it and
lists the distinct stable orbits they settle on. The dataset gets an ``orbit`` dimension (the most orbits found at
any point; unused entries NaN), the orbits ordered by basin share.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.dynamics.backlash.backlash_metrics import orbit_metrics
from thermogear.dynamics.backlash.backlash_orbits import stable_orbits

__all__ = ["ORBIT_VARIABLES", "orbit_dataset_variables", "point_orbits"]

#: Per-orbit variables, dims (model, *parameters, orbit): name → (units, long name, source in the metrics).
ORBIT_VARIABLES: dict[str, tuple[str, str, str]] = {
    "orbit_period_count": ("1", "mesh periods after which the orbit repeats (least period)", "period_count"),
    "orbit_basin_share": ("1", "fraction of the multi-start search's starts that settle on the orbit", "basin_share"),
    "orbit_dte_peak_to_peak": ("m", "peak-to-peak dynamic transmission error of the orbit", "dte_peak_to_peak"),
    "orbit_kv": ("1", "dynamic load factor Kv of the orbit (Luo & Li Eq. 29)", "kv"),
    "orbit_contact_loss_fraction": ("1", "fraction of the orbit without driving-flank contact",
                                    "contact_loss_fraction"),
    "orbit_back_contact_fraction": ("1", "fraction of the orbit with a back flank in contact",
                                    "back_contact_fraction"),
    "orbit_floquet_multiplier_max": ("1", "largest Floquet multiplier modulus of the orbit", "largest_multiplier"),
}


def point_orbits(problem, starts: int, include_damping_force: bool = False) -> dict[str, Any]:
    """The stable orbits of one point: ``orbits`` (a list of {source name: value}, largest basin share first) and
    the shares of the starts that settled on none (``unresolved``) or grew without bound (``unbounded``)."""
    census = stable_orbits(problem, starts=starts, samples_per_interval=1)
    orbits = []
    for found in census.orbits:
        values = orbit_metrics(found.orbit, include_damping_force=include_damping_force)
        values["basin_share"] = found.basin_share
        orbits.append(values)
    return {"orbits": orbits, "unresolved": census.unresolved / census.starts,
            "unbounded": census.unbounded / census.starts}


def orbit_dataset_variables(censuses: np.ndarray, models, dims: tuple[str, ...], starts: int) -> dict[str, tuple]:
    """xarray variables of a study's censuses (an object array (model, *parameters) of :func:`point_orbits`
    results, None where there is none: a jammed point)."""
    width = max([1] + [len(item["orbits"]) for item in censuses.flat if item is not None])
    shape = (*censuses.shape, width)
    arrays = {name: np.full(shape, np.nan) for name in ORBIT_VARIABLES}
    count = np.full(censuses.shape, np.nan)
    unresolved = np.full(censuses.shape, np.nan)
    for index, item in np.ndenumerate(censuses):
        if item is None:
            continue
        count[index] = len(item["orbits"])
        unresolved[index] = item["unresolved"] + item["unbounded"]
        for number, values in enumerate(item["orbits"]):
            for name, (_, _, source) in ORBIT_VARIABLES.items():
                arrays[name][(*index, number)] = float(values[source])
    full = ("model", *dims)
    data = {name: ((*full, "orbit"), arrays[name], {"units": units, "long_name": long_name})
            for name, (units, long_name, _) in ORBIT_VARIABLES.items()}
    data["stable_orbit_count"] = (full, count, {"units": "1", "long_name": f"distinct stable orbits found from "
                                                f"{starts} starts (more may exist)"})
    data["unsettled_start_share"] = (full, unresolved, {"units": "1", "long_name": "fraction of the starts that "
                                                        "settled on no stable orbit of at most 3 periods"})
    return data
