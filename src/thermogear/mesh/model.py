"""The mesh model: the one place that turns a case into what the dynamics need.

``MeshModel(case, model)`` reads the case once for its physics and answers, for the model chosen
(``"elastic"``: k_e with the oil at its reference temperature, Luo & Li (2020) Eq. 5; ``"thermal"``: the case's
thermal model, Eq. 6), per tooth pair along the roll distance: stiffness, friction damping, unloaded deviation
and backlash; and for an operating point (speed and normal load are arguments, never re-read from the case) the
state of one mesh period — k(τ), c(τ), the excitation, the static load, the equivalent mass and the period
(:class:`~thermogear.mesh.state.MeshState`). ``Simulation``, the sweep (both paths), the damping and stiffness
commands, the FE heat input and the report take what they need from here. Which model answers the per-pair
questions is chosen once, as a pair model (:mod:`thermogear.mesh.pair_models`); nothing here tests a model's name.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from thermogear.friction.damping import (PairDamping, friction_damping_exponents, friction_pair_damping,
                                         mesh_circular_frequency, mesh_damping)
from thermogear.errors import CaseError
from thermogear.friction.models import FrictionLaw, friction_law, helical_load_factor, normal_section_radius
from thermogear.lubricant import Lubricant, lubricant_from_case
from thermogear.mesh.helical_model import helical_model_state
from thermogear.mesh.model_names import MODELS, Model
from thermogear.mesh.pair_models import PairModelBase, check_model, pair_model_class
from thermogear.mesh.state import MeshState
from thermogear.mesh.table_file import mesh_table_of
from thermogear.geometry.mesh_cycle import MeshCycle, MeshGrid, load_share_at, load_shares
from thermogear.temperature.kinds import temperature_source
from thermogear.temperature.source import TemperatureField
from thermogear.choices.thermal_models import x_te_source
from thermogear.thermoelastic.load_sharing import loaded_transmission_error
from thermogear.thermoelastic.mesh import ThermoelasticMesh

if TYPE_CHECKING:
    from thermogear.case import Case
    from thermogear.schema import DampingSection


# Temperature sources whose temperatures depend on the operating point (speed and load) are those a model computes
# (temperature_source(name).computed: the FE heat model, the gearbox thermal model): a sweep cannot reuse one mesh
# period across their speeds or loads. Of those, the ones predicted when the case is loaded (.predicted_at_load)
# hold for the case's own speed and load only: the thermal mesh of such a case is refused at any other point.


@dataclass(frozen=True, eq=False)
class MeshModel:
    """The gear mesh of a case under one model.

    Parameters
    ----------
    case:
        The validated case.
    model:
        ``"elastic"`` or ``"thermal"``: the case's ``[thermal] model``, the predictive ``"thermoelastic"`` (E(T),
        gears and housing expanded, backlash, flank deviations: :mod:`thermogear.thermoelastic`) or the paper's
        ``"luo2020"`` (secant k_T with X_te, Eqs. 13–23, to reproduce the paper); or the name of another registered
        pair model (:data:`~thermogear.mesh.pair_models.PAIR_MODELS`).

    Profile modifications (tip relief) are deviations of both models; the elastic model has no thermal ones.
    """

    case: "Case"
    model: Model | str = "thermal"

    def __post_init__(self) -> None:
        check_model(self.model)

    # ------------------------------------------------------------------------------------ what it is
    @cached_property
    def pair_model(self) -> PairModelBase:
        """The pair model answering for this model (chosen once, by name:
        :func:`~thermogear.mesh.pair_models.pair_model_class`), built on the case."""
        return pair_model_class(self.model, self.case.thermal.model)(self.case)

    @property
    def thermal(self) -> bool:
        """True for a thermal pair model (temperatures from the case's field), as the pair model declares."""
        return self.pair_model.thermal

    @property
    def thermal_model(self) -> str | None:
        """Name of the thermal mesh model in use (``"thermoelastic"`` or ``"luo2020"``), None for the elastic one."""
        return self.pair_model.name if self.thermal else None

    @property
    def thermoelastic_mesh(self) -> ThermoelasticMesh | None:
        """The thermo-elastic component of the case (hot geometry, E(T), backlash, deviations) where this model
        needs it: the thermoelastic model, or any model of a case with profile modifications."""
        return self.pair_model.thermoelastic_mesh

    @property
    def gear_pair(self):
        """The gear pair as it meshes under this model (geometry, path of contact A–E, contact ratio): at
        temperature for the thermoelastic model, as built otherwise."""
        return self.pair_model.gear_pair

    @property
    def face_width(self) -> float:
        return self.gear_pair.face_width

    @property
    def equivalent_mass(self) -> float:
        """me of Luo & Li Eq. 5 [kg], total over the face width."""
        return self.case.equivalent_mass

    @cached_property
    def lubricant(self) -> Lubricant:
        return lubricant_from_case(self.case)

    @property
    def temperature(self) -> TemperatureField | None:
        """The tooth temperature field of the thermal model; None for the elastic one."""
        return self.pair_model.temperature

    @property
    def stiffness_depends_on_load(self) -> bool:
        """True where the pair stiffness is computed per normal load (the paper's secant k_T, Eq. 18)."""
        return self.pair_model.stiffness_depends_on_load

    @property
    def load_shares_depend_on_load(self) -> bool:
        """True where the static load shares move with the load (the pair model says why)."""
        return self.pair_model.load_shares_depend_on_load

    @property
    def damping_scaling(self) -> tuple[float, float | None] | None:
        """(speed exponent, load exponent) of the mesh damping, c(n, w) = c(n0, w0)·(n/n0)^a·(w/w0)^b, where this
        model keeps the conditions under which the friction damping is such a power law (geometry, oil
        temperature and load shares independent of speed and load; thermogear.friction.damping); the load exponent is
        None where the load shares move with the load, and the whole is None where the temperature input depends
        on the speed (the FE heat model; the gearbox model, whose predicted temperatures follow speed and load). Sweeps use it to reuse one mesh period (and do not where the pairs carry
        deviations: the excitation is not part of their batch kernel)."""
        if (temperature_source(self.case.temperature.model).computed
                or x_te_source(self.case.thermal.x_te_source).provided):  # X_te by a model (FE)
            return None
        table = mesh_table_of(self.case)
        if table is not None and table.damping is not None:  # the table's c(τ) holds at every speed and load
            return 0.0, 0.0
        speed_exponent, load_exponent = friction_damping_exponents(self.damping_friction_law)
        return speed_exponent, None if self.load_shares_depend_on_load else load_exponent

    @property
    def damping_friction_law(self) -> FrictionLaw:
        """The mean friction law of the friction damping (``[damping] friction_model``, default the paper's)."""
        return friction_law(self.case.damping.friction_model, key="damping.friction_model")

    @property
    def damping_rule(self) -> str:
        return self.case.damping.rule

    # ----------------------------------------------------------------------------------- operating point
    @property
    def speed_rpm(self) -> float:
        """The case's pinion speed [rpm] (the default operating point)."""
        return float(self.case.operating_point.speed_rpm)

    def normal_load(self, speed_rpm: float | None = None) -> float:
        """Static normal load w = T1/r_b1 [N] (total) at a pinion speed [rpm]: the case's torque, or its power
        over ω1 where the case gives a power."""
        operating = self.case.operating_point
        speed = operating.speed_rpm if speed_rpm is None else float(speed_rpm)
        return operating.torque_at(speed) / self.gear_pair.pinion.base_radius

    def normal_loads(self, speeds_rpm) -> np.ndarray:
        """:meth:`normal_load` [N] at many pinion speeds [rpm] in one pass (each element equal to it)."""
        return self.case.operating_point.torques_at(speeds_rpm) / self.gear_pair.pinion.base_radius

    def mesh_period(self, speed_rpm: float) -> float:
        """T_m = 60/(z1·n1) [s]."""
        return self.gear_pair.mesh_period(speed_rpm)

    # ------------------------------------------------------------------------------- per pair, along roll
    def _load(self, normal_load: float | None) -> float:
        return self.normal_load() if normal_load is None else float(normal_load)

    def pair_stiffness_at(self, roll, normal_load: float | None = None) -> np.ndarray:
        """Stiffness of one tooth pair [N/m] (total over the face width) at roll distances on [A, E]."""
        return self.pair_model.pair_stiffness_at(np.asarray(roll, dtype=float), self._load(normal_load))

    def damping_stiffness_at(self, roll, normal_load: float | None = None) -> np.ndarray:
        """The pair stiffness k of Eq. 28 and of the friction load share [N/m]: k_e unless ``[damping]
        stiffness = "thermal"`` asks the thermal model's own; the thermoelastic model always uses its own (its
        path of contact is that of the hot pair, where the cold k_e is not defined)."""
        return self.pair_model.damping_stiffness_at(np.asarray(roll, dtype=float), self._load(normal_load))

    def flank_gamma(self, roll) -> np.ndarray:
        """Contact position Γ on the flanks as built (where the temperature field is given) of the contact at roll
        distances [m] of the pair as it meshes (differs from its Γ where the pair model expands the geometry)."""
        return self.pair_model.flank_gamma(roll)

    def friction_temperature_c(self, gamma) -> np.ndarray:
        """Oil temperature of the friction formula [°C]: the lubricant's reference temperature (elastic) or the
        mean of the pinion and wheel flank temperatures at the contact (thermal)."""
        return self.pair_model.friction_temperature_c(gamma)

    def pair_deviation_at(self, roll) -> np.ndarray:
        """Unloaded deviation of one tooth pair along the line of action [m] (positive: material missing, the
        pair engages later): tip reliefs, and for the thermoelastic model the thermal flank distortion and the
        base-pitch mismatch. The paper's thermal model has none."""
        return self.pair_model.pair_deviation_at(roll)

    @property
    def backlash(self) -> float | None:
        """Normal backlash [m] of the mesh as this model sees it (at temperature for the thermoelastic model, at
        the reference temperature otherwise: the paper's model does not expand the geometry); None where neither
        the model nor a nonlinear mesh needs it."""
        return self.pair_model.backlash

    def _friction(self, roll, share, stiffness, speed_rpm: float, normal_load: float) -> PairDamping:
        pair, case = self.gear_pair, self.case
        gamma = np.asarray(pair.gamma(roll), dtype=float)
        temperature = self.friction_temperature_c(self.flank_gamma(roll))
        viscosity = np.asarray(self.lubricant.dynamic_viscosity(temperature), dtype=float)
        rolling_1, rolling_2 = pair.rolling_speeds(roll, speed_rpm)
        law = self.damping_friction_law
        factor = law.lubricant_factor(self.lubricant.base_oil, case.damping.lubricant_factor,
                                      key="damping.lubricant_factor")
        radius, load_factor = pair.relative_radius_of_curvature(roll), 1.0
        if case.helical_pair is not None:  # the laws take the normal section's radius, ISO/TR 13989's law K_Bγ
            radius = normal_section_radius(radius, case.helical_pair.base_helix_angle)
            load_factor = helical_load_factor(case.helical_pair.total_contact_ratio)
        friction, damping, unit_load = friction_pair_damping(
            stiffness, share, normal_load / pair.face_width, case.roughness_ra, viscosity,
            np.asarray(rolling_1 + rolling_2, dtype=float), radius, factor,
            mesh_circular_frequency(pair.pinion.teeth, speed_rpm), law, case.damping.friction_coefficient,
            load_factor, pair.pinion.pressure_angle)
        return PairDamping(model=self.model, roll=roll, gamma=gamma, friction_coefficient=friction,
                           viscosity=viscosity, damping=damping, temperature_c=temperature, pair_stiffness=stiffness,
                           load_share=share, unit_load=unit_load)

    def pair_damping_at(self, roll, speed_rpm: float | None = None, normal_load: float | None = None) -> PairDamping:
        """Friction damping of one tooth pair at roll distances on [A, E] (Luo & Li Eqs. 26–28): μ of DIN 3990-4
        with the pair's share of the load among the pairs in mesh with it, c = 4μk/(πω_m)."""
        speed = self.speed_rpm if speed_rpm is None else float(speed_rpm)
        load = self._load(normal_load)
        mesh_circular_frequency(self.gear_pair.pinion.teeth, speed)  # refuses standstill first
        roll = np.asarray(roll, dtype=float)
        points = self.gear_pair.path_points
        tolerance = 1e-9 * self.gear_pair.base_pitch
        if np.any((roll < points["A"] - tolerance) | (roll > points["E"] + tolerance)):
            raise CaseError("roll", [float(roll.min()), float(roll.max())],
                            f"[{points['A']:.6g}, {points['E']:.6g}] m (A to E)", "outside the path of contact")
        share, stiffness = load_share_at(roll, lambda other: self.damping_stiffness_at(other, load),
                                         points["A"], points["E"], self.gear_pair.base_pitch)
        return self._friction(roll, share, stiffness, speed, load)

    # ------------------------------------------------------------------------------- one mesh period
    def grid(self, speed_rpm: float | None = None, points_per_period: int | None = None) -> MeshGrid:
        """The mesh-cycle grid of one period at a speed [rpm] (every contact transition a node)."""
        speed = self.speed_rpm if speed_rpm is None else float(speed_rpm)
        count = points_per_period or self.case.dynamics.points_per_period
        return MeshCycle(self.gear_pair, speed).grid(count)

    def _on_grid(self, grid: MeshGrid, evaluate) -> np.ndarray:
        points = self.gear_pair.path_points
        values = np.zeros(grid.roll.shape)
        roll = np.clip(grid.roll[grid.in_contact], points["A"], points["E"])
        values[grid.in_contact] = evaluate(roll)
        return values

    def _check_predicted_operating_point(self, speed: float, load: float) -> None:
        """The temperatures of a ``"gearbox"`` case are the steady state at its own speed and load: its thermal mesh
        at another operating point would mix the two (make a case at that point: ``Case.with_changes``)."""
        if not (self.pair_model.thermal and temperature_source(self.case.temperature.model).predicted_at_load):
            return
        own_speed, own_load = self.speed_rpm, self.normal_load(self.speed_rpm)
        if not (math.isclose(speed, own_speed, rel_tol=1e-12) and math.isclose(load, own_load, rel_tol=1e-12)):
            raise CaseError("operating.speed_rpm", speed, f"the case's own operating point ({own_speed:g} rpm, "
                            f"{own_load:.6g} N)", "its temperatures were predicted by the gearbox model there; "
                            "evaluate another speed or load on a case made at it (Case.with_changes)")

    def state(self, speed_rpm: float | None = None, normal_load: float | None = None,
              points_per_period: int | None = None, damping: bool = True) -> MeshState:
        """Everything the dynamics need over one mesh period at a pinion speed [rpm] and normal load [N]
        (defaults: the case's operating point). ``damping=False`` leaves the friction damping out (zeros), for
        callers that need the stiffness only. A helical pair's period is that of its slice model
        (:mod:`thermogear.mesh.helical_model`), the torsional projection along the transverse line of action."""
        speed = self.speed_rpm if speed_rpm is None else float(speed_rpm)
        load = self.normal_load(speed) if normal_load is None else float(normal_load)
        self._check_predicted_operating_point(speed, load)
        state = self._transverse_state(speed, load, points_per_period, damping)
        if self.case.helical_pair is not None:
            count = points_per_period or self.case.dynamics.points_per_period
            state = helical_model_state(self, state, speed, load, count, damping)
        table = mesh_table_of(self.case)  # a user's k(τ) (dynamics.mesh_table) replaces the model's
        return state if table is None else table.state_like(state)

    def section_state(self, speed_rpm: float | None = None, normal_load: float | None = None,
                      points_per_period: int | None = None, damping: bool = True) -> MeshState:
        """The period as tooth pairs on the mesh-cycle grid, what per-pair quantities (the friction damping of each
        pair, its single- and double-pair regions) refer to: :meth:`state` itself for a spur pair; for a helical
        pair that of its transverse section (its slices share the section's friction, docs/helical.md)."""
        if self.case.helical_pair is None:
            return self.state(speed_rpm, normal_load, points_per_period, damping)
        speed = self.speed_rpm if speed_rpm is None else float(speed_rpm)
        load = self.normal_load(speed) if normal_load is None else float(normal_load)
        self._check_predicted_operating_point(speed, load)
        return self._transverse_state(speed, load, points_per_period, damping)

    def _transverse_state(self, speed: float, load: float, points_per_period: int | None,
                          damping: bool) -> MeshState:
        """The period of the pair's (transverse) section as a spur pair: tooth pairs on the mesh-cycle grid."""
        grid = self.grid(speed, points_per_period)
        stiffness = self._on_grid(grid, lambda roll: self.pair_stiffness_at(roll, load))
        if self.pair_model.damping_uses_pair_stiffness or not damping:
            damping_stiffness = stiffness
        else:
            damping_stiffness = self._on_grid(grid, lambda roll: self.damping_stiffness_at(roll, load))
        deviation = self._on_grid(grid, self.pair_deviation_at)
        engaged, static, share = grid.in_contact, None, None
        if np.any(deviation != 0.0):  # pairs engage where the static approach exceeds their deviation
            loaded = loaded_transmission_error(stiffness, deviation, load, grid.in_contact)
            engaged, static, share = loaded.engaged, loaded.approach, loaded.load_share
        pair_damping = np.zeros(grid.roll.shape)
        if damping:
            if share is None:
                share = load_shares(damping_stiffness, grid.in_contact)
            contact = grid.in_contact
            points = self.gear_pair.path_points
            friction = self._friction(np.clip(grid.roll[contact], points["A"], points["E"]), share[contact],
                                      damping_stiffness[contact], speed, load)
            pair_damping[contact] = np.where(share[contact] > 0.0, friction.damping, 0.0)
        state = MeshState(model=self.model, speed_rpm=speed, normal_load=load, mass=self.equivalent_mass, grid=grid,
                          pair_stiffness=stiffness, pair_damping=pair_damping,
                          mesh_damping=np.asarray(mesh_damping(pair_damping, grid.in_contact, self.damping_rule),
                                                  float),
                          pair_deviation=deviation, pair_engaged=engaged, static_transmission_error=static,
                          backlash=self.backlash, face_width=self.face_width,
                          mesh_frequency_hz=self.gear_pair.mesh_frequency(speed))
        return state

    def natural_frequency_hz(self, state: MeshState) -> float:
        """f_n = sqrt(mean k / me)/2π [Hz] of a state."""
        return math.sqrt(state.mean_mesh_stiffness / state.mass) / (2.0 * math.pi)


def check_damping_friction_law(damping: "DampingSection", oil: "Lubricant") -> None:
    """Load-time check of ``[damping] friction_model``: the law has a lubricant factor X_L for the base oil of the
    case's ``oil`` (or the case gives ``damping.lubricant_factor``); CaseError naming the key otherwise.

    A load-time check (:data:`thermogear.composition.CASE_CHECKS`): it receives these pieces of the case
    (:mod:`thermogear.case.pieces`)."""
    law = friction_law(damping.friction_model, key="damping.friction_model")
    law.lubricant_factor(oil.base_oil, damping.lubricant_factor, key="damping.lubricant_factor")


__all__ = ["MODELS", "MeshModel", "MeshState", "check_damping_friction_law"]
