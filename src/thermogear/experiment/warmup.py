"""Warm-up of a test rig: a sequence of operating states in time, each a steady thermal state of the gear pair.

A warm-up is a temperature history T(t) — measured (a CSV file), the paper's Table 3 (``luo2019:RPM``), or the
first-order model T(t) = T_end − (T_end − T_start)·exp(−t/τ) with a stated time constant τ. Each time becomes one
operating state of the case with

* a **uniform** gear bulk temperature ``temperature.bulk_c = T`` (``temperature.model = "uniform"``), and
* the oil at the same temperature, ``lubricant.operating_temperature_c = T``

(assumption: the rig's measured temperature stands for both the gear bodies and the oil; heat flow inside the
teeth is not resolved). For each state the simulation gives the mean mesh stiffness, the mean mesh damping, the
natural frequency √(k̄/me)/2π and, optionally, the periodic steady dynamic response (Kv, DTE).
The warm-up is quasi-static: the states are independent steady states, with no thermal transient inside a
mesh period (the thermal time constants are minutes, the mesh period milliseconds).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable

import numpy as np

from thermogear.errors import CaseError
from thermogear.schema.temperature import CASE_MAXIMUM_C, CASE_MINIMUM_C
from thermogear.choices.thermal_models import thermal_model_rules, x_te_source

if TYPE_CHECKING:
    from thermogear.schema.thermal import ThermalSection

TIME_COLUMNS = {"time_s": 1.0, "time": 1.0, "t_s": 1.0, "time_min": 60.0, "minute": 60.0, "minutes": 60.0}
TEMPERATURE_COLUMNS = ("temperature_c", "temperature", "temp_c")


@dataclass(frozen=True)
class TemperatureHistory:
    """Temperature [°C] at times [s] of a warm-up, and where it comes from."""

    time_s: np.ndarray
    temperature_c: np.ndarray
    source: str

    def __post_init__(self) -> None:
        time = np.asarray(self.time_s, dtype=float)
        temperature = np.asarray(self.temperature_c, dtype=float)
        if time.ndim != 1 or time.shape != temperature.shape or time.size == 0:
            raise CaseError("temperature_history", self.source, "equal-length, non-empty time and temperature",
                            f"got {time.size} times and {temperature.size} temperatures")
        if not (np.all(np.isfinite(time)) and np.all(np.isfinite(temperature))):
            raise CaseError("temperature_history", self.source, "finite numbers", "NaN or infinite values")
        if np.any(np.diff(time) <= 0):
            raise CaseError("temperature_history", self.source, "strictly rising times",
                            "times must be sorted without duplicates")
        if np.any(temperature < -50) or np.any(temperature > 300):
            raise CaseError("temperature_history", self.source, "−50 … 300 °C", "outside any gear test")
        object.__setattr__(self, "time_s", time)
        object.__setattr__(self, "temperature_c", temperature)


def first_order_warmup(time_s: np.ndarray, start_c: float, final_c: float, time_constant_s: float) -> np.ndarray:
    """First-order warm-up T(t) = T_end − (T_end − T_start)·exp(−t/τ) [°C] at times t [s] (τ > 0 [s])."""
    if not (math.isfinite(time_constant_s) and time_constant_s > 0):
        raise CaseError("time_constant_s", time_constant_s, "> 0", "a first-order warm-up needs a positive τ")
    time = np.asarray(time_s, dtype=float)
    return final_c - (final_c - start_c) * np.exp(-time / time_constant_s)


def first_order_history(start_c: float, final_c: float, time_constant_s: float, duration_s: float,
                        states: int) -> TemperatureHistory:
    """``states`` equally spaced times over [0, duration] [s] of the first-order warm-up."""
    if not (math.isfinite(duration_s) and duration_s > 0):
        raise CaseError("duration_s", duration_s, "> 0", "the warm-up needs a positive duration")
    if states < 1:
        raise CaseError("states", states, "≥ 1", "at least one operating state")
    time = np.linspace(0.0, duration_s, states)
    return TemperatureHistory(time, first_order_warmup(time, start_c, final_c, time_constant_s),
                              f"first-order warm-up {start_c} → {final_c} °C, τ = {time_constant_s} s")


def read_temperature_history(path: str | Path) -> TemperatureHistory:
    """Temperature history from a CSV file with a header: a time column (``time_s`` or ``time_min``/``minute``)
    and a temperature column (``temperature_c``); or ``luo2019:RPM`` for the paper's Table 3 run at RPM."""
    from thermogear.text_files import is_existing_file, read_user_text  # noqa: PLC0415

    text = str(path)
    if text.startswith("luo2019:"):
        return table3_history(history_speed_rpm(text))
    path = Path(path)
    if not is_existing_file(path):
        raise CaseError("temperature_history", text, "a CSV file or luo2019:RPM", "no such file")
    content = read_user_text(path, "temperature_history", text, "CSV").removeprefix("\ufeff")
    rows = list(csv.reader(line for line in content.splitlines() if line.strip()))
    if len(rows) < 2:
        raise CaseError("temperature_history", text, "a header and at least one row", "the file is empty")
    header = [name.strip().lower() for name in rows[0]]
    time_name = next((name for name in header if name in TIME_COLUMNS), None)
    temperature_name = next((name for name in header if name in TEMPERATURE_COLUMNS), None)
    if time_name is None or temperature_name is None:
        raise CaseError("temperature_history", text, "columns time_s|time_min and temperature_c",
                        f"the first line names no such columns ({len(rows[0])} columns; the file's content is not "
                        "shown)")
    try:
        table = np.array([[float(row[header.index(time_name)]), float(row[header.index(temperature_name)])]
                          for row in rows[1:]])
    except (ValueError, IndexError):
        raise CaseError("temperature_history", text, "numbers in every row",
                        "a row has no number in the time or temperature column") from None
    if not np.all(np.isfinite(table)):
        raise CaseError("temperature_history", text, "finite numbers", "a time or temperature is NaN or infinite")
    low, high = CASE_TEMPERATURE_RANGE_C
    if np.any(table[:, 1] < low) or np.any(table[:, 1] > high):
        raise CaseError("temperature_history", text, f"temperatures from {low:g} to {high:g} °C",
                        f"a temperature of {float(table[:, 1].min()):g} … {float(table[:, 1].max()):g} °C is outside "
                        "what a case temperature may be")
    return TemperatureHistory(table[:, 0] * TIME_COLUMNS[time_name], table[:, 1], str(path))


