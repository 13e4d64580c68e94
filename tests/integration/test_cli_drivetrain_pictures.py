"""The drivetrain's pictures from the command line (`run --plot FOLDER`) and in the report (`run --out`): the four
pictures written, refused before any work where they cannot be drawn or would replace files, and in the report
among the figures with a link at the top of the page. What each picture shows is tested in
tests/unit/test_drivetrain_pictures.py."""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest

import inprocess_cli

TWO_SHAFTS = Path(__file__).resolve().parents[1] / "data" / "two_shaft_drivetrain.toml"
PICTURES = ("drivetrain_layout", "drivetrain_modes", "drivetrain_campbell", "drivetrain_bearing_spectra")


def _cli(*args: str) -> subprocess.CompletedProcess:
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=1):
        return inprocess_cli.run(*args)


def test_run_plot_writes_the_four_pictures_and_replaces_them_only_with_force(tmp_path):
    from matplotlib.image import imread

    folder = tmp_path / "pictures"
    result = _cli("run", str(TWO_SHAFTS), "--model", "elastic", "--json", "--plot", str(folder))
    assert result.returncode == 0, result.stderr
    payload = json.loads(result.stdout)
    assert sorted(Path(path).name for path in payload["plots"]) == sorted(f"{name}.png" for name in PICTURES)
    for name in PICTURES:
        pixels = imread(folder / f"{name}.png")
        assert pixels.shape[0] > 300 and pixels.shape[1] > 600 and float(pixels[..., :3].std()) > 0.05
    assert sorted(os.listdir(folder)) == sorted(f"{name}.png" for name in PICTURES)  # no partial file left
    again = _cli("run", str(TWO_SHAFTS), "--model", "elastic", "--plot", str(folder))
    assert again.returncode != 0 and "--plot" in again.stderr and "--force" in again.stderr


def test_run_plot_on_a_case_without_a_drivetrain_is_refused_before_any_work(tmp_path):
    folder = tmp_path / "pictures"
    result = _cli("run", "luo2019", "--plot", str(folder))
    assert result.returncode != 0
    assert "--plot" in result.stderr and "[drivetrain]" in result.stderr
    assert not folder.exists()


@pytest.mark.slow
def test_the_report_shows_the_drivetrain_pictures_and_links_to_them(tmp_path):
    out = tmp_path / "report"
    result = _cli("run", str(TWO_SHAFTS), "--out", str(out), "--quiet")
    assert result.returncode == 0, result.stderr
    page = (out / "report.html").read_text(encoding="utf-8")
    for name in PICTURES:
        assert (out / "figures" / f"{name}.png").is_file() and (out / "figures" / f"{name}.svg").is_file()
        assert page.count(f"<figure id='{name}'>") == 1
        assert f"<b>{name}</b> not drawn" not in page
    assert "<a href='#drivetrain_layout'>drivetrain pictures</a>" in page
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert set(PICTURES) <= set(summary["figures"]["drawn"])
