"""Equivalent viscous damping of tooth friction (Luo & Li (2020) Eqs. 26–28; physics.md §1.5, §1.6, §8).

Chain: Coulomb friction F = μ·w of a tooth pair (Eq. 27, :mod:`thermogear.friction`) dissipates 4·F·B per cycle of
harmonic motion of amplitude B; a viscous damper c dissipates π·c·ω·B². Equal energy gives c = 4F/(πωB) (Eq. 26).
With the quasi-static amplitude B ≈ w/k (frequency ratio ≪ 1) the load cancels: c = 4·μ·k/(π·ω) (Eq. 28), ω the
mesh circular frequency 2π·z1·n1/60 (the paper's constant 1.459 = 0.12·4·60/(π·2π) confirms it).

Conventions (physics.md §1.6): per tooth pair, k is that pair's stiffness and μ uses that pair's share of the
load; stiffness and damping are totals over the face width (N/m, N·s/m), the friction formula gets the load per
unit width.

Design choice — which k in Eq. 28 for the thermal model: the paper's c_r/c_e ratio is 1.677 (single region) and
1.679 (double region), exactly (η(30 °C)/η(T_flank))^0.25 at T_flank ≈ 79.6 °C (physics.md §1.6): only the
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
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

import numpy as np

from thermogear.errors import CaseError
from thermogear.friction import friction_validity_warnings, mean_friction_coefficient
from thermogear.lubricant import Lubricant, lubricant_from_case

if TYPE_CHECKING:  # pragma: no cover
    from thermogear.case import Case

Model = Literal["elastic", "thermal"]
Rule = Literal["paper", "parallel"]
MODELS = ("elastic", "thermal")
RULES = ("paper", "parallel")


# ---------------------------------------------------------------------------------------------- functions
def coulomb_equivalent_damping(friction_force, circular_frequency, amplitude):
    """Viscous damping that dissipates per cycle what Coulomb friction does, c = 4F/(π·ω·B) [N·s/m].

    Luo & Li (2020) Eq. 26; energy equivalence for harmonic motion x = B sin ωt (physics.md §8).
    friction_force F [N], circular_frequency ω [rad/s], amplitude B [m].
    """
    force = np.asarray(friction_force, dtype=float)
    frequency = np.asarray(circular_frequency, dtype=float)
    amplitude = np.asarray(amplitude, dtype=float)
    if np.any(~(frequency > 0.0)):
        raise CaseError("operating.speed_rpm", float(np.min(frequency)), "> 0",
                        "the equivalent viscous damping of Coulomb friction needs motion (ω > 0)")
    if np.any(~(amplitude > 0.0)):
        raise CaseError("amplitude", float(np.min(amplitude)), "> 0", "the vibration amplitude must be positive")
    if np.any(~(force >= 0.0)):
        raise CaseError("friction_force", float(np.min(force)), ">= 0", "a friction force magnitude")
    return 4.0 * force / (math.pi * frequency * amplitude)


def friction_damping(pair_stiffness, friction_coefficient, mesh_circular_frequency):
    """Equivalent viscous damping of a tooth pair's friction, c = 4·μ·k/(π·ω) [N·s/m] (Luo & Li Eq. 28).

    Eq. 26 with F = μ·w and the quasi-static amplitude B = w/k. pair_stiffness k [N/m] (total over the face
    width gives the total damping), friction_coefficient μ [–], mesh_circular_frequency ω = 2π·z1·n1/60 [rad/s].
    With μ = 0.12·X^0.25 and ω in rpm this is the paper's c = 1.459·k·X^0.25/(z1·n1).
    """
    stiffness = np.asarray(pair_stiffness, dtype=float)
    friction = np.asarray(friction_coefficient, dtype=float)
    frequency = np.asarray(mesh_circular_frequency, dtype=float)
    if np.any(~(frequency > 0.0)):
        raise CaseError("operating.speed_rpm", float(np.min(frequency)), "> 0",
                        "the friction damping of Eq. 28 is defined for a running mesh only")
    if np.any(~(stiffness >= 0.0)):
        raise CaseError("pair_stiffness", float(np.min(stiffness)), ">= 0", "a stiffness cannot be negative")
    if np.any(~(friction >= 0.0)):
        raise CaseError("friction_coefficient", float(np.min(friction)), ">= 0", "a friction coefficient")
    return 4.0 * friction * stiffness / (math.pi * frequency)


def mesh_circular_frequency(pinion_teeth: int, pinion_speed_rpm: float) -> float:
    """ω_m = 2π·z1·n1/60 [rad/s] (the ω of Luo & Li Eqs. 26, 28; physics.md §1.5)."""
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
    if rule == "parallel":
        return total
    if rule == "paper":
        count = contact.sum(axis=0)
        return np.divide(total, count, out=np.zeros_like(total), where=count > 0)
    raise CaseError("damping.rule", rule, " | ".join(RULES), "unknown mesh-damping rule")


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


def load_shares(stiffness_at_positions, in_contact) -> np.ndarray:
    """Share of the load of each pair, k_i / Σ k_j over the pairs in contact (axis 0) [–]."""
    stiffness = np.where(in_contact, np.asarray(stiffness_at_positions, dtype=float), 0.0)
    total = stiffness.sum(axis=0)
    return np.divide(stiffness, total, out=np.zeros_like(stiffness), where=total > 0)


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


def _check_model(model: str) -> None:
    if model not in MODELS:
        raise CaseError("model", model, " | ".join(MODELS), "unknown damping model")


def _stiffness_function(case: "Case", model: str):
    """Pair stiffness k(roll) [N/m] (total) used by Eq. 28 and the load share, per ``[damping] stiffness``."""
    choice = getattr(case.damping, "stiffness", "elastic")
    if model == "thermal" and choice == "thermal":
        from thermogear.thermal.stiffness import thermal_pair_stiffness_at

        return lambda roll: np.asarray(thermal_pair_stiffness_at(case, roll), dtype=float)
    from thermogear.stiffness.table import pair_stiffness_at

    return lambda roll: np.asarray(pair_stiffness_at(case.gear_pair, case.material, roll), dtype=float)


def oil_temperature_c(case: "Case", gamma, model: str) -> np.ndarray:
    """Oil temperature of the friction formula [°C]: the lubricant's reference temperature ("elastic") or the
    local flank temperature of the temperature input, mean of pinion and wheel flank at the contact ("thermal")."""
    gamma = np.asarray(gamma, dtype=float)
    if model == "elastic":
        return np.full(gamma.shape, float(case.lubricant.reference_temperature_c))
    from thermogear.thermal.temperature import temperature_field_from_case

    field = temperature_field_from_case(case)
    return 0.5 * (np.asarray(field.pinion_flank_c(gamma), dtype=float)
                  + np.asarray(field.wheel_flank_c(gamma), dtype=float))


def pair_damping(case: "Case", roll, model: Model = "elastic", lubricant: Lubricant | None = None) -> PairDamping:
    """Friction damping of the tooth pair at roll distance(s) ``roll`` [m] along the path A–E.

    μ (Eq. 27) uses the local relative radius of curvature, the local sum of rolling speeds, the pair's share of
    the normal load k_i/Σk over the pairs in contact at that mesh position (neighbours one base pitch apart), the
    viscosity at the model's oil temperature and the case's roughness and X_L; c = 4μk/(πω_m) (Eq. 28).
    """
    _check_model(model)
    pair = case.gear_pair
    speed = case.operating_point.speed_rpm
    omega_m = mesh_circular_frequency(pair.pinion.teeth, speed)
    roll = np.asarray(roll, dtype=float)
    points = pair.path_points
    tolerance = 1e-9 * pair.base_pitch
    if np.any((roll < points["A"] - tolerance) | (roll > points["E"] + tolerance)):
        raise CaseError("roll", [float(roll.min()), float(roll.max())],
                        f"[{points['A']:.6g}, {points['E']:.6g}] m (A to E)", "outside the path of contact")
    oil = lubricant if lubricant is not None else lubricant_from_case(case)
    stiffness_of = _stiffness_function(case, model)
    # Pairs in contact at the same instant sit whole base pitches apart; row 0 is the pair itself.
    offsets = np.array([0, -1, 1, -2, 2], dtype=float)[:, None] * pair.base_pitch
    positions = roll.reshape(1, -1) + offsets
    in_contact = (positions >= points["A"] - tolerance) & (positions <= points["E"] + tolerance)
    stiffness = np.zeros(positions.shape)
    stiffness[in_contact] = stiffness_of(np.clip(positions[in_contact], points["A"], points["E"]))
    share = load_shares(stiffness, in_contact)[0].reshape(roll.shape)
    own_stiffness = stiffness[0].reshape(roll.shape)
    width = pair.face_width
    total_unit_load = case.normal_load / width  # w_Bt of the standard [N/m]
    unit_load = share * total_unit_load
    gamma = np.asarray(pair.gamma(roll), dtype=float)
    temperature = oil_temperature_c(case, gamma, model)
    viscosity = np.asarray(oil.dynamic_viscosity(temperature), dtype=float)
    rolling_1, rolling_2 = pair.rolling_speeds(roll, speed)
    sum_velocity = np.asarray(rolling_1 + rolling_2, dtype=float)
    factor = case.damping.lubricant_factor if case.damping.lubricant_factor is not None else oil.lubricant_factor
    friction_validity_warnings(total_unit_load, sum_velocity)
    friction = mean_friction_coefficient(unit_load, case.roughness_ra, viscosity, sum_velocity,
                                         pair.relative_radius_of_curvature(roll), factor, check_limits=False)
    damping = friction_damping(own_stiffness, friction, omega_m)
    return PairDamping(model=model, roll=roll, gamma=gamma, friction_coefficient=np.asarray(friction),
                       viscosity=viscosity, damping=np.asarray(damping), temperature_c=temperature,
                       pair_stiffness=own_stiffness, load_share=np.asarray(share), unit_load=np.asarray(unit_load))


def per_pair_damping_on_grid(case: "Case", grid, model: Model = "elastic") -> np.ndarray:
    """Pair dampings (slots, n) [N·s/m] at a MeshGrid's roll positions, 0 where a slot is out of contact."""
    roll = np.asarray(grid.roll, dtype=float)
    contact = np.asarray(grid.in_contact, dtype=bool)
    values = np.zeros(roll.shape)
    if np.any(contact):
        values[contact] = pair_damping(case, roll[contact], model).damping
    return values


