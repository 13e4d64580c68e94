"""The one orchestrator of an operating point: a case's systems, each under each model, with the solver chosen once.

``Orchestrator(case, models, method)`` runs, at the case's operating point:

* the **pair**: the 1-DOF pair (two rigid inertias on rigid supports) under each model (``elastic``, ``thermal``),
  solved by the solver the case's ``[dynamics]`` (or ``method``) names, resolved once
  (:func:`thermogear.simulation.solver_for`): a :class:`PairResult` per model;
* the **drivetrain**, where the case has a ``[drivetrain]``: the same models on shafts, bearings, couplings and
  disks (:func:`thermogear.drivetrain.case_model.drivetrain_results`): a typed
  :class:`~thermogear.drivetrain.results.DrivetrainResults`;
* what the case's models say beside (the thermo-elastic summary of the hot pair, the gearbox's predicted
  temperatures where they set the case's temperatures).

Each system is one entry of :data:`SYSTEMS`; :meth:`Orchestrator.run` returns a frozen :class:`RunResults`.
``thermogear run``, the report (:func:`thermogear.evaluation.evaluate_case`) and :func:`thermogear.run` ask it and
format what it returns. As pvlib's ``ModelChain`` and PyBaMM's ``Simulation``: the physics lives in the models
and solvers; this module only wires them.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

from thermogear import warning_scope
from thermogear.composition import TEMPERATURE_MODELS
from thermogear.dynamics.problems.solution_methods import SOLUTION_METHODS, solution_method
from thermogear.errors import CaseError, ModelLimitError
from thermogear.mesh.model_names import MODELS, THERMAL
from thermogear.warning_causes import warning_text

if TYPE_CHECKING:
    from thermogear.drivetrain.results import DrivetrainResults
    from thermogear.dynamics.response import DynamicResponse
    from thermogear.dynamics.results.metric_results import LinearMetrics, NonlinearMetrics

__all__ = ["METHODS", "Orchestrator", "PairResult", "RunResults", "SYSTEMS", "drivetrain_failure", "run",
           "with_separation_note"]

#: Warnings Python hides by default (a library's deprecations): raised again, never listed in the results.
_HIDDEN_BY_DEFAULT = (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning)

#: The solution methods of one operating point (the solver of each, with the case's contact law, in
#: :func:`thermogear.simulation.solver_for`).
METHODS = tuple(SOLUTION_METHODS)


@dataclass(frozen=True, eq=False)
class PairResult:
    """The 1-DOF pair's response under one model: ``response`` (the solver's
    :class:`~thermogear.dynamics.response.DynamicResponse`, arrays over one mesh period) and its ``metrics`` typed
    (:class:`~thermogear.dynamics.results.metric_results.LinearMetrics` or ``NonlinearMetrics``); ``damping_ratio`` the
    mean mesh damping ratio [-]."""

    model: str
    response: DynamicResponse
    metrics: LinearMetrics | NonlinearMetrics
    damping_ratio: float | None
    mesh_stiffness: Any = None  # k(τ) on the mesh-cycle intervals [N/m] (the pairs in contact in parallel)

    @property
    def kv(self) -> float | None:
        """Dynamic factor Kv [-] (Luo & Li 2020 Eq. 29)."""
        return self.metrics.kv

    @property
    def mesh_stiffness_step_ratio(self) -> float:
        """The largest step of the mesh stiffness over one period, k after / k before a grid node [-]: where a pair
        enters contact the total mesh force k·x jumps by this factor (x is continuous), which far below resonance
        sets the "max system load / static" ratio (issue 36)."""
        import numpy as np  # noqa: PLC0415

        stiffness = np.asarray(self.mesh_stiffness, dtype=float)
        return float(np.max(stiffness / np.roll(stiffness, 1)))

    def to_dataset(self):
        """xarray Dataset of the response (:meth:`~thermogear.dynamics.response.DynamicResponse.to_xarray`)."""
        return self.response.to_xarray()

    def to_dataframe(self):
        """The steady period as a table (pandas): time [s], DTE [m], velocity [m/s], system load [N]."""
        import pandas as pd  # noqa: PLC0415

        return pd.DataFrame({"time_s": self.response.time, "dte_m": self.response.displacement,
                             "velocity_m_per_s": self.response.velocity,
                             "system_load_n": self.response.system_load()})

    def scalars(self) -> dict[str, Any]:
        """The scalar metrics (SI) of :meth:`RunResults.to_dataframe`."""
        metrics = self.metrics
        return {"kv": metrics.kv, "dte_rms_m": metrics.dte_rms, "dte_peak_to_peak_m": metrics.dte_peak_to_peak,
                "max_system_load_ratio": metrics.max_system_load_ratio, "stable": metrics.stable,
                "valid": metrics.valid, "natural_frequency_hz": metrics.natural_frequency_hz,
                "frequency_ratio": metrics.frequency_ratio, "damping_ratio": self.damping_ratio}


@dataclass(frozen=True, eq=False)
class RunResults:
    """Everything one operating point of a case gives: per model the pair's result (``pair``; ``not_computed`` the
    models that failed, with the reason), the drivetrain's (None without a ``[drivetrain]``;
    ``drivetrain_not_computed`` the reason where it failed), the thermo-elastic summary of the hot pair (None under
    the paper's k_T), the gearbox's predicted steady state where it set the temperatures, the case's notes and the
    warnings raised while computing (texts, in order, each once)."""

    case_name: str
    method: str
    load_held: str
    pair: Mapping[str, PairResult]
    not_computed: Mapping[str, str] = field(default_factory=dict)
    drivetrain: DrivetrainResults | None = None
    drivetrain_not_computed: str | None = None
    thermoelastic: dict | None = None
    temperatures: Any = None
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    def headline_kv(self, model: str) -> tuple[float | None, str]:
        """(Kv [-], which system) of a model: the drivetrain's where the case has one that was computed, else the
        1-DOF pair's (issue 36: the structure the case describes carries the headline)."""
        if self.drivetrain is not None and model in self.drivetrain.models:
            return self.drivetrain.models[model].kv, "drivetrain"
        return (self.pair[model].kv if model in self.pair else None), "pair"

    def to_dataframe(self):
        """One row per (system, model): Kv, DTE [m], stability and validity (pandas)."""
        import pandas as pd  # noqa: PLC0415

        rows = [{"system": "pair", "model": name, **result.scalars()} for name, result in self.pair.items()]
        if self.drivetrain is not None:
            rows += [{"system": "drivetrain", "model": name, **model.scalars()}
                     for name, model in self.drivetrain.models.items()]
        return pd.DataFrame(rows).set_index(["system", "model"])

    def to_dataset(self):
        """xarray Dataset of the scalar results per system and model (:meth:`to_dataframe` as an array set)."""
        frame = self.to_dataframe().drop(columns=["kind"], errors="ignore")
        return frame.apply(lambda column: column.astype(float) if column.dtype == bool else column).to_xarray()


@dataclass(frozen=True)
class _System:
    """One system the orchestrator runs: ``applies(orchestrator)`` whether the case has it."""

    name: str
    applies: Callable[[Orchestrator], bool]


#: The systems of an operating point, in the order they run: the 1-DOF pair always, the drivetrain where the case
#: describes one. (The pair runs first: its flags and warnings head the output.)
SYSTEMS: dict[str, _System] = {
    "pair": _System("pair", lambda orchestrator: True),
    "drivetrain": _System("drivetrain", lambda orchestrator: orchestrator.case.drivetrain is not None),
}


@dataclass(frozen=True, eq=False)
class Orchestrator:
    """One operating point of ``case`` under ``models`` (default both), solved by ``method`` (``"periodic"`` or
    ``"transient"``; default the case's ``[dynamics] method``) with the case's contact law."""

    case: Any
    models: tuple[str, ...] = MODELS
    method: str | None = None

    def __post_init__(self) -> None:
        if self.method is not None:
            solution_method(self.method, key="method")  # a CaseError for an unknown one

    @cached_property
    def solution_method(self) -> str:
        return self.method or self.case.dynamics.method

    @cached_property
    def solver(self):
        """The solver of the pair, resolved once from the case's ``[dynamics]`` and the method."""
        from thermogear.simulation import solver_for  # noqa: PLC0415

        return solver_for(self.case.dynamics, self.solution_method)

    @cached_property
    def _simulations(self) -> dict:
        return {}

    def simulation(self, model: str):
        """The :class:`~thermogear.simulation.Simulation` of one model (built once)."""
        if model not in self._simulations:
            from thermogear.simulation import Simulation  # noqa: PLC0415

            self._simulations[model] = Simulation(self.case, model, solver=self.solver)
        return self._simulations[model]

    def preflight(self, quiet: bool = True) -> None:
        """Build every component :meth:`run` would build (no solving) and raise CaseError where one fails: the one
        set of checks ``check``, ``run`` and ``sweep`` share (:func:`thermogear.preflight.preflight`). ``quiet``
        drops the warnings of the building."""
        from thermogear.preflight import preflight  # noqa: PLC0415
        from thermogear.simulation import Simulation  # noqa: PLC0415  (registers the FE temperature model too)

        preflight(lambda model: Simulation(self.case, model), self.models, self.case.dynamics,
                  self.solution_method, quiet)

    def pair(self, model: str) -> PairResult:
        """The 1-DOF pair under ``model``, solved (raises ModelLimitError where the model cannot give a result)."""
        from thermogear.dynamics.results.metric_results import typed_metrics  # noqa: PLC0415

        simulation = self.simulation(model)
        response = simulation.run()
        return PairResult(model, response, typed_metrics(response.metrics), response.metrics.get("damping_ratio"),
                          simulation.mesh_stiffness)

    def drivetrain(self, progress: Callable[[str], None] | None = None,
                   series: dict | None = None) -> DrivetrainResults | None:
        """The drivetrain under the orchestrator's models (None without a ``[drivetrain]``); with the transient
        method, the last period of its motion from rest. ``series`` receives each model's arrays (results.nc)."""
        if self.built_drivetrain is None:
            return None
        from thermogear.drivetrain.case_model import drivetrain_results  # noqa: PLC0415

        from_rest = solution_method(self.solution_method).from_rest
        return drivetrain_results(self.built_drivetrain, self.models, transient=from_rest,
                                  progress=progress, series=series)

    @cached_property
    def built_drivetrain(self):
        """The case's drivetrain cold and hot (:class:`~thermogear.drivetrain.case_model.CaseDrivetrain`), built
        once (its results and the report's pictures come from the same one); None without a ``[drivetrain]``."""
        if not SYSTEMS["drivetrain"].applies(self):
            return None
        from thermogear.drivetrain.case_model import case_drivetrain  # noqa: PLC0415

        return case_drivetrain(self.case, self.models)

    def thermoelastic(self) -> dict | None:
        """The thermo-elastic summary of the hot pair (operating geometry, backlash, jamming, E(T), loaded STE)
        where the thermal model is the thermo-elastic one and among the models; None otherwise."""
        if THERMAL not in self.models:
            return None
        thermal = self.simulation(THERMAL).mesh_model
        if thermal.pair_model.uses_x_te:  # the paper's k_T has none of these
            return None
        from thermogear.summaries.helical import pair_thermoelastic_summary  # noqa: PLC0415

        return pair_thermoelastic_summary(thermal)

    def temperatures(self):
        """The gearbox's predicted steady state where a model predicted the case's temperatures at load time
        (``[temperature] model`` of :data:`thermogear.composition.TEMPERATURE_MODELS`), else None."""
        if self.case.temperature.model not in TEMPERATURE_MODELS:
            return None
        from thermogear.gearbox.case_model import (gearbox_model_from_case, gearbox_operating_point,  # noqa: PLC0415
                                                   predicted_steady_state)

        return predicted_steady_state(gearbox_model_from_case(self.case),
                                      gearbox_operating_point(self.case.operating_point, self.case.gearbox))

    def run(self, progress: Callable[[str], None] | None = None) -> RunResults:
        """Run every system of the case under every model (:data:`SYSTEMS`); a model whose pair cannot be solved
        (ModelLimitError, e.g. unstable) is recorded in ``not_computed`` and the others still run; if none can, its
        error is raised. ``progress(step)`` is called before each step."""
        step = progress or (lambda name: None)
        pairs, failed, limit = {}, {}, None
        with warning_scope.recorded() as caught:
            for model in self.models:
                step(f"{model} model")
                try:
                    pairs[model] = self.pair(model)
                except ModelLimitError as error:
                    failed[model], limit = f"{type(error).__name__}: {error}", limit or error
            if not pairs:
                raise limit
            thermoelastic = self.thermoelastic()
            drivetrain, reason = None, None
            if SYSTEMS["drivetrain"].applies(self):
                try:
                    drivetrain = with_separation_note(self.drivetrain(progress=step), pairs)
                except ModelLimitError as error:
                    reason = drivetrain_failure(error)
                except CaseError as error:
                    reason = str(error)
            temperatures = self.temperatures()
        warning_scope.raise_again(warning_scope.kept(caught))  # as they would have been raised: filters decide
        texts: list[str] = []
        for item in caught:
            text = warning_text(item)
            if text not in texts and not issubclass(item.category, _HIDDEN_BY_DEFAULT):
                texts.append(text)
        operating = self.case.operating_point
        return RunResults(self.case.name, self.solution_method, operating.load_held, MappingProxyType(pairs),
                          MappingProxyType(failed), drivetrain, reason, thermoelastic, temperatures,
                          tuple(self.case.notes), tuple(texts))


def with_separation_note(drivetrain: DrivetrainResults | None, pairs: Mapping[str, PairResult]
                         ) -> DrivetrainResults | None:
    """``drivetrain`` with a note where its mesh was linear and the pair's own ``pairs`` find the teeth separating
    (the drivetrain's numbers then assume permanent contact)."""
    separated = [name for name, pair in pairs.items() if pair.metrics.contact_loss.detected]
    if drivetrain is None or not separated or drivetrain.backlash_mesh:
        return drivetrain
    return drivetrain.with_note(f"drivetrain: the pair's {' and '.join(separated)} model finds the teeth separating; "
                                "the drivetrain's numbers assume permanent contact (linear mesh) and overstate the "
                                "mesh force there")


def drivetrain_failure(error: ModelLimitError) -> str:
    """Why the drivetrain could not be solved, with where its damping comes from (most often a mode nothing
    damps)."""
    return (f"{error} (every mode needs damping: give the shafts material_damping_s and the bearings damping in x, "
            "y and, where they locate the shaft, z)")


def run(case, models: tuple[str, ...] = MODELS, method: str | None = None) -> RunResults:
    """Run a case at its operating point: every system (the 1-DOF pair; the drivetrain where the case has one)
    under every model, typed (:class:`RunResults`, with ``to_dataframe()``). ``case`` is a
    :class:`~thermogear.case.Case` or the name of a built-in parameter set or a case file's path.

    >>> import thermogear
    >>> results = thermogear.run("luo2019")
    >>> round(results.pair["thermal"].kv, 2) > 1.0
    True
    """
    if isinstance(case, str):
        from thermogear.case import load_case  # noqa: PLC0415

        case = load_case(case)
    return Orchestrator(case, tuple(models), method).run()
