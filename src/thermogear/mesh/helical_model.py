"""A case's helical pair under a mesh model: its stiffness along the face, the load along the face with the
deviations the model gives (profile deviations of the transverse section, the thermal lead distortion of a
temperature gradient across the face), and the one mesh period the 1-DOF solvers take.

The 1-DOF pair is the torsional projection along the transverse line of action (:mod:`thermogear.mesh.helical_state`):
the transmission error δ = r_b1θ₁ + r_b2θ₂ against F_bt = T₁/r_b1 and the stiffness K_t of the slice model
(:mod:`thermogear.helical.slices`). The model's transverse section is the one the spur machinery gives for the
same case (:attr:`MeshModel.gear_pair`): at temperature for the thermo-elastic model (gears grown by their bulk
rise, centre distance by the housing's), as built otherwise. What the model changes and how it enters here:

- E(T): every compliance of the slice model is ∝ 1/E, so K_t is scaled by the pair's modulus ratio; with different
  ratios of pinion and wheel the series mean 2/(1/r₁ + 1/r₂) is taken (exact for equal ratios; for the tooth
  temperatures of one case the ratios differ by well under 1 %, and the error is second order in that difference);
- the profile deviations of a tooth pair along the transverse path (tip reliefs, base-pitch mismatch, thermal
  profile distortion) become the gap of every slice at its path position;
- the lead distortion of ``[temperature] face_gradient_k`` (g = outlet minus inlet side, linear across the face):
  ΔT(z) = g (1/2 − z/b) for both gears, z from the end face where a tooth pair's contact line leaves the mesh
  last — the slice at z = b reaches the start of the path A first, so a tooth's contact sweeps from z = b to z = 0
  and the oil is driven out at z = 0 (the outlet side). Its gap is
  :func:`~thermogear.helical.face_load.thermal_lead_deviation`.
With deviations, each mesh position is solved with compression-only slices (Σ k_i⟨δ − e_i⟩₊ = F_bt,
:func:`~thermogear.helical.face_load.slice_loads`), and the period takes the stiffness of the slices that carry load
and the deviation e(φ) = δ(φ) − F_bt/K(φ) that reproduces the loaded static transmission error. Without deviations
K_t is the exact face integral and e = 0.

Friction damping: Luo & Li (2020) Eq. 28 gives each contact c = 4μk/(πω_m), so the mesh damping is ∝ the stiffness
at the contacts' mean μ; the helical mesh takes c(τ) = K_t(τ)·c̄/k̄ with c̄/k̄ the time means of the model's
transverse section (the spur pair of the same transverse geometry, oil and load per width). A stated
approximation: a helical contact line spans the path, so μ is averaged along it.
"""

from __future__ import annotations

import threading
import weakref
from dataclasses import dataclass, replace
from functools import lru_cache

import numpy as np

from thermogear import warning_scope
from thermogear.helical.face_load import FaceLoad, SliceContacts, thermal_lead_deviation
from thermogear.helical.geometry import HelicalPair
from thermogear.helical.slices import DEFAULT_SLICES, helical_mesh_stiffness, slice_positions, slice_stiffness_at
from thermogear.mesh.state import MeshState, mesh_state_from_arrays

#: ``mesh_model`` below is a :class:`thermogear.mesh.model.MeshModel` (not imported: it imports this module).
MeshModel = object

__all__ = ["HelicalMeshPeriod", "helical_face_moments", "helical_mesh_period", "helical_model_state",
           "operating_helical_pair", "face_temperature_rise", "clear_cache"]


@dataclass(frozen=True)
class HelicalMeshPeriod:
    """One mesh period of a case's helical pair under a model, at mesh phases φ [m] along the transverse path.

    ``stiffness`` K_t [N/m] of the slices that carry load; ``approach`` δ the loaded static transmission error [m];
    ``face`` the load along the face (None where there are no deviations: the load is then spread as the stiffness
    is); ``stiffness_scale`` the E(T) factor applied."""

    helical: HelicalPair
    phase: np.ndarray
    load: float  # F_bt [N]
    stiffness: np.ndarray
    approach: np.ndarray
    face: FaceLoad | None
    stiffness_scale: float

    @property
    def deviation(self) -> np.ndarray:
        """e(φ) = δ(φ) − F_bt/K(φ) [m]: the unloaded deviation of the mesh whose linear response to F_bt is the
        loaded static transmission error (0 without deviations)."""
        if self.face is None:
            return np.zeros(self.phase.shape)
        return self.approach - self.load / self.stiffness


def operating_helical_pair(mesh_model: MeshModel) -> HelicalPair:
    """The case's helical pair with the model's transverse section (at temperature for the thermo-elastic model)."""
    return replace(mesh_model.case.helical_pair, transverse=mesh_model.gear_pair)


