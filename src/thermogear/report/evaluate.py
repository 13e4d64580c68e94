"""Run the whole chain of one case for the report and compute thermogear's value of every row of the paper table.

:func:`evaluate_case` runs the stages (elastic and thermal stiffness, damping, periodic steady state, the
start-up transient, …) each in its own guarded step: a stage that fails does not stop the report, its rows show
"not computed" with the reason. :func:`paper_values` then turns the stage results into one value per row of
:data:`~thermogear.report.paper_table.PAPER_ROWS`.

Everything here calls the library (layer 3 and below); nothing is recomputed by hand except small derived
numbers (ratios, locations) that the table needs.
"""

from __future__ import annotations

import time as _time
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from thermogear.citations import cite
from thermogear.report.paper_table import PAPER_ROWS, Verdict, judge

__all__ = ["Evaluation", "evaluate_case", "paper_values", "paper_verdicts", "key_results", "model_messages",
           "STEPS", "is_paper_case"]

MODELS = ("elastic", "thermal")

#: Names of the evaluation steps, in order (for progress bars).
STEPS = ("elastic model", "thermal model", "thermal stiffness", "damping", "start-up transients", "rig trend",
         "FE verification")


def is_paper_case(case) -> bool:
    """True for the paper's own case (the report then has the paper column)."""
    return case.name == "luo2019"


@dataclass
class Evaluation:
    """Everything the report shows for one case. Stage results are None when the stage failed (``problems``)."""

    case: Any
    method: str = "periodic"
    simulations: dict = field(default_factory=dict)  # model -> Simulation
    responses: dict = field(default_factory=dict)  # model -> DynamicResponse (steady state, ``method``)
    transients: dict = field(default_factory=dict)  # model -> DynamicResponse from rest
    thermal_curves: Any = None  # thermal.summary.ThermalCurves
    thermal_summary: dict | None = None
    temperature_field: Any = None
    damping: Any = None  # damping.DampingSummary
    rig_trend: dict | None = None
    fem: Any = None
    problems: dict = field(default_factory=dict)  # stage -> reason it failed
    timings: dict = field(default_factory=dict)  # stage -> seconds
    warnings: list = field(default_factory=list)  # warning texts raised during the run (deduplicated)

    @property
    def paper(self) -> bool:
        return is_paper_case(self.case)

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
        except Exception as error:  # noqa: BLE001 - a failed stage becomes "not computed: reason" in the report
            evaluation.problems[name] = f"{type(error).__name__}: {error}"
    for item in caught:
        text = f"{item.category.__name__}: {item.message}"
        if text not in evaluation.warnings:
            evaluation.warnings.append(text)
    evaluation.timings[name] = _time.perf_counter() - start


def evaluate_case(case, method: str = "periodic", models: tuple[str, ...] = MODELS, transient: bool = True,
                  progress: Callable[[str], None] | None = None) -> Evaluation:
    """Run the chain of ``case``: per model the stiffness, damping and dynamics (``method``), the Fig. 4
    thermal-stiffness curves, the damping summary, the start-up transients (Figs. 9–11) and, for the paper's
    case, the rig trend of Fig. 18. ``progress(step)`` is called before each step."""
    from thermogear.simulation import Simulation

    evaluation = Evaluation(case=case, method=method)
    step = progress or (lambda name: None)
    cite("luo2020", "iso21771", "iso53", "yang1987", "tian2004", "sainsot2004", "chaari2009")
    if case.citation and "14635" in case.citation:
        cite("iso14635_1")

    for model in models:
        step(f"{model} model")

        def run_model(model=model):
            simulation = Simulation(case, model)
            evaluation.simulations[model] = simulation
            evaluation.responses[model] = simulation.run(method)
            cite("floquet1883" if method == "periodic" else "rk4", "den_hartog1931", "iso_tr13989_1", "astm_d341")
            if model == "thermal":
                cite("timoshenko1951")

        _run_stage(evaluation, f"{model} model", run_model)

    step("thermal stiffness")

    def thermal():
        from thermogear.thermal.summary import thermal_curves, thermal_stiffness_summary
        from thermogear.thermal.temperature import temperature_field_from_case

        evaluation.temperature_field = temperature_field_from_case(case)
        evaluation.thermal_curves = thermal_curves(case)
        evaluation.thermal_summary = thermal_stiffness_summary(case)
        cite("timoshenko1951")

    _run_stage(evaluation, "thermal stiffness", thermal)

    step("damping")

    def damping():
        from thermogear.mesh.damping_summary import damping_summary

        evaluation.damping = damping_summary(case)
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
        step("rig trend")
        _run_stage(evaluation, "rig trend", lambda: setattr(evaluation, "rig_trend", _rig_trend()))
        step("FE verification")
        _run_stage(evaluation, "FE verification", lambda: setattr(evaluation, "fem", fem_verification(case)))
    return evaluation


