"""The gearbox thermal model: losses and conductances following the node temperatures, steady state and warm-up.

Nodes (:data:`~thermogear.gearbox.losses.NODES`): pinion, wheel, the pinion's and the wheel's shaft each with its
bearings, oil, housing; the ambient air is the boundary (:mod:`~thermogear.gearbox.network`). Losses
(:mod:`~thermogear.gearbox.losses`) follow the oil and shaft temperatures through the viscosity (tooth friction, bearings, churning); the housing's outer conductance follows
the housing and air temperatures (natural convection, radiation). :meth:`GearboxThermalModel.steady_state` gives
the predicted gear and oil temperatures of an operating point — the stable steady state, with its plausibility
flags (:mod:`thermogear.temperature.limits`), or :class:`ThermalRunawayError` where the stable branch followed in
torque ends below the torque asked for; :meth:`GearboxThermalModel.warm_up` the history of temperatures, losses
and backlash from a cold start (with a rig's oil conditioning where the description has one).
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.gearbox.backlash import backlash_allowance, backlash_at_temperatures
from thermogear.gearbox.description import GearboxDescription, GearboxOperatingPoint
from thermogear.gearbox.heat_paths import housing_outer_conductance, internal_conductances
from thermogear.gearbox.losses import (HOUSING, NODES, OIL, PINION, PINION_SHAFT, WHEEL, WHEEL_SHAFT, LossModel,
                                       PowerLosses, node_temperature)
from thermogear.gearbox.network import (NoSteadyStateError, ThermalNetwork, continue_steady_states,
                                        integrate_transient, solve_steady_state, stability_eigenvalues,
                                        steady_state_at)
from thermogear.temperature.limits import FLAG_MEANINGS, NETWORK_EVALUATION_RANGE_C, state_flags

#: Coldest start the model accepts [°C] (the brief's −40 °C; the oil's fit is extrapolated there, with a warning).
COLDEST_START_C = -40.0
#: The property laws are evaluated with temperatures clipped to this range [°C]; a steady state is a result only
#: inside it, HOTTEST_STEADY_C being its upper end less a margin (thermogear.temperature.limits).
EVALUATION_RANGE_C = NETWORK_EVALUATION_RANGE_C
HOTTEST_STEADY_C = NETWORK_EVALUATION_RANGE_C[1] - 10.0


class ThermalRunawayError(NoSteadyStateError):
    """No stable steady state at the operating point: the stable branch of steady states, followed in torque from
    zero, ends at a fold below the torque asked for (``fold_torque`` [N·m], ``fold_temperatures_c`` there)."""

    def __init__(self, message: str, fold_torque: float, fold_temperatures_c: np.ndarray, speed_rpm: float):
        super().__init__(message)
        self.fold_torque = fold_torque
        self.fold_temperatures_c = fold_temperatures_c
        self.speed_rpm = speed_rpm


def _oil_wetted_range(temperatures) -> tuple[float, float]:
    """(lowest, highest) temperature [°C] at which the oil's viscosity is evaluated: the two shafts' bearings and
    the sump (over time where ``temperatures`` is (nodes, m))."""
    values = np.asarray(temperatures, dtype=float)[[PINION_SHAFT, WHEEL_SHAFT, OIL]]
    return float(np.min(values)), float(np.max(values))


@dataclass(frozen=True)
class GearboxState:
    """Temperatures of the nodes [°C] at one instant with the losses and backlash there."""

    temperatures_c: np.ndarray  # by NODES: pinion, wheel, pinion shaft, wheel shaft, oil, housing
    losses: PowerLosses
    backlash: float  # normal backlash [m]

    pinion_c = node_temperature(PINION, "temperatures_c")
    wheel_c = node_temperature(WHEEL, "temperatures_c")
    pinion_shaft_c = node_temperature(PINION_SHAFT, "temperatures_c")
    wheel_shaft_c = node_temperature(WHEEL_SHAFT, "temperatures_c")
    oil_c = node_temperature(OIL, "temperatures_c")
    housing_c = node_temperature(HOUSING, "temperatures_c")


@dataclass(frozen=True)
class GearboxSteadyState(GearboxState):
    """A steady state: also the heat shed to the air [W], |ΣP − Q_out|/ΣP and the network's time constants [s]."""

    heat_out: float
    energy_residual: float
    time_constants: np.ndarray
    largest_eigenvalue: float = float("nan")  # largest real part of the stability eigenvalues [1/s] (< 0: stable)
    flags: tuple[str, ...] = ()  # plausibility flags (thermogear.temperature.limits.FLAG_MEANINGS)

    @property
    def energy_balance_w(self) -> float:
        """|ΣP − Q_out| [W]: the steady state's heat balance (the relative residual times the heat shed)."""
        return self.energy_residual * abs(self.heat_out)

    @property
    def flag_text(self) -> str:
        """The flags in words ('' when none)."""
        return "; ".join(FLAG_MEANINGS[flag] for flag in self.flags)

    def to_dataframe(self):
        """One row per node: its steady temperature [°C] (pandas); the losses and the heat out in ``attrs``."""
        import pandas as pd  # noqa: PLC0415

        frame = pd.DataFrame({"temperature_c": np.asarray(self.temperatures_c, dtype=float)},
                             index=pd.Index(NODES, name="node"))
        frame.attrs.update(heat_out_w=self.heat_out, total_loss_w=self.losses.total,
                           energy_residual=self.energy_residual, backlash_m=self.backlash)
        return frame

    def to_dataset(self):
        """xarray Dataset: the node temperatures [°C], the losses by source [W], the heat out, the backlash."""
        import xarray as xr  # noqa: PLC0415

        losses = self.losses
        return xr.Dataset(
            {"temperature": ("node", np.asarray(self.temperatures_c, dtype=float), {"units": "degC"}),
             "loss": ("source", [losses.mesh, losses.bearings, losses.seals, losses.churning, losses.injection],
                      {"units": "W"}),
             "heat_out": ((), self.heat_out, {"units": "W"}), "backlash": ((), self.backlash, {"units": "m"})},
            coords={"node": list(NODES), "source": ["mesh", "bearings", "seals", "churning", "injection"]},
            attrs={"energy_residual": self.energy_residual})


