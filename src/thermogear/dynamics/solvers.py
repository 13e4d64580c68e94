"""Solvers as objects: how one mesh period's problem becomes a response, chosen once and passed in.

Each solver takes the gear-agnostic problem of its kind and returns a response; it knows nothing of gears or cases.
Its options (samples per interval, number of periods) are fields, set where the solver is chosen.

* :class:`PeriodicSolver` — the exact periodic steady state of the linear problem (Floquet/monodromy).
* :class:`TransientSolver` — the linear motion from rest (x = ẋ = 0) over a number of mesh periods, compiled RK4.
* :class:`BacklashShootingSolver` — the steady response of the backlash problem by shooting with the exact
  event-driven integrator, with its branch.
* :class:`BacklashTransientSolver` — the backlash motion from rest over a number of mesh periods.

``backlash`` says which problem a solver takes: the linear one (:class:`~thermogear.dynamics.problems.problem.
MeshDynamicsProblem`) or the one with backlash
(:class:`~thermogear.dynamics.problems.backlash_problem.BacklashMeshProblem`); the caller builds that problem. Solver
modules are imported when a solver runs (start-up stays light).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Protocol


class Solver(Protocol):
    """A solver of one mesh period's problem."""

    backlash: ClassVar[bool]
    method: ClassVar[str]

    def solve(self, problem, *, include_damping_force: bool = False, label: str = ""): ...


@dataclass(frozen=True)
class PeriodicSolver:
    """Exact periodic steady state of the linear problem; ``samples_per_interval`` samples of the orbit per grid
    interval (:func:`thermogear.dynamics.periodic_orbits.periodic.periodic_steady_state`)."""

    samples_per_interval: int = 64
    backlash: ClassVar[bool] = False
    method: ClassVar[str] = "periodic"

    def solve(self, problem, *, include_damping_force: bool = False, label: str = ""):
        from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
        from thermogear.dynamics.response import response_from_orbit

        orbit = periodic_steady_state(problem, self.samples_per_interval)
        return response_from_orbit(problem, orbit, include_damping_force=include_damping_force, label=label)


@dataclass(frozen=True)
class TransientSolver:
    """Linear motion from rest over ``periods`` mesh periods (:func:`thermogear.dynamics.transients.transient.
    transient_from_rest`)."""

    periods: int = 60
    backlash: ClassVar[bool] = False
    method: ClassVar[str] = "transient"

    def solve(self, problem, *, include_damping_force: bool = False, label: str = ""):
        from thermogear.dynamics.response import response_from_transient
        from thermogear.dynamics.transients.transient import transient_from_rest

        history = transient_from_rest(problem, periods=self.periods)
        return response_from_transient(problem, history, include_damping_force=include_damping_force, label=label)


@dataclass(frozen=True)
class BacklashShootingSolver:
    """Steady response of the backlash problem by shooting, with its branch
    (:func:`thermogear.dynamics.backlash.nonlinear_response.nonlinear_response`)."""

    samples_per_interval: int = 4
    backlash: ClassVar[bool] = True
    method: ClassVar[str] = "periodic"

    def solve(self, problem, *, include_damping_force: bool = False, label: str = ""):
        from thermogear.dynamics.backlash.nonlinear_response import nonlinear_response

        return nonlinear_response(problem, include_damping_force=include_damping_force, label=label,
                                  samples_per_interval=self.samples_per_interval)


@dataclass(frozen=True)
class BacklashTransientSolver:
    """Backlash motion from rest over ``periods`` mesh periods
    (:func:`thermogear.dynamics.backlash.nonlinear_response.nonlinear_transient`)."""

    periods: int = 60
    samples_per_interval: int = 4
    backlash: ClassVar[bool] = True
    method: ClassVar[str] = "transient"

    def solve(self, problem, *, include_damping_force: bool = False, label: str = ""):
        from thermogear.dynamics.backlash.nonlinear_response import nonlinear_transient

        return nonlinear_transient(problem, self.periods, self.samples_per_interval, label=label,
                                   include_damping_force=include_damping_force)


__all__ = ["BacklashShootingSolver", "BacklashTransientSolver", "PeriodicSolver", "Solver", "TransientSolver"]
