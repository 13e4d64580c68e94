"""thermogear's value of every row of the paper table, read from an :class:`~thermogear.evaluation.Evaluation`.

Only reading and comparing: ratios, locations and flags the table needs, taken from the stage results. The
physics is asked of the models: load shares of the mesh model (:mod:`thermogear.summaries.load_share`), decay rates
of the dynamics problem (``MeshPeriod.mean_decay_rate``). A row that cannot be read says why: a stage that failed,
a stage that does not apply to the case's model (:class:`ValueUnavailable`), or a model that refused the case
(:class:`~thermogear.errors.ThermogearError`, whose message names the key and the reason). Any other exception is a
programming error and propagates.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from thermogear.errors import ThermogearError
from thermogear.evaluation import MODELS, Evaluation
from thermogear.luo2020.report.table import PAPER_ROWS

__all__ = ["ValueUnavailable", "paper_values"]


class ValueUnavailable(Exception):
    """A row's value cannot be read from this evaluation; the message says why (shown as "not computed: …")."""


def _needs(results: dict, *names: str, what: str) -> None:
    """ValueUnavailable unless ``results`` holds every one of ``names`` (models or metric keys)."""
    missing = [name for name in names if results.get(name) is None]
    if missing:
        raise ValueUnavailable(f"{what} has no {', '.join(missing)}")


def _present(value, reason: str):
    """``value``, or ValueUnavailable(reason) when it is None (a stage that does not apply to this case)."""
    if value is None:
        raise ValueUnavailable(reason)
    return value


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


def _flank_temperature(evaluation: Evaluation) -> tuple[np.ndarray, np.ndarray]:
    pair = evaluation.case.gear_pair
    field = _present(evaluation.temperature_field, "the stage built no temperature field")
    gamma = np.asarray(pair.gamma(pair.roll_grid(401)), float)
    return gamma, np.asarray(field.pinion_flank_c(gamma), float)


# -------------------------------------------------------------------------------------- paper values
def _input_values(pair, material, operating, oil, lubricant, roughness_ra: float) -> dict[str, Any]:
    """The rows of the paper's Table 1 (and Fig. 7's oil temperature) from a case's gear pair, material, operating
    point, oil, ``[lubricant]`` section and roughness Ra [m]."""
    schema_gap = "not given in this case ([lubricant] specific_heat_j_per_kg_k / thermal_conductivity_w_per_m_k)"
    return {
        "table1.pinion_teeth": pair.pinion.teeth, "table1.wheel_teeth": pair.wheel.teeth,
        "table1.module": pair.module * 1e3, "table1.pressure_angle": np.degrees(pair.pinion.pressure_angle),
        "table1.face_width": pair.face_width * 1e3, "table1.pinion_profile_shift": pair.pinion.profile_shift,
        "table1.wheel_profile_shift": pair.wheel.profile_shift, "table1.centre_distance": pair.centre_distance * 1e3,
        "table1.power": operating.power / 1e3, "table1.speed": operating.speed_rpm,
        "table1.youngs_modulus": material.youngs_modulus / 1e9, "table1.poisson_ratio": material.poisson_ratio,
        "table1.density": material.density, "table1.specific_heat": material.specific_heat,
        "table1.thermal_conductivity": material.thermal_conductivity,
        "table1.oil_density": oil.density_reference,
        "table1.oil_viscosity_40": float(oil.kinematic_viscosity(40.0, warn=False)) * 1e6,
        "table1.oil_viscosity_100": float(oil.kinematic_viscosity(100.0, warn=False)) * 1e6,
        "table1.oil_specific_heat": (lubricant.specific_heat_j_per_kg_k
                                     if lubricant.specific_heat_j_per_kg_k is not None else (None, schema_gap)),
        "table1.oil_thermal_conductivity": (lubricant.thermal_conductivity_w_per_m_k
                                            if lubricant.thermal_conductivity_w_per_m_k is not None
                                            else (None, schema_gap)),
        "table1.oil_operating_temperature": lubricant.operating_temperature_c,
        "table1.roughness": roughness_ra * 1e6,
        "fig7.oil_temperature_elastic": lubricant.reference_temperature_c,
    }


