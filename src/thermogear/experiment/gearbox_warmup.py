"""Warm-up predicted by the gearbox thermal model, coupled to the mesh: ``thermogear warmup CASE --model gearbox``.

The network of the case's ``[gearbox]`` (:mod:`thermogear.gearbox.model`) is integrated from a cold start (every
node at ``start_c``, default the ambient) over ``duration_s``; every ``interval_s`` the gear pair is re-evaluated
at the network's state: pinion and wheel bodies at their node temperatures (uniform over each gear), the oil
(viscosity, damping) at the oil node's, the housing (centre distance) at the housing node's. At each state: the
mean mesh stiffness, the natural frequency, the mesh frequency and, optionally, the periodic steady response (Kv).
Losses by source and the backlash come from the network at every output time.

Coupling is one-way and quasi-static: the losses follow the temperatures (viscosity), the mesh follows the
temperatures, but the mesh's dynamic response does not feed back into the losses (its Kv changes the tooth loads
by a few per cent), and the thermal time constants (minutes) are far longer than a mesh period (milliseconds).
The thermo-elastic mesh model (the default) evaluates gears colder than their assembly temperature (contraction,
E rising) down to the material data's limit; the paper's k_T (``thermal.model = 'luo2020'``) describes heating from
the stress-free state only. A state with a gear colder than its model evaluates
(:attr:`~thermogear.choices.thermal_models.ThermalModelRules.temperature_limits`) gets the network's backlash and
losses but no mesh evaluation (reported as such).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Callable

from thermogear.case.pieces import call_with_pieces
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.errors import CaseError
from thermogear.gearbox.backlash import ColdStart, cold_start_backlash
from thermogear.gearbox.case_model import (PredictedTemperatureError, gearbox_model_from_case, gearbox_operating_point,
                                           gearbox_section)
from thermogear.experiment.warmup import held_x_te
from thermogear.gearbox.description import OilConditioning
from thermogear.gearbox.losses import NODES
from thermogear.gearbox.model import COLDEST_START_C, GearboxThermalModel, WarmUpHistory
from thermogear.schema.temperature import TemperatureSection
from thermogear.temperature.limits import FLAG_MEANINGS, MATERIAL_MAXIMUM_C
from thermogear.choices.thermal_models import thermal_model_rules

#: Longest warm-up accepted [s] (a day: the network's slowest time constants are hours at most).
LONGEST_WARM_UP_S = 86400.0
#: Most mesh re-evaluations in one warm-up (each costs tens of ms with its periodic response).
MOST_STATES = 2000


@dataclass(frozen=True)
class MeshState:
    """The gear pair at one time of the warm-up: mean mesh stiffness [N/m] (total over the face width), natural
    and mesh frequency [Hz], Kv [–] (None without the dynamics), or why it was not evaluated."""

    time_s: float
    mesh_stiffness_mean: float | None
    natural_frequency_hz: float | None
    mesh_frequency_hz: float | None
    kv: float | None
    note: str = ""


@dataclass(frozen=True)
class GearboxWarmupResult:
    """A predicted warm-up: the network's history (temperatures, losses, backlash at every output time) and the
    mesh states every ``interval_s``, with the cold-start backlash at the start temperature."""

    case_name: str
    gear_model: str
    speed_rpm: float
    torque: float
    ambient_c: float
    start_c: float
    interval_s: float
    history: WarmUpHistory
    states: tuple[MeshState, ...]
    cold_start: ColdStart
    flags: tuple[tuple[str, ...], ...] = ()  # plausibility flags at every output time (temperature_limits)

    @property
    def flags_raised(self) -> dict[str, float]:
        """Each flag raised during the warm-up and the first time it was [s]."""
        first: dict[str, float] = {}
        for time, flags in zip(self.history.times, self.flags):
            for flag in flags:
                first.setdefault(flag, float(time))
        return first

    @property
    def smallest_backlash(self) -> tuple[float, float]:
        """(smallest normal backlash during the warm-up [m], its time [s])."""
        return self.history.smallest_backlash

    def as_dict(self) -> dict[str, Any]:
        """JSON view (temperatures °C, losses W, backlash μm, stiffness N/(mm·μm) per mm of face width)."""
        history = self.history
        smallest, at = self.smallest_backlash
        return {
            "case": self.case_name, "model": "gearbox", "gear_model": self.gear_model, "speed_rpm": self.speed_rpm,
            "torque_nm": self.torque, "ambient_c": self.ambient_c, "start_c": self.start_c,
            "interval_s": self.interval_s,
            "assumption": "temperatures predicted by the gearbox thermal network from a cold start; the mesh is "
                          "re-evaluated at the network's state every interval (gears uniform at their node "
                          "temperatures, oil and housing at theirs)",
            "energy_residual": history.energy_residual,
            "smallest_backlash_um": smallest * 1e6, "smallest_backlash_time_s": at,
            "flags_raised": {flag: {"first_time_s": time, "meaning": FLAG_MEANINGS[flag]}
                             for flag, time in self.flags_raised.items()},
            "cold_start": {"soak_c": self.cold_start.soak_c, "backlash_um": self.cold_start.backlash * 1e6,
                           "nominal_um": self.cold_start.nominal * 1e6,
                           "margin_to_jamming_um": self.cold_start.margin_to_jamming * 1e6,
                           "jammed": self.cold_start.jammed},
            "history": {"time_s": history.times.tolist(),
                        **{f"{name}_c": history.node(name).tolist()
                           for name in NODES},
                        "mesh_loss_w": history.mesh_loss.tolist(), "bearing_loss_w": history.bearing_loss.tolist(),
                        "seal_loss_w": history.seal_loss.tolist(), "churning_loss_w": history.churning_loss.tolist(),
                        "injection_loss_w": history.jet_loss.tolist(),
                        "conditioning_w": history.conditioning.tolist(),
                        "flags": [list(flags) for flags in self.flags],
                        "backlash_um": (history.backlash * 1e6).tolist()},
            "states": [{"time_s": state.time_s, "mesh_stiffness_mean_n_per_m": state.mesh_stiffness_mean,
                        "natural_frequency_hz": state.natural_frequency_hz,
                        "mesh_frequency_hz": state.mesh_frequency_hz, "kv": state.kv, "note": state.note}
                       for state in self.states],
        }

    def plot(self):
        from thermogear.experiment.gearbox_warmup_plots import plot_gearbox_warmup  # noqa: PLC0415

        return plot_gearbox_warmup(self)


def state_case(case, temperatures_c):
    """The case at one state of the network: pinion and wheel uniform at their node temperatures (a flat flank
    table over the path, wheel offset), oil and housing at theirs. Built without re-reading the case file: the
    sections are validated one by one.

    A resolver: it writes a new case from the case's own sections, so it takes the whole case."""
    pinion, wheel, oil, housing = (round(float(temperatures_c[NODES.index(name)]), 6)
                                   for name in ("pinion", "wheel", "oil", "housing"))
    pair = case.gear_pair
    points = pair.path_points
    # a flat table a unit of Γ beyond both ends of the path (degree 0: the same value wherever it is read)
    span = [float(pair.gamma(points["A"])) - 1.0, float(pair.gamma(points["E"])) + 1.0]
    temperature = TemperatureSection(model="tabulated", reference_c=case.temperature.reference_c, gamma=span,
                                     flank_c=[pinion, pinion], fit_degree=0, pinion_base_c=pinion,
                                     pinion_bore_c=pinion, wheel_base_c=wheel, wheel_bore_c=wheel,
                                     wheel_flank_offset_c=round(wheel - pinion, 6))
    housing_update: dict[str, Any] = {"temperature_c": housing}
    if "material" not in case.housing.model_fields_set:
        housing_update["material"] = gearbox_section(case.gearbox).housing.material
    changes: dict[str, Any] = dict(
        temperature=temperature, lubricant=case.lubricant.model_copy(update={"operating_temperature_c": oil}),
        housing=case.housing.model_copy(update=housing_update))
    if held := call_with_pieces(held_x_te, case):  # its calibrated X_te, held as the measured warm-up holds it
        changes["thermal"] = case.thermal.model_copy(update=held)
    return replace(case, **changes)


