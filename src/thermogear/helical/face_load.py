"""Load along the face of a helical (or spur) pair: thin slices in contact with lead deviations, the loaded static
transmission error, and the face load factor they imply beside ISO 6336-1's K_Hβ.

At one mesh position the two gears, rigid but for their teeth, approach by δ along the transverse line of action;
slice i of stiffness k_i [N/m] (its share of the slice model's K_t) with an unloaded gap e_i (a deviation: material
missing is positive) carries k_i⟨δ − e_i⟩₊ (compression only). δ follows from the load:

    Σ_i k_i ⟨δ − e_i⟩₊ = F_bt                                                          (monotone in δ: one root)

(Velex & Maatar, J. Sound Vib. 191 (1996) 629, the slice model with shape deviations). Lead deviations e(z)
[m, along the transverse line of action; ×cos β_b for the normal direction]:
- helix slope deviation f_Hβ: e = f_Hβ·z/b (the gap grows across the face);
- lead crowning C_β: e = C_β(2z/b − 1)²;
- end relief C_I over a length b_I at each end: e = C_I·ξ/b_I, ξ the distance into the relief;
- thermal lead distortion of a temperature rise that varies across the face: a gear that grows by λΔT(z) moves its
  flank at the operating pitch point by λΔT(z)·r_w sin α_wt along the line of action (the component of r_w on it),
  towards the mate: e_th(z) = −λ sin α_wt [r_w1 ΔT_1(z) + r_w2 ΔT_2(z)]. Only the part that varies with z loads
  the face unevenly; a uniform rise moves δ and leaves every slice load as it was.

For uniform slice stiffness c per unit width and a linear mismatch F_βy the solution is ISO 6336-1's K_Hβ
(§7, Method C): full contact w_max/w_m = 1 + c F_βy/(2 w_m); partial contact √(2 c F_βy / w_m) (the load a
triangle over b_c = b√(2 w_m/(c F_βy))). A crowning C_β gives 1 + c C_β/(3 w_m) in full contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["slice_loads", "SliceContacts", "FaceLoad", "FaceStiffnessMoments", "face_load", "helix_slope_deviation", "lead_crowning", "end_relief",
           "thermal_lead_deviation", "iso_face_load_factor"]


def slice_loads(stiffness: np.ndarray, gap: np.ndarray, load: float) -> tuple[float, np.ndarray]:
    """(δ [m], the slices' loads [N]) of Σ k_i⟨δ − e_i⟩₊ = F (module docstring), solved exactly: the left side is
    piecewise linear in δ, and Newton's method from full contact ends on the set of slices in contact
    (:class:`SliceContacts`)."""
    stiffness = np.asarray(stiffness, dtype=float).ravel()
    approach, carried = SliceContacts.prepare(stiffness[None, :], np.asarray(gap, dtype=float).ravel()[None, :]) \
        .solve(load)
    return float(approach[0]), carried[0]


@dataclass(frozen=True, eq=False)
class SliceContacts:
    """Slices at many mesh positions (rows) prepared for :func:`slice_loads` at any load, every row solved at once
    (:meth:`solve`, :meth:`totals`).

    ``stiffness`` k ≥ 0 and ``gap`` e (rows, slices) [N/m, m], k = 0 for a slice that cannot touch; ``touching``
    where k > 0; ``total_stiffness`` Σk and ``total_moment`` Σke of each row over its touching slices.

    δ of a row is Newton's method on the piecewise-linear, convex and increasing g(δ) = Σ k⟨δ − e⟩₊ started on the
    right, at the δ of every touching slice in contact: each step is δ = (F + Σ_A ke)/Σ_A k over the slices A
    with e < δ of the step before. The steps fall monotonically onto the root (g lies above each step's line) and
    A shrinks, so it ends, exactly, once A repeats: at once where every slice touches, in a few steps where the
    contact is partial. Nothing is sorted (the cost of a first call is a few passes over the slices)."""

    stiffness: np.ndarray
    gap: np.ndarray
    touching: np.ndarray
    total_stiffness: np.ndarray
    total_moment: np.ndarray

    @classmethod
    def prepare(cls, stiffness: np.ndarray, gap: np.ndarray) -> "SliceContacts":
        stiffness = np.asarray(stiffness, dtype=float)
        gap = np.broadcast_to(np.asarray(gap, dtype=float), stiffness.shape)
        if np.any(stiffness < 0.0):
            raise ValueError("slice_loads: a slice's stiffness is negative (0 for a slice that cannot touch)")
        touching = stiffness > 0.0
        if not np.all(np.any(touching, axis=-1)):
            raise ValueError("slice_loads: a positive load needs at least one slice that can touch")
        moment = np.multiply(stiffness, gap, out=np.zeros(stiffness.shape), where=touching)
        return cls(stiffness, gap, touching, stiffness.sum(axis=-1), moment.sum(axis=-1))

    def approach(self, load: float) -> np.ndarray:
        """δ [m] of each row at F = ``load`` [N] (class docstring): δ = (F + Σ_A ke)/Σ_A k over the slices A in
        contact, e < δ."""
        if not load > 0.0:
            raise ValueError("slice_loads: a positive load needs at least one slice that can touch")
        delta = (load + self.total_moment) / self.total_stiffness
        flat_delta = delta.reshape(-1)
        stiffness, gap, touching = (array.reshape(flat_delta.size, -1)
                                    for array in (self.stiffness, self.gap, self.touching))
        # the rows with a touching slice that the approach of all of them does not reach
        pending = np.flatnonzero(np.any(touching & (gap >= flat_delta[:, None]), axis=-1))
        active = touching[pending] & (gap[pending] < flat_delta[pending, None])
        for _ in range(gap.shape[-1]):  # A shrinks at every step that does not end a row
            if not pending.size:
                break
            row_stiffness, row_gap = stiffness[pending], gap[pending]
            contact = np.where(active, row_stiffness, 0.0)
            step = (load + np.sum(contact * np.where(active, row_gap, 0.0), axis=-1)) / np.sum(contact, axis=-1)
            flat_delta[pending] = step
            still = active & (row_gap < step[:, None])
            moved = np.any(still != active, axis=-1)
            pending, active = pending[moved], still[moved]
        return delta

    def carried(self, load: float) -> tuple[np.ndarray, np.ndarray]:
        """(δ [m] of each row, the slices' loads k⟨δ − e⟩₊ [N], rows × slices) at F = ``load`` [N]."""
        delta = self.approach(load)
        return delta, np.where(self.touching, self.stiffness * np.clip(delta[..., None] - self.gap, 0.0, None), 0.0)

    def solve(self, load: float) -> tuple[np.ndarray, np.ndarray]:
        """(δ [m] of each row, the slices' loads k⟨δ − e⟩₊ [N], rows × slices) at F = ``load`` [N]."""
        return self.carried(load)

    def totals(self, load: float, group: np.ndarray, groups: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(δ [m], the stiffness of the slices that carry load [N/m], the load [N] of each group of slices,
        rows × ``groups``) of each row at F = ``load`` [N]; ``group`` the group (0 … groups − 1) of each slice,
        e.g. its place across the face: one per column, or one per entry (rows × slices) where the rows hold
        different slices."""
        delta, carried = self.carried(load)
        engaged = np.sum(np.where(carried > 0.0, self.stiffness, 0.0), axis=-1)
        rows = np.arange(carried.shape[0])[:, None] * groups
        member = np.broadcast_to(np.asarray(group), carried.shape)
        per_group = np.bincount((rows + member).ravel(), weights=carried.ravel(),
                                minlength=carried.shape[0] * groups)
        return delta, engaged, per_group.reshape(carried.shape[0], groups)

    def engaged_groups(self, load: float, group: np.ndarray, groups: int) -> np.ndarray:
        """The stiffness [N/m] of the slices that carry load at F = ``load`` [N], summed per group (rows ×
        ``groups``; ``group`` as for :meth:`totals`)."""
        _, carried = self.carried(load)
        rows = np.arange(carried.shape[0])[:, None] * groups
        member = np.broadcast_to(np.asarray(group), carried.shape)
        per_group = np.bincount((rows + member).ravel(), weights=np.where(carried > 0.0, self.stiffness, 0.0).ravel(),
                                minlength=carried.shape[0] * groups)
        return per_group.reshape(carried.shape[0], groups)


@dataclass(frozen=True)
class FaceStiffnessMoments:
    """The moments across the face of the stiffness of the slices in contact, per mesh position φ: with z_j from
    mid-face, k₀ = Σk_j [N/m], k₁ = Σk_j z_j [N], k₂ = Σk_j z_j² [N·m]. They are what the mesh element of the
    drivetrain needs: Σ_j k_j w(z_j)w(z_j)ᵀ = k₀ w₀w₀ᵀ + k₁ (w₀w_zᵀ + w_zw₀ᵀ) + k₂ w_zw_zᵀ for w(z) = w₀ + z w_z
    (:mod:`thermogear.drivetrain.mesh_contact`), i.e. k(φ) at the load centre z̄(φ) = k₁/k₀ plus the tilting
    stiffness k(φ)ρ(φ)² = k₂ − k₁²/k₀ about it. The period means of k₀, k₁, k₂ give the mean matrix exactly: its load
    centre ``mean_load_centre`` and radius of gyration ``mean_gyration``."""

    phase: np.ndarray  # [m]
    stiffness: np.ndarray  # k₀(φ) [N/m]
    first_moment: np.ndarray  # k₁(φ) [N]
    second_moment: np.ndarray  # k₂(φ) [N·m]

    @classmethod
    def of_slices(cls, phase, stiffness, position) -> "FaceStiffnessMoments":
        """The moments of the slices' stiffness ``stiffness`` (..., slices) [N/m] at ``position`` z_j (slices,) [m]
        from mid-face, per mesh position ``phase`` [m]."""
        stiffness, position = np.asarray(stiffness, dtype=float), np.asarray(position, dtype=float)
        return cls(phase, stiffness.sum(axis=-1), stiffness @ position, stiffness @ position**2)

    @property
    def load_centre(self) -> np.ndarray:
        """z̄(φ) = k₁/k₀ [m] from mid-face."""
        return self.first_moment / self.stiffness

    @property
    def tilting_stiffness(self) -> np.ndarray:
        """k(φ)ρ(φ)² = k₂ − k₁²/k₀ [N·m]: the stiffness of the relative tilt about the load centre."""
        return self.second_moment - self.first_moment**2 / self.stiffness

    @property
    def mean_load_centre(self) -> float:
        """z̄ of the period-mean matrix, mean k₁ / mean k₀ [m] from mid-face."""
        return float(np.mean(self.first_moment) / np.mean(self.stiffness))

    @property
    def mean_gyration(self) -> float:
        """ρ of the period-mean matrix, √(mean k₂ / mean k₀ − z̄²) [m]."""
        centre = self.mean_load_centre
        return float(math.sqrt(max(np.mean(self.second_moment) / np.mean(self.stiffness) - centre**2, 0.0)))


@dataclass(frozen=True)
class FaceLoad:
    """The load along the face over a mesh period: ``line_load`` [N/m] per phase and slice (slice centres ``z`` [m]),
    the loaded static transmission error ``approach`` δ(φ) [m] along the transverse line of action."""

    z: np.ndarray
    phase: np.ndarray
    line_load: np.ndarray  # (phases, slices)
    approach: np.ndarray  # (phases,)
    engaged_stiffness: np.ndarray | None = None  # (phases, slices) [N/m]: the stiffness of the slices in contact

    @property
    def stiffness_moments(self) -> FaceStiffnessMoments:
        """The moments across the face of the stiffness in contact at each mesh position (z from mid-face; needs
        ``engaged_stiffness``)."""
        if self.engaged_stiffness is None:
            raise ValueError("stiffness_moments: the face load carries no engaged stiffness")
        return FaceStiffnessMoments.of_slices(self.phase, self.engaged_stiffness,
                                              self.z - 0.5 * (self.z[0] + self.z[-1]))

    @property
    def mean_line_load(self) -> np.ndarray:
        """w̄(z): the line load averaged over the mesh period [N/m]."""
        return self.line_load.mean(axis=0)

    @property
    def face_load_factor(self) -> float:
        """max_z w̄ / mean_z w̄ [–]: the distribution across the face (what ISO's K_Hβ describes)."""
        mean = self.mean_line_load
        return float(mean.max() / mean.mean())

    @property
    def peak_factor(self) -> float:
        """max over phase and face of w / mean w [–] (includes the variation in time, ISO's K_Hα/Z_ε part)."""
        return float(self.line_load.max() / self.line_load.mean())

    @property
    def load_centres(self) -> np.ndarray:
        """∫ z w dz / ∫ w dz [m] at each mesh position: where along the face the load acts over the period."""
        return self.line_load @ self.z / self.line_load.sum(axis=-1)

    @property
    def load_centre(self) -> float:
        """∫ z w̄ dz / ∫ w̄ dz [m]: where along the face the load acts on average."""
        mean = self.mean_line_load
        return float(np.sum(self.z * mean) / np.sum(mean))


def face_load(slice_stiffness: np.ndarray, z: np.ndarray, phase: np.ndarray, deviation: np.ndarray,
              load: float) -> FaceLoad:
    """Solve every mesh position: ``slice_stiffness`` (phases, contacts, slices) [N/m] — each slice's stiffness on
    each contact line, 0 where a line is out of the zone —, ``deviation`` e(z) per slice [m], transverse load
    F_bt [N]."""
    stiffness = np.asarray(slice_stiffness, dtype=float)
    width = float(z[1] - z[0]) if len(z) > 1 else 1.0
    gaps = np.broadcast_to(np.asarray(deviation, dtype=float), stiffness.shape)
    rows = stiffness.shape[0]
    approach, carried = SliceContacts.prepare(stiffness.reshape(rows, -1), gaps.reshape(rows, -1)).solve(load)
    carried = carried.reshape(stiffness.shape)
    loads = carried.sum(axis=1) / width
    engaged = np.where(carried > 0.0, stiffness, 0.0).sum(axis=1)
    return FaceLoad(np.asarray(z, dtype=float), np.asarray(phase, dtype=float), loads, approach, engaged)


def helix_slope_deviation(z, face_width: float, amount: float) -> np.ndarray:
    """e = f_Hβ·z/b [m]."""
    return amount * np.asarray(z, dtype=float) / face_width


def lead_crowning(z, face_width: float, amount: float) -> np.ndarray:
    """e = C_β(2z/b − 1)² [m]."""
    return amount * (2.0 * np.asarray(z, dtype=float) / face_width - 1.0) ** 2


def end_relief(z, face_width: float, amount: float, length: float) -> np.ndarray:
    """e = C_I·ξ/b_I at both ends, ξ the distance into the relief of length b_I [m]."""
    z = np.asarray(z, dtype=float)
    into = np.maximum(length - z, 0.0) + np.maximum(z - (face_width - length), 0.0)
    return amount * into / length


def thermal_lead_deviation(pinion_rise, wheel_rise, operating_pitch_radii: tuple[float, float],
                           operating_pressure_angle: float, expansion_per_k: tuple[float, float]) -> np.ndarray:
    """e_th(z) = −sin α_wt [λ_1 r_w1 ΔT_1(z) + λ_2 r_w2 ΔT_2(z)] [m] (module docstring): the temperature rises
    [K] of pinion and wheel at each slice."""
    return -math.sin(operating_pressure_angle) * (
        expansion_per_k[0] * operating_pitch_radii[0] * np.asarray(pinion_rise, dtype=float)
        + expansion_per_k[1] * operating_pitch_radii[1] * np.asarray(wheel_rise, dtype=float))


def iso_face_load_factor(mismatch: float, face_mesh_stiffness: float, mean_line_load: float) -> float:
    """ISO 6336-1 K_Hβ from the effective mismatch F_βy [m], c_γβ [N/m per m] and F_m/b [N/m]:
    1 + F_βy c_γβ/(2 F_m/b) up to 2, √(2 F_βy c_γβ/(F_m/b)) beyond."""
    ratio = mismatch * face_mesh_stiffness / mean_line_load
    return 1.0 + ratio / 2.0 if ratio <= 2.0 else math.sqrt(2.0 * ratio)
