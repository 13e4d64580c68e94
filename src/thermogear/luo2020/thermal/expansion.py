"""Thermal expansion of the tooth flanks along the line of action (Luo & Li 2020 Eqs. 8–12, Timoshenko & Goodier 1951).

Pure, vectorised functions. Temperatures are **rises above the stress-free reference** [K] (Timoshenko & Goodier 1951; the
paper does not say so, but Eq. 10 is the thermo-elastic displacement of a disc from its stress-free state).

Sign: the flank displacement is projected on the outward normal of the flank at the contact point, i.e. on the
line of action pointing towards the mating tooth. Positive = the flank moves into the mate = interference.

Frame of one tooth (Eqs. 11–12): y along the tooth centreline pointing to the tip, x across it towards the loaded
flank. The contact point K sits at (r_k sin φ_k, r_k cos φ_k); the contact force presses on the flank at the load
angle ω_k = α_k − φ_k to the x axis (Luo & Li (2020) Eq. 8; ω_k = α1 of the potential energy method), so the flank's outward normal is
(cos ω_k, sin ω_k).
"""

from __future__ import annotations

from typing import Literal

import numpy as np

from thermogear.errors import CaseError
from thermogear.registry import registered


def base_circle_radial_expansion(alpha_th, base_radius, bore_radius, base_rise, bore_rise):
    """Radial displacement of the base circle Δr_b [m] (Luo & Li 2020 Eq. 10, first three terms; ref. [33]).

    Free thin annular disc (plane stress) from the bore r_n to the base circle r_b under the steady logarithmic
    temperature field between the bore rise t_n and the base-circle rise t_b (Timoshenko & Goodier 1951):

        Δr_b = λ r_b t_n + λ r_b³ (t_b − t_n)/(r_b² − r_n²) − λ r_b (t_b − t_n)/(2 ln(r_b/r_n))

    Parameters: ``alpha_th`` expansion coefficient λ [1/K]; ``base_radius`` r_b [m]; ``bore_radius`` r_n [m]
    (0 ≤ r_n < r_b; r_n = 0 is the solid disc limit, where the logarithmic term vanishes and Δr_b = λ r_b t_b);
    ``base_rise`` t_b, ``bore_rise`` t_n [K] above the stress-free reference. Equal rises give λ r_b t.
    """
    base_radius = np.asarray(base_radius, dtype=float)
    bore_radius = np.asarray(bore_radius, dtype=float)
    if np.any(bore_radius < 0.0) or np.any(bore_radius >= base_radius):
        raise CaseError("bore_radius_mm", np.round(bore_radius * 1e3, 6).tolist(), "0 <= bore < base radius",
                        "the base-circle expansion (Eq. 10) is that of an annulus from the bore to the base circle")
    difference = np.asarray(base_rise, dtype=float) - np.asarray(bore_rise, dtype=float)
    solid = bore_radius == 0.0
    safe_bore = np.where(solid, 0.5 * base_radius, bore_radius)
    logarithmic = np.where(solid, 0.0, base_radius * difference / (2.0 * np.log(base_radius / safe_bore)))
    result = alpha_th * (base_radius * np.asarray(bore_rise, dtype=float)
                         + base_radius**3 * difference / (base_radius**2 - bore_radius**2)
                         - logarithmic)
    return result if np.ndim(result) else float(result)


Circumferential = Literal["paper", "consistent"]


def _as_printed(half_thickness_growth, half_angle, radial):
    """Eq. 9 as printed: the whole Δs_k/2 widens the tooth on top of the radial move."""
    return half_thickness_growth


def _less_radial_widening(half_thickness_growth, half_angle, radial):
    """Eq. 9 less the widening φ_k Δr_k that the radial move at constant angle already gives."""
    return half_thickness_growth - half_angle * radial


#: The forms of Luo & Li Eq. 9 by name (``[thermal] expansion_model``), each the growth of the half thickness
#: ``form(Δs_k/2, φ_k, Δr_k)`` [m] that turns the half angle (:func:`flank_point_displacement`): the one place the
#: names are compared.
EXPANSION_FORMS = {"paper": _as_printed, "consistent": _less_radial_widening}


def expansion_form(name: str):
    """The form of Eq. 9 called ``name``; a CaseError naming ``thermal.expansion_model`` for any other."""
    return registered(EXPANSION_FORMS, name, "thermal.expansion_model", "unknown form of Eq. 9",
                      "'paper' or 'consistent'")


