"""Dynamic response of the mesh over one period: loads, metrics (Kv, Eq. 29), spectra, plots, netCDF.

Definitions (Luo & Li 2020 Sect. 4, Eqs. 5 and 29):

* dynamic transmission error (DTE): x(τ) [m];
* static transmission error / equilibrium on an interval: w/k [m]; per region (single, double, … contact) the
  time-mean of w/k over the intervals of that region;
* amplitude per region: the largest x in the region minus the region's equilibrium (the paper's "peak minus
  equilibrium") [m]; ``deviation_per_region`` gives max |x − equilibrium| as well;
* dynamic load (the paper's definition): system k(τ)·x(τ), pair p: k_p(τ)·x(τ) (k_p·(x − e_p) where the pairs
  have unloaded deviations e_p); with
  ``include_damping_force`` the damping force c·ẋ (c_p·ẋ) is added;
* Kv = 1 + Δw/w0, Δw = max single-pair dynamic load − w0, w0 = static load w (Eq. 29), so Kv = max pair load/w0;
* max system load ratio = max system dynamic load / w0;
* contact loss: the mesh force k·x (+ c·ẋ) < 0 somewhere; the tooth cannot pull, the linear model no longer
  holds and the response is marked invalid (``valid`` False, a :class:`ModelAssumptionWarning`).

Maxima include both one-sided limits at the nodes, where k and c jump while x and ẋ are continuous.
"""

from __future__ import annotations

import json
import os
import tempfile
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from thermogear.dynamics.periodic_orbits.periodic import PeriodicOrbit, evaluate_orbit, floquet_multipliers
from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.dynamics.results.metrics import sampled_load, compute_metrics
from thermogear.dynamics.results.spectra import (harmonic_spectrum, one_sided_amplitudes, right_continuous,
                                         uniform_period_grid)
from thermogear.dynamics.transients.transient import TransientHistory
from thermogear.errors import ModelAssumptionWarning, ProblemError
from thermogear.serialization import json_ready

__all__ = ["DynamicResponse", "compute_metrics", "response_from_orbit", "response_from_transient"]

_QUANTITIES = ("displacement", "velocity", "system_load", "pair_load")


def _at_samples(name: str, doc: str) -> property:
    """A property of a :class:`DynamicResponse`: its problem's per-interval ``name`` at each sample."""
    return property(lambda response: getattr(response.problem, name)[response.interval], doc=doc)


