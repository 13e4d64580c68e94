"""A helical pair against a commercial calculation's printout: the KISSsoft report (release 03/2017) of the third,
parallel helical stage of the NREL 5 MW reference gearbox, "CALCULATION OF A HELICAL GEAR PAIR", ISO 6336:2006
Method B, geometry "according to DIN 3960:1987", as stored in the public repository gfsReboucas/Drivetrain
(``@NREL_5MW/stage_03.rtf``). DIN 3960:1987 and ISO 21771:2007 (its successor, DIN ISO 21771) give the same
formulas for every quantity below; this is the worked helical example the project checks its ISO 21771 geometry,
its ISO 6336-1 stiffness and its helical factors against (issue 37).

Printed inputs: a = 861 mm, m_n = 14 mm, α_n = 20°, β = 10°, z = 24 / 95, b = 360 mm, x_n = 0.4800 / 0.6691,
basic rack ISO 53 profile A (h_aP* = 1, h_fP* = 1.25, ρ_fP* = 0.38), E = 206 000 N/mm², ν = 0.3; pinion torque
40 953.0 N·m at 1165.9 1/min; gear body factor C_R = 0.898 (a web: b_s/b = 0.25, s_R/m_n = 5).

Tolerances: a printed value v with d decimals stands for v ± 0.5·10^−d, so each check is
|computed − printed| ≤ 0.5·10^−d unless said otherwise. The lengths that end on a tip circle (tip diameters, T1A,
g_α, the sliding speed at the wheel's tip) carry one more micrometre: the printout's own tip alteration
k·m_n = −0.938 mm (a − a_d − Σx·m_n = −0.93770 mm from its printed inputs) puts d_a1 at 380.7479 mm, which it prints
380.747, so the report's tip circles differ from the formula by up to 1 μm (about 3e-6 of the diameter);
the check there is ± (0.5 + 1) μm, argued from that printed discrepancy, not fitted.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.friction.models import helical_load_factor
from thermogear.helical.contact_lines import contact_length_extremes
from thermogear.helical.geometry import HelicalPair
from thermogear.stiffness.iso6336 import iso6336_mesh_stiffness, iso6336_single_stiffness
from thermogear.helical.iso_stiffness import FACE_STIFFNESS_SHARE

PAIR = HelicalPair.create(24, 95, 14e-3, math.radians(20.0), math.radians(10.0), 0.360, (0.4800, 0.6691),
                          centre_distance=0.861)
TRANSVERSE = PAIR.transverse
PINION_RPM = 1165.9
PINION_TORQUE = 40953.0  # [N·m]
HALF_UNIT = {0: 0.5, 1: 0.05, 2: 0.005, 3: 0.0005, 4: 0.00005}
TIP_MICROMETRE = 1e-3  # [mm] the report's tip circles against the formula (module docstring)

MM = 1e3
POINTS = TRANSVERSE.path_points


def _degrees(angle: float) -> float:
    return math.degrees(angle)


# name: (computed, printed, decimals, extra tolerance)
GEOMETRY = {
    "transverse module m_t [mm]": (PAIR.transverse_module * MM, 14.216, 3, 0.0),
    "transverse pressure angle α_t [°]": (_degrees(PAIR.transverse_pressure_angle), 20.284, 3, 0.0),
    "working transverse pressure angle α_wt [°]": (_degrees(TRANSVERSE.operating_pressure_angle), 22.856, 3, 0.0),
    "helix angle at the operating pitch circle β_w [°]": (_degrees(PAIR.operating_helix_angle), 10.175, 3, 0.0),
    "base helix angle β_b [°]": (_degrees(PAIR.base_helix_angle), 9.391, 3, 0.0),
    "reference diameter d1 [mm]": (2 * TRANSVERSE.pinion.reference_radius * MM, 341.183, 3, 0.0),
    "reference diameter d2 [mm]": (2 * TRANSVERSE.wheel.reference_radius * MM, 1350.517, 3, 0.0),
    "base diameter d_b1 [mm]": (2 * TRANSVERSE.pinion.base_radius * MM, 320.026, 3, 0.0),
    "base diameter d_b2 [mm]": (2 * TRANSVERSE.wheel.base_radius * MM, 1266.770, 3, 0.0),
    "tip diameter d_a1 [mm]": (2 * TRANSVERSE.pinion.tip_radius * MM, 380.747, 3, TIP_MICROMETRE),
    "tip diameter d_a2 [mm]": (2 * TRANSVERSE.wheel.tip_radius * MM, 1395.376, 3, TIP_MICROMETRE),
    "root diameter d_f1 [mm]": (2 * TRANSVERSE.pinion.root_radius * MM, 319.623, 3, 0.0),
    "root diameter d_f2 [mm]": (2 * TRANSVERSE.wheel.root_radius * MM, 1334.252, 3, 0.0),
    "operating pitch diameter d_w1 [mm]": (2 * TRANSVERSE.operating_pitch_radii[0] * MM, 347.294, 3, 0.0),
    "operating pitch diameter d_w2 [mm]": (2 * TRANSVERSE.operating_pitch_radii[1] * MM, 1374.706, 3, 0.0),
    "virtual number of teeth z_n1": (PAIR.virtual_teeth[0], 25.037, 3, 0.0),
    "virtual number of teeth z_n2": (PAIR.virtual_teeth[1], 99.104, 3, 0.0),
    "transverse base pitch p_bt [mm]": (PAIR.transverse_base_pitch * MM, 41.891, 3, 0.0),
    "axial pitch p_x [mm]": (PAIR.axial_pitch * MM, 253.284, 3, 0.0),
    "T1A [mm]": (POINTS["A"] * MM, 41.865, 3, TIP_MICROMETRE),
    "T1B [mm]": (POINTS["B"] * MM, 61.249, 3, TIP_MICROMETRE),
    "T1C [mm]": (POINTS["C"] * MM, 67.447, 3, 0.0),
    "T1D [mm]": (POINTS["D"] * MM, 83.756, 3, TIP_MICROMETRE),
    "T1E [mm]": (POINTS["E"] * MM, 103.141, 3, TIP_MICROMETRE),
    "T1T2 [mm]": (TRANSVERSE.line_of_action_length * MM, 334.426, 3, 0.0),
    "length of path of contact g_α [mm]": (TRANSVERSE.path_length * MM, 61.276, 3, 2 * TIP_MICROMETRE),
    "transverse contact ratio ε_α": (PAIR.transverse_contact_ratio, 1.463, 3, 0.0),
    "overlap ratio ε_β": (PAIR.overlap_ratio, 1.421, 3, 0.0),
    "total contact ratio ε_γ": (PAIR.total_contact_ratio, 2.884, 3, 0.0),
    # Lmin: the shortest total length of the contact lines over the mesh cycle (ends on the path's tip points)
    "minimal length of contact line L_min [mm]": (
        contact_length_extremes(PAIR.transverse_contact_ratio, PAIR.overlap_ratio, PAIR.face_width,
                                PAIR.base_helix_angle)[1] * MM, 483.685, 3, 0.01),
}
# L_min: ∝ ε_α (closed form), and the report's ε_α rests on its g_α, 1 μm shorter than the formula's (above):
# 483.685·(1 μm / 61.276 mm) = 0.008 mm, whence 0.01 mm beside the half unit.


@pytest.mark.parametrize("name", GEOMETRY)
def test_the_geometry_as_printed(name):
    computed, printed, decimals, extra = GEOMETRY[name]
    assert abs(computed - printed) <= HALF_UNIT[decimals] + extra, (name, computed, printed)


def test_the_sliding_speeds_at_the_tips_as_printed():
    # v_ga1 = 5.459 m/s (pinion tip, E), v_ga2 = 3.912 m/s (wheel tip, A); v_g ∝ |s − s_C|, so the wheel tip's
    # carries the report's 1 μm on T1A: 3.912·(1 μm/25.58 mm) = 1.5e-4 m/s beside the half unit
    tips = TRANSVERSE.sliding_speed(np.array([POINTS["E"], POINTS["A"]]), PINION_RPM)
    assert abs(tips[0] - 5.459) <= 0.0005
    assert abs(tips[1] - 3.912) <= 0.0005 + 0.00015


def test_the_operating_pitch_line_speed_as_printed():
    speed = TRANSVERSE.operating_pitch_radii[0] * PINION_RPM * math.pi / 30.0
    assert abs(speed - 21.20) <= 0.005


def test_the_tooth_forces_as_printed():
    # F_t = 2T/d = 240 064.4 N at the reference circle; F_a = 42 329.8 N; F_r = 88 724.2 N; F_n = 259 412.2 N.
    # The pair gives F_a/F_bt = tan β_b with F_bt = F_t/cos α_t (the transverse base tangential force).
    # rel 2.5e-6: each force is printed to 6 digits (half a unit ≤ 1.2e-6 of it) and carries the printed torque's
    # 6 digits (≤ 1.3e-6) through F_t.
    tangential = PINION_TORQUE / TRANSVERSE.pinion.reference_radius
    base_tangential = tangential / math.cos(PAIR.transverse_pressure_angle)
    assert abs(tangential - 240064.4) <= 0.05 + 240064.4 * 1e-6  # torque printed to 6 digits: 1e-6 relative
    assert PAIR.axial_force_ratio() * base_tangential == pytest.approx(42329.8, rel=2.5e-6)
    assert base_tangential * math.sin(PAIR.transverse_pressure_angle) == pytest.approx(88724.2, rel=2.5e-6)
    assert base_tangential / math.cos(PAIR.base_helix_angle) == pytest.approx(259412.2, rel=2.5e-6)


def test_the_iso_6336_stiffness_as_printed():
    # c′ = 13.832 N/(mm·μm) with C_M = 0.8, C_R = 0.898 (printed), C_B = 0.975, cos β; c_γα = c′(0.75ε_α + 0.25)
    # = 18.632; c_γβ = 0.85·c_γα = 15.837 (0.85 × 18.6324 = 15.8375 prints 15.838: the report rounds down once
    # more, so c_γβ is checked to one unit of its last digit)
    single = iso6336_single_stiffness(24, 95, *PAIR.normal_profile_shifts, 206e9, rim_factor=0.898,
                                      pressure_angle=PAIR.normal_pressure_angle, helix_angle=PAIR.helix_angle,
                                      virtual_teeth=PAIR.virtual_teeth, warn=False)
    mesh = iso6336_mesh_stiffness(single, PAIR.transverse_contact_ratio)
    per_mm_um = 1e-9  # N/m² → N/(mm·μm)
    assert abs(single * per_mm_um - 13.832) <= 0.0005
    assert abs(mesh * per_mm_um - 18.632) <= 0.0005
    assert abs(FACE_STIFFNESS_SHARE * mesh * per_mm_um - 15.837) <= 0.001


def test_the_helical_load_factor_of_scuffing_as_printed():
    # K_Bγ = 1.274 at ε_γ = 2.884 (printed); the factor is 1 up to ε_γ = 2 and 1.3 from 3.5, continuous between
    assert abs(helical_load_factor(PAIR.total_contact_ratio) - 1.274) <= 0.0005
    assert helical_load_factor(1.8) == 1.0 and helical_load_factor(2.0) == 1.0
    assert helical_load_factor(3.5) == pytest.approx(1.3, abs=1e-15) and helical_load_factor(4.2) == 1.3
