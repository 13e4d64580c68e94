"""The steady response of the nonlinear (backlash) mesh model as the rest of thermogear reads a response.

:func:`nonlinear_response` solves a :class:`~thermogear.dynamics.problems.backlash_problem.BacklashMeshProblem` for its
steady response (:func:`~thermogear.dynamics.backlash.backlash_periodic.periodic_response`, started from the linear
periodic solution), checks for a second stable orbit started from rest (x = ẋ = 0, Luo & Li's start) and returns a
:class:`NonlinearResponse`: the orbit, its metrics under the names of the linear response (Kv of Luo & Li Eq. 29,
loads per width, equilibria and amplitudes per contact region, frequencies) plus what only the nonlinear model
knows — ``contact_loss_fraction``, ``back_side_contact``, ``response`` ("periodic" | "subharmonic" |
"non-periodic"), ``branch`` and whether more than one stable orbit coexists (two starts can show that there
are several, never how many: :func:`~thermogear.dynamics.backlash.backlash_orbits.stable_orbits` searches for them all).

Branch: where the two starts settle on different stable orbits, the one with the smaller DTE peak-to-peak is the
"low" branch and the other the "high" branch (the jump phenomenon of a backlash oscillator, Kahraman & Singh
1990); otherwise the branch is "unique".
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from operator import attrgetter
from typing import Any

import numpy as np

from thermogear.dynamics.backlash.backlash_metrics import dte_spectrum, history_forces, orbit_metrics
from thermogear.dynamics.backlash.backlash_periodic import (BacklashOrbit, backlash_flow, backlash_transient,
                                                   periodic_response)
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.dynamics.problems.problem import region_name
from thermogear.dynamics.results.plots import MODEL_STYLES
from thermogear.errors import ModelLimitError
from thermogear.serialization import json_ready

__all__ = ["NonlinearResponse", "NonlinearTransient", "nonlinear_response", "nonlinear_transient"]

#: Two stable orbits whose DTE peak-to-peak differ by more than this fraction are distinct branches [–].
DISTINCT_ORBITS = 1e-3


@dataclass(frozen=True, eq=False)
class NonlinearResponse:
    """Steady response of the backlash mesh model (time from 0 over the orbit's N mesh periods)."""

    problem: BacklashMeshProblem
    orbit: BacklashOrbit
    metrics: dict[str, Any]
    include_damping_force: bool = False
    label: str = ""
    method: str = "nonlinear periodic (shooting)"
    history: None = None  # a steady orbit, not a history from rest (plots repeat the orbit)
    warnings: tuple[str, ...] = field(default=())
    flags: tuple[str, ...] = field(default=())  # checks of the model that produced it, in words

    # ------------------------------------------------------------------ views of the orbit's record
    time = property(attrgetter("orbit.history.time"), doc="Time [s] from 0 over the orbit's N mesh periods.")
    displacement = property(attrgetter("orbit.history.displacement"), doc="Dynamic transmission error x [m].")
    velocity = property(attrgetter("orbit.history.velocity"), doc="Its rate ẋ [m/s].")
    interval = property(attrgetter("orbit.history.interval"), doc="The interval of the mesh period of each record.")

    @property
    def valid(self) -> bool:
        """The nonlinear model holds through contact loss; a response is valid where its orbit was found."""
        return bool(self.metrics["valid"])

    def system_load(self) -> np.ndarray:
        """Mesh force at each record [N] (driving flanks positive, back flanks negative)."""
        return history_forces(self.problem, self.orbit.history, self.include_damping_force)[0]

    def pair_loads(self) -> np.ndarray:
        """(slots, records) driving-flank pair forces [N]."""
        return history_forces(self.problem, self.orbit.history, self.include_damping_force)[1]

    def spectrum(self, quantity: str = "displacement", points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
        """One-sided harmonic amplitudes of the DTE over the orbit: (frequencies [Hz], amplitudes [m])."""
        return dte_spectrum(self.orbit, points)

    # ------------------------------------------------------------------ plots
    def _lines(self, values: np.ndarray, other: "NonlinearResponse | None", ax: Any, ylabel: str, scale: float,
               periods: int | None):
        import matplotlib.pyplot as plt  # noqa: PLC0415

        figure = ax.figure if ax is not None else plt.subplots(figsize=(8, 4), constrained_layout=True)[0]
        ax = ax if ax is not None else figure.axes[0]
        for number, (item, series) in enumerate(((self, values(self)),) + (((other, values(other)),) if other else ())):
            time, series = item._repeated(series, periods)
            ax.plot(time * 1e3, series * scale, lw=1.4, **MODEL_STYLES[number % 2],
                    label=f"{item.label or 'response'} ({item.metrics['response']}, {item.metrics['branch']} branch)")
        ax.set_xlabel("time [ms]")
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
        return figure

    def _repeated(self, values: np.ndarray, periods: int | None) -> tuple[np.ndarray, np.ndarray]:
        """The orbit's record repeated to cover at least ``periods`` mesh periods (its own N periods if None)."""
        span = float(self.time[-1])
        copies = 1 if periods is None else max(1, int(np.ceil(periods * self.problem.period / span - 1e-9)))
        body = slice(0, -1)
        time = np.concatenate([self.time[body] + q * span for q in range(copies)] + [[copies * span]])
        repeated = np.concatenate([np.tile(np.asarray(values)[body], copies), np.asarray(values)[-1:]])
        return time, repeated

    def plot_displacement(self, other=None, ax: Any = None, periods: int | None = None):
        """DTE x over the orbit [μm]."""
        return self._lines(lambda item: item.displacement, other, ax, "dynamic transmission error [μm]", 1e6, periods)

    def plot_velocity(self, other=None, ax: Any = None, periods: int | None = None):
        """Velocity ẋ along the line of action over the orbit [mm/s] (the unit of Luo & Li Fig. 11)."""
        return self._lines(lambda item: item.velocity, other, ax, "velocity ẋ [mm/s]", 1e3, periods)

    def plot_loads(self, other=None, ax: Any = None, periods: int | None = None):
        """Mesh force per face width [N/mm]; below zero the back flanks carry it, at zero the teeth fly."""
        scale = 1.0 / self.problem.face_width / 1e3
        return self._lines(lambda item: item.system_load(), other, ax, "mesh force per face width [N/mm]", scale,
                           periods)

    def plot_phase(self, other=None, ax: Any = None, periods: int | None = None):
        import matplotlib.pyplot as plt  # noqa: PLC0415

        figure = ax.figure if ax is not None else plt.subplots(figsize=(5, 4), constrained_layout=True)[0]
        ax = ax if ax is not None else figure.axes[0]
        for number, item in enumerate((self, other) if other is not None else (self,)):
            ax.plot(item.displacement * 1e6, item.velocity * 1e3, lw=1.2, label=item.label or "response",
                    **MODEL_STYLES[number % 2])
        ax.set_xlabel("x [μm]")
        ax.set_ylabel("ẋ [mm/s]")
        ax.legend(fontsize="small")
        return figure

    # ------------------------------------------------------------------ files
    def metrics_json(self) -> dict[str, Any]:
        """Metrics as plain JSON types; a number the model could not give (the multipliers of a non-periodic
        response) is null beside its ``response`` and ``valid`` (a report of such a point raised before)."""
        return json_ready(self.metrics, non_finite="null")

    def to_xarray(self):
        import xarray as xr  # noqa: PLC0415

        data_vars, coords, attrs = self.dataset_parts()
        return xr.Dataset(data_vars, coords=coords, attrs=attrs)

    def dataset_parts(self) -> tuple[dict, dict, dict]:
        """(data variables, coordinates, attributes) of :meth:`to_xarray` (``name → (dims, values, attrs)``)."""
        return ({"displacement": ("time", self.displacement, {"units": "m", "long_name": "dynamic transmission error"}),
                 "velocity": ("time", self.velocity, {"units": "m/s"}),
                 "system_load": ("time", self.system_load(), {"units": "N", "long_name": "mesh force"})},
                {"time": ("time", self.time, {"units": "s"})},
                {"model": self.label, "method": self.method, "metrics": json.dumps(self.metrics_json())})


def _region_levels(problem: BacklashMeshProblem, orbit: BacklashOrbit) -> tuple[dict, dict]:
    """Equilibria (static TE of the linear problem, time mean per contact region) and amplitudes (largest x in the
    region minus its equilibrium), as the linear metrics define them."""
    linear = problem.linear_problem()
    if linear is None:
        return {}, {}
    static = linear.static_transmission_error
    durations = linear.durations
    history = orbit.history
    equilibrium, amplitude = {}, {}
    for count in linear.regions:
        inside = linear.contact_count == count
        level = float(np.dot(static[inside], durations[inside]) / durations[inside].sum())
        mask = linear.contact_count[history.interval] == count
        name = region_name(count)
        equilibrium[name] = level
        amplitude[name] = float(np.max(history.displacement[mask]) - level) if np.any(mask) else float("nan")
    return equilibrium, amplitude


def _metrics(problem: BacklashMeshProblem, orbit: BacklashOrbit, include_damping_force: bool, branch: str,
             coexisting: bool) -> dict[str, Any]:
    values = orbit_metrics(orbit, include_damping_force=include_damping_force)
    w0, width = problem.static_load, problem.face_width
    equilibrium, amplitude = _region_levels(problem, orbit)
    natural = problem.natural_frequency
    converged = bool(orbit.converged)
    return {
        **values,
        "mesh": "nonlinear",
        "branch": branch,
        "coexisting_orbits": coexisting,
        "static_load": w0, "static_load_n_per_mm": w0 / width / 1e3,
        "max_pair_load": values["max_pair_force"], "max_pair_load_n_per_mm": values["max_pair_force"] / width / 1e3,
        "max_system_load": values["max_mesh_force"],
        "max_system_load_n_per_mm": values["max_mesh_force"] / width / 1e3,
        "max_system_load_ratio": values["max_mesh_force_ratio"],
        "max_velocity": float(np.max(np.abs(orbit.history.velocity))),
        "equilibrium_per_region": equilibrium, "amplitude_per_region": amplitude,
        "natural_frequency_hz": natural, "mesh_frequency_hz": 1.0 / problem.period,
        "frequency_ratio": problem.frequency_ratio,
        "floquet_multipliers_abs": sorted((float(abs(m)) for m in orbit.multipliers), reverse=True),
        "stable": bool(orbit.stable),
        "contact_loss": {"detected": values["contact_loss_fraction"] > 0.0,
                         "fraction": values["contact_loss_fraction"]},
        # a non-periodic response has no steady orbit: its metrics describe the recorded periods, never a valid
        # steady state (issue 25: it was reported "steady orbit found: yes" with NaN multipliers)
        "valid": converged and orbit.response != "non-periodic",
    }


def nonlinear_response(problem: BacklashMeshProblem, include_damping_force: bool = False, label: str = "",
                       samples_per_interval: int = 4, check_coexistence: bool = True) -> NonlinearResponse:
    """Steady response of the backlash model, its branch and whether a second stable orbit coexists (module
    docstring). Raises ModelLimitError where the response grows without bound."""
    orbit = periodic_response(problem, samples_per_interval=samples_per_interval)
    branch, coexisting = "unique", False
    if check_coexistence and orbit.stable:
        try:
            other = periodic_response(problem, initial_state=(0.0, 0.0), samples_per_interval=samples_per_interval)
        except ModelLimitError:
            other = None
        if other is not None and other.stable:
            own, theirs = np.ptp(orbit.history.displacement), np.ptp(other.history.displacement)
            if abs(own - theirs) > DISTINCT_ORBITS * max(own, theirs):
                coexisting = True
                branch = "low" if own < theirs else "high"
    metrics = _metrics(problem, orbit, include_damping_force, branch, coexisting)
    notes = ()
    if coexisting:
        notes = (f"at least two stable orbits coexist at this operating point (started from the linear solution and "
                 f"from rest, the motion settles on different ones): the {branch} branch is reported; `thermogear "
                 "sweep CASE --vary speed_rpm=N --multistart 64` lists every stable orbit a search of the state plane "
                 "finds, with its basin share",)
    return NonlinearResponse(problem=problem, orbit=orbit, metrics=metrics, include_damping_force=include_damping_force,
                             label=label, warnings=notes)


@dataclass(frozen=True, eq=False)
class NonlinearTransient:
    """Motion of the backlash mesh model from rest (x = ẋ = 0, as Luo & Li start it), integrated exactly with the
    same event-driven integrator as the periodic orbits: the start-up plots and a check of the periodic solver
    (the end of a long transient settles on the orbit the shooting finds)."""

    problem: BacklashMeshProblem
    history: Any  # BacklashHistory
    steady: NonlinearResponse  # the last mesh period, read as a steady response (:func:`nonlinear_transient`)
    label: str = ""
    method: str = "nonlinear transient from rest"
    flags: tuple[str, ...] = field(default=())  # checks of the model that produced it, in words

    # the last period's metrics, under the names of the steady response, and what they say
    metrics = property(attrgetter("steady.metrics"), doc="The metrics of the last mesh period.")
    warnings = property(attrgetter("steady.warnings"), doc="The last period's warnings, in words.")
    include_damping_force = property(attrgetter("steady.include_damping_force"),
                                     doc="Whether the pair loads include the damping force.")
    valid = property(attrgetter("steady.valid"),
                     doc="True when the motion from rest has settled on a one-period orbit by its last period.")

    def metrics_json(self) -> dict[str, Any]:
        return json_ready(self.metrics)

    # the steady-state views and plots are those of the last period (as the linear transient's)
    def system_load(self) -> np.ndarray:
        return self.steady.system_load()

    def pair_loads(self) -> np.ndarray:
        return self.steady.pair_loads()

    def spectrum(self, quantity: str = "displacement", points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
        return self.steady.spectrum(quantity, points)

    def plot_displacement(self, other=None, ax: Any = None, periods: int | None = None):
        return self.steady.plot_displacement(getattr(other, "steady", other), ax, periods)

    def plot_velocity(self, other=None, ax: Any = None, periods: int | None = None):
        return self.steady.plot_velocity(getattr(other, "steady", other), ax, periods)

    def plot_loads(self, other=None, ax: Any = None, periods: int | None = None):
        return self.steady.plot_loads(getattr(other, "steady", other), ax, periods)

    # the whole motion from rest
    time = property(attrgetter("history.time"), doc="Time [s] from rest.")
    displacement = property(attrgetter("history.displacement"), doc="Dynamic transmission error x [m].")
    velocity = property(attrgetter("history.velocity"), doc="Its rate ẋ [m/s].")


    def to_xarray(self):
        import xarray as xr  # noqa: PLC0415

        data_vars, coords, attrs = self.dataset_parts()
        return xr.Dataset(data_vars, coords=coords, attrs=attrs)

    def dataset_parts(self) -> tuple[dict, dict, dict]:
        """(data variables, coordinates, attributes) of :meth:`to_xarray` (``name → (dims, values, attrs)``)."""
        return ({"displacement": ("time", self.displacement, {"units": "m", "long_name": "dynamic transmission error"}),
                 "velocity": ("time", self.velocity, {"units": "m/s"})},
                {"time": ("time", self.time, {"units": "s"})},
                {"model": self.label, "method": self.method, "metrics": json.dumps(json_ready(self.metrics))})

    def plot_phase(self, other=None, ax: Any = None, periods: int | None = None):
        """x–ẋ trajectory from rest [μm, mm/s]."""
        import matplotlib.pyplot as plt  # noqa: PLC0415

        figure = ax.figure if ax is not None else plt.subplots(figsize=(5, 4), constrained_layout=True)[0]
        ax = ax if ax is not None else figure.axes[0]
        for number, item in enumerate((self, other) if other is not None else (self,)):
            ax.plot(item.displacement * 1e6, item.velocity * 1e3, lw=0.8, color=MODEL_STYLES[number % 2]["color"],
                    label=f"{item.label or 'response'} from rest")
        ax.set_xlabel("x [μm]")
        ax.set_ylabel("ẋ [mm/s]")
        ax.legend(fontsize="small")
        return figure


#: Scaled change of the state over the last mesh period below which a transient has settled [–] (x by the static
#: deflection, ẋ by it times ω_n: 1e-6 is far below anything a plot or a printed metric shows, and far above the
#: exact integrator's rounding).
SETTLED = 1e-6


def nonlinear_transient(problem: BacklashMeshProblem, periods: int, samples_per_interval: int = 4,
                        label: str = "", include_damping_force: bool = False) -> NonlinearTransient:
    """The backlash model from rest over ``periods`` mesh periods, with the metrics of its last mesh period under
    the names of the steady response (as the linear transient gives them), so that a transient is read like any
    other response. ``metrics["response"]`` is "periodic" when the state repeats over the last period to
    :data:`SETTLED` ("not settled" otherwise, and ``valid`` False); the Floquet multipliers are those of the last
    period's monodromy (the orbit's own once settled); ``transient_last_period_change`` is the scaled change."""
    history = backlash_transient(problem, periods, samples_per_interval)
    start = (0.0, 0.0)
    if periods > 1:
        start = tuple(float(a) for a in backlash_flow(problem, start, int(periods) - 1)[0])
    end, monodromy, _ = backlash_flow(problem, start, 1)
    change = float(np.hypot((end[0] - start[0]) / problem.displacement_scale,
                            (end[1] - start[1]) / problem.velocity_scale))
    multipliers = np.linalg.eigvals(monodromy)
    multipliers = multipliers[np.argsort(-np.abs(multipliers))]
    settled = bool(change <= SETTLED)
    last = BacklashOrbit(problem=problem, response="periodic" if settled else "not settled", period_count=1,
                         converged=settled, residual=change, multipliers=multipliers, initial_state=start,
                         history=backlash_transient(problem, 1, samples_per_interval, start), iterations=0)
    metrics = _metrics(problem, last, include_damping_force, "from rest", False)
    metrics.update(transient_periods=int(periods), transient_last_period_change=change, valid=settled,
                   max_velocity_from_rest=float(np.max(np.abs(history.velocity))))
    steady = NonlinearResponse(problem=problem, orbit=last, metrics=metrics, include_damping_force=include_damping_force,
                               label=label, method="nonlinear transient from rest (last period)")
    return NonlinearTransient(problem=problem, history=history, steady=steady, label=label)
