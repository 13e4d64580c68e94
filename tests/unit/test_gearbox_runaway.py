"""Runaway means no stable steady state: the fold of the stable branch found by continuation, a hot stable state
is a flagged result (thermogear.gearbox.network.continue_steady_states, GearboxThermalModel.steady_state)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.fzg_example import illustrative_fzg_gearbox
from thermogear.gearbox.model import GearboxThermalModel, ThermalRunawayError
from thermogear.gearbox.network import ThermalNetwork, continue_steady_states, stability_eigenvalues

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")

CONDUCTANCE, GAIN = 2.0, 0.05  # [W/K], [1/K]


def semenov_network(power: float) -> ThermalNetwork:
    """One node, source P0·exp(a·(T − T_a)), cooling G·(T − T_a) to T_a = 0: Semenov's thermal explosion. Steady
    states exist for P0 ≤ G/(a·e), the fold, where ΔT = 1/a (tangency of source and cooling lines)."""
    return ThermalNetwork(np.array([100.0]), lambda t: (np.zeros((1, 1)), np.array([CONDUCTANCE])),
                          lambda t, time: np.array([power * np.exp(min(GAIN * t[0], 700.0))]), lambda time: 0.0)


def test_continuation_finds_semenovs_fold():
    critical = CONDUCTANCE / (GAIN * math.e)  # 14.715 W
    fold = continue_steady_states(semenov_network, 0.0, 2.0 * critical, np.array([0.0]), bounds=(-50.0, 200.0),
                                  smallest_step=1e-6)
    assert not fold.reached
    # the natural-parameter continuation stops within its last step below the fold: the parameter within 1e-5
    # relative (the smallest step is 1e-6 of the span and the corrector fails a little before the tangency)
    assert fold.parameter == pytest.approx(critical, rel=1e-5)
    assert fold.parameter <= critical
    # at the fold the temperature is 1/a and the eigenvalue tends to zero (∝ √(P_crit − P) on the branch)
    assert fold.temperatures[0] == pytest.approx(1.0 / GAIN, rel=1e-2)
    assert -1e-3 * CONDUCTANCE / 100.0 < fold.largest_eigenvalue < 0.0


def test_continuation_below_the_fold_reaches_the_stable_branch():
    power = 0.5 * CONDUCTANCE / (GAIN * math.e)
    fold = continue_steady_states(semenov_network, 0.0, power, np.array([0.0]))
    assert fold.reached
    # the lower root of G·ΔT = P·exp(aΔT), checked by its residual, and stable (one eigenvalue < 0)
    temperature = float(fold.temperatures[0])
    assert CONDUCTANCE * temperature == pytest.approx(power * math.exp(GAIN * temperature), rel=1e-10)
    assert temperature < 1.0 / GAIN
    assert float(np.real(stability_eigenvalues(semenov_network(power), fold.temperatures)[-1])) < 0.0


@pytest.fixture(scope="module")
def box_in_still_air():
    # a 0.1 m box in still air, nearly bright (ε 0.05): made to run away at the FZG speed
    base = illustrative_fzg_gearbox()
    tiny = dataclasses.replace(base.housing, length=0.1, width=0.1, height=0.1, air_speed=0.0, emissivity=0.05)
    return GearboxThermalModel(dataclasses.replace(base, housing=tiny))


def test_runaway_is_reported_only_beyond_the_end_of_the_stable_branch(box_in_still_air):
    with pytest.raises(ThermalRunawayError) as caught:
        box_in_still_air.steady_state(GearboxOperatingPoint(2175.0, 265.1, 20.0))
    end = caught.value.fold_torque
    assert 50.0 < end < 265.1 and "followed in torque from 0" in str(caught.value)
    # just below the end: a stable steady state, hot and flagged, a result; just above: runaway
    below = box_in_still_air.steady_state(GearboxOperatingPoint(2175.0, 0.98 * end, 20.0))
    assert below.largest_eigenvalue < 0.0
    assert {"oil_above_usable", "steel_above_tempering", "above_material_data"} <= set(below.flags)
    with pytest.raises(ThermalRunawayError):
        box_in_still_air.steady_state(GearboxOperatingPoint(2175.0, 1.02 * end, 20.0))


def test_a_crawl_speed_gives_the_ambient():
    # 0.001 rpm: the losses vanish, the steady state is the ambient (not "runaway")
    state = GearboxThermalModel(illustrative_fzg_gearbox()).steady_state(GearboxOperatingPoint(0.001, 94.1, 20.0))
    np.testing.assert_allclose(state.temperatures_c, 20.0, atol=1e-3)
    assert state.flags == ()


def test_a_hot_stable_state_is_a_flagged_result_with_its_energy_balance():
    # the paper's friction law at 260 N·m: a stable state far above every limit (pinion 507 °C), never a refusal (at
    # K9, 302 N·m, until the stretches of shaft between gears and bearings were fins: that branch now folds near
    # 285 N·m)
    from thermogear.friction.models import FRICTION_MODELS

    model = GearboxThermalModel(dataclasses.replace(illustrative_fzg_gearbox(), friction=FRICTION_MODELS["paper"]))
    state = model.steady_state(GearboxOperatingPoint(2175.0, 260.0, 20.0))
    assert state.pinion_c > 400.0 and state.largest_eigenvalue < 0.0
    assert state.flags == ("oil_above_usable", "steel_above_tempering", "above_material_data",
                           "viscosity_extrapolated")
    assert state.energy_balance_w < 1e-9
