"""The store of a nonlinear-mesh branch study (:func:`thermogear.sweep.branches.branch_study` with ``out``): its
layout (:class:`~thermogear.sweep.task_store.StoreLayout`) and the region and arrays each task writes (a group's
branches, or one point's multi-start census)."""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.sweep.load_held import study_load_held

__all__ = ["BRANCH_VARIABLES", "branch_layout", "branch_region"]

#: Per-direction, per-model result variables: name → (units, long name).
BRANCH_VARIABLES: dict[str, tuple[str, str]] = {
    "kv": ("1", "dynamic load factor Kv = max pair force / static load (Luo & Li Eq. 29)"),
    "max_pair_load": ("N", "largest single-pair force over the orbit"),
    "max_system_load_ratio": ("1", "largest mesh force / static load"),
    "dte_mean": ("m", "mean dynamic transmission error"),
    "dte_rms": ("m", "RMS of the dynamic transmission error about its mean"),
    "dte_peak_to_peak": ("m", "peak-to-peak dynamic transmission error"),
    "contact_loss_fraction": ("1", "fraction of the period without driving-flank contact"),
    "back_side_contact": ("1", "1 where a back flank is struck"),
    "back_contact_fraction": ("1", "fraction of the period with a back flank in contact"),
    "period_count": ("1", "mesh periods after which the response repeats (1 periodic, >1 subharmonic)"),
    "converged": ("1", "1 where a stable periodic or subharmonic orbit was found"),
    "floquet_multiplier_max": ("1", "largest Floquet multiplier modulus of the orbit"),
    "residual": ("1", "scaled residual |phi_NT(y0) - y0| of the orbit's Newton iteration (large: not converged)"),
}
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
                  StoreVariable("mesh_frequency_hz", study.dims, "float", "Hz", "mesh frequency z1 n1 / 60")]
    coords: dict[str, Any] = {"direction": list(directions), "model": list(study.models)}
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
    definition = {**study.describe(), "kind": "nonlinear branches", "directions": list(directions),
                  "multistart": starts}
    attrs = {"mesh": "nonlinear", "directions": ",".join(directions), "case": study.case.name,
             "case_name": study.case.name, "case_source": str(study.case.source), "load": load,
             "load_note": load_note, "case_json": json.dumps(study.case.document, sort_keys=True, default=str)}
    return StoreLayout(coords=coords, variables=tuple(variables), tasks=tasks, definition=definition, attrs=attrs,
                       chunks=chunks)


def branch_region(study, task, speed_axis, result, starts: int) -> tuple[dict, dict]:
    """The region of the store a task writes and its arrays."""
    names = [p.name for a, p in enumerate(study.parameters) if a != speed_axis]
    region: dict[str, Any] = dict(zip(names, task[1]))
    if task[0] == "orbits":
        from thermogear.sweep.multistart import ORBIT_VARIABLES  # noqa: PLC0415

        region["model"] = task[2]
        if speed_axis is not None:
            region[study.parameters[speed_axis].name] = task[3]
        arrays = {name: np.full(starts, np.nan) for name in ORBIT_VARIABLES}
        arrays["stable_orbit_count"] = np.nan
        arrays["unsettled_start_share"] = np.nan
        if result is not None:
            arrays["stable_orbit_count"] = float(len(result["orbits"]))
            arrays["unsettled_start_share"] = result["unresolved"] + result["unbounded"]
            for number, values in enumerate(result["orbits"]):
                for name, (_, _, source) in ORBIT_VARIABLES.items():
                    arrays[name][number] = float(values[source])
        return region, arrays
    group = result
    pick = (lambda a: a) if speed_axis is not None else (lambda a: a[..., 0])
    arrays = {name: pick(group.arrays[name]) for name in BRANCH_VARIABLES}
    arrays["response"] = pick(group.response)
    arrays["jammed"] = pick(group.jammed).astype(np.int8)
    arrays["natural_frequency_hz"] = pick(group.natural_frequency_hz)
    arrays["static_load"] = pick(group.static_load)
    arrays["mesh_frequency_hz"] = pick(group.mesh_frequency_hz)
    return region, arrays
