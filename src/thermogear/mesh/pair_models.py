"""Pair models: what one tooth pair of a case is under one thermal model, one class per model.

A pair model answers the per-pair questions of the mesh model along the roll distance on [A, E]: the pair stiffness
k_i, the stiffness of the friction damping (Luo & Li (2020) Eq. 28), the unloaded deviation e_i, the normal backlash,
the gear pair as it meshes, the oil temperature of the friction formula and the flank position Γ it is read at, and
whether stiffness or load shares depend on the load. :class:`~thermogear.mesh.model.MeshModel` builds one mesh period
from them and knows nothing of which model answers.

Three models (``PAIR_MODELS``, resolved once by :func:`pair_model_class`):

* ``"elastic"`` — :class:`ElasticPair`: k_e of the gear pair as built, oil at the lubricant's reference temperature
  (Eq. 5).
* ``"luo2020"`` — :class:`Luo2020Pair`: the paper's secant k_T with X_te (Eqs. 13–23), flank temperatures of the
  case's temperature field, no thermal expansion of the geometry.
* ``"thermoelastic"`` — :class:`ThermoelasticPair`: the predictive model of :mod:`thermogear.thermoelastic` (E(T),
  gears and housing expanded, backlash and flank deviations at temperature).

Adding a model is one subclass of :class:`PairModelBase` overriding what differs, and one line in ``PAIR_MODELS``:
it then runs by its name, ``Simulation(case, model=name)``. A model that a case file chooses as its ``[thermal]
model`` also declares its input rules (temperature limits, X_te, own keys): one line in
:data:`thermogear.choices.thermal_models.THERMAL_MODEL_RULES` (which the schema reads), held as the class's ``rules``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any, ClassVar, Protocol

import numpy as np

from thermogear.case.pieces import call_with_pieces
from thermogear.choices.thermal_models import LUO2020_RULES, THERMOELASTIC_RULES, ThermalModelRules
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError
from thermogear.friction.damping import damping_takes_pair_stiffness
from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model
from thermogear.mesh.model_names import MODELS, THERMAL
from thermogear.mesh.secant_checks import secant_stiffness_drop_flag, secant_stiffness_in_nonlinear_mesh
from thermogear.stiffness.table import pair_stiffness_at
from thermogear.temperature.source import TemperatureField, temperature_field_from_case
from thermogear.thermoelastic.mesh import ThermoelasticMesh

if TYPE_CHECKING:
    from thermogear.case import Case


class PairModel(Protocol):
    """The per-pair questions a mesh model asks (roll distances [m] on [A, E], loads [N], totals over the width)."""

    name: ClassVar[str]
    thermal: ClassVar[bool]
    uses_x_te: ClassVar[bool]

    @property
    def gear_pair(self): ...
    @property
    def thermoelastic_mesh(self) -> ThermoelasticMesh | None: ...
    @property
    def temperature(self) -> TemperatureField | None: ...
    @property
    def stiffness_depends_on_load(self) -> bool: ...
    @property
    def load_shares_depend_on_load(self) -> bool: ...
    @property
    def damping_uses_pair_stiffness(self) -> bool: ...
    @property
    def backlash(self) -> float | None: ...
    def pair_stiffness_at(self, roll, normal_load: float) -> np.ndarray: ...
    def damping_stiffness_at(self, roll, normal_load: float) -> np.ndarray: ...
    def pair_deviation_at(self, roll) -> np.ndarray: ...
    def flank_gamma(self, roll) -> np.ndarray: ...
    def friction_temperature_c(self, gamma) -> np.ndarray: ...
    def result_flags(self, mean_stiffness: float, metrics: Mapping[str, Any],
                     elastic_mean_stiffness: Callable[[], float]) -> list[str]: ...


@dataclass(frozen=True, eq=False)
class PairModelBase:
    """What the models share: the elastic pair of the case as built, tip reliefs as cold deviations, the cold
    backlash, the flank temperatures of the case's field. Subclasses override what their model changes."""

    case: "Case"
    name: ClassVar[str] = ""
    #: True for a thermal model: temperatures from the case's field, the friction oil at the flank temperature.
    thermal: ClassVar[bool] = True
    #: True where the stiffness rests on the paper's factor X_te (Luo & Li (2020) Eqs. 13–23): only then do X_te,
    #: its calibration and the paper's stiffness curves along the path exist.
    uses_x_te: ClassVar[bool] = False
    #: The input rules of a ``[thermal] model`` (its temperature limits, whether it reads X_te, its own keys),
    #: checked when a case is loaded; None for a model no case file chooses by name (the elastic one).
    rules: ClassVar[ThermalModelRules | None] = None

    @classmethod
    def choice_flags(cls, mesh: str) -> list[str]:
        """What every result of this model flags under the ``[dynamics] mesh`` kind, known before any solving
        (``check`` says it as ``run`` will): nothing here."""
        return []

    @property
    def has_profile_modifications(self) -> bool:
        gears = self.case.gears_input
        return any(getattr(gear, "tip_relief_um", None) for gear in (gears.pinion, gears.wheel))

    @cached_property
    def thermoelastic_mesh(self) -> ThermoelasticMesh | None:
        """The thermo-elastic component (hot geometry, E(T), backlash, deviations) where the model needs it: here,
        for the deviations of profile modifications."""
        return ThermoelasticMesh.from_case(self.case) if self.has_profile_modifications else None

    @property
    def gear_pair(self):
        """The gear pair as it meshes (geometry, path of contact A–E, contact ratio): as built."""
        return self.case.gear_pair

    @cached_property
    def temperature(self) -> TemperatureField | None:
        """The tooth temperature field of a thermal model; None for the elastic one."""
        return temperature_field_from_case(self.case) if self.thermal else None

    @property
    def stiffness_depends_on_load(self) -> bool:
        """True where the pair stiffness is computed per normal load."""
        return False

    @property
    def load_shares_depend_on_load(self) -> bool:
        """True where the static load shares move with the load: pairs with unloaded deviations engage at a
        load-dependent approach."""
        return self.thermoelastic_mesh is not None

    @property
    def damping_uses_pair_stiffness(self) -> bool:
        """True where the stiffness of the friction damping is the model's pair stiffness (one evaluation serves
        both); here it is k_e, which is the elastic pair's own."""
        return False

    def elastic_pair_stiffness_at(self, roll) -> np.ndarray:
        """k_e of one pair of the gear pair as built [N/m] (Luo & Li Eq. 5's stiffness)."""
        return np.asarray(pair_stiffness_at(self.gear_pair, self.case.material, np.asarray(roll, float)), float)

    def pair_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        return self.elastic_pair_stiffness_at(roll)

    def damping_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        """The pair stiffness k of Eq. 28 and of the friction load share [N/m]: k_e (the paper's reading)."""
        return self.elastic_pair_stiffness_at(roll)

    def pair_deviation_at(self, roll) -> np.ndarray:
        """Unloaded deviation of one pair along the line of action [m]: the tip reliefs, cold."""
        mesh = self.thermoelastic_mesh
        if mesh is None:
            return np.zeros(np.shape(roll))
        return np.asarray(mesh.cold_pair_deviation_at(roll), dtype=float)

    @cached_property
    def backlash(self) -> float | None:
        """Normal backlash [m] at the reference temperature; None where neither the model nor a nonlinear mesh
        needs it."""
        mesh = self.thermoelastic_mesh
        if mesh is None and mesh_law(self.case.dynamics.mesh).backlash:
            mesh = ThermoelasticMesh.from_case(self.case)
        return None if mesh is None else mesh.backlash_normal_cold

    def flank_gamma(self, roll) -> np.ndarray:
        """Contact position Γ on the flanks as built of the contact at roll distances [m]."""
        return np.asarray(self.gear_pair.gamma(np.asarray(roll, dtype=float)), dtype=float)

    def result_flags(self, mean_stiffness: float, metrics: Mapping[str, Any],
                     elastic_mean_stiffness: Callable[[], float]) -> list[str]:
        """Findings of this model that make a result doubtful, in words: ``mean_stiffness`` the result's mean mesh
        stiffness [N/m], ``metrics`` its metrics, ``elastic_mean_stiffness()`` the elastic model's at the same point
        (computed only where a model asks). None here."""
        return []

    def friction_temperature_c(self, gamma) -> np.ndarray:
        """Oil temperature of the friction formula [°C]: the mean of the pinion and wheel flank temperatures."""
        field = self.temperature
        gamma = np.asarray(gamma, dtype=float)
        return 0.5 * (np.asarray(field.pinion_flank_c(gamma), dtype=float)
                      + np.asarray(field.wheel_flank_c(gamma), dtype=float))


