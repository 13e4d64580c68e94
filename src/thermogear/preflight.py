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

from thermogear import warning_scope
from thermogear.errors import CaseError, ProblemError

#: The case-file key a solver quantity comes from and the factor from the solver's SI value to the key's unit.
_KEYS = {"backlash": ("gears.backlash_normal_um", 1e6)}


def preflight(case, models: tuple[str, ...] = ("elastic", "thermal"), quiet: bool = True) -> None:
    """Build every component ``run`` would build for ``models`` (no solving); raise CaseError where one fails.
    ``quiet``: drop the warnings of the building (``check`` validates; the stage that uses a value warns)."""
    from thermogear.simulation import Simulation  # registers the FE temperature model too

    for model in models:
        simulation = Simulation(case, model)
        try:
            if quiet:
                with warning_scope.ignored():
                    _build(simulation, case)
            else:
                _build(simulation, case)
        except ProblemError as error:
            key, scale = _KEYS.get(error.quantity, ("case", None))
            value = round(error.value * scale, 4) if scale is not None else error.value
            raise CaseError(key, value, error.allowed, f"the {model} model's mesh cannot be built (hot backlash "
                            f"{value} μm): {error.reason}" if scale else error.reason) from None


def _build(simulation, case) -> None:
    if case.dynamics.mesh == "nonlinear":
        simulation.state.backlash_problem(case.dynamics.damping_in_flight)
    else:
        simulation.problem  # noqa: B018  (building it is the check)
