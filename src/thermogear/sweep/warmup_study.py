"""Warm-ups over a family of cases (issue 34): the gearbox warm-up of ``thermogear warmup --model gearbox``
(:func:`~thermogear.experiment.gearbox_warmup.gearbox_warmup`) at every point of a grid of case keys — torque ×
ambient (every node's start temperature of a cold start, unless ``start_c`` fixes one), speed × oil fill, … — on
the one executor into the one task store.

Planning. The grid is a :class:`~thermogear.sweep.study.Study` (the same ``--vary`` keys, checks and held load as
every study); a task is one block of it (``chunk_points`` warm-ups, default one: a warm-up integrates the thermal
network and re-evaluates the mesh every ``interval_s``, seconds of work). Each point's warm-up starts from its own
cold start and never from another point's temperatures, so a task is a pure function of the study and its block:
serial, local workers and a scheduler by address give the same store, and ``--resume`` computes only the blocks the
store has not marked done. Progress advances per warm-up.

Stored per point and output time (dims ``(*parameters, time)``): the network's node temperatures, losses by source,
oil conditioning and backlash, the mesh re-evaluated there (mean stiffness, natural and mesh frequency, Kv; NaN with
the reason in ``mesh_note`` where it is not evaluated) and the plausibility flags; per point the smallest backlash
and when, the cold-start backlash and margin to jamming, the energy residual of the integration and ``status``
("computed", or "not computed: why").
"""

from __future__ import annotations

import json
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np

from thermogear.errors import CaseError, JammingError, ModelLimitError, ProblemError
from thermogear.gearbox.losses import NODES  # one stored temperature per node of the network

__all__ = ["WarmupSettings", "run_warmup_study", "warmup_layout"]

#: Per point and time: stored name → (units, long name, history attribute).
LOSSES = {"mesh_loss_w": ("W", "tooth mesh loss", "mesh_loss"),
          "bearing_loss_w": ("W", "bearing losses", "bearing_loss"),
          "seal_loss_w": ("W", "seal losses", "seal_loss"),
          "churning_loss_w": ("W", "churning (no-load) losses", "churning_loss"),
          "injection_loss_w": ("W", "oil injection (jet) losses", "jet_loss"),
          "conditioning_w": ("W", "oil conditioning power into the oil (negative: cooling)", "conditioning")}
#: Per point and time, the mesh at the network's state: stored name → (units, long name, MeshState attribute).
MESH = {"mesh_stiffness_mean": ("N/m", "mean mesh stiffness (total over the face width)", "mesh_stiffness_mean"),
        "natural_frequency_hz": ("Hz", "natural frequency of the pair", "natural_frequency_hz"),
        "mesh_frequency_hz": ("Hz", "mesh frequency", "mesh_frequency_hz"),
        "kv": ("1", "dynamic factor Kv of the periodic response (Luo & Li Eq. 29)", "kv")}
#: What a point's warm-up may raise: the case's and the solvers' refusals.
FAILURES = (CaseError, ModelLimitError, ProblemError, JammingError, np.linalg.LinAlgError, ValueError)


@dataclass(frozen=True)
class WarmupSettings:
    """The warm-up every point runs: ``duration_s`` [s], ``interval_s`` between mesh re-evaluations [s],
    ``start_c`` every node's start temperature [°C] (None: the point's ambient), ``dynamics`` (Kv per state)."""

    duration_s: float = 1200.0
    interval_s: float = 10.0
    start_c: float | None = None
    dynamics: bool = True

    def times(self) -> np.ndarray:
        """The output times [s] (every mesh re-evaluation), checked as the warm-up checks them."""
        from thermogear.experiment.gearbox_warmup import warmup_state_count

        return np.linspace(0.0, float(self.duration_s), warmup_state_count(self.duration_s, self.interval_s) + 1)

    def describe(self) -> dict[str, Any]:
        return {"duration_s": float(self.duration_s), "interval_s": float(self.interval_s),
                "start_c": None if self.start_c is None else float(self.start_c), "dynamics": bool(self.dynamics)}


