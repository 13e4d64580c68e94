"""The ``iso_tr_13989_2`` friction law against a commercial calculation's printout: the KISSsoft report of the
third (parallel helical) stage of the NREL 5 MW gearbox, "Calculation method according to ISO TR 13989:2000",
as stored in the public repository gfsReboucas/Drivetrain (``@NREL_5MW/stage_03.rtf``).

Printed inputs: T1C = 67.447 mm, T2C = 266.979 mm (lengths from the interference points to the pitch point C on
the line of action), base helix angle β_b = 9.391°, working transverse pressure angle α_wt = 22.856°, speed at the
operating pitch circle v(d_w) = 21.20 m/s, w_Bt·K_Bγ = 1425.897 N/mm (w_Bt 1119.632 N/mm, K_Bγ 1.274),
R_a = 0.6 μm, η_oil = 30.09 mPa·s at 80 °C. Printed results under "Integral temperature-criteria": X_L = 1.000
(mineral oil), mean coefficient of friction μ_m = 0.030; in the micropitting section (same law, η = 25.2 mPa·s)
X_R = 0.712 and μ = 0.030. From the geometry, ρ_redC = T1C·T2C/(T1C + T2C)/cos β_b (the normal section of a
helical pair) and v_ΣC = 2·v(d_w)·sin α_wt.

Tolerances: the report prints three decimals, so a printed value v stands for [v − 0.0005, v + 0.0005]; the
inputs are printed to 3–4 significant digits, which moves μ by far less than that (μ ∝ (w/(vρ))^0.2)."""

from __future__ import annotations

import math

import pytest

from thermogear.friction.models import PitchContact, friction_law

T1C, T2C = 67.447e-3, 266.979e-3  # [m]
BASE_HELIX = math.radians(9.391)
RELATIVE_RADIUS = T1C * T2C / (T1C + T2C) / math.cos(BASE_HELIX)  # ρ_redC [m], normal section
SUM_VELOCITY = 2.0 * 21.20 * math.sin(math.radians(22.856))  # v_ΣC [m/s]
LOAD_WITH_HELIX_FACTOR = 1425.897e3  # w_Bt·K_Bγ [N/m]
LOAD_WITHOUT = 1119.632e3  # w_Bt [N/m]
ROUGHNESS = 0.6e-6  # [m]


def _friction(unit_load: float, viscosity_mpa_s: float) -> float:
    contact = PitchContact(unit_load, ROUGHNESS, viscosity_mpa_s * 1e-3, SUM_VELOCITY, RELATIVE_RADIUS, 1.0)
    return friction_law("iso_tr_13989_2").coefficient(contact, warn=False)


def test_the_geometry_of_the_printout():
    assert RELATIVE_RADIUS == pytest.approx(54.57e-3, abs=0.01e-3)
    assert SUM_VELOCITY == pytest.approx(16.47, abs=0.01)


def test_the_roughness_factor_as_printed():
    # X_R = 2.2·(R_a [μm]/ρ_redC [mm])^0.25 = 0.7124 (the ratio in the standard's units, not dimensionless);
    # printed 0.712 (±0.0005)
    assert 2.2 * ((ROUGHNESS * 1e6) / (RELATIVE_RADIUS * 1e3))**0.25 == pytest.approx(0.712, abs=0.0005)


@pytest.mark.parametrize("viscosity_mpa_s", [30.09, 25.2], ids=["integral criterion", "micropitting"])
def test_the_mean_friction_coefficient_as_printed(viscosity_mpa_s):
    # μ_mC = 0.0297 (30.09 mPa·s) and 0.0299 (25.2 mPa·s); printed 0.030 both
    assert _friction(LOAD_WITH_HELIX_FACTOR, viscosity_mpa_s) == pytest.approx(0.030, abs=0.0005)


def test_the_load_includes_the_helical_load_factor():
    # without K_Bγ the law gives 0.0283, which would print 0.028: the printout used w_Bt·K_Bγ, as the law does
    assert _friction(LOAD_WITHOUT, 30.09) < 0.0295


def test_the_helical_load_factor_as_a_field_of_the_contact():
    # the contact's K_Bγ = 1.274 (printed) multiplies w_Bt inside the law: the same μ as w_Bt·K_Bγ given at once
    contact = PitchContact(LOAD_WITHOUT, ROUGHNESS, 30.09e-3, SUM_VELOCITY, RELATIVE_RADIUS, 1.0, 1.274)
    law = friction_law("iso_tr_13989_2")
    assert law.coefficient(contact, warn=False) == pytest.approx(_friction(LOAD_WITHOUT * 1.274, 30.09), rel=1e-14)
    assert friction_law("schlenk").coefficient(contact, warn=False) == friction_law("schlenk").coefficient(
        PitchContact(LOAD_WITHOUT, ROUGHNESS, 30.09e-3, SUM_VELOCITY, RELATIVE_RADIUS, 1.0), warn=False)


def test_the_load_is_taken_at_the_reference_circle():
    # The printout builds w_Bt on F_t, the nominal tangential force at the reference circle (F_t/b = 666.85 N/mm
    # times its load factors = 1119.632 N/mm). thermogear's contacts carry the load along the line of action,
    # F_bt/b = (F_t/b)/cos α_t, with the reference transverse pressure angle α_t = 20.284° (printed): the law must
    # turn it back into F_t/b. Identity to rounding; Schlenk's law takes F_bt/b itself and must not change.
    reference_angle = math.radians(20.284)
    along_the_line = LOAD_WITHOUT / math.cos(reference_angle)
    contact = PitchContact(along_the_line, ROUGHNESS, 30.09e-3, SUM_VELOCITY, RELATIVE_RADIUS, 1.0, 1.274,
                           reference_angle)
    law = friction_law("iso_tr_13989_2")
    assert law.coefficient(contact, warn=False) == pytest.approx(_friction(LOAD_WITHOUT * 1.274, 30.09), rel=1e-12)
    schlenk = friction_law("schlenk")
    assert schlenk.coefficient(contact, warn=False) == schlenk.coefficient(
        PitchContact(along_the_line, ROUGHNESS, 30.09e-3, SUM_VELOCITY, RELATIVE_RADIUS, 1.0), warn=False)
