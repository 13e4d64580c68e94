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


def _shaft_on_rigid_bearings():
    """A 0.5 m shaft (d 40 mm) with a disk at 0.2 m on bearings at both ends that are rigid against it (1e13 N/m,
    against a bending stiffness of order 48EI/L³ ≈ 1e7 N/m and an axial one EA/L ≈ 5e8 N/m)."""
    from drivetrain_builders import uniform_shaft

    from thermogear.drivetrain import Bearing, Drivetrain, NodeLocation, RigidDisk

    shaft = uniform_shaft(0.5, 0.04, 10)
    disk = RigidDisk.annulus("disk", NodeLocation("shaft", 0.2), 7810.0, 0.03, 0.12, 0.04)
    bearings = tuple(Bearing(f"bearing {end}", NodeLocation("shaft", position), 1e13, 1e13, 1e13)
                     for end, position in (("A", 0.0), ("B", 0.5)))
    return Drivetrain((shaft,), (disk,), bearings)


def test_free_expansion_on_rigid_supports_scales_every_frequency_by_the_root_of_one_plus_strain():
    # Every length ×(1 + ε), density ×(1 + ε)⁻³ (mass conserved), E held: a beam's (and the disk's) frequencies
    # go as sqrt(E/ρ)/L, so each one by (1 + ε)^(3/2)/(1 + ε) = sqrt(1 + ε) exactly, Timoshenko or not (shear and
    # rotary terms are ratios of lengths). The held supports break it only through their strain-energy share,
    # largest in the axial mode (an element's EA/l ≈ 5e9 N/m against 1e13: ≤ 5e-4), so δ(shift) ≲ share·ε/2 ≈
    # 2.4e-7 (measured 7.8e-8 axially, ≤ 1e-9 for the bending and torsional modes).
    cold = _shaft_on_rigid_bearings()
    expansion, rise = 1.2e-5, 80.0
    strain = expansion * rise
    warm = WarmState({"shaft": 20.0 + rise}, 0.0, expansion_coefficient_per_k=expansion)
    hot = warm_drivetrain(cold, warm)
    moduli_only = warm_drivetrain(cold, WarmState({"shaft": 20.0 + rise}, 0.0))
    cold_assembled, hot_assembled = cold.assemble(), hot.assemble()
    translation = np.zeros(cold_assembled.size)
    translation[cold_assembled.dof_mask(("x",))] = 1.0
    assert translation @ hot_assembled.mass @ translation == pytest.approx(
        translation @ cold_assembled.mass @ translation, rel=1e-12)  # the mass is conserved
    assert hot_assembled.node_positions["shaft"][-1] == pytest.approx(0.5 * (1.0 + strain), rel=1e-14)
    result = thermal_mode_shifts(cold, hot, count=8, expansion_from=moduli_only)
    np.testing.assert_allclose(result.exact, math.sqrt(1.0 + strain) - 1.0, rtol=0, atol=2.5e-7)
    # E held: the expansion is the whole shift, re-solved (the other causes are zero)
    np.testing.assert_allclose(result.contributions["thermal expansion"], result.exact, rtol=0, atol=1e-12)
    np.testing.assert_allclose(result.first_order, result.exact, rtol=0, atol=1e-12)
    with pytest.raises(CaseError, match="masses"):  # an expanded drivetrain needs its state before the expansion
        thermal_mode_shifts(cold, hot, count=8)


def test_expansion_attribution_sums_to_the_exact_shift_to_first_order():
    # the geared pair warmed with expansion: the remainder (exact − Σ attributions) still falls as the square
    cold = geared_pair(elements=3)
    remainders = []
    for rise in (70.0, 35.0):
        warm = _warm(rise)
        expanded = WarmState(**{**warm.__dict__, "expansion_coefficient_per_k": 11.5e-6})
        result = thermal_mode_shifts(cold, warm_drivetrain(cold, expanded), count=12,
                                     expansion_from=warm_drivetrain(cold, warm))
        assert np.abs(result.contributions["thermal expansion"]).max() > 1e-5  # the expansion moves the modes
        remainders.append(np.abs(result.exact - result.first_order).max())
    assert 3.6 < remainders[0] / remainders[1] < 4.4