def _periodic_kv(sim, previous: tuple[float, float] | None) -> tuple[float, tuple[float, float] | None]:
    """Kv of the periodic steady response at one state, and the orbit's state at τ = 0 for the next one.

    Nonlinear mesh: the shooting starts from the previous state's orbit (the first state: from the linear solution,
    as ``Simulation.solve``): the temperatures drift slowly, so the gears stay on the orbit they were on, which is
    the one Newton finds from its neighbour (a continuation in time). The coexistence check of ``solve`` (a second
    search from rest) is not run: it only labels the branch, which the warm-up does not report. Linear mesh: the
    periodic solution is unique; ``solve`` as it is."""
    dynamics = sim.case.dynamics
    if not mesh_law(dynamics.mesh).backlash:
        return float(sim.solve(method="periodic").metrics["kv"]), None
    from thermogear.dynamics.backlash.backlash_metrics import orbit_metrics  # noqa: PLC0415
    from thermogear.dynamics.backlash.backlash_periodic import periodic_response  # noqa: PLC0415

    orbit = periodic_response(sim.state.backlash_problem(dynamics.damping_in_flight), initial_state=previous,
                              samples_per_interval=dynamics.samples_per_interval)
    kv = float(orbit_metrics(orbit, include_damping_force=dynamics.include_damping_force)["kv"])
    return kv, (orbit.initial_state if orbit.converged else None)


def warmup_state_count(duration_s: float, interval_s: float) -> int:
    """The mesh re-evaluations after the start of a warm-up of ``duration_s`` [s] every ``interval_s`` [s], or a
    CaseError naming the input that does not give evenly spaced times ending at the duration."""
    if not (math.isfinite(duration_s) and 0.0 < duration_s <= LONGEST_WARM_UP_S):
        raise CaseError("--duration-s", duration_s, f"(0, {LONGEST_WARM_UP_S:g}] s", "the warm-up's duration")
    if not (math.isfinite(interval_s) and 0.0 < interval_s <= duration_s):
        raise CaseError("--interval-s", interval_s, f"(0, duration = {duration_s:g}] s",
                        "the time between mesh re-evaluations")
    count = int(round(duration_s / interval_s))
    if count + 1 > MOST_STATES or abs(count * interval_s - duration_s) > 1e-9 * duration_s:
        raise CaseError("--interval-s", interval_s, f"a divisor of the duration giving at most {MOST_STATES} states",
                        "the mesh is re-evaluated at evenly spaced times that end at the duration")
    return count


