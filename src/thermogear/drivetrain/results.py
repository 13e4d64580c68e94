"""The drivetrain's results as frozen, typed objects: its modes, each model's response (linear periodic, backlash
orbit, or the last period of the motion from rest), each bearing's dynamic force, the speeds where mesh harmonics
meet modes and what heat moved per mode. Values are SI (m, N, Hz); :meth:`as_json` gives the JSON object of
``thermogear run --json`` (DTE in μm), :meth:`to_dataframe` a pandas table and :meth:`to_dataset` an xarray Dataset
(imported when asked for). Each quantity is computed once, by the function that builds its object
(:func:`mode_rows`, :func:`bearing_forces_of`, :func:`resonances_of`, :func:`heat_rows`)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from thermogear.drivetrain.case_layout import MESH_NAME
from thermogear.drivetrain.bearing_results import (BearingForces, _frozen_mapping, bearing_forces_of,  # noqa: F401
                                                   unknown_bearing_forces)
from thermogear.drivetrain.heat_results import HeatShift, heat_rows
from thermogear.drivetrain.train_results import StageResult, harmonic_orders, stage_results  # noqa: F401

__all__ = ["BearingForces", "DrivetrainBacklashResult", "DrivetrainLinearResult", "DrivetrainResults",
           "DrivetrainTransientResult", "HeatShift", "MESH_COUPLED_SHARE", "MESH_DOMINATED_SHARE", "ModeRow",
           "Resonance", "StageResult", "bearing_forces_of", "heat_rows", "mode_rows", "resonances_of", "stage_results"]

#: A mode is "mesh-dominated" when the mesh holds more than this share of its strain energy: a threshold chosen
#: here (Velex & Berthe 1989 rank modes by this share; no source fixes one), low so no mode it excites goes unmarked.
MESH_DOMINATED_SHARE = 0.1
#: Modes with a smaller mesh share still respond where a harmonic meets them: lateral modes of 3–4 % mesh share
#: carry the largest bearing forces of the FZG rig set. Their crossings are listed too. A threshold chosen here.
MESH_COUPLED_SHARE = 0.01


@dataclass(frozen=True)
class ModeRow:
    """One undamped mode: frequency [Hz], label, the mesh's (a train's: all meshes') share of its strain energy, the
    shares grouped and per element, whether the mesh dominates it; a train's ``mesh_shares`` and ``dominant_mesh``."""

    frequency_hz: float
    label: str
    mesh_share: float
    energy_shares: Mapping[str, float]
    element_shares: Mapping[str, float]
    mesh_dominated: bool
    mesh_shares: Mapping[str, float] | None = None
    dominant_mesh: str | None = None

    def as_json(self) -> dict[str, Any]:
        row = {"frequency_hz": self.frequency_hz, "label": self.label, "mesh_share": self.mesh_share,
               "energy_shares": dict(self.energy_shares), "element_shares": dict(self.element_shares),
               "mesh_dominated": self.mesh_dominated}
        if self.mesh_shares is not None:  # a train
            row["mesh_shares"], row["dominant_mesh"] = dict(self.mesh_shares), self.dominant_mesh
        return row


def _group(name: str, drivetrain) -> str:
    if any(mesh.name == name for mesh in drivetrain.meshes):
        return "mesh"
    for kind, items in (("bearings", drivetrain.bearings), ("couplings", drivetrain.couplings),
                        ("supports", drivetrain.torsional_supports), ("shafts", drivetrain.shafts)):
        if any(item.name == name for item in items):
            return kind
    return "other"


def mode_rows(modes, drivetrain, first: int = 0) -> tuple[ModeRow, ...]:
    """The modes (:class:`~thermogear.drivetrain.modes.DrivetrainModes`) of ``drivetrain`` as rows, from index
    ``first`` on; mesh-dominated where the mesh share (a train's: all meshes') exceeds
    :data:`MESH_DOMINATED_SHARE`."""
    rows = []
    meshes = [mesh.name for mesh in drivetrain.meshes]
    for index in range(first, modes.frequencies_hz.size):
        shares = {name: float(values[index]) for name, values in modes.strain_energy_shares.items()}
        grouped: dict[str, float] = {}
        for name, value in shares.items():
            kind = _group(name, drivetrain)
            grouped[kind] = grouped.get(kind, 0.0) + value
        train = {}
        if len(meshes) > 1:  # a train: the share of each mesh, and the one that holds most
            train = {"mesh_shares": _frozen_mapping({name: shares.get(name, 0.0) for name in meshes}),
                     "dominant_mesh": max(meshes, key=lambda name: shares.get(name, 0.0))}
        mesh = shares.get(MESH_NAME, 0.0) if len(meshes) == 1 else grouped.get("mesh", 0.0)
        rows.append(ModeRow(float(modes.frequencies_hz[index]), modes.labels[index], mesh, _frozen_mapping(grouped),
                            _frozen_mapping(shares), mesh > MESH_DOMINATED_SHARE, **train))
    return tuple(rows)


