"""The whole chain of one case, as the report and ``thermogear run`` show it.

:func:`evaluate_case` runs the stages — the elastic and thermal models at the operating point, the thermal
stiffness curves, the damping summary, the start-up transients and, for the paper's case, the rig trend and the FE
verification — each in its own guarded step: a stage that fails does not stop the others; its reason is recorded
and the report shows "not computed" with it. Every stage asks the mesh model, a simulation or a summary: nothing
here computes physics by hand.
"""

from __future__ import annotations

import time as _time
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from thermogear import forked
from thermogear.citations import cite, cited_in
from thermogear.dynamics.problems.solution_methods import solution_method
from thermogear.mesh.model_names import ELASTIC, MODELS, THERMAL
from thermogear.choices.thermal_models import LUO2020_RULES, THERMOELASTIC_RULES
from thermogear.warning_causes import warning_text

if TYPE_CHECKING:
    from thermogear.mesh.model import MeshModel
    from thermogear.simulation import Simulation

__all__ = ["Evaluation", "MODELS", "PAPER_REFERENCE", "STEPS", "evaluate_case", "finish_evaluation", "is_paper_case",
           "thermoelastic_beside_paper", "uses_paper_thermal_stiffness"]


#: Names of the evaluation steps, in order (for progress bars); "drivetrain" only for a case with a [drivetrain].
STEPS = ("elastic model", "thermal model", "drivetrain", "thermal stiffness", "damping", "start-up transients",
         "thermoelastic prediction", "rig trend", "FE verification")


def uses_paper_thermal_stiffness(thermal: MeshModel) -> bool:
    """True when the thermal mesh model ``thermal`` (a :class:`~thermogear.mesh.model.MeshModel`) is the paper's k_T
    (Luo & Li 2020 Eqs. 13–23, ``thermal.model = "luo2020"``): only then do its X_te, its stiffness curves along the
    path (Fig. 4) and its stiffness drop exist."""
    return thermal.pair_model.uses_x_te


#: The reference key (:mod:`thermogear.citations`) of the paper whose numbers the paper table holds.
PAPER_REFERENCE = "luo2020"


def is_paper_case(citation: str | None) -> bool:
    """True for a parameter set of Luo & Li (2020): its ``[case] citation`` (``citation``) carries the paper's DOI. Then the
    report has the paper column, the FE verification and the rig trend run, and the commands show the paper's
    numbers beside the case's. Decided by the case's content, never by its name: a renamed copy of the paper's
    parameter set that keeps its citation keeps the comparison; a pair of one's own that does not cite the paper
    never gets it."""
    return cited_in(citation, PAPER_REFERENCE)


@dataclass
class Evaluation:
    """Everything the report shows for one case. Stage results are None when the stage failed (``problems``)."""

    case: Any
    method: str = "periodic"
    simulations: dict = field(default_factory=dict)  # model -> Simulation
    responses: dict = field(default_factory=dict)  # model -> DynamicResponse (steady state, ``method``)
    pairs: dict = field(default_factory=dict)  # model -> orchestrator.PairResult (the response, typed metrics)
    transients: dict = field(default_factory=dict)  # model -> DynamicResponse from rest
    thermal_curves: Any = None  # thermal.summary.ThermalCurves
    thermal_summary: dict | None = None  # the paper's k_T (thermal.model = "luo2020")
    thermoelastic_summary: dict | None = None  # the thermo-elastic model's (summaries.thermoelastic), when in use
    temperature_field: Any = None
    damping: Any = None  # damping.DampingSummary
    rig_trend: dict | None = None
    fem: Any = None
    thermoelastic: dict | None = None  # the predictive model beside the paper's (paper's case only)
    drivetrain: Any = None  # [drivetrain] cases: drivetrain.results.DrivetrainResults (None: none, or failed)
    drivetrain_series: dict = field(default_factory=dict)  # model -> arrays of its drivetrain response (results.nc)
    drivetrain_built: Any = None  # the CaseDrivetrain those results came from (the report's drivetrain pictures)
    problems: dict = field(default_factory=dict)  # stage -> reason it failed
    timings: dict = field(default_factory=dict)  # stage -> seconds, one after the other (they add up to the run)
    background_timings: dict = field(default_factory=dict)  # stage run beside the others -> its own seconds
    pending: dict = field(default_factory=dict)  # stage -> forked.Background still running (finish_evaluation)
    warnings: list = field(default_factory=list)  # warning texts raised during the run (deduplicated)
    orchestrator: Any = None  # the orchestrator.Orchestrator that ran the models and the drivetrain
    pair_load_shares: dict | None = None  # paper's case: model -> single-pair load share at A, B, D, E (Fig. 12)
    rig: Any = None  # paper's case: forked.Background of the rig's predicted temperatures (Table 3)

    @property
    def paper(self) -> bool:
        return is_paper_case(self.case.citation)

    def run_results(self, models: tuple[str, ...] = MODELS):
        """The :class:`~thermogear.orchestrator.RunResults` of ``models`` as this evaluation computed them (what
        ``thermogear run --out`` prints beside the report)."""
        from types import MappingProxyType

        from thermogear.orchestrator import RunResults

        pairs = {name: self.pairs[name] for name in models if name in self.pairs}
        failed = {name: self.problems[f"{name} model"] for name in models if f"{name} model" in self.problems}
        return RunResults(self.case.name, self.method, self.case.operating_point.load_held,
                          MappingProxyType(pairs), MappingProxyType(failed), self.drivetrain,
                          self.problems.get("drivetrain"), self.thermoelastic_summary if THERMAL in models else None,
                          None if self.orchestrator is None else self.orchestrator.temperatures(),
                          tuple(self.case.notes), tuple(self.warnings))

    def problem(self, *stages: str) -> str:
        """The first recorded failure among ``stages`` ('' when none)."""
        for stage in stages:
            if stage in self.problems:
                return f"stage '{stage}' failed: {self.problems[stage]}"
        return ""


