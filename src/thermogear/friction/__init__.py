"""Mean tooth friction coefficient of DIN 3990-4 / ISO/TR 13989-1 (Luo & Li (2020) Eq. 27, ISO/TR 13989-1).

    μ_m = 0.12 · ( w_Bt · R_a / (η · v_Σ · ρ_red) )^0.25 · X_L

with the standard's units **inside** the function only: w_Bt [N/mm], R_a [μm], η [mPa·s], v_Σ [m/s], ρ_red [mm].
Arguments and result are SI. Luo & Li apply the formula locally along the path of contact (local relative radius
of curvature, local sum of rolling speeds, the pair's share of the load, viscosity at the local temperature).
"""

from __future__ import annotations

import warnings

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning

#: Leading constant of the DIN 3990-4 / ISO/TR 13989-1 mean friction coefficient.
FRICTION_CONSTANT = 0.12
#: Usual validity limits of the formula (ISO/TR 13989-1, recalled [R]): sum of rolling speeds at most 50 m/s,
#: transverse unit load at least 150 N/mm.
MAXIMUM_SUM_VELOCITY = 50.0  # [m/s]
MINIMUM_UNIT_LOAD = 150e3  # [N/m]


def friction_validity_warnings(unit_load, sum_velocity, stacklevel: int = 3) -> None:
    """Warn (ExtrapolationWarning) where the friction formula's usual limits are left, saying by how much.

    ``unit_load`` [N/m] is the transverse unit load the standard means (w_Bt = F_bt/b of the gear pair),
    ``sum_velocity`` [m/s] the sum of rolling speeds.
    """
    load = np.asarray(unit_load, dtype=float)
    velocity = np.asarray(sum_velocity, dtype=float)
    if load.size and float(np.min(load)) < MINIMUM_UNIT_LOAD:
        warnings.warn(f"friction coefficient (DIN 3990-4): unit load {float(np.min(load)) * 1e-3:.1f} N/mm is "
                      f"{(MINIMUM_UNIT_LOAD - float(np.min(load))) * 1e-3:.1f} N/mm below the formula's usual lower "
                      f"limit {MINIMUM_UNIT_LOAD * 1e-3:.0f} N/mm", ExtrapolationWarning, stacklevel=stacklevel)
    if velocity.size and float(np.max(velocity)) > MAXIMUM_SUM_VELOCITY:
        warnings.warn(f"friction coefficient (DIN 3990-4): sum of rolling speeds {float(np.max(velocity)):.1f} m/s "
                      f"is {float(np.max(velocity)) - MAXIMUM_SUM_VELOCITY:.1f} m/s above the formula's usual "
                      f"upper limit {MAXIMUM_SUM_VELOCITY:.0f} m/s", ExtrapolationWarning, stacklevel=stacklevel)


def mean_friction_coefficient(unit_load, roughness, dynamic_viscosity, sum_velocity, relative_radius,
                              lubricant_factor: float = 1.0, check_limits: bool = True):
    """Mean friction coefficient μ_m [–] of DIN 3990-4 / ISO/TR 13989-1 (Luo & Li (2020) Eq. 27).

    Parameters (SI, arrays broadcast)
    ----------
    unit_load: normal load per unit face width [N/m] (w_Bt; Luo & Li: the pair's share, locally)
    roughness: composite arithmetic mean roughness R_a = (R_a1 + R_a2)/2 [m]
    dynamic_viscosity: η [Pa·s]
    sum_velocity: sum of rolling speeds v_Σ = v1 + v2 [m/s]
    relative_radius: relative radius of curvature ρ_red = ρ1ρ2/(ρ1+ρ2) [m]
    lubricant_factor: X_L [–] (1 mineral oil)
    check_limits: warn where the usual limits (v_Σ ≤ 50 m/s, w ≥ 150 N/mm) are left

    The formula has no meaning at standstill (v_Σ → 0 makes μ → ∞): a zero or negative sum velocity raises
    CaseError naming ``operating.speed_rpm``.
    """
    load = np.asarray(unit_load, dtype=float)
    roughness = np.asarray(roughness, dtype=float)
    viscosity = np.asarray(dynamic_viscosity, dtype=float)
    velocity = np.asarray(sum_velocity, dtype=float)
    radius = np.asarray(relative_radius, dtype=float)
    if np.any(~(velocity > 0.0)):
        raise CaseError("operating.speed_rpm", float(np.min(velocity)), "a speed > 0 (sum of rolling speeds > 0)",
                        "the DIN 3990-4 friction formula is undefined at standstill (it divides by the sum of "
                        "rolling speeds); a gear at rest has no friction damping of this kind")
    if np.any(~(roughness >= 0.0)):
        raise CaseError("gears.roughness_ra_um", float(np.min(roughness)) * 1e6, ">= 0",
                        "a roughness cannot be negative")
    if np.any(~(load >= 0.0)):
        raise CaseError("unit_load", float(np.min(load)), ">= 0 N/m",
                        "the tooth normal load is compressive (a negative load means the teeth separate)")
    if np.any(~(viscosity > 0.0)):
        raise CaseError("lubricant", float(np.min(viscosity)), "a dynamic viscosity > 0",
                        "the friction formula needs a lubricated contact")
    if np.any(~(radius > 0.0)):
        raise CaseError("relative_radius", float(np.min(radius)), "> 0",
                        "the contact lies outside the involute flanks")
    if not lubricant_factor > 0.0:
        raise CaseError("damping.lubricant_factor", lubricant_factor, "> 0", "X_L scales the friction coefficient")
    if check_limits:
        friction_validity_warnings(load, velocity)
    # DIN 3990-4 units: N/mm, μm, mPa·s, m/s, mm
    group = (load * 1e-3) * (roughness * 1e6) / ((viscosity * 1e3) * velocity * (radius * 1e3))
    return FRICTION_CONSTANT * group**0.25 * lubricant_factor


__all__ = ["FRICTION_CONSTANT", "MAXIMUM_SUM_VELOCITY", "MINIMUM_UNIT_LOAD", "friction_validity_warnings",
           "mean_friction_coefficient"]