# -------------------------------------------------------------------------------------------- stages
def fem_verification(case):
    """Fig. 15: thermogear's own FE verification of the elastic and thermal pair stiffness along the path,
    ``{"gamma", "elastic", "thermal", "driving_elastic", "driving_thermal"}`` arrays [N/m]."""
    from thermogear.fem.verification import stiffness_along_path

    cite("scikit_fem")
    return stiffness_along_path(case)


def _rig_trend() -> dict:
    """Fig. 18 trend: natural frequency of the FZG type C pair (thermal model) at the bulk temperatures of the
    paper's 900 rpm run (first and last reading)."""
    from thermogear.case import load_case
    from thermogear.experiment.rig_data import measured_resonance_shift
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


# ------------------------------------------------------------------------------------- derived numbers
def _region_time_fraction_masks(problem):
    """Per interval: contact count, node times and the transition times (where the count changes)."""
    counts = np.asarray(problem.contact_count)
    nodes = np.asarray(problem.nodes)
    change = np.flatnonzero(np.roll(counts, 1) != counts)
    return counts, nodes, nodes[change]


def _time_after_transition(time: float, transitions: np.ndarray, period: float) -> float:
    """Phase distance [fraction of a period] from the closest transition before ``time``."""
    distance = np.mod(time - transitions, period)
    return float(np.min(distance) / period)


def _phase_distance(time: float, moment: float, period: float) -> float:
    """|time − moment| modulo the period, as a fraction of the period."""
    distance = np.mod(time - moment, period) / period
    return float(min(distance, 1.0 - distance))


def _pair_share(case, model: str) -> dict[str, float]:
    """Steady load share of a pair at A, B, D, E for one model, from its mesh model."""
    from thermogear.mesh.model import MeshModel
    from thermogear.mesh_cycle import load_share_at

    mesh = MeshModel(case, model)
    points = mesh.gear_pair.path_points
    own = np.array([points["A"], points["B"], points["D"], points["E"]])
    share, _ = load_share_at(own, mesh.pair_stiffness_at, points["A"], points["E"], mesh.gear_pair.base_pitch)
    return dict(zip("ABDE", (float(v) for v in share)))


def _flank_temperature(evaluation: Evaluation) -> tuple[np.ndarray, np.ndarray]:
    pair = evaluation.case.gear_pair
    gamma = np.asarray(pair.gamma(pair.roll_grid(401)), float)
    return gamma, np.asarray(evaluation.temperature_field.pinion_flank_c(gamma), float)