def mesh_cycle_damping(case: "Case", grid, model: Model = "elastic", rule: Rule | None = None) -> np.ndarray:
    """Mesh damping c(τ) [N·s/m] (total over the face width) on a MeshCycle grid, under the case's rule."""
    _check_model(model)
    rule = case.damping.rule if rule is None else rule
    return mesh_damping(per_pair_damping_on_grid(case, grid, model), grid.in_contact, rule)


# ---------------------------------------------------------------------------------------------- summary
#: Luo & Li (2020) Sect. 3 mean dampings [N·s/m] (totals over the 25 mm face), for display beside luo2019.
PAPER_MEAN_DAMPING = {"elastic": {"single": 3.41e3, "double": 2.40e3}, "thermal": {"single": 5.72e3, "double": 4.03e3}}


@dataclass(frozen=True)
class DampingSummary:
    """Elastic and thermal friction damping of a case: per pair along the path and c(τ) over one mesh cycle.

    ``path``: PairDamping per model on an even roll grid A–E; ``mesh``: c(τ) [N·s/m] per model on ``grid``
    (MeshGrid); ``region_means``: time means of c(τ) over the single- and double-pair regions per model.
    """

    case_name: str
    rule: str
    stiffness: str
    lubricant: Lubricant
    path: dict
    grid: object
    mesh: dict
    region_means: dict
    pitch: dict  # PairDamping at C per model

    def to_dict(self) -> dict:
        """The JSON summary of ``thermogear damping``."""
        oil, pitch = self.lubricant, self.pitch
        flank_viscosity = float(np.mean(self.path["thermal"].viscosity))
        result = {
            "case": self.case_name, "rule": self.rule, "stiffness": self.stiffness,
            "lubricant": {"name": oil.name, "base_oil": oil.base_oil, "lubricant_factor_oil": oil.lubricant_factor},
            "friction_coefficient_pitch": {model: float(pitch[model].friction_coefficient[0]) for model in MODELS},
            "damping_n_s_per_m": self.region_means,
            "thermal_over_elastic": {region: self.region_means["thermal"][region]
                                     / self.region_means["elastic"][region] for region in ("single", "double")},
            "viscosity_mpa_s": {"oil_reference": float(pitch["elastic"].viscosity[0]) * 1e3,
                                "flank_mean": flank_viscosity * 1e3},
            "temperature_c": {"oil_reference": float(pitch["elastic"].temperature_c[0]),
                              "flank_mean": float(np.mean(self.path["thermal"].temperature_c))},
            "along_path": {"gamma": self.path["elastic"].gamma,
                           "elastic_n_s_per_m": self.path["elastic"].damping,
                           "thermal_n_s_per_m": self.path["thermal"].damping,
                           "friction_elastic": self.path["elastic"].friction_coefficient,
                           "friction_thermal": self.path["thermal"].friction_coefficient},
        }
        if self.case_name == "luo2019":
            result["paper_n_s_per_m"] = PAPER_MEAN_DAMPING
        return result