def flank_point_displacement(alpha_th, radius, half_angle, flank_rise, base_expansion, base_radius,
                             circumferential: Circumferential = "paper"):
    """In-plane displacement (Δx, Δy) [m] of the flank point at radius r_k and half angle φ_k (Eqs. 9–11).

        Δr_k = Δr_b + λ Δt_k (r_k − r_b)                         (Eq. 10, last term Δr_bk)
        Δs_k = λ Δt_k s_k / 2,  s_k = 2 r_k φ_k,  r_k′ = r_k + Δr_k,  φ_k′ = φ_k + Δφ_k
        "paper":       Δφ_k = Δs_k / r_k′                                     (Eq. 9 as printed)
        "consistent":  Δφ_k = (Δs_k − φ_k Δr_k) / r_k′
        Δx = r_k′ sin φ_k′ − r_k sin φ_k,  Δy = r_k′ cos φ_k′ − r_k cos φ_k                              (Eq. 11)

    Eq. 9 as printed counts the circumferential growth twice: moving a point radially at constant angle already
    widens the tooth by φ_k Δr_k, and Eq. 9 adds the whole Δs_k on top. For a uniform rise of a free gear the
    "consistent" form gives the homogeneous expansion (every point moves radially by λ ΔT r, φ unchanged), which
    the finite-element check reproduces to 0.05 %; the printed form overstates the flank expansion by λ ΔT r_b φ_k
    (≈ +30 % at the luo2019 pinion root). "paper" is kept to reproduce Luo & Li.

    ``flank_rise`` Δt_k [K] above the reference; ``base_expansion`` Δr_b [m] from
    :func:`base_circle_radial_expansion`. Eq. 8's φ_k uses the reference-circle thickness (Luo & Li 2020, Eqs. 7–23).
    """
    radius = np.asarray(radius, dtype=float)
    half_angle = np.asarray(half_angle, dtype=float)
    flank_rise = np.asarray(flank_rise, dtype=float)
    radial = base_expansion + alpha_th * flank_rise * (radius - base_radius)
    half_thickness_growth = expansion_form(circumferential)(
        alpha_th * flank_rise * radius * half_angle, half_angle, radial)  # Δs_k = λ Δt_k s_k / 2
    new_radius = radius + radial
    new_half_angle = half_angle + half_thickness_growth / new_radius
    delta_x = new_radius * np.sin(new_half_angle) - radius * np.sin(half_angle)
    delta_y = new_radius * np.cos(new_half_angle) - radius * np.cos(half_angle)
    return delta_x, delta_y


def project_on_line_of_action(delta_x, delta_y, load_angle):
    """Δ_t = Δx cos ω_k + Δy sin ω_k [m] (Luo & Li Eq. 12): the flank displacement along the line of action,
    positive towards the mating tooth (interference)."""
    return np.asarray(delta_x) * np.cos(load_angle) + np.asarray(delta_y) * np.sin(load_angle)


def flank_expansion_along_line_of_action(gear, roll, flank_rise, base_rise, bore_rise, alpha_th,
                                         circumferential: Circumferential = "paper"):
    """Thermal expansion Δ_t [m] of one gear's flank at the contact point, along the line of action, positive =
    interference (Luo & Li 2020 Eqs. 8–12 with the base-circle term of Timoshenko & Goodier 1951).

    ``gear``: a :class:`~thermogear.geometry.Gear` (base radius, bore radius, tooth thickness); ``roll``: distance
    of the contact point from this gear's own base-circle tangency point along the line of action [m]
    (the pinion: T1K; the wheel: T2K = T1T2 − T1K); ``flank_rise`` Δt_k [K] (array like ``roll``),
    ``base_rise`` t_b and ``bore_rise`` t_n [K] above the stress-free reference; ``alpha_th`` λ [1/K];
    ``circumferential``: the form of Eq. 9 (see :func:`flank_point_displacement`).
    """
    roll = np.asarray(roll, dtype=float)
    if np.any(roll < 0.0):
        raise CaseError("roll", float(np.min(roll)), ">= 0", "the contact point lies below the base circle")
    base_radius = gear.base_radius
    radius = np.hypot(base_radius, roll)
    pressure_angle_at_point = np.arctan2(roll, base_radius)  # α_k, tan α_k = ρ_k / r_b
    half_angle = np.asarray(gear.half_angle_at(radius), dtype=float)  # φ_k, Eq. 8
    load_angle = pressure_angle_at_point - half_angle  # ω_k = α_k − φ_k
    base_expansion = base_circle_radial_expansion(alpha_th, base_radius, gear.bore_radius, base_rise, bore_rise)
    delta_x, delta_y = flank_point_displacement(alpha_th, radius, half_angle, flank_rise, base_expansion,
                                                base_radius, circumferential)
    return project_on_line_of_action(delta_x, delta_y, load_angle)


def pair_flank_expansion(gear_pair, roll, pinion_flank_rise, wheel_flank_rise, alpha_th, pinion_base_rise,
                         pinion_bore_rise, wheel_base_rise, wheel_bore_rise,
                         circumferential: Circumferential = "paper"):
    """(Δ_t1, Δ_t2) [m] of the pinion and wheel flanks at roll distances T1K [m] of a pair (Eqs. 8–12)."""
    roll = np.asarray(roll, dtype=float)
    pinion = flank_expansion_along_line_of_action(gear_pair.pinion, roll, pinion_flank_rise, pinion_base_rise,
                                                  pinion_bore_rise, alpha_th, circumferential)
    wheel = flank_expansion_along_line_of_action(gear_pair.wheel, gear_pair.line_of_action_length - roll,
                                                 wheel_flank_rise, wheel_base_rise, wheel_bore_rise, alpha_th,
                                                 circumferential)
    return pinion, wheel
