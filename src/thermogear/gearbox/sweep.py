"""Steady temperatures, losses and backlash of a gearbox over a grid of pinion speeds × torques.

Each grid point is one steady solve of the network (:meth:`GearboxThermalModel.steady_state`, about 2 ms), in a
loop or on a pool of threads (``workers``). The study machinery (:mod:`thermogear.sweep`) stores the outputs of the
dynamics and would need new variables and a new kernel for these, so this sweep is a function of its own; its grid
is written to a zarr store like a study's by :mod:`thermogear.sweep.steady_store` (the dynamics of a case with
``temperature.model = "gearbox"`` does run on the study machinery: every point's case predicts its own
temperatures). A point without a stable steady state (thermal runaway) is masked, never a number, and carries the
torque of the fold where the stable branch ended; a stable point carries its plausibility flags
(:mod:`thermogear.temperature_limits`): a hot stable state is a result, flagged.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.losses import NODES
from thermogear.gearbox.network import NoSteadyStateError

#: Largest grid accepted (each point is one nonlinear solve).
MOST_POINTS = 10_000


@dataclass(frozen=True)
class SteadySweep:
    """Speeds (m,) [rpm] × torques (k,) [N·m]; masked arrays (m, k): losses by source [W], efficiency [–],
    normal backlash [m], and temperatures (5, m, k) [°C] of pinion, wheel, shafts, oil, housing. Masked where the
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
        """True where a steady state carries ``flag`` (m, k) (thermogear.temperature_limits.FLAG_MEANINGS)."""
        shape = self.runaway.shape
        if self.flags is None:
            return np.zeros(shape, dtype=bool)
        return np.array([[flag in self.flags[i, j] for j in range(shape[1])] for i in range(shape[0])], dtype=bool)

    @property
    def valid(self) -> np.ndarray:
        """True where a stable steady state exists with every gear within the material data (m, k): the one
        limit that ``check``/``run``/``sweep`` apply (thermogear.temperature_limits)."""
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


def _solve_points(model, points, ambient_c: float, workers: int | None) -> list:
    """Steady states (or None) of ``points`` [(speed, torque)], in their order: in this thread when ``workers``
    is None or 1, else on a pool of that many threads (each point is a pure function of the model and the point,
    so the results do not depend on where or in which order they are computed; the solve holds the GIL, so
    threads do not make it faster today)."""
    count = min(workers or 1, len(points))
    if count <= 1:
        return [steady_point(model, speed, torque, ambient_c) for speed, torque in points]
    from concurrent.futures import ThreadPoolExecutor  # noqa: PLC0415

    with ThreadPoolExecutor(count, "thermogear-gearbox") as pool:
        return list(pool.map(lambda point: steady_point(model, point[0], point[1], ambient_c), points))


def steady_sweep(model, speeds_rpm, torques, ambient_c: float = 20.0, workers: int | None = None) -> SteadySweep:
    """Steady states of ``model`` (a :class:`~thermogear.gearbox.model.GearboxThermalModel`) on the grid;
    ``workers``: threads that solve the points (default 1: this thread)."""
    speeds = np.atleast_1d(np.asarray(speeds_rpm, dtype=float))
    loads = np.atleast_1d(np.asarray(torques, dtype=float))
    if speeds.ndim != 1 or loads.ndim != 1 or speeds.size * loads.size > MOST_POINTS:
        raise CaseError("speeds/torques", (speeds.size, loads.size), f"1-D, at most {MOST_POINTS} points in all",
                        "each point is one nonlinear steady solve")
    shape = (speeds.size, loads.size)
    temperatures = np.ma.masked_all((5,) + shape)
    outputs = {name: np.ma.masked_all(shape) for name in ("mesh", "bearings", "seals", "churning", "efficiency",
                                                          "backlash", "injection")}
    flags = np.empty(shape, dtype=object)
    flags.fill(())
    fold = np.ma.masked_all(shape)
    points = [(i, j) for i in range(speeds.size) for j in range(loads.size)]
    with warnings.catch_warnings():
        # the viscosity-range warning of each point is raised once below for the whole grid
        warnings.simplefilter("ignore", ExtrapolationWarning)
        for (i, j), state in zip(points, _solve_points(model, [(speeds[i], loads[j]) for i, j in points],
                                                      ambient_c, workers)):
            if isinstance(state, NoSteadyStateError):  # no steady state: the point stays masked
                if getattr(state, "fold_torque", None) is not None:
                    fold[i, j] = state.fold_torque
                continue
            temperatures[:, i, j] = state.temperatures_c
            flags[i, j] = state.flags
            losses = state.losses
            for name, value in (("mesh", losses.mesh), ("bearings", losses.bearings), ("seals", losses.seals),
                                ("churning", losses.churning), ("efficiency", losses.efficiency),
                                ("injection", losses.injection),
                                ("backlash", state.backlash)):
                outputs[name][i, j] = value
    fitted = model.description.lubricant.fitted_range_c
    if temperatures.count() and (temperatures[2:4].min() < fitted[0] or temperatures[2:4].max() > fitted[1]):
        warnings.warn(f"gearbox: oil temperatures {float(temperatures[2:4].min()):.1f}…"
                      f"{float(temperatures[2:4].max()):.1f} °C over the grid leave the viscosity fit's range "
                      f"{fitted[0]:g}…{fitted[1]:g} °C (ASTM D341 extrapolated)", ExtrapolationWarning, stacklevel=2)
    return SteadySweep(speeds, loads, float(ambient_c), temperatures, outputs["mesh"], outputs["bearings"],
                       outputs["seals"], outputs["churning"], outputs["efficiency"], outputs["backlash"],
                       None if model.description.oil_jet is None else outputs["injection"], flags, fold)