@dataclass(frozen=True)
class WarmUpHistory:
    """Temperatures (6, m) [°C] by :data:`NODES`, losses by source (m,) [W], backlash (m,) [m] against times (m,)
    [s]."""

    times: np.ndarray
    temperatures_c: np.ndarray
    mesh_loss: np.ndarray
    bearing_loss: np.ndarray
    seal_loss: np.ndarray
    churning_loss: np.ndarray
    backlash: np.ndarray
    energy_residual: float  # identity ∫ΣP dt = ΔΣCT + ∫Q_out dt, relative
    injection_loss: np.ndarray | None = None  # impulse loss of the oil jet [W] (None: no jet)
    conditioning_power: np.ndarray | None = None  # heat of the oil conditioning into the oil [W] (None: none)

    @property
    def conditioning(self) -> np.ndarray:
        """Heat of the rig's oil conditioning into the oil (m,) [W] (negative: cooling); zeros without one."""
        return np.zeros_like(self.mesh_loss) if self.conditioning_power is None else self.conditioning_power

    @property
    def jet_loss(self) -> np.ndarray:
        """The oil jet's impulse loss (m,) [W]: zeros without a jet."""
        return np.zeros_like(self.mesh_loss) if self.injection_loss is None else self.injection_loss

    @property
    def total_loss(self) -> np.ndarray:
        return self.mesh_loss + self.bearing_loss + self.seal_loss + self.churning_loss + self.jet_loss

    def node(self, name: str) -> np.ndarray:
        """Temperature history of one node [°C] (a name of :data:`NODES`)."""
        if name not in NODES:
            raise CaseError("node", name, f"one of {', '.join(NODES)}", "the nodes of the gearbox network")
        return self.temperatures_c[NODES.index(name)]

    @property
    def smallest_backlash(self) -> tuple[float, float]:
        """(smallest normal backlash [m], the time it occurs [s]); a value ≤ 0 means the gears jam."""
        index = int(np.argmin(self.backlash))
        return float(self.backlash[index]), float(self.times[index])

    def to_dataframe(self):
        """One row per time [s]: each node's temperature [°C], the losses by source [W] and the backlash [m]."""
        import pandas as pd  # noqa: PLC0415

        columns = {f"{name}_c": self.temperatures_c[index] for index, name in enumerate(NODES)}
        columns.update(mesh_loss_w=self.mesh_loss, bearing_loss_w=self.bearing_loss, seal_loss_w=self.seal_loss,
                       churning_loss_w=self.churning_loss, jet_loss_w=self.jet_loss, backlash_m=self.backlash)
        return pd.DataFrame(columns, index=pd.Index(self.times, name="time_s"))

    def to_dataset(self):
        """xarray Dataset over time: node temperatures [°C] (node, time), losses [W] and backlash [m]."""
        import xarray as xr  # noqa: PLC0415

        return xr.Dataset(
            {"temperature": (("node", "time"), self.temperatures_c, {"units": "degC"}),
             "mesh_loss": ("time", self.mesh_loss, {"units": "W"}),
             "bearing_loss": ("time", self.bearing_loss, {"units": "W"}),
             "seal_loss": ("time", self.seal_loss, {"units": "W"}),
             "churning_loss": ("time", self.churning_loss, {"units": "W"}),
             "jet_loss": ("time", self.jet_loss, {"units": "W"}), "backlash": ("time", self.backlash, {"units": "m"})},
            coords={"node": list(NODES), "time": ("time", self.times, {"units": "s"})},
            attrs={"energy_residual": self.energy_residual})