def warmup_layout(study, settings: WarmupSettings, extra_attrs: dict):
    """The store of a warm-up family (:class:`~thermogear.sweep.task_store.StoreLayout`)."""
    from thermogear.sweep.study import case_fingerprint
    from thermogear.sweep.task_store import StoreLayout, StoreVariable

    if len(study.models) != 1:
        raise CaseError("--model", "both", "elastic | thermal for a warm-up study",
                        "a warm-up evaluates the mesh with one gear model at every state")
    dims = study.dims
    timed = (*dims, "time")
    variables = [StoreVariable(f"{node}_c", timed, "float", "degC", f"{node} node temperature") for node in NODES]
    variables += [StoreVariable(name, timed, "float", units, text) for name, (units, text, _) in LOSSES.items()]
    variables += [StoreVariable("backlash_um", timed, "float", "um", "normal backlash at the network's state"),
                  StoreVariable("flags", timed, "str", "", "plausibility flags raised at this time", width=80)]
    variables += [StoreVariable(name, timed, "float", units, text) for name, (units, text, _) in MESH.items()]
    variables += [StoreVariable("mesh_note", timed, "str", "", "why the mesh is not evaluated at this time", width=160)]
    scalars = [("warmup_start_c", "degC", "every node's start temperature"),
               ("warmup_ambient_c", "degC", "ambient temperature"),
               ("warmup_speed_rpm", "rpm", "pinion speed of the warm-up"),
               ("warmup_torque_nm", "N m", "pinion torque of the warm-up"),
               ("smallest_backlash_um", "um", "smallest normal backlash during the warm-up"),
               ("smallest_backlash_time_s", "s", "when the backlash is smallest"),
               ("cold_start_backlash_um", "um", "normal backlash at the start temperature, everything soaked"),
               ("cold_start_margin_um", "um", "cold start: margin to jamming"),
               ("energy_residual", "1", "relative energy residual of the network's integration")]
    variables += [StoreVariable(name, dims, "float", units, text) for name, units, text in scalars]
    variables += [StoreVariable("cold_start_jammed", dims, "bool", "1", "True where the cold start jams the gears"),
                  StoreVariable("status", dims, "str", "", "computed | not computed: why", width=300)]
    coords: dict[str, Any] = {p.name: np.asarray(p.values) for p in study.parameters}
    coords["time"] = settings.times()
    chunks = dict(zip(dims, study.chunk_shape))
    definition = {**study.describe(), "kind": "gearbox warm-ups", "warmup": settings.describe()}
    attrs = {"case": study.case.name, "case_name": study.case.name, "case_source": str(study.case.source),
             "kind": "gearbox warm-up family", "gear_model": study.models[0],
             "case_json": json.dumps(study.case.document, sort_keys=True, default=str),
             "case_document_sha256": case_fingerprint(study.case.document), **extra_attrs}
    return StoreLayout(coords=coords, variables=tuple(variables), tasks=len(study.blocks()), definition=definition,
                       attrs=attrs, chunks=chunks, coord_attrs={"time": {"units": "s"}})


