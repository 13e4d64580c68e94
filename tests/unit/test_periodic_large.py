"""The periodic response of a large system (state of 401 and more): the shared Padé evaluation of its pieces and
the range of its monodromy against the route that exponentiates each piece by itself and takes the dense monodromy
and its eigenvalues (dynamics/periodic_ndof.py, shared_pade.py, monodromy_range.py, periodic_runs.py)."""

from __future__ import annotations

import numpy as np
import pytest

import thermogear.dynamics.monodromy_range as monodromy_range
import thermogear.dynamics.periodic_runs as periodic_runs
import thermogear.dynamics.shared_pade as shared_pade
from thermogear.dynamics.periodic_ndof import PiecewiseLinearSystem, periodic_response


def _stiff_chain(size: int = 200, period: float = 1e-3, intervals: int = 2) -> PiecewiseLinearSystem:
    """Light masses on stiff springs with strong stiffness-proportional damping, so that most modes decay away
    within the period (a monodromy of low numerical rank, as a shaft's finite-element modes give), one
    parametric spring (a square wave, 60 % high) between DOFs 0 and 1; ``intervals`` equal intervals (2: the
    pieces [0, 0.6), [0.6, 1))."""
    generator = np.random.default_rng(11)
    masses = generator.uniform(0.01, 0.02, size)
    springs = generator.uniform(0.5e8, 2e8, size + 1)
    stiffness = np.diag(springs[:-1] + springs[1:]) - np.diag(springs[1:-1], 1) - np.diag(springs[1:-1], -1)
    mass = np.diag(masses)
    pattern = np.zeros((size, size))
    pattern[np.ix_([0, 1], [0, 1])] = [[1.0, -1.0], [-1.0, 1.0]]
    force_pattern = np.zeros(size)
    force_pattern[[0, 1]] = [1.0, -1.0]
    force = np.zeros(size)
    force[0], force[-1] = 500.0, -200.0
    phase = np.array([0.0, 0.6]) if intervals == 2 else np.arange(intervals) / intervals
    high = phase < 0.6 - 1e-12
    return PiecewiseLinearSystem(
        mass=mass, stiffness=stiffness, damping=50.0 * mass + 2e-5 * stiffness, force=force,
        nodes=np.append(phase, 1.0) * period, stiffness_pattern=pattern,
        stiffness_factor=np.where(high, 1.3e8, 0.9e8), damping_pattern=pattern,
        damping_factor=np.where(high, 200.0, 150.0), force_pattern=force_pattern,
        force_factor=np.where(high, 2e2, 0.0))


def _route_before(monkeypatch):
    monkeypatch.setattr(monodromy_range, "LARGEST_RANK_SHARE", 0.0)
    monkeypatch.setattr(shared_pade, "low_rank_piece_exponentials", lambda *arguments: None)


@pytest.mark.parametrize("intervals", [2, 40])
def test_large_system_equals_the_route_of_separate_exponentials_and_dense_monodromy(monkeypatch, intervals):
    system = _stiff_chain(intervals=intervals)
    used = []
    original = periodic_runs.floquet_of_maps

    def watched(maps):
        multipliers, state = original(maps)
        used.append(int(np.sum(multipliers == 0.0)))  # multipliers dropped with the range: the range route ran
        return multipliers, state

    monkeypatch.setattr(periodic_runs, "floquet_of_maps", watched)
    response = periodic_response(system, samples_per_piece=8 if intervals == 2 else 2)
    assert used and used[0] > 0
    with monkeypatch.context() as patch:
        _route_before(patch)
        reference = periodic_response(system, samples_per_piece=8 if intervals == 2 else 2)
    # two exact solutions, the same approximant at the same backward error taken in another order, and the
    # monodromy's range to 1e-13 of its norm with the state refined on the exact maps: rounding times the
    # conditioning of I − Φ, well inside 1e-9 of the orbit and of the spectral radius
    scale = np.abs(reference.displacement).max()
    assert np.abs(response.displacement - reference.displacement).max() < 1e-9 * scale
    moduli = [np.sort(np.abs(item.multipliers))[::-1] for item in (response, reference)]
    assert np.abs(moduli[0] - moduli[1]).max() < 1e-9 * moduli[1][0]