@dataclass(frozen=True, eq=False)
class ElasticPair(PairModelBase):
    """k_e with the oil at the lubricant's reference temperature (Luo & Li (2020) Eq. 5); no thermal input."""

    name: ClassVar[str] = "elastic"
    thermal: ClassVar[bool] = False

    @property
    def damping_uses_pair_stiffness(self) -> bool:
        return True

    def friction_temperature_c(self, gamma) -> np.ndarray:
        """The lubricant's reference temperature [°C] everywhere."""
        return np.full(np.shape(gamma), float(self.case.lubricant.reference_temperature_c))


@dataclass(frozen=True, eq=False)
class Luo2020Pair(PairModelBase):
    """The paper's secant k_T with X_te (Luo & Li (2020) Eqs. 13–23); the geometry is not expanded and the
    thermal distortion is not a deviation (the paper's model has none)."""

    rules: ClassVar[ThermalModelRules] = LUO2020_RULES
    name: ClassVar[str] = LUO2020_RULES.name
    uses_x_te: ClassVar[bool] = LUO2020_RULES.reads_x_te

    @classmethod
    def choice_flags(cls, mesh: str) -> list[str]:
        """The secant k_T at the static load is no contact stiffness once the teeth separate (nonlinear mesh)."""
        return [secant_stiffness_in_nonlinear_mesh(0.0)] if mesh_law(mesh).backlash else []

    @property
    def stiffness_depends_on_load(self) -> bool:
        """The secant k_T is computed per normal load (Eq. 18). With a calibrated X_te its value is the same at
        every load (X_te ∝ F_n), but its single-tooth check (Eq. 23, a warning) is not, so a sweep still asks for
        it load by load."""
        return True

    @property
    def damping_uses_pair_stiffness(self) -> bool:
        """``[damping] stiffness = "thermal"`` asks k_T for Eq. 28 (an option, not the paper)."""
        return damping_takes_pair_stiffness(self.case.damping.stiffness)

    @property
    def load_shares_depend_on_load(self) -> bool:
        """Deviations of profile modifications, or k_T as the stiffness of the friction load share."""
        return self.thermoelastic_mesh is not None or self.damping_uses_pair_stiffness

    @cached_property
    def paper_model(self):
        """The paper's k_T model of the case (:func:`~thermogear.luo2020.thermal.case_stiffness.paper_thermal_model`,
        built from the pieces it names; what it computes once per case is kept in the case's memo)."""
        return call_with_pieces(paper_thermal_model, self.case)

    def pair_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        return np.asarray(self.paper_model.pair_stiffness_at(np.asarray(roll, dtype=float), normal_load=normal_load),
                          dtype=float)

    def damping_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        if self.damping_uses_pair_stiffness:
            return self.pair_stiffness_at(roll, normal_load)
        return self.elastic_pair_stiffness_at(roll)

    def pair_deviation_at(self, roll) -> np.ndarray:
        return np.zeros(np.shape(roll))

    def result_flags(self, mean_stiffness: float, metrics: Mapping[str, Any],
                     elastic_mean_stiffness: Callable[[], float]) -> list[str]:
        """A stiffness drop beyond what E(T) explains (it rests on X_te), and k_T used by the nonlinear mesh."""
        flags = []
        drop = secant_stiffness_drop_flag(self.temperature, mean_stiffness, elastic_mean_stiffness())
        if drop is not None:
            flags.append(drop)
        if mesh_law(metrics.get("mesh")).backlash:
            flags.append(secant_stiffness_in_nonlinear_mesh(metrics.get("contact_loss_fraction") or 0.0))
        return flags


