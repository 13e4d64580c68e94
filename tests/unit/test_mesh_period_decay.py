"""The time-mean decay rate c̄/(2·me) of a mesh-dynamics problem (the mean viscous oscillator's σ in e^(−σt))."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.problems.problem import MeshDynamicsProblem


def _problem(single_damping: float, double_damping: float, contact_ratio: float = 1.6, mass: float = 0.5):
    return MeshDynamicsProblem.square_wave(mass=mass, mesh_period=1e-3, contact_ratio=contact_ratio,
                                           single_stiffness=1e8, double_stiffness=1.6e8,
                                           single_damping=single_damping, double_damping=double_damping, force=1e3)


def test_hand_value_of_a_square_wave():
    # double contact for (ε − 1) of the period, single for (2 − ε): c̄ = 0.6·400 + 0.4·300 = 360 N·s/m;
    # me = 0.5 kg
    assert _problem(300.0, 400.0).mean_decay_rate == pytest.approx(360.0 / (2 * 0.5), rel=1e-12)


def test_constant_damping_gives_the_oscillator_decay_rate():
    # identity: with c the same in both regions σ = c/(2m), whatever the contact ratio
    for ratio in (1.1, 1.5, 1.9):
        assert _problem(250.0, 250.0, ratio).mean_decay_rate == pytest.approx(250.0, rel=1e-12)


def test_undamped_limit_and_monotone_in_damping():
    rates = [_problem(c, c).mean_decay_rate for c in (1e-9, 1.0, 10.0)]
    assert rates[0] == pytest.approx(1e-9, rel=1e-9) and np.all(np.diff(rates) > 0)