def _run_stage(evaluation: Evaluation, name: str, function: Callable[[], None]) -> None:
    """Run one stage; record its time, its warnings and, if it fails, the reason (the report goes on)."""
    start = _time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            function()
        except (KeyboardInterrupt, SystemExit):
            raise
        except forked.ChildFailed as error:  # raised in a child process: its own type and message
            evaluation.problems[name] = str(error)
        except Exception as error:  # noqa: BLE001 - a failed stage becomes "not computed: reason" in the report
            evaluation.problems[name] = f"{type(error).__name__}: {error}"
    for item in caught:
        text = warning_text(item)
        if text not in evaluation.warnings:
            evaluation.warnings.append(text)
    evaluation.timings[name] = _time.perf_counter() - start


def evaluate_case(case, method: str = "periodic", models: tuple[str, ...] = MODELS, transient: bool = True,
                  progress: Callable[[str], None] | None = None, wait: bool = True,
                  rig_prediction: bool = False) -> Evaluation:
    """Run the chain of ``case``: per model the stiffness, damping and dynamics (``method``) of the pair and, for a
    case with a ``[drivetrain]``, of the drivetrain (both through one :class:`~thermogear.orchestrator.
    Orchestrator`), the Fig. 4 thermal-stiffness curves, the damping summary, the start-up transients (Figs. 9–11)
    and, for the paper's case, the pair load shares of Fig. 12, the rig trend of Fig. 18, the FE verification
    (Fig. 15) and, with ``rig_prediction`` (the report asks for it), the rig's temperatures of Table 3, the last two
    in child processes from the start. ``progress(step)`` is called before each step. ``wait=False``: return
    without waiting for the FE verification; :func:`finish_evaluation` collects it (the report draws its other
    figures meanwhile)."""
    from thermogear.orchestrator import Orchestrator
    from thermogear.simulation import Simulation

    orchestrator = Orchestrator(case, tuple(models), method)
    evaluation = Evaluation(case=case, method=method, orchestrator=orchestrator)
    if rig_prediction:
        evaluation.rig = start_rig_prediction()  # the paper's rig, predicted in a child meanwhile
    step = progress or (lambda name: None)
    # the FE verification needs nothing the other stages compute: it runs beside them on a second core, the case
    # resolved into its FE inputs there too (its warnings and failures stay the stage's)
    fe_verification = None
    if evaluation.paper:
        from thermogear.fem.inputs import fem_inputs

        fe_verification = forked.start("FE verification", lambda: fem_verification(fem_inputs(case)))
    cite("luo2020", "iso21771", "iso53", "yang1987", "tian2004", "sainsot2004", "chaari2009")
    if case.citation and "14635" in case.citation:
        cite("iso14635_1")

    for model in models:
        step(f"{model} model")

        def run_model(model=model):
            evaluation.simulations[model] = orchestrator.simulation(model)
            evaluation.pairs[model] = orchestrator.pair(model)
            evaluation.responses[model] = evaluation.pairs[model].response
            cite(solution_method(method).citation, "den_hartog1931", "iso_tr13989_1", "astm_d341")
            if evaluation.simulations[model].mesh_model.thermal:
                cite("timoshenko1951")

        _run_stage(evaluation, f"{model} model", run_model)

    if case.drivetrain is not None:
        step("drivetrain")

        def drivetrain():
            from thermogear.errors import CaseError, ModelLimitError
            from thermogear.orchestrator import drivetrain_failure, with_separation_note

            try:
                built = orchestrator.drivetrain(series=evaluation.drivetrain_series)
            except ModelLimitError as error:  # most often a mode nothing damps: say where damping comes from
                evaluation.problems["drivetrain"] = drivetrain_failure(error)
                return
            except CaseError as error:
                evaluation.problems["drivetrain"] = str(error)
                return
            evaluation.drivetrain = with_separation_note(built, evaluation.pairs)
            evaluation.drivetrain_built = orchestrator.built_drivetrain  # the report's pictures draw from it
            cite("floquet1883")

        _run_stage(evaluation, "drivetrain", drivetrain)

    step("thermal stiffness")

    def thermal():
        from thermogear.mesh.model import MeshModel
        from thermogear.temperature.source import temperature_field_from_case

        evaluation.temperature_field = temperature_field_from_case(case)
        thermal_mesh = MeshModel(case, "thermal")
        if uses_paper_thermal_stiffness(thermal_mesh):  # the paper's k_T curves (Fig. 4) belong to its model only
            from thermogear.case.pieces import call_with_pieces
            from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model
            from thermogear.summaries.thermal import thermal_curves, thermal_stiffness_summary

            paper = call_with_pieces(paper_thermal_model, case)
            evaluation.thermal_curves = thermal_curves(paper)
            evaluation.thermal_summary = thermal_stiffness_summary(paper, MeshModel(case, "elastic"), thermal_mesh)
            cite("timoshenko1951")
        else:  # the thermo-elastic model: its mesh model holds the case's component
            from thermogear.summaries.helical import pair_thermoelastic_summary

            evaluation.thermoelastic_summary = pair_thermoelastic_summary(thermal_mesh)
        if evaluation.paper:  # Fig. 12: the single pair's load share at A, B, D and E
            from thermogear.summaries.load_share import pair_load_share_at_points

            evaluation.pair_load_shares = {name: pair_load_share_at_points(MeshModel(case, name)) for name in MODELS}

    _run_stage(evaluation, "thermal stiffness", thermal)

    step("damping")

    def damping():
        from thermogear.mesh.model import MeshModel
        from thermogear.summaries.damping import damping_summary

        evaluation.damping = damping_summary({model: MeshModel(case, model) for model in MODELS}, case.damping,
                                             case.name)
        cite("den_hartog1931", "iso_tr13989_1", "astm_d341")

    _run_stage(evaluation, "damping", damping)

    if transient:
        step("start-up transients")

        def transients():
            for model in models:
                simulation = evaluation.simulations.get(model) or Simulation(case, model)
                evaluation.transients[model] = simulation.run("transient")
            cite("rk4")

        _run_stage(evaluation, "start-up transients", transients)

    if evaluation.paper:
        step("thermoelastic prediction")

        def beside_paper():
            paper_model, predictive_model = LUO2020_RULES.name, THERMOELASTIC_RULES.name
            predictive = case.with_changes(**{"thermal.model": predictive_model})
            simulations = {ELASTIC: Simulation(case, ELASTIC), paper_model: Simulation(case, THERMAL),
                           predictive_model: Simulation(predictive, THERMAL)}
            evaluation.thermoelastic = thermoelastic_beside_paper(simulations)

        _run_stage(evaluation, "thermoelastic prediction", beside_paper)
        step("rig trend")
        _run_stage(evaluation, "rig trend", lambda: setattr(evaluation, "rig_trend", _rig_trend()))
        evaluation.pending["FE verification"] = fe_verification
        if wait:
            step("FE verification")
            finish_evaluation(evaluation)
    return evaluation


