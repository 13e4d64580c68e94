"""Steady temperatures, losses and backlash of a gearbox over a grid of pinion speeds × torques.

Each grid point is one steady solve of the network (:meth:`GearboxThermalModel.steady_state`, about 2 ms). This
module solves a block of points in a loop (:func:`solve_grid`); :func:`steady_sweep` a whole grid in this thread,
and :mod:`thermogear.sweep.gearbox_grid` a grid cut into blocks on the study executor (worker processes, a
scheduler), written to a zarr store as the blocks finish. A point without a stable steady state (thermal runaway)
is masked, never a number, and carries the torque of the fold where the stable branch ended; a stable point carries
its plausibility flags (:mod:`thermogear.temperature.limits`): a hot stable state is a result, flagged.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.losses import NODES
from thermogear.gearbox.network import NoSteadyStateError
from thermogear.temperature.limits import FLAG_MEANINGS

#: Largest grid accepted (each point is one nonlinear solve).
MOST_POINTS = 10_000


@dataclass(frozen=True)
class SteadySweep:
    """Speeds (m,) [rpm] × torques (k,) [N·m]; masked arrays (m, k): losses by source [W], efficiency [–],
    normal backlash [m], and temperatures (nodes, m, k) [°C] by :data:`NODES`. Masked where the
    network has no steady state (``runaway``)."""

    speeds_rpm: np.ndarray
    torques: np.ndarray
    ambient_c: float
    temperatures_c: np.ma.MaskedArray
    mesh_loss: np.ma.MaskedArray
    bearing_loss: np.ma.MaskedArray
    seal_loss: np.ma.MaskedArray
    churning_loss: np.ma.MaskedArray
    efficiency: np.ma.MaskedArray
    backlash: np.ma.MaskedArray
    injection_loss: np.ma.MaskedArray | None = None  # the oil jet's impulse loss [W] (None: no jet)
    flags: np.ndarray | None = None  # (m, k) tuples of plausibility flags (empty where none or runaway)
    fold_torque: np.ma.MaskedArray | None = None  # (m, k) [N·m] where the stable branch ended (runaway points)

    @property
    def runaway(self) -> np.ndarray:
        """True where no stable steady state exists (m, k)."""
        return np.ma.getmaskarray(self.mesh_loss)

    def flagged(self, flag: str) -> np.ndarray:
        """True where a steady state carries ``flag`` (m, k) (thermogear.temperature.limits.FLAG_MEANINGS)."""
        shape = self.runaway.shape
        if self.flags is None:
            return np.zeros(shape, dtype=bool)
        return np.array([[flag in self.flags[i, j] for j in range(shape[1])] for i in range(shape[0])], dtype=bool)

    @property
    def valid(self) -> np.ndarray:
        """True where a stable steady state exists with every gear within the material data (m, k): the one
        limit that ``check``/``run``/``sweep`` apply (thermogear.temperature.limits)."""
        return ~self.runaway & ~self.flagged("above_material_data")

    @property
    def total_loss(self) -> np.ma.MaskedArray:
        total = self.mesh_loss + self.bearing_loss + self.seal_loss + self.churning_loss
        return total if self.injection_loss is None else total + self.injection_loss

    def node(self, name: str) -> np.ma.MaskedArray:
        """Temperatures of one node (m, k) [°C]."""
        if name not in NODES:
            raise CaseError("node", name, f"one of {', '.join(NODES)}", "the nodes of the gearbox network")
        return self.temperatures_c[NODES.index(name)]

    def as_dict(self) -> dict:
        """JSON view: nested lists [speed][torque], None where there is no steady state."""
        def listed(values):
            return [[None if value is np.ma.masked else float(value) for value in row] for row in values]

        return {"speeds_rpm": self.speeds_rpm.tolist(), "torques_nm": self.torques.tolist(),
                "ambient_c": self.ambient_c,
                **{f"{name}_c": listed(self.node(name)) for name in NODES},
                "mesh_loss_w": listed(self.mesh_loss), "bearing_loss_w": listed(self.bearing_loss),
                "seal_loss_w": listed(self.seal_loss), "churning_loss_w": listed(self.churning_loss),
                **({} if self.injection_loss is None else {"injection_loss_w": listed(self.injection_loss)}),
                "efficiency": listed(self.efficiency), "backlash_um": listed(self.backlash * 1e6),
                "runaway": self.runaway.tolist(), "valid": self.valid.tolist(),
                "flags": [[[] if self.flags is None else list(self.flags[i, j]) for j in range(self.torques.size)]
                          for i in range(self.speeds_rpm.size)],
                **({} if self.fold_torque is None else {"fold_torque_nm": listed(self.fold_torque)})}


def steady_point(model, speed_rpm: float, torque: float, ambient_c: float):
    """The steady state of ``model`` at one point, or the NoSteadyStateError that says why there is none (thermal
    runaway: its fold)."""
    try:
        return model.steady_state(GearboxOperatingPoint(float(speed_rpm), float(torque), float(ambient_c)))
    except NoSteadyStateError as error:
        return error


#: The steady outputs of a grid point besides the node temperatures, in :func:`solve_grid` order.
OUTPUTS = ("mesh", "bearings", "seals", "churning", "efficiency", "backlash", "injection")


def solve_grid(model, speeds_rpm, torques, ambient_c: float) -> dict[str, np.ndarray]:
    """The steady states of ``model`` at every speed [rpm] × torque [N·m] (a block of a grid), in a loop: arrays
    ``temperatures`` (nodes, m, k) [°C] and one (m, k) per name of :data:`OUTPUTS`, NaN where the network has no stable
    steady state, ``runaway`` (m, k) bool, ``fold`` (m, k) the torque [N·m] where the stable branch ended (NaN
    elsewhere) and ``flag_<name>`` (m, k) bool per plausibility flag (:data:`~thermogear.temperature.limits.
    FLAG_MEANINGS`). Each point is a pure function of the model and the point, so a block gives
    the same bits wherever and in whatever order it is solved. The viscosity-range warning of each point is not
    raised here (:func:`warn_oil_range` says it once for a whole grid)."""
    speeds = np.atleast_1d(np.asarray(speeds_rpm, dtype=float))
    loads = np.atleast_1d(np.asarray(torques, dtype=float))
    shape = (speeds.size, loads.size)
    arrays = {"temperatures": np.full((len(NODES),) + shape, np.nan), **{name: np.full(shape, np.nan) for name in OUTPUTS},
              "runaway": np.zeros(shape, dtype=bool), "fold": np.full(shape, np.nan),
              **{f"flag_{flag}": np.zeros(shape, dtype=bool) for flag in FLAG_MEANINGS}}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        for i, speed in enumerate(speeds):
            for j, torque in enumerate(loads):
                state = steady_point(model, speed, torque, ambient_c)
                if isinstance(state, NoSteadyStateError):  # no stable steady state: NaN, with its fold
                    arrays["runaway"][i, j] = True
                    if getattr(state, "fold_torque", None) is not None:
                        arrays["fold"][i, j] = state.fold_torque
                    continue
                for flag in state.flags:
                    arrays[f"flag_{flag}"][i, j] = True
                arrays["temperatures"][:, i, j] = state.temperatures_c
                losses = state.losses
                for name, value in (("mesh", losses.mesh), ("bearings", losses.bearings), ("seals", losses.seals),
                                    ("churning", losses.churning), ("efficiency", losses.efficiency),
                                    ("injection", losses.injection), ("backlash", state.backlash)):
                    arrays[name][i, j] = value
    return arrays


def warn_oil_range(model, temperatures: np.ndarray) -> None:
    """Once for a whole grid: the temperatures [°C] at which the oil's viscosity is evaluated (the two shafts'
    bearings and the sump; ``temperatures`` (nodes, …), NaN where none) that leave the range the viscosity fit was
    made over."""
    fitted = model.description.lubricant.fitted_range_c
    oil = np.asarray(temperatures)[[NODES.index(name) for name in ("pinion_shaft", "wheel_shaft", "oil")]]
    if not np.isfinite(oil).any():
        return
    low, high = float(np.nanmin(oil)), float(np.nanmax(oil))
    if low < fitted[0] or high > fitted[1]:
        warnings.warn(f"gearbox: oil temperatures {low:.1f}…{high:.1f} °C over the grid leave the viscosity fit's "
                      f"range {fitted[0]:g}…{fitted[1]:g} °C (ASTM D341 extrapolated)", ExtrapolationWarning,
                      stacklevel=3)


def grid_result(model, speeds_rpm, torques, ambient_c: float, arrays: dict[str, np.ndarray]) -> SteadySweep:
    """The :class:`SteadySweep` of a grid's arrays (:func:`solve_grid`'s names), masked where ``runaway``."""
    runaway = np.asarray(arrays["runaway"], dtype=bool)

    def masked(values) -> np.ma.MaskedArray:
        values = np.asarray(values, dtype=float)
        return np.ma.masked_array(values, mask=np.broadcast_to(runaway, values.shape))

    shape = runaway.shape
    flags = np.empty(shape, dtype=object)
    for i in range(shape[0]):
        for j in range(shape[1]):
            flags[i, j] = tuple(flag for flag in FLAG_MEANINGS if np.asarray(arrays[f"flag_{flag}"])[i, j])
    fold = np.asarray(arrays["fold"], dtype=float)
    return SteadySweep(np.atleast_1d(np.asarray(speeds_rpm, dtype=float)),
                       np.atleast_1d(np.asarray(torques, dtype=float)), float(ambient_c),
                       masked(arrays["temperatures"]), masked(arrays["mesh"]), masked(arrays["bearings"]),
                       masked(arrays["seals"]), masked(arrays["churning"]), masked(arrays["efficiency"]),
                       masked(arrays["backlash"]),
                       None if model.description.oil_jet is None else masked(arrays["injection"]),
                       flags, np.ma.masked_invalid(fold))


def check_grid(speeds_rpm, torques) -> tuple[np.ndarray, np.ndarray]:
    """The grid's speeds and torques as 1-D arrays; a grid beyond :data:`MOST_POINTS` is refused."""
    speeds = np.atleast_1d(np.asarray(speeds_rpm, dtype=float))
    loads = np.atleast_1d(np.asarray(torques, dtype=float))
    if speeds.ndim != 1 or loads.ndim != 1 or speeds.size * loads.size > MOST_POINTS:
        raise CaseError("speeds/torques", (speeds.size, loads.size), f"1-D, at most {MOST_POINTS} points in all",
                        "each point is one nonlinear steady solve")
    return speeds, loads


def steady_sweep(model, speeds_rpm, torques, ambient_c: float = 20.0) -> SteadySweep:
    """Steady states of ``model`` (a :class:`~thermogear.gearbox.model.GearboxThermalModel`) on the grid, in this
    thread (:mod:`thermogear.sweep.gearbox_grid` runs a grid on the study executor, into a store)."""
    speeds, loads = check_grid(speeds_rpm, torques)
    arrays = solve_grid(model, speeds, loads, ambient_c)
    warn_oil_range(model, arrays["temperatures"])
    return grid_result(model, speeds, loads, ambient_c, arrays)
