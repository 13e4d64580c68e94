"""Helical pair geometry (ISO 21771) built as a transverse spur section plus a helix, checked against ISO 21771's
own normal-section formulas computed independently here, and contact lines on the plane of action."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.geometry import Gear, GearPair
from thermogear.helical.contact_lines import (contact_length_extremes, contact_line_length, line_entries,
                                             total_contact_length, zone_line_entries)
from thermogear.helical.geometry import HelicalPair

ALPHA_N = math.radians(20.0)


def involute(angle: float) -> float:
    return math.tan(angle) - angle


def inverse_involute(value: float) -> float:
    angle = 0.5
    for _ in range(60):
        angle -= (involute(angle) - value) / math.tan(angle) ** 2
    return angle


def iso21771(z1, z2, m_n, beta, b, x1=0.0, x2=0.0, h_a=1.0) -> dict:
    """ISO 21771 in the normal section's own terms (no transverse spur pair): m_t, α_t, inv α_wt with tan α_n,
    a, d_a with tip shortening k, g_α, ε_α, ε_β."""
    m_t = m_n / math.cos(beta)
    alpha_t = math.atan(math.tan(ALPHA_N) / math.cos(beta))
    alpha_wt = inverse_involute(involute(alpha_t) + 2.0 * math.tan(ALPHA_N) * (x1 + x2) / (z1 + z2))
    a_0 = m_n * (z1 + z2) / (2.0 * math.cos(beta))
    a = a_0 * math.cos(alpha_t) / math.cos(alpha_wt)
    k = max(x1 + x2 - (a - a_0) / m_n, 0.0)
    d = (z1 * m_t, z2 * m_t)
    d_a = (d[0] + 2 * m_n * (h_a + x1 - k), d[1] + 2 * m_n * (h_a + x2 - k))
    d_b = (d[0] * math.cos(alpha_t), d[1] * math.cos(alpha_t))
    g_alpha = 0.5 * (math.sqrt(d_a[0]**2 - d_b[0]**2) + math.sqrt(d_a[1]**2 - d_b[1]**2)) - a * math.sin(alpha_wt)
    p_bt = math.pi * m_t * math.cos(alpha_t)
    return {"m_t": m_t, "alpha_t": alpha_t, "a": a, "d_a": d_a, "epsilon_alpha": g_alpha / p_bt,
            "epsilon_beta": b * math.sin(beta) / (math.pi * m_n)}


PAIRS = [  # z1, z2, m_n [m], β [°], b [m], x1, x2
    (27, 35, 3e-3, 15.0, 25e-3, 0.0, 0.0),
    (27, 35, 3e-3, 30.0, 25e-3, 0.0, 0.0),
    (20, 30, 3.5e-3, 15.0, 23e-3, 0.1809, 0.0891),  # FZG helical test gear H501 (a = 91.5 mm rig)
    (17, 61, 2e-3, 22.5, 30e-3, 0.4, -0.1),
]


@pytest.mark.parametrize("z1, z2, m_n, beta_deg, b, x1, x2", PAIRS)
def test_the_transverse_section_gives_iso_21771s_normal_section_geometry(z1, z2, m_n, beta_deg, b, x1, x2):
    beta = math.radians(beta_deg)
    helical = HelicalPair.create(z1, z2, m_n, ALPHA_N, beta, b, profile_shifts=(x1, x2))
    expected = iso21771(z1, z2, m_n, beta, b, x1, x2)
    pair = helical.transverse
    # both sides are exact closed forms of the same quantities: only rounding differs (the inverse involute of
    # the code is solved to 1e-14)
    assert helical.transverse_module == pytest.approx(expected["m_t"], rel=1e-13)
    assert helical.transverse_pressure_angle == pytest.approx(expected["alpha_t"], rel=1e-13)
    assert pair.centre_distance == pytest.approx(expected["a"], rel=1e-12)
    assert 2 * pair.pinion.tip_radius == pytest.approx(expected["d_a"][0], rel=1e-12)
    assert 2 * pair.wheel.tip_radius == pytest.approx(expected["d_a"][1], rel=1e-12)
    assert helical.transverse_contact_ratio == pytest.approx(expected["epsilon_alpha"], rel=1e-11)
    assert helical.overlap_ratio == pytest.approx(expected["epsilon_beta"], rel=1e-14)
    assert helical.total_contact_ratio == pytest.approx(expected["epsilon_alpha"] + expected["epsilon_beta"])


def test_the_fzg_helical_test_gear_h501_meshes_at_the_rigs_centre_distance():
    """H501 (z 20/30, m_n 3.5, β 15°, x 0.1809/0.0891) is made for the FZG rig's 91.5 mm: its shifts, given to four
    decimals, fix the zero-backlash centre distance to about ±0.5 μm; the rounding leaves 91.5003 mm."""
    helical = HelicalPair.create(20, 30, 3.5e-3, ALPHA_N, math.radians(15.0), 23e-3, profile_shifts=(0.1809, 0.0891))
    assert helical.transverse.centre_distance == pytest.approx(91.5e-3, abs=0.5e-6)


@pytest.mark.parametrize("beta_deg", [5.0, 15.0, 30.0, 44.0])
def test_helix_identities(beta_deg):
    helical = HelicalPair.create(27, 35, 3e-3, ALPHA_N, math.radians(beta_deg), 25e-3)
    beta, beta_b, alpha_t = helical.helix_angle, helical.base_helix_angle, helical.transverse_pressure_angle
    assert math.sin(beta_b) == pytest.approx(math.sin(beta) * math.cos(ALPHA_N), rel=1e-14)
    assert math.cos(ALPHA_N) * math.cos(beta) == pytest.approx(math.cos(alpha_t) * math.cos(beta_b), rel=1e-14)
    assert math.sin(ALPHA_N) == pytest.approx(math.sin(alpha_t) * math.cos(beta_b), rel=1e-14)
    assert helical.normal_base_pitch == pytest.approx(helical.transverse_base_pitch * math.cos(beta_b), rel=1e-14)
    assert helical.overlap_ratio == pytest.approx(helical.face_advance / helical.transverse_base_pitch, rel=1e-13)
    assert helical.face_width == pytest.approx(helical.overlap_ratio * helical.axial_pitch, rel=1e-13)


def test_a_zero_helix_is_the_spur_pair_exactly():
    helical = HelicalPair.create(27, 35, 3e-3, ALPHA_N, 0.0, 25e-3, bore_radii=(15e-3, 20e-3),
                                 centre_distance=93.2e-3)
    spur = GearPair.create(Gear(27, 3e-3, ALPHA_N, 25e-3, bore_radius=15e-3),
                           Gear(35, 3e-3, ALPHA_N, 25e-3, bore_radius=20e-3), 93.2e-3)
    assert helical.transverse == spur and helical.virtual_spur_pair() == spur
    assert helical.overlap_ratio == 0.0 and helical.base_helix_angle == 0.0 and helical.axial_pitch == math.inf
    assert helical.virtual_teeth == (27.0, 35.0)


# ------------------------------------------------------------------------------------- contact lines
@pytest.mark.parametrize("beta_deg, width_mm", [(0.0, 25.0), (15.0, 25.0), (30.0, 25.0), (15.0, 10.0),
                                                 (15.0, 45.0), (8.0, 40.0)])
def test_the_total_contact_length_has_its_closed_form_mean_and_extremes(beta_deg, width_mm):
    helical = HelicalPair.create(27, 35, 3e-3, ALPHA_N, math.radians(beta_deg), width_mm * 1e-3)
    pair = helical.transverse
    phase = np.linspace(0.0, pair.base_pitch, 40001)[:-1]
    length = total_contact_length(phase, pair.path_length, helical.face_width, helical.base_helix_angle,
                                  pair.base_pitch)
    mean, low, high = contact_length_extremes(helical.transverse_contact_ratio, helical.overlap_ratio,
                                              helical.face_width, helical.base_helix_angle)
    # 40 000 phases: a step (spur) or a corner (helical) is located within p_bt/40 000, so the mean carries at
    # most b/40 000 per step and the extremes are exact at the sampled plateaus
    assert np.mean(length) == pytest.approx(mean, abs=2 * helical.face_width / 40000)
    assert np.min(length) == pytest.approx(low, rel=1e-4) and np.max(length) == pytest.approx(high, rel=1e-4)


@pytest.mark.parametrize("beta_deg, width_mm", [(0.0, 25.0), (15.0, 25.0), (30.0, 25.0), (15.0, 10.0),
                                                 (8.0, 40.0), (40.0, 60.0)])
def test_the_lines_in_the_zone_are_every_line_that_touches_it(beta_deg, width_mm):
    """zone_line_entries (each phase its own first line, the mesh model's slices) keeps every line with a length
    in the zone, at the same entry value, and leaves out lines: the lengths sum to the same total (to the
    rounding of a sum taken in another order where many lines touch)."""
    helical = HelicalPair.create(27, 35, 3e-3, ALPHA_N, math.radians(beta_deg), width_mm * 1e-3)
    pair = helical.transverse
    phase = (np.arange(4096) + 0.5) / 4096 * pair.base_pitch
    arguments = (pair.path_length, helical.face_advance, pair.base_pitch)
    every, zone = line_entries(phase, *arguments), zone_line_entries(phase, *arguments)
    lengths = [contact_line_length(entries, pair.path_length, helical.face_width, helical.base_helix_angle)
               for entries in (every, zone)]
    assert zone.shape[-1] < every.shape[-1]
    kept = lengths[0] > 0.0
    for row in range(phase.size):  # the touching lines, in order, with their entries exactly
        touching = lengths[1][row] > 0.0
        np.testing.assert_array_equal(zone[row][touching], every[row][kept[row]])
    np.testing.assert_allclose(lengths[1].sum(axis=-1), lengths[0].sum(axis=-1), rtol=1e-14)


def test_the_contact_length_is_constant_at_an_integer_overlap_ratio_and_spur_like_at_a_small_one():
    helical = HelicalPair.create(27, 35, 3e-3, ALPHA_N, math.radians(15.0), 25e-3)
    one_axial_pitch = HelicalPair.create(27, 35, 3e-3, ALPHA_N, math.radians(15.0), helical.axial_pitch)
    mean, low, high = contact_length_extremes(one_axial_pitch.transverse_contact_ratio,
                                              one_axial_pitch.overlap_ratio, one_axial_pitch.face_width,
                                              one_axial_pitch.base_helix_angle)
    assert one_axial_pitch.overlap_ratio == pytest.approx(1.0) and (high - low) / mean < 1e-12
    # while ε_β <= min(n_α, 1 − n_α) a helix only ramps the spur steps: the swing stays b/cos β_b, i.e. 1/ε_α
    narrow = HelicalPair.create(27, 35, 3e-3, ALPHA_N, math.radians(15.0), 10e-3)
    n_alpha = narrow.transverse_contact_ratio % 1.0
    assert narrow.overlap_ratio <= min(n_alpha, 1.0 - n_alpha)
    mean, low, high = contact_length_extremes(narrow.transverse_contact_ratio, narrow.overlap_ratio,
                                              narrow.face_width, narrow.base_helix_angle)
    assert (high - low) / mean == pytest.approx(1.0 / narrow.transverse_contact_ratio, rel=1e-12)
