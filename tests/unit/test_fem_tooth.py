"""Unit checks of the FE tooth model: outline geometry, heat-flux and partition functions, contact geometry and
the section reading."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.fem.heat import blok_heat_partition, mean_flank_heat_flux, rotating_disc_coefficient
from thermogear.fem.tooth_elastic import contact_point_geometry, hertz_half_width, section_deflection
from thermogear.fem.tooth_mesh import tooth_mesh
from thermogear.fem.tooth_profile import trochoid_fillet


@pytest.fixture(scope="module")
def pair():
    return load_case("luo2019").gear_pair


@pytest.mark.parametrize("which", ["pinion", "wheel"])
def test_trochoid_fillet_runs_from_the_root_circle_to_the_involute_start(pair, which):
    gear = getattr(pair, which)
    radius, angle = trochoid_fillet(gear, 50)
    assert radius[0] == pytest.approx(gear.root_radius, rel=1e-12)
    assert radius[-1] == pytest.approx(gear.form_radius, rel=1e-9)  # the rack flank's end generates the form point
    assert angle[-1] == pytest.approx(float(gear.half_angle_at(radius[-1])), abs=1e-12)  # joins the involute
    assert np.all(angle <= math.pi / gear.teeth)  # inside the tooth space centre


@pytest.mark.parametrize("teeth", [1, 3, 0])
def test_mesh_covers_the_outline_and_keeps_the_tags(pair, teeth):
    mesh = tooth_mesh(pair.pinion, teeth=teeth)
    outline = mesh.outline
    loops = outline.loops or (len(outline.points),)
    start, polygon_area = 0, 0.0
    for count in loops:
        x, y = outline.points[start:start + count].T
        polygon_area += 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))) * (1 if start == 0 else -1)
        start += count
    p, t = mesh.mesh.p, mesh.mesh.t
    areas = 0.5 * np.abs((p[0, t[1]] - p[0, t[0]]) * (p[1, t[2]] - p[1, t[0]])
                         - (p[0, t[2]] - p[0, t[0]]) * (p[1, t[1]] - p[1, t[0]]))
    assert areas.sum() == pytest.approx(polygon_area, rel=1e-9)
    for name in ("bore", "active_flank", "passive_flank", "fillet", "tip"):
        assert len(mesh.facets(name)) > 0
    # the loaded flank is the right flank of the middle tooth only
    centres = p[:, mesh.mesh.facets[:, mesh.facets("active_flank")]].mean(axis=1)
    assert np.all(centres[0] > 0)
    assert np.all(np.abs(np.arctan2(centres[0], centres[1])) < math.pi / pair.pinion.teeth)


def test_blok_partition_limits_and_symmetry():
    assert blok_heat_partition(1.0, 1.0) == pytest.approx(0.5)
    assert blok_heat_partition(4.0, 1.0) == pytest.approx(2.0 / 3.0)
    assert blok_heat_partition(0.0, 1.0) == pytest.approx(0.0)


def test_mean_flux_is_the_contact_fraction_of_the_instantaneous_flux():
    """q̄ = q·(2a/(ωρ))/(2π/ω) with q = μ p_m v_s and p_m = F′/(2a) (docs/fem.md)."""
    mu, load, sliding, radius, width = 0.05, 4e5, 2.0, 0.01, 2e-4
    instantaneous = mu * load / (2 * width) * sliding
    expected = instantaneous * (2 * width / radius) / (2 * math.pi)
    assert mean_flank_heat_flux(1.0, mu, load, sliding, radius) == pytest.approx(expected, rel=1e-12)
    assert mean_flank_heat_flux(0.5, mu, load, sliding, radius, 0.9) == pytest.approx(0.45 * expected, rel=1e-12)


def test_rotating_disc_coefficient_scales_with_root_of_speed():
    one = rotating_disc_coefficient(0.03, 0.7, 100.0, 2e-5)
    assert rotating_disc_coefficient(0.03, 0.7, 400.0, 2e-5) == pytest.approx(2 * one)


def test_contact_normal_is_normal_to_the_flank_and_along_the_line_of_action(pair):
    gear = pair.pinion
    roll = pair.roll_grid(5)
    x, y, load_angle, normal = contact_point_geometry(gear, roll)
    x2, y2, _, _ = contact_point_geometry(gear, roll + 1e-7)
    tangent = np.stack([x2 - x, y2 - y])
    assert np.allclose(np.sum(tangent * normal, axis=0) / np.hypot(*tangent), 0.0, atol=1e-5)
    assert np.allclose(load_angle, pair.pinion_load_angle(roll), atol=1e-12)  # ω_k = α1
    # the normal line is tangent to the base circle: its distance from the centre is r_b
    distance = np.abs(x * normal[1] - y * normal[0])
    assert np.allclose(distance, gear.base_radius, rtol=1e-9)


def test_hertz_half_width_hand_value():
    # a = 2 sqrt(F'R/(π E*)), E* = E/(2(1-ν²))
    expected = 2 * math.sqrt(4e5 * 8e-3 / (math.pi * 206e9 / (2 * 0.91)))
    assert hertz_half_width(4e5, 8e-3, 206e9, 0.3) == pytest.approx(expected)


def test_section_reading_recovers_a_rigid_section_motion():
    """A section that translates by (a, b) and rotates by θ moves K = (x_K, y) by (a, b + θ x_K)."""
    chord = np.linspace(-0.75, 0.5, 13)[:, None] * np.array([[1e-3, 2e-3]])
    a, b, theta = np.array([1e-6, -2e-6]), np.array([3e-7, 1e-7]), np.array([1e-4, -5e-4])
    ux = np.broadcast_to(a, chord.shape)
    uy = b + theta * chord
    normal = np.array([[0.8, 1.0], [0.6, 0.0]])
    deflection, moved = section_deflection(ux, uy, chord, np.array([1e-3, 2e-3]), normal)
    expected = np.stack([a, b + theta * np.array([1e-3, 2e-3])])
    assert np.allclose(moved, expected, rtol=1e-12)
    assert np.allclose(deflection, -np.sum(expected * normal, axis=0))
