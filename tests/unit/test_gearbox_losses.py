"""Power losses of the gearbox: tooth friction (gear loss factor and path integral), SKF bearings, seals,
churning (continuity of the regime table) and the mesh model's own load sharing."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.errors import CaseError
from thermogear.gearbox.bearing_loss import NJ406_CONSTANTS, RollingBearing, seal_power_loss
from thermogear.gearbox.churning import (CRITICAL_REYNOLDS, DippedGear, churning_coefficient, churning_power_loss)
from thermogear.gearbox.mesh_loss import (addendum_contact_ratios, blok_heat_partition, gear_loss_factor,
                                          mesh_power_loss, pair_gear_loss_factor, path_friction_power,
                                          path_loss_factor, rigid_load_share)
from thermogear.geometry import Gear, GearPair


@pytest.fixture(scope="module")
def fzg_c() -> GearPair:
    # FZG type C (ISO 14635-1): m 4.5 mm, z 16/24, x 0.1817/0.1715, a 91.5 mm, b 14 mm, tips with ISO 21771 shortening
    pinion = Gear(16, 4.5e-3, math.radians(20.0), 14e-3, 0.1817)
    wheel = Gear(24, 4.5e-3, math.radians(20.0), 14e-3, 0.1715)
    return GearPair.create(pinion, wheel, 91.5e-3)


def exact_roll_nodes(pair: GearPair, count: int = 11) -> tuple[np.ndarray, np.ndarray]:
    """Roll grid on [A, E] with B and D repeated (the jumps of the rigid share) and C a node (the kink of v_g),
    and the rigid share on it (1/2 | 1 | 1/2): the trapezoidal rule is then exact for the piecewise-linear
    F_n·v_g."""
    points = pair.path_points
    pieces = [np.linspace(points[a], points[b], count) for a, b in (("A", "B"), ("B", "D"), ("D", "E"))]
    middle = np.unique(np.concatenate([pieces[1], [points["C"]]]))
    shares = [np.full(count, 0.5), np.ones(middle.size), np.full(count, 0.5)]
    return np.concatenate([pieces[0], middle, pieces[2]]), np.concatenate(shares)


def test_fzg_c_contact_ratios_and_gear_loss_factor(fzg_c):
    # ε1 = 0.7224, ε2 = 0.7153 and H_V = 0.19497 (closed form); 5e-5 is the rounding of the quoted values
    first, second = addendum_contact_ratios(fzg_c)
    assert first == pytest.approx(0.7224, abs=5e-5) and second == pytest.approx(0.7153, abs=5e-5)
    assert pair_gear_loss_factor(fzg_c) == pytest.approx(0.19497, abs=5e-6)


def test_rigid_sharing_path_integral_equals_ohlendorf(fzg_c):
    # exact quadrature (exact_roll_nodes): the two forms are the same integral, so they agree to rounding; 1e-6 is
    # the brief's bound, met with room
    roll, share = exact_roll_nodes(fzg_c)
    integral = path_loss_factor(fzg_c, roll, share)
    assert integral == pytest.approx(pair_gear_loss_factor(fzg_c), rel=1e-6)
    assert integral == pytest.approx(0.19497, abs=5e-6)


def test_rigid_load_share_on_a_fine_grid_converges_to_h_v(fzg_c):
    # rigid_load_share on a plain grid smears each jump over one interval: error O(h), 1e-5 at 20 001 points
    roll = fzg_c.roll_grid(20_001)
    assert path_loss_factor(fzg_c, roll, rigid_load_share(fzg_c, roll)) == pytest.approx(0.194973, rel=1e-4)


def test_without_sharing_the_loss_factor_is_larger(fzg_c):
    # F_n = F_bt on the whole path: (ε1² + ε2²)·π(u+1)/(z1 u) = 0.338 (hand value to 3 digits)
    roll, _ = exact_roll_nodes(fzg_c)
    unshared = path_loss_factor(fzg_c, roll, np.ones_like(roll))
    first, second = addendum_contact_ratios(fzg_c)
    u = fzg_c.gear_ratio
    assert unshared == pytest.approx(math.pi * (u + 1) / (16 * u) * (first**2 + second**2), rel=1e-12)
    assert unshared == pytest.approx(0.338, abs=5e-4)


def test_loss_factor_limit_of_unit_contact_ratio():
    # ε_α = 1: H_V = π(u+1)/(z1 u)·(ε1² + ε2²) exactly
    assert gear_loss_factor(20, 2.0, 0.5, 0.5) == pytest.approx(math.pi * 3 / 40 * 0.5, rel=1e-14)


@pytest.mark.parametrize("first, second", [(0.4, 0.5), (1.2, 0.5), (1.1, 1.05)])
def test_loss_factor_refuses_pairs_outside_its_form(first, second):
    with pytest.raises(CaseError, match="contact_ratio"):
        gear_loss_factor(16, 1.5, first, second)


def test_mesh_power_loss_is_the_path_integral_with_constant_friction(fzg_c):
    # P_in·μ·H_V against (1/p_b)∫μ F_n v_g ds with F_n = share·F_bt at 2250 rpm, 265 N·m (FZG load stage 10)
    torque, speed = 265.0, 2250.0
    load = torque / fzg_c.pinion.base_radius
    roll, share = exact_roll_nodes(fzg_c)
    power = path_friction_power(roll, share * load, fzg_c.sliding_speed(roll, speed),
                                0.06, fzg_c.base_pitch)
    expected = mesh_power_loss(torque * speed * math.pi / 30.0, 0.06, pair_gear_loss_factor(fzg_c))
    assert power == pytest.approx(expected, rel=1e-9)


def test_elastic_sharing_of_the_mesh_model_gives_at_most_h_v():
    # the project's own sharing (stiffness-proportional in double contact) moves load towards the pitch point
    from thermogear.case import load_case
    from thermogear.gearbox.mesh_loss import mesh_model_friction_power
    from thermogear.mesh.model import MeshModel

    model = MeshModel(load_case("fzg_type_c"), "elastic")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        loss = mesh_model_friction_power(model, 2175.0, model.normal_load(), count=401)
    assert loss.loss_factor <= loss.rigid_loss_factor
    assert loss.loss_factor > 0.9 * loss.rigid_loss_factor  # sharing changes H_V by a few per cent, not more
    assert loss.power == pytest.approx(loss.input_power * loss.mean_friction * loss.loss_factor, rel=1e-12)
    assert 0.0 < loss.pinion_heat_share < 1.0


def test_blok_partition_limits():
    # equal effusivities and speeds: half each; a stationary wheel surface takes nothing
    assert float(blok_heat_partition((1.0, 1.0), (2.0, 2.0))) == pytest.approx(0.5)
    assert float(blok_heat_partition((1.0, 1.0), (2.0, 0.0))) == pytest.approx(1.0)


def hand_nj406() -> float:
    """SKF model for NJ 406 at F_r 3917 N, n 2250 r/min, ν 30 mm²/s, μ_bl 0.15, μ_EHL 0.02, written out term by
    term (catalogue units, N·mm): d_m = 60 mm."""
    n, nu, d_m, fr = 2250.0, 30.0, 60.0, 3917.0
    m_rr = 1e-6 * 60.0**2.41 * fr**0.31 * (nu * n)**0.6  # 187.9
    phi_ish = 1 / (1 + 1.84e-9 * (n * d_m)**1.28 * nu**0.64)  # 0.944
    phi_rs = math.exp(-3e-8 * nu * n * 120.0 * math.sqrt(5.1 / (2 * 60.0)))  # 0.951
    phi_bl = math.exp(-2.6e-8 * (n * nu)**1.4 * d_m)
    m_sl = (0.0015 * d_m * fr) * (phi_bl * 0.15 + (1 - phi_bl) * 0.02)  # 7.06
    m_drag = 10 * 1.49e-4 * 0.65 * 5.1 * 120.0 / 60.0 * 1e-12 * 23.0 * d_m**4 * n**2  # 14.9
    return phi_ish * phi_rs * m_rr + m_sl + m_drag


def test_skf_nj406_against_the_hand_calculation():
    # 199.7 N·mm → 47.1 W (docs/gearbox-temperature.md); the code and the hand lines are independent spellings of
    # the same formulas, so they agree to rounding; the documented figures are rounded to 0.1
    moments = RollingBearing.cylindrical_roller(**NJ406_CONSTANTS).moments(2250.0, 30.0, 3917.0)
    assert moments.total * 1e3 == pytest.approx(hand_nj406(), rel=1e-12)
    assert moments.total * 1e3 == pytest.approx(199.7, abs=0.05)
    assert moments.power == pytest.approx(47.05, abs=0.01)
    assert (moments.rolling * 1e3, moments.sliding * 1e3, moments.drag * 1e3) == pytest.approx(
        (177.7, 7.06, 14.9), abs=0.05)


def test_skf_rolling_moment_scales_as_viscosity_speed_to_the_0_6_when_the_factors_are_one():
    # φ_ish, φ_rs → 1 at vanishing speed·viscosity products: M_rr ∝ (ν n)^0.6 (checked over a factor 2 in ν)
    bearing = RollingBearing.cylindrical_roller(**{**NJ406_CONSTANTS, "drag_variable": 0.0,
                                                  "replenishment_constant": 0.0})
    low, high = bearing.moments(1.0, 1e-3, 3917.0).rolling, bearing.moments(1.0, 2e-3, 3917.0).rolling
    assert high / low == pytest.approx(2.0**0.6, rel=1e-6)


def test_bearing_and_seal_inputs_are_checked():
    with pytest.raises(CaseError, match="bearing.outside_mm"):
        RollingBearing.cylindrical_roller(**{**NJ406_CONSTANTS, "outside_mm": 20.0})
    with pytest.raises(CaseError, match="viscosity_mm2_s"):
        RollingBearing.cylindrical_roller(**NJ406_CONSTANTS).moments(1000.0, float("nan"), 100.0)
    # 7.69e-6·30²·2250 = 15.57 W
    assert seal_power_loss(30.0, 2250.0) == pytest.approx(15.57, abs=0.005)


def wheel(immersion: float) -> DippedGear:
    # FZG wheel: D 108 mm, b 14 mm, m 4.5, z 24, tooth height 2.25 m, V0 1.25 L
    return DippedGear(0.054, 0.014, 0.0045, 24, 2.25 * 0.0045, immersion, 1.25e-3)


@pytest.mark.parametrize("speed_rpm, expected_w", [(500.0, 4.1), (1500.0, 23.6), (3000.0, 74.0)])
def test_churning_fzg_wheel_hand_values(speed_rpm, expected_w):
    # half immersed, ν 30 mm²/s, ρ 850 kg/m³: hand evaluation of the correlation (docs), rounded to 0.1 W
    power = churning_power_loss(wheel(0.054), speed_rpm * math.pi / 30.0, 30e-6, 850.0)
    assert power == pytest.approx(expected_w, abs=0.06)


@pytest.mark.parametrize("speed_rad_s", [20.0, 200.0])
def test_churning_coefficient_continuous_at_the_reynolds_boundary(speed_rad_s):
    # the viscosity that puts Re at 4000: the table's constants are rounded to 3–4 digits (0.239 vs 0.2395),
    # so continuity holds to 0.3 %, not better
    gear = wheel(0.03)
    viscosity = speed_rad_s * gear.pitch_radius * gear.face_width / CRITICAL_REYNOLDS
    below = churning_coefficient(gear, speed_rad_s, viscosity * (1 + 1e-9))
    above = churning_coefficient(gear, speed_rad_s, viscosity * (1 - 1e-9))
    assert above == pytest.approx(below, rel=3e-3)


@pytest.mark.parametrize("parameter", [750.0, 1250.0])
def test_churning_coefficient_continuous_at_the_speed_regime_boundaries(parameter):
    # Υ = ω²(R b m)^(1/3): the interpolation makes C_m continuous (to the 1e-9 step used, times the slope)
    gear = wheel(0.03)
    speed = math.sqrt(parameter / (gear.pitch_radius * gear.face_width * gear.module)**(1 / 3))
    values = [churning_coefficient(gear, speed * (1 + step), 30e-6) for step in (-1e-9, 1e-9)]
    assert values[0] == pytest.approx(values[1], rel=1e-6)


def test_churning_is_zero_above_the_oil_and_refuses_bad_immersion():
    assert churning_power_loss(wheel(0.0), 100.0, 30e-6, 850.0) == 0.0
    with pytest.raises(CaseError, match="immersion_depth"):
        wheel(0.2)
