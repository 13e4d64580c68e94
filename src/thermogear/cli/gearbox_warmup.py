"""`thermogear warmup CASE --model gearbox`: the warm-up predicted by the gearbox thermal model (table, JSON,
figure). Called by :mod:`thermogear.cli.warmup`; registers no command of its own."""

from __future__ import annotations

from pathlib import Path

from rich.table import Table

from thermogear.cli.app import console, print_json, result_payload


def run_gearbox_warmup(base, duration_s: float, start_c: float | None, interval_s: float, gear_model: str,
                       speed_rpm: float | None, dynamics: bool, as_json: bool, plot: Path | None, save,
                       torque: float | None = None, conditioning=None) -> None:
    """Predict the warm-up and print it (``save(figure, path)`` writes the figure); ``conditioning``: an
    :class:`~thermogear.gearbox.description.OilConditioning` of the rig (None: the case's)."""
    from thermogear.experiment.gearbox_warmup import gearbox_warmup  # noqa: PLC0415

    result = gearbox_warmup(base, duration_s=duration_s, start_c=start_c, interval_s=interval_s,
                            gear_model=gear_model, dynamics=dynamics, speed_rpm=speed_rpm, torque=torque,
                            conditioning=conditioning)
    payload = result_payload(result, plot, as_json, save)
    if payload is None:  # printed as JSON
        return
    history = result.history
    table = Table(title=f"predicted warm-up of {result.case_name} at {result.speed_rpm:g} rpm, {result.torque:g} N·m "
                        f"(gearbox model, {result.gear_model} mesh; start {result.start_c:g} °C, ambient "
                        f"{result.ambient_c:g} °C)")
    for name in ("t [s]", "pinion [°C]", "wheel [°C]", "oil [°C]", "housing [°C]", "mesh [W]", "bearings [W]",
                 "seals [W]", "churning/jet [W]", "j_bn [μm]", "k̄ [N/μm]", "f_n [Hz]", "Kv"):
        table.add_column(name, justify="right")
    rows = len(result.states)
    shown = sorted(set(range(0, rows, max(1, rows // 12))) | {rows - 1})
    per_state = max(1, (history.times.size - 1) // max(1, rows - 1))
    for index in shown:
        state, column = result.states[index], index * per_state
        table.add_row(f"{state.time_s:.0f}", *(f"{history.node(name)[column]:.1f}"
                                               for name in ("pinion", "wheel", "oil", "housing")),
                      f"{history.mesh_loss[column]:.1f}", f"{history.bearing_loss[column]:.1f}",
                      f"{history.seal_loss[column]:.1f}", f"{history.churning_loss[column] + history.jet_loss[column]:.1f}",
                      f"{history.backlash[column] * 1e6:.1f}",
                      "—" if state.mesh_stiffness_mean is None else f"{state.mesh_stiffness_mean * 1e-6:.1f}",
                      "—" if state.natural_frequency_hz is None else f"{state.natural_frequency_hz:.1f}",
                      "—" if state.kv is None else f"{state.kv:.4f}")
    console.print(table)
    smallest, at = result.smallest_backlash
    cold = result.cold_start
    console.print(f"smallest backlash during the warm-up: {smallest * 1e6:.1f} μm at {at:.0f} s "
                  f"({'JAMMED' if smallest <= 0 else 'margin to jamming ' + format(smallest * 1e6, '.1f') + ' μm'})")
    console.print(f"cold start at {cold.soak_c:g} °C (everything soaked): backlash {cold.backlash * 1e6:.1f} μm "
                  f"(nominal {cold.nominal * 1e6:.1f} μm at assembly), margin to jamming "
                  f"{cold.margin_to_jamming * 1e6:.1f} μm{' — JAMMED' if cold.jammed else ''}")
    console.print(f"energy balance of the integration: {history.energy_residual:.1e} (relative)")
    if history.conditioning_power is not None:
        console.print(f"oil conditioning: {history.conditioning[0]:.1f} W at the start, {history.conditioning[-1]:.1f} W "
                      "at the end (into the oil; negative: cooling)")
    for flag, first in payload["flags_raised"].items():
        console.print(f"flag {flag}: {first['meaning']}, from {first['first_time_s']:.0f} s", highlight=False)
    console.print(payload["assumption"])
    if plot is not None:
        console.print(f"figure written to {plot}")


def run_gearbox_stages(base, stages: str, duration_s: float, start_c: float | None, speed_rpm: float | None,
                       conditioning, as_json: bool) -> None:
    """Run FZG load stages ``FIRST:LAST`` one after another on the case's gearbox network
    (:func:`thermogear.gearbox.procedure.run_load_stages`) and print the end of each stage."""
    from thermogear.errors import CaseError  # noqa: PLC0415
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point  # noqa: PLC0415
    from thermogear.gearbox.losses import NODES  # noqa: PLC0415
    from thermogear.gearbox.procedure import FZG_START_C, fzg_load_stages, run_load_stages  # noqa: PLC0415
    from thermogear.temperature.limits import FLAG_MEANINGS  # noqa: PLC0415

    first, _, last = stages.partition(":")
    try:
        chosen = fzg_load_stages(int(first), int(last or first))
    except ValueError as error:
        raise CaseError("--stages", stages, "FIRST:LAST load stage numbers, e.g. 5:12", "the FZG load stages") from error
    operating = gearbox_operating_point(base.operating_point, base.gearbox, speed_rpm)
    start = FZG_START_C if start_c is None else float(start_c)
    results = run_load_stages(gearbox_model_from_case(base), operating.speed_rpm, chosen, operating.ambient_c,
                              duration_s, start, conditioning)
    if as_json:
        print_json({"case": base.name, "speed_rpm": operating.speed_rpm, "duration_s": duration_s, "start_c": start,
                    "ambient_c": operating.ambient_c,
                    "stages": [{"stage": r.name, "torque_nm": r.torque,
                                **{f"{name}_c": r.node_c(name) for name in NODES}, "total_loss_w": r.total_loss,
                                "conditioning_w": r.conditioning, "flags": list(r.flags),
                                "energy_residual": r.energy_residual} for r in results]})
        return
    table = Table(title=f"load stages of {base.name} at {operating.speed_rpm:g} rpm: each {duration_s:g} s from "
                        f"{start:g} °C (every node), ambient {operating.ambient_c:g} °C — temperatures at the end")
    for name in ("stage", "T [N·m]", "pinion [°C]", "wheel [°C]", "oil [°C]", "housing [°C]", "losses [W]",
                 "conditioning [W]", "flags"):
        table.add_column(name, justify="right")
    for r in results:
        table.add_row(r.name, f"{r.torque:g}", f"{r.pinion_c:.1f}", f"{r.node_c('wheel'):.1f}", f"{r.oil_c:.1f}",
                      f"{r.node_c('housing'):.1f}", f"{r.total_loss:.1f}", f"{r.conditioning:.1f}", ", ".join(r.flags))
    console.print(table)
    for flag, meaning in FLAG_MEANINGS.items():
        if any(flag in r.flags for r in results):
            console.print(f"{flag}: {meaning}", highlight=False)