@dataclass(frozen=True, eq=False)
class ThermoelasticPair(PairModelBase):
    """The predictive thermo-elastic pair (:mod:`thermogear.thermoelastic`): the hot geometry with E(T), the
    backlash and the flank deviations at temperature; its damping uses its own stiffness (its path of contact is
    that of the hot pair, where the cold k_e is not defined)."""

    rules: ClassVar[ThermalModelRules] = THERMOELASTIC_RULES
    name: ClassVar[str] = THERMOELASTIC_RULES.name
    uses_x_te: ClassVar[bool] = THERMOELASTIC_RULES.reads_x_te

    @cached_property
    def thermoelastic_mesh(self) -> ThermoelasticMesh:
        return ThermoelasticMesh.from_case(self.case)

    @property
    def gear_pair(self):
        """The gear pair at temperature."""
        return self.thermoelastic_mesh.gear_pair

    @property
    def damping_uses_pair_stiffness(self) -> bool:
        return True

    def pair_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        return np.asarray(self.thermoelastic_mesh.pair_stiffness_at(np.asarray(roll, dtype=float)), dtype=float)

    def damping_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        return self.pair_stiffness_at(roll, normal_load)

    def pair_deviation_at(self, roll) -> np.ndarray:
        """Tip reliefs, the thermal flank distortion and the base-pitch mismatch at temperature [m]."""
        return np.asarray(self.thermoelastic_mesh.pair_deviation_at(np.asarray(roll, dtype=float)), dtype=float)

    @cached_property
    def backlash(self) -> float:
        """Normal backlash at temperature [m]."""
        return self.thermoelastic_mesh.backlash_normal

    def result_flags(self, mean_stiffness: float, metrics: Mapping[str, Any],
                     elastic_mean_stiffness: Callable[[], float]) -> list[str]:
        """The component's own plausibility findings (jamming margin, hot contact ratio, unexplained stiffness)."""
        return list(self.thermoelastic_mesh.plausibility)

    def flank_gamma(self, roll) -> np.ndarray:
        """Γ on the flanks as built of the contact at roll distances of the hot pair: the hot pinion has grown by its
        strain (the material point at pinion radius r is at r/(1 + ε) cold)."""
        hot, cold = self.gear_pair, self.case.gear_pair
        radius = np.hypot(hot.pinion.base_radius, np.asarray(roll, dtype=float)) / (
            1.0 + self.thermoelastic_mesh.strains[0])
        cold_roll = np.sqrt(np.maximum(radius**2 - cold.pinion.base_radius**2, 0.0))
        return np.asarray(cold.gamma(cold_roll), dtype=float)


