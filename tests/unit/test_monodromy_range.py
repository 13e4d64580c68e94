"""Floquet multipliers and the periodic state from the range of the monodromy
(dynamics/linear_algebra/monodromy_range.py): against the dense product, its eigenvalues and its solve, on maps of
a known low numerical rank."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.linear_algebra.monodromy_range import floquet_of_maps
from thermogear.dynamics.periodic_orbits.periodic_runs import floquet
from thermogear.errors import ModelLimitError


def _maps(size: int, slowest: float = 0.02, fastest: float = 1e6, seed: int = 3) -> list[np.ndarray]:
    """Two augmented maps [[V e^{−Σ h} V⁻¹, p], [0, 1]] of modes decaying at rates spread from ``slowest`` to
    ``fastest`` per map (complex pairs, a non-normal V near I): those decaying by more than 1e-16 over the
    period leave the monodromy, whose numerical rank is then far below its size."""
    generator = np.random.default_rng(seed)
    maps = []
    for shift in (0.0, 0.37):
        pairs = size // 2
        rates = np.geomspace(slowest, fastest, pairs) * (1.0 + shift)
        angles = generator.uniform(0.1, 3.0, pairs)
        blocks = np.zeros((size, size))
        for index, (rate, angle) in enumerate(zip(rates, angles)):
            decay = np.exp(-rate)
            rows = slice(2 * index, 2 * index + 2)
            blocks[rows, rows] = decay * np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
        vectors = np.eye(size) + 0.2 * generator.standard_normal((size, size)) / np.sqrt(size)
        scale = np.geomspace(1.0, 1e4, size)  # unbalanced units: displacements and velocities
        transition = (scale[:, None] * (vectors @ blocks @ np.linalg.inv(vectors))) / scale[None, :]
        matrix = np.eye(size + 1)
        matrix[:size, :size] = transition
        matrix[:size, size] = scale * generator.standard_normal(size)
        maps.append(matrix)
    return maps


def _dense(maps):
    return floquet(maps[1] @ maps[0])


def test_low_rank_monodromy_gives_the_dense_multipliers_and_state():
    maps = _maps(400)
    multipliers, state = floquet_of_maps(maps)
    reference, reference_state = _dense(maps)
    assert multipliers.shape == reference.shape
    # backward errors of 1e-13 of the balanced map (module tolerance) against LAPACK's 1e-16: the moduli agree to
    # 1e-11 of the spectral radius (well-conditioned eigenvalues of a near-normal V), every multiplier above
    # 1e-9 has its partner within 1e-10, and the dropped ones are below 1e-12
    assert np.abs(np.abs(multipliers) - np.abs(reference)).max() < 1e-11 * np.abs(reference[0])
    for value in reference[np.abs(reference) > 1e-9]:
        assert np.abs(multipliers - value).min() < 1e-10
    dropped = multipliers == 0.0
    assert dropped.sum() > 100 and np.abs(reference[dropped]).max() < 1e-12
    # z₀ refined with the exact maps: equal to the dense solve at its own rounding (I − Φ well conditioned here)
    assert np.abs(state - reference_state).max() < 1e-11 * np.abs(reference_state).max()


def test_full_rank_monodromy_takes_the_dense_route():
    maps = _maps(400, slowest=0.3, fastest=0.6)  # nothing decays away: rank 400
    multipliers, state = floquet_of_maps(maps)
    reference, reference_state = _dense(maps)
    assert np.array_equal(multipliers, reference) and np.array_equal(state, reference_state)


def test_a_multiplier_outside_the_unit_circle_is_refused():
    maps = _maps(400)
    maps[0][:400, :400] *= 1.2e3  # |μ| of the slowest pair: 1.2e3·e^{−0.02·2.37}... > 1
    with pytest.raises(ModelLimitError, match="modulus"):
        floquet_of_maps(maps)
