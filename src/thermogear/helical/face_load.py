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

__all__ = ["slice_loads", "SliceContacts", "FaceLoad", "face_load", "helix_slope_deviation", "lead_crowning", "end_relief",
           "thermal_lead_deviation", "iso_face_load_factor"]


def slice_loads(stiffness: np.ndarray, gap: np.ndarray, load: float) -> tuple[float, np.ndarray]:
    """(δ [m], the slices' loads [N]) of Σ k_i⟨δ − e_i⟩₊ = F (module docstring), solved exactly on the sorted
    gaps: between consecutive gaps the left side is linear in δ."""
    stiffness = np.asarray(stiffness, dtype=float).ravel()
    approach, carried = SliceContacts.prepare(stiffness[None, :], np.asarray(gap, dtype=float).ravel()[None, :]) \
        .solve(load)
    return float(approach[0]), carried[0]


@dataclass(frozen=True, eq=False)
class SliceContacts:
    """Slices at many mesh positions (rows) prepared for :func:`slice_loads` at any load: what does not depend on
    the load — each row's touching slices sorted by gap, the running sums Σk and Σke over them — is computed once
    (:meth:`prepare`), and :meth:`solve` or :meth:`totals` take every row at once.

    ``stiffness`` k and ``gap`` e (rows, slices) [N/m, m]; ``order`` each row's slices that can touch (k > 0) by
    ascending gap, padded to the most any row has (the padding: k = 0, e = +∞); ``sorted_stiffness`` and
    ``sorted_gap`` k and e in that order, ``upper`` the next sorted gap (+∞ after the last);
    ``cumulative_stiffness`` and ``cumulative_moment`` Σk and Σke over the first m + 1 of them."""

    stiffness: np.ndarray
    gap: np.ndarray
    order: np.ndarray
    sorted_stiffness: np.ndarray
    sorted_gap: np.ndarray
    upper: np.ndarray
    cumulative_stiffness: np.ndarray
    cumulative_moment: np.ndarray

    @classmethod
    def prepare(cls, stiffness: np.ndarray, gap: np.ndarray) -> "SliceContacts":
        stiffness = np.asarray(stiffness, dtype=float)
        gap = np.broadcast_to(np.asarray(gap, dtype=float), stiffness.shape)
        touching = stiffness > 0.0
        counts = np.count_nonzero(touching, axis=-1)
        if not np.all(counts > 0):
            raise ValueError("slice_loads: a positive load needs at least one slice that can touch")
        order = np.argsort(np.where(touching, gap, np.inf), axis=-1, kind="stable")[..., :int(counts.max())]
        k = np.take_along_axis(stiffness, order, axis=-1)
        inside = k > 0.0  # the padding (rows with fewer touching slices) has k = 0
        e = np.where(inside, np.take_along_axis(gap, order, axis=-1), np.inf)
        moment = np.where(inside, k * np.where(inside, e, 0.0), 0.0)
        upper = np.concatenate([e[..., 1:], np.full(e.shape[:-1] + (1,), np.inf)], axis=-1)
        return cls(stiffness, gap, order, k, e, upper, np.cumsum(k, axis=-1), np.cumsum(moment, axis=-1))

    def approach(self, load: float) -> np.ndarray:
        """δ [m] of each row at F = ``load`` [N]: with exactly the first m + 1 sorted slices touching,
        δ = (F + Σke)/Σk, the m whose δ lies between its gap and the next one's."""
        if not load > 0.0:
            raise ValueError("slice_loads: a positive load needs at least one slice that can touch")
        candidates = (load + self.cumulative_moment) / self.cumulative_stiffness
        first = np.argmax((candidates >= self.sorted_gap) & (candidates <= self.upper), axis=-1)
        return np.take_along_axis(candidates, first[..., None], axis=-1)[..., 0]

    def solve(self, load: float) -> tuple[np.ndarray, np.ndarray]:
        """(δ [m] of each row, the slices' loads k⟨δ − e⟩₊ [N], rows × slices) at F = ``load`` [N]."""
        delta = self.approach(load)
        touching = self.stiffness > 0.0
        return delta, self.stiffness * np.clip(delta[..., None] - self.gap, 0.0, None) * touching

    def totals(self, load: float, group: np.ndarray, groups: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(δ [m], the stiffness of the slices that carry load [N/m], the load [N] of each group of slices,
        rows × ``groups``) of each row at F = ``load`` [N], from the touching slices only; ``group`` the group
        (0 … groups − 1) of each slice, e.g. its place across the face."""
        delta = self.approach(load)
        carried = self.sorted_stiffness * np.clip(delta[..., None] - self.sorted_gap, 0.0, None)
        engaged = np.sum(np.where(carried > 0.0, self.sorted_stiffness, 0.0), axis=-1)
        rows = np.arange(carried.shape[0])[:, None] * groups
        per_group = np.bincount((rows + np.asarray(group)[self.order]).ravel(), weights=carried.ravel(),
                                minlength=carried.shape[0] * groups)
        return delta, engaged, per_group.reshape(carried.shape[0], groups)


@dataclass(frozen=True)
class FaceLoad:
    """The load along the face over a mesh period: ``line_load`` [N/m] per phase and slice (slice centres ``z`` [m]),
    the loaded static transmission error ``approach`` δ(φ) [m] along the transverse line of action."""

    z: np.ndarray
    phase: np.ndarray
    line_load: np.ndarray  # (phases, slices)
    approach: np.ndarray  # (phases,)

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
    loads = carried.reshape(stiffness.shape).sum(axis=1) / width
    return FaceLoad(np.asarray(z, dtype=float), np.asarray(phase, dtype=float), loads, approach)


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
