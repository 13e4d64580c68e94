"""Mesh cycle: pair positions, contact flags, transitions as grid nodes, parallel sum and load share."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.geometry import Gear, GearPair
from thermogear.materials import Material
from thermogear.geometry.mesh_cycle import MeshCycle, load_shares


def high_contact_ratio_pair() -> GearPair:
    angle = math.radians(16)
    common = dict(module=0.002, pressure_angle=angle, face_width=0.02, addendum_coefficient=1.35,
                  dedendum_coefficient=1.6)
    return GearPair.create(Gear(teeth=60, bore_radius=0.02, **common), Gear(teeth=80, bore_radius=0.03, **common))


def test_luo2019_double_then_single_contact(luo2019):
    pair = luo2019.gear_pair
    cycle = MeshCycle(pair, 2000.0)
    assert cycle.slots == 2
    assert cycle.period == pytest.approx(60 / (27 * 2000))
    np.testing.assert_allclose(cycle.transition_times, [0.0, (pair.contact_ratio - 1) * cycle.period])
    grid = cycle.grid(100)
    for time in cycle.transition_times:
        assert np.any(grid.nodes == time)
    assert grid.nodes[0] == 0.0 and grid.nodes[-1] == pytest.approx(cycle.period)
    assert set(np.unique(grid.contact_count)) == {1, 2}
    # the fraction of the period in double contact is ε − 1; the mean number of pairs in contact is ε
    assert grid.time_average(grid.contact_count) == pytest.approx(pair.contact_ratio, rel=1e-12)
    # the leading slot runs from A; the second one finishes at E at the transition
    roll, in_contact = cycle.positions(np.array([0.0, cycle.transition_times[1] - 1e-12]))
    assert roll[0, 0] == pytest.approx(pair.path_points["A"])
    assert roll[1, 1] == pytest.approx(pair.path_points["E"], abs=1e-9)
    assert in_contact[:, 0].all()


def test_positions_are_periodic(luo2019):
    cycle = MeshCycle(luo2019.gear_pair, 2000.0)
    times = np.linspace(0, cycle.period, 7, endpoint=False)
    np.testing.assert_allclose(cycle.positions(times)[0], cycle.positions(times + 3 * cycle.period)[0],
                               atol=1e-12)


def test_contact_ratio_above_two(mesh_stiffness):
    pair = high_contact_ratio_pair()
    assert pair.contact_ratio > 2.5
    cycle = MeshCycle(pair, 1000.0)
    assert cycle.slots == 3
    grid = cycle.grid(64)
    assert set(np.unique(grid.contact_count)) == {2, 3}
    assert grid.time_average(grid.contact_count) == pytest.approx(pair.contact_ratio, rel=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        grid, per_pair, total = mesh_stiffness(pair, Material(), 1000.0, 64)
    np.testing.assert_allclose(total, per_pair.sum(axis=0))
    assert np.all(per_pair[~grid.in_contact] == 0.0)


def test_total_and_load_share():
    per_pair = np.array([[1.0, 2.0, 3.0], [3.0, 2.0, 5.0]])
    in_contact = np.array([[True, True, True], [True, True, False]])
    np.testing.assert_allclose(MeshCycle.total(per_pair, in_contact), [4.0, 4.0, 3.0])
    share = load_shares(per_pair, in_contact)
    np.testing.assert_allclose(share, [[0.25, 0.5, 1.0], [0.75, 0.5, 0.0]])
    np.testing.assert_allclose(share.sum(axis=0), 1.0)


def test_mesh_stiffness_jumps_at_the_transitions(luo2019, mesh_stiffness):
    grid, per_pair, total = mesh_stiffness(luo2019.gear_pair, luo2019.material, 2000.0, 512)
    double = grid.contact_count == 2
    assert total[double].min() > total[~double].max()
    # per-pair values are the table's pair stiffness
    assert per_pair.max() < total.max()
