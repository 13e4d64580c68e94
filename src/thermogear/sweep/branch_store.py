"""The store of a nonlinear-mesh branch study (:func:`thermogear.sweep.branches.branch_study` with ``out``): its
layout (:class:`~thermogear.sweep.task_store.StoreLayout`) and the region and arrays each task writes (a group's
branches, or one point's multi-start census)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from thermogear.sweep.load_held import study_load_held
from thermogear.sweep.metric_variables import DTE_VARIABLES

__all__ = ["BRANCH_POINT", "BRANCH_VARIABLES", "ORBIT_SEARCH", "STATE_SIZE", "TASK_KINDS", "TaskKind", "branch_layout",
           "branch_region", "orbit_arrays"]


@dataclass(frozen=True)
class TaskKind:
    """A kind of task of a branch study, by the tag (``name``) its tuple starts with: whether it is a point of a
    branch (``follows_branch``: it continues from its neighbour's state, and its tuple holds a direction), and where
    its tuple holds the direction and the speed index."""

    name: str
    follows_branch: bool
    direction_position: int | None
    speed_position: int


#: A point of a branch: ("point", group, model, direction, speed[, stored state]).
BRANCH_POINT = TaskKind("point", follows_branch=True, direction_position=3, speed_position=4)
#: The multi-start orbit search at one point: ("orbits", group, model, speed).
ORBIT_SEARCH = TaskKind("orbits", follows_branch=False, direction_position=None, speed_position=3)
#: The tasks of a branch study by tag: the one place the tags are compared.
TASK_KINDS: dict[str, TaskKind] = {kind.name: kind for kind in (BRANCH_POINT, ORBIT_SEARCH)}

#: Per-direction, per-model result variables: name → (units, long name).
BRANCH_VARIABLES: dict[str, tuple[str, str]] = {
    "kv": ("1", "dynamic load factor Kv = max pair force / static load (Luo & Li Eq. 29)"),
    "max_pair_load": ("N", "largest single-pair force over the orbit"),
    "max_system_load_ratio": ("1", "largest mesh force / static load"),
    **DTE_VARIABLES,
    "contact_loss_fraction": ("1", "fraction of the period without driving-flank contact"),
    "back_side_contact": ("1", "1 where a back flank is struck"),
    "back_contact_fraction": ("1", "fraction of the period with a back flank in contact"),
    "period_count": ("1", "mesh periods after which the response repeats (1 periodic, >1 subharmonic)"),
    "converged": ("1", "1 where a stable periodic or subharmonic orbit was found"),
    "floquet_multiplier_max": ("1", "largest Floquet multiplier modulus of the orbit"),
    "residual": ("1", "scaled residual |phi_NT(y0) - y0| of the orbit's Newton iteration (large: not converged)"),
}
#: The state a branch carries from point to point: (x [m], dx/dt [m/s]) at the start of the period.
STATE_SIZE = 2


def branch_layout(study, directions: tuple[str, ...], starts: int, tasks: int):
    """The store of a branch study (:class:`~thermogear.sweep.task_store.StoreLayout`)."""
    import json  # noqa: PLC0415

    from thermogear.sweep.task_store import StoreLayout, StoreVariable  # noqa: PLC0415

    dims = ("direction", "model", *study.dims)
    point = ("model", *study.dims)
    variables = [StoreVariable(name, dims, "float", units, text) for name, (units, text) in BRANCH_VARIABLES.items()]
    variables += [StoreVariable("response", dims, "str", "", "periodic | subharmonic | non-periodic | failed | "
                                "jammed", width=12),
                  StoreVariable("jammed", point, "int8", "1", "1 where the gears jam (the thermal expansion closes "
                                "the backlash): no result, NaN"),
                  StoreVariable("natural_frequency_hz", point, "float", "Hz", "natural frequency of the linear mesh "
                                "with every pair in contact, sqrt(mean k / me) / 2 pi"),
                  StoreVariable("static_load", study.dims, "float", "N", "static normal load w"),
                  StoreVariable("mesh_frequency_hz", study.dims, "float", "Hz", "mesh frequency z1 n1 / 60"),
                  StoreVariable("branch_state", (*dims, "state"), "float", "", "state (x [m], dx/dt [m/s]) the branch "
                                "carries on from this point (resume); NaN before its first orbit")]
    coords: dict[str, Any] = {"direction": list(directions), "model": list(study.models),
                              "state": np.arange(STATE_SIZE)}
    coords.update({p.name: np.asarray(p.values) for p in study.parameters})
    if starts:
        from thermogear.sweep.multistart import ORBIT_VARIABLES  # noqa: PLC0415

        variables += [StoreVariable(name, (*point, "orbit"), "float", units, text)
                      for name, (units, text, _) in ORBIT_VARIABLES.items()]
        variables += [StoreVariable("stable_orbit_count", point, "float", "1", f"distinct stable orbits found from "
                                    f"{starts} starts (more may exist)"),
                      StoreVariable("unsettled_start_share", point, "float", "1", "fraction of the starts that "
                                    "settled on no stable orbit of at most 3 periods")]
        coords["orbit"] = np.arange(starts)
    load, load_note = study_load_held(study)
    speed = next((p.name for p in study.parameters if p.key == "operating.speed_rpm"), None)
    chunks = {"model": 1, **{p.name: 1 for p in study.parameters if p.name != speed}}
    definition = {**study.describe(), "kind": "nonlinear branches, a task per point", "directions": list(directions),
                  "multistart": starts}
    attrs = {"mesh": "nonlinear", "directions": ",".join(directions), "case": study.case.name,
             "case_name": study.case.name, "case_source": str(study.case.source), "load": load,
             "load_note": load_note, "case_json": json.dumps(study.case.document, sort_keys=True, default=str)}
    return StoreLayout(coords=coords, variables=tuple(variables), tasks=tasks, definition=definition, attrs=attrs,
                       chunks=chunks)


def branch_region(study, task, speed_axis) -> dict[str, Any]:
    """The region of the store a task writes: one point of one model (and direction, for a branch point)."""
    names = [p.name for a, p in enumerate(study.parameters) if a != speed_axis]
    region: dict[str, Any] = dict(zip(names, task[1]))
    region["model"] = task[2]
    kind = TASK_KINDS[task[0]]
    if kind.direction_position is not None:
        region["direction"] = task[kind.direction_position]
    if speed_axis is not None:
        region[study.parameters[speed_axis].name] = task[kind.speed_position]
    return region


def orbit_arrays(result, starts: int) -> dict[str, Any]:
    """The stored arrays of one point's multi-start search (:func:`thermogear.sweep.multistart.point_orbits`;
    None where the gears jam: NaN)."""
    from thermogear.sweep.multistart import ORBIT_VARIABLES  # noqa: PLC0415

    arrays: dict[str, Any] = {name: np.full(starts, np.nan) for name in ORBIT_VARIABLES}
    arrays["stable_orbit_count"] = np.nan
    arrays["unsettled_start_share"] = np.nan
    if result is not None:
        arrays["stable_orbit_count"] = float(len(result["orbits"]))
        arrays["unsettled_start_share"] = result["unresolved"] + result["unbounded"]
        for number, values in enumerate(result["orbits"]):
            for name, (_, _, source) in ORBIT_VARIABLES.items():
                arrays[name][number] = float(values[source])
    return arrays
