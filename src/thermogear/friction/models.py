"""Mean tooth friction coefficients of spur gears as a choice: each law with its source, range and validity checks,
resolved once by name from :data:`FRICTION_MODELS` (``[gearbox] friction_model`` for the loss model,
``[damping] friction_model`` for the friction damping, which applies the law locally along the path of contact).

Every law is a power law in the contact's state at the pitch point C, evaluated in the units of its source
**inside** the law only (w [N/mm], R_a [μm], η [mPa·s], v_Σ [m/s], ρ [mm]); arguments and results are SI:

* ``"paper"`` — the law Luo & Li (2020) use for their friction damping (Eq. 27), the mean friction coefficient
  they attribute to DIN 3990-4 (the project's :mod:`thermogear.friction`; which of the standard's methods it
  belongs to was not checked in the standard):
  μ = 0.12·(w_Bt·R_a/(η·v_ΣC·ρ_redC))^0.25·X_L (:mod:`thermogear.friction`; X_L of
  :data:`thermogear.lubricant.LUBRICANT_FACTORS`). Kept for the paper's damping and its reproduction.
* ``"iso_tr_13989_2"`` — the mean coefficient of the integral-temperature method of ISO/TR 13989:2000 (Part 2): μ_mC =
  0.045·(w_Bt·K_Bγ/(v_ΣC·ρ_redC))^0.2·η^−0.05·X_R·X_L with X_R = 2.2·(R_a/ρ_redC)^0.25 and the helical load factor K_Bγ
  (:func:`helical_load_factor`; 1 for spur gears, ε_γ = ε_α ≤ 2); X_L of the same table (mineral oil 1). The standard
  itself was not read (no copy was found); the form, its constants and its part were checked against a commercial
  calculation's printout: the KISSsoft report of the NREL 5 MW gearbox's third stage ("Calculation method according to
  ISO TR 13989:2000", repository gfsReboucas/Drivetrain, ``@NREL_5MW/stage_03.rtf``) prints, under its
  **integral**-temperature criteria, μ_m = 0.030 with X_L = 1.000, η = 30.09 mPa·s, w_Bt·K_Bγ = 1425.897 N/mm, and X_R =
  0.712 for R_a = 0.6 μm; its geometry (T1C 67.447 mm, T2C 266.979 mm, β_b 9.391°, v(d_w) 21.20 m/s, α_wt 22.856°) gives
  ρ_redC = 54.57 mm and v_ΣC = 16.47 m/s, from which this form gives X_R = 0.7124 and μ_mC = 0.0297 (0.0283 without
  K_Bγ): both printed values reproduced (tests/validation/test_iso_tr_13989_friction.py). The same report's
  **flash**-temperature criteria print another μ (0.041 with X_L = 0.843): the 0.045 form is the integral method's, not
  Part 1's, whence the name (it was filed as ``"iso_tr_13989_1"`` before).
* ``"schlenk"`` — Schlenk's mean coefficient from FZG power-loss measurements (L. Schlenk, Untersuchungen zur
  Fresstragfähigkeit von Großzahnrädern, Dissertation TU München, 1994), in the form that FZG power-loss work
  uses it (Fernandes, Marques, Martins & Seabra (2015), Gearbox power loss. Part II: Friction losses in gears,
  Tribology International 88:309–316):
  μ_mZ = 0.048·((F_bt/b)/(v_ΣC·ρ_C))^0.2·η^−0.05·R_a^0.25·X_L, with Fernandes et al.'s X_L per base oil
  (:data:`SCHLENK_LUBRICANT_FACTORS`). The form and the units were read in two open implementations (C. M. C. G.
  Fernandes' Gear-Calculation ``contact.py`` and ``oils.py``, and TUM FTM's ``Getrieberechnung_Einstufig.m``,
  "according to Schlenk"); the dissertation and the paper's own table of X_L were not read.
* ``"constant"`` — a given μ (``[gearbox] friction_coefficient``): for a measured value or a sensitivity study.

Temperature dependence: all three laws depend on temperature only through η (μ ∝ η^e with e = −0.25 for the
paper's law and −0.05 for the others), which :attr:`FrictionLaw.viscosity_exponent` exposes: from 40 to 90 °C a
VG 100 mineral oil thins about 8-fold, raising the paper's μ by 64 % and Schlenk's by 10 %. Load and speed enter
all three as μ ∝ (w/v_Σ)^p (:attr:`FrictionLaw.load_exponent`: p = 0.25 for the paper's law, 0.2 for the others,
0 for a constant), which makes the friction damping c = 4μk/(πω) a power law in speed and load.

The laws take arrays as well as numbers (the damping evaluates them along the path of contact).

Validity (all three laws): the usual limits of the DIN 3990-4 / ISO/TR 13989 formulas, sum of rolling speeds
v_ΣC ≤ 50 m/s and unit load w_Bt ≥ 150 N/mm (recalled [R]; Schlenk's own measurement range, FZG gears at
v_t up to about 20 m/s and loads of the FZG load stages, is narrower and is not restated in the open codes): outside
them each law warns (ExtrapolationWarning) and still gives its value.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Callable

import numpy as np

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.friction import MAXIMUM_SUM_VELOCITY, MINIMUM_UNIT_LOAD, mean_friction_coefficient
from thermogear.choices.friction import FRICTION_INPUTS, FrictionInputs

#: Lubricant factor X_L of Schlenk's law per base oil, as calibrated on FZG power-loss tests by Fernandes et al.
#: (2015) Part II and coded in their Gear-Calculation ``oils.py`` (mineral 0.846, PAO 0.666, PAG 0.585, ester
#: 0.65; read in the code, not in the paper). Traction fluids: none published; give ``[gearbox]
#: lubricant_factor``.
SCHLENK_LUBRICANT_FACTORS = {"mineral": 0.846, "pao": 0.666, "pag_insoluble": 0.585, "pag_soluble": 0.585,
                             "ester": 0.65}
#: Largest constant friction coefficient accepted [–]: dry steel on steel is about 0.5–0.8, lubricated gear
#: teeth 0.01–0.1; a lubricated mesh above 0.3 is a wrong input.
LARGEST_CONSTANT_FRICTION = 0.3


@dataclass(frozen=True)
class PitchContact:
    """The contact at the pitch point of a gear pair: unit load w_Bt = F_bt/b [N/m], composite roughness
    R_a [m], dynamic viscosity η [Pa·s], sum of rolling speeds v_ΣC [m/s], relative radius of curvature
    ρ_redC [m] (of the normal section for a helical pair: ρ_t/cos β_b) and the lubricant factor X_L of the chosen
    law [–]; ``helical_load_factor`` K_Bγ [–] (:func:`helical_load_factor`; 1 for a spur pair) and
    ``reference_pressure_angle`` α_t [rad], the transverse pressure angle at the reference circle, which only the
    ISO/TR 13989 law takes: its load is the nominal tangential force at the reference circle, w = F_t/b with
    F_t = F_bt·cos α_t (ISO 6336-1's F_t = 2000·T/d; a KISSsoft printout of the law builds its w_Bt on F_t);
    0 takes ``unit_load`` as that load."""

    unit_load: float
    roughness: float
    viscosity: float
    sum_velocity: float
    relative_radius: float
    lubricant_factor: float
    helical_load_factor: float = 1.0
    reference_pressure_angle: float = 0.0


def helical_load_factor(total_contact_ratio: float) -> float:
    """K_Bγ [–], the helical load factor of ISO/TR 13989 by the total contact ratio ε_γ: 1 for ε_γ ≤ 2,
    1 + 0.2·√((ε_γ − 2)(5 − ε_γ)) for 2 < ε_γ < 3.5, 1.3 from 3.5 (continuous at both ends). The form is recalled
    [R]; its middle branch reproduces a KISSsoft printout of an ISO/TR 13989 calculation, K_Bγ = 1.274 at
    ε_γ = 2.884 (tests/validation/test_helical_kisssoft_printout.py)."""
    if not math.isfinite(total_contact_ratio) or total_contact_ratio <= 0.0:
        raise CaseError("total_contact_ratio", total_contact_ratio, "> 0", "a pair in mesh")
    if total_contact_ratio <= 2.0:
        return 1.0
    if total_contact_ratio >= 3.5:
        return 1.3
    return 1.0 + 0.2 * math.sqrt((total_contact_ratio - 2.0) * (5.0 - total_contact_ratio))


def normal_section_radius(transverse_radius, base_helix_angle: float):
    """ρ_redC of the normal section [m], the radius every friction law takes (ISO/TR 13989-1 defines it there):
    ρ_t/cos β_b for the transverse section's relative radius of curvature ρ_t [m] and the base helix angle β_b
    [rad]; ρ_t itself for a spur pair (β_b = 0). Arrays broadcast."""
    return transverse_radius / math.cos(base_helix_angle) if base_helix_angle else transverse_radius


def _smallest(value) -> float:
    """The smallest of a number or an array (NaN where any value is not finite)."""
    values = np.asarray(value, dtype=float)
    return float(np.min(values)) if np.all(np.isfinite(values)) else float("nan")


def _check(contact: PitchContact) -> None:
    for key, value in (("operating.speed_rpm (sum of rolling speeds)", contact.sum_velocity),
                       ("lubricant (dynamic viscosity)", contact.viscosity),
                       ("relative_radius", contact.relative_radius),
                       ("lubricant_factor", contact.lubricant_factor)):
        smallest = _smallest(value)
        if not smallest > 0.0:
            raise CaseError(key, smallest, "> 0", "the friction law is a power law in it")
    smallest = _smallest(contact.unit_load)
    if not smallest >= 0.0:
        raise CaseError("unit_load", smallest, ">= 0 N/m", "the teeth are pressed together")
    smallest = _smallest(contact.roughness)
    if not smallest >= 0.0:
        raise CaseError("gears.roughness_ra_um", smallest * 1e6, ">= 0", "a roughness")


def _paper(contact: PitchContact, constant: float | None) -> float:
    value = mean_friction_coefficient(contact.unit_load, contact.roughness, contact.viscosity, contact.sum_velocity,
                                      contact.relative_radius, contact.lubricant_factor, check_limits=False)
    return float(value) if np.ndim(value) == 0 else np.asarray(value, dtype=float)


def _iso_tr_13989_2(contact: PitchContact, constant: float | None) -> float:
    _check(contact)
    load, speed = contact.unit_load * 1e-3, contact.sum_velocity  # N/mm, m/s
    radius, roughness, viscosity = contact.relative_radius * 1e3, contact.roughness * 1e6, contact.viscosity * 1e3
    roughness_factor = 2.2 * (roughness / radius)**0.25
    load = load * math.cos(contact.reference_pressure_angle) * contact.helical_load_factor  # F_t/b·K_Bγ
    return 0.045 * (load / (speed * radius))**0.2 * viscosity**-0.05 * roughness_factor * contact.lubricant_factor


def _schlenk(contact: PitchContact, constant: float | None) -> float:
    _check(contact)
    load, speed = contact.unit_load * 1e-3, contact.sum_velocity  # N/mm, m/s
    radius, roughness, viscosity = contact.relative_radius * 1e3, contact.roughness * 1e6, contact.viscosity * 1e3
    return 0.048 * (load / (speed * radius))**0.2 * viscosity**-0.05 * roughness**0.25 * contact.lubricant_factor


def _constant(contact: PitchContact, constant: float | None) -> float:
    if constant is None or not (math.isfinite(constant) and 0.0 < constant <= LARGEST_CONSTANT_FRICTION):
        raise CaseError("gearbox.friction_coefficient", constant, f"(0, {LARGEST_CONSTANT_FRICTION}]",
                        "friction_model = 'constant' needs the coefficient")
    return float(constant)


def _standard_factor(base_oil: str) -> float | None:
    from thermogear.lubricant import LUBRICANT_FACTORS  # noqa: PLC0415

    return LUBRICANT_FACTORS.get(base_oil)


@dataclass(frozen=True)
class FrictionLaw:
    """One mean friction law: its name, source, the exponent of η in it, its X_L per base oil (None: the law has no
    published value for that base oil), the law itself, ``law(contact, constant) -> μ [–]``, and the exponent p of
    μ ∝ (w/v_Σ)^p (module docstring)."""

    name: str
    source: str
    viscosity_exponent: float
    checks_limits: bool
    law: Callable[[PitchContact, float | None], float]
    factor_of: Callable[[str], float | None]
    load_exponent: float

    @property
    def inputs(self) -> FrictionInputs:
        """What this law takes from the case besides its name (a given coefficient, a lubricant factor), as the
        case's checks read it (:data:`thermogear.choices.friction.FRICTION_INPUTS`)."""
        return FRICTION_INPUTS[self.name]

    def lubricant_factor(self, base_oil: str, given: float | None = None,
                         key: str = "gearbox.lubricant_factor") -> float:
        """X_L of this law for a base oil, or ``given`` where the case gives one; CaseError naming ``key`` where
        neither exists."""
        if given is not None:
            return float(given)
        factor = self.factor_of(base_oil)
        if factor is None:
            raise CaseError(key, None, "a value > 0",
                            f"the friction law {self.name!r} has no published lubricant factor for base oil "
                            f"{base_oil!r}")
        return factor

    def coefficient(self, contact: PitchContact, constant: float | None = None, warn: bool = True) -> float:
        """μ [–] of this law at the contact (``constant``: the value of the ``"constant"`` law); warns where the
        law's usual limits are left (module docstring)."""
        if warn and self.checks_limits:
            validity_warnings(self.name, contact.unit_load, contact.sum_velocity)
        return self.law(contact, constant)


def validity_warnings(name: str, unit_load: float, sum_velocity: float, stacklevel: int = 4) -> None:
    """ExtrapolationWarning where the usual limits of the friction laws are left (v_Σ ≤ 50 m/s, w ≥ 150 N/mm)."""
    if unit_load < MINIMUM_UNIT_LOAD:
        warnings.warn(f"friction coefficient ({name}): unit load {unit_load * 1e-3:.1f} N/mm is below the law's "
                      f"usual lower limit {MINIMUM_UNIT_LOAD * 1e-3:.0f} N/mm (extrapolated)", ExtrapolationWarning,
                      stacklevel=stacklevel)
    if sum_velocity > MAXIMUM_SUM_VELOCITY:
        warnings.warn(f"friction coefficient ({name}): sum of rolling speeds {sum_velocity:.1f} m/s is above the "
                      f"law's usual upper limit {MAXIMUM_SUM_VELOCITY:.0f} m/s (extrapolated)", ExtrapolationWarning,
                      stacklevel=stacklevel)


#: The friction laws by name (module docstring); the loss model's default is ``"schlenk"``
#: (docs/gearbox-temperature.md, "Which friction law").
FRICTION_MODELS: dict[str, FrictionLaw] = {
    "paper": FrictionLaw("paper", "DIN 3990-4 mean coefficient as Luo & Li (2020) Eq. 27",
                         -0.25, True, _paper, _standard_factor, 0.25),
    "iso_tr_13989_2": FrictionLaw("iso_tr_13989_2", "ISO/TR 13989-2:2000 mean coefficient (integral-temperature "
                                  "method), checked against a KISSsoft printout", -0.05, True, _iso_tr_13989_2,
                                  _standard_factor, 0.2),
    "schlenk": FrictionLaw("schlenk", "Schlenk (1994) with X_L of Fernandes et al. (2015)", -0.05, True, _schlenk,
                           SCHLENK_LUBRICANT_FACTORS.get, 0.2),
    "constant": FrictionLaw("constant", "a given constant coefficient", 0.0, False, _constant, lambda base: 1.0,
                            0.0),
}
#: The gearbox loss model's default friction law (docs/gearbox-temperature.md, "Which friction law").
DEFAULT_LOSS_FRICTION_MODEL = "schlenk"
#: The friction damping's default friction law: the paper's, so the reproduction of Luo & Li keeps every number
#: (docs/damping.md, "Which friction law").
DEFAULT_DAMPING_FRICTION_MODEL = "paper"


def friction_law(name: str, key: str = "gearbox.friction_model") -> FrictionLaw:
    """The friction law registered under ``name`` (CaseError naming ``key`` where none is)."""
    law = FRICTION_MODELS.get(name)
    if law is None:
        raise CaseError(key, name, " | ".join(FRICTION_MODELS), "not a friction law")
    return law


__all__ = ["DEFAULT_DAMPING_FRICTION_MODEL", "DEFAULT_LOSS_FRICTION_MODEL", "FRICTION_MODELS", "FrictionLaw",
           "LARGEST_CONSTANT_FRICTION", "PitchContact", "SCHLENK_LUBRICANT_FACTORS", "friction_law",
           "helical_load_factor", "normal_section_radius", "validity_warnings"]