def _stiffness_scale(mesh_model: MeshModel) -> float:
    """E(T)/E(20 °C) of the pair (module docstring): 1 for a model without E(T)."""
    mesh = mesh_model.thermoelastic_mesh
    if mesh is None or not mesh_model.thermal:
        return 1.0
    pinion, wheel = mesh.modulus_ratios
    return pinion if pinion == wheel else 2.0 / (1.0 / pinion + 1.0 / wheel)


def face_temperature_rise(mesh_model: MeshModel, z: np.ndarray) -> np.ndarray:
    """ΔT(z) = g (1/2 − z/b) [K] of ``[temperature] face_gradient_k`` g under a thermal model, 0 otherwise."""
    gradient = float(getattr(mesh_model.case.temperature, "face_gradient_k", 0.0))
    if gradient == 0.0 or not mesh_model.thermal:
        return np.zeros(np.shape(z))
    return gradient * (0.5 - np.asarray(z, dtype=float) / mesh_model.case.helical_pair.face_width)


def _lead_gap(mesh_model: MeshModel, helical: HelicalPair, z: np.ndarray) -> np.ndarray:
    rise = face_temperature_rise(mesh_model, z)
    if not np.any(rise):
        return np.zeros(z.shape)
    mesh = mesh_model.thermoelastic_mesh
    transverse = helical.transverse
    return thermal_lead_deviation(rise, rise, transverse.operating_pitch_radii, transverse.operating_pressure_angle,
                                  (mesh.gears[0].expansion_per_k, mesh.gears[1].expansion_per_k))


@dataclass(frozen=True, eq=False)
class _PeriodContacts:
    """What a model's period on given phases needs that changes with neither speed nor load (computed once per
    model: :func:`_cached`): the operating pair, the phases [m], the E(T) factor, and one of: the exact face
    integral K_t (``integral``); the slices' gaps (``z`` the slice centres, ``gap`` the deviation of every slice
    in the zone of action, in the order of :class:`_SliceLayout`, ``gap_free`` where none has one); the slices
    prepared for the solve at any load (``contacts``: their stiffness ×scale and gap, a row per phase;
    ``group`` the slice of each entry of a row)."""

    helical: HelicalPair
    phase: np.ndarray
    scale: float
    integral: np.ndarray | None = None
    z: np.ndarray | None = None
    gap: np.ndarray | None = None
    gap_free: bool = True
    contacts: SliceContacts | None = None
    group: np.ndarray | None = None


@dataclass(frozen=True, eq=False)
class _SliceLayout:
    """The slices in the zone of action over a period (once per operating pair, material, points and slices:
    :func:`_slice_layout`), only those: a slice on a contact line is in the zone where its path position s lies
    on A…E (where :func:`~thermogear.helical.slices.contact_stiffness` gives it stiffness); the others carry
    nothing and are left out (of the (phases, lines, slices) array, about 1 − ε_α/lines of it). The entries are in
    the order of that array (phase, then line, then slice): ``position`` s [m] from A, ``slice_index`` the slice,
    ``stiffness`` [N/m] (E at 20 °C); ``filled`` (phases, longest row) where a row has an entry;
    ``phase`` the period's phases [m], ``z`` the slice centres [m]."""

    phase: np.ndarray
    z: np.ndarray
    position: np.ndarray
    slice_index: np.ndarray
    stiffness: np.ndarray
    filled: np.ndarray

    def padded(self, values: np.ndarray, fill=0.0) -> np.ndarray:
        """``values`` of the entries as rows (phases, longest row), ``fill`` after a row's last entry."""
        rows = np.full(self.filled.shape, fill, dtype=np.asarray(values).dtype)
        rows[self.filled] = values
        return rows


_CACHE: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
_CACHE_LOCK = threading.Lock()


def _cached(mesh_model: MeshModel, key: tuple, compute):
    """``compute()`` once per mesh model and ``key`` (a model's geometry, material and temperatures never change:
    it is frozen). The warnings the computation raised (a stiffness table's extrapolation) are kept with the
    value and raised again on every later call, as the stiffness tables do. Threads of one sweep may compute the
    same entry twice; both are equal."""
    with _CACHE_LOCK:
        entry = _CACHE.setdefault(mesh_model, {}).get(key)
    if entry is None:
        with warning_scope.recorded() as caught:
            value = compute()
        with _CACHE_LOCK:
            entry = _CACHE.setdefault(mesh_model, {}).setdefault(key, (value, warning_scope.kept(caught)))
    warning_scope.raise_again(entry[1])
    return entry[0]


def _frozen(array: np.ndarray) -> np.ndarray:
    array.setflags(write=False)
    return array


def _phases(helical: HelicalPair, points: int) -> np.ndarray:
    return _frozen((np.arange(points) + 0.5) / points * helical.transverse.base_pitch)