def finish_evaluation(evaluation: Evaluation) -> Evaluation:
    """Collect the stages still running in child processes (the FE verification): their results, warnings and
    failures as any stage's; the stage's timing is the wait for it, its own run time goes to
    ``background_timings``."""
    for name, background in list(evaluation.pending.items()):
        def collect(background=background):
            result = background.result()
            if name == "FE verification":
                cite("scikit_fem")
                evaluation.fem = result

        _run_stage(evaluation, name, collect)
        evaluation.background_timings[name] = background.seconds
        del evaluation.pending[name]
    return evaluation


# -------------------------------------------------------------------------------------------- stages
def fem_verification(inputs):
    """Fig. 15: thermogear's own FE verification of the elastic and thermal pair stiffness along the path,
    ``{"gamma", "elastic", "thermal", "driving_elastic", "driving_thermal"}`` arrays [N/m], from a case's FE inputs
    (:func:`thermogear.fem.inputs.fem_inputs`)."""
    from thermogear.fem.verification import cached_analysis, stiffness_along_path

    cite("scikit_fem")
    return stiffness_along_path(cached_analysis(inputs, checks=False))


def _predicted_rig_runs() -> dict:
    """The rig's temperatures of Table 3 predicted by the gearbox model, cold start and runs chained, with the
    warnings of the prediction (:func:`thermogear.luo2020.rig.prediction.predicted_runs`)."""
    from thermogear import warning_scope
    from thermogear.luo2020.rig.prediction import predicted_runs

    with warning_scope.recorded() as caught:  # the viscosity fit extrapolated below 40 °C: said in the section
        cold, chained = predicted_runs()
    messages = [str(item.message) for item in caught]
    return {"cold": cold, "chained": chained, "messages": messages}


