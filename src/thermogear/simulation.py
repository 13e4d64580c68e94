"""The model chain of one operating point: case → mesh model → dynamics → response.

``Simulation(case, model="thermal", solver=None)`` wires the stages of design.md for the thermal model of Luo & Li (2020)
(k_T with c_r, Eq. 6) or the elastic one (k_e with c_e, Eq. 5). The elastic and thermal models are the same
pipeline with different per-pair stiffness and damping; nothing here knows how either is computed: the
:class:`~thermogear.mesh.model.MeshModel` gives the mesh period, a solver object the response (passed in, or the one
the case's ``[dynamics]`` names, resolved once by :func:`solver_for`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Callable, Literal

import numpy as np

from thermogear.case import Case
from thermogear.dynamics.problems.solution_methods import SOLUTION_METHODS, solution_method
from thermogear.dynamics.solvers import (BacklashShootingSolver, BacklashTransientSolver, PeriodicSolver, Solver,
                                         TransientSolver)
from thermogear.mesh.model import MeshModel
from thermogear.mesh.model_names import MODELS, Model
from thermogear.mesh.pair_models import check_model
from thermogear.mesh.state import MeshState

Method = Literal["periodic", "transient"]
METHODS: tuple[str, ...] = tuple(SOLUTION_METHODS)


@dataclass(frozen=True)
class Simulation:
    """One operating point of one model.

    Parameters
    ----------
    case:
        The validated case.
    model:
        ``"elastic"`` (k_e, damping with oil at the reference temperature), ``"thermal"`` (the case's ``[thermal]
        model``, damping with the viscosity at the flank temperature), or the name of another registered pair
        model (:data:`thermogear.mesh.pair_models.PAIR_MODELS`).
    points_per_period:
        Intervals of the mesh-cycle grid; default from the case's [dynamics] section.
    solver:
        The dynamics solver (:mod:`thermogear.dynamics.solvers`); default the one the case's ``[dynamics]`` names
        (:func:`solver_for`).
    """

    case: Case
    model: Model | str = "thermal"
    points_per_period: int | None = None
    solver: Solver | None = None

    def __post_init__(self) -> None:
        check_model(self.model)

    # ------------------------------------------------------------------------------------ mesh model
    @cached_property
    def mesh_model(self) -> MeshModel:
        """The mesh model of the case under this model: the one reader of the case for physics."""
        return MeshModel(self.case, self.model)

    @property
    def speed_rpm(self) -> float:
        return self.mesh_model.speed_rpm

    @cached_property
    def state(self) -> MeshState:
        """The mesh period at the case's operating point: k(τ), c(τ), deviations, load, mass."""
        return self.mesh_model.state(points_per_period=self.points_per_period)

    @property
    def grid(self):
        """The mesh-cycle grid (interval nodes with every contact transition, pair roll distances)."""
        return self.state.grid

    @property
    def pair_stiffness(self) -> np.ndarray:
        """Per-pair stiffness on the grid, (slots, n) [N/m], total over the face width."""
        return self.state.pair_stiffness

    @property
    def mesh_stiffness(self) -> np.ndarray:
        """k(τ) on the grid intervals [N/m]: the pairs in contact in parallel."""
        return self.state.mesh_stiffness

    @property
    def mesh_damping(self) -> np.ndarray:
        """c(τ) on the grid intervals [N·s/m] under the case's damping rule."""
        return self.state.mesh_damping

    @property
    def mesh_stiffness_mean(self) -> float:
        """Time mean of k(τ) over one mesh period [N/m]."""
        return self.state.mean_mesh_stiffness

    @property
    def mesh_frequency_hz(self) -> float:
        return self.state.mesh_frequency_hz

    @property
    def natural_frequency_hz(self) -> float:
        """f_n = sqrt(mean k / me) / 2π [Hz]."""
        return math.sqrt(self.mesh_stiffness_mean / self.state.mass) / (2.0 * math.pi)

    @property
    def frequency_ratio(self) -> float:
        """λ = f_mesh / f_n [–] (the paper's frequency ratio)."""
        return self.mesh_frequency_hz / self.natural_frequency_hz

    # ------------------------------------------------------------------------------------- dynamics
    @cached_property
    def problem(self):
        """The gear-agnostic dynamics problem me·ẍ + c(τ)ẋ + k(τ)(x − e(τ)) = w over one mesh period."""
        return self.state.problem()

    def run(self, method: Method | None = None, include_damping_force: bool | None = None,
            solver: Solver | None = None):
        """Solve the dynamics and return the response with the checks of a thermal result (``flags``).

        See :meth:`solve` for the methods."""
        from thermogear.load_capacity import load_flags
        from thermogear.mesh.plausibility import damping_ratio_flags, thermal_result_flags

        response = self.solve(method, include_damping_force, solver)
        response.metrics["damping_ratio"] = self.state.damping_ratio  # the solver's fresh dict: a gear quantity
        case = self.case
        flags = load_flags(case.gear_pair, case.material, case.operating_point.torque)  # a load no tooth carries
        flags += damping_ratio_flags(self.state)
        if self.mesh_model.thermal:
            flags += thermal_result_flags(self.mesh_model, self.state, response.metrics)
        return replace(response, flags=flags)

    def solve(self, method: Method | None = None, include_damping_force: bool | None = None,
              solver: Solver | None = None):
        """Solve the dynamics and return the response.

        The solver: ``solver`` if given, else the one a ``method`` string names (:func:`solver_for`), else the
        simulation's own (``Simulation(..., solver=...)``), else the case's ``[dynamics]`` choice. A solver of the
        backlash problem gets the mesh with backlash, a linear one the linear mesh (:mod:`thermogear.dynamics.solvers`).
        """
        dynamics = self.case.dynamics
        if solver is None:
            solver = self.solver if method is None and self.solver is not None else solver_for(dynamics, method)
        damping_force = dynamics.include_damping_force if include_damping_force is None else include_damping_force
        problem = self.state.backlash_problem(dynamics.damping_in_flight) if solver.backlash else self.problem
        return solver.solve(problem, include_damping_force=damping_force, label=self.model)


#: The solver of each (``[dynamics] mesh``, method) from the case's ``[dynamics]`` options: the one place a method
#: name becomes a solver.
_SOLVERS: dict[tuple[str, str], Callable[..., Solver]] = {
    ("linear", "periodic"): lambda dynamics: PeriodicSolver(dynamics.samples_per_interval),
    ("linear", "transient"): lambda dynamics: TransientSolver(dynamics.transient_periods),
    ("nonlinear", "periodic"): lambda dynamics: BacklashShootingSolver(dynamics.samples_per_interval),
    ("nonlinear", "transient"): lambda dynamics: BacklashTransientSolver(dynamics.transient_periods,
                                                                        dynamics.samples_per_interval),
}


def solver_for(dynamics, method: str | None = None) -> Solver:
    """The solver of a case's ``[dynamics]`` section for a method (``"periodic"`` or ``"transient"``; default the
    section's own): the exact periodic steady state or the transient from rest, of the linear mesh or of the mesh
    with backlash as ``[dynamics] mesh`` says."""
    method = method or dynamics.method
    solution_method(method, key="method")  # a CaseError for an unknown one (the registry of the names)
    return _SOLVERS[(dynamics.mesh, method)](dynamics)


def compare(simulation: Simulation, method: Method | None = None) -> dict:
    """Run the elastic and the thermal model of a simulation's operating point (its case, points per period and
    solver; its own model is one of the two): ``{"elastic": response, "thermal": response}``."""
    return {model: replace(simulation, model=model).run(method) for model in MODELS}