@dataclass(frozen=True)
class DynamicResponse:
    """Steady dynamic response over one mesh period, its metrics, and optionally the whole transient.

    ``time`` [s] from 0 to T, ``displacement`` x [m], ``velocity`` ẋ [m/s], ``interval`` the interval of each
    sample. ``history`` is the full transient when the response was built from one (plots show the start-up).
    ``valid`` is False when the linear model does not hold (contact loss or instability); ``warnings`` says why.
    """

    problem: MeshDynamicsProblem
    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    method: str
    include_damping_force: bool
    metrics: dict[str, Any]
    interval: np.ndarray
    multipliers: np.ndarray
    history: TransientHistory | None = None
    initial_state: tuple[float, float] | None = None
    label: str = ""
    warnings: tuple[str, ...] = field(default=())
    flags: tuple[str, ...] = field(default=())  # checks of the model that produced it, in words

    # ------------------------------------------------------------------ basic views
    @property
    def valid(self) -> bool:
        """True when the linear model holds: stable and no contact loss."""
        return bool(self.metrics["valid"])

    # the problem's per-interval coefficients at each sample (right-continuous at nodes)
    stiffness = _at_samples("stiffness", "k at each sample [N/m] (right-continuous at nodes).")
    damping = _at_samples("damping", "c at each sample [N·s/m].")
    contact_count = _at_samples("contact_count", "Pairs in contact at each sample.")
    static_transmission_error = _at_samples("static_transmission_error", "w/k at each sample [m] (the equilibrium "
                                            "the response oscillates about).")

    @property
    def _system_offset(self) -> np.ndarray | None:
        return None if self.problem.pair_offset is None else self.problem.system_offset

    def system_load(self) -> np.ndarray:
        """System dynamic load k·x (+ c·ẋ) at each sample [N] (right-continuous at nodes)."""
        return sampled_load(self.problem.stiffness, self.problem.damping, self._system_offset, self.interval,
                            self.displacement, self.velocity, self.include_damping_force)

    def pair_loads(self) -> np.ndarray:
        """(slots, samples) pair dynamic loads k_p·x (+ c_p·ẋ) [N]; needs ``pair_stiffness`` in the problem."""
        pair = self.problem.pair_arrays()
        if pair is None:
            raise ProblemError("pair_stiffness", None, "a (slots, n) array",
                               "pair loads need the stiffness of each pair")
        return sampled_load(pair[0], pair[1], self.problem.pair_offset, self.interval, self.displacement,
                            self.velocity, self.include_damping_force)

    # ------------------------------------------------------------------ spectra
    def spectrum(self, quantity: str = "displacement", points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
        """Harmonic amplitude spectrum of the steady period: (frequencies [Hz] = j·f_m, amplitudes [SI]).

        ``quantity``: "displacement" [m], "velocity" [m/s], "system_load" [N] or "pair_load" [N] (2-D: slots).
        The periodic orbit is evaluated exactly on a uniform grid (when the response holds its initial state);
        otherwise x and ẋ are interpolated. Loads use k of the interval each grid time falls in.
        """
        if quantity not in _QUANTITIES:
            raise ProblemError("quantity", quantity, str(_QUANTITIES), "signal whose spectrum is asked for")
        period = self.problem.period
        if quantity in ("displacement", "velocity") and self.initial_state is None:
            values = self.displacement if quantity == "displacement" else self.velocity
            return harmonic_spectrum(self.time, values, period, points)
        grid = uniform_period_grid(period, points)
        if self.initial_state is not None:
            x, v = evaluate_orbit(self.problem, self.initial_state, grid)
        else:
            x = np.interp(grid, *right_continuous(self.time, self.displacement))
            v = np.interp(grid, *right_continuous(self.time, self.velocity))
        interval = np.clip(np.searchsorted(self.problem.nodes, grid, side="right") - 1, 0,
                           self.problem.interval_count - 1)
        if quantity == "displacement":
            values = x
        elif quantity == "velocity":
            values = v
        elif quantity == "system_load":
            values = sampled_load(self.problem.stiffness, self.problem.damping, self._system_offset, interval, x, v,
                                  self.include_damping_force)
        else:
            pair = self.problem.pair_arrays()
            if pair is None:
                raise ProblemError("pair_stiffness", None, "a (slots, n) array", "pair loads need each pair's stiffness")
            values = sampled_load(pair[0], pair[1], self.problem.pair_offset, interval, x, v,
                                  self.include_damping_force)
        return np.arange(grid.size // 2 + 1) / period, one_sided_amplitudes(values)

    # ------------------------------------------------------------------ plots (Luo & Li Figs. 9–12)
    def plot_displacement(self, other: DynamicResponse | None = None, ax: Any = None, periods: int | None = None):
        """Fig. 9: transmission error x(τ) with the static levels; returns the figure."""
        from thermogear.dynamics.results.plots import plot_displacement

        return plot_displacement(self, other=other, ax=ax, periods=periods)

    def plot_phase(self, other: DynamicResponse | None = None, ax: Any = None, periods: int | None = None):
        """Fig. 10: phase portrait ẋ against x; returns the figure."""
        from thermogear.dynamics.results.plots import plot_phase

        return plot_phase(self, other=other, ax=ax, periods=periods)

    def plot_velocity(self, other: DynamicResponse | None = None, ax: Any = None, periods: int | None = None):
        """Fig. 11: velocity ẋ(τ); returns the figure."""
        from thermogear.dynamics.results.plots import plot_velocity

        return plot_velocity(self, other=other, ax=ax, periods=periods)

    def plot_loads(self, other: DynamicResponse | None = None, ax: Any = None, periods: int | None = None):
        """Fig. 12: pair and system dynamic loads per unit face width [N/mm]; returns the figure."""
        from thermogear.dynamics.results.plots import plot_loads

        return plot_loads(self, other=other, ax=ax, periods=periods)

    def plot_spectrum(self, quantity: str = "displacement", ax: Any = None, harmonics: int = 20):
        """Bar chart of the harmonic amplitudes of ``quantity``; returns the figure."""
        from thermogear.dynamics.results.plots import plot_spectrum

        return plot_spectrum(self, quantity=quantity, ax=ax, harmonics=harmonics)

    # ------------------------------------------------------------------ export
    def metrics_json(self) -> dict[str, Any]:
        """Metrics as plain JSON types, plus ``method``, ``label`` and ``warnings``."""
        summary = json_ready(self.metrics, non_finite="null")  # a number not given is null beside ``valid``
        summary["method"] = self.method
        summary["label"] = self.label
        summary["include_damping_force"] = self.include_damping_force
        summary["warnings"] = list(self.warnings)
        return summary

    def to_xarray(self):
        """xarray Dataset: the steady period, the problem's coefficients, the history (if any), metrics in attrs."""
        import xarray as xr

        data_vars, coords, attrs = self.dataset_parts()
        return xr.Dataset(data_vars=data_vars, coords=coords, attrs=attrs)

    def dataset_parts(self) -> tuple[dict, dict, dict]:
        """(data variables, coordinates, attributes) of :meth:`to_xarray`, as ``name → (dims, values, attrs)``
        (what the report's results file writes without building a Dataset)."""
        from thermogear import __version__

        problem = self.problem
        data_vars: dict[str, Any] = {
            "displacement": ("time", self.displacement, {"units": "m", "long_name": "dynamic transmission error"}),
            "velocity": ("time", self.velocity, {"units": "m/s"}),
            "system_load": ("time", self.system_load(), {"units": "N", "long_name": "system dynamic load"}),
            "static_transmission_error": ("time", self.static_transmission_error, {"units": "m"}),
            "mesh_stiffness": ("time", self.stiffness, {"units": "N/m"}),
            "mesh_damping": ("time", self.damping, {"units": "N s/m"}),
            "interval_index": ("time", self.interval.astype(np.int64)),
            "node_time": ("node", problem.nodes, {"units": "s"}),
            "interval_stiffness": ("interval", problem.stiffness, {"units": "N/m"}),
            "interval_damping": ("interval", problem.damping, {"units": "N s/m"}),
            "interval_force": ("interval", problem.force_per_interval, {"units": "N"}),
            "interval_contact_count": ("interval", problem.contact_count.astype(np.int64)),
        }
        if problem.pair_stiffness is not None:
            data_vars["pair_load"] = (("slot", "time"), self.pair_loads(), {"units": "N"})
            data_vars["interval_pair_stiffness"] = (("slot", "interval"), problem.pair_stiffness, {"units": "N/m"})
        if self.history is not None:
            data_vars["history_displacement"] = ("history_time", self.history.displacement, {"units": "m"})
            data_vars["history_velocity"] = ("history_time", self.history.velocity, {"units": "m/s"})
        coords: dict[str, Any] = {"time": ("time", self.time, {"units": "s"})}
        if self.history is not None:
            coords["history_time"] = ("history_time", self.history.time, {"units": "s"})
        attrs: dict[str, Any] = {
            "title": "thermogear mesh dynamic response",
            "thermogear_version": __version__,
            "method": self.method,
            "label": self.label,
            "include_damping_force": int(self.include_damping_force),
            "valid": int(self.valid),
            "mass_kg": problem.mesh_mass,
            "face_width_m": problem.face_width,
            "metrics_json": json.dumps(self.metrics_json()),
        }
        for key, value in self.metrics.items():
            if isinstance(value, float):
                attrs[key] = value
        return data_vars, coords, attrs

    def save(self, path: str | os.PathLike) -> Path:
        """Write :meth:`to_xarray` to netCDF (h5netcdf), atomically: a temporary file, then ``os.replace``."""
        target = Path(path)
        target.parent.mkdir(parents=True, exist_ok=True)
        dataset = self.to_xarray()
        handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
        os.close(handle)
        try:
            dataset.to_netcdf(temporary, engine="h5netcdf")
            os.replace(temporary, target)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
        return target


def _warn(problem: MeshDynamicsProblem, metrics: dict[str, Any]) -> tuple[str, ...]:
    messages = []
    if not metrics["stable"]:
        messages.append(f"parametric instability: Floquet multiplier moduli {metrics['floquet_multipliers_abs']} "
                        "(one is >= 1); the response grows and has no steady state")
    loss = metrics["contact_loss"]
    if loss["detected"]:
        starts = ", ".join(f"{t * 1e6:.2f} μs" for t in loss["start_times"][:5])
        lengths = ", ".join(f"{d * 1e6:.2f} μs" for d in loss["durations"][:5])
        messages.append(f"contact loss: the mesh force turns negative (minimum {loss['min_force']:.4g} N, "
                        f"{loss['min_force_ratio']:.3g} × the static load) starting at τ = {starts} for {lengths} "
                        f"(in all {loss['total_duration'] / problem.period:.1%} of the mesh period); the teeth would "
                        "separate, so the linear model and its loads do not hold there")
    for message in messages:
        warnings.warn(message, ModelAssumptionWarning, stacklevel=3)
    return tuple(messages)


def response_from_orbit(problem: MeshDynamicsProblem, orbit: PeriodicOrbit, include_damping_force: bool = False,
                        label: str = "") -> DynamicResponse:
    """Response of the exact periodic steady state (from :func:`periodic_steady_state`)."""
    metrics = compute_metrics(problem, orbit.time, orbit.displacement, orbit.velocity, orbit.interval,
                              orbit.multipliers, include_damping_force)
    return DynamicResponse(problem=problem, time=orbit.time, displacement=orbit.displacement,
                           velocity=orbit.velocity, method=orbit.method,
                           include_damping_force=bool(include_damping_force), metrics=metrics,
                           interval=orbit.interval, multipliers=orbit.multipliers, history=None,
                           initial_state=orbit.initial_state, label=label, warnings=_warn(problem, metrics))


def response_from_transient(problem: MeshDynamicsProblem, history: TransientHistory,
                            include_damping_force: bool = False, label: str = "") -> DynamicResponse:
    """Response whose steady state is the last period of a transient; the whole history is kept for plots.

    The Floquet multipliers are computed from the problem (cheap) so that an unstable point is flagged; the
    convergence of the last period is in ``metrics["transient_last_period_change"]`` (relative change of the
    period-start displacement over the last period).
    """
    time, x, v, interval = history.last_period()
    multipliers = floquet_multipliers(problem)
    metrics = compute_metrics(problem, time, x, v, interval, multipliers, include_damping_force)
    metrics["transient_periods"] = history.periods
    metrics["transient_last_period_change"] = float(history.convergence()[-1])
    return DynamicResponse(problem=problem, time=time, displacement=x, velocity=v, method=history.method,
                           include_damping_force=bool(include_damping_force), metrics=metrics, interval=interval,
                           multipliers=multipliers, history=history, initial_state=None, label=label,
                           warnings=_warn(problem, metrics))