#: Temperatures a history may hold [°C]: those of a case.
CASE_TEMPERATURE_RANGE_C = (CASE_MINIMUM_C, CASE_MAXIMUM_C)


def history_speed_rpm(text: str) -> float:
    """The RPM of ``luo2019:RPM`` [rpm]; CaseError naming --temperature-history when it is not a number."""
    value = text.split(":", 1)[1]
    try:
        speed = float(value)
    except ValueError:
        speed = math.nan
    if not (math.isfinite(speed) and speed > 0.0):
        raise CaseError("--temperature-history", text, "luo2019:RPM with RPM a positive number (a speed of the "
                        "paper's rig run)", "the speed after 'luo2019:' is not a positive number")
    return speed


def table3_history(speed_rpm: float) -> TemperatureHistory:
    """The temperatures of Luo & Li (2020) Table 3 at the 3rd/5th/10th minute of the run at ``speed_rpm``."""
    from thermogear.luo2020.rig.data import measurements_at, rig_speeds_rpm

    rows = measurements_at(speed_rpm)
    if not rows:
        raise CaseError("temperature_history", f"luo2019:{speed_rpm:g}", f"luo2019:RPM with RPM in "
                        f"{[f'{s:g}' for s in rig_speeds_rpm()]}", "the paper has no run at that speed")
    return TemperatureHistory(np.array([row.minute * 60.0 for row in rows]),
                              np.array([row.temperature_c for row in rows]),
                              f"Luo & Li (2020) Table 3, {speed_rpm:g} rpm")


@dataclass(frozen=True)
class OperatingState:
    """One state of the warm-up: time [s], temperature [°C], mean mesh stiffness [N/m] and damping [N·s/m]
    (totals over the face width), natural and mesh frequency [Hz], and the steady response metrics (or None)."""

    time_s: float
    temperature_c: float
    mesh_stiffness_mean: float
    mesh_damping_mean: float
    natural_frequency_hz: float
    mesh_frequency_hz: float
    response: dict[str, Any] | None = None

    def as_dict(self, face_width: float) -> dict[str, Any]:
        """JSON view, with per-unit-width stiffness [N/(mm·μm)] and damping [N·s/m per mm] for display."""
        return {"time_s": self.time_s, "temperature_c": self.temperature_c,
                "mesh_stiffness_mean_n_per_m": self.mesh_stiffness_mean,
                "mesh_stiffness_mean_n_per_mm_um": self.mesh_stiffness_mean / (face_width * 1e3) / 1e6,
                "mesh_damping_mean_n_s_per_m": self.mesh_damping_mean,
                "natural_frequency_hz": self.natural_frequency_hz, "mesh_frequency_hz": self.mesh_frequency_hz,
                "response": self.response}


def _over_states(name: str, doc: str) -> property:
    """A property of a :class:`WarmupResult`: the ``name`` of each of its states, in time order, as an array."""
    return property(lambda result: np.array([getattr(state, name) for state in result.states]), doc=doc)


