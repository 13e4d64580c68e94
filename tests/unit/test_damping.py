"""Friction damping (Luo & Li Eqs. 26–28): energy equivalence, Eq. 28 constant, mesh rules, pair wiring.

The pair-damping tests replace the potential-energy pair stiffness by a smooth hump (monkeypatched), so that
they test this module's wiring (load share, local μ, model choice) one function at a time; the real stiffness
is exercised in tests/validation/test_luo2019_damping.py.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.friction.damping import (contact_region_means, coulomb_equivalent_damping, friction_damping,
                                         mesh_circular_frequency, mesh_damping)
from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.lubricant import lubricant_from_case
from thermogear.mesh.model import MeshModel
from thermogear.geometry.mesh_cycle import load_shares


def pair_damping(case, roll, model):
    """The pair damping of a case's mesh model at its operating point."""
    return MeshModel(case, model).pair_damping_at(roll)


def test_coulomb_equivalent_damping_hand_value():
    assert coulomb_equivalent_damping(100.0, 2.0, 1e-3) == pytest.approx(4 * 100.0 / (math.pi * 2.0 * 1e-3))


def test_energy_per_cycle_of_the_equivalent_damper_equals_coulomb_friction():
    # integrate the dissipated power over one cycle of x = B sin ωt for both dampers
    force, omega, amplitude = 37.0, 1.3e3, 2e-6
    time = np.linspace(0.0, 2 * math.pi / omega, 200001)
    velocity = amplitude * omega * np.cos(omega * time)
    coulomb = np.trapezoid(force * np.abs(velocity), time)
    c = coulomb_equivalent_damping(force, omega, amplitude)
    viscous = np.trapezoid(c * velocity**2, time)
    assert viscous == pytest.approx(coulomb, rel=1e-6)


def test_eq_28_is_eq_26_with_the_quasi_static_amplitude_and_has_the_papers_constant():
    stiffness, friction, load, teeth, speed = 4.5e8, 0.07, 1.0e4, 27, 2000.0
    omega = mesh_circular_frequency(teeth, speed)
    assert omega == pytest.approx(2 * math.pi * 900.0)
    direct = friction_damping(stiffness, friction, omega)
    assert direct == pytest.approx(coulomb_equivalent_damping(friction * load, omega, load / stiffness))
    # Luo & Li Eq. 28: c = 1.459·k/(z1·n1)·X^0.25 with μ = 0.12·X^0.25 → c = (1.459/0.12)·μ·k/(z1·n1)
    assert direct == pytest.approx(1.45903 / 0.12 * friction * stiffness / (teeth * speed), rel=1e-5)


def test_zero_speed_is_refused_with_the_speed_key():
    with pytest.raises(CaseError) as caught:
        mesh_circular_frequency(27, 0.0)
    assert caught.value.key == "operating.speed_rpm"
    with pytest.raises(CaseError):
        friction_damping(1e8, 0.05, 0.0)


def test_mesh_rules_mean_and_sum():
    per_pair = np.array([[1.0, 2.0, 3.0], [5.0, 0.0, 7.0]])
    contact = np.array([[True, True, True], [True, False, True]])
    assert mesh_damping(per_pair, contact, "paper") == pytest.approx([3.0, 2.0, 5.0])
    assert mesh_damping(per_pair, contact, "parallel") == pytest.approx([6.0, 2.0, 10.0])
    with pytest.raises(CaseError):
        mesh_damping(per_pair, contact, "series")


def test_region_means_and_load_shares():
    means = contact_region_means([1.0, 2.0, 4.0, 8.0], [1, 2, 2, 1])
    assert means == {"single": 4.5, "double": 3.0}
    shares = load_shares(np.array([[2.0, 5.0], [6.0, 9.0]]), np.array([[True, True], [True, False]]))
    assert shares == pytest.approx(np.array([[0.25, 1.0], [0.75, 0.0]]))


# ------------------------------------------------------------------------------------ pair wiring (hump k)
@pytest.fixture()
def hump_stiffness(monkeypatch, luo2019):
    points = luo2019.gear_pair.path_points
    middle, half = 0.5 * (points["A"] + points["E"]), 0.5 * (points["E"] - points["A"])
    calls = []

    def damping_stiffness_at(self, roll, normal_load=None):
        calls.append(self.model)
        return 3.0e8 * (1.0 - 0.5 * ((np.asarray(roll) - middle) / half) ** 2)

    monkeypatch.setattr(MeshModel, "damping_stiffness_at", damping_stiffness_at)
    return calls