def _point(study, settings: WarmupSettings, values: tuple, times: int) -> dict[str, Any]:
    """One point's warm-up as the stored values (NaN with the reason in ``status`` where it cannot be computed)."""
    from thermogear.experiment.gearbox_warmup import gearbox_warmup
    from thermogear.gearbox.case_model import PredictedTemperatureError

    point: dict[str, Any] = {"status": "", "cold_start_jammed": False}
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the case's warnings were printed by the study's checks
            try:
                case = study.case_at(values)
            except PredictedTemperatureError:  # the warm-up reports the network at any temperature
                case = study.case.with_changes(predict_temperatures=False, **study.changes(values))
            result = gearbox_warmup(case, duration_s=settings.duration_s, start_c=settings.start_c,
                                    interval_s=settings.interval_s, gear_model=study.models[0],
                                    dynamics=settings.dynamics)
    except FAILURES as error:
        point["status"] = f"not computed: {error}"
        return point
    history = result.history
    if history.times.size != times or len(result.states) != times:  # pragma: no cover - the layout's own times
        raise AssertionError("the warm-up's output times differ from the study's")
    for node in NODES:
        point[f"{node}_c"] = history.node(node)
    for name, (_, _, source) in LOSSES.items():
        point[name] = np.asarray(getattr(history, source), dtype=float)
    point["backlash_um"] = np.asarray(history.backlash, dtype=float) * 1e6
    point["flags"] = np.array([",".join(flags) for flags in result.flags], dtype=object)
    for name, (_, _, source) in MESH.items():
        point[name] = np.array([np.nan if getattr(state, source) is None else getattr(state, source)
                                for state in result.states], dtype=float)
    point["mesh_note"] = np.array([state.note for state in result.states], dtype=object)
    smallest, at = result.smallest_backlash
    cold = result.cold_start
    point.update(warmup_start_c=result.start_c, warmup_ambient_c=result.ambient_c,
                 warmup_speed_rpm=result.speed_rpm, warmup_torque_nm=result.torque, smallest_backlash_um=smallest * 1e6, smallest_backlash_time_s=at,
                 cold_start_backlash_um=cold.backlash * 1e6, cold_start_margin_um=cold.margin_to_jamming * 1e6,
                 energy_residual=history.energy_residual, cold_start_jammed=bool(cold.jammed), status="computed")
    return point


def warmup_task(shared: tuple, block) -> dict[str, np.ndarray]:
    """One task: the warm-ups of a block of the grid, as the arrays of its region."""
    study, settings, names = shared
    times = settings.times().size
    shape = block.shape
    arrays: dict[str, np.ndarray] = {}
    for name, kind, timed in names:
        full = (*shape, times) if timed else shape
        arrays[name] = (np.full(full, "", dtype=object) if kind == "str" else
                        np.zeros(full, dtype=bool) if kind == "bool" else np.full(full, np.nan))
    for flat, values in enumerate(study.block_values(block)):
        where = np.unravel_index(flat, shape)
        for name, value in _point(study, settings, tuple(values), times).items():
            arrays[name][where] = value
    return arrays


def run_warmup_study(study, out, settings: WarmupSettings, scheduler: str = "serial", workers: int | None = None,
                     resume: bool = False, overwrite: bool = False, progress=None):
    """Run the warm-up family of ``study`` on ``scheduler`` (:func:`thermogear.sweep.executor.execute`) into the
    store ``out`` (module docstring) and return the store's Dataset. ``progress(total, completed)``: a context
    manager yielding ``advance(points)``."""
    from contextlib import nullcontext

    from thermogear.sweep.executor import execute
    from thermogear.sweep.load_held import study_load_held
    from thermogear.sweep.task_store import TaskStore

    load, load_note = study_load_held(study)
    layout = warmup_layout(study, settings, {"load": load, "load_note": load_note})
    store = TaskStore.open(out, layout, resume=resume, overwrite=overwrite)
    blocks = study.blocks()
    done = store.done_tasks()
    pending = [block for block in blocks if block.number not in done]
    names = tuple((variable.name, variable.kind, variable.dims[-1:] == ("time",)) for variable in layout.variables)
    dims = study.dims

    with (progress(study.size, sum(block.size for block in blocks if block.number in done)) if progress is not None
          else nullcontext(lambda points=1: None)) as advance:
        def finished(index: int, arrays) -> None:
            block = pending[index]
            store.write(block.number, dict(zip(dims, block.slices)), arrays)
            advance(block.size)

        execute(warmup_task, (study, settings, names), pending, finished, scheduler, workers)
    return store.dataset()