# -------------------------------------------------------------------------------------- paper values
def _input_values(case) -> dict[str, Any]:
    from thermogear.lubricant import lubricant_from_case

    pair, material, document = case.gear_pair, case.material, case.document
    oil = lubricant_from_case(case)
    schema_gap = "not given in this case ([lubricant] specific_heat_j_per_kg_k / thermal_conductivity_w_per_m_k)"
    return {
        "table1.pinion_teeth": pair.pinion.teeth, "table1.wheel_teeth": pair.wheel.teeth,
        "table1.module": pair.module * 1e3, "table1.pressure_angle": np.degrees(pair.pinion.pressure_angle),
        "table1.face_width": pair.face_width * 1e3, "table1.pinion_profile_shift": pair.pinion.profile_shift,
        "table1.wheel_profile_shift": pair.wheel.profile_shift, "table1.centre_distance": pair.centre_distance * 1e3,
        "table1.power": case.operating_point.power / 1e3, "table1.speed": case.operating_point.speed_rpm,
        "table1.youngs_modulus": material.youngs_modulus / 1e9, "table1.poisson_ratio": material.poisson_ratio,
        "table1.density": material.density, "table1.specific_heat": material.specific_heat,
        "table1.thermal_conductivity": material.thermal_conductivity,
        "table1.oil_density": oil.density_reference,
        "table1.oil_viscosity_40": float(oil.kinematic_viscosity(40.0, warn=False)) * 1e6,
        "table1.oil_viscosity_100": float(oil.kinematic_viscosity(100.0, warn=False)) * 1e6,
        "table1.oil_specific_heat": (case.lubricant.specific_heat_j_per_kg_k
                                     if case.lubricant.specific_heat_j_per_kg_k is not None else (None, schema_gap)),
        "table1.oil_thermal_conductivity": (case.lubricant.thermal_conductivity_w_per_m_k
                                            if case.lubricant.thermal_conductivity_w_per_m_k is not None
                                            else (None, schema_gap)),
        "table1.oil_operating_temperature": case.lubricant.operating_temperature_c,
        "table1.roughness": case.roughness_ra * 1e6,
        "fig7.oil_temperature_elastic": case.lubricant.reference_temperature_c,
        "_document": document,
    }