def _integral_contacts(mesh_model: MeshModel, points: int) -> _PeriodContacts:
    helical = operating_helical_pair(mesh_model)
    scale = _stiffness_scale(mesh_model)
    phase = _phases(helical, points)
    total = scale * helical_mesh_stiffness(helical, mesh_model.case.material, phase).stiffness
    return _PeriodContacts(helical, phase, scale, integral=_frozen(total))


def _slice_gaps(mesh_model: MeshModel, points: int, slices: int) -> _PeriodContacts:
    """The gap of every slice in the zone of action (:class:`_SliceLayout`): the transverse section's profile
    deviation at the slice's path position and the thermal lead distortion at its place across the face."""
    helical = operating_helical_pair(mesh_model)
    points_on_path = helical.transverse.path_points
    layout = _slice_layout(helical, mesh_model.case.material, points, slices)
    lead = _lead_gap(mesh_model, helical, layout.z)
    roll = np.clip(points_on_path["A"] + layout.position, points_on_path["A"], points_on_path["E"])
    gap = _frozen(mesh_model.pair_deviation_at(roll) + lead[layout.slice_index])
    # a slice out of the zone has the lead's gap alone: gap-free as a whole only with neither
    return _PeriodContacts(helical, layout.phase, _stiffness_scale(mesh_model), z=layout.z, gap=gap,
                           gap_free=not (np.any(gap) or np.any(lead)))


@lru_cache(maxsize=8)
def _recorded_slice_layout(helical: HelicalPair, material, points: int, slices: int) -> tuple:
    with warning_scope.recorded() as caught:
        phase = _phases(helical, points)
        path_length = helical.transverse.path_length
        z, positions = slice_positions(helical, phase, slices)
        # contact_stiffness's test 0 ≤ s/g_α ≤ 1 without the quotient of every slice: s ≥ 0 is s/g_α ≥ 0 (g_α > 0,
        # s a sum of lengths of order mm, never subnormal), and only an s past g_α by rounding needs it
        inside = (positions >= 0.0) & (positions <= path_length)
        near = (positions > path_length) & (positions <= path_length * (1.0 + 1e-12))
        if near.any():
            inside[near] = positions[near] / path_length <= 1.0
        counts = np.count_nonzero(inside.reshape(points, -1), axis=-1)
        position = positions[inside]
        slice_index = np.broadcast_to(np.arange(slices, dtype=np.int32), positions.shape)[inside]
        stiffness = slice_stiffness_at(helical, material, position, slices)
        layout = _SliceLayout(phase, _frozen(z), _frozen(position), _frozen(slice_index), _frozen(stiffness),
                              _frozen(np.arange(int(counts.max(initial=0))) < counts[:, None]))
    return layout, warning_scope.kept(caught)


def _slice_layout(helical: HelicalPair, material, points: int, slices: int) -> _SliceLayout:
    """The :class:`_SliceLayout` at the period's phases, cached on its (frozen, hashable) inputs as the spur pair's
    stiffness tables are: the mesh models of one pair at other speeds (the points of a sweep, each its own case)
    share it. Its warnings (the stiffness table's) are raised again on every call."""
    layout, kept = _recorded_slice_layout(helical, material, points, slices)
    warning_scope.raise_again(kept)
    return layout


def clear_cache() -> None:
    """Drop the cached slice layouts (tests, benchmarks, memory); what one mesh model keeps goes with it."""
    _recorded_slice_layout.cache_clear()


def _slice_contacts(mesh_model: MeshModel, points: int, slices: int) -> _PeriodContacts:
    gaps = _cached(mesh_model, ("gaps", points, slices), lambda: _slice_gaps(mesh_model, points, slices))
    layout = _slice_layout(gaps.helical, mesh_model.case.material, points, slices)
    contacts = SliceContacts.prepare(layout.padded(gaps.scale * layout.stiffness), layout.padded(gaps.gap))
    return replace(gaps, contacts=contacts, group=_frozen(layout.padded(layout.slice_index, 0)))


def _integral_period(mesh_model: MeshModel, load: float, points: int) -> HelicalMeshPeriod:
    contacts = _cached(mesh_model, ("integral", points), lambda: _integral_contacts(mesh_model, points))
    total = contacts.integral.copy()
    return HelicalMeshPeriod(contacts.helical, contacts.phase.copy(), load, total, load / total, None,
                             contacts.scale)


