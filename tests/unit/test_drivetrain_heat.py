"""Heat in the drivetrain: the first-order attribution of each mode's shift adds up to the exact re-solved shift to
first order (the remainder falls as the square of the temperature rise), equals Σ e_j·δk_j/k_j where an element only
scales, and names the mesh as the cause of the mesh mode's shift."""

from __future__ import annotations

import math

import numpy as np
import pytest
from drivetrain_builders import geared_pair

from thermogear.drivetrain.heat import WarmState, thermal_mode_shifts, warm_drivetrain
from thermogear.drivetrain.modes import drivetrain_modes
from thermogear.errors import CaseError

BETA = -3.33e-4  # β_E of carbon steel [1/K], the gears' default in thermogear


def _warm(rise: float) -> WarmState:
    # shafts warmed by the rise (the wheel shaft a little less), mesh stiffness by E(T), hot pair grown by
    # 11.5e-6/K, operating pressure angle moved by the housing (2e-5 rad/K: a made-up but typical size)
    return WarmState({"pinion shaft": 20.0 + rise, "wheel shaft": 20.0 + 0.8 * rise}, BETA,
                     mesh_stiffness=3e8 * (1.0 + BETA * rise), base_radius_1=0.0381 * (1 + 11.5e-6 * rise),
                     base_radius_2=0.0493 * (1 + 11.5e-6 * rise),
                     operating_pressure_angle=math.radians(20.0) + 2e-5 * rise)


def test_attributions_sum_to_the_exact_shift_to_first_order():
    cold = geared_pair(elements=3)
    remainders, shifts = [], []
    for rise in (70.0, 35.0):
        result = thermal_mode_shifts(cold, warm_drivetrain(cold, _warm(rise)), count=12)
        remainders.append(np.abs(result.exact - result.first_order).max())
        shifts.append(np.abs(result.exact).max())
    # second-order remainder: halving every change quarters it (measured 9.71e-5 → 2.41e-5, ratio 4.02); the
    # shifts themselves only halve (measured 0.83 % → 0.41 %)
    assert 3.6 < remainders[0] / remainders[1] < 4.4
    assert 1.9 < shifts[0] / shifts[1] < 2.1
    assert remainders[0] < 0.02 * shifts[0]


def test_a_scaled_element_contributes_its_energy_share_times_its_change():
    cold = geared_pair(elements=3)
    warm = WarmState({}, BETA, mesh_stiffness=3e8 * 0.98)  # the mesh stiffness alone falls by 2 %
    result = thermal_mode_shifts(cold, warm_drivetrain(cold, warm), count=12)
    shares = drivetrain_modes(cold.assemble(), count=12).mesh_share("mesh")
    # δf/f = ½·e_mesh·δk/k (the module docstring's formula, same arithmetic: rounding only)
    assert result.contributions["mesh stiffness"] == pytest.approx(0.5 * shares * (-0.02), abs=1e-14)
    for name, values in result.contributions.items():
        if name != "mesh stiffness":
            assert np.abs(values).max() == 0.0
    torsional = int(np.argmax(shares))
    assert result.dominant_cause(torsional) == "mesh stiffness"
    # exact: the second-order remainder relative to the shift is of the order of δk/k = 2 % times the coupling of
    # the mode to its neighbours through the mesh (measured 1.9 %): 5 %
    assert result.exact[torsional] == pytest.approx(result.first_order[torsional], rel=5e-2)


def test_warm_drivetrain_scales_the_shaft_moduli():
    cold = geared_pair(elements=2)
    hot = warm_drivetrain(cold, WarmState({"pinion shaft": 90.0}, BETA))
    ratio = hot.shafts[0].segments[0].material.youngs_modulus / cold.shafts[0].segments[0].material.youngs_modulus
    assert ratio == pytest.approx(1.0 + BETA * 70.0, rel=1e-14)
    assert hot.shafts[1].segments[0].material == cold.shafts[1].segments[0].material
    with pytest.raises(CaseError, match="shaft_temperature_c"):
        warm_drivetrain(cold, WarmState({"motor shaft": 90.0}, BETA))
    with pytest.raises(CaseError, match="modulus_coefficient_per_k"):
        WarmState({}, 0.01)
    with pytest.raises(CaseError, match="shaft_temperature_c"):
        WarmState({"pinion shaft": 900.0}, BETA)