def paper_values(evaluation: Evaluation) -> dict[str, Any]:
    """thermogear's value of every row: a number / bool, or ``(None, reason)`` when it cannot be computed."""
    case = evaluation.case
    values: dict[str, Any] = {}
    values.update(_input_values(case))
    values.pop("_document", None)

    def guarded(keys: tuple[str, ...], stages: tuple[str, ...], compute: Callable[[], dict]) -> None:
        reason = evaluation.problem(*stages)
        if not reason:
            try:
                values.update(compute())
                return
            except (KeyboardInterrupt, SystemExit):
                raise
            except Exception as error:  # noqa: BLE001 - shown as "not computed: reason"
                reason = f"{type(error).__name__}: {error}"
        for key in keys:
            values.setdefault(key, (None, reason))

    pair = case.gear_pair
    points = pair.path_points

    # ---------------------------------------------------------------- Fig. 3c
    def fig3():
        gamma, flank = _flank_temperature(evaluation)
        at = {name: float(evaluation.temperature_field.pinion_flank_c(np.array([pair.gamma(points[name])]))[0])
              for name in "ACE"}
        return {"fig3.flank_temperature_min": float(flank.min()), "fig3.flank_temperature_max": float(flank.max()),
                "fig3.gamma_start": float(pair.gamma(points["A"])), "fig3.gamma_end": float(pair.gamma(points["E"])),
                "fig3.minimum_near_pitch": bool(abs(gamma[np.argmin(flank)]) < 0.15),
                "fig3.higher_towards_ends": bool(at["A"] > at["C"] and at["E"] > at["C"])}

    guarded(("fig3.flank_temperature_min", "fig3.flank_temperature_max", "fig3.gamma_start", "fig3.gamma_end",
             "fig3.minimum_near_pitch", "fig3.higher_towards_ends"), ("thermal stiffness",), fig3)

    # ---------------------------------------------------------------- Fig. 4
    def fig4():
        summary, curve = evaluation.thermal_summary, evaluation.thermal_curves.curve
        drop = summary["stiffness_drop_percent"]
        change = summary["single_tooth_compliance_change_percent"]
        gamma = np.asarray(curve.gamma)
        largest = gamma[np.argmax(curve.drop_percent)]

        def spread(values):
            values = np.asarray(values)
            return (values.max() - values.min()) / values.mean()

        crossing = summary["single_tooth_crossing_gamma"]["driving"]
        pinion_change = evaluation.thermal_curves.points.pinion_compliance_change_percent
        return {
            "fig4.kt_below_ke": bool(summary["thermal_below_elastic_everywhere"]),
            "fig4.drop_at_A": drop["A"], "fig4.drop_at_E": drop["E"], "fig4.drop_at_C": drop["C"],
            "fig4.largest_drop_where_ke_largest": bool(pair.gamma(points["B"]) <= largest <= pair.gamma(points["D"])),
            "fig4.kt_flatter": bool(spread(curve.stiffness) < spread(curve.elastic_stiffness)),
            "fig4.single_tooth_crossings": float(summary["single_tooth_crossing_count"]["driving"]),
            # no crossing at all: the claim "they cross near the root" is false
            "fig4.crossing_near_root": bool(crossing is not None and crossing < 0.0),
            # driving tooth meshes from its root (A) to its tip (E): thermal stiffer at A ⇔ compliance change < 0
            "fig4.thermal_higher_root_side": bool(pinion_change[0] < 0.0 < pinion_change[4]),
            "fig4.driving_compliance_tip": change["driving_tip"], "fig4.driving_compliance_root": change["driving_root"],
            "fig4.driven_compliance_tip": change["driven_tip"], "fig4.driven_compliance_root": change["driven_root"],
        }

    guarded(tuple(r.key for r in PAPER_ROWS if r.key.startswith("fig4.")), ("thermal stiffness",), fig4)

    # ---------------------------------------------------------------- Fig. 6
    values["fig6.contact_ratio"] = float(pair.contact_ratio)

    def fig6():
        simulation = evaluation.simulations["thermal"]
        from thermogear.report.figures import FIG6_SPAN_MS

        return {"fig6.stiffness_scale": float(simulation.mesh_stiffness.max() / pair.face_width),
                "fig6.time_span": FIG6_SPAN_MS}

    guarded(("fig6.stiffness_scale", "fig6.time_span"), ("thermal model",), fig6)

    # ---------------------------------------------------------------- Figs. 7–8
    def damping():
        means = evaluation.damping.region_means
        ratio = {region: means["thermal"][region] / means["elastic"][region] for region in ("single", "double")}
        return {"fig7.ce_single": means["elastic"]["single"], "fig7.ce_double": means["elastic"]["double"],
                "fig8.cr_single": means["thermal"]["single"], "fig8.cr_double": means["thermal"]["double"],
                "fig7.double_below_single": bool(all(means[m]["double"] < means[m]["single"] for m in MODELS)),
                "fig8.thermal_damping_ratio": 0.5 * (ratio["single"] + ratio["double"]),
                "_damping_ratio": ratio}

    guarded(("fig7.ce_single", "fig7.ce_double", "fig8.cr_single", "fig8.cr_double", "fig7.double_below_single",
             "fig8.thermal_damping_ratio"), ("damping",), damping)

    def frequency_ratio():
        return {"sec3.frequency_ratio": evaluation.responses["elastic"].metrics["frequency_ratio"]}

    guarded(("sec3.frequency_ratio",), ("elastic model",), frequency_ratio)

    # ---------------------------------------------------------------- Figs. 9–12 (steady state)
    def response():
        elastic, thermal = evaluation.responses["elastic"], evaluation.responses["thermal"]
        e, t = elastic.metrics, thermal.metrics
        eq_e, eq_t = e["equilibrium_per_region"], t["equilibrium_per_region"]
        amp_e, amp_t = e["amplitude_per_region"], t["amplitude_per_region"]
        out = {
            "fig9.two_levels": bool(eq_e["single"] > 1.1 * eq_e["double"] and eq_t["single"] > 1.1 * eq_t["double"]),
            "fig9.equilibrium_increase_single": 100.0 * (eq_t["single"] / eq_e["single"] - 1.0),
            "fig9.equilibrium_increase_double": 100.0 * (eq_t["double"] / eq_e["double"] - 1.0),
            "fig9.amplitude_elastic_single": amp_e["single"] * 1e6, "fig9.amplitude_elastic_double": amp_e["double"] * 1e6,
            "fig9.amplitude_thermal_single": amp_t["single"] * 1e6, "fig9.amplitude_thermal_double": amp_t["double"] * 1e6,
            "fig9.amplitude_change_single": 100.0 * (amp_t["single"] / amp_e["single"] - 1.0),
            "fig9.amplitude_change_double": 100.0 * (amp_t["double"] / amp_e["double"] - 1.0),
            "fig10.thermal_lags_displacement": bool(
                eq_t["single"] > eq_e["single"] and eq_t["double"] > eq_e["double"]
                and eq_t["single"] - eq_e["single"] > eq_t["double"] - eq_e["double"]),
            "fig12.max_system_load_ratio": t["max_system_load_ratio"],
            "fig12.max_load_elastic": e["max_pair_load_n_per_mm"] * 1e3,
            "fig12.max_load_thermal": t["max_pair_load_n_per_mm"] * 1e3,
            "fig12.kv_elastic": e["kv"], "fig12.kv_thermal": t["kv"],
            "fig12.kv_falls_under_heat": bool(t["kv"] < e["kv"]),
        }
        # convergence to two points: before every transition the velocity has decayed below 20 % of its peak
        converged = True
        for item in (elastic, thermal):
            counts, nodes, transitions = _region_time_fraction_masks(item.problem)
            period = item.problem.period
            speed = np.abs(item.velocity)
            for moment in transitions:
                before = (np.mod(moment - item.time, period) > 0) & (np.mod(moment - item.time, period) < 0.05 * period)
                converged &= bool(speed[before].max() < 0.2 * speed.max()) if np.any(before) else True
        out["fig10.converges_to_two_points"] = converged
        # decay rate c/(2 me), time mean over the period
        rates = {name: float(np.sum(item.problem.damping * np.diff(item.problem.nodes)) / item.problem.period
                             / (2.0 * item.problem.mass)) for name, item in (("e", elastic), ("t", thermal))}
        out["fig11.thermal_decays_faster"] = bool(rates["t"] > rates["e"])
        # steady value of the system load = static load
        load = thermal.system_load()
        mean_load = float(np.trapezoid(load, thermal.time) / thermal.problem.period)
        out["fig12.steady_value_is_static_load"] = bool(abs(mean_load / thermal.problem.static_load - 1.0) < 0.02)
        out["_steady_load_ratio"] = mean_load / thermal.problem.static_load
        # peaks at transitions; maximum pair load at B (entry of a pair into single contact)
        counts, nodes, transitions = _region_time_fraction_masks(thermal.problem)
        period = thermal.problem.period
        peak_time = float(thermal.time[np.argmax(load)])
        out["fig12.peaks_at_transitions"] = _time_after_transition(peak_time, transitions, period) < 0.15
        pair_loads = thermal.pair_loads()
        peak_pair_time = float(thermal.time[np.unravel_index(np.argmax(pair_loads), pair_loads.shape)[-1]])
        into_single = nodes[np.flatnonzero((counts == 1) & (np.roll(counts, 1) == 2))]
        out["fig12.max_pair_load_at_B"] = bool(min(_phase_distance(peak_pair_time, moment, period)
                                                   for moment in into_single) < 0.15) if into_single.size else (
            None, "the mesh cycle has no transition into single contact")
        return out

    guarded(("fig9.two_levels", "fig9.equilibrium_increase_single", "fig9.equilibrium_increase_double",
             "fig9.amplitude_elastic_single", "fig9.amplitude_elastic_double", "fig9.amplitude_thermal_single",
             "fig9.amplitude_thermal_double", "fig9.amplitude_change_single", "fig9.amplitude_change_double",
             "fig10.thermal_lags_displacement", "fig10.converges_to_two_points", "fig11.thermal_decays_faster",
             "fig12.max_system_load_ratio", "fig12.max_load_elastic", "fig12.max_load_thermal", "fig12.kv_elastic",
             "fig12.kv_thermal", "fig12.kv_falls_under_heat", "fig12.steady_value_is_static_load",
             "fig12.peaks_at_transitions", "fig12.max_pair_load_at_B"), ("elastic model", "thermal model"), response)

    def shares():
        elastic, thermal = _pair_share(case, "elastic"), _pair_share(case, "thermal")
        return {"fig12.single_pair_rises_at_A_E": bool(thermal["A"] > elastic["A"] and thermal["E"] > elastic["E"]
                                                       and thermal["B"] < elastic["B"] and thermal["D"] < elastic["D"]),
                "_pair_share": {"elastic": elastic, "thermal": thermal}}

    guarded(("fig12.single_pair_rises_at_A_E",), ("thermal stiffness",), shares)

    # ---------------------------------------------------------------- transients (Figs. 9, 11)
    def transient():
        out = {}
        ok = True
        for item in evaluation.transients.values():
            history = item.history
            stride = history.samples_per_period
            last = history.displacement[-stride - 1:]
            previous = history.displacement[-2 * stride - 1:-stride]
            amplitude = np.ptp(last)
            ok &= bool(np.max(np.abs(last - previous)) < 0.01 * amplitude)
        out["fig9.period_equals_mesh_period"] = ok
        peak = {name: float(np.max(np.abs(item.history.velocity))) for name, item in evaluation.transients.items()}
        out["fig11.thermal_peak_velocity_larger"] = bool(peak["thermal"] > peak["elastic"])
        out["_peak_velocity"] = peak
        return out

    guarded(("fig9.period_equals_mesh_period", "fig11.thermal_peak_velocity_larger"), ("start-up transients",),
            transient)

    # ---------------------------------------------------------------- FE (Fig. 15), optional
    def fem():
        result = evaluation.fem
        gamma = np.asarray(result["gamma"])
        below = bool(np.all(np.asarray(result["thermal"]) < np.asarray(result["elastic"])))
        out = {"fig15.fe_kt_below_ke": below}
        if "driving_elastic" in result:
            from thermogear.thermal.summary import crossing_gammas

            crossings = crossing_gammas(gamma, result["driving_elastic"], result["driving_thermal"])
            out["fig15.fe_single_crossing"] = bool(len(crossings) == 1 and crossings[0] < 0.0)
        return out

    guarded(("fig15.fe_kt_below_ke", "fig15.fe_single_crossing"), ("FE verification",), fem)
    values.setdefault("fig15.fe_single_crossing", (None, "the FE result has no single-tooth curves"))

    # ---------------------------------------------------------------- experiment (§5.2)
    def experiment():
        from thermogear.experiment.rig_data import rig_measurements
        from thermogear.fzg import fzg_load_stage_torque

        out = {}
        for item in rig_measurements():
            base = f"table3.n{item.speed_rpm:g}_m{item.minute:g}"
            out[f"{base}.temperature"] = item.temperature_c
            out[f"{base}.mean_acceleration"] = item.mean_acceleration_m_s2
            out[f"{base}.max_acceleration"] = item.max_acceleration_m_s2
            if item.resonance_frequency_hz is not None:
                out[f"fig18.spectrum_peak_{item.temperature_c:g}C"] = item.spectrum_peak_m_s2
                out[f"fig18.resonance_{item.temperature_c:g}C"] = item.resonance_frequency_hz
        out["sec5.load_stage_torque"] = fzg_load_stage_torque(6)
        return out

    guarded(tuple(r.key for r in PAPER_ROWS if r.kind == "measured" or r.key == "sec5.load_stage_torque"), (),
            experiment)
    values["sec5.run_duration"] = (None, "the run duration is a test procedure; thermogear's bundled data holds only "
                                         "the readings at minutes 3, 5 and 10")

    def rig():
        return {"fig18.resonance_falls_with_temperature": bool(evaluation.rig_trend["relative_change"] < 0.0)}

    guarded(("fig18.resonance_falls_with_temperature",), ("rig trend",), rig)
    return values


