"""Is the load one a steel tooth can carry? Nominal contact and root stresses and the static deflection of a case,
compared with what the best gear steels carry, so that an absurd load is labelled beside the result.

The dynamics of the project are linear-elastic in the teeth: they compute a result for any load, and a torque of
10⁷ N·m on a module-0.5 pair gave a transmission error of 5.4 m called valid (issue 25). These checks say so in
words; the results stay.

- Contact stress at the pitch point, ISO 6336-2 (nominal, all K factors 1): σ_H0 = Z_H Z_E Z_ε √(F_t (u + 1)/
  (b d₁ u)), Z_H = √(2 cos α_w / (cos²α sin α_w)), Z_E = √(1/(π[(1 − ν²)/E + (1 − ν²)/E])), Z_ε = √((4 − ε_α)/3).
- Root stress, ISO 6336-3 form: σ_F0 = F_t Y_FS / (b m) with the combined form and stress-correction factor Y_FS
  taken at 4.0, below its usual range for external spur teeth (about 4.2 to 5), so the flag is conservative.
- Static deflection of the mesh: δ = F_bt / (b c_γα) with ISO 6336-1's mean mesh stiffness c_γα (clause 9).

Limits (assumptions of this project: recalled from ISO 6336-5 and ISO 6336-2/-3, not re-read): the best case-
hardened gear steels have σ_H,lim ≈ 1500 N/mm² and σ_FE ≈ 1000 N/mm²; under static load the life factors allow
about 1.6 × and 2.5 × that. A stress above :data:`CONTACT_LIMIT_PA` or :data:`ROOT_LIMIT_PA`, or a deflection
above :data:`DEFLECTION_LIMIT_MODULES` of the module, is flagged.
"""

from __future__ import annotations

import math

from thermogear.stiffness.iso6336 import iso6336_stiffness

__all__ = ["CONTACT_LIMIT_PA", "DEFLECTION_LIMIT_MODULES", "ROOT_LIMIT_PA", "load_flags", "nominal_stresses"]

#: Static contact strength of the best case-hardened steels [Pa]: σ_H,lim 1500 N/mm² × static life factor 1.6.
CONTACT_LIMIT_PA = 1500e6 * 1.6
#: Static root strength of the best case-hardened steels [Pa]: σ_FE 1000 N/mm² × static life factor 2.5.
ROOT_LIMIT_PA = 1000e6 * 2.5
#: Largest static mesh deflection as a share of the module [–]: a tenth of the module is about the tip relief of a
#: heavily loaded gear and far beyond the small deflections the stiffness models assume.
DEFLECTION_LIMIT_MODULES = 0.1
#: Combined tooth form and stress-correction factor Y_F·Y_S of the root stress (module docstring) [–].
FORM_STRESS_FACTOR = 4.0


def nominal_stresses(gear_pair, material, torque: float) -> dict[str, float]:
    """Nominal contact stress σ_H0 [Pa], root stress σ_F0 [Pa] and static deflection δ [m] of a pinion torque
    ``torque`` [N m] (module docstring)."""
    pinion, wheel = gear_pair.pinion, gear_pair.wheel
    width = gear_pair.face_width
    tangential = torque / pinion.reference_radius  # F_t on the reference circle [N]
    ratio = wheel.teeth / pinion.teeth
    angle, working = pinion.pressure_angle, gear_pair.operating_pressure_angle
    zone = math.sqrt(2.0 * math.cos(working) / (math.cos(angle) ** 2 * math.sin(working)))
    elasticity = math.sqrt(1.0 / (math.pi * 2.0 * (1.0 - material.poisson_ratio ** 2) / material.youngs_modulus))
    contact_ratio = math.sqrt(max(4.0 - gear_pair.contact_ratio, 1.0) / 3.0)
    contact = zone * elasticity * contact_ratio * math.sqrt(
        tangential * (ratio + 1.0) / (width * 2.0 * pinion.reference_radius * ratio))
    root = tangential * FORM_STRESS_FACTOR / (width * pinion.module)
    stiffness = iso6336_stiffness(gear_pair, material)["c_gamma_alpha"] * width  # [N/m]
    deflection = torque / pinion.base_radius / stiffness
    return {"contact_stress": contact, "root_stress": root, "static_deflection": deflection}


def load_flags(gear_pair, material, torque: float) -> tuple[str, ...]:
    """Words for each way the load exceeds what a steel tooth carries (empty when it does not)."""
    values = nominal_stresses(gear_pair, material, torque)
    flags = []
    if values["contact_stress"] > CONTACT_LIMIT_PA:
        flags.append(f"the nominal contact stress {values['contact_stress'] / 1e6:.4g} N/mm² (ISO 6336-2, K factors 1) "
                     f"exceeds the static strength of the best case-hardened steels (about "
                     f"{CONTACT_LIMIT_PA / 1e6:.0f} N/mm²): no steel flank carries this load")
    if values["root_stress"] > ROOT_LIMIT_PA:
        flags.append(f"the nominal root stress {values['root_stress'] / 1e6:.4g} N/mm² (ISO 6336-3 form, Y_FS = "
                     f"{FORM_STRESS_FACTOR:g}) exceeds the static strength of the best case-hardened steels (about "
                     f"{ROOT_LIMIT_PA / 1e6:.0f} N/mm²): the teeth would break")
    module = gear_pair.pinion.module
    if values["static_deflection"] > DEFLECTION_LIMIT_MODULES * module:
        flags.append(f"the static mesh deflection {values['static_deflection'] * 1e6:.4g} μm is "
                     f"{values['static_deflection'] / module:.3g} modules (more than "
                     f"{DEFLECTION_LIMIT_MODULES:g}): far outside the small deflections the tooth models assume")
    return tuple(flags)