@dataclass(frozen=True)
class WarmupResult:
    """The operating states of a warm-up, in time order."""

    case_name: str
    model: str
    history_source: str
    speed_rpm: float
    face_width: float
    states: tuple[OperatingState, ...] = field(default=())

    time_s = _over_states("time_s", "Time of each state [s].")
    temperature_c = _over_states("temperature_c", "Temperature of each state [°C].")
    mesh_stiffness_mean = _over_states("mesh_stiffness_mean", "Mean mesh stiffness of each state [N/m].")
    natural_frequency_hz = _over_states("natural_frequency_hz", "Natural frequency of each state [Hz].")

    def as_dict(self) -> dict[str, Any]:
        return {"case": self.case_name, "model": self.model, "temperature_history": self.history_source,
                "speed_rpm": self.speed_rpm,
                "assumption": "uniform gear bulk temperature = oil temperature = the history's temperature",
                "states": [state.as_dict(self.face_width) for state in self.states]}

    def plot(self, ax=None):
        from thermogear.experiment.plots import plot_warmup

        return plot_warmup(self, ax=ax)


def held_x_te(thermal: "ThermalSection", paper_thermal_model_of: Callable[[], Any]) -> dict[str, Any]:
    """The ``[thermal]`` keys that hold a case's calibrated X_te through a warm-up (the pieces of the case it reads,
    :mod:`thermogear.case.pieces`): the paper's X_te is calibrated once, at the case's own temperatures, and held,
    since a state near the assembly temperature has no thermal interference to calibrate against. None (``{}``)
    where the case's thermal model reads no X_te or its X_te is not calibrated. Both warm-ups' states hold it so."""
    if not (thermal_model_rules(thermal.model).reads_x_te and x_te_source(thermal.x_te_source).calibrated):
        return {}
    return {"x_te": paper_thermal_model_of().resolve_x_te()[0], "x_te_source": "given",
            "calibration_drop_percent": None}


def state_case(case, temperature_c: float, speed_rpm: float | None = None):
    """The case at one warm-up state: uniform bulk and oil temperature ``temperature_c`` (and the speed), written
    through the case file's keys, so checked as a loaded case is, with its calibrated X_te held (:func:`held_x_te`).

    A resolver: it writes a new case from the case's own keys, so it takes the whole case."""
    from thermogear.case.pieces import call_with_pieces  # noqa: PLC0415

    # the whole [temperature] section is replaced: a uniform field takes no flank table, base or bore temperatures
    section = {"model": "uniform", "bulk_c": float(temperature_c), "reference_c": case.temperature.reference_c}
    changes: dict[str, Any] = {"temperature": section, "lubricant.operating_temperature_c": float(temperature_c)}
    changes.update({f"thermal.{key}": value for key, value in call_with_pieces(held_x_te, case).items()})
    if speed_rpm is not None:
        changes["operating.speed_rpm"] = float(speed_rpm)
    return case.with_changes(**changes)


def time_mean(values: np.ndarray, nodes: np.ndarray) -> float:
    """Time mean of a piecewise-constant quantity on the intervals between ``nodes`` [same unit]."""
    durations = np.diff(np.asarray(nodes, dtype=float))
    return float(np.sum(np.asarray(values, dtype=float) * durations) / np.sum(durations))


def warmup(case, history: TemperatureHistory, model: str = "thermal", speed_rpm: float | None = None,
           dynamics: bool = True, simulation: Callable | None = None) -> WarmupResult:
    """Run one simulation per state of ``history``.

    Parameters
    ----------
    case:
        The case (its temperature input is replaced by a uniform bulk temperature per state).
    model:
        "thermal" or "elastic" (the elastic model shows only the oil's effect on damping).
    speed_rpm:
        Pinion speed [rpm]; default the case's.
    dynamics:
        Also solve the periodic steady response of each state.
    simulation:
        Factory ``(case, model) -> Simulation`` (default :class:`thermogear.simulation.Simulation`).
    """
    if simulation is None:
        from thermogear.simulation import Simulation as simulation
    # the speed of every state, from the case's operating point unless given (read once, here)
    speed = case.operating_point.speed_rpm if speed_rpm is None else float(speed_rpm)
    states = []
    for time, temperature in zip(history.time_s, history.temperature_c):
        sim = simulation(state_case(case, temperature, speed_rpm), model)
        response = None
        if dynamics:
            metrics = sim.run(method="periodic").metrics
            response = {"kv": metrics["kv"], "dte_rms_m": metrics["dte_rms"],
                        "dte_peak_to_peak_m": metrics["dte_peak_to_peak"],
                        "max_system_load_ratio": metrics["max_system_load_ratio"], "valid": metrics["valid"]}
        states.append(OperatingState(float(time), float(temperature), sim.mesh_stiffness_mean,
                                     time_mean(sim.mesh_damping, sim.grid.nodes), sim.natural_frequency_hz,
                                     sim.mesh_frequency_hz, response))
    return WarmupResult(case.name, model, history.source, speed, case.gear_pair.face_width, tuple(states))
