"""Solvers are objects passed in: Simulation(case, model, solver=...) uses the one given, a method string is resolved
once to a solver (solver_for), and a solver gets the problem of its kind (linear, or with backlash)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import pytest

from thermogear.case import load_case
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.dynamics.solvers import (BacklashShootingSolver, BacklashTransientSolver, PeriodicSolver,
                                         TransientSolver)
from thermogear.errors import CaseError
from thermogear.simulation import Simulation, solver_for


@pytest.fixture(scope="module")
def luo2019():
    return load_case("luo2019").with_changes(**{"dynamics.points_per_period": 128})


@pytest.mark.parametrize(("mesh", "method", "expected"), [
    ("linear", "periodic", PeriodicSolver), ("linear", "transient", TransientSolver),
    ("nonlinear", "periodic", BacklashShootingSolver), ("nonlinear", "transient", BacklashTransientSolver)])
def test_a_method_resolves_to_the_solver_of_the_mesh(luo2019, mesh, method, expected):
    dynamics = luo2019.with_changes(**{"dynamics.mesh": mesh, "dynamics.samples_per_interval": 3,
                                       "dynamics.transient_periods": 7}).dynamics
    solver = solver_for(dynamics, method)
    assert type(solver) is expected and solver.method == method and solver.backlash == (mesh == "nonlinear")
    assert getattr(solver, "samples_per_interval", 3) == 3 and getattr(solver, "periods", 7) == 7


def test_the_default_method_is_the_cases(luo2019):
    assert type(solver_for(luo2019.dynamics)) is PeriodicSolver  # luo2019: linear, periodic


def test_an_unknown_method_is_a_case_error(luo2019):
    with pytest.raises(CaseError, match="periodic | transient"):
        solver_for(luo2019.dynamics, "shooting")


@dataclass(frozen=True)
class RecordingSolver:
    """A solver that only records the problem it was given."""

    backlash: bool
    method: ClassVar[str] = "recorded"

    def solve(self, problem, *, include_damping_force=False, label=""):
        return problem, include_damping_force, label


@pytest.mark.parametrize(("backlash", "problem_type"), [(False, MeshDynamicsProblem), (True, BacklashMeshProblem)])
def test_a_solver_passed_in_is_used_with_the_problem_of_its_kind(luo2019, backlash, problem_type):
    case = luo2019.with_changes(**{"dynamics.mesh": "nonlinear"})  # the backlash is known (needed by the one kind)
    problem, damping_force, label = Simulation(case, "elastic", solver=RecordingSolver(backlash)).solve()
    assert type(problem) is problem_type and label == "elastic"
    assert damping_force == luo2019.dynamics.include_damping_force


def test_a_solver_argument_gives_what_the_method_string_gives(luo2019):
    simulation = Simulation(luo2019, "thermal")
    by_string = simulation.run("transient").metrics
    by_object = Simulation(luo2019, "thermal", solver=TransientSolver(luo2019.dynamics.transient_periods)).run().metrics
    assert by_object == by_string
    # a method given to run() names the solver for that call, over the simulation's own
    assert simulation.run("periodic").method == Simulation(luo2019, "thermal", solver=TransientSolver(3)).run(
        "periodic").method
