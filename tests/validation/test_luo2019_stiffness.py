"""luo2019 (Luo & Li 2020, Table 1): geometry of the path, ISO 6336-1 cross-check and the PEM numbers derived in
docs/derivations.md (the issue's acceptance numbers)."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

import thermogear.stiffness.potential_energy as potential_energy
from thermogear.stiffness.iso6336 import iso6336_stiffness
from thermogear.stiffness.table import pair_stiffness_at


@pytest.fixture(scope="module")
def summary():
    result = subprocess.run([sys.executable, "-m", "thermogear", "stiffness", "luo2019", "--json"],
                            capture_output=True, text=True, check=True)
    return json.loads(result.stdout)


def test_contact_ratio(summary):
    # docs/derivations.md: ε_α = 1.658; the issue allows ±0.001
    assert summary["contact_ratio"] == pytest.approx(1.658, abs=0.001)


@pytest.mark.parametrize("point, value", [("A", 6.383), ("B", 12.212), ("C", 13.852), ("D", 15.240),
                                          ("E", 21.068)])
def test_path_points(summary, point, value):
    # docs/derivations.md (three decimals given): ±0.002 mm as in the issue
    assert summary["path_mm"][point] == pytest.approx(value, abs=0.002)


@pytest.mark.parametrize("key, value", [("c_prime_n_per_mm_um", 12.92), ("c_gamma_alpha_n_per_mm_um", 19.30)])
def test_iso6336(summary, key, value):
    # docs/derivations.md, given to four figures: ±1 % as in the issue
    assert summary["iso6336"][key] == pytest.approx(value, rel=0.01)


def test_mean_mesh_stiffness_within_8_percent_of_iso(summary):
    mean = summary["mesh_stiffness_n_per_mm_um"]["mean"]
    assert mean == pytest.approx(summary["iso6336"]["c_gamma_alpha_n_per_mm_um"], rel=0.08)


def test_fzg_type_c_geometry():
    result = subprocess.run([sys.executable, "-m", "thermogear", "stiffness", "fzg_type_c", "--json"],
                            capture_output=True, text=True, check=True)
    data = json.loads(result.stdout)
    assert data["centre_distance_mm"] == pytest.approx(91.5, abs=1e-9)
    assert data["contact_ratio"] == pytest.approx(1.46, abs=0.02)


# docs/derivations.md pair stiffness per m of face width (three or four figures given)
HAND_PAIR = {"A": 9.27e9, "B": 1.323e10, "C": 1.345e10, "D": 1.327e10, "E": 9.25e9}


@pytest.mark.parametrize("point", list(HAND_PAIR))
def test_hand_values_with_the_gear_addendum_root_angle(luo2019, point, monkeypatch):
    """docs/derivations.md was computed with θ_f from the gear's addendum (h* = 1 in the θ_f formula, 0.1048 rad).
    With that θ_f every other part of our PEM reproduces its numbers to the figures given (±0.3 %)."""
    original = potential_energy.root_half_angle
    monkeypatch.setattr(potential_energy, "root_half_angle",
                        lambda teeth, angle, tool_addendum, rho: original(teeth, angle, 1.0, rho))
    pair = luo2019.gear_pair
    value = potential_energy.pair_compliance(pair, luo2019.material, pair.path_points[point], 1.0).stiffness
    assert float(value) == pytest.approx(HAND_PAIR[point], rel=0.003)


@pytest.mark.parametrize("point", list(HAND_PAIR))
def test_hand_values_with_the_rack_derived_root_angle(luo2019, point):
    """With θ_f derived from the rack (tool addendum 1.25, θ_f = 0.1116 rad; docs/stiffness.md) the fillet
    foundation is stiffer and the pair 2–3 % stiffer than docs/derivations.md: assert the size and sign of that gap."""
    pair = luo2019.gear_pair
    value = float(pair_stiffness_at(pair, luo2019.material, pair.path_points[point])) / pair.face_width
    assert 1.015 < value / HAND_PAIR[point] < 1.03


def test_mesh_stiffness_against_the_hand_values(luo2019, mesh_stiffness):
    # docs/derivations.md: min 1.32e10, mean 1.99e10, max 2.36e10 per m (with its θ_f); ours 2–3 % higher
    grid, _, total = mesh_stiffness(luo2019.gear_pair, luo2019.material, 2000.0, 2048)
    width = luo2019.gear_pair.face_width
    for ours, theirs in ((total.min(), 1.32e10), (grid.time_average(total), 1.99e10), (total.max(), 2.36e10)):
        assert 1.0 < ours / width / theirs < 1.035


def test_iso_cross_check_in_si(luo2019):
    iso = iso6336_stiffness(luo2019.gear_pair, luo2019.material, luo2019.operating_point)
    assert np.isclose(iso["c_prime"], 12.92e9, rtol=0.01)
