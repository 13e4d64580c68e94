"""Study axes that change nothing: a parameter whose values give every model the same mesh period.

A sweep over such an axis would store identical columns and look like a result (an oil temperature with a
tabulated flank temperature field enters neither model, for instance). The check compares, per model, what the
mesh model hands the solvers — pair stiffness, damping, deviations, load, mass and nodes — at the first and the
last value of each parameter (the others at their first values): equal arrays mean the axis is inert.
"""

from __future__ import annotations

import numpy as np

from thermogear.temperature.kinds import temperature_source
from thermogear.errors import JammingError
from thermogear.mesh.model import MeshModel

__all__ = ["inert_parameters"]

#: Parameters that act on the grid and the dynamics by definition and are never inert.
_ALWAYS_ACTIVE = ("operating.speed_rpm",)


def _signature(mesh: MeshModel) -> list[np.ndarray]:
    state = mesh.state()
    return [state.grid.nodes, state.pair_stiffness, state.mesh_damping, state.pair_deviation,
            np.array([state.normal_load, state.mass, float(state.backlash or 0.0)])]


def inert_parameters(study) -> list[str]:
    """Names of the study's parameters whose first and last values give every model identical mesh periods.
    Cases whose temperature comes from the FE heat model are not checked (each state would run the FE model)."""
    if temperature_source(study.case.temperature.model).solved_per_state:
        return []
    first = tuple(parameter.values[0] for parameter in study.parameters)
    inert = []
    for axis, parameter in enumerate(study.parameters):
        if parameter.size < 2 or parameter.key in _ALWAYS_ACTIVE:
            continue
        last = first[:axis] + (parameter.values[-1],) + first[axis + 1:]
        try:
            start, end = study.case_at(first), study.case_at(last)
        except JammingError:  # an end of the axis jams: the axis does something
            continue
        same = all(np.array_equal(a, b) for model in study.models
                   for a, b in zip(_signature(MeshModel(start, model)), _signature(MeshModel(end, model))))
        if same:
            inert.append(parameter.name)
    return inert