@dataclass(frozen=True)
class Resonance:
    """A (first) pinion speed [rpm] at which mesh harmonic ``harmonic`` meets a mode (at rest) of ``mode_hz`` [Hz];
    for a train, ``mesh`` the mesh whose harmonic it is."""

    speed_rpm: float
    harmonic: int
    mode_hz: float
    label: str
    mesh_share: float
    mesh_dominated: bool
    mesh: str | None = None

    def as_json(self) -> dict[str, Any]:
        row = {"speed_rpm": self.speed_rpm, "harmonic": self.harmonic, "mode_hz": self.mode_hz,
               "label": self.label, "mesh_share": self.mesh_share, "mesh_dominated": self.mesh_dominated}
        if self.mesh is not None:  # a train
            row["mesh"] = self.mesh
        return row


def resonances_of(rows: tuple[ModeRow, ...], teeth: int, harmonics: int,
                  stages: tuple[tuple[str, float], ...] = ()) -> tuple[Resonance, ...]:
    """Pinion speeds n = 60·f/(j·z1) [rpm] at which mesh harmonic j = 1…``harmonics`` meets a mode with a mesh
    share above :data:`MESH_COUPLED_SHARE` (the modes at standstill; the Campbell diagram,
    :mod:`thermogear.drivetrain.campbell`, follows their gyroscopic shift). A train's further ``stages`` (mesh name,
    teeth per input revolution z_p·n_p/n_1): the first pinion's speeds where their mesh harmonics meet such a mode,
    each naming its ``mesh``."""
    coupled = [row for row in rows if row.mesh_share > MESH_COUPLED_SHARE]
    meshes = ((MESH_NAME if stages else None, teeth), *stages)
    return tuple(Resonance(60.0 * row.frequency_hz / (j * per_turn), j, row.frequency_hz, row.label, row.mesh_share,
                           row.mesh_dominated, name)
                 for name, per_turn in meshes for row in coupled for j in range(1, harmonics + 1))


def _micro(value: float | None) -> float | None:
    return None if value is None else value * 1e6


