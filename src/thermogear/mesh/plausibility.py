"""Checks of a thermal result before it is shown: what heat can and cannot do to a gear mesh.

What a pair model finds doubtful in its own result (the paper's k_T: :mod:`thermogear.mesh.secant_checks`; the
thermo-elastic component's plausibility), a frequency ratio near a resonance of the mesh, a negative amplitude or a
damping ratio no gear mesh has are said in words beside the result.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.case import cached_per_case
from thermogear.mesh.model import MeshModel
from thermogear.mesh.state import MeshState

__all__ = ["DAMPING_RATIO_LIMIT", "MEASURED_DAMPING_RATIO_RANGE", "damping_ratio_flags", "thermal_result_flags"]

#: Measured gear-mesh damping ratios lie around 0.03–0.17 [–]: the range gear-dynamics studies quote and use (e.g.
#: Kahraman & Singh 1990, J. Sound Vib. 142(1)); its attribution to the measurements of Gregory, Harris & Munro
#: (1963) is recalled, not verified here.
MEASURED_DAMPING_RATIO_RANGE = (0.03, 0.17)
#: Mean mesh damping ratio above which a result is flagged [–]: twice the top of the measured range. The mean
#: oscillator's ζ (time means of c and k) is itself an approximation of a periodic system, and the measured range
#: is a spread over rigs, not a bound, so a factor of two keeps the flag for damping no mesh has (resonance
#: amplification 1/(2ζ) below about 1.5: a mesh resonance that hardly shows) and off ordinary values. Luo & Li's own
#: thermal damping (their Table 1 pair, c_r = 1.68·c_e) gives 0.30, below it.
DAMPING_RATIO_LIMIT = 2.0 * MEASURED_DAMPING_RATIO_RANGE[1]

#: A frequency ratio f_mesh/f_n within this fraction of 1/j (j = 1, 2, 3) is flagged as near the j-th resonance.
RESONANCE_MARGIN = 0.10


@cached_per_case
def elastic_stiffness_memo() -> dict:
    """The elastic model's mean mesh stiffness of a case by (normal load, points per period): one memo per case,
    dropped with the case (:func:`thermogear.case.cached_per_case`). Without the speed: the elastic stiffness of a
    position does not depend on it, and the period's time mean of k(τ) is its mean over the path (uniform speed), so
    every point of a speed sweep at one load asks the same value."""
    return {}


def thermal_result_flags(mesh: MeshModel, state: MeshState, metrics: dict[str, Any]) -> tuple[str, ...]:
    """Findings that make a result doubtful, in words (empty when nothing is flagged): the pair model's own
    (:meth:`~thermogear.mesh.pair_models.PairModelBase.result_flags`), then a resonance or a negative amplitude."""
    flags: list[str] = []

    def elastic_mean_stiffness() -> float:  # the elastic model at the same load: what heat changed
        points = state.grid.nodes.size - 1
        memo = elastic_stiffness_memo(mesh.case)
        key = (float(state.normal_load), points)
        if key not in memo:
            elastic = MeshModel(mesh.case, "elastic").state(speed_rpm=state.speed_rpm, normal_load=state.normal_load,
                                                           points_per_period=points, damping=False)
            memo[key] = elastic.mean_mesh_stiffness
        return memo[key]

    flags += mesh.pair_model.result_flags(state.mean_mesh_stiffness, metrics, elastic_mean_stiffness)
    ratio = metrics.get("frequency_ratio")
    if ratio is not None and np.isfinite(ratio):
        for order in (1, 2, 3):
            if abs(ratio * order - 1.0) < RESONANCE_MARGIN:
                flags.append(f"the frequency ratio f_mesh/f_n = {ratio:.3f} is within {100 * RESONANCE_MARGIN:.0f} % "
                             f"of the {'primary' if order == 1 else f'order-{order}'} resonance (f_mesh = f_n/{order})")
    amplitudes = metrics.get("amplitude_per_region") or {}
    negative = [name for name, value in amplitudes.items() if np.isfinite(value) and value < 0.0]
    if negative:
        flags.append("a negative amplitude (peak below the static equilibrium) in the " + ", ".join(negative)
                     + " region: the response there is dominated by the jumps between regions, not by a vibration "
                       "about the equilibrium")
    return tuple(flags)


def damping_ratio_flags(state: MeshState) -> tuple[str, ...]:
    """The damping ratio of a mesh period when no gear mesh has it (above :data:`DAMPING_RATIO_LIMIT`), in words;
    the result is kept."""
    ratio = state.damping_ratio
    if not (np.isfinite(ratio) and ratio > DAMPING_RATIO_LIMIT):
        return ()
    low, high = MEASURED_DAMPING_RATIO_RANGE
    return (f"damping ratio ζ = {ratio:.2f} (mean c over 2·sqrt(mean k·me)) is above {DAMPING_RATIO_LIMIT:.2f}, more "
            f"than any gear mesh has (measured ratios lie around {low:g}–{high:g}): the friction damping of Luo & Li Eq. 28 "
            f"grows as 1/speed, so at {state.speed_rpm:g} rpm the amplitudes and Kv are damped far more than in a "
            "real mesh; the result is kept, read it as a lower bound of the vibration",)
