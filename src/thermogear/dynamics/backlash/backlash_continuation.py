"""Follow a branch of backlash-model responses over operating points ordered by speed, sweeping up or down.

Each point starts Newton from the converged state of its neighbour at τ = 0 (the mesh period is rescaled with
the speed, so the state at τ = 0 transfers directly). When that Newton fails or lands on an unstable orbit, the
point is solved by :func:`~thermogear.dynamics.backlash.backlash_periodic.periodic_response` from the same state: a
transient run-in (what a slowly swept gearbox does when its branch ends: it jumps to the attractor that is
left), then sub-harmonics. A point with no converged stable orbit is reported with its residual and the sweep
goes on from the last good state. Sweeping up and down through a softening primary resonance with contact loss
therefore shows the jump-up / jump-down hysteresis (Kahraman & Singh 1990, J. Sound Vib. 142(1):49–75).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_metrics import orbit_metrics
from thermogear.dynamics.backlash.backlash_periodic import (BacklashOrbit, orbit_from_shot, periodic_response, shoot,
                                                   shot_is_stable)
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.problems.continuation_inputs import continuation_labels, continuation_order
from thermogear.errors import ModelLimitError

__all__ = ["Branch", "BranchPoint", "branch_options", "branch_point", "follow_branch"]

_FLOAT_METRICS = ("residual", "largest_multiplier", "contact_loss_fraction", "back_contact_fraction",
                  "max_mesh_force", "max_pair_force", "kv", "dte_peak_to_peak", "dte_rms", "dte_mean")


@dataclass(frozen=True)
class Branch:
    """Responses along a sweep, one entry per problem in the order given (whatever the sweep direction).

    ``parameter`` the values labelling the problems (e.g. speed [rpm]); ``direction`` "up" (first to last) or
    "down"; ``response`` "periodic" | "subharmonic" | "non-periodic" | "failed"; ``period_count``, ``converged``;
    ``initial_state`` (m, 2) the state at τ = 0 [m, m/s]; ``metrics`` {name: (m,) array} of the floats of
    :func:`~thermogear.dynamics.backlash.backlash_metrics.orbit_metrics` plus ``back_side_contact`` (bool).
    """

    parameter: np.ndarray
    direction: str
    response: np.ndarray
    period_count: np.ndarray
    converged: np.ndarray
    initial_state: np.ndarray
    metrics: dict[str, np.ndarray]

    def __getitem__(self, name: str) -> np.ndarray:
        return self.metrics[name]


def _solve_point(problem: BacklashMeshProblem, state: tuple[float, float] | None, options: dict) -> BacklashOrbit:
    if state is not None:
        result = shoot(problem, state, 1, options["tolerance"], options["max_iterations"])
        if shot_is_stable(result, problem):
            return orbit_from_shot(problem, result, 1, options["samples_per_interval"], result["iterations"])
    return periodic_response(problem, initial_state=state, **options)


@dataclass(frozen=True)
class BranchPoint:
    """One point of a branch: ``response``, ``period_count``, ``converged``, ``initial_state`` (2,) at τ = 0
    [m, m/s] (NaN where the point failed), ``metrics`` {name: float} of :data:`_FLOAT_METRICS` plus
    ``back_side_contact`` (bool), and ``carried``: the state the branch goes on from (this orbit's where it
    converged, else the state the point started from)."""

    response: str
    period_count: int
    converged: bool
    initial_state: np.ndarray
    metrics: dict
    carried: tuple[float, float] | None


def branch_options(max_period_count: int = 4, tolerance: float = 1e-10, max_iterations: int = 30,
                   run_in_periods: int = 200, classify_periods: int = 400, samples_per_interval: int = 1) -> dict:
    """The solver options of a branch point (the defaults of :func:`follow_branch`)."""
    return {"max_period_count": max_period_count, "tolerance": tolerance, "max_iterations": max_iterations,
            "run_in_periods": run_in_periods, "classify_periods": classify_periods,
            "samples_per_interval": samples_per_interval}


def branch_point(problem: BacklashMeshProblem, state: tuple[float, float] | None, options: dict | None = None,
                 include_damping_force: bool = False) -> BranchPoint:
    """One step of a continuation: the orbit of ``problem`` started from its neighbour's ``state`` (None: from the
    linear response), as :func:`follow_branch` solves each point (a point that fails is reported "failed" and the
    state carries over unchanged)."""
    options = branch_options() if options is None else options
    metrics = {name: np.nan for name in _FLOAT_METRICS}
    try:
        orbit = _solve_point(problem, state, options)
    except ModelLimitError:
        return BranchPoint("failed", 0, False, np.full(2, np.nan), {**metrics, "back_side_contact": False}, state)
    values = orbit_metrics(orbit, include_damping_force=include_damping_force)
    metrics = {name: values[name] for name in _FLOAT_METRICS}
    metrics["back_side_contact"] = values["back_side_contact"]
    return BranchPoint(orbit.response, orbit.period_count, orbit.converged, orbit.initial_state, metrics,
                       orbit.initial_state if orbit.converged else state)


def follow_branch(problems: Sequence[BacklashMeshProblem], direction: str = "up",
                  parameter: Sequence[float] | None = None, initial_state: tuple[float, float] | None = None,
                  max_period_count: int = 4, tolerance: float = 1e-10, max_iterations: int = 30,
                  run_in_periods: int = 200, classify_periods: int = 400, samples_per_interval: int = 1,
                  include_damping_force: bool = False) -> Branch:
    """Continuation over ``problems`` (ordered by speed), ``direction`` "up" or "down" (module docstring).

    ``samples_per_interval`` defaults to 1: the metrics stay exact at the maxima (switches, extrema and node
    limits are always recorded); only the DTE RMS and spectrum use the sampled curve.
    """
    count = len(problems)
    labels = continuation_labels(direction, count, parameter, "problem")
    options = branch_options(max_period_count, tolerance, max_iterations, run_in_periods, classify_periods,
                             samples_per_interval)
    response = np.empty(count, dtype=object)
    period_count = np.zeros(count, dtype=np.int64)
    converged = np.zeros(count, dtype=bool)
    states = np.full((count, 2), np.nan)
    metrics = {name: np.full(count, np.nan) for name in _FLOAT_METRICS}
    metrics["back_side_contact"] = np.zeros(count, dtype=bool)
    order = continuation_order(direction, count)
    state = None if initial_state is None else (float(initial_state[0]), float(initial_state[1]))
    for index in order:
        point = branch_point(problems[index], state, options, include_damping_force)
        state = point.carried
        response[index] = point.response  # a failed point: "failed", NaN metrics, 0 periods, not converged
        period_count[index] = point.period_count
        converged[index] = point.converged
        states[index] = point.initial_state
        for name in _FLOAT_METRICS:
            metrics[name][index] = point.metrics[name]
        metrics["back_side_contact"][index] = point.metrics["back_side_contact"]
    return Branch(parameter=labels, direction=direction, response=response.astype(str), period_count=period_count,
                  converged=converged, initial_state=states, metrics=metrics)