def paper_verdicts(evaluation: Evaluation, values: dict | None = None) -> list[Verdict]:
    """Every row of the paper table judged against thermogear's value (in table order, none left out)."""
    values = paper_values(evaluation) if values is None else values
    verdicts = []
    for item in PAPER_ROWS:
        value = values.get(item.key, (None, "no evaluation is wired for this row"))
        reason = ""
        if isinstance(value, tuple):
            value, reason = value
        if isinstance(value, np.generic):
            value = value.item()
        if isinstance(value, (int,)) and not isinstance(value, bool):
            value = float(value)
        verdicts.append(judge(item, value, reason))
    return verdicts


# ----------------------------------------------------------------------------------- any case's results
def key_results(evaluation: Evaluation) -> list[dict]:
    """The results table of any case: quantity, unit, elastic and thermal value (None where not available)."""
    rows: list[dict] = []

    def add(quantity: str, unit: str, elastic=None, thermal=None, note: str = ""):
        rows.append({"quantity": quantity, "unit": unit, "elastic": _plain(elastic), "thermal": _plain(thermal),
                     "note": note})

    pair = evaluation.case.gear_pair
    add("contact ratio ε", "–", pair.contact_ratio, pair.contact_ratio)
    metrics = {model: response.metrics for model, response in evaluation.responses.items()}

    def metric(model, *path, scale=1.0):
        value = metrics.get(model)
        for key in path:
            if value is None:
                return None
            value = value.get(key) if isinstance(value, dict) else None
        if value is None or isinstance(value, (list, dict)):
            return value
        return value * scale

    simulations = evaluation.simulations
    add("mean mesh stiffness per width", "N/(mm·μm)",
        *(simulations[m].mesh_stiffness_mean / pair.face_width * 1e-9 if m in simulations else None for m in MODELS))
    add("natural frequency f_n", "Hz", metric("elastic", "natural_frequency_hz"), metric("thermal", "natural_frequency_hz"))
    add("frequency ratio λ = f_mesh / f_n", "–", metric("elastic", "frequency_ratio"), metric("thermal", "frequency_ratio"))
    counts = sorted({region for m in metrics.values() for region in m["equilibrium_per_region"]},
                    key=lambda name: ("single", "double", "triple").index(name) if name in ("single", "double", "triple")
                    else 9)
    for region in counts:
        add(f"equilibrium (static TE), {region} region", "μm", metric("elastic", "equilibrium_per_region", region, scale=1e6),
            metric("thermal", "equilibrium_per_region", region, scale=1e6))
    for region in counts:
        add(f"amplitude (peak − equilibrium), {region} region", "μm",
            metric("elastic", "amplitude_per_region", region, scale=1e6),
            metric("thermal", "amplitude_per_region", region, scale=1e6))
    add("maximum pair load", "N/mm", metric("elastic", "max_pair_load_n_per_mm"), metric("thermal", "max_pair_load_n_per_mm"))
    add("dynamic load factor Kv (Eq. 29)", "–", metric("elastic", "kv"), metric("thermal", "kv"))
    add("maximum system load / static load", "–", metric("elastic", "max_system_load_ratio"),
        metric("thermal", "max_system_load_ratio"))
    add("largest |Floquet multiplier|", "–", *(metric(m, "floquet_multipliers_abs")[0]
                                              if metric(m, "floquet_multipliers_abs") else None for m in MODELS))
    if evaluation.damping is not None:
        means = evaluation.damping.region_means
        for region in ("single", "double"):
            add(f"mean mesh damping, {region} region", "N·s/m", means["elastic"].get(region), means["thermal"].get(region))
    if evaluation.thermal_summary is not None:
        summary = evaluation.thermal_summary
        add("X_te (thermo-elastic correction factor)", "–", None, summary["x_te"], note=str(summary["x_te_source"]))
        for name in ("A", "C", "E"):
            add(f"stiffness drop kT vs ke at {name}", "%", None, summary["stiffness_drop_percent"][name])
        for name, value in summary["single_tooth_compliance_change_percent"].items():
            add(f"single-tooth compliance change, {name.replace('_', ' ')}", "%", None, value)
    return rows


