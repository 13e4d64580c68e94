"""Signals with stiffness jumps: the solvers sample both sides of a jump at one time. Means, RMS values and
spectra must not depend on how such ties are ordered or on the sampling density (the validation page once moved
by 0.1 % between machines because ``np.interp(..., period=T)`` sorts its abscissae with an unstable sort)."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermogear.dynamics.results.spectra import harmonic_spectrum, right_continuous, time_mean_and_rms


def _square_wave(samples_per_half: int):
    """One period T = 1 of a square wave 1 on [0, ½), 3 on [½, 1), both sides of each jump sampled."""
    first = np.linspace(0.0, 0.5, samples_per_half + 1)
    second = np.linspace(0.5, 1.0, samples_per_half + 1)
    return np.concatenate([first, second]), np.concatenate([np.ones_like(first), 3 * np.ones_like(second)])


def test_right_continuous_keeps_the_value_after_each_jump():
    time, values = right_continuous(*_square_wave(2))
    assert np.all(np.diff(time) > 0)
    assert values[time == 0.5] == pytest.approx(3.0)
    assert time[-1] == 1.0


@pytest.mark.parametrize("samples_per_half", [1, 3, 50])
def test_mean_and_rms_of_a_jump_are_exact_at_any_sampling(samples_per_half):
    """Square wave 1/3: mean 2, RMS about the mean 1, exactly (a piecewise-constant signal is integrated without
    error by the trapezoidal rule when both sides of the jump are samples)."""
    mean, rms = time_mean_and_rms(*_square_wave(samples_per_half))
    assert mean == pytest.approx(2.0, rel=1e-14)
    assert rms == pytest.approx(1.0, rel=1e-14)


def test_force_harmonics_read_each_jump_from_after_it():
    """The rig signal's harmonics of a sampled square wave equal those of its right-continuous samples (ties
    resolved by position, not by a sort) and approach the analytic fundamental 4/π of a wave of height 2."""
    from thermogear.experiment.comparison import periodic_force_harmonics

    time, values = _square_wave(64)
    harmonics = periodic_force_harmonics(time, values, 1.0, 8, samples=256)
    reference = periodic_force_harmonics(*right_continuous(time, values), 1.0, 8, samples=256)
    np.testing.assert_array_equal(harmonics, reference)
    assert abs(harmonics[1]) == pytest.approx(4 / np.pi, rel=2e-3)  # linear resampling: O(1/N) on the jumps
    assert harmonics[0].real == pytest.approx(2.0, abs=1 / 256)      # one sample of 256 on each jump


@pytest.mark.slow
def test_rig_dynamic_force_rms_converges_with_the_sampling():
    """The rig page's RMS dynamic mesh force (FZG stand-in, 1400 rpm, 52.1 °C) with 4 and 16 samples per interval
    agrees to 1e-5 (measured 6e-7: the trapezoidal rule on the solver's grid is O(h²)); the earlier uniform
    resampling gave 332.80 and 333.20 N for the same orbit."""
    from thermogear.case import load_case
    from thermogear.experiment.comparison import dynamic_force_rms, state_case
    from thermogear.simulation import Simulation

    base = load_case("fzg_type_c")
    values = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for samples in (4, 16):
            case = state_case(base, 52.1, 1400.0).with_changes(**{"dynamics.samples_per_interval": samples})
            values.append(dynamic_force_rms(Simulation(case, "thermal").run(method="periodic")))
    assert values[0] == pytest.approx(values[1], rel=1e-5)
