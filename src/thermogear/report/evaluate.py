"""Verdicts of the paper table, the key results and the model messages of an evaluated case (the report layer:
it reads the results of :mod:`thermogear.evaluation` and formats them)."""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.evaluation import MODELS, STEPS, Evaluation, evaluate_case, is_paper_case
from thermogear.mesh.model_names import THERMAL
from thermogear.luo2020.report.table import PAPER_ROWS, Verdict, judge
from thermogear.luo2020.report.values import paper_values

__all__ = ["DYNAMIC_FACTORS_NOTE", "Evaluation", "evaluate_case", "paper_values", "paper_verdicts", "key_results",
           "model_messages",
           "STEPS", "is_paper_case"]


#: What the two dynamic factors of the 1-DOF pair are, said beside them (issue 36: "Kv 1.275" and "max system load /
#: static 1.689" far below resonance disagreed without it). The ratio keeps its definition (the paper's system load
#: k(τ)·x(τ) of Fig. 12, and every golden number holds it); the words say what sets it.
DYNAMIC_FACTORS_NOTE = (
    "Kv (Luo & Li 2020 Eq. 29) is the largest load of one tooth pair over the static load; 'max system load / "
    "static' is the largest total mesh force k(τ)·x(τ) over the static load. Where a pair enters contact the mesh "
    "stiffness steps up while the deflection x cannot jump, so the total force jumps to about (stiffness after / "
    "before the step) × the static load and rings down from there: far below resonance the ratio is that stiffness "
    "step (the largest is given as 'mesh stiffness step'), not a vibration. Read Kv as the dynamic factor of the "
    "teeth, the ratio as the peak force the stiffness steps put on shafts and bearings.")


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
    thermal_pair = (evaluation.simulations[THERMAL].mesh_model.gear_pair if THERMAL in evaluation.simulations
                    else pair)  # at temperature under the thermo-elastic model
    add("contact ratio ε", "–", pair.contact_ratio, thermal_pair.contact_ratio)
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
    add("mean damping ratio ζ", "–", metric("elastic", "damping_ratio"), metric("thermal", "damping_ratio"))
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
        metric("thermal", "max_system_load_ratio"), note=DYNAMIC_FACTORS_NOTE)
    if evaluation.drivetrain is not None:
        drivetrain = evaluation.drivetrain.models
        add("dynamic load factor Kv, the pair in its drivetrain", "–",
            *(drivetrain[m].kv if m in drivetrain else None for m in MODELS),
            note="shafts, bearings and couplings of the case's [drivetrain]; the Kv rows above are the 1-DOF pair's "
                 "on rigid supports")
    add("largest |Floquet multiplier|", "–", *(metric(m, "floquet_multipliers_abs")[0]
                                              if metric(m, "floquet_multipliers_abs") else None for m in MODELS))
    add("DTE peak-to-peak", "μm", metric("elastic", "dte_peak_to_peak", scale=1e6),
        metric("thermal", "dte_peak_to_peak", scale=1e6))
    if any(mesh_law(m.get("mesh")).backlash for m in metrics.values()):
        add("time without contact (nonlinear mesh)", "%", metric("elastic", "contact_loss_fraction", scale=100.0),
            metric("thermal", "contact_loss_fraction", scale=100.0),
            note="; ".join(f"{m}: {metrics[m]['response']}, {metrics[m]['branch']} branch"
                           + (", back flanks struck" if metrics[m]["back_side_contact"] else "")
                           for m in MODELS if m in metrics))
    if evaluation.damping is not None:
        means = evaluation.damping.region_means
        for region in ("single", "double"):
            add(f"mean mesh damping, {region} region", "N·s/m", means["elastic"].get(region), means["thermal"].get(region))
    if evaluation.thermoelastic_summary is not None:
        from thermogear.report.thermoelastic_rows import thermoelastic_rows

        for quantity, unit, elastic, thermal, note in thermoelastic_rows(evaluation.thermoelastic_summary):
            add(quantity, unit, elastic, thermal, note=note)
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
    messages = [f"{model}: check — {flag}" for flag in getattr(response, "flags", ())]
    metrics = response.metrics
    if mesh_law(metrics.get("mesh")).backlash:
        return messages + _nonlinear_messages(metrics, model) + list(getattr(response, "warnings", ()))
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


def _nonlinear_messages(metrics: dict, model: str) -> list[str]:
    """What the nonlinear mesh found, in words: contact loss and back-side impacts (computed, not a failure), a
    response that is not periodic, an orbit that was not found."""
    messages = []
    if metrics["contact_loss_fraction"] > 0.0:
        messages.append(f"{model}: contact loss — the teeth separate for {100 * metrics['contact_loss_fraction']:.1f} % "
                        f"of the period{' and strike the back flanks' if metrics['back_side_contact'] else ''}; the "
                        "nonlinear mesh model computes the loads through it")
    if metrics["response"] == "not settled":
        messages.append(f"{model}: the motion from rest has not settled after {metrics['transient_periods']} mesh "
                        f"periods (scaled change over the last period {metrics['residual']:.3g}): the numbers above "
                        "are those of its last period, not of a steady state; raise [dynamics] transient_periods or "
                        "use --method periodic")
        return messages
    if metrics["response"] != "periodic":
        kind = ("subharmonic, repeating every " f"{metrics['period_count']} mesh periods"
                if metrics["response"] == "subharmonic" else "non-periodic (no repeating orbit was found)")
        messages.append(f"{model}: the response is {kind}; its metrics are taken over the recorded periods"
                        + (" and are not a steady state (not valid)" if metrics["response"] == "non-periodic" else ""))
    if not metrics["valid"] and metrics["response"] != "non-periodic":
        messages.append(f"{model}: no steady orbit was found (residual {metrics['residual']:.3g}): the numbers "
                        "above are not a steady state")
    return messages
