"""Contact lines of a helical pair on the plane of action, and their total length over the mesh cycle.

The zone of action is the rectangle g_α (the transverse path A…E) × b (the face). Contact lines are straight,
inclined at β_b to the axis, one transverse base pitch p_bt apart along the path. A line that enters the face at
path position s reaches s + g_β at the other end face (g_β = b tan β_b), so its length inside the zone is

    ℓ(s) = |[s, s + g_β] ∩ [0, g_α]| / sin β_b                  (β_b > 0; a spur line: b where 0 ≤ s ≤ g_α)

and the total L(φ) = Σ_k ℓ(φ + k p_bt) repeats with the mesh period (φ advancing at r_b1·ω1). In units of p_bt the
sum is the periodic convolution of a box of width ε_α with one of width ε_β, which gives its mean and extremes in
closed form (derived here, and checked against the sum in the tests) with n_α, n_β the fractional parts:

    L_mean = b ε_α / cos β_b
    L_min  = L_mean [1 − n_α n_β/(ε_α ε_β)]                 (n_α + n_β ≤ 1)
           = L_mean [1 − (1 − n_α)(1 − n_β)/(ε_α ε_β)]     (n_α + n_β > 1)
    L_max  = L_mean [1 + (min(n_α, n_β) − n_α n_β)/(ε_α ε_β)]

(derivation: the integer parts of the two boxes add constants; the two fractional boxes convolve to a trapezoid
of height min(n_α, n_β) that wraps onto itself where n_α + n_β > 1). L is constant when ε_α or ε_β is an integer.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["contact_line_length", "total_contact_length", "contact_length_extremes", "contact_line_segments",
           "zone_line_entries"]


def contact_line_length(entry, path_length: float, face_width: float, base_helix_angle: float) -> np.ndarray:
    """ℓ [m] of the contact lines entering the face at path positions ``entry`` [m] (0 at A) (module docstring)."""
    entry = np.asarray(entry, dtype=float)
    if base_helix_angle == 0.0:
        return np.where((entry >= 0.0) & (entry <= path_length), face_width, 0.0)
    advance = face_width * math.tan(base_helix_angle)
    overlap = np.clip(np.minimum(entry + advance, path_length) - np.maximum(entry, 0.0), 0.0, None)
    return overlap / math.sin(base_helix_angle)


def line_entries(phase, path_length: float, advance: float, base_pitch: float) -> np.ndarray:
    """Entry positions φ + k p_bt [m] of every line that may touch the zone, shape (..., lines): k from the first
    line whose far end reaches A (s + g_β ≥ 0) to the last that starts before E."""
    phase = np.asarray(phase, dtype=float)[..., None]
    first = -math.ceil((advance + base_pitch) / base_pitch)
    last = math.ceil(path_length / base_pitch) + 1
    return phase + base_pitch * np.arange(first, last + 1)


def zone_line_entries(phase, path_length: float, advance: float, base_pitch: float) -> np.ndarray:
    """Entry positions φ + k p_bt [m] of the lines that touch the zone at each phase, shape (..., lines): each row
    from its own first line whose far end reaches A, as many lines as the row that needs most (a row needing fewer
    ends with lines past E, which touch nothing). The same values as :func:`line_entries` for every line that
    touches; it leaves out those that touch at no phase of its row (a fraction of them where ε_β is small: the
    arrays of slices on lines are that much shorter). The test is widened by 1e-9 of g_α + g_β, so a line that
    reaches the zone by rounding only is kept."""
    entries = line_entries(phase, path_length, advance, base_pitch)
    first_line = -math.ceil((advance + base_pitch) / base_pitch)  # line_entries' first k
    margin = 1e-9 * (path_length + advance)
    touching = (entries + advance >= -margin) & (entries <= path_length + margin)
    first = np.argmax(touching, axis=-1)
    last = touching.shape[-1] - 1 - np.argmax(touching[..., ::-1], axis=-1)
    count = int(np.max(np.where(touching.any(axis=-1), last - first + 1, 1), initial=1))
    lines = first_line + first[..., None] + np.arange(count)
    return np.asarray(phase, dtype=float)[..., None] + base_pitch * lines


def total_contact_length(phase, path_length: float, face_width: float, base_helix_angle: float,
                         base_pitch: float) -> np.ndarray:
    """L(φ) = Σ_k ℓ(φ + k p_bt) [m] at mesh phases φ [m] along the path (module docstring)."""
    advance = face_width * math.tan(base_helix_angle)
    entries = line_entries(phase, path_length, advance, base_pitch)
    return contact_line_length(entries, path_length, face_width, base_helix_angle).sum(axis=-1)


def contact_length_extremes(transverse_ratio: float, overlap_ratio: float, face_width: float,
                            base_helix_angle: float) -> tuple[float, float, float]:
    """(L_mean, L_min, L_max) [m] in closed form (module docstring); ε_β = 0 gives the spur values
    ⌊ε_α⌋b … ⌈ε_α⌉b."""
    mean = face_width * transverse_ratio / math.cos(base_helix_angle)
    n_alpha = transverse_ratio - math.floor(transverse_ratio)
    if overlap_ratio == 0.0:
        low, high = math.floor(transverse_ratio), math.floor(transverse_ratio) + (n_alpha > 0.0)
        return mean, face_width * low, face_width * high
    n_beta = overlap_ratio - math.floor(overlap_ratio)
    product = transverse_ratio * overlap_ratio
    if n_alpha + n_beta <= 1.0:
        low = 1.0 - n_alpha * n_beta / product
    else:
        low = 1.0 - (1.0 - n_alpha) * (1.0 - n_beta) / product
    high = 1.0 + (min(n_alpha, n_beta) - n_alpha * n_beta) / product
    return mean, mean * low, mean * high


def contact_line_segments(phase: float, path_length: float, face_width: float, base_helix_angle: float,
                          base_pitch: float) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The contact lines inside the zone of action at mesh phase ``phase`` [m], each as its two ends
    ((s, z), (s, z)) [m] (s along the transverse path from A, z across the face): the line entering at s_0 is
    s(z) = s_0 + z tan β_b, clipped to 0 ≤ s ≤ g_α and 0 ≤ z ≤ b."""
    slope = math.tan(base_helix_angle)
    advance = face_width * slope
    segments = []
    for entry in line_entries(float(phase), path_length, advance, base_pitch):
        if slope == 0.0:
            if 0.0 <= entry <= path_length:
                segments.append(((float(entry), 0.0), (float(entry), face_width)))
            continue
        low = max(0.0, -entry / slope)
        high = min(face_width, (path_length - entry) / slope)
        if low < high:
            segments.append(((float(entry + low * slope), low), (float(entry + high * slope), high)))
    return segments
