"""Load-dependent tooth-mesh power loss: gear loss factor and the friction integral along the path of contact.

The sliding friction of the teeth dissipates, averaged over a mesh period (a new pair enters every base pitch p_b
while one pair traverses the path A → E),

    P_VZP = (1/p_b) ∫_A^E μ(s)·F_n(s)·v_g(s) ds                                              [W]

with F_n the normal load of one pair [N] and v_g = |v1 − v2| its sliding speed [m/s] (Wimmer's local loss factor;
Niemann & Winter, Maschinenelemente II, 2nd ed. 1989, §21.6). With a constant μ this is P_in·μ·H_V, and for the
"ideal" (rigid) load sharing — one pair carries F_bt in single contact, each of two pairs F_bt/2 in double contact —
the integral is Ohlendorf's closed form (Ohlendorf 1958, TU Braunschweig; quoted in Niemann & Winter §21.6)

    H_V = π·(u + 1)/(z1·u·cos β_b)·(1 − ε_α + ε1² + ε2²)                                      [–]

ε1, ε2 the addendum contact ratios of pinion and wheel. Derivation (spur): v_g = |s − s_C|·ω1·(u + 1)/u; with
x = (s − s_C)/p_b on [−ε2, ε1], ∫F_n|s − s_C| ds = F_bt p_b²·(1 − ε_α + ε1² + ε2²)/2; divided by
p_b·F_bt·ω1·r_b1 (P_in = F_bt·ω1·r_b1) and with p_b = 2π r_b1/z1 this is H_V. Validity of the closed form:
1 ≤ ε_α ≤ 2 and ε1, ε2 ≤ 1 (the pitch point in single contact). Any sharing that moves load from the ends of the
path towards the pitch point lowers the integral below H_V, because v_g grows with the distance from it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.errors import CaseError
from thermogear.geometry import GearPair


def addendum_contact_ratios(pair: GearPair) -> tuple[float, float]:
    """ε1 = CE/p_b (pinion addendum) and ε2 = AC/p_b (wheel addendum) [–] (ISO 21771 path points)."""
    points = pair.path_points
    return ((points["E"] - points["C"]) / pair.base_pitch, (points["C"] - points["A"]) / pair.base_pitch)


def gear_loss_factor(pinion_teeth: int, gear_ratio: float, pinion_addendum_ratio: float,
                     wheel_addendum_ratio: float, base_helix_angle: float = 0.0) -> float:
    """Ohlendorf's gear loss factor H_V [–] (module docstring; Niemann & Winter §21.6).

    ``pinion_addendum_ratio`` ε1 and ``wheel_addendum_ratio`` ε2 [–]; ``base_helix_angle`` β_b [rad]. Refuses
    pairs outside the closed form's validity (1 ≤ ε_α ≤ 2, ε1, ε2 ≤ 1): use :func:`path_loss_factor` there.
    """
    total = pinion_addendum_ratio + wheel_addendum_ratio
    if not (1.0 <= total <= 2.0 and 0.0 < pinion_addendum_ratio <= 1.0 and 0.0 < wheel_addendum_ratio <= 1.0):
        raise CaseError("contact_ratio", round(total, 6), "1 <= ε_α <= 2 with ε1, ε2 in (0, 1]",
                        "Ohlendorf's gear loss factor assumes the pitch point in single contact; integrate the "
                        "friction along the path (path_loss_factor) instead")
    if not gear_ratio > 0.0 or pinion_teeth < 1:
        raise CaseError("gear_ratio", gear_ratio, "> 0 with z1 >= 1", "a gear pair needs teeth")
    return (math.pi * (gear_ratio + 1.0) / (pinion_teeth * gear_ratio * math.cos(base_helix_angle))
            * (1.0 - total + pinion_addendum_ratio**2 + wheel_addendum_ratio**2))


def pair_gear_loss_factor(pair: GearPair, base_helix_angle: float = 0.0) -> float:
    """H_V [–] of a pair from its own path points: a spur pair, or the transverse section of a helical pair of base
    helix angle β_b [rad] (Ohlendorf's 1/cos β_b)."""
    return gear_loss_factor(pair.pinion.teeth, pair.gear_ratio, *addendum_contact_ratios(pair), base_helix_angle)


def rigid_load_share(pair: GearPair, roll) -> np.ndarray:
    """Share of the total normal load carried by one pair at roll distances on [A, E] [–] for "ideal" rigid
    sharing: 1 in single contact (B..D), 1/2 in the double-contact zones (A..B, D..E)."""
    roll = np.asarray(roll, dtype=float)
    points = pair.path_points
    single = (roll >= points["B"]) & (roll <= points["D"])
    return np.where(single, 1.0, 0.5)


def path_friction_power(roll, normal_load, sliding_speed, friction, base_pitch: float) -> float:
    """P_VZP = (1/p_b) ∫ μ·F_n·v_g ds [W] (module docstring) by the trapezoidal rule over one pair's roll.

    ``roll`` [m] non-decreasing from A to E (repeat a position to mark a jump: the rule is then exact for a
    piecewise-linear integrand with its kinks at nodes); ``normal_load`` F_n of that pair [N], ``sliding_speed``
    v_g [m/s] and ``friction`` μ [–] at those positions (scalars broadcast); ``base_pitch`` p_b [m]. Take F_n, μ
    from the mesh model's own load sharing and friction coefficient (:func:`mesh_model_friction_power`).
    """
    roll = np.asarray(roll, dtype=float)
    if roll.ndim != 1 or roll.size < 2 or np.any(np.diff(roll) < 0.0) or not roll[-1] > roll[0]:
        raise CaseError("roll", roll.size, "a non-decreasing array of at least 2 positions",
                        "the path integral (a position repeated marks a jump of the load share)")
    if not base_pitch > 0.0:
        raise CaseError("base_pitch", base_pitch, "> 0 m", "one pair enters every base pitch")
    integrand = np.broadcast_to(np.asarray(friction, float) * np.asarray(normal_load, float)
                                * np.asarray(sliding_speed, float), roll.shape)
    if not np.all(np.isfinite(integrand)) or np.any(integrand < 0.0):
        raise CaseError("friction·load·sliding", float(np.min(integrand)), "finite and >= 0",
                        "friction power cannot be negative")
    return float(np.sum(0.5 * (integrand[1:] + integrand[:-1]) * np.diff(roll)) / base_pitch)


def path_loss_factor(pair: GearPair, roll, load_share) -> float:
    """Local gear loss factor H_VL = (1/(p_b·F_bt·v_b)) ∫ F_n·v_g ds [–] for a load share F_n/F_bt along the
    roll (1 everywhere is "no sharing"; :func:`rigid_load_share` gives H_V). Independent of speed and load."""
    roll = np.asarray(roll, dtype=float)
    speed_rpm = 1.0  # H_VL is a ratio: any speed and a unit load give it
    base_speed = pair.pinion.base_radius * speed_rpm * math.pi / 30.0
    power = path_friction_power(roll, load_share, pair.sliding_speed(roll, speed_rpm), 1.0, pair.base_pitch)
    return power / base_speed


def mesh_power_loss(input_power: float, friction: float, loss_factor: float) -> float:
    """P_VZP = P_in·μ_m·H_V [W] (Niemann & Winter §21.6): ``input_power`` [W], mean ``friction`` [–]."""
    for key, value in (("input_power", input_power), ("friction", friction), ("loss_factor", loss_factor)):
        if not (math.isfinite(value) and value >= 0.0):
            raise CaseError(key, value, "finite and >= 0", "a power loss is not negative")
    return input_power * friction * loss_factor


def blok_heat_partition(effusivities: tuple[float, float], rolling_speeds) -> np.ndarray:
    """Share β1 of the friction heat entering the pinion [–] by Blok's partition of equal flash temperatures
    (Blok 1937, Proc. Gen. Disc. Lubrication, IMechE 2:222): β1 = e1√v1/(e1√v1 + e2√v2), e = √(λρc)
    [W·s^0.5/(m²·K)], v1, v2 the rolling speeds [m/s] (arrays broadcast). The wheel gets 1 − β1."""
    v_1, v_2 = (np.maximum(np.asarray(v, dtype=float), 0.0) for v in rolling_speeds)
    first, second = effusivities[0] * np.sqrt(v_1), effusivities[1] * np.sqrt(v_2)
    total = first + second
    return np.where(total > 0.0, first / np.where(total > 0.0, total, 1.0), 0.5)


def rigid_pinion_heat_share(pair: GearPair, points_per_stretch: int = 4001) -> float:
    """β1 [–]: the pinion's share of the mesh's friction heat, Blok's partition (:func:`blok_heat_partition`, one
    material: the effusivities cancel) averaged over one pair's passage A → E with the friction power of rigid load
    sharing, β1 = ∫F_n·v_g·β(s) ds / ∫F_n·v_g ds (F_n from :func:`rigid_load_share`, v_g = |v1 − v2|, μ constant
    as in H_V). Near A the pinion's root rolls slowly against the wheel's tip (β < 1/2), near E the reverse; both
    rolling speeds scale with the pinion speed, so β1 is a property of the geometry. Trapezoidal rule on
    ``points_per_stretch`` points of each smooth stretch A–B, B–C, C–D, D–E (exact to about 1e-9)."""
    points = pair.path_points
    heat = pinion = 0.0
    for start, end in (("A", "B"), ("B", "C"), ("C", "D"), ("D", "E")):
        if not points[end] > points[start]:
            continue
        roll = np.linspace(points[start], points[end], points_per_stretch)
        speeds = pair.rolling_speeds(roll, 1.0)  # any speed: only their ratio matters
        power = rigid_load_share(pair, 0.5 * (roll[0] + roll[-1])) * np.abs(np.asarray(speeds[0] - speeds[1]))
        heat += float(np.trapezoid(power, roll))
        pinion += float(np.trapezoid(power * blok_heat_partition((1.0, 1.0), speeds), roll))
    return pinion / heat


@dataclass(frozen=True)
class MeshFrictionLoss:
    """Tooth friction loss of one operating point from a mesh model's load sharing and μ."""

    power: float  # P_VZP from the path integral [W]
    input_power: float  # T1·ω1 [W]
    loss_factor: float  # local H_VL with the model's sharing [–]
    rigid_loss_factor: float  # Ohlendorf's H_V [–]
    mean_friction: float  # P_VZP/(P_in·H_VL) [–]
    pinion_heat_share: float  # Blok partition averaged with the friction power [–]


def mesh_model_friction_power(mesh_model, speed_rpm: float, normal_load: float, count: int = 801,
                              effusivities: tuple[float, float] = (12_940.0, 12_940.0)) -> MeshFrictionLoss:
    """P_VZP [W] from the mesh model's own load sharing and friction coefficient (``pair_damping_at``: the
    DIN 3990-4 μ at the local viscosity) at a pinion speed [rpm] and total normal load F_bt [N]; ``count``
    roll positions from A to E; ``effusivities`` √(λρc) of pinion and wheel (steel ≈ 12 940 W·s^0.5/(m²K))."""
    pair = mesh_model.gear_pair
    roll = pair.roll_grid(count)
    damping = mesh_model.pair_damping_at(roll, speed_rpm, normal_load)
    share = np.asarray(damping.load_share, dtype=float)
    friction = np.asarray(damping.friction_coefficient, dtype=float)
    sliding = pair.sliding_speed(roll, speed_rpm)
    power = path_friction_power(roll, share * normal_load, sliding, friction, pair.base_pitch)
    input_power = normal_load * pair.pinion.base_radius * speed_rpm * math.pi / 30.0
    local = path_loss_factor(pair, roll, share)
    beta = blok_heat_partition(effusivities, pair.rolling_speeds(roll, speed_rpm))
    weight = friction * share * sliding
    pinion_share = float(np.sum(beta * weight) / np.sum(weight)) if np.sum(weight) > 0.0 else 0.5
    return MeshFrictionLoss(power, input_power, local, pair_gear_loss_factor(pair),
                            power / (input_power * local), pinion_share)