def _plain(value):
    if value is None:
        return None
    value = float(value)
    return value if np.isfinite(value) else None


def model_messages(response, model: str) -> list[str]:
    """What a user must be told in words about a response: contact loss (when, how long, how deep) and
    instability. Empty when the linear model holds."""
    messages = []
    metrics = response.metrics
    loss = metrics.get("contact_loss", {})
    period = response.problem.period
    if loss.get("detected"):
        starts = ", ".join(f"{t * 1e3:.3f} ms ({t / period:.2f} T)" for t in loss["start_times"][:4])
        longest = max(loss["durations"]) if loss["durations"] else 0.0
        messages.append(
            f"{model}: CONTACT LOSS — the mesh force goes negative {len(loss['start_times'])} time(s) per mesh period, "
            f"starting at {starts}; longest {longest * 1e3:.3f} ms ({longest / period * 100:.0f} % of the period); "
            f"deepest {loss['min_force']:.4g} N ({loss['min_force_ratio'] * 100:.0f} % of the static load). The linear "
            "model assumes permanent contact: the loads and Kv above are not valid for this operating point.")
    if not metrics.get("stable", True):
        largest = metrics["floquet_multipliers_abs"][0]
        messages.append(
            f"{model}: UNSTABLE — the largest Floquet multiplier has |μ| = {largest:.4g} > 1 (parametric resonance): "
            "the response grows from period to period and no periodic steady state exists; the numbers above describe "
            "an unbounded solution and must not be used.")
    return messages
