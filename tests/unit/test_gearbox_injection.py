"""Injection lubrication: the oil jet's impulse loss (thermogear.gearbox.injection) and its place in the gearbox."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import thermogear.simulation  # noqa: F401  (registers the "gearbox" temperature provider)
from thermogear.case import case_from_document
from thermogear.errors import CaseError
from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.injection import OilJet, jet_impulse_power, jet_validity
from thermogear.gearbox.losses import NODES

CASE = Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"
pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


def test_hand_calculation_of_the_docs():
    # docs/gearbox-temperature.md: ρ = 880 kg/m³, Q = 3 L/min = 5e-5 m³/s, v_t = 20 m/s, v_j = 8 m/s:
    # P = 880 · 5e-5 · 20 · (20 − 8) = 10.56 W
    jet = OilJet(3.0 / 60000.0, 8.0)
    assert jet_impulse_power(jet, 880.0, 20.0) == pytest.approx(10.56, rel=1e-12)


def test_limits():
    jet = OilJet(5e-5, 20.0)
    assert jet_impulse_power(jet, 880.0, 20.0) == 0.0  # a jet at the pitch-line speed is not accelerated
    assert jet_validity(jet, 20.0) is None
    # a slow jet: the whole ρ·Q·v_t² (the oil taken from rest to the pitch-line speed, as far as the jet is slow)
    slow = OilJet(5e-5, 1e-9)
    assert jet_impulse_power(slow, 880.0, 20.0) == pytest.approx(880.0 * 5e-5 * 400.0, rel=1e-9)
    # a jet faster than the pitch line would drive the gears: not modelled, taken as 0 and said
    fast = OilJet(5e-5, 30.0)
    assert jet_impulse_power(fast, 880.0, 20.0) == 0.0
    assert "faster than the pitch line" in jet_validity(fast, 20.0)


def test_a_jet_at_the_outlet_is_reversed():
    # against the teeth leaving the mesh the oil's tangential momentum is reversed: ρ·Q·v_t·(v_t + v_j)
    # = 880 · 5e-5 · 20 · 28 = 24.64 W, and a jet faster than the pitch line is still a loss
    assert jet_impulse_power(OilJet(5e-5, 8.0, at_outlet=True), 880.0, 20.0) == pytest.approx(24.64, rel=1e-12)
    fast = OilJet(5e-5, 30.0, at_outlet=True)
    assert jet_impulse_power(fast, 880.0, 20.0) == pytest.approx(880.0 * 5e-5 * 20.0 * 50.0, rel=1e-12)
    assert jet_validity(fast, 20.0) is None


def test_proportional_to_flow_and_density():
    one, two = OilJet(1e-5, 5.0), OilJet(2e-5, 5.0)
    assert jet_impulse_power(two, 880.0, 12.0) == pytest.approx(2.0 * jet_impulse_power(one, 880.0, 12.0), rel=1e-14)
    assert jet_impulse_power(one, 900.0, 12.0) / jet_impulse_power(one, 850.0, 12.0) == pytest.approx(900 / 850)


@pytest.mark.parametrize("flow, speed", [(0.0, 5.0), (-1e-5, 5.0), (1e-5, 0.0), (math.inf, 5.0), (1e-5, 1e4)])
def test_bad_jets_are_refused(flow, speed):
    with pytest.raises(CaseError):
        OilJet(flow, speed)


def _injection_case(flow_l_min=4.0, jet_m_s=5.0, speed_rpm=3000.0, position="inlet"):
    document = tomllib.loads(CASE.read_text(encoding="utf-8"))
    document["gearbox"]["oil"].update(lubrication="injection", injection_flow_l_min=flow_l_min, jet_speed_m_s=jet_m_s,
                                      jet_position=position)
    document["operating"]["speed_rpm"] = speed_rpm
    return case_from_document(document)


def test_the_gearbox_takes_the_jet_loss_into_the_oil():
    case = _injection_case()
    model = gearbox_model_from_case(case)
    description = model.description
    assert description.wheel_immersion == 0.0 and description.pinion_immersion == 0.0  # nothing dipped
    losses_model = model.losses(gearbox_operating_point(case.operating_point, case.gearbox))
    temperatures = np.array([70.0, 65.0, 60.0, 58.0, 55.0, 45.0])  # by NODES: the oil at 55 °C
    losses = losses_model.at(temperatures)
    # by hand from the model's own oil density at 55 °C and the operating pitch-line speed
    pitch_speed = 3000.0 * math.pi / 30.0 * description.gear_pair.operating_pitch_radii[0]
    density = float(description.lubricant.density(55.0))
    expected = density * 4.0 / 60000.0 * pitch_speed * (pitch_speed - 5.0)
    assert losses.injection == pytest.approx(expected, rel=1e-12) and losses.injection > 0.0
    assert losses.churning == 0.0
    assert losses.total == pytest.approx(losses.mesh + losses.bearings + losses.seals + losses.injection, rel=1e-15)
    sources = losses.node_sources
    assert sources[NODES.index("oil")] == pytest.approx(losses.injection, rel=1e-15)  # all of it to the oil node
    assert sources.sum() == pytest.approx(losses.total, rel=1e-14)


def test_steady_state_balances_with_a_jet():
    case = _injection_case()
    model = gearbox_model_from_case(case)
    steady = model.steady_state(gearbox_operating_point(case.operating_point, case.gearbox))
    assert steady.energy_residual < 1e-9  # the heat shed equals the losses, the jet's included
    assert steady.losses.injection > 0.0
    # more flow, more impulse loss, a warmer oil
    stronger = gearbox_model_from_case(_injection_case(flow_l_min=40.0)).steady_state(
        gearbox_operating_point(case.operating_point, case.gearbox))
    assert stronger.losses.injection > steady.losses.injection and stronger.oil_c > steady.oil_c


def test_warm_up_reports_the_jet_loss():
    case = _injection_case()
    model = gearbox_model_from_case(case)
    history = model.warm_up(GearboxOperatingPoint(3000.0, 138.0, 20.0), 600.0, points=11)
    assert history.injection_loss is not None and np.all(history.jet_loss > 0.0)
    assert history.energy_residual < 1e-5  # the integrator's rtol 1e-6 on the energy states
    dip = gearbox_model_from_case(case_from_document(tomllib.loads(CASE.read_text(encoding="utf-8"))))
    assert dip.description.oil_jet is None


def test_the_case_file_chooses_the_jet_position():
    inlet = gearbox_model_from_case(_injection_case()).description.oil_jet
    outlet = gearbox_model_from_case(_injection_case(position="outlet")).description.oil_jet
    assert not inlet.at_outlet and outlet.at_outlet and outlet.sense == -1.0
