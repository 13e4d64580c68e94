"""`thermogear stiffness`: JSON keys and units, the table, the figure, --thermal without the thermal module."""

from __future__ import annotations

import json
import subprocess

import pytest

import inprocess_cli

KEYS = ("contact_ratio", "centre_distance_mm", "mesh_period_s", "path_mm", "gamma", "pair_stiffness_n_per_mm_um",
        "mesh_stiffness_n_per_mm_um", "iso6336")


def run(*arguments: str) -> subprocess.CompletedProcess:
    return inprocess_cli.run("stiffness", *arguments)


@pytest.fixture(scope="module")
def fzg_json():
    result = run("fzg_type_c", "--json")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout), result.stderr


def test_json_has_the_documented_keys(fzg_json):
    data, _ = fzg_json
    for key in KEYS:
        assert key in data
    for key in ("path_mm", "gamma", "pair_stiffness_n_per_mm_um"):
        assert set(data[key]) == set("ABCDE")
    assert set(data["mesh_stiffness_n_per_mm_um"]) == {"min", "mean", "max"}
    assert set(data["iso6336"]) == {"c_prime_n_per_mm_um", "c_gamma_alpha_n_per_mm_um"}
    assert data["gamma"]["C"] == 0.0
    mesh = data["mesh_stiffness_n_per_mm_um"]
    assert mesh["min"] < mesh["mean"] < mesh["max"]
    # per mm of face width: the total over 14 mm divided by the width
    assert mesh["mean"] == pytest.approx(data["mesh_stiffness_total_n_per_m"]["mean"] / 14e-3 / 1e9)
    assert data["mesh_period_s"] == pytest.approx(60 / (16 * 2175))


def test_extrapolation_is_reported_not_fatal(fzg_json):
    data, stderr = fzg_json
    # the z = 16 pinion has θ_f = 0.188 rad, beyond the Sainsot range: a warning, in the JSON and on stderr
    assert any("θ_f" in message for message in data["warnings"])
    assert "warning" in stderr


def test_table_output():
    result = run("luo2019")
    assert result.returncode == 0, result.stderr
    assert "ISO 6336-1" in result.stdout and "13.852" in result.stdout


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_is_written(tmp_path, suffix):
    path = tmp_path / f"stiffness{suffix}"
    result = run("luo2019", "--plot", str(path))
    assert result.returncode == 0, result.stderr
    assert path.stat().st_size > 1000
    assert list(tmp_path.iterdir()) == [path]  # no temporary file left behind


def test_bad_plot_suffix_exits_2(tmp_path):
    result = run("luo2019", "--plot", str(tmp_path / "figure.txt"))
    assert result.returncode == 2
    assert "Traceback" not in result.stderr


def test_unknown_case_exits_2():
    result = run("luo2091")
    assert result.returncode == 2
    assert "luo2019" in result.stderr and "Traceback" not in result.stderr
