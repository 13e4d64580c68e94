"""Checks of the paper's secant thermal stiffness k_T (Luo & Li (2020) Eqs. 17–18) on a result, in words.

What heat can do to a gear mesh's stiffness: Young's modulus falls by about 0.033 %/K for carbon and low-alloy steels
(Roark's table of E against temperature), and the operating geometry moves the mean stiffness by a little more. A
k_T that lowers the mean stiffness by far more than that rests on the factor X_te; and k_T is a secant at the
static load, which the nonlinear mesh would use as a contact stiffness at every deflection.
"""

from __future__ import annotations

import numpy as np

from thermogear.temperature.field import TemperatureField
from thermogear.thermoelastic.materials import MODULUS_TEMPERATURE_COEFFICIENTS_PER_K

#: Slack on the stiffness change that E(T) explains before a thermal model's change is flagged [–]: the operating
#: geometry (contact ratio at temperature) moves the mean stiffness by up to about 2 % for the usual rises.
GEOMETRY_SLACK = 0.02



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


def secant_stiffness_drop_flag(temperature: TemperatureField, mean_stiffness: float,
                               elastic_mean_stiffness: float) -> str | None:
    """The change of the mean mesh stiffness [N/m → –] against the elastic model when it exceeds what Young's
    modulus at the largest flank rise and the operating geometry (:data:`GEOMETRY_SLACK`) can explain; else None."""
    gamma = np.linspace(-0.5, 0.5, 21)
    rise = float(np.max(np.asarray(temperature.pinion_flank_c(gamma), float))) - temperature.reference_c
    steepest = max(abs(value) for value in MODULUS_TEMPERATURE_COEFFICIENTS_PER_K.values())
    modulus_limit = steepest * max(rise, 0.0)
    change = mean_stiffness / elastic_mean_stiffness - 1.0
    if change >= -(modulus_limit + GEOMETRY_SLACK):
        return None
    return (f"the paper's secant k_T lowers the mean mesh stiffness by {-100 * change:.1f} %, more than "
            f"Young's modulus at a {rise:.0f} K rise can ({100 * modulus_limit:.1f} %): it rests on the "
            "factor X_te; [thermal] model = \"thermoelastic\" predicts without it")


__all__ = ["GEOMETRY_SLACK", "secant_stiffness_drop_flag", "secant_stiffness_in_nonlinear_mesh"]
