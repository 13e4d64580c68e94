"""What the numbers of ``thermogear fem`` mean, in words, from the case's own content.

The FE run reads the factor X_te of the paper's secant stiffness k_T = F_n·k_e/(F_n + X_te·k_e·ΣΔ_t) (Luo & Li
2020 Eqs. 17–18) and the stiffness drop 1 − k_T/k_e that this X_te gives. Neither is a property of the teeth:
X_te has no unique FE definition (the magnitude and the line-of-action readings differ in size and sign), and the
drop is that of a secant stiffness, which depends on the load (→ 0 at no load). What heat itself does to the
stiffness of a steel tooth is bounded by Young's modulus at temperature: E falls by at most |β_E|·ΔT (Roark's
table of E against temperature: β_E ≈ −3.3e-4 /K for carbon, C–Mo and nickel steels). A case that calibrates X_te
to a published drop reproduces that drop by construction; for any other pair the paper's model is not predictive.
"""

from __future__ import annotations

from thermogear.choices.thermal_models import x_te_source
from thermogear.thermoelastic.materials import MODULUS_TEMPERATURE_COEFFICIENTS_PER_K

__all__ = ["fem_interpretation"]


def fem_interpretation(reference_c: float, thermal, summary: dict) -> dict:
    """``{"youngs_modulus_change_limit_percent", "notes"}`` for the summary of a case's FE run (module docstring),
    given the case's reference temperature ``reference_c`` [°C] and ``[thermal]`` section: the largest stiffness
    drop E(T) explains at the FE pitch-point flank temperature [%], and the notes in words."""
    rise = float(summary["flank_temperature_c"]["C"]) - reference_c
    steepest = max(abs(value) for value in MODULUS_TEMPERATURE_COEFFICIENTS_PER_K.values())
    limit = 100.0 * steepest * max(rise, 0.0)
    drop = float(summary["stiffness_drop_percent"]["C"])
    notes = [
        f"X_te = {summary['x_te']:.4g} is the factor of the paper's secant stiffness k_T = F_n·k_e/(F_n + "
        "X_te·k_e·ΣΔ_t) (Luo & Li 2020 Eqs. 17–18), read from the FE as the paper does (§5.1): the growth of the "
        "meshing-point displacement magnitude under the temperature rise over the flank expansion of Eqs. 8–12; read "
        f"along the line of action it is {summary['x_te_line_of_action']:.4g}: the factor has no unique definition, "
        "so neither number is a property of the teeth",
        f"the stiffness drop of {drop:.1f} % at the pitch point is what the paper's model gives with this X_te at this "
        f"load and these temperatures; Young's modulus at the flank temperature ({rise:+.0f} K) lowers a steel "
        f"tooth's stiffness by at most {limit:.1f} %: the rest is the secant construction (it depends on the load and "
        "tends to 0 without load), not a softer tooth",
    ]
    if x_te_source(thermal.x_te_source).calibrated and thermal.calibration_drop_percent is not None:
        notes.append(f"this case calibrates X_te to a {thermal.calibration_drop_percent:g} % drop at "
                     f"{thermal.calibration_point}: the paper's model reproduces that drop by construction, and the FE "
                     "X_te is a check of the calibration, not a prediction")
    else:
        notes.append("the paper's model is not predictive for this pair (its X_te was calibrated to one published "
                     "drop of one pair); the thermo-elastic model (thermal.model = 'thermoelastic', the default) "
                     "predicts without a fitted factor: see `thermogear stiffness CASE --thermal`")
    return {"youngs_modulus_change_limit_percent": limit, "notes": notes}
