"""A helical pair in the 1-DOF solvers: its mesh state from the slice model, the spur pair's at β = 0, and the
transmission error a helix smooths."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
from thermogear.errors import ExtrapolationWarning, ModelAssumptionWarning
from thermogear.helical.geometry import HelicalPair
from thermogear.materials import Material
from thermogear.mesh.helical_state import helical_mesh_state
from thermogear.stiffness.table import pair_stiffness_at

INERTIAS = (4e-3, 9e-3)


@pytest.fixture(autouse=True)
def _quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        warnings.simplefilter("ignore", ModelAssumptionWarning)
        yield


def _state(beta_deg: float, points: int = 256):
    helical = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(beta_deg), 25e-3,
                                 bore_radii=(15e-3, 20e-3))
    return helical, helical_mesh_state(helical, Material(), 2000.0, 382.0, INERTIAS, points, damping_ratio=0.05)


def test_a_zero_helix_gives_the_spur_pairs_stiffness_load_and_mass():
    helical, state = _state(0.0, 64)
    pair = helical.transverse
    midpoints = (np.arange(64) + 0.5) / 64 * pair.base_pitch
    roll = pair.path_points["A"] + midpoints[:, None] + pair.base_pitch * np.arange(-1, 3)
    inside = (roll >= pair.path_points["A"]) & (roll <= pair.path_points["E"])
    spur = np.where(inside, pair_stiffness_at(pair, Material(), np.where(inside, roll, pair.path_points["A"])), 0.0)
    np.testing.assert_allclose(state.mesh_stiffness, spur.sum(axis=1), rtol=1e-13)
    assert state.normal_load == pytest.approx(382.0 / pair.pinion.base_radius, rel=1e-15)
    assert state.mass == pytest.approx(pair.equivalent_mass(7850.0, INERTIAS), rel=1e-13)
    assert state.period == pytest.approx(pair.mesh_period(2000.0), rel=1e-14)


def test_a_helix_smooths_the_transmission_error():
    """27/35 at 2000 rpm, 382 N·m, ζ = 0.05: the helical K_t swings 24 % where the spur one swings 52 %, and the
    dynamic transmission error follows (the same mass and damping ratio, far from resonance: f_m 900 Hz)."""
    swings = {}
    for beta in (0.0, 15.0):
        _, state = _state(beta)
        orbit = periodic_steady_state(state.problem(), 4)
        swings[beta] = np.ptp(orbit.displacement)
        assert np.all(np.abs(orbit.multipliers) < 1.0)
    assert swings[15.0] < 0.5 * swings[0.0]
