"""What ``run`` builds before it solves, built without solving: the one set of checks every command shares.

``check`` used to test the backlash at the base-circle temperatures while ``run`` built the thermo-elastic mesh
from the whole temperature field (a hot bore, the FE field) and the dynamics problem from the hot flanks, so a case
``check`` called valid could jam in ``run`` (issue 25). :func:`preflight` builds, for each model, exactly the
components ``run`` builds — the temperature field (the FE model for ``temperature.model = "fem"``), the
thermo-elastic mesh and its backlash, the mesh problem — and refuses the case where any of them would: the same
message from ``check``, ``run`` and ``stiffness``. The components are cached on the case, so a command that goes
on to solve pays nothing twice.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from thermogear import warning_scope
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.dynamics.problems.solution_methods import solution_method
from thermogear.errors import CaseError, ProblemError

#: The case-file key a solver quantity comes from and the factor from the solver's SI value to the key's unit.
_KEYS = {"backlash": ("gears.backlash_normal_um", 1e6)}


def preflight(simulation_of: Callable[[str], Any], models: tuple[str, ...], dynamics, method: str,
              quiet: bool = True) -> None:
    """Build every component ``run`` would build for ``models`` (no solving); raise CaseError where one fails.
    ``simulation_of(model)`` gives a model's :class:`~thermogear.simulation.Simulation` of the case, ``dynamics``
    is the case's ``[dynamics]`` section and ``method`` the solution method ``run`` will use. ``quiet``: drop the
    warnings of the building (``check`` validates; the stage that uses a value warns). Asked through the case's
    resolver, :meth:`thermogear.orchestrator.Orchestrator.preflight`."""
    for model in models:
        simulation = simulation_of(model)
        try:
            if quiet:
                with warning_scope.ignored():
                    _build(simulation, dynamics, method)
            else:
                _build(simulation, dynamics, method)
        except ProblemError as error:
            key, scale = _KEYS.get(error.quantity, ("case", None))
            value = round(error.value * scale, 4) if scale is not None else error.value
            raise CaseError(key, value, error.allowed, f"the {model} model's mesh cannot be built (hot backlash "
                            f"{value} μm): {error.reason}" if scale else error.reason) from None


def _build(simulation, dynamics, method: str) -> None:
    """Build the problem ``simulation`` would solve under the ``[dynamics]`` section and ``method`` (the check)."""
    if mesh_law(dynamics.mesh).backlash:
        simulation.state.backlash_problem(dynamics.damping_in_flight)
    elif solution_method(method).from_rest:
        check_transient_length(simulation.problem, dynamics.transient_periods, simulation.speed_rpm)
    else:
        simulation.problem  # noqa: B018  (building it is the check)


def check_transient_length(problem, periods: int, speed_rpm: float) -> None:
    """Refuse a motion from rest of the linear mesh whose history would exceed what the RK4 transient stores
    (:data:`~thermogear.dynamics.transients.transient.MAX_STORED_SAMPLES`): its steps per interval keep |λ|·h <= 0.05
    (:func:`~thermogear.dynamics.transients.transient.default_steps_per_interval`), so at a low speed a mesh period
    holds many natural oscillations and needs many steps. ``run`` refused such a case with the solver's own words
    after ``check`` had accepted it (issue 25, found by the random-pair check)."""
    from thermogear.dynamics.transients.transient import MAX_STORED_SAMPLES, default_steps_per_interval

    per_period = problem.interval_count * default_steps_per_interval(problem)
    if periods * per_period + 1 <= MAX_STORED_SAMPLES:
        return
    most = (MAX_STORED_SAMPLES - 1) // per_period
    raise CaseError("dynamics.transient_periods", periods, f"<= {most} at {speed_rpm:g} rpm, or dynamics.method = "
                    "'periodic'" if most >= 1 else "dynamics.method = 'periodic' at this speed",
                    f"the motion from rest takes {per_period:,} RK4 steps per mesh period at this speed (each period "
                    f"holds about {problem.natural_frequency * problem.period:.3g} natural oscillations), more than "
                    f"the {MAX_STORED_SAMPLES:,} samples a transient stores; the periodic solver gives the steady "
                    "state directly")
