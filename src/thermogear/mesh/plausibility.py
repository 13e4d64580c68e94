"""Checks of a thermal result before it is shown: what heat can and cannot do to a gear mesh.

A thermal model that changes the mesh stiffness by far more than Young's modulus at temperature and the operating
geometry can (E falls by about 0.033 %/K for carbon and low-alloy steels: Roark's table of E against temperature),
a frequency ratio near a resonance of the mesh, or a negative amplitude are said in words beside the result.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from thermogear.mesh.model import MeshModel
from thermogear.mesh.state import MeshState
from thermogear.thermoelastic.materials import MODULUS_TEMPERATURE_COEFFICIENTS_PER_K

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
#: Slack on the stiffness change that E(T) explains before a thermal model's change is flagged [–]: the operating
#: geometry (contact ratio at temperature) moves the mean stiffness by up to about 2 % for the usual rises.
GEOMETRY_SLACK = 0.02


def thermal_result_flags(mesh: MeshModel, state: MeshState, metrics: dict[str, Any]) -> tuple[str, ...]:
    """Findings that make a result doubtful, in words (empty when nothing is flagged)."""
    flags: list[str] = []
    if mesh.thermoelastic and mesh.thermoelastic_mesh is not None:
        flags += list(mesh.thermoelastic_mesh.plausibility)
    if mesh.thermal_model == "luo2020":
        field = mesh.temperature
        gamma = np.linspace(-0.5, 0.5, 21)
        rise = float(np.max(np.asarray(field.pinion_flank_c(gamma), float))) - field.reference_c
        steepest = max(abs(value) for value in MODULUS_TEMPERATURE_COEFFICIENTS_PER_K.values())
        modulus_limit = steepest * max(rise, 0.0)
        elastic = MeshModel(mesh.case, "elastic").state(speed_rpm=state.speed_rpm, normal_load=state.normal_load,
                                                       points_per_period=state.grid.nodes.size - 1, damping=False)
        change = state.mean_mesh_stiffness / elastic.mean_mesh_stiffness - 1.0
        if change < -(modulus_limit + GEOMETRY_SLACK):
            flags.append(f"the paper's secant k_T lowers the mean mesh stiffness by {-100 * change:.1f} %, more than "
                         f"Young's modulus at a {rise:.0f} K rise can ({100 * modulus_limit:.1f} %): it rests on the "
                         "factor X_te; [thermal] model = \"thermoelastic\" predicts without it")
    if mesh.thermal_model == "luo2020" and metrics.get("mesh") == "nonlinear":
        flags.append(secant_stiffness_in_nonlinear_mesh(metrics.get("contact_loss_fraction") or 0.0))
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


def secant_stiffness_in_nonlinear_mesh(contact_loss_fraction: float) -> str:
    """Why the paper's k_T has no meaning as the contact stiffness of the nonlinear mesh.

    k_T = F_n/Δ_te (Luo & Li 2020 Eqs. 17–18) is a secant stiffness, computed at the static load: it falls to 0 as
    F_n → 0 and rises to k_e as F_n → ∞. The nonlinear mesh uses it as the slope of the contact force at every
    deflection; as the mesh force swings away from the static load that slope is no longer the secant the paper
    defines, and once the teeth separate (force 0) the secant at that load would be 0, not the static value."""
    where = (f"here the teeth separate for {100 * contact_loss_fraction:.1f} % of the period, where it has no "
             "meaning at all" if contact_loss_fraction > 0.0 else
             "it holds only while the mesh force stays near the static load")
    return ("the paper's k_T (thermal.model = 'luo2020') is a secant stiffness at the static load (Luo & Li Eq. 18), "
            f"used by the nonlinear mesh as the contact stiffness at every deflection: {where}; use thermal.model = "
            "'thermoelastic' (a tangent stiffness with E(T) and the backlash at temperature) for the nonlinear mesh, "
            "or dynamics.mesh = 'linear' to reproduce the paper")


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