def start_rig_prediction() -> forked.Background:
    """Start the rig predictions in a forked child (or run them now where forking is not available)."""
    return forked.start("rig prediction", _predicted_rig_runs)


def _rig_trend() -> dict:
    """Fig. 18 trend: natural frequency of the FZG type C pair (thermal model) at the bulk temperatures of the
    paper's 900 rpm run (first and last reading)."""
    from thermogear.case import load_case
    from thermogear.luo2020.rig.data import measured_resonance_shift
    from thermogear.simulation import Simulation

    measured = measured_resonance_shift()
    base = load_case("fzg_type_c")
    frequencies = {}
    for name in ("temperature_start_c", "temperature_end_c"):
        temperature = measured[name]
        changed = base.with_changes(**{"temperature.model": "uniform", "temperature.bulk_c": temperature})
        frequencies[temperature] = Simulation(changed, "thermal").natural_frequency_hz
    cite("iso14635_1", "fernandes_gearpie")
    first, last = measured["temperature_start_c"], measured["temperature_end_c"]
    return {"measured": measured, "natural_frequency_hz": frequencies,
            "relative_change": frequencies[last] / frequencies[first] - 1.0}


def thermoelastic_beside_paper(simulations: Mapping[str, Simulation]) -> dict:
    """The paper's own pair under the predictive thermo-elastic model beside the paper's model (``luo2020``) and
    the elastic one, at the same operating point and temperatures: ``simulations`` of the elastic model and of the
    paper's ``luo2020`` model (the paper's case, elastic and thermal) and of ``thermoelastic`` (the same case with
    the predictive thermal model, as :func:`evaluate_case` builds them), keyed by those names. Mean mesh stiffness per
    width [N/(mm·μm)], its change against the elastic model [%], the natural frequency [Hz], Kv and the DTE
    peak-to-peak [μm] of the steady state, the normal backlash cold and hot [μm], the loaded static transmission
    error [μm], the jamming temperature [°C] and what the model flags. Nothing is fitted: the thermo-elastic model
    takes no X_te."""
    paper_model, predictive_model = LUO2020_RULES.name, THERMOELASTIC_RULES.name
    width = simulations[ELASTIC].mesh_model.face_width  # the pair as built (the elastic model's)
    result: dict = {}
    for name, simulation in simulations.items():
        metrics = simulation.run("periodic").metrics
        mesh = simulation.mesh_model
        state = simulation.state
        static = state.static_transmission_error
        static = state.problem().static_transmission_error if static is None else static
        result[name] = {"mean_mesh_stiffness_n_per_mm_um": simulation.mesh_stiffness_mean / width * 1e-9,
                        "natural_frequency_hz": simulation.natural_frequency_hz, "kv": metrics["kv"],
                        "dte_peak_to_peak_um": metrics["dte_peak_to_peak"] * 1e6,
                        "static_transmission_error_peak_to_peak_um": float(np.ptp(static)) * 1e6,
                        "backlash_normal_um": None if mesh.backlash is None else mesh.backlash * 1e6}
    elastic = result[ELASTIC]["mean_mesh_stiffness_n_per_mm_um"]
    for name in (paper_model, predictive_model):
        result[name]["stiffness_change_percent"] = 100.0 * (result[name]["mean_mesh_stiffness_n_per_mm_um"] / elastic - 1)
    component = simulations[predictive_model].mesh_model.thermoelastic_mesh  # the predictive case's
    result[ELASTIC]["backlash_normal_um"] = component.backlash_normal_cold * 1e6  # the cold mesh's
    result[predictive_model].update(
        backlash_cold_um=component.backlash_normal_cold * 1e6, backlash_hot_um=component.backlash_normal * 1e6,
        jamming_bulk_temperature_c=component.jamming_bulk_temperature_c, flags=list(component.plausibility),
        youngs_modulus_gpa=[value * 1e-9 for value in component.youngs_modulus])
    cite("luo2020")
    return result
