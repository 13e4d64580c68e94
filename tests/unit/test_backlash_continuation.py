"""Speed continuation of the backlash model: jump-up / jump-down hysteresis through a softening primary resonance.

Textbook single mesh (Kahraman & Singh 1990 type): me = 1 kg, k0 = 1e8 N/m (ω_n = 1e4 rad/s), w = 1e3 N
(x_st = 10 μm), stiffness variation ε = 0.1, transmission-error excitation 0.1·x_st·sin 2πτ/T (pitch type:
e' = −e), ζ = 0.03, backlash j = x_st. The mesh frequency ratio Ω = ω_m/ω_n plays the speed.
"""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics import periodic_steady_state
from thermogear.dynamics.backlash.backlash_continuation import follow_branch
from thermogear.errors import ProblemError

from backlash_textbook import X_STATIC, textbook_problem


def textbook(ratio, zeta=0.03, **options):
    """The textbook oscillator (module ``backlash_textbook``) with this file's damping ratio 0.03."""
    return textbook_problem(ratio, zeta, **options)


@pytest.fixture(scope="module")
def sweeps():
    ratios = np.round(np.arange(0.80, 1.1001, 0.005), 6)
    problems = [textbook(r) for r in ratios]
    return ratios, problems, follow_branch(problems, "up", ratios), follow_branch(problems, "down", ratios)


def test_up_and_down_sweeps_show_the_softening_hysteresis(sweeps):
    ratios, problems, up, down = sweeps
    assert np.all(up.converged) and np.all(down.converged)
    assert np.all(up["largest_multiplier"] < 1.0) and np.all(down["largest_multiplier"] < 1.0)
    swing_up, swing_down = up["dte_peak_to_peak"], down["dte_peak_to_peak"]
    # the jumps: the largest rise of the swing going up, the largest drop going down
    jump_up = int(np.argmax(np.diff(swing_up)))  # between ratios[jump_up] and ratios[jump_up + 1]
    jump_down = int(np.argmax(np.diff(swing_down)))  # going down, the swing drops between these two as well
    # the linear model's peak (every pair always in contact): the backlash softens the mesh, so the resonance
    # bends to lower speeds and both jumps lie below the linear peak, the jump-down below the jump-up
    linear_peak = _linear_peak_ratio(ratios)
    assert ratios[jump_down] < ratios[jump_up] < linear_peak
    # a jump, not a steep slope: the linear swing grows by < 5 % per 0.005 of Ω here, the jumps by > 30 %
    assert swing_up[jump_up + 1] > 1.3 * swing_up[jump_up] and swing_down[jump_down + 1] > 1.3 * swing_down[jump_down]
    band = slice(jump_down + 1, jump_up + 1)  # both branches exist here: hysteresis
    assert band.stop - band.start >= 3
    assert np.all(swing_down[band] > 1.3 * swing_up[band])
    assert np.all(down["contact_loss_fraction"][band] > 0.1) and np.all(up["contact_loss_fraction"][band] == 0.0)
    # outside the band there is one attractor: up and down give the same orbit (Newton tolerance 1e-10)
    outside = np.ones(ratios.size, dtype=bool)
    outside[band] = False
    np.testing.assert_allclose(up.initial_state[outside], down.initial_state[outside], rtol=0,
                               atol=1e-8 * X_STATIC * 1e4)


def _linear_peak_ratio(ratios):
    """Ω of the largest linear swing (all pairs in contact), on a fine grid around the given range."""
    fine = np.linspace(ratios[0], ratios[-1], 601)
    swings = []
    for r in fine:
        orbit = periodic_steady_state(textbook(r).linear_problem(), samples_per_interval=4)
        swings.append(np.ptp(orbit.displacement))
    return fine[int(np.argmax(swings))]


def test_a_failed_point_is_reported_and_the_sweep_goes_on():
    ratios = np.array([0.5, 0.55, 0.6, 0.65, 0.7])
    problems = [textbook(r) for r in ratios]
    undamped = problems[2].with_changes(damping=np.zeros(32))  # no attracting orbit: |μ| = 1 (det M = 1)
    branch = follow_branch([*problems[:2], undamped, *problems[3:]], "up", ratios, max_period_count=2,
                           run_in_periods=50, classify_periods=50)
    reference = follow_branch(problems, "up", ratios)
    assert not branch.converged[2] and branch.response[2] in ("non-periodic", "failed")
    assert np.isfinite(branch["residual"][2]) and branch["residual"][2] > 1e-10
    good = [0, 1, 3, 4]
    assert np.all(branch.converged[good])
    np.testing.assert_allclose(branch.initial_state[good], reference.initial_state[good], rtol=1e-8)


def test_direction_is_checked():
    with pytest.raises(ProblemError, match="direction"):
        follow_branch([textbook(1.0)], "sideways")
