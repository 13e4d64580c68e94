"""The model chain of one operating point: case → mesh model → dynamics → response.

``Simulation(case, model="thermal")`` wires the stages of design.md for the thermal model of Luo & Li (2020)
(k_T with c_r, Eq. 6) or the elastic one (k_e with c_e, Eq. 5). The elastic and thermal models are the same
pipeline with different per-pair stiffness and damping; nothing here knows how either is computed: the
:class:`~thermogear.mesh.model.MeshModel` gives the mesh period, a solver the response.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Literal

import numpy as np

from thermogear.case import Case
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel
from thermogear.mesh.model_names import MODELS, Model
from thermogear.mesh.state import MeshState

Method = Literal["periodic", "transient"]


@dataclass(frozen=True)
class Simulation:
    """One operating point of one model.

    Parameters
    ----------
    case:
        The validated case.
    model:
        ``"elastic"`` (k_e, damping with oil at the reference temperature) or ``"thermal"`` (k_T, damping with
        the viscosity at the flank temperature).
    points_per_period:
        Intervals of the mesh-cycle grid; default from the case's [dynamics] section.
    """

    case: Case
    model: Model = "thermal"
    points_per_period: int | None = None

    def __post_init__(self) -> None:
        if self.model not in MODELS:
            raise CaseError("model", self.model, " | ".join(MODELS), "unknown model")

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

    def run(self, method: Method | None = None, include_damping_force: bool | None = None):
        """Solve the dynamics and return the response with the checks of a thermal result (``flags``).

        See :meth:`solve` for the methods."""
        from thermogear.load_capacity import load_flags
        from thermogear.mesh.plausibility import damping_ratio_flags, thermal_result_flags

        response = self.solve(method, include_damping_force)
        response.metrics["damping_ratio"] = self.state.damping_ratio  # the solver's fresh dict: a gear quantity
        case = self.case
        flags = load_flags(case.gear_pair, case.material, case.operating_point.torque)  # a load no tooth carries
        flags += damping_ratio_flags(self.state)
        if self.model == "thermal":
            flags += thermal_result_flags(self.mesh_model, self.state, response.metrics)
        return replace(response, flags=flags)

    def solve(self, method: Method | None = None, include_damping_force: bool | None = None):
        """Solve the dynamics and return the response.

        Linear mesh (``[dynamics] mesh = "linear"``): ``"periodic"`` gives the exact periodic steady state
        (Floquet/monodromy), ``"transient"`` the motion from rest (x = ẋ = 0, as the paper) over the case's number
        of mesh periods with the compiled RK4 — a :class:`~thermogear.dynamics.response.DynamicResponse`.
        Nonlinear mesh (the default): the steady response of the backlash model by shooting with the exact
        event-driven integrator, with its branch — a :class:`~thermogear.dynamics.nonlinear_response.NonlinearResponse`.
        """
        from thermogear.dynamics.response import response_from_orbit, response_from_transient

        dynamics = self.case.dynamics
        method = method or dynamics.method
        damping_force = dynamics.include_damping_force if include_damping_force is None else include_damping_force
        if method not in ("periodic", "transient"):
            raise CaseError("method", method, "periodic | transient", "unknown solution method")
        if dynamics.mesh == "nonlinear":
            from thermogear.dynamics.nonlinear_response import nonlinear_response, nonlinear_transient

            problem = self.state.backlash_problem(dynamics.damping_in_flight)
            if method == "transient":
                return nonlinear_transient(problem, dynamics.transient_periods, dynamics.samples_per_interval,
                                           label=self.model, include_damping_force=damping_force)
            return nonlinear_response(problem, include_damping_force=damping_force, label=self.model,
                                      samples_per_interval=dynamics.samples_per_interval)
        if method == "periodic":
            from thermogear.dynamics.periodic import periodic_steady_state

            orbit = periodic_steady_state(self.problem, dynamics.samples_per_interval)
            return response_from_orbit(self.problem, orbit, include_damping_force=damping_force, label=self.model)
        from thermogear.dynamics.transient import transient_from_rest

        history = transient_from_rest(self.problem, periods=dynamics.transient_periods)
        return response_from_transient(self.problem, history, include_damping_force=damping_force, label=self.model)


def compare(case: Case, method: Method | None = None, points_per_period: int | None = None) -> dict:
    """Run the elastic and the thermal model of one case: ``{"elastic": response, "thermal": response}``."""
    return {model: Simulation(case, model, points_per_period).run(method) for model in MODELS}
