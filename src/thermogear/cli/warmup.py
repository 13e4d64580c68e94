"""`thermogear warmup CASE`: operating states of a rig warm-up (stiffness, damping, natural frequency, steady
response per temperature), and with ``--rig-comparison`` the model beside Luo & Li (2020) Table 3 / Fig. 18."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import typer
from rich.table import Table

from thermogear.case import load_case
from thermogear.cli.app import app, console, result_payload
from thermogear.errors import CaseError


@dataclass(frozen=True)
class WarmupModel:
    """A warm-up model of ``--model``: ``name``, and whether it integrates the case's gearbox thermal network
    (``network``: the case is loaded as the network's commands load it, reported at any temperature it reaches;
    else the first-order rise of ``--start-c`` to ``--final-c``)."""

    name: str
    network: bool


#: The warm-up models of ``--model`` by name: the one place the names are compared.
WARMUP_MODELS: dict[str, WarmupModel] = {model.name: model for model in (
    WarmupModel("first-order", network=False), WarmupModel("gearbox", network=True))}


@app.command()
def warmup(
    case: str = typer.Argument(..., metavar="CASE",
                               help="built-in parameter set (see `thermogear cases`) or a .toml file"),
    temperature_history: str | None = typer.Option(
        None, "--temperature-history",
        help="CSV with time_s|time_min and temperature_c, or luo2019:RPM (the paper's Table 3 run)"),
    model: str | None = typer.Option(None, "--model", help="warm-up model instead of a history: 'first-order', or 'gearbox' (predicted "
                                     "by the case's [gearbox] thermal network)"),
    start_c: float | None = typer.Option(None, "--start-c", help="start temperature [°C] (first-order: default "
                                         "20; gearbox: every node, default the ambient, down to -40)"),
    final_c: float = typer.Option(60.0, "--final-c", help="first-order model: final temperature [°C]"),
    time_constant_s: float = typer.Option(600.0, "--time-constant-s", help="first-order model: τ [s]"),
    duration_s: float = typer.Option(1200.0, "--duration-s", help="first-order or gearbox model: duration [s]"),
    interval_s: float = typer.Option(10.0, "--interval-s", help="gearbox model: time between mesh "
                                     "re-evaluations [s]"),
    states: int = typer.Option(7, "--states", min=1, max=500, help="first-order model: number of states"),
    gear_model: str = typer.Option("thermal", "--gear-model", help="'thermal' (k_T, c_r) or 'elastic' (k_e, c_e)"),
    speed_rpm: float | None = typer.Option(None, "--speed-rpm", help="pinion speed [rpm] (default: the case's, "
                                           "or RPM of luo2019:RPM)"),
    dynamics: bool = typer.Option(True, "--dynamics/--no-dynamics", help="solve the steady response per state"),
    torque_nm: float | None = typer.Option(None, "--torque-nm", help="gearbox model: pinion torque [N·m] "
                                           "(default: the case's)"),
    oil_setpoint_c: float | None = typer.Option(None, "--oil-setpoint-c", help="gearbox model: the rig's oil "
                                                "conditioning holds the sump at this temperature [°C] (with "
                                                "--heater-w and/or --cooling-w)"),
    heater_w: float = typer.Option(0.0, "--heater-w", help="gearbox model: oil heater power [W]"),
    stages: str | None = typer.Option(None, "--stages", help="gearbox model: FZG load stages FIRST:LAST (e.g. 5:12) "
                                      "run one after another, each for --duration-s from every node at --start-c "
                                      "(the FZG procedure: 900 s from 90 °C)"),
    cooling_w: float = typer.Option(0.0, "--cooling-w", help="gearbox model: oil cooler power [W]"),
    rig_comparison: bool = typer.Option(False, "--rig-comparison",
                                        help="instead: CASE beside the paper's Table 3 / Fig. 18 (relative shifts)"),
    as_json: bool = typer.Option(False, "--json", help="one JSON object on stdout"),
    plot: Path | None = typer.Option(None, "--plot", help="write the figure to this file (.png/.svg/.pdf)"),
) -> None:
    """Warm-up of a test rig as a sequence of steady operating states."""
    if plot is not None:
        from thermogear.ownership import check_figure_file

        check_figure_file(plot)  # before any work
    if rig_comparison:  # the comparison loads the case itself, one case per Table 3 state
        _rig_comparison(case, gear_model, as_json, plot)
        return
    chosen = None if model is None else WARMUP_MODELS.get(model)
    if chosen is not None and chosen.network:  # reported at any temperature it reaches (flags, not a refusal)
        from thermogear.gearbox.case_model import load_gearbox_case  # noqa: PLC0415

        base = load_gearbox_case(case)
    else:
        base = load_case(case)
    from thermogear.experiment.warmup import first_order_history, read_temperature_history, warmup as run_warmup

    if (temperature_history is None) == (model is None):
        raise CaseError("--temperature-history/--model", temperature_history or model,
                        "exactly one of --temperature-history FILE|luo2019:RPM or --model first-order",
                        "the warm-up needs one temperature source")
    if model is not None:
        if chosen is None:
            raise CaseError("--model", model, " | ".join(WARMUP_MODELS), "unknown warm-up model")
        if chosen.network:
            from thermogear.cli.gearbox_warmup import run_gearbox_warmup  # noqa: PLC0415

            conditioning = None
            if oil_setpoint_c is not None:
                from thermogear.gearbox.description import OilConditioning  # noqa: PLC0415

                if heater_w == 0.0 and cooling_w == 0.0:
                    raise CaseError("--heater-w/--cooling-w", 0.0, "> 0 with --oil-setpoint-c",
                                    "a conditioning without heater or cooler has no effect")
                conditioning = OilConditioning(oil_setpoint_c, heater_w, cooling_w)
            elif heater_w or cooling_w:
                raise CaseError("--oil-setpoint-c", None, "a temperature [°C] with --heater-w/--cooling-w",
                                "the thermostat needs its set point")
            if stages is not None:
                from thermogear.cli.gearbox_warmup import run_gearbox_stages  # noqa: PLC0415

                run_gearbox_stages(base, stages, duration_s, start_c, speed_rpm, conditioning, as_json)
                return
            run_gearbox_warmup(base, duration_s, start_c, interval_s, gear_model, speed_rpm, dynamics, as_json,
                               plot, _save, torque_nm, conditioning)
            return
        history = first_order_history(20.0 if start_c is None else start_c, final_c, time_constant_s, duration_s,
                                      states)
    else:
        history = read_temperature_history(temperature_history)
        if speed_rpm is None and temperature_history.startswith("luo2019:"):
            from thermogear.experiment.warmup import history_speed_rpm

            speed_rpm = history_speed_rpm(temperature_history)
    result = run_warmup(base, history, gear_model, speed_rpm, dynamics)
    payload = result_payload(result, plot, as_json, _save)
    if payload is None:  # printed as JSON
        return
    table = Table(title=f"warm-up of {result.case_name} at {result.speed_rpm:g} rpm ({result.model} model; "
                        f"{result.history_source})")
    for name in ("t [s]", "T [°C]", "k̄ [N/(mm·μm)]", "c̄ [N·s/m]", "f_n [Hz]", "f_mesh [Hz]", "Kv", "DTE rms [μm]"):
        table.add_column(name, justify="right")
    for state in payload["states"]:
        response = state["response"]
        table.add_row(f"{state['time_s']:.0f}", f"{state['temperature_c']:.1f}",
                      f"{state['mesh_stiffness_mean_n_per_mm_um']:.3f}", f"{state['mesh_damping_mean_n_s_per_m']:.0f}",
                      f"{state['natural_frequency_hz']:.1f}", f"{state['mesh_frequency_hz']:.1f}",
                      "—" if response is None else f"{response['kv']:.3f}",
                      "—" if response is None else f"{response['dte_rms_m'] * 1e6:.3f}")
    console.print(table)
    console.print(payload["assumption"])
    if plot is not None:
        console.print(f"figure written to {plot}")


def _rig_comparison(case: str, gear_model: str, as_json: bool, plot: Path | None) -> None:
    from thermogear.experiment.comparison import compare_with_rig

    comparison = compare_with_rig(case, gear_model)
    if result_payload(comparison, plot, as_json, _save) is None:  # printed as JSON
        return
    console.print(f"{comparison.case_name} ({comparison.model} model) beside Luo & Li (2020) Table 3 / Fig. 18")
    console.print(comparison.markdown())
    for note in comparison.notes:
        console.print(f"• {note}")
    if plot is not None:
        console.print(f"figure written to {plot}")


def _save(figure, path: Path) -> None:
    import matplotlib.pyplot as plt

    if path.suffix.lower() not in (".png", ".svg", ".pdf"):
        raise CaseError("--plot", str(path), ".png, .svg or .pdf", "unknown figure format")
    path.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(path, dpi=130)
    plt.close(figure)