def paper_values(evaluation: Evaluation) -> dict[str, Any]:
    """thermogear's value of every row: a number / bool, or ``(None, reason)`` when it cannot be computed."""
    case = evaluation.case
    values: dict[str, Any] = {}
    from thermogear.lubricant import lubricant_from_case

    values.update(_input_values(case.gear_pair, case.material, case.operating_point, lubricant_from_case(case),
                                case.lubricant, case.roughness_ra))

    def guarded(keys: tuple[str, ...], stages: tuple[str, ...], compute: Callable[[], dict]) -> None:
        reason = evaluation.problem(*stages)
        if not reason:
            try:
                values.update(compute())
                return
            except ValueUnavailable as error:  # the stage does not apply to this case: the reason says why
                reason = str(error)
            except ThermogearError as error:  # a model refused the case: its message names the key and the reason
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
        paper_model_only = ("the case's thermal model is not the paper's k_T (thermal.model = 'luo2020'): Fig. 4's "
                            "curves, drops and compliance changes belong to that model only")
        summary = _present(evaluation.thermal_summary, paper_model_only)
        curve = _present(evaluation.thermal_curves, paper_model_only).curve
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
        _needs(evaluation.simulations, "thermal", what="the evaluation")
        simulation = evaluation.simulations["thermal"]
        from thermogear.report.figures import FIG6_SPAN_MS

        return {"fig6.stiffness_scale": float(simulation.mesh_stiffness.max() / pair.face_width),
                "fig6.time_span": FIG6_SPAN_MS}

    guarded(("fig6.stiffness_scale", "fig6.time_span"), ("thermal model",), fig6)

    # ---------------------------------------------------------------- Figs. 7–8
    def damping():
        means = _present(evaluation.damping, "the damping stage did not run").region_means
        ratio = {region: means["thermal"][region] / means["elastic"][region] for region in ("single", "double")}
        return {"fig7.ce_single": means["elastic"]["single"], "fig7.ce_double": means["elastic"]["double"],
                "fig8.cr_single": means["thermal"]["single"], "fig8.cr_double": means["thermal"]["double"],
                "fig7.double_below_single": bool(all(means[m]["double"] < means[m]["single"] for m in MODELS)),
                "fig8.thermal_damping_ratio": 0.5 * (ratio["single"] + ratio["double"]),
                "_damping_ratio": ratio}

    guarded(("fig7.ce_single", "fig7.ce_double", "fig8.cr_single", "fig8.cr_double", "fig7.double_below_single",
             "fig8.thermal_damping_ratio"), ("damping",), damping)

    def frequency_ratio():
        _needs(evaluation.responses, "elastic", what="the evaluation")
        return {"sec3.frequency_ratio": evaluation.responses["elastic"].metrics["frequency_ratio"]}

    guarded(("sec3.frequency_ratio",), ("elastic model",), frequency_ratio)

    # ---------------------------------------------------------------- Figs. 9–12 (steady state)
    def response():
        _needs(evaluation.responses, "elastic", "thermal", what="the evaluation")
        elastic, thermal = evaluation.responses["elastic"], evaluation.responses["thermal"]
        e, t = elastic.metrics, thermal.metrics
        for model, metrics in (("elastic", e), ("thermal", t)):
            _needs(metrics, "equilibrium_per_region", "amplitude_per_region", "max_system_load_ratio",
                   "max_pair_load_n_per_mm", "kv", what=f"the {model} response")
            _needs(metrics["equilibrium_per_region"], "single", "double", what=f"the {model} response's regions")
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
        # the time-mean decay rate c̄/(2 me) of each model's dynamics problem
        out["fig11.thermal_decays_faster"] = bool(thermal.problem.mean_decay_rate > elastic.problem.mean_decay_rate)
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
        if evaluation.pair_load_shares is None:
            raise ValueUnavailable("the pair load shares are computed for the paper's case only")
        elastic, thermal = evaluation.pair_load_shares["elastic"], evaluation.pair_load_shares["thermal"]
        return {"fig12.single_pair_rises_at_A_E": bool(thermal["A"] > elastic["A"] and thermal["E"] > elastic["E"]
                                                       and thermal["B"] < elastic["B"] and thermal["D"] < elastic["D"]),
                "_pair_share": {"elastic": elastic, "thermal": thermal}}

    guarded(("fig12.single_pair_rises_at_A_E",), ("thermal stiffness",), shares)

    # ---------------------------------------------------------------- transients (Figs. 9, 11)
    def transient():
        _needs(evaluation.transients, "elastic", "thermal", what="the start-up transients")
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
        result = _present(evaluation.fem, "the FE verification runs for a parameter set of the paper only")
        gamma = np.asarray(result["gamma"])
        below = bool(np.all(np.asarray(result["thermal"]) < np.asarray(result["elastic"])))
        out = {"fig15.fe_kt_below_ke": below}
        if "driving_elastic" in result:
            from thermogear.summaries.thermal import crossing_gammas

            crossings = crossing_gammas(gamma, result["driving_elastic"], result["driving_thermal"])
            out["fig15.fe_single_crossing"] = bool(len(crossings) == 1 and crossings[0] < 0.0)
        return out

    guarded(("fig15.fe_kt_below_ke", "fig15.fe_single_crossing"), ("FE verification",), fem)
    values.setdefault("fig15.fe_single_crossing", (None, "the FE result has no single-tooth curves"))

    # ---------------------------------------------------------------- experiment (§5.2)
    def experiment():
        from thermogear.luo2020.rig.data import rig_measurements
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

    guarded(tuple(r.key for r in PAPER_ROWS if (r.section.startswith("§5.2") and r.kind == "input") or r.key == "sec5.load_stage_torque"), (),
            experiment)
    values["sec5.run_duration"] = (None, "the run duration is a test procedure; thermogear's bundled data holds only "
                                         "the readings at minutes 3, 5 and 10")

    def rig():
        trend = _present(evaluation.rig_trend, "the rig trend runs for a parameter set of the paper only")
        return {"fig18.resonance_falls_with_temperature": bool(trend["relative_change"] < 0.0)}

    guarded(("fig18.resonance_falls_with_temperature",), ("rig trend",), rig)
    return values