def helical_mesh_period(mesh_model: MeshModel, load: float, points: int, slices: int = DEFAULT_SLICES,
                        always_face: bool = False, deviations: bool = True,
                        face_stiffness: bool = False) -> HelicalMeshPeriod:
    """The period of ``mesh_model``'s case at F_bt = ``load`` [N] on ``points`` intervals (each at its midpoint;
    module docstring). ``always_face`` solves the load along the face even without deviations (for the report);
    ``deviations=False`` leaves the model's deviations out (the stiffness of the flanks as they are);
    ``face_stiffness`` keeps the stiffness of the slices in contact per place across the face
    (``face.stiffness_moments``: the load centre and tilting stiffness over the period; implies ``always_face``).

    What depends on neither speed nor load (the slices in the zone of action with their stiffness, cached on the
    pair; their gaps; the face integral) is computed once per model and number of points, the slices only where
    the face load is solved; a call solves every mesh position at once for its load."""
    always_face = always_face or face_stiffness
    if not deviations or (mesh_model.thermoelastic_mesh is None and not always_face):
        # no deviation at all: the profile's and the lead's come from the thermo-elastic component only
        # (MeshModel.pair_deviation_at, face_temperature_rise), which this model does not have
        return _integral_period(mesh_model, load, points)
    gaps = _cached(mesh_model, ("gaps", points, slices), lambda: _slice_gaps(mesh_model, points, slices))
    if gaps.gap_free and not always_face:
        return _integral_period(mesh_model, load, points)
    contacts = _cached(mesh_model, ("slices", points, slices), lambda: _slice_contacts(mesh_model, points, slices))
    approach, engaged, carried = contacts.contacts.totals(load, contacts.group, slices)
    line_load = carried / (contacts.helical.face_width / slices)
    face = FaceLoad(contacts.z, contacts.phase, line_load, approach,
                    contacts.contacts.engaged_groups(load, contacts.group, slices) if face_stiffness else None)
    return HelicalMeshPeriod(contacts.helical, contacts.phase.copy(), load, engaged, approach, face, contacts.scale)


def helical_face_moments(mesh_model: MeshModel, load: float, points: int,
                         slices: int = DEFAULT_SLICES) -> np.ndarray:
    """(5, points): the moments across the face of the slices in contact at F_bt = ``load`` [N] per mesh position
    (the phases of :func:`helical_mesh_period`), about mid-face in the slice model's face coordinate (z_s − b/2,
    z_s = 0 the end face a contact line leaves last, where the oil leaves the mesh): k₀ = Σk_j [N/m] (the
    period's stiffness K_t), k₁ = Σk_jζ_j [N], k₂ = Σk_jζ_j² [N·m], Σk_je_j [N] (the excitation k₀δ − F_bt of
    the unloaded deviations) and Σk_je_jζ_j [N·m] (their moment), over every slice entry on a contact line in the
    zone of action that carries load (its gap e_j the profile deviation at its path position plus the lead's at its
    place across the face). The drivetrain takes them as the spread contact's variation over the period
    (:func:`thermogear.drivetrain.mesh_contact.face_variation`)."""
    gaps = _cached(mesh_model, ("gaps", points, slices), lambda: _slice_gaps(mesh_model, points, slices))
    contacts = _cached(mesh_model, ("slices", points, slices), lambda: _slice_contacts(mesh_model, points, slices))
    _, carried = contacts.contacts.carried(load)
    stiffness = np.where(carried > 0.0, contacts.contacts.stiffness, 0.0)
    position = (gaps.z - 0.5 * gaps.helical.face_width)[contacts.group]
    gap = np.where(carried > 0.0, contacts.contacts.gap, 0.0)
    return np.array([stiffness.sum(axis=-1), np.sum(stiffness * position, axis=-1),
                     np.sum(stiffness * position**2, axis=-1), np.sum(stiffness * gap, axis=-1),
                     np.sum(stiffness * gap * position, axis=-1)])


def helical_model_state(mesh_model: MeshModel, transverse_state: MeshState, speed: float, load: float,
                        points: int, damping: bool) -> MeshState:
    """The :class:`MeshState` of the case's helical pair (module docstring); ``transverse_state`` is the model's
    state of the transverse section at the same point, whose c̄/k̄ gives the friction damping."""
    period = helical_mesh_period(mesh_model, load, points)
    if damping and transverse_state.mean_mesh_stiffness > 0.0:
        ratio = float(transverse_state.grid.time_average(transverse_state.mesh_damping)) \
            / transverse_state.mean_mesh_stiffness
        mesh_damping = ratio * period.stiffness
    else:
        mesh_damping = np.zeros(points)
    deviation = period.deviation
    transverse = period.helical.transverse
    return mesh_state_from_arrays(np.arange(points) / points, period.stiffness, damping=mesh_damping,
                                  deviation=deviation if np.any(deviation) else None, speed_rpm=speed,
                                  normal_load=load, mass=transverse_state.mass, pinion_teeth=transverse.pinion.teeth,
                                  backlash=transverse_state.backlash, face_width=period.helical.face_width,
                                  model=transverse_state.model)
