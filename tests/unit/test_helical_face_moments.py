"""The stiffness in contact across the face over the mesh period (its moments: the load centre z̄(φ) and the tilting
stiffness k(φ)ρ(φ)² the drivetrain's spread contact needs) and the load centre of the line load, from the slice
model of a case (the FZG helical test gear H501, ``fzg_h501``): without deviations the stiffness is spread
symmetrically about mid-face and its period mean is the unloaded slice model's (face_contact_moments); a uniform
temperature leaves the load at mid-face, a gradient across the face moves it to the hot side."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.drivetrain.mesh_contact import face_contact_moments
from thermogear.mesh.helical_model import helical_mesh_period
from thermogear.mesh.model import MeshModel

POINTS = 64


def _period(model: str, gradient_k: float):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case("fzg_h501").with_changes(**{"temperature.face_gradient_k": gradient_k})
        mesh = MeshModel(case, model)
        return case, helical_mesh_period(mesh, mesh.normal_load(), POINTS, face_stiffness=True)


def test_without_deviations_the_stiffness_is_spread_symmetrically_about_mid_face():
    case, period = _period("elastic", 0.0)
    width = case.helical_pair.face_width
    moments = period.face.stiffness_moments
    # every slice in contact (no deviation): k₀ is the period's stiffness, and the period means are the unloaded
    # slice model's, which the drivetrain's face_contact_moments computes on the same slices and phases
    np.testing.assert_allclose(moments.stiffness, period.stiffness, rtol=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        centre, gyration = face_contact_moments(case.helical_pair, case.material, 100, POINTS)
    assert moments.mean_load_centre == pytest.approx(centre, rel=1e-9, abs=1e-12 * width)
    assert moments.mean_gyration == pytest.approx(gyration, rel=1e-9)
    # the load centre moves across the face with the contact lines, symmetrically about mid-face: its mean is 0
    # and its extremes are opposite (each slice sees the same stiffness history shifted in phase; on 64 phases
    # and 100 slices the sampling leaves 4e-5 b of the mean and 0.6 % between the extremes), and the spread is
    # that of a uniform face, ρ = b/√12 (to 1e-4 relative)
    swing = moments.load_centre
    assert abs(np.mean(swing)) < 1e-3 * width and abs(moments.mean_load_centre) < 1e-4 * width
    assert swing.max() == pytest.approx(-swing.min(), rel=0.02) and swing.max() > 0.03 * width
    assert moments.mean_gyration == pytest.approx(width / math.sqrt(12.0), rel=1e-3)
    assert np.all(moments.tilting_stiffness > 0.0)


def test_a_uniform_temperature_keeps_the_load_at_mid_face_and_a_gradient_moves_it_to_the_hot_side():
    case, uniform = _period("thermal", 0.0)
    width = case.helical_pair.face_width
    middle = width / 2.0
    # a uniform rise: the profile deviations act alike on every slice at its place on the path, so the line load
    # stays centred (2.6e-4 b measured: the sampling of the contact lines)
    assert abs(uniform.face.load_centre - middle) < 1e-3 * width
    shifts = {}
    for gradient in (10.0, -10.0, 30.0):
        _, period = _period("thermal", gradient)
        shifts[gradient] = period.face.load_centre - middle
        # the hot side is z = 0 for a positive gradient (ΔT = g(1/2 − z/b)): the load moves there at every
        # mesh position, and the stiffness in contact is unchanged while every slice still touches
        below = period.face.load_centres - uniform.face.load_centres
        assert np.all(np.sign(below) == -np.sign(gradient))
        np.testing.assert_allclose(period.face.stiffness_moments.stiffness, uniform.face.stiffness_moments.stiffness,
                                   rtol=1e-12)
    assert shifts[10.0] < -0.01 * width and shifts[-10.0] > 0.01 * width
    # in full contact the slice loads are linear in the gaps: the shift is odd and proportional in the gradient
    assert shifts[-10.0] - (uniform.face.load_centre - middle) == pytest.approx(
        -(shifts[10.0] - (uniform.face.load_centre - middle)), rel=1e-6)
    assert shifts[30.0] - (uniform.face.load_centre - middle) == pytest.approx(
        3.0 * (shifts[10.0] - (uniform.face.load_centre - middle)), rel=1e-6)