def _quiet(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        return function(*args, **kwargs)


def test_pair_alone_carries_the_whole_load_in_single_contact(luo2019, hump_stiffness):
    points = luo2019.gear_pair.path_points
    result = _quiet(pair_damping, luo2019, np.array([points["C"]]), "elastic")
    assert result.load_share == pytest.approx([1.0])
    assert result.temperature_c == pytest.approx([30.0])
    # Luo & Li (2020) Sect. 3: μ = 0.0709 at the pitch point with oil at 30 °C (share 1, so independent of k)
    assert result.friction_coefficient[0] == pytest.approx(0.0709, abs=1e-4)
    omega = mesh_circular_frequency(27, 2000.0)
    assert result.damping[0] == pytest.approx(4 * result.friction_coefficient[0] * 3.0e8 * (
        1 - 0.5 * ((points["C"] - 0.5 * (points["A"] + points["E"])) / (0.5 * (points["E"] - points["A"]))) ** 2)
        / (math.pi * omega))


def test_pairs_share_the_load_in_double_contact(luo2019, hump_stiffness):
    points = luo2019.gear_pair.path_points
    pitch = luo2019.gear_pair.base_pitch
    roll = np.array([points["A"] + 0.3 * (points["B"] - points["A"])])
    first = _quiet(pair_damping, luo2019, roll, "elastic")
    partner = _quiet(pair_damping, luo2019, roll + pitch, "elastic")
    assert 0.0 < first.load_share[0] < 1.0
    assert first.load_share[0] + partner.load_share[0] == pytest.approx(1.0)
    assert first.unit_load[0] == pytest.approx(first.load_share[0] * luo2019.normal_load / 0.025)


def test_thermal_over_elastic_is_the_viscosity_ratio_to_the_quarter(luo2019, hump_stiffness):
    # uniform 80 °C flanks, k_e in both (the paper's choice): c_r/c_e = (η(30 °C)/η(80 °C))^0.25 = 1.683
    case = luo2019.with_changes(**{"temperature": {"model": "uniform", "bulk_c": 80.0}})
    points = case.gear_pair.path_points
    roll = np.linspace(points["A"], points["E"], 41)
    elastic = _quiet(pair_damping, case, roll, "elastic")
    thermal = _quiet(pair_damping, case, roll, "thermal")
    oil = lubricant_from_case(case)
    expected = _quiet(lambda: (oil.dynamic_viscosity(30.0) / oil.dynamic_viscosity(80.0)) ** 0.25)
    assert thermal.damping / elastic.damping == pytest.approx(np.full(41, expected), rel=1e-12)
    assert expected == pytest.approx(1.683, abs=1e-3)
    assert thermal.temperature_c == pytest.approx(np.full(41, 80.0))
    assert set(hump_stiffness) == {"elastic", "thermal"}


def test_same_load_on_a_wider_face_lowers_mu_by_the_quarter_power(luo2019, hump_stiffness):
    # same total load on a wider face: lower unit load, lower μ by (1/2)^0.25
    points = luo2019.gear_pair.path_points
    wide = luo2019.with_changes(**{"gears.face_width_mm": 50.0})
    narrow_mu = _quiet(pair_damping, luo2019, np.array([points["C"]]), "elastic").friction_coefficient
    wide_mu = _quiet(pair_damping, wide, np.array([wide.gear_pair.path_points["C"]]), "elastic").friction_coefficient
    assert wide_mu / narrow_mu == pytest.approx(0.5 ** 0.25, rel=1e-9)


def test_roll_outside_the_path_is_refused(luo2019, hump_stiffness):
    with pytest.raises(CaseError, match="outside the path"):
        pair_damping(luo2019, np.array([0.0]), "elastic")
    with pytest.raises(CaseError):
        pair_damping(luo2019, np.array([luo2019.gear_pair.path_points["C"]]), "plastic")


def test_zero_speed_case_is_refused_at_load_with_the_speed_key(luo2019):
    with pytest.raises(CaseError) as caught:
        luo2019.with_changes(**{"operating.speed_rpm": 0.0})
    assert caught.value.key == "operating.speed_rpm"