@dataclass(frozen=True, eq=False)
class DrivetrainLinearResult:
    """One model's drivetrain under the linear mesh (permanent contact): the exact periodic response. ``kv`` [-],
    DTE RMS and peak-to-peak [m], the largest |Floquet multiplier| and stability, the bearing forces, the modes and
    the resonance speeds; ``response`` the solver's response (arrays over one mesh period, for :meth:`to_dataset`)."""

    kv: float | None
    dte_rms: float | None
    dte_peak_to_peak: float | None
    largest_floquet_multiplier_abs: float | None
    stable: bool | None
    bearing_forces: Mapping[str, BearingForces]
    modes: tuple[ModeRow, ...]
    resonances: tuple[Resonance, ...]
    mesh_modes: tuple[ModeRow, ...] = ()  # mesh-dominated modes above the section's mode_count (listed apart)
    response: Any = field(default=None, repr=False)
    common_period_s: float | None = None  # a train: the common period [s] and each mesh over it
    stages: Mapping[str, StageResult] | None = None
    cutoff_error: Any = None  # the response cut-off's estimated error (drivetrain.cutoff.CutoffError)

    kind = "linear"

    def _head(self) -> dict[str, Any]:
        return {"kv": self.kv, "dte_rms_um": _micro(self.dte_rms), "dte_peak_to_peak_um": _micro(self.dte_peak_to_peak),
                "largest_floquet_multiplier_abs": self.largest_floquet_multiplier_abs, "stable": self.stable}

    def _middle(self) -> dict[str, Any]:
        return {}

    def as_json(self) -> dict[str, Any]:
        """The JSON object of ``run --json`` (drivetrain → models → model)."""
        train = {} if self.stages is None else {
            "common_period_s": self.common_period_s,
            "stages": {name: stage.as_json() for name, stage in self.stages.items()}}
        return {**self._head(), **self._middle(),
                "bearing_forces": {name: force.as_json() for name, force in self.bearing_forces.items()}, **train,
                "modes": [row.as_json() for row in self.modes],
                "resonances": [row.as_json() for row in self.resonances],
                "mesh_modes_above_count": [row.as_json() for row in self.mesh_modes],
                "cutoff_error": None if self.cutoff_error is None else self.cutoff_error.as_json()}

    def scalars(self) -> dict[str, Any]:
        """The scalar results (SI) of this model, one row of :meth:`DrivetrainResults.to_dataframe`."""
        values = {**self._head(), **self._middle()}
        values["dte_rms_m"], values["dte_peak_to_peak_m"] = self.dte_rms, self.dte_peak_to_peak
        del values["dte_rms_um"], values["dte_peak_to_peak_um"]
        return {"kind": self.kind, **values}

    def to_dataframe(self):
        """The scalar results as one row (pandas)."""
        import pandas as pd  # noqa: PLC0415

        return pd.DataFrame([self.scalars()])

    def to_dataset(self, harmonics: int | None = None, points: int = 1024):
        """xarray Dataset of the response over one mesh period: DTE, mesh force, each bearing's force in x, y, z
        and its mesh harmonics (:func:`~thermogear.drivetrain.response_dataset.response_dataset_parts`), the
        scalars in the attributes; None where the response carries no motion (an orbit not found)."""
        import xarray as xr  # noqa: PLC0415

        from thermogear.drivetrain.response_dataset import response_dataset_parts  # noqa: PLC0415

        first = next(iter(self.bearing_forces.values()), None)
        count = harmonics if harmonics is not None else (len(first.harmonic_hz) if first is not None else 3)
        motion = self.response if hasattr(self.response, "bearing_forces") else None
        parts = None if motion is None else response_dataset_parts(motion, count, None, points)
        if parts is None:
            return None
        data_vars, coords, attrs = parts
        attrs.update({key: value for key, value in self.scalars().items() if value is not None
                      and not isinstance(value, bool)})
        return xr.Dataset(data_vars, coords=coords, attrs=attrs)


@dataclass(frozen=True, eq=False)
class DrivetrainBacklashResult(DrivetrainLinearResult):
    """One model's drivetrain under the backlash mesh: the periodic orbit (``converged``, or the ``failure``), its
    time without contact and on the back flanks [-], the contact switches per period."""

    converged: bool = False
    failure: str = ""
    contact_loss_fraction: float | None = None
    back_side_contact: bool | None = None
    back_contact_fraction: float | None = None
    switches_per_period: float | None = None
    reached_from: str | None = None  # where the reported orbit was reached from; ``coexisting_orbits``: others
    branch: str | None = None
    coexisting_orbits: tuple = ()
    orbit_notes: tuple[str, ...] = ()  # what the solver says of the orbit (coexistence, fall-backs)

    kind = "backlash"

    def _middle(self) -> dict[str, Any]:
        return {"reached_from": self.reached_from, "branch": self.branch,
                "coexisting_orbits": list(self.coexisting_orbits), "notes": list(self.orbit_notes),
                "converged": self.converged, "failure": self.failure,
                "contact_loss_fraction": self.contact_loss_fraction, "back_side_contact": self.back_side_contact,
                "back_contact_fraction": self.back_contact_fraction, "switches_per_period": self.switches_per_period}


@dataclass(frozen=True, eq=False)
class DrivetrainTransientResult(DrivetrainLinearResult):
    """One model's drivetrain moved from rest for ``transient_periods`` mesh periods: the last period's numbers
    (no orbit, so no multipliers), its time without contact and on the back flanks [-]."""

    transient_periods: int = 0
    contact_loss_fraction: float | None = None
    back_side_contact: bool | None = None
    back_contact_fraction: float | None = None

    kind = "transient"

    def _middle(self) -> dict[str, Any]:
        return {"transient_periods": self.transient_periods, "contact_loss_fraction": self.contact_loss_fraction,
                "back_side_contact": self.back_side_contact, "back_contact_fraction": self.back_contact_fraction}


