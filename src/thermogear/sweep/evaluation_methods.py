"""How a study evaluates its points, chosen once: ``method`` of :func:`thermogear.sweep.run_study` (``sweep
--method``) resolved here into what the engine and the study kinds ask, never compared as a string.

* ``"batch"`` (the default): the points that share a case but for the speed are solved together, on the fast path
  where it is exact (:func:`thermogear.sweep.batch.evaluate_group`); a backlash mesh follows its branches in speed
  (:mod:`thermogear.sweep.branches`), a drivetrain its orbit on its modal reduction;
* ``"simulation"``: one :class:`~thermogear.simulation.Simulation` per point and model (the reference of the fast
  path, for the linear-mesh grid only).

A new method is one :class:`EvaluationMethod` line in :data:`EVALUATION_METHODS`.
"""

from __future__ import annotations

from dataclasses import dataclass

from thermogear.registry import registered

__all__ = ["EVALUATION_METHODS", "EvaluationMethod", "evaluation_method", "is_batched"]


@dataclass(frozen=True)
class EvaluationMethod:
    """A study's evaluation method: ``name`` (the ``method`` value) and whether it solves the points of a group
    together (``batched``: the fast path, a branch, a drivetrain's speed sweep; else one Simulation per point)."""

    name: str
    batched: bool


#: Every evaluation method by name (the first the default): the one place the names are compared.
EVALUATION_METHODS: dict[str, EvaluationMethod] = {method.name: method for method in (
    EvaluationMethod("batch", batched=True), EvaluationMethod("simulation", batched=False))}


def evaluation_method(name: str) -> EvaluationMethod:
    """The evaluation method called ``name``; a CaseError naming ``method`` for any other."""
    return registered(EVALUATION_METHODS, name, "method", "unknown evaluation method")


def is_batched(name: str) -> bool:
    """Whether ``name`` is a batched evaluation method (False for an unknown name: the caller that runs it refuses
    it with :func:`evaluation_method`'s error, where it always did)."""
    method = EVALUATION_METHODS.get(name)
    return method is not None and method.batched
