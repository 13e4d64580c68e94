"""Unloaded deviations of a tooth pair along the line of action [m], positive = material missing (the pair
engages later than a perfect involute pair would).

Three parts (docs/thermal.md):

- profile modification: linear or parabolic tip relief of each gear, given by its amount at the tip and its length
  as a roll distance along the line of action measured from the tip (Lin, Townsend & Oswald 1986, ASME J. Mech.
  Trans. Autom. Des. 108(1):86 use the same two shapes);
- base-pitch deviation: gears at different bulk strains have base pitches p_b1 ≠ p_b2; successive pairs meet
  p_b1 − p_b2 late (pinion hotter) per pitch. Referred to the nominal gear ratio this is a deviation that varies
  linearly along each pair's roll, zero at the pitch point C, with slope (p_b2 − p_b1)/p_b1, so that two pairs one
  pinion base pitch apart differ by exactly p_b1 − p_b2; the same function serves every pair slot;
- thermal flank distortion: the flank expansion of the non-uniform part of the temperature field, i.e. the
  consistent form of Luo & Li (2020) Eqs. 8–12 (:func:`thermogear.luo2020.thermal.expansion.flank_expansion_along_line_of_action`)
  minus the homogeneous expansion of the gear's equivalent bulk rise, which is already in the operating geometry.
"""

from __future__ import annotations

import numpy as np

from thermogear.geometry import Gear
from thermogear.luo2020.thermal.expansion import base_circle_radial_expansion, flank_expansion_along_line_of_action

RELIEF_EXPONENTS = {"linear": 1.0, "parabolic": 2.0}


def tip_relief(own_roll, tip_roll: float, amount: float, length: float, shape: str = "linear"):
    """Tip relief of one gear's flank [m] at roll distances ``own_roll`` measured from that gear's own base-circle
    tangency point (pinion: T1K; wheel: T2K).

        e = C·((ρ − (ρ_tip − L))/L)^n  for ρ > ρ_tip − L, else 0;  n = 1 (linear), 2 (parabolic)

    ``tip_roll`` ρ_tip: roll distance of the tip [m]; ``amount`` C at the tip [m]; ``length`` L [m].
    """
    own_roll = np.asarray(own_roll, dtype=float)
    if amount == 0.0:
        return np.zeros_like(own_roll)
    exponent = RELIEF_EXPONENTS[shape]
    depth = np.clip((own_roll - (tip_roll - length)) / length, 0.0, None)
    return amount * depth**exponent


def base_pitch_deviation(roll, pitch_point_roll: float, pinion_base_pitch: float, wheel_base_pitch: float):
    """e_pb = (p_b2 − p_b1)/p_b1 · (roll − roll_C) [m] (module docstring): zero when the pitches are equal.

    Only the ratio of the two pitches matters, so they may be given in any common unit (e.g. 1 + ε1, 1 + ε2)."""
    roll = np.asarray(roll, dtype=float)
    return (wheel_base_pitch - pinion_base_pitch) / pinion_base_pitch * (roll - pitch_point_roll)


def equivalent_bulk_rise(gear: Gear, expansion_per_k: float, base_rise: float, bore_rise: float) -> float:
    """Uniform rise [K] that gives the gear body the same base-circle expansion as its bore/base-circle field
    (Luo & Li Eq. 10): Δr_b/(λ r_b). Equal to the rise itself for a uniform field."""
    if base_rise == bore_rise:
        return float(base_rise)
    if expansion_per_k == 0.0:
        return 0.5 * (base_rise + bore_rise)
    expansion = base_circle_radial_expansion(expansion_per_k, gear.base_radius, gear.bore_radius, base_rise,
                                             bore_rise)
    return float(expansion / (expansion_per_k * gear.base_radius))


def flank_distortion(gear: Gear, own_roll, flank_rise, base_rise: float, bore_rise: float,
                     expansion_per_k: float, bulk_rise: float):
    """Flank expansion of the non-uniform part of the field along the line of action [m], positive =
    interference: Eqs. 8–12 (consistent form) minus the homogeneous expansion λ·ΔT_bulk·ρ of the bulk rise.

    A homogeneous expansion moves the contact point at radius r radially by λΔT·r; along the flank normal that
    is λΔT·r·sin α_k = λΔT·ρ (ρ the gear's own roll distance), which is what is subtracted.
    """
    own_roll = np.asarray(own_roll, dtype=float)
    total = flank_expansion_along_line_of_action(gear, own_roll, flank_rise, base_rise, bore_rise,
                                                 expansion_per_k, "consistent")
    return np.asarray(total, dtype=float) - expansion_per_k * bulk_rise * own_roll
