"""Equivalent viscous damping of tooth friction (Luo & Li (2020) Eqs. 26–28; docs/damping.md).

Chain: Coulomb friction F = μ·w of a tooth pair (Eq. 27, :mod:`thermogear.friction`; another law of
:data:`thermogear.friction.models.FRICTION_MODELS` by ``[damping] friction_model``) dissipates 4·F·B per cycle of
harmonic motion of amplitude B; a viscous damper c dissipates π·c·ω·B². Equal energy gives c = 4F/(πωB) (Eq. 26).
With the quasi-static amplitude B ≈ w/k (frequency ratio ≪ 1) the load cancels: c = 4·μ·k/(π·ω) (Eq. 28), ω the
mesh circular frequency 2π·z1·n1/60 (the paper's constant 1.459 = 0.12·4·60/(π·2π) confirms it).

Conventions (docs/damping.md, units): per tooth pair, k is that pair's stiffness and μ uses that pair's share of the
load; stiffness and damping are totals over the face width (N/m, N·s/m), the friction formula gets the load per
unit width.

The pair stiffness, load share and oil temperature of a case come from :class:`thermogear.mesh.model.MeshModel`;
this module holds the relations only.

Design choice — which k in Eq. 28 for the thermal model: the paper's c_r/c_e ratio is 1.677 (single region) and
1.679 (double region), exactly (η(30 °C)/η(T_flank))^0.25 at T_flank ≈ 79.6 °C (docs/damping.md): only the
viscosity changed between c_e and c_r, so the paper used the elastic pair stiffness k_e (and the k_e load share)
in both. That is the default, ``[damping] stiffness = "elastic"``; ``"thermal"`` uses the thermal model's k_T
for Eq. 28 and the load share of the thermal model (an option, not the paper).

Mesh-cycle rule (``[damping] rule``), how pair dampings combine into c(τ):
* ``"paper"``: the arithmetic mean of the dampings of the pairs in contact. In single contact it is that pair's
  value; in double contact the mean of the two. This is the reading of Luo & Li's Fig. 7 (c(τ) lower in the
  double-pair region than in the single-pair one, as the per-pair values are, because the shared load lowers
  μ and the pairs near the path ends are less stiff). It is not what the energy argument gives for two dampers
  acting on the same coordinate.
* ``"parallel"``: the sum over the pairs in contact. Each pair is a damper between the same two base circles
  (same relative velocity ẋ), so their forces add, exactly as the stiffnesses of pairs in parallel add
  (physically consistent; the double-region value is then about twice the paper's).

At standstill the friction formula is undefined (it divides by the sum of rolling speeds): every function here
raises CaseError naming ``operating.speed_rpm``; a gear pair at rest is a static problem without this damping
model (the dynamics relays the error).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

import numpy as np

from thermogear.errors import CaseError
from thermogear.registry import registered
from thermogear.friction import friction_validity_warnings
from thermogear.friction.models import DEFAULT_DAMPING_FRICTION_MODEL, FRICTION_MODELS, FrictionLaw, PitchContact
from thermogear.mesh.model_names import MODELS

#: How the friction damping c = 4·μ·k/(π·ω_m) with μ = 0.12·X_L·(w_i·R_a/(η·v_Σ·ρ_red))^(1/4) (Eqs. 27–28) scales
#: with the pinion speed n1 and the normal load w when the geometry, the oil temperature and the load shares stay
#: as they are: v_Σ ∝ n1 and ω_m ∝ n1 give c ∝ n1^(−5/4); the pair's load w_i ∝ w gives c ∝ w^(1/4). Exact for the
#: formula (it is a pure power law); the mesh model says when its inputs keep those conditions. Another friction
#: law with μ ∝ (w/v_Σ)^p gives c ∝ n1^(−1−p)·w^p (:func:`friction_damping_exponents`).
FRICTION_DAMPING_SPEED_EXPONENT = -1.25
FRICTION_DAMPING_LOAD_EXPONENT = 0.25


def friction_damping_exponents(law: FrictionLaw) -> tuple[float, float]:
    """(speed, load) exponents of c = 4μk/(πω_m) for a friction law with μ ∝ (w/v_Σ)^p: (−1 − p, p) [–]
    (v_Σ ∝ n1, ω_m ∝ n1; the paper's law, p = 1/4, gives the constants above)."""
    return -1.0 - law.load_exponent, law.load_exponent


Rule = Literal["paper", "parallel"]


def _mean_of_pairs(total: np.ndarray, count: np.ndarray) -> np.ndarray:
    """The arithmetic mean of the pairs in contact (0 where none is)."""
    return np.divide(total, count, out=np.zeros_like(total), where=count > 0)


def _sum_of_pairs(total: np.ndarray, count: np.ndarray) -> np.ndarray:
    """The sum of the pairs in contact: dampers in parallel."""
    return total


@dataclass(frozen=True)
class MeshDampingRule:
    """How the dampings of the pairs in contact combine into the mesh damping c(τ): ``name`` (the ``[damping]
    rule`` value), ``combine(total, count)`` of the summed dampings [N·s/m] and the number of pairs in contact per
    position, and whether it is the rule of Luo & Li (2020) (``published``: their mean dampings are of this rule)."""

    name: str
    combine: Callable[[np.ndarray, np.ndarray], np.ndarray]
    published: bool


#: Every mesh-damping rule by name (the first the default): the one place the names are compared.
DAMPING_RULES: dict[str, MeshDampingRule] = {rule.name: rule for rule in (
    MeshDampingRule("paper", _mean_of_pairs, published=True),  # Luo & Li Fig. 7
    MeshDampingRule("parallel", _sum_of_pairs, published=False))}
RULES = tuple(DAMPING_RULES)


def damping_rule(name: str) -> MeshDampingRule:
    """The mesh-damping rule called ``name``; a CaseError naming ``damping.rule`` for any other."""
    return registered(DAMPING_RULES, name, "damping.rule", "unknown mesh-damping rule")


#: Whether Eq. 28 takes the pair model's own stiffness (k_T, an option) rather than the elastic k_e (Luo & Li's), by
#: the ``[damping] stiffness`` value (the first the default): the one place the names are compared.
DAMPING_STIFFNESSES: dict[str, bool] = {"elastic": False, "thermal": True}


def damping_takes_pair_stiffness(name: str) -> bool:
    """Whether the ``[damping] stiffness`` choice ``name`` asks the pair model's stiffness (CaseError otherwise)."""
    return registered(DAMPING_STIFFNESSES, name, "damping.stiffness", "unknown pair stiffness of the damping")


# ---------------------------------------------------------------------------------------------- functions
def _checked(key: str, value, positive: bool, reason: str) -> np.ndarray:
    """``value`` as a float array, every element > 0 (``positive``) or >= 0 (NaN fails both); CaseError naming
    ``key``, the smallest value and ``reason`` otherwise."""
    array = np.asarray(value, dtype=float)
    if np.any(~(array > 0.0 if positive else array >= 0.0)):
        raise CaseError(key, float(np.min(array)), "> 0" if positive else ">= 0", reason)
    return array


def coulomb_equivalent_damping(friction_force, circular_frequency, amplitude):
    """Viscous damping that dissipates per cycle what Coulomb friction does, c = 4F/(π·ω·B) [N·s/m].

    Luo & Li (2020) Eq. 26; energy equivalence for harmonic motion x = B sin ωt (Den Hartog's equivalent
    viscous damping of Coulomb friction).
    friction_force F [N], circular_frequency ω [rad/s], amplitude B [m].
    """
    frequency = _checked("operating.speed_rpm", circular_frequency, True,
                         "the equivalent viscous damping of Coulomb friction needs motion (ω > 0)")
    amplitude = _checked("amplitude", amplitude, True, "the vibration amplitude must be positive")
    force = _checked("friction_force", friction_force, False, "a friction force magnitude")
    return 4.0 * force / (math.pi * frequency * amplitude)


def friction_damping(pair_stiffness, friction_coefficient, mesh_circular_frequency):
    """Equivalent viscous damping of a tooth pair's friction, c = 4·μ·k/(π·ω) [N·s/m] (Luo & Li Eq. 28).

    Eq. 26 with F = μ·w and the quasi-static amplitude B = w/k. pair_stiffness k [N/m] (total over the face
    width gives the total damping), friction_coefficient μ [–], mesh_circular_frequency ω = 2π·z1·n1/60 [rad/s].
    With μ = 0.12·X^0.25 and ω in rpm this is the paper's c = 1.459·k·X^0.25/(z1·n1).
    """
    frequency = _checked("operating.speed_rpm", mesh_circular_frequency, True,
                         "the friction damping of Eq. 28 is defined for a running mesh only")
    stiffness = _checked("pair_stiffness", pair_stiffness, False, "a stiffness cannot be negative")
    friction = _checked("friction_coefficient", friction_coefficient, False, "a friction coefficient")
    return 4.0 * friction * stiffness / (math.pi * frequency)


def mesh_circular_frequency(pinion_teeth: int, pinion_speed_rpm: float) -> float:
    """ω_m = 2π·z1·n1/60 [rad/s] (the ω of Luo & Li Eqs. 26, 28)."""
    if not pinion_speed_rpm > 0.0:
        raise CaseError("operating.speed_rpm", pinion_speed_rpm, "> 0",
                        "the friction formula is undefined at standstill; the dynamics at rest is static")
    return 2.0 * math.pi * pinion_teeth * pinion_speed_rpm / 60.0


def mesh_damping(per_pair_damping, in_contact, rule: Rule = "paper"):
    """Mesh damping c(τ) [N·s/m] from the pair dampings (slots, n) and the contact mask (slots, n).

    ``"paper"``: arithmetic mean over the pairs in contact (Luo & Li Fig. 7); ``"parallel"``: sum over the pairs
    in contact (dampers in parallel). Positions with no pair in contact get 0 (and cannot occur for ε > 1).
    """
    damping = np.asarray(per_pair_damping, dtype=float)
    contact = np.asarray(in_contact, dtype=bool)
    if damping.shape != contact.shape:
        raise ValueError(f"mesh_damping: per_pair_damping {damping.shape} and in_contact {contact.shape} differ")
    total = np.where(contact, damping, 0.0).sum(axis=0)
    return damping_rule(rule).combine(total, contact.sum(axis=0))


def contact_region_means(mesh_values, contact_count, weights=None) -> dict[str, float]:
    """Means of a mesh-cycle quantity over the single-pair and the double-pair region.

    ``weights``: interval lengths of the grid (``MeshGrid.steps``) for a time average on a non-uniform grid;
    None for equal weights. A region absent from the cycle gives NaN (documented; a contact ratio of exactly 1
    or 2 has only one region).
    """
    values = np.asarray(mesh_values, dtype=float)
    count = np.asarray(contact_count)
    weights = np.ones_like(values) if weights is None else np.asarray(weights, dtype=float)
    result = {}
    for name, pairs in (("single", 1), ("double", 2)):
        mask = count == pairs
        result[name] = float(np.average(values[mask], weights=weights[mask])) if np.any(mask) else float("nan")
    return result


def friction_pair_damping(pair_stiffness, load_share, total_unit_load, roughness, viscosity, sum_velocity,
                          relative_radius, lubricant_factor, circular_frequency, law: FrictionLaw | None = None,
                          constant: float | None = None, helical_load_factor: float = 1.0,
                          reference_pressure_angle: float = 0.0):
    """Friction coefficient, equivalent viscous damping and unit load of tooth pairs (Luo & Li Eqs. 27–28).

    μ of the friction ``law`` (default the paper's, DIN 3990-4 as Luo & Li Eq. 27; ``constant`` the value of the
    ``"constant"`` law) with the pair's load per unit width (its share of ``total_unit_load`` w_Bt [N/m]), the
    composite ``roughness`` R_a [m], ``viscosity`` η [Pa·s] at the contact, ``sum_velocity`` v_Σ [m/s] and
    ``relative_radius`` ρ_red [m] at the contact (of the normal section for a helical pair,
    :func:`~thermogear.friction.models.normal_section_radius`), X_L ``lubricant_factor`` [–],
    ``helical_load_factor`` K_Bγ [–] (1 for a spur pair) and ``reference_pressure_angle`` α_t [rad] (only ISO/TR
    13989's law takes these two, :class:`~thermogear.friction.models.PitchContact`); then c = 4·μ·k/(π·ω_m) with
    the pair stiffness k [N/m] (total) and the mesh circular frequency ω_m [rad/s]. Arrays broadcast.
    The formula's usual limits are checked on the pair's total unit load w_Bt (the standard's load) and warned
    about once. Returns (μ [–], c [N·s/m], unit load of the pair [N/m]).
    """
    share = np.asarray(load_share, dtype=float)
    unit_load = share * float(total_unit_load)
    friction_validity_warnings(float(total_unit_load), sum_velocity)
    law = FRICTION_MODELS[DEFAULT_DAMPING_FRICTION_MODEL] if law is None else law
    contact = PitchContact(unit_load, roughness, viscosity, sum_velocity, relative_radius, lubricant_factor,
                           helical_load_factor, reference_pressure_angle)
    shape = np.broadcast(unit_load, *(np.asarray(value) for value in (roughness, viscosity, sum_velocity,
                                                                      relative_radius))).shape
    friction = np.array(np.broadcast_to(np.asarray(law.law(contact, constant), dtype=float), shape))
    damping = np.asarray(friction_damping(pair_stiffness, friction, circular_frequency), dtype=float)
    return friction, damping, unit_load


# --------------------------------------------------------------------------------------------- component
@dataclass(frozen=True)
class PairDamping:
    """Friction damping of one tooth pair at roll distances along the path (arrays of the shape of ``roll``).

    roll [m] from T1, gamma Γ [–], friction_coefficient μ [–], viscosity η [Pa·s] at temperature_c [°C],
    damping [N·s/m] total over the face width, pair_stiffness [N/m] total, load_share [–], unit_load [N/m]
    (the pair's load per unit width in the friction formula).
    """

    model: str
    roll: np.ndarray
    gamma: np.ndarray
    friction_coefficient: np.ndarray
    viscosity: np.ndarray
    damping: np.ndarray
    temperature_c: np.ndarray
    pair_stiffness: np.ndarray
    load_share: np.ndarray
    unit_load: np.ndarray


__all__ = ["contact_region_means", "coulomb_equivalent_damping", "damping_rule", "DAMPING_RULES", "damping_takes_pair_stiffness",
           "DAMPING_STIFFNESSES", "friction_damping", "friction_damping_exponents",
           "FRICTION_DAMPING_LOAD_EXPONENT", "FRICTION_DAMPING_SPEED_EXPONENT", "friction_pair_damping",
           "mesh_circular_frequency", "mesh_damping", "MeshDampingRule", "MODELS", "PairDamping", "RULES"]
