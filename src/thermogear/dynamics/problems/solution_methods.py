"""The solution method of one operating point, chosen once: ``[dynamics] method`` (or ``run --method``) =
``"periodic" | "transient"`` resolved here into what the rest of the package asks (is it the motion from rest, what
source does it cite), never compared as a string.

* ``"periodic"``: the exact periodic steady state of the mesh period (Floquet 1883: the monodromy of the
  piecewise-constant system, or its shooting for the backlash dead zone);
* ``"transient"``: the motion from rest, integrated over ``[dynamics] transient_periods`` mesh periods (classical
  fourth-order Runge–Kutta), whose last period is reported.

A new method is one :class:`SolutionMethod` line in :data:`SOLUTION_METHODS` (and its solvers in
:mod:`thermogear.simulation`), as a contact law is one line of :data:`thermogear.dynamics.problems.mesh_laws.MESH_LAWS`.
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.errors import CaseError

__all__ = ["SOLUTION_METHODS", "SolutionMethod", "solution_method"]


@dataclass(frozen=True)
class SolutionMethod:
    """A solution method: ``name`` (the ``[dynamics] method`` value), whether it is the motion from rest
    (``from_rest``; else the periodic steady state) and the key of the source its results cite (``citation``, a
    key of :mod:`thermogear.citations`)."""

    name: str
    from_rest: bool
    citation: str


#: Every solution method by name (the first the default of ``[dynamics] method``): the one place the names are
#: compared.
SOLUTION_METHODS: dict[str, SolutionMethod] = {method.name: method for method in (
    SolutionMethod("periodic", from_rest=False, citation="floquet1883"),
    SolutionMethod("transient", from_rest=True, citation="rk4"))}


def solution_method(name: str, key: str = "dynamics.method") -> SolutionMethod:
    """The solution method called ``name``; a CaseError naming ``key`` (the case-file key or the option it came
    from) for any other name."""
    method = SOLUTION_METHODS.get(name)
    if method is None:
        raise CaseError(key, name, " | ".join(SOLUTION_METHODS), "unknown solution method")
    return method