#: The pair models by name: ``"elastic"`` and every ``[thermal] model``. One line per model.
PAIR_MODELS: dict[str, type[PairModelBase]] = {
    ElasticPair.name: ElasticPair,
    Luo2020Pair.name: Luo2020Pair,
    ThermoelasticPair.name: ThermoelasticPair,
}


def pair_model_name(model: str, thermal_model: str) -> str:
    """The pair model a simulation model means: the case's ``[thermal] model`` for ``"thermal"``, else ``model``
    itself (``"elastic"`` or the name of another registered pair model)."""
    return thermal_model if model == THERMAL else model


def check_model(model: str) -> None:
    """Raise CaseError unless ``model`` is a simulation model (``"elastic"``, ``"thermal"``) or a registered pair
    model's name."""
    if model not in MODELS and model not in PAIR_MODELS:
        allowed = " | ".join(dict.fromkeys((*MODELS, *PAIR_MODELS)))
        raise CaseError("model", model, allowed, "unknown model")


def pair_model_class(model: str, thermal_model: str) -> type[PairModelBase]:
    """The one place a model name becomes a pair model (``model``: ``"elastic"``, ``"thermal"`` for the case's
    ``[thermal] model`` ``thermal_model``, or a registered pair model's name): its class, which is built on the case
    (``pair_model_class(model, case.thermal.model)(case)``). The choice reads the two names only.

    A model with input rules (one a case file chooses by name) runs only on a case of that ``[thermal] model``:
    its rules (temperature limits, X_te) were checked when that case was loaded, and would not have been otherwise."""
    check_model(model)
    name = pair_model_name(model, thermal_model)
    if name not in PAIR_MODELS:
        raise CaseError("thermal.model", name, " | ".join(PAIR_MODELS), "no pair model of this name")
    chosen = PAIR_MODELS[name]
    if chosen.rules is not None and chosen.rules.name != thermal_model:
        raise CaseError("thermal.model", thermal_model, chosen.rules.name,
                        f"the pair model '{name}' checks its input when the case is loaded: set thermal.model = "
                        f"'{chosen.rules.name}' in the case and run the \"{THERMAL}\" model")
    return chosen


__all__ = ["ElasticPair", "Luo2020Pair", "PAIR_MODELS", "PairModel", "PairModelBase", "ThermoelasticPair",
           "check_model", "pair_model_class", "pair_model_name"]
