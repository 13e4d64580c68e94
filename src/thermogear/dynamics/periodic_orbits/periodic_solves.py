"""Periodic responses solved once per system: a solve asked again for a system equal bit for bit (the same matrices,
pieces and factors) and the same samples per piece returns the first solve's response.

Several views of one operating point solve the same reduced system: the linear periodic response of a drivetrain
and the switch-free orbit its backlash solver starts from (every contact closed) are the one periodic orbit of the
same matrices where no clearance adds a vector to the basis. Equality is tested on the arrays themselves
(``numpy.array_equal`` of every field), never assumed, so a system that differs in one bit is solved afresh. Knows
nothing of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from thermogear.dynamics.periodic_orbits.periodic_ndof import PeriodicResponse, PiecewiseLinearSystem, periodic_response

__all__ = ["PeriodicSolves", "same_system"]


def same_system(first: PiecewiseLinearSystem, second: PiecewiseLinearSystem) -> bool:
    """Whether two piecewise-linear systems hold the same matrices, nodes and factors, bit for bit."""
    return first is second or all(np.array_equal(getattr(first, item.name), getattr(second, item.name))
                                  for item in fields(first))


class PeriodicSolves:
    """The periodic responses solved so far
    (:func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.periodic_response`), each kept with its system and
    samples per piece. ``observer`` is passed to a solve that runs; a response found again feeds no observer (the caller
    sees that its observer was not fed, e.g. ``MotionProjector.complete``).
    ``capacity``: the most responses kept, the oldest dropped first (a sweep over speeds keeps its last few)."""

    def __init__(self, capacity: int = 2) -> None:
        self.capacity = max(1, int(capacity))
        self._kept: list[tuple[PiecewiseLinearSystem, int, PeriodicResponse]] = []

    def __len__(self) -> int:
        return len(self._kept)

    def find(self, system: PiecewiseLinearSystem, samples_per_piece: int) -> PeriodicResponse | None:
        """The response kept for ``system`` (equal bit for bit) at ``samples_per_piece``, else None."""
        for kept, samples, response in self._kept:
            if samples == int(samples_per_piece) and same_system(kept, system):
                return response
        return None

    def response(self, system: PiecewiseLinearSystem, samples_per_piece: int = 16,
                 observer=None) -> PeriodicResponse:
        """The periodic response of ``system`` at ``samples_per_piece``: the kept one, else solved and kept."""
        found = self.find(system, samples_per_piece)
        if found is not None:
            return found
        solved = periodic_response(system, samples_per_piece, observer=observer)
        self._kept = [*self._kept, (system, int(samples_per_piece), solved)][-self.capacity:]
        return solved
