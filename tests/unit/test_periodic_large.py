"""The periodic response of a large system (state of 401 and more): the shared Padé evaluation of its pieces and
the range of its monodromy against the route that exponentiates each piece by itself and takes the dense monodromy
and its eigenvalues (dynamics/periodic_orbits/periodic_ndof.py, shared_pade.py, monodromy_range.py,
periodic_runs.py)."""

from __future__ import annotations

import numpy as np
import pytest

import thermogear.dynamics.linear_algebra.monodromy_range as monodromy_range
import thermogear.dynamics.periodic_orbits.periodic_runs as periodic_runs
import thermogear.dynamics.linear_algebra.shared_pade as shared_pade
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, periodic_response


def _stiff_chain(size: int = 200, period: float = 1e-3, intervals: int = 2) -> PiecewiseLinearSystem:
    """The chain of test_periodic_ndof with light masses (10–20 g) and strong stiffness-proportional damping, so that
    most modes decay away within the period (a monodromy of low numerical rank, as a shaft's finite-element modes
    give); ``intervals`` equal intervals (2: its pieces [0, 0.6), [0.6, 1))."""
    from dataclasses import replace

    from test_periodic_ndof import _chain

    chain = _chain(size, period)
    mass = np.diag(np.random.default_rng(11).uniform(0.01, 0.02, size))
    chain = replace(chain, mass=mass, damping=50.0 * mass + 2e-5 * chain.stiffness)
    if intervals == 2:
        return chain
    high = np.arange(intervals) / intervals < 0.6 - 1e-12
    pick = np.where(high, 0, 1)
    return replace(chain, nodes=np.arange(intervals + 1) / intervals * period,
                   stiffness_factor=chain.stiffness_factor[pick], damping_factor=chain.damping_factor[pick],
                   force_factor=chain.force_factor[pick])


def _route_before(monkeypatch):
    monkeypatch.setattr(monodromy_range, "LARGEST_RANK_SHARE", 0.0)
    monkeypatch.setattr(shared_pade, "shared_piece_powers", lambda *arguments: None)


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
    shared = []
    original_powers = shared_pade.shared_piece_powers
    monkeypatch.setattr(shared_pade, "shared_piece_powers", lambda *arguments: shared.append(
        original_powers(*arguments)) or shared[-1])
    response = periodic_response(system, samples_per_piece=8 if intervals == 2 else 2)
    assert used and used[0] > 0
    # the runs continue the powers of the pieces' common step (two pieces of 0.6 and 0.4 of the period: n = 3, 2;
    # 40 equal intervals: n = 1)
    assert shared and shared[0] is not None
    assert sorted(shared[0].multiples.tolist()) == ([2, 3] if intervals == 2 else [1, 1])
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
