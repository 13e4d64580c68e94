"""Load plausibility (issue 25): loads no steel tooth carries are labelled beside the result (which stays)."""

from __future__ import annotations

import math

import pytest

from thermogear.case import case_from_document, load_case
from thermogear.load_capacity import load_flags, nominal_stresses


def pair_document(module_mm: float, width_mm: float, operating: dict) -> dict:
    return {"case": {"name": "load"},
            "gears": {"module_mm": module_mm, "face_width_mm": width_mm, "pinion": {"teeth": 20},
                      "wheel": {"teeth": 40}},
            "operating": {"speed_rpm": 1000.0, **operating}, "temperature": {"bulk_c": 60.0}}


def _flags(case) -> tuple[str, ...]:
    return load_flags(case.gear_pair, case.material, case.operating_point.torque)


@pytest.mark.parametrize("name", ["luo2019", "fzg_type_c"])
def test_the_built_in_cases_carry_plausible_loads(name):
    case = load_case(name)
    values = nominal_stresses(case.gear_pair, case.material, case.operating_point.torque)
    # luo2019 (80 kW at 2000 rpm, b 16 mm): about 1200 N/mm² at the pitch point, a usual case-hardened load
    assert 500e6 < values["contact_stress"] < 1600e6
    assert _flags(case) == ()


def test_the_stresses_scale_with_the_load_as_the_iso_forms_say():
    case = load_case("luo2019")
    one = nominal_stresses(case.gear_pair, case.material, 100.0)
    four = nominal_stresses(case.gear_pair, case.material, 400.0)
    # σ_H ∝ √F_t (Hertz), σ_F ∝ F_t and δ ∝ F_t (linear): exact up to rounding
    assert four["contact_stress"] / one["contact_stress"] == pytest.approx(2.0, rel=1e-12)
    assert four["root_stress"] / one["root_stress"] == pytest.approx(4.0, rel=1e-12)
    assert four["static_deflection"] / one["static_deflection"] == pytest.approx(4.0, rel=1e-12)


def test_elasticity_factor_of_steel_is_the_iso_value():
    # ISO 6336-2: Z_E = √(E / (2π(1 − ν²))) for two equal materials, 189.8 √(N/mm²) for steel (E 206 GPa, ν 0.3)
    modulus, poisson = 206e9, 0.3
    assert math.sqrt(modulus / (2 * math.pi * (1 - poisson**2))) / 1e3 == pytest.approx(189.8, abs=0.05)


@pytest.mark.parametrize("module_mm, width_mm, operating, words", [
    (0.5, 5.0, {"torque_nm": 1e7}, ("contact stress", "root stress", "deflection")),  # DTE 5.4 m, "valid"
    (0.5, 5.0, {"fzg_load_stage": 6}, ("contact stress", "root stress")),  # m 0.5 at an FZG load of m 4.5
])
def test_loads_no_steel_tooth_carries_are_flagged(module_mm, width_mm, operating, words):
    case = case_from_document(pair_document(module_mm, width_mm, operating))
    flags = " ".join(_flags(case))
    for word in words:
        assert word in flags