def damping_summary(case: "Case", count: int = 720, path_points: int = 81, rule: Rule | None = None
                    ) -> DampingSummary:
    """Compute the elastic and thermal friction damping of a case (per pair and over the mesh cycle)."""
    from thermogear.mesh_cycle import MeshCycle

    rule = case.damping.rule if rule is None else rule
    oil = lubricant_from_case(case)
    pair = case.gear_pair
    grid = MeshCycle(pair, case.operating_point.speed_rpm).grid(count)
    roll = pair.roll_grid(path_points)
    path, mesh, means, pitch = {}, {}, {}, {}
    for model in MODELS:
        path[model] = pair_damping(case, roll, model, lubricant=oil)
        pitch[model] = pair_damping(case, np.array([pair.path_points["C"]]), model, lubricant=oil)
        mesh[model] = mesh_damping(per_pair_damping_on_grid(case, grid, model), grid.in_contact, rule)
        means[model] = contact_region_means(mesh[model], grid.contact_count, grid.steps)
    return DampingSummary(case_name=case.name, rule=rule, stiffness=case.damping.stiffness, lubricant=oil,
                          path=path, grid=grid, mesh=mesh, region_means=means, pitch=pitch)


def plot_damping(summary: DampingSummary, periods: int = 3, axes=None):
    """Luo & Li Figs. 7–8: per-pair damping along Γ and mesh damping c(τ) over a few mesh periods, elastic
    and thermal. Returns the matplotlib figure."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if axes is None:
        figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    else:
        figure = axes[0].figure
    styles = {"elastic": dict(color="tab:blue", label="elastic c_e (oil at reference temperature)"),
              "thermal": dict(color="tab:red", label="thermal c_r (oil at flank temperature)")}
    for model in MODELS:
        axes[0].plot(summary.path[model].gamma, summary.path[model].damping, **styles[model])
    axes[0].set_xlabel("contact position Γ [–]")
    axes[0].set_ylabel("damping of one tooth pair [N·s/m]")
    axes[0].set_title("per pair along the path")
    grid = summary.grid
    period = grid.nodes[-1]
    for model in MODELS:
        times = np.concatenate([grid.nodes[:-1] + j * period for j in range(periods)] + [[periods * period]])
        values = np.tile(summary.mesh[model], periods)
        axes[1].stairs(values, times * 1e3, baseline=None, color=styles[model]["color"], label=model)
        if summary.case_name == "luo2019" and summary.rule == "paper":
            for region in ("single", "double"):
                axes[1].axhline(PAPER_MEAN_DAMPING[model][region], color=styles[model]["color"], lw=0.8, ls=":")
    axes[1].set_xlabel("time τ [ms]")
    axes[1].set_ylabel("mesh damping c(τ) [N·s/m]")
    title = f"mesh cycle, rule '{summary.rule}'"
    if summary.case_name == "luo2019" and summary.rule == "paper":
        title += " (dotted: paper's means)"
    axes[1].set_title(title)
    axes[0].legend(loc="best", fontsize=8)
    axes[1].legend(loc="best", fontsize=8)
    figure.suptitle(f"Friction damping (Luo & Li Eqs. 26–28), case {summary.case_name}")
    return figure


__all__ = ["DampingSummary", "PAPER_MEAN_DAMPING", "damping_summary", "plot_damping", "MODELS", "RULES", "PairDamping", "contact_region_means", "coulomb_equivalent_damping",
           "friction_damping", "load_shares", "mesh_circular_frequency", "mesh_cycle_damping", "mesh_damping",
           "oil_temperature_c", "pair_damping", "per_pair_damping_on_grid"]