@dataclass(frozen=True, eq=False)
class GearboxThermalModel:
    """The thermal network of one gearbox (see the module docstring)."""

    description: GearboxDescription

    @cached_property
    def internal(self) -> np.ndarray:
        return internal_conductances(self.description)

    @cached_property
    def allowance(self):
        return backlash_allowance(self.description.gear_pair, self.description.backlash)

    def losses(self, operating: GearboxOperatingPoint) -> LossModel:
        return LossModel(self.description, operating)

    def network(self, operating: GearboxOperatingPoint) -> ThermalNetwork:
        """The network at an operating point: sources and outer conductance follow the temperatures."""
        loss_model, housing, internal = self.losses(operating), self.description.housing, self.internal
        ambient = float(operating.ambient_c)

        def conductances(temperatures):
            boundary = np.zeros(len(NODES))
            boundary[HOUSING] = housing_outer_conductance(
                housing, float(np.clip(temperatures[HOUSING], *EVALUATION_RANGE_C)), ambient)
            return internal, boundary

        conditioning = self.description.conditioning
        if conditioning is None:
            def sources(temperatures, time):
                return loss_model.at(np.clip(temperatures, *EVALUATION_RANGE_C)).node_sources
        else:
            def sources(temperatures, time):
                heat = loss_model.at(np.clip(temperatures, *EVALUATION_RANGE_C)).node_sources
                heat[OIL] += conditioning.power(float(temperatures[OIL]))
                return heat

        return ThermalNetwork(np.array(self.description.capacities), conductances, sources, lambda time: ambient)

    def backlash(self, temperatures_c) -> float:
        """Normal backlash [m] with the pinion, wheel and housing at the node temperatures."""
        description = self.description
        return backlash_at_temperatures(description.gear_pair, self.allowance, description.gear_expansion,
                                        description.housing.expansion, temperatures_c[PINION],
                                        temperatures_c[WHEEL], temperatures_c[HOUSING], description.assembly_c)

    def _warn_viscosity_range(self, low_c: float, high_c: float) -> None:
        fitted = self.description.lubricant.fitted_range_c
        if low_c < fitted[0] - 1e-9 or high_c > fitted[1] + 1e-9:
            warnings.warn(f"gearbox: oil temperatures {low_c:.1f}…{high_c:.1f} °C leave the viscosity fit's range "
                          f"{fitted[0]:g}…{fitted[1]:g} °C (ASTM D341 extrapolated)", ExtrapolationWarning,
                          stacklevel=3)

    def flags(self, temperatures_c) -> tuple[str, ...]:
        """Plausibility flags of a state (:func:`thermogear.temperature.limits.state_flags`)."""
        values = np.asarray(temperatures_c, dtype=float)
        oil = self.description.lubricant
        return state_flags(float(max(values[PINION], values[WHEEL])), float(values[OIL]), oil.base_oil,
                           oil.fitted_range_c, _oil_wetted_range(values))

    def steady_state(self, operating: GearboxOperatingPoint) -> GearboxSteadyState:
        """The stable steady state of an operating point, with its plausibility flags (a hot stable state is a
        result, flagged). Raises :class:`ThermalRunawayError` only where no stable steady state exists: the direct
        solve is checked for stability (every eigenvalue of C⁻¹J negative); where it fails or is unstable the stable
        branch is followed in torque from zero (:func:`~thermogear.gearbox.network.continue_steady_states`), and
        either reaches the torque asked for or ends at a fold, which the error names."""
        network = self.network(operating)
        ambient = np.full(len(NODES), float(operating.ambient_c))
        steady, eigenvalue = None, float("nan")
        try:
            steady = solve_steady_state(network, ambient, temperature_limit=HOTTEST_STEADY_C)
            eigenvalue = float(np.max(np.real(stability_eigenvalues(network, steady.temperatures))))
            if not eigenvalue < 0.0:
                steady = None
        except NoSteadyStateError:
            steady = None
        if steady is None:
            steady, eigenvalue = self._continued_steady_state(operating, network)
        temperatures = steady.temperatures
        self._warn_viscosity_range(*_oil_wetted_range(temperatures))
        return GearboxSteadyState(temperatures, self.losses(operating).at(temperatures), self.backlash(temperatures),
                                  steady.heat_out, steady.energy_residual, steady.time_constants, eigenvalue,
                                  self.flags(temperatures))

    def _continued_steady_state(self, operating: GearboxOperatingPoint, network: ThermalNetwork):
        """The stable steady state at ``operating`` reached by continuation in torque from zero, or
        ThermalRunawayError at the fold where the stable branch ends (:meth:`steady_state`)."""
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ExtrapolationWarning)  # raised again for the result itself
            fold = continue_steady_states(lambda torque: self.network(replace(operating, torque=torque)), 0.0,
                                          operating.torque, np.full(len(NODES), float(operating.ambient_c)),
                                          bounds=(EVALUATION_RANGE_C[0], HOTTEST_STEADY_C))
        if fold.reached:
            return steady_state_at(network, fold.temperatures), fold.largest_eigenvalue
        hottest = float(np.max(fold.temperatures))
        where = (f"leaves the {HOTTEST_STEADY_C:g} °C up to which the network's property laws are evaluated"
                 if hottest > HOTTEST_STEADY_C - 60.0 else
                 f"ends at a fold (largest stability eigenvalue {fold.largest_eigenvalue:.3g} 1/s there)")
        if fold.parameter == 0.0:
            message = (f"no stable steady state at {operating.speed_rpm:g} rpm even without load: the speed-dependent "
                       "losses grow with temperature faster than the cooling (thermal runaway)")
        else:
            message = (f"no stable steady state at {operating.speed_rpm:g} rpm, {operating.torque:g} N·m: the stable "
                       f"branch of steady states, followed in torque from 0, {where} near {fold.parameter:.4g} N·m "
                       f"(pinion {fold.temperatures[PINION]:.1f} °C, oil {fold.temperatures[OIL]:.1f} °C there); "
                       "above it "
                       "the losses grow with temperature faster than the cooling: thermal runaway")
        raise ThermalRunawayError(message, float(fold.parameter), fold.temperatures, float(operating.speed_rpm))

    def warm_up(self, operating: GearboxOperatingPoint, duration: float, points: int = 121,
                initial_c=None, method: str = "Radau") -> WarmUpHistory:
        """Temperatures, losses and backlash over ``duration`` [s] at ``points`` evenly spaced times, from the
        ambient temperature (default) or ``initial_c`` (one value or one per node of :data:`NODES`, [°C], down
        to −40 °C)."""
        if not duration > 0.0:
            raise CaseError("warm_up.duration_s", duration, "> 0 s", "a warm-up takes time")
        start = np.full(len(NODES), float(operating.ambient_c)) if initial_c is None else np.broadcast_to(
            np.asarray(initial_c, dtype=float), (len(NODES),)).copy()
        if not np.all(np.isfinite(start)) or np.min(start) < COLDEST_START_C:
            raise CaseError("warm_up.initial_c", start.tolist(), f">= {COLDEST_START_C:g} °C",
                            "the coldest start the model supports")
        times = np.linspace(0.0, float(duration), int(points))
        transient = integrate_transient(self.network(operating), start, times, method=method)
        temperatures = transient.temperatures
        self._warn_viscosity_range(*_oil_wetted_range(temperatures))
        loss_model = self.losses(operating)
        conditioning = self.description.conditioning
        states = [loss_model.at(temperatures[:, index]) for index in range(times.size)]
        return WarmUpHistory(times, temperatures, np.array([s.mesh for s in states]),
                             np.array([s.bearings for s in states]), np.array([s.seals for s in states]),
                             np.array([s.churning for s in states]),
                             np.array([self.backlash(temperatures[:, index]) for index in range(times.size)]),
                             transient.energy_residual,
                             None if self.description.oil_jet is None else np.array([s.injection for s in states]),
                             None if conditioning is None else np.array([conditioning.power(float(value))
                                                                         for value in temperatures[OIL]]))