def gearbox_warmup(case, duration_s: float = 1200.0, start_c: float | None = None, interval_s: float = 10.0,
                   gear_model: str = "thermal", dynamics: bool = True, speed_rpm: float | None = None,
                   points_per_interval: int = 1, simulation: Callable | None = None,
                   warm_start: bool = True, torque: float | None = None,
                   conditioning: OilConditioning | None = None) -> GearboxWarmupResult:
    """Predict a warm-up (module docstring). ``start_c``: every node's start temperature [°C] (default the
    ambient, down to −40 °C); ``interval_s``: time between mesh re-evaluations [s]; ``points_per_interval``:
    network output times per interval (losses and backlash are reported at each); ``warm_start``: each state's
    periodic solve starts from the previous state's orbit (:func:`_periodic_kv`), else every state is solved
    afresh with ``Simulation.run`` (its checks and the coexistence search included: the reference); ``torque``:
    the pinion torque [N·m] (default the case's); ``conditioning``: a rig's oil conditioning (heater, cooler,
    thermostat) instead of the case's ``[gearbox.conditioning]``."""
    if simulation is None:
        from thermogear.simulation import Simulation as simulation  # noqa: PLC0415
    count = warmup_state_count(duration_s, interval_s)
    operating = gearbox_operating_point(case.operating_point, case.gearbox, speed_rpm, torque)
    start = operating.ambient_c if start_c is None else float(start_c)
    if not (math.isfinite(start) and COLDEST_START_C <= start <= 150.0):
        # the start is the ambient unless --start-c gives it: name the input the user actually set (issue 36)
        key, what = (("--start-c", "the start temperature of every node") if start_c is not None else
                     ("gearbox.ambient_c", "the ambient is every node's start temperature unless --start-c gives one"))
        raise CaseError(key, start, f"[{COLDEST_START_C:g}, 150] °C", what)
    model = gearbox_model_from_case(case)
    if conditioning is not None:
        model = GearboxThermalModel(replace(model.description, conditioning=conditioning))
    history = model.warm_up(operating, duration_s, points=count * int(points_per_interval) + 1, initial_c=start)
    description = model.description
    cold = cold_start_backlash(description.gear_pair, model.allowance, description.gear_expansion,
                               description.housing.expansion, start, description.assembly_c)
    states = []
    limits = thermal_model_rules(case.thermal.model).temperature_limits
    reference = case.temperature.reference_c
    floor = reference if limits.lowest_c is None else limits.lowest_c
    changes = {} if speed_rpm is None else {"operating.speed_rpm": operating.speed_rpm}
    if torque is not None:
        changes.update({"operating.torque_nm": operating.torque, "operating.fzg_load_stage": None,
                        "operating.power_kw": None})
    try:
        base = case.with_changes(**changes) if changes else case
    except PredictedTemperatureError:  # its own steady state is above the material data: the warm-up sets every
        base = case.with_changes(predict_temperatures=False, **changes)  # state's temperatures itself (state_case)
    orbit_start = None  # the previous state's orbit: where the next state's periodic solve starts
    for index in range(0, history.times.size, int(points_per_interval)):
        time, temperatures = float(history.times[index]), history.temperatures_c[:, index]
        if max(temperatures[0], temperatures[1], temperatures[3], temperatures[4]) > MATERIAL_MAXIMUM_C:
            states.append(MeshState(time, None, None, None, None, f"above the {MATERIAL_MAXIMUM_C:g} °C the material "
                                                                 "data cover: mesh not evaluated"))
            continue
        if min(temperatures[0], temperatures[1]) < floor:
            below = (f"the stress-free reference {reference:g} °C" if limits.lowest_c is None else f"{floor:g} °C")
            states.append(MeshState(time, None, None, None, None, f"gears below {below}, the coldest "
                                                                 f"{limits.model} evaluates: mesh not evaluated"))
            continue
        sim = simulation(state_case(base, temperatures), gear_model)
        kv = None
        if dynamics and warm_start:
            kv, orbit_start = _periodic_kv(sim, orbit_start)
        elif dynamics:
            kv = float(sim.run(method="periodic").metrics["kv"])
        states.append(MeshState(time, float(sim.mesh_stiffness_mean), float(sim.natural_frequency_hz),
                                float(sim.mesh_frequency_hz), kv))
    flags = tuple(model.flags(history.temperatures_c[:, index]) for index in range(history.times.size))
    return GearboxWarmupResult(case.name, gear_model, operating.speed_rpm, operating.torque, operating.ambient_c,
                               start, float(interval_s), history, tuple(states), cold, flags)

