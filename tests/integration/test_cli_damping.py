"""`thermogear damping` and `thermogear oils`: JSON keys, plot file, bad input → exit 2 with one clear line."""

from __future__ import annotations

import json
import subprocess

import pytest

import inprocess_cli


def run(*arguments: str) -> subprocess.CompletedProcess:
    return inprocess_cli.run(*arguments)


@pytest.fixture(scope="module")
def luo2019_json():
    result = run("damping", "luo2019", "--json", "--points", "240")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_damping_json_has_the_documented_keys(luo2019_json):
    data = luo2019_json
    assert set(data["friction_coefficient_pitch"]) == {"elastic", "thermal"}
    for model in ("elastic", "thermal"):
        assert set(data["damping_n_s_per_m"][model]) == {"single", "double"}
        assert all(value > 0 for value in data["damping_n_s_per_m"][model].values())
    assert set(data["viscosity_mpa_s"]) == {"oil_reference", "flank_mean"}
    assert data["viscosity_mpa_s"]["oil_reference"] == pytest.approx(457.8, rel=1e-3)
    assert data["rule"] == "paper" and data["paper_n_s_per_m"]["elastic"]["single"] == 3410.0
    assert any("10.0 K below" in message for message in data["warnings"])


def test_parallel_rule_doubles_up_the_double_region(luo2019_json):
    result = run("damping", "luo2019", "--json", "--points", "240", "--rule", "parallel")
    assert result.returncode == 0, result.stderr
    parallel = json.loads(result.stdout)["damping_n_s_per_m"]["elastic"]
    paper = luo2019_json["damping_n_s_per_m"]["elastic"]
    assert parallel["single"] == pytest.approx(paper["single"], rel=1e-9)
    assert parallel["double"] == pytest.approx(2 * paper["double"], rel=1e-9)


def test_damping_plot_is_written(tmp_path):
    target = tmp_path / "damping.png"
    result = run("damping", "luo2019", "--points", "120", "--plot", str(target))
    assert result.returncode == 0, result.stderr
    assert target.stat().st_size > 10_000
    assert "single-pair" in result.stdout


def test_oils_lists_the_library_with_sources():
    result = run("oils", "--json")
    assert result.returncode == 0, result.stderr
    oils = {row["name"]: row for row in json.loads(result.stdout)["oils"]}
    assert {"sch632", "iso_vg_100_mineral"} <= set(oils)
    assert oils["sch632"]["viscosity_points_c_mm2_s"] == [[40.0, 320.0], [100.0, 38.5]]
    assert all(row["source"] for row in oils.values())
    assert run("oils").returncode == 0


def test_case_file_with_rising_viscosity_exits_2_with_one_line(tmp_path):
    from thermogear.case import parameter_set_path

    text = parameter_set_path("luo2019").read_text(encoding="utf-8")
    text = text.replace('name = "sch632"', 'name = "mine"\nviscosity_points = [[40.0, 30.0], [100.0, 320.0]]\n'
                                           'base_oil = "pao"')
    case_file = tmp_path / "bad_oil.toml"
    case_file.write_text(text, encoding="utf-8")
    result = run("damping", str(case_file))
    assert result.returncode == 2
    assert "lubricant.viscosity_points" in result.stderr and "Traceback" not in result.stderr


def test_negative_roughness_exits_2(tmp_path):
    from thermogear.case import parameter_set_path

    text = parameter_set_path("luo2019").read_text(encoding="utf-8").replace("roughness_ra_um = 6.3",
                                                                             "roughness_ra_um = -1.0")
    case_file = tmp_path / "rough.toml"
    case_file.write_text(text, encoding="utf-8")
    result = run("damping", str(case_file))
    assert result.returncode == 2 and "roughness_ra_um" in result.stderr
