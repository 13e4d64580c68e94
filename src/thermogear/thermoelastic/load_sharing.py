"""Quasi-static load sharing of tooth pairs with deviations: the loaded static transmission error.

At each mesh position the approach δ of the gear bodies along the line of action solves

    Σ_i k_i·⟨δ − e_i⟩₊ = W,      ⟨u⟩₊ = max(u, 0)

(pairs engage only when the approach exceeds their unloaded deviation e_i; Lin, Townsend & Oswald 1986, ASME
J. Mech. Trans. Autom. Des. 108(1):86, compute static transmission error and load sharing this way). The left side
is continuous, piecewise linear and increasing in δ, so the root is exact: with the pairs sorted by deviation and
the first j engaged, δ_j = (W + Σ_{i≤j} k_i e_i)/Σ_{i≤j} k_i, and the answer is the first j with δ_j ≤ e_{j+1}
(Σ k⟨e_{j+1} − e⟩₊ ≥ W). Vectorised over positions.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, eq=False)
class LoadedTransmissionError:
    """Loaded static transmission error over mesh positions (arrays (pairs, positions) or (positions,))."""

    approach: np.ndarray  # δ, the loaded static transmission error along the line of action [m]
    load_share: np.ndarray  # k_i⟨δ − e_i⟩₊ / W [–], (pairs, positions)
    contact_stiffness: np.ndarray  # Σ k_i over the pairs with δ > e_i [N/m]
    engaged: np.ndarray  # δ > e_i and the pair on the path, (pairs, positions)

    @property
    def peak_to_peak(self) -> float:
        """max δ − min δ [m]."""
        return float(np.ptp(self.approach))


def loaded_transmission_error(stiffness, deviation, normal_load: float, active=None) -> LoadedTransmissionError:
    """Solve Σ_i k_i⟨δ − e_i⟩₊ = W exactly at every position (module docstring).

    ``stiffness`` k_i [N/m] and ``deviation`` e_i [m]: arrays (pairs, positions); ``active``: bool (pairs,
    positions), the pairs on the path of contact (default: all with k_i > 0); ``normal_load`` W > 0 [N].
    """
    stiffness = np.asarray(stiffness, dtype=float)
    deviation = np.asarray(deviation, dtype=float)
    if not normal_load > 0.0:
        raise ValueError("loaded_transmission_error: the normal load must be positive")
    active = stiffness > 0.0 if active is None else np.asarray(active, dtype=bool) & (stiffness > 0.0)
    if not np.all(active.any(axis=0)):
        raise ValueError("loaded_transmission_error: a mesh position has no tooth pair on the path of contact")
    key = np.where(active, deviation, np.inf)
    order = np.argsort(key, axis=0, kind="stable")
    sorted_key = np.take_along_axis(key, order, axis=0)
    sorted_k = np.where(np.isfinite(sorted_key), np.take_along_axis(stiffness, order, axis=0), 0.0)
    sorted_e = np.where(np.isfinite(sorted_key), sorted_key, 0.0)
    cumulative_k = np.cumsum(sorted_k, axis=0)
    cumulative_ke = np.cumsum(sorted_k * sorted_e, axis=0)
    with np.errstate(divide="ignore", invalid="ignore"):
        candidate = np.where(cumulative_k > 0.0, (normal_load + cumulative_ke) / cumulative_k, np.inf)
    following = np.vstack([sorted_key[1:], np.full((1, sorted_key.shape[1]), np.inf)])
    valid = candidate <= following
    first = np.argmax(valid, axis=0)
    approach = np.take_along_axis(candidate, first[None, :], axis=0)[0]
    engaged = active & (approach[None, :] > deviation)
    share = np.where(engaged, stiffness * (approach[None, :] - deviation), 0.0) / normal_load
    contact = np.where(engaged, stiffness, 0.0).sum(axis=0)
    return LoadedTransmissionError(approach, share, contact, engaged)
