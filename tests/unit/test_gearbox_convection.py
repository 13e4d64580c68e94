"""Heat-transfer correlations: values from the sources or documented hand calculations, limits and continuity."""

from __future__ import annotations

import math

import pytest

from thermogear.errors import CaseError
from thermogear.gearbox.convection import (STEFAN_BOLTZMANN, air_properties, churchill_chu_vertical,
                                           combined_nusselt, flat_plate_forced, horizontal_plate,
                                           radiation_coefficient, rotating_disc)


def test_churchill_chu_against_a_published_value():
    # Nu(Pr 0.69, Gr 2.63e9) = 147.16 (Churchill & Chu's correlation as evaluated in the documentation of
    # CalebBell/ht, Nu_vertical_plate_Churchill); quoted to 5 digits
    assert churchill_chu_vertical(2.63e9 * 0.69, 0.69) == pytest.approx(147.16, abs=0.005)


def test_churchill_chu_limits():
    # Ra → 0: Nu → 0.825² (pure conduction limit of the fit); large Ra: Nu ∝ Ra^(1/3)
    assert churchill_chu_vertical(0.0, 0.7) == pytest.approx(0.825**2, rel=1e-15)
    ratio = churchill_chu_vertical(8e12, 0.7) / churchill_chu_vertical(1e12, 0.7)
    assert ratio == pytest.approx(2.0, rel=0.02)  # the 0.825 offset is 2 % of Nu at Ra 1e12


def test_housing_wall_hand_calculation():
    # wall 0.3 m high at 60 °C in air at 20 °C (film 40 °C): documented hand values Ra 8.3e7, Nu 57.7, h 5.2
    air = air_properties(40.0)
    rayleigh = air.rayleigh(40.0, 0.3)
    nusselt = churchill_chu_vertical(rayleigh, air.prandtl)
    # Sutherland air properties are within a few per cent of tables: Ra to 10 %, Nu (∝ Ra^~0.3) to 3 %
    assert rayleigh == pytest.approx(8.3e7, rel=0.10)
    assert nusselt == pytest.approx(57.7, rel=0.03)
    assert nusselt * air.conductivity / 0.3 == pytest.approx(5.2, rel=0.05)


def test_air_properties_near_tables():
    # air at 300 K (Incropera Table A.4): k 0.0263 W/(m·K), ν 15.89e-6 m²/s, Pr 0.707; Sutherland within 3 %
    air = air_properties(26.85)
    assert air.conductivity == pytest.approx(0.0263, rel=0.03)
    assert air.kinematic_viscosity == pytest.approx(15.89e-6, rel=0.03)
    assert air.prandtl == pytest.approx(0.707, rel=0.03)
    with pytest.raises(CaseError, match="air film temperature"):
        air_properties(-200.0)


def test_horizontal_plate_branches():
    # hand values: 0.54·1e6^0.25 = 17.08, 0.15·1e9^(1/3) = 150, 0.27·1e8^0.25 = 27.0
    assert horizontal_plate(1e6, True) == pytest.approx(0.54 * 31.6227766, rel=1e-9)
    assert horizontal_plate(1e9, True) == pytest.approx(150.0, rel=1e-12)
    assert horizontal_plate(1e8, False) == pytest.approx(27.0, rel=1e-12)
    # the published hot-up branches are 6.4 % apart at Ra = 1e7: 32.32 vs 30.37 (documented, not a bug of this code)
    assert horizontal_plate(1e7 * 1.000001, True) / horizontal_plate(1e7, True) == pytest.approx(1.064, abs=0.001)


def test_flat_plate_branches_meet_at_the_transition():
    # laminar 0.664·Re^0.5 and mixed (0.037 Re^0.8 − 871): the constant 871 is chosen to meet at 5e5 (to 0.1 %)
    below, above = flat_plate_forced(5e5, 0.7), flat_plate_forced(5e5 * (1 + 1e-9), 0.7)
    assert above == pytest.approx(below, rel=1e-3)
    # 2 m/s along 0.3 m of air at 20 °C: Re ≈ 4e4, h ≈ 10 W/(m²K) (hand value, docs)
    air = air_properties(20.0)
    reynolds = 2.0 * 0.3 / air.kinematic_viscosity
    assert flat_plate_forced(reynolds, air.prandtl) * air.conductivity / 0.3 == pytest.approx(10.0, rel=0.1)


def test_combined_nusselt_limits():
    assert combined_nusselt(10.0, 0.0) == pytest.approx(10.0)
    assert combined_nusselt(3.0, 4.0) == pytest.approx(91.0**(1 / 3))


def test_radiation_coefficient_is_the_exact_secant():
    # h_r·(T_s − T_a) = εσ(T_s⁴ − T_a⁴) for any pair of temperatures (algebraic identity)
    surface, ambient = 80.0, -30.0
    flux = radiation_coefficient(0.9, surface, ambient) * (surface - ambient)
    assert flux == pytest.approx(0.9 * STEFAN_BOLTZMANN * ((surface + 273.15)**4 - (ambient + 273.15)**4), rel=1e-13)
    with pytest.raises(CaseError, match="emissivity"):
        radiation_coefficient(1.2, 20.0, 20.0)


def test_rotating_disc_branches():
    # laminar 0.36·Re^0.5; turbulent 0.015·Re^0.8 − 100 (hand values at 1e4 and 1e6)
    assert rotating_disc(1e4) == pytest.approx(36.0)
    assert rotating_disc(1e6) == pytest.approx(0.015 * 1e6**0.8 - 100.0)
    assert math.isfinite(rotating_disc(0.0))
