"""Modal analysis on matrices: damped oscillators with known ω_n and ζ, energy shares and fractions, rigid-body
modes and the reduction onto their complement."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.modes.modal import (damped_modes, kinetic_energy_fractions, strain_energy_shares,
                                       undamped_modes)
from thermogear.dynamics.modes.rigid_body import rigid_body_modes, rigid_body_reduction
from thermogear.errors import ProblemError


def test_damped_oscillators_give_their_natural_frequency_and_damping_ratio():
    # two uncoupled oscillators: ω_n = √(k/m), ζ = c/(2√(km)), ω_d = ω_n√(1−ζ²): exact to rounding
    mass, stiffness, damping = np.diag([2.0, 0.5]), np.diag([8e6, 2e6]), np.diag([400.0, 60.0])
    modes = damped_modes(mass, damping, stiffness)
    assert modes.natural_frequencies == pytest.approx([2000.0, 2000.0], rel=1e-12)
    assert np.sort(modes.damping_ratios) == pytest.approx(np.sort([400 / (2 * 4000.0), 60 / (2 * 1000.0)]),
                                                          rel=1e-10)
    assert modes.damped_frequencies == pytest.approx(modes.natural_frequencies
                                                     * np.sqrt(1 - modes.damping_ratios**2), rel=1e-12)


def test_undamped_modes_are_mass_normalised_and_refuse_bad_matrices():
    mass = np.array([[2.0, 0.3], [0.3, 1.0]])
    stiffness = np.array([[3e6, -1e6], [-1e6, 1e6]])
    modes = undamped_modes(mass, stiffness)
    assert modes.shapes.T @ mass @ modes.shapes == pytest.approx(np.eye(2), abs=1e-12)
    residual = stiffness @ modes.shapes - mass @ modes.shapes * modes.angular_frequencies**2
    assert np.abs(residual).max() < 1e-9 * np.abs(stiffness).max()
    with pytest.raises(ProblemError, match="mass"):
        undamped_modes(-mass, stiffness)
    with pytest.raises(ProblemError, match="stiffness"):
        undamped_modes(mass, -stiffness)
    with pytest.raises(ProblemError, match="stiffness"):
        undamped_modes(mass, np.ones((3, 3)))


def test_shares_and_fractions_sum_to_one_and_single_out_the_element():
    # a chain ground–k1–m1–k2–m2: each spring's matrix; the shares of every mode add up to 1
    k1, k2 = 1e6, 3e7
    springs = {"k1": np.array([[k1, 0.0], [0.0, 0.0]]), "k2": k2 * np.array([[1.0, -1.0], [-1.0, 1.0]])}
    mass = np.diag([1.0, 2.0])
    modes = undamped_modes(mass, sum(springs.values()))
    shares = strain_energy_shares(modes.shapes, springs)
    assert shares["k1"] + shares["k2"] == pytest.approx([1.0, 1.0], abs=1e-14)
    # k2 thirty times stiffer: the first mode moves both masses together and k1 (to ground) holds nearly all its
    # energy; the second stretches k2 (each holds > 95 % of its mode's; the exact split is 1 − O(k1/k2))
    assert shares["k1"][0] > 0.95 and shares["k2"][1] > 0.95
    fractions = kinetic_energy_fractions(modes.shapes, mass, {"first": np.array([True, False]),
                                                             "second": np.array([False, True])})
    assert fractions["first"] + fractions["second"] == pytest.approx([1.0, 1.0], abs=1e-14)
    with pytest.raises(ProblemError, match="rigid-body"):
        strain_energy_shares(np.array([[1.0], [1.0]]), {"k2": springs["k2"]})


def test_rigid_body_modes_and_the_complement():
    # two bodies joined by one spring, nothing to ground: one rigid translation; with a candidate that nothing
    # touches, that one is free too
    connection = 5e9 * np.array([[1.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, 0.0]])
    candidates = np.eye(3)
    rigid = rigid_body_modes(connection, candidates)
    assert rigid.shape == (3, 2)
    assert np.abs(connection @ rigid).max() < 1e-6
    mass = np.diag([1.0, 3.0, 2.0])
    reduction = rigid_body_reduction(mass, connection, candidates)
    assert reduction.basis.shape == (3, 1)
    assert np.abs(rigid.T @ mass @ reduction.basis).max() < 1e-12
    # ω² of the remaining elastic mode: k(1/m1 + 1/m2)
    values = np.linalg.eigvals(np.linalg.solve(reduction.project(mass), reduction.project(connection)))
    assert values[0] == pytest.approx(5e9 * (1 + 1 / 3), rel=1e-12)
    with pytest.raises(ProblemError, match="damping"):
        rigid_body_reduction(mass, connection, candidates, damping=np.diag([1.0, 0.0, 0.0]))