@dataclass(frozen=True, eq=False)
class DrivetrainResults:
    """A case's drivetrain at its operating point, per model (cold: elastic, hot: thermal): the size, how the
    response was solved (``mesh``, ``solved_on``), the notes, each model's result, with both models the shift of
    each mode by heat, and the hot drivetrain's ``warm_state`` (shaft temperatures and their source, bearing rings
    and play: :mod:`~thermogear.drivetrain.warm_state`)."""

    degrees_of_freedom: int
    response_cutoff_hz: float
    mesh: str
    backlash_mesh: bool
    transient: bool
    solved_on: str
    notes: tuple[str, ...]
    models: Mapping[str, DrivetrainLinearResult]
    heat: tuple[HeatShift, ...] | None = None
    warm_state: Mapping[str, Any] = field(default_factory=dict)

    def with_note(self, note: str) -> DrivetrainResults:
        return replace(self, notes=(*self.notes, note))

    def as_json(self) -> dict[str, Any]:
        """The ``drivetrain`` object of ``run --json`` and ``summary.json``."""
        result = {"degrees_of_freedom": self.degrees_of_freedom, "response_cutoff_hz": self.response_cutoff_hz,
                  "mesh": self.mesh, "backlash_mesh": self.backlash_mesh, "transient": self.transient,
                  "solved_on": self.solved_on, "notes": list(self.notes), "warm_state": dict(self.warm_state),
                  "models": {name: model.as_json() for name, model in self.models.items()}}
        if self.heat is not None:
            result["heat"] = [row.as_json() for row in self.heat]
        return result

    def to_dataframe(self):
        """One row per model: Kv, DTE [m], stability and, where the mesh may separate, the contact (pandas)."""
        import pandas as pd  # noqa: PLC0415

        return pd.DataFrame([{"model": name, **model.scalars()} for name, model in self.models.items()]
                            ).set_index("model")

    def modes_dataframe(self):
        """One row per (model, mode): frequency [Hz], label, the grouped energy shares, mesh-dominated (pandas)."""
        import pandas as pd  # noqa: PLC0415

        return pd.DataFrame([{"model": name, "mode": index + 1, "frequency_hz": row.frequency_hz,
                              "label": row.label, "mesh_share": row.mesh_share, "mesh_dominated": row.mesh_dominated,
                              **{f"{kind}_share": value for kind, value in row.energy_shares.items()}}
                             for name, model in self.models.items() for index, row in enumerate(model.modes)]
                            ).set_index(["model", "mode"])

    def to_dataset(self):
        """xarray Dataset: the scalars per model, the mode frequencies and mesh shares per (model, mode), and the
        bearing forces per (model, bearing, harmonic)."""
        import xarray as xr  # noqa: PLC0415

        names = list(self.models)
        models = list(self.models.values())
        bearings = list(models[0].bearing_forces) if models else []
        harmonics = len(next(iter(models[0].bearing_forces.values())).harmonic_hz) if bearings else 0

        def number(value):
            return np.nan if value is None else float(value)

        data = {key: ("model", [number(model.scalars().get(key)) for model in models])
                for key in ("kv", "dte_rms_m", "dte_peak_to_peak_m", "largest_floquet_multiplier_abs")}
        count = min(len(model.modes) for model in models) if models else 0
        data["mode_frequency"] = (("model", "mode"), [[row.frequency_hz for row in model.modes[:count]]
                                                       for model in models], {"units": "Hz"})
        data["mode_mesh_share"] = (("model", "mode"), [[row.mesh_share for row in model.modes[:count]]
                                                        for model in models])
        data["bearing_dynamic_rms"] = (("model", "bearing"), [[number(model.bearing_forces[b].dynamic_rms_n)
                                                                for b in bearings] for model in models],
                                       {"units": "N"})
        data["bearing_harmonic_amplitude"] = (
            ("model", "bearing", "harmonic"),
            [[[number(a) for a in model.bearing_forces[b].harmonic_amplitude_n] for b in bearings]
             for model in models], {"units": "N"})
        coords = {"model": names, "mode": np.arange(1, count + 1), "bearing": bearings,
                  "harmonic": np.arange(1, harmonics + 1)}
        return xr.Dataset(data, coords=coords, attrs={"mesh": self.mesh, "solved_on": self.solved_on,
                                                       "degrees_of_freedom": self.degrees_of_freedom})
